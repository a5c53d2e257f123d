/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "grainGather.H"
#include "Pstream.H"
#include "scalarList.H"

#include <algorithm>
#include <numeric>

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

//- The per-grain fields of a GrainData with their widths, in one order for
//- packing and unpacking
template<class Visit>
void forEachField(dem::GrainData& g, Visit&& visit)
{
    visit(g.position, 3);
    visit(g.displacement, 3);
    visit(g.velocity, 3);
    visit(g.angularVelocity, 3);
    visit(g.force, 3);
    visit(g.fluidForce, 3);
    visit(g.torque, 3);
    visit(g.radius, 1);
    visit(g.coreHalfLength, 1);
    visit(g.orientation, 4);
    visit(g.volume, 1);
    visit(g.mass, 1);
    visit(g.contactCount, 1);
    visit(g.flag, 1);
    visit(g.id, 1);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

dem::GrainData Foam::grainGather::toMaster(const dem::GrainData& g)
{
    if (!Pstream::parRun())
    {
        return g;
    }

    // One record of doubles per grain (ints and flags are exact in doubles)
    dem::GrainData local(g);
    const size_t n = local.id.size();
    label width = 0;
    forEachField(local, [&](auto&, int w) { width += w; });

    List<scalarList> records(Pstream::nProcs());
    scalarList& mine = records[Pstream::myProcNo()];
    mine.setSize(label(n)*width);
    label offset = 0;
    forEachField
    (
        local,
        [&](auto& field, int w)
        {
            for (size_t i = 0; i < n; ++i)
            {
                for (int c = 0; c < w; ++c)
                {
                    mine[label(i)*width + offset + c] = scalar(field[w*i + c]);
                }
            }
            offset += w;
        }
    );
    Pstream::gatherList(records);

    dem::GrainData all;
    if (!Pstream::master())
    {
        return all;
    }

    // Every grain's record, then the order of their ids
    scalarList joined;
    for (const scalarList& r : records)
    {
        joined.append(r);
    }
    const size_t total = joined.size()/width;
    std::vector<double> id(total);
    for (size_t i = 0; i < total; ++i)
    {
        id[i] = joined[label(i)*width + width - 1];
    }
    std::vector<size_t> order(total);
    std::iota(order.begin(), order.end(), size_t(0));
    std::sort
    (
        order.begin(), order.end(),
        [&](size_t a, size_t b) { return id[a] < id[b]; }
    );

    offset = 0;
    forEachField
    (
        all,
        [&](auto& field, int w)
        {
            using value = typename std::decay_t<decltype(field)>::value_type;
            field.resize(w*total);
            for (size_t k = 0; k < total; ++k)
            {
                for (int c = 0; c < w; ++c)
                {
                    field[w*k + c] =
                        value(joined[label(order[k])*width + offset + c]);
                }
            }
            offset += w;
        }
    );
    return all;
}


// ************************************************************************* //

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

namespace Foam
{
namespace
{

//- The per-grain fields of a GrainData with their widths, in one order for
//- packing and unpacking; the id first: the sort key
template<class Visit>
void forEachField(dem::GrainData& g, Visit&& visit)
{
    visit(g.id, 1);
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
}


//- The per-bond fields of a BondData, the grains' ids first: the sort key
template<class Visit>
void forEachField(dem::BondData& b, Visit&& visit)
{
    visit(b.first, 1);
    visit(b.second, 1);
    visit(b.patchRadius, 1);
    visit(b.normalForce, 1);
    visit(b.shearForce, 3);
    visit(b.twistMoment, 1);
    visit(b.bendMoment, 3);
    visit(b.normal, 3);
    visit(b.point, 3);
    visit(b.age, 1);
    visit(b.softening, 1);
    visit(b.creepNormal, 1);
    visit(b.creepShear, 1);
    visit(b.creepTwist, 1);
    visit(b.creepBend, 1);
}


//- Collective: every rank's records (count of them each, one row of doubles
//- per record: ints, flags and ids are exact in doubles) joined on the
//- master and sorted by their first keys columns; empty on the other ranks
template<class Data>
Data gatherSorted(const Data& data, const size_t count, const int keys)
{
    Data local(data);
    label width = 0;
    forEachField(local, [&](auto&, int w) { width += w; });

    List<scalarList> records(Pstream::nProcs());
    scalarList& mine = records[Pstream::myProcNo()];
    mine.setSize(label(count)*width);
    label offset = 0;
    forEachField
    (
        local,
        [&](auto& field, int w)
        {
            for (size_t i = 0; i < count; ++i)
            {
                for (int c = 0; c < w; ++c)
                {
                    mine[label(i)*width + offset + c] =
                        scalar(field[w*i + c]);
                }
            }
            offset += w;
        }
    );
    Pstream::gatherList(records);

    Data all;
    if (!Pstream::master())
    {
        return all;
    }

    scalarList joined;
    for (const scalarList& r : records)
    {
        joined.append(r);
    }
    const size_t total = joined.size()/width;
    std::vector<size_t> order(total);
    std::iota(order.begin(), order.end(), size_t(0));
    std::sort
    (
        order.begin(), order.end(),
        [&](size_t a, size_t b)
        {
            return std::lexicographical_compare
            (
                &joined[label(a)*width], &joined[label(a)*width] + keys,
                &joined[label(b)*width], &joined[label(b)*width] + keys
            );
        }
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

} // End anonymous namespace
} // End namespace Foam


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

dem::GrainData Foam::grainGather::toMaster(const dem::GrainData& g)
{
    if (!Pstream::parRun())
    {
        return g;
    }
    return gatherSorted(g, g.id.size(), 1);
}


dem::BondData Foam::grainGather::toMaster(const dem::BondData& b)
{
    if (!Pstream::parRun())
    {
        return b;
    }
    return gatherSorted(b, b.first.size(), 2);
}


// ************************************************************************* //

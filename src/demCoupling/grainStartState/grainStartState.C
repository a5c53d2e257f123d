/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "grainStartState.H"
#include "grainsFile.H"
#include "error.H"

#include <algorithm>
#include <cmath>
#include <sstream>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- A number as a user would write it (10 digits: the OpenFOAM error stream
//- follows writePrecision, and 0.1 read back prints 0.10000000000000001)
std::string num(const double x)
{
    std::ostringstream os;
    os.precision(10);
    os  << x;
    return os.str();
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::grainStartState::grainStartState
(
    const fileName& path,
    const dictionary& demProperties,
    const dem::UniformGrid& mesh,
    const std::vector<dem::WallSpec>& walls
)
:
    path_(path)
{
    grains_ = grainsFile(path).read(lines_);
    checkPlacement(demProperties, mesh, walls);
    checkOverlaps(demProperties, mesh);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::string Foam::grainStartState::describe(const size_t i) const
{
    std::ostringstream os;
    os.precision(10);
    const auto& x = grains_[i].position;
    os  << "grain " << i << " (line " << lines_[i] << ") at (" << x[0] << ' '
        << x[1] << ' ' << x[2] << ')';
    return os.str();
}


void Foam::grainStartState::checkPlacement
(
    const dictionary& demProperties,
    const dem::UniformGrid& mesh,
    const std::vector<dem::WallSpec>& walls
)
{
    const bool wrap = demProperties.getOrDefault<bool>("wrapGrains", false);
    label wrapped = 0;

    for (size_t i = 0; i < grains_.size(); ++i)
    {
        auto& x = grains_[i].position;

        // Periodic in x and y: [lo, hi)
        for (int d = 0; d < 2; ++d)
        {
            const scalar lo = mesh.origin[d];
            const scalar length = mesh.n[d]*mesh.spacing[d];
            if (x[d] >= lo && x[d] < lo + length)
            {
                continue;
            }
            if (!wrap || !std::isfinite(x[d]))
            {
                FatalIOErrorInFunction(demProperties)
                    << describe(i).c_str() << " of " << path_ << " lies"
                    << " outside the periodic box, " << char('x' + d)
                    << " in [" << num(lo).c_str() << ", "
                    << num(lo + length).c_str() << ")." << nl
                    << "Set 'wrapGrains yes;' in " << demProperties.name()
                    << " to wrap such grains into the box." << nl
                    << exit(FatalIOError);
            }
            x[d] -= length*std::floor((x[d] - lo)/length);
            x[d] = std::min(std::max(x[d], lo), lo + length);
            ++wrapped;
        }

        const scalar zLo = mesh.origin[2];
        const scalar zHi = zLo + mesh.n[2]*mesh.spacing[2];
        if (!(x[2] >= zLo && x[2] <= zHi))
        {
            FatalErrorInFunction
                << describe(i).c_str() << " of " << path_ << " lies outside"
                << " the mesh, z in [" << num(zLo).c_str() << ", "
                << num(zHi).c_str() << "]" << nl
                << exit(FatalError);
        }
        for (const dem::WallSpec& w : walls)
        {
            const bool lower = w.side == dem::WallSpec::Side::lower;
            if (lower ? x[2] < w.position : x[2] > w.position)
            {
                FatalIOErrorInFunction(demProperties)
                    << describe(i).c_str() << " of " << path_ << " lies "
                    << (lower ? "below the lower" : "above the upper")
                    << " wall at z = " << num(w.position).c_str() << " ("
                    << demProperties.name() << ", walls)" << nl
                    << exit(FatalIOError);
            }
        }
    }

    if (wrapped)
    {
        Info<< "    wrapGrains: " << wrapped << " coordinate(s) of " << path_
            << " wrapped into the periodic box" << endl;
    }
}


void Foam::grainStartState::checkOverlaps
(
    const dictionary& demProperties,
    const dem::UniformGrid& mesh
) const
{
    const scalar allowed =
        demProperties.getOrDefault<scalar>("maxInitialOverlap", 0.05);
    if (!(allowed >= 0))
    {
        FatalIOErrorInFunction(demProperties)
            << "Entry 'maxInitialOverlap' in " << demProperties.name()
            << " must be >= 0 (a fraction of the smaller radius), found "
            << allowed << nl << exit(FatalIOError);
    }

    const label n = grains_.size();
    // A capsule is bounded by the sphere of radius r + h about its centre
    const auto bounding = [&](const size_t i)
    {
        return grains_[i].radius + grains_[i].coreHalfLength;
    };
    scalar rMax = 0;
    for (size_t i = 0; i < grains_.size(); ++i)
    {
        rMax = max(rMax, bounding(i));
    }

    // Cells at least one largest diameter wide: overlapping grains lie in
    // the same or neighbouring cells. At most about n cells in all.
    scalar length[3];
    label cells[3];
    scalar size = 2*rMax;
    for (;;)
    {
        scalar total = 1;
        for (int d = 0; d < 3; ++d)
        {
            length[d] = mesh.n[d]*mesh.spacing[d];
            cells[d] = max(label(1), label(std::floor(length[d]/size)));
            total *= cells[d];
        }
        if (total <= 2*n + 8)
        {
            break;
        }
        size *= 1.5;
    }

    const auto cellOf = [&](const size_t i, const int d) -> label
    {
        const scalar s = (grains_[i].position[d] - mesh.origin[d])/length[d];
        return min(max(label(std::floor(s*cells[d])), label(0)), cells[d] - 1);
    };
    const auto indexOf = [&](const label cx, const label cy, const label cz)
    {
        return cx + cells[0]*(cy + cells[1]*cz);
    };

    // Grains sorted by cell: start[c] .. start[c + 1] in 'order'
    std::vector<label> cellOfGrain(n), start(cells[0]*cells[1]*cells[2] + 1, 0);
    for (label i = 0; i < n; ++i)
    {
        cellOfGrain[i] = indexOf(cellOf(i, 0), cellOf(i, 1), cellOf(i, 2));
        ++start[cellOfGrain[i] + 1];
    }
    for (size_t c = 1; c < start.size(); ++c)
    {
        start[c] += start[c - 1];
    }
    std::vector<label> order(n), fill(start.begin(), start.end() - 1);
    for (label i = 0; i < n; ++i)
    {
        order[fill[cellOfGrain[i]]++] = i;
    }

    label worstI = -1, worstJ = -1, count = 0, capsulePairs = 0;
    scalar worst = 0;
    for (label i = 0; i < n; ++i)
    {
        const label c[3] = {cellOf(i, 0), cellOf(i, 1), cellOf(i, 2)};
        // Neighbouring cells, each once (a box of one or two cells wraps
        // onto itself)
        std::vector<label> visited;
        for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
        {
            const label cz = c[2] + dz;
            if (cz < 0 || cz >= cells[2])
            {
                continue;
            }
            const label cx = (c[0] + dx + cells[0]) % cells[0];
            const label cy = (c[1] + dy + cells[1]) % cells[1];
            const label cell = indexOf(cx, cy, cz);
            if (std::find(visited.begin(), visited.end(), cell) != visited.end())
            {
                continue;
            }
            visited.push_back(cell);

            for (label k = start[cell]; k < start[cell + 1]; ++k)
            {
                const label j = order[k];
                if (j <= i)
                {
                    continue;
                }
                scalar distance2 = 0;
                for (int d = 0; d < 3; ++d)
                {
                    scalar s = grains_[j].position[d] - grains_[i].position[d];
                    if (d < 2)
                    {
                        s -= length[d]*std::round(s/length[d]);
                    }
                    distance2 += s*s;
                }
                if
                (
                    bounding(i) > grains_[i].radius
                 || bounding(j) > grains_[j].radius
                )
                {
                    // A capsule: its bounding spheres overlap, the capsules
                    // themselves may not
                    const scalar reach = bounding(i) + bounding(j);
                    capsulePairs += distance2 < sqr(reach);
                    continue;
                }
                const scalar rI = grains_[i].radius, rJ = grains_[j].radius;
                const scalar overlap = rI + rJ - std::sqrt(distance2);
                const scalar fraction = overlap/min(rI, rJ);
                if (fraction > allowed)
                {
                    ++count;
                    if (fraction > worst)
                    {
                        worst = fraction;
                        worstI = i;
                        worstJ = j;
                    }
                }
            }
        }
    }

    if (capsulePairs)
    {
        WarningInFunction
            << path_ << ": " << capsulePairs << " pair(s) with a capsule lie"
            << " closer than their bounding spheres (radius r + h); their"
            << " overlap is not checked here (spheres only)" << endl;
    }

    if (count)
    {
        const scalar distance =
            grains_[worstI].radius + grains_[worstJ].radius
          - worst*min(grains_[worstI].radius, grains_[worstJ].radius);
        FatalIOErrorInFunction(demProperties)
            << path_ << ": " << count << " pair(s) of grains overlap by more"
            << " than maxInitialOverlap = " << num(allowed).c_str() << " of"
            << " the smaller radius. The worst: " << nl << "    "
            << describe(worstI).c_str() << nl << "    "
            << describe(worstJ).c_str() << nl << "    "
            << (distance <= SMALL*grains_[worstI].radius ? "coincident, " : "")
            << "overlap " << num(100*worst).c_str()
            << " % of the smaller radius" << nl
            << "Such an overlap stores elastic energy k delta^2/2 far above a"
            << " settled packing's; remove the duplicate or spread the grains"
            << " (bin/makeGrains), or raise maxInitialOverlap in "
            << demProperties.name() << nl << exit(FatalIOError);
    }
}


// ************************************************************************* //

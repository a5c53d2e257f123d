/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "grainStartState.H"
#include "grainsFile.H"
#include "error.H"

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
    path_(path),
    demProperties_(demProperties),
    maxOverlap_
    (
        demProperties.getOrDefault<scalar>("maxInitialOverlap", 0.05)
    )
{
    if (!(maxOverlap_ >= 0))
    {
        FatalIOErrorInFunction(demProperties)
            << "Entry 'maxInitialOverlap' in " << demProperties.name()
            << " must be >= 0 (a fraction of the smaller radius), found "
            << maxOverlap_ << nl << exit(FatalIOError);
    }
    grains_ = grainsFile(path).read(lines_);
    checkPlacement(demProperties, mesh, walls);
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

        // Periodic sides: [lo, hi), wrapped if asked; closed sides (walls):
        // inside the mesh, never wrapped
        for (int d = 0; d < 2; ++d)
        {
            const scalar lo = mesh.origin[d];
            const scalar length = mesh.n[d]*mesh.spacing[d];
            if (x[d] >= lo && x[d] < lo + length)
            {
                continue;
            }
            if (!mesh.periodic[d])
            {
                FatalErrorInFunction
                    << describe(i).c_str() << " of " << path_ << " lies"
                    << " outside the mesh, " << char('x' + d) << " in ["
                    << num(lo).c_str() << ", " << num(lo + length).c_str()
                    << "]" << nl << exit(FatalError);
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
            const scalar xw = x[w.axis];
            if (lower ? xw < w.position : xw > w.position)
            {
                FatalIOErrorInFunction(demProperties)
                    << describe(i).c_str() << " of " << path_ << " lies "
                    << (lower ? "below the lower" : "above the upper")
                    << " wall at " << char('x' + w.axis) << " = "
                    << num(w.position).c_str() << " ("
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


void Foam::grainStartState::checkOverlaps(const dem::System& system) const
{
    if (system.grainCount() != grains_.size())
    {
        FatalErrorInFunction
            << "The overlap check needs exactly the grains of " << path_
            << " in the DEM system (" << label(grains_.size()) << "), found "
            << label(system.grainCount()) << nl << exit(FatalError);
    }

    // The real shapes (capsules by their cores' closest points), through the
    // library's own neighbour search
    const dem::GrainOverlap worst(system.largestOverlap());
    if (worst.first < 0 || !(worst.relativeOverlap > maxOverlap_))
    {
        return;
    }

    const dem::GrainInit& a = grains_[worst.first];
    const dem::GrainInit& b = grains_[worst.second];
    // Overlap r_a + r_b: the centres (spheres) or cores (capsules) meet
    const bool coincident =
        worst.overlap >= a.radius + b.radius - SMALL*min(a.radius, b.radius);
    FatalIOErrorInFunction(demProperties_)
        << path_ << ": grains overlap by more than maxInitialOverlap = "
        << num(maxOverlap_).c_str() << " of the smaller radius. The worst:"
        << nl << "    " << describe(worst.first).c_str() << nl << "    "
        << describe(worst.second).c_str() << nl << "    "
        << (coincident ? "coincident, " : "")
        << "overlap " << num(100*worst.relativeOverlap).c_str()
        << " % of the smaller radius" << nl
        << "Such an overlap stores elastic energy k delta^2/2 far above a"
        << " settled packing's; remove the duplicate or spread the grains"
        << " (bin/makeGrains), or raise maxInitialOverlap in "
        << demProperties_.name() << nl << exit(FatalIOError);
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "grainsFile.H"
#include "atomicFile.H"
#include "error.H"

#include <cmath>
#include <fstream>
#include <sstream>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Whether a line holds a grain (not blank, not a comment)
bool isGrainLine(const std::string& line)
{
    const auto first = line.find_first_not_of(" \t\r");
    return first != std::string::npos && line[first] != '#';
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::grainsFile::grainsFile(const fileName& path)
:
    path_(path)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

std::array<double, 4> Foam::grainsFile::orientation
(
    const double w,
    const double x,
    const double y,
    const double z,
    const label lineNo,
    const std::string& line
) const
{
    // Written by hand with four or five digits a unit quaternion is off by
    // about 1e-4; a larger error is a slip (a wrong column), not round-off
    const double norm = std::sqrt(w*w + x*x + y*y + z*z);
    if (!(std::abs(norm - 1) <= quaternionTolerance))
    {
        FatalErrorInFunction
            << path_ << " line " << lineNo << ": the orientation 'qw qx qy"
            << " qz' (columns 6 to 9) must be a unit quaternion (|q| within "
            << quaternionTolerance << " of 1), |q| = " << norm << " in '"
            << line << "'" << nl << exit(FatalError);
    }
    return {w/norm, x/norm, y/norm, z/norm};
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::grainsFile::found() const
{
    return std::ifstream(path_).good();
}


std::vector<dem::GrainInit> Foam::grainsFile::read
(
    std::vector<label>& lines
) const
{
    std::ifstream is(path_);
    if (!is.good())
    {
        FatalErrorInFunction
            << "Cannot read the grains: neither " << path_ << " (x y z r per"
            << " line) nor a restart file " << path_.path()/"demState"
            << " exists" << nl << exit(FatalError);
    }

    std::vector<dem::GrainInit> grains;
    lines.clear();
    std::string line;
    label lineNo = 0;
    while (std::getline(is, line))
    {
        ++lineNo;
        if (!isGrainLine(line))
        {
            continue;
        }
        // Sphere: x y z r; capsule: x y z r h qw qx qy qz; either
        // optionally followed by the velocity vx vy vz
        std::istringstream ls(line);
        std::vector<double> v;
        double value;
        while (ls >> value)
        {
            v.push_back(value);
        }
        const bool capsule = v.size() == 9 || v.size() == 12;
        if
        (
            !ls.eof()
         || (v.size() != 4 && v.size() != 7 && !capsule)
         || !(v[3] > 0 && std::isfinite(v[3]))
        )
        {
            FatalErrorInFunction
                << path_ << " line " << lineNo << ": expected 'x y z r' (a"
                << " sphere) or 'x y z r h qw qx qy qz' (a capsule: core"
                << " half-length h, orientation quaternion), either"
                << " optionally followed by 'vx vy vz', with r > 0; found '"
                << line << "'" << nl << exit(FatalError);
        }
        dem::GrainInit g;
        g.position = {v[0], v[1], v[2]};
        g.radius = v[3];
        if (capsule)
        {
            g.coreHalfLength = v[4];
            g.orientation = orientation(v[5], v[6], v[7], v[8], lineNo, line);
            if (!(g.coreHalfLength >= 0 && std::isfinite(g.coreHalfLength)))
            {
                FatalErrorInFunction
                    << path_ << " line " << lineNo << ": the core half-length"
                    << " h (5th column) must be >= 0, found '" << line << "'"
                    << nl << exit(FatalError);
            }
        }
        if (v.size() == 7 || v.size() == 12)
        {
            const size_t k = v.size() - 3;
            g.velocity = {v[k], v[k + 1], v[k + 2]};
        }
        grains.push_back(g);
        lines.push_back(lineNo);
    }

    if (grains.empty())
    {
        FatalErrorInFunction
            << path_ << " holds no grains" << nl << exit(FatalError);
    }
    return grains;
}


Foam::label Foam::grainsFile::count() const
{
    std::ifstream is(path_);
    label n = 0;
    std::string line;
    while (std::getline(is, line))
    {
        n += isGrainLine(line);
    }
    return n;
}


void Foam::grainsFile::write(const dem::GrainData& g) const
{
    const atomicFile file(path_);
    {
        std::ofstream os(file.tmpPath());
        os.precision(17);
        os  << "# darcyDem grains, one per line: a sphere 'x y z r' [m], a"
            << " capsule 'x y z r h qw qx qy qz' (h: core half-length [m],"
            << " q: orientation, body z axis = capsule axis); written at a"
            << " write time, the demState of that time holds the complete"
            << " state (beside it, or each rank's part in"
            << " processor<N>/<time> of a decomposed run)\n";
        for (size_t i = 0; i < g.radius.size(); ++i)
        {
            os  << g.position[3*i] << ' ' << g.position[3*i + 1] << ' '
                << g.position[3*i + 2] << ' ' << g.radius[i];
            // A sphere's line stays as it always was
            const double h =
                g.coreHalfLength.empty() ? 0 : g.coreHalfLength[i];
            if (h > 0)
            {
                os  << ' ' << h;
                for (int k = 0; k < 4; ++k)
                {
                    os  << ' ' << g.orientation[4*i + k];
                }
            }
            os  << '\n';
        }
        os.close();
        if (!os)
        {
            FatalErrorInFunction
                << "Cannot write " << file.tmpPath() << nl << exit(FatalError);
        }
    }
    file.commit();
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "grainsFile.H"
#include "atomicFile.H"
#include "error.H"

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
        // x y z r, optionally followed by the velocity vx vy vz
        std::istringstream ls(line);
        std::vector<double> v;
        double value;
        while (ls >> value)
        {
            v.push_back(value);
        }
        if (!ls.eof() || (v.size() != 4 && v.size() != 7) || !(v[3] > 0))
        {
            FatalErrorInFunction
                << path_ << " line " << lineNo << ": expected 'x y z r' or"
                << " 'x y z r vx vy vz' with r > 0, found '" << line << "'"
                << nl << exit(FatalError);
        }
        dem::GrainInit g;
        g.position = {v[0], v[1], v[2]};
        g.radius = v[3];
        if (v.size() == 7)
        {
            g.velocity = {v[4], v[5], v[6]};
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
        os  << "# darcyDem grains: x y z r [m], one grain per line (written"
            << " at a write time; demState beside it holds the complete"
            << " state)\n";
        for (size_t i = 0; i < g.radius.size(); ++i)
        {
            os  << g.position[3*i] << ' ' << g.position[3*i + 1] << ' '
                << g.position[3*i + 2] << ' ' << g.radius[i] << '\n';
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

/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "atomicFile.H"
#include "error.H"

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::atomicFile::atomicFile(const fileName& path)
:
    path_(path),
    tmpPath_(path + ".tmp")
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::atomicFile::commit() const
{
    if (std::rename(tmpPath_.c_str(), path_.c_str()) != 0)
    {
        FatalErrorInFunction
            << "Cannot rename " << tmpPath_ << " to " << path_ << ": "
            << std::strerror(errno) << nl << exit(FatalError);
    }
}


void Foam::atomicFile::killPoint(const char* name)
{
    const char* request = std::getenv("DARCYDEM_TEST_KILL_AT");
    if (!request)
    {
        return;
    }

    // "name" or "name@n"
    const std::string value(request);
    const auto at = value.find('@');
    if (value.substr(0, at) != name)
    {
        return;
    }
    const int wanted = at == std::string::npos ? 1 : std::atoi(value.c_str() + at + 1);

    static std::map<std::string, int> reached;
    if (++reached[name] == wanted)
    {
        std::fprintf
        (
            stderr, "DARCYDEM_TEST_KILL_AT: SIGKILL at %s (%d)\n", name, wanted
        );
        std::fflush(stderr);
        std::raise(SIGKILL);
    }
}


// ************************************************************************* //

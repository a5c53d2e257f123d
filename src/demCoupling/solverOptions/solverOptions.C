/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "solverOptions.H"
#include "argList.H"
#include "dem/Mpi.h"
#include "error.H"

#include <algorithm>
#include <cstdlib>
#include <cstring>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const char* const Foam::solverOptions::processCountVariables[] =
{
    "OMPI_COMM_WORLD_SIZE",     // Open MPI
    "PMI_SIZE",                 // MPICH (hydra), Intel MPI
    "MV2_COMM_WORLD_SIZE",      // MVAPICH
    nullptr
};


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::solverOptions::given(int argc, char* argv[], const char* name)
{
    for (int argi = 1; argi < argc; ++argi)
    {
        // argList takes '--name' as '-name'
        const char* arg = argv[argi];
        if (arg[0] == '-' && arg[1] == '-')
        {
            ++arg;
        }
        if (arg[0] == '-' && std::strcmp(arg + 1, name) == 0)
        {
            return true;
        }
    }
    return false;
}


int Foam::solverOptions::mpiProcesses()
{
    int n = 1;
    for (const char* const* var = processCountVariables; *var; ++var)
    {
        const char* value = std::getenv(*var);
        if (value)
        {
            n = std::max(n, std::atoi(value));
        }
    }
    return n;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::solverOptions::check(int argc, char* argv[])
{
    const word solver(argc > 0 ? fileName(argv[0]).name() : word("solver"));
    const bool parallel = given(argc, argv, "parallel");

    if (parallel && !dem::mpiBuild())
    {
        FatalErrorInFunction
            << "-parallel: the DEM library of " << solver << " was built"
            << " without MPI, so its grains cannot be split over ranks."
            << nl << "Install libopenmpi-dev and rebuild (./Allwmake), or"
            << " run without mpirun and -parallel on the undecomposed case"
            << nl << exit(FatalError);
    }

    const int n = mpiProcesses();
    if (n > 1 && !parallel)
    {
        FatalErrorInFunction
            << "Started by mpirun with " << n << " processes but without"
            << " -parallel: each process would run the whole case and"
            << " overwrite the others' files." << nl
            << "Decompose the case (decomposePar, system/decomposeParDict:"
            << " method simple or hierarchical) and run 'mpirun -np " << n
            << " " << solver << " -parallel', or run '" << solver
            << "' alone on the undecomposed case" << nl << exit(FatalError);
    }

    if (given(argc, argv, "dry-run") || given(argc, argv, "dry-run-write"))
    {
        FatalErrorInFunction
            << "-dry-run is not supported by " << solver << ": OpenFOAM's"
            << " dry run replaces the mesh by a one-dimensional column,"
            << " which the grains' box cannot take." << nl
            << "To check a case, run it with endTime equal to startTime in"
            << " system/controlDict: the dictionaries, the mesh and the"
            << " grains are read and checked, and no step is taken." << nl
            << exit(FatalError);
    }
}


// ************************************************************************* //

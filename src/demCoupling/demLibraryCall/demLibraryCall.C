/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "demLibraryCall.H"

#include <cstdlib>

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::demLibraryFailed(const string& message, const string& context)
{
    FatalErrorInFunction
        << message.c_str() << nl << "(" << context.c_str() << ")" << nl
        << exit(FatalError);

    // exit(FatalError) does not return; this keeps [[noreturn]] honest
    // should it ever throw instead (FatalError.throwExceptions())
    std::abort();
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "staticPorosity.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace solidPhases
{
    defineTypeNameAndDebug(staticPorosity, 0);
    addToRunTimeSelectionTable(solidPhase, staticPorosity, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::solidPhases::staticPorosity::staticPorosity
(
    const fvMesh& mesh,
    const dictionary& dict
)
:
    solidPhase(mesh, dict, wordList())
{
    if (!porosity_.typeHeaderOk<volScalarField>(true))
    {
        FatalIOErrorInFunction(dict)
            << "solidPhase type " << type() << " needs the field file "
            << porosity_.objectPath() << nl
            << "(porosity in (0, 1) per cell), which was not found" << nl
            << exit(FatalIOError);
    }

    checkPorosity();
}


// ************************************************************************* //

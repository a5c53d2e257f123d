/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "pressureGradient.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fluidForceModels
{
    defineTypeNameAndDebug(pressureGradient, 0);
    addToRunTimeSelectionTable(fluidForceModel, pressureGradient, dictionary);
}
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::volVectorField>
Foam::fluidForceModels::pressureGradient::forceDensity
(
    const volVectorField& gradp,
    const volScalarField&
) const
{
    return tmp<volVectorField>::New("fluidForceDensity", -gradp);
}


// ************************************************************************* //

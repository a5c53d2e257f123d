/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "noFluidForce.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fluidForceModels
{
    defineTypeNameAndDebug(noFluidForce, 0);
    addToRunTimeSelectionTable(fluidForceModel, noFluidForce, dictionary);
}
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::volVectorField>
Foam::fluidForceModels::noFluidForce::forceDensity
(
    const volVectorField& gradp,
    const volScalarField&
) const
{
    return volVectorField::New
    (
        "fluidForceDensity",
        gradp.mesh(),
        dimensionedVector(gradp.dimensions(), Zero)
    );
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "darcy.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fluidForceModels
{
    defineTypeNameAndDebug(darcy, 0);
    addToRunTimeSelectionTable(fluidForceModel, darcy, dictionary);
}
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::volVectorField>
Foam::fluidForceModels::darcy::forceDensity
(
    const volVectorField& gradp,
    const volScalarField& porosity
) const
{
    return tmp<volVectorField>::New("fluidForceDensity", -gradp/(1 - porosity));
}


// ************************************************************************* //

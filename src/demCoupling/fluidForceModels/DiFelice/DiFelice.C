/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "DiFelice.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fluidForceModels
{
    defineTypeNameAndDebug(DiFelice, 0);
    addToRunTimeSelectionTable(fluidForceModel, DiFelice, dictionary);
}
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::fluidForceModels::DiFelice::betaGrain
(
    const scalar phi,
    const scalar w,
    const scalar rho,
    const scalar mu,
    const scalar d
) const
{
    // C_d w, finite as w -> 0: (0.63 sqrt(Re) + 4.8)^2/Re w with w/Re =
    // mu/(phi rho d)
    const scalar Re = phi*rho*w*d/mu;
    const scalar CdW = sqr(0.63*sqrt(Re) + 4.8)*mu/(phi*rho*d);
    const scalar chi =
        Re > 0 ? 3.7 - 0.65*exp(-0.5*sqr(1.5 - log10(Re))) : 3.7;
    return 0.75*CdW*rho*pow(phi, 2 - chi)/d;
}


// ************************************************************************* //

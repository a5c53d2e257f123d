/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "ErgunWenYu.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fluidForceModels
{
    defineTypeNameAndDebug(ErgunWenYu, 0);
    addToRunTimeSelectionTable(fluidForceModel, ErgunWenYu, dictionary);
}
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::fluidForceModels::ErgunWenYu::betaGrain
(
    const scalar phi,
    const scalar w,
    const scalar rho,
    const scalar mu,
    const scalar d
) const
{
    if (phi < 0.8)
    {
        return 150*(1 - phi)*mu/(phi*sqr(d)) + 1.75*rho*w/d;
    }

    // C_d w, written so that it stays finite as w -> 0: 24/Re w = 24
    // mu/(phi rho d)
    const scalar Re = phi*rho*w*d/mu;
    const scalar CdW =
        Re < 1000
      ? 24*mu/(phi*rho*d)*(1 + 0.15*pow(Re, 0.687))
      : 0.44*w;
    return 0.75*CdW*rho*pow(phi, -1.65)/d;
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "Beetstra.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fluidForceModels
{
    defineTypeNameAndDebug(Beetstra, 0);
    addToRunTimeSelectionTable(fluidForceModel, Beetstra, dictionary);
}
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::fluidForceModels::Beetstra::betaGrain
(
    const scalar phi,
    const scalar w,
    const scalar rho,
    const scalar mu,
    const scalar d
) const
{
    const scalar s = 1 - phi;
    const scalar Re = phi*rho*w*d/mu;

    // The inertial term with numerator and denominator times Re^a, a = (1 +
    // 4 s)/2 > 0.343, so that it vanishes smoothly as Re -> 0
    const scalar a = 0.5*(1 + 4*s);
    const scalar Ra = pow(Re, a);
    const scalar inertial =
        0.413*Re/(24*sqr(phi))
       *((1/phi + 3*phi*s)*Ra + 8.4*pow(Re, a - 0.343))
       /(Ra + pow(10.0, 3*s));
    const scalar F = 10*s/sqr(phi) + sqr(phi)*(1 + 1.5*sqrt(s)) + inertial;
    return 18*mu*phi*F/sqr(d);
}


// ************************************************************************* //

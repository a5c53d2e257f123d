/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "uniformPorosity.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace solidPhases
{
    defineTypeNameAndDebug(uniformPorosity, 0);
    addToRunTimeSelectionTable(solidPhase, uniformPorosity, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::solidPhases::uniformPorosity::porosityAt
(
    const scalar t
) const
{
    const scalar phi = history_->value(t);

    if (!(phi > 0 && phi < 1))
    {
        FatalIOErrorInFunction(dict_)
            << "Entry 'porosity' in " << dict_.name() << " gives "
            << phi << " at time " << t << "; porosity must lie in (0, 1)"
            << nl << exit(FatalIOError);
    }

    return phi;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::solidPhases::uniformPorosity::uniformPorosity
(
    const fvMesh& mesh,
    const dictionary& dict
)
:
    // porosity: a Function1 of time (porosityCoeffs: its coefficients in
    // the older form)
    solidPhase(mesh, dict, {"porosity", "porosityCoeffs"}),
    history_(Function1<scalar>::New("porosity", dict))
{
    porosity_ == dimensionedScalar("porosity", dimless, porosityAt(mesh.time().value()));
    Us_ == dimensionedVector("Us", dimVelocity, Zero);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::solidPhases::uniformPorosity::evolve()
{
    const scalar t = mesh_.time().value();
    const scalar dt = mesh_.time().deltaTValue();

    porosity_ == dimensionedScalar("porosity", dimless, porosityAt(t));
    porosityRate_ == dimensionedScalar
    (
        "porosityRate",
        dimless/dimTime,
        (porosityAt(t + dt) - porosityAt(t - dt))/(2*dt)
    );
}


// ************************************************************************* //

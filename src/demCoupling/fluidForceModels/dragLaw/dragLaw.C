/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "dragLaw.H"
#include "inputChecks.H"
#include "zeroGradientFvPatchFields.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::wordList Foam::fluidForceModels::dragLaw::entryNames({"diameter"});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fluidForceModels::dragLaw::dragLaw
(
    const dictionary& dict,
    const Pair<scalar>& porosityRange,
    const Pair<scalar>& reynoldsRange
)
:
    fluidForceModel(dict, entryNames),
    diameter_
    (
        dict.found("diameter") ? inputChecks::getPositive(dict, "diameter") : 0
    ),
    porosityRange_(porosityRange),
    reynoldsRange_(reynoldsRange),
    porosityReported_(false),
    reynoldsReported_(false)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::volVectorField>
Foam::fluidForceModels::dragLaw::forceDensity
(
    const volVectorField& gradp,
    const volScalarField&
) const
{
    return tmp<volVectorField>::New("fluidForceDensity", -gradp);
}


Foam::tmp<Foam::volScalarField>
Foam::fluidForceModels::dragLaw::dragCoefficient
(
    const volScalarField& porosity,
    const volVectorField& slip,
    const scalar porosityMax,
    const scalar rho,
    const scalar mu,
    const scalar d
) const
{
    const fvMesh& mesh = porosity.mesh();
    tmp<volScalarField> tBeta
    (
        volScalarField::New
        (
            "dragCoefficient",
            mesh,
            dimensionedScalar(dimDensity/dimTime, Zero),
            zeroGradientFvPatchScalarField::typeName
        )
    );
    scalarField& beta = tBeta.ref().primitiveFieldRef();
    const Pair<scalar>& phiRange = porosityRange_;
    const Pair<scalar>& reRange = reynoldsRange_;

    forAll(beta, celli)
    {
        const scalar phi = porosity[celli];
        const scalar w = mag(slip[celli]);
        beta[celli] = betaGrain(phi, w, rho, mu, d);

        if (phi >= porosityMax)
        {
            continue; // no grains: beta multiplies nothing
        }
        const scalar Re = phi*rho*w*d/mu;
        if
        (
            !porosityReported_
         && (phi < phiRange.first() || phi > phiRange.second())
        )
        {
            porosityReported_ = true;
            Info<< "Drag law " << type() << ": porosity "
                << inputChecks::shortForm(phi).c_str() << " in cell " << celli
                << " at t = " << mesh.time().timeName()
                << " is outside the law's range ["
                << inputChecks::shortForm(phiRange.first()).c_str() << ", "
                << inputChecks::shortForm(phiRange.second()).c_str()
                << "] (doc/EQUATIONS.md section 11); reported once" << endl;
        }
        if
        (
            !reynoldsReported_
         && ((Re > 0 && Re < reRange.first()) || Re > reRange.second())
        )
        {
            reynoldsReported_ = true;
            Info<< "Drag law " << type() << ": Reynolds number "
                << inputChecks::shortForm(Re).c_str() << " in cell " << celli
                << " at t = " << mesh.time().timeName()
                << " is outside the law's range ["
                << inputChecks::shortForm(reRange.first()).c_str() << ", "
                << inputChecks::shortForm(reRange.second()).c_str()
                << "] (doc/EQUATIONS.md section 11); reported once" << endl;
        }
    }
    tBeta.ref().correctBoundaryConditions();
    return tBeta;
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "darcyFluid.H"
#include "inputChecks.H"
#include "fvMesh.H"
#include "Time.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- The entries of darcyProperties: the fluid's, read here, and the
//- sub-dictionaries of the models (permeabilityModel::New,
//- solidPhase::New, which check their own entries)
const Foam::wordList darcyPropertiesNames
({
    "mu", "beta", "rho", "permeability", "solidPhase"
});

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::darcyFluid::darcyFluid(const fvMesh& mesh)
:
    IOdictionary
    (
        IOobject
        (
            "darcyProperties",
            mesh.time().constant(),
            mesh,
            IOobject::MUST_READ_IF_MODIFIED,
            IOobject::NO_WRITE
        )
    ),
    mu_
    (
        inputChecks::getPositive
        (
            inputChecks::checkKnownEntries(*this, darcyPropertiesNames),
            "mu",
            dimDynamicViscosity
        )
    ),
    beta_(inputChecks::getPositive(*this, "beta", dimless/dimPressure)),
    rho_(inputChecks::getNonNegative(*this, "rho", dimDensity))
{
    Info<< "Pore fluid: mu = " << mu_.value() << " Pa s, beta = "
        << beta_.value() << " 1/Pa, rho = " << rho_.value() << " kg/m^3"
        << endl;
}


// ************************************************************************* //

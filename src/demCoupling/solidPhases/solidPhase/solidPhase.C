/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "solidPhase.H"
#include "inputChecks.H"
#include "latestCompleteTime.H"
#include "zeroGradientFvPatchFields.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(solidPhase, 0);
    defineRunTimeSelectionTable(solidPhase, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::solidPhase::solidPhase
(
    const fvMesh& mesh,
    const dictionary& dict,
    const wordList& entryNames
)
:
    mesh_(mesh),
    dict_(inputChecks::checkModelEntries(dict, entryNames)),
    porosity_
    (
        IOobject
        (
            "porosity",
            mesh.time().timeName(),
            mesh,
            IOobject::READ_IF_PRESENT,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedScalar("porosity", dimless, 1),
        zeroGradientFvPatchScalarField::typeName
    ),
    porosityRate_
    (
        IOobject
        (
            "ddt(porosity)",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedScalar("porosityRate", dimless/dimTime, Zero),
        zeroGradientFvPatchScalarField::typeName
    ),
    Us_
    (
        IOobject
        (
            "Us",
            mesh.time().timeName(),
            mesh,
            IOobject::READ_IF_PRESENT,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedVector("Us", dimVelocity, Zero),
        zeroGradientFvPatchVectorField::typeName
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::solidPhase::write(Time& runTime) const
{
    latestCompleteTime::write(runTime);
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

void Foam::solidPhase::checkPorosity() const
{
    const scalarField& phi = porosity_.primitiveField();

    forAll(phi, celli)
    {
        if (!(phi[celli] > 0 && phi[celli] < 1))
        {
            FatalErrorInFunction
                << "Porosity " << phi[celli] << " in cell " << celli
                << " at " << mesh_.C()[celli] << " (field "
                << porosity_.objectPath() << ", solidPhase type "
                << type() << ") is outside (0, 1)" << nl
                << exit(FatalError);
        }
    }
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "demGrains.H"
#include "inputChecks.H"
#include "zeroGradientFvPatchFields.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace solidPhases
{
    defineTypeNameAndDebug(demGrains, 0);
    addToRunTimeSelectionTable(solidPhase, demGrains, dictionary);
}
}

const Foam::Enum<Foam::solidPhases::demGrains::porosityRateForm>
Foam::solidPhases::demGrains::porosityRateFormNames
({
    { porosityRateForm::predictedPosition, "predictedPosition" },
    { porosityRateForm::exactDifference, "exactDifference" },
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::solidPhases::demGrains::deposit(const scalar dt)
{
    cloud_.deposit(dt, porosity_, predictedPorosity_, Us_);

    const dimensionedScalar lo("porosityMin", dimless, porosityMin_);
    const dimensionedScalar hi("porosityMax", dimless, porosityMax_);
    porosity_ = max(min(porosity_, hi), lo);
    predictedPorosity_ = max(min(predictedPorosity_, hi), lo);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::solidPhases::demGrains::demGrains
(
    const fvMesh& mesh,
    const dictionary& dict
)
:
    solidPhase(mesh, dict),
    cloud_(mesh),
    fluidForce_(fluidForceModel::New(dict)),
    porosityMin_(inputChecks::getInOpenRange(dict, "porosityMin", 0, 1)),
    porosityMax_(inputChecks::getInOpenRange(dict, "porosityMax", 0, 1)),
    topPressure_(dict.get<scalar>("topPressure")),
    rateForm_
    (
        porosityRateFormNames.getOrDefault
        (
            "porosityRate",
            dict,
            porosityRateForm::predictedPosition
        )
    ),
    predictedPorosity_
    (
        IOobject
        (
            "predictedPorosity",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE
        ),
        mesh,
        dimensionedScalar("porosity", dimless, 1),
        zeroGradientFvPatchScalarField::typeName
    )
{
    if (porosityMin_ >= porosityMax_)
    {
        FatalIOErrorInFunction(dict)
            << "Entries 'porosityMin' (" << porosityMin_
            << ") and 'porosityMax' (" << porosityMax_ << ") in "
            << dict.name() << " must satisfy porosityMin < porosityMax" << nl
            << exit(FatalIOError);
    }

    Info<< "    porosity rate: " << porosityRateFormNames[rateForm_] << endl;

    // The grains of the start time define the porosity there (also on a
    // restart: the deposit is deterministic)
    deposit(mesh.time().deltaTValue());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::solidPhases::demGrains::evolve()
{
    const scalar dt = mesh_.time().deltaTValue();
    const volScalarField previous("porosityPrevious", porosity_);

    cloud_.evolve(dt);
    deposit(dt);

    if (rateForm_ == porosityRateForm::exactDifference)
    {
        porosityRate_ = (porosity_ - previous)/mesh_.time().deltaT();
    }
    else
    {
        porosityRate_ =
            (predictedPorosity_ - previous)/(2*mesh_.time().deltaT());
    }
}


void Foam::solidPhases::demGrains::setPressureGradient
(
    const volVectorField& gradp,
    const dimensionedScalar& rhoFluid
)
{
    if (fluidForce_->acts())
    {
        cloud_.setFluidForce
        (
            fluidForce_->forceDensity(gradp, porosity_)(),
            rhoFluid.value()
        );
    }
    else
    {
        cloud_.clearFluidForce();
    }
}


void Foam::solidPhases::demGrains::fixedPressureCells
(
    labelList& cells,
    scalar& value
) const
{
    cells.clear();
    value = topPressure_;
    if (!cloud_.hasTopWall())
    {
        return;
    }

    const meshGrid& grid = cloud_.grid();
    const dem::UniformGrid& g = grid.grid();
    const label kWall = label
    (
        std::floor((cloud_.topWallPosition() - g.origin[2])/g.spacing[2])
    );

    DynamicList<label> fixed;
    for (label gi = 0; gi < grid.size(); ++gi)
    {
        if (grid.layerOf(gi) >= kWall)
        {
            fixed.append(grid.cellOf(gi));
        }
    }
    cells.transfer(fixed);
}


// ************************************************************************* //

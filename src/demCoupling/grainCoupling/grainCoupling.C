/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "grainCoupling.H"
#include "dragLaw.H"
#include "inputChecks.H"
#include "latestCompleteTime.H"
#include "zeroGradientFvPatchFields.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::grainCoupling::porosityRateForm>
Foam::grainCoupling::porosityRateFormNames
({
    { porosityRateForm::predictedPosition, "predictedPosition" },
    { porosityRateForm::exactDifference, "exactDifference" },
});


const Foam::Enum<Foam::grainCoupling::wallDeposit>
Foam::grainCoupling::wallDepositNames
({
    { wallDeposit::inside, "inside" },
    { wallDeposit::across, "across" },
});


const Foam::wordList Foam::grainCoupling::entryNames
({
    "porosityMin", "porosityMax", "topPressure", "porosityRate",
    "depositAtWalls", "fluidForce"
});


const Foam::wordList Foam::grainCoupling::momentumEntryNames
({
    "porosityMin", "porosityMax", "porosityRate", "depositAtWalls",
    "fluidForce"
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::grainCoupling::stepGrains()
{
    stepTimers::scope timed(timers_, stepTimers::demSteps);
    const label nSub = cloud_.evolve(mesh_.time().deltaTValue());
    timers_.countStep(double(nSub)*cloud_.system().grainCount());
}


void Foam::grainCoupling::deposit()
{
    cloud_.deposit
    (
        mesh_.time().deltaTValue(), porosity_, predictedPorosity_, Us_
    );

    // The pressure equation's clamp; a dry run writes the deposit as it is
    if (coupled())
    {
        const dimensionedScalar lo("porosityMin", dimless, porosityMin_);
        const dimensionedScalar hi("porosityMax", dimless, porosityMax_);
        porosity_ = max(min(porosity_, hi), lo);
        predictedPorosity_ = max(min(predictedPorosity_, hi), lo);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::grainCoupling::grainCoupling
(
    const fvMesh& mesh,
    const dictionary& dict,
    const fluidKind kind,
    volScalarField& porosity,
    volScalarField& porosityRate,
    volVectorField& Us
)
:
    mesh_(mesh),
    kind_(kind),
    cloud_(mesh),
    fluidForce_
    (
        coupled()
      ? fluidForceModel::New
        (
            kind == fluidKind::momentum
          ? inputChecks::checkKnownEntries(dict, momentumEntryNames)
          : dict,
            kind == fluidKind::momentum
        )
      : nullptr
    ),
    porosityMin_
    (
        coupled() ? inputChecks::getInOpenRange(dict, "porosityMin", 0, 1) : 0
    ),
    porosityMax_
    (
        coupled() ? inputChecks::getInOpenRange(dict, "porosityMax", 0, 1) : 1
    ),
    topPressure_
    (
        kind == fluidKind::darcy ? dict.get<scalar>("topPressure") : 0
    ),
    rateForm_
    (
        coupled()
      ? inputChecks::getChoiceOrDefault
        (
            dict,
            "porosityRate",
            porosityRateFormNames,
            porosityRateForm::predictedPosition
        )
      : porosityRateForm::exactDifference
    ),
    porosity_(porosity),
    porosityRate_(porosityRate),
    Us_(Us),
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
    ),
    dragCoefficient_
    (
        IOobject
        (
            "dragCoefficient",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            kind == fluidKind::momentum
          ? IOobject::AUTO_WRITE
          : IOobject::NO_WRITE
        ),
        mesh,
        dimensionedScalar(dimDensity/dimTime, Zero),
        zeroGradientFvPatchScalarField::typeName
    ),
    dragDiameter_(0),
    timers_(stepTimers::New(mesh))
{
    if (kind_ == fluidKind::momentum)
    {
        dragDiameter_ =
            refCast<const fluidForceModels::dragLaw>(fluidForce_())
           .diameter(cloud_.meanDiameter());
    }

    if (coupled() && cloud_.deformingBox())
    {
        FatalIOErrorInFunction(cloud_.properties())
            << "Entry 'boxLengthRate' in " << cloud_.properties().name()
            << ": a deforming periodic box runs without a fluid only"
            << " (demFoam); the fluid's mesh keeps its box. Remove the entry"
            << " or set it to (0 0 0)" << nl << exit(FatalIOError);
    }

    if (coupled())
    {
        // Where the deposit may reach at walls: the grains' own setting
        const wallDeposit atWalls = inputChecks::getChoiceOrDefault
        (
            dict,
            "depositAtWalls",
            wallDepositNames,
            wallDeposit::inside
        );
        cloud_.keepDepositInsideWalls(atWalls == wallDeposit::inside);
        if (porosityMin_ >= porosityMax_)
        {
            FatalIOErrorInFunction(dict)
                << "Entries 'porosityMin' (" << porosityMin_
                << ") and 'porosityMax' (" << porosityMax_ << ") in "
                << dict.name() << " must satisfy porosityMin < porosityMax"
                << nl << exit(FatalIOError);
        }
        Info<< "    porosity rate: " << porosityRateFormNames[rateForm_]
            << nl << "    deposit at walls: " << wallDepositNames[atWalls]
            << endl;
    }

    // The grains of the start time define the porosity there (also on a
    // restart: the deposit is deterministic)
    deposit();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::grainCoupling::advance()
{
    const Time& runTime = mesh_.time();

    if (!coupled())
    {
        stepGrains();
        // Nothing reads the fields between writes
        if (runTime.writeTime())
        {
            stepTimers::scope timed(timers_, stepTimers::deposit);
            deposit();
        }
        return;
    }

    const volScalarField previous("porosityPrevious", porosity_);
    stepGrains();

    stepTimers::scope timed(timers_, stepTimers::deposit);
    deposit();
    if (rateForm_ == porosityRateForm::exactDifference)
    {
        porosityRate_ = (porosity_ - previous)/runTime.deltaT();
    }
    else
    {
        porosityRate_ = (predictedPorosity_ - previous)/(2*runTime.deltaT());
    }
}


void Foam::grainCoupling::setPressureGradient
(
    const volVectorField& gradp,
    const scalar rhoFluid
)
{
    stepTimers::scope timed(timers_, stepTimers::exchange);
    if (fluidForce_.valid() && fluidForce_->acts())
    {
        cloud_.setFluidForce
        (
            fluidForce_->forceDensity(gradp, porosity_)(),
            rhoFluid
        );
    }
    else
    {
        cloud_.clearFluidForce();
    }
}


void Foam::grainCoupling::setFlow
(
    const volVectorField& gradp,
    const volVectorField& U,
    const scalar rhoFluid,
    const scalar muFluid
)
{
    stepTimers::scope timed(timers_, stepTimers::exchange);
    const fluidForceModels::dragLaw& law =
        refCast<const fluidForceModels::dragLaw>(fluidForce_());
    dragCoefficient_ = law.dragCoefficient
    (
        porosity_,
        U - Us_,
        porosityMax_,
        rhoFluid,
        muFluid,
        dragDiameter_
    );
    cloud_.setFluidForce
    (
        law.forceDensity(gradp, porosity_)(),
        dragCoefficient_,
        U,
        rhoFluid
    );
}


Foam::vector Foam::grainCoupling::gravity() const
{
    return cloud_.gravity(mesh_.time().deltaTValue());
}


Foam::tmp<Foam::volVectorField> Foam::grainCoupling::reaction() const
{
    stepTimers::scope timed(timers_, stepTimers::exchange);
    tmp<volVectorField> tReaction
    (
        volVectorField::New
        (
            "grainReaction",
            mesh_,
            dimensionedVector(dimForce/dimVolume, Zero),
            zeroGradientFvPatchVectorField::typeName
        )
    );
    cloud_.depositReaction(tReaction.ref());
    return tReaction;
}


void Foam::grainCoupling::fixedPressureCells
(
    labelList& cells,
    scalar& value
) const
{
    cells.clear();
    value = topPressure_;
    if (!coupled() || !cloud_.hasTopWall())
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
        if (grid.layerOf(gi) >= kWall && grid.cellOf(gi) >= 0)
        {
            fixed.append(grid.cellOf(gi));
        }
    }
    cells.transfer(fixed);
}


void Foam::grainCoupling::write(Time& runTime) const
{
    // Last in the time: the grains' restart state
    latestCompleteTime::write(runTime, [this]{ cloud_.writeState(); });
}


// ************************************************************************* //

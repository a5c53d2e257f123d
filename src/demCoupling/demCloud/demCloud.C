/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "demCloud.H"
#include "demLibraryCall.H"
#include "Time.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(demCloud, 0);
}

const char* const Foam::demCloud::topWall0Key = "demCloud.topWallInitialPosition";
const char* const Foam::demCloud::displacement0Key = "demCloud.displacementAtStart";
const char* const Foam::demCloud::periodicBoxKey = "demCloud.periodicBox";


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demCloud::demCloud(const fvMesh& mesh)
:
    regIOobject
    (
        IOobject
        (
            "demCloud",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        )
    ),
    mesh_(mesh),
    properties_
    (
        IOobject
        (
            "demProperties",
            mesh.time().constant(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    ),
    bonds_(properties_),
    grid_(mesh),
    walls_(properties_, grid_.grid(), mesh.time().value()),
    system_(),
    topWall0_(0),
    asciiOutput_(false),
    surfaceOutput_(true),
    simStart_(mesh.time().value()),
    particleSteps_(0),
    stepSeconds_(0)
{
    Info<< "Reading grains (" << properties_.objectPath() << ")" << endl;

    if (properties_.found("output"))
    {
        const word format
        (
            properties_.subDict("output").getOrDefault<word>("format", "binary")
        );
        if (format != "binary" && format != "ascii")
        {
            FatalIOErrorInFunction(properties_)
                << "Entry 'output/format' in " << properties_.name()
                << " is '" << format << "'; valid: binary ascii" << nl
                << exit(FatalIOError);
        }
        asciiOutput_ = (format == "ascii");
    }
    // Surfaces cost about 2.4 kB per grain and write time: by default only for runs small
    // enough to look at grain by grain (1e5 capsules would write 236 MB per time).
    const label maxDefaultSurfaceGrains = 20000;
    const bool surfaceChoiceGiven =
        properties_.found("output")
     && properties_.subDict("output").found("capsuleSurfaces");
    if (surfaceChoiceGiven)
    {
        surfaceOutput_ =
            properties_.subDict("output").get<bool>("capsuleSurfaces");
    }

    const fileName statePath(mesh.time().timePath()/"demState");
    const bool fromState = isFile(statePath);
    demLibraryCall
    (
        "while setting up the grains of " + properties_.objectPath(),
        [&]
        {
            system_.reset(new dem::System(readParameters()));
            walls_.addTo(*system_);
            if (fromState)
            {
                startFromState(statePath);
            }
            else
            {
                addGrainsFromFile();
            }
            checkTimeStep();
            Info<< "    backend " << system_->backendName() << ", "
                << system_->threadCount() << " thread(s)" << endl;

            if (hasTopWall() && !fromState)
            {
                topWall0_ = system_->wall(walls_.top()).position;
            }
            if (displacement0_.empty())
            {
                displacement0_.assign(3*system_->grainCount(), 0.0);
            }
            if
            (
                !surfaceChoiceGiven
             && label(system_->grainCount()) > maxDefaultSurfaceGrains
            )
            {
                surfaceOutput_ = false;
                Info<< "    capsule surfaces (VTK/capsules_<time>.vtp) not written: "
                    << system_->grainCount() << " grains > "
                    << maxDefaultSurfaceGrains
                    << "; output { capsuleSurfaces yes; } writes them" << endl;
            }
        }
    );

    wallStart_ = std::chrono::steady_clock::now();
    lastReport_ = wallStart_;
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::demCloud::~demCloud()
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::demCloud::reportProgress()
{
    using clock = std::chrono::steady_clock;
    const auto now = clock::now();
    if (std::chrono::duration<double>(now - lastReport_).count() < 5)
    {
        return;
    }
    lastReport_ = now;

    const Time& runTime = mesh_.time();
    const scalar elapsed = std::chrono::duration<double>(now - wallStart_).count();
    const scalar done = runTime.value() - simStart_;
    const scalar total = runTime.endTime().value() - simStart_;
    const scalar left = done > 0 ? elapsed*(total - done)/done : 0;

    Info<< "Progress: t = " << runTime.timeName() << " s, "
        << label(100*(runTime.value()/runTime.endTime().value()))
        << " %, " << particleStepsPerSecond() << " particle-steps/s, "
        << "about " << label(left) << " s left" << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::demCloud::evolve(const scalar dtFluid)
{
    const scalar dt = system_->timeStep();
    const label nSub = label(std::round(dtFluid/dt));

    if (nSub < 1 || mag(nSub*dt - dtFluid) > 1e-9*dtFluid)
    {
        FatalErrorInFunction
            << "The fluid time step (deltaT " << dtFluid << " s in "
            << "system/controlDict) must be a whole multiple of the DEM time"
            << " step (timeStep " << dt << " s in "
            << properties_.objectPath() << ")" << nl << exit(FatalError);
    }

    const auto start = std::chrono::steady_clock::now();
    demLibraryCall
    (
        "at t = " + mesh_.time().timeName() + " s, grains of "
      + properties_.objectPath(),
        [&]
        {
            // Wall stresses and gravity held for the fluid step, at its
            // middle. The end time as its name reads: the value a restart
            // starts from, where the running sum of time steps differs in
            // the last bits, so time-dependent loads restart bit-identically
            const Time& runTime = mesh_.time();
            scalar t = runTime.value();
            readScalar(runTime.timeName(), t);
            walls_.update(*system_, t - 0.5*dtFluid);
            system_->step(nSub);
        }
    );
    stepSeconds_ += std::chrono::duration<double>
    (
        std::chrono::steady_clock::now() - start
    ).count();
    particleSteps_ += double(nSub)*system_->grainCount();

    reportProgress();
}


void Foam::demCloud::deposit
(
    const scalar dtFluid,
    volScalarField& porosity,
    volScalarField& predictedPorosity,
    volVectorField& Us
) const
{
    const label n = grid_.size();
    std::vector<double> phi(n), phiPred(n), u(3*n);

    demLibraryCall
    (
        "depositing the grains on the mesh",
        [&]
        {
            system_->deposit
            (
                grid_.grid(), dtFluid, phi.data(), phiPred.data(), u.data()
            );
        }
    );

    grid_.toMesh(phi, porosity.primitiveFieldRef());
    grid_.toMesh(phiPred, predictedPorosity.primitiveFieldRef());
    grid_.toMesh(u, Us.primitiveFieldRef());
    porosity.correctBoundaryConditions();
    predictedPorosity.correctBoundaryConditions();
    Us.correctBoundaryConditions();
}


void Foam::demCloud::setFluidForce
(
    const volVectorField& forceDensity,
    const scalar rhoFluid
)
{
    std::vector<double> f;
    grid_.toGrid(forceDensity.primitiveField(), f);
    dem::FluidFields fluid;
    fluid.forceDensity = f.data();
    fluid.buoyancyDensity = rhoFluid;
    demLibraryCall
    (
        "handing the fluid force to the grains",
        [&]{ system_->setFluid(grid_.grid(), fluid); }
    );
}


void Foam::demCloud::setFluidForce
(
    const volVectorField& forceDensity,
    const volScalarField& dragCoefficient,
    const volVectorField& fluidVelocity,
    const scalar rhoFluid
)
{
    std::vector<double> f, beta, u;
    grid_.toGrid(forceDensity.primitiveField(), f);
    grid_.toGrid(dragCoefficient.primitiveField(), beta);
    grid_.toGrid(fluidVelocity.primitiveField(), u);
    dem::FluidFields fluid;
    fluid.forceDensity = f.data();
    fluid.dragCoefficient = beta.data();
    fluid.velocity = u.data();
    fluid.buoyancyDensity = rhoFluid;
    demLibraryCall
    (
        "handing the fluid force with drag to the grains",
        [&]{ system_->setFluid(grid_.grid(), fluid); }
    );
}


void Foam::demCloud::depositReaction(volVectorField& reaction) const
{
    std::vector<double> r(3*grid_.size());
    demLibraryCall
    (
        "depositing the grains' reaction on the fluid",
        [&]{ system_->depositFluidReaction(grid_.grid(), r.data()); }
    );
    grid_.toMesh(r, reaction.primitiveFieldRef());
    reaction.correctBoundaryConditions();
}


void Foam::demCloud::clearFluidForce()
{
    demLibraryCall
    (
        "clearing the fluid force on the grains",
        [&]{ system_->clearFluid(); }
    );
}


dem::GrainData Foam::demCloud::libraryGrains() const
{
    return demLibraryCall
    (
        "reading the grains of " + properties_.objectPath(),
        [&]{ return system_->grains(); }
    );
}


dem::GrainData Foam::demCloud::grains() const
{
    dem::GrainData g = libraryGrains();
    for (size_t i = 0; i < g.displacement.size(); ++i)
    {
        g.displacement[i] -= displacement0_[i];
    }
    return g;
}


Foam::scalar Foam::demCloud::topWallPosition() const
{
    if (!hasTopWall())
    {
        return GREAT;
    }
    return demLibraryCall
    (
        "reading the top wall", [&]{ return system_->wall(walls_.top()); }
    ).position;
}


Foam::scalar Foam::demCloud::topWallStress() const
{
    if (!hasTopWall())
    {
        return 0;
    }
    const dem::WallSpec spec = demLibraryCall
    (
        "reading the top wall", [&]{ return system_->wall(walls_.top()); }
    ).spec;
    return spec.mode == dem::WallSpec::Mode::stress ? spec.normalStress : 0;
}


Foam::scalar Foam::demCloud::boxArea() const
{
    const dem::UniformGrid& g = grid_.grid();
    return g.n[0]*g.spacing[0]*g.n[1]*g.spacing[1];
}


Foam::scalar Foam::demCloud::meanDiameter() const
{
    const dem::GrainData g = libraryGrains();
    scalar sum = 0;
    for (const double r : g.radius)
    {
        sum += 2*r;
    }
    return g.radius.empty() ? 0 : sum/g.radius.size();
}


Foam::scalar Foam::demCloud::particleStepsPerSecond() const
{
    return stepSeconds_ > 0 ? particleSteps_/stepSeconds_ : 0;
}


// ************************************************************************* //

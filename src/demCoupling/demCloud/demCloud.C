/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "demCloud.H"
#include "demLibraryCall.H"
#include "demStart.H"
#include "Time.H"

#include <sstream>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(demCloud, 0);
}


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
    grid_(mesh),
    depositInsideWalls_(true),
    settings_(mesh, grid_.grid()),
    writer_(mesh.time(), settings_),
    system_(),
    topWall0_(0),
    simStart_(mesh.time().value()),
    particleSteps_(0),
    stepSeconds_(0)
{
    Info<< "Reading grains (" << settings_.dict().objectPath() << ")"
        << endl;

    demLibraryCall
    (
        "while setting up the grains of " + settings_.dict().objectPath(),
        [&]
        {
            // Decomposed: the grains' boxes are the mesh's parts (meshGrid)
            dem::Parameters p(settings_.parameters(mesh.time().value()));
            p.decomposition.ranks = grid_.rankBoxes();
            system_.reset(new dem::System(p));
            settings_.walls().addTo(*system_);
            const demStart start(mesh.time(), settings_, grid_.grid(), *system_);
            topWall0_ = start.topWall0();
            displacement0_ = start.displacement0();
            // The box deforms from the mesh's, from the start state's clock;
            // a restart at the same rate continues the motion the run left
            // (the written mesh is that box to round-off only)
            if (settings_.deformingBox())
            {
                const vector& rate = settings_.boxLengthRate();
                const std::vector<double>& m = start.boxMotion();
                if (m.size() == 5 && m[3] == rate.x() && m[4] == rate.y())
                {
                    system_->setBoxMotion({m[0], m[1]}, m[2], {m[3], m[4]});
                }
                else
                {
                    system_->setBoxLengthRate({rate.x(), rate.y()});
                }
                grid_.followBox(system_->boxUpper());
                Info<< "    periodic box: lengths change at " << rate
                    << " m/s from x " << grid_.grid().n[0]*grid_.grid().spacing[0]
                    << " m, y " << grid_.grid().n[1]*grid_.grid().spacing[1]
                    << " m" << endl;
            }
            settings_.checkTimeStep(*system_);
            Info<< "    backend " << system_->backendName() << ", "
                << system_->threadCount() << " thread(s)";
            if (system_->threadUse().adaptive)
            {
                // threads 0: each step on one thread or on all, whichever
                // its timing finds faster (AdaptiveThreads.h)
                Info<< " (adaptive: 1 or " << system_->threadCount()
                    << " per step, whichever runs faster)";
            }
            if (Pstream::parRun())
            {
                Info<< " on each of " << Pstream::nProcs() << " ranks";
            }
            Info<< endl;

            const label n = system_->grainCount();
            if (settings_.surfaceOutputDefaulted() && !settings_.surfaceOutput(n))
            {
                Info<< "    capsule surfaces (" << grainWriter::outputDir
                    << "/capsules_<time>.vtp) not"
                    << " written: " << n << " grains > "
                    << demSettings::maxDefaultSurfaceGrains
                    << "; output { capsuleSurfaces yes; } writes them"
                    << endl;
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
    if
    (
        std::chrono::duration<double>(now - lastReport_).count()
      < settings_.progressInterval()
    )
    {
        return;
    }
    lastReport_ = now;

    // This run's share, from its start time: after a restart t/endTime
    // would count the earlier runs' time as done. t as the printed name
    // reads (evolve), so that the last step shows 100 %, not 99 % of a
    // running sum of time steps short of endTime in the last bit
    const Time& runTime = mesh_.time();
    scalar t = runTime.value();
    readScalar(runTime.timeName(), t);
    const scalar elapsed = std::chrono::duration<double>(now - wallStart_).count();
    const scalar done = t - simStart_;
    const scalar total = runTime.endTime().value() - simStart_;
    const scalar fraction = total > 0 ? done/total : 1;
    const scalar left = done > 0 ? elapsed*(total - done)/done : 0;

    // The rate to 3 digits, whatever writePrecision sets Info's to
    std::ostringstream rate;
    rate.precision(3);
    rate<< particleStepsPerSecond();

    Info<< "Progress: t = " << runTime.timeName() << " s, "
        << label(100*fraction) << " %, "
        << rate.str().c_str() << " particle-steps/s, "
        << "about " << label(left) << " s left";
    const dem::ThreadUse use = system_->threadUse();
    if (use.adaptive && use.steps > 0)
    {
        Info<< " (" << std::to_string(use.stepsOnMost).c_str() << " of "
            << std::to_string(use.steps).c_str() << " DEM steps on "
            << use.most << " threads, the rest on 1)";
    }
    Info<< endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::demCloud::subStepsPerFluidStep(const scalar dtFluid) const
{
    const scalar dt = system_->timeStep();
    const label nSub = label(std::round(dtFluid/dt));

    if (nSub < 1 || mag(nSub*dt - dtFluid) > 1e-9*dtFluid)
    {
        FatalErrorInFunction
            << "The fluid time step (deltaT " << dtFluid << " s in "
            << "system/controlDict) must be a whole multiple of the DEM time"
            << " step (timeStep " << dt << " s in "
            << settings_.dict().objectPath() << ")" << nl << exit(FatalError);
    }
    return nSub;
}


Foam::scalar Foam::demCloud::midStepTime(const scalar dtFluid) const
{
    // The end time as its name reads: the value a restart starts from,
    // where the running sum of time steps differs in the last bits, so
    // time-dependent loads restart bit-identically
    const Time& runTime = mesh_.time();
    scalar t = runTime.value();
    readScalar(runTime.timeName(), t);
    return t - 0.5*dtFluid;
}


Foam::vector Foam::demCloud::gravity(const scalar dtFluid) const
{
    return settings_.walls().gravity(midStepTime(dtFluid));
}


Foam::label Foam::demCloud::evolve(const scalar dtFluid)
{
    const label nSub = subStepsPerFluidStep(dtFluid);

    const auto start = std::chrono::steady_clock::now();
    demLibraryCall
    (
        "at t = " + mesh_.time().timeName() + " s, grains of "
      + settings_.dict().objectPath(),
        [&]
        {
            // Wall stresses and gravity held for the fluid step, at its
            // middle
            settings_.walls().update(*system_, midStepTime(dtFluid));
            system_->step(nSub);
            if (settings_.deformingBox())
            {
                grid_.followBox(system_->boxUpper());
            }
        }
    );
    stepSeconds_ += std::chrono::duration<double>
    (
        std::chrono::steady_clock::now() - start
    ).count();
    particleSteps_ += double(nSub)*system_->grainCount();

    reportProgress();
    return nSub;
}


dem::UniformGrid Foam::demCloud::couplingGrid() const
{
    dem::UniformGrid g = grid_.grid();
    g.depositInsideWalls = depositInsideWalls_;
    return g;
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
                couplingGrid(), dtFluid, phi.data(), phiPred.data(), u.data()
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
    handOver(forceDensity, nullptr, nullptr, rhoFluid);
}


void Foam::demCloud::setFluidForce
(
    const volVectorField& forceDensity,
    const volScalarField& dragCoefficient,
    const volVectorField& fluidVelocity,
    const scalar rhoFluid
)
{
    handOver(forceDensity, &dragCoefficient, &fluidVelocity, rhoFluid);
}


void Foam::demCloud::handOver
(
    const volVectorField& forceDensity,
    const volScalarField* dragCoefficient,
    const volVectorField* fluidVelocity,
    const scalar rhoFluid
)
{
    std::vector<double> f, beta, u;
    dem::FluidFields fluid;
    grid_.toGrid(forceDensity.primitiveField(), f);
    fluid.forceDensity = f.data();
    if (dragCoefficient)
    {
        grid_.toGrid(dragCoefficient->primitiveField(), beta);
        grid_.toGrid(fluidVelocity->primitiveField(), u);
        fluid.dragCoefficient = beta.data();
        fluid.velocity = u.data();
    }
    fluid.buoyancyDensity = rhoFluid;
    demLibraryCall
    (
        "handing the fluid force to the grains",
        [&]{ system_->setFluid(couplingGrid(), fluid); }
    );
}


void Foam::demCloud::depositReaction(volVectorField& reaction) const
{
    std::vector<double> r(3*grid_.size());
    demLibraryCall
    (
        "depositing the grains' reaction on the fluid",
        [&]{ system_->depositFluidReaction(couplingGrid(), r.data()); }
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
        "reading the grains of " + settings_.dict().objectPath(),
        [&]{ return system_->grains(); }
    );
}


dem::GrainData Foam::demCloud::grains() const
{
    dem::GrainData g = libraryGrains();
    for (size_t k = 0; k < g.id.size(); ++k)
    {
        for (int d = 0; d < 3; ++d)
        {
            g.displacement[3*k + d] -= displacement0_[3*size_t(g.id[k]) + d];
        }
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
        "reading the top wall",
        [&]{ return system_->wall(settings_.walls().top()); }
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
        "reading the top wall",
        [&]{ return system_->wall(settings_.walls().top()); }
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
    // Over all ranks (collective)
    const dem::GrainData g = libraryGrains();
    scalar sum = 0;
    for (const double r : g.radius)
    {
        sum += 2*r;
    }
    reduce(sum, sumOp<scalar>());
    const label n = returnReduce(label(g.radius.size()), sumOp<label>());
    return n == 0 ? 0 : sum/n;
}


bool Foam::demCloud::writeObject
(
    IOstream::streamFormat,
    IOstream::versionNumber,
    IOstream::compressionType,
    const bool
) const
{
    writer_.writeGrains(grains(), *system_);
    return true;
}


void Foam::demCloud::writeState() const
{
    writer_.writeState(*system_, topWall0_, displacement0_, grid_.grid());
}


Foam::scalar Foam::demCloud::particleStepsPerSecond() const
{
    return stepSeconds_ > 0 ? particleSteps_/stepSeconds_ : 0;
}


// ************************************************************************* //

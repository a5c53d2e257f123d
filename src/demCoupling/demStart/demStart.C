/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "demStart.H"
#include "demStateFile.H"
#include "grainStartState.H"
#include "grainsFile.H"
#include "OSspecific.H"

#include <sstream>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const char* const Foam::demStart::topWall0Key = "demCloud.topWallInitialPosition";
const char* const Foam::demStart::displacement0Key = "demCloud.displacementAtStart";
const char* const Foam::demStart::periodicBoxKey = "demCloud.periodicBox";
const char* const Foam::demStart::boxMotionKey = "demCloud.boxMotion";


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::fileName Foam::demStart::caseTimePath() const
{
    // Decomposed: the case directory's own time (a serial packing starts a
    // parallel run; the grains of a decomposed run are written there)
    return runTime_.globalPath()/runTime_.timeName();
}


void Foam::demStart::addGrainsFromFile(dem::System& system) const
{
    const fileName path(caseTimePath()/"grains");
    // Every rank reads and checks the file alike; the master adds them all
    // (the call is collective) and the first step sends each to its owner
    const grainStartState start
    (
        path, settings_.dict(), grid_, settings_.walls().specs()
    );
    system.addGrains
    (
        Pstream::master() ? start.grains() : std::vector<dem::GrainInit>()
    );
    if (!Pstream::parRun())
    {
        start.checkOverlaps(system);
    }
    else if (Pstream::master())
    {
        // The overlap check reads the whole packing at once: a one-process
        // system of the same grains, on the master
        dem::Parameters p(system.parameters());
        p.decomposition.ranks = {{1, 1}};
        dem::System whole(p);
        settings_.walls().addTo(whole);
        whole.addGrains(start.grains());
        start.checkOverlaps(whole);
    }
    Info<< "    " << start.grains().size() << " grains from " << path << endl;
    settings_.applyGrainFlags(system);
}


std::vector<double> Foam::demStart::displacementById
(
    const dem::System& system
)
{
    // Each rank's own grains, then summed: every grain's on every rank
    const dem::GrainData g(system.grains());
    scalarField byId(3*system.grainCount(), 0.0);
    for (size_t k = 0; k < g.id.size(); ++k)
    {
        for (int d = 0; d < 3; ++d)
        {
            byId[3*g.id[k] + d] = g.displacement[3*k + d];
        }
    }
    if (Pstream::parRun())
    {
        reduce(byId, sumOp<scalarField>());
    }
    return std::vector<double>(byId.begin(), byId.end());
}


void Foam::demStart::startFromState(const fileName& path, dem::System& system)
{
    dem::SystemState state(demStateFile(path).read());

    // The cloud's own entries travel in the same file
    const auto own = [&](const char* key) -> std::vector<double>
    {
        auto iter = state.reals.find(key);
        if (iter == state.reals.end())
        {
            return {};
        }
        std::vector<double> values(std::move(iter->second));
        state.reals.erase(iter);
        return values;
    };
    const std::vector<double> topWall0(own(topWall0Key));
    std::vector<double> displacement0(own(displacement0Key));
    const std::vector<double> stateBox(own(periodicBoxKey));
    std::vector<double> boxMotion(own(boxMotionKey));

    system.importState(state);
    checkGrainsInsideMesh(system, path);

    if (system.wallCount() != int(settings_.walls().specs().size()))
    {
        FatalIOErrorInFunction(settings_.dict())
            << path << " holds " << system.wallCount() << " walls but "
            << settings_.dict().name() << " defines " << settings_.walls().specs().size() << nl
            << exit(FatalIOError);
    }

    const scalar t = runTime_.value();
    const bool restart =
        mag(system.time() - t) <= 1e-9*max(scalar(1), mag(t))
     && topWall0.size() == 1;

    checkStateMatchesCase(system, path, stateBox, restart);

    if (restart)
    {
        topWall0_ = topWall0[0];
        displacement0_ = std::move(displacement0);
        boxMotion_ = std::move(boxMotion);
        Info<< "    restart from " << path << " (" << system.grainCount()
            << " grains)" << endl;
        return;
    }

    // A packing prepared by another run: this case's settings apply, and
    // displacements and dilation count from here
    Info<< "    packing prepared by another run (" << path << ", its clock at "
        << system.time() << " s): applying walls, flags, time step and"
        << " drag of " << settings_.dict().name() << endl;
    settings_.walls().applyTo(system);
    const dem::Parameters p(settings_.parameters(t));
    system.setTimeStep(p.timeStep);
    system.setViscousDrag(p.viscousDrag);
    settings_.applyGrainFlags(system);
    displacement0_ = displacementById(system);
    if (settings_.walls().top() >= 0)
    {
        topWall0_ = system.wall(settings_.walls().top()).position;
    }
}


void Foam::demStart::checkGrainsInsideMesh
(
    const dem::System& system,
    const fileName& source
) const
{
    const dem::GrainData g = system.grains();
    const dem::UniformGrid& grid = grid_;
    const scalar zMax = grid.origin[2] + grid.n[2]*grid.spacing[2];

    for (size_t i = 0; i < g.radius.size(); ++i)
    {
        for (int d = 0; d < 3; ++d)
        {
            const scalar lo = grid.origin[d];
            const scalar hi = (d < 2)
                ? grid.origin[d] + grid.n[d]*grid.spacing[d] : zMax;
            const scalar x = g.position[3*i + d];
            if (!(x >= lo && x <= hi))
            {
                FatalErrorInFunction
                    << "Grain " << g.id[i] << " of " << source << " at ("
                    << g.position[3*i] << " " << g.position[3*i + 1] << " "
                    << g.position[3*i + 2] << ") lies outside the mesh, "
                    << vector::componentNames[d] << " in [" << lo << ", "
                    << hi << "]" << nl << exit(FatalError);
            }
        }
    }
}


void Foam::demStart::checkStateMatchesCase
(
    const dem::System& system,
    const fileName& path,
    const std::vector<double>& stateBox,
    const bool restart
) const
{
    const std::vector<double> box(periodicBox(grid_));
    // Written by this code from the same mesh: equal to round-off of the
    // mesh points (1e-9 of the box)
    const scalar tol = 1e-9*max(box[1] - box[0], box[3] - box[2]);
    if (stateBox.size() == 4)
    {
        for (int k = 0; k < 4; ++k)
        {
            if (mag(stateBox[k] - box[k]) > tol)
            {
                // Ten digits: as the box was written in blockMeshDict
                const auto range = [](const scalar lo, const scalar hi)
                {
                    std::ostringstream os;
                    os.precision(10);
                    os  << '[' << lo << ", " << hi << ']';
                    return os.str();
                };
                FatalErrorInFunction
                    << path << " was written for another case: its periodic"
                    << " box is x in "
                    << range(stateBox[0], stateBox[1]).c_str()
                    << ", y in "
                    << range(stateBox[2], stateBox[3]).c_str()
                    << ", this mesh's is x in " << range(box[0], box[1]).c_str()
                    << ", y in " << range(box[2], box[3]).c_str() << nl
                    << exit(FatalError);
            }
        }
    }

    // In a restart, the grains file written beside it at the same time
    // lists as many grains (a prepared packing copied into a case may sit
    // beside that case's own start grains)
    // (decomposed: the grains of the case directory's time, where a
    // decomposed run writes them all; every rank reads the same file)
    const grainsFile beside(caseTimePath()/"grains");
    if (!restart || !beside.found())
    {
        return;
    }
    const label listed = beside.count();
    if (listed != label(system.grainCount()))
    {
        FatalErrorInFunction
            << path << " holds " << label(system.grainCount())
            << " grains but " << beside.path() << " beside it lists " << listed
            << ": the demState comes from another case or another run."
            << " Remove one of the two (the grains file alone starts without"
            << " contact history)." << nl << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demStart::demStart
(
    const Time& runTime,
    const demSettings& settings,
    const dem::UniformGrid& grid,
    dem::System& system
)
:
    runTime_(runTime),
    settings_(settings),
    grid_(grid),
    fromState_(false),
    topWall0_(0)
{
    // Decomposed: each rank's part in its processor directory, on all ranks
    // or none; with none, the one-process state of the case directory's
    // time (written by a run on one process, or gathered by a decomposed
    // one), which the library distributes over the ranks
    fileName statePath(runTime.timePath()/"demState");
    fromState_ = isFile(statePath);
    if (Pstream::parRun())
    {
        const label parts = returnReduce(label(fromState_), sumOp<label>());
        if (parts != 0 && parts != Pstream::nProcs())
        {
            FatalErrorInFunction
                << "Only " << parts << " of " << Pstream::nProcs()
                << " processor directories hold a demState at time "
                << runTime.timeName() << " (this rank: "
                << (fromState_ ? "" : "none at ") << statePath << ")." << nl
                << "Restart from a time every rank wrote, or remove the"
                << " processor directories' demState files of this time to"
                << " start from " << caseTimePath()/"grains" << nl
                << exit(FatalError);
        }
        if (parts == 0 && isFile(caseTimePath()/"demState"))
        {
            statePath = caseTimePath()/"demState";
            fromState_ = true;
            Info<< "    one-process state " << statePath << ": distributed"
                << " over the ranks at the first step" << endl;
        }
    }
    if (fromState_)
    {
        startFromState(statePath, system);
    }
    else
    {
        // A time a solver wrote (uniform/time is there) but without the
        // state beside its grains (its demState removed, or a time of a
        // decomposed run reconstructed and then decomposed afresh: each
        // rank's demState belongs to the old decomposition)
        if
        (
            isFile(caseTimePath()/"uniform"/"time")
         && !isFile(caseTimePath()/"demState")
        )
        {
            WarningInFunction
                << "No demState at time " << runTime.timeName() << ": the"
                << " grains start from " << caseTimePath()/"grains"
                << " without their contacts' history (tangential springs,"
                << " bonds), with the walls where "
                << settings_.dict().name() << " puts them and displacements"
                << " measured from this time. A decomposed run continues"
                << " exactly from its processor directories' demState"
                << " files." << endl;
        }
        addGrainsFromFile(system);
        if (settings_.walls().top() >= 0)
        {
            topWall0_ = system.wall(settings_.walls().top()).position;
        }
    }
    if (displacement0_.empty())
    {
        displacement0_.assign(3*system.grainCount(), 0.0);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

std::vector<double> Foam::demStart::periodicBox(const dem::UniformGrid& grid)
{
    const dem::UniformGrid& g = grid;
    return
    {
        g.origin[0], g.origin[0] + g.n[0]*g.spacing[0],
        g.origin[1], g.origin[1] + g.n[1]*g.spacing[1]
    };
}


void Foam::demStart::addOwnEntries
(
    dem::SystemState& state,
    const scalar topWall0,
    const std::vector<double>& displacement0,
    const dem::UniformGrid& grid,
    const dem::Parameters& parameters
)
{
    state.reals[topWall0Key] = {topWall0};
    state.reals[displacement0Key] = displacement0;
    state.reals[periodicBoxKey] = periodicBox(grid);
    const dem::Parameters& p = parameters;
    if (p.boxLengthRate[0] != 0 || p.boxLengthRate[1] != 0)
    {
        state.reals[boxMotionKey] =
        {
            p.boxUpper[0], p.boxUpper[1], p.boxTime,
            p.boxLengthRate[0], p.boxLengthRate[1]
        };
    }
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
-------------------------------------------------------------------------------
    Reading constant/demProperties and the start time's grains.
\*---------------------------------------------------------------------------*/

#include "demCloud.H"
#include "inputChecks.H"
#include "demStateFile.H"
#include "grainStartState.H"
#include "grainsFile.H"
#include "contactLaw.H"
#include "Enum.H"

#include <sstream>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

static const Enum<dem::Backend> backendNames
({
    { dem::Backend::automatic, "auto" },
    { dem::Backend::cpu, "cpu" },
    { dem::Backend::cuda, "cuda" },
});

static const Enum<dem::GrainFlag> grainFlagNames
({
    { dem::GrainFlag::free, "free" },
    { dem::GrainFlag::fixed, "fixed" },
    { dem::GrainFlag::prescribedVelocity, "prescribedVelocity" },
    { dem::GrainFlag::translationOnly, "translationOnly" },
});

} // End namespace Foam


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

dem::Parameters Foam::demCloud::readParameters() const
{
    const dictionary& dict = properties_;
    dem::Parameters p;

    p.backend = backendNames.get("backend", dict);
    p.threads = dict.getOrDefault<label>("threads", 0);
    p.timeStep = inputChecks::getPositive(dict, "timeStep");
    p.maxTimeStepFraction = dict.getOrDefault<scalar>("maxTimeStepFraction", 0.2);
    p.neighbourSkin = dict.getOrDefault<scalar>("neighbourSkin", 0);
    p.viscousDrag = dict.getOrDefault<scalar>("viscousDrag", 0);
    p.defaultDensity = inputChecks::getPositive(dict, "density");

    const vector g(walls_.gravity(mesh_.time().value()));
    p.gravity = {g.x(), g.y(), g.z()};

    // One run-time selected law each; grain-wall contacts default to the
    // grain-grain law
    p.grainGrain = contactLaw::New(dict.subDict("contact"))->material();
    p.grainWall =
        dict.found("wallContact")
      ? contactLaw::New(dict.subDict("wallContact"))->material()
      : p.grainGrain;
    p.bonds = bonds_.parameters();

    // The box is the mesh's horizontal extent, periodic where the mesh
    // sides are cyclic
    const dem::UniformGrid& g3 = grid_.grid();
    for (int d = 0; d < 2; ++d)
    {
        p.boxLower[d] = g3.origin[d];
        p.boxUpper[d] = g3.origin[d] + g3.n[d]*g3.spacing[d];
        p.periodic[d] = g3.periodic[d];
    }

    if (p.neighbourSkin < 0 || p.threads < 0 || p.viscousDrag < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Entries 'neighbourSkin', 'threads' and 'viscousDrag' in "
            << dict.name() << " must be >= 0" << nl << exit(FatalIOError);
    }
    if (!(p.maxTimeStepFraction > 0 && p.maxTimeStepFraction <= 1))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'maxTimeStepFraction' in " << dict.name()
            << " must lie in (0, 1], found " << p.maxTimeStepFraction << nl
            << exit(FatalIOError);
    }

    return p;
}


void Foam::demCloud::addGrainsFromFile()
{
    const grainStartState start
    (
        mesh_.time().timePath()/"grains", properties_, grid_.grid(),
        walls_.specs()
    );
    system_->addGrains(start.grains());
    start.checkOverlaps(*system_);
    Info<< "    " << start.grains().size() << " grains from "
        << mesh_.time().timePath()/"grains" << endl;
    applyGrainFlags();
}


void Foam::demCloud::applyGrainFlags()
{
    if (!properties_.found("grainFlags"))
    {
        return;
    }

    const dem::GrainData g = system_->grains();
    const dictionary& flags = properties_.subDict("grainFlags");
    for (const entry& e : flags)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(flags)
                << "Entry '" << e.keyword() << "' in " << flags.name()
                << " must be a dictionary { flag ...; zMin ...; zMax ...; }"
                << nl << exit(FatalIOError);
        }
        const dictionary& dict = e.dict();
        const dem::GrainFlag flag = grainFlagNames.get("flag", dict);
        const scalar zLo = dict.getOrDefault<scalar>("zMin", -GREAT);
        const scalar zHi = dict.getOrDefault<scalar>("zMax", GREAT);
        vector2D v(Zero);
        if (flag == dem::GrainFlag::prescribedVelocity)
        {
            v = dict.get<vector2D>("velocity");
        }

        std::vector<int> selected;
        for (size_t i = 0; i < g.radius.size(); ++i)
        {
            const scalar z = g.position[3*i + 2];
            if (z >= zLo && z < zHi)
            {
                selected.push_back(int(i));
            }
        }
        system_->setGrainFlags(selected, flag, v.x(), v.y());
        Info<< "    grain flags " << e.keyword() << ": "
            << grainFlagNames[flag] << " for " << selected.size()
            << " grains" << endl;
    }
}


void Foam::demCloud::startFromState(const fileName& path)
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

    system_->importState(state);
    checkGrainsInsideMesh(path);

    if (system_->wallCount() != int(walls_.specs().size()))
    {
        FatalIOErrorInFunction(properties_)
            << path << " holds " << system_->wallCount() << " walls but "
            << properties_.name() << " defines " << walls_.specs().size() << nl
            << exit(FatalIOError);
    }

    const scalar t = mesh_.time().value();
    const bool restart =
        mag(system_->time() - t) <= 1e-9*max(scalar(1), mag(t))
     && topWall0.size() == 1;

    checkStateMatchesCase(path, stateBox, restart);

    if (restart)
    {
        topWall0_ = topWall0[0];
        displacement0_ = std::move(displacement0);
        Info<< "    restart from " << path << " (" << system_->grainCount()
            << " grains)" << endl;
        return;
    }

    // A packing prepared by another run: this case's settings apply, and
    // displacements and dilation count from here
    Info<< "    packing prepared by another run (" << path << ", its clock at "
        << system_->time() << " s): applying walls, flags, time step and"
        << " drag of " << properties_.name() << endl;
    walls_.applyTo(*system_);
    const dem::Parameters p(readParameters());
    system_->setTimeStep(p.timeStep);
    system_->setViscousDrag(p.viscousDrag);
    applyGrainFlags();
    displacement0_ = system_->grains().displacement;
    if (hasTopWall())
    {
        topWall0_ = system_->wall(walls_.top()).position;
    }
}


void Foam::demCloud::checkGrainsInsideMesh(const fileName& source) const
{
    const dem::GrainData g = system_->grains();
    const dem::UniformGrid& grid = grid_.grid();
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
                    << "Grain " << label(i) << " of " << source << " at ("
                    << g.position[3*i] << " " << g.position[3*i + 1] << " "
                    << g.position[3*i + 2] << ") lies outside the mesh, "
                    << vector::componentNames[d] << " in [" << lo << ", "
                    << hi << "]" << nl << exit(FatalError);
            }
        }
    }
}


std::vector<double> Foam::demCloud::periodicBox() const
{
    const dem::UniformGrid& g = grid_.grid();
    return
    {
        g.origin[0], g.origin[0] + g.n[0]*g.spacing[0],
        g.origin[1], g.origin[1] + g.n[1]*g.spacing[1]
    };
}


void Foam::demCloud::checkStateMatchesCase
(
    const fileName& path,
    const std::vector<double>& stateBox,
    const bool restart
) const
{
    const std::vector<double> box(periodicBox());
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
    const grainsFile beside(path.path()/"grains");
    if (!restart || !beside.found())
    {
        return;
    }
    const label listed = beside.count();
    if (listed != label(system_->grainCount()))
    {
        FatalErrorInFunction
            << path << " holds " << label(system_->grainCount())
            << " grains but " << beside.path() << " beside it lists " << listed
            << ": the demState comes from another case or another run."
            << " Remove one of the two (the grains file alone starts without"
            << " contact history)." << nl << exit(FatalError);
    }
}


void Foam::demCloud::checkTimeStep() const
{
    const scalar dt = system_->timeStep();
    const scalar critical = system_->criticalTimeStep();
    const scalar fraction = system_->parameters().maxTimeStepFraction;

    Info<< "    DEM time step " << dt << " s = "
        << dt/critical << " sqrt(m_min/k_max)" << endl;

    if (dt > fraction*critical)
    {
        FatalIOErrorInFunction(properties_)
            << "Entry 'timeStep' (" << dt << " s) in " << properties_.name()
            << " is above the stable limit maxTimeStepFraction"
            << " sqrt(m_min/k_max) = " << fraction << " x " << critical
            << " = " << fraction*critical << " s" << nl
            << exit(FatalIOError);
    }
}


// ************************************************************************* //

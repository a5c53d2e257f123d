/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "demSettings.H"
#include "inputChecks.H"
#include "contactLaw.H"
#include "Enum.H"

#include <cmath>

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

//- The entries of demProperties: read by parameters() (backend ...
//- density, contact, wallContact), demWalls (gravity, walls),
//- applyGrainFlags (grainFlags), the constructor and bondProperties
//- (output, bonds, boxLengthRate) and grainStartState (wrapGrains,
//- maxInitialOverlap)
static const wordList demPropertiesNames
({
    "backend", "threads", "timeStep", "maxTimeStepFraction",
    "neighbourSkin", "viscousDrag", "density", "gravity", "gravityCoeffs",
    "contact", "wallContact", "walls", "grainFlags", "output", "bonds",
    "wrapGrains", "maxInitialOverlap", "boxLengthRate"
});

//- The entries of 'output': format, capsuleSurfaces and progressInterval
//- read by the constructor, bonds by bondProperties
static const wordList outputNames
({
    "format", "capsuleSurfaces", "bonds", "progressInterval"
});

//- The entries of each 'grainFlags' sub-dictionary (applyGrainFlags)
static const wordList grainFlagEntryNames
({
    "flag", "zMin", "zMax", "velocity"
});

//- properties, after checking that its top level, 'output' and each
//- 'grainFlags' sub-dictionary hold only entries of the lists above
//- ('contact', 'wallContact', 'bonds' and 'walls' are checked where they
//- are read)
static const dictionary& checkedEntries(const dictionary& properties)
{
    inputChecks::checkKnownEntries(properties, demPropertiesNames);
    if (properties.isDict("output"))
    {
        inputChecks::checkKnownEntries
        (
            properties.subDict("output"),
            outputNames
        );
    }
    if (properties.isDict("grainFlags"))
    {
        for (const entry& e : properties.subDict("grainFlags"))
        {
            if (e.isDict())
            {
                inputChecks::checkKnownEntries(e.dict(), grainFlagEntryNames);
            }
        }
    }
    return properties;
}

} // End namespace Foam


// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::label Foam::demSettings::maxDefaultSurfaceGrains = 20000;


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demSettings::demSettings
(
    const fvMesh& mesh,
    const dem::UniformGrid& grid
)
:
    grid_(grid),
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
    bonds_(checkedEntries(properties_)),
    walls_(properties_, grid, mesh.time().value()),
    asciiOutput_(false),
    surfaceChoiceGiven_(false),
    surfaceOutput_(true),
    progressInterval_(5),
    boxLengthRate_(Zero)
{
    readBoxLengthRate();

    if (properties_.found("output"))
    {
        const dictionary& output = properties_.subDict("output");
        const word format(output.getOrDefault<word>("format", "binary"));
        if (format != "binary" && format != "ascii")
        {
            FatalIOErrorInFunction(properties_)
                << "Entry 'output/format' in " << properties_.name()
                << " is '" << format << "'; valid: binary ascii" << nl
                << exit(FatalIOError);
        }
        asciiOutput_ = (format == "ascii");
        // Surfaces cost about 2.4 kB per grain and write time: by default
        // only for runs small enough to look at grain by grain (1e5
        // capsules would write 236 MB per time)
        surfaceChoiceGiven_ = output.found("capsuleSurfaces");
        if (surfaceChoiceGiven_)
        {
            surfaceOutput_ = output.get<bool>("capsuleSurfaces");
        }
        // Wall-clock seconds between progress lines; 0: every fluid step
        progressInterval_ =
            output.getOrDefault<scalar>("progressInterval", progressInterval_);
        if (progressInterval_ < 0)
        {
            FatalIOErrorInFunction(properties_)
                << "Entry 'output/progressInterval' in "
                << properties_.name() << " is " << progressInterval_
                << "; it must be >= 0 (seconds of wall time between progress"
                << " lines, 0: every fluid step)" << nl
                << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::demSettings::readBoxLengthRate()
{
    const dictionary& dict = properties_;
    boxLengthRate_ = dict.getOrDefault<vector>("boxLengthRate", Zero);
    const char* const names[3] = {"x", "y", "z"};
    for (direction d = 0; d < 3; ++d)
    {
        const scalar rate = boxLengthRate_[d];
        if (rate == 0)
        {
            continue;
        }
        string why;
        if (!std::isfinite(rate))
        {
            why = "is not finite";
        }
        else if (d == 2)
        {
            why = "changes z, which is never periodic (walls bound it)";
        }
        else if (!grid_.periodic[d])
        {
            why = "changes " + word(names[d]) + ", whose mesh sides are not"
                " cyclic patches (only a periodic length can change)";
        }
        else if (Pstream::parRun())
        {
            why = "is not available over MPI ranks (a deforming box runs on"
                " one process)";
        }
        if (!why.empty())
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'boxLengthRate' " << boxLengthRate_ << " in "
                << dict.name() << " " << why.c_str() << "; it is the rate of"
                << " change [m/s] of the periodic lengths (x y 0), the upper"
                << " sides moving" << nl << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

dem::Parameters Foam::demSettings::parameters(const scalar t) const
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

    const vector g(walls_.gravity(t));
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
    const dem::UniformGrid& g3 = grid_;
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


void Foam::demSettings::applyGrainFlags(dem::System& system) const
{
    if (!properties_.found("grainFlags"))
    {
        return;
    }

    // Decomposed: each rank selects among its own grains (by id); the call
    // is collective
    const dictionary& flags = properties_.subDict("grainFlags");
    const dem::GrainData g = system.grains();
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
                selected.push_back(g.id[i]);
            }
        }
        system.setGrainFlags(selected, flag, v.x(), v.y());
        Info<< "    grain flags " << e.keyword() << ": "
            << grainFlagNames[flag] << " for "
            << returnReduce(label(selected.size()), sumOp<label>())
            << " grains" << endl;
    }
}


void Foam::demSettings::checkTimeStep(const dem::System& system) const
{
    const scalar dt = system.timeStep();
    const scalar critical = system.criticalTimeStep();
    const scalar fraction = system.parameters().maxTimeStepFraction;

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

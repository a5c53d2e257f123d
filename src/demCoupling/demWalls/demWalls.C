/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "demWalls.H"
#include "inputChecks.H"
#include "Enum.H"

#include <sstream>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

static const Enum<dem::WallSpec::Side> wallSideNames
({
    { dem::WallSpec::Side::lower, "lower" },
    { dem::WallSpec::Side::upper, "upper" },
});

static const Enum<dem::WallSpec::Mode> wallModeNames
({
    { dem::WallSpec::Mode::fixed, "fixed" },
    { dem::WallSpec::Mode::velocity, "velocity" },
    { dem::WallSpec::Mode::stress, "stress" },
    { dem::WallSpec::Mode::free, "free" },
});

static const Enum<vector::components> wallAxisNames
({
    { vector::X, "x" },
    { vector::Y, "y" },
    { vector::Z, "z" },
});

//- The entries of a wall's dictionary, as readWall reads them
//- (normalStress: a Function1 of time, normalStressCoeffs its
//- coefficients in the older form)
static const wordList wallEntryNames
({
    "axis", "side", "mode", "position", "velocity", "frictional", "mass",
    "normalStress", "normalStressCoeffs"
});

//- The choice of entry key of wall 'wall' (deflt when absent, unless deflt
//- is empty: then it is required); anything else stops naming the file,
//- the entry, the value found and the valid choices
template<class EnumType>
static EnumType readChoice
(
    const Enum<EnumType>& names,
    const dictionary& dict,
    const word& key,
    const word& wall,
    const word& deflt = word::null
)
{
    std::ostringstream valid;
    for (const word& name : names.names())
    {
        valid << ' ' << name;
    }
    if (deflt.empty() && !dict.found(key, keyType::LITERAL))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' of wall '" << wall << "' is missing in "
            << dict.name() << "; valid:" << valid.str().c_str() << nl
            << exit(FatalIOError);
    }
    const word value(dict.getOrDefault<word>(key, deflt, keyType::LITERAL));
    if (!names.found(value))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' of wall '" << wall << "' in "
            << dict.name() << " is '" << value << "'; valid:"
            << valid.str().c_str() << nl << exit(FatalIOError);
    }
    return names[value];
}

} // End namespace Foam


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

dem::WallSpec Foam::demWalls::readWall
(
    const word& name,
    const dictionary& dict,
    const dem::UniformGrid& grid,
    const scalar t
)
{
    inputChecks::checkKnownEntries(dict, wallEntryNames);

    dem::WallSpec w;
    w.axis = readChoice(wallAxisNames, dict, "axis", name, "z");
    w.side = readChoice(wallSideNames, dict, "side", name);
    w.mode = readChoice(wallModeNames, dict, "mode", name);
    w.position = dict.get<scalar>("position");
    w.velocity = dict.getOrDefault<scalar>("velocity", 0);
    w.frictional = dict.getOrDefault<bool>("frictional", true);

    normalStress_.resize(normalStress_.size() + 1);
    if
    (
        w.mode == dem::WallSpec::Mode::stress
     || w.mode == dem::WallSpec::Mode::free
    )
    {
        w.mass = inputChecks::getPositive(dict, "mass");
    }
    if (w.mode == dem::WallSpec::Mode::stress)
    {
        normalStress_.set
        (
            normalStress_.size() - 1,
            Function1<scalar>::New("normalStress", dict)
        );
        w.normalStress = normalStress_.last().value(t);
    }

    const int d = w.axis;
    const char* axis = vector::componentNames[d];
    if (d < 2 && grid.periodic[d])
    {
        FatalIOErrorInFunction(dict)
            << "Wall '" << name << "' in " << dict.name() << " is an " << axis
            << " wall, but the mesh sides normal to " << axis << " are cyclic"
            << " (periodic): make them wall patches in the mesh (e.g. type"
            << " wall in blockMeshDict) or remove the wall" << nl
            << exit(FatalIOError);
    }
    const scalar lo = grid.origin[d];
    const scalar hi = lo + grid.n[d]*grid.spacing[d];
    if (w.position < lo - SMALL || w.position > hi + SMALL)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'position' (" << w.position << ") of wall " << name
            << " in " << dict.name() << " lies outside the mesh, " << axis
            << " in [" << lo << ", " << hi << "]" << nl << exit(FatalIOError);
    }
    return w;
}


void Foam::demWalls::checkClosedSides
(
    const dictionary& walls,
    const dem::UniformGrid& grid
) const
{
    bool hasZ[2] = {false, false};
    for (const dem::WallSpec& w : specs_)
    {
        if (w.axis == 2)
        {
            hasZ[int(w.side)] = true;
        }
    }

    for (int d = 0; d < 2; ++d)
    {
        bool has[2] = {false, false};
        for (const dem::WallSpec& w : specs_)
        {
            if (w.axis == d)
            {
                has[int(w.side)] = true;
            }
        }
        const char* axis = vector::componentNames[d];
        if (!grid.periodic[d] && !(has[0] && has[1]))
        {
            FatalIOErrorInFunction(walls)
                << "The mesh sides normal to " << axis << " are not cyclic,"
                << " so the grains' box is closed there: 'walls' in "
                << walls.name() << " needs a lower and an upper " << axis
                << " wall, e.g. { axis " << axis << "; side lower; mode fixed;"
                << " position " << grid.origin[d] << "; } (else grains"
                << " would leave the mesh)" << nl << exit(FatalIOError);
        }
    }

    forAll(names_, w)
    {
        const dem::WallSpec& s = specs_[w];
        if
        (
            s.mode == dem::WallSpec::Mode::stress && s.axis != 2
         && !(hasZ[0] && hasZ[1])
        )
        {
            const char* other = s.axis == 0 ? "y" : "x";
            FatalIOErrorInFunction(walls)
                << "Wall '" << names_[w] << "' in " << walls.name() << " is a"
                << " stress-controlled " << vector::componentNames[s.axis]
                << " wall: its stress acts on the box's " << other
                << " length times the gap between the z walls, so 'walls'"
                << " needs a lower and an upper z wall (or use mode free)"
                << nl << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demWalls::demWalls
(
    const dictionary& demProperties,
    const dem::UniformGrid& grid,
    const scalar t
)
:
    names_(),
    specs_(),
    normalStress_(),
    gravity_(Function1<vector>::New("gravity", demProperties)),
    top_(-1)
{
    const dictionary& walls = demProperties.subDict("walls");
    scalar topZ = -GREAT;

    for (const entry& e : walls)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(walls)
                << "Entry '" << e.keyword() << "' in " << walls.name()
                << " must be a wall dictionary { side ...; mode ...; }" << nl
                << exit(FatalIOError);
        }
        const dem::WallSpec w = readWall(e.keyword(), e.dict(), grid, t);
        if
        (
            w.axis == 2 && w.side == dem::WallSpec::Side::upper
         && w.position > topZ
        )
        {
            topZ = w.position;
            top_ = int(specs_.size());
        }
        names_.append(e.keyword());
        specs_.push_back(w);
    }

    checkClosedSides(walls, grid);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::demWalls::addTo(dem::System& system) const
{
    forAll(names_, w)
    {
        system.addWall(specs_[w]);
        Info<< "    wall " << describe(w).c_str() << endl;
    }
}


void Foam::demWalls::applyTo(dem::System& system) const
{
    forAll(names_, w)
    {
        system.setWallMotion(w, specs_[w]);
    }
}


void Foam::demWalls::update(dem::System& system, const scalar t) const
{
    forAll(normalStress_, w)
    {
        if (normalStress_.set(w))
        {
            system.setWallStress(w, normalStress_[w].value(t));
        }
    }
    const vector g(gravity(t));
    system.setGravity({g.x(), g.y(), g.z()});
}


Foam::string Foam::demWalls::describe(const int w) const
{
    const dem::WallSpec& s = specs_[w];
    std::ostringstream os;
    os  << names_[w] << ": " << wallSideNames[s.side] << ' '
        << vector::componentNames[s.axis] << ", "
        << wallModeNames[s.mode] << " at " << vector::componentNames[s.axis]
        << " = " << s.position;
    if (s.mass > 0)
    {
        os  << ", mass " << s.mass << " kg";
    }
    return os.str();
}


// ************************************************************************* //

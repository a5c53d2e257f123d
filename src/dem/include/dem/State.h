// dem/State.h
// Host-side read-back and restart data. GrainData is the user's view (grains in the order they
// were added). SystemState is the complete internal state (grain arrays in internal order,
// neighbour pairs and contact history, walls, clock) for bit-exact restart; treat it as opaque
// named arrays that a caller may serialise.
#pragma once

#include "dem/Parameters.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace dem
{

//- Grain state in add order; vectors are 3 per grain interleaved (x0 y0 z0 x1 ...). With a
//- Decomposition: the grains the calling rank owns, in add order (see id).
struct GrainData
{
    std::vector<double> position;     //!< wrapped into the periodic box
    std::vector<double> displacement; //!< since the grain was added (unwrapped)
    std::vector<double> velocity;
    std::vector<double> angularVelocity;
    std::vector<double> force; //!< total force of the last step (contacts, gravity, fluid)
    //- -V grad p - rho_f V g at the grain's position with the current fluid (0 without fluid)
    std::vector<double> fluidForce;
    std::vector<double> torque;
    std::vector<double> radius;
    std::vector<double> coreHalfLength; //!< 0 for a sphere
    std::vector<double> orientation;    //!< 4 per grain (w, x, y, z), body to global
    std::vector<double> volume;         //!< true solid volume (capsule: pi r^2 L + 4/3 pi r^3)
    std::vector<double> mass;
    std::vector<int> contactCount; //!< touching grain-grain contacts (walls not counted)
    std::vector<GrainFlag> flag;
    //- add-order index of each grain (0, 1, 2, ... on one process; with a Decomposition the
    //- grains this rank owns, in increasing index)
    std::vector<int> id;
};

//- The deepest overlap between two grains (System::largestOverlap): depth of the overlap of
//- the real shapes (the cores' closest points for capsules), also relative to the smaller
//- radius of the two (dilation radii); add-order indices first < second, -1 when no grains
//- touch (then both overlaps are 0).
struct GrainOverlap
{
    double relativeOverlap = 0.0;
    double overlap = 0.0; //!< [m]
    int first = -1, second = -1;
};

//- State of one wall.
struct WallData
{
    double position = 0.0;
    double velocity = 0.0;
    double grainForce = 0.0; //!< force of the grains on the wall along its axis [N] (+: to +axis)
    WallSpec spec;
};

//- The intact bonds, sorted by (first, second), first < second (add-order indices). Vectors 3
//- per bond interleaved, in the global frame; loads are those on `first` (on `second`: minus).
struct BondData
{
    std::vector<int> first, second;
    std::vector<double> patchRadius;     //!< r_b [m]
    std::vector<double> normalForce;     //!< N [N], tension positive (elastic part)
    std::vector<double> shearForce;      //!< S [N] (3), in the contact plane
    std::vector<double> twistMoment;     //!< M_t [N m] along the normal (scalar)
    std::vector<double> bendMoment;      //!< M_b [N m] (3), in the contact plane
    std::vector<double> normal;          //!< n (3), unit, from first to second (patches' bisector)
    std::vector<double> point;           //!< contact point (3), wrapped into the periodic box
    std::vector<double> age;             //!< time since the bond formed [s]
    std::vector<std::uint8_t> softening; //!< 1 once r_b shrinks (past peak strength)
    //- Creep since the bond formed, per mechanism: path length of the creep displacement,
    //- normal and shear [m], twist and bend [rad] (doc/EQUATIONS.md, "Bonds").
    std::vector<double> creepNormal, creepShear, creepTwist, creepBend;
};

//- Bond totals: intact now, formed and broken since the System was built (restart keeps them),
//- and intact bonds whose grains do not touch (held by tension).
struct BondCounts
{
    std::size_t intact = 0, formed = 0, broken = 0, apart = 0;
    double meanPatchRadius = 0.0; //!< over intact bonds (0 without)
    //- Creep of the intact bonds and of those broken since the System was built, summed, per
    //- mechanism in the order normal [m], shear [m], twist [rad], bend [rad] (BondData).
    std::array<double, 4> intactCreep = {}, brokenCreep = {};
};

//- The CPU threads of the steps so far: `most` the threads a step may use (Parameters::threads,
//- or OpenMP's default for 0); with threads 0 (adaptive) each step's team is one or most, chosen
//- by timing both (probes: windows run with the other size; switches: probes that won).
struct ThreadUse
{
    int most = 1;
    bool adaptive = false;
    long long steps = 0, stepsOnMost = 0, probes = 0, switches = 0;
};

struct SystemState
{
    std::map<std::string, std::vector<double>> reals;
    std::map<std::string, std::vector<std::int64_t>> integers;
};

} // namespace dem

// PourPacking.h
// The start of the flowing benchmark (demBench --pour; src/dem/bench/README.md, "The flowing
// benchmark"): N equal spheres on a loose simple-cubic lattice above the wall at z = 0, each
// moved off its site at random by less than half the gap between neighbours (nothing touches at
// the start), all falling at the pour speed with a random spread added to every velocity
// component. The lattice side holds a whole number of sites, so the box is periodic in x and y
// without seams; the layers fill from the bottom, the last one may be partial. Deterministic
// for a given seed on any platform (std::mt19937_64 and our own mapping to [-1, 1)).
#pragma once

#include "PackingFile.h"

namespace dem
{

struct PourSettings
{
    long grains = 10000;
    unsigned seed = 1;
    double radius = 0.01; //!< the standard packings' radius [m]
    //- Lattice spacing (1 + gapFraction) d in x, y and z; the lowest layer is one gap above the
    //- wall.
    double gapFraction = 0.02;
    //- Each centre moves off its site by at most jitterFraction x gap per component (< 0.5:
    //- no two grains and no grain and the wall touch at the start).
    double jitterFraction = 0.45;
    //- About this many layers: ceil(sqrt(N / layers)) sites per side.
    int layers = 25;
    double fallSpeed = 10.0; //!< mean velocity, downwards [m/s] (a fall of about 5 m)
    double spread = 5.0;     //!< each component + a uniform number in [-spread, spread) [m/s]
};

//- The pour's grains (positions and velocities; spins zero), L = sites per side x spacing,
//- height twice the top of the highest grain.
Packing pourPacking(const PourSettings& settings, double density);

} // namespace dem

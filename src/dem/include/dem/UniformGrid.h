// dem/UniformGrid.h
// The uniform Cartesian grid on which grains are deposited and the fluid pressure gradient is
// given (the fluid mesh: OpenFOAM blockMesh hex cells). Cell (i, j, k) has index
// i + n[0] * (j + n[1] * k) (x fastest, blockMesh order) and centre origin + (i + 1/2) spacing.
// Non-periodic sides are walls: weights falling outside are mirrored back into the grid; by
// default the engine also keeps each deposit point half a cell inside the grains' own walls.
// A decomposed mesh passes its own block (origin, n) and later halo sides; nothing here assumes
// the grid covers the whole DEM box.
#pragma once

#include <array>
#include <cstddef>

namespace dem
{

struct UniformGrid
{
    std::array<double, 3> origin{0.0, 0.0, 0.0};  //!< lower corner of cell (0,0,0) [m]
    std::array<double, 3> spacing{1.0, 1.0, 1.0}; //!< cell size [m]
    std::array<int, 3> n{1, 1, 1};                //!< cells per direction
    std::array<bool, 3> periodic{true, true, false};
    //- true: every deposit and interpolation point is kept half a cell inside the grains' walls,
    //- so no grain volume reaches cells beyond the wall it rests on (doc/EQUATIONS.md 6);
    //- false: the weights cross walls inside the grid (only the grid's own sides mirror)
    bool depositInsideWalls = true;

    std::size_t cellCount() const { return std::size_t(n[0]) * n[1] * n[2]; }
    double cellVolume() const { return spacing[0] * spacing[1] * spacing[2]; }
};

//- The fluid's load on the grains, per cell of a UniformGrid (doc/EQUATIONS.md 7). Every step
//- a grain of solid volume V at x with velocity v feels
//-     F = V (f(x) + beta(x) (u(x) - v) - rho_f g),
//- the cell fields interpolated at its centre with the deposit's trilinear weights. The fluid
//- solver's force model decides what f and beta are: f = -grad p (Damsgaard et al. 2015,
//- eq. 12), f = -grad p/(1 - phi) (Darcy flow with Terzaghi's effective stress), or a drag law
//- with beta and u (Navier-Stokes). The library applies the sum; it holds no formula of its own.
struct FluidFields
{
    //- f: force per unit grain volume [N/m^3], 3 per cell interleaved (required)
    const double* forceDensity = nullptr;
    //- beta: drag coefficient per unit grain volume [kg/(m^3 s)], 1 per cell; nullptr: no drag
    const double* dragCoefficient = nullptr;
    //- u: fluid velocity [m/s], 3 per cell interleaved (required with dragCoefficient)
    const double* velocity = nullptr;
    //- rho_f [kg/m^3]: buoyancy -rho_f V g (g the gravity of the step)
    double buoyancyDensity = 0.0;
};

} // namespace dem

// dem/UniformGrid.h
// The uniform Cartesian grid on which grains are deposited and the fluid pressure gradient is
// given (the fluid mesh: OpenFOAM blockMesh hex cells). Cell (i, j, k) has index
// i + n[0] * (j + n[1] * k) (x fastest, blockMesh order) and centre origin + (i + 1/2) spacing.
// Non-periodic sides are walls: weights falling outside are mirrored back into the grid.
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

    std::size_t cellCount() const { return std::size_t(n[0]) * n[1] * n[2]; }
    double cellVolume() const { return spacing[0] * spacing[1] * spacing[2]; }
};

} // namespace dem

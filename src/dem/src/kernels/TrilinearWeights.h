// TrilinearWeights.h
// Trilinear weights of a point to the 8 surrounding cell centres of a uniform grid
// (doc/EQUATIONS.md 6): s = prod_d (1 - |x_d - x_c,d| / dx_d). Indices outside the grid wrap across
// periodic sides and are mirrored at the others (a wall between the last centre and the
// boundary), so the 8 weights always sum to 1 and deposited volume is conserved. A point is
// first kept at least half a cell inside the grains' walls (GridView::pointLower/Upper): a
// grain's volume never reaches cells beyond the wall that holds it, wherever the wall lies in
// the grid (at a cell face this is the same mirror as at the grid's own sides).
#pragma once

#include "backends/HostDevice.h"

#include <cmath>

namespace dem
{
namespace detail
{
inline namespace DEM_KERNEL_NS
{

struct GridView
{
    double origin[3] = {0, 0, 0};
    double spacing[3] = {1, 1, 1};
    int n[3] = {1, 1, 1};
    bool periodic[3] = {true, true, false};
    //- The range a deposit or interpolation point is kept in per direction: half a cell
    //- inside the grains' walls (EngineImpl::fluidGridView); unbounded without walls.
    double pointLower[3] = {-1e300, -1e300, -1e300};
    double pointUpper[3] = {1e300, 1e300, 1e300};

    DEM_HD long cellCount() const { return long(n[0]) * n[1] * n[2]; }
    DEM_HD double cellVolume() const { return spacing[0] * spacing[1] * spacing[2]; }

    DEM_HD int mapIndex(int k, int dim) const
    {
        const int cells = n[dim];
        if (periodic[dim])
        {
            k %= cells;
            return k < 0 ? k + cells : k;
        }
        if (k < 0)
            k = -k - 1; // mirror about the lower side
        else if (k >= cells)
            k = 2 * cells - 1 - k;                       // mirror about the upper side
        return k < 0 ? 0 : (k >= cells ? cells - 1 : k); // far outside: nearest cell
    }
};

struct TrilinearStencil
{
    long cell[8];
    double weight[8];
};

DEM_HD TrilinearStencil trilinearStencil(const GridView& grid, const Vector3d& x)
{
    int index[3][2];
    double w[3][2];
    for (int d = 0; d < 3; ++d)
    {
        const double xd = x[d] < grid.pointLower[d]
                              ? grid.pointLower[d]
                              : (x[d] > grid.pointUpper[d] ? grid.pointUpper[d] : x[d]);
        const double s = (xd - grid.origin[d]) / grid.spacing[d] - 0.5;
        const double base = std::floor(s);
        const double t = s - base;
        index[d][0] = grid.mapIndex(int(base), d);
        index[d][1] = grid.mapIndex(int(base) + 1, d);
        w[d][0] = 1.0 - t;
        w[d][1] = t;
    }
    TrilinearStencil stencil;
    for (int c = 0; c < 8; ++c)
    {
        const int a = c & 1, b = (c >> 1) & 1, e = (c >> 2) & 1;
        stencil.cell[c] =
            index[0][a] + long(grid.n[0]) * (index[1][b] + long(grid.n[1]) * index[2][e]);
        stencil.weight[c] = w[0][a] * w[1][b] * w[2][e];
    }
    return stencil;
}

//- A 3-per-cell interleaved field at a stencil's point (trilinearStencil: the deposit's
//- weights); one stencil serves every field read at that point.
DEM_HD Vector3d interpolateVector(const TrilinearStencil& s, const double* field)
{
    Vector3d value = Vector3d::Zero();
    for (int c = 0; c < 8; ++c)
        value += s.weight[c] *
                 Vector3d(field[3 * s.cell[c]], field[3 * s.cell[c] + 1], field[3 * s.cell[c] + 2]);
    return value;
}

//- A 1-per-cell field at a stencil's point.
DEM_HD double interpolateScalar(const TrilinearStencil& s, const double* field)
{
    double value = 0.0;
    for (int c = 0; c < 8; ++c)
        value += s.weight[c] * field[s.cell[c]];
    return value;
}

} // namespace DEM_KERNEL_NS
} // namespace detail
} // namespace dem

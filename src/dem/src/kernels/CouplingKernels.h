// CouplingKernels.h
// Grain -> grid deposit (doc/EQUATIONS.md 6): solid volume s V_g and volume-weighted velocity
// s V_g v scattered to the 8 nearest cell centres of each of the grain's deposit points (a
// sphere: its centre; a capsule: points of its axis, VolumeSpread.h), optionally from the
// predicted position x + v dt_f, then turned into porosity and mean velocity per cell.
#pragma once

#include "kernels/TrilinearWeights.h"
#include "kernels/Views.h"
#include "kernels/VolumeSpread.h"

namespace dem
{
namespace detail
{
inline namespace DEM_KERNEL_NS
{

//- A capsule's prediction x + v dt_f moves its axis without turning it (its rotation over dt_f
//- is ignored), and every deposit point carries the centre's velocity v (the rotation's
//- contribution, omega x (p - x), sums to zero over the grain and is ignored in the split).
struct DepositGrains
{
    Vec3Array position, velocity;
    const double* radius;
    const double* coreHalfLength; //!< nullptr: every grain is a sphere
    const double* orientation;    //!< (w, x, y, z) component-blocked, stride position.stride
    GridView grid;
    double lookAhead; //!< deposit at x + lookAhead * v (0: current position)
    double* solid;    //!< per cell
    double* momentum; //!< 3 per cell interleaved, or nullptr
    //- Decomposed: the grains' flags, whose ghosts are left to their owners (nullptr: all)
    const int* flag = nullptr;

    DEM_HD void operator()(int i) const
    {
        if (flag && flag[i] == kFlagGhost)
            return;
        const double r = radius[i];
        const double h = coreHalfLength ? coreHalfLength[i] : 0.0;
        const long s = position.stride;
        const Vector3d a = h > 0.0 ? halfAxisOf(h, orientation[i], orientation[i + s],
                                                orientation[i + 2 * s], orientation[i + 3 * s])
                                   : Vector3d::Zero();
        const Vector3d v = velocity(i);
        forEachSpreadPoint(position(i) + lookAhead * v, a, r, grainVolume(r, h),
                           spreadCylinderPoints(grid, a),
                           [&](const Vector3d& point, double volume) { add(point, volume, v); });
    }

    //- volume at point, with velocity v, to the 8 cells around it.
    DEM_HD void add(const Vector3d& point, double volume, const Vector3d& v) const
    {
        const TrilinearStencil s = trilinearStencil(grid, point);
        for (int c = 0; c < 8; ++c)
        {
            const double share = s.weight[c] * volume;
            atomicAddDouble(solid + s.cell[c], share);
            if (momentum)
                for (int d = 0; d < 3; ++d)
                    atomicAddDouble(momentum + 3 * s.cell[c] + d, share * v[d]);
        }
    }
};

struct FinishDeposit
{
    const double* solid;
    const double* momentum; //!< nullptr: no velocity wanted
    double cellVolume;
    double* porosity;
    double* meanVelocity; //!< in place over momentum allowed

    DEM_HD void operator()(int c) const
    {
        porosity[c] = 1.0 - solid[c] / cellVolume;
        if (momentum)
            for (int d = 0; d < 3; ++d)
                meanVelocity[3 * c + d] = solid[c] > 0.0 ? momentum[3 * c + d] / solid[c] : 0.0;
    }
};

} // namespace DEM_KERNEL_NS
} // namespace detail
} // namespace dem

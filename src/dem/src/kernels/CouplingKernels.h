// CouplingKernels.h
// Grain -> grid deposit (doc/EQUATIONS.md 6): solid volume s V_g and volume-weighted velocity
// s V_g v scattered to the 8 nearest cell centres (optionally from the predicted position
// x + v dt_f), then turned into porosity and mean velocity per cell.
#pragma once

#include "kernels/TrilinearWeights.h"
#include "kernels/Views.h"

namespace dem
{
namespace detail
{
inline namespace DEM_KERNEL_NS
{

struct DepositGrains
{
    Vec3Array position, velocity;
    const double* radius;
    GridView grid;
    double lookAhead; //!< deposit at x + lookAhead * v (0: current position)
    double* solid;    //!< per cell
    double* momentum; //!< 3 per cell interleaved, or nullptr

    DEM_HD void operator()(int i) const
    {
        const double r = radius[i];
        const double volume = 4.18879020478639098 * r * r * r;
        const Vector3d v = velocity(i);
        const TrilinearStencil s = trilinearStencil(grid, position(i) + lookAhead * v);
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

// FluidKernels.h
// The fluid's load on the grains (dem::FluidFields, doc/EQUATIONS.md 7), written once for both
// backends: the force on one grain (FluidView, added per grain by GrainForceKernel), its
// read-back for every grain, and the grains' reaction deposited on the fluid's cells.
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

//- The fluid's force on a grain of solid volume V (grainVolume: a capsule's true volume) at x
//- with velocity v (dem::FluidFields): F = V (f(x) + beta(x) (u(x) - v) - rho_f g), the cell
//- fields interpolated at the centre with the deposit's trilinear weights. It acts at the
//- centre: no torque, also for a capsule in a field that varies along its axis
//- (doc/EQUATIONS.md 7). Without drag the sum is V (f - rho_f g) exactly as written, so that
//- f = -grad p gives the bits of -V (grad p + rho_f g).
struct FluidView
{
    bool active = false;
    GridView grid;
    const double* forceDensity = nullptr;    //!< f, 3 per cell interleaved
    const double* dragCoefficient = nullptr; //!< beta, 1 per cell; nullptr: no drag
    const double* velocity = nullptr;        //!< u, 3 per cell interleaved
    double density = 0;                      //!< rho_f

    DEM_HD Vector3d force(const Vector3d& x, const Vector3d& v, double volume,
                          const Vector3d& gvec) const
    {
        if (!active)
            return Vector3d::Zero();
        Vector3d perVolume = interpolateVector(grid, forceDensity, x);
        if (dragCoefficient)
            perVolume += interpolateScalar(grid, dragCoefficient, x) *
                         (interpolateVector(grid, velocity, x) - v);
        return volume * (perVolume - density * gvec);
    }
};

//- The fluid force on grain i as the next step applies it (FluidView at its stored position
//- and velocity, its true volume): shared by the read-back and the reaction deposit.
struct GrainFluidForce
{
    Vec3Array position, velocity;
    const double* radius;
    const double* coreHalfLength; //!< nullptr: every grain is a sphere
    FluidView fluid;
    double gravity[3];

    DEM_HD Vector3d operator()(int i) const
    {
        const double volume = grainVolume(radius[i], coreHalfLength ? coreHalfLength[i] : 0.0);
        return fluid.force(position(i), velocity(i), volume,
                           Vector3d(gravity[0], gravity[1], gravity[2]));
    }
};

//- Read-back of the fluid force on every grain (internal order, like the grain fields).
struct FluidForceOnGrains
{
    GrainFluidForce force;
    Vec3Array out;

    DEM_HD void operator()(int i) const { out.store(i, force(i)); }
};

//- Per grain: minus its fluid force spread to the 8 cell centres around it with the weights
//- that interpolate the fields to it, per unit cell volume (System::depositFluidReaction).
//- The weights sum to 1: the cells receive exactly minus what the grains feel.
struct DepositFluidReaction
{
    GrainFluidForce force;
    GridView grid;
    double* reaction; //!< 3 per cell interleaved

    DEM_HD void operator()(int i) const
    {
        const Vector3d perCell = -force(i) / grid.cellVolume();
        const TrilinearStencil s = trilinearStencil(grid, force.position(i));
        for (int c = 0; c < 8; ++c)
            for (int d = 0; d < 3; ++d)
                atomicAddDouble(reaction + 3 * s.cell[c] + d, s.weight[c] * perCell[d]);
    }
};

} // namespace DEM_KERNEL_NS
} // namespace detail
} // namespace dem

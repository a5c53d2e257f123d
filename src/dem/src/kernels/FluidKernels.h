// FluidKernels.h
// The fluid's load on the grains (dem::FluidFields, doc/EQUATIONS.md 7), written once for both
// backends: each grain's load taken from the cell fields once per fluid step (StoreFluidLoad),
// the force it makes in every DEM step (FluidLoadView, added per grain by GrainForceKernel), its
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

//- The cell fields of dem::FluidFields as the backend holds them (FluidFields: f, and beta
//- with u for a drag law).
struct FluidFieldsView
{
    GridView grid;
    const double* forceDensity = nullptr;    //!< f, 3 per cell interleaved
    const double* dragCoefficient = nullptr; //!< beta, 1 per cell; nullptr: no drag
    const double* velocity = nullptr;        //!< u, 3 per cell interleaved
};

//- Grain i's fluid load for the coming fluid step, from the cell fields at its centre with the
//- deposit's trilinear weights (one stencil for all fields): load = (V (f + beta u), V beta)
//- with V its true volume (grainVolume). Why per fluid step and not per DEM step: the fields
//- are constant over a fluid step, a grain moves a tiny fraction of a cell within it, and the
//- interpolation cost as much as a fifth of a sphere's DEM step; only the drag's velocity term
//- needs the grain's current state and stays per DEM step (FluidLoadView).
struct StoreFluidLoad
{
    FluidFieldsView fields;
    Vec3Array position;
    const double* radius;
    const double* coreHalfLength; //!< nullptr: every grain is a sphere
    double* load;                 //!< 4 per grain, component-blocked (stride n)
    long n;

    DEM_HD void operator()(int i) const
    {
        const double volume = grainVolume(radius[i], coreHalfLength ? coreHalfLength[i] : 0.0);
        const TrilinearStencil s = trilinearStencil(fields.grid, position(i));
        Vector3d source = interpolateVector(s, fields.forceDensity);
        double beta = 0.0;
        if (fields.dragCoefficient)
        {
            beta = interpolateScalar(s, fields.dragCoefficient);
            source += beta * interpolateVector(s, fields.velocity);
        }
        for (int d = 0; d < 3; ++d)
            load[d * n + i] = volume * source[d];
        load[3 * n + i] = volume * beta;
    }
};

//- The fluid's force on grain i (solid volume V, velocity v), doc/EQUATIONS.md 7:
//- F = V (f + beta (u - v) - rho_f g) = load_F - load_beta v - rho_f V g, with f, beta and u
//- taken where the grain was when the fields were handed over (StoreFluidLoad), v and g of
//- the current step. It acts at the centre: no torque, also for a capsule in a field that
//- varies along its axis.
struct FluidLoadView
{
    bool active = false;
    const double* load = nullptr; //!< StoreFluidLoad's, 4 per grain, stride n
    long n = 0;
    double density = 0; //!< rho_f

    DEM_HD Vector3d force(int i, const Vector3d& v, double volume, const Vector3d& gvec) const
    {
        if (!active)
            return Vector3d::Zero();
        return Vector3d(load[i], load[n + i], load[2 * n + i]) - load[3 * n + i] * v -
               (density * volume) * gvec;
    }
};

//- The fluid force on grain i as the next step applies it (FluidLoadView at its stored velocity,
//- its true volume): shared by the read-back and the reaction deposit.
struct GrainFluidForce
{
    Vec3Array position, velocity;
    const double* radius;
    const double* coreHalfLength; //!< nullptr: every grain is a sphere
    FluidLoadView fluid;
    double gravity[3];

    DEM_HD Vector3d operator()(int i) const
    {
        const double volume = grainVolume(radius[i], coreHalfLength ? coreHalfLength[i] : 0.0);
        return fluid.force(i, velocity(i), volume, Vector3d(gravity[0], gravity[1], gravity[2]));
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
    //- Decomposed: the grains' flags, whose ghosts are left to their owners (nullptr: all)
    const int* flag = nullptr;

    DEM_HD void operator()(int i) const
    {
        if (flag && flag[i] == kFlagGhost)
            return;
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

// DiagnosticKernels.h
// Small per-grain functors for read-back reductions: touching contacts, wall forces and the
// shear force on prescribed-velocity grains.
#pragma once

#include "kernels/StepKernels.h"

namespace dem
{
namespace detail
{
inline namespace DEM_KERNEL_NS
{

//- Touching pairs of grain i: owned ones only (each pair once) or owned + incoming.
struct TouchingPairs
{
    GrainView g;
    PairView pairs;
    BoxView box;
    bool bothSides;
    int* perGrain; //!< optional output

    DEM_HD bool touching(int i, int j) const
    {
        const double sum = g.radius[i] + g.radius[j];
        return box.separation(g.position(i), g.position(j)).squaredNorm() < sum * sum;
    }

    DEM_HD double operator()(int i) const
    {
        int count = 0;
        for (int p = pairs.start[i]; p < pairs.start[i + 1]; ++p)
            count += touching(i, pairs.partner[p]);
        if (bothSides)
            for (int q = pairs.incomingStart[i]; q < pairs.incomingStart[i + 1]; ++q)
            {
                const int p = pairs.incomingPair[q];
                if (p < 0)
                    continue;
                count += touching(pairs.owner[p], i);
            }
        if (perGrain)
            perGrain[i] = count;
        return count;
    }
};

struct ComponentOf
{
    const double* values;
    DEM_HD double operator()(int i) const { return values[i]; }
};

//- Grain i's z-force on wall w (GrainView::wallState).
struct WallForceOf
{
    double* wallState;
    int wall;
    DEM_HD double operator()(int i) const { return wallRecordOf(wallState, i, wall)[3]; }
};

struct PrescribedForceX
{
    GrainView g;
    DEM_HD double operator()(int i) const
    {
        return g.flag[i] == kFlagPrescribed ? g.force.data[i] : 0.0;
    }
};

} // namespace DEM_KERNEL_NS
} // namespace detail
} // namespace dem

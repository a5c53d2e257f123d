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

//- From grain i's closest core point to grain j's (the SoA fields; capsules false: the
//- centres' separation, as for spheres).
DEM_HD Vector3d coreSeparation(const GrainView& g, const BoxView& box, bool capsules, int i, int j)
{
    const Vector3d d = box.separation(g.position(i), g.position(j));
    if (!capsules)
        return d;
    const Vector3d ai = g.halfAxis(i), aj = g.halfAxis(j);
    double ui, uj;
    closestSegmentParameters(ai, aj, d, ui, uj);
    return d - (ui * ai - uj * aj);
}

//- Touching pairs of grain i: owned ones only (each pair once) or owned + incoming.
struct TouchingPairs
{
    GrainView g;
    PairView pairs;
    BoxView box;
    bool bothSides;
    int* perGrain; //!< optional output
    bool capsules; //!< a system with capsules: the cores' closest points

    DEM_HD bool touching(int i, int j) const
    {
        const double sum = g.radius[i] + g.radius[j];
        return coreSeparation(g, box, capsules, i, j).squaredNorm() < sum * sum;
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

//- Read-back of the bonds at the SoA state: each bond's unit normal (3) and contact point (3,
//- as the force pass takes them, BondGeometry.h; wrapped into the periodic box), and whether
//- its grains touch (1) or not (0) by the contact count's own test, so that touching pairs plus
//- bonds apart count every pair once.
struct BondReadback
{
    GrainView g;
    BondView bonds;
    BoxView box;
    double* normal; //!< 3 per bond
    double* point;  //!< 3 per bond
    double* touching;
    bool bodyFixed; //!< BondPoint::bodyFixedPatches

    DEM_HD void operator()(int b) const
    {
        const int i = bonds.grainA[b], j = bonds.grainB[b];
        const Vector3d xi = g.position(i);
        const Vector3d d = box.separation(xi, g.position(j));
        const BondGeometry geometry =
            bodyFixed
                ? patchGeometry(bonds.loadPatches(b), d, g.orientationOf(i), g.orientationOf(j),
                                g.halfAxis(i), g.halfAxis(j), g.radius[i], g.radius[j])
                : bondGeometry(d, g.halfAxis(i), g.halfAxis(j), g.radius[i], g.radius[j]);
        Vector3d c = xi + geometry.offsetA;
        for (int d = 0; d < 2; ++d)
            if (box.periodic[d])
                c[d] -= box.length[d] * std::floor((c[d] - box.lower[d]) / box.length[d]);
        for (int d = 0; d < 3; ++d)
        {
            normal[3L * b + d] = geometry.normal[d];
            point[3L * b + d] = c[d];
        }
        const TouchingPairs test{g, PairView(), box, false, nullptr, true};
        touching[b] = test.touching(i, j) ? 1.0 : 0.0;
    }
};

//- Grain i's deepest overlap among the pairs it owns, relative to the smaller radius of the
//- pair (the dilation radii): relative[i] (0 when none touches) and partner[i] (-1 then).
struct DeepestOverlap
{
    GrainView g;
    PairView pairs;
    BoxView box;
    bool capsules;
    double* relative;
    double* overlap;
    int* partner;

    DEM_HD void operator()(int i) const
    {
        double best = 0.0, bestOverlap = 0.0;
        int bestPartner = -1;
        for (int p = pairs.start[i]; p < pairs.start[i + 1]; ++p)
        {
            const int j = pairs.partner[p];
            const double ri = g.radius[i], rj = g.radius[j];
            const double depth = (ri + rj) - coreSeparation(g, box, capsules, i, j).norm();
            const double fraction = depth / (ri < rj ? ri : rj);
            if (fraction > best)
            {
                best = fraction;
                bestOverlap = depth;
                bestPartner = j;
            }
        }
        relative[i] = best;
        overlap[i] = bestOverlap;
        partner[i] = bestPartner;
    }
};

//- 1 / m_eff for the critical time step: 1/m, and for a capsule also its rotation under a
//- force at the end of the longest lever about each principal axis: (r + h)^2 / I_perp about
//- a transverse axis (a contact at a tip), r^2 / I_axial about its own axis. A sphere keeps
//- 1/m (the library's rule since its first version).
struct EffectiveInverseMass
{
    GrainView g;
    DEM_HD double operator()(int i) const
    {
        const double inverseMass = g.inverseMass[i];
        const double h = g.coreHalfLength[i], r = g.radius[i];
        if (!(h > 0.0))
            return inverseMass;
        const Vector3d inertia = g.principalInertia(i);
        const double tip = (r + h) * (r + h) / inertia.x(), side = r * r / inertia.z();
        const double rotational = tip > side ? tip : side;
        return rotational > inverseMass ? rotational : inverseMass;
    }
};

struct ComponentOf
{
    const double* values;
    DEM_HD double operator()(int i) const { return values[i]; }
};

//- Grain i's force on wall w along its axis (GrainView::wallState; with capsules both ends).
struct WallForceOf
{
    double* wallState;
    double* wallStateEnd; //!< nullptr without capsules
    int wall;
    DEM_HD double operator()(int i) const
    {
        const double f = wallRecordOf(wallState, i, wall)[3];
        return wallStateEnd ? f + wallRecordOf(wallStateEnd, i, wall)[3] : f;
    }
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

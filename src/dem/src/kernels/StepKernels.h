// StepKernels.h
// The kernels of one velocity-Verlet step, written once for both backends:
//   KickDrift   v += dt/2 a, x += dt v (grain flags applied); returns the squared displacement
//               since the last neighbour rebuild, so the caller knows when to rebuild
//   ForceKernel per owner grain: gravity, drag, fluid force, walls and the owned half of the
//               pair list; writes the partner's share of each pair into PairView::reaction
//   GatherKick  adds the reactions of the pairs the grain is partner of (fixed order, so
//               results do not depend on the thread count) and does the second half kick
#pragma once

#include "kernels/LinearSpringContact.h"
#include "kernels/TrilinearWeights.h"
#include "kernels/Views.h"

namespace dem
{
namespace detail
{
inline namespace DEM_KERNEL_NS
{

constexpr int kFlagFree = 0, kFlagFixed = 1, kFlagPrescribed = 2, kFlagTranslationOnly = 3;

//- Half kick of grain i with its current force and torque, respecting its flag.
DEM_HD void halfKick(const GrainView& g, int i, double halfDt)
{
    const int flag = g.flag[i];
    if (flag == kFlagFixed)
    {
        g.velocity.store(i, Vector3d::Zero());
        g.angularVelocity.store(i, Vector3d::Zero());
        return;
    }
    Vector3d v = g.velocity(i) + (halfDt * g.inverseMass[i]) * g.force(i);
    if (flag == kFlagPrescribed)
    {
        v.x() = g.prescribedVelocity[i];
        v.y() = g.prescribedVelocity[i + g.n];
    }
    g.velocity.store(i, v);
    if (flag == kFlagFree)
        g.angularVelocity.store(i, g.angularVelocity(i) +
                                       (halfDt * g.inverseInertia[i]) * g.torque(i));
    else
        g.angularVelocity.store(i, Vector3d::Zero());
}

struct KickDrift
{
    GrainView g;
    double dt;

    DEM_HD double operator()(int i) const
    {
        halfKick(g, i, 0.5 * dt);
        const Vector3d x = g.position(i) + dt * g.velocity(i);
        g.position.store(i, x);
        g.pack(i);
        return (x - g.positionAtBuild(i)).squaredNorm();
    }
};

//- Refresh the packed copies (after adding, importing or re-sorting grains).
struct PackGrains
{
    GrainView g;
    DEM_HD void operator()(int i) const { g.pack(i); }
};

struct FluidView
{
    bool active = false;
    GridView grid;
    const double* gradP = nullptr; //!< 3 per cell interleaved
    double density = 0;
};

struct ForceKernel
{
    GrainView g;
    PairView pairs;
    BoxView box;
    WallsView walls;
    LinearSpringContact grainLaw, wallLaw, frictionlessWallLaw;
    double gravity[3];
    double drag;
    FluidView fluid;

    DEM_HD void operator()(int i) const
    {
        const Vector3d x = g.packedPosition(i), v = g.packedVelocity(i),
                       omega = g.packedAngularVelocity(i);
        const double r = g.packedRadius(i);
        const Vector3d gvec(gravity[0], gravity[1], gravity[2]);
        Vector3d force = gvec / g.inverseMass[i] - drag * v;
        Vector3d torque = Vector3d::Zero();
        if (fluid.active)
        {
            const double volume = 4.18879020478639098 * r * r * r; // 4/3 pi r^3
            force -= volume * (interpolateVector(fluid.grid, fluid.gradP, x) + fluid.density * gvec);
        }
        addWallContacts(i, x, v, omega, r, force, torque);
        addOwnedPairs(i, x, v, omega, r, force, torque);
        g.force.store(i, force);
        g.torque.store(i, torque);
    }

    DEM_HD void addWallContacts(int i, const Vector3d& x, const Vector3d& v, const Vector3d& omega,
                                double r, Vector3d& force, Vector3d& torque) const
    {
        const long n = g.n;
        for (int w = 0; w < walls.count; ++w)
        {
            double* h = g.wallHistory + 3 * w * n + i;
            const double overlap = r - (x.z() - walls.position[w]) * walls.normalZ[w];
            if (overlap <= 0.0)
            {
                h[0] = h[n] = h[2 * n] = 0.0;
                g.wallForce[w * n + i] = 0.0;
                continue;
            }
            Vector3d history(h[0], h[n], h[2 * n]);
            const Vector3d normal(0.0, 0.0, -walls.normalZ[w]); // from the grain to the wall
            const ContactLoads loads = evaluateContact(
                walls.frictional[w] ? wallLaw : frictionlessWallLaw, normal, overlap, r, 0.0, v,
                Vector3d(0.0, 0.0, walls.velocity[w]), omega, Vector3d::Zero(), history);
            h[0] = history.x();
            h[n] = history.y();
            h[2 * n] = history.z();
            force += loads.forceOnI;
            torque += loads.torqueOnI;
            g.wallForce[w * n + i] = -loads.forceOnI.z();
        }
    }

    DEM_HD void addOwnedPairs(int i, const Vector3d& x, const Vector3d& v, const Vector3d& omega,
                              double r, Vector3d& force, Vector3d& torque) const
    {
        const long cs = pairs.componentStride;
        for (int p = pairs.start[i]; p < pairs.start[i + 1]; ++p)
        {
            const int j = pairs.partner[p];
            const Vector3d d = box.separation(x, g.packedPosition(j));
            const double rj = g.packedRadius(j);
            const double sumRadii = r + rj;
            const double distance2 = d.squaredNorm();
            double* h = pairs.historyOf(p);
            double* reaction = pairs.reactionOf(p);
            if (distance2 >= sumRadii * sumRadii)
            {
                if (h[0] != 0.0 || h[cs] != 0.0 || h[2 * cs] != 0.0)
                    for (int c = 0; c < 3 * kHistoryVectors; ++c)
                        h[c * cs] = 0.0;
                for (int c = 0; c < 6; ++c)
                    reaction[c * cs] = 0.0;
                continue;
            }
            const double inverseDistance = 1.0 / std::sqrt(distance2);
            Vector3d history(h[0], h[cs], h[2 * cs]);
            const ContactLoads loads = evaluateContact(
                grainLaw, d * inverseDistance, sumRadii - distance2 * inverseDistance, r, rj, v,
                g.packedVelocity(j), omega, g.packedAngularVelocity(j), history);
            h[0] = history.x();
            h[cs] = history.y();
            h[2 * cs] = history.z();
            force += loads.forceOnI;
            torque += loads.torqueOnI;
            for (int c = 0; c < 3; ++c)
            {
                reaction[c * cs] = -loads.forceOnI[c];
                reaction[(3 + c) * cs] = loads.torqueOnJ[c];
            }
        }
    }
};

//- Completes the step (gather, half kick). With driftNext it also runs the next step's
//- KickDrift in the same pass over the grains and returns its squared displacement.
struct GatherKick
{
    GrainView g;
    PairView pairs;
    double dt;
    bool driftNext;

    DEM_HD double operator()(int j) const
    {
        Vector3d force = g.force(j), torque = g.torque(j);
        const long cs = pairs.componentStride;
        for (int q = pairs.incomingStart[j]; q < pairs.incomingStart[j + 1]; ++q)
        {
            const int p = pairs.incomingPair[q];
            if (p < 0)
                continue; // cannot happen: the neighbour test is symmetric
            const double* reaction = pairs.reactionOf(p);
            force += Vector3d(reaction[0], reaction[cs], reaction[2 * cs]);
            torque += Vector3d(reaction[3 * cs], reaction[4 * cs], reaction[5 * cs]);
        }
        g.force.store(j, force);
        g.torque.store(j, torque);
        halfKick(g, j, 0.5 * dt);
        if (!driftNext)
            return 0.0;
        return KickDrift{g, dt}(j);
    }
};

} // namespace DEM_KERNEL_NS
} // namespace detail
} // namespace dem

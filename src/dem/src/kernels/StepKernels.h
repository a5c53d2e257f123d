// StepKernels.h
// The force kernel of a velocity-Verlet step, written once for both backends: per owner grain
// gravity, drag, fluid force, walls and the owned half of the pair list; the partner's share
// of each pair goes to PairView::reaction for GatherKick (IntegrationKernels.h).
#pragma once

#include "kernels/IntegrationKernels.h"
#include "kernels/LinearSpringContact.h"
#include "kernels/TrilinearWeights.h"
#include "kernels/Views.h"

namespace dem
{
namespace detail
{
inline namespace DEM_KERNEL_NS
{

//- The pore fluid's force on a grain (Damsgaard et al. 2015, eq. 12): f = -V grad p(x) -
//- rho_f V g, grad p interpolated with the deposit's trilinear weights.
struct FluidView
{
    bool active = false;
    GridView grid;
    const double* gradP = nullptr; //!< 3 per cell interleaved
    double density = 0;

    DEM_HD Vector3d force(const Vector3d& x, double r, const Vector3d& gvec) const
    {
        if (!active)
            return Vector3d::Zero();
        const double volume = 4.18879020478639098 * r * r * r; // 4/3 pi r^3
        return -volume * (interpolateVector(grid, gradP, x) + density * gvec);
    }
};

//- Read-back of the fluid force on every grain (internal order, 3 per grain interleaved).
struct FluidForceOnGrains
{
    Vec3Array position;
    const double* radius;
    FluidView fluid;
    double gravity[3];
    double* out;

    DEM_HD void operator()(int i) const
    {
        const Vector3d f =
            fluid.force(position(i), radius[i], Vector3d(gravity[0], gravity[1], gravity[2]));
        for (int d = 0; d < 3; ++d)
            out[3L * i + d] = f[d];
    }
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
        Vector3d force = gvec / g.packedVelocities[8L * i + 3] - drag * v; // m g - c v
        Vector3d torque = Vector3d::Zero();
        force += fluid.force(x, r, gvec);
        addWallContacts(i, x, v, omega, r, force, torque);
        addOwnedPairs(i, x, v, omega, r, force, torque);
        double* partial = g.packedForce + 8L * i; // summed up by GatherKick
        for (int c = 0; c < 3; ++c)
        {
            partial[c] = force[c];
            partial[4 + c] = torque[c];
        }
    }

    DEM_HD void addWallContacts(int i, const Vector3d& x, const Vector3d& v, const Vector3d& omega,
                                double r, Vector3d& force, Vector3d& torque) const
    {
        const long n = g.n;
        const int wasTouching = g.wallContacts[i];
        int touching = 0;
        for (int w = 0; w < walls.count; ++w)
        {
            double* h = g.wallHistory + 3 * w * n + i;
            const double overlap = r - (x.z() - walls.position[w]) * walls.normalZ[w];
            if (overlap <= 0.0)
            {
                if (wasTouching & (1 << w))
                {
                    h[0] = h[n] = h[2 * n] = 0.0;
                    g.wallForce[w * n + i] = 0.0;
                }
                continue;
            }
            touching |= 1 << w;
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
        if (touching != wasTouching)
            g.wallContacts[i] = touching;
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
                if (pairs.touching[p])
                {
                    for (int c = 0; c < 3 * kHistoryVectors; ++c)
                        h[c * cs] = 0.0;
                    pairs.touching[p] = 0;
                }
                continue;
            }
            pairs.touching[p] = 1;
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

} // namespace DEM_KERNEL_NS
} // namespace detail
} // namespace dem

// IntegrationKernels.h
// Velocity-Verlet integration kernels, written once for both backends:
//   KickDrift   first half kick and drift of a step() call (from the SoA fields)
//   GatherKick  (StepKernels.h) per-grain loads, the pairs' loads, the second half kick and,
//               within a step() call, the next step's kick and drift in the same pass
// Within a step() call the packed per-grain copies (GrainView::pack) are the current state,
// so a pass touches three cache lines per grain instead of ~25 arrays; the SoA fields are
// brought up to date at the end of the call and before a neighbour rebuild.
#pragma once

#include "kernels/RigidBody.h"
#include "kernels/Views.h"

#include <cmath>

namespace dem
{
namespace detail
{
inline namespace DEM_KERNEL_NS
{

//- Half kick of grain i's (v, omega), respecting its flag (a driven grain keeps both).
DEM_HD void kick(const GrainView& g, int i, int flag, double halfDt, double inverseMass,
                 double inverseInertia, const Vector3d& force, const Vector3d& torque, Vector3d& v,
                 Vector3d& omega)
{
    if (flag == kFlagDriven)
        return;
    if (flag == kFlagFixed)
    {
        v.setZero();
        omega.setZero();
        return;
    }
    v = v + (halfDt * inverseMass) * force;
    if (flag == kFlagPrescribed)
    {
        v.x() = g.prescribedVelocity[i];
        v.y() = g.prescribedVelocity[i + g.n];
    }
    if (flag == kFlagFree)
        omega = omega + (halfDt * inverseInertia) * torque;
    else
        omega.setZero();
}

//- Half kick of a capsule's global angular momentum L by the torque, and its angular velocity
//- omega = R I^-1 R^T L at orientation q; a driven capsule keeps its omega (and L), any other
//- that is not free does not rotate.
DEM_HD void kickRotation(int flag, double halfDt, const Vector3d& torque, const Quaterniond& q,
                         const Vector3d& inertia, Vector3d& L, Vector3d& omega)
{
    if (flag == kFlagDriven)
        return;
    if (flag != kFlagFree)
    {
        L.setZero();
        omega.setZero();
        return;
    }
    L = L + halfDt * torque;
    omega = angularVelocityOf(q, inertia, L);
}

//- Drift of a free capsule's orientation over dt at constant L (freeRotation, RigidBody.h):
//- stores q, refreshes its packed half-axis vector and returns omega at the new orientation.
//- A driven capsule turns at its constant omega by |omega| dt.
DEM_HD void rotate(const GrainView& g, int i, int flag, double dt, const Vector3d& inertia,
                   const Vector3d& L, Quaterniond& q, Vector3d& omega)
{
    if (flag == kFlagDriven)
    {
        const double angle = omega.norm() * dt;
        if (angle > 0.0)
        {
            q = Quaterniond(Eigen::AngleAxisd(angle, omega / omega.norm())) * q;
            q.normalize();
            g.storeOrientation(i, q);
            g.packHalfAxis(i);
        }
        return;
    }
    if (flag != kFlagFree)
        return;
    q = freeRotation(q, inertia, L, dt);
    omega = angularVelocityOf(q, inertia, L);
    g.storeOrientation(i, q);
    g.packHalfAxis(i);
}

//- A sphere's drift of orientation in a system with bonds (its bonds' patches turn with it;
//- without bonds nothing reads a sphere's orientation): q turned by omega dt, exact for the
//- drift's constant omega.
DEM_HD void turnSphere(const GrainView& g, int i, const Vector3d& omega, double dt)
{
    const double angle = omega.norm() * dt;
    if (angle > 0.0)
    {
        Quaterniond q =
            Quaterniond(Eigen::AngleAxisd(angle, omega / omega.norm())) * g.orientationOf(i);
        q.normalize();
        g.storeOrientation(i, q);
    }
}

//- Squared bound on how far any point of grain i's core moved since the last rebuild, x its
//- centre now: |x - x_build| + |a - a_build| (a point x + u a, |u| <= 1, moved at most that).
DEM_HD double endsMoved2(const GrainView& g, int i, const Vector3d& x)
{
    const double* b = g.packedPositionAtBuild + 4L * i;
    const double moved = (x - Vector3d(b[0], b[1], b[2])).norm() +
                         (g.packedHalfAxisOf(i) - g.halfAxisAtBuild(i)).norm();
    return moved * moved;
}

//- Packed copy of the rebuild positions, for the displacement check.
DEM_HD void packBuildPosition(const GrainView& g, int i)
{
    double* b = g.packedPositionAtBuild + 4L * i;
    for (int c = 0; c < 3; ++c)
        b[c] = g.positionAtBuild.data[i + c * g.positionAtBuild.stride];
    b[3] = 0.0;
}

//- A moved distance^2 for the step's max reduction, NaN made +inf: a max drops NaN, and a
//- grain that left the numbers must stop the step (EngineImpl::stopIfNotFinite).
DEM_HD double movedOrInfinity(double moved2)
{
    return moved2 == moved2 ? moved2 : HUGE_VAL;
}

//- First kick and drift of a step() call; returns |x - x_build|^2 (see movedOrInfinity; a
//- capsule: endsMoved2). Shapes: SphereShapes or CapsuleShapes (StepKernels.h).
template <class Shapes>
struct KickDrift
{
    GrainView g;
    double dt;

    DEM_HD double operator()(int i) const
    {
        if (g.flag[i] == kFlagGhost) // its owner moves it
            return 0.0;
        if constexpr (Shapes::kCapsules)
            if (g.coreHalfLength[i] > 0.0)
                return capsule(i);
        Vector3d v = g.velocity(i), omega = g.angularVelocity(i);
        kick(g, i, g.flag[i], 0.5 * dt, g.inverseMass[i], g.inverseInertia[i], g.force(i),
             g.torque(i), v, omega);
        g.velocity.store(i, v);
        g.angularVelocity.store(i, omega);
        const Vector3d x = g.position(i) + dt * v;
        g.position.store(i, x);
        if constexpr (Shapes::kBonds)
            turnSphere(g, i, omega, dt);
        g.pack(i);
        packBuildPosition(g, i);
        return movedOrInfinity((x - g.positionAtBuild(i)).squaredNorm());
    }

    DEM_HD double capsule(int i) const
    {
        const int flag = g.flag[i];
        Vector3d v = g.velocity(i), omega = g.angularVelocity(i), L = g.angularMomentum(i);
        Quaterniond q = g.orientationOf(i);
        const Vector3d inertia = g.principalInertia(i), torque = g.torque(i);
        kick(g, i, flag, 0.5 * dt, g.inverseMass[i], g.inverseInertia[i], g.force(i), torque, v,
             omega);
        kickRotation(flag, 0.5 * dt, torque, q, inertia, L, omega);
        const Vector3d x = g.position(i) + dt * v;
        g.position.store(i, x);
        rotate(g, i, flag, dt, inertia, L, q, omega);
        g.velocity.store(i, v);
        g.angularVelocity.store(i, omega);
        g.angularMomentum.store(i, L);
        g.pack(i);
        packBuildPosition(g, i);
        return movedOrInfinity(endsMoved2(g, i, x));
    }
};

//- The core's half-axis vector at a rebuild (systems with capsules; the skin check).
struct StoreHalfAxisAtBuild
{
    GrainView g;
    DEM_HD void operator()(int i) const { g.halfAxisAtBuild.store(i, g.halfAxis(i)); }
};

//- Refresh all packed copies from the SoA fields (after adding, importing or re-sorting).
struct PackGrains
{
    GrainView g;
    DEM_HD void operator()(int i) const
    {
        g.pack(i);
        packBuildPosition(g, i);
    }
};

//- Bring the SoA position and velocities up to date from the packed copies.
struct UnpackGrains
{
    GrainView g;
    DEM_HD void operator()(int i) const
    {
        g.position.store(i, g.packedPosition(i));
        g.velocity.store(i, g.packedVelocity(i));
        g.angularVelocity.store(i, g.packedAngularVelocity(i));
    }
};

} // namespace DEM_KERNEL_NS
} // namespace detail
} // namespace dem

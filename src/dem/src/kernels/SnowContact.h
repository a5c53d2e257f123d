// SnowContact.h
// Evaluator of the unfrozen contact law of snow grains (Johnson & Hopkins 2005): a viscous-
// elastic normal force that never pulls, F_n = max(0, k_n delta + c_n d(delta)/dt), with the
// stiffness of a contact area pi Rbar^2 over a spring of stiffness per area k_ne = E / (2 Rbar),
// k_n = E pi Rbar / 2, Rbar = (R_i + R_j) / 2 (a wall: R_i), and the damping
// c_n = 2 zeta_n sqrt(m* k_n) of a damping ratio zeta_n (m*: the reduced mass; a wall: m_i);
// tangential: the incremental history spring k_t = (k_t/k_n) k_n of LinearSpringContact with a
// dashpot c_t = 2 zeta_t sqrt(m* k_t) and the Coulomb cap |F_t| <= mu F_n. The pair's
// stiffness and damping depend on its radii and masses (ContactPair). Host and device.
#pragma once

#include "backends/HostDevice.h"
#include "kernels/ContactPair.h"
#include "kernels/TangentialSpring.h"

#include <cmath>

namespace dem
{
namespace detail
{
inline namespace DEM_KERNEL_NS
{

struct SnowContact
{
    double youngsModulus = 0;
    double tangentialToNormalStiffness = 0;
    double normalDampingRatio = 0;
    double tangentialDampingRatio = 0;
    double friction = 0;
    double timeStep = 0;
    //- 1 with a tangential spring (friction and k_t/k_n both nonzero), else 0: a factor rather
    //- than a select, so that the pair loop vectorises.
    double tangential = 0;

    static SnowContact make(double E, double ktOverKn, double zetaN, double zetaT, double mu,
                            double dt)
    {
        return SnowContact{E,
                           ktOverKn,
                           zetaN,
                           zetaT,
                           mu,
                           dt,
                           mu != 0.0 && ktOverKn != 0.0 && E != 0.0 ? 1.0 : 0.0};
    }

    //- k_n = E pi Rbar / 2 of a pair.
    DEM_HD double normalStiffness(const ContactPair& pair) const
    {
        const double meanRadius = 0.5 * (pair.radiusI + pair.radiusJ);
        return 0.5 * 3.14159265358979323846 * youngsModulus * meanRadius;
    }

    //- Returns the normal magnitude F_n >= 0 (the force on i is -F_n n + tangentialForce).
    //- n: unit normal from i towards j; overlap > 0; relativeVelocity: velocity of i's contact
    //- point minus j's. tangentialDisplacement (the contact's history) is updated. The normal
    //- force is clipped at zero: a contact whose dashpot would pull lets go, so the force ends
    //- while the grains still overlap (where k_n delta + c_n d(delta)/dt = 0).
    DEM_HD double forces(const Vector3d& n, double overlap, const Vector3d& relativeVelocity,
                         Vector3d& tangentialDisplacement, Vector3d& tangentialForce,
                         const ContactPair& pair) const
    {
        const double kn = normalStiffness(pair);
        const double kt = tangentialToNormalStiffness * kn;
        const double inverseMassSum = pair.inverseMassI + pair.inverseMassJ;
        // Two immovable grains (no inverse mass): no dashpot rather than an infinite one.
        const double reducedMass =
            inverseMassSum > 0.0 ? 1.0 / (inverseMassSum > 0.0 ? inverseMassSum : 1.0) : 0.0;
        const double cn = 2.0 * normalDampingRatio * std::sqrt(reducedMass * kn);
        const double ct = 2.0 * tangentialDampingRatio * std::sqrt(reducedMass * kt);
        const double inverseKt = kt > 0.0 ? 1.0 / (kt > 0.0 ? kt : 1.0) : 0.0;

        const double approachSpeed = relativeVelocity.dot(n);
        const double spring = kn * overlap + cn * approachSpeed;
        const double normalMagnitude = spring > 0.0 ? spring : 0.0;
        const Vector3d tangentialVelocity = relativeVelocity - approachSpeed * n;
        tangentialSpringForce(n, tangentialVelocity, normalMagnitude, kt, ct, inverseKt, friction,
                              tangential, timeStep, tangentialDisplacement, tangentialForce);
        return normalMagnitude;
    }
};

} // namespace DEM_KERNEL_NS
} // namespace detail
} // namespace dem

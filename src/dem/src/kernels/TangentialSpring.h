// TangentialSpring.h
// The tangential part shared by the contact laws: an incremental history spring rotated into
// the current tangent plane, a dashpot in parallel and a Coulomb cap that shortens the spring
// on slip. Branch-free (selects, no data-dependent branches), so that the pair kernel
// vectorises across pairs: the rotation factor and the Coulomb cap differ at random from
// contact to contact.
#pragma once

#include "backends/HostDevice.h"

#include <cmath>

namespace dem
{
namespace detail
{
inline namespace DEM_KERNEL_NS
{

//- Updates tangentialDisplacement (the contact's history) and sets tangentialForce on i.
//- n: unit normal from i to j; tangentialVelocity: relative velocity of i's contact point minus
//- j's, normal part removed; normalMagnitude: the normal force that sets the Coulomb limit;
//- tangential: 1 with a tangential spring, else 0 (a factor rather than a select).
DEM_HD void tangentialSpringForce(const Vector3d& n, const Vector3d& tangentialVelocity,
                                  double normalMagnitude, double stiffness, double damping,
                                  double inverseStiffness, double friction, double tangential,
                                  double timeStep, Vector3d& tangentialDisplacement,
                                  Vector3d& tangentialForce)
{
    // Rotate the stored displacement into the current tangent plane, keeping its length.
    Vector3d xi = tangentialDisplacement;
    const double normalPart = xi.dot(n);
    const double normal2 = normalPart * normalPart;
    const double lengthAfter2 = xi.squaredNorm() - normal2;
    xi -= normalPart * n;
    // Restore the length: factor sqrt(1 + e), e = normal2 / lengthAfter2 ~ (rotation per
    // step)^2. Below 1e-17 the series rounds to exactly 1 (the common quasi-static case);
    // below 1e-4 it is exact to round-off.
    const bool rotated = lengthAfter2 > 0.0;
    const double e = rotated ? normal2 / (rotated ? lengthAfter2 : 1.0) : 0.0;
    const double series = 1.0 + e * (0.5 - 0.125 * e);
    xi *= e < 1e-4 ? series : std::sqrt(1.0 + e);
    xi += tangentialVelocity * timeStep;

    Vector3d ft = -stiffness * xi - damping * tangentialVelocity;
    const double limit = friction * std::fabs(normalMagnitude);
    const double magnitude2 = ft.squaredNorm();
    // Gross slip: cap the force and shorten the spring to |xi| = mu |f_n| / k_t.
    const bool slip = magnitude2 > limit * limit;
    const double cap = limit / std::sqrt(slip ? magnitude2 : 1.0);
    const double shorten = -cap * inverseStiffness;
    for (int c = 0; c < 3; ++c)
    {
        tangentialDisplacement[c] = tangential * (slip ? shorten * ft[c] : xi[c]);
        tangentialForce[c] = tangential * (slip ? cap * ft[c] : ft[c]);
    }
}

} // namespace DEM_KERNEL_NS
} // namespace detail
} // namespace dem

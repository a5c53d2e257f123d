// LinearSpringContact.h
// Evaluator of the contact law of DESIGN.md 4.1 (Damsgaard et al. 2015, eqs 1-3): linear normal
// spring with optional dashpot, tangential history spring rotated into the current tangent
// plane with optional dashpot and a Coulomb cap that shortens the spring on slip. Shared by
// grain-grain and grain-wall contacts, host and device.
#pragma once

#include "backends/HostDevice.h"

#include <cmath>

namespace dem
{
namespace detail
{
inline namespace DEM_KERNEL_NS
{

struct LinearSpringContact
{
    double normalStiffness = 0;
    double tangentialStiffness = 0;
    double normalDamping = 0;
    double tangentialDamping = 0;
    double friction = 0;
    double timeStep = 0;

    //- Force on grain i. n: unit normal from i towards j; overlap > 0; relativeVelocity:
    //- velocity of i's contact point minus j's. tangentialDisplacement (the contact's history)
    //- is updated. The normal force is not clipped: with a dashpot it may pull at the end of
    //- an impact, which keeps restitution in closed form, e = exp(-zeta pi / sqrt(1 - zeta^2)).
    DEM_HD Vector3d force(const Vector3d& n, double overlap, const Vector3d& relativeVelocity,
                          Vector3d& tangentialDisplacement) const
    {
        const double approachSpeed = relativeVelocity.dot(n);
        const double normalMagnitude = normalStiffness * overlap + normalDamping * approachSpeed;
        const Vector3d normalForce = -normalMagnitude * n;
        if (friction == 0.0 || tangentialStiffness == 0.0)
        {
            tangentialDisplacement.setZero();
            return normalForce;
        }
        const Vector3d tangentialVelocity = relativeVelocity - approachSpeed * n;

        // Rotate the stored displacement into the current tangent plane, keeping its length.
        Vector3d xi = tangentialDisplacement;
        const double normalPart = xi.dot(n);
        if (normalPart != 0.0)
        {
            const double lengthBefore2 = xi.squaredNorm();
            xi -= normalPart * n;
            const double normal2 = normalPart * normalPart;
            // Restore the length: factor sqrt(1 + e), e = normal2 / lengthAfter2 ~ (rotation per
            // step)^2. Below 1e-17 the factor rounds to exactly 1 (the common quasi-static case,
            // no division); below 1e-4 the series is exact to round-off.
            const double lengthAfter2 = lengthBefore2 - normal2;
            if (lengthAfter2 > 0.0 && normal2 > 1e-17 * lengthAfter2)
            {
                const double e = normal2 / lengthAfter2;
                xi *= e < 1e-4 ? 1.0 + e * (0.5 - 0.125 * e) : std::sqrt(1.0 + e);
            }
        }
        xi += tangentialVelocity * timeStep;

        Vector3d tangentialForce =
            -tangentialStiffness * xi - tangentialDamping * tangentialVelocity;
        const double limit = friction * std::fabs(normalMagnitude);
        const double magnitude2 = tangentialForce.squaredNorm();
        if (magnitude2 > limit * limit)
        {
            // Gross slip: cap the force and shorten the spring to |xi| = mu |f_n| / k_t.
            tangentialForce *= limit / std::sqrt(magnitude2);
            xi = -tangentialForce / tangentialStiffness;
        }
        tangentialDisplacement = xi;
        return normalForce + tangentialForce;
    }
};

//- Result of one contact: force and torque on i, torque on j.
struct ContactLoads
{
    Vector3d forceOnI, torqueOnI, torqueOnJ;
};

//- Geometry and kinematics of two touching spheres (or sphere and wall: radiusJ = 0,
//- omegaJ = 0) and the law's loads. Lever arms reach the middle of the overlap.
DEM_HD ContactLoads evaluateContact(const LinearSpringContact& law, const Vector3d& n,
                                    double overlap, double radiusI, double radiusJ,
                                    const Vector3d& velocityI, const Vector3d& velocityJ,
                                    const Vector3d& omegaI, const Vector3d& omegaJ,
                                    Vector3d& history)
{
    const double leverI = radiusI - 0.5 * overlap;
    const double leverJ = radiusJ - 0.5 * overlap;
    const Vector3d relative =
        velocityI - velocityJ + omegaI.cross(leverI * n) + omegaJ.cross(leverJ * n);
    ContactLoads loads;
    loads.forceOnI = law.force(n, overlap, relative, history);
    const Vector3d nCrossF = n.cross(loads.forceOnI);
    loads.torqueOnI = leverI * nCrossF;
    loads.torqueOnJ = leverJ * nCrossF;
    return loads;
}

} // namespace DEM_KERNEL_NS
} // namespace detail
} // namespace dem

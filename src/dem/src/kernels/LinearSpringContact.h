// LinearSpringContact.h
// Evaluator of the contact law (doc/EQUATIONS.md 1; Damsgaard et al. 2015, eqs 1-3): linear normal
// spring with optional dashpot, tangential history spring rotated into the current tangent
// plane with optional dashpot and a Coulomb cap that shortens the spring on slip. Shared by
// grain-grain and grain-wall contacts, host and device.
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

struct LinearSpringContact
{
    double normalStiffness = 0;
    double tangentialStiffness = 0;
    double normalDamping = 0;
    double tangentialDamping = 0;
    double friction = 0;
    double timeStep = 0;
    double inverseTangentialStiffness = 0; //!< 1 / tangentialStiffness (0 when that is 0)
    //- 1 with a tangential spring (friction and k_t both nonzero), else 0: a factor rather than a
    //- select, so that the pair loop vectorises.
    double tangential = 0;

    static LinearSpringContact make(double kn, double kt, double cn, double ct, double mu,
                                    double dt)
    {
        return LinearSpringContact{
            kn, kt, cn, ct, mu, dt, kt != 0.0 ? 1.0 / kt : 0.0, mu != 0.0 && kt != 0.0 ? 1.0 : 0.0};
    }

    //- Force on grain i. n: unit normal from i towards j; overlap > 0; relativeVelocity:
    //- velocity of i's contact point minus j's. tangentialDisplacement (the contact's history)
    //- is updated. The normal force is not clipped: with a dashpot it may pull at the end of
    //- an impact, which keeps restitution in closed form, e = exp(-zeta pi / sqrt(1 - zeta^2)).
    DEM_HD Vector3d force(const Vector3d& n, double overlap, const Vector3d& relativeVelocity,
                          Vector3d& tangentialDisplacement) const
    {
        Vector3d tangentialForce;
        const double normalMagnitude =
            forces(n, overlap, relativeVelocity, tangentialDisplacement, tangentialForce);
        return tangentialForce - normalMagnitude * n;
    }

    //- The same law split into its parts: returns the normal magnitude (the force on i is
    //- -magnitude n + tangentialForce). Branch-free (selects, no data-dependent branches), so
    //- that the pair kernel vectorises across pairs.
    DEM_HD double forces(const Vector3d& n, double overlap, const Vector3d& relativeVelocity,
                         Vector3d& tangentialDisplacement, Vector3d& tangentialForce) const
    {
        const double approachSpeed = relativeVelocity.dot(n);
        const double normalMagnitude = normalStiffness * overlap + normalDamping * approachSpeed;
        const Vector3d tangentialVelocity = relativeVelocity - approachSpeed * n;

        tangentialSpringForce(n, tangentialVelocity, normalMagnitude, tangentialStiffness,
                              tangentialDamping, inverseTangentialStiffness, friction, tangential,
                              timeStep, tangentialDisplacement, tangentialForce);
        return normalMagnitude;
    }

    //- The call every law answers (the pair's radii and masses, unused by this law).
    DEM_HD double forces(const Vector3d& n, double overlap, const Vector3d& relativeVelocity,
                         Vector3d& tangentialDisplacement, Vector3d& tangentialForce,
                         const ContactPair&) const
    {
        return forces(n, overlap, relativeVelocity, tangentialDisplacement, tangentialForce);
    }
};

} // namespace DEM_KERNEL_NS
} // namespace detail
} // namespace dem

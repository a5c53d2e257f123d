// ElasticPatch.h
// The elastic glue of a frozen contact (Johnson & Hopkins 2005 after Potyondy & Cundall 2004):
// a circular patch of radius r_b, area A = pi r_b^2, second moments I = pi r_b^4 / 4 (bending)
// and J = pi r_b^4 / 2 (twist), with a normal stiffness per unit area k_ne = E / (2 Rbar) and
// a shear stiffness per unit area k_se = (k_se/k_ne) k_ne. Loads build up incrementally from the
// relative motion at the contact point; the stored in-plane vectors (shear force, bending
// moment) are first carried into the current contact plane. Host and device.
#pragma once

#include "backends/HostDevice.h"

#include <cmath>

namespace dem
{
namespace detail
{
inline namespace DEM_KERNEL_NS
{

constexpr double kPi = 3.14159265358979323846;

//- Area and second moments of a patch, and the stiffnesses per area.
struct PatchSection
{
    double radius, area, bendInertia, twistInertia; //!< r_b, A, I, J
    double normalStiffness, shearStiffness;         //!< k_ne, k_se per unit area [Pa/m]

    DEM_HD static PatchSection make(double patchRadius, double youngsModulus, double shearToNormal,
                                    double meanRadius)
    {
        PatchSection s;
        s.radius = patchRadius;
        const double r2 = patchRadius * patchRadius;
        s.area = kPi * r2;
        s.bendInertia = 0.25 * kPi * r2 * r2;
        s.twistInertia = 2.0 * s.bendInertia;
        s.normalStiffness = youngsModulus / (2.0 * meanRadius);
        s.shearStiffness = shearToNormal * s.normalStiffness;
        return s;
    }
};

//- The relative motion over one step at the contact point, B minus A: displacement split into
//- its normal part du_n (opening positive) and in-plane part du_t, rotation (omega_B - omega_A)
//- dt split into twist dtheta_t (along n, scalar) and bend dtheta_b (in the plane).
struct PatchIncrement
{
    double normal;     //!< du_n
    Vector3d shear;    //!< du_t
    double twist;      //!< dtheta_t
    Vector3d bend;     //!< dtheta_b
    Vector3d velocity; //!< relative velocity of the contact point (for the dashpots)
};

DEM_HD PatchIncrement patchIncrement(const Vector3d& n, const Vector3d& offsetA,
                                     const Vector3d& offsetB, const Vector3d& velocityA,
                                     const Vector3d& velocityB, const Vector3d& omegaA,
                                     const Vector3d& omegaB, double dt)
{
    PatchIncrement inc;
    inc.velocity = (velocityB + omegaB.cross(offsetB)) - (velocityA + omegaA.cross(offsetA));
    const Vector3d du = inc.velocity * dt;
    inc.normal = du.dot(n);
    inc.shear = du - inc.normal * n;
    const Vector3d dtheta = (omegaB - omegaA) * dt;
    inc.twist = dtheta.dot(n);
    inc.bend = dtheta - inc.twist * n;
    return inc;
}

//- Carries a stored in-plane vector X (shear force or bending moment) into the current contact
//- plane of normal n. X first turns with the pair's mean rotation over the step,
//- theta = (omega_A + omega_B) dt / 2, by the Cayley rotation (orthogonal, angle
//- 2 atan(|theta|/2) = |theta| - |theta|^3/12 + ...), then its normal part is removed and its
//- length restored. A pair turning as a rigid body thus keeps its loads, turned with it to
//- O(|theta|^3) per step; a pair whose normal tilts without turning (one grain sliding round
//- the other) has its loads carried by the projection. X along n (a normal turned by 90 degrees
//- in one step) has no direction left in the plane and is dropped.
DEM_HD Vector3d rotateIntoPlane(const Vector3d& X, const Vector3d& n, const Vector3d& theta)
{
    const Vector3d h = 0.5 * theta;
    const Vector3d hX = h.cross(X);
    Vector3d Y = X + (2.0 / (1.0 + h.squaredNorm())) * (hX + h.cross(hX));
    Y -= Y.dot(n) * n;
    const double length2 = Y.squaredNorm();
    const bool inPlane = length2 > 0.0;
    const double scale = inPlane ? std::sqrt(X.squaredNorm() / (inPlane ? length2 : 1.0)) : 0.0;
    return scale * Y;
}

} // namespace DEM_KERNEL_NS
} // namespace detail
} // namespace dem

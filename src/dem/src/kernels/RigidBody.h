// RigidBody.h
// Mass properties of a capsule and the rotation of a rigid body, written once for both
// backends. Orientation q is a unit quaternion taking body to global coordinates (R = R(q));
// a capsule's axis is the body z axis; the inertia tensor is diagonal in the body frame
// (principal moments I = (I_1, I_2, I_3)).
//
// Free rotation. A step of the engine is kick (torque changes the global angular momentum L),
// rotate at constant L, kick. The rotation at constant L is the NO_SQUISH splitting of Miller
// et al. (2002, J. Chem. Phys. 116, 8649): the free-rotor Hamiltonian
// H = sum_k Lb_k^2 / (2 I_k) (Lb = R^T L, the body-frame momentum) is split into its three
// terms, and the flow of each term alone is exact: a rotation about body axis k by the angle
// t Lb_k / I_k, during which Lb_k is constant. The symmetric composition
//   R_1(dt/2) R_2(dt/2) R_3(dt) R_2(dt/2) R_1(dt/2)
// is symplectic and time-reversible, hence second order: the energy error stays bounded at
// O(dt^2) over long runs instead of drifting, and L, held fixed in the global frame, is
// conserved to round-off. It works for any principal moments (the library must handle an
// asymmetric body, so the exact solution of the symmetric top alone would not do), it needs
// neither the Jacobi elliptic functions of the exact asymmetric solution nor an iteration
// (implicit midpoint), and it keeps q a unit quaternion (each sub-step is a rotation; q is
// re-normalised against round-off).
#pragma once

#include "backends/HostDevice.h"

namespace dem
{
namespace detail
{
inline namespace DEM_KERNEL_NS
{

//- Volume, mass and principal moments of inertia (I_perp, I_perp, I_axial: the axis is body z).
struct MassProperties
{
    double volume, mass;
    Vector3d inertia;
};

//- A capsule of radius r and core half-length h (cylinder of length L = 2h between two
//- hemispheres) and density rho. Cylinder mass m_c = rho pi r^2 L, hemispheres m_h =
//- rho 4/3 pi r^3 (both); I_axial = m_c r^2/2 + 2 m_h r^2/5; I_perp = m_c (L^2/12 + r^2/4) +
//- m_h (2 r^2/5 + L^2/4 + 3 L r/8) (each hemisphere: 2/5 r^2 per mass about its flat face, its
//- centroid 3r/8 from that face, moved by the parallel-axis theorem to L/2 + 3r/8 from the
//- centre). h = 0 is the sphere: 4/3 pi r^3 rho and 2/5 m r^2 about every axis.
DEM_HD MassProperties capsuleMassProperties(double radius, double halfLength, double density)
{
    const double pi = 3.14159265358979323846;
    const double r2 = radius * radius, length = 2.0 * halfLength;
    const double cylinder = density * pi * r2 * length;
    const double hemispheres = density * 4.0 / 3.0 * pi * r2 * radius;
    const double axial = cylinder * r2 / 2.0 + 2.0 * hemispheres * r2 / 5.0;
    const double perpendicular =
        cylinder * (length * length / 12.0 + r2 / 4.0) +
        hemispheres * (2.0 * r2 / 5.0 + length * length / 4.0 + 3.0 * length * radius / 8.0);
    MassProperties p;
    p.volume = pi * r2 * length + 4.0 / 3.0 * pi * r2 * radius;
    p.mass = cylinder + hemispheres;
    p.inertia = Vector3d(perpendicular, perpendicular, axial);
    return p;
}

//- omega = R I^-1 R^T L (I: principal moments, body frame).
DEM_HD Vector3d angularVelocityOf(const Eigen::Quaterniond& q, const Vector3d& inertia,
                                  const Vector3d& angularMomentum)
{
    const Eigen::Matrix3d rotation = q.toRotationMatrix();
    const Vector3d bodyMomentum = rotation.transpose() * angularMomentum;
    return rotation * bodyMomentum.cwiseQuotient(inertia);
}

//- L = R I R^T omega.
DEM_HD Vector3d angularMomentumOf(const Eigen::Quaterniond& q, const Vector3d& inertia,
                                  const Vector3d& omega)
{
    const Eigen::Matrix3d rotation = q.toRotationMatrix();
    const Vector3d bodyOmega = rotation.transpose() * omega;
    return rotation * bodyOmega.cwiseProduct(inertia);
}

//- Exact flow of Lb_k^2 / (2 I_k) for time t: q turns about its body axis k by t Lb_k / I_k,
//- and the body-frame momentum of the fixed global L turns the opposite way.
DEM_HD void rotateAboutBodyAxis(int k, double t, const Vector3d& inertia, Eigen::Quaterniond& q,
                                Vector3d& bodyMomentum)
{
    const double angle = t * bodyMomentum[k] / inertia[k];
    const Eigen::Quaterniond turn(Eigen::AngleAxisd(angle, Vector3d::Unit(k)));
    q = q * turn;
    bodyMomentum = turn.conjugate() * bodyMomentum;
}

//- Orientation after dt of torque-free rotation at constant global angular momentum L, from
//- q (NO_SQUISH, see the top of the file). Returns a unit quaternion.
DEM_HD Eigen::Quaterniond freeRotation(const Eigen::Quaterniond& q, const Vector3d& inertia,
                                       const Vector3d& angularMomentum, double dt)
{
    Eigen::Quaterniond turned = q;
    Vector3d bodyMomentum = q.conjugate() * angularMomentum;
    rotateAboutBodyAxis(0, 0.5 * dt, inertia, turned, bodyMomentum);
    rotateAboutBodyAxis(1, 0.5 * dt, inertia, turned, bodyMomentum);
    rotateAboutBodyAxis(2, dt, inertia, turned, bodyMomentum);
    rotateAboutBodyAxis(1, 0.5 * dt, inertia, turned, bodyMomentum);
    rotateAboutBodyAxis(0, 0.5 * dt, inertia, turned, bodyMomentum);
    turned.normalize();
    return turned;
}

//- Kinetic energy of rotation, L . omega / 2.
DEM_HD double rotationalEnergy(const Eigen::Quaterniond& q, const Vector3d& inertia,
                               const Vector3d& angularMomentum)
{
    const Vector3d bodyMomentum = q.conjugate() * angularMomentum;
    return 0.5 * bodyMomentum.dot(bodyMomentum.cwiseQuotient(inertia));
}

} // namespace DEM_KERNEL_NS
} // namespace detail
} // namespace dem

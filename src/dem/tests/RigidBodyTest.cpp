// RigidBodyTest.cpp
// Capsule mass properties against a direct integral over the body; torque-free rotation
// (NO_SQUISH): an asymmetric body keeps its angular momentum to round-off and its energy
// within a bounded O(dt^2) error without drift; a symmetric capsule follows the closed-form
// precession with an error falling as dt^2. Host-side: the evaluators are the same header for
// both backends.
#include "kernels/RigidBody.h"

#include <gtest/gtest.h>

#include <cstdio>

using dem::detail::Vector3d;
using Eigen::AngleAxisd;
using Eigen::Quaterniond;
namespace k = dem::detail;

namespace
{

//- Volume and second moments of a capsule (axis z) by integration over slices z: a slice is a
//- disc of radius rho(z) (r on the cylinder, sqrt(r^2 - (|z| - h)^2) on the caps) with area
//- pi rho^2, polar moment pi rho^4 / 2 and moment about a diameter pi rho^4 / 4; the x axis
//- adds z^2 per area (I_xx = int (y^2 + z^2) dV). Simpson on each of the three pieces (smooth
//- polynomials of z there), 20000 intervals: error ~ (interval)^4, far below 1e-10.
Vector3d integrateCapsule(double r, double h, double density, double& volume)
{
    double v = 0, axial = 0, perpendicular = 0;
    const double pieces[4] = {-h - r, -h, h, h + r};
    for (int p = 0; p < 3; ++p)
    {
        const int n = 20000;
        const double a = pieces[p], step = (pieces[p + 1] - a) / n;
        for (int s = 0; s <= n; ++s)
        {
            const double z = a + s * step;
            const double beyond = std::fabs(z) - h;
            const double rho2 = beyond > 0 ? std::max(0.0, r * r - beyond * beyond) : r * r;
            const double weight = (s == 0 || s == n ? 1.0 : (s % 2 ? 4.0 : 2.0)) * step / 3.0;
            v += weight * M_PI * rho2;
            axial += weight * M_PI * rho2 * rho2 / 2.0;
            perpendicular += weight * (M_PI * rho2 * rho2 / 4.0 + z * z * M_PI * rho2);
        }
    }
    volume = v;
    return density * Vector3d(perpendicular, perpendicular, axial);
}

} // namespace

TEST(RigidBody, CapsuleMassPropertiesMatchTheVolumeIntegral)
{
    const double density = 917.0; // ice
    for (double aspect : {0.0, 0.25, 1.0, 3.0})
    {
        const double r = 0.002, h = aspect * r;
        double volume;
        const Vector3d inertia = integrateCapsule(r, h, density, volume);
        const k::MassProperties p = k::capsuleMassProperties(r, h, density);
        std::printf("  h/r %.2f: V %.12e (integral %.12e), I_perp %.12e (%.12e), I_axial %.12e "
                    "(%.12e)\n",
                    aspect, p.volume, volume, p.inertia.x(), inertia.x(), p.inertia.z(),
                    inertia.z());
        EXPECT_NEAR(p.volume / volume, 1.0, 1e-10);
        EXPECT_NEAR(p.mass / (density * volume), 1.0, 1e-10);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(p.inertia[c] / inertia[c], 1.0, 1e-10) << "component " << c;
    }
    // h = 0 is the sphere: 2/5 m r^2.
    const k::MassProperties sphere = k::capsuleMassProperties(0.01, 0.0, 2600.0);
    EXPECT_NEAR(sphere.inertia.z() / (0.4 * sphere.mass * 1e-4), 1.0, 1e-14);
    EXPECT_NEAR(sphere.inertia.x() / sphere.inertia.z(), 1.0, 1e-14);
}

namespace
{

struct RotationRun
{
    double energyErrorFirstHalf = 0, energyErrorSecondHalf = 0, momentumError = 0, normError = 0;
    Quaterniond q;
};

//- Torque-free rotation for a time T in steps of dt, as the engine does it (L fixed between
//- kicks; the body's angular velocity read back through angularVelocityOf).
RotationRun rotate(const Vector3d& inertia, const Vector3d& L, Quaterniond q, double dt, long steps)
{
    RotationRun run;
    const double energy0 = k::rotationalEnergy(q, inertia, L);
    for (long s = 1; s <= steps; ++s)
    {
        q = k::freeRotation(q, inertia, L, dt);
        const double error = std::fabs(k::rotationalEnergy(q, inertia, L) / energy0 - 1.0);
        double& half = s <= steps / 2 ? run.energyErrorFirstHalf : run.energyErrorSecondHalf;
        half = std::max(half, error);
        const Vector3d omega = k::angularVelocityOf(q, inertia, L);
        run.momentumError = std::max(
            run.momentumError, (k::angularMomentumOf(q, inertia, omega) - L).norm() / L.norm());
        run.normError = std::max(run.normError, std::fabs(q.norm() - 1.0));
    }
    run.q = q;
    return run;
}

} // namespace

TEST(RigidBody, AsymmetricBodyConservesMomentumAndEnergy)
{
    // Principal moments 1 : 2 : 3, L off every axis, near the stable largest axis; about 50
    // body periods, |omega| dt = 0.02 and 0.01.
    const Vector3d inertia(1.0, 2.0, 3.0), L(0.4, -0.7, 2.5);
    const Quaterniond q0(AngleAxisd(0.3, Vector3d(1, 2, 3).normalized()));
    const double omega = k::angularVelocityOf(q0, inertia, L).norm();
    const double dt = 0.02 / omega;
    const RotationRun coarse = rotate(inertia, L, q0, dt, 20000);
    const RotationRun fine = rotate(inertia, L, q0, 0.5 * dt, 40000);
    std::printf("  |omega| dt 0.02: max energy error %.3e (first half), %.3e (second half); "
                "L error %.3e, | |q| - 1 | %.3e\n",
                coarse.energyErrorFirstHalf, coarse.energyErrorSecondHalf, coarse.momentumError,
                coarse.normError);
    std::printf("  |omega| dt 0.01: max energy error %.3e, %.3e\n", fine.energyErrorFirstHalf,
                fine.energyErrorSecondHalf);
    // L is held fixed and read back through R I R^T: round-off of a few operations per read,
    // not growing with the step count (1e-13 = ~500 ulp).
    EXPECT_LT(coarse.momentumError, 1e-13);
    EXPECT_LT(coarse.normError, 1e-13);
    // Symplectic, second order: the energy error is bounded, O((|omega| dt)^2) with an O(1)
    // constant (the commutators of the three sub-flows scale with the spread of the moments),
    // so below (|omega| dt)^2 = 4e-4; it does not drift (second half within 1.5 x the first: a
    // linear drift would double it) and falls by 2^2 = 4 when dt halves (3 to 5 allows for
    // where the maximum falls in the oscillation).
    const double bound = 0.02 * 0.02;
    EXPECT_LT(coarse.energyErrorFirstHalf, bound);
    EXPECT_LT(coarse.energyErrorSecondHalf, 1.5 * coarse.energyErrorFirstHalf);
    const double ratio = coarse.energyErrorSecondHalf / fine.energyErrorSecondHalf;
    std::printf("  energy error ratio dt / (dt/2): %.3f (second order: 4)\n", ratio);
    EXPECT_GT(ratio, 3.0);
    EXPECT_LT(ratio, 5.0);
}

TEST(RigidBody, SymmetricCapsulePrecessesAtTheClosedFormRate)
{
    // Capsule r = 1, h = 2 (rho = 1): I_perp > I_axial. L at 30 degrees from the axis.
    const k::MassProperties p = k::capsuleMassProperties(1.0, 2.0, 1.0);
    const Vector3d inertia = p.inertia;
    const Quaterniond q0(AngleAxisd(-0.4, Vector3d(0, 1, 0))); // axis 53 degrees from L
    const Vector3d L = 3.0 * Vector3d(std::sin(M_PI / 6), 0, std::cos(M_PI / 6));
    // Exact: R(t) = Rot(L/|L|, |L|/I_perp t) R_0 Rot(e_z, psi' t), the axis precessing about L
    // at |L|/I_perp and the body spinning about its axis at psi' = Lb_z (1/I_axial - 1/I_perp).
    const double precession = L.norm() / inertia.x();
    const double spin = (q0.conjugate() * L).z() * (1.0 / inertia.z() - 1.0 / inertia.x());
    const double T = 4.0 * 2.0 * M_PI / precession; // four precession periods
    const double omega = k::angularVelocityOf(q0, inertia, L).norm();
    std::printf("  I_perp %.6f, I_axial %.6f, |L|/I_perp %.6f, body-frame rate %.6f\n", inertia.x(),
                inertia.z(), precession, spin);
    double previous = 0, previousAngle = 0;
    for (int level = 0; level < 3; ++level)
    {
        const long steps = std::lround(T * omega / 0.05) << level; // |omega| dt = 0.05 / 2^l
        const double dt = T / steps;
        const RotationRun run = rotate(inertia, L, q0, dt, steps);
        const Quaterniond exact = Quaterniond(AngleAxisd(precession * T, L.normalized())) * q0 *
                                  Quaterniond(AngleAxisd(spin * T, Vector3d::UnitZ()));
        const double error = run.q.angularDistance(exact);
        // The axis's precession angle about L, measured against the closed form.
        const Vector3d axis0 = q0 * Vector3d::UnitZ(), axis = run.q * Vector3d::UnitZ();
        const Vector3d l = L.normalized();
        const Vector3d a0 = (axis0 - axis0.dot(l) * l).normalized();
        const Vector3d a1 = (axis - axis.dot(l) * l).normalized();
        const double turned = std::atan2(l.dot(a0.cross(a1)), a0.dot(a1)); // mod 2 pi
        const double angleError = std::fabs(std::remainder(turned - precession * T, 2 * M_PI));
        std::printf("  |omega| dt %.4f: orientation error %.3e rad, axis precession angle "
                    "error %.3e rad (of %.3f)\n",
                    omega * dt, error, angleError, precession * T);
        // Second order: halving dt divides the errors by 4 (3.5 to 4.5: the next term is
        // O(dt^4), relatively (|omega| dt)^2 < 2.5e-3 here).
        if (level > 0)
        {
            std::printf("    ratios to the previous dt: %.3f, %.3f\n", previous / error,
                        previousAngle / angleError);
            EXPECT_GT(previous / error, 3.5);
            EXPECT_LT(previous / error, 4.5);
            EXPECT_GT(previousAngle / angleError, 3.5);
            EXPECT_LT(previousAngle / angleError, 4.5);
        }
        // The coarsest run is already close: (|omega| dt)^2 per unit of the angle turned.
        EXPECT_LT(angleError, omega * dt * omega * dt * precession * T);
        previous = error;
        previousAngle = angleError;
    }
}

// SnowContactTest.cpp
// The snow contact law's evaluator against its closed form for a head-on impact of two
// grains, integrated over time with the engine's velocity-Verlet (half kick, drift, force at
// the new position and half-step velocity, half kick); its stiffness and damping per pair;
// the tangential spring (k_t = 0.6 k_n) and its Coulomb cap; and the linear spring law's pair
// overload unchanged. Host-side: the evaluators are the same header for both backends.
#include "kernels/LinearSpringContact.h"
#include "kernels/SnowContact.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>

using dem::detail::ContactPair;
using dem::detail::LinearSpringContact;
using dem::detail::SnowContact;
using dem::detail::Vector3d;

namespace
{

//- Closed form of the clipped damped spring, m* x'' = -max(0, k x + c x'), x(0) = 0,
//- x'(0) = v0 > 0 (x the overlap), with omega_0 = sqrt(k/m*), zeta = c / (2 sqrt(k m*)) < 1,
//- omega_d = omega_0 sqrt(1 - zeta^2).
//- While the force pushes, x = v0/omega_d e^(-zeta omega_0 t) sin(omega_d t) and
//-   x' = v0 e^(-zeta omega_0 t) (cos(omega_d t) - zeta omega_0/omega_d sin(omega_d t)),
//- so with k = m* omega_0^2 and c = 2 zeta m* omega_0,
//-   k x + c x' = m* v0 e^(-zeta omega_0 t) [omega_0 (1 - 2 zeta^2)/sqrt(1 - zeta^2) sin(omega_d t)
//-                                           + 2 zeta omega_0 cos(omega_d t)],
//- zero when tan(omega_d t) = -2 zeta sqrt(1 - zeta^2) / (1 - 2 zeta^2) = -tan(2 phi), with
//- sin(phi) = zeta: the force ends at omega_d t_f = pi - 2 arcsin(zeta), before the undamped
//- half period, while the grains still overlap. There cos(omega_d t_f) = -(1 - 2 zeta^2) and
//- sin(omega_d t_f) = 2 zeta sqrt(1 - zeta^2), so the bracket of x' is 1 - 2 zeta^2 + 2 zeta^2
//- = 1: the grains leave with x'(t_f) = -v0 e^(-zeta omega_0 t_f), restitution
//-   e = exp(-zeta (pi - 2 arcsin zeta) / sqrt(1 - zeta^2)),
//- and fly apart force-free: the overlap closes at t_f + x(t_f) / |x'(t_f)|.
struct ClippedSpring
{
    double forceDuration, restitution, contactDuration;
};

ClippedSpring closedForm(double reducedMass, double k, double zeta, double v0)
{
    const double omega0 = std::sqrt(k / reducedMass);
    const double omegaD = omega0 * std::sqrt(1.0 - zeta * zeta);
    ClippedSpring c;
    c.forceDuration = (M_PI - 2.0 * std::asin(zeta)) / omegaD;
    c.restitution = std::exp(-zeta * omega0 * c.forceDuration);
    const double overlapAtEnd = v0 / omegaD * std::exp(-zeta * omega0 * c.forceDuration) *
                                std::sin(omegaD * c.forceDuration);
    c.contactDuration = c.forceDuration + overlapAtEnd / (c.restitution * v0);
    return c;
}

struct Grain
{
    Vector3d x, v;
    double inverseMass;
};

//- Two grains of radius R approach head-on along x; the engine's velocity-Verlet with the
//- evaluator; times of the force's end and of separation interpolated linearly between steps.
ClippedSpring simulate(const SnowContact& law, double R, Grain a, Grain b, double& omega0)
{
    const ContactPair pair{R, R, a.inverseMass, b.inverseMass};
    const double dt = law.timeStep;
    const double kn = law.normalStiffness(pair);
    const double reducedMass = 1.0 / (a.inverseMass + b.inverseMass);
    omega0 = std::sqrt(kn / reducedMass);
    const double cn = 2.0 * law.normalDampingRatio * std::sqrt(reducedMass * kn);
    const double approach0 = (a.v - b.v).norm();
    Vector3d history = Vector3d::Zero(), force = Vector3d::Zero(); // force on a
    double start = -1, forceEnd = -1, end = -1, previousOverlap = 0, previousSpring = 0;
    for (long s = 1; s < 1000000 && end < 0; ++s)
    {
        a.v += 0.5 * dt * a.inverseMass * force;
        b.v -= 0.5 * dt * b.inverseMass * force;
        a.x += dt * a.v;
        b.x += dt * b.v;
        const Vector3d d = b.x - a.x;
        const Vector3d n = d.normalized();
        const double overlap = 2.0 * R - d.norm();
        force.setZero();
        const double t = s * dt;
        // Unclipped k delta + c delta', as the law sees it (half-step velocities).
        const double spring = kn * overlap + cn * (a.v - b.v).dot(n);
        if (overlap > 0)
        {
            Vector3d tangentialForce;
            const double fn = law.forces(n, overlap, a.v - b.v, history, tangentialForce, pair);
            EXPECT_GE(fn, 0.0);
            force = tangentialForce - fn * n;
            if (previousOverlap <= 0)
                start = t - dt * overlap / (overlap - previousOverlap);
        }
        if (start > 0 && forceEnd < 0 && previousSpring > 0 && spring <= 0)
            forceEnd = t - dt * spring / (spring - previousSpring);
        if (previousOverlap > 0 && overlap <= 0)
            end = t - dt * overlap / (overlap - previousOverlap);
        previousOverlap = overlap;
        previousSpring = spring;
        a.v += 0.5 * dt * a.inverseMass * force;
        b.v -= 0.5 * dt * b.inverseMass * force;
    }
    EXPECT_GT(start, 0.0);
    EXPECT_GT(forceEnd, start);
    EXPECT_GE(end, forceEnd); // equal without damping
    return {forceEnd - start, (b.v - a.v).norm() / approach0, end - start};
}

} // namespace

TEST(SnowContact, HeadOnImpactMatchesTheClippedDampedSpring)
{
    // Ice grains R = 1 mm of unequal mass, E = 10 MPa (a soft unfrozen contact), meeting at
    // 0.5 m/s along a skewed line, for damping ratios 0 (elastic), 0.2 and 0.5.
    const double R = 1e-3, E = 1e7;
    const double mass = 917.0 * 4.0 / 3.0 * M_PI * R * R * R;
    const Vector3d line = Vector3d(1, 2, -0.5).normalized();
    for (double zeta : {0.0, 0.2, 0.5})
    {
        const double kn = E * M_PI * R / 2.0; // E pi Rbar / 2 with Rbar = R
        const double reducedMass = 1.0 / (1.0 / mass + 1.0 / (2.0 * mass));
        const double tc = M_PI / std::sqrt(kn / reducedMass);
        const double dt = tc / 2000.0;
        const SnowContact law = SnowContact::make(E, 0.6, zeta, 0.3, 0.5, dt);
        Grain a{Vector3d::Zero(), 0.5 * line, 1.0 / mass};
        Grain b{(2.0 * R + 1e-6) * line, Vector3d::Zero(), 1.0 / (2.0 * mass)};
        double omega0;
        const ClippedSpring sim = simulate(law, R, a, b, omega0);
        const ClippedSpring ref = closedForm(reducedMass, kn, zeta, 0.5);
        std::printf("  zeta %.1f: force duration %.6e s (closed form %.6e), restitution %.6f "
                    "(%.6f), contact duration %.6e (%.6e)\n",
                    zeta, sim.forceDuration, ref.forceDuration, sim.restitution, ref.restitution,
                    sim.contactDuration, ref.contactDuration);
        // Velocity-Verlet is second order for the spring alone, but the dashpot sees the
        // half-step velocity, v_{n+1} - a dt/2: a damping force off by O(c a dt), i.e. relative
        // errors O(zeta omega_0 dt) in the decay; the interpolated crossing times add
        // O((omega_0 dt)^2). omega_0 dt = pi/2000 = 1.6e-3: tolerance 2 omega_0 dt.
        const double tolerance = 2.0 * omega0 * dt;
        EXPECT_NEAR(sim.forceDuration / ref.forceDuration, 1.0, tolerance);
        EXPECT_NEAR(sim.restitution / ref.restitution, 1.0, tolerance);
        EXPECT_NEAR(sim.contactDuration / ref.contactDuration, 1.0, tolerance);
    }
}

TEST(SnowContact, StiffnessDampingAndCoulombCap)
{
    const double E = 2e6, dt = 1e-6, mu = 0.4;
    const SnowContact law = SnowContact::make(E, 0.6, 0.3, 0.2, mu, dt);
    const ContactPair pair{1e-3, 3e-3, 1.0 / 2e-6, 1.0 / 6e-6};
    const double kn = E * M_PI * 2e-3 / 2.0, reducedMass = 1.5e-6;
    EXPECT_NEAR(law.normalStiffness(pair) / kn, 1.0, 1e-15);
    const Vector3d n(0, 0, 1);
    // Normal: k_n delta + c_n delta' with c_n = 2 zeta sqrt(m* k_n); pulling is clipped to 0.
    Vector3d history = Vector3d::Zero(), ft;
    const double cn = 2.0 * 0.3 * std::sqrt(reducedMass * kn);
    double fn = law.forces(n, 1e-5, Vector3d(0, 0, 0.01), history, ft, pair);
    EXPECT_NEAR(fn / (kn * 1e-5 + cn * 0.01), 1.0, 1e-14);
    fn = law.forces(n, 1e-5, Vector3d(0, 0, -10.0), history, ft, pair);
    EXPECT_EQ(fn, 0.0);
    EXPECT_EQ(ft.norm(), 0.0) << "no normal force, no friction";
    // Tangential: one step of sliding velocity w builds xi = w dt; F_t = -k_t xi - c_t w,
    // k_t = 0.6 k_n, c_t = 2 zeta_t sqrt(m* k_t), well below the cap.
    const double kt = 0.6 * kn, ct = 2.0 * 0.2 * std::sqrt(reducedMass * kt);
    history.setZero();
    const Vector3d w(1e-4, 0, 0);
    fn = law.forces(n, 1e-5, w, history, ft, pair);
    std::printf("  k_n %.6e N/m, F_n %.6e N, F_t %.6e N (spring and dashpot %.6e)\n", kn, fn,
                ft.x(), -kt * 1e-4 * dt - ct * 1e-4);
    EXPECT_NEAR(ft.x() / (-kt * 1e-4 * dt - ct * 1e-4), 1.0, 1e-14);
    EXPECT_NEAR(history.x() / (1e-4 * dt), 1.0, 1e-14);
    // Gross slip: |F_t| = mu F_n and the spring shortened to mu F_n / k_t.
    history = Vector3d(1.0, 0, 0);
    fn = law.forces(n, 1e-5, Vector3d::Zero(), history, ft, pair);
    EXPECT_NEAR(ft.norm() / (mu * fn), 1.0, 1e-14);
    EXPECT_NEAR(history.norm() / (mu * fn / kt), 1.0, 1e-14);
    // A wall: radiusJ = radiusI and inverseMassJ = 0, so Rbar = R_i and m* = m_i.
    const ContactPair wall{1e-3, 1e-3, 1.0 / 2e-6, 0.0};
    EXPECT_NEAR(law.normalStiffness(wall) / (E * M_PI * 1e-3 / 2.0), 1.0, 1e-15);
    history.setZero();
    fn = law.forces(n, 0.0, Vector3d(0, 0, 0.01), history, ft, wall);
    EXPECT_NEAR(fn / (2.0 * 0.3 * std::sqrt(2e-6 * E * M_PI * 1e-3 / 2.0) * 0.01), 1.0, 1e-14);
}

TEST(SnowContact, LinearSpringPairOverloadIsTheLawUnchanged)
{
    const LinearSpringContact law = LinearSpringContact::make(1e6, 8e5, 3.0, 2.0, 0.5, 1e-6);
    const ContactPair pair{1e-3, 2e-3, 5.0, 7.0};
    const Vector3d n = Vector3d(1, -2, 0.3).normalized();
    for (int c = 0; c < 100; ++c)
    {
        const Vector3d velocity(0.01 * std::sin(c), 0.02 * std::cos(3 * c), 0.005 * c);
        Vector3d h1(1e-7 * c, -2e-8 * c, 3e-8), h2 = h1, f1, f2;
        const double a = law.forces(n, 1e-6 * c, velocity, h1, f1);
        const double b = law.forces(n, 1e-6 * c, velocity, h2, f2, pair);
        EXPECT_EQ(std::memcmp(&a, &b, sizeof a), 0);
        for (int k = 0; k < 3; ++k)
        {
            EXPECT_EQ(f1[k], f2[k]);
            EXPECT_EQ(h1[k], h2[k]);
        }
    }
}

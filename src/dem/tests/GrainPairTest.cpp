// GrainPairTest.cpp
// Tangential contact law between two grains (the grain-wall cases are in FrictionTest.cpp):
//  - two spheres pressed together and sliding past each other: |f_t| = mu f_n once sliding,
//    equal torques (r - overlap/2) n x f_t on both grains (equal radii), and the total angular
//    momentum (orbital about the centre of mass plus spins) conserved to round-off;
//  - a stuck contact in a pair that rotates rigidly while one grain spins slowly on top of that
//    rotation: the tangential spring grows as k_t (r - overlap/2) omega_s t from the relative
//    spin alone and stays in the current tangent plane; the rigid rotation turns the spring
//    with the pair and does not stretch it.
#include "TestSupport.h"

using namespace demTest;

namespace
{

Vec3 cross(const Vec3& a, const Vec3& b)
{
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec3 scaled(const Vec3& a, double s)
{
    return {s * a[0], s * a[1], s * a[2]};
}
Vec3 add(const Vec3& a, const Vec3& b)
{
    return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}

class GrainPair : public BackendTest
{
protected:
    const double r = 0.01;

    //- Unit normal from grain 0 to grain 1, the overlap, and the tangential part of the
    //- contact force on grain 1 (no gravity, no fluid: the force is the contact's).
    struct Contact
    {
        Vec3 n, tangentialForce;
        double overlap, normalForce;
    };
    Contact contact(const dem::GrainData& g) const
    {
        Contact c;
        const Vec3 d = sub(at(g.position, 1), at(g.position, 0));
        const double distance = norm(d);
        c.n = scaled(d, 1.0 / distance);
        c.overlap = 2 * r - distance;
        const Vec3 f = at(g.force, 1);
        c.normalForce = dot(f, c.n); // > 0: pushes grain 1 away from grain 0
        c.tangentialForce = sub(f, scaled(c.n, c.normalForce));
        return c;
    }
};

} // namespace

//- Grains of 2600 kg/m^3 overlapping by 2e-5 m along z (f_n = 20 N), grain 1 moving at +1 m/s
//- and grain 0 at -1 m/s along x: the spring reaches mu f_n = 10 N after five steps of
//- 2e-6 m; from then on the contact slides. 50 steps: the grains separate by 5e-6 m of the
//- overlap and the normal turns by 5e-3 rad, so the contact stays closed.
TEST_P(GrainPair, SlidingFrictionTorquesAndAngularMomentum)
{
    dem::Parameters p = parameters();
    const double mu = p.grainGrain.friction, kn = p.grainGrain.normalStiffness;
    dem::System s(p);
    const double overlap0 = 2e-5, speed = 1.0;
    dem::GrainInit a, b;
    a.radius = b.radius = r;
    a.position = {0.5, 0.5, 0.5};
    b.position = {0.5, 0.5, 0.5 + 2 * r - overlap0};
    a.velocity = {-speed, 0.0, 0.0};
    b.velocity = {speed, 0.0, 0.0};
    s.addGrains({a, b});

    // Angular momentum about the centre of mass (fixed: the total momentum is zero) plus spins
    const auto angularMomentum = [&](const dem::GrainData& g)
    {
        const Vec3 centre = scaled(add(at(g.position, 0), at(g.position, 1)), 0.5);
        Vec3 total{0.0, 0.0, 0.0};
        for (std::size_t i = 0; i < 2; ++i)
        {
            const double inertia = 0.4 * g.mass[i] * g.radius[i] * g.radius[i];
            total = add(
                total, scaled(cross(sub(at(g.position, i), centre), at(g.velocity, i)), g.mass[i]));
            total = add(total, scaled(at(g.angularVelocity, i), inertia));
        }
        return total;
    };
    const Vec3 L0 = angularMomentum(s.grains());

    double worstRatio = 0, worstTorque = 0, worstLever = 0;
    int sliding = 0;
    for (int step = 1; step <= 50; ++step)
    {
        s.step(1);
        const dem::GrainData g = s.grains();
        const Contact c = contact(g);
        ASSERT_GT(c.overlap, 0.0) << "the grains separated at step " << step;
        // Normal force k_n overlap (no damping), from the same positions the step ended at
        EXPECT_NEAR(c.normalForce / (kn * c.overlap), 1.0, 1e-9);
        const double ft = norm(c.tangentialForce);
        if (step >= 10) // sliding: capped at mu f_n, opposing grain 1's motion (+x)
        {
            ++sliding;
            worstRatio = std::max(worstRatio, std::fabs(ft / (mu * c.normalForce) - 1.0));
            EXPECT_LT(c.tangentialForce[0], 0.0);
        }
        else
            EXPECT_LE(ft, mu * c.normalForce * (1 + 1e-12));
        // Torques: equal on both grains (equal radii), lever (r - overlap/2), n x f_t
        const Vec3 expected = scaled(cross(c.n, c.tangentialForce), -(r - 0.5 * c.overlap));
        const Vec3 t0 = at(g.torque, 0), t1 = at(g.torque, 1);
        worstTorque = std::max(worstTorque, norm(sub(t0, t1)) / norm(t1));
        worstLever = std::max(worstLever, norm(sub(t1, expected)) / norm(expected));
    }
    const dem::GrainData g = s.grains();
    const Vec3 L = angularMomentum(g);
    const double transferred =
        norm(scaled(at(g.angularVelocity, 0), 0.4 * g.mass[0] * g.radius[0] * g.radius[0])) * 2;
    const double drift = norm(sub(L, L0));
    std::printf("  sliding steps %d: max | |f_t|/(mu f_n) - 1 | %.2e; torque 0 vs 1 %.2e, vs "
                "(r - overlap/2) n x f_t %.2e; |L - L0| %.2e of the spin angular momentum "
                "exchanged %.3e N m s\n",
                sliding, worstRatio, worstTorque, worstLever, drift / transferred, transferred);
    // Round-off: the cap is one product and one square root; the torque one cross product
    EXPECT_LT(worstRatio, 1e-12);
    EXPECT_LT(worstTorque, 1e-12);
    EXPECT_LT(worstLever, 1e-12);
    // Velocity Verlet kicks orbital and spin momentum with forces and torques from the same
    // positions, whose moments cancel exactly (lever arms sum to the centre distance); drifts
    // do not change x m v. What is left is round-off of the sums (~1e-16 of the orbital
    // 2e-4 N m s per step, 50 steps), far below 1e-10 of the exchanged spin.
    EXPECT_LT(drift / transferred, 1e-10);
    EXPECT_GT(transferred, 0.0);
}

//- Two grains of 1e12 kg/m^3 (the contact's forces and torques change their motion by < 1e-6
//- over the run) overlapping by 2e-5 m along z (f_n = 20 N, mu f_n = 10 N). The pair rotates
//- rigidly about y through its centre at Omega = 5 rad/s (velocities Omega x (x - c), both
//- spins Omega); grain 1 spins at Omega + omega_s, omega_s = 0.8 rad/s. The contact's relative
//- tangential velocity is (r - overlap/2) omega_s alone, so after t the spring holds
//- xi = (r - overlap/2) omega_s t (8e-6 m after 1e-3 s: stuck, k_t xi = 8 N < 10 N), turned
//- with the pair by Omega t = 5e-3 rad.
TEST_P(GrainPair, StuckSpringFollowsRigidRotation)
{
    dem::Parameters p = parameters();
    const double kt = p.grainGrain.tangentialStiffness, kn = p.grainGrain.normalStiffness;
    p.defaultDensity = 1e12;
    p.timeStep = 1e-6;
    dem::System s(p);
    const double overlap = 2e-5, Omega = 5.0, omegaS = 0.8, duration = 1e-3;
    const Vec3 centre{0.5, 0.5, 0.5 + r - 0.5 * overlap};
    dem::GrainInit a, b;
    a.radius = b.radius = r;
    a.position = {0.5, 0.5, 0.5};
    b.position = {0.5, 0.5, 0.5 + 2 * r - overlap};
    const Vec3 axis{0.0, 1.0, 0.0};
    const Vec3 va = cross(scaled(axis, Omega), sub({0.5, 0.5, 0.5}, centre));
    a.velocity = {va[0], va[1], va[2]};
    b.velocity = {-va[0], -va[1], -va[2]};
    a.angularVelocity = {0.0, Omega, 0.0};
    b.angularVelocity = {0.0, Omega + omegaS, 0.0};
    s.addGrains({a, b});

    const int steps = int(std::lround(duration / p.timeStep));
    double worstMagnitude = 0, worstPlane = 0, worstTurn = 0;
    for (int chunk = 1; chunk <= 10; ++chunk)
    {
        s.step(steps / 10);
        const dem::GrainData g = s.grains();
        const Contact c = contact(g);
        const double t = s.time();
        const double lever = r - 0.5 * c.overlap;
        const double expected = kt * lever * omegaS * t;
        const double ft = norm(c.tangentialForce);
        worstMagnitude = std::max(worstMagnitude, std::fabs(ft / expected - 1.0));
        // In the current tangent plane: the normal part of the force is the normal law's
        // k_n overlap exactly, so the spring adds nothing along n(t) (a spring left in the
        // start frame would add k_t xi sin(Omega t), 2.5e-3 of |f_t| here); and it stays in
        // the plane of the rotation (no y part)
        worstPlane = std::max(worstPlane, std::fabs(c.normalForce - kn * c.overlap) / ft);
        worstTurn = std::max(worstTurn, std::fabs(c.tangentialForce[1]) / ft);
        const double turn = std::atan2(c.n[0], c.n[2]); // angle of n from z about y
        if (chunk == 10)
            std::printf("  t %.1e s: |f_t| %.9f N, k_t l omega_s t %.9f N (rel. %.1e); pair "
                        "turned %.3e rad (Omega t %.3e)\n",
                        t, ft, expected, ft / expected - 1.0, turn, Omega * t);
    }
    std::printf("  max |f_t/(k_t l omega_s t) - 1| %.2e; along n(t) %.1e of |f_t|; along y %.1e\n",
                worstMagnitude, worstPlane, worstTurn);
    // Integration error of the magnitude: (i) the grains fly on straight lines (contacts do not
    // attract), so the relative contact velocity gains a tangential part ~ Omega^3 d t^2, i.e.
    // (d (Omega t)^3 / 3) / (l omega_s t) = 1.3e-4 of the spring at the end; (ii) the spring's
    // torque slows the spin by k_t l^2 t^2 / (2 I) ~ 1e-9. Tolerance 3e-4, twice (i).
    EXPECT_LT(worstMagnitude, 3e-4);
    // Round-off: the overlap (2e-5 m) is a difference of positions ~0.5 m, 1e-16 of which is
    // 5e-12 of it, i.e. 1e-10 N of f_n against |f_t| ~ 1..8 N
    EXPECT_LT(worstPlane, 1e-9);
    EXPECT_LT(worstTurn, 1e-12);
    // and the pair really turned, with the spring
    EXPECT_NEAR(std::atan2(contact(s.grains()).n[0], contact(s.grains()).n[2]) / (Omega * duration),
                1.0, 1e-3);
}

DEM_TEST_ON_ALL_BACKENDS(GrainPair);

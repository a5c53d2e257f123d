// BondLawTest.cpp
// The bond evaluator (kernels/bonds) against closed forms, called directly on the host: the
// header is the one both backends compile. Geometry of bonded grains apart; elastic slopes and
// sign rules of the four modes; balance of the loads; loads of a pair turning as a rigid body;
// Maxwell relaxation, its exact constant-rate response and its stability at dt >> tau;
// compressive power-law creep; tensile and shear rupture at the ice strength; the softening
// sequence of r_b; sintering at constant load; the dashpots.
#include "kernels/bonds/BondLaw.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>

using dem::BondParameters;
using dem::detail::BondGeometry;
using dem::detail::bondGeometry;
using dem::detail::BondLaw;
using dem::detail::BondLoads;
using dem::detail::BondMotion;
using dem::detail::BondState;
using dem::detail::Vector3d;

namespace
{

// Two ice spheres of R = 1 mm side by side along x, touching, with a patch r_b = 0.3 R.
constexpr double R = 1e-3, rb = 0.3e-3, E = 1e7, dt = 1e-6;
const double area = M_PI * rb * rb, bendI = M_PI * rb * rb * rb * rb / 4.0, twistJ = 2.0 * bendI;
const double kne = E / (2.0 * R), kse = 0.6 * kne;

BondParameters elastic()
{
    BondParameters p;
    p.enabled = true;
    p.youngsModulus = E;
    p.shearToNormalStiffness = 0.6;
    return p;
}

//- Strengths 1 MPa in tension and shear, softening ratio rho = 0.5 (the branch at zero at
//- x = delta/delta_1 = 3), broken below brokenFraction Rbar.
BondParameters softening(double brokenFraction)
{
    BondParameters p = elastic();
    p.strength = dem::BondStrength::constant;
    p.tensileStrength = 1e6;
    p.shearStrength = 1e6;
    p.softeningRatio = 0.5;
    p.brokenFraction = brokenFraction;
    return p;
}

BondGeometry touching()
{
    return bondGeometry(Vector3d(2.0 * R, 0, 0), Vector3d::Zero(), Vector3d::Zero(), R, R);
}

BondState fresh()
{
    BondState s;
    s.patchRadius = rb;
    return s;
}

//- B moves with velocity v and angular velocity w, A fixed (inverse masses 0: no dashpots).
BondMotion driven(const Vector3d& v, const Vector3d& w)
{
    return BondMotion{Vector3d::Zero(), v, Vector3d::Zero(), w, 0.0, 0.0};
}

double relative(double a, double b)
{
    return std::fabs(a - b) / std::fabs(b);
}

} // namespace

TEST(BondLaw, GeometryOfGrainsApart)
{
    // Spheres 0.2 mm apart: normal +x, gap 0.2 mm, contact point in the middle of the gap.
    double overlap;
    BondGeometry g = bondGeometry(Vector3d(2.2e-3, 0, 0), Vector3d::Zero(), Vector3d::Zero(), 1e-3,
                                  1e-3, overlap);
    EXPECT_NEAR(overlap, -0.2e-3, 1e-18);
    EXPECT_NEAR((g.normal - Vector3d(1, 0, 0)).norm(), 0.0, 1e-15);
    EXPECT_NEAR((g.offsetA - Vector3d(1.1e-3, 0, 0)).norm(), 0.0, 1e-18);
    EXPECT_NEAR((g.offsetB - Vector3d(-1.1e-3, 0, 0)).norm(), 0.0, 1e-18);
    // Crossed capsules (A along x, B along y, 3 mm above): closest core points are both centres
    // shifted by the axes' parameters 0; the gap 3 - 2 = 1 mm; the point 1.5 mm above A.
    const Vector3d aA(2e-3, 0, 0), aB(0, 2e-3, 0), d(0.5e-3, -0.7e-3, 3e-3);
    g = bondGeometry(d, aA, aB, 1e-3, 1e-3, overlap);
    EXPECT_NEAR(overlap, -1e-3, 1e-15);
    EXPECT_NEAR((g.normal - Vector3d(0, 0, 1)).norm(), 0.0, 1e-12);
    EXPECT_NEAR((g.offsetA - Vector3d(0.5e-3, 0, 1.5e-3)).norm(), 0.0, 1e-15);
    EXPECT_NEAR((g.offsetB - (g.offsetA - d)).norm(), 0.0, 1e-18);
}

TEST(BondLaw, ElasticSlopesAndSigns)
{
    // Fixed geometry, B driven for 100 steps: the incremental update must give exactly the
    // spring laws N = k_ne A u_n, S = k_se A u_t, M_t = k_se J theta_t, M_b = k_ne I theta_b
    // (sums of equal increments: relative error of round-off, 1e-12).
    const BondLaw law = BondLaw::make(elastic(), dt);
    const BondGeometry g = touching();
    const int steps = 100;
    const double t = steps * dt, v = 1e-3, w = 1e-1;
    struct Mode
    {
        const char* name;
        Vector3d velocity, omega;
    };
    for (const Mode& mode : {Mode{"pull", Vector3d(v, 0, 0), Vector3d::Zero()},
                             Mode{"shear", Vector3d(0, v, 0), Vector3d::Zero()},
                             Mode{"twist", Vector3d::Zero(), Vector3d(w, 0, 0)},
                             Mode{"bend", Vector3d::Zero(), Vector3d(0, 0, w)}})
    {
        BondState s = fresh();
        BondLoads loads;
        for (int i = 0; i < steps; ++i)
            loads = law.advance(s, g, driven(mode.velocity, mode.omega));
        std::printf("  %s: N %.9e N, S (%.3e %.3e %.3e) N, M_t %.9e N m, M_b (%.3e %.3e %.3e)\n",
                    mode.name, s.normalForce, s.shearForce.x(), s.shearForce.y(), s.shearForce.z(),
                    s.twistMoment, s.bendMoment.x(), s.bendMoment.y(), s.bendMoment.z());
        const std::string name = mode.name;
        if (name == "pull")
        {
            // Opening is tension (N > 0) and pulls A towards B (+x); no lever arm on A.
            EXPECT_LT(relative(s.normalForce, kne * area * v * t), 1e-12);
            EXPECT_LT(relative(loads.forceOnA.x(), kne * area * v * t), 1e-12);
            EXPECT_EQ(s.shearForce.norm(), 0.0);
            EXPECT_LT(loads.torqueOnA.norm(), 1e-12 * kne * area * v * t * R);
        }
        if (name == "shear")
        {
            // B moving +y drags A along +y; the force acts at R from A's centre: torque +z on A.
            EXPECT_LT(relative(s.shearForce.y(), kse * area * v * t), 1e-12);
            EXPECT_EQ(s.normalForce, 0.0);
            EXPECT_LT(relative(loads.torqueOnA.z(), R * kse * area * v * t), 1e-12);
            EXPECT_LT(relative(loads.torqueOnB.z(), R * kse * area * v * t), 1e-12);
        }
        if (name == "twist")
        {
            // B turning about +n turns A with it (+x on A) and is held back (-x on B).
            EXPECT_LT(relative(s.twistMoment, kse * twistJ * w * t), 1e-12);
            EXPECT_LT(relative(loads.torqueOnA.x(), kse * twistJ * w * t), 1e-12);
            EXPECT_LT(relative(-loads.torqueOnB.x(), kse * twistJ * w * t), 1e-12);
            EXPECT_EQ(s.shearForce.norm(), 0.0);
        }
        if (name == "bend")
        {
            // B turning about +z at its centre: bending k_ne I theta on A along +z, and its
            // contact point (at -R x from B's centre) moves by -R theta y: shear -k_se A R theta.
            EXPECT_LT(relative(s.bendMoment.z(), kne * bendI * w * t), 1e-12);
            EXPECT_LT(relative(s.shearForce.y(), -kse * area * R * w * t), 1e-12);
            EXPECT_EQ(s.normalForce, 0.0);
        }
    }
}

TEST(BondLaw, LoadsBalance)
{
    // Whatever the state and motion, the loads on A and B have zero resultant and zero moment
    // about any point (angular momentum is conserved): x_A x F + T_A + x_B x (-F) + T_B = 0.
    BondParameters p = elastic();
    p.normalDampingRatio = 0.3;
    p.shearDampingRatio = 0.2;
    const BondLaw law = BondLaw::make(p, dt);
    const Vector3d xA(0.3e-3, -0.1e-3, 0.2e-3), d(1.2e-3, 0.9e-3, -0.6e-3);
    const Vector3d aA(0.4e-3, 0.3e-3, 0), aB(0, -0.2e-3, 0.5e-3);
    const BondGeometry g = bondGeometry(d, aA, aB, 0.8e-3, 0.9e-3);
    BondState s = fresh();
    s.normalForce = 0.02;
    s.shearForce = Vector3d(0.01, -0.02, 0.005);
    s.twistMoment = 3e-6;
    s.bendMoment = Vector3d(-2e-6, 1e-6, 4e-6);
    const BondMotion m{Vector3d(0.01, 0.02, -0.01),
                       Vector3d(-0.03, 0.01, 0.02),
                       Vector3d(1.0, -2.0, 0.5),
                       Vector3d(0.3, 0.2, -1.0),
                       1.0 / 4e-6,
                       1.0 / 5e-6};
    const BondLoads loads = law.advance(s, g, m);
    const Vector3d xB = xA + d;
    const Vector3d moment =
        xA.cross(loads.forceOnA) + loads.torqueOnA - xB.cross(loads.forceOnA) + loads.torqueOnB;
    const double scale = loads.forceOnA.norm() * 1e-3 + loads.torqueOnA.norm();
    std::printf("  |moment sum| %.3e N m of %.3e\n", moment.norm(), scale);
    EXPECT_LT(moment.norm(), 1e-14 * scale); // round-off of a few cross products
    EXPECT_LT(std::fabs(s.shearForce.dot(g.normal)), 1e-14 * s.shearForce.norm());
    EXPECT_LT(std::fabs(s.bendMoment.dot(g.normal)), 1e-14 * s.bendMoment.norm());
}

TEST(BondLaw, RigidRotationTurnsTheLoads)
{
    // A loaded pair turning as a rigid body (omega about an axis off every symmetry) creates
    // no deformation: the loads keep their size and turn with the pair. The Cayley rotation is
    // exact but for its angle, |theta| - |theta|^3/12 per step, so after 1000 steps of
    // |theta| = 1e-3 the loads' direction is off by ~1e-7 rad (tolerance 1e-6).
    const BondLaw law = BondLaw::make(elastic(), dt);
    const Vector3d omega = Vector3d(0.2, 0.5, 1.0).normalized() * (1e-3 / dt);
    const Vector3d aA(0.5e-3, 0, 0.2e-3), aB(0, 0.4e-3, 0.1e-3);
    Vector3d xA(0, 0, 0), xB(1.0e-3, 0.8e-3, 1.2e-3);
    BondGeometry g = bondGeometry(xB - xA, aA, aB, R, R);
    BondState s = fresh();
    s.normalForce = -0.01;
    const Vector3d t1 = g.normal.cross(Vector3d(0, 0, 1)).normalized();
    s.shearForce = 0.02 * t1;
    s.bendMoment = 1e-6 * g.normal.cross(t1);
    const Vector3d S0 = s.shearForce, M0 = s.bendMoment;
    Eigen::AngleAxisd turn(0.0, omega.normalized());
    for (int i = 0; i < 1000; ++i)
    {
        // Exact rigid motion over the step: positions and axes turned about the origin.
        const Eigen::AngleAxisd step(omega.norm() * dt, omega.normalized());
        xA = step * xA;
        xB = step * xB;
        turn = Eigen::AngleAxisd(turn.angle() + omega.norm() * dt, turn.axis());
        g = bondGeometry(xB - xA, turn * aA, turn * aB, R, R);
        const BondMotion m{omega.cross(xA), omega.cross(xB), omega, omega, 0.0, 0.0};
        law.advance(s, g, m);
    }
    const double directionS = (s.shearForce - turn * S0).norm() / S0.norm();
    const double directionM = (s.bendMoment - turn * M0).norm() / M0.norm();
    std::printf("  after %.3f rad: N %.9e (was -1e-2), shear off by %.3e, bend off by %.3e\n",
                turn.angle(), s.normalForce, directionS, directionM);
    EXPECT_LT(std::fabs(s.normalForce / -0.01 - 1.0), 1e-9); // only rounding of v dt
    EXPECT_LT(directionS, 1e-6);
    EXPECT_LT(directionM, 1e-6);
}

TEST(BondLaw, MaxwellRelaxationAndStability)
{
    // Contact viscosity nu_s: tau_shear = tau_twist = nu_s / (0.6 E), tau_bend = nu_s / E.
    BondParameters p = elastic();
    p.creep = dem::BondCreep::maxwell;
    p.contactViscosity = 1.0; // Pa s: tau_bend = 1e-7 s, tau_shear = 1.667e-7 s
    const double tauS = 1.0 / (0.6 * E), tauB = 1.0 / E;
    const BondGeometry g = touching();
    // 1. Constant rate from zero: the update is the exact solution X = K rate tau (1 - e^{-t/tau})
    //    for any dt (round-off, 1e-12). Shear with bending in one run (B sliding along y and
    //    turning about z), twist alone (its spin about n turns the stored in-plane loads).
    // 2. Then the motion stops (constant deformation): X = X_0 e^{-t/tau} (1e-12; the update
    //    multiplies by the exact e^{-dt/tau}).
    for (double step : {1e-9, 1e-5})
    {
        const BondLaw law = BondLaw::make(p, step);
        const double v = 3e-3, w = 1.0;
        const int n = 50;
        const double t = n * step;
        BondState s = fresh(), twist = fresh();
        for (int i = 0; i < n; ++i)
        {
            law.advance(s, g, driven(Vector3d(0, v, 0), Vector3d(0, 0, w)));
            law.advance(twist, g, driven(Vector3d::Zero(), Vector3d(w, 0, 0)));
        }
        // Bending about z at B's centre also shears the contact point by -R w (see above).
        const double shearRate = kse * area * (v - R * w), twistRate = kse * twistJ * w,
                     bendRate = kne * bendI * w;
        const double S = shearRate * tauS * -std::expm1(-t / tauS);
        const double Mt = twistRate * tauS * -std::expm1(-t / tauS);
        const double Mb = bendRate * tauB * -std::expm1(-t / tauB);
        std::printf("  dt %.0e s (dt/tau_b %.0e): S %.9e (%.9e), M_t %.9e (%.9e), "
                    "M_b %.9e (%.9e)\n",
                    step, step / tauB, s.shearForce.y(), S, twist.twistMoment, Mt, s.bendMoment.z(),
                    Mb);
        EXPECT_LT(relative(s.shearForce.y(), S), 1e-12);
        EXPECT_LT(relative(twist.twistMoment, Mt), 1e-12);
        EXPECT_LT(relative(s.bendMoment.z(), Mb), 1e-12);
        // The creep displacement: the imposed motion less the spring's, rate (t - X / (K rate)),
        // summed step by step (round-off of the difference: 1e-10).
        const double creepS = std::fabs(v - R * w) * (t + tauS * std::expm1(-t / tauS));
        const double creepT = w * (t + tauS * std::expm1(-t / tauS));
        const double creepB = w * (t + tauB * std::expm1(-t / tauB));
        std::printf("  creep: shear %.9e m (%.9e), twist %.9e (%.9e), bend %.9e rad (%.9e)\n",
                    s.creepShear, creepS, twist.creepTwist, creepT, s.creepBend, creepB);
        EXPECT_LT(relative(s.creepShear, creepS), 1e-10);
        EXPECT_LT(relative(twist.creepTwist, creepT), 1e-10);
        EXPECT_LT(relative(s.creepBend, creepB), 1e-10);
        EXPECT_EQ(s.creepNormal, 0.0);
        // Bounded at dt >> tau: never above the steady value K rate tau.
        EXPECT_LE(std::fabs(s.shearForce.y()), std::fabs(shearRate) * tauS * (1 + 1e-12));
        for (int i = 0; i < n; ++i)
        {
            law.advance(s, g, driven(Vector3d::Zero(), Vector3d::Zero()));
            law.advance(twist, g, driven(Vector3d::Zero(), Vector3d::Zero()));
        }
        const double decayS = std::exp(-t / tauS), decayB = std::exp(-t / tauB);
        std::printf("  relaxed over %.1e s: S/S0 %.9e (%.9e), M_b/M_b0 %.9e (%.9e)\n", t,
                    s.shearForce.y() / S, decayS, s.bendMoment.z() / Mb, decayB);
        if (decayS > 1e-200)
        {
            EXPECT_LT(relative(s.shearForce.y(), S * decayS), 1e-12);
            EXPECT_LT(relative(twist.twistMoment, Mt * decayS), 1e-12);
            EXPECT_LT(relative(s.bendMoment.z(), Mb * decayB), 1e-12);
        }
        else // dt = 100 tau: e^{-50 dt/tau} underflows, the loads are gone exactly.
        {
            EXPECT_EQ(s.shearForce.norm(), 0.0);
            EXPECT_EQ(twist.twistMoment, 0.0);
            EXPECT_EQ(s.bendMoment.norm(), 0.0);
        }
    }
    // Each mechanism can be switched off: shear creep off keeps the elastic S = k_se A u_t.
    p.shearCreep = false;
    const BondLaw law = BondLaw::make(p, 1e-9);
    BondState s = fresh();
    for (int i = 0; i < 10; ++i)
        law.advance(s, g, driven(Vector3d(0, 1e-3, 0), Vector3d::Zero()));
    EXPECT_LT(relative(s.shearForce.y(), kse * area * 1e-3 * 1e-8), 1e-12);
}

TEST(BondLaw, CompressivePowerLawCreep)
{
    // A bond compressed to sigma_0 and held: d sigma/dt = -E A(T) |sigma|^m, so
    // |sigma| = sigma_0 (1 + (m - 1) E A(T) sigma_0^{m-1} t)^{-1/(m-1)}, which the update solves
    // exactly over each step (round-off, 1e-10 after 1000 steps), at any dt.
    BondParameters p = elastic();
    p.compressiveCreep = dem::BondCompressiveCreep::powerLaw;
    p.temperature = -5.0;
    const double A = p.creepPrefactor * std::exp(-p.creepActivationEnergy / (8.314 * 268.15));
    const double m = 3.0; // the default exponent, the one A0's units (s^-1 Pa^-3) hold
    const BondGeometry g = touching();
    const double sigma0 = 2e5;
    for (double step : {1e-3, 1.0})
    {
        const BondLaw law = BondLaw::make(p, step);
        BondState s = fresh();
        s.normalForce = -sigma0 * area;
        const int n = 1000;
        for (int i = 0; i < n; ++i)
            law.advance(s, g, driven(Vector3d::Zero(), Vector3d::Zero()));
        const double t = n * step;
        const double sigma =
            sigma0 *
            std::pow(1.0 + (m - 1.0) * E * A * std::pow(sigma0, m - 1.0) * t, -1.0 / (m - 1.0));
        std::printf("  dt %.0e s: sigma after %.0e s %.9e Pa (closed form %.9e)\n", step, t,
                    -s.normalForce / area, sigma);
        EXPECT_LT(relative(-s.normalForce / area, sigma), 1e-10);
        // Held still, all the stress lost went into creep: (sigma0 - sigma) / k_ne (the 1e-10
        // of sigma above, over sigma0 - sigma ~ 2.6e-4 sigma0: 1e-6).
        EXPECT_LT(relative(s.creepNormal, (sigma0 - sigma) / kne), 1e-6);
    }
    // Steady compression at approach speed v: the creep rate balances it, 2 Rbar A(T) sigma^m
    // = v. With A0 = 4e-4 it settles in seconds (sigma about 1e5 Pa, relaxation time
    // sigma / (n k_ne v) = 0.35 s; 10 s run). The elastic step and the creep step alternate:
    // the steady stress is low by k_ne v dt = 2e-5 of it; tolerance 1e-4.
    p.creepPrefactor = 4e-4;
    const double v = 2e-5, step = 2e-5;
    const BondLaw law = BondLaw::make(p, step);
    BondState s = fresh();
    const double sigmaSteady = std::pow(v / (2.0 * R * A * 4e-4 / 0.00554458), 1.0 / m);
    s.normalForce = -0.5 * sigmaSteady * area;
    for (int i = 0; i < 500000; ++i)
        law.advance(s, g, driven(Vector3d(-v, 0, 0), Vector3d::Zero()));
    // Creep is the approach less the spring's shortening (round-off over 5e5 steps: 1e-9).
    const double approachLessElastic =
        v * 500000 * step - (-s.normalForce - 0.5 * sigmaSteady * area) / (kne * area);
    std::printf("  normal creep %.9e m, approach less elastic %.9e m\n", s.creepNormal,
                approachLessElastic);
    EXPECT_LT(relative(s.creepNormal, approachLessElastic), 1e-9);
    std::printf("  steady stress at %.0e m/s: %.6e Pa (creep law %.6e)\n", v, -s.normalForce / area,
                sigmaSteady);
    EXPECT_LT(relative(-s.normalForce / area, sigmaSteady), 1e-4);
    // Tension creeps as compression does (the contact points migrate out of the grains): a
    // bond held in tension relaxes as the mirror image of one held in compression, bit for
    // bit, and its net creep opens it by as much as the other's closes.
    BondState pulled = fresh(), pushed = fresh();
    pulled.normalForce = 0.3 * sigmaSteady * area;
    pushed.normalForce = -pulled.normalForce;
    for (int i = 0; i < 50000; ++i) // 1 s: |sigma| falls by about 8 %
    {
        law.advance(pulled, g, driven(Vector3d::Zero(), Vector3d::Zero()));
        law.advance(pushed, g, driven(Vector3d::Zero(), Vector3d::Zero()));
    }
    std::printf("  held in tension: N %.9e N from %.9e N, net creep %.6e m\n", pulled.normalForce,
                0.3 * sigmaSteady * area, pulled.normalCreepOffset);
    EXPECT_LT(pulled.normalForce, 0.3 * sigmaSteady * area * 0.99); // it did relax
    EXPECT_EQ(pulled.normalForce, -pushed.normalForce);
    EXPECT_EQ(pulled.normalCreepOffset, -pushed.normalCreepOffset);
    EXPECT_GT(pulled.normalCreepOffset, 0.0);
    EXPECT_EQ(pulled.creepNormal, pulled.normalCreepOffset); // one direction: path = net
}

TEST(BondLaw, NormalCreepStopsAtTheMeanRadius)
{
    // The paper keeps each contact point within R/2 of where it started (effective dilation
    // radii in (R/2, 3R/2)): the bond's net normal creep stays within +-Rbar. Pushed together
    // at 1 m/s with a creep law that lets it through (steady stress ~1e5 Pa), the net creep
    // reaches -Rbar = -R exactly and stays there; from then on the spring alone takes the
    // approach: N falls by k_ne A v dt per step, exactly as an elastic bond's.
    BondParameters p = elastic();
    p.compressiveCreep = dem::BondCompressiveCreep::powerLaw;
    p.temperature = -5.0;
    p.creepPrefactor = 20.0;
    const double v = 1.0, step = 1e-6;
    const BondLaw law = BondLaw::make(p, step);
    const BondGeometry g = touching();
    BondState s = fresh();
    int steps = 0;
    while (s.normalCreepOffset > -R && steps < 2000000)
    {
        law.advance(s, g, driven(Vector3d(-v, 0, 0), Vector3d::Zero()));
        ++steps;
    }
    std::printf("  net creep %.9e m after %d steps (-Rbar %.9e m), N %.6e N\n", s.normalCreepOffset,
                steps, -R, s.normalForce);
    ASSERT_EQ(s.normalCreepOffset, -R);
    const double N0 = s.normalForce;
    for (int i = 0; i < 100; ++i)
        law.advance(s, g, driven(Vector3d(-v, 0, 0), Vector3d::Zero()));
    EXPECT_EQ(s.normalCreepOffset, -R);
    EXPECT_LT(relative(s.normalForce - N0, -100 * kne * area * v * step), 1e-9);
}

TEST(BondLaw, RuptureAtTheIceStrength)
{
    // Pulled (or sheared) at constant speed, a brittle bond (softening ratio 1e3: the branch
    // falls to zero within 1e-3 delta_1) carries at most sigma_ice(T) A: sigma_ice(-10 C) =
    // 0.99648 + 0.45904 = 1.45552 MPa. The force per step grows by k A v dt = 1e-4 of the peak,
    // so the largest force seen is within 1e-3 of it; tolerance 1 %.
    BondParameters p = elastic();
    p.temperature = -10.0;
    p.strength = dem::BondStrength::iceTemperature;
    p.softeningRatio = 1e3;
    const BondLaw law = BondLaw::make(p, dt);
    const double sigmaIce = 1.45552e6;
    const BondGeometry g = touching();
    for (int mode = 0; mode < 2; ++mode)
    {
        const double k = mode == 0 ? kne : kse;
        const double v = 1e-4 * sigmaIce / (k * dt); // 1e-4 of delta_1 per step
        const Vector3d velocity = mode == 0 ? Vector3d(v, 0, 0) : Vector3d(0, 0, v);
        BondState s = fresh();
        double peak = 0;
        int steps = 0;
        while (!s.broken && steps < 100000)
        {
            const BondLoads loads = law.advance(s, g, driven(velocity, Vector3d::Zero()));
            peak = std::max(peak, loads.forceOnA.norm());
            ++steps;
        }
        std::printf("  %s: peak force %.6e N, sigma_ice A %.6e N, broken after %d steps\n",
                    mode == 0 ? "tension" : "shear", peak, sigmaIce * area, steps);
        EXPECT_TRUE(s.broken);
        EXPECT_NEAR(peak / (sigmaIce * area), 1.0, 0.01);
    }
}

TEST(BondLaw, SofteningSequence)
{
    // Pulled at constant speed with softening ratio rho = 0.5: past the onset x = delta/delta_1
    // = 1 the patch follows r_b = r_0 sqrt((1 - rho (x - 1)) / x) and the force the branch
    // sigma_t A_0 (1 - rho (x - 1)), to zero at x = 3; broken once r_b < 0.05 Rbar. delta is
    // the extension v t exactly, so both are met to round-off (1e-9).
    const BondLaw law = BondLaw::make(softening(0.05), dt);
    const BondGeometry g = touching();
    const double delta1 = 1e6 / kne, v = delta1 / (400.5 * dt); // no step lands on x = 1
    BondState s = fresh();
    int checked = 0;
    double lastX = 0;
    for (int i = 1; i <= 2000 && !s.broken; ++i)
    {
        const BondLoads loads = law.advance(s, g, driven(Vector3d(v, 0, 0), Vector3d::Zero()));
        const double x = v * i * dt / delta1;
        if (s.broken)
        {
            // The first step whose r_b would fall below brokenFraction Rbar.
            const double q = std::pow(0.05 * R / rb, 2);
            const double xBreak = 3.0 / (1.0 + 2.0 * q); // (1.5 - x/2)/x = q
            std::printf("  broken at x = %.6f (r_b < 0.05 Rbar from x = %.6f)\n", x, xBreak);
            EXPECT_GE(x, xBreak);
            EXPECT_LT(lastX, xBreak);
            break;
        }
        lastX = x;
        if (x <= 1.0)
        {
            EXPECT_EQ(s.patchRadius, rb);
            EXPECT_FALSE(s.softening);
            continue;
        }
        const double r = rb * std::sqrt((1.0 - 0.5 * (x - 1.0)) / x);
        const double force = 1e6 * area * (1.0 - 0.5 * (x - 1.0));
        if (i % 100 == 0)
            std::printf("  x %.3f: r_b/r_0 %.9f (closed form %.9f), F %.9e N (%.9e)\n", x,
                        s.patchRadius / rb, r / rb, loads.forceOnA.x(), force);
        EXPECT_TRUE(s.softening);
        EXPECT_LT(relative(s.patchRadius, r), 1e-9);
        EXPECT_LT(relative(loads.forceOnA.x(), force), 1e-9);
        ++checked;
    }
    EXPECT_TRUE(s.broken);
    EXPECT_GT(checked, 600);
    // Unloading keeps the smaller patch; the stress on it falls with the secant k_ne.
    s = fresh();
    for (int i = 0; i < 600; ++i)
        law.advance(s, g, driven(Vector3d(v, 0, 0), Vector3d::Zero()));
    const double r = s.patchRadius, N = s.normalForce;
    law.advance(s, g, driven(Vector3d(-v, 0, 0), Vector3d::Zero()));
    EXPECT_EQ(s.patchRadius, r);
    EXPECT_LT(relative(s.normalForce, N - kne * M_PI * r * r * v * dt), 1e-12);
}

TEST(BondLaw, BranchAtZeroBreaksWithoutABrokenFraction)
{
    // brokenFraction 0: the bond breaks where the softening branch reaches zero force, x =
    // delta/delta_1 = 1 + 1/rho = 3 for rho = 0.5, and not one step later or earlier (a patch
    // shrunk to r_b = 0 used to stay on as an intact bond that carries nothing).
    const BondLaw law = BondLaw::make(softening(0.0), dt);
    const BondGeometry g = touching();
    const double delta1 = 1e6 / kne, v = delta1 / (400.5 * dt); // no step lands on x = 3
    BondState s = fresh();
    double lastX = 0, x = 0;
    for (int i = 1; i <= 2000 && !s.broken; ++i)
    {
        law.advance(s, g, driven(Vector3d(v, 0, 0), Vector3d::Zero()));
        x = v * i * dt / delta1;
        if (!s.broken)
        {
            lastX = x;
            EXPECT_GT(s.patchRadius, 0.0);
        }
    }
    std::printf("  broken at x = %.6f, intact at x = %.6f (the branch is zero at x = 3)\n", x,
                lastX);
    EXPECT_TRUE(s.broken);
    EXPECT_GT(x, 3.0);
    EXPECT_LT(lastX, 3.0);
}

TEST(BondLaw, SinteringAtConstantLoad)
{
    // Pressure sintering under a constant compressive force F:
    // r_b^{m+6} = r_0^{m+6} + ((m+6)/m) R*^m A(T) (F/pi)^3 t. The update integrates the rate
    // exactly at constant force, so any dt meets it (round-off, 1e-12); a small step checks
    // the rate form dr_b/dt = (R*/m) (r_b/R*)^{1-m} A(T) sigma_c^3 it stands for (first-order
    // difference, relative error ~ dr/r = 1e-7: tolerance 1e-6).
    BondParameters p = elastic();
    p.sintering = dem::BondSintering::pressureSintering;
    p.temperature = -2.0;
    const double A = p.creepPrefactor * std::exp(-p.creepActivationEnergy / (8.314 * 271.15));
    const double m = 1.98488 - 0.00607767 * -2.0;
    const double Rstar = R / 2.0, F = 0.01;
    const BondGeometry g = touching();
    const double tEnd = 100.0;
    const double r6 = std::pow(rb, m + 6.0) +
                      (m + 6.0) / m * std::pow(Rstar, m) * A * std::pow(F / M_PI, 3) * tEnd;
    const double rEnd = std::pow(r6, 1.0 / (m + 6.0));
    for (int n : {1, 10, 1000})
    {
        const BondLaw law = BondLaw::make(p, tEnd / n);
        BondState s = fresh();
        s.normalForce = -F;
        for (int i = 0; i < n; ++i)
            law.advance(s, g, driven(Vector3d::Zero(), Vector3d::Zero()));
        std::printf("  %d steps: r_b %.9e m (closed form %.9e, r_0 %.1e), N %.3e\n", n,
                    s.patchRadius, rEnd, rb, s.normalForce);
        EXPECT_LT(relative(s.patchRadius, rEnd), 1e-12);
        EXPECT_EQ(s.normalForce, -F); // the new neck carries no load
    }
    const double small = 1e-6;
    const BondLaw law = BondLaw::make(p, small);
    BondState s = fresh();
    s.normalForce = -F;
    law.advance(s, g, driven(Vector3d::Zero(), Vector3d::Zero()));
    const double sigma = F / area;
    const double rate = Rstar / m * std::pow(rb / Rstar, 1.0 - m) * A * std::pow(sigma, 3);
    std::printf("  rate %.9e m/s (rate form %.9e)\n", (s.patchRadius - rb) / small, rate);
    EXPECT_LT(relative((s.patchRadius - rb) / small, rate), 1e-6);
    // Tension does not sinter.
    s = fresh();
    s.normalForce = F;
    law.advance(s, g, driven(Vector3d::Zero(), Vector3d::Zero()));
    EXPECT_EQ(s.patchRadius, rb);
}

TEST(BondLaw, DashpotsAreFractionsOfCritical)
{
    // c_n = 2 zeta_n sqrt(m* k_ne A), c_s = 2 zeta_s sqrt(m* k_se A) on the relative velocity of
    // the contact point (B minus A); the elastic part of one step is k A v dt.
    BondParameters p = elastic();
    p.normalDampingRatio = 0.4;
    p.shearDampingRatio = 0.1;
    const BondLaw law = BondLaw::make(p, dt);
    const double mA = 4e-6, mB = 6e-6, reduced = mA * mB / (mA + mB), v = 1e-2;
    const BondMotion motion{Vector3d::Zero(), Vector3d(v, v, 0), Vector3d::Zero(),
                            Vector3d::Zero(), 1.0 / mA,          1.0 / mB};
    BondState s = fresh();
    const BondLoads loads = law.advance(s, touching(), motion);
    const double cn = 2 * 0.4 * std::sqrt(reduced * kne * area);
    const double cs = 2 * 0.1 * std::sqrt(reduced * kse * area);
    std::printf("  F_n %.9e N (%.9e), F_s %.9e N (%.9e)\n", loads.forceOnA.x(),
                cn * v + kne * area * v * dt, loads.forceOnA.y(), cs * v + kse * area * v * dt);
    EXPECT_LT(relative(loads.forceOnA.x(), cn * v + kne * area * v * dt), 1e-12);
    EXPECT_LT(relative(loads.forceOnA.y(), cs * v + kse * area * v * dt), 1e-12);
    EXPECT_LT(relative(s.normalForce, kne * area * v * dt), 1e-12); // dashpots are not stored
}

TEST(BondLaw, ZeroStepEvaluatesWithoutChangingTheState)
{
    // dt = 0 (the engine's loads after grains were added): the loads of the state as it is,
    // the state untouched bit for bit, whatever the mechanisms (bonds present when grains are
    // added mid-run keep their state exactly).
    BondParameters p = elastic();
    p.creep = dem::BondCreep::maxwell;
    p.contactViscosity = 1e3;
    p.compressiveCreep = dem::BondCompressiveCreep::powerLaw;
    p.sintering = dem::BondSintering::pressureSintering;
    p.strength = dem::BondStrength::constant;
    p.tensileStrength = p.shearStrength = 1e2; // softening from the first steps,
    p.softeningRatio = 0.01;                   // to zero only at x = 101
    const BondGeometry g =
        bondGeometry(Vector3d(1.5e-3, 0.9e-3, -0.4e-3), Vector3d(0.3e-3, 0, 0.2e-3),
                     Vector3d(0, 0.4e-3, 0), 0.8e-3, 0.9e-3);
    const BondMotion moving{Vector3d(0.01, 0.02, 0),
                            Vector3d(-0.01, 0.0, 0.02),
                            Vector3d(1.0, -2.0, 0.5),
                            Vector3d(0.3, 0.2, -1.0),
                            0.0,
                            0.0};
    BondState s = fresh();
    for (int i = 0; i < 20; ++i)
        BondLaw::make(p, dt).advance(s, g, moving);
    std::printf("  state: r_b %.6e m, softening %d, broken %d\n", s.patchRadius, int(s.softening),
                int(s.broken));
    ASSERT_TRUE(s.softening && !s.broken);
    const BondState before = s;
    const BondLoads loads =
        BondLaw::make(p, 0.0).advance(s, g, driven(Vector3d::Zero(), Vector3d::Zero()));
    const auto same = [](const auto& a, const auto& b)
    { return std::memcmp(&a, &b, sizeof a) == 0; };
    EXPECT_TRUE(same(before.normalForce, s.normalForce) && same(before.shearForce, s.shearForce) &&
                same(before.twistMoment, s.twistMoment) && same(before.bendMoment, s.bendMoment) &&
                same(before.patchRadius, s.patchRadius) &&
                same(before.onsetRadius, s.onsetRadius) && same(before.age, s.age) &&
                before.softening == s.softening && before.broken == s.broken);
    const Vector3d force = s.normalForce * g.normal + s.shearForce;
    std::printf("  force %.9e N (N n + S %.9e N)\n", loads.forceOnA.norm(), force.norm());
    EXPECT_EQ((loads.forceOnA - force).norm(), 0.0);
}

// BondSystemTest.cpp
// Bonds through dem::System, one body per backend: two bonded ice capsules end to end, the
// first fixed, the second driven (GrainFlag::driven), pulled, sheared, twisted and bent
// (elastic slopes k_ne A, k_se A, k_se J, k_ne I); Maxwell relaxation at constant deformation
// and at dt >> tau; tensile rupture at sigma_ice(T) A; the softening sequence of r_b; a grain
// resting on a bond under gravity sintering at constant load; a bonded column under a
// stress-controlled lid creeping at the rate of the compressive creep law for bonds in series;
// a chain of Maxwell elements creeping sideways under its own weight; a restart with every
// mechanism on continues bit for bit.
// The evaluator's closed forms are derived in doc/EQUATIONS.md section 10.
#include "CapsuleTestSupport.h"

#include <cstring>
#include <functional>

using namespace demTest;
using Eigen::Vector3d;

namespace
{

class BondedGrains : public BackendTest
{
};

// Ice capsules of R = 1 mm, core half-length h = 1 mm, end to end along x and touching (the
// cores' ends 2R apart), bonded by a patch r_b = 0.3 R; E = 10 MPa.
constexpr double R = 1e-3, h = 1e-3, rb = 0.3e-3, E = 1e7, rhoIce = 917.0;
const double area = M_PI * rb * rb, bendI = M_PI * std::pow(rb, 4) / 4.0, twistJ = 2.0 * bendI;
const double kne = E / (2.0 * R), kse = 0.6 * kne;

dem::Parameters bondedParameters(dem::Parameters p)
{
    return iceBondPairParameters(p, E);
}

//- Capsule A (fixed) at the origin and capsule B (driven) to its +x, both along x.
void addPair(dem::System& s)
{
    dem::GrainInit a, b;
    a.radius = b.radius = R;
    a.coreHalfLength = b.coreHalfLength = h;
    a.density = b.density = rhoIce;
    a.orientation = b.orientation = rotation(Vector3d::UnitY(), M_PI / 2); // e_z -> e_x
    a.position = {0, 0, 0};
    b.position = {2 * h + 2 * R, 0, 0};
    a.flag = dem::GrainFlag::fixed;
    b.flag = dem::GrainFlag::driven;
    s.addGrains({a, b});
    s.addBonds({dem::BondInit{0, 1, rb}});
}

void drive(dem::System& s, const Vector3d& v, const Vector3d& w)
{
    s.setGrainVelocities({1}, {v.x(), v.y(), v.z()}, {w.x(), w.y(), w.z()});
}

Vector3d bondVector(const std::vector<double>& v)
{
    return Vector3d(v[0], v[1], v[2]);
}

double relative(double a, double b)
{
    return std::fabs(a - b) / std::fabs(b);
}

} // namespace

TEST_P(BondedGrains, ElasticSlopesOfTheFourModes)
{
    // 1000 steps of 1e-6 s at v = 1e-3 m/s or omega = 1 rad/s: u = 1e-6 m, theta = 1e-3 rad.
    // Pull and twist leave the geometry as it was; bending turns B's near end but about z,
    // normal to every normal the pair takes, so all of it is bend. Shear tilts the normal by
    // phi = u / (2R) = 5e-4, so S = k_se A u (1 - O(phi^2)): geometric error ~1e-7. Tolerance
    // 1e-6 for all four.
    const double v = 1e-3, w = 1.0, t = 1000 * 1e-6;
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
        dem::System s(bondedParameters(parameters()));
        addPair(s);
        drive(s, mode.velocity, mode.omega);
        s.step(1000);
        const dem::BondData b = s.bonds();
        ASSERT_EQ(b.first.size(), 1u);
        const Vector3d S = bondVector(b.shearForce), Mb = bondVector(b.bendMoment);
        const double N = b.normalForce[0], Mt = b.twistMoment[0];
        std::printf("  %s: N %.9e N, |S| %.9e N, M_t %.9e N m, |M_b| %.9e N m\n", mode.name, N,
                    S.norm(), Mt, Mb.norm());
        const std::string name = mode.name;
        if (name == "pull")
            EXPECT_LT(relative(N, kne * area * v * t), 1e-6);
        if (name == "shear")
        {
            EXPECT_LT(relative(S.y(), kse * area * v * t), 1e-6);
            // the opening u^2/(4R) is second order: N/S = (k_ne/k_se) u/(4R) = 4e-4
            EXPECT_LT(std::fabs(N), 1e-3 * S.norm());
        }
        if (name == "twist")
            EXPECT_LT(relative(Mt, kse * twistJ * w * t), 1e-6);
        if (name == "bend")
            EXPECT_LT(relative(Mb.z(), kne * bendI * w * t), 1e-6);
    }
}

TEST_P(BondedGrains, MaxwellRelaxationAtConstantDeformation)
{
    // Contact viscosity nu_s = 100 Pa s: tau_shear = tau_twist = nu_s/(0.6 E) = 1.67e-5 s,
    // tau_bend = nu_s/E = 1e-5 s. B slides, twists and bends for 20 steps, then stops: at
    // constant deformation each load decays as e^{-t/tau}, which the update reproduces exactly
    // (only round-off: 1e-6 leaves room for the direction of S, which the twist turned).
    dem::Parameters p = bondedParameters(parameters());
    p.bonds.creep = dem::BondCreep::maxwell;
    p.bonds.contactViscosity = 100.0;
    const double tauS = 100.0 / (0.6 * E), tauB = 100.0 / E;
    dem::System s(p);
    addPair(s);
    drive(s, Vector3d(0, 1e-3, 0), Vector3d(1.0, 0, 1.0));
    s.step(20);
    drive(s, Vector3d::Zero(), Vector3d::Zero());
    s.step(1);
    const dem::BondData b0 = s.bonds();
    s.step(30);
    const dem::BondData b1 = s.bonds();
    const double t = 30 * p.timeStep;
    const double ratioS = bondVector(b1.shearForce).norm() / bondVector(b0.shearForce).norm();
    const double ratioT = b1.twistMoment[0] / b0.twistMoment[0];
    const double ratioB = bondVector(b1.bendMoment).norm() / bondVector(b0.bendMoment).norm();
    std::printf("  over %.1e s: S %.9f (e^-t/tau_s %.9f), M_t %.9f, M_b %.9f (e^-t/tau_b %.9f)\n",
                t, ratioS, std::exp(-t / tauS), ratioT, ratioB, std::exp(-t / tauB));
    EXPECT_LT(relative(ratioS, std::exp(-t / tauS)), 1e-6);
    EXPECT_LT(relative(ratioT, std::exp(-t / tauS)), 1e-6);
    EXPECT_LT(relative(ratioB, std::exp(-t / tauB)), 1e-6);
}

TEST_P(BondedGrains, MaxwellStableAtStepsFarAboveTau)
{
    // nu_s = 0.1 Pa s: tau_shear = 1.67e-8 s, 60 times below dt = 1e-6 s. Sliding at v the
    // shear force is bounded by its steady value k_se A v tau (reached after one step, to
    // e^{-60}); once B stops it is gone after one step (factor e^{-60}).
    dem::Parameters p = bondedParameters(parameters());
    p.bonds.creep = dem::BondCreep::maxwell;
    p.bonds.contactViscosity = 0.1;
    const double tauS = 0.1 / (0.6 * E), v = 1e-3;
    dem::System s(p);
    addPair(s);
    drive(s, Vector3d(0, v, 0), Vector3d::Zero());
    double largest = 0;
    for (int i = 0; i < 100; ++i)
    {
        s.step(1);
        largest = std::max(largest, bondVector(s.bonds().shearForce).norm());
    }
    const double steady = kse * area * v * tauS;
    const double S = bondVector(s.bonds().shearForce).norm();
    std::printf("  largest |S| %.9e N, last %.9e N, k_se A v tau %.9e N\n", largest, S, steady);
    EXPECT_LE(largest, steady * (1 + 1e-6)); // the tilt (phi ~ 5e-5) is far below 1e-6
    EXPECT_LT(relative(S, steady), 1e-6);
    drive(s, Vector3d::Zero(), Vector3d::Zero());
    s.step(1);
    const double after = bondVector(s.bonds().shearForce).norm();
    std::printf("  one step after stopping: |S| %.3e N (e^{-60} of it: %.3e)\n", after,
                S * std::exp(-p.timeStep / tauS));
    EXPECT_LE(after, S * std::exp(-p.timeStep / tauS) * (1 + 1e-6));
}

TEST_P(BondedGrains, CreepDisplacementsAreTheImposedMotionLessTheElastic)
{
    // nu_s = 100 Pa s: tau_shear = tau_twist = 1.67e-5 s, tau_bend = 1e-5 s. B slides, twists
    // or bends at a constant rate for 50 steps (t = 3 tau_shear): in each Maxwell element the
    // imposed motion is the spring's plus the dashpot's, so the creep is u - X / K, and at a
    // constant rate u (t - tau (1 - e^{-t/tau})) in closed form. The slide tilts the normal by
    // u / (2R) = 2.5e-5 (second-order error 1e-9); tolerance 1e-6 as for the elastic slopes.
    // Bending about z at B's centre also slides the contact point: only the bend is checked.
    // The mechanisms not driven creep by round-off only: below 1e-9 of the driven one's
    // (rotations compared as arc lengths at R).
    dem::Parameters p = bondedParameters(parameters());
    p.bonds.creep = dem::BondCreep::maxwell;
    p.bonds.contactViscosity = 100.0;
    const double tauS = 100.0 / (0.6 * E), tauB = 100.0 / E, v = 1e-3, w = 1.0;
    const double t = 50 * p.timeStep;
    const auto closedForm = [t](double rate, double tau)
    { return rate * (t + tau * std::expm1(-t / tau)); };
    struct Mode
    {
        const char* name;
        Vector3d velocity, omega;
    };
    for (const Mode& mode : {Mode{"shear", Vector3d(0, v, 0), Vector3d::Zero()},
                             Mode{"twist", Vector3d::Zero(), Vector3d(w, 0, 0)},
                             Mode{"bend", Vector3d::Zero(), Vector3d(0, 0, w)}})
    {
        dem::System s(p);
        addPair(s);
        drive(s, mode.velocity, mode.omega);
        s.step(50);
        const dem::BondData b = s.bonds();
        const dem::BondCounts counts = s.bondCounts();
        ASSERT_EQ(b.first.size(), 1u);
        const std::string name = mode.name;
        double creep = 0, imposedLessElastic = 0, expected = 0, total = 0;
        if (name == "shear")
        {
            creep = b.creepShear[0];
            imposedLessElastic = v * t - bondVector(b.shearForce).norm() / (kse * area);
            expected = closedForm(v, tauS);
            total = counts.intactCreep[1];
            EXPECT_LT(R * (b.creepTwist[0] + b.creepBend[0]), 1e-9 * creep);
        }
        if (name == "twist")
        {
            creep = b.creepTwist[0];
            imposedLessElastic = w * t - b.twistMoment[0] / (kse * twistJ);
            expected = closedForm(w, tauS);
            total = counts.intactCreep[2];
            EXPECT_LT(b.creepShear[0] + R * b.creepBend[0], 1e-9 * R * creep);
        }
        if (name == "bend")
        {
            creep = b.creepBend[0];
            imposedLessElastic = w * t - bondVector(b.bendMoment).norm() / (kne * bendI);
            expected = closedForm(w, tauB);
            total = counts.intactCreep[3];
            EXPECT_LT(R * b.creepTwist[0], 1e-9 * R * creep);
        }
        std::printf("  %s: creep %.9e, imposed - elastic %.9e, closed form %.9e\n", mode.name,
                    creep, imposedLessElastic, expected);
        EXPECT_LT(relative(creep, imposedLessElastic), 1e-6);
        EXPECT_LT(relative(creep, expected), 1e-6);
        EXPECT_EQ(total, creep);          // one bond: the sample's sum is its own
        EXPECT_EQ(b.creepNormal[0], 0.0); // no compressive creep law: exactly none
    }
}

TEST_P(BondedGrains, BrokenBondsKeepTheirCreepInTheSample)
{
    // B slides for 50 steps with Maxwell creep, then is pulled off at 0.2 delta_1 per step:
    // the bond breaks and is removed, and the sample's creep keeps what it crept. While being
    // pulled the stored shear force still relaxes (at most |S| / (k_se A) more creep in all,
    // (1 - e^{-dt/tau}) of it in the step that breaks it).
    dem::Parameters p = bondedParameters(parameters());
    p.bonds.creep = dem::BondCreep::maxwell;
    p.bonds.contactViscosity = 100.0;
    p.bonds.temperature = -10.0;
    p.bonds.strength = dem::BondStrength::iceTemperature;
    p.bonds.softeningRatio = 1e3;
    const double tauS = 100.0 / (0.6 * E), delta1 = 1.45552e6 / kne;
    dem::System s(p);
    addPair(s);
    drive(s, Vector3d(0, 1e-3, 0), Vector3d::Zero());
    s.step(50);
    drive(s, Vector3d(0.2 * delta1 / p.timeStep, 0, 0), Vector3d::Zero());
    double lastCreep = 0, lastElastic = 0;
    int steps = 0;
    while (s.bondCounts().intact == 1 && steps < 100)
    {
        const dem::BondData b = s.bonds();
        lastCreep = b.creepShear[0];
        lastElastic = bondVector(b.shearForce).norm() / (kse * area);
        s.step(1);
        ++steps;
    }
    const dem::BondCounts counts = s.bondCounts();
    std::printf("  broken after %d steps of the pull: shear creep %.9e m (last intact %.9e m, "
                "stored elastic %.3e m)\n",
                steps, counts.brokenCreep[1], lastCreep, lastElastic);
    ASSERT_EQ(counts.broken, 1u);
    EXPECT_EQ(counts.intact, 0u);
    EXPECT_EQ(counts.intactCreep[1], 0.0);
    EXPECT_GE(counts.brokenCreep[1], lastCreep);
    EXPECT_LE(counts.brokenCreep[1],
              lastCreep + lastElastic * -std::expm1(-p.timeStep / tauS) * (1 + 1e-9));
    EXPECT_GT(lastCreep, 0.5 * 1e-3 * 50 * p.timeStep); // it did creep: t = 3 tau
}

TEST_P(BondedGrains, TensileRuptureAtTheIceStrength)
{
    // sigma_ice(-10 C) = 0.99648 + 0.45904 = 1.45552 MPa. Pulled at 1e-4 of delta_1 per step
    // with a brittle softening branch (rho = 1e3), the largest normal force is sigma_ice A to
    // within 1e-3 (the last elastic step's shortfall); tolerance 1 %. Then the bond is gone.
    dem::Parameters p = bondedParameters(parameters());
    p.bonds.temperature = -10.0;
    p.bonds.strength = dem::BondStrength::iceTemperature;
    p.bonds.softeningRatio = 1e3;
    const double sigmaIce = 1.45552e6, delta1 = sigmaIce / kne;
    dem::System s(p);
    addPair(s);
    drive(s, Vector3d(1e-4 * delta1 / p.timeStep, 0, 0), Vector3d::Zero());
    double peak = 0;
    int steps = 0;
    while (s.bondCounts().intact == 1 && steps < 20000)
    {
        s.step(1);
        ++steps;
        const dem::BondData b = s.bonds();
        if (!b.normalForce.empty())
            peak = std::max(peak, b.normalForce[0]);
    }
    const dem::BondCounts counts = s.bondCounts();
    std::printf("  peak N %.6e N, sigma_ice A %.6e N, broken after %d steps (broken %zu)\n", peak,
                sigmaIce * area, steps, counts.broken);
    EXPECT_EQ(counts.intact, 0u);
    EXPECT_EQ(counts.broken, 1u);
    EXPECT_NEAR(peak / (sigmaIce * area), 1.0, 0.01);
}

TEST_P(BondedGrains, SofteningSequence)
{
    // Pulled at constant speed with rho = 0.5 (constant strength 1 MPa): past x = delta/delta_1
    // = 1, r_b = r_0 sqrt((1 - rho (x - 1)) / x) with delta = v t exactly (a pure pull leaves
    // the geometry as it is): round-off only, tolerance 1e-9.
    dem::Parameters p = bondedParameters(parameters());
    p.bonds.strength = dem::BondStrength::constant;
    p.bonds.tensileStrength = p.bonds.shearStrength = 1e6;
    p.bonds.softeningRatio = 0.5;
    const double delta1 = 1e6 / kne, v = delta1 / (400.5 * p.timeStep);
    dem::System s(p);
    addPair(s);
    drive(s, Vector3d(v, 0, 0), Vector3d::Zero());
    int checked = 0;
    for (int chunk = 1; chunk <= 11; ++chunk)
    {
        s.step(100);
        const double x = v * s.time() / delta1;
        const dem::BondData b = s.bonds();
        ASSERT_EQ(b.patchRadius.size(), 1u) << "broken too early at x = " << x;
        const double expected = x <= 1.0 ? rb : rb * std::sqrt((1.0 - 0.5 * (x - 1.0)) / x);
        std::printf("  x %.4f: r_b %.9e m (closed form %.9e), softening %d\n", x, b.patchRadius[0],
                    expected, int(b.softening[0]));
        EXPECT_LT(relative(b.patchRadius[0], expected), 1e-9);
        EXPECT_EQ(b.softening[0] != 0, x > 1.0);
        ++checked;
    }
    // r_b < 0.05 Rbar from x = 3 / (1 + 2 (0.05 R / r_b)^2) = 2.842: broken by x = 2.85.
    s.step(int(std::ceil((2.85 * delta1 / v - s.time()) / p.timeStep)));
    EXPECT_EQ(s.bondCounts().broken, 1u);
    EXPECT_EQ(checked, 11);
}

TEST_P(BondedGrains, SinteringAtConstantLoad)
{
    // A sphere resting on a fixed sphere below it, held by a bond that carries its weight
    // F = m g (gravity 9.81 m/s^2, critical damping on the bond: the bounce dies out within
    // 1e-3 s). Pressure sintering then grows r_b as
    //   r_b^{m+6}(t) = r_b^{m+6}(t0) + ((m+6)/m) R*^m A(T) (F/pi)^3 (t - t0).
    // Ice's A(T) would need years here: A0 is raised so that r_b grows by ~30 % in 0.05 s. The
    // load stays m g (quasi-static: the grain's acceleration is ~ m dr/dt^2-small); tolerance
    // 1e-6 of r_b.
    dem::Parameters p = bondedParameters(parameters());
    p.gravity = {0, 0, -9.81};
    p.bonds.temperature = -2.0;
    p.bonds.normalDampingRatio = 1.0;
    p.bonds.shearDampingRatio = 1.0;
    p.bonds.sintering = dem::BondSintering::pressureSintering;
    p.bonds.creepPrefactor = 2e8;
    dem::System s(p);
    dem::GrainInit a, b;
    a.radius = b.radius = R;
    a.density = b.density = rhoIce;
    a.position = {0, 0, 0};
    b.position = {0, 0, 2 * R};
    a.flag = dem::GrainFlag::fixed;
    s.addGrains({a, b});
    s.addBonds({dem::BondInit{0, 1, rb}});
    s.step(2000); // settle
    const double t0 = s.time(), r0 = s.bonds().patchRadius[0];
    const double F = s.grains().mass[1] * 9.81;
    const double m = 1.98488 - 0.00607767 * -2.0;
    const double A = 2e8 * std::exp(-70e3 / (8.314 * 271.15)), Rstar = R / 2;
    s.step(50000);
    const double t = s.time() - t0;
    const double expected = std::pow(std::pow(r0, m + 6) + (m + 6) / m * std::pow(Rstar, m) * A *
                                                               std::pow(F / M_PI, 3) * t,
                                     1.0 / (m + 6));
    const dem::BondData bond = s.bonds();
    std::printf("  N %.9e N (-m g %.9e), r_b %.9e m from %.9e (closed form %.9e)\n",
                bond.normalForce[0], -F, bond.patchRadius[0], r0, expected);
    EXPECT_LT(relative(bond.normalForce[0], -F), 1e-6);
    EXPECT_GT(bond.patchRadius[0], 1.1 * r0);
    EXPECT_LT(relative(bond.patchRadius[0], expected), 1e-6);
}

TEST_P(BondedGrains, ColumnUnderALidCreepsAtThePowerLawRate)
{
    // Four spheres stacked along z, bonded in series (three bonds), the lowest fixed, under a
    // stress-controlled lid: each bond carries about F = sigma0 L_x L_y, and compressive creep
    // shortens it at 2 Rbar A(T) sigma^n, sigma = |N| / A, n = 3, so the lid sinks at
    // 3 * 2R A(T) sigma^3. A0 is 4e-4 instead of 0.0055 so that the rate is ~2e-5 m/s
    // per bond, and the bonds and the lid are critically damped so that the start dies out
    // within 8 ms (the rate over 2 ms windows is steady to 1e-5 from there). The rate is
    // predicted from the bonds' stored N; the dashpots carry c_n u_c ~ 1e-4 F of the load at
    // the creep speed, so N = -F to 1e-3 only.
    dem::Parameters p = bondedParameters(parameters());
    const double box = 10 * R, sigma0 = 1e5 * area / (box * box); // sigma = F / A = 1e5 Pa
    p.boxLower = {0, 0};
    p.boxUpper = {box, box};
    p.grainWall.normalDamping = 2 * 1.0 * std::sqrt(1e4 * 4e-6);
    p.bonds.temperature = -5.0;
    p.bonds.normalDampingRatio = 1.0;
    p.bonds.shearDampingRatio = 1.0;
    p.bonds.compressiveCreep = dem::BondCompressiveCreep::powerLaw;
    p.bonds.creepPrefactor = 4e-4;
    dem::System s(p);
    std::vector<dem::GrainInit> grains(4);
    for (int i = 0; i < 4; ++i)
    {
        grains[i].radius = R;
        grains[i].density = rhoIce;
        grains[i].position = {box / 2, box / 2, (2 * i + 1) * R};
    }
    grains[0].flag = dem::GrainFlag::fixed;
    s.addGrains(grains);
    s.addBonds({{0, 1, rb}, {1, 2, rb}, {2, 3, rb}});
    dem::WallSpec lid;
    lid.side = dem::WallSpec::Side::upper;
    lid.mode = dem::WallSpec::Mode::stress;
    lid.position = 8 * R;
    lid.mass = 4e-6;
    lid.normalStress = sigma0;
    const int lidIndex = s.addWall(lid);
    s.step(10000);
    const double z0 = s.wall(lidIndex).position, t0 = s.time();
    s.step(10000);
    const double rate = -(s.wall(lidIndex).position - z0) / (s.time() - t0);
    const double F = sigma0 * box * box;
    const double A = 4e-4 * std::exp(-70e3 / (8.314 * 268.15));
    const double m = 3.0; // the default exponent
    const dem::BondData b = s.bonds();
    double predicted = 0;
    for (int i = 0; i < 3; ++i)
        predicted += 2 * R * A * std::pow(-b.normalForce[i] / area, m);
    std::printf("  N %.9e %.9e %.9e N (-F %.9e), lid rate %.9e m/s (bonds in series %.9e)\n",
                b.normalForce[0], b.normalForce[1], b.normalForce[2], -F, rate, predicted);
    for (int i = 0; i < 3; ++i)
        EXPECT_LT(relative(b.normalForce[i], -F), 1e-3);
    EXPECT_LT(relative(rate, predicted), 1e-4);
}

TEST_P(BondedGrains, MaxwellChainCreepsUnderItsWeight)
{
    // Four spheres stacked along z and bonded in series, the lowest fixed, the others free to
    // move but not to turn (translationOnly: no bending), under gravity along x. At steady
    // creep bond k (from the bottom, k = 1..3) carries the weight of the 4 - k grains above it
    // as its shear force, S_k = (4 - k) m g, and slides at the Newtonian rate of its Maxwell
    // element, S / (k_se A tau_s) = 2 Rbar S / (A nu_s); the top grain moves at the sum,
    // 2R m g (3 + 2 + 1) / (A nu_s). nu_s = 1 kPa s: tau_s = 1.7e-4 s, the start dies out
    // within 5 ms (creep damps the shear oscillation, omega tau_s = 2.5); then 5 ms of creep
    // tilt the lowest bond by 2e-3 rad, so the tilt changes the rates by ~phi^2 = 4e-6 and
    // the loads' shares by as little: tolerance 1e-4.
    dem::Parameters p = bondedParameters(parameters());
    const double nu = 1e3, g = 9.81;
    p.boxLower = {0, 0};
    p.boxUpper = {10 * R, 10 * R};
    p.gravity = {g, 0, 0};
    p.bonds.creep = dem::BondCreep::maxwell;
    p.bonds.contactViscosity = nu;
    dem::System s(p);
    std::vector<dem::GrainInit> grains(4);
    for (int i = 0; i < 4; ++i)
    {
        grains[i].radius = R;
        grains[i].density = rhoIce;
        grains[i].position = {5 * R, 5 * R, (2 * i + 1) * R};
        grains[i].flag = i == 0 ? dem::GrainFlag::fixed : dem::GrainFlag::translationOnly;
    }
    s.addGrains(grains);
    s.addBonds({{0, 1, rb}, {1, 2, rb}, {2, 3, rb}});
    s.step(5000);
    const double x0 = s.grains().displacement[9], t0 = s.time();
    s.step(5000);
    const dem::GrainData after = s.grains();
    const double rate = (after.displacement[9] - x0) / (s.time() - t0);
    const double weight = after.mass[1] * g;
    const double predicted = 2 * R * weight * (3 + 2 + 1) / (area * nu);
    const dem::BondData b = s.bonds();
    std::printf("  top grain %.9e m/s (Maxwell chain %.9e); S_x %.6e %.6e %.6e N (m g %.6e)\n",
                rate, predicted, b.shearForce[0], b.shearForce[3], b.shearForce[6], weight);
    EXPECT_LT(relative(rate, predicted), 1e-4);
    for (int k = 0; k < 3; ++k)
        EXPECT_LT(relative(b.shearForce[3 * k], (3 - k) * weight), 1e-4);
}

TEST_P(BondedGrains, RestartWithEveryMechanismContinuesBitForBit)
{
    // Every mechanism on (Maxwell creep, compressive creep, sintering, strength with
    // softening): a fixed capsule, a driven sphere pressing into it, sliding and spinning, and
    // a free sphere bonded to that one. Export, continue; import into a fresh System and
    // continue: bonds (including the onset radius and softening flag the strength check
    // reads) and grains bit for bit.
    dem::Parameters p = bondedParameters(parameters());
    p.bonds.creep = dem::BondCreep::maxwell;
    p.bonds.contactViscosity = 1e3;
    p.bonds.compressiveCreep = dem::BondCompressiveCreep::powerLaw;
    p.bonds.creepPrefactor = 40.0;
    p.bonds.sintering = dem::BondSintering::pressureSintering;
    p.bonds.strength = dem::BondStrength::constant;
    p.bonds.tensileStrength = p.bonds.shearStrength = 1e3;
    p.bonds.softeningRatio = 0.01;
    p.bonds.normalDampingRatio = p.bonds.shearDampingRatio = 0.3;
    auto make = [&]
    {
        dem::System s(p);
        dem::GrainInit a, b, c;
        a.radius = b.radius = c.radius = R;
        a.density = b.density = c.density = rhoIce;
        a.coreHalfLength = h;
        a.orientation = rotation(Vector3d(1, 1, 0), 1.0);
        a.flag = dem::GrainFlag::fixed;
        b.position = {0.3 * R, 0.2 * R, 2 * R};
        b.flag = dem::GrainFlag::driven;
        c.position = {0.3 * R, 0.2 * R, 4 * R};
        s.addGrains({a, b, c});
        s.setGrainVelocities({1}, {1e-3, -2e-3, -1e-3}, {5.0, -3.0, 2.0});
        s.addBonds({{0, 1, rb}, {1, 2, rb}});
        return s;
    };
    dem::System original = make();
    original.step(300);
    const dem::SystemState state = original.exportState();
    original.step(300);
    dem::System restarted(p);
    restarted.importState(state);
    restarted.step(300);
    const dem::BondData a = original.bonds(), b = restarted.bonds();
    std::printf("  %zu bonds; r_b %.9e %.9e m, softening %d %d\n", a.first.size(), a.patchRadius[0],
                a.patchRadius[1], int(a.softening[0]), int(a.softening[1]));
    ASSERT_EQ(a.first.size(), 2u);
    EXPECT_TRUE(a.softening[0] != 0 || a.softening[1] != 0); // the strength check ran
    const auto identical = [](const std::vector<double>& x, const std::vector<double>& y)
    { return x.size() == y.size() && std::memcmp(x.data(), y.data(), x.size() * 8) == 0; };
    EXPECT_TRUE(identical(a.patchRadius, b.patchRadius));
    EXPECT_TRUE(identical(a.normalForce, b.normalForce));
    EXPECT_TRUE(identical(a.shearForce, b.shearForce));
    EXPECT_TRUE(identical(a.twistMoment, b.twistMoment));
    EXPECT_TRUE(identical(a.bendMoment, b.bendMoment));
    EXPECT_TRUE(identical(a.age, b.age));
    EXPECT_TRUE(identical(a.creepNormal, b.creepNormal));
    EXPECT_TRUE(identical(a.creepShear, b.creepShear));
    EXPECT_TRUE(identical(a.creepTwist, b.creepTwist));
    EXPECT_TRUE(identical(a.creepBend, b.creepBend));
    const dem::GrainData ga = original.grains(), gb = restarted.grains();
    EXPECT_TRUE(identical(ga.position, gb.position));
    EXPECT_TRUE(identical(ga.velocity, gb.velocity));
    EXPECT_TRUE(identical(ga.angularVelocity, gb.angularVelocity));
}

TEST_P(BondedGrains, BadBondLawConstantsAreNamed)
{
    // Each mechanism's constants are checked when it is on; the message names the parameter,
    // its value and the valid range.
    struct Case
    {
        std::function<void(dem::BondParameters&)> set;
        const char* expected;
    };
    const std::vector<Case> cases = {
        {[](dem::BondParameters& b) { b.youngsModulus = 0; }, "bonds.youngsModulus = 0"},
        {[](dem::BondParameters& b) { b.temperature = 5; }, "bonds.temperature = 5"},
        {[](dem::BondParameters& b) { b.normalDampingRatio = 1.5; },
         "bonds.normalDampingRatio = 1.5"},
        {[](dem::BondParameters& b) { b.creep = dem::BondCreep::maxwell; },
         "bonds.contactViscosity = 0"},
        {[](dem::BondParameters& b)
         {
             b.sintering = dem::BondSintering::pressureSintering;
             b.creepPrefactor = -1;
         },
         "bonds.creepPrefactor = -1"},
        {[](dem::BondParameters& b)
         {
             b.compressiveCreep = dem::BondCompressiveCreep::powerLaw;
             b.creepExponent = 1;
         },
         "bonds.creepExponent = 1"},
        {[](dem::BondParameters& b)
         {
             b.compressiveCreep = dem::BondCompressiveCreep::powerLaw;
             b.sintering = dem::BondSintering::pressureSintering;
             b.creepExponent = 2;
         },
         "3 with pressureSintering"},
        {[](dem::BondParameters& b)
         {
             b.strength = dem::BondStrength::constant;
             b.tensileStrength = -1;
         },
         "bonds.tensileStrength = -1"},
        {[](dem::BondParameters& b)
         {
             b.strength = dem::BondStrength::iceTemperature;
             b.softeningRatio = 0;
         },
         "bonds.softeningRatio = 0"},
        {[](dem::BondParameters& b)
         {
             b.strength = dem::BondStrength::iceTemperature;
             b.brokenFraction = 1;
         },
         "bonds.brokenFraction = 1"}};
    for (const Case& c : cases)
    {
        dem::Parameters p = bondedParameters(parameters());
        c.set(p.bonds);
        try
        {
            dem::System s(p);
            ADD_FAILURE() << "not refused: " << c.expected;
        }
        catch (const dem::Error& e)
        {
            std::printf("  refused: %s\n", e.what());
            EXPECT_NE(std::string(e.what()).find(c.expected), std::string::npos) << e.what();
        }
    }
    // Off mechanisms are not checked: no contact viscosity needed without creep.
    dem::Parameters p = bondedParameters(parameters());
    p.bonds.contactViscosity = -1;
    EXPECT_NO_THROW(dem::System s(p));
}

DEM_TEST_ON_ALL_BACKENDS(BondedGrains);

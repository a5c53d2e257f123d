// BondStoreTest.cpp
// The bond store through dem::System, each body on every backend: a bond persists whatever its
// grains' distance, through neighbour rebuilds, re-sorting of the grains, the periodic seam and
// a restart, bit for bit; a bonded pair gets no contact-law loads; formation (frozenOnContact)
// bonds every touching pair once with r_b^2 / r_min^2 uniform in areaFraction; addBonds and
// importState refuse bad input by name; driven grains keep their velocity and spin.
#include "CapsuleTestSupport.h"

#include <algorithm>
#include <cstring>
#include <functional>
#include <numeric>
#include <random>

using namespace demTest;

namespace
{

class BondStore : public BackendTest
{
protected:
    //- The fixture's grains (r = 0.01 m, k = 1e6 N/m) with bonds on (elastic patch of E, no
    //- other mechanism) and a time step well below the bond's and contact's critical steps.
    dem::Parameters bondParameters() const
    {
        dem::Parameters p = parameters();
        p.timeStep = 1e-5;
        p.bonds.enabled = true;
        p.bonds.youngsModulus = 1e6;
        return p;
    }
};

template <class T>
bool identical(const std::vector<T>& a, const std::vector<T>& b)
{
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

//- Every array of two bond read-backs, bit for bit.
void expectIdenticalBonds(const dem::BondData& a, const dem::BondData& b)
{
    EXPECT_EQ(a.first, b.first);
    EXPECT_EQ(a.second, b.second);
    EXPECT_TRUE(identical(a.patchRadius, b.patchRadius));
    EXPECT_TRUE(identical(a.normalForce, b.normalForce));
    EXPECT_TRUE(identical(a.shearForce, b.shearForce));
    EXPECT_TRUE(identical(a.twistMoment, b.twistMoment));
    EXPECT_TRUE(identical(a.bendMoment, b.bendMoment));
    EXPECT_TRUE(identical(a.normal, b.normal));
    EXPECT_TRUE(identical(a.point, b.point));
    EXPECT_TRUE(identical(a.age, b.age));
    EXPECT_EQ(a.softening, b.softening);
}

//- A fast gas of n spheres between walls at z = 0 and z = 1 that keeps the cell sort busy:
//- grains change cells every few steps, so internal indices change at every rebuild.
std::vector<dem::GrainInit> gas(int n, unsigned seed)
{
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> place(0.05, 0.95), speed(-5.0, 5.0);
    std::vector<dem::GrainInit> grains;
    while (int(grains.size()) < n)
    {
        dem::GrainInit g;
        g.radius = 0.01;
        g.position = {place(random), place(random), place(random)};
        // keep clear of the bonded pair's neighbourhood at the start
        if (std::fabs(g.position[2] - 0.5) < 0.05)
            continue;
        g.velocity = {speed(random), speed(random), speed(random)};
        grains.push_back(g);
    }
    return grains;
}

void addWalls(dem::System& s)
{
    s.addWall(dem::WallSpec());
    dem::WallSpec top;
    top.side = dem::WallSpec::Side::upper;
    top.position = 1.0;
    s.addWall(top);
}

//- Grain 0: a fixed capsule across y; grain 1: a sphere in tension, driven away from it along
//- x (and sideways, spinning) from 0.2 mm apart, shifted by `shift` in x (periodic box of 1 m).
void addBondedPair(dem::System& s, double shift)
{
    dem::GrainInit a, b;
    a.radius = 0.01;
    a.coreHalfLength = 0.01;
    a.orientation = rotation(Eigen::Vector3d::UnitX(), 0.5 * M_PI);
    a.position = {0.99 + shift, 0.5, 0.5};
    a.flag = dem::GrainFlag::fixed;
    b.radius = 0.008;
    b.position = {std::fmod(0.99 + 0.0182 + shift, 1.0), 0.5, 0.5};
    b.flag = dem::GrainFlag::driven;
    s.addGrains({a, b});
    s.setGrainVelocities({1}, {0.01, 0.003, 0.0}, {0.0, 0.0, 20.0});
    s.addBonds({{0, 1, 0.004}});
}

} // namespace

TEST_P(BondStore, BondedPairSurvivesRebuildsResortingAndTheSeamBitForBit)
{
    // The pair's motion is prescribed (fixed and driven grains), so the bond's state depends on
    // nothing but the two grains and the law: with a gas of 300 grains re-sorted at every
    // rebuild (skin 0.3 mm at 5 m/s: a rebuild every 3 steps) it must be the same, bit for
    // bit, as the pair alone with one neighbour list. The pair straddles the periodic seam at
    // x = 1 (the capsule's axis 1 cm left of it, the sphere's centre 8 mm right of it), so every
    // separation is a minimum image across the seam, and the contact point wraps.
    dem::Parameters p = bondParameters();
    p.neighbourSkin = 3e-4;
    dem::System busy(p);
    addBondedPair(busy, 0.0);
    busy.addGrains(gas(300, 5));
    addWalls(busy);
    dem::Parameters quiet = bondParameters();
    quiet.neighbourSkin = 0.05; // the pair moves 0.2 mm: one neighbour list for the whole run
    dem::System alone(quiet);
    addBondedPair(alone, 0.0);
    const int steps = 2000;
    busy.step(steps);
    alone.step(steps);
    const dem::BondData a = busy.bonds(), b = alone.bonds();
    const dem::GrainData ga = busy.grains(), gb = alone.grains();
    std::printf("  %zu rebuilds with the gas, %zu alone; bond (%d, %d), N %.6e N\n",
                busy.neighbourRebuildCount(), alone.neighbourRebuildCount(), a.first.at(0),
                a.second.at(0), a.normalForce.at(0));
    EXPECT_GT(busy.neighbourRebuildCount(), 100u);
    ASSERT_EQ(a.first.size(), 1u);
    EXPECT_EQ(a.first[0], 0);
    EXPECT_EQ(a.second[0], 1);
    expectIdenticalBonds(a, b);
    EXPECT_EQ(busy.bondCounts().intact, 1u);
    EXPECT_EQ(busy.bondCounts().broken, 0u);
    // The driven sphere kept its velocity and moved exactly v t (it crossed no seam: 0.2 mm).
    for (int d = 0; d < 3; ++d)
    {
        EXPECT_EQ(ga.position[3 + d], gb.position[3 + d]);
        EXPECT_EQ(ga.velocity[3 + d], (std::array<double, 3>{0.01, 0.003, 0.0}[d]));
    }
    // Geometry of the read-back: n from the capsule's core (along y through x = 0.99) to the
    // sphere's centre, minimum image across the seam; the point in the middle of the gap,
    // wrapped into the box.
    const Vec3 xa = at(ga.position, 0), xb = at(ga.position, 1);
    Vec3 d = sub(xb, xa);
    d[0] -= std::round(d[0]);
    const Vec3 radial{d[0], 0.0, d[2]}; // the core is along y and the sphere within its length
    const double distance = norm(radial);
    const double gap = distance - 0.018;
    const double expectedPoint = xa[0] + (0.01 + 0.5 * gap) * radial[0] / distance;
    std::printf("  gap %.9e m, normal (%.12f %.12f %.12f), point x %.12f\n", gap, a.normal[0],
                a.normal[1], a.normal[2], a.point[0]);
    EXPECT_GT(gap, 0.0); // apart: the bond, not a contact, holds the pair
    EXPECT_EQ(busy.bondCounts().apart, 1u);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(a.normal[c], radial[c] / distance, 1e-12); // unit vector: round-off
    EXPECT_NEAR(a.point[0], expectedPoint - std::floor(expectedPoint), 1e-12);
    EXPECT_GE(a.point[0], 0.0);
    EXPECT_LT(a.point[0], 1.0);

    // Translation invariance: the same pair half a box away from the seam has the same bond
    // (positions differ by 0.5 m, so to round-off of the coordinates, 1e-15 m relative to 1 m,
    // against the 1e-2 m geometry: 1e-12 relative).
    dem::System shifted(quiet);
    addBondedPair(shifted, -0.5);
    shifted.step(steps);
    const dem::BondData s = shifted.bonds();
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(s.normal[c], a.normal[c], 1e-12);
    const double scale = std::max(1e-30, std::fabs(a.normalForce[0]));
    EXPECT_NEAR(s.normalForce[0], a.normalForce[0], 1e-9 * scale);
}

TEST_P(BondStore, BondedPairGetsNoContactLoads)
{
    // Two overlapping spheres at rest (overlap 1e-4 m): unbonded, the linear spring pushes them
    // apart with k delta = 100 N (the loads of step(0), before anything moves); bonded with zero
    // initial loads and no relative motion, the bond's increments are zero, so the pair feels
    // nothing, step after step, and stays where it is.
    for (const bool bonded : {false, true})
    {
        dem::Parameters p = bondParameters();
        dem::System s(p);
        dem::GrainInit a, b;
        a.radius = b.radius = 0.01;
        a.position = {0.5, 0.5, 0.5};
        b.position = {0.5199, 0.5, 0.5};
        s.addGrains({a, b});
        if (bonded)
            s.addBonds({{1, 0, 0.003}}); // either order
        s.step(bonded ? 5 : 0);
        const dem::GrainData g = s.grains();
        std::printf("  bonded %d: force on grain 0 %.6e N, contacts %zu\n", int(bonded), g.force[0],
                    s.contactCount());
        EXPECT_EQ(s.contactCount(), 1u); // touching, bonded or not
        if (bonded)
        {
            EXPECT_EQ(g.force[0], 0.0);
            EXPECT_EQ(g.position[3], 0.5199);
            EXPECT_EQ(s.bonds().first, std::vector<int>{0});
            EXPECT_EQ(s.bonds().second, std::vector<int>{1});
        }
        else // -k delta; delta = 0.02 - 0.0199 to the round-off of the coordinates, 1e-16 m
            EXPECT_NEAR(g.force[0], -1e6 * 1e-4, 1e-6 * 100.0);
    }
}

TEST_P(BondStore, FormationBondsEveryTouchingPairOnce)
{
    // A simple cubic lattice of 5 x 5 x 4 spheres, neighbours overlapping by 0.1 mm, radii
    // alternating 10 and 9.8 mm by parity (every neighbour pair has r_min = 9.8 mm). The first
    // step freezes every touching pair, the lattice's 4 5 4 + 5 4 4 + 5 5 3 = 235 neighbour
    // pairs; the second formation step (interval 3) finds them all bonded.
    const int nx = 5, ny = 5, nz = 4;
    const std::size_t lattice =
        std::size_t((nx - 1) * ny * nz + nx * (ny - 1) * nz + nx * ny * (nz - 1));
    dem::Parameters p = bondParameters();
    p.bonds.formation = dem::BondFormation::frozenOnContact;
    p.bonds.formationInterval = 3;
    p.bonds.seed = 11;
    dem::System s(p);
    std::vector<dem::GrainInit> grains;
    for (int i = 0; i < nx; ++i)
        for (int j = 0; j < ny; ++j)
            for (int k = 0; k < nz; ++k)
            {
                dem::GrainInit g;
                g.radius = (i + j + k) % 2 ? 0.0098 : 0.01;
                g.position = {0.3 + 0.0197 * i, 0.3 + 0.0197 * j, 0.3 + 0.0197 * k};
                grains.push_back(g);
            }
    s.addGrains(grains);
    s.step(0);
    const std::size_t touching = s.contactCount();
    s.step(4); // formation at steps 0 and 3: the second finds every touching pair bonded
    const dem::BondCounts counts = s.bondCounts();
    const dem::BondData bonds = s.bonds();
    const double low = p.bonds.areaFraction[0], high = p.bonds.areaFraction[1];
    double mean = 0, smallest = 1, largest = 0;
    for (double rb : bonds.patchRadius)
    {
        const double f = rb * rb / (0.0098 * 0.0098);
        mean += f / bonds.patchRadius.size();
        smallest = std::min(smallest, f);
        largest = std::max(largest, f);
    }
    std::printf("  %zu touching, %zu formed, %zu intact; r_b^2 / r_min^2 in [%.5f, %.5f], mean "
                "%.5f\n",
                touching, counts.formed, counts.intact, smallest, largest, mean);
    EXPECT_EQ(touching, lattice);
    EXPECT_EQ(counts.formed, lattice);
    EXPECT_EQ(counts.intact, lattice);
    EXPECT_EQ(counts.apart, 0u);
    EXPECT_TRUE(std::is_sorted(bonds.first.begin(), bonds.first.end()));
    for (std::size_t b = 0; b < bonds.first.size(); ++b)
        EXPECT_LT(bonds.first[b], bonds.second[b]);
    // Uniform on [low, high]: every value inside (to the rounding of sqrt and the square), the
    // mean within 4 standard errors (high - low) / sqrt(12 N), and with N = 235 the extremes
    // within 5 % of the range of its ends (probability of failing 0.95^235 = 6e-6 each).
    EXPECT_GE(smallest, low * (1 - 1e-14));
    EXPECT_LE(largest, high * (1 + 1e-14));
    EXPECT_NEAR(mean, 0.5 * (low + high), 4 * (high - low) / std::sqrt(12.0 * lattice));
    EXPECT_LT(smallest, low + 0.05 * (high - low));
    EXPECT_GT(largest, high - 0.05 * (high - low));
    EXPECT_NEAR(counts.meanPatchRadius,
                std::accumulate(bonds.patchRadius.begin(), bonds.patchRadius.end(), 0.0) / lattice,
                1e-15);
}

TEST_P(BondStore, RestartContinuesBitIdentically)
{
    // A gas that freezes on contact (formation every 5 steps) plus one added bond, with walls
    // and many rebuilds: export, continue; import into a fresh System and continue: grains and
    // bonds bit for bit, counters equal.
    dem::Parameters p = bondParameters();
    p.neighbourSkin = 5e-4;
    p.bonds.formation = dem::BondFormation::frozenOnContact;
    p.bonds.formationInterval = 5;
    auto make = [&]
    {
        dem::System s(p);
        addBondedPair(s, 0.0);
        s.addGrains(gas(400, 9));
        addWalls(s);
        return s;
    };
    dem::System original = make();
    original.step(1500);
    const dem::SystemState state = original.exportState();
    const dem::BondCounts before = original.bondCounts();
    original.step(1500);
    dem::System restarted(p);
    restarted.importState(state);
    restarted.step(1500);
    const dem::BondCounts a = original.bondCounts(), b = restarted.bondCounts();
    std::printf("  at export %zu intact, %zu formed; at the end %zu intact, %zu formed, %zu "
                "apart\n",
                before.intact, before.formed, a.intact, a.formed, a.apart);
    EXPECT_GT(a.formed, before.formed); // bonds formed after the export too
    EXPECT_EQ(a.intact, b.intact);
    EXPECT_EQ(a.formed, b.formed);
    EXPECT_EQ(a.broken, b.broken);
    EXPECT_EQ(a.apart, b.apart);
    expectIdenticalBonds(original.bonds(), restarted.bonds());
    const dem::GrainData ga = original.grains(), gb = restarted.grains();
    EXPECT_TRUE(identical(ga.position, gb.position));
    EXPECT_TRUE(identical(ga.velocity, gb.velocity));
    EXPECT_TRUE(identical(ga.angularVelocity, gb.angularVelocity));
    EXPECT_TRUE(identical(ga.force, gb.force));
    EXPECT_TRUE(identical(ga.torque, gb.torque));
    EXPECT_TRUE(identical(ga.orientation, gb.orientation));
}

TEST_P(BondStore, BadBondsAreRefusedByName)
{
    auto refused = [](const std::function<void()>& call, const std::string& expected)
    {
        try
        {
            call();
        }
        catch (const dem::Error& e)
        {
            std::printf("  refused: %s\n", e.what());
            EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
            return;
        }
        ADD_FAILURE() << "not refused: " << expected;
    };
    dem::System s(bondParameters());
    dem::GrainInit a, b;
    a.position = {0.3, 0.5, 0.5};
    b.position = {0.4, 0.5, 0.5};
    s.addGrains({a, b});
    s.addBonds({{0, 1, 0.003}});
    refused([&] { s.addBonds({{0, 2, 0.003}}); }, "grain index 2 out of range [0, 2)");
    refused([&] { s.addBonds({{-1, 1, 0.003}}); }, "grain index -1 out of range");
    refused([&] { s.addBonds({{1, 1, 0.003}}); }, "joins a grain to itself");
    refused([&] { s.addBonds({{1, 0, 0.003}}); }, "bonded already");
    dem::System t(bondParameters());
    t.addGrains({a, b});
    refused([&] { t.addBonds({{0, 1, 0.0}}); }, "patchRadius 0.000000; it must be > 0");
    refused([&] { t.addBonds({{0, 1, 0.001}, {1, 0, 0.002}}); }, "bonded already");
    EXPECT_EQ(t.bondCounts().intact, 0u); // a refused call adds nothing
    dem::Parameters off = bondParameters();
    off.bonds.enabled = false;
    dem::System u(off);
    u.addGrains({a, b});
    refused([&] { u.addBonds({{0, 1, 0.003}}); }, "bonds are not enabled");
    // A state with bonds cannot go into a System without them: nothing is dropped silently.
    refused([&] { u.importState(s.exportState()); }, "the state holds bonds");
}

TEST_P(BondStore, DrivenGrainsKeepTheirVelocityAndSpin)
{
    // A driven capsule under gravity ploughing through a resting sphere: its velocity and
    // angular velocity never change, its centre moves v t and its axis turns |omega| t about
    // omega (exact rotation; round-off of the 4000 quaternion products, ~1e-13, allowed).
    dem::Parameters p = parameters();
    p.gravity = {0.0, 0.0, -9.81};
    p.timeStep = 5e-6;
    dem::System s(p);
    dem::GrainInit c, sphere;
    c.radius = 0.005;
    c.coreHalfLength = 0.01;
    c.position = {0.5, 0.5, 0.5};
    c.flag = dem::GrainFlag::driven;
    sphere.radius = 0.01;
    sphere.position = {0.52, 0.5, 0.5};
    s.addGrains({c, sphere});
    const std::array<double, 3> v{0.5, 0.0, 0.1}, omega{0.0, 30.0, 10.0};
    s.setGrainVelocities({0}, v, omega);
    const int steps = 4000;
    s.step(steps);
    const dem::GrainData g = s.grains();
    const double t = steps * p.timeStep;
    const Eigen::Vector3d w(omega[0], omega[1], omega[2]);
    const Eigen::Quaterniond expected(Eigen::AngleAxisd(w.norm() * t, w.normalized()));
    const Eigen::Quaterniond q = orientationOf(g, 0);
    std::printf("  sphere moved %.6f m; capsule angle error %.3e\n",
                norm(sub(at(g.position, 1), {0.52, 0.5, 0.5})), q.angularDistance(expected));
    EXPECT_GT(norm(at(g.velocity, 1)), 0.1); // the sphere was hit
    for (int d = 0; d < 3; ++d)
    {
        EXPECT_EQ(g.velocity[d], v[d]);
        EXPECT_EQ(g.angularVelocity[d], omega[d]);
        // 4000 additions of v dt to ~0.5 m: round-off below 4000 x 0.5 x 1.1e-16 = 2.2e-13 m
        EXPECT_NEAR(g.position[d], c.position[d] + v[d] * t, 1e-12);
    }
    EXPECT_LT(q.angularDistance(expected), 1e-11);
}

DEM_TEST_ON_ALL_BACKENDS(BondStore);

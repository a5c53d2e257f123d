// BondStoreTest.cpp
// The bond store through dem::System, each body on every backend: a bond persists whatever its
// grains' distance, through neighbour rebuilds and re-sorting of the grains (bit for bit), across
// the periodic seam (to round-off) and through a restart (bit for bit); a broken bond is removed
// and the contact law takes the pair back; a bonded pair gets no contact-law loads; formation
// (frozenOnContact) bonds every touching pair once with r_b^2 / r_min^2 uniform in areaFraction;
// addBonds and importState refuse bad input by name; driven grains keep their velocity and spin;
// the other bonds keep their own loads on the step a bond breaks.
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

//- A gas of n spheres between walls at z = 0 and z = 1 that keeps the cell sort busy:
//- grains change cells every few steps, so internal indices change at every rebuild.
std::vector<dem::GrainInit> gas(int n, unsigned seed)
{
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> place(0.05, 0.95), speed(-2.0, 2.0);
    std::vector<dem::GrainInit> grains;
    while (int(grains.size()) < n)
    {
        dem::GrainInit g;
        g.radius = 0.01;
        g.position = {place(random), place(random), place(random)};
        // clear of the bonded pair's neighbourhood at the start, and of each other
        bool clear = std::fabs(g.position[2] - 0.5) > 0.05;
        for (const dem::GrainInit& other : grains)
            clear = clear && norm(sub(g.position, other.position)) > 0.025;
        if (!clear)
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
//- drift: both grains driven with that x velocity on top (the capsule then driven too).
void addBondedPair(dem::System& s, double shift, double drift = 0.0)
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
    s.setGrainVelocities({1}, {0.01 + drift, 0.003, 0.0}, {0.0, 0.0, 20.0});
    if (drift != 0.0)
    {
        s.setGrainFlags({0}, dem::GrainFlag::driven);
        s.setGrainVelocities({0}, {drift, 0.0, 0.0}, {0.0, 0.0, 0.0});
    }
    s.addBonds({{0, 1, 0.004}});
}

} // namespace

TEST_P(BondStore, BondedPairSurvivesRebuildsAndResortingBitForBit)
{
    // The pair's motion is prescribed (fixed and driven grains), so the bond's state depends on
    // nothing but the two grains and the law: with a gas of 300 grains re-sorted at every
    // rebuild (skin 0.3 mm, speeds up to 3.5 m/s: a rebuild every few steps) it must be the
    // same, bit for
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
    // In tension: the gap opened by v_x t = 0.2 mm along n, N = k_ne A du_n with
    // k_ne = E / (2 Rbar), Rbar = 9 mm, A = pi r_b^2 (the sideways and spinning motion is in the
    // contact plane: shear and twist only). The sum of 2000 increments: 1e-12 relative.
    const double kA = 1e6 / (2 * 0.009) * M_PI * 0.004 * 0.004;
    const double opened = 0.01 * steps * 1e-5;
    std::printf("  N %.12e N, k_ne A du_n %.12e N\n", a.normalForce[0], kA * opened);
    EXPECT_NEAR(a.normalForce[0], kA * opened, 1e-12 * kA * opened);
}

TEST_P(BondStore, BondedPairCrossingTheSeamKeepsItsBond)
{
    // The same pair carried across the periodic seam at x = 1 at 1.5 m/s (3 cm in 2000 steps,
    // from x = 0.98: the sphere crosses first, then the capsule), with rebuilds that wrap each
    // grain as it crosses (skin 0.5 mm: one every 17 steps), against the pair half a box away from
    // the seam. The bond sees only relative motion, so both must agree up to the round-off of
    // coordinates near 1 m against the 1e-2 m geometry: 1e-12 relative in the normal and the
    // normal force.
    dem::Parameters p = bondParameters();
    p.neighbourSkin = 5e-4;
    dem::System crossing(p), away(p);
    addBondedPair(crossing, -0.01, 1.5);
    addBondedPair(away, -0.51, 1.5);
    const int steps = 2000;
    crossing.step(steps);
    away.step(steps);
    const dem::GrainData g = crossing.grains();
    const dem::BondData a = crossing.bonds(), b = away.bonds();
    std::printf("  capsule at x %.6f, sphere at x %.6f, %zu rebuilds; N %.12e vs %.12e N\n",
                g.position[0], g.position[3], crossing.neighbourRebuildCount(), a.normalForce.at(0),
                b.normalForce.at(0));
    EXPECT_LT(g.position[0], 0.01); // both crossed and were wrapped
    EXPECT_LT(g.position[3], 0.03);
    EXPECT_GE(g.position[0], 0.0);
    ASSERT_EQ(a.first.size(), 1u);
    EXPECT_EQ(crossing.bondCounts().apart, 1u);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(a.normal[c], b.normal[c], 1e-12);
    const double shiftedPoint = b.point[0] + 0.5;
    EXPECT_NEAR(a.point[0], shiftedPoint - std::floor(shiftedPoint), 1e-12);
    EXPECT_NEAR(a.normalForce[0], b.normalForce[0], 1e-12 * std::fabs(b.normalForce[0]));
    EXPECT_GT(b.normalForce[0], 0.0); // in tension
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
    original.step(1000);
    const dem::SystemState state = original.exportState();
    const dem::BondCounts before = original.bondCounts();
    original.step(1000);
    dem::System restarted(p);
    restarted.importState(state);
    restarted.step(1000);
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

TEST_P(BondStore, BrokenBondIsRemovedAndTheContactLawReturns)
{
    // Two spheres just touching (r = 10 mm), bonded (r_b = 3 mm, tensile strength 1 kPa, no
    // shear failure, softening ratio 1): the driven one pulls away at 1 cm/s. k_ne = E / (2 Rbar)
    // = 5e7 Pa/m, so the bond softens past an opening of sigma_t / k_ne = 20 um and breaks by
    // 40 um (the softening branch reaches zero), i.e. after 2 and 4 ms (200 and 400 steps).
    // The store must drop it and count it; pushed back together, the pair feels the contact
    // law again: -k delta on the fixed grain, from a history that starts at zero.
    dem::Parameters p = bondParameters();
    p.bonds.strength = dem::BondStrength::constant;
    p.bonds.tensileStrength = 1e3;
    p.bonds.shearStrength = 0.0; // never fails in shear
    p.bonds.softeningRatio = 1.0;
    dem::System s(p);
    dem::GrainInit a, b;
    a.radius = b.radius = 0.01;
    a.position = {0.5, 0.5, 0.5};
    a.flag = dem::GrainFlag::fixed;
    b.position = {0.52, 0.5, 0.5};
    b.flag = dem::GrainFlag::driven;
    s.addGrains({a, b});
    s.addBonds({{0, 1, 0.003}});
    s.setGrainVelocities({1}, {0.01, 0.0, 0.0}, {0.0, 0.0, 0.0});
    s.step(300); // 30 um: softening
    const dem::BondData softened = s.bonds();
    ASSERT_EQ(softened.first.size(), 1u);
    std::printf("  at 30 um: r_b %.6e m, softening %d, N %.6e N\n", softened.patchRadius[0],
                int(softened.softening[0]), softened.normalForce[0]);
    EXPECT_EQ(softened.softening[0], 1);
    // x = 30 um / 20 um = 1.5 on the branch: r_b = r_0 sqrt((1 - (x - 1)) / x) (the
    // softening closed form, 300 increments: round-off far below 1e-9 relative)
    EXPECT_NEAR(softened.patchRadius[0], 0.003 * std::sqrt(0.5 / 1.5), 1e-9 * 0.003);
    s.step(200); // 50 um: broken
    dem::BondCounts counts = s.bondCounts();
    std::printf("  at 50 um: %zu intact, %zu broken, %zu formed\n", counts.intact, counts.broken,
                counts.formed);
    EXPECT_EQ(counts.intact, 0u);
    EXPECT_EQ(counts.broken, 1u);
    EXPECT_EQ(counts.formed, 0u);
    EXPECT_TRUE(s.bonds().first.empty());
    EXPECT_EQ(s.grains().force[0], 0.0); // apart and unbonded: nothing acts
    // Back by 60 um: 10 um of overlap at the end.
    s.setGrainVelocities({1}, {-0.01, 0.0, 0.0}, {0.0, 0.0, 0.0});
    s.step(600);
    const dem::GrainData g = s.grains();
    const double overlap = 0.02 - (g.position[3] - g.position[0]);
    std::printf("  overlap %.6e m, force on the fixed grain %.9e N, contacts %zu\n", overlap,
                g.force[0], s.contactCount());
    EXPECT_GT(overlap, 5e-6);
    EXPECT_EQ(s.contactCount(), 1u);
    EXPECT_EQ(s.bondCounts().broken, 1u);
    // k delta with delta from the read-back positions (round-off 1e-16 m of 1e-5 m)
    EXPECT_NEAR(g.force[0], -1e6 * overlap, 1e-9 * 1e6 * overlap);
}

// Two bonded pairs far apart: one pulled until its bond breaks, one held stretched. The second
// is independent of the first, so the force on its fixed grain must be the same, step by step
// and bit for bit, as in a system without the first pair, also on the step the first bond breaks
// and is removed from the store (its removal moves the other bond to another index; the loads
// must move with it). Both store orders: the breaking pair placed before and after the other.
TEST_P(BondStore, OtherBondsKeepTheirLoadsWhenABondBreaks)
{
    dem::Parameters p = bondParameters();
    p.bonds.strength = dem::BondStrength::constant;
    p.bonds.tensileStrength = 1e3;
    p.bonds.shearStrength = 0.0;
    for (const double breakingAt : {0.2, 0.7})
    {
        const double heldAt = 0.9 - breakingAt;
        auto pair = [](double x, dem::GrainInit& fixed, dem::GrainInit& driven)
        {
            fixed.radius = driven.radius = 0.01;
            fixed.position = {x, 0.5, 0.5};
            fixed.flag = dem::GrainFlag::fixed;
            driven.position = {x + 0.02, 0.5, 0.5};
            driven.flag = dem::GrainFlag::driven;
        };
        dem::GrainInit a, b, c, d;
        pair(breakingAt, a, b);
        pair(heldAt, c, d);
        dem::System both(p), alone(p);
        both.addGrains({a, b, c, d});
        both.addBonds({{0, 1, 0.003}, {2, 3, 0.003}});
        both.setGrainVelocities({1}, {0.01, 0.0, 0.0}, {0.0, 0.0, 0.0});
        both.setGrainVelocities({3}, {0.001, 0.0, 0.0}, {0.0, 0.0, 0.0});
        alone.addGrains({c, d});
        alone.addBonds({{0, 1, 0.003}});
        alone.setGrainVelocities({1}, {0.001, 0.0, 0.0}, {0.0, 0.0, 0.0});
        int differing = 0, brokeAt = -1;
        for (int step = 0; step < 500; ++step)
        {
            both.step(1);
            alone.step(1);
            if (brokeAt < 0 && both.bondCounts().broken == 1)
                brokeAt = step;
            differing += both.grains().force[6] != alone.grains().force[0];
        }
        EXPECT_GT(brokeAt, 0) << "the pulled bond should break within 500 steps";
        EXPECT_EQ(both.bondCounts().intact, 1u);
        EXPECT_EQ(differing, 0) << "breaking pair at x = " << breakingAt << ", broke at step "
                                << brokeAt;
    }
}

TEST_P(BondStore, ThreadCountChangesNoBit)
{
    // A lattice of 4800 spheres frozen on contact (about 13,000 bonds: the per-grain and
    // per-bond passes run on all threads above 4096 items) settling on a wall under gravity,
    // with a skin small enough for rebuilds: 1 and 2 threads give the same bits (each bond is
    // evaluated alone, each grain sums its pairs and bonds in a fixed order).
    auto run = [&](int threads)
    {
        dem::Parameters p = bondParameters();
        p.threads = threads;
        p.gravity = {0.0, 0.0, -9.81};
        p.neighbourSkin = 2e-5;
        p.bonds.formation = dem::BondFormation::frozenOnContact;
        p.bonds.formationInterval = 7;
        p.bonds.normalDampingRatio = 0.3;
        dem::System s(p);
        std::vector<dem::GrainInit> grains;
        for (int i = 0; i < 20; ++i)
            for (int j = 0; j < 20; ++j)
                for (int k = 0; k < 12; ++k)
                {
                    dem::GrainInit g;
                    g.radius = (i + j + k) % 2 ? 0.0098 : 0.01;
                    g.position = {0.1 + 0.0197 * i, 0.1 + 0.0197 * j, 0.0098 + 0.0197 * k};
                    grains.push_back(g);
                }
        s.addGrains(grains);
        s.addWall(dem::WallSpec());
        s.step(60);
        return std::make_pair(s.grains(), std::make_pair(s.bonds(), s.neighbourRebuildCount()));
    };
    const auto one = run(1), two = run(2);
    std::printf("  %zu bonds, %zu rebuilds\n", one.second.first.first.size(), one.second.second);
    EXPECT_GT(one.second.first.first.size(), 4096u);
    EXPECT_GT(one.second.second, 1u);
    EXPECT_TRUE(identical(one.first.position, two.first.position));
    EXPECT_TRUE(identical(one.first.velocity, two.first.velocity));
    EXPECT_TRUE(identical(one.first.force, two.first.force));
    EXPECT_TRUE(identical(one.first.torque, two.first.torque));
    expectIdenticalBonds(one.second.first, two.second.first);
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

TEST_P(BondStore, StiffBondsLowerTheCriticalTimeStep)
{
    // A bond as wide as the grains (r_b = r = 1 cm) with E = 1e9 Pa: k_ne A = E / (2 r) pi r^2
    // = 1.571e7 N/m, stiffer than the contacts (1e6 N/m), so it sets sqrt(m / k_max); with
    // formation on, the stiffest bond it may add, E pi f_max r / 2, counts before any forms.
    dem::Parameters p = bondParameters();
    p.bonds.youngsModulus = 1e9;
    dem::System s(p);
    dem::GrainInit a, b;
    a.position = {0.5, 0.5, 0.5};
    b.position = {0.52, 0.5, 0.5};
    s.addGrains({a, b});
    const double mass = 2600 * sphereVolume(0.01);
    const double contactStep = std::sqrt(mass / 1e6);
    EXPECT_NEAR(s.criticalTimeStep(), contactStep, 1e-12 * contactStep); // no bond yet
    s.addBonds({{0, 1, 0.01}});
    const double bondStep = std::sqrt(mass / (1e9 / 0.02 * M_PI * 1e-4));
    std::printf("  critical step %.6e s with the bond (%.6e s by the closed form), %.6e s "
                "without\n",
                s.criticalTimeStep(), bondStep, contactStep);
    EXPECT_NEAR(s.criticalTimeStep(), bondStep, 1e-12 * bondStep);
    s.setTimeStep(0.5 * (0.2 * bondStep + 0.2 * contactStep)); // allowed without the bond only
    EXPECT_THROW(s.step(1), dem::Error);
    p.bonds.formation = dem::BondFormation::frozenOnContact;
    dem::System t(p);
    t.addGrains({a, b});
    const double formationStep =
        std::sqrt(mass / (0.5 * M_PI * 1e9 * p.bonds.areaFraction[1] * 0.01));
    EXPECT_NEAR(t.criticalTimeStep(), formationStep, 1e-12 * formationStep);
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

    // A free capsule given omega by setGrainVelocities turns at it: its angular momentum is
    // R I R^T omega (read back as omega = R I^-1 R^T L, to round-off of the two products).
    dem::System f(p);
    dem::GrainInit free = c;
    free.flag = dem::GrainFlag::free;
    free.orientation = rotation(Eigen::Vector3d(1.0, 2.0, 0.5), 0.7);
    f.addGrain(free);
    f.setGrainVelocities({0}, v, omega);
    f.step(0);
    const dem::GrainData h = f.grains();
    for (int d = 0; d < 3; ++d)
        EXPECT_NEAR(h.angularVelocity[d], omega[d], 1e-12 * 31.7); // |omega| = 31.6 rad/s
}

DEM_TEST_ON_ALL_BACKENDS(BondStore);

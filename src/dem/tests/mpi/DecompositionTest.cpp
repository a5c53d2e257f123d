// DecompositionTest.cpp
// The DEM System split over two MPI ranks (Parameters::decomposition), run by ctest as
// `mpiexec -n 2 demMpiTests` (main below): every rank runs every test body, and a test fails
// when it fails on any rank. Assertions come after the collective calls (EXPECT, not ASSERT,
// where a rank leaving early would leave the other waiting).
//   - A sheared packing whose grains cross the rank boundaries for more than 100 neighbour
//     rebuilds keeps every grain exactly once, its mass, and its momentum to round-off.
//   - A dense packing with pairs across the boundaries, on a wall and under a stress-controlled
//     lid, follows the one-process run within the growth of round-off (bound measured as
//     BackendComparisonTest does); so does one whose grains all lie in one rank's box (the
//     other owns nothing).
//   - A restart from each rank's exported state continues bit for bit, with bonds too; the
//     state gathered on rank 0 continues on one process with the split run's kinetic energy
//     and bond counts, and a one-process state continues split as on one process.
//   - Bonded capsules sheared across the boundaries (bonds forming, breaking and travelling
//     with their grains) end with the one-process kinetic energy and bond counts.
//   - The fluid coupling: the deposit and the grains' reaction summed over the ranks equal the
//     one-process ones within the rounding of their sums; under a fluid force and drag the bed
//     follows the one-process run within the growth of round-off.
//   - Grain flags set by each rank for its own block (fixed base, driven top): the sheared bed
//     and the driving force follow one process within the growth of round-off.
//   - Misuse is refused with messages that name the entry: rank counts, calls not available
//     yet (addBonds), a decomposed state imported on one process.
// (The benchmark packing on 1 and 2 ranks: tests/mpi/test_dem_mpi.py, through demBench.)
#include "PackingFile.h"
#include "TestSupport.h"
#include "dem/Mpi.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>

using namespace demTest;

namespace
{

const dem::MpiSession* mpi = nullptr;

//- The bottom grains of the benchmark packing (z < zTop), in its periodic box of side L.
dem::Packing bottomOfBenchmarkPacking(double zTop)
{
    dem::Packing all = dem::readPacking(DEM_BENCH_PACKINGS "/packing_10000.txt", 2600.0);
    dem::Packing out = all;
    out.grains.clear();
    for (const dem::GrainInit& g : all.grains)
        if (g.position[2] < zTop)
            out.grains.push_back(g);
    return out;
}

//- Benchmark contact law (bench/README.md), no gravity, periodic in x and y, no walls.
dem::Parameters shearParameters(dem::Backend backend, double length, double skin)
{
    dem::Parameters p;
    p.grainGrain = {1.16e9, 1.16e9, 0.0, 0.0, 0.5};
    p.grainWall = p.grainGrain;
    p.gravity = {0.0, 0.0, 0.0};
    p.boxLower = {0.0, 0.0};
    p.boxUpper = {length, length};
    p.periodic = {true, true};
    p.timeStep = 2.14e-7;
    p.neighbourSkin = skin;
    p.backend = backend;
    p.threads = 1;
    return p;
}

//- The grains of rank r's share when each rank adds a contiguous block (add order kept).
std::vector<dem::GrainInit> blockOf(const std::vector<dem::GrainInit>& grains)
{
    const std::size_t n = grains.size(), r = std::size_t(mpi->rank()),
                      ranks = std::size_t(mpi->size());
    return {grains.begin() + long(n * r / ranks), grains.begin() + long(n * (r + 1) / ranks)};
}

//- Sum over all ranks of a per-grain quantity of the grains each rank owns.
template <class F>
double sumOwned(const dem::GrainData& g, F f)
{
    double s = 0.0;
    for (std::size_t i = 0; i < g.mass.size(); ++i)
        s += f(i);
    return mpi->sum(s);
}

//- The grains moved by eta0 = steps x 4 ulp of the box length, each in a random direction: the
//- start of the one-process run whose distance from the reference bounds the growth of
//- round-off (the sum of every step's possible difference, BackendComparisonTest).
std::vector<dem::GrainInit> perturbedForSteps(const std::vector<dem::GrainInit>& grains,
                                              double boxLength, int steps, unsigned seed)
{
    const double eta0 = steps * 4.0 * (std::nextafter(boxLength, 2.0 * boxLength) - boxLength);
    std::vector<dem::GrainInit> perturbed = grains;
    std::mt19937 random(seed);
    std::normal_distribution<double> normal;
    for (dem::GrainInit& g : perturbed)
    {
        Vec3 e{normal(random), normal(random), normal(random)};
        const double length = norm(e);
        for (int d = 0; d < 3; ++d)
            g.position[d] += eta0 * e[d] / length;
    }
    return perturbed;
}

//- p, split into 2 x 1 boxes when `split` (else on one process).
dem::Parameters splitIf(dem::Parameters p, bool split)
{
    if (split)
        p.decomposition.ranks = {2, 1};
    return p;
}

//- The largest distance between the grains of two one-process runs (same order).
double largestDistance(const dem::GrainData& a, const dem::GrainData& reference)
{
    double largest = 0.0;
    for (std::size_t i = 0; i < reference.mass.size(); ++i)
        largest = std::max(largest, norm(sub(at(a.position, i), at(reference.position, i))));
    return largest;
}

//- The largest distance, over all ranks, between a split run's grains and the same grains
//- (by id) of a one-process run.
double largestSplitDistance(const dem::GrainData& split, const dem::GrainData& reference)
{
    double largest = 0.0;
    for (std::size_t k = 0; k < split.id.size(); ++k)
        largest = std::max(largest, norm(sub(at(split.position, k),
                                             at(reference.position, std::size_t(split.id[k])))));
    return mpi->max(largest);
}

//- p with bonds frozen on contact every 10 steps (elastic patch, Maxwell creep, a constant
//- strength low enough that many break in the sheared packings here); rMax the largest radius.
dem::Parameters withFrozenBonds(dem::Parameters p, double rMax)
{
    p.bonds.enabled = true;
    p.bonds.formation = dem::BondFormation::frozenOnContact;
    p.bonds.formationInterval = 10;
    p.bonds.youngsModulus = 2.0 * p.grainGrain.normalStiffness / (M_PI * 0.09375 * rMax);
    p.bonds.creep = dem::BondCreep::maxwell;
    p.bonds.contactViscosity = 1e6;
    p.bonds.strength = dem::BondStrength::constant;
    p.bonds.tensileStrength = p.bonds.shearStrength = 1e8;
    return p;
}

//- The grains with v_x = 20 (z - 0.05) / 0.05 m/s: a shear that carries them across the cuts.
std::vector<dem::GrainInit> sheared(std::vector<dem::GrainInit> grains)
{
    for (dem::GrainInit& g : grains)
        g.velocity = {20.0 * (g.position[2] - 0.05) / 0.05, 0.0, 0.0};
    return grains;
}

//- Kinetic energy of the grains in g (this rank's, or all of a one-process System's).
double kineticEnergy(const dem::GrainData& g)
{
    double energy = 0.0;
    for (std::size_t i = 0; i < g.mass.size(); ++i)
        energy += 0.5 * g.mass[i] * dot(at(g.velocity, i), at(g.velocity, i));
    return energy;
}

class Decomposition : public BackendTest
{
};

// A shear flow v_x = U (z - z_mid) / (h / 2) through a dense periodic packing: the grains cross
// the cuts at x = 0 and x = L/2 all the time. Invariants: each grain owned by exactly one rank
// (count, sum of ids and of their squares, exact in doubles), its mass (a record field that
// travels), and the momentum. Momentum bound: every step rounds each grain's two kicks (a
// relative change of at most eps |m v| each) and the two ranks of a pair across a boundary
// evaluate its force separately (forces differing in the last bits, each a change of at most
// eps |m dv| per step, below the kicks' eps |m v| while |dv| << |v|); so after S steps
// |P(S) - P(0)| <= 4 eps S max_t sum_i m_i |v_i|. Summed with random signs the actual drift is
// ~sqrt(S N) smaller. A force lost at a boundary, a ghost one step stale or a grain dropped would
// change P by ~k |dx| dt ~ 1e-4 N s per contact and step, far above this bound (~1e-9 N s).
TEST_P(Decomposition, ShearedPackingKeepsGrainsMassAndMomentum)
{
    const dem::Packing packing = bottomOfBenchmarkPacking(0.1);
    const double U = 20.0, skin = 8e-4; // a rebuild every ~90 steps
    double zLow = HUGE_VAL, zHigh = -HUGE_VAL;
    for (const dem::GrainInit& g : packing.grains)
    {
        zLow = std::min(zLow, g.position[2]);
        zHigh = std::max(zHigh, g.position[2]);
    }
    std::vector<dem::GrainInit> grains = packing.grains;
    for (dem::GrainInit& g : grains)
        g.velocity = {U * (g.position[2] - 0.5 * (zLow + zHigh)) / (0.5 * (zHigh - zLow)), 0.0,
                      0.0};
    const long n = long(grains.size());
    double mass0 = 0.0;
    for (const dem::GrainInit& g : grains)
        mass0 += 2600.0 * sphereVolume(g.radius);

    dem::Parameters p = shearParameters(GetParam(), packing.length, skin);
    p.decomposition.ranks = {2, 1};
    dem::System system(p);
    system.addGrains(blockOf(grains));
    system.step(0);
    const dem::GrainData start = system.grains();
    std::vector<int> ownedAtStart = start.id;
    auto momentum = [&](const dem::GrainData& g, int d)
    { return sumOwned(g, [&](std::size_t i) { return g.mass[i] * g.velocity[3 * i + d]; }); };
    auto absoluteMomentum = [&](const dem::GrainData& g)
    { return sumOwned(g, [&](std::size_t i) { return g.mass[i] * norm(at(g.velocity, i)); }); };
    const std::array<double, 3> p0 = {momentum(start, 0), momentum(start, 1), momentum(start, 2)};
    double largestAbsolute = absoluteMomentum(start);
    long steps = 0;
    while (system.neighbourRebuildCount() < 110 && steps < 40000)
    {
        system.step(250);
        steps += 250;
        largestAbsolute = std::max(largestAbsolute, absoluteMomentum(system.grains()));
    }
    const dem::GrainData end = system.grains();
    const double count = mpi->sum(double(end.id.size()));
    const double idSum = sumOwned(end, [&](std::size_t i) { return double(end.id[i]); });
    const double idSquares =
        sumOwned(end, [&](std::size_t i) { return double(end.id[i]) * double(end.id[i]); });
    const double mass = sumOwned(end, [&](std::size_t i) { return end.mass[i]; });
    std::vector<int> ownedAtEnd = end.id;
    std::sort(ownedAtEnd.begin(), ownedAtEnd.end());
    std::vector<int> changed;
    std::set_difference(ownedAtEnd.begin(), ownedAtEnd.end(), ownedAtStart.begin(),
                        ownedAtStart.end(), std::back_inserter(changed));
    const double arrived = mpi->sum(double(changed.size()));
    const double bound =
        4.0 * std::numeric_limits<double>::epsilon() * double(steps) * largestAbsolute;
    std::array<double, 3> drift{};
    for (int d = 0; d < 3; ++d)
        drift[d] = momentum(end, d) - p0[d];

    EXPECT_GE(system.neighbourRebuildCount(), 100u);
    EXPECT_GT(arrived, 0.0) << "the shear should move grains to the other rank";
    EXPECT_EQ(count, double(n));
    EXPECT_EQ(system.grainCount(), std::size_t(n));
    EXPECT_EQ(idSum, double(n) * double(n - 1) / 2.0);
    EXPECT_EQ(idSquares, double(n - 1) * double(n) * double(2 * n - 1) / 6.0);
    EXPECT_NEAR(mass, mass0, 64.0 * std::numeric_limits<double>::epsilon() * mass0);
    for (int d = 0; d < 3; ++d)
        EXPECT_LE(std::fabs(drift[d]), bound)
            << "momentum component " << d << " after " << steps << " steps";
    if (mpi->rank() == 0)
        std::printf("  %ld grains, %ld steps, %zu rebuilds, %.0f changed rank; momentum drift "
                    "(%.3g %.3g %.3g) N s, bound %.3g N s (sum m|v| up to %.4g N s)\n",
                    n, steps, system.neighbourRebuildCount(), arrived, drift[0], drift[1], drift[2],
                    bound, largestAbsolute);
}

// Pairs across the boundaries: forces of such a pair are evaluated on both ranks (in either
// order, summed in another order), so the split run leaves the one-process trajectory by
// round-off, which grows in a dense packing. The bound is that growth, measured on one process
// as BackendComparisonTest does: a second run starts from positions moved by
// eta0 = steps x 4 ulp(x_max) in random directions, the sum of every step's possible difference.
// The second case puts all grains on one side, away from the cuts: rank 1 owns nothing and still
// takes part in every collective call.
TEST_P(Decomposition, DensePackingFollowsOneProcessWithinRoundOffGrowth)
{
    const dem::Packing packing = bottomOfBenchmarkPacking(0.1);
    for (const bool oneSided : {false, true})
    {
        std::vector<dem::GrainInit> grains;
        for (const dem::GrainInit& g : packing.grains)
            if (!oneSided ||
                (g.position[0] > 0.05 * packing.length && g.position[0] < 0.4 * packing.length))
                grains.push_back(g);
        const int steps = 1500;
        dem::Parameters p = shearParameters(GetParam(), packing.length, 2e-3);
        p.gravity = {0.0, 0.0, -9.81};
        p.grainGrain.normalDamping = p.grainGrain.tangentialDamping = 0.0;
        // A lid under a normal stress on the highest grain: its motion follows the sum of the
        // grains' forces on it over both ranks (the same on each rank).
        dem::WallSpec lid;
        lid.side = dem::WallSpec::Side::upper;
        lid.mode = dem::WallSpec::Mode::stress;
        lid.mass = 0.1;
        lid.normalStress = 500.0;
        for (const dem::GrainInit& g : grains)
            lid.position = std::max(lid.position, g.position[2] + g.radius);
        auto run = [&](const std::vector<dem::GrainInit>& start, bool split, double& wallForce,
                       double& contacts, double& lidPosition)
        {
            dem::System s(splitIf(p, split));
            s.addGrains(split ? blockOf(start) : start);
            s.addWall(dem::WallSpec{});
            s.addWall(lid);
            s.step(steps);
            wallForce = s.wall(0).grainForce;
            contacts = double(s.contactCount());
            lidPosition = s.wall(1).position;
            return s.grains();
        };
        const double xMax = packing.length;
        const double eta0 = steps * 4.0 * (std::nextafter(xMax, 2.0 * xMax) - xMax);
        const std::vector<dem::GrainInit> perturbed =
            perturbedForSteps(grains, packing.length, steps, 7);
        double wallForce = 0.0, contacts = 0.0, splitWallForce = 0.0, splitContacts = 0.0, unused;
        double lidReference = 0.0, lidMoved = 0.0, lidSplit = 0.0;
        const dem::GrainData reference = run(grains, false, wallForce, contacts, lidReference),
                             moved = run(perturbed, false, unused, unused, lidMoved),
                             split = run(grains, true, splitWallForce, splitContacts, lidSplit);
        double bound = std::fabs(lidMoved - lidReference),
               largest = std::fabs(lidSplit - lidReference);
        EXPECT_EQ(mpi->max(lidSplit), mpi->min(lidSplit)) << "the lid must be one on all ranks";
        bound = std::max(bound, largestDistance(moved, reference));
        largest = std::max(largest, largestSplitDistance(split, reference));
        const double owned = double(split.id.size());
        EXPECT_LE(largest, bound) << (oneSided ? "one-sided" : "whole bed");
        EXPECT_EQ(mpi->sum(owned), double(grains.size()));
        if (oneSided)
            EXPECT_EQ(mpi->min(owned), 0.0) << "one rank should own nothing";
        // The wall's load and the contacts: the same terms, summed per rank and then over the
        // ranks, from positions within the bound (far below the overlaps, ~1e-6 m).
        EXPECT_NEAR(splitWallForce, wallForce, 1e-6 * std::fabs(wallForce));
        EXPECT_EQ(splitContacts, contacts);
        if (mpi->rank() == 0)
            std::printf("  %s: %zu grains, %d steps: largest position difference split vs one "
                        "process %.3g m, bound from eta0 = %.3g m: %.3g m; contacts %.0f / %.0f, "
                        "wall load %.10g / %.10g N, lid %.12g / %.12g m\n",
                        oneSided ? "one-sided" : "whole bed", reference.mass.size(), steps, largest,
                        eta0, bound, splitContacts, contacts, splitWallForce, wallForce, lidSplit,
                        lidReference);
    }
}

// Capsules (cores 0.05 r along random axes, dilated by 0.95 r: each inside its sphere of the
// packing, so no new overlap) sheared at up to 10 m/s across both cuts, bonds frozen on contact
// every 10 steps (elastic patch, Maxwell creep, constant strength low enough that many break), the
// lists rebuilt as grains change rank with their bonds: the split run ends with the one-process
// kinetic energy within 1e-6 relative (the MPI issue's criterion) and the same bond counts.
// (A bond across a boundary is evaluated alike on both ranks, from the same bits: measured,
// the two runs agree to 12 digits. This test found that a bond's loads stayed at their old
// index when a broken bond was removed, so on that step the bonds after it applied their
// neighbours' loads, in another store order on each rank.)
TEST_P(Decomposition, BondedCapsulesAcrossTheBoundaryFollowOneProcess)
{
    const dem::Packing packing = bottomOfBenchmarkPacking(0.06);
    std::vector<dem::GrainInit> grains = packing.grains;
    std::mt19937 random(3);
    std::normal_distribution<double> normal;
    double rMax = 0.0;
    for (dem::GrainInit& g : grains)
    {
        const double r = g.radius;
        rMax = std::max(rMax, r);
        g.radius = 0.95 * r;
        g.coreHalfLength = 0.05 * r;
        Vec3 axis{normal(random), normal(random), normal(random)};
        const double length = norm(axis);
        // the rotation taking z to the axis: q = (1 + a_z, z x a), normalised
        const Vec3 a{axis[0] / length, axis[1] / length, axis[2] / length};
        const double w = 1.0 + a[2], qNorm = std::sqrt(w * w + a[1] * a[1] + a[0] * a[0]);
        g.orientation = {w / qNorm, -a[1] / qNorm, a[0] / qNorm, 0.0};
        g.velocity = {10.0 * (g.position[2] - 0.03) / 0.03, 0.0, 0.0};
    }
    const dem::Parameters p =
        withFrozenBonds(shearParameters(GetParam(), packing.length, 8e-4), rMax);
    auto run = [&](bool split, dem::BondCounts& counts, std::size_t& rebuilds)
    {
        dem::System s(splitIf(p, split));
        s.addGrains(split ? blockOf(grains) : grains);
        s.step(3000);
        counts = s.bondCounts();
        rebuilds = s.neighbourRebuildCount();
        const double energy = kineticEnergy(s.grains());
        return split ? mpi->sum(energy) : energy;
    };
    dem::BondCounts one, two;
    std::size_t rebuildsOne = 0, rebuildsTwo = 0;
    const double energyOne = run(false, one, rebuildsOne), energyTwo = run(true, two, rebuildsTwo);
    EXPECT_NEAR(energyTwo, energyOne, 1e-6 * energyOne);
    EXPECT_EQ(two.intact, one.intact);
    EXPECT_EQ(two.formed, one.formed);
    EXPECT_EQ(two.broken, one.broken);
    EXPECT_GT(one.broken, 0u) << "some bonds should break (raise the load or lower the strength)";
    EXPECT_GT(one.intact, 0u);
    EXPECT_EQ(rebuildsTwo, rebuildsOne);
    EXPECT_GE(rebuildsOne, 10u);
    if (mpi->rank() == 0)
        std::printf("  %zu capsules, 3000 steps, %zu rebuilds: KE %.12g / %.12g J, bonds intact "
                    "%zu / %zu, formed %zu / %zu, broken %zu / %zu (2 ranks / 1)\n",
                    grains.size(), rebuildsOne, energyTwo, energyOne, two.intact, one.intact,
                    two.formed, one.formed, two.broken, one.broken);
}

// Each rank exports its part (owned grains, ghosts, pair lists with histories, exchange lists);
// a new System on the same decomposition imports it and continues bit for bit as the run that
// was not interrupted, through rebuilds with grains changing rank (the sheared packing).
TEST_P(Decomposition, RestartFromDecomposedStateIsExact)
{
    const dem::Packing packing = bottomOfBenchmarkPacking(0.1);
    const std::vector<dem::GrainInit> grains = sheared(packing.grains);
    for (const bool bonded : {false, true})
    {
        dem::Parameters p = shearParameters(GetParam(), packing.length, 8e-4);
        p.decomposition.ranks = {2, 1};
        if (bonded) // many breaking in the shear (the test above's)
            p = withFrozenBonds(p, 0.0105);
        dem::System whole(p), first(p);
        whole.addGrains(blockOf(grains));
        first.addGrains(blockOf(grains));
        whole.step(700);
        first.step(700);
        const dem::SystemState state = first.exportState();
        whole.step(700);
        dem::System second(p);
        second.importState(state);
        second.step(700);
        const dem::GrainData a = whole.grains(), b = second.grains();
        const dem::BondData bondsA = whole.bonds(), bondsB = second.bonds();
        bool same = a.id == b.id && a.position == b.position && a.velocity == b.velocity &&
                    a.angularVelocity == b.angularVelocity && bondsA.first == bondsB.first &&
                    bondsA.second == bondsB.second && bondsA.normalForce == bondsB.normalForce;
        const double sameEverywhere = mpi->min(same ? 1.0 : 0.0);
        const dem::BondCounts countsA = whole.bondCounts(), countsB = second.bondCounts();
        EXPECT_EQ(sameEverywhere, 1.0) << (bonded ? "with bonds" : "without bonds");
        EXPECT_EQ(second.neighbourRebuildCount(), whole.neighbourRebuildCount());
        EXPECT_GT(whole.neighbourRebuildCount(), 10u);
        EXPECT_EQ(second.grainCount(), grains.size());
        EXPECT_EQ(countsB.formed, countsA.formed);
        EXPECT_EQ(countsB.broken, countsA.broken);
        if (bonded)
            EXPECT_GT(countsA.broken, 0u);
        if (mpi->rank() == 0)
            std::printf("  %s: %zu rebuilds, bonds formed %zu, broken %zu, intact %zu\n",
                        bonded ? "bonded" : "unbonded", whole.neighbourRebuildCount(),
                        countsA.formed, countsA.broken, countsA.intact);
    }
}

// The split run's state gathered on rank 0 (exportGatheredState: every grain in id order, each
// contact history and bond once) and imported by a one-process System: at once it holds the
// split run's grains (count, kinetic energy to the rounding of the sums, 2 (n - 1) eps) and
// bond counts; after 700 more steps of both it ends with the split run's kinetic energy within
// 1e-6 relative (the MPI issue's criterion, as above) and the same bond counts. That the
// contact histories came along matters: without bonds the same import with the histories
// zeroed ends further away than that (measured 2.2e-5 relative), so the criterion would catch
// a gather that dropped them; with bonds the bond counts at import say the bonds came.
TEST_P(Decomposition, GatheredStateContinuesOnOneProcess)
{
    const dem::Packing packing = bottomOfBenchmarkPacking(0.1);
    const std::vector<dem::GrainInit> grains = sheared(packing.grains);
    const double eps = std::numeric_limits<double>::epsilon();
    for (const bool bonded : {false, true})
    {
        dem::Parameters p = shearParameters(GetParam(), packing.length, 8e-4);
        if (bonded)
            p = withFrozenBonds(p, 0.0105);
        dem::System split(splitIf(p, true));
        split.addGrains(blockOf(grains));
        split.step(700);
        const dem::SystemState gathered = split.exportGatheredState();
        const double energyAtGather = mpi->sum(kineticEnergy(split.grains()));
        const dem::BondCounts countsAtGather = split.bondCounts();
        split.step(700);
        const double energyEnd = mpi->sum(kineticEnergy(split.grains()));
        const dem::BondCounts countsEnd = split.bondCounts();
        if (mpi->rank() != 0)
        {
            EXPECT_TRUE(gathered.reals.empty() && gathered.integers.empty());
            continue;
        }
        dem::System one(p);
        one.importState(gathered);
        const std::size_t n = grains.size();
        EXPECT_EQ(one.grainCount(), n);
        EXPECT_NEAR(kineticEnergy(one.grains()), energyAtGather,
                    2.0 * (n - 1) * eps * energyAtGather);
        EXPECT_EQ(one.bondCounts().intact, countsAtGather.intact);
        EXPECT_EQ(one.bondCounts().formed, countsAtGather.formed);
        EXPECT_EQ(one.bondCounts().broken, countsAtGather.broken);
        one.step(700);
        const double energyOne = kineticEnergy(one.grains());
        EXPECT_NEAR(energyOne, energyEnd, 1e-6 * energyEnd);
        EXPECT_EQ(one.bondCounts().intact, countsEnd.intact);
        EXPECT_EQ(one.bondCounts().formed, countsEnd.formed);
        EXPECT_EQ(one.bondCounts().broken, countsEnd.broken);

        double energyForgetful = 0.0;
        if (bonded) // the bonds came along (most pairs are bonded or broken apart here: their
            EXPECT_GT(countsAtGather.intact, 0u); // friction histories barely matter)
        else
        {
            dem::SystemState forgetful = gathered;
            std::vector<double>& history = forgetful.reals["pairs.history"];
            std::fill(history.begin(), history.end(), 0.0);
            dem::System withoutHistory(p);
            withoutHistory.importState(forgetful);
            withoutHistory.step(700);
            energyForgetful = kineticEnergy(withoutHistory.grains());
            EXPECT_GT(std::fabs(energyForgetful - energyEnd), 1e-6 * energyEnd);
        }
        std::printf("  %s: KE after 700 more steps %.12g J split, %.12g J on one process from the "
                    "gathered state (%.12g J with its contact histories zeroed); bonds intact %zu "
                    "/ %zu, broken %zu / %zu\n",
                    bonded ? "bonded" : "unbonded", energyEnd, energyOne, energyForgetful,
                    countsEnd.intact, one.bondCounts().intact, countsEnd.broken,
                    one.bondCounts().broken);
    }
}

// The other way: a one-process run's state imported by a split System (every rank passes the
// same state; rank 0 takes it whole, the first step's rebuild sends each grain to its owner with
// its pairs' histories and bonds). After 700 more steps of both the split run ends with the
// one-process kinetic energy within 1e-6 relative and the same bond counts; without bonds the
// same import with the histories zeroed ends further away than that.
TEST_P(Decomposition, OneProcessStateContinuesSplit)
{
    const dem::Packing packing = bottomOfBenchmarkPacking(0.1);
    const std::vector<dem::GrainInit> grains = sheared(packing.grains);
    for (const bool bonded : {false, true})
    {
        dem::Parameters p = shearParameters(GetParam(), packing.length, 8e-4);
        if (bonded)
            p = withFrozenBonds(p, 0.0105);
        // every rank runs the same one-process System (no MPI calls), so each holds its state
        dem::System one(p);
        one.addGrains(grains);
        one.step(700);
        const dem::SystemState state = one.exportState();
        const dem::BondCounts countsAtExport = one.bondCounts();
        one.step(700);
        const double energyOne = kineticEnergy(one.grains());
        const dem::BondCounts countsOne = one.bondCounts();

        auto splitFrom = [&](const dem::SystemState& s, dem::BondCounts& atImport,
                             dem::BondCounts& atEnd, std::size_t& count)
        {
            dem::System split(splitIf(p, true));
            split.importState(s);
            atImport = split.bondCounts();
            split.step(700);
            atEnd = split.bondCounts();
            count = split.grainCount();
            return mpi->sum(kineticEnergy(split.grains()));
        };
        dem::BondCounts atImport, atEnd;
        std::size_t count = 0;
        const double energySplit = splitFrom(state, atImport, atEnd, count);
        EXPECT_EQ(count, grains.size());
        EXPECT_EQ(atImport.intact, countsAtExport.intact);
        EXPECT_EQ(atImport.formed, countsAtExport.formed);
        EXPECT_EQ(atImport.broken, countsAtExport.broken);
        EXPECT_NEAR(energySplit, energyOne, 1e-6 * energyOne);
        EXPECT_EQ(atEnd.intact, countsOne.intact);
        EXPECT_EQ(atEnd.formed, countsOne.formed);
        EXPECT_EQ(atEnd.broken, countsOne.broken);
        double energyForgetful = 0.0;
        if (bonded)
            EXPECT_GT(countsAtExport.intact, 0u);
        else
        {
            dem::SystemState forgetful = state;
            std::vector<double>& history = forgetful.reals["pairs.history"];
            std::fill(history.begin(), history.end(), 0.0);
            dem::BondCounts unused;
            energyForgetful = splitFrom(forgetful, unused, unused, count);
            EXPECT_GT(std::fabs(energyForgetful - energyOne), 1e-6 * energyOne);
        }
        if (mpi->rank() == 0)
            std::printf("  %s: KE after 700 more steps %.12g J on one process, %.12g J split from "
                        "its state (%.12g J with the histories zeroed); bonds intact %zu / %zu, "
                        "broken %zu / %zu\n",
                        bonded ? "bonded" : "unbonded", energyOne, energySplit, energyForgetful,
                        countsOne.intact, atEnd.intact, countsOne.broken, atEnd.broken);
    }
}

// The fluid coupling on a grid over the whole box, which every rank passes whole: each rank
// deposits the grains it owns and the cells' sums are added over the ranks. So the deposit
// differs from one process's only in the order of each cell's sum of positive terms: by at most
// 2 (n - 1) eps times the cell's solid volume (n the grains, the bound of recursive summation
// on each side). The same holds for the reaction with every grain's force of one sign per
// component (f_x > 0, f_z + rho_f g > 0, u_x > 0 = v, f_y = 0). Under that force and drag the
// bed then follows the one-process run within the growth of round-off (as in the dense test).
TEST_P(Decomposition, FluidCouplingFollowsOneProcess)
{
    const dem::Packing packing = bottomOfBenchmarkPacking(0.1);
    const std::vector<dem::GrainInit>& grains = packing.grains;
    const double eps = std::numeric_limits<double>::epsilon();
    dem::UniformGrid grid;
    grid.n = {4, 4, 5};
    grid.spacing = {packing.length / 4, packing.length / 4, 0.025};
    grid.periodic = {true, true, false};
    const std::size_t cells = grid.cellCount();
    std::vector<double> force(3 * cells), drag(cells, 2e4), velocity(3 * cells, 0.0);
    for (std::size_t c = 0; c < cells; ++c)
    {
        const double k = double(c / 16), i = double(c % 4);
        force[3 * c] = 3e6 * (1.0 + 0.5 * i); // sideways push, ~100 g
        force[3 * c + 2] = 12000.0 * (1.0 + 0.2 * k);
        velocity[3 * c] = 0.05;
    }
    dem::FluidFields fluid{force.data(), drag.data(), velocity.data(), 1000.0};
    const int steps = 1500;
    dem::Parameters p = shearParameters(GetParam(), packing.length, 2e-3);
    p.gravity = {0.0, 0.0, -9.81};
    struct Result
    {
        std::vector<double> solid, porosity, predicted, reaction;
        dem::GrainData end;
    };
    auto run = [&](const std::vector<dem::GrainInit>& start, bool split)
    {
        dem::System s(splitIf(p, split));
        s.addGrains(split ? blockOf(start) : start);
        s.addWall(dem::WallSpec{});
        s.step(0);
        Result r;
        r.solid.resize(cells);
        r.porosity.resize(cells);
        r.predicted.resize(cells);
        r.reaction.resize(3 * cells);
        s.deposit(grid, 1e-3, r.porosity.data(), r.predicted.data(), nullptr, r.solid.data());
        s.setFluid(grid, fluid);
        s.depositFluidReaction(grid, r.reaction.data());
        s.step(steps);
        r.end = s.grains();
        return r;
    };
    const std::vector<dem::GrainInit> perturbed =
        perturbedForSteps(grains, packing.length, steps, 11);
    const Result one = run(grains, false), moved = run(perturbed, false), split = run(grains, true);

    const double rounding = 2.0 * double(grains.size() - 1) * eps;
    double solidVolume = 0.0, depositedVolume = 0.0, worstCell = 0.0, worstReaction = 0.0;
    for (const dem::GrainInit& g : grains)
        solidVolume += sphereVolume(g.radius);
    for (std::size_t c = 0; c < cells; ++c)
    {
        depositedVolume += split.solid[c];
        const double scale = rounding * one.solid[c];
        worstCell = std::max(worstCell, std::fabs(split.solid[c] - one.solid[c]) / scale);
        worstCell = std::max(worstCell, std::fabs(split.porosity[c] - one.porosity[c]) /
                                            (scale / grid.cellVolume()));
        for (int d = 0; d < 3; ++d)
            if (one.reaction[3 * c + d] != 0.0)
                worstReaction = std::max(
                    worstReaction, std::fabs(split.reaction[3 * c + d] - one.reaction[3 * c + d]) /
                                       (rounding * std::fabs(one.reaction[3 * c + d])));
            else
                EXPECT_EQ(split.reaction[3 * c + d], 0.0);
    }
    EXPECT_LE(worstCell, 1.0) << "deposit: worst cell's difference in units of its bound";
    EXPECT_LE(worstReaction, 1.0) << "reaction: worst component in units of its bound";
    EXPECT_NEAR(depositedVolume, solidVolume, rounding * solidVolume);
    EXPECT_EQ(split.predicted.size(), cells);

    const double bound = largestDistance(moved.end, one.end),
                 largest = largestSplitDistance(split.end, one.end);
    // The fluid force acts on the split run's grains: their x momentum grows by the fluid's push,
    // t sum_g V_g f_x(x_g) = t sum_c f_x,c solid_c at the start (interpolation is the deposit's
    // transpose); the grains move 1e-4 m of 0.025 m cells, changing it by < 1 %; the bottom
    // wall's friction (mu times the bed's net weight) and the drag against the bed's speed take
    // ~1 % more; contact forces between grains cancel. So within 5 %.
    const double pushed = sumOwned(split.end, [&](std::size_t k)
                                   { return split.end.mass[k] * split.end.velocity[3 * k]; });
    double push = 0.0;
    for (std::size_t c = 0; c < cells; ++c)
        push += force[3 * c] * one.solid[c] * steps * p.timeStep;
    EXPECT_NEAR(pushed, push, 0.05 * push) << "the fluid force should push the bed";
    if (mpi->rank() == 0)
        std::printf("  %zu grains on a 4 x 4 x 5 grid: deposit within %.3g, reaction within %.3g "
                    "of their rounding bounds; solid volume %.15g of %.15g m^3; after %d steps "
                    "(x momentum %.4g N s, push %.4g N s) split vs one process %.3g m, bound "
                    "%.3g m\n",
                    grains.size(), worstCell, worstReaction, depositedVolume, solidVolume, steps,
                    pushed, push, largest, bound);
}

// Grain flags over the ranks: a bed on a wall whose lowest grains are fixed and whose highest
// are driven sideways (prescribedVelocity), the shear carried across the cut. Each rank flags
// the grains of its own block (setGrainFlags is collective: the union applies). The split run
// follows one process within the growth of round-off (as in the dense test), and so does the
// force the driven grains need (summed over the ranks).
TEST_P(Decomposition, GrainFlagsFollowOneProcess)
{
    const dem::Packing packing = bottomOfBenchmarkPacking(0.1);
    const int steps = 1500;
    dem::Parameters p = shearParameters(GetParam(), packing.length, 2e-3);
    p.gravity = {0.0, 0.0, -9.81};
    auto run = [&](const std::vector<dem::GrainInit>& start, bool split, double& drivingForce)
    {
        dem::System s(splitIf(p, split));
        const std::size_t n = start.size();
        const std::size_t first = split ? n * std::size_t(mpi->rank()) / 2 : 0,
                          last = split ? n * std::size_t(mpi->rank() + 1) / 2 : n;
        s.addGrains(split ? blockOf(start) : start);
        s.addWall(dem::WallSpec{});
        std::vector<int> base, lid;
        for (std::size_t i = first; i < last; ++i)
            if (start[i].position[2] < 0.015)
                base.push_back(int(i));
            else if (start[i].position[2] > 0.085)
                lid.push_back(int(i));
        s.setGrainFlags(base, dem::GrainFlag::fixed);
        s.setGrainFlags(lid, dem::GrainFlag::prescribedVelocity, 0.5, 0.0);
        s.step(steps);
        drivingForce = s.prescribedGrainForceX();
        return s.grains();
    };
    const std::vector<dem::GrainInit> perturbed =
        perturbedForSteps(packing.grains, packing.length, steps, 13);
    double force = 0.0, movedForce = 0.0, splitForce = 0.0;
    const dem::GrainData one = run(packing.grains, false, force),
                         moved = run(perturbed, false, movedForce),
                         split = run(packing.grains, true, splitForce);
    const double bound = largestDistance(moved, one), largest = largestSplitDistance(split, one);
    double baseMoved = 0.0, lidShift = 0.0;
    for (std::size_t k = 0; k < split.id.size(); ++k)
    {
        const std::size_t i = std::size_t(split.id[k]);
        if (packing.grains[i].position[2] < 0.015)
            baseMoved = std::max(baseMoved, norm(at(split.displacement, k)));
        else if (packing.grains[i].position[2] > 0.085)
            lidShift =
                std::max(lidShift, std::fabs(split.displacement[3 * k] - 0.5 * steps * p.timeStep));
    }
    baseMoved = mpi->max(baseMoved);
    lidShift = mpi->max(lidShift);
    EXPECT_LE(largest, bound);
    EXPECT_EQ(baseMoved, 0.0) << "fixed grains must not move";
    EXPECT_LE(lidShift, 1e-12) << "driven grains move at their prescribed velocity";
    EXPECT_NE(force, 0.0);
    EXPECT_LE(std::fabs(splitForce - force), std::fabs(movedForce - force));
    if (mpi->rank() == 0)
        std::printf("  flags: split vs one process %.3g m (bound %.3g m); driving force %.12g / "
                    "%.12g N (perturbed %.12g N)\n",
                    largest, bound, splitForce, force, movedForce);
}

TEST_P(Decomposition, MisuseIsRefusedWithAClearMessage)
{
    dem::Parameters p = shearParameters(GetParam(), 1.0, 1e-3);
    auto message = [&](const dem::Parameters& q, auto&& use)
    {
        try
        {
            dem::System s(q);
            use(s);
        }
        catch (const dem::Error& e)
        {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    auto nothing = [](dem::System&) {};
    p.decomposition.ranks = {3, 1};
    EXPECT_NE(message(p, nothing).find("needs 3 MPI ranks, but mpirun started 2"),
              std::string::npos)
        << message(p, nothing);
    p.decomposition.ranks = {0, 2};
    EXPECT_NE(message(p, nothing).find("decomposition.ranks[0] = 0 is invalid"), std::string::npos)
        << message(p, nothing);
    p.decomposition.ranks = {2, 1};
    dem::Parameters bonded = p;
    bonded.bonds.enabled = true;
    bonded.bonds.youngsModulus = 1e9;
    const std::string added = message(bonded, [](dem::System& s) { s.addBonds({{0, 1, 1e-3}}); });
    EXPECT_NE(added.find("addBonds (bonds form by frozenOnContact) is not available yet"),
              std::string::npos)
        << added;
    // a decomposed state into a System on one process
    dem::SystemState decomposed;
    {
        dem::System s(p);
        decomposed = s.exportState();
    }
    dem::Parameters single = p;
    single.decomposition.ranks = {1, 1};
    const std::string restart = message(single, [&](dem::System& s) { s.importState(decomposed); });
    EXPECT_NE(restart.find("one rank's part of a run decomposed over 2 MPI ranks"),
              std::string::npos)
        << restart;
}

INSTANTIATE_TEST_SUITE_P(Backends, Decomposition,
                         ::testing::Values(dem::Backend::cpu, dem::Backend::cuda),
                         [](const auto& info)
                         { return info.param == dem::Backend::cpu ? "cpu" : "cuda"; });

} // namespace

int main(int argc, char** argv)
{
    dem::MpiSession session(&argc, &argv);
    mpi = &session;
    // The test list (ctest's discovery) from rank 0 only; a run prints from every rank, so a
    // failure on rank 1 is seen.
    for (int a = 1; a < argc; ++a)
        if (std::strcmp(argv[a], "--gtest_list_tests") == 0 && session.rank() != 0 &&
            !std::freopen("/dev/null", "w", stdout))
            return 1;
    ::testing::InitGoogleTest(&argc, argv);
    const int failed = RUN_ALL_TESTS();
    // A test that failed on any rank fails the run (every rank's exit status).
    return session.max(double(failed)) > 0.0 ? 1 : 0;
}

// DeformingBoxTest.cpp
// A periodic box whose length changes (Parameters::boxLengthRate): a grain meets its
// neighbours' images across the moving side with their velocity plus the rate per image, the
// neighbour list is rebuilt when the box alone brings grains together, displacements stay
// unwrapped across the moving side, and a restart continues the same box.
#include "TestSupport.h"

#include "dem/Error.h"

#include <cmath>
#include <string>
#include <vector>

using namespace demTest;

namespace
{

class DeformingBox : public BackendTest
{
protected:
    static constexpr double kRadius = 0.01;
    static constexpr int kChain = 8;
    static constexpr double kSpacing = 0.0199;  // overlap 1e-4 m between neighbours
    static constexpr double kStrainRate = -2.0; // [1/s] along y, box and grains alike

    //- A chain of spheres along y that fills the periodic length, each on the homogeneous
    //- strain-rate field v_y = rate (y - L/2) plus a common drift (so that grains cross both
    //- seams), in a box whose y length shrinks at rate L.
    dem::Parameters chainParameters() const
    {
        dem::Parameters p = parameters();
        p.grainGrain.normalDamping = 5.0; // the seam pair's damping must see the image's speed
        p.grainWall = p.grainGrain;
        p.boxUpper = {0.1, kChain * kSpacing};
        p.boxLengthRate = {0.0, kStrainRate * kChain * kSpacing};
        p.timeStep = 2e-7;
        return p;
    }
    //- coreHalfLength > 0: capsules lying along x, touching side by side (their pair path)
    std::vector<dem::GrainInit> chain(double coreHalfLength = 0.0) const
    {
        const double length = kChain * kSpacing;
        std::vector<dem::GrainInit> grains(kChain);
        for (int i = 0; i < kChain; ++i)
        {
            dem::GrainInit& g = grains[std::size_t(i)];
            g.radius = kRadius;
            g.coreHalfLength = coreHalfLength;
            g.orientation = {std::sqrt(0.5), 0.0, std::sqrt(0.5), 0.0}; // body z along x
            g.position = {0.095, (i + 0.5) * kSpacing, 0.5};
            g.velocity = {3.0, 17.0 + kStrainRate * (g.position[1] - 0.5 * length), 0.0};
        }
        return grains;
    }
    void affineContraction(double coreHalfLength);
};

} // namespace

// The affine field is an exact solution: every contact, the one across the moving seam too,
// has the same overlap and the same approach speed, so every grain's net force is zero and
// the field persists. A seam pair that saw the image's velocity without the rate would be
// damped 0.2 N against 100 N of spring force (net force 2e-3 of it), a fixed length would
// leave its overlap behind by the contraction (8e-5 m against 1e-4 m), and a grain that
// crossed the seam without taking its image's velocity would strike its new neighbour at the
// rate (0.32 m/s).
TEST_P(DeformingBox, AffineContractionLoadsEveryContactAlike)
{
    for (const double coreHalfLength : {0.0, 0.01})
        affineContraction(coreHalfLength);
}

void DeformingBox::affineContraction(double coreHalfLength)
{
    SCOPED_TRACE(coreHalfLength > 0 ? "capsules" : "spheres");
    const dem::Parameters p = chainParameters();
    dem::System s(p);
    const std::vector<dem::GrainInit> grains = chain(coreHalfLength);
    s.addGrains(grains);
    const int steps = 10000; // 2 ms: the overlap grows from 1e-4 to 1.8e-4 m
    const double springForce = p.grainGrain.normalStiffness * (2 * kRadius - kSpacing);
    double worstNet = 0.0, worstVelocity = 0.0, worstDisplacement = 0.0, crossings = 0.0;
    for (int block = 0; block < 20; ++block)
    {
        s.step(steps / 20);
        const dem::GrainData g = s.grains();
        ASSERT_EQ(s.contactCount(), std::size_t(kChain)) << "the seam contact is one of them";
        const double length = p.boxUpper[1] + p.boxLengthRate[1] * s.time();
        for (int i = 0; i < kChain; ++i)
        {
            const Vec3 v0 = {grains[i].velocity[0], grains[i].velocity[1], 0.0};
            worstNet = std::max(worstNet, norm(at(g.force, i)) / springForce);
            // unwrapped in the lattice of images (y + k L(t)): the grain's own path at v0
            const Vec3 expected = {v0[0] * s.time(), v0[1] * s.time(), 0.0};
            worstDisplacement =
                std::max(worstDisplacement, norm(sub(at(g.displacement, i), expected)));
            // the image read back, k lengths below, moves at v0 - k dL/dt
            const double k = std::round(
                (grains[i].position[1] + g.displacement[3 * i + 1] - g.position[3 * i + 1]) /
                length);
            crossings = std::max(crossings, std::fabs(k));
            const Vec3 image = {v0[0], v0[1] - k * p.boxLengthRate[1], 0.0};
            worstVelocity = std::max(worstVelocity, norm(sub(at(g.velocity, i), image)));
        }
    }
    const double length = p.boxUpper[1] + p.boxLengthRate[1] * s.time();
    std::printf("  %s: box y length %.6f -> %.6f m; worst net force / spring force %.1e, velocity "
                "change %.1e m/s, displacement error %.1e m; %zu rebuilds\n",
                coreHalfLength > 0 ? "capsules" : "spheres", p.boxUpper[1], length, worstNet,
                worstVelocity, worstDisplacement, s.neighbourRebuildCount());
    // Round-off: positions summed over 1e4 drifts of 3.4e-6 m against the box's closed form
    // L0 + rate t differ by 1e-17 m a step, 1e-13 m at worst: k_n 1e-13 m = 1e-9 of the spring
    // force, which over 2 ms changes a grain's velocity by 2e-8 m/s.
    EXPECT_LT(worstNet, 1e-9);
    EXPECT_LT(worstVelocity, 2e-8);
    EXPECT_LT(worstDisplacement, 1e-12);
    EXPECT_GE(s.neighbourRebuildCount(), 10u) << "drift and contraction exceed the skin";
    EXPECT_EQ(crossings, 1.0) << "the drift carries grains across the moving seam";
}

// The same chain bonded, each neighbour to the next and the last across the moving seam to
// the first (bonded pairs are the bonds'). The incremental bond law integrates the relative
// velocity: every bond is compressed by |rate| s0 T = 8e-5 m, its elastic normal force
// -k_ne pi r_b^2 |rate| s0 T with k_ne = E / (2 Rbar) (doc/EQUATIONS.md section 10), the seam
// bond's too; one that missed the image's velocity would gain dL/dt T = 6e-4 m more, 8 x the
// others' force. Every grain's net force is then round-off.
TEST_P(DeformingBox, BondsAcrossTheMovingSeamFollowTheField)
{
    dem::Parameters p = chainParameters();
    p.bonds.enabled = true;
    p.bonds.youngsModulus = 1e9;
    p.bonds.normalDampingRatio = 0.2; // the dashpots see the image's velocity too
    p.bonds.shearDampingRatio = 0.2;
    dem::System s(p);
    s.addGrains(chain());
    std::vector<dem::BondInit> bonds;
    for (int i = 0; i < kChain; ++i)
        bonds.push_back({i, (i + 1) % kChain, 0.3 * kRadius});
    s.addBonds(bonds);
    s.step(10000);
    const dem::BondData b = s.bonds();
    ASSERT_EQ(b.first.size(), std::size_t(kChain)) << "every bond intact";
    double largest = 0.0, smallest = 1e300;
    for (double n : b.normalForce)
    {
        largest = std::max(largest, std::fabs(n));
        smallest = std::min(smallest, std::fabs(n));
    }
    const dem::GrainData g = s.grains();
    double worstNet = 0.0;
    for (int i = 0; i < kChain; ++i)
        worstNet = std::max(worstNet, norm(at(g.force, i)));
    std::printf("  bond normal force %.6g .. %.6g N; worst net force on a grain %.1e N\n", smallest,
                largest, worstNet);
    const double expected = p.bonds.youngsModulus / (2 * kRadius) * M_PI *
                            std::pow(0.3 * kRadius, 2) * std::fabs(kStrainRate) * kSpacing *
                            s.time();
    std::printf("  expected %.6g N (compression)\n", expected);
    for (double n : b.normalForce)
        EXPECT_NEAR(n, -expected, 1e-9 * expected);
    EXPECT_LT(worstNet, 1e-9 * largest);
}

// The uninterrupted run and a restart half way (export, import into a System built with the
// same Parameters) continue on the same box: bit-identical positions.
TEST_P(DeformingBox, RestartContinuesTheSameBox)
{
    const dem::Parameters p = chainParameters();
    dem::System whole(p);
    whole.addGrains(chain());
    whole.step(3000);
    dem::System first(p);
    first.addGrains(chain());
    first.step(1500);
    dem::System second(p);
    second.importState(first.exportState());
    second.step(1500);
    const dem::GrainData a = whole.grains(), b = second.grains();
    for (std::size_t k = 0; k < a.position.size(); ++k)
    {
        EXPECT_EQ(a.position[k], b.position[k]) << k;
        EXPECT_EQ(a.velocity[k], b.velocity[k]) << k;
    }
}

// Two spheres at rest on either side of the y seam, 2 mm apart across it: only the box brings
// them together (no grain moves, so the skin test on displacements alone would never rebuild
// and the pair, beyond the 2 mm skin's cutoff, would pass through). Contact begins when the
// length has shrunk by the gap; the image strikes at the rate u, so an elastic (undamped)
// contact sends the grains off at +u and -u, momentum staying zero.
TEST_P(DeformingBox, ShrinkingBoxBringsGrainsAtRestIntoContact)
{
    dem::Parameters p = parameters(); // undamped linear spring, skin 2 mm
    const double gap = 0.004, u = 2.0, length = 0.2;
    p.boxUpper = {0.1, length};
    p.boxLengthRate = {0.0, -u};
    p.timeStep = 2e-7;
    dem::System s(p);
    dem::GrainInit a, b;
    a.radius = b.radius = kRadius;
    a.position = {0.05, kRadius + 0.5 * gap, 0.5};
    b.position = {0.05, length - kRadius - 0.5 * gap, 0.5};
    s.addGrains({a, b});
    const double mass = s.grains().mass[0];
    const double contactTime = M_PI * std::sqrt(0.5 * mass / p.grainGrain.normalStiffness);
    double firstTouch = -1.0;
    while (s.time() < gap / u + 2.0 * contactTime)
    {
        s.step(1);
        if (firstTouch < 0.0 && s.contactCount() > 0)
            firstTouch = s.time();
    }
    const dem::GrainData g = s.grains();
    const double va = g.velocity[1], vb = g.velocity[4];
    std::printf("  first touch at %.7f s (gap / u = %.7f s); v_A = %.6f, v_B = %.6f m/s (u = "
                "%.1f); contact time %.2e s = %.0f steps\n",
                firstTouch, gap / u, va, vb, u, contactTime, contactTime / p.timeStep);
    EXPECT_GE(firstTouch, gap / u - 1e-12);
    EXPECT_LE(firstTouch, gap / u + p.timeStep + 1e-12);
    EXPECT_NEAR(va + vb, 0.0, 1e-12 * u); // internal forces: momentum kept
    // Velocity Verlet keeps a linear spring's energy to O((dt / t_contact)^2) per contact;
    // the onset inside a step costs O(dt / t_contact) = 1.7e-4 of the rebound speed
    EXPECT_NEAR(va, u, 10.0 * p.timeStep / contactTime * u);
    EXPECT_NEAR(vb, -u, 10.0 * p.timeStep / contactTime * u);
    EXPECT_NEAR(g.velocity[0] + g.velocity[2] + g.velocity[3] + g.velocity[5], 0.0, 1e-15);
}

// setBoxLengthRate starts (and stops) the change from the box as it is: the length follows
// L0 + rate (t - t_set) and stays where it was when the rate is set to zero.
TEST_P(DeformingBox, RateSetDuringTheRunStartsFromTheBoxAsItIs)
{
    dem::Parameters p = chainParameters();
    p.boxLengthRate = {0.0, 0.0};
    dem::System s(p);
    s.addGrains(chain());
    s.step(1000);
    const double rate = chainParameters().boxLengthRate[1];
    const double set = s.time();
    s.setBoxLengthRate({0.0, rate});
    s.step(2000);
    EXPECT_NEAR(s.boxUpper()[1], p.boxUpper[1] + rate * (s.time() - set), 1e-15);
    EXPECT_EQ(s.boxUpper()[0], p.boxUpper[0]);
    EXPECT_EQ(s.parameters().boxTime, set);
    const double stopped = s.boxUpper()[1];
    s.setBoxLengthRate({0.0, 0.0});
    s.step(1000);
    EXPECT_EQ(s.boxUpper()[1], stopped);
}

// A stress-controlled z wall presses with sigma0 on the box's x-y area as it is: alone (no
// grain touches it) it accelerates at sigma0 Lx Ly(t) / m, linear in time, which velocity
// Verlet's trapezoid integrates exactly: v(T) = -(sigma0 Lx / m)(Ly0 T + rate T^2 / 2). The
// area of the box as built would be 1.25 % off by then.
TEST_P(DeformingBox, StressWallPressesOnTheAreaAsItIs)
{
    dem::Parameters p = parameters();
    const double ly0 = 0.2, rate = -0.5, sigma = 100.0, mass = 0.3;
    p.boxUpper = {0.1, ly0};
    p.boxLengthRate = {0.0, rate};
    dem::System s(p);
    dem::GrainInit g;
    g.radius = kRadius;
    g.position = {0.05, 0.1, 0.5};
    s.addGrain(g);
    dem::WallSpec lid;
    lid.side = dem::WallSpec::Side::upper;
    lid.mode = dem::WallSpec::Mode::stress;
    lid.position = 0.9;
    lid.mass = mass;
    lid.normalStress = sigma;
    s.addWall(lid);
    s.step(10000); // T = 0.01 s
    const double t = s.time();
    const double expected = -sigma * p.boxUpper[0] / mass * (ly0 * t + 0.5 * rate * t * t);
    std::printf("  lid velocity %.15g m/s, expected %.15g m/s\n", s.wall(0).velocity, expected);
    EXPECT_NEAR(s.wall(0).velocity, expected, 1e-12 * std::fabs(expected));
}

// Refused: a rate on a side that is not periodic, and with a decomposition over MPI ranks;
// the message names the entry and why.
TEST_P(DeformingBox, RefusesWhatItCannotDo)
{
    const auto refused = [](const dem::Parameters& p, const char* entry, const char* why)
    {
        try
        {
            dem::System s(p);
            ADD_FAILURE() << entry << " accepted";
        }
        catch (const dem::Error& e)
        {
            EXPECT_NE(std::string(e.what()).find(entry), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
        }
    };
    dem::Parameters wallBounded = parameters();
    wallBounded.periodic = {true, false};
    wallBounded.boxLengthRate = {0.0, -1.0};
    refused(wallBounded, "boxLengthRate[1]", "not periodic");
    dem::Parameters decomposed = parameters();
    decomposed.boxLengthRate = {-1.0, 0.0};
    decomposed.decomposition.ranks = {2, 1};
    refused(decomposed, "boxLengthRate[0]", "decomposition");
}

DEM_TEST_ON_ALL_BACKENDS(DeformingBox);

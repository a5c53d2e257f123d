// CapsuleWallTest.cpp
// Capsules on a wall: a horizontal capsule rests on both ends of its core (each end one
// contact carrying half the weight), a vertical one on its lower end alone; a packing of
// capsules and spheres dropped on a wall under gravity comes to rest above it.
#include "TestSupport.h"

#include <algorithm>
#include <random>

using namespace demTest;

namespace
{

class CapsuleWall : public BackendTest
{
protected:
    //- k_n = 1e6 N/m, dashpots of 300 N s/m (0.7 of critical damping for the capsules
    //- below on one contact, 1.0 on two), gravity.
    dem::Parameters restingParameters() const
    {
        dem::Parameters p = parameters();
        p.grainWall = {1e6, 1e6, 300.0, 0.0, 0.5};
        p.gravity = {0.0, 0.0, -9.81};
        return p;
    }
};

//- Capsule of radius 0.01 m, core half-length 0.02 m, rho 2600, at height z with its axis
//- along x (horizontal: q a turn of 90 degrees about y) or z.
dem::GrainInit capsule(double z, bool horizontal)
{
    dem::GrainInit g;
    g.position = {0.5, 0.5, z};
    g.radius = 0.01;
    g.coreHalfLength = 0.02;
    if (horizontal)
        g.orientation = {std::sqrt(0.5), 0.0, std::sqrt(0.5), 0.0};
    return g;
}

//- Principal moments (I_perp, I_axial) of a capsule (the closed forms of the library's
//- convention), for the rotational kinetic energy.
std::array<double, 2> capsuleInertia(double r, double h, double mass)
{
    const double L = 2.0 * h;
    const double cylinder = M_PI * r * r * L, caps = 4.0 / 3.0 * M_PI * r * r * r;
    const double rho = mass / (cylinder + caps);
    const double mc = rho * cylinder, mh = rho * caps;
    return {mc * (L * L / 12 + r * r / 4) + mh * (2 * r * r / 5 + L * L / 4 + 3 * L * r / 8),
            mc * r * r / 2 + 2 * mh * r * r / 5};
}

//- Translational plus rotational kinetic energy of all grains (rotational from the body
//- frame: omega_body = R^T omega); translational alone with rotation = false.
double kineticEnergy(const dem::GrainData& g, bool rotation = true)
{
    double energy = 0.0;
    for (std::size_t i = 0; i < g.mass.size(); ++i)
    {
        const Vec3 v = at(g.velocity, i), w = at(g.angularVelocity, i);
        energy += 0.5 * g.mass[i] * dot(v, v);
        if (!rotation)
            continue;
        const auto I = capsuleInertia(g.radius[i], g.coreHalfLength[i], g.mass[i]);
        // The body axis e_z in global coordinates; omega split along and across it.
        const double* q = &g.orientation[4 * i];
        const Vec3 axis{2 * (q[1] * q[3] + q[0] * q[2]), 2 * (q[2] * q[3] - q[0] * q[1]),
                        1 - 2 * (q[1] * q[1] + q[2] * q[2])};
        const double along = dot(w, axis);
        energy += 0.5 * (I[1] * along * along + I[0] * (dot(w, w) - along * along));
    }
    return energy;
}

} // namespace

TEST_P(CapsuleWall, HorizontalCapsuleRestsOnBothEnds)
{
    dem::System system(restingParameters());
    system.addGrain(capsule(0.01, true)); // touching, at rest
    system.addWall(dem::WallSpec());
    system.step(20000); // 0.02 s: > 60 decay times of the slowest mode
    const dem::GrainData g = system.grains();
    const double weight = g.mass[0] * 9.81, kn = 1e6;
    // Two contacts share the weight: each end sinks weight / (2 k_n) (one contact: twice that).
    const double expected = 0.01 - weight / (2.0 * kn);
    // z component of the axis R e_z
    const double axisZ = 1 - 2 * (g.orientation[1] * g.orientation[1] + g.orientation[2] * g.orientation[2]);
    std::printf("  wall force %.12f N, weight %.12f N; height %.12e m, expected %.12e m; axis z "
                "%.1e\n",
                system.wall(0).grainForce, weight, g.position[2], expected, axisZ);
    // At rest the sinking oscillation (amplitude < 1 um) has decayed by e^-60: round-off is
    // what remains.
    EXPECT_NEAR(-system.wall(0).grainForce, weight, 1e-9 * weight); // grains push it down
    EXPECT_NEAR(g.position[2], expected, 1e-12);
    // Both ends alike: the axis stays horizontal (any tilt would come from round-off).
    EXPECT_LT(std::fabs(axisZ), 1e-9);
}

TEST_P(CapsuleWall, VerticalCapsuleRestsOnItsLowerEnd)
{
    dem::System system(restingParameters());
    system.addGrain(capsule(0.03, false));
    system.addWall(dem::WallSpec());
    system.step(20000);
    const dem::GrainData g = system.grains();
    const double weight = g.mass[0] * 9.81, kn = 1e6;
    const double expected = 0.02 + 0.01 - weight / kn; // one contact carries all
    std::printf("  wall force %.12f N, weight %.12f N; height %.12e m, expected %.12e m\n",
                system.wall(0).grainForce, weight, g.position[2], expected);
    EXPECT_NEAR(-system.wall(0).grainForce, weight, 1e-9 * weight); // grains push it down
    EXPECT_NEAR(g.position[2], expected, 1e-12);
}

TEST_P(CapsuleWall, MixedPackingSettlesAboveTheWall)
{
    // 224 grains (every other one a capsule of random orientation and aspect ratio 1 to 2,
    // radii 3 to 4 mm) on a 4 x 4 x 14 lattice, dropped into a periodic box on a wall: a bed
    // of a few layers. k_n = 1e4 N/m, dashpots (~0.7 of critical damping), friction 0.5, a
    // light drag (time constant ~0.1 s).
    dem::Parameters p = parameters();
    p.grainGrain = {1e4, 1e4, 2.0, 0.0, 0.5};
    p.grainWall = p.grainGrain;
    p.gravity = {0.0, 0.0, -9.81};
    p.boxUpper = {0.068, 0.068};
    p.timeStep = 2e-5;
    p.neighbourSkin = 0.0005;
    p.viscousDrag = 0.003;
    dem::System system(p);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> radius(0.003, 0.004), aspect(1.0, 2.0), unit(-1, 1);
    std::normal_distribution<double> gauss;
    std::vector<dem::GrainInit> grains;
    const double spacing = 0.017; // > the longest grain, 2 (r + h) <= 0.016 m
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 14; ++k)
            {
                dem::GrainInit g;
                g.radius = radius(random);
                g.position = {spacing * (i + 0.5), spacing * (j + 0.5), spacing * (k + 0.5)};
                g.velocity = {0.1 * unit(random), 0.1 * unit(random), 0.0};
                if ((i + j + k) % 2 == 0) // length 2 (r + h) = aspect * 2 r
                {
                    g.coreHalfLength = (aspect(random) - 1.0) * g.radius;
                    std::array<double, 4> q{gauss(random), gauss(random), gauss(random),
                                            gauss(random)};
                    const double length =
                        std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
                    for (double& c : q)
                        c /= length;
                    g.orientation = q;
                }
                grains.push_back(g);
            }
    system.addGrains(grains);
    system.addWall(dem::WallSpec());
    double largest = 0.0, before = 0.0;
    for (int block = 0; block < 50; ++block) // 1 s
    {
        system.step(1000);
        const dem::GrainData g = system.grains();
        largest = std::max(largest, kineticEnergy(g));
        if (block % 5 == 4)
            std::printf("  t %.2f s: kinetic energy %.3e J (translation %.3e J)\n",
                        system.time(), kineticEnergy(g), kineticEnergy(g, false));
        if (block == 39)
            before = kineticEnergy(g);
    }
    const dem::GrainData g = system.grains();
    const double final = kineticEnergy(g), translation = kineticEnergy(g, false);
    double totalWeight = 0.0, lowest = 1.0;
    for (std::size_t i = 0; i < g.mass.size(); ++i)
    {
        totalWeight += 9.81 * g.mass[i];
        const double* q = &g.orientation[4 * i];
        const double axisZ = 1 - 2 * (q[1] * q[1] + q[2] * q[2]);
        lowest = std::min(lowest, g.position[3 * i + 2] - g.coreHalfLength[i] * std::fabs(axisZ) -
                                      g.radius[i]);
    }
    const dem::GrainOverlap deepest = system.largestOverlap();
    std::printf("  %zu grains, %zu contacts; kinetic energy %.3e J (translation %.3e J) of at "
                "most %.3e J; lowest "
                "point %.3e m; deepest overlap %.3e m (grains %d, %d); wall force %.6f N, "
                "weight %.6f N\n",
                g.mass.size(), system.contactCount(), final, translation, largest, lowest,
                deepest.overlap,
                deepest.first, deepest.second, system.wall(0).grainForce, totalWeight);
    // At rest: the translational kinetic energy below 1e-6 of the largest kinetic energy of
    // the fall (the dashpots take the energy out over a few ms per contact; the last 0.4 s
    // are a hundred times that). What stays is spin about contact normals, which no force of
    // this model (point contacts, no twisting resistance) damps: constant, never growing.
    EXPECT_LT(translation, 1e-6 * largest);
    EXPECT_LE(final, before * (1.0 + 1e-6));
    // No grain below the wall: a static contact carries at most the whole weight, so no
    // overlap (with the wall or another grain) exceeds weight / k_n.
    EXPECT_GT(lowest, -totalWeight / 1e4);
    EXPECT_LT(deepest.overlap, totalWeight / 1e4);
    // At rest the wall carries the weight (to the remaining motion).
    EXPECT_NEAR(-system.wall(0).grainForce, totalWeight, 1e-3 * totalWeight);
    EXPECT_GT(system.contactCount(), g.mass.size()); // a packing, not a gas
}

DEM_TEST_ON_ALL_BACKENDS(CapsuleWall);

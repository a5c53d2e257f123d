// EnergyTest.cpp
// An undamped frictionless gas between frictionless walls in a periodic box conserves total
// energy (kinetic + rotational + spring) to 1e-4 relative over 1e5 velocity-Verlet steps.
#include "TestSupport.h"

#include <random>

using namespace demTest;

namespace
{

class Energy : public BackendTest
{
};

double totalEnergy(const dem::System& s, double box, double height, double k, double kWall)
{
    const dem::GrainData g = s.grains();
    const std::size_t n = g.radius.size();
    double e = 0;
    for (std::size_t i = 0; i < n; ++i)
    {
        const Vec3 v = at(g.velocity, i), w = at(g.angularVelocity, i);
        const double inertia = 0.4 * g.mass[i] * g.radius[i] * g.radius[i];
        e += 0.5 * g.mass[i] * dot(v, v) + 0.5 * inertia * dot(w, w);
        const double z = g.position[3 * i + 2];
        for (const double overlap : {g.radius[i] - z, g.radius[i] - (height - z)})
            if (overlap > 0)
                e += 0.5 * kWall * overlap * overlap;
        for (std::size_t j = i + 1; j < n; ++j)
        {
            Vec3 d = sub(at(g.position, j), at(g.position, i));
            for (int c = 0; c < 2; ++c)
                d[c] -= box * std::round(d[c] / box);
            const double overlap = g.radius[i] + g.radius[j] - norm(d);
            if (overlap > 0)
                e += 0.5 * k * overlap * overlap;
        }
    }
    return e;
}

} // namespace

TEST_P(Energy, FrictionlessGasConservesEnergy)
{
    dem::Parameters p = parameters();
    const double box = 0.1, height = 0.1;
    p.boxUpper = {box, box};
    p.grainGrain.friction = p.grainWall.friction = 0.0;
    p.neighbourSkin = 0.003;
    dem::System s(p);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    std::vector<dem::GrainInit> grains;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k)
            {
                dem::GrainInit g;
                g.radius = 0.008 + 0.002 * (i + j + k) / 6.0;
                g.position = {(i + 0.5) * box / 3, (j + 0.5) * box / 3, (k + 0.5) * height / 3};
                g.velocity = {uniform(random), uniform(random), uniform(random)};
                g.angularVelocity = {10 * uniform(random), 10 * uniform(random),
                                     10 * uniform(random)};
                grains.push_back(g);
            }
    s.addGrains(grains);
    dem::WallSpec bottom, top;
    top.side = dem::WallSpec::Side::upper;
    top.position = height;
    s.addWall(bottom);
    s.addWall(top);
    const double mMin = 2600 * sphereVolume(0.008);
    s.setTimeStep(0.01 * std::sqrt(mMin / p.grainGrain.normalStiffness));
    const double k = p.grainGrain.normalStiffness, kWall = p.grainWall.normalStiffness;
    const double e0 = totalEnergy(s, box, height, k, kWall);
    double worst = 0;
    for (int block = 0; block < 100; ++block)
    {
        s.step(1000);
        worst = std::max(worst, std::fabs(totalEnergy(s, box, height, k, kWall) / e0 - 1.0));
    }
    std::printf("  %lld steps, %zu rebuilds, max |E/E0 - 1| = %.2e\n", s.stepCount(),
                s.neighbourRebuildCount(), worst);
    EXPECT_EQ(s.stepCount(), 100000);
    EXPECT_GT(s.neighbourRebuildCount(), 10u);
    EXPECT_LT(worst, 1e-4);
}

DEM_TEST_ON_ALL_BACKENDS(Energy);

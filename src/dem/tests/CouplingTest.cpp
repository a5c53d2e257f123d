// CouplingTest.cpp
// Grain -> grid deposit and grid -> grain fluid force (doc/EQUATIONS.md sections 6, 7):
//  - deposited solid volume equals sum V_g to round-off, in a periodic box and next to walls;
//  - a rigidly translating packing deposits exactly its velocity;
//  - the predicted porosity equals the porosity of the grains moved by v dt_f;
//  - a uniform grad p gives f = -V grad p - rho_f V g on every grain.
#include "TestSupport.h"

#include <numeric>
#include <random>

using namespace demTest;

namespace
{

class Coupling : public BackendTest
{
protected:
    const double box = 0.2, height = 0.15;

    dem::UniformGrid grid() const
    {
        dem::UniformGrid g;
        g.origin = {0, 0, 0};
        g.n = {5, 4, 6};
        g.spacing = {box / 5, box / 4, height / 6};
        g.periodic = {true, true, false};
        return g;
    }

    //- Random grains in [0, box)^2 x [zLow, zHigh], all with velocity u.
    std::vector<dem::GrainInit> grains(int n, double zLow, double zHigh, const Vec3& u) const
    {
        std::mt19937 random(11);
        std::uniform_real_distribution<double> x(0.0, box), z(zLow, zHigh), r(0.004, 0.01);
        std::vector<dem::GrainInit> out(n);
        for (dem::GrainInit& g : out)
        {
            g.position = {x(random), x(random), z(random)};
            g.radius = r(random);
            g.velocity = {u[0], u[1], u[2]};
        }
        return out;
    }

    void expectConserved(const std::vector<dem::GrainInit>& added, const char* where)
    {
        dem::Parameters p = parameters();
        p.boxUpper = {box, box};
        dem::System s(p);
        s.addGrains(added);
        const dem::UniformGrid g = grid();
        std::vector<double> solid(g.cellCount()), porosity(g.cellCount());
        s.deposit(g, 0.0, porosity.data(), nullptr, nullptr, solid.data());
        double grainVolume = 0;
        for (const dem::GrainInit& grain : added)
            grainVolume += sphereVolume(grain.radius);
        const double deposited = std::accumulate(solid.begin(), solid.end(), 0.0);
        double fromPorosity = 0;
        for (double phi : porosity)
            fromPorosity += (1.0 - phi) * g.cellVolume();
        std::printf("  %s: relative volume error %.2e (solid), %.2e (porosity)\n", where,
                    deposited / grainVolume - 1.0, fromPorosity / grainVolume - 1.0);
        EXPECT_NEAR(deposited / grainVolume, 1.0, 1e-13) << where;
        EXPECT_NEAR(fromPorosity / grainVolume, 1.0, 1e-12) << where;
    }
};

} // namespace

TEST_P(Coupling, DepositConservesSolidVolume)
{
    expectConserved(grains(300, 0.01, height - 0.01, {0, 0, 0}), "periodic box");
    expectConserved(grains(300, 0.0, 0.012, {0, 0, 0}), "next to the bottom wall");
    expectConserved(grains(300, height - 0.012, height, {0, 0, 0}), "next to the top wall");
}

TEST_P(Coupling, TranslatingPackingDepositsItsVelocity)
{
    const Vec3 u = {0.3, -0.2, 0.05};
    dem::Parameters p = parameters();
    p.boxUpper = {box, box};
    dem::System s(p);
    s.addGrains(grains(300, 0.0, height, u));
    const dem::UniformGrid g = grid();
    std::vector<double> velocity(3 * g.cellCount()), solid(g.cellCount());
    s.deposit(g, 0.0, nullptr, nullptr, velocity.data(), solid.data());
    double worst = 0;
    for (std::size_t c = 0; c < g.cellCount(); ++c)
    {
        ASSERT_GT(solid[c], 0.0);
        for (int d = 0; d < 3; ++d)
            worst = std::max(worst, std::fabs(velocity[3 * c + d] / u[d] - 1.0));
    }
    std::printf("  max relative error of the mean velocity %.2e\n", worst);
    EXPECT_LT(worst, 1e-13);
}

TEST_P(Coupling, PredictedPorosityUsesProjectedPositions)
{
    const Vec3 u = {0.3, -0.2, 0.05};
    const double dtFluid = 0.02;
    dem::Parameters p = parameters();
    p.boxUpper = {box, box};
    const std::vector<dem::GrainInit> now = grains(300, 0.01, height - 0.02, u);
    std::vector<dem::GrainInit> later = now;
    for (dem::GrainInit& grain : later)
        for (int d = 0; d < 3; ++d)
            grain.position[d] += u[d] * dtFluid;
    dem::System a(p), b(p);
    a.addGrains(now);
    b.addGrains(later);
    const dem::UniformGrid g = grid();
    std::vector<double> predicted(g.cellCount()), moved(g.cellCount()), current(g.cellCount());
    a.deposit(g, dtFluid, current.data(), predicted.data(), nullptr);
    b.deposit(g, 0.0, moved.data(), nullptr, nullptr);
    double worst = 0, change = 0;
    for (std::size_t c = 0; c < g.cellCount(); ++c)
    {
        worst = std::max(worst, std::fabs(predicted[c] - moved[c]));
        change = std::max(change, std::fabs(predicted[c] - current[c]));
    }
    std::printf("  max |phi_pred - phi(x + v dt)| = %.2e (porosity change %.2e)\n", worst, change);
    EXPECT_LT(worst, 1e-13);
    EXPECT_GT(change, 1e-3);
}

TEST_P(Coupling, UniformPressureGradientAndBuoyancy)
{
    dem::Parameters p = parameters();
    p.boxUpper = {box, box};
    p.gravity = {0, 0, -9.81};
    dem::System s(p);
    std::vector<dem::GrainInit> lattice = grains(50, 0, 0, {0, 0, 0}); // radii vary
    for (std::size_t i = 0; i < lattice.size(); ++i)                   // apart: no contacts
        lattice[i].position = {0.02 + 0.04 * (i % 5), 0.02 + 0.04 * (i / 5 % 5),
                               0.03 + 0.05 * (i / 25)};
    s.addGrains(lattice);
    const dem::UniformGrid g = grid();
    const Vec3 gradP = {1e3, -2e3, 5e3};
    const double rhoFluid = 1000.0;
    std::vector<double> field(3 * g.cellCount());
    for (std::size_t c = 0; c < g.cellCount(); ++c)
        for (int d = 0; d < 3; ++d)
            field[3 * c + d] = gradP[d];
    s.setFluid(g, field.data(), rhoFluid);
    s.step(1);
    const dem::GrainData out = s.grains();
    double worst = 0;
    for (std::size_t i = 0; i < out.radius.size(); ++i)
    {
        const double volume = sphereVolume(out.radius[i]);
        for (int d = 0; d < 3; ++d)
        {
            const double expected =
                out.mass[i] * p.gravity[d] - volume * gradP[d] - rhoFluid * volume * p.gravity[d];
            worst =
                std::max(worst, std::fabs(out.force[3 * i + d] - expected) / std::fabs(expected));
        }
    }
    std::printf("  max relative force error %.2e\n", worst);
    EXPECT_LT(worst, 1e-12);
    s.clearFluid();
    s.step(1);
    EXPECT_NEAR(s.grains().force[2], out.mass[0] * p.gravity[2], 1e-12);
}

DEM_TEST_ON_ALL_BACKENDS(Coupling);

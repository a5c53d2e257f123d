// WallTest.cpp
// A stress-controlled top wall (mass m_w, normal stress sigma0) on columns of grains comes to
// rest where the grains' reaction equals sigma0 A, at the height given by the column's springs
// in series; a velocity-controlled wall moves at its velocity; prescribed-velocity grains keep
// their horizontal velocity and report their x-force; a prescribed grain sliding on a
// frictional floor accumulates the impulse -mu m g t of Coulomb friction.
#include "TestSupport.h"

using namespace demTest;

namespace
{

class Walls : public BackendTest
{
};

} // namespace

TEST_P(Walls, StressControlledWallComesToRestAtSigma0)
{
    const double r = 0.01, spacing = 0.022, sigma0 = 1e4;
    const int columns = 3, layers = 3;
    dem::Parameters p = parameters();
    const double m = 2600 * sphereVolume(r), k = p.grainGrain.normalStiffness;
    p.boxUpper = {columns * spacing, columns * spacing};
    p.grainGrain.friction = p.grainWall.friction = 0.0;
    p.grainGrain.normalDamping = p.grainWall.normalDamping = 2 * 0.5 * std::sqrt(k * m);
    p.timeStep = 0.05 * std::sqrt(m / k);
    dem::System s(p);
    std::vector<dem::GrainInit> grains;
    for (int i = 0; i < columns; ++i)
        for (int j = 0; j < columns; ++j)
            for (int l = 0; l < layers; ++l)
            {
                dem::GrainInit g;
                g.radius = r;
                g.position = {(i + 0.5) * spacing, (j + 0.5) * spacing, (2 * l + 1) * r};
                grains.push_back(g);
            }
    s.addGrains(grains);
    s.addWall(dem::WallSpec());
    dem::WallSpec top;
    top.side = dem::WallSpec::Side::upper;
    top.mode = dem::WallSpec::Mode::stress;
    top.position = 2 * layers * r;
    top.mass = 0.1;
    top.normalStress = sigma0;
    const int topIndex = s.addWall(top);
    s.step(int(0.1 / p.timeStep));
    const dem::WallData w = s.wall(topIndex);
    const double area = p.boxUpper[0] * p.boxUpper[1];
    const double overlap = sigma0 * area / (columns * columns) / k; // per contact
    const double expectedZ = 2 * layers * r - (layers + 1) * overlap;
    std::printf("  reaction / (sigma0 A) - 1 = %.2e, wall z error / compression = %.2e, v = %.1e\n",
                w.grainForce / (sigma0 * area) - 1,
                (w.position - expectedZ) / ((layers + 1) * overlap), w.velocity);
    EXPECT_NEAR(w.grainForce / (sigma0 * area), 1.0, 1e-6);
    EXPECT_NEAR((w.position - expectedZ) / ((layers + 1) * overlap), 0.0, 1e-4);
    EXPECT_LT(std::fabs(w.velocity), 1e-8);
    EXPECT_NEAR(s.wall(0).grainForce, -sigma0 * area, 1e-6 * sigma0 * area);
}

TEST_P(Walls, VelocityWallAndPrescribedGrains)
{
    dem::Parameters p = parameters();
    p.gravity = {0, 0, -9.81};
    dem::System s(p);
    dem::GrainInit resting, carried;
    resting.position = {0.3, 0.5, 0.0099999};
    carried.position = {0.6, 0.5, 0.2};
    s.addGrains({resting, carried});
    s.setGrainFlags({1}, dem::GrainFlag::prescribedVelocity, 0.25, -0.1);
    s.addWall(dem::WallSpec());
    dem::WallSpec lid;
    lid.side = dem::WallSpec::Side::upper;
    lid.mode = dem::WallSpec::Mode::velocity;
    lid.position = 0.5;
    lid.velocity = -0.1;
    s.addWall(lid);
    s.step(10000);
    const dem::GrainData g = s.grains();
    EXPECT_NEAR(s.wall(1).position, 0.5 - 0.1 * s.time(), 1e-12);
    EXPECT_DOUBLE_EQ(g.velocity[3], 0.25);
    EXPECT_DOUBLE_EQ(g.velocity[4], -0.1);
    EXPECT_NEAR(g.velocity[5], -9.81 * s.time(), 1e-9); // free along z
    EXPECT_EQ(g.angularVelocity[3] + g.angularVelocity[4] + g.angularVelocity[5], 0.0);
    EXPECT_NEAR(g.displacement[3], 0.25 * s.time(), 1e-9);
    EXPECT_EQ(g.flag[1], dem::GrainFlag::prescribedVelocity);
    EXPECT_DOUBLE_EQ(s.prescribedGrainForceX(), 0.0);
    s.setGrainFlags({0}, dem::GrainFlag::fixed);
    s.step(10);
    EXPECT_EQ(s.grains().velocity[2], 0.0);
}

TEST_P(Walls, PrescribedGrainImpulseIsCoulombFriction)
{
    dem::Parameters p = parameters();
    p.gravity = {0, 0, -9.81};
    p.grainWall.normalDamping =
        2 * 0.5 * std::sqrt(p.grainWall.normalStiffness * 0.0109); // zeta 0.5
    dem::System s(p);
    dem::GrainInit g;
    g.position = {0.5, 0.5, 0.01 - 0.0109 * 9.81 / p.grainWall.normalStiffness}; // at rest
    s.addGrains({g});
    s.setGrainFlags({0}, dem::GrainFlag::prescribedVelocity, 0.2, 0.0);
    s.addWall(dem::WallSpec());
    s.step(20000); // settled on the floor, sliding at 0.2 m/s
    const double m = s.grains().mass[0], t0 = s.time(), i0 = s.prescribedGrainImpulseX();
    s.step(10000);
    const double meanForce = (s.prescribedGrainImpulseX() - i0) / (s.time() - t0);
    const double coulomb = -p.grainWall.friction * m * 9.81;
    std::printf("  mean x-force %.9g N, Coulomb friction %.9g N\n", meanForce, coulomb);
    EXPECT_NEAR(meanForce / coulomb, 1.0, 1e-9);
    EXPECT_NEAR(s.prescribedGrainForceX() / coulomb, 1.0, 1e-9);
}

DEM_TEST_ON_ALL_BACKENDS(Walls);

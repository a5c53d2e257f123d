// CoincidentTest.cpp
// Two grains at the same centre (a duplicated input line) have no contact normal. The pair
// kernel floors the distance and takes +z as the normal, so the forces stay finite: the pair
// is pushed apart along z by the full-overlap spring and, once apart, carries exactly the
// elastic energy k_n (2r)^2 / 2 that the overlap stored.
#include "TestSupport.h"

using namespace demTest;

namespace
{

class Coincident : public BackendTest
{
};

} // namespace

TEST_P(Coincident, GrainsAtTheSameCentreGetFiniteForcesAndSeparateAlongZ)
{
    dem::Parameters p = parameters();
    dem::System system(p);
    dem::GrainInit g;
    g.radius = 0.01;
    g.position = {0.5, 0.5, 0.5};
    system.addGrains({g, g});

    system.step(1);
    dem::GrainData d = system.grains();
    for (const auto* v : {&d.position, &d.velocity, &d.force, &d.torque, &d.angularVelocity})
        for (const double x : *v)
            ASSERT_TRUE(std::isfinite(x)) << "non-finite grain value after one step";

    // Equal and opposite, along z only, of the size of the spring at (nearly) full overlap.
    const double kn = p.grainGrain.normalStiffness, sumRadii = 2 * g.radius;
    const Vec3 f0 = at(d.force, 0), f1 = at(d.force, 1);
    const double gap = norm(sub(at(d.position, 1), at(d.position, 0)));
    std::printf("  force on grain 0 (%g %g %g) N, centres %g m apart\n", f0[0], f0[1], f0[2], gap);
    EXPECT_EQ(f0[0], 0.0);
    EXPECT_EQ(f0[1], 0.0);
    EXPECT_EQ(f0[2], -f1[2]);
    // Linear spring at overlap 2r - gap (round-off of the distance: 1e-9 relative).
    EXPECT_NEAR(std::fabs(f0[2]), kn * (sumRadii - gap), 1e-9 * kn * sumRadii);

    // Run until the pair is apart: the stored energy k_n (2r)^2 / 2 is now kinetic. Velocity
    // Verlet keeps the energy of a linear spring to O((omega dt)^2) = 2e-4 here (omega =
    // sqrt(2 k_n / m) = 1.4e4 1/s, dt = 1e-6 s); 1e-3 leaves room for the step in which the
    // contact opens.
    system.step(400);
    d = system.grains();
    const double separation = at(d.position, 1)[2] - at(d.position, 0)[2];
    EXPECT_GT(std::fabs(separation), sumRadii);
    EXPECT_EQ(at(d.position, 0)[0], 0.5);
    EXPECT_EQ(at(d.position, 1)[1], 0.5);
    double kinetic = 0;
    for (std::size_t i = 0; i < 2; ++i)
        kinetic += 0.5 * d.mass[i] * dot(at(d.velocity, i), at(d.velocity, i));
    const double stored = 0.5 * kn * sumRadii * sumRadii;
    std::printf("  kinetic energy after separation %.6g J, stored %.6g J\n", kinetic, stored);
    EXPECT_NEAR(kinetic, stored, 1e-3 * stored);
}

DEM_TEST_ON_ALL_BACKENDS(Coincident);

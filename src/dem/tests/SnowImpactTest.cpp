// SnowImpactTest.cpp
// The snow contact law through dem::System (ContactMaterial.law = snow) against the closed
// form of the clipped damped spring (derived in SnowContactTest.cpp): two spheres head-on,
// two capsules side-on and a sphere on a wall; k_n = E pi Rbar / 2 from the dilation radii,
// c_n = 2 zeta sqrt(m* k_n); contact duration (until the overlap closes, after the force has
// ended) and restitution.
#include "CapsuleTestSupport.h"

using namespace demTest;

namespace
{

class SnowImpact : public BackendTest
{
protected:
    const double r = 0.01, v = 0.2, rho = 917.0, E = 1e7, zeta = 0.3;

    dem::ContactMaterial snow() const
    {
        dem::ContactMaterial m;
        m.law = dem::ContactLaw::snow;
        m.youngsModulus = E;
        m.normalDampingRatio = zeta;
        m.tangentialDampingRatio = zeta;
        m.friction = 0.5;
        return m;
    }

    void expectClippedSpring(const ImpactMeasure& sim, double reducedMass, double k, double dt,
                             const char* what)
    {
        const ImpactMeasure ref = clippedSpring(reducedMass, k, zeta);
        std::printf("  %s: contact duration %.6e s (closed form %.6e), restitution %.6f "
                    "(%.6f)\n",
                    what, sim.duration, ref.duration, sim.restitution, ref.restitution);
        // The dashpot sees the half-step velocity: relative errors O(zeta omega_0 dt) (the
        // evaluator test measures 5e-4 at omega_0 dt = 1.6e-3); tolerance 2 omega_0 dt.
        const double tolerance = 2 * std::sqrt(k / reducedMass) * dt;
        EXPECT_NEAR(sim.duration / ref.duration, 1.0, tolerance);
        EXPECT_NEAR(sim.restitution / ref.restitution, 1.0, tolerance);
    }

    //- Two equal grains (capsules of half-length h along y, or spheres) head-on along x.
    void pair(double h, const char* what)
    {
        const double mass = capsuleBody(r, h, rho).mass, reduced = 0.5 * mass;
        const double k = E * M_PI * r / 2; // Rbar = r
        dem::Parameters p = parameters();
        p.grainGrain = p.grainWall = snow();
        p.defaultDensity = rho;
        p.timeStep = M_PI * std::sqrt(reduced / k) / 2000;
        dem::System s(p);
        dem::GrainInit a;
        a.radius = r;
        a.coreHalfLength = h;
        a.orientation = rotation(Eigen::Vector3d::UnitX(), M_PI / 2); // axis along -y
        dem::GrainInit b = a;
        a.position = {0.5 - r - 1e-5, 0.5, 0.5};
        b.position = {0.5 + r + 1e-5, 0.5, 0.5};
        a.velocity = {0.5 * v, 0, 0};
        b.velocity = {-0.5 * v, 0, 0};
        s.addGrains({a, b});
        const ImpactMeasure sim = measureImpact(
            s, [&](const dem::GrainData& g) { return 2 * r - (g.position[3] - g.position[0]); },
            [](const dem::GrainData& g) { return g.velocity[0] - g.velocity[3]; });
        expectClippedSpring(sim, reduced, k, p.timeStep, what);
    }
};

} // namespace

TEST_P(SnowImpact, TwoSpheresHeadOn)
{
    pair(0.0, "spheres");
}

TEST_P(SnowImpact, TwoCapsulesSideOn)
{
    pair(0.02, "capsules side-on");
}

TEST_P(SnowImpact, SphereOnAWall)
{
    // A wall: Rbar = r and m* = m.
    const double mass = capsuleBody(r, 0.0, rho).mass, k = E * M_PI * r / 2;
    dem::Parameters p = parameters();
    p.grainGrain = p.grainWall = snow();
    p.defaultDensity = rho;
    p.timeStep = M_PI * std::sqrt(mass / k) / 2000;
    dem::System s(p);
    dem::GrainInit g;
    g.radius = r;
    g.position = {0.5, 0.5, r + 1e-5};
    g.velocity = {0, 0, -v};
    s.addGrain(g);
    s.addWall(dem::WallSpec());
    const ImpactMeasure sim = measureImpact(
        s, [&](const dem::GrainData& d) { return r - d.position[2]; },
        [](const dem::GrainData& d) { return -d.velocity[2]; });
    expectClippedSpring(sim, mass, k, p.timeStep, "sphere on a wall");
}

DEM_TEST_ON_ALL_BACKENDS(SnowImpact);

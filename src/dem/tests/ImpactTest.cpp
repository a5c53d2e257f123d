// ImpactTest.cpp
// Normal impacts against the closed form of the linear spring-dashpot (doc/REFERENCES.md 2):
// two spheres and sphere-wall; contact duration, maximum overlap, peak force and restitution,
// undamped and damped (unclipped dashpot, as implemented), each within 0.5 %.
#include "TestSupport.h"

#include <algorithm>

using namespace demTest;

namespace
{

struct ImpactResult
{
    double duration = 0, maxOverlap = 0, peakForce = 0, restitution = 0;
};

//- Closed form of m* x'' = -k x - gamma x', x(0) = 0, x'(0) = v.
ImpactResult closedForm(double reducedMass, double k, double gamma, double v)
{
    const double omega0 = std::sqrt(k / reducedMass);
    const double zeta = gamma / (2.0 * std::sqrt(k * reducedMass));
    const double omegaD = omega0 * std::sqrt(1.0 - zeta * zeta);
    ImpactResult r;
    r.duration = M_PI / omegaD;
    r.restitution = std::exp(-zeta * omega0 * r.duration);
    for (int s = 0; s <= 200000; ++s) // dense sampling of the analytic solution
    {
        const double t = r.duration * s / 200000.0;
        const double decay = std::exp(-zeta * omega0 * t);
        const double x = v / omegaD * decay * std::sin(omegaD * t);
        const double xdot =
            v * decay * (std::cos(omegaD * t) - zeta * omega0 / omegaD * std::sin(omegaD * t));
        r.maxOverlap = std::max(r.maxOverlap, x);
        r.peakForce = std::max(r.peakForce, k * x + gamma * xdot);
    }
    return r;
}

//- Steps one at a time; overlap(g) and approach speed are measured from read-back state.
template <class Overlap, class Speed, class Force>
ImpactResult simulate(dem::System& s, Overlap overlap, Speed speed, Force force)
{
    ImpactResult r;
    const double dt = s.timeStep();
    const double approach = speed(s.grains());
    double previous = overlap(s.grains());
    double start = -1, end = -1;
    for (int step = 0; step < 200000 && end < 0; ++step)
    {
        s.step(1);
        const dem::GrainData g = s.grains();
        const double o = overlap(g);
        if (previous <= 0 && o > 0) // interpolated crossing times: O(dt^2) accurate
            start = s.time() - dt * o / (o - previous);
        if (previous > 0 && o <= 0)
            end = s.time() - dt * o / (o - previous);
        if (o > 0)
        {
            r.maxOverlap = std::max(r.maxOverlap, o);
            r.peakForce = std::max(r.peakForce, force(g));
        }
        previous = o;
    }
    EXPECT_GT(start, 0.0);
    EXPECT_GT(end, 0.0);
    r.duration = end - start;
    r.restitution = -speed(s.grains()) / approach;
    return r;
}

void expectClose(const ImpactResult& sim, const ImpactResult& ref, double tolerance)
{
    EXPECT_NEAR(sim.duration / ref.duration, 1.0, tolerance) << "contact duration";
    EXPECT_NEAR(sim.maxOverlap / ref.maxOverlap, 1.0, tolerance) << "maximum overlap";
    EXPECT_NEAR(sim.peakForce / ref.peakForce, 1.0, tolerance) << "peak force";
    EXPECT_NEAR(sim.restitution / ref.restitution, 1.0, tolerance) << "restitution";
    std::printf(
        "  duration %.6e (ref %.6e), overlap %.6e (%.6e), force %.6e (%.6e), e %.6f (%.6f)\n",
        sim.duration, ref.duration, sim.maxOverlap, ref.maxOverlap, sim.peakForce, ref.peakForce,
        sim.restitution, ref.restitution);
}

class Impact : public BackendTest
{
protected:
    const double r = 0.01, v = 0.2;
    double mass() const { return 2600.0 * sphereVolume(r); }

    void twoSpheres(double zeta)
    {
        dem::Parameters p = parameters();
        const double reduced = 0.5 * mass(), k = p.grainGrain.normalStiffness;
        p.grainGrain.normalDamping = 2.0 * zeta * std::sqrt(k * reduced);
        p.timeStep = M_PI * std::sqrt(reduced / k) / 2000.0;
        dem::System s(p);
        dem::GrainInit a, b;
        a.radius = b.radius = r;
        a.position = {0.5 - r - 1e-5, 0.5, 0.5};
        b.position = {0.5 + r + 1e-5, 0.5, 0.5};
        a.velocity = {0.5 * v, 0, 0};
        b.velocity = {-0.5 * v, 0, 0};
        s.addGrains({a, b});
        const ImpactResult sim = simulate(
            s,
            [&](const dem::GrainData& g)
            { return 2 * r - norm(sub(at(g.position, 1), at(g.position, 0))); },
            [](const dem::GrainData& g) { return g.velocity[0] - g.velocity[3]; },
            [](const dem::GrainData& g) { return norm(at(g.force, 0)); });
        expectClose(sim, closedForm(reduced, k, p.grainGrain.normalDamping, v), 0.005);
    }

    void sphereOnWall(double zeta)
    {
        dem::Parameters p = parameters();
        const double k = p.grainWall.normalStiffness;
        p.grainWall.normalDamping = 2.0 * zeta * std::sqrt(k * mass());
        p.timeStep = M_PI * std::sqrt(mass() / k) / 2000.0;
        dem::System s(p);
        dem::GrainInit a;
        a.radius = r;
        a.position = {0.5, 0.5, r + 1e-5};
        a.velocity = {0, 0, -v};
        s.addGrain(a);
        dem::WallSpec wall;
        s.addWall(wall);
        const ImpactResult sim = simulate(
            s, [&](const dem::GrainData& g) { return r - g.position[2]; },
            [](const dem::GrainData& g) { return -g.velocity[2]; },
            [](const dem::GrainData& g) { return norm(at(g.force, 0)); });
        expectClose(sim, closedForm(mass(), k, p.grainWall.normalDamping, v), 0.005);
        EXPECT_NEAR(s.wall(0).grainForce, 0.0, 1e-12);
    }
};

} // namespace

TEST_P(Impact, TwoSpheresUndamped)
{
    twoSpheres(0.0);
}
TEST_P(Impact, TwoSpheresDamped)
{
    twoSpheres(0.2);
}
TEST_P(Impact, SphereWallUndamped)
{
    sphereOnWall(0.0);
}
TEST_P(Impact, SphereWallDamped)
{
    sphereOnWall(0.5);
}

DEM_TEST_ON_ALL_BACKENDS(Impact);

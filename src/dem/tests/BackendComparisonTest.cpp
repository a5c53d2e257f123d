// BackendComparisonTest.cpp
// The CPU and the CUDA backend run the same dense, frictional, slightly polydisperse packing
// (grains pushed apart by their initial overlaps, under gravity between a fixed floor and a
// stress-controlled lid, neighbour lists rebuilt on the way) and must end on the same
// trajectory, to within the growth of round-off in that packing.
//
// Why not bit for bit: nvcc contracts a*b+c into fused multiply-adds and the GPU sums the lid's
// force in another order, so each step's results may differ in the last bit. In a chaotic
// packing such differences grow, so the tolerance must come from their growth, not from a fixed
// number. Each step, a difference of at most a few units in the last place (ulp) of a position
// enters (the drift x + dt v rounds once instead of twice; a force's relative change of ~1e-16
// moves a grain far less than that). The tolerance is measured on the CPU alone: a second CPU
// run starts from positions moved by eta0 = steps x 4 ulp(x_max), the sum of every step's
// worst-case difference, in a random direction. While differences stay small (checked: far
// below the grains' overlaps), they evolve linearly, and one that enters at a later step has
// had less time to grow (here 500 steps amplify eta0 about 4000 times), so CUDA's steps-many
// small differences cannot end further from the CPU run than this one early difference of
// their total size: |x_cuda - x_cpu| <= |x_pert - x_cpu|, the same for the velocities, and for
// the kinetic energy the bound that follows from the velocities'. (Summed with random signs,
// the per-step differences grow as sqrt(steps), not steps: a margin of ~20.)
// Skipped without a CUDA device.
#include "TestSupport.h"

#include <algorithm>
#include <random>

using namespace demTest;

namespace
{

struct Trajectory
{
    std::vector<double> unwrapped; //!< start position + displacement (no periodic jumps)
    std::vector<double> velocity, mass;
    std::size_t rebuilds = 0, contacts = 0;
    double maxDisplacement = 0;
};

dem::Parameters packingParameters(dem::Backend backend)
{
    dem::Parameters p;
    p.grainGrain = {1e6, 1e6, 0.0, 0.0, 0.5};
    p.grainWall = p.grainGrain;
    p.gravity = {0.0, 0.0, -9.81};
    p.boxLower = {0.0, 0.0};
    p.boxUpper = {0.24, 0.24};
    p.periodic = {true, true};
    p.neighbourSkin = 2e-4;
    p.timeStep = 0.1 * std::sqrt(2600 * sphereVolume(0.00998) / p.grainGrain.normalStiffness);
    p.backend = backend;
    return p;
}

//- 12 x 12 x 10 grains of r = 0.01 m +- 0.2 %, jittered by up to 20 um on a lattice of
//- spacing 2 r: neighbours overlap by up to 60 um or miss each other by as much, and start with
//- random velocities of up to 0.05 m/s.
std::vector<dem::GrainInit> packing()
{
    std::mt19937 random(2026);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    std::vector<dem::GrainInit> grains;
    for (int k = 0; k < 10; ++k)
        for (int j = 0; j < 12; ++j)
            for (int i = 0; i < 12; ++i)
            {
                dem::GrainInit g;
                g.radius = 0.01 * (1.0 + 0.002 * uniform(random));
                g.position = {(2 * i + 1) * 0.01 + 2e-5 * uniform(random),
                              (2 * j + 1) * 0.01 + 2e-5 * uniform(random),
                              (2 * k + 1) * 0.01 + 2e-5 * uniform(random)};
                g.velocity = {0.05 * uniform(random), 0.05 * uniform(random),
                              0.05 * uniform(random)};
                grains.push_back(g);
            }
    return grains;
}

Trajectory run(dem::Backend backend, const std::vector<dem::GrainInit>& grains, int steps)
{
    const dem::Parameters p = packingParameters(backend);
    dem::System s(p);
    s.addGrains(grains);
    s.addWall(dem::WallSpec());
    dem::WallSpec lid;
    lid.side = dem::WallSpec::Side::upper;
    lid.mode = dem::WallSpec::Mode::stress;
    lid.position = 0.2 + 1e-5;
    lid.mass = 0.5;
    lid.normalStress = 1e3;
    s.addWall(lid);
    s.step(steps);
    const dem::GrainData g = s.grains();
    Trajectory r;
    r.velocity = g.velocity;
    r.mass = g.mass;
    r.unwrapped.resize(g.displacement.size());
    for (std::size_t i = 0; i < grains.size(); ++i)
        for (int d = 0; d < 3; ++d)
        {
            r.unwrapped[3 * i + d] = grains[i].position[d] + g.displacement[3 * i + d];
            r.maxDisplacement = std::max(r.maxDisplacement, std::fabs(g.displacement[3 * i + d]));
        }
    r.rebuilds = s.neighbourRebuildCount();
    r.contacts = s.contactCount();
    return r;
}

double maxDifference(const std::vector<double>& a, const std::vector<double>& b)
{
    double worst = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
        worst = std::max(worst, std::fabs(a[i] - b[i]));
    return worst;
}

double kineticEnergy(const Trajectory& r)
{
    double e = 0;
    for (std::size_t i = 0; i < r.mass.size(); ++i)
        e += 0.5 * r.mass[i] * dot(at(r.velocity, i), at(r.velocity, i));
    return e;
}

} // namespace

TEST(CpuVsCuda, SamePackingSameTrajectoryWithinRoundOffGrowth)
{
    if (dem::cudaDeviceCount() == 0)
        GTEST_SKIP() << "no CUDA device answers";
    const int steps = 500;
    const std::vector<dem::GrainInit> grains = packing();

    // eta0: every step's worst-case difference (4 ulp of the largest coordinate), summed.
    const double ulp = std::nextafter(0.24, 1.0) - 0.24;
    const double eta0 = steps * 4 * ulp;
    std::vector<dem::GrainInit> perturbed = grains;
    std::mt19937 random(1);
    std::normal_distribution<double> normal;
    for (dem::GrainInit& g : perturbed)
    {
        const Vec3 u = {normal(random), normal(random), normal(random)};
        for (int d = 0; d < 3; ++d)
            g.position[d] += eta0 * u[d] / norm(u);
    }

    const Trajectory cpu = run(dem::Backend::cpu, grains, steps);
    const Trajectory pert = run(dem::Backend::cpu, perturbed, steps);
    const Trajectory cuda = run(dem::Backend::cuda, grains, steps);

    const double dxTol = maxDifference(pert.unwrapped, cpu.unwrapped);
    const double dvTol = maxDifference(pert.velocity, cpu.velocity);
    // |KE_a - KE_b| <= sum m (|v| |dv| + |dv|^2 / 2) with |dv| <= dvTol per component.
    double keTol = 0;
    for (std::size_t i = 0; i < cpu.mass.size(); ++i)
        keTol += cpu.mass[i] *
                 (std::sqrt(3.0) * norm(at(cpu.velocity, i)) * dvTol + 1.5 * dvTol * dvTol);
    const double dx = maxDifference(cuda.unwrapped, cpu.unwrapped);
    const double dv = maxDifference(cuda.velocity, cpu.velocity);
    const double ke = kineticEnergy(cpu), dke = std::fabs(kineticEnergy(cuda) - ke);
    std::printf("  %d steps, %zu grains, %zu rebuilds (cuda %zu), %zu contacts, max displacement "
                "%.3g m, eta0 = %.3g m\n"
                "  |x_cuda - x_cpu| = %.3g m (tolerance |x_pert - x_cpu| = %.3g m)\n"
                "  |v_cuda - v_cpu| = %.3g m/s (tolerance %.3g m/s)\n"
                "  |KE_cuda - KE_cpu| = %.3g J of %.3g J (tolerance %.3g J)\n",
                steps, grains.size(), cpu.rebuilds, cuda.rebuilds, cpu.contacts,
                cpu.maxDisplacement, eta0, dx, dxTol, dv, dvTol, dke, ke, keTol);

    // The comparison means something: grains moved, touched and were re-listed on the way ...
    EXPECT_GT(cpu.maxDisplacement, 2e-5);
    EXPECT_GT(cpu.contacts, grains.size());
    EXPECT_GT(cpu.rebuilds, 2u);
    // ... and the calibration run is still in the small-difference regime, where the argument
    // above holds: differences below 1e-8 m, a thousandth of the smallest change of contact
    // geometry that matters here (the 2e-5 m jitter, the 6e-5 m initial overlaps).
    EXPECT_GT(dxTol, 0.0);
    EXPECT_LT(dxTol, 1e-8);
    EXPECT_LE(dx, dxTol);
    EXPECT_LE(dv, dvTol);
    EXPECT_LE(dke, keTol);
}

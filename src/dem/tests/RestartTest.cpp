// RestartTest.cpp
// Exporting the complete state, importing it into a fresh System and stepping gives results
// bit-identical to the uninterrupted run (contacts with history, rebuilds, a stress wall).
// And the CPU-vs-CUDA comparison, skipped when no device answers.
#include "TestSupport.h"

#include <cstring>
#include <random>

using namespace demTest;

namespace
{

class Restart : public BackendTest
{
};

const int n = 17;
const double r = 0.01, spacing = 0.0199;

dem::Parameters packingParameters(dem::Parameters p)
{
    p.boxUpper = {n * spacing, n * spacing};
    p.gravity = {0, 0, -9.81};
    p.grainGrain.normalDamping = 5.0;
    p.neighbourSkin = 0.0005;
    p.timeStep = 5e-6;
    return p;
}

//- A jittered, jostling packing on a wall under a stress-controlled lid (> 4096 grains, so
//- the CPU kernels run multi-threaded). capsules: every third grain is a spinning capsule of
//- random orientation (r = 0.005 m, h = 0.004 m: it fits its lattice site) instead.
dem::System makeSystem(const dem::Parameters& base, bool capsules = false)
{
    dem::System s(packingParameters(base));
    std::mt19937 random(3);
    std::uniform_real_distribution<double> jitter(-1e-4, 1e-4), speed(-0.05, 0.05);
    std::vector<dem::GrainInit> grains;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k)
            {
                dem::GrainInit g;
                g.radius = r * (0.95 + 0.05 * ((i + 2 * j + 3 * k) % 3) / 2.0);
                g.position = {(i + 0.5) * spacing + jitter(random),
                              (j + 0.5) * spacing + jitter(random), (k + 0.5) * spacing};
                g.velocity = {speed(random), speed(random), speed(random)};
                if (capsules && (i + j + k) % 3 == 0)
                {
                    g.radius = 0.005;
                    g.coreHalfLength = 0.004;
                    std::normal_distribution<double> gauss;
                    std::array<double, 4> q{gauss(random), gauss(random), gauss(random),
                                            gauss(random)};
                    const double length =
                        std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
                    for (double& c : q)
                        c /= length;
                    g.orientation = q;
                    g.angularVelocity = {100 * speed(random), 100 * speed(random),
                                         100 * speed(random)};
                }
                grains.push_back(g);
            }
    s.addGrains(grains);
    s.addWall(dem::WallSpec());
    dem::WallSpec lid;
    lid.side = dem::WallSpec::Side::upper;
    lid.mode = dem::WallSpec::Mode::stress;
    lid.position = n * spacing + 0.002;
    lid.mass = 1.0;
    lid.normalStress = 1e3;
    s.addWall(lid);
    return s;
}

template <class T>
bool identical(const std::vector<T>& a, const std::vector<T>& b)
{
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

void expectBitIdenticalRestart(const dem::Parameters& p, bool capsules)
{
    dem::System original = makeSystem(p, capsules);
    original.step(300);
    const dem::SystemState state = original.exportState();
    const std::size_t rebuildsBefore = original.neighbourRebuildCount();
    original.step(300);
    dem::System restarted(packingParameters(p));
    restarted.importState(state);
    restarted.step(300);
    const dem::GrainData a = original.grains(), b = restarted.grains();
    std::printf("  %zu grains, %zu contacts, %zu rebuilds after the export, %d threads\n",
                a.radius.size(), original.contactCount(),
                original.neighbourRebuildCount() - rebuildsBefore, original.threadCount());
    EXPECT_GT(original.neighbourRebuildCount(), rebuildsBefore);
    EXPECT_GT(original.contactCount(), capsules ? 20u : 200u); // the small capsules touch less
    EXPECT_TRUE(identical(a.position, b.position));
    EXPECT_TRUE(identical(a.velocity, b.velocity));
    EXPECT_TRUE(identical(a.angularVelocity, b.angularVelocity));
    EXPECT_TRUE(identical(a.force, b.force));
    EXPECT_TRUE(identical(a.displacement, b.displacement));
    EXPECT_TRUE(identical(a.orientation, b.orientation));
    EXPECT_TRUE(identical(a.torque, b.torque));
    EXPECT_EQ(original.wall(1).position, restarted.wall(1).position);
    EXPECT_EQ(original.time(), restarted.time());
    EXPECT_EQ(original.stepCount(), restarted.stepCount());
}

} // namespace

TEST_P(Restart, ImportedStateContinuesBitIdentically)
{
    expectBitIdenticalRestart(parameters(), false);
}

//- The same with capsules mixed in (orientation, angular momentum, both-end wall records and
//- the rebuild's half-axis vectors are part of the state).
TEST_P(Restart, ImportedStateWithCapsulesContinuesBitIdentically)
{
    expectBitIdenticalRestart(parameters(), true);
}

DEM_TEST_ON_ALL_BACKENDS(Restart);

TEST(BackendComparison, CpuAndCudaAgree)
{
    if (dem::cudaDeviceCount() == 0)
        GTEST_SKIP() << "no CUDA device answers";
    dem::Parameters p;
    p.grainGrain = {1e6, 1e6, 0.0, 0.0, 0.5};
    p.grainWall = p.grainGrain;
    p.backend = dem::Backend::cpu;
    dem::System cpu = makeSystem(p);
    p.backend = dem::Backend::cuda;
    dem::System cuda = makeSystem(p);
    cpu.step(200);
    cuda.step(200);
    const dem::GrainData a = cpu.grains(), b = cuda.grains();
    double worst = 0;
    for (std::size_t i = 0; i < a.position.size(); ++i)
        worst = std::max(worst, std::fabs(a.position[i] - b.position[i]));
    std::printf("  max |x_cpu - x_cuda| = %.2e m\n", worst);
    EXPECT_LT(worst, 1e-9);
    EXPECT_EQ(cpu.contactCount(), cuda.contactCount());
}

TEST(ThreadCount, CpuResultsDoNotDependOnThreads)
{
    // Same packing on 1 and 3 threads (the kernels split grains and pairs differently, the
    // pair loop's vector and remainder iterations fall elsewhere): bit-identical results.
    dem::Parameters p;
    p.grainGrain = {1e6, 1e6, 0.0, 0.0, 0.5};
    p.grainWall = p.grainGrain;
    p.backend = dem::Backend::cpu;
    for (const bool capsules : {false, true})
    {
        std::vector<dem::GrainData> results;
        std::vector<double> lids;
        for (const int threads : {1, 3})
        {
            p.threads = threads;
            dem::System s = makeSystem(p, capsules);
            s.step(300);
            EXPECT_EQ(s.threadCount(), threads);
            results.push_back(s.grains());
            lids.push_back(s.wall(1).position);
        }
        EXPECT_TRUE(identical(results[0].position, results[1].position)) << capsules;
        EXPECT_TRUE(identical(results[0].velocity, results[1].velocity)) << capsules;
        EXPECT_TRUE(identical(results[0].angularVelocity, results[1].angularVelocity)) << capsules;
        EXPECT_TRUE(identical(results[0].orientation, results[1].orientation)) << capsules;
        EXPECT_TRUE(identical(results[0].force, results[1].force)) << capsules;
        EXPECT_EQ(lids[0], lids[1]) << capsules;
    }
}

// ErrorTest.cpp
// Refusals are exceptions with clear messages: contact-storage overflow (never a silent drop),
// a time step above the critical fraction, invalid parameters, an unavailable CUDA backend, a
// decomposition over MPI ranks without MPI.
#include "TestSupport.h"
#include "dem/Mpi.h"

using namespace demTest;

namespace
{

class Errors : public BackendTest
{
protected:
    std::vector<dem::GrainInit> denseLattice(int n, double spacing) const
    {
        std::vector<dem::GrainInit> out;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                for (int k = 0; k < n; ++k)
                {
                    dem::GrainInit g;
                    g.position = {(i + 0.5) * spacing, (j + 0.5) * spacing, (k + 0.5) * spacing};
                    out.push_back(g);
                }
        return out;
    }
};

std::string messageOf(const std::function<void()>& f)
{
    try
    {
        f();
    }
    catch (const dem::Error& e)
    {
        return e.what();
    }
    return "";
}

} // namespace

TEST_P(Errors, ContactStorageOverflowIsReported)
{
    dem::Parameters p = parameters();
    p.boxUpper = {0.2, 0.2};
    p.maxPairsPerGrain = 2;
    dem::System limited(p);
    limited.addGrains(denseLattice(10, 0.0199)); // 6 touching neighbours each
    const std::string message = messageOf([&] { limited.step(1); });
    std::printf("  %s\n", message.c_str());
    EXPECT_NE(message.find("contact storage overflow"), std::string::npos) << message;
    EXPECT_NE(message.find("maxPairsPerGrain"), std::string::npos) << message;

    p.maxPairsPerGrain = 0; // grow: every contact is kept
    dem::System growing(p);
    growing.addGrains(denseLattice(10, 0.0199));
    growing.step(1);
    EXPECT_EQ(growing.contactCount(), 3u * 10 * 10 * 9); // lattice neighbours, none across the seam
}

TEST_P(Errors, TimeStepAboveCriticalIsRefused)
{
    dem::Parameters p = parameters();
    p.timeStep = 1e-3;
    dem::System s(p);
    s.addGrain(dem::GrainInit());
    const std::string message = messageOf([&] { s.step(1); });
    std::printf("  %s\n", message.c_str());
    EXPECT_NE(message.find("timeStep"), std::string::npos) << message;
    EXPECT_NE(message.find("critical"), std::string::npos) << message;
    s.setTimeStep(0.1 * s.criticalTimeStep());
    EXPECT_NO_THROW(s.step(1));
}

TEST_P(Errors, InvalidParametersAreNamed)
{
    dem::Parameters p = parameters();
    p.grainGrain.friction = -1;
    const std::string message = messageOf([&] { dem::System s(p); });
    EXPECT_NE(message.find("grainGrain.friction"), std::string::npos) << message;
    dem::System s(parameters());
    dem::WallSpec w;
    w.mode = dem::WallSpec::Mode::stress;
    EXPECT_NE(messageOf([&] { s.addWall(w); }).find("wall.mass"), std::string::npos);
    dem::UniformGrid bad;
    bad.n = {0, 1, 1};
    EXPECT_NE(messageOf([&] { s.deposit(bad, 0, nullptr, nullptr, nullptr); }).find("grid"),
              std::string::npos);
}

TEST_P(Errors, BlownUpStepNamesTheGrain)
{
    // Explicit drag with c dt / m = 92 >> 2: the velocity grows about 90-fold per step and
    // overflows after some 160 steps. The step stops there, naming the grain, instead of
    // binning a NaN position into a cell.
    dem::Parameters p = parameters();
    p.viscousDrag = 1e6;
    dem::System system(p);
    dem::GrainInit g;
    g.position = {0.5, 0.5, 0.5};
    g.velocity = {0.0, 0.0, 1.0};
    system.addGrains({g});
    const std::string message = messageOf([&] { system.step(1000); });
    std::printf("  %s\n", message.c_str());
    EXPECT_NE(message.find("grain 0 left the numbers"), std::string::npos) << message;
    EXPECT_NE(message.find("time step"), std::string::npos) << message;
}

DEM_TEST_ON_ALL_BACKENDS(Errors);

// A decomposition over ranks in a program that did not start MPI (this test binary): the
// message says how to start it (with MPI built in), or that MPI is not built in.
TEST_P(Errors, DecompositionWithoutMpiIsRefused)
{
    dem::Parameters p = parameters();
    p.decomposition.ranks = {2, 1};
    const std::string message = messageOf([&] { dem::System s(p); });
    const std::string expected = dem::mpiBuild() ? "MPI is not running" : "built without MPI";
    EXPECT_NE(message.find(expected), std::string::npos) << message;
    EXPECT_NE(message.find("decomposition"), std::string::npos) << message;
}

TEST(Backends, CudaWithoutDeviceFailsClearly)
{
    if (dem::cudaDeviceCount() > 0)
        GTEST_SKIP() << "a CUDA device answers";
    dem::Parameters p;
    p.backend = dem::Backend::cuda;
    const std::string message = messageOf([&] { dem::System s(p); });
    EXPECT_NE(message.find("cuda"), std::string::npos) << message;
    p.backend = dem::Backend::automatic;
    EXPECT_EQ(dem::System(p).backendName(), "cpu");
}

// TestSupport.h
// Shared pieces of the unit tests: the per-backend fixture (every test body runs on the CPU
// and, when a device answers, on the CUDA backend; otherwise the CUDA instance is skipped),
// default parameters and small vector helpers.
#pragma once

#include "dem/System.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

namespace demTest
{

using Vec3 = std::array<double, 3>;

inline Vec3 at(const std::vector<double>& v, std::size_t i)
{
    return {v[3 * i], v[3 * i + 1], v[3 * i + 2]};
}
inline Vec3 sub(const Vec3& a, const Vec3& b)
{
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
inline double dot(const Vec3& a, const Vec3& b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline double norm(const Vec3& a)
{
    return std::sqrt(dot(a, a));
}
inline double sphereVolume(double r)
{
    return 4.0 / 3.0 * M_PI * r * r * r;
}

//- Fixture: GetParam() is the backend under test.
class BackendTest : public ::testing::TestWithParam<dem::Backend>
{
protected:
    void SetUp() override
    {
        if (GetParam() == dem::Backend::cuda && dem::cudaDeviceCount() == 0)
            GTEST_SKIP() << "no CUDA device answers";
    }

    //- Dry grains of r = 0.01 m, rho = 2600, k_n = k_t = 1e6 N/m, no gravity, 1 m periodic box.
    dem::Parameters parameters() const
    {
        dem::Parameters p;
        p.grainGrain = {1e6, 1e6, 0.0, 0.0, 0.5};
        p.grainWall = p.grainGrain;
        p.gravity = {0.0, 0.0, 0.0};
        p.boxLower = {0.0, 0.0};
        p.boxUpper = {1.0, 1.0};
        p.timeStep = 1e-6;
        p.neighbourSkin = 0.002;
        p.backend = GetParam();
        return p;
    }
};

inline std::string backendName(const ::testing::TestParamInfo<dem::Backend>& info)
{
    return info.param == dem::Backend::cuda ? "cuda" : "cpu";
}

} // namespace demTest

#define DEM_TEST_ON_ALL_BACKENDS(Suite)                                                            \
    INSTANTIATE_TEST_SUITE_P(Backends, Suite,                                                      \
                             ::testing::Values(dem::Backend::cpu, dem::Backend::cuda),             \
                             demTest::backendName)

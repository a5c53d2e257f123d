// CapsuleSetupTest.cpp
// Capsules as added: the read-back gives the shape, the unit orientation and the true volume
// and mass (closed forms of a cylinder between two hemispheres); bad shapes and orientations
// are refused with a message naming the grain and the rule.
#include "TestSupport.h"

#include <functional>

using namespace demTest;

namespace
{

class CapsuleSetup : public BackendTest
{
};

std::string refusal(const std::function<void()>& f)
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

TEST_P(CapsuleSetup, ReadBackGivesShapeOrientationVolumeAndMass)
{
    dem::System system(parameters());
    dem::GrainInit sphere, capsule;
    sphere.position = {0.2, 0.2, 0.2};
    capsule.position = {0.6, 0.6, 0.6};
    capsule.radius = 0.005;
    capsule.coreHalfLength = 0.01;
    capsule.density = 917.0;
    // A rotation of 90 degrees about x, given 5e-7 too long: normalised when added.
    const double c = std::sqrt(0.5) * (1.0 + 5e-7);
    capsule.orientation = {c, c, 0.0, 0.0};
    system.addGrains({sphere, capsule});
    const dem::GrainData g = system.grains();

    const double r = 0.005, L = 0.02;
    const double volume = M_PI * r * r * L + 4.0 / 3.0 * M_PI * r * r * r;
    std::printf("  capsule volume %.15e (closed form %.15e), mass %.15e kg\n", g.volume[1], volume,
                g.mass[1]);
    // Round-off of a few products: 1e-14 relative.
    EXPECT_NEAR(g.volume[1], volume, 1e-14 * volume);
    EXPECT_NEAR(g.mass[1], 917.0 * volume, 1e-14 * 917.0 * volume);
    EXPECT_EQ(g.coreHalfLength[1], 0.01);
    EXPECT_EQ(g.coreHalfLength[0], 0.0);
    EXPECT_NEAR(g.volume[0], sphereVolume(0.01), 1e-15 * sphereVolume(0.01));
    // The mass is stored as 1 / m: two roundings.
    EXPECT_NEAR(g.mass[0], 2600.0 * g.volume[0], 1e-15 * g.mass[0]);
    const double* q = &g.orientation[4];
    const double length = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    EXPECT_NEAR(length, 1.0, 1e-15); // normalised to round-off
    EXPECT_NEAR(q[0], std::sqrt(0.5), 1e-15);
    EXPECT_NEAR(q[1], std::sqrt(0.5), 1e-15);
    EXPECT_EQ(g.orientation[0], 1.0); // the sphere keeps the identity
}

TEST_P(CapsuleSetup, BadShapesAndOrientationsAreRefused)
{
    dem::System system(parameters());
    dem::GrainInit g;
    g.position = {0.5, 0.5, 0.5};

    g.coreHalfLength = -1e-3;
    std::string message = refusal([&] { system.addGrain(g); });
    std::printf("  %s\n", message.c_str());
    EXPECT_NE(message.find("grain 0 has coreHalfLength"), std::string::npos) << message;
    g.coreHalfLength = std::nan("");
    EXPECT_NE(refusal([&] { system.addGrain(g); }).find("coreHalfLength"), std::string::npos);

    g.coreHalfLength = 0.01;
    g.orientation = {1.0, 1e-5, 0.0, 0.0}; // |q| - 1 = 5e-11: accepted
    EXPECT_EQ(refusal([&] { system.addGrain(g); }), "");
    g.orientation = {1.0, 0.01, 0.0, 0.0}; // |q| - 1 = 5e-5: refused
    message = refusal([&] { system.addGrain(g); });
    std::printf("  %s\n", message.c_str());
    EXPECT_NE(message.find("grain 1 has orientation"), std::string::npos) << message;
    EXPECT_NE(message.find("unit quaternion"), std::string::npos) << message;
    g.orientation = {std::nan(""), 0.0, 0.0, 0.0};
    EXPECT_NE(refusal([&] { system.addGrain(g); }).find("orientation"), std::string::npos);
    EXPECT_EQ(system.grainCount(), 1u); // the refused grains were not added
}

DEM_TEST_ON_ALL_BACKENDS(CapsuleSetup);

// CapsuleSetupTest.cpp
// Capsules as added: the read-back gives the shape, the unit orientation and the true volume
// and mass (closed forms of a cylinder between two hemispheres); bad shapes and orientations
// are refused with a message naming the grain and the rule.
#include "TestSupport.h"

#include <algorithm>
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

TEST_P(CapsuleSetup, LargestOverlapUsesTheCoresClosestPoints)
{
    dem::System system(parameters());
    const double c = std::sqrt(0.5);
    dem::GrainInit alongX, alongY, tipSphere, farSphere;
    alongX.position = {0.5, 0.5, 0.5}; // core from x = 0.47 to 0.53
    alongX.coreHalfLength = 0.03;
    alongX.orientation = {c, 0.0, c, 0.0}; // body z -> global x
    alongY.position = {0.52, 0.5, 0.519};  // crosses above: cores 0.019 m apart
    alongY.coreHalfLength = 0.03;
    alongY.orientation = {c, -c, 0.0, 0.0}; // body z -> global y
    tipSphere.position = {0.542, 0.5, 0.5}; // 0.012 m beyond the tip at x = 0.53
    tipSphere.radius = 0.005;
    farSphere.position = {0.2, 0.2, 0.2};
    system.addGrains({alongX, alongY, tipSphere, farSphere});
    const dem::GrainOverlap deepest = system.largestOverlap();
    std::printf("  deepest: grains %d and %d, overlap %.15e m, relative %.15f\n", deepest.first,
                deepest.second, deepest.overlap, deepest.relativeOverlap);
    // The tip sphere overlaps 0.015 - 0.012 = 3 mm (0.6 of its radius; its centre is 0.042 m
    // from the capsule's, far outside the sum of radii); the crossing pair 1 mm (0.1).
    // Round-off of coordinates near 0.5: 1e-15.
    EXPECT_EQ(deepest.first, 0);
    EXPECT_EQ(deepest.second, 2);
    EXPECT_NEAR(deepest.overlap, 0.003, 1e-15);
    EXPECT_NEAR(deepest.relativeOverlap, 0.6, 1e-13);
    EXPECT_EQ(system.contactCount(), 2u);

    // The query builds the neighbour list early; the run continues as without it.
    dem::System unqueried(parameters());
    unqueried.addGrains({alongX, alongY, tipSphere, farSphere});
    system.step(50);
    unqueried.step(50);
    EXPECT_EQ(system.grains().position, unqueried.grains().position);
    EXPECT_EQ(system.grains().orientation, unqueried.grains().orientation);

    dem::System apart(parameters());
    apart.addGrains({alongX, farSphere});
    const dem::GrainOverlap none = apart.largestOverlap();
    EXPECT_EQ(none.first, -1);
    EXPECT_EQ(none.second, -1);
    EXPECT_EQ(none.relativeOverlap, 0.0);
}

TEST_P(CapsuleSetup, CriticalTimeStepCountsCapsuleRotationAndSnowStiffness)
{
    // A capsule (r = 0.01 m, h = 0.02 m, rho 2600) under the linear spring k = 1e6 N/m: the
    // smallest of m, I_perp / (r + h)^2 and I_axial / r^2 (closed forms) sets the step.
    dem::System linear(parameters());
    dem::GrainInit g;
    g.position = {0.5, 0.5, 0.5};
    g.coreHalfLength = 0.02;
    linear.addGrain(g);
    const double r = 0.01, L = 0.04, rho = 2600.0;
    const double mc = rho * M_PI * r * r * L, mh = rho * 4.0 / 3.0 * M_PI * r * r * r;
    const double perp =
        mc * (L * L / 12 + r * r / 4) + mh * (2 * r * r / 5 + L * L / 4 + 3 * L * r / 8);
    const double axial = mc * r * r / 2 + 2 * mh * r * r / 5;
    const double effective = std::min({mc + mh, perp / (0.03 * 0.03), axial / (r * r)});
    std::printf("  capsule: m %.6e kg, I_perp/(r+h)^2 %.6e kg, I_axial/r^2 %.6e kg; step %.6e s\n",
                mc + mh, perp / (0.03 * 0.03), axial / (r * r), linear.criticalTimeStep());
    EXPECT_NEAR(linear.criticalTimeStep(), std::sqrt(effective / 1e6),
                1e-14 * std::sqrt(effective / 1e6));

    // The snow law (E = 1e7 Pa) on spheres of r = 0.01 and 0.02 m: k_n = E pi R_max / 2 at
    // the largest radius (k_t = 0.6 k_n is smaller), m the smaller sphere's.
    dem::Parameters p = parameters();
    p.grainGrain.law = dem::ContactLaw::snow;
    p.grainGrain.youngsModulus = 1e7;
    p.grainWall = p.grainGrain;
    dem::System snow(p);
    dem::GrainInit small, large;
    small.position = {0.2, 0.2, 0.2};
    large.position = {0.6, 0.6, 0.6};
    large.radius = 0.02;
    snow.addGrains({small, large});
    const double kn = 0.5 * M_PI * 1e7 * 0.02, m = rho * 4.0 / 3.0 * M_PI * r * r * r;
    EXPECT_NEAR(snow.criticalTimeStep(), std::sqrt(m / kn), 1e-14 * std::sqrt(m / kn));
}

TEST_P(CapsuleSetup, SnowLawConstantsAreChecked)
{
    dem::Parameters p = parameters();
    p.grainWall.law = dem::ContactLaw::snow;
    p.grainWall.youngsModulus = 0.0;
    std::string message = refusal([&] { dem::System s(p); });
    std::printf("  %s\n", message.c_str());
    EXPECT_NE(message.find("grainWall.youngsModulus"), std::string::npos) << message;
    p.grainWall.youngsModulus = 1e7;
    p.grainWall.normalDampingRatio = 1.5;
    message = refusal([&] { dem::System s(p); });
    std::printf("  %s\n", message.c_str());
    EXPECT_NE(message.find("grainWall.normalDampingRatio"), std::string::npos) << message;
    p.grainWall.normalDampingRatio = 0.2;
    p.grainWall.tangentialToNormalStiffness = -0.1;
    EXPECT_NE(refusal([&] { dem::System s(p); }).find("tangentialToNormalStiffness"),
              std::string::npos);
    p.grainWall.tangentialToNormalStiffness = 0.6;
    EXPECT_EQ(refusal([&] { dem::System s(p); }), "");
}

DEM_TEST_ON_ALL_BACKENDS(CapsuleSetup);

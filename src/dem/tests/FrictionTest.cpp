// FrictionTest.cpp
// Tangential contact law against rigid-body references (doc/REFERENCES.md section 2):
//  - oblique sphere-wall impact in gross sliding: tangential restitution
//    e_t = 1 - mu (1 + e) / tan(theta) and rebound spin w' = 5 mu (1 + e) V cos(theta) / (2 R);
//  - a grain that cannot rotate on a plane inclined at theta (gravity tilted instead of the
//    wall): at rest below atan(mu), sliding with a = g (sin(theta) - mu cos(theta)) above.
#include "TestSupport.h"

using namespace demTest;

namespace
{

class Friction : public BackendTest
{
protected:
    const double r = 0.01, mu = 0.5, g0 = 9.81;
    double mass() const { return 2600.0 * sphereVolume(r); }

    //- Grain-wall friction mu, damping ratio 0.3, gravity tilted by theta (the plane's slope).
    dem::Parameters inclineParameters(double theta) const
    {
        dem::Parameters p = parameters();
        p.grainWall.friction = mu;
        p.grainWall.normalDamping = 2.0 * 0.3 * std::sqrt(p.grainWall.normalStiffness * mass());
        p.grainWall.tangentialDamping = p.grainWall.normalDamping;
        p.gravity = {g0 * std::sin(theta), 0.0, -g0 * std::cos(theta)};
        p.timeStep = 0.05 * std::sqrt(mass() / p.grainWall.normalStiffness);
        return p;
    }

    //- A grain that cannot rotate, at x = y = 0.5 and its static overlap (so the normal
    //- spring does not ring).
    dem::GrainInit block(const dem::Parameters& p, double theta) const
    {
        dem::GrainInit b;
        b.radius = r;
        b.flag = dem::GrainFlag::translationOnly;
        b.position = {0.5, 0.5, r - mass() * g0 * std::cos(theta) / p.grainWall.normalStiffness};
        return b;
    }
};

} // namespace

TEST_P(Friction, ObliqueImpactInGrossSliding)
{
    for (const double thetaDegrees : {45.0, 60.0})
    {
        dem::Parameters p = parameters();
        p.grainWall.friction = 0.1;
        p.timeStep = M_PI * std::sqrt(mass() / p.grainWall.normalStiffness) / 2000.0;
        dem::System s(p);
        const double theta = thetaDegrees * M_PI / 180.0, speed = 0.2;
        dem::GrainInit g;
        g.radius = r;
        g.position = {0.5, 0.5, r + 1e-6};
        g.velocity = {speed * std::sin(theta), 0.0, -speed * std::cos(theta)};
        s.addGrain(g);
        s.addWall(dem::WallSpec());
        while (s.grains().position[2] <= r + 2e-6) // through the contact and off the wall
            s.step(50);
        const dem::GrainData out = s.grains();
        const double e = 1.0, mu = p.grainWall.friction;
        const double tangentialRestitution = out.velocity[0] / g.velocity[0];
        const double expectedEt = 1.0 - mu * (1.0 + e) / std::tan(theta);
        const double expectedSpin = 5.0 * mu * (1.0 + e) * speed * std::cos(theta) / (2.0 * r);
        std::printf("  theta %.0f: e_t %.6f (ref %.6f), spin %.6f (ref %.6f) rad/s, e_n %.6f\n",
                    thetaDegrees, tangentialRestitution, expectedEt, out.angularVelocity[1],
                    expectedSpin, -out.velocity[2] / g.velocity[2]);
        EXPECT_NEAR(tangentialRestitution / expectedEt, 1.0, 0.005);
        EXPECT_NEAR(out.angularVelocity[1] / expectedSpin, 1.0, 0.005);
        EXPECT_NEAR(out.velocity[2] / -g.velocity[2], 1.0, 0.005);
    }
}

TEST_P(Friction, BlockOnInclinedPlane)
{
    for (const double thetaDegrees : {20.0, 35.0})
    {
        const double theta = thetaDegrees * M_PI / 180.0;
        const dem::Parameters p = inclineParameters(theta);
        dem::System s(p);
        s.addGrain(block(p, theta));
        s.addWall(dem::WallSpec());
        const double t1 = 0.05, t2 = 0.15;
        s.step(int(t1 / p.timeStep));
        const dem::GrainData a = s.grains();
        s.step(int((t2 - t1) / p.timeStep));
        const dem::GrainData b = s.grains();
        const double measured =
            (b.velocity[0] - a.velocity[0]) / (int((t2 - t1) / p.timeStep) * p.timeStep);
        EXPECT_DOUBLE_EQ(b.angularVelocity[1], 0.0);
        if (std::tan(theta) < mu)
        {
            std::printf("  theta %.0f (< atan mu): vx %.3e m/s, creep %.3e m\n", thetaDegrees,
                        b.velocity[0], b.position[0] - a.position[0]);
            EXPECT_LT(std::fabs(b.velocity[0]), 1e-6);
            EXPECT_LT(std::fabs(b.position[0] - a.position[0]), 1e-7);
        }
        else
        {
            const double expected = g0 * (std::sin(theta) - mu * std::cos(theta));
            std::printf("  theta %.0f (> atan mu): a %.6f m/s^2 (ref %.6f)\n", thetaDegrees,
                        measured, expected);
            EXPECT_NEAR(measured / expected, 1.0, 0.005);
        }
    }
}

//- A block held by static friction on a 20 degree incline; a grain added later sorts before
//- it, so the next rebuild moves the block's wall contact state to another storage slot. Its
//- tangential wall spring holds m g sin(theta) / k_t = 3.7e-8 m of stretch: lost or mixed up
//- in the re-sort, the block would slip by about that much.
TEST_P(Friction, WallHistorySurvivesResorting)
{
    const double theta = 20.0 * M_PI / 180.0;
    const dem::Parameters p = inclineParameters(theta);
    dem::System s(p);
    s.addGrain(block(p, theta));
    s.addWall(dem::WallSpec());
    s.step(int(0.05 / p.timeStep));
    const dem::GrainData a = s.grains();
    dem::GrainInit early = block(p, theta); // lower x and y: an earlier cell than the block's
    early.position[0] = early.position[1] = 0.1;
    s.addGrain(early);
    s.step(int(0.05 / p.timeStep));
    const dem::GrainData b = s.grains();
    const double stretch = mass() * g0 * std::sin(theta) / p.grainWall.tangentialStiffness;
    const double slip = std::fabs(b.position[0] - a.position[0]);
    std::printf("  block slip after re-sorting %.3e m (spring stretch %.3e m)\n", slip, stretch);
    EXPECT_LT(slip, 0.01 * stretch);
    EXPECT_LT(std::fabs(b.velocity[0]), 1e-6);
}

DEM_TEST_ON_ALL_BACKENDS(Friction);

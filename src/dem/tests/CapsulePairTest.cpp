// CapsulePairTest.cpp
// Two capsules in an oblique, off-centre, frictional collision: the contact's torques on both
// grains come from one contact point with equal and opposite forces, so the total angular
// momentum (orbital x m v plus each grain's spin R I R^T omega) and the total momentum are
// conserved while the collision turns and spins both grains.
#include "CapsuleTestSupport.h"

using namespace demTest;

namespace
{

class CapsulePair : public BackendTest
{
};

//- Total angular momentum about the origin and total momentum.
void totals(const dem::GrainData& g, Eigen::Vector3d& angular, Eigen::Vector3d& linear,
            Eigen::Vector3d& spinOfFirst)
{
    angular.setZero();
    linear.setZero();
    for (std::size_t i = 0; i < g.mass.size(); ++i)
    {
        const CapsuleBody body =
            capsuleBody(g.radius[i], g.coreHalfLength[i], g.mass[i] / g.volume[i]);
        const Eigen::Vector3d inertia(body.inertiaPerpendicular, body.inertiaPerpendicular,
                                      body.inertiaAxial);
        const Eigen::Matrix3d R = orientationOf(g, i).toRotationMatrix();
        const Eigen::Vector3d spin =
            R * inertia.asDiagonal() * R.transpose() * vectorOf(g.angularVelocity, i);
        const Eigen::Vector3d momentum = g.mass[i] * vectorOf(g.velocity, i);
        angular += vectorOf(g.position, i).cross(momentum) + spin;
        linear += momentum;
        if (i == 0)
            spinOfFirst = spin;
    }
}

} // namespace

TEST_P(CapsulePair, ObliqueCollisionConservesMomentumAndAngularMomentum)
{
    dem::Parameters p = parameters(); // k_n = k_t = 1e6 N/m, mu = 0.5, no gravity
    p.grainGrain.normalDamping = 2.0;
    p.boxLower = {-1.0, -1.0};
    p.boxUpper = {1.0, 1.0};
    p.timeStep = 1e-5;
    dem::System s(p);
    dem::GrainInit a, b;
    a.radius = b.radius = 0.01;
    a.coreHalfLength = 0.03;
    b.coreHalfLength = 0.02;
    a.orientation = rotation(Eigen::Vector3d(1, 1, 0).normalized(), 1.1);
    b.orientation = rotation(Eigen::Vector3d(0, 1, 2).normalized(), 0.7);
    a.position = {0.0, 0.0, 0.0};
    b.position = {0.08, 0.015, 0.01}; // off the line of the approach: a glancing hit
    a.velocity = {0.5, 0.0, 0.0};
    b.velocity = {-0.3, 0.05, 0.0};
    a.angularVelocity = {0.0, 0.0, 3.0};
    s.addGrains({a, b});
    ASSERT_EQ(s.largestOverlap().first, -1); // apart at the start
    Eigen::Vector3d angular0, linear0, spin0;
    totals(s.grains(), angular0, linear0, spin0);
    double largestExchange = 0.0, angularError = 0.0, linearError = 0.0;
    for (int chunk = 0; chunk < 40; ++chunk) // 0.1 s: approach, contact, separation
    {
        s.step(250);
        Eigen::Vector3d angular, linear, spin;
        totals(s.grains(), angular, linear, spin);
        largestExchange = std::max(largestExchange, (spin - spin0).norm());
        angularError = std::max(angularError, (angular - angular0).norm());
        linearError = std::max(linearError, (linear - linear0).norm());
    }
    std::printf("  spin exchanged %.3e N m s; |L - L0| %.3e N m s; |P - P0| %.3e N s of %.3e\n",
                largestExchange, angularError, linearError, linear0.norm());
    // The collision happened: it changed the first grain's spin (3 rad/s about z at the start,
    // I_perp ~5e-6 kg m^2: ~1.6e-5 N m s) by a good part.
    const Eigen::Vector3d v = vectorOf(s.grains().velocity, 0);
    std::printf("  first grain's velocity after (%.4f %.4f %.4f) m/s\n", v.x(), v.y(), v.z());
    EXPECT_GT(largestExchange, 1e-6);
    EXPECT_GT((v - Eigen::Vector3d(0.5, 0.0, 0.0)).norm(), 0.1);
    // Exact in the scheme up to round-off (a few ulp of each term per step, 10^4 steps).
    EXPECT_LT(angularError, 1e-10 * largestExchange);
    EXPECT_LT(linearError, 1e-12 * linear0.norm());
}

DEM_TEST_ON_ALL_BACKENDS(CapsulePair);

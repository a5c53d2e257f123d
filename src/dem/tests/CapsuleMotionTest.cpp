// CapsuleMotionTest.cpp
// Capsule kinematics through dem::System: torque-free precession of a symmetric capsule
// against the closed form (angular momentum conserved, error falling as dt^2), and a capsule
// lying along the slope of a plane inclined at theta (gravity tilted instead of the wall):
// held by friction below atan(mu), sliding with a = g (sin(theta) - mu cos(theta)) above.
#include "CapsuleTestSupport.h"

using namespace demTest;

namespace
{

class CapsuleMotion : public BackendTest
{
protected:
    const double r = 0.01, h = 0.02, rho = 2600.0;
    const CapsuleBody body = capsuleBody(r, h, rho);
};

} // namespace

TEST_P(CapsuleMotion, TorqueFreePrecession)
{
    // One capsule alone, no gravity. Its axis starts 0.4 rad from z (turned about y); omega0
    // gives L = R I R^T omega0. Exact motion of the symmetric top:
    //   R(t) = Rot(L/|L|, |L|/I_perp t) R_0 Rot(e_z, psi' t),  psi' = Lb_z (1/I_axial - 1/I_perp)
    // (the axis precesses about L at |L|/I_perp; in the body frame omega turns about the axis
    // at (I_axial - I_perp)/I_perp omega_axial).
    const Eigen::Vector3d inertia(body.inertiaPerpendicular, body.inertiaPerpendicular,
                                  body.inertiaAxial);
    const Eigen::Quaterniond q0(Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitY()));
    const Eigen::Vector3d omega0(30.0, -20.0, 150.0);
    const Eigen::Matrix3d R0 = q0.toRotationMatrix();
    const Eigen::Vector3d L = R0 * inertia.asDiagonal() * R0.transpose() * omega0;
    const double precession = L.norm() / inertia.x();
    const double spin = (R0.transpose() * L).z() * (1 / inertia.z() - 1 / inertia.x());
    const double T = 2 * 2 * M_PI / precession; // two precession periods
    std::printf("  |L|/I_perp %.6f rad/s, body-frame rate %.6f rad/s, T %.6f s\n", precession, spin,
                T);
    const Eigen::Quaterniond exact =
        Eigen::Quaterniond(Eigen::AngleAxisd(precession * T, L.normalized())) * q0 *
        Eigen::Quaterniond(Eigen::AngleAxisd(spin * T, Eigen::Vector3d::UnitZ()));
    double previous = 0;
    for (int level = 0; level < 2; ++level)
    {
        dem::Parameters p = parameters();
        // |omega| dt = 5.4e-3, then half (below the critical-step limit 0.2 sqrt(m/k)).
        const int steps = 8000 << level;
        p.timeStep = T / steps;
        // Free flight, no contact: the step guard's rotational term (I / (r + h)^2, for
        // contacts at a tip) would refuse the coarser step; it is not what this test measures.
        p.maxTimeStepFraction = 0.5;
        dem::System s(p);
        dem::GrainInit g;
        g.radius = r;
        g.coreHalfLength = h;
        g.orientation = {q0.w(), q0.x(), q0.y(), q0.z()};
        g.position = {0.5, 0.5, 0.5};
        g.angularVelocity = {omega0.x(), omega0.y(), omega0.z()};
        s.addGrain(g);
        double momentumError = 0;
        for (int chunk = 0; chunk < 8; ++chunk)
        {
            s.step(steps / 8);
            const dem::GrainData d = s.grains();
            const Eigen::Matrix3d R = orientationOf(d, 0).toRotationMatrix();
            const Eigen::Vector3d Lt =
                R * inertia.asDiagonal() * R.transpose() * vectorOf(d.angularVelocity, 0);
            momentumError = std::max(momentumError, (Lt - L).norm() / L.norm());
        }
        const dem::GrainData d = s.grains();
        const double error = orientationOf(d, 0).angularDistance(exact);
        const double omegaDt = omega0.norm() * p.timeStep;
        std::printf("  |omega| dt %.4f: orientation error after 2 periods %.3e rad, largest "
                    "|L - L0|/|L0| %.3e\n",
                    omegaDt, error, momentumError);
        // L changes only by torques; torque-free it is kept to round-off of reading omega back
        // (R I R^T omega: a few ulp per step of the chunk, not accumulating).
        EXPECT_LT(momentumError, 1e-12);
        // A second-order rotation: error ~ (|omega| dt)^2 per radian turned (the kernel test
        // measures 0.3 of that bound), and a quarter of it at dt/2 (3.5 to 4.5: the next
        // term is O(dt^4)).
        EXPECT_LT(error, omegaDt * omegaDt * omega0.norm() * T);
        if (level > 0)
        {
            std::printf("    error ratio dt / (dt/2): %.3f (second order: 4)\n", previous / error);
            EXPECT_GT(previous / error, 3.5);
            EXPECT_LT(previous / error, 4.5);
        }
        previous = error;
    }
}

TEST_P(CapsuleMotion, RestsBelowAndSlidesAboveTheFrictionAngle)
{
    // Axis along the slope (x), so it cannot roll; both ends on the wall. Grain-wall friction
    // mu = 0.5 (atan mu = 26.6 degrees), damping ratio 0.3 of each end's spring with half the
    // mass, gravity g (sin theta, 0, -cos theta).
    const double mu = 0.5, g0 = 9.81;
    for (const double thetaDegrees : {20.0, 35.0})
    {
        const double theta = thetaDegrees * M_PI / 180.0;
        dem::Parameters p = parameters();
        const double k = p.grainWall.normalStiffness;
        p.grainWall.friction = mu;
        p.grainWall.normalDamping = 2.0 * 0.3 * std::sqrt(k * 0.5 * body.mass);
        p.grainWall.tangentialDamping = p.grainWall.normalDamping;
        p.gravity = {g0 * std::sin(theta), 0.0, -g0 * std::cos(theta)};
        p.timeStep = 0.05 * std::sqrt(0.5 * body.mass / k);
        dem::System s(p);
        dem::GrainInit g;
        g.radius = r;
        g.coreHalfLength = h;
        g.orientation = rotation(Eigen::Vector3d::UnitY(), M_PI / 2);
        // At the static overlap of each end, m g cos(theta) / (2k): the springs do not ring.
        g.position = {0.5, 0.5, r - body.mass * g0 * std::cos(theta) / (2 * k)};
        s.addGrain(g);
        s.addWall(dem::WallSpec());
        const double t1 = 0.05, t2 = 0.15;
        s.step(int(t1 / p.timeStep));
        const dem::GrainData a = s.grains();
        const int n = int((t2 - t1) / p.timeStep);
        s.step(n);
        const dem::GrainData b = s.grains();
        const double measured = (b.velocity[0] - a.velocity[0]) / (n * p.timeStep);
        if (std::tan(theta) < mu)
        {
            // Held by the tangential springs (stretch m g sin(theta) / (2 k_t) = 7e-8 m per
            // end): after the damped transient it neither moves nor creeps (thresholds as for
            // the sphere block, FrictionTest), nor turns.
            std::printf("  theta %.0f (< atan mu): vx %.3e m/s, creep %.3e m, |omega| %.3e\n",
                        thetaDegrees, b.velocity[0], b.position[0] - a.position[0],
                        norm(at(b.angularVelocity, 0)));
            EXPECT_LT(std::fabs(b.velocity[0]), 1e-6);
            EXPECT_LT(std::fabs(b.position[0] - a.position[0]), 1e-7);
            EXPECT_LT(norm(at(b.angularVelocity, 0)), 1e-4);
        }
        else
        {
            // Both ends in gross slip: total friction mu times the total normal force
            // m g cos(theta), however it is shared between the ends. 0.5 % as for the block
            // (the normal springs' transient is damped out by t1).
            const double expected = g0 * (std::sin(theta) - mu * std::cos(theta));
            std::printf("  theta %.0f (> atan mu): a %.6f m/s^2 (closed form %.6f), "
                        "|omega| %.3e rad/s\n",
                        thetaDegrees, measured, expected, norm(at(b.angularVelocity, 0)));
            EXPECT_NEAR(measured / expected, 1.0, 0.005);
            EXPECT_LT(norm(at(b.angularVelocity, 0)), 1e-3);
        }
    }
}

DEM_TEST_ON_ALL_BACKENDS(CapsuleMotion);

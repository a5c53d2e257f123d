// BondPatchTest.cpp
// Where a bond sits with BondPoint::bodyFixedPatches, through dem::System on both backends
// (kernels/bonds/BondGeometry.h): the bond's patch centre is held in each grain's body frame,
// its point is the midpoint of the two copies, and creep moves the copies towards each other
// (Johnson & Hopkins 2005); the normal runs between the cores at that point. Closed forms:
// two nearly parallel capsules turned through parallel keep their bond where it froze (the
// cores' closest points jumped by half the shared stretch at any tilt); under shear creep the
// copies end the elastic displacement apart, each moved by half the creep; a bonded sphere's
// patch turns with it; a state written before the patches is placed at import.
#include "CapsuleTestSupport.h"

#include <algorithm>

using namespace demTest;
using Eigen::AngleAxisd;
using Eigen::Quaterniond;
using Eigen::Vector3d;

namespace
{

class BondPatches : public BackendTest
{
};

constexpr double R = 1e-3, E = 1e7, rb = 0.3e-3, rhoIce = 917.0;
const double kne = E / (2.0 * R), kse = 0.6 * kne;
const double area = M_PI * rb * rb, bendI = M_PI * std::pow(rb, 4) / 4.0;

dem::Parameters patchParameters(dem::Parameters p)
{
    p = iceBondPairParameters(p, E);
    p.bonds.point = dem::BondPoint::bodyFixedPatches;
    return p;
}

dem::GrainInit capsule(double h, const Vector3d& x, const std::array<double, 4>& q,
                       dem::GrainFlag flag)
{
    dem::GrainInit g;
    g.radius = R;
    g.coreHalfLength = h;
    g.density = rhoIce;
    g.position = {x.x(), x.y(), x.z()};
    g.orientation = q;
    g.flag = flag;
    return g;
}

//- The bond's patch copies in the global frame (c_A, c_B), from the exported state (body
//- frames) and the grains' poses.
struct GlobalPatches
{
    Vector3d centreA, centreB;
};

GlobalPatches globalPatches(const dem::System& s)
{
    const dem::SystemState state = s.exportState();
    const dem::GrainData g = s.grains();
    const auto body = [&](const char* name)
    {
        const std::vector<double>& v = state.reals.at(std::string("bonds.") + name);
        return Vector3d(v.at(0), v.at(1), v.at(2));
    };
    const Quaterniond qA = orientationOf(g, 0), qB = orientationOf(g, 1);
    return {vectorOf(g.position, 0) + qA * body("patchPointA"),
            vectorOf(g.position, 1) + qB * body("patchPointB")};
}

} // namespace

TEST_P(BondPatches, NearlyParallelCapsulesKeepTheirBondWhereItFroze)
{
    // Two capsules (R = 1 mm, core half-length 2 mm) side by side along x, B 1 mm further in x
    // and 1 um into A (shared stretch of A's core x in [-1, 2] mm), B tilted about y by -theta0
    // and turned by 2 theta0 through parallel in 400 steps about its centre. A is fixed, so the
    // bond's patch on A stays where the bond froze (X0, placed at the middle of the touching
    // stretch) and B's turns with B: point (X0 + x_B + R_y(dphi)(X0 - x_B)) / 2, normal from
    // A's core to B's at that point, bending moment k_ne I dphi. Round-off only (1e-12 R,
    // 1e-12, 1e-9); the closest points would sit at an end of the shared stretch, 1.5 mm
    // away, at any tilt.
    for (const double theta0 : {1e-9, 1e-6})
    {
        dem::System s(patchParameters(parameters()));
        const double h = 2e-3, steps = 400;
        const Vector3d xB(1e-3, 0.0, 2 * R - 1e-6);
        const double omega = 2 * theta0 / (steps * 1e-6);
        s.addGrains({capsule(h, Vector3d::Zero(), rotation(Vector3d::UnitY(), M_PI / 2),
                             dem::GrainFlag::fixed),
                     capsule(h, xB, rotation(Vector3d::UnitY(), M_PI / 2 - theta0),
                             dem::GrainFlag::driven)});
        s.setGrainVelocities({1}, {0.0, 0.0, 0.0}, {0.0, omega, 0.0});
        s.addBonds({dem::BondInit{0, 1, rb}});
        const dem::BondData placed = s.bonds();
        const Vector3d X0 = vectorOf(placed.point, 0), n0 = vectorOf(placed.normal, 0);
        std::printf("  tilt %.0e rad: placed at x %.9e m (shared stretch's middle 5e-4), "
                    "normal (%.3e %.3e %.12f)\n",
                    theta0, X0.x(), n0.x(), n0.y(), n0.z());
        EXPECT_NEAR(X0.x(), 0.5e-3, 1e-3 * R);
        EXPECT_NEAR(X0.z(), R - 0.5e-6, 1e-3 * R);
        double worstPoint = 0, worstNormal = 0, worstMoment = 0, torqueStep = 0;
        Vector3d lastTorque = Vector3d::Zero();
        for (int k = 1; k <= steps; ++k)
        {
            s.step(1);
            const dem::BondData b = s.bonds();
            const double dphi = omega * k * 1e-6;
            const Vector3d turnedB = AngleAxisd(dphi, Vector3d::UnitY()) * (X0 - xB);
            const Vector3d point = 0.5 * (X0 + xB + turnedB);
            const dem::GrainData g = s.grains();
            const auto corePoint = [&](std::size_t i)
            {
                const Vector3d x = vectorOf(g.position, i), a = halfAxisOf(g, i);
                const double u = std::clamp((point - x).dot(a) / a.squaredNorm(), -1.0, 1.0);
                return Vector3d(x + u * a);
            };
            const Vector3d normal = (corePoint(1) - corePoint(0)).normalized();
            worstPoint = std::max(worstPoint, (vectorOf(b.point, 0) - point).norm());
            worstNormal = std::max(worstNormal, (vectorOf(b.normal, 0) - normal).norm());
            const double moment = kne * bendI * dphi;
            worstMoment = std::max(worstMoment, std::fabs(b.bendMoment[1] - moment) / moment);
            const Vector3d torque = vectorOf(g.torque, 0);
            if (k > 1)
                torqueStep = std::max(torqueStep, (torque - lastTorque).norm());
            lastTorque = torque;
        }
        std::printf("  worst: point %.3e m, normal %.3e, bending moment %.3e relative; largest "
                    "step of A's torque %.3e N m\n",
                    worstPoint, worstNormal, worstMoment, torqueStep);
        EXPECT_LT(worstPoint, 1e-12 * R);
        EXPECT_LT(worstNormal, 1e-12);
        EXPECT_LT(worstMoment, 1e-9);
    }
}

TEST_P(BondPatches, ShearCreepBringsThePatchesIntoAlignment)
{
    // Capsules end to end along x (A fixed, B driven sideways at v = 1 mm/s), shear creep alone
    // (nu_s = 100 Pa s, tau = nu_s / (0.6 E) = 1.67e-5 s) for 200 steps (12 tau). The copies
    // start together at X0; B's moves with B by u = v t; creep moves each by half of what
    // crept towards the other. So c_B - c_A is the elastic displacement S / (k_se A) and c_A
    // moved by (u - S / (k_se A)) / 2, the creep, v (t - tau (1 - e^{-t/tau})) in closed form.
    // Both to first order in the slide: the normal (between the cores at the point) tilts by
    // up to u / 2R, so the in-plane steps are summed in planes that turn (within u^2 / R); the
    // creep's closed form as the bond law's (1e-6).
    dem::Parameters p = patchParameters(parameters());
    p.bonds.creep = dem::BondCreep::maxwell;
    p.bonds.contactViscosity = 100.0;
    p.bonds.twistCreep = p.bonds.bendCreep = false;
    dem::System s(p);
    const double h = 1e-3, v = 1e-3, tau = 100.0 / (0.6 * E);
    const std::array<double, 4> alongX = rotation(Vector3d::UnitY(), M_PI / 2);
    s.addGrains({capsule(h, Vector3d::Zero(), alongX, dem::GrainFlag::fixed),
                 capsule(h, Vector3d(2 * h + 2 * R - 1e-6, 0, 0), alongX, dem::GrainFlag::driven)});
    s.setGrainVelocities({1}, {0.0, v, 0.0}, {0.0, 0.0, 0.0});
    s.addBonds({dem::BondInit{0, 1, rb}});
    const Vector3d X0 = vectorOf(s.bonds().point, 0);
    s.step(200);
    const double t = 200 * 1e-6;
    const dem::BondData b = s.bonds();
    const GlobalPatches c = globalPatches(s);
    const Vector3d u(0.0, v * t, 0.0);
    const Vector3d elastic = vectorOf(b.shearForce, 0) / (kse * area) +
                             b.normalForce[0] / (kne * area) * vectorOf(b.normal, 0);
    const double creep = v * (t + tau * std::expm1(-t / tau));
    std::printf("  c_B - c_A (%.6e %.6e %.6e), elastic (%.6e %.6e %.6e); c_A moved %.9e m, "
                "half the creep %.9e m\n",
                (c.centreB - c.centreA).x(), (c.centreB - c.centreA).y(),
                (c.centreB - c.centreA).z(), elastic.x(), elastic.y(), elastic.z(),
                (c.centreA - X0).y(), 0.5 * creep);
    const double turning = u.squaredNorm() / R;
    EXPECT_LT((c.centreB - c.centreA - elastic).norm(), turning);
    EXPECT_LT((c.centreA - X0 - 0.5 * (u - elastic)).norm(), turning);
    EXPECT_NEAR((c.centreA - X0).y(), 0.5 * creep, 1e-6 * creep);
    // The bond's point is the copies' midpoint, X0 + u / 2 whatever crept.
    EXPECT_LT((vectorOf(b.point, 0) - (X0 + 0.5 * u)).norm(), 1e-12 * R);
}

TEST_P(BondPatches, BondedSpheresTurnTheirPatches)
{
    // Two spheres (R = 1 mm) touching along x, A fixed, B driven to spin about z at 10 rad/s
    // for 1000 steps (0.01 rad): in a system with bonds a sphere's orientation is integrated,
    // so B's patch turns with B about its centre, and the bond's point is the midpoint of X0
    // and x_B + R_z(w t)(X0 - x_B); its normal stays the line of centres x (round-off: 1e-12).
    dem::System s(patchParameters(parameters()));
    dem::GrainInit a, b;
    a.radius = b.radius = R;
    a.density = b.density = rhoIce;
    const Vector3d xB(2 * R - 1e-6, 0, 0);
    b.position = {xB.x(), xB.y(), xB.z()};
    a.flag = dem::GrainFlag::fixed;
    b.flag = dem::GrainFlag::driven;
    s.addGrains({a, b});
    const double w = 10.0, t = 1000 * 1e-6;
    s.setGrainVelocities({1}, {0.0, 0.0, 0.0}, {0.0, 0.0, w});
    s.addBonds({dem::BondInit{0, 1, rb}});
    const Vector3d X0 = vectorOf(s.bonds().point, 0);
    EXPECT_NEAR((X0 - Vector3d(R - 0.5e-6, 0, 0)).norm(), 0.0, 1e-12 * R); // the overlap's middle
    s.step(1000);
    const dem::BondData bond = s.bonds();
    const Vector3d point = 0.5 * (X0 + xB + AngleAxisd(w * t, Vector3d::UnitZ()) * (X0 - xB));
    const Vector3d normal = Vector3d::UnitX();
    std::printf("  point (%.12e %.12e) m, closed form (%.12e %.12e) m\n", bond.point[0],
                bond.point[1], point.x(), point.y());
    EXPECT_LT((vectorOf(bond.point, 0) - point).norm(), 1e-12 * R);
    EXPECT_LT((vectorOf(bond.normal, 0) - normal).norm(), 1e-12);
}

TEST_P(BondPatches, StateWithoutPatchesIsPlacedAtImport)
{
    // A bond state written before the patches (the patch entries absent) is placed when it is
    // imported, where the grains' contact is then (the middle of the overlap on the line of
    // centres, 1e-12 R), and carries on. The pair: spheres touching along x, B sliding along y
    // at v = 1 mm/s and spinning about x at w = 10 rad/s, exported after 500 steps (t0) and
    // continued for 500 with its patches and from the stripped state. The kept copies are
    // u = v t0 apart (nothing creeps), B's on B's spin axis; the placed ones coincide at their
    // midpoint, B's u/2 off the axis, so the spin moves the point by up to w u/2 per second
    // against the slide's v: the shear within w t0 / 2 of the kept run's.
    dem::Parameters p = patchParameters(parameters());
    const double v = 1e-3, w = 10.0;
    const auto pair = [&](dem::System& s)
    {
        dem::GrainInit a, b;
        a.radius = b.radius = R;
        a.density = b.density = rhoIce;
        b.position = {2 * R - 1e-6, 0, 0};
        a.flag = dem::GrainFlag::fixed;
        b.flag = dem::GrainFlag::driven;
        s.addGrains({a, b});
        s.setGrainVelocities({1}, {0.0, v, 0.0}, {w, 0.0, 0.0});
        s.addBonds({dem::BondInit{0, 1, rb}});
    };
    dem::System whole(p);
    pair(whole);
    whole.step(500);
    const dem::BondData kept = whole.bonds();
    dem::SystemState state = whole.exportState();
    for (const char* name : {"patchPointA", "patchPointB"})
        ASSERT_EQ(state.reals.erase(std::string("bonds.") + name), 1u);
    dem::System restarted(p);
    restarted.importState(state);
    const dem::BondData placed = restarted.bonds();
    const dem::GrainData g = restarted.grains();
    const Vector3d d = vectorOf(g.position, 1) - vectorOf(g.position, 0);
    const double overlap = 2 * R - d.norm();
    const Vector3d expected = vectorOf(g.position, 0) + (R - 0.5 * overlap) * d.normalized();
    EXPECT_LT((vectorOf(placed.point, 0) - expected).norm(), 1e-12 * R);
    const double dp = (vectorOf(placed.point, 0) - vectorOf(kept.point, 0)).norm();
    EXPECT_LT(dp, 1e-12 * R); // the same midpoint
    whole.step(500);
    restarted.step(500);
    const dem::BondData a = whole.bonds(), b = restarted.bonds();
    const double shear = (vectorOf(a.shearForce, 0) - vectorOf(b.shearForce, 0)).norm() /
                         vectorOf(a.shearForce, 0).norm();
    const double bound = 0.5 * w * 500e-6;
    std::printf("  placed %.3e m from the kept point; shear %.3e apart (bound %.3e)\n", dp, shear,
                bound);
    EXPECT_LT(shear, bound);
    EXPECT_EQ(b.first.size(), 1u);
}

DEM_TEST_ON_ALL_BACKENDS(BondPatches);

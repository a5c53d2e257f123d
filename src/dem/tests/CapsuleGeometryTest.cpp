// CapsuleGeometryTest.cpp
// Closest points of two core segments against closed forms (crossing, skew, clamped at an end,
// parallel, end-to-end, a sphere against a capsule) to 1e-12, and against an independent
// minimisation for random pairs; the pair geometry of spheres equals the sphere pair kernel's
// arithmetic bit for bit; capsule-capsule and capsule-plane contact points. Host-side: the
// evaluators are the same header for both backends.
#include "kernels/CapsuleGeometry.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>

using dem::detail::capsulePairGeometry;
using dem::detail::capsulePlaneGeometry;
using dem::detail::closestSegmentParameters;
using dem::detail::Vector3d;

namespace
{

// Closed forms below are exact in real arithmetic; 1e-12 leaves round-off of a few operations
// on O(1) numbers (1e-16 each) a wide margin while catching any wrong case.
constexpr double kTolerance = 1e-12;

void expectParameters(const Vector3d& ai, const Vector3d& aj, const Vector3d& d, double ui,
                      double uj, const char* what)
{
    double si = 2, sj = 2;
    closestSegmentParameters(ai, aj, d, si, sj);
    std::printf("  %s: ui %.15f (exact %.15f), uj %.15f (exact %.15f)\n", what, si, ui, sj, uj);
    EXPECT_NEAR(si, ui, kTolerance) << what;
    EXPECT_NEAR(sj, uj, kTolerance) << what;
}

double segmentDistance(const Vector3d& ai, const Vector3d& aj, const Vector3d& d, double ui,
                       double uj)
{
    return (d + uj * aj - ui * ai).norm();
}

//- Independent minimum distance: for fixed ui the best uj is the clamped projection (exact);
//- the remaining function of ui is convex, minimised by golden-section search to 1e-15.
double bruteForceDistance(const Vector3d& ai, const Vector3d& aj, const Vector3d& d)
{
    auto best = [&](double ui)
    {
        const Vector3d p = ui * ai - d; // i's point relative to x_j
        double uj = aj.squaredNorm() > 0 ? aj.dot(p) / aj.squaredNorm() : 0.0;
        uj = std::min(1.0, std::max(-1.0, uj));
        return (p - uj * aj).norm();
    };
    double lo = -1, hi = 1;
    const double g = (std::sqrt(5.0) - 1) / 2;
    while (hi - lo > 1e-15)
    {
        const double a = hi - g * (hi - lo), b = lo + g * (hi - lo);
        if (best(a) < best(b))
            hi = b;
        else
            lo = a;
    }
    return std::min({best(lo), best(-1.0), best(1.0)});
}

} // namespace

TEST(CapsuleGeometry, CrossingCores)
{
    // i along x, j along y, j's centre above (0.3, -0.25): closest points straight above each
    // other at x = 0.3 and y = 0, 0.5 apart.
    expectParameters(Vector3d(1, 0, 0), Vector3d(0, 0.8, 0), Vector3d(0.3, -0.25, 0.5), 0.3, 0.3125,
                     "crossing");
    // Cores that intersect (distance 0).
    expectParameters(Vector3d(2, 0, 0), Vector3d(0, 0, 1), Vector3d(1, 0, -0.5), 0.5, 0.5,
                     "intersecting");
}

TEST(CapsuleGeometry, SkewCoresInteriorAndClamped)
{
    // Built from the answer: closest points ui*, uj* inside both segments joined by the common
    // perpendicular w (ai x aj) of length D, so that d = ui* ai - uj* aj + D w.
    std::mt19937 random(7);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    for (int c = 0; c < 20; ++c)
    {
        const Vector3d ai(uniform(random), uniform(random), uniform(random));
        const Vector3d aj(uniform(random), uniform(random), uniform(random));
        const double ui = 0.9 * uniform(random), uj = 0.9 * uniform(random);
        const Vector3d w = ai.cross(aj).normalized();
        const Vector3d d = ui * ai - uj * aj + 0.3 * w;
        double si, sj;
        closestSegmentParameters(ai, aj, d, si, sj);
        EXPECT_NEAR(si, ui, kTolerance);
        EXPECT_NEAR(sj, uj, kTolerance);
        if (c == 0)
            std::printf("  skew: ui %.15f (exact %.15f), uj %.15f (exact %.15f)\n", si, ui, sj, uj);
    }
    // i's end (u = 1) against j's side: from i's end P the closest point of j is P + D w with
    // w perpendicular to aj and leaning beyond i's end (w . ai > 0), so the constrained
    // minimum is ui = 1 and the perpendicular foot on j, uj = 0.4.
    const Vector3d ai(1, 0, 0), aj(0, 0.7, 0), w = Vector3d(1, 0, 1).normalized();
    expectParameters(ai, aj, ai + 0.2 * w - 0.4 * aj, 1.0, 0.4, "end against side");
}

TEST(CapsuleGeometry, ParallelCores)
{
    // Side by side, j shifted along the axis: j covers z in [0.3, 1.3], i [-1, 1]; the
    // contact sits in the middle of the shared stretch [0.3, 1], z = 0.65.
    expectParameters(Vector3d(0, 0, 1), Vector3d(0, 0, 0.5), Vector3d(0.3, 0, 0.8), 0.65, -0.3,
                     "parallel");
    expectParameters(Vector3d(0, 0, 1), Vector3d(0, 0, -0.5), Vector3d(0.3, 0, 0.8), 0.65, 0.3,
                     "antiparallel");
    // Aligned and equal: the centres.
    expectParameters(Vector3d(0.6, 0.8, 0), Vector3d(0.6, 0.8, 0), Vector3d(0, 0, 1), 0.0, 0.0,
                     "parallel aligned");
    // Parallel without a shared stretch: nearest ends (i's top at z = 1, j's bottom at 2.5).
    expectParameters(Vector3d(0, 0, 1), Vector3d(0, 0, 0.5), Vector3d(0.2, 0, 3), 1.0, -1.0,
                     "parallel apart");
}

TEST(CapsuleGeometry, EndToEnd)
{
    // Collinear, tip to tip: i's top z = 1, j's bottom z = 3.5 - 2.
    expectParameters(Vector3d(0, 0, 1), Vector3d(0, 0, 2), Vector3d(0, 0, 3.5), 1.0, -1.0,
                     "collinear tips");
    // A V opened away from both tips: from i's tip E_i = (1, 0, 0) j's tip lies ahead along
    // ai (so ui would grow past 1) and j runs away from E_i (so uj would fall below -1).
    const Vector3d ai(1, 0, 0), aj = 0.5 * Vector3d(0.6, 0.8, 0);
    const Vector3d tipJ = ai + Vector3d(0.1, 0.05, 0);
    expectParameters(ai, aj, tipJ + aj, 1.0, -1.0, "tips of a V");
}

TEST(CapsuleGeometry, SphereAndCapsule)
{
    // A sphere's parameter is exactly 0; the capsule's is the projection of the sphere centre.
    double ui = 1, uj = 1;
    closestSegmentParameters(Vector3d(0, 0, 2), Vector3d::Zero(), Vector3d(0.5, 0, 0.5), ui, uj);
    EXPECT_NEAR(ui, 0.25, kTolerance);
    EXPECT_EQ(uj, 0.0);
    closestSegmentParameters(Vector3d::Zero(), Vector3d(0, 0, 2), Vector3d(0.5, 0, 3), ui, uj);
    EXPECT_EQ(ui, 0.0);
    EXPECT_NEAR(uj, -1.0, kTolerance);
    closestSegmentParameters(Vector3d::Zero(), Vector3d::Zero(), Vector3d(0.5, 0, 3), ui, uj);
    EXPECT_EQ(ui, 0.0);
    EXPECT_EQ(uj, 0.0);
    EXPECT_FALSE(std::signbit(ui) || std::signbit(uj)) << "+0, so that u a adds nothing";
}

TEST(CapsuleGeometry, RandomPairsAgainstIndependentMinimum)
{
    // Random lengths (some zero, some nearly parallel) and separations: the distance of the
    // points found equals an independent minimisation (golden section, 1e-15 in u: the
    // distance at the minimum is flat, so its error is far below 1e-12).
    std::mt19937 random(11);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    double worst = 0;
    for (int c = 0; c < 2000; ++c)
    {
        Vector3d ai(uniform(random), uniform(random), uniform(random));
        Vector3d aj(uniform(random), uniform(random), uniform(random));
        const Vector3d d = 1.5 * Vector3d(uniform(random), uniform(random), uniform(random));
        if (c % 10 == 1)
            ai.setZero();
        if (c % 10 == 2) // nearly parallel (sin up to 1e-9)
            aj = 0.7 * ai + Vector3d(1e-9, 0, 0) * uniform(random);
        if (c % 10 == 4) // nearly parallel (sin up to 1e-13)
            aj = 0.7 * ai + Vector3d(1e-13, 0, 0) * uniform(random);
        if (c % 10 == 3)
            aj = -1.3 * ai;
        double ui, uj;
        closestSegmentParameters(ai, aj, d, ui, uj);
        ASSERT_LE(std::fabs(ui), 1.0);
        ASSERT_LE(std::fabs(uj), 1.0);
        const double error = segmentDistance(ai, aj, d, ui, uj) - bruteForceDistance(ai, aj, d);
        worst = std::max(worst, std::fabs(error));
        EXPECT_LT(error, kTolerance) << "pair " << c;
    }
    std::printf("  largest |distance - independent minimum| %.3e\n", worst);
}

namespace
{

//- The sphere pair kernel's arithmetic (PairForceKernel, StepKernels.h) for the comparison.
void spherePairReference(const Vector3d& d, double ri, double rj, Vector3d& n, double& overlap,
                         bool& touching)
{
    const double sumRadii = ri + rj;
    const double distance2 = d.squaredNorm();
    const double sumRadii2 = sumRadii * sumRadii;
    touching = distance2 < sumRadii2;
    const double floor2 = 1e-24 * sumRadii2;
    const bool coincident = distance2 < floor2;
    const double distance = std::sqrt(touching ? (coincident ? floor2 : distance2) : 1.0);
    const double inverse = 1.0 / distance;
    n = Vector3d(coincident ? 0.0 : d.x() * inverse, coincident ? 0.0 : d.y() * inverse,
                 coincident ? 1.0 : d.z() * inverse);
    overlap = sumRadii - distance;
}

} // namespace

TEST(CapsuleGeometry, SpheresBitForBitAsSpherePairs)
{
    std::mt19937 random(3);
    std::uniform_real_distribution<double> uniform(-0.02, 0.02);
    int compared = 0;
    for (int c = 0; c < 10000; ++c)
    {
        Vector3d d(uniform(random), uniform(random), uniform(random));
        if (c % 100 == 0)
            d = Vector3d(0, 0, 0); // coincident centres
        if (c % 100 == 1)
            d = Vector3d(-0.0, 1e-20, 0.0);
        const double ri = 0.01 + 0.2 * std::fabs(uniform(random)), rj = 0.01;
        Vector3d n;
        double overlap;
        bool touching;
        spherePairReference(d, ri, rj, n, overlap, touching);
        const auto g = capsulePairGeometry(d, Vector3d::Zero(), Vector3d::Zero(), ri, rj);
        ASSERT_EQ(g.touching, touching);
        if (!touching)
            continue;
        ++compared;
        EXPECT_EQ(std::memcmp(&overlap, &g.overlap, sizeof overlap), 0) << "pair " << c;
        for (int k = 0; k < 3; ++k)
            EXPECT_EQ(n[k], g.normal[k]) << "pair " << c;
        // Contact point: the middle of the overlap on the line of centres.
        // Contact point: the middle of the overlap on the line of centres (round-off of a few
        // operations on 0.01-sized numbers: 1e-17). Coincident centres have no line of
        // centres: there only c - x_j = (c - x_i) - d holds.
        EXPECT_NEAR((g.offsetI - (ri - 0.5 * overlap) * n).norm(), 0.0, 1e-17);
        EXPECT_NEAR((g.offsetJ - (g.offsetI - d)).norm(), 0.0, 1e-17);
        if (d.squaredNorm() > 1e-24 * (ri + rj) * (ri + rj))
            EXPECT_NEAR((g.offsetJ + (rj - 0.5 * overlap) * n).norm(), 0.0, 1e-17);
    }
    std::printf("  %d touching sphere pairs, identical normal and overlap\n", compared);
    EXPECT_GT(compared, 1000);
}

TEST(CapsuleGeometry, CapsulePairContactPoints)
{
    const double r = 0.01;
    // Side by side along z, 1.8 r apart in x, j shifted up by 0.5 h: normal +x, overlap 0.2 r,
    // contact mid-way between the cores, in the middle of the shared stretch z in [-0.5 h, h]
    // (relative to x_i), z = 0.25 h.
    const double h = 0.02;
    const Vector3d a(0, 0, h), d(1.8 * r, 0, 0.5 * h);
    auto g = capsulePairGeometry(d, a, a, r, r);
    EXPECT_TRUE(g.touching);
    EXPECT_NEAR((g.normal - Vector3d(1, 0, 0)).norm(), 0.0, kTolerance);
    EXPECT_NEAR(g.overlap, 0.2 * r, 1e-15);
    EXPECT_NEAR((g.offsetI - Vector3d(0.9 * r, 0, 0.25 * h)).norm(), 0.0, 1e-15);
    EXPECT_NEAR((g.offsetJ - (g.offsetI - d)).norm(), 0.0, 1e-18);
    std::printf("  side by side: overlap %.6e (exact %.6e), contact z %.6e (exact %.6e)\n",
                g.overlap, 0.2 * r, g.offsetI.z(), 0.25 * h);
    // T: j's end (u = -1) presses on i's side from above. j's axis along z, its centre at
    // (0.3 h, 0, h + 1.9 r): its tip at (0.3 h, 0, 1.9 r) above i's core (along x).
    const Vector3d ai(h, 0, 0), aj(0, 0, h), dT(0.3 * h, 0, h + 1.9 * r);
    g = capsulePairGeometry(dT, ai, aj, r, r);
    EXPECT_TRUE(g.touching);
    EXPECT_NEAR((g.normal - Vector3d(0, 0, 1)).norm(), 0.0, kTolerance);
    EXPECT_NEAR(g.overlap, 0.1 * r, 1e-15);
    EXPECT_NEAR((g.offsetI - Vector3d(0.3 * h, 0, 0.95 * r)).norm(), 0.0, 1e-15);
    EXPECT_NEAR((g.offsetJ - Vector3d(0, 0, -h - 0.95 * r)).norm(), 0.0, 1e-15);
    // Apart: not touching.
    EXPECT_FALSE(capsulePairGeometry(Vector3d(2.01 * r, 0, 0), a, a, r, r).touching);
}

//- Contact point of two side-by-side capsules as j tilts through parallel (issue 30: the
//- closest point jumped from the middle of the shared stretch to its end at a tilt of 1e-14,
//- and the torque with it). i along z at the origin, j's centre 1.8 r away in x (overlap 0.2 r
//- when parallel), j's axis (sin t, 0, cos t). Closed form of the touching stretch of i's
//- axis, z in [-h, h]: the distance from (0, 0, z) to j's line is |z sin t + 1.8 r cos t|
//- (touching below 2 r), and j's nearest point lies on its core for -h <= z cos t - 1.8 r
//- sin t <= h; the contact sits at the stretch's middle, so it stays at z = 0 until the tilt
//- lifts j's top clear (sin t = 0.2 r / h = 0.1), then moves continuously towards the end
//- still pressed.
TEST(CapsuleGeometry, ContactPointMovesContinuouslyThroughParallel)
{
    const double r = 0.01, h = 0.02;
    const Vector3d ai(0, 0, h), d(1.8 * r, 0, 0);
    double previousZ = 0.0, previousT = 0.0;
    bool first = true;
    for (const double t : {-0.3, -0.15, -0.1, -1e-3, -1e-6, -1e-9, -1e-12, -1e-14, 0.0, 1e-14,
                           1e-12, 1e-9, 1e-6, 1e-3, 0.05, 0.1, 0.12, 0.15, 0.3})
    {
        const double s = std::sin(t), c = std::cos(t);
        const auto g = capsulePairGeometry(d, ai, h * Vector3d(s, 0, c), r, r);
        ASSERT_TRUE(g.touching) << t;
        // The stretch where |z s + 1.8 r c| < 2 r, within both cores' reach.
        double from = std::max(-h, (-h + 1.8 * r * s) / c);
        double to = std::min(h, (h + 1.8 * r * s) / c);
        if (s > 0)
            to = std::min(to, (2 * r - 1.8 * r * c) / s);
        if (s < 0)
            from = std::max(from, (2 * r - 1.8 * r * c) / s);
        const double expected = 0.5 * (from + to);
        // The point sits (r - overlap/2) off i's axis along the normal; its z is the axis
        // point's plus that offset's z (the normal tilts with j by less than t).
        const double axisZ = g.offsetI.z() - (r - 0.5 * g.overlap) * g.normal.z();
        std::printf("  tilt %+.0e rad: contact z / h %+.15f (closed form %+.15f), "
                    "torque_y %+.6e\n",
                    t, axisZ / h, expected / h, g.offsetI.cross(g.normal).y());
        EXPECT_NEAR(axisZ, expected, kTolerance * h) << t;
        // Continuity: the closed form's slope is at most 5 h per rad here (0.05 h / sin^2 t
        // past the lift-off at sin t = 0.1, 0.45 h before it); 100 h per rad between
        // neighbouring tilts catches any jump (the closest point jumped by h over 1e-9 rad).
        if (!first)
            EXPECT_LE(std::fabs(axisZ - previousZ), 100 * h * std::fabs(t - previousT) + kTolerance)
                << t;
        first = false;
        previousZ = axisZ;
        previousT = t;
    }
}

TEST(CapsuleGeometry, PlaneContacts)
{
    const double r = 0.01, h = 0.03;
    // A sphere over a z-plane: one contact, the sphere wall kernel's overlap bit for bit.
    const Vector3d x(0.1, -0.2, 0.5093), planePoint(0, 0, 0.5);
    for (double side : {1.0, -1.0})
    {
        const double zw = side > 0 ? 0.5 : 0.515;
        const auto g =
            capsulePlaneGeometry(x, Vector3d::Zero(), r, Vector3d(0, 0, zw), Vector3d(0, 0, side));
        const double reference = r - (x.z() - zw) * side;
        EXPECT_EQ(std::memcmp(&reference, &g.ends[0].overlap, sizeof reference), 0);
        EXPECT_TRUE(g.ends[0].touching);
        EXPECT_FALSE(g.ends[1].touching) << "a sphere touches at one point";
        EXPECT_NEAR((g.ends[0].offset - Vector3d(0, 0, -side * (r - 0.5 * reference))).norm(), 0.0,
                    1e-18);
    }
    // A flat capsule (axis along x) on the plane: both ends, equal overlap 0.1 r.
    const Vector3d flat(h, 0, 0);
    auto g =
        capsulePlaneGeometry(Vector3d(0, 0, 0.5 + 0.9 * r), flat, r, planePoint, Vector3d(0, 0, 1));
    for (int e = 0; e < 2; ++e)
    {
        EXPECT_TRUE(g.ends[e].touching);
        EXPECT_NEAR(g.ends[e].overlap, 0.1 * r, 1e-15);
        EXPECT_NEAR((g.ends[e].offset - Vector3d((2 * e - 1) * h, 0, -0.95 * r)).norm(), 0.0,
                    1e-15);
    }
    // Tilted by 30 degrees: the lower end only, overlap r - (z_c - h sin 30 - z_w).
    const Vector3d tilted(h * std::cos(M_PI / 6), 0, h * std::sin(M_PI / 6));
    const double zc = 0.5 + 0.9 * r + 0.5 * h;
    g = capsulePlaneGeometry(Vector3d(0, 0, zc), tilted, r, planePoint, Vector3d(0, 0, 1));
    EXPECT_TRUE(g.ends[0].touching);
    EXPECT_FALSE(g.ends[1].touching);
    EXPECT_NEAR(g.ends[0].overlap, 0.1 * r, 1e-15);
    EXPECT_NEAR((g.ends[0].offset - (-tilted - 0.95 * r * Vector3d(0, 0, 1))).norm(), 0.0, 1e-15);
    // An x-plane (normal -x, grains on the low side): the end nearest it.
    const Vector3d m(-1, 0, 0);
    g = capsulePlaneGeometry(Vector3d(0.2, 0, 0), flat, r, Vector3d(0.2 + h + 0.95 * r, 0, 0), m);
    EXPECT_FALSE(g.ends[0].touching);
    EXPECT_TRUE(g.ends[1].touching);
    EXPECT_NEAR(g.ends[1].overlap, 0.05 * r, 1e-15);
}

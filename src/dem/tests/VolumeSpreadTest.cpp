// VolumeSpreadTest.cpp
// The capsule deposit's spread along the axis (kernels/VolumeSpread.h, doc/EQUATIONS.md 6),
// evaluated on the host (a pure evaluator: no System, no backend).
//
// What "exact" is. The deposit with trilinear (hat) weights w_c of a continuous body B is the
// hat-weighted integral D_c = int_B w_c(y) dy; the test computes it by fine quadrature (the
// same w_c, with the grid's wrapping and mirroring). The spread replaces each piece P_k of the
// body by its volume at one point p_k (cylinder pieces: the midpoints of K equal pieces of the
// core; caps: the ends of the core), so D^spread_c - D_c = sum_k int_{P_k} (w_c(p_k) - w_c(y)) dy.
// Bound. sum_c |dw_c / dy_d| = 2 / dx_d everywhere (two hats per direction, slopes +-1/dx_d,
// the other directions' hats summing to 1; cells merged by mirroring or wrapping only add
// terms), so sum_c |w_c(p) - w_c(y)| <= 2 sum_d |p_d - y_d| / dx_d, and
//   sum_c |D^spread_c - D_c| <= 2 sum_k int_{P_k} sum_d |y_d - p_{k,d}| / dx_d dy.
// With y - p = t e + rho (e the unit axis, rho perpendicular to it), |y_d - p_d| <= |t| |e_d| +
// |rho_d|, and int over a disk of radius R of |rho_d| = 4/3 R^3 sqrt(1 - e_d^2), so with
// A = sum_d |e_d| / dx_d and P = sum_d sqrt(1 - e_d^2) / dx_d:
//   cylinder pieces (length delta = 2h/K): pi r^2 h delta A / 2 + 2h (4/3) r^3 P,
//   each cap (hemisphere about its flat face's centre): pi r^4 / 4 (A + P),
//   B = pi r^2 h delta A + 16/3 h r^3 P + pi r^4 (A + P).
// The part the spread controls (collapsing the cylinder onto K points instead of its whole
// axis) is bounded alike by B_axis = pi r^2 h delta A, and vanishes as K grows; the rest
// (the cross-section and the caps collapsed onto the axis) is what a sphere's point deposit
// makes too, and does not depend on K.
#include "kernels/VolumeSpread.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

using dem::detail::GridView;
using dem::detail::Vector3d;

namespace
{

struct Capsule
{
    Vector3d centre, axis; //!< axis: unit vector
    double radius, halfLength;

    Vector3d halfAxis() const { return halfLength * axis; }
    double volume() const { return dem::detail::grainVolume(radius, halfLength); }
};

GridView testGrid()
{
    GridView g; // unequal spacings; periodic in x and y, mirrored in z
    const double spacing[3] = {0.010, 0.012, 0.009};
    for (int d = 0; d < 3; ++d)
    {
        g.origin[d] = 0.1 * d;
        g.spacing[d] = spacing[d];
        g.n[d] = 8;
    }
    g.periodic[0] = g.periodic[1] = true;
    g.periodic[2] = false;
    return g;
}

void addAt(const GridView& g, const Vector3d& p, double volume, std::vector<double>& cells)
{
    const dem::detail::TrilinearStencil s = dem::detail::trilinearStencil(g, p);
    for (int c = 0; c < 8; ++c)
        cells[s.cell[c]] += s.weight[c] * volume;
}

//- The spread with K cylinder points (K = 0: the kernel's own choice).
std::vector<double> spread(const GridView& g, const Capsule& c, int pieces = 0)
{
    std::vector<double> cells(g.cellCount(), 0.0);
    const Vector3d a = c.halfAxis();
    dem::detail::forEachSpreadPoint(c.centre, a, c.radius, c.volume(),
                                    pieces > 0 ? pieces : dem::detail::spreadCylinderPoints(g, a),
                                    [&](const Vector3d& p, double volume)
                                    { addAt(g, p, volume, cells); });
    return cells;
}

//- int_B w_c(y) dy by quadrature: n points per radius across (equal-area rings, 4n angles),
//- axial slabs of r/n; each slab's exact volume at its mid-plane.
std::vector<double> hatIntegral(const GridView& g, const Capsule& c, int n)
{
    std::vector<double> cells(g.cellCount(), 0.0);
    const Vector3d e = c.axis;
    const Vector3d u = e.unitOrthogonal(), w = e.cross(u);
    const double r = c.radius, h = c.halfLength;
    const int angles = 4 * n;
    auto disk = [&](const Vector3d& centre, double radius, double volume)
    {
        for (int j = 0; j < n; ++j)
        {
            const double rho = radius * std::sqrt((j + 0.5) / n);
            for (int m = 0; m < angles; ++m)
            {
                const double theta = 2.0 * M_PI * (m + 0.5) / angles;
                addAt(g, centre + rho * (std::cos(theta) * u + std::sin(theta) * w),
                      volume / (n * angles), cells);
            }
        }
    };
    const double dt = r / n;
    const int slabs = int(std::ceil(2.0 * h / dt));
    for (int k = 0; k < slabs; ++k) // the cylinder
    {
        const double ds = 2.0 * h / slabs, s = -h + (k + 0.5) * ds;
        disk(c.centre + s * e, r, M_PI * r * r * ds);
    }
    for (int k = 0; k < n; ++k) // the caps
    {
        const double t0 = k * dt, t1 = t0 + dt, t = 0.5 * (t0 + t1);
        const double volume = M_PI * (r * r * dt - (t1 * t1 * t1 - t0 * t0 * t0) / 3.0);
        const double radius = std::sqrt(r * r - t * t);
        disk(c.centre + (h + t) * e, radius, volume);
        disk(c.centre - (h + t) * e, radius, volume);
    }
    return cells;
}

double l1(const std::vector<double>& a, const std::vector<double>& b)
{
    double sum = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
        sum += std::fabs(a[i] - b[i]);
    return sum;
}

double sum(const std::vector<double>& a)
{
    double s = 0;
    for (double x : a)
        s += x;
    return s;
}

//- A = sum_d |e_d| / dx_d and P = sum_d sqrt(1 - e_d^2) / dx_d of the bound above.
void slopes(const GridView& g, const Vector3d& e, double& along, double& across)
{
    along = across = 0;
    for (int d = 0; d < 3; ++d)
    {
        along += std::fabs(e[d]) / g.spacing[d];
        across += std::sqrt(std::max(0.0, 1.0 - e[d] * e[d])) / g.spacing[d];
    }
}

//- B_axis = pi r^2 h delta A (see the top of the file).
double axialBound(const GridView& g, const Capsule& c, int pieces)
{
    double along, across;
    slopes(g, c.axis, along, across);
    const double delta = 2.0 * c.halfLength / pieces;
    return M_PI * c.radius * c.radius * c.halfLength * delta * along;
}

//- B = pi r^2 h delta A + 16/3 h r^3 P + pi r^4 (A + P).
double totalBound(const GridView& g, const Capsule& c, int pieces)
{
    double along, across;
    slopes(g, c.axis, along, across);
    const double r = c.radius, h = c.halfLength;
    return axialBound(g, c, pieces) + 16.0 / 3.0 * h * r * r * r * across +
           M_PI * r * r * r * r * (along + across);
}

Vector3d randomAxis(std::mt19937& random)
{
    std::normal_distribution<double> normal;
    Vector3d e(normal(random), normal(random), normal(random));
    return e.normalized();
}

} // namespace

// The spread against the hat-weighted integral of capsules straddling cells anywhere in the
// grid (near the periodic seams and the mirrored z sides too), aspect ratios 1 (a sphere) to 6.
TEST(VolumeSpread, ErrorAgainstHatWeightedIntegralWithinBound)
{
    const GridView g = testGrid();
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double aspects[] = {1.0, 1.5, 3.0, 6.0};
    const int quadrature = 24;
    double worstRatio = 0;
    for (int trial = 0; trial < 16; ++trial)
    {
        Capsule c;
        c.radius = 0.002 + 0.003 * unit(random);
        c.halfLength = (aspects[trial % 4] - 1.0) * c.radius; // A = (L + 2r) / 2r
        c.axis = randomAxis(random);
        for (int d = 0; d < 3; ++d)
            c.centre[d] = g.origin[d] + g.n[d] * g.spacing[d] * unit(random);
        const int pieces = dem::detail::spreadCylinderPoints(g, c.halfAxis());
        const std::vector<double> exact = hatIntegral(g, c, quadrature);
        const double error = l1(spread(g, c), exact), bound = totalBound(g, c, pieces);
        // The K-independent part: the whole axis (K = 4096) against the body
        const double collapse = l1(spread(g, c, 4096), exact);
        std::printf("  aspect %.1f, r = %.2e m, K = %2d: sum_c |D_spread - D| / V = %.3e "
                    "(whole axis %.3e), bound %.3e (ratio %.2f)\n",
                    aspects[trial % 4], c.radius, pieces, error / c.volume(), collapse / c.volume(),
                    bound / c.volume(), error / bound);
        worstRatio = std::max(worstRatio, error / bound);
        EXPECT_LE(error, bound) << "trial " << trial;
        // The quadrature's own volume is exact per slab; its sum is V to round-off.
        EXPECT_NEAR(sum(exact) / c.volume(), 1.0, 1e-12);
    }
    std::printf("  worst error / bound %.3f\n", worstRatio);
}

// The reference is converged far below the errors it judges: doubling the quadrature changes
// it by less than 2 % of the spread's error (midpoint rules on a piecewise-cubic integrand
// with kinks: the change falls like 1 / n^2 away from kinks, 1 / n at them).
TEST(VolumeSpread, ReferenceQuadratureConverged)
{
    const GridView g = testGrid();
    Capsule c{Vector3d(0.047, 0.151, 0.236), Vector3d(1.0, 0.6, 0.3).normalized(), 0.004, 0.008};
    const std::vector<double> coarse = hatIntegral(g, c, 24), fine = hatIntegral(g, c, 48);
    const double change = l1(coarse, fine), error = l1(spread(g, c), fine);
    std::printf("  reference change on doubling %.3e V, spread error %.3e V\n", change / c.volume(),
                error / c.volume());
    EXPECT_LT(change, 0.02 * error);
}

// The part of the error the spread controls: K cylinder points against the cylinder collapsed
// onto its whole axis (K = 4096 stands for the line: its own bound is 4096 times smaller),
// within B_axis and falling as K grows.
TEST(VolumeSpread, AxialQuadratureErrorWithinBound)
{
    const GridView g = testGrid();
    // A long capsule (aspect 6, the core 2.5 cells long) across cells, off all axes
    Capsule c{Vector3d(0.043, 0.147, 0.232), Vector3d(0.8, -0.5, 0.33).normalized(), 0.005, 0.025};
    const std::vector<double> line = spread(g, c, 4096);
    const int rule = dem::detail::spreadCylinderPoints(g, c.halfAxis());
    double previous = HUGE_VAL;
    for (int pieces : {1, 2, 4, 8, rule, 4 * rule})
    {
        const double error = l1(spread(g, c, pieces), line), bound = axialBound(g, c, pieces);
        std::printf("  K = %3d: sum_c |D_K - D_line| / V = %.3e, bound %.3e\n", pieces,
                    error / c.volume(), bound / c.volume());
        EXPECT_LE(error, bound) << "K = " << pieces;
        if (pieces > 8)
        {
            EXPECT_LT(error, previous) << "K = " << pieces;
            previous = error;
        }
    }
}

// Volume: the cells receive the true volume pi r^2 L + 4/3 pi r^3 to round-off (K + 2 points,
// each adding 8 weights that sum to 1 within a few ulp), also next to the mirrored sides and
// across the periodic ones.
TEST(VolumeSpread, DepositsTheTrueVolume)
{
    const GridView g = testGrid();
    std::mt19937 random(3);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    double worst = 0;
    for (int trial = 0; trial < 50; ++trial)
    {
        Capsule c;
        c.radius = 0.002 + 0.003 * unit(random);
        c.halfLength = 4.0 * c.radius * unit(random);
        c.axis = randomAxis(random);
        for (int d = 0; d < 3; ++d)
            c.centre[d] = g.origin[d] + g.n[d] * g.spacing[d] * unit(random);
        const double exactVolume = M_PI * c.radius * c.radius * 2.0 * c.halfLength +
                                   4.0 / 3.0 * M_PI * std::pow(c.radius, 3);
        worst = std::max(worst, std::fabs(sum(spread(g, c)) / exactVolume - 1.0));
    }
    std::printf("  worst relative volume error %.2e\n", worst);
    EXPECT_LT(worst, 1e-14);
}

// Centroid: away from the non-periodic sides and the seams, sum_c D_c x_c / V = x (the hat
// weights reproduce linear functions, and the points' centroid is the centre) to round-off of
// the coordinates (1e-12 of a cell).
TEST(VolumeSpread, CentroidIsTheCentre)
{
    const GridView g = testGrid();
    const Capsule c{Vector3d(0.0437, 0.1461, 0.2352), Vector3d(0.3, 0.9, -0.4).normalized(), 0.004,
                    0.009};
    const std::vector<double> cells = spread(g, c);
    Vector3d moment = Vector3d::Zero();
    for (int k = 0; k < g.n[2]; ++k)
        for (int j = 0; j < g.n[1]; ++j)
            for (int i = 0; i < g.n[0]; ++i)
            {
                const Vector3d centre(g.origin[0] + (i + 0.5) * g.spacing[0],
                                      g.origin[1] + (j + 0.5) * g.spacing[1],
                                      g.origin[2] + (k + 0.5) * g.spacing[2]);
                moment += cells[i + g.n[0] * (j + g.n[1] * k)] * centre;
            }
    const Vector3d error = moment / sum(cells) - c.centre;
    std::printf("  centroid - centre = (%.2e, %.2e, %.2e) m\n", error.x(), error.y(), error.z());
    for (int d = 0; d < 3; ++d)
        EXPECT_LT(std::fabs(error[d]), 1e-12 * g.spacing[d]);
}

// A capsule across the periodic x side deposits on both sides, exactly as its copy one box
// length further (to round-off: the copy's cell coordinate is larger by n, its fractional part
// a few ulp of n different).
TEST(VolumeSpread, CapsuleAcrossPeriodicSideDepositsOnBothSides)
{
    const GridView g = testGrid();
    const double length = g.n[0] * g.spacing[0];
    Capsule c{Vector3d(g.origin[0] + 0.002, 0.15, 0.24), Vector3d(0.9, 0.3, 0.1).normalized(),
              0.003, 0.012};
    const std::vector<double> cells = spread(g, c);
    Capsule copy = c;
    copy.centre.x() += length;
    double low = 0, high = 0; // the first and the last column of cells in x
    for (int k = 0; k < g.n[2]; ++k)
        for (int j = 0; j < g.n[1]; ++j)
        {
            low += cells[0 + g.n[0] * (j + g.n[1] * k)];
            high += cells[g.n[0] - 1 + g.n[0] * (j + g.n[1] * k)];
        }
    const double difference = l1(cells, spread(g, copy));
    std::printf("  first column %.3f V, last column %.3f V, |D - D(copy)| = %.2e V\n",
                low / c.volume(), high / c.volume(), difference / c.volume());
    EXPECT_GT(low, 0.1 * c.volume());
    EXPECT_GT(high, 0.1 * c.volume());
    EXPECT_NEAR(sum(cells) / c.volume(), 1.0, 1e-14);
    EXPECT_LT(difference, 1e-12 * c.volume());
}

// A sphere (a = 0) deposits from its centre alone: the spread is the sphere deposit, bit for bit.
TEST(VolumeSpread, SphereIsOnePoint)
{
    const GridView g = testGrid();
    const Vector3d x(0.0431, 0.1533, 0.2217);
    const double r = 0.004;
    std::vector<double> cells(g.cellCount(), 0.0), direct(g.cellCount(), 0.0);
    int points = 0;
    dem::detail::forEachSpreadPoint(x, Vector3d::Zero(), r, dem::detail::grainVolume(r, 0.0), 7,
                                    [&](const Vector3d& p, double volume)
                                    {
                                        ++points;
                                        addAt(g, p, volume, cells);
                                    });
    addAt(g, x, 4.18879020478639098 * r * r * r, direct);
    EXPECT_EQ(points, 1);
    for (std::size_t i = 0; i < cells.size(); ++i)
        EXPECT_EQ(cells[i], direct[i]);
}

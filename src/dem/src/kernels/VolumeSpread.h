// VolumeSpread.h
// A grain's solid volume and the points it is deposited from (doc/EQUATIONS.md 6). A sphere
// deposits its whole volume from its centre. A capsule (core segment x + u a, u in [-1, 1],
// dilated by r) is collapsed onto points of its axis: its cylinder pi r^2 2h in K equal pieces,
// each from the midpoint of its piece of the core, and each hemispherical cap 2/3 pi r^3 from
// its end of the core. K grows with the cells the core spans, so that every hat function of
// the deposit is sampled by several points; the deposit's error against the hat-weighted
// integral of the body is bounded in tests/VolumeSpreadTest.cpp.
#pragma once

#include "kernels/TrilinearWeights.h"

#include <cmath>

namespace dem
{
namespace detail
{
inline namespace DEM_KERNEL_NS
{

//- Solid volume of a grain of radius r and core half-length h: 4/3 pi r^3 + pi r^2 2h. For a
//- sphere (h = 0) the second term is +0: the same bits as the sphere-only code (and the same
//- arithmetic as the engine's volume read-back).
DEM_HD double grainVolume(double r, double h)
{
    return 4.18879020478639098 * r * r * r + M_PI * r * r * (2.0 * h);
}

//- Half-axis vector a = h R(q) e_z of a grain with core half-length h and orientation q
//- (w, x, y, z); zero for a sphere.
DEM_HD Vector3d halfAxisOf(double h, double w, double x, double y, double z)
{
    return h * (Eigen::Quaterniond(w, x, y, z) * Vector3d::UnitZ());
}

//- Cylinder points per cell width the core spans: a hat function (two cell widths) sees at
//- least 8 of them, so the axial quadrature error is a small part of the deposit's error.
constexpr double kSpreadPointsPerCell = 4.0;
//- More cylinder points than this only for a core longer than kMaxSpreadPoints / 4 cells.
constexpr int kMaxSpreadPoints = 1024;

//- Number K of cylinder points for half-axis a: kSpreadPointsPerCell per cell width crossed
//- (sum over directions of 2 |a_d| / dx_d), at least 1, at most kMaxSpreadPoints.
DEM_HD int spreadCylinderPoints(const GridView& grid, const Vector3d& a)
{
    double cells = 0.0;
    for (int d = 0; d < 3; ++d)
        cells += 2.0 * std::fabs(a[d]) / grid.spacing[d];
    const double wanted = std::ceil(kSpreadPointsPerCell * cells);
    // Written so that NaN gives 1 (a bad grain is reported by the step, not here)
    return wanted >= 1.0 ? (wanted < kMaxSpreadPoints ? int(wanted) : kMaxSpreadPoints) : 1;
}

//- Calls visit(point, volume) for every point a grain of centre x, half-axis a, radius r and
//- solid volume V deposits from. a = 0 (a sphere): once, (x, V). A capsule: (x -+ a, 2/3 pi r^3)
//- for the caps, then K = pieces points x + u_k a, u_k = (2k + 1 - K) / K, each with
//- (V - 4/3 pi r^3) / K. The volumes sum to V to round-off, and their centroid is x (the
//- points come in pairs +-u_k, u_k exactly opposite).
template <class Visit>
DEM_HD void forEachSpreadPoint(const Vector3d& x, const Vector3d& a, double r, double volume,
                               int pieces, Visit&& visit)
{
    if (a.x() == 0.0 && a.y() == 0.0 && a.z() == 0.0)
    {
        visit(x, volume);
        return;
    }
    const double cap = 2.09439510239319549 * r * r * r; // 2/3 pi r^3
    const double piece = (volume - 2.0 * cap) / pieces;
    visit(Vector3d(x - a), cap);
    visit(Vector3d(x + a), cap);
    for (int k = 0; k < pieces; ++k)
    {
        const double u = double(2 * k + 1 - pieces) / double(pieces);
        visit(Vector3d(x + u * a), piece);
    }
}

} // namespace DEM_KERNEL_NS
} // namespace detail
} // namespace dem

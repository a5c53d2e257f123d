// CapsuleGeometry.h
// Contact geometry of capsules, written once for both backends. A grain is the set of points
// within its radius of the core segment x + u a, u in [-1, 1], a = coreHalfLength R(q) e_z (the
// half-axis vector; a = 0 for a sphere). Two grains touch where their cores come closer than the
// sum of radii; a grain touches a plane where an end of its core comes closer than its radius.
// Straight-line code with selects (no data-dependent branches): the CPU pair loop vectorises
// across pairs whichever case (crossing, parallel, end-to-end, sphere) each pair is in.
#pragma once

#include "backends/HostDevice.h"

#include <cmath>

namespace dem
{
namespace detail
{
inline namespace DEM_KERNEL_NS
{

//- Below this value of sin^2 of the angle between two cores (sin < 1e-14: parallel up to
//- round-off) they count as parallel, and the contact sits in the middle of their common
//- stretch. Above it the lines' solution, from cross products, is accurate to about
//- eps / sin in the parameter, which moves the distance only at second order (the distance is
//- flat along the lines' valley); below it every point of the common stretch is within
//- sin x (stretch length) of the closest distance.
constexpr double kParallelSine2 = 1e-28;

DEM_HD double clampUnit(double u)
{
    return u < -1.0 ? -1.0 : (u > 1.0 ? 1.0 : u);
}

//- Parameters ui, uj in [-1, 1] of the closest points x_i + ui ai and x_j + uj aj of two core
//- segments, d = x_j - x_i (minimum image). Skew cores: the closest points of the two lines,
//- clamped to the segments (clamp ui, take the best uj for it and clamp, then the best ui for
//- that uj and clamp: exact for segments, because the best ui for a given uj is a convex
//- combination of the lines' solution and the clamped ui). Parallel cores: the middle of the
//- stretch they share (the contact of two side-by-side capsules sits mid-way, not at an end),
//- or the nearest ends when they share none. A core of zero length (a sphere) gets u = 0
//- exactly.
DEM_HD void closestSegmentParameters(const Vector3d& ai, const Vector3d& aj, const Vector3d& d,
                                     double& ui, double& uj)
{
    const double aa = ai.squaredNorm(), bb = aj.squaredNorm(), ab = ai.dot(aj);
    const double ad = ai.dot(d), bd = aj.dot(d);
    // Lines: ai.(ui ai - uj aj - d) = 0 and aj.(ui ai - uj aj - d) = 0 give
    // ui = (ad bb - ab bd) / (aa bb - ab^2) = (w . (d x aj)) / |w|^2, w = ai x aj: the cross
    // products avoid the cancellation of aa bb - ab^2 (relative error eps / sin^2) for nearly
    // parallel cores.
    const Vector3d w = ai.cross(aj);
    const double denominator = w.squaredNorm();
    // Also true when either core has zero length (denominator and aa bb are both 0).
    const bool parallel = denominator <= kParallelSine2 * aa * bb;
    const double inverseA = aa > 0.0 ? 1.0 / (aa > 0.0 ? aa : 1.0) : 0.0;
    const double inverseB = bb > 0.0 ? 1.0 / (bb > 0.0 ? bb : 1.0) : 0.0;
    const double uSkew = w.dot(d.cross(aj)) / (parallel ? 1.0 : denominator);
    // Parallel: j's core covers ui in [(ad - |ab|)/aa, (ad + |ab|)/aa]; the middle of its
    // intersection with [-1, 1] (an empty one puts the middle beyond the nearest end).
    const double reach = std::fabs(ab);
    const double lower = (ad - reach) * inverseA, upper = (ad + reach) * inverseA;
    const double uParallel = 0.5 * ((lower > -1.0 ? lower : -1.0) + (upper < 1.0 ? upper : 1.0));
    const double u0 = clampUnit(parallel ? uParallel : uSkew);
    uj = clampUnit((ab * u0 - bd) * inverseB);
    ui = clampUnit((ab * uj + ad) * inverseA);
    // A zero-length core: (...) * 0 may be -0; make it +0 so that u a is +0 (see below).
    ui = aa > 0.0 ? ui : 0.0;
    uj = bb > 0.0 ? uj : 0.0;
}

//- Two grains' contact geometry. normal: unit, from i towards j; overlap: r_i + r_j minus the
//- cores' distance; offsetI, offsetJ: the contact point c - x_i and c - x_j, with c the middle
//- of the overlap, (x_i + ui ai) + (r_i - overlap/2) normal. normal, overlap and the offsets
//- are meaningful only when touching.
struct CapsulePairGeometry
{
    Vector3d normal, offsetI, offsetJ;
    double overlap;
    bool touching;
};

//- Squared fraction of the radii sum below which two cores count as intersecting (1e-12: far
//- below any physical overlap, far above where 1/distance overflows).
constexpr double kCoincidentFraction2 = 1e-24;

//- Geometry of grains i and j: d = x_j - x_i (minimum image), ai, aj their half-axis vectors,
//- ri, rj their radii. For spheres (ai = aj = 0) the separation is d itself and the distance,
//- normal and overlap are those of the sphere pair kernel, bit for bit: intersecting cores
//- (coincident centres) have no direction, so the distance is floored at kCoincidentFraction
//- of the radii sum and the normal is +z, which pushes the grains apart along z with the
//- full-overlap force instead of dividing by zero.
DEM_HD CapsulePairGeometry capsulePairGeometry(const Vector3d& d, const Vector3d& ai,
                                               const Vector3d& aj, double ri, double rj)
{
    double ui, uj;
    closestSegmentParameters(ai, aj, d, ui, uj);
    // From i's closest core point to j's. For spheres shift = (+0) - (+0) = +0 and d - 0 is d
    // exactly (also for signed zeros).
    const Vector3d shift = ui * ai - uj * aj;
    const Vector3d separation = d - shift;
    const double sumRadii = ri + rj;
    const double distance2 = separation.squaredNorm();
    const double sumRadii2 = sumRadii * sumRadii;
    CapsulePairGeometry geometry;
    geometry.touching = distance2 < sumRadii2;
    const double floor2 = kCoincidentFraction2 * sumRadii2;
    const bool coincident = distance2 < floor2;
    const double distance = std::sqrt(geometry.touching ? (coincident ? floor2 : distance2) : 1.0);
    const double inverse = 1.0 / distance;
    geometry.normal = Vector3d(coincident ? 0.0 : separation.x() * inverse,
                               coincident ? 0.0 : separation.y() * inverse,
                               coincident ? 1.0 : separation.z() * inverse);
    geometry.overlap = sumRadii - distance;
    geometry.offsetI = ui * ai + (ri - 0.5 * geometry.overlap) * geometry.normal;
    geometry.offsetJ = geometry.offsetI - d;
    return geometry;
}

//- A grain against a plane: one contact per end of the core (ends[0] at u = -1, ends[1] at
//- u = +1), the second only for a capsule (a sphere's two ends are one point). overlap: radius
//- minus the end's height above the plane; offset: contact point minus the grain's centre, the
//- middle of the overlap, end - (radius - overlap/2) m. The normal from the grain to the plane
//- is -m. overlap and offset are meaningful only when touching.
struct PlaneContactPoint
{
    Vector3d offset;
    double overlap;
    bool touching;
};

struct CapsulePlaneGeometry
{
    PlaneContactPoint ends[2];
};

//- x: centre, a: half-axis vector, r: radius; the plane passes through planePoint with unit
//- normal m pointing to the side the grains are on. For a sphere and a z-plane (planePoint
//- (0, 0, z_w), m = (0, 0, +-1)) the overlap is r - (x_z - z_w) m_z, as the sphere wall kernel's.
DEM_HD CapsulePlaneGeometry capsulePlaneGeometry(const Vector3d& x, const Vector3d& a, double r,
                                                 const Vector3d& planePoint, const Vector3d& m)
{
    const double centreHeight = (x - planePoint).dot(m);
    const double axialHeight = a.dot(m);
    const bool capsule = a.squaredNorm() > 0.0;
    CapsulePlaneGeometry geometry;
    for (int e = 0; e < 2; ++e)
    {
        const double u = e == 0 ? -1.0 : 1.0;
        // A sphere: (0 or -0) * u is +-0 and height - (+-0) is height, exactly.
        const double height = centreHeight + (capsule ? u * axialHeight : 0.0);
        PlaneContactPoint& end = geometry.ends[e];
        end.overlap = r - height;
        end.touching = end.overlap > 0.0 && (capsule || e == 0);
        end.offset = (capsule ? u : 0.0) * a - (r - 0.5 * end.overlap) * m;
    }
    return geometry;
}

} // namespace DEM_KERNEL_NS
} // namespace detail
} // namespace dem

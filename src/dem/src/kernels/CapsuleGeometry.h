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
//- The dot and cross products of two cores' half-axis vectors ai, aj and their separation d
//- that both the closest points and the touching stretch take: computed once per pair.
struct CoreProducts
{
    double aa, bb, ab, ad, bd;
    double inverseA, inverseB; // 1/aa, 1/bb; 0 for a core of zero length
    Vector3d w;                // ai x aj
};

DEM_HD CoreProducts coreProducts(const Vector3d& ai, const Vector3d& aj, const Vector3d& d)
{
    CoreProducts k;
    k.aa = ai.squaredNorm();
    k.bb = aj.squaredNorm();
    k.ab = ai.dot(aj);
    k.ad = ai.dot(d);
    k.bd = aj.dot(d);
    k.inverseA = k.aa > 0.0 ? 1.0 / (k.aa > 0.0 ? k.aa : 1.0) : 0.0;
    k.inverseB = k.bb > 0.0 ? 1.0 / (k.bb > 0.0 ? k.bb : 1.0) : 0.0;
    k.w = ai.cross(aj);
    return k;
}

DEM_HD void closestSegmentParameters(const Vector3d& aj, const Vector3d& d, const CoreProducts& k,
                                     double& ui, double& uj)
{
    const double aa = k.aa, bb = k.bb, ab = k.ab, ad = k.ad, bd = k.bd;
    const double inverseA = k.inverseA, inverseB = k.inverseB;
    // Lines: ai.(ui ai - uj aj - d) = 0 and aj.(ui ai - uj aj - d) = 0 give
    // ui = (ad bb - ab bd) / (aa bb - ab^2) = (w . (d x aj)) / |w|^2, w = ai x aj: the cross
    // products avoid the cancellation of aa bb - ab^2 (relative error eps / sin^2) for nearly
    // parallel cores.
    const Vector3d& w = k.w;
    const double denominator = w.squaredNorm();
    // Also true when either core has zero length (denominator and aa bb are both 0).
    const bool parallel = denominator <= kParallelSine2 * aa * bb;
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

DEM_HD void closestSegmentParameters(const Vector3d& ai, const Vector3d& aj, const Vector3d& d,
                                     double& ui, double& uj)
{
    closestSegmentParameters(aj, d, coreProducts(ai, aj, d), ui, uj);
}

//- Parameter on i's core of the middle of the stretch along which the two cores come closer
//- than sumRadii, for two capsules (aa, bb > 0); uClosest (the closest point's parameter) where
//- there is no such stretch along j's line (an end of j's core is what touches) or for a
//- sphere. Why: the closest point of two nearly parallel cores jumps from the middle of their
//- shared stretch (exactly parallel) to its end at the slightest tilt (sin 1e-14), and the
//- contact's torque with it; the middle of the touching stretch stays the middle until the
//- tilt lifts one end clear ((r_i + r_j - distance) / core length), then moves continuously
//- towards the end still pressed, and for crossing cores is the closest point itself (the
//- stretch is symmetric about it). Along i's core the squared distance to j's line is
//- quadratic, D^2(ref + x) = s2 x^2 + 2 g x + c0 about ref, the middle of the stretch where
//- j's nearest line point lies on j's core; s2 and g from cross products (w = ai x aj), so
//- that nearly parallel cores lose no digits (the lines' own closest point, ~1/sin away, is
//- never formed). The stretch is [ref + roots] within that common stretch and within i's core.
//- No division by zero and no infinity: +-2 stands for an unbounded end (everything is then
//- clipped to [-1, 1]).
DEM_HD double touchingStretchMiddle(const Vector3d& ai, const Vector3d& aj, const Vector3d& d,
                                    const CoreProducts& k, double sumRadii, double uClosest)
{
    const double bb = k.bb, ab = k.ab, bd = k.bd, inverseB = k.inverseB;
    const bool capsules = k.aa > 0.0 && bb > 0.0;
    // j's nearest line point to x_i + u ai is uj = (ab u - bd) / bb: on j's core for u between
    // (bd - bb) / ab and (bd + bb) / ab; for perpendicular cores (ab = 0) everywhere or nowhere.
    const bool tilted = ab != 0.0;
    const double inverseAb = 1.0 / (tilted ? ab : 1.0);
    const double e1 = (bd - bb) * inverseAb, e2 = (bd + bb) * inverseAb;
    const bool reaches = std::fabs(bd) <= bb;
    const double lowJ = tilted ? (e1 < e2 ? e1 : e2) : (reaches ? -2.0 : 2.0);
    const double highJ = tilted ? (e1 < e2 ? e2 : e1) : (reaches ? 2.0 : -2.0);
    const double lower = lowJ > -1.0 ? lowJ : -1.0, upper = highJ < 1.0 ? highJ : 1.0;
    const double ref = lower <= upper ? 0.5 * (lower + upper) : 0.0;
    // D^2(u) = |p|^2 - (aj . p)^2 / bb with p = u ai - d; about ref: c0, the slope g = dD^2/du
    // / 2 = (w . (p x aj)) / bb and the curvature s2 = |w|^2 / bb.
    const Vector3d& w = k.w;
    const Vector3d p = ref * ai - d;
    const double pj = aj.dot(p);
    const double c0 = p.squaredNorm() - pj * pj * inverseB - sumRadii * sumRadii;
    const double g = w.dot(p.cross(aj)) * inverseB;
    const double s2 = w.squaredNorm() * inverseB;
    // Roots of s2 x^2 + 2 g x + c0 = 0 without cancellation: q = -(g + sign(g) sqrt(g^2 - s2
    // c0)), x = q / s2 and c0 / q. s2 = 0 (parallel): the linear root c0 / q and an unbounded
    // end on the side where D^2 falls; s2 = g = 0: all of the line or none.
    const double discriminant = g * g - s2 * c0;
    const double root = std::sqrt(discriminant > 0.0 ? discriminant : 0.0);
    const double q = -(g + (g < 0.0 ? -root : root));
    const bool quadratic = s2 > 0.0, linear = !quadratic && g != 0.0;
    // q / s2 and c0 / q with one division (s2 q cannot underflow: both are products of a few
    // lengths and sines, far above 1e-300)
    const double safeS2 = quadratic ? s2 : 1.0, safeQ = q != 0.0 ? q : 1.0;
    const double inverse = 1.0 / (safeS2 * safeQ);
    const double xA = quadratic ? q * safeQ * inverse : (q < 0.0 ? -2.0 : 2.0);
    const double xB = c0 * safeS2 * inverse;
    const bool some = quadratic ? (discriminant > 0.0 && q != 0.0) : (linear || c0 < 0.0);
    const bool roots = quadratic || linear;
    const double low = roots ? ref + (xA < xB ? xA : xB) : -2.0;
    const double high = roots ? ref + (xA < xB ? xB : xA) : 2.0;
    const double from = low > lower ? low : lower, to = high < upper ? high : upper;
    return capsules && some && from < to ? 0.5 * (from + to) : uClosest;
}

//- Two grains' contact geometry. normal: unit, from i towards j; overlap: r_i + r_j minus the
//- cores' distance (normal and overlap from the cores' closest points); offsetI, offsetJ: the
//- contact point c - x_i and c - x_j, c = (x_i + uc ai) + (r_i - overlap/2) normal with uc
//- the middle of the stretch of i's core that touches j (touchingStretchMiddle: the closest
//- point for crossing cores, the middle of the shared stretch for parallel ones, continuous
//- in between). normal, overlap and the offsets are meaningful only when touching.
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
    const CoreProducts k = coreProducts(ai, aj, d);
    double ui, uj;
    closestSegmentParameters(aj, d, k, ui, uj);
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
    const double uc = touchingStretchMiddle(ai, aj, d, k, sumRadii, ui);
    geometry.offsetI = uc * ai + (ri - 0.5 * geometry.overlap) * geometry.normal;
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

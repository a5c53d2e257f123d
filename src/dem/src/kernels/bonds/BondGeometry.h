// BondGeometry.h
// Where a bond sits: the closest points of the two grains' core segments, whether the grains
// touch or are held apart by the bond (tension). The contact point is the middle of the overlap
// or of the gap, c = (x_A + u_A a_A) + (R_A - delta/2) n with delta = R_A + R_B - |s| and n the
// unit vector s/|s| from A's closest core point to B's. Host and device.
#pragma once

#include "backends/HostDevice.h"
#include "kernels/CapsuleGeometry.h"

namespace dem
{
namespace detail
{
inline namespace DEM_KERNEL_NS
{

//- Where the bond sits now: the cores' closest points, whether the grains touch or not.
struct BondGeometry
{
    Vector3d normal;           //!< unit, from A to B
    Vector3d offsetA, offsetB; //!< contact point minus each centre (point: middle of gap/overlap)
    double radiusA, radiusB;   //!< dilation radii
};

//- Geometry of a bond between A and B: d = x_B - x_A (minimum image), aA, aB their half-axis
//- vectors (zero for spheres), rA, rB their radii. overlap: R_A + R_B minus the cores'
//- distance (negative when the bond holds the grains apart). Cores that intersect (a distance
//- below kCoincidentFraction of the radii sum) have no direction: the normal is then +z, as in
//- capsulePairGeometry, so that a degenerate pair gives finite loads.
DEM_HD BondGeometry bondGeometry(const Vector3d& d, const Vector3d& aA, const Vector3d& aB,
                                 double rA, double rB, double& overlap)
{
    double uA, uB;
    closestSegmentParameters(aA, aB, d, uA, uB);
    const Vector3d separation = d - (uA * aA - uB * aB);
    const double sumRadii = rA + rB;
    const double distance2 = separation.squaredNorm();
    const double floor2 = kCoincidentFraction2 * sumRadii * sumRadii;
    const bool coincident = distance2 < floor2;
    const double distance = std::sqrt(coincident ? floor2 : distance2);
    const double inverse = 1.0 / distance;
    BondGeometry g;
    g.normal = Vector3d(coincident ? 0.0 : separation.x() * inverse,
                        coincident ? 0.0 : separation.y() * inverse,
                        coincident ? 1.0 : separation.z() * inverse);
    overlap = sumRadii - distance;
    g.offsetA = uA * aA + (rA - 0.5 * overlap) * g.normal;
    g.offsetB = g.offsetA - d;
    g.radiusA = rA;
    g.radiusB = rB;
    return g;
}

//- The same without the overlap.
DEM_HD BondGeometry bondGeometry(const Vector3d& d, const Vector3d& aA, const Vector3d& aB,
                                 double rA, double rB)
{
    double overlap;
    return bondGeometry(d, aA, aB, rA, rB, overlap);
}

} // namespace DEM_KERNEL_NS
} // namespace detail
} // namespace dem

// BondGeometry.h
// Where a bond sits, two models (BondPoint). closestPoints: the cores' closest points, taken
// afresh every step (bondGeometry). bodyFixedPatches (Johnson & Hopkins 2005: "the locations of
// the frozen-contact planes are stored in the body coordinate frame of each particle and move
// with them"): per grain the patch's centre (minus the grain's centre) in its body frame,
// rotated into the global frame with the grain's orientation; the bond's point is the midpoint
// of the two copies; relative motion moves them apart, creep moves them back towards each other
// (creptPatches: the paper's "creep acts by bringing the circular contact patches into
// alignment"). So two nearly parallel capsules keep their bond where it froze, whatever the
// tilt. The patch plane is not held: its normal runs between the two cores at the bond's point
// (patchGeometry), so that the bond's normal load acts across the grains as they are. The
// loads themselves are the bond law's (BondLaw.h). A bond is placed when it is made (formed,
// added, or imported from a state written before the patches) where the grains' contact law
// puts their contact (bondPlacement, PlaceBonds). Host and device.
#pragma once

#include "backends/HostDevice.h"
#include "kernels/CapsuleGeometry.h"

#include <cmath>

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

//- The cores' closest points and the middle of their gap (where a bond across a gap is
//- placed): d = x_B - x_A (minimum image), aA, aB their half-axis vectors (zero for spheres),
//- rA, rB their radii. overlap: R_A + R_B minus the cores'
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

//- Where a new bond is placed: for grains that touch, the contact law's point and normal
//- (capsulePairGeometry: the middle of the stretch of A's core that touches B, continuous
//- through parallel), so that a contact freezes where it pressed; for grains apart (bonds
//- given by the user across a gap), the cores' closest points.
DEM_HD BondGeometry bondPlacement(const Vector3d& d, const Vector3d& aA, const Vector3d& aB,
                                  double rA, double rB)
{
    const CapsulePairGeometry contact = capsulePairGeometry(d, aA, aB, rA, rB);
    BondGeometry g = bondGeometry(d, aA, aB, rA, rB);
    if (contact.touching)
    {
        g.normal = contact.normal;
        g.offsetA = contact.offsetI;
        g.offsetB = contact.offsetJ;
    }
    return g;
}

//- A bond's patch centre in each grain's body frame: the contact point minus the grain's
//- centre, as A holds it and as B holds it. A zero pointA marks a bond not yet placed (no real
//- bond sits at a grain's centre).
struct BondPatches
{
    Vector3d pointA, pointB;

    DEM_HD bool placed() const { return pointA.squaredNorm() > 0.0; }
};

//- The bond's geometry now from its patches: qA, qB the grains' orientations (body to global),
//- d = x_B - x_A (minimum image), aA, aB the half-axis vectors. Point: the midpoint of the two
//- copies. Normal: from the point of A's core nearest to it to that of B's core (for spheres
//- the line of centres), so that the bond's normal load always acts across the grains as they
//- are now; cores that meet there have no direction: +z, as capsulePairGeometry.
DEM_HD BondGeometry patchGeometry(const BondPatches& p, const Vector3d& d, const Quaterniond& qA,
                                  const Quaterniond& qB, const Vector3d& aA, const Vector3d& aB,
                                  double rA, double rB)
{
    BondGeometry g;
    g.offsetA = 0.5 * ((qA * p.pointA) + d + (qB * p.pointB));
    g.offsetB = g.offsetA - d;
    const double aa = aA.squaredNorm(), bb = aB.squaredNorm();
    const double uA = aa > 0.0 ? clampUnit(g.offsetA.dot(aA) / (aa > 0.0 ? aa : 1.0)) : 0.0;
    const double uB = bb > 0.0 ? clampUnit(g.offsetB.dot(aB) / (bb > 0.0 ? bb : 1.0)) : 0.0;
    const Vector3d separation = d + uB * aB - uA * aA;
    const double sumRadii = rA + rB;
    const double distance2 = separation.squaredNorm();
    const bool coincident = distance2 < kCoincidentFraction2 * sumRadii * sumRadii;
    const double inverse = 1.0 / std::sqrt(coincident ? 1.0 : distance2);
    g.normal = coincident ? Vector3d(0.0, 0.0, 1.0) : Vector3d(separation * inverse);
    g.radiusA = rA;
    g.radiusB = rB;
    return g;
}

//- Both copies at the point of geometry g (a bond placed now): the patch on each grain from
//- here.
DEM_HD BondPatches patchesAt(const BondGeometry& g, const Quaterniond& qA, const Quaterniond& qB)
{
    return BondPatches{qA.conjugate() * g.offsetA, qB.conjugate() * g.offsetB};
}

//- The patches after a step's creep: each copy moved by half of it towards the other
//- (creepShift: B's crept displacement relative to A, global frame), so that only the elastic
//- part of the relative motion keeps them apart.
DEM_HD BondPatches creptPatches(const BondPatches& p, const Quaterniond& qA, const Quaterniond& qB,
                                const Vector3d& creepShift)
{
    const Vector3d half = 0.5 * creepShift;
    return BondPatches{p.pointA + qA.conjugate() * half, p.pointB - qB.conjugate() * half};
}

} // namespace DEM_KERNEL_NS
} // namespace detail
} // namespace dem

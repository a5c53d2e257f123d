// StepKernels.h
// The force kernels of a velocity-Verlet step, written once for both backends and templated on
// the shape family (Shapes: SphereShapes, CapsuleShapes) and the contact law (Law:
// LinearSpringContact, SnowContact; the engine picks one per ContactMaterial::law at run time):
// per pair of the half list the contact law (PairForceKernel, loads to PairView::reaction);
// GatherKick adds per grain gravity, drag, fluid force and walls (GrainForceKernel) and the
// pairs' loads in a fixed order, then kicks and drifts (rotating capsules in the body frame).
#pragma once

#include "kernels/CapsuleGeometry.h"
#include "kernels/ContactPair.h"
#include "kernels/FluidKernels.h"
#include "kernels/IntegrationKernels.h"
#include "kernels/LinearSpringContact.h"
#include "kernels/RigidBody.h"
#include "kernels/SnowContact.h"
#include "kernels/TrilinearWeights.h"
#include "kernels/Views.h"
#include "kernels/VolumeSpread.h"
#include "kernels/bonds/BondKernels.h"

namespace dem
{
namespace detail
{
inline namespace DEM_KERNEL_NS
{

//- Shape families: which geometry the pair and wall kernels use and which load record a pair
//- stores. A system of spheres only takes SphereShapes (the sphere arithmetic and its compact
//- record); a system with any capsule takes CapsuleShapes for every grain (a sphere is a
//- capsule with a zero-length core). A new family: a struct like these, its branch in
//- PairForceKernel, GrainForceKernel and GatherKick, and its selection in EngineImpl::withShapes.
struct SphereShapes
{
    static constexpr bool kCapsules = false;
    static constexpr bool kBonds = false;
    static constexpr int kReactionComponents = kSphereReactionComponents;
};
struct CapsuleShapes
{
    static constexpr bool kCapsules = true;
    static constexpr bool kBonds = false;
    static constexpr int kReactionComponents = kCapsuleReactionComponents;
};
//- A system with bonds (Parameters::bonds.enabled, spheres and capsules alike): the capsule
//- forms, the pair kernel leaves bonded pairs to their bond (PairView::bonded) and GatherKick
//- adds the bonds' loads after the pairs'. Without bonds nothing of this is compiled in.
struct BondedCapsuleShapes : CapsuleShapes
{
    static constexpr bool kBonds = true;
};

//- Result of one contact: force and torque on i, torque on j, and their parts (the torques are
//- lever (n x f)).
struct ContactLoads
{
    Vector3d forceOnI, torqueOnI, torqueOnJ, nCrossF;
    double leverI, leverJ;
};

//- Two touching spheres (or sphere and wall: radiusJ = 0, omegaJ = 0) under any law: loads
//- with lever arms to the middle of the overlap (the arithmetic the sphere code always had;
//- LinearSpringContact ignores the pair).
template <class Law>
DEM_HD ContactLoads sphereContact(const Law& law, const Vector3d& n, double overlap, double radiusI,
                                  double radiusJ, const Vector3d& velocityI,
                                  const Vector3d& velocityJ, const Vector3d& omegaI,
                                  const Vector3d& omegaJ, Vector3d& history,
                                  const ContactPair& pair)
{
    const double leverI = radiusI - 0.5 * overlap;
    const double leverJ = radiusJ - 0.5 * overlap;
    // omega_i x (l_i n) + omega_j x (l_j n) = (l_i omega_i + l_j omega_j) x n
    const Vector3d relative = velocityI - velocityJ + (leverI * omegaI + leverJ * omegaJ).cross(n);
    Vector3d tangentialForce;
    const double normalMagnitude = law.forces(n, overlap, relative, history, tangentialForce, pair);
    ContactLoads loads;
    loads.forceOnI = tangentialForce - normalMagnitude * n;
    loads.nCrossF = n.cross(tangentialForce); // n x n = 0
    loads.leverI = leverI;
    loads.leverJ = leverJ;
    loads.torqueOnI = leverI * loads.nCrossF;
    loads.torqueOnJ = leverJ * loads.nCrossF;
    return loads;
}

//- Loads of a contact at a point off the line of centres (capsules): force on i, and the
//- torques (contact point - centre) x force on i and on j (whose force is minus i's).
struct PointContactLoads
{
    Vector3d forceOnI, torqueOnI, torqueOnJ;
};

//- n: unit normal from i towards j; offsetI, offsetJ: contact point minus each centre (j: a
//- wall passes zero with omegaJ = 0 and its velocity).
template <class Law>
DEM_HD PointContactLoads pointContact(const Law& law, const Vector3d& n, double overlap,
                                      const Vector3d& offsetI, const Vector3d& offsetJ,
                                      const Vector3d& velocityI, const Vector3d& velocityJ,
                                      const Vector3d& omegaI, const Vector3d& omegaJ,
                                      Vector3d& history, const ContactPair& pair)
{
    const Vector3d relative =
        velocityI + omegaI.cross(offsetI) - (velocityJ + omegaJ.cross(offsetJ));
    Vector3d tangentialForce;
    const double normalMagnitude = law.forces(n, overlap, relative, history, tangentialForce, pair);
    PointContactLoads loads;
    loads.forceOnI = tangentialForce - normalMagnitude * n;
    loads.torqueOnI = offsetI.cross(loads.forceOnI);
    loads.torqueOnJ = loads.forceOnI.cross(offsetJ); // offsetJ x (-f)
    return loads;
}

//- Per grain: gravity, drag, fluid force and walls at the packed state (evaluated by GatherKick,
//- before it adds the pairs' loads). Walls: a sphere has one contact per wall (record in
//- GrainView::wallState); with CapsuleShapes each end of the core is a contact with its own
//- tangential history (ends u = -1 and u = +1: wallState and wallStateEnd; wallContacts bit w
//- and bit kMaxWalls + w), and the wall's force sums both.
template <class Shapes, class WallLaw>
struct GrainForceKernel
{
    GrainView g;
    WallsView walls;
    WallLaw wallLaw, frictionlessWallLaw;
    double gravity[3];
    double drag;
    FluidLoadView fluid;

    //- Sets force and torque to grain i's loads (updates its wall history and wall forces).
    DEM_HD void add(int i, Vector3d& force, Vector3d& torque) const
    {
        const Vector3d x = g.packedPosition(i), v = g.packedVelocity(i),
                       omega = g.packedAngularVelocity(i);
        const double r = g.packedRadius(i);
        force = gravityAndDrag(i, v);
        torque = Vector3d::Zero();
        if (fluid.active) // the true volume (a capsule's too); its core read only with a fluid
            force +=
                fluid.force(i, v, grainVolume(r, Shapes::kCapsules ? g.coreHalfLength[i] : 0.0),
                            gravityVector());
        if constexpr (Shapes::kCapsules)
            addEndContacts(i, x, v, omega, r, force, torque);
        else
            addWallContacts(i, x, v, omega, r, force, torque);
    }

    //- The gravitational acceleration g.
    DEM_HD Vector3d gravityVector() const { return Vector3d(gravity[0], gravity[1], gravity[2]); }

    //- m g - c v of grain i at velocity v.
    DEM_HD Vector3d gravityAndDrag(int i, const Vector3d& v) const
    {
        const double mass = 1.0 / g.packedVelocities[8L * i + 3];
        return mass * gravityVector() - drag * v;
    }

    //- Whether, without a fluid (GatherKick::freeFlightPossible checks that once per pass),
    //- gravity and drag are all that add() gives sphere i at x (radius r): no wall that it
    //- touches, and none that it touched at the last step (whose record add() would clear).
    DEM_HD bool gravityAndDragOnly(int i, const Vector3d& x, double r) const
    {
        if (g.wallContacts[i] != 0)
            return false;
        for (int w = 0; w < walls.count; ++w)
            if (!(r - walls.distance(w, x) <= 0.0)) // addWallContacts' test (NaN: touching)
                return false;
        return true;
    }

    //- Prefetch grain i's wall records if it is near a wall: the few grains on a wall are
    //- scattered through the cell order, where the prefetcher cannot foresee them.
    DEM_HD void prefetchWallState(int i) const
    {
        if (Shapes::kCapsules || i >= g.n)
            return;
        const double* xr = g.packedPositionRadius + 4L * i;
        const double reach = 1.1 * xr[3]; // near contact
        for (int w = 0; w < walls.count; ++w)
            if ((xr[walls.axis[w]] - walls.position[w]) * walls.normalSign[w] < reach)
                prefetch(wallRecordOf(g.wallState, i, w));
    }
    static constexpr int kWallPrefetchDistance = 24; //!< grains ahead of the one summed

    DEM_HD void addWallContacts(int i, const Vector3d& x, const Vector3d& v, const Vector3d& omega,
                                double r, Vector3d& force, Vector3d& torque) const
    {
        const int wasTouching = g.wallContacts[i];
        int touching = 0;
        for (int w = 0; w < walls.count; ++w)
        {
            double* h = wallRecordOf(g.wallState, i, w);
            const double overlap = r - walls.distance(w, x);
            if (overlap <= 0.0)
            {
                if (wasTouching & (1 << w))
                    h[0] = h[1] = h[2] = h[3] = 0.0;
                continue;
            }
            touching |= 1 << w;
            Vector3d history(h[0], h[1], h[2]);
            const ContactLoads loads = sphereContact(
                walls.frictional[w] ? wallLaw : frictionlessWallLaw, walls.towardsWall(w), overlap,
                r, 0.0, v, walls.wallVelocity(w), omega, Vector3d::Zero(), history,
                ContactPair{r, r, g.packedVelocities[8L * i + 3], 0.0});
            h[0] = history.x();
            h[1] = history.y();
            h[2] = history.z();
            h[3] = -WallsView::component(loads.forceOnI, walls.axis[w]);
            force += loads.forceOnI;
            torque += loads.torqueOnI;
        }
        if (touching != wasTouching)
            g.wallContacts[i] = touching;
    }

    //- Capsules (and the spheres of a system with capsules): a contact per touching end.
    DEM_HD void addEndContacts(int i, const Vector3d& x, const Vector3d& v, const Vector3d& omega,
                               double r, Vector3d& force, Vector3d& torque) const
    {
        const int wasTouching = g.wallContacts[i];
        int touching = 0;
        const Vector3d a = g.packedHalfAxisOf(i);
        const ContactPair pair{r, r, g.packedVelocities[8L * i + 3], 0.0};
        for (int w = 0; w < walls.count; ++w)
        {
            const Vector3d m = -walls.towardsWall(w);
            const CapsulePlaneGeometry plane =
                capsulePlaneGeometry(x, a, r, walls.alongAxis(w, walls.position[w]), m);
            for (int e = 0; e < 2; ++e)
            {
                const int bit = 1 << (w + e * kMaxWalls);
                double* h = wallRecordOf(e == 0 ? g.wallState : g.wallStateEnd, i, w);
                const PlaneContactPoint& end = plane.ends[e];
                if (!end.touching)
                {
                    if (wasTouching & bit)
                        h[0] = h[1] = h[2] = h[3] = 0.0;
                    continue;
                }
                touching |= bit;
                Vector3d history(h[0], h[1], h[2]);
                const PointContactLoads loads =
                    pointContact(walls.frictional[w] ? wallLaw : frictionlessWallLaw, -m,
                                 end.overlap, end.offset, Vector3d::Zero(), v,
                                 walls.wallVelocity(w), omega, Vector3d::Zero(), history, pair);
                h[0] = history.x();
                h[1] = history.y();
                h[2] = history.z();
                h[3] = -WallsView::component(loads.forceOnI, walls.axis[w]);
                force += loads.forceOnI;
                torque += loads.torqueOnI;
            }
        }
        if (touching != wasTouching)
            g.wallContacts[i] = touching;
    }
};

//- Per pair of the half list that may touch (the execution policy's forEachTouchingPair picks
//- them with mayTouch; the others get a cleared history and the zero record): the contact law
//- when the grains overlap, else zero loads and a cleared history, into the pair's own record.
//- Straight-line code (selects, no branches) so that the CPU loop vectorises across pairs
//- (both shape families); one thread per pair on the GPU. Owner and partner sums are
//- GatherKick's, in a fixed order.
template <class Shapes, class Law>
struct PairForceKernel
{
    GrainView g;
    PairView pairs;
    BoxView box;
    Law law;

    //- a[k], a[k + s], a[k + 2 s], loaded by value: indexed loads (not references into the
    //- arrays) are what GCC turns into vector gathers.
    DEM_HD static Vector3d load(const double* a, long k, long s = 1)
    {
        const double x = a[k], y = a[k + s], z = a[k + 2 * s];
        return Vector3d(x, y, z);
    }

    //- Whether pair p may touch: centres closer than the radii sum (the spheres' own test, the
    //- same arithmetic as spherePair's) or, with capsules, than the bounding radii (radius +
    //- core half length) of both. Widened by kMayTouchMargin, so that no rounding difference
    //- between this test and the kernel's can leave a contact out: the kernel decides.
    DEM_HD bool mayTouch(long p) const
    {
        const long i = pairs.owner[p], j = pairs.partner[p];
        const double* xr = g.packedPositionRadius;
        return mayTouch(p, i, j, xr + 4 * i, xr + 4 * j, 1);
    }
    //- The same with the two grains' positions and radii read from xrI[c * s] and xrJ[c * s],
    //- c < 4: in place (s = 1) or from a backend's staging of a block of pairs, field by field.
    DEM_HD bool mayTouch(long p, long i, long j, const double* xrI, const double* xrJ, long s) const
    {
        const Vector3d d = box.separation(load(xrI, 0, s), load(xrJ, 0, s));
        double reach = xrI[3 * s] + xrJ[3 * s];
        if constexpr (Shapes::kCapsules)
            reach += g.coreHalfLength[i] + g.coreHalfLength[j];
        bool may = d.squaredNorm() < (1.0 + kMayTouchMargin) * (reach * reach);
        // A bonded pair is the bond's: zero contact loads and a cleared history, so that the
        // contact law starts afresh from the overlap it finds when the bond breaks. (The flag
        // is read for every pair: a load behind && would be conditional, and the loop would
        // not vectorise.)
        if constexpr (Shapes::kBonds)
        {
            const bool unbonded = pairs.bonded[p] == 0;
            may = may & unbonded;
        }
        return may;
    }
    static constexpr double kMayTouchMargin = 1e-9;

    //- A pair that cannot touch forgets its tangential history (a select, not a branch: the CPU
    //- loop stays vectorised); one that may touch keeps it for the contact law.
    DEM_HD void keepHistoryIf(bool mayTouchNow, long p) const
    {
        const long hs = pairs.historyStride();
        for (int c = 0; c < 3 * kHistoryVectors; ++c)
        {
            const double kept = pairs.history[p + c * hs];
            pairs.history[p + c * hs] = mayTouchNow ? kept : 0.0;
        }
    }

    //- Pair p (which may touch): its loads into its own record, p + 1 (the GPU's pass).
    DEM_HD void operator()(long p) const
    {
        const long i = pairs.owner[p], j = pairs.partner[p];
        const double *xr = g.packedPositionRadius, *vw = g.packedVelocities;
        evaluate(i, j, PairGrainRecords{xr + 4 * i, xr + 4 * j, vw + 8 * i, vw + 8 * j, 1},
                 pairs.history + p, pairs.historyStride(), p + 1);
    }

    //- The pair of grains i < j that may touch, their records read from grains: its history
    //- h[c * hs] (c < 3 kHistoryVectors) read and written, its loads into record r. The CPU's
    //- pass calls it on a batch of pairs that may touch, their grains' records staged and
    //- their history copied into a contiguous scratch.
    DEM_HD void evaluate(long i, long j, const PairGrainRecords& grains, double* h, long hs,
                         long r) const
    {
        if constexpr (Shapes::kCapsules)
            capsulePair(i, j, grains, h, hs, r);
        else
            spherePair(grains, h, hs, r);
    }

    DEM_HD void spherePair(const PairGrainRecords& grains, double* h, long hs, long r) const
    {
        const long s = grains.s;
        const Vector3d xi = load(grains.positionI, 0, s), xj = load(grains.positionJ, 0, s);
        const Vector3d d = box.separation(xi, xj);
        const double ri = grains.positionI[3 * s], rj = grains.positionJ[3 * s];
        const double sumRadii = ri + rj;
        const double distance2 = d.squaredNorm();
        const double sumRadii2 = sumRadii * sumRadii;
        const bool touching = distance2 < sumRadii2;
        // Coincident centres (a duplicated grain) have no direction: the distance is floored at
        // kCoincidentFraction of the radii sum and the normal is +z, so the pair is pushed apart
        // along z by the full-overlap spring force instead of dividing by zero. Selects only:
        // the loop stays vectorised, and other pairs get the same arithmetic as before.
        const double floor2 = kCoincidentFraction2 * sumRadii2;
        const bool coincident = distance2 < floor2;
        const double distance = std::sqrt(touching ? (coincident ? floor2 : distance2) : 1.0);
        const double inverse = 1.0 / distance;
        const Vector3d n(coincident ? 0.0 : d.x() * inverse, coincident ? 0.0 : d.y() * inverse,
                         coincident ? 1.0 : d.z() * inverse);
        const double overlap = sumRadii - distance;

        constexpr int kReactionComponents = kSphereReactionComponents;
        const long cs = pairs.stride();
        const long r0 = r * (kPairMajorLayout ? kReactionComponents : pairs.reactionPairStride);
        double* out = pairs.reaction;
        Vector3d history = load(h, 0, hs);
        const double *vwI = grains.velocityI, *vwJ = grains.velocityJ;
        // j's image across a deforming periodic side moves with it (zero in a fixed box)
        const Vector3d vj = load(vwJ, 0, s) + box.imageVelocity(xi, xj);
        const ContactLoads loads = sphereContact(law, n, overlap, ri, rj, load(vwI, 0, s), vj,
                                                 load(vwI, 4 * s, s), load(vwJ, 4 * s, s), history,
                                                 ContactPair{ri, rj, vwI[3 * s], vwJ[3 * s]});
        // Select, then store unconditionally (conditional stores would not vectorise).
        double value[3 * kHistoryVectors + kReactionComponents];
        for (int c = 0; c < 3; ++c)
        {
            value[c] = touching ? history[c] : 0.0;
            value[3 + c] = touching ? loads.forceOnI[c] : 0.0;
            value[6 + c] = touching ? loads.nCrossF[c] : 0.0;
        }
        value[9] = touching ? loads.leverI : 0.0;
        value[10] = touching ? loads.leverJ : 0.0;
        for (int c = 0; c < 3; ++c)
            h[c * hs] = value[c];
        for (int c = 0; c < kReactionComponents; ++c)
            out[r0 + c * cs] = value[3 + c];
    }

    //- Cores' closest points (CapsuleGeometry.h; a sphere's core is its centre), the contact
    //- at the middle of the overlap, the full torques on both grains.
    DEM_HD void capsulePair(long i, long j, const PairGrainRecords& grains, double* h, long hs,
                            long r) const
    {
        const long s = grains.s;
        const double* ax = g.packedHalfAxis;
        const Vector3d xi = load(grains.positionI, 0, s), xj = load(grains.positionJ, 0, s);
        const Vector3d d = box.separation(xi, xj);
        const double ri = grains.positionI[3 * s], rj = grains.positionJ[3 * s];
        const CapsulePairGeometry geometry =
            capsulePairGeometry(d, load(ax, 4 * i), load(ax, 4 * j), ri, rj);
        const bool touching = geometry.touching; // bonded pairs never come here (mayTouch)

        constexpr int kReactionComponents = kCapsuleReactionComponents;
        const long cs = pairs.stride();
        // The run-time stride (kCapsuleReactionComponents on the CPU): GCC 12 vectorises a
        // group of 9 stores at a constant stride only by permutes it does not have (not a power
        // of 2), but stores at an unknown stride element by element.
        const long r0 = r * pairs.reactionPairStride;
        double* out = pairs.reaction;
        Vector3d history = load(h, 0, hs);
        const double *vwI = grains.velocityI, *vwJ = grains.velocityJ;
        const Vector3d vj = load(vwJ, 0, s) + box.imageVelocity(xi, xj);
        const PointContactLoads loads =
            pointContact(law, geometry.normal, geometry.overlap, geometry.offsetI, geometry.offsetJ,
                         load(vwI, 0, s), vj, load(vwI, 4 * s, s), load(vwJ, 4 * s, s), history,
                         ContactPair{ri, rj, vwI[3 * s], vwJ[3 * s]});
        double value[3 * kHistoryVectors + kReactionComponents];
        for (int c = 0; c < 3; ++c)
        {
            value[c] = touching ? history[c] : 0.0;
            value[3 + c] = touching ? loads.forceOnI[c] : 0.0;
            value[6 + c] = touching ? loads.torqueOnI[c] : 0.0;
            value[9 + c] = touching ? loads.torqueOnJ[c] : 0.0;
        }
        for (int c = 0; c < 3; ++c)
            h[c * hs] = value[c];
        for (int c = 0; c < kReactionComponents; ++c)
            out[r0 + c * cs] = value[3 + c];
    }
};

//- Ends a step: per-grain loads (grainLoads: gravity, drag, fluid, walls), then the loads of
//- the pairs the grain owns and of those it is partner of, then (BondedCapsuleShapes) of its
//- bonds (fixed order: results do not depend on the thread count), the second half kick
//- and, within a step() call, the next step's kick and drift in the same pass. Capsules
//- (coreHalfLength > 0, free) rotate in the body frame: half kick of the global angular
//- momentum L, free rotation at constant L (RigidBody.h), omega = R I^-1 R^T L; spheres as
//- always (omega += dt/2 T / I). Driven grains keep v and omega (capsules turn at omega).
template <class Shapes, class WallLaw>
struct GatherKick
{
    GrainView g;
    PairView pairs;
    GrainForceKernel<Shapes, WallLaw> grainLoads;
    double dt;
    bool driftNext;   //!< false: last step of the call, update the SoA fields
    BondGather bonds; //!< BondedCapsuleShapes only

    DEM_HD double operator()(int j) const
    {
        grainLoads.prefetchWallState(j + GrainForceKernel<Shapes, WallLaw>::kWallPrefetchDistance);
        // Most grains of a flowing bed: gravity, drag, kicks and drift only.
        if (freeFlightPossible() && inFreeFlight(j))
            return freeFlight(j);
        const int flag = g.flag[j];
        if (flag == kFlagGhost) // its owner sums its loads and moves it
            return 0.0;
        Vector3d force, torque;
        grainLoads.add(j, force, torque);
        // Pairs j owns, then pairs j is the partner of (open pairs read zero loads). GCC
        // splits the loop at k = owned into two tight loops; a single loop without a branch
        // (masks for the owned/incoming choice) was slower (src/dem/README.md, Benchmark).
        // x + (-y) is x - y.
        // Skipped where no pair of j may touch in this pass (then all its records are the
        // zero record): most grains of a flowing bed. A branch around the loop, expected
        // taken: a static bed has contacts nearly everywhere (a zero trip count instead cost
        // the static benchmark 3 %).
        const long cs = pairs.stride();
        const int firstOwned = pairs.start[j], owned = pairs.start[j + 1] - firstOwned;
        const int firstIncoming = pairs.incomingStart[j] - owned;
        const int all = owned + pairs.incomingStart[j + 1] - pairs.incomingStart[j];
        if (__builtin_expect(pairs.anyMayTouch(j), 1))
        {
            // The sums in 4 lanes (Packed4d): a third of the instructions of 3-vectors.
            Packed4d force4{force.x(), force.y(), force.z(), 0.0};
            Packed4d torque4{torque.x(), torque.y(), torque.z(), 0.0};
            for (int k = 0; k < all; ++k)
            {
                const bool own = k < owned;
                const long p = own ? firstOwned + k : pairs.incomingPair[firstIncoming + k];
                const double* loads = pairs.template loadsOf<Shapes::kReactionComponents>(p);
                const double sign = own ? 1.0 : -1.0;
                force4 += sign * Packed4d{loads[0], loads[cs], loads[2 * cs], loads[3 * cs]};
                if constexpr (Shapes::kCapsules)
                {
                    const double* t = loads + (own ? 3 : 6) * cs;
                    torque4 += Packed4d{t[0], t[cs], t[2 * cs], 0.0};
                }
                else
                {
                    const double lever = loads[(own ? 6 : 7) * cs];
                    torque4 += lever *
                               Packed4d{loads[3 * cs], loads[4 * cs], loads[5 * cs], loads[6 * cs]};
                }
            }
            force = firstThree(force4);
            torque = firstThree(torque4);
        }
        if constexpr (Shapes::kBonds)
            bonds.add(j, force, torque);
        if (flag == kFlagPrescribed) // the shear resistance, averaged over any interval
            g.impulseX[j] += dt * force.x();
        double* vw = g.packedVelocities + 8L * j;
        double* xr = g.packedPositionRadius + 4L * j;
        Vector3d v(vw[0], vw[1], vw[2]), omega(vw[4], vw[5], vw[6]);
        if constexpr (Shapes::kCapsules)
            if (g.coreHalfLength[j] > 0.0)
                return capsuleKickDrift(j, flag, force, torque, v, omega, vw, xr);
        kick(g, j, flag, 0.5 * dt, vw[3], vw[7], force, torque, v, omega);
        if (!driftNext)
        {
            g.force.store(j, force);
            g.torque.store(j, torque);
            g.velocity.store(j, v);
            g.angularVelocity.store(j, omega);
            g.position.store(j, Vector3d(xr[0], xr[1], xr[2]));
            g.pack(j);
            // No move; 0 v^2 is 0 unless the velocity left the numbers (then NaN, made +inf),
            // so the step's check sees a bad velocity before the call returns.
            return movedOrInfinity(0.0 * v.squaredNorm());
        }
        kick(g, j, flag, 0.5 * dt, vw[3], vw[7], force, torque, v, omega);
        const Vector3d x = Vector3d(xr[0], xr[1], xr[2]) + dt * v;
        if constexpr (Shapes::kBonds)
            turnSphere(g, j, omega, dt);
        return storeDrifted(j, x, v, omega);
    }

    //- Sphere j's state after the drift into its packed records; returns |x - x_build|^2
    //- (see movedOrInfinity).
    DEM_HD double storeDrifted(int j, const Vector3d& x, const Vector3d& v,
                               const Vector3d& omega) const
    {
        double* vw = g.packedVelocities + 8L * j;
        double* xr = g.packedPositionRadius + 4L * j;
        for (int c = 0; c < 3; ++c)
        {
            xr[c] = x[c];
            vw[c] = v[c];
            vw[4 + c] = omega[c];
        }
        const double* b = g.packedPositionAtBuild + 4L * j;
        return movedOrInfinity((x - Vector3d(b[0], b[1], b[2])).squaredNorm());
    }

    //- Whether operator()(j) would take grain j through gravity, drag, two half kicks and a
    //- drift only (where freeFlightPossible): a free grain with none of its pairs that may
    //- touch in this pass and gravityAndDragOnly. In a flowing bed most grains.
    DEM_HD bool inFreeFlight(int j) const
    {
        return g.flag[j] == kFlagFree && !pairs.anyMayTouch(j) &&
               grainLoads.gravityAndDragOnly(j, g.packedPosition(j), g.packedRadius(j));
    }
    //- Whether any grain may be inFreeFlight in this pass (else freeFlight is not to be called).
    DEM_HD bool freeFlightPossible() const
    {
        return !Shapes::kCapsules && !Shapes::kBonds && driftNext && !grainLoads.fluid.active;
    }

    //- operator()(j) for a grain inFreeFlight: the same arithmetic in the same order (the
    //- same bits) without the cases that do not arise (walls, pairs, fluid, flags).
    DEM_HD double freeFlight(int j) const
    {
        const double* vw = g.packedVelocities + 8L * j;
        Vector3d v = g.packedVelocity(j), omega = g.packedAngularVelocity(j);
        const Vector3d force = grainLoads.gravityAndDrag(j, v);
        const Vector3d torque = Vector3d::Zero();
        kick(g, j, kFlagFree, 0.5 * dt, vw[3], vw[7], force, torque, v, omega);
        kick(g, j, kFlagFree, 0.5 * dt, vw[3], vw[7], force, torque, v, omega);
        return storeDrifted(j, g.packedPosition(j) + dt * v, v, omega);
    }

    //- The same for a capsule: translation as a sphere's, rotation from the global angular
    //- momentum (GrainView::angularMomentum and orientation are its state during a call).
    DEM_HD double capsuleKickDrift(int j, int flag, const Vector3d& force, const Vector3d& torque,
                                   Vector3d& v, Vector3d& omega, double* vw, double* xr) const
    {
        Quaterniond q = g.orientationOf(j);
        const Vector3d inertia = g.principalInertia(j);
        Vector3d L = g.angularMomentum(j);
        kick(g, j, flag, 0.5 * dt, vw[3], vw[7], force, torque, v, omega);
        kickRotation(flag, 0.5 * dt, torque, q, inertia, L, omega);
        if (!driftNext)
        {
            g.force.store(j, force);
            g.torque.store(j, torque);
            g.velocity.store(j, v);
            g.angularVelocity.store(j, omega);
            g.angularMomentum.store(j, L);
            g.position.store(j, Vector3d(xr[0], xr[1], xr[2]));
            g.pack(j);
            return movedOrInfinity(0.0 * (v.squaredNorm() + L.squaredNorm()));
        }
        kick(g, j, flag, 0.5 * dt, vw[3], vw[7], force, torque, v, omega);
        kickRotation(flag, 0.5 * dt, torque, q, inertia, L, omega);
        const Vector3d x = Vector3d(xr[0], xr[1], xr[2]) + dt * v;
        rotate(g, j, flag, dt, inertia, L, q, omega);
        g.angularMomentum.store(j, L);
        for (int c = 0; c < 3; ++c)
        {
            xr[c] = x[c];
            vw[c] = v[c];
            vw[4 + c] = omega[c];
        }
        return movedOrInfinity(endsMoved2(g, j, x));
    }
};

} // namespace DEM_KERNEL_NS
} // namespace detail
} // namespace dem

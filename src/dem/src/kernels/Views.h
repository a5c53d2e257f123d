// Views.h
// Trivially copyable views of the structure-of-arrays storage that kernels receive by value.
// A vector field of N grains is stored component-blocked: x[0..N), y[0..N), z[0..N).
#pragma once

#include "backends/HostDevice.h"

namespace dem
{
namespace detail
{
inline namespace DEM_KERNEL_NS
{

//- GrainView::flag values: GrainFlag's, and one internal to the engine.
constexpr int kFlagFree = 0, kFlagFixed = 1, kFlagPrescribed = 2, kFlagTranslationOnly = 3,
              kFlagDriven = 4;
//- Internal only: a copy of another MPI rank's grain (EngineHalo.h). Its state is overwritten
//- from its owner before every force evaluation; the step neither kicks nor moves it, and its
//- loads are not summed.
constexpr int kFlagGhost = 5;

//- Maximum number of walls (their contact history is stored per grain): a box of six sides.
constexpr int kMaxWalls = 6;
//- Per grain, wall and contact: tangential history (x, y, z), then the grain's force on the
//- wall along the wall's axis. A sphere touches a plane once; a capsule at both ends of its
//- core segment, the second end's records in a second array (GrainView::wallStateEnd).
constexpr int kWallRecord = 4;
constexpr int kWallStateComponents = kWallRecord * kMaxWalls;

//- Grain i's record for wall w in a wallState array (GrainView::wallState or wallStateEnd).
DEM_HD double* wallRecordOf(double* wallState, long i, int w)
{
    return wallState + i * kWallStateComponents + kWallRecord * w;
}
//- Vectors of history per contact (1: tangential spring; bonds will add more).
constexpr int kHistoryVectors = 1;

//- Per-pair loads of the last force evaluation (zero when open), two records:
//- spheres only (SphereShapes): force on the owner (3), n x tangential force (3), the owner's
//- and the partner's lever arm. The owner's torque is lever_owner (n x f), the partner's
//- lever_partner (n x f), its force minus the owner's. For spheres the contact point lies on
//- the line of centres, so lever (n x f) is the whole torque.
//- with capsules (CapsuleShapes): force on the owner (3), torque on the owner (3), torque on
//- the partner (3), each (contact point - centre) x force.
constexpr int kSphereReactionComponents = 8;
constexpr int kCapsuleReactionComponents = 9;

//- Three components with a stride (a component-blocked vector field).
struct Vec3Array
{
    double* data = nullptr;
    long stride = 0;

    DEM_HD Vector3d operator()(long i) const
    {
        return Vector3d(data[i], data[i + stride], data[i + 2 * stride]);
    }
    DEM_HD void store(long i, const Vector3d& v) const
    {
        data[i] = v.x();
        data[i + stride] = v.y();
        data[i + 2 * stride] = v.z();
    }
};

//- Per-grain arrays used by the step kernels.
struct GrainView
{
    int n = 0;
    Vec3Array position, velocity, angularVelocity, force, torque, positionAtBuild;
    double* prescribedVelocity = nullptr; //!< 2 components (x, y)
    double* radius = nullptr;
    double* inverseMass = nullptr;
    double* inverseInertia = nullptr; //!< spheres: 1 / (2/5 m r^2)
    //- Shape (capsules): half the core segment's length (0: a sphere), the body-to-global
    //- unit quaternion (w, x, y, z; 4 blocked components), principal moments of inertia
    //- (I_perp, I_perp, I_axial) in the body frame, and the global angular momentum, the
    //- integrated rotational state of a non-spherical grain (omega follows from it).
    double* coreHalfLength = nullptr;
    double* orientation = nullptr;
    Vec3Array principalInertia, angularMomentum;
    Vec3Array halfAxisAtBuild; //!< a at the last rebuild (systems with capsules)
    //- Per grain kMaxWalls records of kWallRecord (wallRecordOf). Together per grain, not one
    //- array per component: the grains touching a wall are scattered through the cell-sorted
    //- order, and this way each costs one cache line.
    double* wallState = nullptr;
    double* wallStateEnd = nullptr; //!< the same for a capsule's second segment end (u = +1)
    int* flag = nullptr;
    int* wallContacts = nullptr; //!< bit w: touching wall w (history and force to clear)
    double* impulseX = nullptr;  //!< integral of F_x dt on prescribed-velocity grains
    //- Packed copies (one or two cache lines per grain instead of ten arrays), the current
    //- state within a step() call: (x, y, z, r), (vx, vy, vz, 1/m, wx, wy, wz, 1/I) and
    //- (x, y, z, 0) at the last rebuild.
    double* packedPositionRadius = nullptr;
    double* packedVelocities = nullptr;
    double* packedPositionAtBuild = nullptr;
    //- Systems with capsules only (else nullptr): the half-axis vector a = h R(q) e_z (ax, ay,
    //- az, 0), read by the pair kernel beside the packed position.
    double* packedHalfAxis = nullptr;

    DEM_HD Quaterniond orientationOf(long i) const
    {
        return Quaterniond(orientation[i], orientation[i + n], orientation[i + 2L * n],
                           orientation[i + 3L * n]);
    }
    DEM_HD void storeOrientation(long i, const Quaterniond& q) const
    {
        orientation[i] = q.w();
        orientation[i + n] = q.x();
        orientation[i + 2L * n] = q.y();
        orientation[i + 3L * n] = q.z();
    }
    //- a = h R(q) e_z from the SoA fields (0 for a sphere).
    DEM_HD Vector3d halfAxis(long i) const
    {
        return coreHalfLength[i] * (orientationOf(i) * Vector3d::UnitZ());
    }
    DEM_HD Vector3d packedHalfAxisOf(long i) const
    {
        const double* a = packedHalfAxis + 4L * i;
        return Vector3d(a[0], a[1], a[2]);
    }
    DEM_HD void packHalfAxis(long i) const
    {
        const Vector3d a = halfAxis(i);
        for (int c = 0; c < 3; ++c)
            packedHalfAxis[4L * i + c] = a[c];
        packedHalfAxis[4L * i + 3] = 0.0;
    }

    DEM_HD void pack(int i) const
    {
        double* xr = packedPositionRadius + 4L * i;
        double* vw = packedVelocities + 8L * i;
        for (int c = 0; c < 3; ++c)
        {
            xr[c] = position.data[i + c * position.stride];
            vw[c] = velocity.data[i + c * velocity.stride];
            vw[4 + c] = angularVelocity.data[i + c * angularVelocity.stride];
        }
        xr[3] = radius[i];
        vw[3] = inverseMass[i];
        vw[7] = inverseInertia[i];
        if (packedHalfAxis)
            packHalfAxis(i);
    }
    DEM_HD Vector3d packedPosition(int i) const
    {
        const double* xr = packedPositionRadius + 4L * i;
        return Vector3d(xr[0], xr[1], xr[2]);
    }
    DEM_HD double packedRadius(int i) const { return packedPositionRadius[4L * i + 3]; }
    DEM_HD Vector3d packedVelocity(int i) const
    {
        const double* vw = packedVelocities + 8L * i;
        return Vector3d(vw[0], vw[1], vw[2]);
    }
    DEM_HD Vector3d packedAngularVelocity(int i) const
    {
        const double* vw = packedVelocities + 8L * i + 4;
        return Vector3d(vw[0], vw[1], vw[2]);
    }
};

//- Layout of the pairs' loads, fixed per backend at compile time so that the kernels' index
//- arithmetic folds: pair by pair on the CPU (GatherKick reads a pair's loads from one cache
//- line), component by component on the GPU (coalescing). The execution policies' kPairMajor
//- must agree (checked by PairStorage). The contact history, read and written by the pair
//- kernel only, is component by component on both (contiguous vector loads and stores).
#if defined(__CUDACC__)
constexpr bool kPairMajorLayout = false;
#else
constexpr bool kPairMajorLayout = true;
#endif

//- Half neighbour list (pair p owned by the lower index) and its per-pair state.
//- The loads of pair p live in the record contactSlot[p] > 0 that the last force pass gave it
//- (p + 1 on the GPU; on the CPU the pairs of a thread's range that may touch fill the
//- range's first records in order), or in record 0, which holds zeros, when the pair could
//- not touch (contactSlot[p] = 0): most listed pairs do not touch (about 60 % at the
//- benchmark's 2e-3 m skin), and they cost the force pass neither the contact law nor a
//- store of loads.
struct PairView
{
    long count = 0;
    //- Layout of the loads: component c of record r at r * reactionPairStride +
    //- c * componentStride (pair-major on the CPU, component-major on the GPU); count + 1
    //- records, record 0 the zero record.
    long reactionPairStride = 0, componentStride = 0;
    const int* start = nullptr;         //!< N + 1: pairs of owner i are [start[i], start[i+1])
    const int* owner = nullptr;         //!< the lower grain of each pair
    const int* partner = nullptr;       //!< the other grain, > owner
    double* history = nullptr;          //!< 3 * kHistoryVectors components, c at c * count + p
    double* reaction = nullptr;         //!< k{Sphere,Capsule}ReactionComponents per record
    int* contactSlot = nullptr;         //!< per pair: its record (> 0), or 0 (cannot touch)
    const int* incomingStart = nullptr; //!< N + 1: pairs in which grain j is the partner
    const int* incomingPair = nullptr;
    const int* bonded = nullptr; //!< systems with bonds: 1 for a bonded pair (no contact law)
    //- Per grain: the number of the last pair pass that found a pair of it that may touch.
    int* grainMayTouch = nullptr;
    //- The number of the pair pass that wrote the records (1, 2, ...); 0 while a list has had
    //- none, when every grain counts as marked and GatherKick reads its zero records.
    int pass = 0;

    //- Distance between two components of one record (1 when pair-major).
    DEM_HD long stride() const { return kPairMajorLayout ? 1 : componentStride; }
    //- Distance between two components of one pair's history.
    DEM_HD long historyStride() const { return count; }
    DEM_HD double* historyOf(long p) const { return history + p; }
    //- Pair (i, j) may touch: GatherKick is to sum the loads of both grains' pairs. It skips
    //- the grains none of whose pairs may touch in this pass (in a flowing bed most of them):
    //- their records are all the zero record. (A pass number rather than a flag that GatherKick
    //- would have to lower: no store per grain and step.)
    DEM_HD void markMayTouch(long i, long j) const
    {
        storeShared(grainMayTouch + i, pass);
        storeShared(grainMayTouch + j, pass);
    }
    DEM_HD bool anyMayTouch(long i) const { return grainMayTouch[i] == pass; }
    //- Pair p's loads, C components per record (the shapes' record): its own record, or the
    //- zero record when the last force pass found that it could not touch.
    template <int C>
    DEM_HD const double* loadsOf(long p) const
    {
        return reaction + long(contactSlot[p]) * (kPairMajorLayout ? C : reactionPairStride);
    }
};

//- The packed records of a pair's two grains as PairForceKernel reads them: field f of grain
//- i's position record (x, y, z, r; GrainView::packedPositionRadius) at positionI[f * s], of
//- its velocity record (v, 1/m, omega, 1/I; packedVelocities) at velocityI[f * s], and j's
//- alike. In place (s = 1: the GPU's pass) or from a backend's staging of a batch of pairs,
//- field by field (the CPU's: whole vectors instead of element loads).
struct PairGrainRecords
{
    const double *positionI, *positionJ, *velocityI, *velocityJ;
    long s;
};

//- Periodic box in x and y; z is never periodic. A periodic side may change its length at
//- lengthRate (Parameters::boxLengthRate): the box is the one at the time of the positions.
struct BoxView
{
    double lower[3] = {0, 0, 0};
    double length[3] = {1, 1, 1};
    double lengthRate[3] = {0, 0, 0};
    bool periodic[3] = {false, false, false};

    DEM_HD double minimumImage(double d, int dim) const
    {
        if (periodic[dim])
        {
            if (d > 0.5 * length[dim])
                d -= length[dim];
            else if (d < -0.5 * length[dim])
                d += length[dim];
        }
        return d;
    }
    DEM_HD Vector3d separation(const Vector3d& from, const Vector3d& to) const
    {
        return Vector3d(minimumImage(to.x() - from.x(), 0), minimumImage(to.y() - from.y(), 1),
                        to.z() - from.z());
    }
    //- The image of the grain at `to` that separation() takes moves with that grain's velocity
    //- plus this: -lengthRate across the upper side, +lengthRate across the lower (the image
    //- is one box length away, and the length changes). Zero in a fixed box.
    DEM_HD double imageVelocity(double d, int dim) const
    {
        const double half = 0.5 * length[dim];
        const double rate = periodic[dim] ? lengthRate[dim] : 0.0;
        return d > half ? -rate : (d < -half ? rate : 0.0);
    }
    DEM_HD Vector3d imageVelocity(const Vector3d& from, const Vector3d& to) const
    {
        return Vector3d(imageVelocity(to.x() - from.x(), 0), imageVelocity(to.y() - from.y(), 1),
                        0.0);
    }
};

//- Axis-aligned walls: the plane x[axis] = position with unit normal normalSign e_axis
//- pointing into the grains (lower z wall: axis 2, +1; upper: -1; x and y walls alike). A wall
//- moves along its normal.
struct WallsView
{
    int count = 0;
    int axis[kMaxWalls] = {};
    double position[kMaxWalls] = {};
    double normalSign[kMaxWalls] = {};
    double velocity[kMaxWalls] = {};
    bool frictional[kMaxWalls] = {};

    //- Component `axis` of x, by selects (an index into a vector held in registers would
    //- send it through memory in the per-grain pass).
    DEM_HD static double component(const Vector3d& x, int axis)
    {
        return axis == 0 ? x.x() : (axis == 1 ? x.y() : x.z());
    }
    //- value along the axis of wall w, zero elsewhere.
    DEM_HD Vector3d alongAxis(int w, double value) const
    {
        return Vector3d(axis[w] == 0 ? value : 0.0, axis[w] == 1 ? value : 0.0,
                        axis[w] == 2 ? value : 0.0);
    }
    //- Signed distance of point x from wall w (positive on the grains' side).
    DEM_HD double distance(int w, const Vector3d& x) const
    {
        return (component(x, axis[w]) - position[w]) * normalSign[w];
    }
    //- Unit vector from a grain towards wall w.
    DEM_HD Vector3d towardsWall(int w) const { return alongAxis(w, -normalSign[w]); }
    DEM_HD Vector3d wallVelocity(int w) const { return alongAxis(w, velocity[w]); }
};

} // namespace DEM_KERNEL_NS
} // namespace detail
} // namespace dem

namespace dem
{
namespace detail
{
inline namespace DEM_KERNEL_NS
{

struct MaxOp
{
    DEM_HD double operator()(double a, double b) const { return a > b ? a : b; }
};
struct MinOp
{
    DEM_HD double operator()(double a, double b) const { return a < b ? a : b; }
};

} // namespace DEM_KERNEL_NS
} // namespace detail
} // namespace dem

// BondKernels.h
// The bond store's kernels, written once for both backends: the per-bond force pass
// (BondForceKernel: geometry and motion of the two grains, BondLaw::advance, a load record of
// 9), the per-grain index of the bonds a
// grain belongs to (the fixed-order gather in GatherKick), the bonded flag of each neighbour
// pair (the pair kernel leaves bonded pairs to the bond) and the formation of new bonds.
#pragma once

#include "kernels/CapsuleGeometry.h"
#include "kernels/Views.h"
#include "kernels/bonds/BondGeometry.h"
#include "kernels/bonds/BondLaw.h"

#include <cstdint>

namespace dem
{
namespace detail
{
inline namespace DEM_KERNEL_NS
{

//- A bond's stored state (BondState and BondPatches) as component-blocked arrays: component c
//- of bond b at c * count + b. A new member: a component here, in BondView's load and store
//- and in BondStorage's table (export, import and re-sorting follow).
enum BondStateComponent
{
    kBondNormalForce = 0,
    kBondShearForce = 1, // 3
    kBondTwistMoment = 4,
    kBondBendMoment = 5, // 3
    kBondPatchRadius = 8,
    kBondOnsetRadius = 9,
    kBondAge = 10,
    kBondSoftening = 11, // 0 or 1
    kBondCreepNormal = 12,
    kBondCreepShear = 13,
    kBondCreepTwist = 14,
    kBondCreepBend = 15,
    kBondNormalCreepOffset = 16,
    // Where the bond sits (BondPatches, BondGeometry.h), in each grain's body frame:
    kBondPatchPointA = 17, // 3
    kBondPatchPointB = 20, // 3
    kBondStateComponents = 23
};

//- Per bond: force on A (3), torque on A (3), torque on B (3); on B the force is minus A's.
constexpr int kBondLoadComponents = 9;

//- The bonds as the kernels see them. Bond b joins grains a[b] (the lower add-order index,
//- id first[b]) and bb[b] (id second[b]), internal indices of the current grain order.
struct BondView
{
    int count = 0;
    int* first = nullptr;    //!< add-order index of A
    int* second = nullptr;   //!< add-order index of B
    int* grainA = nullptr;   //!< internal index of A
    int* grainB = nullptr;   //!< internal index of B
    double* state = nullptr; //!< kBondStateComponents, component-blocked
    double* loads = nullptr; //!< kBondLoadComponents per bond, bond by bond
    //- Per grain (internal index) the bonds it belongs to: entries [grainStart[i],
    //- grainStart[i + 1]) of grainEntry, each 2 b + end (end 0: the grain is A, 1: B), in
    //- increasing b (the fixed order of the gather).
    const int* grainStart = nullptr;
    const int* grainEntry = nullptr;

    DEM_HD BondState load(long b) const
    {
        const long s = count;
        const double* x = state + b;
        BondState st;
        st.normalForce = x[kBondNormalForce * s];
        st.shearForce = Vector3d(x[kBondShearForce * s], x[(kBondShearForce + 1) * s],
                                 x[(kBondShearForce + 2) * s]);
        st.twistMoment = x[kBondTwistMoment * s];
        st.bendMoment = Vector3d(x[kBondBendMoment * s], x[(kBondBendMoment + 1) * s],
                                 x[(kBondBendMoment + 2) * s]);
        st.patchRadius = x[kBondPatchRadius * s];
        st.onsetRadius = x[kBondOnsetRadius * s];
        st.age = x[kBondAge * s];
        st.softening = x[kBondSoftening * s] != 0.0;
        st.creepNormal = x[kBondCreepNormal * s];
        st.creepShear = x[kBondCreepShear * s];
        st.creepTwist = x[kBondCreepTwist * s];
        st.creepBend = x[kBondCreepBend * s];
        st.normalCreepOffset = x[kBondNormalCreepOffset * s];
        st.broken = false;
        return st;
    }
    DEM_HD void store(long b, const BondState& st) const
    {
        const long s = count;
        double* x = state + b;
        x[kBondNormalForce * s] = st.normalForce;
        for (int c = 0; c < 3; ++c)
        {
            x[(kBondShearForce + c) * s] = st.shearForce[c];
            x[(kBondBendMoment + c) * s] = st.bendMoment[c];
        }
        x[kBondTwistMoment * s] = st.twistMoment;
        x[kBondPatchRadius * s] = st.patchRadius;
        x[kBondOnsetRadius * s] = st.onsetRadius;
        x[kBondAge * s] = st.age;
        x[kBondSoftening * s] = st.softening ? 1.0 : 0.0;
        x[kBondCreepNormal * s] = st.creepNormal;
        x[kBondCreepShear * s] = st.creepShear;
        x[kBondCreepTwist * s] = st.creepTwist;
        x[kBondCreepBend * s] = st.creepBend;
        x[kBondNormalCreepOffset * s] = st.normalCreepOffset;
    }
    DEM_HD BondPatches loadPatches(long b) const
    {
        return BondPatches{vectorAt(b, kBondPatchPointA), vectorAt(b, kBondPatchPointB)};
    }
    DEM_HD void storePatches(long b, const BondPatches& p) const
    {
        const long s = count;
        double* x = state + b;
        for (int c = 0; c < 3; ++c)
        {
            x[(kBondPatchPointA + c) * s] = p.pointA[c];
            x[(kBondPatchPointB + c) * s] = p.pointB[c];
        }
    }
    DEM_HD Vector3d vectorAt(long b, int component) const
    {
        const long s = count;
        const double* x = state + b + component * s;
        return Vector3d(x[0], x[s], x[2 * s]);
    }
};

//- Per bond: its geometry (BondPoint: the cores' closest points, or its patches in the grains'
//- body frames) and motion at the packed state, one step of BondLaw::advance (the state is
//- updated in place), body-fixed patches moved by the step's creep, and the load record.
//- Returns 1 for a bond that broke this step (its loads are zero; the engine removes it before
//- the gather), else 0: the engine sums it.
//- law.dt may be 0 (the loads of freshly added or imported grains: evaluate, do not advance).
struct BondForceKernel
{
    GrainView g;
    BondView bonds;
    BoxView box;
    BondLaw law;
    double* broken; //!< per bond: 1 broke this step, else 0

    //- Bonds ahead whose B records are prefetched: the bonds follow A's memory order, B's
    //- records lie a cell layer away or more, where the hardware prefetcher cannot foresee them.
    static constexpr int kPrefetchDistance = 16;

    DEM_HD double operator()(int b) const
    {
        const long i = bonds.grainA[b], j = bonds.grainB[b];
        const double* xr = g.packedPositionRadius;
        const double* vw = g.packedVelocities;
        if (b + kPrefetchDistance < bonds.count)
        {
            const long ahead = bonds.grainB[b + kPrefetchDistance];
            prefetch(xr + 4 * ahead);
            prefetch(vw + 8 * ahead);
            prefetch(g.packedHalfAxis + 4 * ahead);
        }
        const Vector3d xi(xr[4 * i], xr[4 * i + 1], xr[4 * i + 2]);
        const Vector3d xj(xr[4 * j], xr[4 * j + 1], xr[4 * j + 2]);
        const Vector3d d = box.separation(xi, xj);
        // The orientations and patches are read by the body-fixed model only.
        const bool bodyFixed = law.p.point == BondPoint::bodyFixedPatches;
        Quaterniond qA, qB;
        BondPatches patches;
        BondGeometry geometry;
        if (bodyFixed)
        {
            qA = g.orientationOf(i);
            qB = g.orientationOf(j);
            patches = bonds.loadPatches(b);
            geometry = patchGeometry(patches, d, qA, qB, g.packedHalfAxisOf(i),
                                     g.packedHalfAxisOf(j), xr[4 * i + 3], xr[4 * j + 3]);
        }
        else
            geometry = bondGeometry(d, g.packedHalfAxisOf(i), g.packedHalfAxisOf(j), xr[4 * i + 3],
                                    xr[4 * j + 3]);
        BondMotion motion;
        motion.velocityA = Vector3d(vw[8 * i], vw[8 * i + 1], vw[8 * i + 2]);
        motion.velocityB =
            Vector3d(vw[8 * j], vw[8 * j + 1], vw[8 * j + 2]) + box.imageVelocity(xi, xj);
        motion.omegaA = Vector3d(vw[8 * i + 4], vw[8 * i + 5], vw[8 * i + 6]);
        motion.omegaB = Vector3d(vw[8 * j + 4], vw[8 * j + 5], vw[8 * j + 6]);
        motion.inverseMassA = vw[8 * i + 3];
        motion.inverseMassB = vw[8 * j + 3];
        BondState state = bonds.load(b);
        const BondLoads loads = law.advance(state, geometry, motion);
        bonds.store(b, state);
        // A creeping bond's patches moved towards each other (a dt = 0 evaluation changes
        // nothing; without creep the patches stay as they are on their grains).
        if (bodyFixed && law.dt > 0.0 && !state.broken && law.creeps)
            bonds.storePatches(b, creptPatches(patches, qA, qB, loads.creepShift));
        double* out = bonds.loads + long(kBondLoadComponents) * b;
        for (int c = 0; c < 3; ++c)
        {
            out[c] = state.broken ? 0.0 : loads.forceOnA[c];
            out[3 + c] = state.broken ? 0.0 : loads.torqueOnA[c];
            out[6 + c] = state.broken ? 0.0 : loads.torqueOnB[c];
        }
        broken[b] = state.broken ? 1.0 : 0.0;
        return broken[b];
    }
};

//- Per bond: a bond not yet placed (formed, added, or imported from a state written before
//- the patches) gets its patches where the grains' contact is now (bondPlacement), at the
//- packed state; placed bonds are left as they are.
struct PlaceBonds
{
    GrainView g;
    BondView bonds;
    BoxView box;

    DEM_HD void operator()(int b) const
    {
        if (bonds.loadPatches(b).placed())
            return;
        const long i = bonds.grainA[b], j = bonds.grainB[b];
        const double* xr = g.packedPositionRadius;
        const Vector3d xi(xr[4 * i], xr[4 * i + 1], xr[4 * i + 2]);
        const Vector3d xj(xr[4 * j], xr[4 * j + 1], xr[4 * j + 2]);
        const BondGeometry placement =
            bondPlacement(box.separation(xi, xj), g.packedHalfAxisOf(i), g.packedHalfAxisOf(j),
                          xr[4 * i + 3], xr[4 * j + 3]);
        bonds.storePatches(b, patchesAt(placement, g.orientationOf(i), g.orientationOf(j)));
    }
};

//- Grain j's bond loads, added after its pairs' in the fixed order of its bond entries.
struct BondGather
{
    const int* grainStart = nullptr;
    const int* grainEntry = nullptr;
    const double* loads = nullptr;

    DEM_HD void add(int j, Vector3d& force, Vector3d& torque) const
    {
        for (int e = grainStart[j]; e < grainStart[j + 1]; ++e)
        {
            const int entry = grainEntry[e];
            const bool isA = (entry & 1) == 0;
            const double* l = loads + long(kBondLoadComponents) * (entry >> 1);
            const Vector3d f(l[0], l[1], l[2]);
            force += isA ? f : Vector3d(-f);
            const double* t = l + (isA ? 3 : 6);
            torque += Vector3d(t[0], t[1], t[2]);
        }
    }
};

//- out bond b's loads = in bond order[b]'s (kBondLoadComponents per bond, together).
struct GatherBondLoads
{
    const double* in;
    double* out;
    const int* order;
    DEM_HD void operator()(int b) const
    {
        for (int c = 0; c < kBondLoadComponents; ++c)
            out[long(b) * kBondLoadComponents + c] = in[long(order[b]) * kBondLoadComponents + c];
    }
};

//- Creep component `component` of the bonds that broke this step (broken[b] = 1), summed
//- before they are removed: the sample's creep keeps what broken bonds crept.
struct BrokenBondCreep
{
    BondView bonds;
    const double* broken;
    int component;

    DEM_HD double operator()(int b) const
    {
        // broken: 1 for a broken bond (over MPI ranks its share, BondRankShare), else 0
        return broken[b] != 0.0 ? broken[b] * bonds.state[long(component) * bonds.count + b] : 0.0;
    }
};

//- A bond's normal stiffness k_ne A = E / (2 Rbar) pi r_b^2 (the critical time step).
struct BondStiffnessOf
{
    const double* radius;
    BondView bonds;
    double youngsModulus;

    DEM_HD double operator()(int b) const
    {
        const double meanRadius = 0.5 * (radius[bonds.grainA[b]] + radius[bonds.grainB[b]]);
        const double rb = bonds.state[long(kBondPatchRadius) * bonds.count + b];
        return youngsModulus / (2.0 * meanRadius) * (3.14159265358979323846 * rb * rb);
    }
};

//- The sort key of a bond: its grains' internal indices (A, B) in one 64-bit integer.
struct BondKey
{
    DEM_HD std::int64_t operator()(int a, int b) const
    {
        return std::int64_t(a) << 32 | std::int64_t(std::uint32_t(b));
    }
};

//- Stencil of the bonds kept (a broken flag of 0).
struct IsZeroValue
{
    DEM_HD bool operator()(double x) const { return x == 0.0; }
};

//- internalOf[id[i]] = i: the internal index of each add-order index.
struct InvertIds
{
    const int* id;
    int* internalOf;
    DEM_HD void operator()(int i) const { internalOf[id[i]] = i; }
};

//- A bond's share in the counts summed over MPI ranks: a bond with a ghost is held by two ranks
//- (each owns one of its grains), so each counts it half.
struct BondRankShare
{
    BondView bonds;
    const int* flag;
    const double* weight; //!< optional per bond (broken flags), else 1
    DEM_HD double operator()(int b) const
    {
        const bool shared =
            flag[bonds.grainA[b]] == kFlagGhost || flag[bonds.grainB[b]] == kFlagGhost;
        return (weight ? weight[b] : 1.0) * (shared ? 0.5 : 1.0);
    }
};

//- Stores BondRankShare per bond.
struct StoreBondShare
{
    BondView bonds;
    const int* flag;
    const double* weight;
    double* out;
    DEM_HD void operator()(int b) const { out[b] = BondRankShare{bonds, flag, weight}(b); }
};

//- The same share for the bond formed on pair[k] (before the store indexes it).
struct FormedBondShare
{
    PairView pairs;
    const int* pair;
    const int* flag;
    DEM_HD double operator()(int k) const
    {
        const int p = pair[k];
        const bool shared =
            flag[pairs.owner[p]] == kFlagGhost || flag[pairs.partner[p]] == kFlagGhost;
        return shared ? 0.5 : 1.0;
    }
};

//- Each bond's internal grain indices.
struct RemapBonds
{
    BondView bonds;
    const int* internalOf;

    DEM_HD void operator()(int b) const
    {
        bonds.grainA[b] = internalOf[bonds.first[b]];
        bonds.grainB[b] = internalOf[bonds.second[b]];
    }
};

//- The keys of each bond's two per-grain entries: the grain of entry 2 b + end.
struct BondEntryKeys
{
    BondView bonds;
    int* entryKey;

    DEM_HD void operator()(int b) const
    {
        entryKey[2L * b] = bonds.grainA[b];
        entryKey[2L * b + 1] = bonds.grainB[b];
    }
};

//- Per grain i: mark the pairs it owns whose partner it is bonded to (bonded[p] = 1).
struct MarkBondedPairs
{
    PairView pairs;
    BondView bonds;
    int* bonded;

    DEM_HD void operator()(int i) const
    {
        for (int p = pairs.start[i]; p < pairs.start[i + 1]; ++p)
        {
            const int j = pairs.partner[p];
            int mark = 0;
            for (int e = bonds.grainStart[i]; e < bonds.grainStart[i + 1]; ++e)
            {
                const int entry = bonds.grainEntry[e];
                const int b = entry >> 1;
                const int other = (entry & 1) == 0 ? bonds.grainB[b] : bonds.grainA[b];
                mark |= other == j ? 1 : 0;
            }
            bonded[p] = mark;
        }
    }
};

//- Formation (frozenOnContact): a neighbour pair whose grains touch and are not bonded.
struct FormationCandidate
{
    GrainView g;
    PairView pairs;
    BoxView box;
    const int* bonded;

    DEM_HD bool operator()(int p) const
    {
        if (bonded[p])
            return false;
        const long i = pairs.owner[p], j = pairs.partner[p];
        if (g.flag[i] == kFlagGhost && g.flag[j] == kFlagGhost) // the ranks owning them form it
            return false;
        const double* xr = g.packedPositionRadius;
        const Vector3d xi(xr[4 * i], xr[4 * i + 1], xr[4 * i + 2]);
        const Vector3d xj(xr[4 * j], xr[4 * j + 1], xr[4 * j + 2]);
        return capsulePairGeometry(box.separation(xi, xj), g.packedHalfAxisOf(i),
                                   g.packedHalfAxisOf(j), xr[4 * i + 3], xr[4 * j + 3])
            .touching;
    }
};

//- A number in [0, 1) from (seed, first, second) alone (splitmix64 finaliser over the three):
//- a new bond's size does not depend on threads, backend or the order grains are stored in.
DEM_HD double bondHash(std::uint64_t seed, int first, int second)
{
    std::uint64_t z =
        seed ^ (std::uint64_t(std::uint32_t(first)) << 32 | std::uint64_t(std::uint32_t(second)));
    for (int round = 0; round < 2; ++round)
    {
        z += 0x9e3779b97f4a7c15ULL;
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        z = z ^ (z >> 31);
    }
    return double(z >> 11) * (1.0 / 9007199254740992.0); // 53 bits
}

//- New bond k (stored at offset + k) on candidate pair pair[k]: ids in order, zero loads,
//- r_b^2 = f r_min^2 with f uniform in [fractionLow, fractionHigh] (r_min the smaller
//- dilation radius).
struct FormBonds
{
    GrainView g;
    PairView pairs;
    const int* id;
    const int* pair;
    BondView bonds; //!< the store after growing (count = old + new)
    int offset;
    std::uint64_t seed;
    double fractionLow, fractionHigh;

    DEM_HD void operator()(int k) const
    {
        const int p = pair[k];
        const int i = pairs.owner[p], j = pairs.partner[p];
        const int idI = id[i], idJ = id[j];
        const int b = offset + k;
        bonds.first[b] = idI < idJ ? idI : idJ;
        bonds.second[b] = idI < idJ ? idJ : idI;
        const double ri = g.radius[i], rj = g.radius[j];
        const double rMin = ri < rj ? ri : rj;
        const double f = fractionLow + (fractionHigh - fractionLow) *
                                           bondHash(seed, bonds.first[b], bonds.second[b]);
        BondState st;
        st.patchRadius = std::sqrt(f) * rMin;
        st.onsetRadius = st.patchRadius;
        bonds.store(b, st); // its patches: zero from the store's growth, not placed yet
    }
};

} // namespace DEM_KERNEL_NS
} // namespace detail
} // namespace dem

// GrainStorage.h
// RAII structure-of-arrays storage of the grains on one backend. Fields are registered in
// one table (name, components), so appending grains, re-sorting, export and import treat every
// field alike; a new per-grain quantity (e.g. capsule orientation, already present) is one
// table entry. Components are blocked (component c of grain i at c * N + i) unless a field is
// interleaved (grain i's components together, at i * components + c).
#pragma once

#include "kernels/Views.h"

#include <thrust/copy.h>
#include <thrust/fill.h>
#include <thrust/gather.h>

#include <array>
#include <string>
#include <vector>

namespace dem
{
namespace detail
{

enum RealField
{
    fPosition,
    fVelocity,
    fAngularVelocity,
    fForce,
    fTorque,
    fPositionAtBuild,
    fOrigin, //!< unwrapped position when added (displacement read-back)
    fPrescribedVelocity,
    fOrientation, //!< unit quaternion (w, x, y, z), body to global; integrated for capsules
    fRadius,
    fInverseMass,
    fInverseInertia,
    fWallState,        //!< interleaved, see GrainView::wallState
    fImpulseX,         //!< time integral of the x-force on a prescribed-velocity grain (else 0)
    fCoreHalfLength,   //!< half the core segment's length (0: a sphere)
    fPrincipalInertia, //!< (I_perp, I_perp, I_axial), body frame
    fAngularMomentum,  //!< global angular momentum (integrated for capsules; 0 for spheres)
    fWallStateEnd,     //!< interleaved, a capsule's second end (GrainView::wallStateEnd)
    fHalfAxisAtBuild,  //!< half-axis vector at the last rebuild (skin check with rotation)
    fFluidLoad,        //!< (V (f + beta u), V beta) of the current fluid step (StoreFluidLoad)
    kRealFieldCount
};

enum IntField
{
    fFlag,
    fId,           //!< add-order index of the grain
    fImage,        //!< periodic images crossed in x and y
    fWallContacts, //!< bit w set: the grain touched wall w in the last force evaluation
    kIntFieldCount
};

struct FieldInfo
{
    const char* name;
    int components;
    bool interleaved = false;
    //- Derived each fluid step, not state: not exported, zero on import (setFluid makes it).
    bool transient = false;
};

inline const FieldInfo& realFieldInfo(int f)
{
    static const FieldInfo table[kRealFieldCount] = {{"position", 3},
                                                     {"velocity", 3},
                                                     {"angularVelocity", 3},
                                                     {"force", 3},
                                                     {"torque", 3},
                                                     {"positionAtBuild", 3},
                                                     {"origin", 3},
                                                     {"prescribedVelocity", 2},
                                                     {"orientation", 4},
                                                     {"radius", 1},
                                                     {"inverseMass", 1},
                                                     {"inverseInertia", 1},
                                                     {"wallState", kWallStateComponents, true},
                                                     {"impulseX", 1},
                                                     {"coreHalfLength", 1},
                                                     {"principalInertia", 3},
                                                     {"angularMomentum", 3},
                                                     {"wallStateEnd", kWallStateComponents, true},
                                                     {"halfAxisAtBuild", 3},
                                                     {"fluidLoad", 4, false, true}};
    return table[f];
}

inline const FieldInfo& intFieldInfo(int f)
{
    static const FieldInfo table[kIntFieldCount] = {
        {"flag", 1}, {"id", 1}, {"image", 2}, {"wallContacts", 1}};
    return table[f];
}

inline namespace DEM_KERNEL_NS
{
//- out record i = in record order[i] (interleaved fields).
template <class T>
struct GatherRecords
{
    const T* in;
    T* out;
    const int* order;
    int components;

    DEM_HD void operator()(int i) const
    {
        for (int c = 0; c < components; ++c)
            out[long(i) * components + c] = in[long(order[i]) * components + c];
    }
};
} // namespace DEM_KERNEL_NS

template <class Exec>
class GrainStorage
{
public:
    template <class T>
    using Vec = typename Exec::template Vector<T>;

    int size() const { return n_; }
    //- Any grain with a core segment (coreHalfLength > 0): the pair and step kernels take the
    //- capsule forms (CapsuleShapes), and the packed half-axis vectors exist.
    //- Also true in a system with bonds (setCapsulePath): the bond kernels take the capsule
    //- forms, spheres in them are zero-length cores.
    bool hasCapsules() const { return capsules_ || capsulePath_; }
    void setCapsulePath(bool on) { capsulePath_ = on; }

    double* real(int f) { return thrust::raw_pointer_cast(reals_[f].data()); }
    int* integer(int f) { return thrust::raw_pointer_cast(ints_[f].data()); }
    Vec3Array vec3(int f) { return Vec3Array{real(f), n_}; }

    GrainView view()
    {
        GrainView g;
        g.n = n_;
        g.position = vec3(fPosition);
        g.velocity = vec3(fVelocity);
        g.angularVelocity = vec3(fAngularVelocity);
        g.force = vec3(fForce);
        g.torque = vec3(fTorque);
        g.positionAtBuild = vec3(fPositionAtBuild);
        g.prescribedVelocity = real(fPrescribedVelocity);
        g.radius = real(fRadius);
        g.inverseMass = real(fInverseMass);
        g.inverseInertia = real(fInverseInertia);
        g.wallState = real(fWallState);
        g.wallStateEnd = real(fWallStateEnd);
        g.coreHalfLength = real(fCoreHalfLength);
        g.orientation = real(fOrientation);
        g.principalInertia = vec3(fPrincipalInertia);
        g.angularMomentum = vec3(fAngularMomentum);
        g.halfAxisAtBuild = vec3(fHalfAxisAtBuild);
        g.impulseX = real(fImpulseX);
        g.flag = integer(fFlag);
        g.wallContacts = integer(fWallContacts);
        if (packedPositionRadius_.size() != 4 * std::size_t(n_))
        {
            packedPositionRadius_.resize(4 * std::size_t(n_));
            packedVelocities_.resize(8 * std::size_t(n_));
            packedPositionAtBuild_.resize(4 * std::size_t(n_));
        }
        g.packedPositionRadius = thrust::raw_pointer_cast(packedPositionRadius_.data());
        g.packedVelocities = thrust::raw_pointer_cast(packedVelocities_.data());
        g.packedPositionAtBuild = thrust::raw_pointer_cast(packedPositionAtBuild_.data());
        if (hasCapsules())
        {
            if (packedHalfAxis_.size() != 4 * std::size_t(n_))
                packedHalfAxis_.resize(4 * std::size_t(n_));
            g.packedHalfAxis = thrust::raw_pointer_cast(packedHalfAxis_.data());
        }
        return g;
    }

    //- Host copies, component-blocked.
    std::vector<double> hostReal(int f) const { return toHost(reals_[f]); }
    std::vector<int> hostInt(int f) const { return toHost(ints_[f]); }
    void setReal(int f, const std::vector<double>& v)
    {
        fromHost(reals_[f], v);
        if (f == fCoreHalfLength)
            capsules_ = anyPositive(v);
    }
    void setInt(int f, const std::vector<int>& v) { fromHost(ints_[f], v); }

    //- Append grains given component-blocked host arrays of `added` grains per field.
    void append(int added, const std::array<std::vector<double>, kRealFieldCount>& reals,
                const std::array<std::vector<int>, kIntFieldCount>& ints)
    {
        const int m = n_ + added;
        for (int f = 0; f < kRealFieldCount; ++f)
            fromHost(reals_[f], merge(hostReal(f), reals[f], realFieldInfo(f), m));
        for (int f = 0; f < kIntFieldCount; ++f)
            fromHost(ints_[f], merge(hostInt(f), ints[f], intFieldInfo(f), m));
        n_ = m;
        capsules_ = capsules_ || anyPositive(reals[fCoreHalfLength]);
    }

    //- Reorder every field: new grain i = old grain order[i] (policy: the engine's Thrust
    //- execution policy).
    template <class Policy>
    void permute(const Policy& policy, const Vec<int>& order)
    {
        permuteAll(policy, reals_, realFieldInfo, scratchReal_, order);
        permuteAll(policy, ints_, intFieldInfo, scratchInt_, order);
    }

    //- Replace all fields (import); sizes are checked by the caller.
    void resizeForImport(int n) { n_ = n; }

private:
    static bool anyPositive(const std::vector<double>& v)
    {
        for (double x : v)
            if (x > 0.0)
                return true;
        return false;
    }
    template <class T>
    static std::vector<T> toHost(const Vec<T>& v)
    {
        std::vector<T> h(v.size());
        thrust::copy(v.begin(), v.end(), h.begin());
        return h;
    }
    template <class T>
    static void fromHost(Vec<T>& v, const std::vector<T>& h)
    {
        v.resize(h.size());
        thrust::copy(h.begin(), h.end(), v.begin());
    }
    template <class T>
    std::vector<T> merge(const std::vector<T>& old, const std::vector<T>& added,
                         const FieldInfo& info, int m) const
    {
        const int k = m - n_, components = info.components;
        std::vector<T> out(std::size_t(components) * m);
        if (info.interleaved) // the added records follow the old ones
        {
            std::copy(old.begin(), old.end(), out.begin());
            std::copy(added.begin(), added.end(), out.begin() + old.size());
            return out;
        }
        for (int c = 0; c < components; ++c)
        {
            std::copy(old.begin() + std::size_t(c) * n_, old.begin() + std::size_t(c + 1) * n_,
                      out.begin() + std::size_t(c) * m);
            std::copy(added.begin() + std::size_t(c) * k, added.begin() + std::size_t(c + 1) * k,
                      out.begin() + std::size_t(c) * m + n_);
        }
        return out;
    }
    template <class Policy, class T, std::size_t F, class Info>
    void permuteAll(const Policy& policy, std::array<Vec<T>, F>& fields, Info info, Vec<T>& scratch,
                    const Vec<int>& order)
    {
        for (std::size_t f = 0; f < F; ++f)
        {
            scratch.resize(fields[f].size());
            const int components = info(int(f)).components;
            if (info(int(f)).interleaved)
            {
                Exec::forEach(n_,
                              GatherRecords<T>{thrust::raw_pointer_cast(fields[f].data()),
                                               thrust::raw_pointer_cast(scratch.data()),
                                               thrust::raw_pointer_cast(order.data()), components});
                fields[f].swap(scratch);
                continue;
            }
            for (int c = 0; c < components; ++c)
                thrust::gather(policy, order.begin(), order.end(), fields[f].begin() + long(c) * n_,
                               scratch.begin() + long(c) * n_);
            fields[f].swap(scratch);
        }
    }

    int n_ = 0;
    std::array<Vec<double>, kRealFieldCount> reals_;
    std::array<Vec<int>, kIntFieldCount> ints_;
    Vec<double> scratchReal_;
    Vec<double> packedPositionRadius_, packedVelocities_, packedPositionAtBuild_;
    Vec<double> packedHalfAxis_;
    bool capsules_ = false;
    bool capsulePath_ = false;
    Vec<int> scratchInt_;
};

} // namespace detail
} // namespace dem

// BondStorage.h
// RAII storage of the bonds (frozen ice contacts), separate from the neighbour list: a bond
// lives here from addBonds or formation until it breaks, whatever the distance of its grains,
// across neighbour rebuilds, re-sorting, periodic wrapping and restart. Per bond: the two
// add-order indices (first < second: A and B), the two internal indices, the state (BondState,
// component-blocked) and the loads of the last force pass; per grain, the index of the bonds it
// belongs to. After every re-sort of the grains the bonds are re-sorted by their internal
// indices (A's, then B's): the force pass then walks the grains' records in memory order, and
// the order is a function of the grain order alone (same on every backend and thread count,
// restored by a restart).
#pragma once

#include "kernels/bonds/BondKernels.h"

#include <thrust/binary_search.h>
#include <thrust/copy.h>
#include <thrust/gather.h>
#include <thrust/iterator/counting_iterator.h>
#include <thrust/sequence.h>
#include <thrust/sort.h>
#include <thrust/transform.h>

#include <cstdint>
#include <string>
#include <vector>

namespace dem
{
namespace detail
{

//- Named groups of BondState components for export and import (restart).
struct BondField
{
    const char* name;
    int component, components;
    //- Absent from states written before the field existed: imported as zero.
    bool zeroIfAbsent = false;
};

inline const std::vector<BondField>& bondFields()
{
    static const std::vector<BondField> fields = {
        {"normalForce", kBondNormalForce, 1},
        {"shearForce", kBondShearForce, 3},
        {"twistMoment", kBondTwistMoment, 1},
        {"bendMoment", kBondBendMoment, 3},
        {"patchRadius", kBondPatchRadius, 1},
        {"onsetRadius", kBondOnsetRadius, 1},
        {"age", kBondAge, 1},
        {"softening", kBondSoftening, 1},
        {"creepNormal", kBondCreepNormal, 1, true},
        {"creepShear", kBondCreepShear, 1, true},
        {"creepTwist", kBondCreepTwist, 1, true},
        {"creepBend", kBondCreepBend, 1, true},
        {"normalCreepOffset", kBondNormalCreepOffset, 1, true},
        // States written before the patches: placed again at the first step (BondPatches)
        {"patchPointA", kBondPatchPointA, 3, true},
        {"patchPointB", kBondPatchPointB, 3, true}};
    return fields;
}

template <class Exec>
class BondStorage
{
public:
    template <class T>
    using Vec = typename Exec::template Vector<T>;

    int count() const { return int(first_.size()); }

    BondView view()
    {
        BondView v;
        v.count = count();
        v.first = raw(first_);
        v.second = raw(second_);
        v.grainA = raw(grainA_);
        v.grainB = raw(grainB_);
        v.state = raw(state_);
        v.loads = raw(loads_);
        v.grainStart = raw(grainStart_);
        v.grainEntry = raw(grainEntry_);
        return v;
    }

    BondGather gather() { return BondGather{raw(grainStart_), raw(grainEntry_), raw(loads_)}; }

    //- Make room for `added` bonds after the present ones (state zero, to be filled by the
    //- caller), keeping the component-blocked layout.
    template <class Policy>
    void grow(const Policy& policy, int added)
    {
        const long n = count(), m = n + added;
        first_.resize(m);
        second_.resize(m);
        grainA_.resize(m);
        grainB_.resize(m);
        scratch_.assign(kBondStateComponents * m, 0.0);
        for (int c = 0; c < kBondStateComponents; ++c)
            thrust::copy(policy, state_.begin() + c * n, state_.begin() + (c + 1) * n,
                         scratch_.begin() + c * m);
        state_.swap(scratch_);
        loads_.resize(kBondLoadComponents * m);
    }

    //- Keep bonds order[0], order[1], ... in that order (re-sorting, removal).
    template <class Policy>
    void select(const Policy& policy, const Vec<int>& order)
    {
        const long n = count(), m = long(order.size());
        for (Vec<int>* v : {&first_, &second_, &grainA_, &grainB_})
        {
            intScratch_.resize(m);
            thrust::gather(policy, order.begin(), order.end(), v->begin(), intScratch_.begin());
            v->swap(intScratch_);
        }
        scratch_.resize(kBondStateComponents * m);
        for (int c = 0; c < kBondStateComponents; ++c)
            thrust::gather(policy, order.begin(), order.end(), state_.begin() + c * n,
                           scratch_.begin() + c * m);
        state_.swap(scratch_);
        // The loads follow their bonds: after a removal in the force pass, GatherKick reads
        // this step's loads by the new indices (they were left in place until the MPI work
        // found it: on the step a bond broke, the bonds after it in the store applied their
        // neighbours' loads).
        scratch_.resize(kBondLoadComponents * m);
        Exec::forEach(int(m), GatherBondLoads{raw(loads_), raw(scratch_), raw(order)});
        loads_.swap(scratch_);
    }

    //- Remove the bonds whose `broken` entry is non-zero.
    template <class Policy>
    void removeBroken(const Policy& policy, const Vec<double>& broken)
    {
        order_.resize(count());
        const auto end = thrust::copy_if(policy, thrust::counting_iterator<int>(0),
                                         thrust::counting_iterator<int>(count()), broken.begin(),
                                         order_.begin(), IsZeroValue());
        order_.resize(end - order_.begin());
        select(policy, order_);
    }

    //- Internal grain indices from the add-order ones (internalOf: per add-order index), the
    //- bonds sorted by them (A's, then B's), and the per-grain index of n grains: entries
    //- sorted by grain, each grain's by bond.
    template <class Policy>
    void index(const Policy& policy, const Vec<int>& internalOf, int n)
    {
        const int bonds = count();
        Exec::forEach(bonds, RemapBonds{view(), raw(internalOf)});
        keys_.resize(bonds);
        thrust::transform(policy, grainA_.begin(), grainA_.end(), grainB_.begin(), keys_.begin(),
                          BondKey());
        order_.resize(bonds);
        thrust::sequence(policy, order_.begin(), order_.end());
        thrust::stable_sort_by_key(policy, keys_.begin(), keys_.end(), order_.begin());
        select(policy, order_);
        entryKeys_.resize(2 * std::size_t(bonds));
        Exec::forEach(bonds, BondEntryKeys{view(), raw(entryKeys_)});
        grainEntry_.resize(2 * std::size_t(bonds));
        thrust::sequence(policy, grainEntry_.begin(), grainEntry_.end());
        thrust::stable_sort_by_key(policy, entryKeys_.begin(), entryKeys_.end(),
                                   grainEntry_.begin());
        grainStart_.resize(std::size_t(n) + 1);
        thrust::lower_bound(policy, entryKeys_.begin(), entryKeys_.end(),
                            thrust::counting_iterator<int>(0),
                            thrust::counting_iterator<int>(n + 1), grainStart_.begin());
    }

    // ---- host access (read-back, addBonds, restart) ----------------------------------------
    std::vector<int> hostFirst() const { return toHost(first_); }
    std::vector<int> hostSecond() const { return toHost(second_); }
    //- Component-blocked state, kBondStateComponents x count().
    std::vector<double> hostState() const { return toHost(state_); }
    void assign(const std::vector<int>& first, const std::vector<int>& second,
                const std::vector<double>& state)
    {
        fromHost(first_, first);
        fromHost(second_, second);
        fromHost(state_, state);
        grainA_.resize(first.size());
        grainB_.resize(first.size());
        loads_.assign(kBondLoadComponents * first.size(), 0.0);
    }

private:
    template <class T>
    static T* raw(Vec<T>& v)
    {
        return thrust::raw_pointer_cast(v.data());
    }
    template <class T>
    static const T* raw(const Vec<T>& v)
    {
        return thrust::raw_pointer_cast(v.data());
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

    Vec<int> first_, second_, grainA_, grainB_;
    Vec<double> state_, loads_;
    Vec<int> grainStart_ = Vec<int>(1, 0), grainEntry_;
    Vec<int> order_, intScratch_, entryKeys_;
    Vec<std::int64_t> keys_;
    Vec<double> scratch_;
};

} // namespace detail
} // namespace dem

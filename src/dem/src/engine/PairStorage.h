// PairStorage.h
// RAII storage of the half neighbour list (CSR by owner, plus each pair's owner), its per-pair
// state (contact history, loads) and the transposed list (pairs by partner). Grows with the
// packing; a limit set by Parameters::maxPairsPerGrain is enforced with an error, never by
// dropping.
#pragma once

#include "kernels/Views.h"

#include <limits>
#include <utility>

namespace dem
{
namespace detail
{

template <class Exec>
struct PairStorage
{
    template <class T>
    using Vec = typename Exec::template Vector<T>;

    Vec<int> start = Vec<int>(1, 0), owner, partner, incomingStart = Vec<int>(1, 0), incomingPair;
    Vec<double> history, reaction;
    //- Per pair its record of the loads or 0 (PairView::contactSlot).
    Vec<int> contactSlot;
    //- Systems with bonds: 1 for a pair whose grains are bonded (the bond acts, not the
    //- contact law), set after every rebuild, formation and removal.
    Vec<int> bonded;
    //- Per grain (start.size() - 1 of them): PairView::grainMayTouch, and the pass's number.
    Vec<int> grainMayTouch;
    int pass = 0;
    //- Loads per pair: kSphereReactionComponents, or kCapsuleReactionComponents in a system
    //- with capsules (set by the engine before the list is filled).
    int reactionComponents = kSphereReactionComponents;

    long count() const { return long(partner.size()); }

    static_assert(Exec::kPairMajor == kPairMajorLayout,
                  "the execution policy and the kernels disagree on the pair layout");

    PairView view()
    {
        PairView v;
        v.count = count();
        v.componentStride = Exec::kPairMajor ? 1 : v.count + 1;
        v.reactionPairStride = Exec::kPairMajor ? reactionComponents : 1;
        v.start = thrust::raw_pointer_cast(start.data());
        v.owner = thrust::raw_pointer_cast(owner.data());
        v.partner = thrust::raw_pointer_cast(partner.data());
        v.history = thrust::raw_pointer_cast(history.data());
        v.reaction = thrust::raw_pointer_cast(reaction.data());
        v.contactSlot = thrust::raw_pointer_cast(contactSlot.data());
        v.incomingStart = thrust::raw_pointer_cast(incomingStart.data());
        v.incomingPair = thrust::raw_pointer_cast(incomingPair.data());
        v.bonded = thrust::raw_pointer_cast(bonded.data());
        v.grainMayTouch = thrust::raw_pointer_cast(grainMayTouch.data());
        v.pass = pass;
        return v;
    }

    //- Loads for the current list (components per record): the zero record and one per pair,
    //- all zero, every pair pointing at the zero record until the next force pass, no grain
    //- marked by a pass (the start array sized already).
    void sizeLoads(int components)
    {
        reactionComponents = components;
        reaction.assign(std::size_t(components) * std::size_t(count() + 1), 0.0);
        contactSlot.assign(std::size_t(count()), 0);
        grainMayTouch.assign(start.size() - 1, 0);
        pass = 0;
    }

    //- Numbers the next pair pass (1, 2, ...; after 2^31 - 1 passes 1 again: a grain marked
    //- that long ago only has its zero records summed once more).
    void beginPass() { pass = pass == std::numeric_limits<int>::max() ? 1 : pass + 1; }

    void swap(PairStorage& other)
    {
        start.swap(other.start);
        owner.swap(other.owner);
        partner.swap(other.partner);
        incomingStart.swap(other.incomingStart);
        incomingPair.swap(other.incomingPair);
        history.swap(other.history);
        reaction.swap(other.reaction);
        contactSlot.swap(other.contactSlot);
        bonded.swap(other.bonded);
        grainMayTouch.swap(other.grainMayTouch);
        std::swap(pass, other.pass);
        std::swap(reactionComponents, other.reactionComponents);
    }
};

} // namespace detail
} // namespace dem

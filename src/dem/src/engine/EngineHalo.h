// EngineHalo.h
// EngineImpl over MPI ranks (Parameters::decomposition). Each rank's engine holds the grains
// whose centres lie in its box (owned) and copies of the other ranks' grains within
// reach = 2 b_max + skin of its box (ghosts, flagged kFlagGhost), so every pair of an owned
// grain is in its own list. Both ranks of a pair across a boundary evaluate it (no reverse
// communication of loads); each sums the loads of its owned grain only.
//   - every step, after the drift: the owners' per-step state (packed position, radius,
//     velocities, and for capsules orientation, angular momentum and half-axis) overwrites the
//     ghosts (refreshGhosts), in id order on both sides;
//   - at every rebuild (all ranks together: the skin check takes the largest move of all):
//     grains that left the box move to their new owner with the contact history of each of
//     their pairs (their old owner's list held every pair of theirs), then the ghost sets are
//     made afresh (redistribute); after the sort the arrived histories replace what the new
//     owner had (restoreArrivedHistories).
// Host code: records are copied through host memory at rebuilds (stage 1 of the MPI work;
// GPU-resident packing and CUDA-aware MPI are later steps, src/dem/README.md).
#pragma once

#include <algorithm>
#include <climits>

namespace dem
{
namespace detail
{

inline namespace DEM_KERNEL_NS
{
//- The per-step state of grain index[k] copied into record k of buffer (gather) or back from it
//- (scatter): packed position and radius (4), packed velocities with inverse mass and inertia
//- (8); with capsules or bonds (EngineImpl::ghostsTurn) also orientation (4), angular momentum
//- (3) and packed half-axis (4).
struct GhostStepState
{
    GrainView g;
    const int* index;
    double* buffer;
    int width;
    bool capsules;
    bool scatter;

    static constexpr int kSphereWidth = 12, kCapsuleWidth = 23;

    DEM_HD void operator()(int k) const
    {
        const long i = index[k];
        double* r = buffer + long(k) * width;
        move(g.packedPositionRadius + 4 * i, 1, r, 4);
        move(g.packedVelocities + 8 * i, 1, r + 4, 8);
        if (!capsules)
            return;
        move(g.orientation + i, g.n, r + 12, 4);
        move(g.angularMomentum.data + i, g.angularMomentum.stride, r + 16, 3);
        move(g.packedHalfAxis + 4 * i, 1, r + 19, 4);
    }
    DEM_HD void move(double* grain, long stride, double* record, int count) const
    {
        for (int c = 0; c < count; ++c)
        {
            if (scatter)
                grain[c * stride] = record[c];
            else
                record[c] = grain[c * stride];
        }
    }
};
} // namespace DEM_KERNEL_NS

namespace haloDetail
{
//- All fields of some grains on the host, component-blocked (or interleaved) as stored.
struct HostGrains
{
    int n = 0;
    std::array<std::vector<double>, kRealFieldCount> reals;
    std::array<std::vector<int>, kIntFieldCount> ints;

    //- Every field of a grain storage, copied to the host.
    template <class Storage>
    static HostGrains of(const Storage& grains)
    {
        HostGrains h;
        h.n = grains.size();
        for (int f = 0; f < kRealFieldCount; ++f)
            h.reals[f] = grains.hostReal(f);
        for (int f = 0; f < kIntFieldCount; ++f)
            h.ints[f] = grains.hostInt(f);
        return h;
    }

    void resize(int m)
    {
        n = m;
        for (int f = 0; f < kRealFieldCount; ++f)
            reals[f].assign(std::size_t(realFieldInfo(f).components) * m, 0.0);
        for (int f = 0; f < kIntFieldCount; ++f)
            ints[f].assign(std::size_t(intFieldInfo(f).components) * m, 0);
    }
    template <class T>
    static T& at(std::vector<T>& v, const FieldInfo& info, int n, int i, int c)
    {
        return info.interleaved ? v[std::size_t(i) * info.components + c]
                                : v[std::size_t(c) * n + i];
    }
    //- Grain i as one record: every real component, then every integer one (exact as double).
    void appendRecord(int i, std::vector<double>& out)
    {
        for (int f = 0; f < kRealFieldCount; ++f)
            for (int c = 0; c < realFieldInfo(f).components; ++c)
                out.push_back(at(reals[f], realFieldInfo(f), n, i, c));
        for (int f = 0; f < kIntFieldCount; ++f)
            for (int c = 0; c < intFieldInfo(f).components; ++c)
                out.push_back(double(at(ints[f], intFieldInfo(f), n, i, c)));
    }
    //- Grain i from a record; returns the record's end.
    const double* readRecord(const double* r, int i)
    {
        for (int f = 0; f < kRealFieldCount; ++f)
            for (int c = 0; c < realFieldInfo(f).components; ++c)
                at(reals[f], realFieldInfo(f), n, i, c) = *r++;
        for (int f = 0; f < kIntFieldCount; ++f)
            for (int c = 0; c < intFieldInfo(f).components; ++c)
                at(ints[f], intFieldInfo(f), n, i, c) = int(*r++);
        return r;
    }
    static int recordWidth()
    {
        int w = 0;
        for (int f = 0; f < kRealFieldCount; ++f)
            w += realFieldInfo(f).components;
        for (int f = 0; f < kIntFieldCount; ++f)
            w += intFieldInfo(f).components;
        return w;
    }
    //- Where a record holds the grain's id.
    static int idOffset()
    {
        int at = 0;
        for (int f = 0; f < kRealFieldCount; ++f)
            at += realFieldInfo(f).components;
        for (int f = 0; f < fId; ++f)
            at += intFieldInfo(f).components;
        return at;
    }
    const double* position(int i, double* x) const
    {
        for (int d = 0; d < 3; ++d)
            x[d] = reals[fPosition][std::size_t(d) * n + i];
        return x;
    }
};

} // namespace haloDetail

template <class Exec>
void EngineImpl<Exec>::sumOverRanks(Vec<double>& values) const
{
    if (!halo_)
        return;
    // Through host memory: the communicator takes host buffers (no CUDA-aware MPI assumed)
    std::vector<double> host = haloDetail::toHost(values);
    halo_->comm->sumInPlace(host.data(), long(host.size()));
    thrust::copy(host.begin(), host.end(), values.begin());
}

template <class Exec>
void EngineImpl<Exec>::refuseDecomposed(const char* what) const
{
    if (halo_)
        throw Error(std::string(what) +
                    " is not available yet with a decomposition over MPI "
                    "ranks (Parameters::decomposition " +
                    std::to_string(params_.decomposition.ranks[0]) + " x " +
                    std::to_string(params_.decomposition.ranks[1]) +
                    "); run it on one process (decomposition 1 x 1)");
}

template <class Exec>
void EngineImpl<Exec>::redistribute()
{
    using haloDetail::HostGrains;
    HaloState<Exec>& h = *halo_;
    const Communicator& comm = *h.comm;
    const int me = comm.rank(), ranks = comm.size(), n = grains_.size();
    constexpr int H = 3 * kHistoryVectors;
    const int width = HostGrains::recordWidth();

    // Bonds: the ranks decide where a ghost's grain goes from its position, so the ghosts
    // must be their owners' state of this step (the rebuild came instead of the refresh).
    const bool bonded = params_.bonds.enabled;
    if (bonded && h.receiveSizes.size() == std::size_t(ranks))
    {
        refreshGhosts();
        Exec::forEach(n, UnpackGrains{grains_.view()});
    }
    HostGrains old = HostGrains::of(grains_);
    const std::vector<int>& flag = old.ints[fFlag];
    const std::vector<int>& id = old.ints[fId];

    std::unordered_map<int, int> oldIndex;
    oldIndex.reserve(std::size_t(n));
    for (int i = 0; i < n; ++i)
        oldIndex[id[i]] = i;
    auto ownerOfOld = [&](int grainId)
    {
        const auto found = oldIndex.find(grainId);
        if (found == oldIndex.end())
            throw Error("internal error: bonded grain " + std::to_string(grainId) +
                        " is not on rank " + std::to_string(me));
        double y[3];
        return h.boxes.ownerOf(old.position(found->second, y));
    };

    // 1. Owned grains that left the box go to their new owner.
    std::vector<int> destination(static_cast<std::size_t>(n), -1), kept;
    double x[3];
    for (int i = 0; i < n; ++i)
    {
        if (flag[i] == kFlagGhost)
            continue;
        const int o = h.boxes.ownerOf(old.position(i, x));
        if (o == me)
            kept.push_back(i);
        else
            destination[i] = o;
    }
    // Their pairs' histories, as seen from the leaving grain: the old owner listed every pair
    // of its grains (a pair listed nowhere here has not touched since the last rebuild).
    std::unordered_map<int, std::vector<double>> leavingPairs;
    const bool listed =
        grainsAtLastBuild_ > 0 && long(pairs_.start.size()) == grainsAtLastBuild_ + 1;
    if (listed)
    {
        const std::vector<int> owner = haloDetail::toHost(pairs_.owner),
                               partner = haloDetail::toHost(pairs_.partner);
        const std::vector<double> history = haloDetail::toHost(pairs_.history);
        const long count = long(partner.size());
        auto add = [&](int grain, int other, long p, double sign)
        {
            std::vector<double>& list = leavingPairs[grain];
            list.push_back(double(id[other]));
            for (int c = 0; c < H; ++c)
                list.push_back(sign * history[std::size_t(c) * count + p]);
        };
        for (long p = 0; p < count; ++p)
        {
            const int a = owner[p], b = partner[p];
            if (destination[a] >= 0)
                add(a, b, p, 1.0);
            if (destination[b] >= 0)
                add(b, a, p, -1.0);
        }
    }
    // and their bonds (first, second, the partner's new owner, the state), which this rank
    // evaluated as their owner.
    constexpr int S = kBondStateComponents;
    const std::vector<int> bondFirst = bonded ? bonds_.hostFirst() : std::vector<int>(),
                           bondSecond = bonded ? bonds_.hostSecond() : std::vector<int>();
    const std::vector<double> bondState = bonded ? bonds_.hostState() : std::vector<double>();
    const std::size_t bondCount = bondFirst.size();
    std::unordered_map<int, std::vector<double>> leavingBonds;
    for (std::size_t b = 0; b < bondCount; ++b)
        for (const int end : {bondFirst[b], bondSecond[b]})
        {
            const int i = oldIndex.at(end);
            if (destination[i] < 0)
                continue;
            const int partner = end == bondFirst[b] ? bondSecond[b] : bondFirst[b];
            std::vector<double>& list = leavingBonds[i];
            list.insert(list.end(),
                        {double(bondFirst[b]), double(bondSecond[b]), double(ownerOfOld(partner))});
            for (int c = 0; c < S; ++c)
                list.push_back(bondState[std::size_t(c) * bondCount + b]);
        }
    std::vector<std::vector<double>> send(static_cast<std::size_t>(ranks));
    for (int i = 0; i < n; ++i)
        if (destination[i] >= 0)
        {
            std::vector<double>& out = send[destination[i]];
            old.appendRecord(i, out);
            const std::vector<double>& list = leavingPairs[i];
            out.push_back(double(list.size() / (1 + H)));
            out.insert(out.end(), list.begin(), list.end());
            const std::vector<double>& bondList = leavingBonds[i];
            out.push_back(double(bondList.size() / (3 + S)));
            out.insert(out.end(), bondList.begin(), bondList.end());
        }
    const std::vector<std::vector<double>> arrived = comm.exchange(send);

    // 2. The owned grains now: those kept, then those arrived (with their histories).
    std::vector<double> owned;
    owned.reserve(std::size_t(width) * kept.size());
    for (int i : kept)
        old.appendRecord(i, owned);
    h.arrivedHistory.clear();
    h.arrivedIds.clear();
    std::vector<std::vector<double>> arrivedBonds; //!< first, second, partner's owner, state
    for (const std::vector<double>& message : arrived)
        for (std::size_t at = 0; at < message.size();)
        {
            const int arrivedId = int(message[at + std::size_t(HostGrains::idOffset())]);
            owned.insert(owned.end(), message.begin() + long(at),
                         message.begin() + long(at) + width);
            at += std::size_t(width);
            const int pairsOf = int(message[at++]);
            h.arrivedIds.insert(arrivedId);
            for (int k = 0; k < pairsOf; ++k, at += 1 + H)
            {
                typename HaloState<Exec>::History history;
                std::copy(message.begin() + long(at) + 1, message.begin() + long(at) + 1 + H,
                          history.begin());
                h.arrivedHistory[HaloState<Exec>::key(arrivedId, int(message[at]))] = history;
            }
            const int bondsOf = int(message[at++]);
            for (int k = 0; k < bondsOf; ++k, at += 3 + S)
                arrivedBonds.emplace_back(message.begin() + long(at),
                                          message.begin() + long(at + 3 + S));
        }
    const int ownedCount = int(owned.size() / std::size_t(width));

    // The bonds now: those with a grain owned here, kept or arrived (a bond held before and
    // arrived again is the same bits: both ranks evaluated it alike). Each owned grain's bond
    // partners must be here: their owners send them (below, the ghosts' extra ranks).
    std::unordered_set<int> ownedNow;
    for (int k = 0; k < ownedCount; ++k)
        ownedNow.insert(int(owned[std::size_t(k) * width + HostGrains::idOffset()]));
    std::vector<int> nextFirst, nextSecond;
    std::vector<std::vector<double>> nextState;
    std::unordered_map<std::uint64_t, int> partnerOwner; //!< (owned grain, partner): its owner
    {
        std::unordered_set<std::uint64_t> held;
        auto hold = [&](int first, int second, const double* state)
        {
            if (!(ownedNow.count(first) || ownedNow.count(second)) ||
                !held.insert(HaloState<Exec>::key(first, second)).second)
                return;
            nextFirst.push_back(first);
            nextSecond.push_back(second);
            nextState.emplace_back(state, state + S);
        };
        for (const std::vector<double>& bond : arrivedBonds)
        {
            const int first = int(bond[0]), second = int(bond[1]);
            const int partner = ownedNow.count(first) ? second : first;
            partnerOwner[HaloState<Exec>::key(partner == second ? first : second, partner)] =
                int(bond[2]);
            hold(first, second, bond.data() + 3);
        }
        std::vector<double> state(S);
        for (std::size_t b = 0; b < bondCount; ++b)
        {
            for (int c = 0; c < S; ++c)
                state[c] = bondState[std::size_t(c) * bondCount + b];
            hold(bondFirst[b], bondSecond[b], state.data());
        }
    }
    std::unordered_map<int, std::vector<int>> bondRanks; //!< owned grain: its partners' owners
    for (std::size_t b = 0; b < nextFirst.size(); ++b)
        for (const int end : {nextFirst[b], nextSecond[b]})
        {
            const int partner = end == nextFirst[b] ? nextSecond[b] : nextFirst[b];
            if (!ownedNow.count(end) || ownedNow.count(partner))
                continue;
            const auto told = partnerOwner.find(HaloState<Exec>::key(end, partner));
            bondRanks[end].push_back(told != partnerOwner.end() ? told->second
                                                                : ownerOfOld(partner));
        }

    // 3. Ghosts afresh: each owned grain to every other rank whose box lies within reach, and
    // to the owners of its bond partners.
    // (the largest bounding radius as the cell grid measures it, of the grains before the move)
    const double reach =
        2.0 * comm.max(exec_.maxOf(n, BoundingRadiusOf{grains_.real(fRadius), halfLengths()})) +
        params_.neighbourSkin;
    HostGrains next;
    next.resize(ownedCount);
    std::vector<std::vector<double>> ghostSend(static_cast<std::size_t>(ranks));
    h.sentIds.assign(std::size_t(ranks), {});
    std::vector<int> near;
    for (int k = 0; k < ownedCount; ++k)
    {
        next.readRecord(owned.data() + std::size_t(k) * width, k);
        h.boxes.ranksNear(next.position(k, x), reach, me, near);
        if (bonded)
        {
            const auto extra = bondRanks.find(next.ints[fId][k]);
            if (extra != bondRanks.end())
                for (int r : extra->second)
                    if (r != me && std::find(near.begin(), near.end(), r) == near.end())
                        near.push_back(r);
        }
        for (int r : near)
        {
            ghostSend[r].insert(ghostSend[r].end(), owned.begin() + long(k) * width,
                                owned.begin() + long(k + 1) * width);
            h.sentIds[r].push_back(next.ints[fId][k]);
        }
    }
    const std::vector<std::vector<double>> ghosts = comm.exchange(ghostSend);
    int ghostCount = 0;
    for (const std::vector<double>& message : ghosts)
        ghostCount += int(message.size() / std::size_t(width));

    // 4. The new local set: owned, then ghosts by source rank; previous indices by id.
    HostGrains all;
    all.resize(ownedCount + ghostCount);
    for (int k = 0; k < ownedCount; ++k)
        all.readRecord(owned.data() + std::size_t(k) * width, k);
    h.ghostIds.assign(std::size_t(ranks), {});
    int slot = ownedCount;
    for (int r = 0; r < ranks; ++r)
        for (std::size_t at = 0; at < ghosts[r].size(); at += std::size_t(width), ++slot)
        {
            all.readRecord(ghosts[r].data() + at, slot);
            all.ints[fFlag][slot] = kFlagGhost;
            all.ints[fWallContacts][slot] = 0;
            all.reals[fImpulseX][slot] = 0.0;
            for (int c = 0; c < kWallStateComponents; ++c) // its owner sums the wall loads
            {
                all.reals[fWallState][std::size_t(slot) * kWallStateComponents + c] = 0.0;
                all.reals[fWallStateEnd][std::size_t(slot) * kWallStateComponents + c] = 0.0;
            }
            h.ghostIds[r].push_back(all.ints[fId][slot]);
        }
    h.previousBeforeSort.assign(std::size_t(all.n), INT_MAX / 2);
    for (int i = 0; i < all.n; ++i)
    {
        const auto found = oldIndex.find(all.ints[fId][i]);
        if (found != oldIndex.end())
            h.previousBeforeSort[i] = found->second;
    }
    grains_.resizeForImport(all.n);
    for (int f = 0; f < kRealFieldCount; ++f)
        grains_.setReal(f, all.reals[f]);
    for (int f = 0; f < kIntFieldCount; ++f)
        grains_.setInt(f, all.ints[f]);
    h.ghostCount = ghostCount;
    if (bonded)
    {
        std::vector<double> state(std::size_t(S) * nextFirst.size());
        for (std::size_t b = 0; b < nextFirst.size(); ++b)
            for (int c = 0; c < S; ++c)
                state[std::size_t(c) * nextFirst.size() + b] = nextState[b][std::size_t(c)];
        bonds_.assign(nextFirst, nextSecond, state); // indexed after the rebuild's sort
    }
    // One shape path on every rank: the per-step records have one width.
    if (comm.max(grains_.hasCapsules() ? 1.0 : 0.0) > 0.0)
        grains_.setCapsulePath(true);
}

template <class Exec>
void EngineImpl<Exec>::restoreArrivedHistories()
{
    HaloState<Exec>& h = *halo_;
    if (h.arrivedIds.empty())
        return;
    constexpr int H = 3 * kHistoryVectors;
    const std::vector<int> start = haloDetail::toHost(pairs_.start),
                           partner = haloDetail::toHost(pairs_.partner), id = grains_.hostInt(fId);
    std::vector<double> history = haloDetail::toHost(pairs_.history);
    const long count = long(partner.size());
    for (int i = 0; i < grains_.size(); ++i)
        for (long p = start[i]; p < start[i + 1]; ++p)
        {
            const int a = id[i], b = id[partner[p]];
            const bool aArrived = h.arrivedIds.count(a) > 0, bArrived = h.arrivedIds.count(b) > 0;
            if (!aArrived && !bArrived)
                continue;
            const typename HaloState<Exec>::History* found = nullptr;
            double sign = 1.0;
            if (aArrived)
            {
                const auto f = h.arrivedHistory.find(HaloState<Exec>::key(a, b));
                found = f == h.arrivedHistory.end() ? nullptr : &f->second;
            }
            if (!found && bArrived)
            {
                const auto f = h.arrivedHistory.find(HaloState<Exec>::key(b, a));
                found = f == h.arrivedHistory.end() ? nullptr : &f->second;
                sign = -1.0;
            }
            for (int c = 0; c < H; ++c)
                history[std::size_t(c) * count + p] = found ? sign * (*found)[c] : 0.0;
        }
    thrust::copy(history.begin(), history.end(), pairs_.history.begin());
    h.arrivedIds.clear();
    h.arrivedHistory.clear();
}

template <class Exec>
void EngineImpl<Exec>::indexGhostExchange()
{
    HaloState<Exec>& h = *halo_;
    const int ranks = h.comm->size(), n = grains_.size();
    const std::vector<int> id = grains_.hostInt(fId);
    std::unordered_map<int, int> internal;
    internal.reserve(std::size_t(n));
    for (int i = 0; i < n; ++i)
        internal[id[i]] = i;
    const int width = ghostsTurn() ? GhostStepState::kCapsuleWidth : GhostStepState::kSphereWidth;
    std::vector<int> sendIndex, receiveIndex;
    h.sendOffset.assign(1, 0);
    h.receiveOffset.assign(1, 0);
    h.receiveSizes.assign(std::size_t(ranks), 0);
    for (int r = 0; r < ranks; ++r)
    {
        std::sort(h.sentIds[r].begin(), h.sentIds[r].end());
        std::sort(h.ghostIds[r].begin(), h.ghostIds[r].end());
        for (int g : h.sentIds[r])
            sendIndex.push_back(internal.at(g));
        for (int g : h.ghostIds[r])
            receiveIndex.push_back(internal.at(g));
        h.sendOffset.push_back(long(sendIndex.size()));
        h.receiveOffset.push_back(long(receiveIndex.size()));
        h.receiveSizes[r] = long(h.ghostIds[r].size()) * width;
    }
    h.sendIndex.resize(sendIndex.size());
    thrust::copy(sendIndex.begin(), sendIndex.end(), h.sendIndex.begin());
    h.receiveIndex.resize(receiveIndex.size());
    thrust::copy(receiveIndex.begin(), receiveIndex.end(), h.receiveIndex.begin());
}

template <class Exec>
void EngineImpl<Exec>::refreshGhosts()
{
    HaloState<Exec>& h = *halo_;
    const int ranks = h.comm->size();
    const bool capsules = ghostsTurn();
    const int width = capsules ? GhostStepState::kCapsuleWidth : GhostStepState::kSphereWidth;
    const long sent = h.sendOffset.back(), received = h.receiveOffset.back();
    h.buffer.resize(std::size_t(std::max(sent, received)) * width);
    double* buffer = thrust::raw_pointer_cast(h.buffer.data());
    Exec::forEach(int(sent),
                  GhostStepState{grains_.view(), thrust::raw_pointer_cast(h.sendIndex.data()),
                                 buffer, width, capsules, false});
    h.hostBuffer.resize(std::size_t(sent) * width);
    thrust::copy(h.buffer.begin(), h.buffer.begin() + sent * width, h.hostBuffer.begin());
    std::vector<std::vector<double>> send(static_cast<std::size_t>(ranks));
    for (int r = 0; r < ranks; ++r)
        send[r].assign(h.hostBuffer.begin() + h.sendOffset[r] * width,
                       h.hostBuffer.begin() + h.sendOffset[r + 1] * width);
    const std::vector<std::vector<double>> in = h.comm->exchange(send, &h.receiveSizes);
    for (int r = 0; r < ranks; ++r)
        thrust::copy(in[r].begin(), in[r].end(), h.buffer.begin() + h.receiveOffset[r] * width);
    Exec::forEach(int(received),
                  GhostStepState{grains_.view(), thrust::raw_pointer_cast(h.receiveIndex.data()),
                                 buffer, width, capsules, true});
}

template <class Exec>
void EngineImpl<Exec>::exportHalo(SystemState& s) const
{
    const HaloState<Exec>& h = *halo_;
    s.integers["halo.decomposition"] = {h.comm->rank(), h.comm->size(),
                                        params_.decomposition.ranks[0],
                                        params_.decomposition.ranks[1]};
    s.integers["halo.counts"] = {h.addedGrains, h.ghostCount};
    s.reals["halo.bondCounts"] = {h.bondsFormed,    h.bondsBroken,    h.brokenCreep[0],
                                  h.brokenCreep[1], h.brokenCreep[2], h.brokenCreep[3]};
    auto lists = [&](const std::vector<std::vector<int>>& ids, const std::string& name)
    {
        std::vector<std::int64_t>& sizes = s.integers[name + "Counts"];
        std::vector<std::int64_t>& all = s.integers[name];
        for (const std::vector<int>& list : ids)
        {
            sizes.push_back(std::int64_t(list.size()));
            all.insert(all.end(), list.begin(), list.end());
        }
    };
    lists(h.sentIds, "halo.sentIds");
    lists(h.ghostIds, "halo.ghostIds");
}

template <class Exec>
void EngineImpl<Exec>::importHalo(const SystemState& s)
{
    const auto found = s.integers.find("halo.decomposition");
    if (!halo_)
    {
        if (found != s.integers.end())
            throw Error("importState: the state is one rank's part of a run decomposed over " +
                        std::to_string(found->second.at(1)) +
                        " MPI ranks; import it with the same Parameters::decomposition on as "
                        "many ranks");
        return;
    }
    HaloState<Exec>& h = *halo_;
    const std::vector<std::int64_t> expected = {h.comm->rank(), h.comm->size(),
                                                params_.decomposition.ranks[0],
                                                params_.decomposition.ranks[1]};
    if (found == s.integers.end() || found->second != expected)
        throw Error("importState: the state was not written by rank " +
                    std::to_string(h.comm->rank()) + " of this decomposition (" +
                    std::to_string(expected[2]) + " x " + std::to_string(expected[3]) +
                    " boxes); each rank imports the part it wrote, on the same decomposition");
    const std::vector<std::int64_t>& counts = stateDetail::entry(s.integers, "halo.counts");
    if (counts.size() != 2)
        throw Error("importState: 'halo.counts' must have 2 entries");
    h.addedGrains = counts[0];
    h.ghostCount = int(counts[1]);
    const std::vector<double>& bondCounts = stateDetail::entry(s.reals, "halo.bondCounts");
    if (bondCounts.size() != 6)
        throw Error("importState: 'halo.bondCounts' must have 6 entries");
    h.bondsFormed = bondCounts[0];
    h.bondsBroken = bondCounts[1];
    std::copy(bondCounts.begin() + 2, bondCounts.end(), h.brokenCreep.begin());
    auto lists = [&](std::vector<std::vector<int>>& ids, const std::string& name)
    {
        const std::vector<std::int64_t>& sizes = stateDetail::entry(s.integers, name + "Counts");
        const std::vector<std::int64_t>& all = stateDetail::entry(s.integers, name);
        if (sizes.size() != std::size_t(h.comm->size()))
            throw Error("importState: '" + name + "Counts' must have one entry per rank");
        ids.assign(sizes.size(), {});
        std::size_t at = 0;
        for (std::size_t r = 0; r < sizes.size(); ++r)
        {
            if (at + std::size_t(sizes[r]) > all.size())
                throw Error("importState: '" + name + "' is shorter than its counts");
            ids[r].assign(all.begin() + long(at), all.begin() + long(at + sizes[r]));
            at += std::size_t(sizes[r]);
        }
    };
    lists(h.sentIds, "halo.sentIds");
    lists(h.ghostIds, "halo.ghostIds");
    if (grainsAtLastBuild_ == grains_.size()) // the lists as they were (else the next step's
        indexGhostExchange();                 // rebuild makes them)
}

} // namespace detail
} // namespace dem

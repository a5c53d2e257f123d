// EngineGatheredState.h
// A decomposed system and one process's state, both ways:
//   - exportGatheredState: the system decomposed over MPI ranks as one process's state on
//     rank 0, so that a run continues on one process from a time whose parts were written by
//     the ranks (OpenFOAM's reconstructPar gives the fields; this gives the grains' state);
//   - importWholeState: one process's state into a decomposed system (a run decomposed
//     afresh): rank 0 takes every grain as its own with the state's pair list and bonds, the
//     other ranks none, and the first step's rebuild sends each grain to its owner with the
//     history of each of its pairs and its bonds, as it moves any grain that left its box.
//
// The gather:
// Each rank sends rank 0 its owned grains (every state field, as exportState holds them), the
// contact history of each listed pair whose lower-id grain it owns (the owner of a grain
// lists every pair of that grain, so each pair is sent once, by one rank), and the bonds it
// reports (those whose first grain it owns). Rank 0 orders the grains by id, lists each pair
// under its lower-id grain (the half list's owner < partner, with the history as seen from
// that grain: the reverse view is its negative, as TransferHistory and the migration use it),
// and asks for a rebuild at the next step, which carries every history over to the fresh
// list. Walls and clock are the same on every rank; the bond totals are summed over them.
#pragma once

#include <algorithm>
#include <cstdint>
#include <unordered_map>

namespace dem
{
namespace detail
{

template <class Exec>
SystemState EngineImpl<Exec>::exportGatheredState() const
{
    if (!halo_)
        return exportState();
    const Communicator& comm = *halo_->comm;
    constexpr int H = 3 * kHistoryVectors;
    const bool bonded = params_.bonds.enabled;
    const BondCounts bondTotals = bonded ? decomposedBondCounts() : BondCounts{}; // collective
    const SystemState own = exportState();
    const int n = grains_.size();

    using haloDetail::HostGrains;
    HostGrains local = HostGrains::of(grains_);
    const std::vector<int>& flag = local.ints[fFlag];
    const std::vector<int>& id = local.ints[fId];
    std::unordered_map<std::int64_t, int> localIndex;
    for (int i = 0; i < n; ++i)
        localIndex[id[i]] = i;
    auto owns = [&](std::int64_t grainId)
    {
        const auto found = localIndex.find(grainId);
        return found != localIndex.end() && flag[found->second] != kFlagGhost;
    };

    // This rank's part: counts, then grain records (HostGrains: every field), pair records
    // (lower id, upper id, the history seen from the lower), bond records (first, second, the
    // bond's fields).
    std::vector<double> part(3, 0.0);
    for (int i = 0; i < n; ++i)
        if (flag[i] != kFlagGhost)
        {
            local.appendRecord(i, part);
            part[0] += 1;
        }
    const std::vector<std::int64_t>& start = own.integers.at("pairs.start");
    if (long(start.size()) == n + 1) // else no list was built yet: no history to keep
    {
        const std::vector<std::int64_t>& partner = own.integers.at("pairs.partner");
        const std::vector<double>& history = own.reals.at("pairs.history");
        const std::size_t count = partner.size();
        for (int i = 0; i < n; ++i)
            for (std::int64_t p = start[i]; p < start[i + 1]; ++p)
            {
                const std::int64_t a = id[i], b = id[partner[p]];
                const std::int64_t lower = std::min(a, b);
                if (!owns(lower))
                    continue;
                const double sign = a == lower ? 1.0 : -1.0;
                part.insert(part.end(), {double(lower), double(std::max(a, b))});
                for (int c = 0; c < H; ++c)
                    part.push_back(sign * history[std::size_t(c) * count + std::size_t(p)]);
                part[1] += 1;
            }
    }
    if (bonded)
    {
        const std::vector<std::int64_t>& first = own.integers.at("bonds.first");
        const std::vector<std::int64_t>& second = own.integers.at("bonds.second");
        const std::size_t count = first.size();
        for (std::size_t b = 0; b < count; ++b)
        {
            if (!owns(first[b]))
                continue;
            part.insert(part.end(), {double(first[b]), double(second[b])});
            for (const BondField& f : bondFields())
                for (int c = 0; c < f.components; ++c)
                    part.push_back(own.reals.at(std::string("bonds.") + f.name)[c * count + b]);
            part[2] += 1;
        }
    }

    std::vector<std::vector<double>> send(std::size_t(comm.size()));
    if (comm.rank() != 0)
        send[0] = std::move(part);
    std::vector<std::vector<double>> parts = comm.exchange(send);
    if (comm.rank() != 0)
        return SystemState{};
    parts[0] = std::move(part);

    // Rank 0: the records of all ranks, read back in the order they were written.
    const int grainWidth = HostGrains::recordWidth(), idAt = HostGrains::idOffset();
    int bondWidth = 2;
    for (const BondField& f : bondFields())
        bondWidth += f.components;
    std::vector<const double*> grainRecords, pairRecords, bondRecords;
    for (const std::vector<double>& r : parts)
    {
        if (r.empty())
            continue;
        const double* at = r.data() + 3;
        for (long k = 0; k < long(r[0]); ++k, at += grainWidth)
            grainRecords.push_back(at);
        for (long k = 0; k < long(r[1]); ++k, at += 2 + H)
            pairRecords.push_back(at);
        for (long k = 0; k < long(r[2]); ++k, at += bondWidth)
            bondRecords.push_back(at);
    }
    auto byKeys = [](int first, int keys)
    {
        return [first, keys](const double* a, const double* b) {
            return std::lexicographical_compare(a + first, a + first + keys, b + first,
                                                b + first + keys);
        };
    };
    std::sort(grainRecords.begin(), grainRecords.end(), byKeys(idAt, 1));
    std::sort(pairRecords.begin(), pairRecords.end(), byKeys(0, 2));
    std::sort(bondRecords.begin(), bondRecords.end(), byKeys(0, 2));

    // The grains in id order, their fields laid out as exportState lays them out.
    SystemState s;
    const int total = int(grainRecords.size());
    HostGrains all;
    all.resize(total);
    std::unordered_map<std::int64_t, int> index;
    for (int i = 0; i < total; ++i)
    {
        all.readRecord(grainRecords[i], i);
        index[std::int64_t(grainRecords[i][idAt])] = i;
    }
    for (int f = 0; f < kRealFieldCount; ++f)
        if (!realFieldInfo(f).transient)
            s.reals[std::string("grain.") + realFieldInfo(f).name] = all.reals[f];
    for (int f = 0; f < kIntFieldCount; ++f)
        s.integers[std::string("grain.") + intFieldInfo(f).name].assign(all.ints[f].begin(),
                                                                        all.ints[f].end());

    // The pairs under their lower index (ids and indices in the same order), and the
    // transposed list.
    const std::size_t pairCount = pairRecords.size();
    std::vector<std::int64_t>& pairStart = s.integers["pairs.start"];
    std::vector<std::int64_t>& partner = s.integers["pairs.partner"];
    std::vector<double>& history = s.reals["pairs.history"];
    pairStart.assign(std::size_t(total) + 1, 0);
    partner.resize(pairCount);
    history.assign(std::size_t(H) * pairCount, 0.0);
    std::vector<std::int64_t> incomingCount(std::size_t(total) + 1, 0);
    for (std::size_t p = 0; p < pairCount; ++p)
    {
        const int owner = index.at(std::int64_t(pairRecords[p][0]));
        const int other = index.at(std::int64_t(pairRecords[p][1]));
        ++pairStart[std::size_t(owner) + 1];
        ++incomingCount[std::size_t(other) + 1];
        partner[p] = other;
        for (int c = 0; c < H; ++c)
            history[std::size_t(c) * pairCount + p] = pairRecords[p][2 + c];
    }
    for (int i = 0; i < total; ++i)
    {
        pairStart[std::size_t(i) + 1] += pairStart[std::size_t(i)];
        incomingCount[std::size_t(i) + 1] += incomingCount[std::size_t(i)];
    }
    s.integers["pairs.incomingStart"] = incomingCount;
    std::vector<std::int64_t>& incomingPair = s.integers["pairs.incomingPair"];
    incomingPair.resize(pairCount);
    std::vector<std::int64_t> next(incomingCount.begin(), incomingCount.end() - 1);
    for (std::size_t p = 0; p < pairCount; ++p)
        incomingPair[std::size_t(next[std::size_t(partner[p])]++)] = std::int64_t(p);

    for (const char* key : {"walls.real", "clock", "bonds.brokenCreep"})
        if (own.reals.count(key))
            s.reals[key] = own.reals.at(key);
    for (const char* key : {"walls.int", "walls.layout", "pairs.historyLayout"})
        s.integers[key] = own.integers.at(key);
    // steps, rebuilds, grains at the last build (the list above), a rebuild at the next step
    // (it sorts the grains and carries the histories over), forces stale, grain count
    const std::vector<std::int64_t>& counters = own.integers.at("counters");
    s.integers["counters"] = {counters[0], counters[1], total, 1, counters[4], total};

    if (bonded)
    {
        const std::size_t count = bondRecords.size();
        std::vector<std::int64_t>& first = s.integers["bonds.first"];
        std::vector<std::int64_t>& second = s.integers["bonds.second"];
        for (const double* r : bondRecords)
        {
            first.push_back(std::int64_t(r[0]));
            second.push_back(std::int64_t(r[1]));
        }
        int offset = 2;
        for (const BondField& f : bondFields())
        {
            std::vector<double>& v = s.reals[std::string("bonds.") + f.name];
            v.assign(std::size_t(f.components) * count, 0.0);
            for (std::size_t b = 0; b < count; ++b)
                for (int c = 0; c < f.components; ++c)
                    v[c * count + b] = bondRecords[b][offset + c];
            offset += f.components;
        }
        s.integers["bonds.counters"] = {std::int64_t(bondTotals.formed),
                                        std::int64_t(bondTotals.broken)};
        s.reals["bonds.brokenCreep"].assign(bondTotals.brokenCreep.begin(),
                                            bondTotals.brokenCreep.end());
    }
    return s;
}

template <class Exec>
void EngineImpl<Exec>::importWholeState(const SystemState& whole)
{
    using namespace stateDetail;
    const HaloState<Exec>& h = *halo_;
    const int me = h.comm->rank(), ranks = h.comm->size();
    const std::vector<std::int64_t>& counters = entry(whole.integers, "counters"); // 6, checked
    const std::int64_t total = counters[5];
    SystemState s = whole;
    s.integers["halo.decomposition"] = {me, ranks, params_.decomposition.ranks[0],
                                        params_.decomposition.ranks[1]};
    s.integers["halo.counts"] = {total, 0}; // ids 0 .. total-1 taken; no ghosts yet
    for (const char* lists : {"halo.sentIds", "halo.ghostIds"})
    {
        s.integers[std::string(lists) + "Counts"].assign(std::size_t(ranks), 0);
        s.integers[lists].clear();
    }
    // Bond totals: rank 0's share is the whole's (bondCounts sums the ranks' shares)
    std::vector<double> bondShare(6, 0.0);
    const auto bondCounters = whole.integers.find("bonds.counters");
    const auto brokenCreep = whole.reals.find("bonds.brokenCreep");
    if (me == 0 && bondCounters != whole.integers.end() && bondCounters->second.size() == 2)
    {
        bondShare[0] = double(bondCounters->second[0]);
        bondShare[1] = double(bondCounters->second[1]);
        if (brokenCreep != whole.reals.end() && brokenCreep->second.size() == 4)
            std::copy(brokenCreep->second.begin(), brokenCreep->second.end(),
                      bondShare.begin() + 2);
    }
    s.reals["halo.bondCounts"] = bondShare;
    // a rebuild at the first step: it moves the grains to their owners
    s.integers["counters"] = {counters[0], counters[1], me == 0 ? counters[2] : 0,
                              1,           counters[4], me == 0 ? total : 0};
    if (me != 0) // no grains, no pairs, no bonds here until the first rebuild
    {
        for (auto& [name, values] : s.reals)
            if (name.rfind("grain.", 0) == 0 || name.rfind("bonds.", 0) == 0 ||
                name == "pairs.history")
                values.clear();
        for (auto& [name, values] : s.integers)
            if (name.rfind("grain.", 0) == 0 || name.rfind("bonds.", 0) == 0 ||
                name == "pairs.partner" || name == "pairs.incomingPair")
                values.clear();
        s.integers["pairs.start"] = {0};
        s.integers["pairs.incomingStart"] = {0};
        if (s.integers.count("bonds.first"))
            s.integers["bonds.counters"] = {0, 0};
        if (s.reals.count("bonds.brokenCreep"))
            s.reals["bonds.brokenCreep"].assign(4, 0.0);
    }
    importState(s);
}

} // namespace detail
} // namespace dem

// HaloState.h
// What an engine run over MPI ranks (Parameters::decomposition) keeps besides its grains: the
// communicator, the ranks' boxes, which of its grains other ranks hold as ghosts and which of
// its ghosts come from where (both in grain-id order, so the two sides agree), and the contact
// histories that arrived with migrating grains. EngineHalo.h uses it.
#pragma once

#include "engine/Communicator.h"
#include "engine/RankBoxes.h"
#include "kernels/Views.h"

#include <thrust/copy.h>

#include <array>
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace dem
{
namespace detail
{

namespace haloDetail
{
//- A host copy of a backend vector.
template <class V>
std::vector<typename V::value_type> toHost(const V& v)
{
    std::vector<typename V::value_type> h(v.size());
    thrust::copy(v.begin(), v.end(), h.begin());
    return h;
}
} // namespace haloDetail

template <class Exec>
struct HaloState
{
    template <class T>
    using Vec = typename Exec::template Vector<T>;
    using History = std::array<double, 3 * kHistoryVectors>;

    std::unique_ptr<Communicator> comm;
    RankBoxes boxes;
    long long addedGrains = 0; //!< over all ranks: the next grain's id
    int ghostCount = 0;
    //- Per rank: ids of this rank's grains that rank keeps as ghosts / of the ghosts it sent here.
    std::vector<std::vector<int>> sentIds, ghostIds;
    //- The per-step exchange: internal indices to send (by rank, id order) and to fill.
    std::vector<long> sendOffset, receiveOffset, receiveSizes;
    Vec<int> sendIndex, receiveIndex;
    Vec<double> buffer;
    std::vector<double> hostBuffer;
    //- The grains' previous internal index (before the rebuild's sort; large: new here) and
    //- the same after it, for TransferHistory.
    std::vector<int> previousBeforeSort;
    Vec<int> previous;
    //- Histories of the pairs of grains that arrived this rebuild, from their old owner,
    //- keyed (id of the arrived grain, id of its partner), as the arrived grain's own.
    std::unordered_map<std::uint64_t, History> arrivedHistory;
    std::unordered_set<int> arrivedIds;
    //- Bonds formed and broken here since the System was built, each bond held by two ranks
    //- counted half (BondRankShare): summed over the ranks, the counts.
    double bondsFormed = 0.0, bondsBroken = 0.0;
    std::array<double, 4> brokenCreep = {}; //!< creep of the broken bonds, by share

    static std::uint64_t key(int a, int b)
    {
        return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b);
    }
};

} // namespace detail
} // namespace dem

// EngineNeighbours.h
// Neighbour rebuild of EngineImpl: wrap into the periodic box, sort grains by cell (locality,
// and the cell ranges the search walks), build the half list and its transpose, and carry
// every contact's history over from the previous list.
#pragma once

#include <thrust/count.h>
#include <thrust/reduce.h>

#include <limits>

namespace dem
{
namespace detail
{

template <class Exec>
CellGridView EngineImpl<Exec>::cellGrid()
{
    const int n = grains_.size();
    // One cell size for all: the largest bounding radius (radius + coreHalfLength) of any grain,
    // doubled, plus the skin, so that every listed pair lies in neighbouring cells. Mixed sizes
    // make the cells as large as the largest grain needs (small grains then test more
    // candidates, never miss one).
    const double rMax = exec_.maxOf(n, BoundingRadiusOf{grains_.real(fRadius), halfLengths()});
    const BoxView box = boxView();
    double lower[3], upper[3];
    for (int d = 0; d < 3; ++d)
    {
        const double* x = grains_.real(fPosition) + long(d) * n;
        lower[d] = thrust::reduce(exec_.policy(), x, x + n, std::numeric_limits<double>::infinity(),
                                  MinOp());
        upper[d] = thrust::reduce(exec_.policy(), x, x + n,
                                  -std::numeric_limits<double>::infinity(), MaxOp());
    }
    double cellSize = 2.0 * rMax + params_.neighbourSkin;
    // Grains spread over more than 1e8 cells of one diameter are not a packing but a blown-up
    // step; binned, their image and cell indices would overflow an int. (Called before the
    // wrap into the periodic box, so the periodic sides are measured too.)
    for (int d = 0; d < 3; ++d)
        if (!(upper[d] - lower[d] <= 1e8 * cellSize))
            throwLeftTheNumbers();
    for (int d = 0; d < 2; ++d)
        if (box.periodic[d] && box.length[d] < 2.0 * cellSize)
            throw Error("periodic box length " + std::to_string(box.length[d]) + " m in " +
                        (d == 0 ? "x" : "y") + " is below 2 (2 b_max + neighbourSkin) = " +
                        std::to_string(2.0 * cellSize) +
                        " m (b_max: the largest radius + coreHalfLength); a grain would meet "
                        "two images of another");
    // Few, large cells when grains are spread thin (a gas): the search stays correct.
    const double cellLimit = 4.0 * n + 64.0;
    for (;;)
    {
        CellGridView cells;
        double total = 1.0;
        for (int d = 0; d < 3; ++d)
        {
            cells.periodic[d] = box.periodic[d];
            if (box.periodic[d])
            {
                cells.n[d] = std::max(1, int(std::floor(box.length[d] / cellSize)));
                cells.lower[d] = box.lower[d];
                cells.inverseCellSize[d] = cells.n[d] / box.length[d];
            }
            else
            {
                cells.n[d] = int(std::floor((upper[d] - lower[d]) / cellSize)) + 1;
                cells.lower[d] = lower[d];
                cells.inverseCellSize[d] = 1.0 / cellSize;
            }
            total *= cells.n[d];
        }
        if (total <= cellLimit)
        {
            cells.orderCells();
            return cells;
        }
        cellSize *= 1.5;
    }
}

template <class Exec>
void EngineImpl<Exec>::rebuild()
{
    if (halo_)
    {
        redistribute();
        if (grains_.size() == 0) // nothing near this rank's box: an empty list
        {
            pairs_.swap(oldPairs_);
            pairs_.start.assign(1, 0);
            pairs_.incomingStart.assign(1, 0);
            pairs_.owner.clear();
            pairs_.partner.clear();
            pairs_.incomingPair.clear();
            pairs_.history.clear();
            pairs_.sizeLoads(reactionComponents());
            grainsAtLastBuild_ = 0;
            needRebuild_ = false;
            ++rebuilds_;
            indexGhostExchange();
            return;
        }
    }
    const int n = grains_.size();
    const BoxView box = boxView();
    // The grid before the wrap: its bounds on the non-periodic sides do not change with it,
    // and a blown-up step is caught before image counts overflow (see cellGrid).
    CellGridView cells = cellGrid();
    Exec::forEach(n, WrapIntoBox{grains_.vec3(fPosition), grains_.vec3(fVelocity),
                                 grains_.integer(fImage), box, n});
    boxLengthAtBuild_ = {box.length[0], box.length[1]};

    // Sort by cell: grains of a cell become contiguous and neighbours close in memory.
    const int cellCount = cells.n[0] * cells.n[1] * cells.n[2];
    cellKey_.resize(n);
    order_.resize(n);
    Exec::forEach(
        n, CellKey{grains_.vec3(fPosition), cells, thrust::raw_pointer_cast(cellKey_.data())});
    thrust::sequence(exec_.policy(), order_.begin(), order_.end());
    thrust::stable_sort_by_key(exec_.policy(), cellKey_.begin(), cellKey_.end(), order_.begin());
    grains_.permute(exec_.policy(), order_);
    cellStart_.resize(cellCount + 1);
    thrust::lower_bound(exec_.policy(), cellKey_.begin(), cellKey_.end(),
                        thrust::counting_iterator<int>(0),
                        thrust::counting_iterator<int>(cellCount + 1), cellStart_.begin());
    cells.cellStart = thrust::raw_pointer_cast(cellStart_.data());

    // Half list (owner < partner): count, scan, fill.
    pairs_.swap(oldPairs_);
    const NeighbourSearch search{grains_.vec3(fPosition),
                                 grains_.real(fRadius),
                                 halfLengths(),
                                 box,
                                 cells,
                                 params_.neighbourSkin,
                                 grains_.real(fOrientation),
                                 n};
    counts_.resize(n + 1);
    int* counts = thrust::raw_pointer_cast(counts_.data());
    counts_[n] = 0;
    Exec::forEach(n, CountNeighbours{search, true, counts});
    pairs_.start.resize(n + 1);
    thrust::exclusive_scan(exec_.policy(), counts_.begin(), counts_.end(), pairs_.start.begin());
    const long pairCount = pairs_.start[n];
    if (params_.maxPairsPerGrain > 0 && pairCount > long(params_.maxPairsPerGrain) * n)
    {
        std::ostringstream msg;
        msg << "contact storage overflow: " << pairCount << " neighbour pairs for " << n
            << " grains exceed maxPairsPerGrain = " << params_.maxPairsPerGrain
            << " per grain (limit " << long(params_.maxPairsPerGrain) * n
            << "); raise maxPairsPerGrain or set it to 0 to let the storage grow";
        pairs_.swap(oldPairs_);
        throw Error(msg.str());
    }
    pairs_.owner.resize(pairCount);
    pairs_.partner.resize(pairCount);
    pairs_.history.resize(3 * kHistoryVectors * pairCount);
    pairs_.sizeLoads(reactionComponents()); // the records are filled by the force pass
    Exec::forEach(n, FillOwnedPairs{search, thrust::raw_pointer_cast(pairs_.start.data()),
                                    thrust::raw_pointer_cast(pairs_.owner.data()),
                                    thrust::raw_pointer_cast(pairs_.partner.data())});

    // The previous index of each grain: its index before the sort, or over MPI ranks the one it
    // had before redistribute (large for a grain new here).
    const int* previous = thrust::raw_pointer_cast(order_.data());
    if (halo_)
    {
        halo_->previous.resize(n);
        const std::vector<int>& before = halo_->previousBeforeSort;
        std::vector<int> sorted = haloDetail::toHost(order_);
        for (int& i : sorted)
            i = before[std::size_t(i)];
        thrust::copy(sorted.begin(), sorted.end(), halo_->previous.begin());
        previous = thrust::raw_pointer_cast(halo_->previous.data());
    }
    Exec::forEach(n,
                  TransferHistory{pairs_.view(), oldPairs_.view(), previous, grainsAtLastBuild_});
    if (halo_)
        restoreArrivedHistories();

    // Transposed list: for each grain the pairs it is the partner of.
    Exec::forEach(n, CountNeighbours{search, false, counts});
    counts_[n] = 0;
    pairs_.incomingStart.resize(n + 1);
    thrust::exclusive_scan(exec_.policy(), counts_.begin(), counts_.end(),
                           pairs_.incomingStart.begin());
    if (long(pairs_.incomingStart[n]) != pairCount)
        throw Error("internal error: neighbour lists disagree (" + std::to_string(pairCount) +
                    " owned vs " + std::to_string(long(pairs_.incomingStart[n])) + " incoming)");
    pairs_.incomingPair.resize(pairCount);
    Exec::forEach(n, FillIncomingPairs{search, thrust::raw_pointer_cast(pairs_.start.data()),
                                       thrust::raw_pointer_cast(pairs_.partner.data()),
                                       thrust::raw_pointer_cast(pairs_.incomingStart.data()),
                                       thrust::raw_pointer_cast(pairs_.incomingPair.data())});
    // GatherKick reads every entry without a check.
    if (thrust::count(exec_.policy(), pairs_.incomingPair.begin(), pairs_.incomingPair.end(), -1))
        throw Error("internal error: a neighbour pair is missing from the transposed list");

    const double* x = grains_.real(fPosition);
    thrust::copy(exec_.policy(), x, x + 3L * n, grains_.real(fPositionAtBuild));
    if (grains_.hasCapsules())
        Exec::forEach(n, StoreHalfAxisAtBuild{grains_.view()});
    Exec::forEach(n, PackGrains{grains_.view()});
    grainsAtLastBuild_ = n;
    needRebuild_ = false;
    ++rebuilds_;
    if (params_.bonds.enabled)
        indexBonds();
    if (halo_)
        indexGhostExchange();
}

} // namespace detail
} // namespace dem

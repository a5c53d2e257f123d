// NeighbourKernels.h
// Neighbour search on a uniform cell grid: grains are sorted by cell (cellStart[c] is the first
// grain of cell c), pairs whose centres are closer than b_i + b_j + skin are candidates (b =
// radius + coreHalfLength, the bounding radius: a grain lies within b of its centre), and of
// those, with capsules, the pairs whose cores come closer than r_i + r_j + skin are listed, once,
// owned by the lower index. Count and fill kernels share one traversal, so their results always
// agree. The history transfer keeps each contact's tangential spring across rebuilds and
// re-sorting.
#pragma once

#include "kernels/CapsuleGeometry.h"
#include "kernels/Views.h"

#include <cmath>
#include <utility>

namespace dem
{
namespace detail
{
inline namespace DEM_KERNEL_NS
{

struct CellGridView
{
    double lower[3] = {0, 0, 0};
    double inverseCellSize[3] = {1, 1, 1};
    int n[3] = {1, 1, 1};
    //- Linear cell index = sum of coordinate * stride, set by orderCells(): the direction with
    //- the fewest cells varies fastest, so that a flat bed's neighbour cells (and the grains,
    //- sorted by cell) lie closer in memory than with z slowest. Measured on the benchmark's
    //- 100,000-grain bed (70 x 70 x 18 cells), one thread: 6 % faster.
    int stride[3] = {0, 0, 0};
    bool periodic[3] = {false, false, false};
    const int* cellStart = nullptr; //!< cellCount + 1 entries

    //- Strides from the cell counts: fastest the direction with the fewest cells, slowest the
    //- one with the most (ties in x, y, z order).
    void orderCells()
    {
        int order[3] = {0, 1, 2};
        for (int a = 0; a < 3; ++a)
            for (int b = a + 1; b < 3; ++b)
                if (n[order[b]] < n[order[a]])
                    std::swap(order[a], order[b]);
        int s = 1;
        for (int k = 0; k < 3; ++k)
        {
            stride[order[k]] = s;
            s *= n[order[k]];
        }
    }

    DEM_HD int coordinate(double x, int d) const
    {
        int c = int(std::floor((x - lower[d]) * inverseCellSize[d]));
        if (periodic[d])
        {
            c %= n[d];
            return c < 0 ? c + n[d] : c;
        }
        return c < 0 ? 0 : (c >= n[d] ? n[d] - 1 : c);
    }
    //- The number of the cell at cell coordinates (cx, cy, cz).
    DEM_HD int cellAt(int cx, int cy, int cz) const
    {
        return cx * stride[0] + cy * stride[1] + cz * stride[2];
    }
    DEM_HD int cellOf(const Vector3d& x) const
    {
        return cellAt(coordinate(x.x(), 0), coordinate(x.y(), 1), coordinate(x.z(), 2));
    }

    //- Call visit(j) for every grain j in the cells around x (each cell once) that can hold
    //- grains of higher index than one in x's own cell (higher: the cells numbered not below
    //- it) or of lower index (the cells not above it): the grains are sorted by cell, so a
    //- one-sided search (NeighbourSearch::forEachNeighbour) skips about half of the 27 cells.
    template <class Visit>
    DEM_HD void forEachNearbyGrain(const Vector3d& x, bool higher, Visit&& visit) const
    {
        int centre[3], first[3], last[3];
        for (int d = 0; d < 3; ++d)
        {
            centre[d] = coordinate(x[d], d);
            if (periodic[d])
            {
                first[d] = n[d] >= 3 ? -1 : 0; // fewer than 3 cells: visit each once
                last[d] = n[d] >= 2 ? 1 : 0;
            }
            else
            {
                first[d] = centre[d] > 0 ? -1 : 0;
                last[d] = centre[d] < n[d] - 1 ? 1 : 0;
            }
        }
        const int own = cellAt(centre[0], centre[1], centre[2]);
        for (int dz = first[2]; dz <= last[2]; ++dz)
            for (int dy = first[1]; dy <= last[1]; ++dy)
                for (int dx = first[0]; dx <= last[0]; ++dx)
                {
                    const int cell =
                        cellAt(wrap(centre[0] + dx, 0), wrap(centre[1] + dy, 1), centre[2] + dz);
                    if (higher ? cell < own : cell > own)
                        continue;
                    for (int j = cellStart[cell]; j < cellStart[cell + 1]; ++j)
                        visit(j);
                }
    }

    DEM_HD int wrap(int c, int d) const
    {
        if (!periodic[d])
            return c;
        return c < 0 ? c + n[d] : (c >= n[d] ? c - n[d] : c);
    }
};

//- Wrap positions into the periodic box, counting the images crossed (for displacements).
//- Across a deforming side (BoxView::lengthRate) the image one box length away moves with
//- the rate: a grain that crosses takes its image's velocity (v - shift rate), so that its
//- neighbours on the other side see it as before (a deforming periodic cell's velocity field,
//- v(x + L) = v(x) + dL/dt).
struct WrapIntoBox
{
    Vec3Array position;
    Vec3Array velocity;
    int* image; //!< 2 components (x, y)
    BoxView box;
    int n;

    DEM_HD void operator()(int i) const
    {
        for (int d = 0; d < 2; ++d)
        {
            if (!box.periodic[d])
                continue;
            double& x = position.data[i + d * position.stride];
            const double shift = std::floor((x - box.lower[d]) / box.length[d]);
            if (shift != 0.0)
            {
                x -= shift * box.length[d];
                velocity.data[i + d * velocity.stride] -= shift * box.lengthRate[d];
                image[i + d * n] += int(shift);
            }
        }
    }
};

struct CellKey
{
    Vec3Array position;
    CellGridView cells;
    int* key;

    DEM_HD void operator()(int i) const { key[i] = cells.cellOf(position(i)); }
};

//- Bounding radius of grain i: radius + coreHalfLength (coreHalfLength nullptr: spheres).
DEM_HD double boundingRadius(const double* radius, const double* coreHalfLength, int i)
{
    return coreHalfLength ? radius[i] + coreHalfLength[i] : radius[i];
}

//- max(0, bounding radius) over the grains (Exec::maxOf).
struct BoundingRadiusOf
{
    const double* radius;
    const double* coreHalfLength;
    DEM_HD double operator()(int i) const { return boundingRadius(radius, coreHalfLength, i); }
};

//- Shared neighbour test: higher = true lists partners j > i, false lists j < i.
struct NeighbourSearch
{
    Vec3Array position;
    const double* radius;
    const double* coreHalfLength; //!< nullptr in a system of spheres
    BoxView box;
    CellGridView cells;
    double skin;
    //- Orientations (4 blocked components of n grains; with coreHalfLength): the cores' own
    //- distance prunes pairs whose bounding spheres meet but whose cores stay apart. Valid for
    //- the list's lifetime because a rebuild comes before any core point has moved skin/2
    //- (endsMoved2), so two cores approach by less than skin. An aspect-3 capsule packing has
    //- about half as many pairs that way as bounding spheres give, each a pair-kernel evaluation
    //- every step; the pairs dropped could not have touched, so the results are the same bits.
    const double* orientation = nullptr;
    int n = 0;

    DEM_HD Vector3d halfAxis(int i) const
    {
        const double w = orientation[i], x = orientation[i + n], y = orientation[i + 2L * n],
                     z = orientation[i + 3L * n];
        return coreHalfLength[i] *
               Vector3d(2.0 * (x * z + w * y), 2.0 * (y * z - w * x), 1.0 - 2.0 * (x * x + y * y));
    }

    //- Whether the cores of grains lo < hi come within r_lo + r_hi + skin. Always evaluated
    //- with the lower index first, so the owner's and the partner's traversals agree bit for bit.
    DEM_HD bool coresNear(int lo, int hi) const
    {
        const Vector3d d = box.separation(position(lo), position(hi));
        const Vector3d alo = halfAxis(lo), ahi = halfAxis(hi);
        double ulo, uhi;
        closestSegmentParameters(alo, ahi, d, ulo, uhi);
        // 1e-9 relative: the pair kernel computes the half-axes through Eigen's rotation, whose
        // last bits may differ from these; a pair at contact within round-off stays listed.
        const double reach = (radius[lo] + radius[hi] + skin) * (1.0 + 1e-9);
        return (d + uhi * ahi - ulo * alo).squaredNorm() < reach * reach;
    }

    template <class Visit>
    DEM_HD void forEachNeighbour(int i, bool higher, Visit&& visit) const
    {
        const Vector3d x = position(i);
        const double ri = boundingRadius(radius, coreHalfLength, i);
        cells.forEachNearbyGrain(
            x, higher,
            [&](int j)
            {
                if (higher ? j <= i : j >= i)
                    return;
                const double cutoff = (ri + boundingRadius(radius, coreHalfLength, j)) + skin;
                if (box.separation(x, position(j)).squaredNorm() >= cutoff * cutoff)
                    return;
                if (coreHalfLength && !(i < j ? coresNear(i, j) : coresNear(j, i)))
                    return;
                visit(j);
            });
    }
};

struct CountNeighbours
{
    NeighbourSearch search;
    bool higher;
    int* count;

    DEM_HD void operator()(int i) const
    {
        int c = 0;
        search.forEachNeighbour(i, higher, [&](int) { ++c; });
        count[i] = c;
    }
};

struct FillOwnedPairs
{
    NeighbourSearch search;
    const int* start;
    int* owner;
    int* partner;

    DEM_HD void operator()(int i) const
    {
        int p = start[i];
        search.forEachNeighbour(i, true,
                                [&](int j)
                                {
                                    owner[p] = i;
                                    partner[p++] = j;
                                });
    }
};

//- Each pair's owner from the CSR starts (after an import).
struct FillOwners
{
    const int* start;
    int* owner;

    DEM_HD void operator()(int i) const
    {
        for (int p = start[i]; p < start[i + 1]; ++p)
            owner[p] = i;
    }
};

//- For grain j, the indices of the pairs (owned by lower grains) in which it is the partner.
struct FillIncomingPairs
{
    NeighbourSearch search;
    const int* start;
    const int* partner;
    const int* incomingStart;
    int* incomingPair;

    DEM_HD void operator()(int j) const
    {
        int q = incomingStart[j];
        search.forEachNeighbour(j, false,
                                [&](int i)
                                {
                                    int found = -1;
                                    for (int p = start[i]; p < start[i + 1]; ++p)
                                        if (partner[p] == j)
                                            found = p;
                                    incomingPair[q++] = found;
                                });
    }
};

//- Copy each new pair's history from the old list (before re-sorting; previous[i] is the old
//- index of new grain i). A pair owned by the other grain before has its history negated.
struct TransferHistory
{
    PairView pairs;    //!< the new list
    PairView oldPairs; //!< the previous list
    const int* previous;
    int previousGrains;

    DEM_HD void operator()(int i) const
    {
        const int oi = previous[i];
        for (int p = pairs.start[i]; p < pairs.start[i + 1]; ++p)
        {
            const int oj = previous[pairs.partner[p]];
            long found = -1;
            double sign = 1.0;
            if (oi < previousGrains && oj < previousGrains)
            {
                found = find(oi, oj);
                if (found < 0)
                {
                    found = find(oj, oi);
                    sign = -1.0;
                }
            }
            double* h = pairs.historyOf(p);
            const double* oldH = found < 0 ? nullptr : oldPairs.historyOf(found);
            for (int c = 0; c < 3 * kHistoryVectors; ++c)
                h[c * pairs.historyStride()] =
                    oldH ? sign * oldH[c * oldPairs.historyStride()] : 0.0;
        }
    }

    DEM_HD long find(int owner, int other) const
    {
        for (int p = oldPairs.start[owner]; p < oldPairs.start[owner + 1]; ++p)
            if (oldPairs.partner[p] == other)
                return p;
        return -1;
    }
};

} // namespace DEM_KERNEL_NS
} // namespace detail
} // namespace dem

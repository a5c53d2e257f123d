// RankBoxes.h
// The boxes of a Decomposition: which rank owns a point, and which ranks lie within a distance
// of it (the ranks that keep a ghost of a grain there). Host code, plain arithmetic.
#pragma once

#include "dem/Parameters.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace dem
{
namespace detail
{

struct RankBoxes
{
    std::array<int, 2> n{1, 1};
    std::array<double, 2> lower{0.0, 0.0}, length{1.0, 1.0};
    std::array<bool, 2> periodic{true, true};

    RankBoxes() = default;
    explicit RankBoxes(const Parameters& p) : n(p.decomposition.ranks), periodic(p.periodic)
    {
        for (int d = 0; d < 2; ++d)
        {
            lower[d] = p.boxLower[d];
            length[d] = p.boxUpper[d] - p.boxLower[d];
        }
    }

    int count() const { return n[0] * n[1]; }
    //- The box column (x: 0, y: 1) of rank r (ranks run x fastest).
    int column(int r, int d) const { return d == 0 ? r % n[0] : r / n[0]; }

    //- The box index along d holding coordinate x: periodic sides wrap, the outer boxes of a
    //- non-periodic side reach to infinity.
    int slot(double x, int d) const
    {
        double t = (x - lower[d]) / length[d];
        if (periodic[d])
            t -= std::floor(t);
        return std::clamp(int(std::floor(t * n[d])), 0, n[d] - 1);
    }
    int ownerOf(const double* x) const { return slot(x[0], 0) + n[0] * slot(x[1], 1); }

    //- Distance along d from x to rank column k's interval (the nearest periodic image).
    double distance(double x, int d, int k) const
    {
        const double width = length[d] / n[d];
        double lo = lower[d] + k * width, hi = lo + width;
        if (!periodic[d])
        {
            if (k == 0)
                lo = -HUGE_VAL;
            if (k == n[d] - 1)
                hi = HUGE_VAL;
            return std::max({0.0, lo - x, x - hi});
        }
        double best = HUGE_VAL;
        const double wrapped = x - length[d] * std::floor((x - lower[d]) / length[d]);
        for (int image = -1; image <= 1; ++image)
        {
            const double xi = wrapped + image * length[d];
            best = std::min(best, std::max({0.0, lo - xi, xi - hi}));
        }
        return best;
    }

    //- The ranks other than `self` whose box lies within `reach` of x in x and in y.
    void ranksNear(const double* x, double reach, int self, std::vector<int>& out) const
    {
        out.clear();
        for (int r = 0; r < count(); ++r)
            if (r != self && distance(x[0], 0, column(r, 0)) <= reach &&
                distance(x[1], 1, column(r, 1)) <= reach)
                out.push_back(r);
    }
};

} // namespace detail
} // namespace dem

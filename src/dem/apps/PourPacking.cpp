// PourPacking.cpp
// The start of the flowing benchmark.
#include "PourPacking.h"

#include "dem/Error.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace dem
{

namespace
{

//- A uniform number in [-1, 1) from the engine's top 53 bits (the standard's distributions
//- may differ between libraries; the engine's sequence may not).
double symmetricUniform(std::mt19937_64& engine)
{
    return 2.0 * double(engine() >> 11) * 0x1.0p-53 - 1.0;
}

} // namespace

Packing pourPacking(const PourSettings& s, double density)
{
    if (s.grains < 1 || s.radius <= 0.0 || s.gapFraction <= 0.0 || s.layers < 1 ||
        s.jitterFraction < 0.0 || s.jitterFraction >= 0.5)
        throw Error("pourPacking: need grains >= 1, radius > 0, gapFraction > 0, layers >= 1 and "
                    "0 <= jitterFraction < 0.5");
    const double diameter = 2.0 * s.radius;
    const double gap = s.gapFraction * diameter;
    const double spacing = diameter + gap;
    const double jitter = s.jitterFraction * gap;
    const long perSide = std::max(1L, long(std::ceil(std::sqrt(double(s.grains) / s.layers))));
    const long perLayer = perSide * perSide;

    Packing packing;
    packing.length = double(perSide) * spacing;
    packing.grains.reserve(std::size_t(s.grains));
    std::mt19937_64 engine(s.seed);
    double top = 0.0;
    for (long i = 0; i < s.grains; ++i)
    {
        const long layer = i / perLayer, row = (i % perLayer) / perSide, column = i % perSide;
        GrainInit g;
        g.radius = s.radius;
        g.density = density;
        g.position = {(double(column) + 0.5) * spacing, (double(row) + 0.5) * spacing,
                      s.radius + gap + double(layer) * spacing};
        for (int d = 0; d < 3; ++d)
            g.position[d] += jitter * symmetricUniform(engine);
        for (int d = 0; d < 3; ++d)
            g.velocity[d] = s.spread * symmetricUniform(engine);
        g.velocity[2] -= s.fallSpeed;
        top = std::max(top, g.position[2] + s.radius);
        packing.grains.push_back(g);
    }
    packing.height = 2.0 * top;
    return packing;
}

} // namespace dem

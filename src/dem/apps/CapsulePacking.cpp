// CapsulePacking.cpp
// The capsule packing of demBench --shape capsule (see CapsulePacking.h).
#include "CapsulePacking.h"

#include "dem/Error.h"
#include "dem/System.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <utility>
#include <vector>

namespace dem
{

namespace
{

//- Uniformly distributed unit quaternion (w, x, y, z): four normal deviates, normalised.
std::array<double, 4> randomOrientation(std::mt19937& random)
{
    std::normal_distribution<double> normal;
    std::array<double, 4> q{};
    double norm = 0;
    while (norm < 1e-3) // practically never repeats
    {
        norm = 0;
        for (double& c : q)
        {
            c = normal(random);
            norm += c * c;
        }
        norm = std::sqrt(norm);
    }
    for (double& c : q)
        c /= norm;
    return q;
}

//- |z component| of the capsule's axis, rotate(q, e_z).z = 1 - 2 (x^2 + y^2).
double axisZ(const std::array<double, 4>& q)
{
    return std::fabs(1.0 - 2.0 * (q[1] * q[1] + q[2] * q[2]));
}

double volumeOf(const GrainInit& g)
{
    return M_PI * g.radius * g.radius * (2.0 * g.coreHalfLength + 4.0 / 3.0 * g.radius);
}

//- steps steps at stiffness fraction x the benchmark's (time step and drag scaled to keep
//- their ratios to the contact time sqrt(m / k), grains of size x their full size), from rest;
//- the packing takes the end state, at rest.
void quenchedRun(Packing& packing, const Parameters& benchmark, double fraction, double drag,
                 int steps, double size = 1.0)
{
    const double scale = std::sqrt(fraction) / std::pow(size, 1.5);     // dt: sqrt(m / k)
    const double dragScale = std::sqrt(fraction) * std::pow(size, 1.5); // drag: sqrt(m k)
    Parameters p = benchmark;
    p.grainGrain.normalStiffness *= fraction;
    p.grainGrain.tangentialStiffness *= fraction;
    p.grainWall = p.grainGrain;
    p.timeStep = benchmark.timeStep / scale;
    p.neighbourSkin = std::max(benchmark.neighbourSkin, 1e-3);
    System system(p);
    system.addGrains(packing.grains);
    WallSpec bottom;
    bottom.side = WallSpec::Side::lower;
    bottom.position = 0.0;
    system.addWall(bottom);
    system.setViscousDrag(drag * dragScale);
    system.step(steps);
    const GrainOverlap overlap = system.largestOverlap();
    const double contacts = 2.0 * double(system.contactCount()) / double(packing.grains.size());
    const GrainData out = system.grains();
    double fastest = 0, spin = 0;
    for (std::size_t i = 0; i < packing.grains.size(); ++i)
    {
        GrainInit& g = packing.grains[i];
        double v2 = 0, w2 = 0;
        for (int d = 0; d < 3; ++d)
        {
            g.position[d] = out.position[3 * i + d];
            v2 += out.velocity[3 * i + d] * out.velocity[3 * i + d];
            w2 += out.angularVelocity[3 * i + d] * out.angularVelocity[3 * i + d];
        }
        for (int c = 0; c < 4; ++c)
            g.orientation[c] = out.orientation[4 * i + c];
        fastest = std::max(fastest, std::sqrt(v2));
        spin = std::max(spin, std::sqrt(w2));
    }
    double interior;
    const double bed = bedSolidFraction(packing, interior);
    std::printf("capsule packing: k = %.3g N/m, dt = %.3g s, drag %.3g N s/m, %d steps: largest "
                "overlap %.2g r, %.3f contacts per grain, fastest grain %.2g m/s, %.2g rad/s, "
                "solid fraction %.3f (bed) / %.3f (0.05 < z < 0.30 m)\n",
                p.grainGrain.normalStiffness, p.timeStep, drag * dragScale, steps,
                overlap.relativeOverlap, contacts, fastest, spin, bed, interior);
    std::fflush(stdout);
}

} // namespace

Packing capsulePacking(const Packing& spheres, const Parameters& benchmark, double drag,
                       const CapsulePackingSettings& settings)
{
    const double aspect = settings.aspect;
    if (!(aspect >= 1.0) || !std::isfinite(aspect))
        throw Error("--aspect " + std::to_string(aspect) +
                    ": the aspect ratio (L + 2r) / (2r) must be >= 1 (1: spheres)");
    // Same volume: pi r^2 2 (A - 1) r + 4/3 pi r^3 = 4/3 pi R^3
    const double shrink = std::cbrt(2.0 / (3.0 * aspect - 1.0));
    std::mt19937 random(settings.seed);
    Packing packing = spheres;
    std::vector<double> radius, halfLength; // at full size
    for (GrainInit& g : packing.grains)
    {
        radius.push_back(g.radius * shrink);
        halfLength.push_back((aspect - 1.0) * radius.back());
        g.orientation = randomOrientation(random);
    }
    // Start inside the spheres: bounding radius A r_full x start = R
    const double start = 1.0 / (aspect * shrink);
    auto resize = [&](double size)
    {
        for (std::size_t i = 0; i < packing.grains.size(); ++i)
        {
            packing.grains[i].radius = size * radius[i];
            packing.grains[i].coreHalfLength = size * halfLength[i];
        }
    };

    // Stages of stiffness k = fraction k_bench, fraction x 10 each, up to k_bench / 10. The time
    // step and the drag keep the benchmark's ratios to the contact time sqrt(m / k) (dt ~ 1/32
    // of a contact, drag 612 N s/m damping in ~83 steps) by scaling with sqrt(k_bench / k).
    // A looser Verlet skin (0.05 d) while the grains move.
    for (double fraction = settings.firstStiffnessFraction; fraction < 0.5; fraction *= 10.0)
    {
        const bool first = fraction == settings.firstStiffnessFraction;
        if (first)
            for (int k = 1; k <= settings.growthRuns; ++k)
            {
                resize(start * std::pow(1.0 / start, double(k) / settings.growthRuns));
                if (k == settings.growthRuns)
                    resize(1.0); // exactly the full size
                quenchedRun(packing, benchmark, fraction, drag, settings.growthSteps,
                            packing.grains.empty() ? 1.0 : packing.grains[0].radius / radius[0]);
            }
        std::vector<std::pair<int, double>> runs; // steps, drag relative to the scaled one
        if (first)
            runs.push_back({settings.settleSteps, settings.settleDragFraction});
        for (int k = 0; k < settings.runsPerStage; ++k)
            runs.push_back({settings.runSteps, 1.0});
        for (const auto& [steps, dragFraction] : runs)
            quenchedRun(packing, benchmark, fraction, dragFraction * drag, steps);
    }
    return packing;
}

double bedSolidFraction(const Packing& packing, double& interior)
{
    double top = 0, solid = 0, layer = 0;
    for (const GrainInit& g : packing.grains)
    {
        const double v = volumeOf(g);
        solid += v;
        if (g.position[2] > 0.05 && g.position[2] < 0.30)
            layer += v;
        top = std::max(top, g.position[2] + g.radius + g.coreHalfLength * axisZ(g.orientation));
    }
    const double area = packing.length * packing.length;
    interior = layer / (area * 0.25);
    return solid / (area * top);
}

} // namespace dem

// CapsulePacking.cpp
// The capsule packing of demBench --shape capsule (see CapsulePacking.h).
#include "CapsulePacking.h"

#include "dem/Error.h"
#include "dem/System.h"

#include <algorithm>
#include <chrono>
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

//- One run at stiffness fraction x the benchmark's (time step and drag scaled to keep their
//- ratios to the contact time sqrt(m / k), grains of size x their full size), from rest, with
//- contact dashpots of dampingRatio x critical for the pair's mass (grain-grain m / 2,
//- grain-wall m): they damp the relative normal and sliding motion of touching grains, and so
//- their spins too, which the drag does not. Runs at least minSteps steps, then in chunks of
//- checkSteps until the kinetic energy has decayed below restEnergy x N (m g)^2 / k (the
//- elastic energy of one grain resting on one contact under its own weight: it scales as the
//- energy each stiffening releases) or maxSteps is reached. The kinetic energy counts the
//- rotation as m (|w| (r + h))^2 / 2, an upper bound (all mass lies within r + h of the centre).
//- The packing takes the end state, at rest; returns the steps run.
long settledRun(Packing& packing, const Parameters& benchmark, double fraction, double drag,
                double dampingRatio, double skin, int minSteps, int checkSteps, int maxSteps,
                double restEnergy, double size = 1.0)
{
    const double scale = std::sqrt(fraction) / std::pow(size, 1.5);     // dt: sqrt(m / k)
    const double dragScale = std::sqrt(fraction) * std::pow(size, 1.5); // drag: sqrt(m k)
    Parameters p = benchmark;
    p.grainGrain.normalStiffness *= fraction;
    p.grainGrain.tangentialStiffness *= fraction;
    p.grainWall = p.grainGrain;
    const double mass =
        packing.grains.empty() ? 0.0 : p.defaultDensity * volumeOf(packing.grains[0]);
    const double k = p.grainGrain.normalStiffness;
    p.grainGrain.normalDamping = 2.0 * dampingRatio * std::sqrt(0.5 * mass * k);
    p.grainGrain.tangentialDamping =
        2.0 * dampingRatio * std::sqrt(0.5 * mass * p.grainGrain.tangentialStiffness);
    p.grainWall.normalDamping = 2.0 * dampingRatio * std::sqrt(mass * k);
    p.grainWall.tangentialDamping =
        2.0 * dampingRatio * std::sqrt(mass * p.grainWall.tangentialStiffness);
    p.timeStep = benchmark.timeStep / scale;
    p.neighbourSkin = std::max(benchmark.neighbourSkin, skin);
    System system(p);
    for (GrainInit& g : packing.grains)
    {
        g.velocity = {0.0, 0.0, 0.0};
        g.angularVelocity = {0.0, 0.0, 0.0};
    }
    system.addGrains(packing.grains);
    WallSpec bottom;
    bottom.side = WallSpec::Side::lower;
    bottom.position = 0.0;
    system.addWall(bottom);
    system.setViscousDrag(drag * dragScale);
    const double weight = mass * std::fabs(benchmark.gravity[2]);
    const double threshold = restEnergy * double(packing.grains.size()) * weight * weight / k;
    long steps = 0;
    double energy = 0;
    GrainData out;
    while (true)
    {
        const int chunk = steps < minSteps ? minSteps : checkSteps;
        system.step(chunk);
        steps += chunk;
        out = system.grains();
        energy = 0;
        for (std::size_t i = 0; i < packing.grains.size(); ++i)
        {
            double v2 = 0, w2 = 0;
            for (int d = 0; d < 3; ++d)
            {
                v2 += out.velocity[3 * i + d] * out.velocity[3 * i + d];
                w2 += out.angularVelocity[3 * i + d] * out.angularVelocity[3 * i + d];
            }
            const double reach = out.radius[i] + out.coreHalfLength[i];
            energy += 0.5 * out.mass[i] * (v2 + w2 * reach * reach);
        }
        if (energy < threshold || steps >= maxSteps)
            break;
    }
    const GrainOverlap overlap = system.largestOverlap();
    const double contacts = 2.0 * double(system.contactCount()) / double(packing.grains.size());
    for (std::size_t i = 0; i < packing.grains.size(); ++i)
    {
        GrainInit& g = packing.grains[i];
        for (int d = 0; d < 3; ++d)
            g.position[d] = out.position[3 * i + d];
        for (int c = 0; c < 4; ++c)
            g.orientation[c] = out.orientation[4 * i + c];
    }
    double interior;
    const double bed = bedSolidFraction(packing, interior);
    std::printf("capsule packing: k = %.3g N/m, dt = %.3g s, drag %.3g N s/m, dashpots %.2g "
                "critical, %ld steps (%zu rebuilds): kinetic energy %.2g of %.2g J%s, largest "
                "overlap %.2g r, %.3f contacts per grain, solid fraction %.3f (bed) / %.3f "
                "(0.05 < z < 0.30 m)\n",
                k, p.timeStep, drag * dragScale, dampingRatio, steps,
                system.neighbourRebuildCount(), energy, threshold,
                energy < threshold    ? " (at rest)"
                : minSteps < maxSteps ? " (NOT at rest: step limit)"
                                      : "",
                overlap.relativeOverlap, contacts, bed, interior);
    std::fflush(stdout);
    return steps;
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

    // Growth at the first, softest stiffness: fixed damped runs (drag and dashpots) after each
    // growth step. Then stages of stiffness k = fraction k_bench, x stiffeningFactor each, up
    // to k_bench itself, each run with dashpots until the kinetic energy has decayed. The time
    // step and the drag keep the benchmark's ratios to the contact time sqrt(m / k) (dt ~ 1/32
    // of a contact) by scaling with sqrt(k_bench / k). A looser Verlet skin while grains move.
    const double f0 = settings.firstStiffnessFraction;
    const double z = settings.dampingRatio;
    const double e = settings.restEnergy;
    long total = 0;
    const auto clockStart = std::chrono::steady_clock::now();
    for (int k = 1; k <= settings.growthRuns; ++k)
    {
        resize(start * std::pow(1.0 / start, double(k) / settings.growthRuns));
        if (k == settings.growthRuns)
            resize(1.0); // exactly the full size
        const double size = packing.grains.empty() ? 1.0 : packing.grains[0].radius / radius[0];
        total +=
            settledRun(packing, benchmark, f0, drag, z, settings.growthSkin, settings.growthSteps,
                       settings.growthSteps, settings.growthSteps, e, size);
    }
    for (double fraction = f0;; fraction = std::min(1.0, fraction * settings.stiffeningFactor))
    {
        const bool first = fraction == f0;
        // The first stage without drag (the raised bed falls back); then the drag too: the
        // dashpots damp the bed's slow collective modes weakly (their damping ratio falls with
        // the mode's frequency), the drag damps them all at the same rate.
        total += settledRun(packing, benchmark, fraction,
                            first ? 0.0 : settings.stageDragFraction * drag, z,
                            first ? settings.growthSkin : settings.settleSkin,
                            first ? settings.settleSteps : settings.checkSteps, settings.checkSteps,
                            settings.maxStageSteps, e);
        if (fraction == 1.0)
            break;
    }
    std::printf(
        "capsule packing: %ld steps in all, %.1f s\n", total,
        std::chrono::duration<double>(std::chrono::steady_clock::now() - clockStart).count());
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

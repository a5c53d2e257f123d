// EngineIo.h
// EngineImpl: adding grains, flags, host read-back, the fluid-grid coupling (deposit and
// pressure-gradient force) and the complete state for bit-exact restart.
#pragma once

#include <thrust/fill.h>

#include <cmath>
#include <string>

namespace dem
{
namespace detail
{

template <class Exec>
void EngineImpl<Exec>::addGrains(const std::vector<GrainInit>& grains)
{
    const int k = int(grains.size()), first = grains_.size();
    std::array<std::vector<double>, kRealFieldCount> reals;
    std::array<std::vector<int>, kIntFieldCount> ints;
    for (int f = 0; f < kRealFieldCount; ++f)
        reals[f].assign(std::size_t(realFieldInfo(f).components) * k, 0.0);
    for (int f = 0; f < kIntFieldCount; ++f)
        ints[f].assign(std::size_t(intFieldInfo(f).components) * k, 0);
    for (int i = 0; i < k; ++i)
    {
        const GrainInit& g = grains[i];
        if (!(g.radius > 0.0) || !std::isfinite(g.radius))
            throw Error("addGrains: grain " + std::to_string(first + i) + " has radius " +
                        std::to_string(g.radius) + "; it must be > 0");
        const double density = g.density > 0.0 ? g.density : params_.defaultDensity;
        const double mass = density * 4.18879020478639098 * g.radius * g.radius * g.radius;
        for (int d = 0; d < 3; ++d)
        {
            if (!std::isfinite(g.position[d]))
                throw Error("addGrains: grain " + std::to_string(first + i) +
                            " has a non-finite position");
            reals[fPosition][d * k + i] = g.position[d];
            reals[fOrigin][d * k + i] = g.position[d];
            reals[fVelocity][d * k + i] = g.velocity[d];
            reals[fAngularVelocity][d * k + i] = g.angularVelocity[d];
        }
        reals[fPrescribedVelocity][i] = g.velocity[0];
        reals[fPrescribedVelocity][k + i] = g.velocity[1];
        reals[fOrientation][i] = 1.0;
        reals[fRadius][i] = g.radius;
        reals[fInverseMass][i] = 1.0 / mass;
        reals[fInverseInertia][i] = 1.0 / (0.4 * mass * g.radius * g.radius);
        ints[fFlag][i] = int(g.flag);
        ints[fId][i] = first + i;
    }
    grains_.append(k, reals, ints);
    needRebuild_ = true;
    forcesStale_ = true;
}

template <class Exec>
void EngineImpl<Exec>::setGrainFlags(const std::vector<int>& indices, GrainFlag flag, double vx,
                                     double vy)
{
    const int n = grains_.size();
    const std::vector<int> id = grains_.hostInt(fId);
    std::vector<int> internal(n);
    for (int i = 0; i < n; ++i)
        internal[id[i]] = i;
    std::vector<int> flags = grains_.hostInt(fFlag);
    std::vector<double> prescribed = grains_.hostReal(fPrescribedVelocity);
    for (int index : indices)
    {
        if (index < 0 || index >= n)
            throw Error("setGrainFlags: grain index " + std::to_string(index) +
                        " out of range [0, " + std::to_string(n) + ")");
        const int i = internal[index];
        flags[i] = int(flag);
        prescribed[i] = vx;
        prescribed[n + i] = vy;
    }
    grains_.setInt(fFlag, flags);
    grains_.setReal(fPrescribedVelocity, prescribed);
}

template <class Exec>
double EngineImpl<Exec>::minimumMass() const
{
    const int n = grains_.size();
    const double* inverseMass = self().grains_.real(fInverseMass);
    return 1.0 / thrust::reduce(exec_.policy(), inverseMass, inverseMass + n, 0.0, MaxOp());
}

template <class Exec>
GrainData EngineImpl<Exec>::grains() const
{
    const int n = grains_.size();
    const std::vector<int> id = grains_.hostInt(fId), image = grains_.hostInt(fImage),
                           flag = grains_.hostInt(fFlag);
    std::vector<int> contacts(n, 0);
    if (grainsAtLastBuild_ == n && !needRebuild_)
    {
        Vec<int>& perGrain = contactScratch_;
        perGrain.resize(n);
        EngineImpl& e = self();
        Exec::forEach(n, TouchingPairs{e.grains_.view(), e.pairs_.view(), boxView(), true,
                                       thrust::raw_pointer_cast(perGrain.data())});
        thrust::copy(perGrain.begin(), perGrain.end(), contacts.begin());
    }
    GrainData out;
    // component-blocked internal order -> interleaved add order
    auto toAddOrder = [&](const std::vector<double>& h, std::vector<double>& dest)
    {
        dest.resize(3 * std::size_t(n));
        for (int i = 0; i < n; ++i)
            for (int d = 0; d < 3; ++d)
                dest[3 * std::size_t(id[i]) + d] = h[std::size_t(d) * n + i];
    };
    auto vector3 = [&](int field, std::vector<double>& dest)
    { toAddOrder(grains_.hostReal(field), dest); };
    vector3(fPosition, out.position);
    vector3(fVelocity, out.velocity);
    vector3(fAngularVelocity, out.angularVelocity);
    vector3(fForce, out.force);
    vector3(fTorque, out.torque);
    {
        Vec<double>& fluidForce = fluidForceScratch_; // every entry set by the kernel
        fluidForce.resize(3 * std::size_t(n));
        EngineImpl& e = self();
        FluidView fluid = fluid_;
        fluid.gradP = thrust::raw_pointer_cast(e.fluidGradP_.data());
        Exec::forEach(
            n, FluidForceOnGrains{e.grains_.vec3(fPosition),
                                  e.grains_.real(fRadius),
                                  nullptr,
                                  fluid,
                                  {params_.gravity[0], params_.gravity[1], params_.gravity[2]},
                                  Vec3Array{thrust::raw_pointer_cast(fluidForce.data()), n}});
        std::vector<double> h(fluidForce.size());
        thrust::copy(fluidForce.begin(), fluidForce.end(), h.begin());
        toAddOrder(h, out.fluidForce);
    }
    std::vector<double> origin;
    vector3(fOrigin, origin);
    out.displacement.resize(3 * std::size_t(n));
    const std::vector<double> radius = grains_.hostReal(fRadius),
                              inverseMass = grains_.hostReal(fInverseMass);
    out.radius.resize(n);
    out.mass.resize(n);
    out.contactCount.resize(n);
    out.flag.resize(n);
    for (int i = 0; i < n; ++i)
    {
        const int u = id[i];
        out.radius[u] = radius[i];
        out.mass[u] = 1.0 / inverseMass[i];
        out.contactCount[u] = contacts[i];
        out.flag[u] = GrainFlag(flag[i]);
        for (int d = 0; d < 3; ++d)
        {
            const double shift =
                d < 2 ? image[std::size_t(d) * n + i] * (params_.boxUpper[d] - params_.boxLower[d])
                      : 0.0;
            out.displacement[3 * u + d] = out.position[3 * u + d] + shift - origin[3 * u + d];
        }
        // Inside the box also between rebuilds (a grain may have crossed a seam since)
        for (int d = 0; d < 2; ++d)
        {
            const double lower = params_.boxLower[d], length = params_.boxUpper[d] - lower;
            double& x = out.position[3 * u + d];
            if (params_.periodic[d] && (x < lower || x >= lower + length))
                x -= length * std::floor((x - lower) / length);
        }
    }
    return out;
}

template <class Exec>
WallData EngineImpl<Exec>::wall(int w) const
{
    const WallState& s = walls_.at(checkWall(w));
    WallData out;
    out.position = s.position;
    out.velocity = s.velocity;
    out.grainForce = wallGrainForce(w);
    out.spec = s.spec;
    out.spec.position = s.position;
    return out;
}

template <class Exec>
std::size_t EngineImpl<Exec>::contactCount() const
{
    const int n = grains_.size();
    if (grainsAtLastBuild_ != n || needRebuild_)
        return 0;
    EngineImpl& e = self();
    return std::size_t(std::llround(exec_.sumOf(
        n, TouchingPairs{e.grains_.view(), e.pairs_.view(), boxView(), false, nullptr})));
}

inline GridView gridView(const UniformGrid& grid, const char* caller)
{
    GridView v;
    for (int d = 0; d < 3; ++d)
    {
        if (grid.n[d] < 1 || !(grid.spacing[d] > 0.0))
            throw Error(std::string(caller) + ": grid direction " + std::to_string(d) +
                        " has n = " + std::to_string(grid.n[d]) + ", spacing = " +
                        std::to_string(grid.spacing[d]) + "; need n >= 1 and spacing > 0");
        v.origin[d] = grid.origin[d];
        v.spacing[d] = grid.spacing[d];
        v.n[d] = grid.n[d];
        v.periodic[d] = grid.periodic[d];
    }
    return v;
}

template <class Exec>
void EngineImpl<Exec>::deposit(const UniformGrid& grid, double dtFluid, double* porosity,
                               double* predictedPorosity, double* meanVelocity,
                               double* solidVolume) const
{
    const GridView g = gridView(grid, "deposit");
    const int n = grains_.size();
    const long cells = g.cellCount();
    EngineImpl& e = self();
    Vec<double>& solid = depositSolid_;
    Vec<double>& momentum = depositMomentum_;
    Vec<double>& phi = depositPorosity_;
    solid.resize(cells);
    momentum.resize(meanVelocity ? 3 * cells : 0);
    phi.resize(cells);
    auto depositAt = [&](double lookAhead, bool withVelocity)
    {
        thrust::fill(exec_.policy(), solid.begin(), solid.end(), 0.0);
        if (withVelocity)
            thrust::fill(exec_.policy(), momentum.begin(), momentum.end(), 0.0);
        Exec::forEachScatter(
            n, DepositGrains{e.grains_.vec3(fPosition), e.grains_.vec3(fVelocity),
                             e.grains_.real(fRadius), nullptr, nullptr, g, lookAhead,
                             thrust::raw_pointer_cast(solid.data()),
                             withVelocity ? thrust::raw_pointer_cast(momentum.data()) : nullptr});
        Exec::forEach(
            int(cells),
            FinishDeposit{thrust::raw_pointer_cast(solid.data()),
                          withVelocity ? thrust::raw_pointer_cast(momentum.data()) : nullptr,
                          g.cellVolume(), thrust::raw_pointer_cast(phi.data()),
                          thrust::raw_pointer_cast(momentum.data())});
    };
    depositAt(0.0, meanVelocity != nullptr);
    if (porosity)
        thrust::copy(phi.begin(), phi.end(), porosity);
    if (meanVelocity)
        thrust::copy(momentum.begin(), momentum.end(), meanVelocity);
    if (solidVolume)
        thrust::copy(solid.begin(), solid.end(), solidVolume);
    if (predictedPorosity)
    {
        depositAt(dtFluid, false);
        thrust::copy(phi.begin(), phi.end(), predictedPorosity);
    }
}

template <class Exec>
void EngineImpl<Exec>::setFluid(const UniformGrid& grid, const double* gradP, double density)
{
    fluid_.grid = gridView(grid, "setFluid");
    if (!gradP)
        throw Error("setFluid: gradP is null");
    const long values = 3 * fluid_.grid.cellCount();
    fluidGradP_.resize(values);
    thrust::copy(gradP, gradP + values, fluidGradP_.begin());
    fluid_.density = density;
    fluid_.active = true;
}

} // namespace detail
} // namespace dem

#include "engine/EngineState.h"

// EngineIo.h
// EngineImpl: adding grains, flags, host read-back, the fluid-grid coupling (deposit and
// pressure-gradient force) and the complete state for bit-exact restart.
#pragma once

#include <unordered_map>

#include <thrust/fill.h>

#include <cmath>
#include <string>

namespace dem
{
namespace detail
{

namespace shapeDetail
{
//- Mass and principal moments (I_perp, I_perp, I_axial) of a sphere or capsule.
struct ShapeMass
{
    double mass;
    double inertia[3];
};

//- True solid volume: 4/3 pi r^3 + pi r^2 2h (the sphere's as the deposit computes it).
inline double shapeVolume(double r, double h)
{
    return 4.18879020478639098 * r * r * r + M_PI * r * r * (2.0 * h);
}

inline ShapeMass shapeMass(double r, double h, double density)
{
    ShapeMass s;
    if (h == 0.0) // a sphere: today's arithmetic, bit for bit
    {
        s.mass = density * 4.18879020478639098 * r * r * r;
        s.inertia[0] = s.inertia[1] = s.inertia[2] = 0.4 * s.mass * r * r;
        return s;
    }
    const double L = 2.0 * h;
    const double cylinder = density * M_PI * r * r * L;
    const double caps = density * 4.18879020478639098 * r * r * r;
    s.mass = cylinder + caps;
    s.inertia[2] = cylinder * r * r / 2.0 + 2.0 * caps * r * r / 5.0;
    s.inertia[0] = s.inertia[1] = cylinder * (L * L / 12.0 + r * r / 4.0) +
                                  caps * (2.0 * r * r / 5.0 + L * L / 4.0 + 3.0 * L * r / 8.0);
    return s;
}

//- The unit quaternion of orientation (w, x, y, z), normalised; refused when not finite or
//- further than 1e-6 from unit length (a typo, not round-off).
inline Quaterniond checkedOrientation(const std::array<double, 4>& q, const std::string& name)
{
    const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (!std::isfinite(norm) || !(std::fabs(norm - 1.0) <= 1e-6))
        throw Error(name + " has orientation (" + std::to_string(q[0]) + ", " +
                    std::to_string(q[1]) + ", " + std::to_string(q[2]) + ", " +
                    std::to_string(q[3]) + ") of length " + std::to_string(norm) +
                    "; it must be a unit quaternion (w, x, y, z), | |q| - 1 | <= 1e-6");
    if (norm == 1.0)
        return Quaterniond(q[0], q[1], q[2], q[3]);
    return Quaterniond(q[0] / norm, q[1] / norm, q[2] / norm, q[3] / norm);
}

//- L = R I R^T omega (I the principal moments, body frame).
inline Vector3d angularMomentum(const Quaterniond& q, const Vector3d& inertia,
                                const Vector3d& omega)
{
    return q * inertia.cwiseProduct(q.conjugate() * omega);
}
} // namespace shapeDetail

template <class Exec>
int EngineImpl<Exec>::addGrains(const std::vector<GrainInit>& grains)
{
    using namespace shapeDetail;
    const int k = int(grains.size());
    // Ids count in add order over all ranks (rank 0's grains of a call first).
    const int first =
        halo_ ? int(halo_->addedGrains + halo_->comm->exclusiveSum(k)) : grains_.size();
    std::array<std::vector<double>, kRealFieldCount> reals;
    std::array<std::vector<int>, kIntFieldCount> ints;
    for (int f = 0; f < kRealFieldCount; ++f)
        reals[f].assign(std::size_t(realFieldInfo(f).components) * k, 0.0);
    for (int f = 0; f < kIntFieldCount; ++f)
        ints[f].assign(std::size_t(intFieldInfo(f).components) * k, 0);
    for (int i = 0; i < k; ++i)
    {
        const GrainInit& g = grains[i];
        const std::string name = "addGrains: grain " + std::to_string(first + i);
        if (!(g.radius > 0.0) || !std::isfinite(g.radius))
            throw Error(name + " has radius " + std::to_string(g.radius) + "; it must be > 0");
        if (!(g.coreHalfLength >= 0.0) || !std::isfinite(g.coreHalfLength))
            throw Error(name + " has coreHalfLength " + std::to_string(g.coreHalfLength) +
                        "; it must be >= 0 and finite (0: a sphere)");
        const Quaterniond q = checkedOrientation(g.orientation, name);
        const double density = g.density > 0.0 ? g.density : params_.defaultDensity;
        const ShapeMass shape = shapeMass(g.radius, g.coreHalfLength, density);
        for (int d = 0; d < 3; ++d)
        {
            if (!std::isfinite(g.position[d]))
                throw Error(name + " has a non-finite position");
            reals[fPosition][d * k + i] = g.position[d];
            reals[fOrigin][d * k + i] = g.position[d];
            reals[fVelocity][d * k + i] = g.velocity[d];
            reals[fAngularVelocity][d * k + i] = g.angularVelocity[d];
            reals[fPrincipalInertia][d * k + i] = shape.inertia[d];
        }
        reals[fPrescribedVelocity][i] = g.velocity[0];
        reals[fPrescribedVelocity][k + i] = g.velocity[1];
        reals[fOrientation][i] = q.w();
        reals[fOrientation][k + i] = q.x();
        reals[fOrientation][2 * k + i] = q.y();
        reals[fOrientation][3 * k + i] = q.z();
        reals[fRadius][i] = g.radius;
        reals[fCoreHalfLength][i] = g.coreHalfLength;
        reals[fInverseMass][i] = 1.0 / shape.mass;
        reals[fInverseInertia][i] = 1.0 / shape.inertia[0];
        if (g.coreHalfLength > 0.0) // the integrated rotational state: L = R I R^T omega
        {
            const Vector3d omega(g.angularVelocity[0], g.angularVelocity[1], g.angularVelocity[2]);
            const Vector3d L = angularMomentum(
                q, Vector3d(shape.inertia[0], shape.inertia[1], shape.inertia[2]), omega);
            for (int d = 0; d < 3; ++d)
                reals[fAngularMomentum][d * k + i] = L[d];
        }
        ints[fFlag][i] = int(g.flag);
        ints[fId][i] = first + i;
    }
    grains_.append(k, reals, ints);
    needRebuild_ = true;
    forcesStale_ = true;
    if (fluid_.active) // the new grains feel the fluid set before they came
        storeFluidLoads();
    if (halo_)
        halo_->addedGrains += std::llround(halo_->comm->sum(double(k)));
    return first;
}

template <class Exec>
void EngineImpl<Exec>::setGrainFlags(const std::vector<int>& indices, GrainFlag flag, double vx,
                                     double vy)
{
    const int n = grains_.size();
    const std::vector<int> id = grains_.hostInt(fId);
    // Decomposed: collective; the union of the ranks' lists applies to the grains each rank
    // owns (a ghost's flag is kFlagGhost: its owner moves it, and the flag travels with the
    // grain's record when it changes rank)
    std::vector<int> all = indices;
    long total = n;
    if (halo_)
    {
        const Communicator& comm = *halo_->comm;
        std::vector<std::vector<double>> send(std::size_t(comm.size()),
                                              std::vector<double>(indices.begin(), indices.end()));
        all.clear();
        for (const std::vector<double>& from : comm.exchange(send))
            for (double index : from)
                all.push_back(int(index));
        total = long(halo_->addedGrains);
    }
    std::unordered_map<int, int> internal;
    internal.reserve(std::size_t(n));
    for (int i = 0; i < n; ++i)
        internal[id[i]] = i;
    std::vector<int> flags = grains_.hostInt(fFlag);
    std::vector<double> prescribed = grains_.hostReal(fPrescribedVelocity);
    for (int index : all)
    {
        if (index < 0 || index >= total)
            throw Error("setGrainFlags: grain index " + std::to_string(index) +
                        " out of range [0, " + std::to_string(total) + ")");
        const auto found = internal.find(index);
        if (found == internal.end())
            continue; // another rank's grain, not near this one
        const int i = found->second;
        if (halo_ && flags[i] == kFlagGhost)
            continue;
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
    if (!grains_.hasCapsules())
        return 1.0 / globalMax(thrust::reduce(exec_.policy(), inverseMass, inverseMass + n, 0.0,
                                              MaxOp()));
    return 1.0 / globalMax(exec_.maxOf(n, EffectiveInverseMass{self().grains_.view()}));
}

template <class Exec>
GrainOverlap EngineImpl<Exec>::largestOverlap()
{
    refuseDecomposed("largestOverlap");
    const int n = grains_.size();
    GrainOverlap out;
    if (n < 2)
        return out;
    if (needRebuild_ || grainsAtLastBuild_ != n)
    {
        rebuild();           // between step() calls the SoA fields are the current state
        forcesStale_ = true; // the pair loads belong to the list before
    }
    overlapScratch_.resize(n);
    depthScratch_.resize(n);
    contactScratch_.resize(n);
    Exec::forEach(n, DeepestOverlap{grains_.view(), pairs_.view(), boxView(), grains_.hasCapsules(),
                                    thrust::raw_pointer_cast(overlapScratch_.data()),
                                    thrust::raw_pointer_cast(depthScratch_.data()),
                                    thrust::raw_pointer_cast(contactScratch_.data())});
    std::vector<double> relative(n), depth(n);
    std::vector<int> partner(n);
    thrust::copy(overlapScratch_.begin(), overlapScratch_.end(), relative.begin());
    thrust::copy(depthScratch_.begin(), depthScratch_.end(), depth.begin());
    thrust::copy(contactScratch_.begin(), contactScratch_.end(), partner.begin());
    const std::vector<int> id = grains_.hostInt(fId);
    for (int i = 0; i < n; ++i)
        if (partner[i] >= 0 && relative[i] > out.relativeOverlap)
        {
            out.relativeOverlap = relative[i];
            out.overlap = depth[i];
            out.first = std::min(id[i], id[partner[i]]);
            out.second = std::max(id[i], id[partner[i]]);
        }
    return out;
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
                                       thrust::raw_pointer_cast(perGrain.data()),
                                       grains_.hasCapsules()});
        thrust::copy(perGrain.begin(), perGrain.end(), contacts.begin());
    }
    GrainData out;
    // Where each grain goes in the read-back: its add-order index, or over MPI ranks its place
    // among this rank's owned grains in add order (-1: a ghost, not read back).
    std::vector<int> slot = id;
    int m = n;
    if (halo_)
    {
        std::vector<int> owned;
        for (int i = 0; i < n; ++i)
            if (flag[i] != kFlagGhost)
                owned.push_back(id[i]);
        std::sort(owned.begin(), owned.end());
        m = int(owned.size());
        for (int i = 0; i < n; ++i)
            slot[i] =
                flag[i] == kFlagGhost
                    ? -1
                    : int(std::lower_bound(owned.begin(), owned.end(), id[i]) - owned.begin());
    }
    // component-blocked internal order -> interleaved add order
    auto toAddOrder = [&](const std::vector<double>& h, std::vector<double>& dest)
    {
        dest.resize(3 * std::size_t(m));
        for (int i = 0; i < n; ++i)
            if (slot[i] >= 0)
                for (int d = 0; d < 3; ++d)
                    dest[3 * std::size_t(slot[i]) + d] = h[std::size_t(d) * n + i];
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
        Exec::forEach(
            n, FluidForceOnGrains{grainFluidForce(),
                                  Vec3Array{thrust::raw_pointer_cast(fluidForce.data()), n}});
        std::vector<double> h(fluidForce.size());
        thrust::copy(fluidForce.begin(), fluidForce.end(), h.begin());
        toAddOrder(h, out.fluidForce);
    }
    std::vector<double> origin;
    vector3(fOrigin, origin);
    out.displacement.resize(3 * std::size_t(m));
    const std::vector<double> radius = grains_.hostReal(fRadius),
                              inverseMass = grains_.hostReal(fInverseMass),
                              halfLength = grains_.hostReal(fCoreHalfLength),
                              orientation = grains_.hostReal(fOrientation);
    out.radius.resize(m);
    out.coreHalfLength.resize(m);
    out.orientation.resize(4 * std::size_t(m));
    out.volume.resize(m);
    out.mass.resize(m);
    out.contactCount.resize(m);
    out.flag.resize(m);
    out.id.resize(m);
    for (int i = 0; i < n; ++i)
    {
        const int u = slot[i];
        if (u < 0)
            continue;
        out.id[u] = id[i];
        out.radius[u] = radius[i];
        out.coreHalfLength[u] = halfLength[i];
        for (int c = 0; c < 4; ++c)
            out.orientation[4 * std::size_t(u) + c] = orientation[std::size_t(c) * n + i];
        out.volume[u] = shapeDetail::shapeVolume(radius[i], halfLength[i]);
        out.mass[u] = 1.0 / inverseMass[i];
        out.contactCount[u] = contacts[i];
        out.flag[u] = GrainFlag(flag[i]);
        for (int d = 0; d < 3; ++d)
        {
            // the lattice of images at the current length (a deforming side's scale with it)
            const double shift = d < 2 ? image[std::size_t(d) * n + i] * currentBoxLength(d) : 0.0;
            out.displacement[3 * u + d] = out.position[3 * u + d] + shift - origin[3 * u + d];
        }
        // Inside the box also between rebuilds (a grain may have crossed a seam since)
        for (int d = 0; d < 2; ++d)
        {
            const double lower = params_.boxLower[d], length = currentBoxLength(d);
            double& x = out.position[3 * u + d];
            if (params_.periodic[d] && (x < lower || x >= lower + length))
            {
                const double crossed = std::floor((x - lower) / length);
                x -= length * crossed;
                out.velocity[3 * u + d] -= crossed * params_.boxLengthRate[d]; // WrapIntoBox
            }
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
    // Decomposed: the answer is collective, so every rank returns early or none does
    const bool stale = grainsAtLastBuild_ != n || needRebuild_;
    if (halo_ ? globalMax(stale ? 1.0 : 0.0) > 0.0 : stale)
        return 0;
    EngineImpl& e = self();
    if (!halo_)
        return std::size_t(
            std::llround(exec_.sumOf(n, TouchingPairs{e.grains_.view(), e.pairs_.view(), boxView(),
                                                      false, nullptr, grains_.hasCapsules()})));
    // Over MPI ranks: each owned grain's touching pairs, both sides, summed over all ranks,
    // count every pair twice (a pair across a boundary once on each of its two ranks).
    Vec<int>& perGrain = contactScratch_;
    perGrain.resize(n);
    Exec::forEach(n,
                  TouchingPairs{e.grains_.view(), e.pairs_.view(), boxView(), true,
                                thrust::raw_pointer_cast(perGrain.data()), grains_.hasCapsules()});
    const std::vector<int> counts = haloDetail::toHost(perGrain), flag = grains_.hostInt(fFlag);
    double owned = 0.0;
    for (int i = 0; i < n; ++i)
        if (flag[i] != kFlagGhost)
            owned += counts[i];
    return std::size_t(std::llround(0.5 * globalSum(owned)));
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

//- The grid as the coupling kernels see it: points kept half a cell inside the walls, so that
//- no grain deposits its volume into, or reads its fluid from, cells beyond the wall it rests
//- on (a distributor inside the fluid, a loading plate below the mesh's top). Without this a
//- bed's layer on a wall inside the fluid averages its porosity with the clear fluid beyond
//- and gets too little drag (doc/EQUATIONS.md 6). Walls closer than a cell: their middle.
//- Unless the grid asks for the weights to cross the walls (UniformGrid::depositInsideWalls).
template <class Exec>
GridView EngineImpl<Exec>::fluidGridView(const UniformGrid& grid, const char* caller) const
{
    GridView v = gridView(grid, caller);
    if (!grid.depositInsideWalls)
        return v;
    for (const WallState& w : walls_)
    {
        const int a = w.spec.axis;
        const double inside = 0.5 * v.spacing[a];
        if (w.spec.side == WallSpec::Side::lower)
            v.pointLower[a] = std::max(v.pointLower[a], w.position + inside);
        else
            v.pointUpper[a] = std::min(v.pointUpper[a], w.position - inside);
    }
    for (int d = 0; d < 3; ++d)
        if (v.pointLower[d] > v.pointUpper[d])
            v.pointLower[d] = v.pointUpper[d] = 0.5 * (v.pointLower[d] + v.pointUpper[d]);
    return v;
}

template <class Exec>
void EngineImpl<Exec>::deposit(const UniformGrid& grid, double dtFluid, double* porosity,
                               double* predictedPorosity, double* meanVelocity,
                               double* solidVolume) const
{
    const GridView g = fluidGridView(grid, "deposit");
    // Decomposed: every rank deposits the grains it owns (not its ghosts) on the whole grid,
    // and the cells' sums are added over the ranks before they are finished
    const int n = grains_.size();
    const long cells = g.cellCount();
    EngineImpl& e = self();
    Vec<double>& solid = depositSolid_;
    Vec<double>& momentum = depositMomentum_;
    Vec<double>& phi = depositPorosity_;
    solid.resize(cells);
    momentum.resize(meanVelocity ? 3 * cells : 0);
    phi.resize(cells);
    const bool capsules = grains_.hasCapsules(); // else the sphere-only deposit
    auto depositAt = [&](double lookAhead, bool withVelocity)
    {
        thrust::fill(exec_.policy(), solid.begin(), solid.end(), 0.0);
        if (withVelocity)
            thrust::fill(exec_.policy(), momentum.begin(), momentum.end(), 0.0);
        Exec::forEachScatter(
            n, DepositGrains{e.grains_.vec3(fPosition), e.grains_.vec3(fVelocity),
                             e.grains_.real(fRadius),
                             capsules ? e.grains_.real(fCoreHalfLength) : nullptr,
                             e.grains_.real(fOrientation), g, lookAhead,
                             thrust::raw_pointer_cast(solid.data()),
                             withVelocity ? thrust::raw_pointer_cast(momentum.data()) : nullptr,
                             ghostFlagsOrNull()});
        sumOverRanks(solid);
        if (withVelocity)
            sumOverRanks(momentum);
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
void EngineImpl<Exec>::setFluid(const UniformGrid& grid, const FluidFields& fluid)
{
    // Decomposed: every rank passes the whole grid's fields (the same on each) and interpolates
    // them to its own grains
    const GridView g = fluidGridView(grid, "setFluid");
    if (!fluid.forceDensity)
        throw Error("setFluid: forceDensity is null");
    if (fluid.dragCoefficient && !fluid.velocity)
        throw Error("setFluid: a dragCoefficient needs the fluid velocity");
    const long cells = g.cellCount();
    fluidForceDensity_.resize(3 * cells);
    thrust::copy(fluid.forceDensity, fluid.forceDensity + 3 * cells, fluidForceDensity_.begin());
    if (fluid.dragCoefficient)
    {
        fluidDrag_.resize(cells);
        thrust::copy(fluid.dragCoefficient, fluid.dragCoefficient + cells, fluidDrag_.begin());
        fluidVelocity_.resize(3 * cells);
        thrust::copy(fluid.velocity, fluid.velocity + 3 * cells, fluidVelocity_.begin());
    }
    else
    {
        fluidDrag_.clear();
        fluidVelocity_.clear();
    }
    fluidGrid_ = g;
    fluid_.density = fluid.buoyancyDensity;
    fluid_.active = true;
    storeFluidLoads();
}

template <class Exec>
void EngineImpl<Exec>::storeFluidLoads()
{
    const int n = grains_.size();
    if (n == 0)
        return;
    FluidFieldsView fields;
    fields.grid = fluidGrid_;
    fields.forceDensity = thrust::raw_pointer_cast(fluidForceDensity_.data());
    const bool drag = !fluidDrag_.empty();
    fields.dragCoefficient = drag ? thrust::raw_pointer_cast(fluidDrag_.data()) : nullptr;
    fields.velocity = drag ? thrust::raw_pointer_cast(fluidVelocity_.data()) : nullptr;
    Exec::forEach(n, StoreFluidLoad{fields, grains_.vec3(fPosition), grains_.real(fRadius),
                                    grains_.hasCapsules() ? grains_.real(fCoreHalfLength) : nullptr,
                                    grains_.real(fFluidLoad), n});
}

template <class Exec>
void EngineImpl<Exec>::pointFluidAt(FluidLoadView& fluid) const
{
    EngineImpl& e = self();
    fluid.load = e.grains_.real(fFluidLoad);
    fluid.n = grains_.size();
}

template <class Exec>
GrainFluidForce EngineImpl<Exec>::grainFluidForce() const
{
    EngineImpl& e = self();
    FluidLoadView fluid = fluid_;
    pointFluidAt(fluid);
    return GrainFluidForce{e.grains_.vec3(fPosition),
                           e.grains_.vec3(fVelocity),
                           e.grains_.real(fRadius),
                           grains_.hasCapsules() ? e.grains_.real(fCoreHalfLength) : nullptr,
                           fluid,
                           {params_.gravity[0], params_.gravity[1], params_.gravity[2]}};
}

template <class Exec>
void EngineImpl<Exec>::depositFluidReaction(const UniformGrid& grid, double* reaction) const
{
    const GridView g = fluidGridView(grid, "depositFluidReaction");
    const long values = 3 * g.cellCount();
    Vec<double>& out = reactionScratch_;
    out.resize(values);
    thrust::fill(exec_.policy(), out.begin(), out.end(), 0.0);
    if (fluid_.active)
        Exec::forEachScatter(grains_.size(),
                             DepositFluidReaction{grainFluidForce(), g,
                                                  thrust::raw_pointer_cast(out.data()),
                                                  ghostFlagsOrNull()});
    sumOverRanks(out);
    thrust::copy(out.begin(), out.end(), reaction);
}

} // namespace detail
} // namespace dem

#include "engine/EngineState.h"

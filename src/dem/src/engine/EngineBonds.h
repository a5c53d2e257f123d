// EngineBonds.h
// EngineImpl: the bond store's upkeep (the grains' internal indices after every re-sort, the
// per-grain index for the gather, the pairs' bonded flags), the bond force pass with the
// removal of broken bonds, formation (frozenOnContact), addBonds, setGrainVelocities and the
// bonds' read-back.
#pragma once

#include <thrust/copy.h>
#include <thrust/iterator/counting_iterator.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>
#include <string>
#include <utility>

namespace dem
{
namespace detail
{

template <class Exec>
void EngineImpl<Exec>::indexBonds()
{
    const int n = grains_.size();
    if (halo_) // ids count over all ranks; -1: not here
        internalOf_.assign(std::size_t(halo_->addedGrains), -1);
    else
        internalOf_.resize(n);
    Exec::forEach(n, InvertIds{grains_.integer(fId), thrust::raw_pointer_cast(internalOf_.data())});
    bonds_.index(exec_.policy(), internalOf_, n);
    // Bonds just made (formed, added, imported without patches) get their patches where their
    // grains touch now, at the packed state (the body-fixed model alone reads them).
    if (bodyFixedPatches())
        Exec::forEach(bonds_.count(), PlaceBonds{grains_.view(), bonds_.view(), boxView()});
    // The pairs' flags, when the list is the current grains' (else the next rebuild sets them).
    if (grainsAtLastBuild_ == n && long(pairs_.start.size()) == long(n) + 1)
    {
        pairs_.bonded.resize(pairs_.count());
        Exec::forEach(n, MarkBondedPairs{pairs_.view(), bonds_.view(),
                                         thrust::raw_pointer_cast(pairs_.bonded.data())});
    }
}

template <class Exec>
void EngineImpl<Exec>::computeBondForces(double dt)
{
    const int count = bonds_.count();
    if (count == 0)
        return;
    bondBroken_.resize(count);
    const double broken =
        exec_.sumOf(count, BondForceKernel{grains_.view(), bonds_.view(), boxView(),
                                           BondLaw::make(params_.bonds, dt),
                                           thrust::raw_pointer_cast(bondBroken_.data())});
    if (broken > 0.0)
    {
        const double* flags = thrust::raw_pointer_cast(bondBroken_.data());
        for (int c = 0; c < 4; ++c)
            brokenBondCreep_[c] +=
                exec_.sumOf(count, BrokenBondCreep{bonds_.view(), flags, kBondCreepNormal + c});
        if (halo_)
        {
            Vec<double>& share = bondReadback_; // per bond: its share if broken, else 0
            share.resize(std::size_t(count));
            Exec::forEach(count, StoreBondShare{bonds_.view(), grains_.integer(fFlag), flags,
                                                thrust::raw_pointer_cast(share.data())});
            halo_->bondsBroken +=
                exec_.sumOf(count, ComponentOf{thrust::raw_pointer_cast(share.data())});
            for (int c = 0; c < 4; ++c)
                halo_->brokenCreep[std::size_t(c)] += exec_.sumOf(
                    count, BrokenBondCreep{bonds_.view(), thrust::raw_pointer_cast(share.data()),
                                           kBondCreepNormal + c});
        }
        bonds_.removeBroken(exec_.policy(), bondBroken_);
        bondsBroken_ += std::size_t(std::llround(broken));
        indexBonds();
    }
}

template <class Exec>
void EngineImpl<Exec>::formBonds()
{
    const int pairCount = int(pairs_.count());
    if (pairCount == 0)
        return;
    formationPairs_.resize(pairCount);
    const auto end =
        thrust::copy_if(exec_.policy(), thrust::counting_iterator<int>(0),
                        thrust::counting_iterator<int>(pairCount), formationPairs_.begin(),
                        FormationCandidate{grains_.view(), pairs_.view(), boxView(),
                                           thrust::raw_pointer_cast(pairs_.bonded.data())});
    const int added = int(end - formationPairs_.begin());
    if (added == 0)
        return;
    const int offset = bonds_.count();
    bonds_.grow(exec_.policy(), added);
    const BondParameters& p = params_.bonds;
    Exec::forEach(added, FormBonds{grains_.view(), pairs_.view(), grains_.integer(fId),
                                   thrust::raw_pointer_cast(formationPairs_.data()), bonds_.view(),
                                   offset, p.seed, p.areaFraction[0], p.areaFraction[1]});
    bondsFormed_ += std::size_t(added);
    if (halo_)
        halo_->bondsFormed += exec_.sumOf(
            added, FormedBondShare{pairs_.view(), thrust::raw_pointer_cast(formationPairs_.data()),
                                   grains_.integer(fFlag)});
    indexBonds();
}

template <class Exec>
void EngineImpl<Exec>::addBonds(const std::vector<BondInit>& added)
{
    refuseDecomposed("addBonds (bonds form by frozenOnContact)");
    const int n = grains_.size();
    std::vector<int> first = bonds_.hostFirst(), second = bonds_.hostSecond();
    const std::vector<double> oldState = bonds_.hostState();
    const std::size_t old = first.size(), m = old + added.size();
    std::set<std::pair<int, int>> bonded;
    for (std::size_t b = 0; b < old; ++b)
        bonded.insert({first[b], second[b]});
    std::vector<double> state(kBondStateComponents * m, 0.0);
    for (int c = 0; c < kBondStateComponents; ++c)
        std::copy(oldState.begin() + c * old, oldState.begin() + (c + 1) * old,
                  state.begin() + c * m);
    for (std::size_t k = 0; k < added.size(); ++k)
    {
        const BondInit& bond = added[k];
        const std::string name = "addBonds: bond " + std::to_string(k) + " (grains " +
                                 std::to_string(bond.first) + " and " +
                                 std::to_string(bond.second) + ")";
        for (int index : {bond.first, bond.second})
            if (index < 0 || index >= n)
                throw Error(name + ": grain index " + std::to_string(index) + " out of range [0, " +
                            std::to_string(n) + ")");
        if (bond.first == bond.second)
            throw Error(name + " joins a grain to itself; a bond needs two different grains");
        if (!(bond.patchRadius > 0.0) || !std::isfinite(bond.patchRadius))
            throw Error(name + " has patchRadius " + std::to_string(bond.patchRadius) +
                        "; it must be > 0 and finite");
        const std::pair<int, int> ids{std::min(bond.first, bond.second),
                                      std::max(bond.first, bond.second)};
        if (!bonded.insert(ids).second)
            throw Error(name + ": these grains are bonded already (one bond per pair)");
        first.push_back(ids.first);
        second.push_back(ids.second);
        state[kBondPatchRadius * m + old + k] = bond.patchRadius;
        state[kBondOnsetRadius * m + old + k] = bond.patchRadius;
    }
    bonds_.assign(first, second, state);
    // Body-fixed patches are placed at the packed state (PlaceBonds): packed from the grains now.
    if (bodyFixedPatches())
        Exec::forEach(n, PackGrains{grains_.view()});
    indexBonds();
}

template <class Exec>
void EngineImpl<Exec>::setGrainVelocities(const std::vector<int>& indices,
                                          const std::array<double, 3>& velocity,
                                          const std::array<double, 3>& angularVelocity)
{
    refuseDecomposed("setGrainVelocities");
    const int n = grains_.size();
    const std::vector<int> id = grains_.hostInt(fId);
    std::vector<int> internal(n);
    for (int i = 0; i < n; ++i)
        internal[id[i]] = i;
    std::vector<double> v = grains_.hostReal(fVelocity), omega = grains_.hostReal(fAngularVelocity),
                        L = grains_.hostReal(fAngularMomentum),
                        h = grains_.hostReal(fCoreHalfLength), q = grains_.hostReal(fOrientation),
                        inertia = grains_.hostReal(fPrincipalInertia);
    const Vector3d w(angularVelocity[0], angularVelocity[1], angularVelocity[2]);
    for (int index : indices)
    {
        if (index < 0 || index >= n)
            throw Error("setGrainVelocities: grain index " + std::to_string(index) +
                        " out of range [0, " + std::to_string(n) + ")");
        const std::size_t i = std::size_t(internal[index]);
        for (int d = 0; d < 3; ++d)
        {
            v[d * n + i] = velocity[d];
            omega[d * n + i] = angularVelocity[d];
        }
        if (h[i] > 0.0) // a capsule's rotational state is its angular momentum
        {
            const Quaterniond qi(q[i], q[n + i], q[2 * n + i], q[3 * n + i]);
            const Vector3d Li = shapeDetail::angularMomentum(
                qi, Vector3d(inertia[i], inertia[n + i], inertia[2 * n + i]), w);
            for (int d = 0; d < 3; ++d)
                L[d * n + i] = Li[d];
        }
    }
    grains_.setReal(fVelocity, v);
    grains_.setReal(fAngularVelocity, omega);
    grains_.setReal(fAngularMomentum, L);
}

template <class Exec>
BondData EngineImpl<Exec>::bonds() const
{
    BondData out;
    const int count = bonds_.count();
    if (count == 0)
        return out;
    EngineImpl& e = self();
    bondReadback_.resize(7 * std::size_t(count));
    double* scratch = thrust::raw_pointer_cast(bondReadback_.data());
    Exec::forEach(count,
                  BondReadback{e.grains_.view(), e.bonds_.view(), boxView(), scratch,
                               scratch + 3L * count, scratch + 6L * count, bodyFixedPatches()});
    std::vector<double> geometry(bondReadback_.size());
    thrust::copy(bondReadback_.begin(), bondReadback_.end(), geometry.begin());
    const std::vector<double> state = bonds_.hostState();
    const std::vector<int> first = bonds_.hostFirst(), second = bonds_.hostSecond();
    // In the order of the grains' add-order indices (the store's follows the grain order).
    std::vector<int> order(count);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(),
              [&](int a, int b) {
                  return std::make_pair(first[a], second[a]) < std::make_pair(first[b], second[b]);
              });
    auto component = [&](int c, std::size_t b) { return state[std::size_t(c) * count + b]; };
    // Over MPI ranks: the bonds whose first grain this rank owns (each bond on one rank).
    const std::vector<char> reported = reportedBonds();
    for (const int k : order)
    {
        const std::size_t b = std::size_t(k);
        if (!reported[b])
            continue;
        out.first.push_back(first[b]);
        out.second.push_back(second[b]);
        out.patchRadius.push_back(component(kBondPatchRadius, b));
        out.normalForce.push_back(component(kBondNormalForce, b));
        out.twistMoment.push_back(component(kBondTwistMoment, b));
        out.age.push_back(component(kBondAge, b));
        out.softening.push_back(component(kBondSoftening, b) != 0.0 ? 1 : 0);
        out.creepNormal.push_back(component(kBondCreepNormal, b));
        out.creepShear.push_back(component(kBondCreepShear, b));
        out.creepTwist.push_back(component(kBondCreepTwist, b));
        out.creepBend.push_back(component(kBondCreepBend, b));
        for (int d = 0; d < 3; ++d)
        {
            out.shearForce.push_back(component(kBondShearForce + d, b));
            out.bendMoment.push_back(component(kBondBendMoment + d, b));
            out.normal.push_back(geometry[3 * b + d]);
            out.point.push_back(geometry[3 * (count + b) + d]);
        }
    }
    return out;
}

template <class Exec>
double EngineImpl<Exec>::maximumBondStiffness() const
{
    const BondParameters& b = params_.bonds;
    if (!b.enabled)
        return 0.0;
    // Formation's largest: r_b^2 = f_max r_min^2 and Rbar >= r_min give
    // k_ne A <= E pi f_max r_min / 2 <= E pi f_max R_max / 2.
    double largest = b.formation == BondFormation::frozenOnContact
                         ? 0.5 * M_PI * b.youngsModulus * b.areaFraction[1] * maximumRadius()
                         : 0.0;
    const int count = bonds_.count();
    if (count > 0)
    {
        EngineImpl& e = self();
        largest = std::max(largest,
                           exec_.maxOf(count, BondStiffnessOf{e.grains_.real(fRadius),
                                                              e.bonds_.view(), b.youngsModulus}));
    }
    return globalMax(largest);
}

template <class Exec>
BondCounts EngineImpl<Exec>::bondCounts() const
{
    BondCounts out;
    if (halo_)
        return decomposedBondCounts();
    out.formed = bondsFormed_;
    out.broken = bondsBroken_;
    out.brokenCreep = brokenBondCreep_;
    const int count = bonds_.count();
    out.intact = std::size_t(count);
    if (count == 0)
        return out;
    const BondData data = bonds(); // sorted by the grains' add-order indices
    std::vector<double> touching(count);
    thrust::copy(bondReadback_.begin() + 6L * count, bondReadback_.end(), touching.begin());
    double radiusSum = 0.0;
    for (int b = 0; b < count; ++b)
    {
        out.apart += touching[b] == 0.0 ? 1 : 0;
        radiusSum += data.patchRadius[b]; // in that order: whatever the grain order
        out.intactCreep[0] += data.creepNormal[b];
        out.intactCreep[1] += data.creepShear[b];
        out.intactCreep[2] += data.creepTwist[b];
        out.intactCreep[3] += data.creepBend[b];
    }
    out.meanPatchRadius = radiusSum / count;
    return out;
}

template <class Exec>
std::vector<char> EngineImpl<Exec>::reportedBonds() const
{
    const std::vector<int> first = bonds_.hostFirst();
    std::vector<char> reported(first.size(), 1);
    if (!halo_)
        return reported;
    const std::vector<int> id = grains_.hostInt(fId), flag = grains_.hostInt(fFlag);
    std::unordered_map<int, int> flagOf;
    for (std::size_t i = 0; i < id.size(); ++i)
        flagOf[id[i]] = flag[i];
    for (std::size_t b = 0; b < first.size(); ++b)
        reported[b] = flagOf.at(first[b]) != kFlagGhost;
    return reported;
}

template <class Exec>
BondCounts EngineImpl<Exec>::decomposedBondCounts() const
{
    // Each bond counted once over the ranks: by the rank that owns its first grain (bonds());
    // formed and broken from the shares each rank counted (BondRankShare).
    const BondData data = bonds();
    const int count = bonds_.count();
    double apart = 0.0;
    if (count > 0)
    {
        const std::vector<char> reported = reportedBonds();
        std::vector<double> touching(static_cast<std::size_t>(count));
        thrust::copy(bondReadback_.begin() + 6L * count, bondReadback_.end(), touching.begin());
        for (int b = 0; b < count; ++b)
            if (reported[std::size_t(b)] && touching[std::size_t(b)] == 0.0)
                apart += 1.0;
    }
    double radiusSum = 0.0;
    std::array<double, 4> creep = {};
    for (std::size_t b = 0; b < data.first.size(); ++b)
    {
        radiusSum += data.patchRadius[b];
        creep[0] += data.creepNormal[b];
        creep[1] += data.creepShear[b];
        creep[2] += data.creepTwist[b];
        creep[3] += data.creepBend[b];
    }
    BondCounts out;
    out.intact = std::size_t(std::llround(globalSum(double(data.first.size()))));
    out.apart = std::size_t(std::llround(globalSum(apart)));
    out.formed = std::size_t(std::llround(globalSum(halo_->bondsFormed)));
    out.broken = std::size_t(std::llround(globalSum(halo_->bondsBroken)));
    const double radii = globalSum(radiusSum);
    out.meanPatchRadius = out.intact > 0 ? radii / double(out.intact) : 0.0;
    for (int c = 0; c < 4; ++c)
        out.intactCreep[std::size_t(c)] = globalSum(creep[std::size_t(c)]);
    for (int c = 0; c < 4; ++c)
        out.brokenCreep[std::size_t(c)] = globalSum(halo_->brokenCreep[std::size_t(c)]);
    return out;
}

} // namespace detail
} // namespace dem

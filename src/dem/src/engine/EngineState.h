// EngineState.h
// EngineImpl: complete state as named host arrays (grains in internal order, the neighbour
// list with contact history, walls, clock; with bonds the bond store and its counters). Importing
// it restores the engine exactly, so the continued run is bit-identical to the uninterrupted one.
#pragma once

namespace dem
{
namespace detail
{

namespace stateDetail
{
//- Marks the layout of pairs.history in exported states: 2 = component by component
//- (c * pairs + p) on every backend (1, before, was pair by pair on the CPU).
constexpr std::int64_t kHistoryLayout = 2;

template <class Vec, class T>
void toHost(const Vec& v, std::vector<T>& out)
{
    out.resize(v.size());
    thrust::copy(v.begin(), v.end(), out.begin());
}
template <class Vec, class T>
void fromHost(const std::vector<T>& in, Vec& v)
{
    v.resize(in.size());
    thrust::copy(in.begin(), in.end(), v.begin());
}
template <class Map>
const typename Map::mapped_type& entry(const Map& map, const std::string& name)
{
    const auto it = map.find(name);
    if (it == map.end())
        throw Error("importState: the state has no entry '" + name + "'");
    return it->second;
}

//- A state written when a grain had wall records for 4 walls and the walls were z planes
//- (no 'walls.layout'), in today's layout: records padded to kMaxWalls, the capsule end's
//- contact bits moved up, axis z.
inline SystemState withWallLayoutOf6(const SystemState& old)
{
    constexpr int oldMaxWalls = 4;
    SystemState s = old;
    const std::int64_t n = entry(s.integers, "counters").at(5);
    for (const char* name : {"grain.wallState", "grain.wallStateEnd"})
    {
        const auto it = s.reals.find(name);
        if (it == s.reals.end() || it->second.size() != std::size_t(kWallRecord * oldMaxWalls * n))
            continue; // absent (sphere-only states) or not the old layout: checked later
        std::vector<double> padded(std::size_t(kWallStateComponents * n), 0.0);
        for (std::int64_t i = 0; i < n; ++i)
            std::copy_n(&it->second[std::size_t(i * kWallRecord * oldMaxWalls)],
                        kWallRecord * oldMaxWalls, &padded[std::size_t(i * kWallStateComponents)]);
        it->second = padded;
    }
    for (std::int64_t& bits : s.integers["grain.wallContacts"])
        bits = (bits & ((1 << oldMaxWalls) - 1)) | ((bits >> oldMaxWalls) << kMaxWalls);
    std::vector<std::int64_t>& wallInts = s.integers["walls.int"];
    std::vector<std::int64_t> withAxis;
    for (std::size_t w = 0; w + 2 < wallInts.size(); w += 3)
        withAxis.insert(withAxis.end(), {wallInts[w], wallInts[w + 1], wallInts[w + 2], 2});
    wallInts = withAxis;
    s.integers["walls.layout"] = {kMaxWalls};
    return s;
}
} // namespace stateDetail

template <class Exec>
SystemState EngineImpl<Exec>::exportState() const
{
    using namespace stateDetail;
    SystemState s;
    for (int f = 0; f < kRealFieldCount; ++f)
        if (!realFieldInfo(f).transient)
            s.reals[std::string("grain.") + realFieldInfo(f).name] = grains_.hostReal(f);
    for (int f = 0; f < kIntFieldCount; ++f)
    {
        const std::vector<int> v = grains_.hostInt(f);
        s.integers[std::string("grain.") + intFieldInfo(f).name].assign(v.begin(), v.end());
    }
    std::vector<int> ints;
    toHost(pairs_.start, ints);
    s.integers["pairs.start"].assign(ints.begin(), ints.end());
    toHost(pairs_.partner, ints);
    s.integers["pairs.partner"].assign(ints.begin(), ints.end());
    toHost(pairs_.incomingStart, ints);
    s.integers["pairs.incomingStart"].assign(ints.begin(), ints.end());
    toHost(pairs_.incomingPair, ints);
    s.integers["pairs.incomingPair"].assign(ints.begin(), ints.end());
    toHost(pairs_.history, s.reals["pairs.history"]);
    std::vector<double>& walls = s.reals["walls.real"];
    std::vector<std::int64_t>& wallInts = s.integers["walls.int"];
    for (const WallState& w : walls_)
    {
        walls.insert(walls.end(), {w.position, w.velocity, w.acceleration, w.grainForce,
                                   w.spec.velocity, w.spec.mass, w.spec.normalStress});
        wallInts.insert(wallInts.end(), {std::int64_t(w.spec.side), std::int64_t(w.spec.mode),
                                         std::int64_t(w.spec.frictional), w.spec.axis});
    }
    if (halo_) // this rank's part of a decomposed state: its grains, ghosts and exchange lists
        exportHalo(s);
    s.integers["walls.layout"] = {kMaxWalls}; // grain wall records per grain; 4 per wall int
    s.integers["pairs.historyLayout"] = {kHistoryLayout};
    s.reals["clock"] = {time_, params_.timeStep, params_.viscousDrag};
    if (params_.boxLengthRate[0] != 0.0 || params_.boxLengthRate[1] != 0.0)
        s.reals["box.lengthAtBuild"] = {boxLengthAtBuild_[0], boxLengthAtBuild_[1]};
    s.integers["counters"] = {steps_,
                              std::int64_t(rebuilds_),
                              grainsAtLastBuild_,
                              std::int64_t(needRebuild_),
                              std::int64_t(forcesStale_),
                              grains_.size()};
    if (params_.bonds.enabled)
    {
        // Bonds by add-order indices (their internal ones, the per-grain index and the pairs'
        // bonded flags follow from them at import).
        const std::vector<int> first = bonds_.hostFirst(), second = bonds_.hostSecond();
        s.integers["bonds.first"].assign(first.begin(), first.end());
        s.integers["bonds.second"].assign(second.begin(), second.end());
        const std::vector<double> state = bonds_.hostState();
        const std::size_t count = first.size();
        for (const BondField& f : bondFields())
            s.reals[std::string("bonds.") + f.name].assign(
                state.begin() + f.component * count,
                state.begin() + (f.component + f.components) * count);
        s.integers["bonds.counters"] = {std::int64_t(bondsFormed_), std::int64_t(bondsBroken_)};
        s.reals["bonds.brokenCreep"].assign(brokenBondCreep_.begin(), brokenBondCreep_.end());
    }
    return s;
}

template <class Exec>
void EngineImpl<Exec>::importState(const SystemState& s)
{
    using namespace stateDetail;
    if (s.integers.find("walls.layout") == s.integers.end())
        return importState(withWallLayoutOf6(s));
    if (entry(s.integers, "walls.layout") != std::vector<std::int64_t>{kMaxWalls})
        throw Error("importState: the state's wall layout (walls.layout) is not this version's (" +
                    std::to_string(kMaxWalls) + " walls)");
    const std::vector<std::int64_t>& counters = entry(s.integers, "counters");
    if (counters.size() != 6)
        throw Error("importState: 'counters' has " + std::to_string(counters.size()) +
                    " entries, expected 6");
    if (halo_ && s.integers.find("halo.decomposition") == s.integers.end())
        return importWholeState(s); // one process's state, distributed by the first rebuild
    if (entry(s.integers, "pairs.historyLayout") != std::vector<std::int64_t>{kHistoryLayout})
        throw Error("importState: the state's contact history layout (pairs.historyLayout) is "
                    "not this version's (" +
                    std::to_string(kHistoryLayout) + ")");
    const int n = int(counters[5]);
    grains_.resizeForImport(n);
    // A state written before grains had shapes (spheres only) lacks the shape fields: they
    // are what those spheres had (no core, I from 1/I, no capsule state), not an error.
    std::map<std::string, std::vector<double>> spheres;
    if (s.reals.find("grain.coreHalfLength") == s.reals.end())
    {
        const std::vector<double>& inverseInertia = entry(s.reals, "grain.inverseInertia");
        std::vector<double>& inertia = spheres["grain.principalInertia"];
        for (int c = 0; c < 3; ++c)
            for (double inverse : inverseInertia)
                inertia.push_back(1.0 / inverse);
        for (const int f : {fCoreHalfLength, fAngularMomentum, fWallStateEnd, fHalfAxisAtBuild})
            spheres[std::string("grain.") + realFieldInfo(f).name].assign(
                std::size_t(realFieldInfo(f).components) * n, 0.0);
    }
    for (int f = 0; f < kRealFieldCount; ++f)
    {
        if (realFieldInfo(f).transient)
        {
            grains_.setReal(f, std::vector<double>(std::size_t(realFieldInfo(f).components) * n));
            continue;
        }
        const std::string name = std::string("grain.") + realFieldInfo(f).name;
        const auto sphereDefault = spheres.find(name);
        const std::vector<double>& v =
            sphereDefault != spheres.end() ? sphereDefault->second : entry(s.reals, name);
        if (v.size() != std::size_t(realFieldInfo(f).components) * n)
            throw Error("importState: '" + name + "' has " + std::to_string(v.size()) +
                        " values for " + std::to_string(n) + " grains");
        grains_.setReal(f, v);
    }
    for (int f = 0; f < kIntFieldCount; ++f)
    {
        const std::string name = std::string("grain.") + intFieldInfo(f).name;
        const std::vector<std::int64_t>& v = entry(s.integers, name);
        if (v.size() != std::size_t(intFieldInfo(f).components) * n)
            throw Error("importState: '" + name + "' has the wrong size");
        grains_.setInt(f, std::vector<int>(v.begin(), v.end()));
    }
    auto ints = [&](const char* name)
    {
        const std::vector<std::int64_t>& v = entry(s.integers, name);
        return std::vector<int>(v.begin(), v.end());
    };
    fromHost(ints("pairs.start"), pairs_.start);
    fromHost(ints("pairs.partner"), pairs_.partner);
    fromHost(ints("pairs.incomingStart"), pairs_.incomingStart);
    fromHost(ints("pairs.incomingPair"), pairs_.incomingPair);
    fromHost(entry(s.reals, "pairs.history"), pairs_.history);
    pairs_.owner.resize(pairs_.partner.size());
    pairs_.sizeLoads(reactionComponents());
    if (pairs_.history.size() != 3 * kHistoryVectors * pairs_.partner.size())
        throw Error("importState: pair history and pair list sizes disagree");
    if (pairs_.start.empty() || long(pairs_.start.back()) != long(pairs_.partner.size()))
        throw Error("importState: pair starts and pair list sizes disagree");
    Exec::forEach(int(pairs_.start.size()) - 1,
                  FillOwners{thrust::raw_pointer_cast(pairs_.start.data()),
                             thrust::raw_pointer_cast(pairs_.owner.data())});

    const std::vector<double>& walls = entry(s.reals, "walls.real");
    const std::vector<std::int64_t>& wallInts = entry(s.integers, "walls.int");
    const std::size_t wallCount = wallInts.size() / 4;
    if (walls.size() != 7 * wallCount || wallInts.size() != 4 * wallCount ||
        wallCount > std::size_t(kMaxWalls))
        throw Error("importState: wall data is inconsistent");
    walls_.assign(wallCount, WallState());
    for (std::size_t w = 0; w < wallCount; ++w)
    {
        WallState& ws = walls_[w];
        const double* r = &walls[7 * w];
        ws.position = r[0];
        ws.velocity = r[1];
        ws.acceleration = r[2];
        ws.grainForce = r[3];
        ws.spec.position = r[0];
        ws.spec.velocity = r[4];
        ws.spec.mass = r[5];
        ws.spec.normalStress = r[6];
        ws.spec.side = WallSpec::Side(wallInts[4 * w]);
        ws.spec.mode = WallSpec::Mode(wallInts[4 * w + 1]);
        ws.spec.frictional = wallInts[4 * w + 2] != 0;
        ws.spec.axis = int(wallInts[4 * w + 3]);
    }
    const std::vector<double>& clock = entry(s.reals, "clock");
    if (clock.size() != 3)
        throw Error("importState: 'clock' must have 3 entries");
    time_ = clock[0];
    positionsTime_ = time_;
    // The list was built in this box, unless a deforming box's state says otherwise
    const auto built = s.reals.find("box.lengthAtBuild");
    if (built != s.reals.end() && built->second.size() == 2)
        boxLengthAtBuild_ = {built->second[0], built->second[1]};
    else
        boxLengthAtBuild_ = {currentBoxLength(0), currentBoxLength(1)};
    params_.timeStep = clock[1];
    params_.viscousDrag = clock[2];
    steps_ = counters[0];
    rebuilds_ = std::size_t(counters[1]);
    grainsAtLastBuild_ = int(counters[2]);
    needRebuild_ = counters[3] != 0;
    forcesStale_ = counters[4] != 0;
    oldPairs_ = PairStorage<Exec>();
    importHalo(s);
    importBonds(s);
    if (fluid_.active) // the imported grains feel the fluid set before
        storeFluidLoads();
}

template <class Exec>
void EngineImpl<Exec>::importBonds(const SystemState& s)
{
    using namespace stateDetail;
    const bool stored = s.integers.find("bonds.first") != s.integers.end();
    if (!params_.bonds.enabled)
    {
        if (stored && !entry(s.integers, "bonds.first").empty())
            throw Error("importState: the state holds bonds, but this System has none "
                        "(Parameters::bonds.enabled is false)");
        return;
    }
    std::vector<int> first, second;
    std::vector<double> state;
    bondsFormed_ = bondsBroken_ = 0;
    brokenBondCreep_ = {};
    if (stored) // else a state written without bonds: none yet
    {
        const std::vector<std::int64_t>& a = entry(s.integers, "bonds.first");
        const std::vector<std::int64_t>& b = entry(s.integers, "bonds.second");
        const std::vector<std::int64_t>& counters = entry(s.integers, "bonds.counters");
        if (b.size() != a.size() || counters.size() != 2)
            throw Error("importState: 'bonds.second' or 'bonds.counters' has the wrong size");
        const std::size_t count = a.size();
        // ids of this System's grains (over MPI ranks: of all ranks' grains)
        const std::int64_t n = halo_ ? halo_->addedGrains : grains_.size();
        for (std::size_t k = 0; k < count; ++k)
            if (a[k] < 0 || b[k] <= a[k] || b[k] >= n)
                throw Error("importState: bond " + std::to_string(k) + " joins grains " +
                            std::to_string(a[k]) + " and " + std::to_string(b[k]) +
                            "; expected 0 <= first < second < " + std::to_string(n));
        first.assign(a.begin(), a.end());
        second.assign(b.begin(), b.end());
        state.assign(kBondStateComponents * count, 0.0);
        for (const BondField& f : bondFields())
        {
            const std::string name = std::string("bonds.") + f.name;
            if (f.zeroIfAbsent && s.reals.find(name) == s.reals.end())
                continue; // a state written before the field existed
            const std::vector<double>& v = entry(s.reals, name);
            if (v.size() != std::size_t(f.components) * count)
                throw Error("importState: '" + name + "' has " + std::to_string(v.size()) +
                            " values for " + std::to_string(count) + " bonds");
            std::copy(v.begin(), v.end(), state.begin() + f.component * count);
        }
        bondsFormed_ = std::size_t(counters[0]);
        bondsBroken_ = std::size_t(counters[1]);
        const auto crept = s.reals.find("bonds.brokenCreep"); // absent before it existed
        if (crept != s.reals.end())
        {
            if (crept->second.size() != brokenBondCreep_.size())
                throw Error("importState: 'bonds.brokenCreep' has " +
                            std::to_string(crept->second.size()) + " values; expected " +
                            std::to_string(brokenBondCreep_.size()));
            std::copy(crept->second.begin(), crept->second.end(), brokenBondCreep_.begin());
        }
    }
    bonds_.assign(first, second, state);
    // A state written before the patches: its bonds are placed at the packed state.
    if (bodyFixedPatches())
        Exec::forEach(grains_.size(), PackGrains{grains_.view()});
    indexBonds(); // the order they had: a function of the grain order, restored above
}

} // namespace detail
} // namespace dem

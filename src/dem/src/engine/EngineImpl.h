// EngineImpl.h
// The engine, written once over an execution policy (OmpExecution with g++, CudaExecution
// with nvcc): owns grains, pairs and walls, and runs the velocity-Verlet step
//     kick-drift -> (rebuild if a grain moved more than skin/2) -> (bond formation) ->
//     pair forces -> bond forces (removal of broken bonds) ->
//     gather-kick (per-grain forces, the pairs' and bonds' sums, the kicks and the next drift)
// Walls are few and live on the host. Read-back, coupling and restart are in EngineIo.h, the
// bond store's set-up, upkeep and read-back in EngineBonds.h.
#pragma once

#include "dem/Error.h"
#include "engine/BondStorage.h"
#include "engine/Engine.h"
#include "engine/GrainStorage.h"
#include "engine/HaloState.h"
#include "engine/PairStorage.h"
#include "kernels/CouplingKernels.h"
#include "kernels/DiagnosticKernels.h"
#include "kernels/NeighbourKernels.h"
#include "kernels/StepKernels.h"

#include <thrust/binary_search.h>
#include <thrust/extrema.h>
#include <thrust/iterator/counting_iterator.h>
#include <thrust/scan.h>
#include <thrust/sequence.h>
#include <thrust/sort.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace dem
{
namespace detail
{

struct WallState
{
    WallSpec spec;
    double position = 0, velocity = 0, acceleration = 0, grainForce = 0;
};

template <class Exec>
class EngineImpl final : public Engine
{
public:
    template <class T>
    using Vec = typename Exec::template Vector<T>;

    explicit EngineImpl(const Parameters& p)
        : exec_(p.threads), params_(p), boxLengthAtBuild_{boxLength(0), boxLength(1)}
    {
        grains_.setCapsulePath(p.bonds.enabled); // bonds take the capsule forms
        if (p.decomposition.rankCount() > 1)
        {
            halo_ = std::make_unique<HaloState<Exec>>();
            halo_->comm = makeWorldCommunicator(p.decomposition.rankCount());
            halo_->boxes = RankBoxes(p);
        }
    }

    // ---- set-up ---------------------------------------------------------------------------
    int addGrains(const std::vector<GrainInit>& grains) override;
    int addWall(const WallSpec& wall) override
    {
        if (walls_.size() >= std::size_t(kMaxWalls))
            throw Error("addWall: at most " + std::to_string(kMaxWalls) + " walls are supported");
        WallState w;
        w.spec = wall;
        w.position = wall.position;
        w.velocity = wall.mode == WallSpec::Mode::fixed ? 0.0 : wall.velocity;
        walls_.push_back(w);
        if (!forcesStale_)
            accelerateWalls(); // its grain force is zero until the next force evaluation
        return int(walls_.size()) - 1;
    }
    void setWallMotion(int wall, const WallSpec& spec) override
    {
        WallState& w = walls_.at(checkWall(wall));
        if (spec.axis != w.spec.axis)
            throw Error("setWallMotion: wall " + std::to_string(wall) +
                        " cannot change its axis (add another wall)");
        w.spec = spec;
        w.spec.position = w.position;
        w.velocity = spec.mode == WallSpec::Mode::fixed ? 0.0 : spec.velocity;
        w.acceleration = 0.0;
        if (!forcesStale_)
            accelerateWalls(); // the next half kick sees the new mode's acceleration
    }
    void setWallStress(int wall, double normalStress) override
    {
        WallState& w = walls_.at(checkWall(wall));
        if (w.spec.mode != WallSpec::Mode::stress)
            throw Error("setWallStress: wall " + std::to_string(wall) +
                        " is not stress-controlled");
        w.spec.normalStress = normalStress;
    }
    void setGrainFlags(const std::vector<int>& indices, GrainFlag flag, double vx,
                       double vy) override;
    void setGrainVelocities(const std::vector<int>& indices, const std::array<double, 3>& velocity,
                            const std::array<double, 3>& angularVelocity) override;
    void setViscousDrag(double drag) override { params_.viscousDrag = drag; }
    void addBonds(const std::vector<BondInit>& bonds) override;
    BondData bonds() const override;
    BondCounts bondCounts() const override;
    void setGravity(const std::array<double, 3>& gravity) override { params_.gravity = gravity; }
    double maximumBondStiffness() const override;
    void setTimeStep(double dt) override { params_.timeStep = dt; }
    void setBoxMotion(const std::array<double, 2>& upper, double time,
                      const std::array<double, 2>& rate) override
    {
        params_.boxUpper = upper;
        params_.boxTime = time;
        params_.boxLengthRate = rate;
    }
    std::array<double, 2> boxUpper() const override
    {
        return {params_.boxLower[0] + currentBoxLength(0),
                params_.boxLower[1] + currentBoxLength(1)};
    }

    // ---- stepping -------------------------------------------------------------------------
    void step(int nSteps) override
    {
        const double dt = params_.timeStep;
        const double halfSkin = 0.5 * params_.neighbourSkin;
        if (forcesStale_ && (halo_ ? halo_->addedGrains > 0 : grains_.size() > 0))
            computeInitialForces();
        if (nSteps <= 0)
            return;
        checkWallAreas();
        // Each pass over the grains ends one step and begins the next (see GatherKick).
        double moved2 = 0.0;
        withShapes(
            [&](auto shapes) {
                moved2 =
                    exec_.maxOf(grains_.size(), KickDrift<decltype(shapes)>{grains_.view(), dt});
            });
        moved2 = globalMax(moved2); // all ranks rebuild together
        stopIfNotFinite(moved2);
        wallsKickDrift(dt);
        positionsTime_ = time_ + dt;
        for (int s = 0; s < nSteps; ++s)
        {
            // A pair across a deforming periodic side also comes closer by the box's change
            // since the last rebuild (0 in a fixed box: the plain skin/2 test)
            const double reach = halfSkin - 0.5 * boxChangeSinceBuild();
            exec_.stepBegins();
            if (needRebuild_ || reach < 0.0 || moved2 > reach * reach)
            {
                Exec::forEach(grains_.size(), UnpackGrains{grains_.view()});
                rebuild();
            }
            else if (halo_)
                refreshGhosts();
            if (formationDue())
                formBonds();
            computeForces(dt);
            const bool last = s + 1 == nSteps;
            moved2 = globalMax(gatherKick(dt, dt, !last));
            exec_.stepEnds(); // the CPU's team for the next step (OmpExecution)
            stopIfNotFinite(moved2);
            wallsFinishStep(dt); // the walls' grain forces were summed up by GatherKick
            if (!last)
                wallsKickDrift(dt);
            time_ += dt;
            positionsTime_ = last ? time_ : time_ + dt;
            ++steps_;
        }
        if (halo_) // the ghosts' fields as their owners' at the end of the call (read-backs)
        {
            refreshGhosts();
            Exec::forEach(grains_.size(), UnpackGrains{grains_.view()});
        }
    }

    // ---- read-back (EngineIo.h) -------------------------------------------------------------
    std::size_t ghostCount() const override { return halo_ ? std::size_t(halo_->ghostCount) : 0; }
    //- With a decomposition: the grains of all ranks (each counted by its owner).
    std::size_t grainCount() const override
    {
        return halo_ ? std::size_t(std::llround(globalSum(double(ownedCount()))))
                     : std::size_t(grains_.size());
    }
    double minimumMass() const override;
    GrainData grains() const override;
    int wallCount() const override { return int(walls_.size()); }
    WallData wall(int wall) const override;
    double prescribedGrainForceX() const override
    {
        return globalSum(exec_.sumOf(grains_.size(), PrescribedForceX{self().grains_.view()}));
    }
    double prescribedGrainImpulseX() const override
    {
        return globalSum(exec_.sumOf(grains_.size(), ComponentOf{self().grains_.real(fImpulseX)}));
    }
    std::size_t contactCount() const override;
    GrainOverlap largestOverlap() override;
    double maximumRadius() const override
    {
        return globalMax(exec_.maxOf(grains_.size(), ComponentOf{self().grains_.real(fRadius)}));
    }
    std::size_t pairCount() const override { return std::size_t(pairs_.count()); }
    std::size_t rebuildCount() const override { return rebuilds_; }
    double time() const override { return time_; }
    long long stepCount() const override { return steps_; }
    std::string name() const override { return Exec::name(); }
    int threads() const override { return exec_.threads(); }
    ThreadUse threadUse() const override { return exec_.threadUse(); }

    void deposit(const UniformGrid& grid, double dtFluid, double* porosity,
                 double* predictedPorosity, double* meanVelocity,
                 double* solidVolume) const override;
    void setFluid(const UniformGrid& grid, const FluidFields& fluid) override;
    void clearFluid() override { fluid_.active = false; }
    void depositFluidReaction(const UniformGrid& grid, double* reaction) const override;
    //- Each grain's fluid load (fFluidLoad) from the fields setFluid copied, at its position
    //- now: by setFluid, and again for grains added or imported while a fluid is set.
    void storeFluidLoads();
    //- grid checked, with the points kept half a cell inside the walls (EngineIo.h)
    GridView fluidGridView(const UniformGrid& grid, const char* caller) const;
    //- Points a copy of fluid_ at the grains' fluid loads (kernels get raw pointers).
    void pointFluidAt(FluidLoadView& fluid) const;
    //- The fluid force per grain as the next step applies it (read-back and reaction).
    GrainFluidForce grainFluidForce() const;

    SystemState exportState() const override;
    void importState(const SystemState& state) override;
    SystemState exportGatheredState() const override; // EngineGatheredState.h

private:
    // ---- over MPI ranks (EngineHalo.h) --------------------------------------------------------
    double globalMax(double v) const { return halo_ ? halo_->comm->max(v) : v; }
    double globalSum(double v) const { return halo_ ? halo_->comm->sum(v) : v; }
    //- Decomposed: each value replaced by its sum over the ranks (else unchanged).
    void sumOverRanks(Vec<double>& values) const;
    int ownedCount() const { return grains_.size() - (halo_ ? halo_->ghostCount : 0); }
    //- Decomposed: the grains' flags, for kernels that leave ghosts to their owners (else
    //- nullptr: every grain is the rank's own).
    const int* ghostFlagsOrNull() const { return halo_ ? self().grains_.integer(fFlag) : nullptr; }
    //- Throw for a call that a decomposed engine does not offer yet.
    void refuseDecomposed(const char* what) const;
    //- Before a rebuild: migration to the new owners and the ghost sets afresh.
    void redistribute();
    //- After the rebuild's TransferHistory: the histories that came with arrived grains.
    void restoreArrivedHistories();
    //- After the rebuild's sort: the internal indices of the per-step exchange.
    void indexGhostExchange();
    //- After every drift (no rebuild): the owners' step state onto the ghosts.
    void refreshGhosts();
    //- Whether the ghosts' step state includes their orientation: capsules (their cores), and
    //- spheres with bonds (the patches turn with the grains).
    bool ghostsTurn() const { return grains_.hasCapsules() || params_.bonds.enabled; }
    //- Bonds sit on patches held in the grains' body frames (BondPoint::bodyFixedPatches).
    bool bodyFixedPatches() const
    {
        return params_.bonds.enabled && params_.bonds.point == BondPoint::bodyFixedPatches;
    }
    //- The decomposed part of exportState / importState (restart on the same decomposition).
    void exportHalo(SystemState& s) const;
    void importHalo(const SystemState& s);
    //- importState of one process's state into a decomposed engine (EngineGatheredState.h).
    void importWholeState(const SystemState& whole);
    //- bondCounts over MPI ranks (EngineBonds.h).
    BondCounts decomposedBondCounts() const;
    //- Per bond in store order: 1 for the bonds this rank reports (all on one process; over
    //- MPI ranks those whose first grain it owns, so each bond is reported by one rank).
    std::vector<char> reportedBonds() const;

    // Read-back kernels need non-const views of storage they do not modify.
    EngineImpl& self() const { return const_cast<EngineImpl&>(*this); }

    int checkWall(int wall) const
    {
        if (wall < 0 || wall >= int(walls_.size()))
            throw Error("wall index " + std::to_string(wall) + " out of range [0, " +
                        std::to_string(walls_.size()) + ")");
        return wall;
    }

    //- The box at the time of the grains' positions (a deforming side's length changes).
    BoxView boxView() const
    {
        BoxView b;
        for (int d = 0; d < 2; ++d)
        {
            b.lower[d] = params_.boxLower[d];
            b.length[d] = currentBoxLength(d);
            b.lengthRate[d] = params_.boxLengthRate[d];
            b.periodic[d] = params_.periodic[d];
        }
        return b;
    }
    //- Parameters::boxLengthRate: the length at the positions' time (exactly boxLength(d) in a
    //- fixed box).
    double currentBoxLength(int d) const
    {
        return boxLength(d) + params_.boxLengthRate[d] * (positionsTime_ - params_.boxTime);
    }
    //- How far the box's lengths moved since the last rebuild (the Verlet test's share: a
    //- pair across a seam is nearer by at most that; 0 in a fixed box).
    double boxChangeSinceBuild() const
    {
        const double dx = currentBoxLength(0) - boxLengthAtBuild_[0];
        const double dy = currentBoxLength(1) - boxLengthAtBuild_[1];
        return std::sqrt(dx * dx + dy * dy);
    }

    //- The contact-law family: calls f(law, frictionlessLaw) with the evaluators of material
    //- m (ContactMaterial::law; frictionlessLaw: the same with mu = 0, for frictionless walls).
    //- A new law: its evaluator (forces(..., ContactPair) as LinearSpringContact's), its
    //- ContactLaw value and a branch here.
    template <class F>
    static void withLaw(const ContactMaterial& m, double dt, F&& f)
    {
        switch (m.law)
        {
        case ContactLaw::snow:
        {
            auto snow = [&](double mu)
            {
                return SnowContact::make(m.youngsModulus, m.tangentialToNormalStiffness,
                                         m.normalDampingRatio, m.tangentialDampingRatio, mu, dt);
            };
            f(snow(m.friction), snow(0.0));
            return;
        }
        case ContactLaw::linearSpring:
            break;
        }
        auto linear = [&](double mu)
        {
            return LinearSpringContact::make(m.normalStiffness, m.tangentialStiffness,
                                             m.normalDamping, m.tangentialDamping, mu, dt);
        };
        f(linear(m.friction), linear(0.0));
    }

    //- The shape family: SphereShapes while every grain is a sphere (today's arithmetic and
    //- the compact load record), CapsuleShapes once any grain has a core segment,
    //- BondedCapsuleShapes in a system with bonds.
    template <class F>
    void withShapes(F&& f) const
    {
        if (params_.bonds.enabled)
            f(BondedCapsuleShapes{});
        else if (grains_.hasCapsules())
            f(CapsuleShapes{});
        else
            f(SphereShapes{});
    }

    //- Per-pair and per-bond loads for GatherKick. historyDt: time step of the tangential
    //- spring increment and of the bonds' update (0: evaluate without advancing).
    void computeForces(double historyDt)
    {
        computePairForces(historyDt);
        if (params_.bonds.enabled)
            computeBondForces(historyDt);
    }

    void computePairForces(double historyDt)
    {
        withShapes(
            [&](auto shapes)
            {
                withLaw(params_.grainGrain, historyDt,
                        [&](auto law, auto)
                        {
                            using Kernel = PairForceKernel<decltype(shapes), decltype(law)>;
                            pairs_.beginPass();
                            Exec::forEachTouchingPair(
                                Kernel{grains_.view(), pairs_.view(), boxView(), law});
                        });
            });
    }

    //- The pass that ends a step: per-grain loads (gravity, drag, fluid, walls as they are now,
    //- before wallsFinishStep), the pairs' loads, the kicks and, with driftNext, the next drift.
    //- Returns the step's largest squared move (see movedOrInfinity).
    double gatherKick(double dt, double historyDt, bool driftNext)
    {
        double moved2 = 0.0;
        withShapes(
            [&](auto shapes)
            {
                withLaw(params_.grainWall, historyDt,
                        [&](auto law, auto frictionless)
                        {
                            using Shapes = decltype(shapes);
                            using Law = decltype(law);
                            GrainForceKernel<Shapes, Law> grainLoads{
                                grains_.view(),
                                wallsView(),
                                law,
                                frictionless,
                                {params_.gravity[0], params_.gravity[1], params_.gravity[2]},
                                params_.viscousDrag,
                                fluid_};
                            pointFluidAt(grainLoads.fluid);
                            const BondGather bonds =
                                Shapes::kBonds ? bonds_.gather() : BondGather{};
                            moved2 = exec_.maxOf(grains_.size(),
                                                 GatherKick<Shapes, Law>{grains_.view(),
                                                                         pairs_.view(), grainLoads,
                                                                         dt, driftNext, bonds});
                        });
            });
        return moved2;
    }

    WallsView wallsView() const
    {
        WallsView v;
        v.count = int(walls_.size());
        for (int w = 0; w < v.count; ++w)
        {
            v.axis[w] = walls_[w].spec.axis;
            v.position[w] = walls_[w].position;
            v.normalSign[w] = walls_[w].spec.side == WallSpec::Side::lower ? 1.0 : -1.0;
            v.velocity[w] = walls_[w].velocity;
            v.frictional[w] = walls_[w].spec.frictional;
        }
        return v;
    }

    //- The area a stress-controlled wall's normal stress acts on (WallSpec::Mode::stress): z
    //- walls the box's x-y area; x (y) walls the box's y (x) length times the gap between the
    //- z walls (the highest lower and the lowest upper one).
    double stressArea(const WallState& wall) const
    {
        const int axis = wall.spec.axis;
        if (axis == 2)
            return currentBoxLength(0) * currentBoxLength(1);
        return currentBoxLength(1 - axis) * zWallGap();
    }
    double boxLength(int d) const { return params_.boxUpper[d] - params_.boxLower[d]; }
    //- The gap between the z walls; -1 without a lower and an upper one.
    double zWallGap() const
    {
        double lower = -HUGE_VAL, upper = HUGE_VAL;
        for (const WallState& w : walls_)
            if (w.spec.axis == 2)
            {
                if (w.spec.side == WallSpec::Side::lower)
                    lower = std::max(lower, w.position);
                else
                    upper = std::min(upper, w.position);
            }
        return std::isfinite(lower) && std::isfinite(upper) ? upper - lower : -1.0;
    }
    //- Refuse a stress-controlled x or y wall without the z walls its area is measured between.
    void checkWallAreas() const
    {
        for (std::size_t w = 0; w < walls_.size(); ++w)
            if (walls_[w].spec.mode == WallSpec::Mode::stress && walls_[w].spec.axis != 2 &&
                zWallGap() < 0.0)
                throw Error("wall " + std::to_string(w) + ": a stress-controlled " +
                            (walls_[w].spec.axis == 0 ? "x" : "y") +
                            " wall needs a lower and an upper z wall (its area is the box's " +
                            (walls_[w].spec.axis == 0 ? "y" : "x") +
                            " length times their gap); add them or use another mode");
    }

    void wallsKickDrift(double dt)
    {
        for (WallState& w : walls_)
        {
            if (w.spec.mode == WallSpec::Mode::stress || w.spec.mode == WallSpec::Mode::free)
                w.velocity += 0.5 * dt * w.acceleration;
            if (w.spec.mode != WallSpec::Mode::fixed)
                w.position += dt * w.velocity;
        }
    }

    double wallGrainForce(int w) const
    {
        EngineImpl& e = self();
        // Ghosts hold zero wall loads (their owners sum them).
        return globalSum(exec_.sumOf(
            grains_.size(),
            WallForceOf{e.grains_.real(fWallState),
                        grains_.hasCapsules() ? e.grains_.real(fWallStateEnd) : nullptr, w}));
    }

    //- The accelerations of the stress-controlled and free walls from the grains' forces on
    //- them at the current state: stress walls (grain force + sigma0 A pressing onto the
    //- grains) / m; free walls grain force / m + g along their axis.
    void accelerateWalls()
    {
        for (std::size_t w = 0; w < walls_.size(); ++w)
        {
            WallState& wall = walls_[w];
            if (wall.spec.mode != WallSpec::Mode::stress && wall.spec.mode != WallSpec::Mode::free)
                continue;
            wall.grainForce = wallGrainForce(int(w));
            if (wall.spec.mode == WallSpec::Mode::free)
            {
                wall.acceleration =
                    wall.grainForce / wall.spec.mass + params_.gravity[std::size_t(wall.spec.axis)];
                continue;
            }
            // The applied stress presses the wall onto the grains (-axis for an upper wall).
            const double normalSign = wall.spec.side == WallSpec::Side::lower ? 1.0 : -1.0;
            wall.acceleration =
                (wall.grainForce + normalSign * wall.spec.normalStress * stressArea(wall)) /
                wall.spec.mass;
        }
    }

    void wallsFinishStep(double dt)
    {
        accelerateWalls();
        for (WallState& wall : walls_)
            if (wall.spec.mode == WallSpec::Mode::stress || wall.spec.mode == WallSpec::Mode::free)
                wall.velocity += 0.5 * dt * wall.acceleration;
    }

    //- Forces of freshly added grains, so the first half kick is second-order too.
    void computeInitialForces()
    {
        rebuild(); // with a decomposition: the grains go to their owners first
        Exec::forEach(grains_.size(), PackGrains{grains_.view()});
        computeForces(0.0);
        gatherKick(0.0, 0.0, false);
        forcesStale_ = false;
        accelerateWalls(); // so the walls' first half kick is second-order too
    }

    int reactionComponents() const
    {
        return grains_.hasCapsules() ? kCapsuleReactionComponents : kSphereReactionComponents;
    }

    //- The core half-lengths for kernels that take nullptr as "spheres only".
    double* halfLengths() const
    {
        return grains_.hasCapsules() ? self().grains_.real(fCoreHalfLength) : nullptr;
    }

    CellGridView cellGrid(); //!< also throwLeftTheNumbers if grains are absurdly far apart
    void rebuild();

    // ---- the bond store (EngineBonds.h) ------------------------------------------------------
    //- Internal grain indices of the bonds, the per-grain index and the pairs' bonded flags,
    //- after anything that changes the grain order, the pair list or the bonds.
    void indexBonds();
    //- Per-bond loads (BondForceKernel); broken bonds are counted and removed at once.
    void computeBondForces(double dt);
    bool formationDue() const
    {
        return params_.bonds.enabled && params_.bonds.formation == BondFormation::frozenOnContact &&
               steps_ % params_.bonds.formationInterval == 0;
    }
    //- frozenOnContact: a bond on every touching unbonded pair of the neighbour list.
    void formBonds();
    void importBonds(const SystemState& state); //!< the bond part of importState

    //- Throw when the step's largest squared move moved2 is not finite (before a NaN reaches a
    //- cell index): see throwLeftTheNumbers.
    void stopIfNotFinite(double moved2)
    {
        if (!(moved2 <= std::numeric_limits<double>::max()))
            throwLeftTheNumbers();
    }

    //- Throw naming the first grain whose position or velocity is not finite, else the one
    //- farthest out or fastest (a step far too large for the loads).
    [[noreturn]] void throwLeftTheNumbers()
    {
        const int n = grains_.size();
        Exec::forEach(n, UnpackGrains{grains_.view()});
        const std::vector<double> x = grains_.hostReal(fPosition), v = grains_.hostReal(fVelocity);
        const std::vector<int> id = grains_.hostInt(fId);
        int worst = 0;
        double worstSize = -1.0;
        for (int i = 0; i < n && worstSize <= std::numeric_limits<double>::max(); ++i)
            for (int d = 0; d < 3; ++d)
            {
                const double size = std::fabs(x[std::size_t(d) * n + i]) +
                                    std::fabs(v[std::size_t(d) * n + i]); // NaN stays NaN
                if (!(size <= worstSize))
                {
                    worst = i;
                    worstSize = std::isnan(size) ? HUGE_VAL : size;
                }
            }
        const int i = worst;
        std::ostringstream msg;
        msg.precision(10);
        msg << "grain " << id[i] << " left the numbers at step " << steps_ + 1 << " (t = " << time_
            << " s): position (" << x[i] << ' ' << x[n + i] << ' ' << x[2 * n + i]
            << "), velocity (" << v[i] << ' ' << v[n + i] << ' ' << v[2 * n + i]
            << "); the time step " << params_.timeStep
            << " s is too large for the loads (stiffness, drag, fluid force)";
        throw Error(msg.str());
    }

    //- The backend's execution state (CUDA: cached temporary storage and scratch for the
    //- reductions; the CPU: the team size from step to step). Mutable: read-back methods
    //- reduce too.
    mutable Exec exec_;
    Parameters params_;
    GrainStorage<Exec> grains_;
    PairStorage<Exec> pairs_, oldPairs_;
    BondStorage<Exec> bonds_;
    Vec<int> internalOf_, formationPairs_;
    Vec<double> bondBroken_;
    mutable Vec<double> bondReadback_;
    std::size_t bondsFormed_ = 0, bondsBroken_ = 0; //!< since the System was built
    //- Creep (normal, shear, twist, bend) of the bonds broken since the System was built.
    std::array<double, 4> brokenBondCreep_ = {};
    std::vector<WallState> walls_;
    Vec<int> cellKey_, order_, cellStart_, counts_;
    //- FluidFields as copied by setFluid: f (3 per cell), beta (1 per cell, empty: no drag),
    //- u (3 per cell); read into the grains' loads once per fluid step (storeFluidLoads)
    Vec<double> fluidForceDensity_, fluidDrag_, fluidVelocity_;
    GridView fluidGrid_;
    //- Scratch of the read-back and coupling calls (deposit each fluid step, grains() at each
    //- diagnostics write): kept, so those calls allocate no device memory once sized.
    mutable Vec<double> depositSolid_, depositMomentum_, depositPorosity_, fluidForceScratch_,
        reactionScratch_;
    mutable Vec<double> overlapScratch_, depthScratch_;
    mutable Vec<int> contactScratch_;
    FluidLoadView fluid_;
    //- Over MPI ranks only (Parameters::decomposition); null on one process.
    std::unique_ptr<HaloState<Exec>> halo_;
    bool needRebuild_ = true;
    bool forcesStale_ = true;
    int grainsAtLastBuild_ = 0;
    std::size_t rebuilds_ = 0;
    double time_ = 0.0;
    double positionsTime_ = 0.0; //!< time of the grains' positions (time_ + dt inside step())
    //- currentBoxLength at the last rebuild (state of a deforming box: "box.lengthAtBuild")
    std::array<double, 2> boxLengthAtBuild_;
    long long steps_ = 0;
};

} // namespace detail
} // namespace dem

#include "engine/EngineIo.h"
#include "engine/EngineHalo.h"
#include "engine/EngineGatheredState.h"
#include "engine/EngineNeighbours.h"
#include "engine/EngineBonds.h"

// dem/System.h
// The DEM system: spheres, walls, contacts and the grain <-> fluid-grid coupling, run by a CPU
// (OpenMP) or CUDA backend chosen at run time. Plain C++ only: this header is included by
// OpenFOAM code. All refusals throw dem::Error.
//
// Over MPI ranks (Parameters::decomposition, src/dem/README.md): each rank's System owns the
// grains in its box; set-up, step() and the read-backs that reduce (grainCount, wall,
// contactCount, prescribedGrainForceX/ImpulseX, criticalTimeStep) are collective; grains()
// returns this rank's own; pairCount is this rank's list; deposit and depositFluidReaction
// take the grid of the whole mesh on every rank and return the whole grid's values (summed over
// the ranks), setFluid takes the whole grid's fields; setGrainFlags is collective. addBonds,
// setGrainVelocities and largestOverlap are refused for now.
//
// Typical use:
//     dem::System dem(params);
//     dem.addGrains(grains); dem.addWall(bottom); dem.addWall(top);
//     dem.setFluid(grid, fluid);            // V (f + beta (u - v) - rho_f g) on every grain
//     dem.step(nSub);
//     dem.deposit(grid, dtFluid, porosity, predictedPorosity, meanVelocity);
#pragma once

#include "dem/Error.h"
#include "dem/Parameters.h"
#include "dem/State.h"
#include "dem/UniformGrid.h"

#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace dem
{

//- Number of CUDA devices that answer (0 when built without CUDA or without a driver).
DEM_API int cudaDeviceCount();

class DEM_API System
{
public:
    explicit System(const Parameters& parameters);
    ~System();
    System(System&&) noexcept;
    System& operator=(System&&) noexcept;
    System(const System&) = delete;
    System& operator=(const System&) = delete;

    // ---- set-up -------------------------------------------------------------------------
    //- Add grains; returns the index of the first (indices count in add order from 0). With a
    //- Decomposition (Parameters::decomposition) the call is collective: every rank adds its
    //- own grains (any, maybe none; they move to their owners at the first step), indices
    //- count rank 0's first, and the return is this rank's first.
    int addGrains(const std::vector<GrainInit>& grains);
    int addGrain(const GrainInit& grain) { return addGrains({grain}); }
    //- Add a wall; returns its index.
    int addWall(const WallSpec& wall);
    //- Change a wall's mode/velocity/mass/stress/friction; its current position is kept.
    void setWallMotion(int wall, const WallSpec& spec);
    //- Change the normal stress of a stress-controlled wall (load ramps); its position,
    //- velocity and acceleration are kept, so the wall's motion stays continuous.
    void setWallStress(int wall, double normalStress);
    //- Set the flag of grains `indices`; prescribedVelocity uses (vx, vy) for all of them.
    //- With a Decomposition the call is collective: each rank may list any grains (by add-order
    //- index), the union of the lists applies.
    void setGrainFlags(const std::vector<int>& indices, GrainFlag flag, double vx = 0.0,
                       double vy = 0.0);
    //- Set velocity and angular velocity of grains `indices` (any flag; a driven grain keeps
    //- them for ever). omega of a capsule sets its angular momentum.
    void setGrainVelocities(const std::vector<int>& indices, const std::array<double, 3>& velocity,
                            const std::array<double, 3>& angularVelocity);
    void setViscousDrag(double dragCoefficient);
    //- Change gravity (ramps): grains and free walls feel it from the next step.
    void setGravity(const std::array<double, 3>& gravity);
    //- Add bonds (Parameters::bonds.enabled); refused for unknown grains, a pair bonded twice or
    //- r_b <= 0. A bond acts while intact, whatever the distance of its grains.
    void addBonds(const std::vector<BondInit>& bonds);
    //- Change the time step (checked against the critical step at the next step()).
    void setTimeStep(double dt);
    //- From now on the periodic lengths change at `rate` [m/s] (Parameters::boxLengthRate),
    //- from the box as it is now (Parameters::boxTime becomes time()); {0, 0} stops them.
    void setBoxLengthRate(const std::array<double, 2>& rate);
    //- The box's motion as Parameters give it: boxUpper at System time boxTime, changing at
    //- boxLengthRate (a restart continuing a deforming box to the bit; boxLower is kept).
    void setBoxMotion(const std::array<double, 2>& boxUpper, double boxTime,
                      const std::array<double, 2>& rate);
    //- The box's upper corner in x and y now: boxLower + the lengths at time().
    std::array<double, 2> boxUpper() const;

    // ---- running ------------------------------------------------------------------------
    //- Advance nSteps DEM steps (velocity Verlet). Throws if dt > maxTimeStepFraction * dt_crit.
    void step(int nSteps);
    //- sqrt(m_min / k_max), k_max the largest normal or tangential stiffness in use (snow law:
    //- k_n = E pi R_max / 2 of the largest radius, and its k_t; bonds: the stiffest bond's
    //- k_ne A, or E pi f_max R_max / 2 with formation), m_min the smallest mass, or
    //- for a capsule also I_min / (r + h)^2 (its rotation against the longest lever).
    double criticalTimeStep() const;

    // ---- read-back ----------------------------------------------------------------------
    std::size_t grainCount() const;
    //- With a Decomposition: the copies of other ranks' grains this rank holds (its halo, as of
    //- the last neighbour rebuild); 0 on one process.
    std::size_t ghostCount() const;
    GrainData grains() const;
    int wallCount() const;
    WallData wall(int wall) const;
    //- Sum of x-forces on prescribedVelocity grains (shear resistance of the top layer) [N].
    double prescribedGrainForceX() const;
    //- Time integral of that force since the grains were added [N s], summed every step:
    //- differences over an interval give the interval's mean shear resistance.
    double prescribedGrainImpulseX() const;
    //- Grain-grain pairs currently touching (each counted once; bonded pairs included).
    std::size_t contactCount() const;
    //- Intact bonds and their state (empty without bonds).
    BondData bonds() const;
    BondCounts bondCounts() const;
    //- The pair of grains that overlap most relative to their smaller radius (shapes as they
    //- are, through the neighbour search: a start-state check before the first step; builds
    //- the neighbour list if it is not current).
    GrainOverlap largestOverlap() const;
    //- Neighbour-list pairs stored (each counted once).
    std::size_t pairCount() const;
    std::size_t neighbourRebuildCount() const;
    double time() const;
    long long stepCount() const;
    double timeStep() const;
    std::string backendName() const; //!< "cpu" or "cuda"
    int threadCount() const;         //!< CPU threads a step may use (1 for cuda)
    ThreadUse threadUse() const;     //!< the steps' CPU teams so far (threads 0: adaptive)
    const Parameters& parameters() const;

    // ---- fluid coupling (doc/EQUATIONS.md 6-7) -------------------------------------------------
    //- Deposit the grains on `grid` with trilinear weights to cell centres (mirrored at
    //- non-periodic sides, wrapped across periodic ones). Outputs (any may be nullptr, each
    //- grid.cellCount() long, meanVelocity 3 per cell interleaved):
    //-   porosity          phi = 1 - sum s V_g / V_cell
    //-   predictedPorosity the same with grains at x + v dtFluid
    //-   meanVelocity      sum s V_g v / sum s V_g (0 in cells without solid)
    //-   solidVolume       sum s V_g [m^3]
    void deposit(const UniformGrid& grid, double dtFluid, double* porosity,
                 double* predictedPorosity, double* meanVelocity,
                 double* solidVolume = nullptr) const;
    //- From now on every step adds F = V_g (f(x) + beta(x) (u(x) - v) - rho_f g) to each grain
    //- (FluidFields), the cell fields interpolated with the deposit's weights at x, where the
    //- grain is now (this call), and held until the next call; v and g are those of each step.
    //- The fields are copied; call again after every fluid solution (once per fluid step).
    void setFluid(const UniformGrid& grid, const FluidFields& fluid);
    void clearFluid();
    //- The grains' reaction on the fluid: per cell of `grid` (3 per cell interleaved) minus
    //- the sum of the fluid forces F on the grains (as the next step would apply them, at the
    //- current velocities), each spread with the trilinear weights of its current position,
    //- divided by the cell volume [N/m^3]. Momentum is
    //- conserved: sum over cells of reaction V_cell = -sum over grains of F. Zero without a
    //- fluid.
    void depositFluidReaction(const UniformGrid& grid, double* reaction) const;

    // ---- restart ------------------------------------------------------------------------
    //- Complete state; importing it into a System built with the same Parameters and walls
    //- and stepping gives bit-identical results to the uninterrupted run (same backend and
    //- thread count).
    SystemState exportState() const;
    //- Over MPI ranks (collective): each rank imports the part it exported, on the same
    //- decomposition (bit for bit as above); or every rank passes the same one-process state
    //- (exportState of a one-process System, or exportGatheredState), which rank 0 takes whole
    //- and the first step's rebuild distributes, each grain to its owner with its contacts'
    //- histories and bonds (as the split run would continue, to round-off).
    void importState(const SystemState& state);
    //- Collective. Over MPI ranks: on rank 0 every grain of every rank as one process's state
    //- (grains in id order, each contact's history and each bond once, walls, clock and
    //- counters; the neighbour list is rebuilt at the next step), which a one-process System
    //- with the same Parameters (decomposition 1 x 1) and walls imports and continues from;
    //- an empty state on the other ranks. On one process: exportState().
    SystemState exportGatheredState() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace dem

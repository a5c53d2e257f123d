// Engine.h
// The backend-neutral interface between dem::System (plain C++) and the engines that own the
// grain storage and run the kernels: EngineImpl<OmpExecution> (g++) and
// EngineImpl<CudaExecution> (nvcc). No Thrust or CUDA type appears here.
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
namespace detail
{

class Engine
{
public:
    virtual ~Engine() = default;

    //- Returns the index of the first grain added (with a decomposition: this rank's first; the
    //- call is collective, every rank adds its own grains, maybe none).
    virtual int addGrains(const std::vector<GrainInit>& grains) = 0;
    virtual int addWall(const WallSpec& wall) = 0;
    virtual void setWallMotion(int wall, const WallSpec& spec) = 0;
    virtual void setWallStress(int wall, double normalStress) = 0;
    virtual void setGrainFlags(const std::vector<int>& indices, GrainFlag flag, double vx,
                               double vy) = 0;
    virtual void setViscousDrag(double drag) = 0;
    // Issue 11 interfaces (bonds, walls, gravity): the engine overrides these; until then
    // they refuse with a clear error.
    virtual void setGrainVelocities(const std::vector<int>&, const std::array<double, 3>&,
                                    const std::array<double, 3>&)
    {
        throw Error("setGrainVelocities is not implemented yet");
    }
    virtual void setGravity(const std::array<double, 3>&)
    {
        throw Error("setGravity is not implemented yet");
    }
    virtual void addBonds(const std::vector<BondInit>&)
    {
        throw Error("addBonds is not implemented yet");
    }
    virtual BondData bonds() const { return BondData{}; }
    virtual BondCounts bondCounts() const { return BondCounts{}; }
    virtual ThreadUse threadUse() const = 0;
    //- The largest bond stiffness k_ne A of the bonds present and of those formation may add
    //- (the critical time step); 0 without bonds.
    virtual double maximumBondStiffness() const { return 0.0; }
    virtual void setTimeStep(double dt) = 0;
    //- The box's motion: boxUpper at time, changing at rate (Parameters::boxLengthRate;
    //- checked by System); boxUpper: the box now.
    virtual void setBoxMotion(const std::array<double, 2>& upper, double time,
                              const std::array<double, 2>& rate) = 0;
    virtual std::array<double, 2> boxUpper() const = 0;
    virtual void step(int nSteps) = 0;

    virtual std::size_t grainCount() const = 0;
    //- Copies of other ranks' grains this rank holds (0 on one process).
    virtual std::size_t ghostCount() const { return 0; }
    virtual double minimumMass() const = 0;
    virtual GrainData grains() const = 0;
    virtual int wallCount() const = 0;
    virtual WallData wall(int wall) const = 0;
    virtual double prescribedGrainForceX() const = 0;
    virtual double prescribedGrainImpulseX() const = 0;
    virtual std::size_t contactCount() const = 0;
    virtual GrainOverlap largestOverlap() = 0;
    virtual double maximumRadius() const = 0;
    virtual std::size_t pairCount() const = 0;
    virtual std::size_t rebuildCount() const = 0;
    virtual double time() const = 0;
    virtual long long stepCount() const = 0;
    virtual std::string name() const = 0;
    virtual int threads() const = 0;

    virtual void deposit(const UniformGrid& grid, double dtFluid, double* porosity,
                         double* predictedPorosity, double* meanVelocity,
                         double* solidVolume) const = 0;
    virtual void setFluid(const UniformGrid& grid, const FluidFields& fluid) = 0;
    virtual void clearFluid() = 0;
    virtual void depositFluidReaction(const UniformGrid& grid, double* reaction) const = 0;

    virtual SystemState exportState() const = 0;
    //- Collective: the whole system as one process's state on rank 0 (empty elsewhere).
    virtual SystemState exportGatheredState() const { return exportState(); }
    virtual void importState(const SystemState& state) = 0;
};

std::unique_ptr<Engine> makeCpuEngine(const Parameters& parameters);
//- Throws dem::Error when the library was built without CUDA or no device answers.
std::unique_ptr<Engine> makeCudaEngine(const Parameters& parameters);

} // namespace detail
} // namespace dem

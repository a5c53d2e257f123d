// System.cpp
// dem::System: parameter checks, run-time backend selection and the critical-time-step guard;
// everything else is forwarded to the engine of the chosen backend.
#include "dem/System.h"

#include "engine/Engine.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace dem
{

struct System::Impl
{
    Parameters parameters;
    std::unique_ptr<detail::Engine> engine;
};

namespace
{

void require(bool ok, const std::string& name, double value, const std::string& limit)
{
    if (!ok)
    {
        std::ostringstream msg;
        msg << "parameter " << name << " = " << value << " is invalid: it must be " << limit;
        throw Error(msg.str());
    }
}

void checkMaterial(const ContactMaterial& m, const std::string& prefix)
{
    require(m.friction >= 0, prefix + ".friction", m.friction, ">= 0");
    if (m.law == ContactLaw::snow)
    {
        require(m.youngsModulus > 0 && std::isfinite(m.youngsModulus), prefix + ".youngsModulus",
                m.youngsModulus, "> 0 and finite (snow law)");
        require(m.tangentialToNormalStiffness >= 0 && m.tangentialToNormalStiffness <= 1,
                prefix + ".tangentialToNormalStiffness", m.tangentialToNormalStiffness,
                "in [0, 1] (snow law: k_t / k_n)");
        require(m.normalDampingRatio >= 0 && m.normalDampingRatio <= 1,
                prefix + ".normalDampingRatio", m.normalDampingRatio,
                "in [0, 1] (snow law: fraction of critical damping)");
        require(m.tangentialDampingRatio >= 0 && m.tangentialDampingRatio <= 1,
                prefix + ".tangentialDampingRatio", m.tangentialDampingRatio,
                "in [0, 1] (snow law: fraction of critical damping)");
        return;
    }
    require(m.law == ContactLaw::linearSpring, prefix + ".law", double(int(m.law)),
            "linearSpring or snow");
    require(m.normalStiffness > 0, prefix + ".normalStiffness", m.normalStiffness, "> 0");
    require(m.tangentialStiffness >= 0, prefix + ".tangentialStiffness", m.tangentialStiffness,
            ">= 0");
    require(m.normalDamping >= 0, prefix + ".normalDamping", m.normalDamping, ">= 0");
    require(m.tangentialDamping >= 0, prefix + ".tangentialDamping", m.tangentialDamping, ">= 0");
}

//- What the bond store itself needs (formation); the laws' constants are checked beside them.
void checkBondStore(const BondParameters& b)
{
    if (!b.enabled)
        return;
    require(b.formationInterval >= 1, "bonds.formationInterval", b.formationInterval,
            ">= 1 (steps between freezing checks)");
    require(b.areaFraction[0] > 0 && b.areaFraction[0] <= 1, "bonds.areaFraction[0]",
            b.areaFraction[0], "in (0, 1] (r_b^2 / r_min^2)");
    require(b.areaFraction[1] >= b.areaFraction[0] && b.areaFraction[1] <= 1,
            "bonds.areaFraction[1]", b.areaFraction[1], "in [areaFraction[0], 1]");
}

//- The bond law's constants (src/kernels/bonds): each mechanism's only when it is on.
void checkBondLaw(const BondParameters& b)
{
    if (!b.enabled)
        return;
    require(b.youngsModulus > 0 && std::isfinite(b.youngsModulus), "bonds.youngsModulus",
            b.youngsModulus, "> 0 and finite");
    require(b.shearToNormalStiffness > 0 && b.shearToNormalStiffness <= 1,
            "bonds.shearToNormalStiffness", b.shearToNormalStiffness, "in (0, 1] (k_se / k_ne)");
    require(b.normalDampingRatio >= 0 && b.normalDampingRatio <= 1, "bonds.normalDampingRatio",
            b.normalDampingRatio, "in [0, 1] (fraction of critical)");
    require(b.shearDampingRatio >= 0 && b.shearDampingRatio <= 1, "bonds.shearDampingRatio",
            b.shearDampingRatio, "in [0, 1] (fraction of critical)");
    require(b.temperature > -273.15 && b.temperature <= 0, "bonds.temperature", b.temperature,
            "in (-273.15, 0] degrees C (ice)");
    if (b.creep == BondCreep::maxwell)
        require(b.contactViscosity > 0 && std::isfinite(b.contactViscosity),
                "bonds.contactViscosity", b.contactViscosity, "> 0 and finite (maxwell creep)");
    if (b.compressiveCreep == BondCompressiveCreep::powerLaw ||
        b.sintering == BondSintering::pressureSintering)
    {
        require(b.creepPrefactor > 0 && std::isfinite(b.creepPrefactor), "bonds.creepPrefactor",
                b.creepPrefactor, "> 0 and finite (powerLaw creep, pressureSintering)");
        require(b.creepActivationEnergy >= 0 && std::isfinite(b.creepActivationEnergy),
                "bonds.creepActivationEnergy", b.creepActivationEnergy,
                ">= 0 and finite (powerLaw creep, pressureSintering)");
    }
    if (b.compressiveCreep == BondCompressiveCreep::powerLaw)
    {
        require(b.creepExponent > 1 && b.creepExponent <= 10, "bonds.creepExponent",
                b.creepExponent, "in (1, 10] (powerLaw creep)");
        // Sintering's law is A(T) sigma^3 with the same A0: its units hold for one exponent.
        if (b.sintering == BondSintering::pressureSintering)
            require(b.creepExponent == 3, "bonds.creepExponent", b.creepExponent,
                    "3 with pressureSintering (both use A0 [s^-1 Pa^-3])");
    }
    if (b.strength == BondStrength::iceTemperature)
        require(b.strengthScale > 0 && std::isfinite(b.strengthScale), "bonds.strengthScale",
                b.strengthScale, "> 0 and finite (iceTemperature strength)");
    if (b.strength == BondStrength::constant)
    {
        require(b.tensileStrength >= 0 && std::isfinite(b.tensileStrength), "bonds.tensileStrength",
                b.tensileStrength,
                ">= 0 and finite (constant strength; 0: never fails in tension)");
        require(b.shearStrength >= 0 && std::isfinite(b.shearStrength), "bonds.shearStrength",
                b.shearStrength, ">= 0 and finite (constant strength; 0: never fails in shear)");
    }
    if (b.strength != BondStrength::none)
    {
        require(b.softeningRatio > 0 && std::isfinite(b.softeningRatio), "bonds.softeningRatio",
                b.softeningRatio, "> 0 and finite (k_2 / k_ne)");
        require(b.brokenFraction >= 0 && b.brokenFraction < 1, "bonds.brokenFraction",
                b.brokenFraction, "in [0, 1) (of the mean radius)");
    }
}

//- The box: upper above lower, and a length rate only on a periodic side of one process.
void checkBox(const Parameters& p)
{
    for (int d = 0; d < 2; ++d)
        require(p.boxUpper[d] > p.boxLower[d], d == 0 ? "boxUpper[0]" : "boxUpper[1]",
                p.boxUpper[d], "> boxLower");
    for (int d = 0; d < 2; ++d)
    {
        const char* rate = d == 0 ? "boxLengthRate[0]" : "boxLengthRate[1]";
        require(std::isfinite(p.boxLengthRate[d]), rate, p.boxLengthRate[d], "finite");
        if (p.boxLengthRate[d] != 0.0)
        {
            require(p.periodic[d], rate, p.boxLengthRate[d],
                    "0 on a side that is not periodic (Parameters::periodic)");
            require(p.decomposition.rankCount() == 1, rate, p.boxLengthRate[d],
                    "0 with a decomposition over MPI ranks (a deforming box runs on one "
                    "process)");
        }
    }
    require(std::isfinite(p.boxTime), "boxTime", p.boxTime, "finite");
}

void checkParameters(const Parameters& p)
{
    checkMaterial(p.grainGrain, "grainGrain");
    checkMaterial(p.grainWall, "grainWall");
    require(p.timeStep > 0, "timeStep", p.timeStep, "> 0");
    require(p.neighbourSkin >= 0, "neighbourSkin", p.neighbourSkin, ">= 0");
    require(p.maxTimeStepFraction > 0, "maxTimeStepFraction", p.maxTimeStepFraction, "> 0");
    require(p.defaultDensity > 0, "defaultDensity", p.defaultDensity, "> 0");
    require(p.viscousDrag >= 0, "viscousDrag", p.viscousDrag, ">= 0");
    require(p.threads >= 0, "threads", p.threads, ">= 0 (0: OpenMP default)");
    require(p.maxPairsPerGrain >= 0, "maxPairsPerGrain", p.maxPairsPerGrain, ">= 0 (0: grow)");
    checkBox(p);
    checkBondStore(p.bonds);
    checkBondLaw(p.bonds);
    for (int d = 0; d < 2; ++d)
        require(p.decomposition.ranks[d] >= 1,
                d == 0 ? "decomposition.ranks[0]" : "decomposition.ranks[1]",
                p.decomposition.ranks[d], ">= 1 (boxes along x and y; 1 x 1: one process)");
}

void checkWall(const WallSpec& w, const Parameters& p)
{
    require(w.axis >= 0 && w.axis <= 2, "wall.axis", w.axis, "0 (x), 1 (y) or 2 (z)");
    require(std::isfinite(w.position), "wall.position", w.position, "finite");
    if (w.axis < 2 && p.periodic[std::size_t(w.axis)])
        throw Error(std::string("a wall on ") + (w.axis == 0 ? "x" : "y") +
                    " needs a box that is "
                    "not periodic in " +
                    (w.axis == 0 ? "x" : "y") +
                    " (Parameters::periodic): grains would meet it and its periodic image");
    if (w.mode == WallSpec::Mode::stress)
        require(w.mass > 0, "wall.mass", w.mass, "> 0 for a stress-controlled wall");
    if (w.mode == WallSpec::Mode::free)
        require(w.mass > 0 && std::isfinite(w.mass), "wall.mass", w.mass,
                "> 0 and finite for a free wall");
}

//- The largest normal or tangential stiffness of a material: its constants (linear spring), or
//- k_n = E pi Rbar / 2 at the largest mean radius Rbar <= rMax and k_t = (k_t/k_n) k_n (snow).
double stiffest(const ContactMaterial& m, double rMax)
{
    if (m.law == ContactLaw::snow)
    {
        const double kn = 0.5 * M_PI * m.youngsModulus * rMax;
        return std::max(kn, m.tangentialToNormalStiffness * kn);
    }
    return std::max(m.normalStiffness, m.tangentialStiffness);
}

double stiffest(const Parameters& p, double rMax)
{
    return std::max(stiffest(p.grainGrain, rMax), stiffest(p.grainWall, rMax));
}

} // namespace

System::System(const Parameters& parameters) : impl_(std::make_unique<Impl>())
{
    checkParameters(parameters);
    impl_->parameters = parameters;
    switch (parameters.backend)
    {
    case Backend::cpu:
        impl_->engine = detail::makeCpuEngine(parameters);
        break;
    case Backend::cuda:
        impl_->engine = detail::makeCudaEngine(parameters);
        break;
    case Backend::automatic:
        impl_->engine = cudaDeviceCount() > 0 ? detail::makeCudaEngine(parameters)
                                              : detail::makeCpuEngine(parameters);
        break;
    }
}

System::~System() = default;
System::System(System&&) noexcept = default;
System& System::operator=(System&&) noexcept = default;

int System::addGrains(const std::vector<GrainInit>& grains)
{
    return impl_->engine->addGrains(grains);
}

int System::addWall(const WallSpec& wall)
{
    checkWall(wall, impl_->parameters);
    return impl_->engine->addWall(wall);
}

void System::setWallMotion(int wall, const WallSpec& spec)
{
    checkWall(spec, impl_->parameters);
    impl_->engine->setWallMotion(wall, spec);
}

void System::setWallStress(int wall, double normalStress)
{
    require(std::isfinite(normalStress), "wall.normalStress", normalStress, "finite");
    impl_->engine->setWallStress(wall, normalStress);
}

void System::setGrainFlags(const std::vector<int>& indices, GrainFlag flag, double vx, double vy)
{
    impl_->engine->setGrainFlags(indices, flag, vx, vy);
}

void System::setGrainVelocities(const std::vector<int>& indices,
                                const std::array<double, 3>& velocity,
                                const std::array<double, 3>& angularVelocity)
{
    for (int d = 0; d < 3; ++d)
    {
        require(std::isfinite(velocity[d]), "velocity", velocity[d], "finite");
        require(std::isfinite(angularVelocity[d]), "angularVelocity", angularVelocity[d], "finite");
    }
    impl_->engine->setGrainVelocities(indices, velocity, angularVelocity);
}

void System::setGravity(const std::array<double, 3>& gravity)
{
    for (int d = 0; d < 3; ++d)
        require(std::isfinite(gravity[d]), "gravity", gravity[d], "finite");
    impl_->parameters.gravity = gravity;
    impl_->engine->setGravity(gravity);
}

void System::addBonds(const std::vector<BondInit>& bonds)
{
    if (!impl_->parameters.bonds.enabled)
        throw Error("addBonds: bonds are not enabled (Parameters::bonds.enabled)");
    impl_->engine->addBonds(bonds);
}

BondData System::bonds() const
{
    return impl_->engine->bonds();
}

BondCounts System::bondCounts() const
{
    return impl_->engine->bondCounts();
}

void System::setViscousDrag(double drag)
{
    require(drag >= 0, "viscousDrag", drag, ">= 0");
    impl_->parameters.viscousDrag = drag;
    impl_->engine->setViscousDrag(drag);
}

void System::setBoxLengthRate(const std::array<double, 2>& rate)
{
    setBoxMotion(boxUpper(), time(), rate);
}
void System::setBoxMotion(const std::array<double, 2>& upper, double boxTime,
                          const std::array<double, 2>& rate)
{
    Parameters p = impl_->parameters;
    p.boxUpper = upper;
    p.boxTime = boxTime;
    p.boxLengthRate = rate;
    checkBox(p);
    impl_->engine->setBoxMotion(upper, boxTime, rate);
    impl_->parameters = p;
}
std::array<double, 2> System::boxUpper() const
{
    return impl_->engine->boxUpper();
}

void System::setTimeStep(double dt)
{
    require(dt > 0, "timeStep", dt, "> 0");
    impl_->parameters.timeStep = dt;
    impl_->engine->setTimeStep(dt);
}

//- k_max of the critical time step: the contact laws' and the bonds' (present and to come).
static double largestStiffness(const Parameters& p, const detail::Engine& engine)
{
    return std::max(stiffest(p, engine.maximumRadius()), engine.maximumBondStiffness());
}

double System::criticalTimeStep() const
{
    if (impl_->engine->grainCount() == 0)
        return 0.0;
    return std::sqrt(impl_->engine->minimumMass() /
                     largestStiffness(impl_->parameters, *impl_->engine));
}

void System::step(int nSteps)
{
    require(nSteps >= 0, "nSteps", nSteps, ">= 0");
    if (impl_->engine->grainCount() > 0)
    {
        const Parameters& p = impl_->parameters;
        const double critical = criticalTimeStep();
        if (p.timeStep > p.maxTimeStepFraction * critical)
        {
            std::ostringstream msg;
            msg << "timeStep = " << p.timeStep << " s exceeds the limit "
                << p.maxTimeStepFraction * critical << " s = maxTimeStepFraction ("
                << p.maxTimeStepFraction
                << ") x critical time step sqrt(m_min / k_max) = " << critical
                << " s (m_min = " << impl_->engine->minimumMass()
                << " kg, the smallest mass or capsule's I / lever^2; k_max = "
                << largestStiffness(p, *impl_->engine) << " N/m); reduce timeStep";
            throw Error(msg.str());
        }
    }
    impl_->engine->step(nSteps);
}

std::size_t System::ghostCount() const
{
    return impl_->engine->ghostCount();
}

std::size_t System::grainCount() const
{
    return impl_->engine->grainCount();
}
GrainData System::grains() const
{
    return impl_->engine->grains();
}
int System::wallCount() const
{
    return impl_->engine->wallCount();
}
WallData System::wall(int wall) const
{
    return impl_->engine->wall(wall);
}
double System::prescribedGrainForceX() const
{
    return impl_->engine->prescribedGrainForceX();
}
double System::prescribedGrainImpulseX() const
{
    return impl_->engine->prescribedGrainImpulseX();
}
std::size_t System::contactCount() const
{
    return impl_->engine->contactCount();
}
GrainOverlap System::largestOverlap() const
{
    return impl_->engine->largestOverlap();
}
std::size_t System::pairCount() const
{
    return impl_->engine->pairCount();
}
std::size_t System::neighbourRebuildCount() const
{
    return impl_->engine->rebuildCount();
}
double System::time() const
{
    return impl_->engine->time();
}
long long System::stepCount() const
{
    return impl_->engine->stepCount();
}
double System::timeStep() const
{
    return impl_->parameters.timeStep;
}
std::string System::backendName() const
{
    return impl_->engine->name();
}
int System::threadCount() const
{
    return impl_->engine->threads();
}
ThreadUse System::threadUse() const
{
    return impl_->engine->threadUse();
}
const Parameters& System::parameters() const
{
    return impl_->parameters;
}

void System::deposit(const UniformGrid& grid, double dtFluid, double* porosity,
                     double* predictedPorosity, double* meanVelocity, double* solidVolume) const
{
    impl_->engine->deposit(grid, dtFluid, porosity, predictedPorosity, meanVelocity, solidVolume);
}

void System::setFluid(const UniformGrid& grid, const FluidFields& fluid)
{
    impl_->engine->setFluid(grid, fluid);
}

void System::depositFluidReaction(const UniformGrid& grid, double* reaction) const
{
    if (!reaction)
        throw Error("depositFluidReaction: reaction is null");
    impl_->engine->depositFluidReaction(grid, reaction);
}

void System::clearFluid()
{
    impl_->engine->clearFluid();
}

SystemState System::exportState() const
{
    return impl_->engine->exportState();
}

SystemState System::exportGatheredState() const
{
    return impl_->engine->exportGatheredState();
}

void System::importState(const SystemState& state)
{
    impl_->engine->importState(state);
    const auto clock = state.reals.find("clock");
    if (clock != state.reals.end() && clock->second.size() == 3)
    {
        impl_->parameters.timeStep = clock->second[1];
        impl_->parameters.viscousDrag = clock->second[2];
    }
}

} // namespace dem

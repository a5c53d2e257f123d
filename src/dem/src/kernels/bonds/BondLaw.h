// BondLaw.h
// The bond evaluator, written once for both backends: one frozen ice contact (Johnson & Hopkins
// 2005) between grains A (the lower add-order index) and B, advanced by one step. The mechanisms
// (elastic patch, grain-boundary creep, compressive creep, strength and softening, sintering)
// are families chosen by BondParameters; each model is a small evaluator in this directory, its
// constants computed once on the host by BondLaw::make. doc/EQUATIONS.md, "Bonds", has the
// equations, the sign rules and the choices.
#pragma once

#include "backends/HostDevice.h"
#include "dem/Parameters.h"
#include "kernels/bonds/BondGeometry.h"
#include "kernels/bonds/ElasticPatch.h"
#include "kernels/bonds/IceStrength.h"
#include "kernels/bonds/MaxwellCreep.h"
#include "kernels/bonds/PowerLawCreep.h"
#include "kernels/bonds/Sintering.h"

#include <cmath>

namespace dem
{
namespace detail
{
inline namespace DEM_KERNEL_NS
{

//- What a bond remembers between steps (BondStorage holds it per bond, structure of arrays).
//- Forces and moments are the elastic (stored) loads on grain A, in the global frame.
struct BondState
{
    double normalForce = 0.0;               //!< N, tension positive
    Vector3d shearForce = Vector3d::Zero(); //!< S, in the contact plane
    double twistMoment = 0.0;               //!< M_t, along the normal
    Vector3d bendMoment = Vector3d::Zero(); //!< M_b, in the contact plane
    double patchRadius = 0.0;               //!< r_b
    double onsetRadius = 0.0;               //!< r_b when softening began (= r_b before)
    double age = 0.0;                       //!< time since the bond formed [s]
    //- Creep accumulated since the bond formed, per mechanism: the path length of the creep
    //- displacement (load relaxed by creep over the mode's stiffness, summed in magnitude step
    //- by step): normal and shear [m], twist and bend [rad].
    double creepNormal = 0.0, creepShear = 0.0, creepTwist = 0.0, creepBend = 0.0;
    //- Net normal creep of the power law (opening positive) [m], within +-Rbar.
    double normalCreepOffset = 0.0;
    bool softening = false; //!< past peak strength (r_b only shrinks)
    bool broken = false;    //!< set by advance: remove the bond
};

// BondGeometry (where the bond sits) and bondGeometry() are in BondGeometry.h.

//- How the two grains move (centres' velocities, angular velocities, inverse masses).
struct BondMotion
{
    Vector3d velocityA, velocityB, omegaA, omegaB;
    double inverseMassA, inverseMassB;
};

//- Loads of the bond this step (elastic + viscous): force on A (on B: minus), torques on both
//- including (contact point - centre) x force. And the step's normal and shear creep as B's
//- displacement relative to A (global frame; zero without creep): the patches move by it
//- towards each other (creptPatches), as the paper's creep brings them into alignment.
struct BondLoads
{
    Vector3d forceOnA, torqueOnA, torqueOnB;
    Vector3d creepShift;
};

//- The evaluator: constants from BondParameters and the time step (trivially copyable).
struct BondLaw
{
    BondParameters p; // plain struct of numbers and enums
    double dt = 0.0;
    // Each mechanism's evaluator with its constants (make() fills them).
    MaxwellCreep shearCreep, twistCreep, bendCreep;
    PowerLawCreep compressiveCreep;
    IceStrength strength;
    Sintering sintering;
    double normalDashpot = 0.0, shearDashpot = 0.0; //!< 2 zeta_n, 2 zeta_s sqrt(k_se/k_ne)
    bool creeps = false; //!< any creep mechanism on: the creep displacements are summed

    //- Relaxation times of grain-boundary creep: tau_shear = tau_twist = nu_s / (k_se/k_ne E),
    //- tau_bend = nu_s / E (the viscosity over the patch's modulus in that mode).
    static BondLaw make(const BondParameters& parameters, double timeStep)
    {
        BondLaw law;
        law.p = parameters;
        law.dt = timeStep;
        const bool maxwell = parameters.creep == BondCreep::maxwell;
        const double E = parameters.youngsModulus, nu = parameters.contactViscosity;
        const double tauShear = nu / (parameters.shearToNormalStiffness * E);
        const double tauBend = nu / E;
        law.shearCreep = MaxwellCreep::make(maxwell && parameters.shearCreep, tauShear, timeStep);
        law.twistCreep = MaxwellCreep::make(maxwell && parameters.twistCreep, tauShear, timeStep);
        law.bendCreep = MaxwellCreep::make(maxwell && parameters.bendCreep, tauBend, timeStep);
        law.compressiveCreep = PowerLawCreep::make(parameters, timeStep);
        law.strength = IceStrength::make(parameters);
        law.sintering = Sintering::make(parameters, timeStep);
        law.creeps =
            (maxwell && (parameters.shearCreep || parameters.twistCreep || parameters.bendCreep)) ||
            law.compressiveCreep.on;
        law.normalDashpot = 2.0 * parameters.normalDampingRatio;
        law.shearDashpot =
            2.0 * parameters.shearDampingRatio * std::sqrt(parameters.shearToNormalStiffness);
        return law;
    }

    //- Advance state s over one step dt with the grains' motion and return the loads. Sets
    //- s.broken when the bond breaks (its loads this step are then zero). dt = 0 evaluates
    //- the loads of s as it is and leaves s untouched, bit for bit (the engine's loads of
    //- freshly added grains: bonds already present, when grains are added mid-run, keep their
    //- state exactly, whatever the mechanisms).
    DEM_HD BondLoads advance(BondState& s, const BondGeometry& g, const BondMotion& m) const
    {
        BondLoads loads{Vector3d::Zero(), Vector3d::Zero(), Vector3d::Zero(), Vector3d::Zero()};
        if (s.broken)
            return loads;
        const Vector3d& n = g.normal;
        const double meanRadius = 0.5 * (g.radiusA + g.radiusB);
        const PatchIncrement du = patchIncrement(n, g.offsetA, g.offsetB, m.velocityA, m.velocityB,
                                                 m.omegaA, m.omegaB, dt);
        PatchSection patch = PatchSection::make(s.patchRadius, p.youngsModulus,
                                                p.shearToNormalStiffness, meanRadius);
        if (dt > 0.0 && !evolve(s, g, m, du, meanRadius, patch, loads))
        {
            s.broken = true;
            return loads;
        }

        // The loads: the elastic loads and the dashpots of the patch as it is now,
        // c = 2 zeta sqrt(m* k A) (k_se A = (k_se/k_ne) k_ne A: one root for both).
        const double inverseMassSum = m.inverseMassA + m.inverseMassB;
        // Two immovable grains (no inverse mass): no dashpot rather than an infinite one.
        const double reducedMass = inverseMassSum > 0.0 ? 1.0 / inverseMassSum : 0.0;
        const double root = std::sqrt(reducedMass * patch.normalStiffness * patch.area);
        const double normalSpeed = du.velocity.dot(n);
        const Vector3d force = (s.normalForce + normalDashpot * root * normalSpeed) * n +
                               s.shearForce +
                               (shearDashpot * root) * (du.velocity - normalSpeed * n);
        const Vector3d moment = s.twistMoment * n + s.bendMoment;
        loads.forceOnA = force;
        loads.torqueOnA = g.offsetA.cross(force) + moment;
        loads.torqueOnB = -g.offsetB.cross(force) - moment;
        return loads;
    }

private:
    //- One step of the state: returns false when the bond breaks. patch: the section at the
    //- start of the step, on return the section at its end; loads: its creep of the step.
    DEM_HD bool evolve(BondState& s, const BondGeometry& g, const BondMotion& m,
                       const PatchIncrement& du, double meanRadius, PatchSection& patch,
                       BondLoads& loads) const
    {
        const Vector3d& n = g.normal;
        // 1. Stored in-plane loads into the current plane, turning with the pair's mean rotation.
        const Vector3d theta = (0.5 * dt) * (m.omegaA + m.omegaB);
        s.shearForce = rotateIntoPlane(s.shearForce, n, theta);
        s.bendMoment = rotateIntoPlane(s.bendMoment, n, theta);

        // 2. Elastic increments with the patch at the start of the step, and creep. The load a
        //    mechanism's creep relaxed this step (purely elastic load minus the crept one) over
        //    the mode's stiffness is the creep displacement of the step: in a Maxwell element
        //    the imposed increment splits into the spring's (dX / K) and the dashpot's.
        const double kn = patch.normalStiffness * patch.area,
                     ks = patch.shearStiffness * patch.area;
        const double kt = patch.shearStiffness * patch.twistInertia;
        const double kb = patch.normalStiffness * patch.bendInertia;
        const double elasticN = s.normalForce + kn * du.normal;
        const Vector3d elasticS = s.shearForce + ks * du.shear;
        const double elasticMt = s.twistMoment + kt * du.twist;
        const Vector3d elasticMb = s.bendMoment + kb * du.bend;
        s.normalForce =
            compressiveCreep.relax(elasticN, patch.area, kn, meanRadius, s.normalCreepOffset);
        s.shearForce = shearCreep.update(s.shearForce, Vector3d(ks * du.shear));
        s.twistMoment = twistCreep.update(s.twistMoment, kt * du.twist);
        s.bendMoment = bendCreep.update(s.bendMoment, Vector3d(kb * du.bend));
        // Without creep every difference is exactly zero: not computed. (A patch never
        // shrinks to nothing: the strength check below breaks it first; kn > 0 guards the
        // division all the same.)
        if (creeps && kn > 0.0)
        {
            const double normalCreep = (elasticN - s.normalForce) / kn;
            const Vector3d shearCreep = (elasticS - s.shearForce) / ks;
            const double twistCreep = (elasticMt - s.twistMoment) / kt;
            const Vector3d bendCreep = (elasticMb - s.bendMoment) / kb;
            s.creepNormal += std::fabs(normalCreep);
            s.creepShear += shearCreep.norm();
            s.creepTwist += std::fabs(twistCreep);
            s.creepBend += bendCreep.norm();
            loads.creepShift = normalCreep * n + shearCreep;
        }

        // 3. Sintering grows an intact patch under compression (new material, no load).
        if (sintering.on && !s.softening)
        {
            const double reducedRadius = g.radiusA * g.radiusB / (g.radiusA + g.radiusB);
            s.patchRadius = sintering.grow(s.patchRadius, s.normalForce, reducedRadius);
            patch = PatchSection::make(s.patchRadius, p.youngsModulus, p.shearToNormalStiffness,
                                       meanRadius);
        }
        if (!s.softening)
            s.onsetRadius = s.patchRadius;
        s.age += dt;

        // 4. Strength: past it, the patch shrinks along the softening branch or breaks.
        if (!strength.on)
            return true;
        const double x =
            strength.loadRatio(s.normalForce, s.shearForce, s.twistMoment, s.bendMoment,
                               patch.radius, patch.area, patch.bendInertia, patch.twistInertia);
        if (!(x > 1.0))
            return true;
        s.softening = true;
        const double fraction = strength.areaFraction(x);
        // Broken where the branch reaches zero, or below brokenFraction Rbar (with 0, a patch
        // shrunk to nothing would otherwise stay on as an intact bond of zero size)
        if (!(fraction > 0.0))
            return false;
        const double target = s.onsetRadius * std::sqrt(fraction);
        if (!(target >= strength.brokenFraction * meanRadius))
            return false;
        if (target < s.patchRadius)
        {
            const double areaRatio = (target / s.patchRadius) * (target / s.patchRadius);
            const double inertiaRatio = areaRatio * areaRatio;
            s.normalForce *= areaRatio;
            s.shearForce *= areaRatio;
            s.twistMoment *= inertiaRatio;
            s.bendMoment *= inertiaRatio;
            s.patchRadius = target;
            patch = PatchSection::make(s.patchRadius, p.youngsModulus, p.shearToNormalStiffness,
                                       meanRadius);
        }
        return true;
    }
};

} // namespace DEM_KERNEL_NS
} // namespace detail
} // namespace dem

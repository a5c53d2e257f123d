// BondLaw.h
// The bond evaluator, written once for both backends: one frozen ice contact (Johnson & Hopkins
// 2005) between grains A (the lower add-order index) and B, advanced by one step. The mechanisms
// (elastic patch, grain-boundary creep, compressive creep, strength and softening, sintering)
// are families chosen by BondParameters; each model is a small evaluator in this directory.
// INTERFACE SKELETON (issue 11 plan): the types and the signature below are fixed; the body of
// BondLaw::advance is the bond-law helper's.
#pragma once

#include "backends/HostDevice.h"
#include "dem/Parameters.h"

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
    bool softening = false;                 //!< past peak strength (r_b only shrinks)
    bool broken = false;                    //!< set by advance: remove the bond
};

//- Where the bond sits now: the cores' closest points, whether the grains touch or not.
struct BondGeometry
{
    Vector3d normal;           //!< unit, from A to B
    Vector3d offsetA, offsetB; //!< contact point minus each centre (point: middle of gap/overlap)
    double radiusA, radiusB;   //!< dilation radii
};

//- How the two grains move (centres' velocities, angular velocities, inverse masses).
struct BondMotion
{
    Vector3d velocityA, velocityB, omegaA, omegaB;
    double inverseMassA, inverseMassB;
};

//- Loads of the bond this step (elastic + viscous): force on A (on B: minus), torques on both
//- including (contact point - centre) x force.
struct BondLoads
{
    Vector3d forceOnA, torqueOnA, torqueOnB;
};

//- The evaluator: constants from BondParameters and the time step (trivially copyable).
struct BondLaw
{
    BondParameters p; // plain struct of numbers and enums
    double dt = 0.0;

    static BondLaw make(const BondParameters& parameters, double timeStep)
    {
        BondLaw law;
        law.p = parameters;
        law.dt = timeStep;
        return law;
    }

    //- Advance state s over one step dt with the grains' motion and return the loads. Sets
    //- s.broken when the bond breaks (its loads this step are then zero).
    DEM_HD BondLoads advance(BondState& s, const BondGeometry& g, const BondMotion& m) const
    {
        (void)s;
        (void)g;
        (void)m;
        BondLoads loads{Vector3d::Zero(), Vector3d::Zero(), Vector3d::Zero()};
        return loads; // placeholder until the bond-law branch lands
    }
};

} // namespace DEM_KERNEL_NS
} // namespace detail
} // namespace dem

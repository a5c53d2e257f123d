// MaxwellCreep.h
// Grain-boundary creep of a frozen contact (Johnson & Hopkins 2005): Newtonian sliding at a
// contact viscosity nu_s relaxes the shear force, twisting moment and bending moment, each a
// Maxwell element dX/dt = K dU/dt - X / tau (a spring K in series with a dashpot). Over a step
// with a constant rate dU/dt the exact solution is
//     X(t + dt) = X(t) e^{-dt/tau} + K dU (tau/dt) (1 - e^{-dt/tau}),
// which is stable at any dt (bounded by K dU tau/dt for dt >> tau). A component without creep
// keeps the plain elastic update X + K dU (decay 1, gain 1). The factors depend only on tau
// and dt: they are computed once on the host. Host and device.
#pragma once

#include "backends/HostDevice.h"

#include <cmath>

namespace dem
{
namespace detail
{
inline namespace DEM_KERNEL_NS
{

struct MaxwellCreep
{
    double decay = 1.0; //!< e^{-dt/tau}
    double gain = 1.0;  //!< (tau/dt) (1 - e^{-dt/tau}), the share of K dU kept over the step

    //- tau: relaxation time [s]; creep false: purely elastic. tau = 0 (no viscosity): the
    //- element keeps no load (the limit of the formula).
    static MaxwellCreep make(bool creep, double tau, double dt)
    {
        MaxwellCreep m;
        if (creep)
        {
            const double x = tau > 0.0 ? dt / tau : INFINITY;
            m.decay = std::exp(-x);
            // -expm1(-x) / x: accurate when dt << tau, where 1 - e^{-x} would cancel.
            // dt = 0 (loads evaluated without advancing): the limit 1.
            m.gain = tau > 0.0 ? (x > 0.0 ? -std::expm1(-x) / x : 1.0) : 0.0;
        }
        return m;
    }

    //- X <- decay X + gain (K dU), for a scalar or a vector load.
    template <class T>
    DEM_HD T update(const T& X, const T& elasticIncrement) const
    {
        return decay * X + gain * elasticIncrement;
    }
};

} // namespace DEM_KERNEL_NS
} // namespace detail
} // namespace dem

// PowerLawCreep.h
// Normal power-law creep of a frozen contact (Johnson & Hopkins 2005, ice constants as the
// paper gives them): the contact points migrate into the grains under compression and out of
// them under tension at the creep displacement rate u_c = 2 Rbar A(T) |sigma_n|^n,
// sigma_n = N / A, with
//     A(T) = A0 exp(-Q / (R_g T_K)),   A0 [s^-1 Pa^-n].
// The paper's A0 = 0.00554458 s^-1 Pa^-3 holds for n = 3 (it is the constant of its sintering
// law, A(T) sigma^3): n = 3 is the default, and another n needs A0 in its units. The normal
// spring k_ne A in series with it relaxes the stress as
//     d|sigma|/dt = -k_ne 2 Rbar A(T) |sigma|^n = -E A(T) |sigma|^n   (k_ne = E / (2 Rbar)),
// whose exact solution over a step (n > 1),
//     |sigma(t + dt)| = |sigma(t)| (1 + (n - 1) E A(T) |sigma(t)|^{n-1} dt)^{-1/(n-1)},
// is used: stable at any dt, never past zero, and exact at constant deformation. The paper
// lets the two contact points move by at most R/2 each (effective dilation radii between R/2
// and 3R/2): the bond's net normal creep (the opening, positive in tension) stays within
// +-Rbar; at that bound creep stops and the spring alone carries the load. Host and device.
#pragma once

#include "backends/HostDevice.h"
#include "dem/Parameters.h"

#include <cmath>

namespace dem
{
namespace detail
{
inline namespace DEM_KERNEL_NS
{

constexpr double kGasConstant = 8.314;  //!< R_g [J/(mol K)]
constexpr double kZeroCelsius = 273.15; //!< T_K = T + kZeroCelsius

//- A(T) = A0 exp(-Q / (R_g T_K)) of the ice creep law [s^-1 Pa^-m].
inline double iceCreepCoefficient(const BondParameters& p)
{
    return p.creepPrefactor *
           std::exp(-p.creepActivationEnergy / (kGasConstant * (p.temperature + kZeroCelsius)));
}

//- m(T) = 1.98488 - 0.00607767 T[C], the paper's exponent of single-crystal ice creep (about
//- 2), used by the sintering law's neck geometry.
inline double iceCreepExponent(const BondParameters& p)
{
    return 1.98488 - 0.00607767 * p.temperature;
}

struct PowerLawCreep
{
    bool on = false;
    double rate = 0.0;     //!< E A(T) dt [Pa^{1-n}]
    double exponent = 3.0; //!< n
    double power = -0.5;   //!< -1/(n - 1)

    static PowerLawCreep make(const BondParameters& p, double dt)
    {
        PowerLawCreep c;
        c.on = p.compressiveCreep == BondCompressiveCreep::powerLaw;
        c.rate = p.youngsModulus * iceCreepCoefficient(p) * dt;
        c.exponent = p.creepExponent;
        c.power = -1.0 / (c.exponent - 1.0);
        return c;
    }

    //- The normal force N (tension positive) after one step of creep on a patch of area A and
    //- normal stiffness k = k_ne A; offset: the bond's net normal creep so far (opening
    //- positive), updated, within +-limit (Rbar).
    DEM_HD double relax(double N, double area, double k, double limit, double& offset) const
    {
        if (!on || N == 0.0 || !(k > 0.0)) // k = 0: a patch shrunk to nothing
            return N;
        const double stress = std::fabs(N) / area;
        const double nm1 = exponent - 1.0;
        const double x = nm1 * rate * std::pow(stress, nm1);
        // (1 + x)^a, a = -1/(n-1): its series to x^3 where x < 1e-4 (the usual step changes
        // sigma by far less), whose remainder, below |a(a-1)(a-2)(a-3)/24| x^4 ~ 1e-16, is
        // round-off; saves a pow per bond and step.
        const double a = power;
        const double series =
            1.0 + a * x * (1.0 + 0.5 * (a - 1.0) * x * (1.0 + (a - 2.0) / 3.0 * x));
        double relaxed = N * (x < 1e-4 ? series : std::pow(1.0 + x, a));
        // The creep of the step, (N - relaxed) / k, opens the bond in tension, closes it in
        // compression; past the bound only the part up to it.
        const double moved = offset + (N - relaxed) / k;
        if (moved > limit || moved < -limit)
        {
            const double bound = moved > limit ? limit : -limit;
            relaxed = N - k * (bound - offset);
            offset = bound;
            return relaxed;
        }
        offset = moved;
        return relaxed;
    }
};

} // namespace DEM_KERNEL_NS
} // namespace detail
} // namespace dem

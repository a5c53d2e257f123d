// PowerLawCreep.h
// Compressive power-law creep of a frozen contact (Johnson & Hopkins 2005, ice constants of
// Jones & Brunet): while the bond is in compression its contact points migrate into the grains
// at the creep displacement rate u_c = 2 Rbar A(T) |sigma_n|^m, sigma_n = N / A, with
//     A(T) = A0 exp(-Q / (R_g T_K)),   m(T) = 1.98488 - 0.00607767 T[C].
// The normal spring k_ne A in series with it relaxes the stress as
//     d sigma/dt = -k_ne 2 Rbar A(T) |sigma|^m = -E A(T) |sigma|^m   (k_ne = E / (2 Rbar)),
// whose exact solution over a step (m > 1),
//     |sigma(t + dt)| = |sigma(t)| (1 + (m - 1) E A(T) |sigma(t)|^{m-1} dt)^{-1/(m-1)},
// is used: stable at any dt, never past zero into tension, and exact at constant deformation.
// Tension does not creep (the paper's creep acts in compression only). Host and device.
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

//- m(T) = 1.98488 - 0.00607767 T[C], the exponent of the ice creep law (about 2).
inline double iceCreepExponent(const BondParameters& p)
{
    return 1.98488 - 0.00607767 * p.temperature;
}

struct PowerLawCreep
{
    bool on = false;
    double rate = 0.0;     //!< E A(T) dt [Pa^{1-m}]
    double exponent = 2.0; //!< m
    double power = -1.0;   //!< -1/(m - 1)

    static PowerLawCreep make(const BondParameters& p, double dt)
    {
        PowerLawCreep c;
        c.on = p.compressiveCreep == BondCompressiveCreep::powerLaw;
        c.rate = p.youngsModulus * iceCreepCoefficient(p) * dt;
        c.exponent = iceCreepExponent(p);
        c.power = -1.0 / (c.exponent - 1.0);
        return c;
    }

    //- The normal force N (tension positive) after one step of creep on a patch of area A.
    DEM_HD double relax(double N, double area) const
    {
        if (!on || !(N < 0.0))
            return N;
        const double stress = -N / area;
        const double mm1 = exponent - 1.0;
        const double x = mm1 * rate * std::pow(stress, mm1);
        // (1 + x)^a, a = -1/(m-1): its series to x^3 where x < 1e-4 (the usual step changes
        // sigma by far less), whose remainder, below |a(a-1)(a-2)(a-3)/24| x^4 ~ 1e-16, is
        // round-off; saves a pow per bond and step.
        const double a = power;
        const double series =
            1.0 + a * x * (1.0 + 0.5 * (a - 1.0) * x * (1.0 + (a - 2.0) / 3.0 * x));
        return N * (x < 1e-4 ? series : std::pow(1.0 + x, a));
    }
};

} // namespace DEM_KERNEL_NS
} // namespace detail
} // namespace dem

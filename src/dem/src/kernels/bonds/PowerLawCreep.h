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

    static PowerLawCreep make(const BondParameters& p, double dt)
    {
        PowerLawCreep c;
        c.on = p.compressiveCreep == BondCompressiveCreep::powerLaw;
        c.rate = p.youngsModulus * iceCreepCoefficient(p) * dt;
        c.exponent = iceCreepExponent(p);
        return c;
    }

    //- The normal force N (tension positive) after one step of creep on a patch of area A.
    DEM_HD double relax(double N, double area) const
    {
        if (!on || !(N < 0.0))
            return N;
        const double stress = -N / area;
        const double mm1 = exponent - 1.0;
        const double factor = 1.0 + mm1 * rate * std::pow(stress, mm1);
        return N * std::pow(factor, -1.0 / mm1);
    }
};

} // namespace DEM_KERNEL_NS
} // namespace detail
} // namespace dem

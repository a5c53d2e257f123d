// Sintering.h
// Pressure sintering of a frozen contact (after Wilkinson's power-law creep model of two
// particles, the form chosen here; Johnson & Hopkins 2005 combine it with a pressureless part
// fitted to Gubler 1982 whose constants are lost): the patch grows under the compressive stress
// sigma_c = max(0, -N) / A as
//     (r_b / R*)^m = A(T) sigma_c^3 t,   in rate form   dr_b/dt = (R*/m) (r_b/R*)^{1-m} A(T)
//     sigma_c^3,
// with R* = R_A R_B / (R_A + R_B) and A(T), m(T) of the ice creep law (PowerLawCreep.h). At a
// constant compressive force F (sigma_c = F / (pi r_b^2)) the rate integrates to
//     rho^{m+6} = rho_0^{m+6} + ((m + 6)/m) A(T) (F / (pi R*^2))^3 t,   rho = r_b / R*,
// which is used as the update over each step (the force held at its value this step): exact at
// constant load, stable at any dt. The new neck material is unstressed: the stored loads stay.
// Host and device.
#pragma once

#include "backends/HostDevice.h"
#include "dem/Parameters.h"
#include "kernels/bonds/ElasticPatch.h"
#include "kernels/bonds/PowerLawCreep.h"

#include <cmath>

namespace dem
{
namespace detail
{
inline namespace DEM_KERNEL_NS
{

struct Sintering
{
    bool on = false;
    double rate = 0.0;     //!< ((m + 6)/m) A(T) dt [Pa^-3]
    double exponent = 2.0; //!< m

    static Sintering make(const BondParameters& p, double dt)
    {
        Sintering s;
        s.on = p.sintering == BondSintering::pressureSintering;
        s.exponent = iceCreepExponent(p);
        s.rate = (s.exponent + 6.0) / s.exponent * iceCreepCoefficient(p) * dt;
        return s;
    }

    //- The patch radius after one step under the normal force N (tension positive), R* the
    //- pair's reduced radius. Only compression sinters.
    DEM_HD double grow(double patchRadius, double N, double reducedRadius) const
    {
        if (!on || !(N < 0.0))
            return patchRadius;
        const double power = exponent + 6.0;
        const double rho = patchRadius / reducedRadius;
        const double stress = -N / (kPi * reducedRadius * reducedRadius);
        const double grown = std::pow(rho, power) + rate * stress * stress * stress;
        return reducedRadius * std::pow(grown, 1.0 / power);
    }
};

} // namespace DEM_KERNEL_NS
} // namespace detail
} // namespace dem

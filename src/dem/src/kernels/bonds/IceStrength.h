// IceStrength.h
// Strength and strain-softening fracture of a frozen contact (Johnson & Hopkins 2005, Fig. 3).
// Peak stresses on the patch: sigma_max = N/A + |M_b| r_b / I (outer fibre in tension),
// tau_max = |S|/A + |M_t| r_b / J. Strengths sigma_t (tension) and tau_s (shear): ice,
// sigma_ice[MPa] = 0.99648 - 0.045904 T[C] for both (times a scale for scaled runs), or given.
//
// Softening. Fig. 3: a point's stress rises as k delta up to the strength at delta_1, then falls
// along sigma_t - k_2 (delta - delta_1) to zero at delta_2 = delta_1 (1 + 1/rho), rho = k_2/k.
// The paper keeps the stress and shrinks the patch instead. Here the loads scale with the
// shrinking patch at constant deformation (N, S by A'/A, M_b by I'/I, M_t by J'/J), so the
// stress on the patch stays k times its strain: x = max(sigma_max/sigma_t, tau_max/tau_s)
// measures delta/delta_1 of the worse mode, and the patch is shrunk to
//     A'/A_0 = (1 - rho (x - 1)) / x,   i.e.   r_b = r_0 sqrt((1 - rho (x - 1)) / x),
// (A_0, r_0 at the onset x = 1), so that the force, x sigma_t A', follows the softening branch
// sigma_t A_0 - k_2 A_0 (delta - delta_1) exactly in pure tension or pure shear, reaching zero
// at x = 1 + 1/rho. The patch only shrinks: unloading is elastic on the smaller patch (towards
// zero, a secant), and reloading shrinks it again once it meets the branch. Broken: the branch
// reached zero, or r_b < brokenFraction Rbar. With bending or twisting the strain is not
// uniform over the patch and the rule is an approximation (as in the paper). Host and device.
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

//- sigma_ice(T) = 0.99648 - 0.045904 T[C] MPa, the tensile strength of polycrystalline ice.
inline double iceTensileStrength(double temperature)
{
    return (0.99648 - 0.045904 * temperature) * 1e6;
}

struct IceStrength
{
    bool on = false;
    double inverseTensile = 0.0; //!< 1 / sigma_t (0: never fails in tension)
    double inverseShear = 0.0;   //!< 1 / tau_s (0: never fails in shear)
    double softeningRatio = 1.0; //!< rho = k_2 / k
    double brokenFraction = 0.0;

    static IceStrength make(const BondParameters& p)
    {
        IceStrength s;
        s.on = p.strength != BondStrength::none;
        double tensile = p.tensileStrength, shear = p.shearStrength;
        if (p.strength == BondStrength::iceTemperature)
            tensile = shear = p.strengthScale * iceTensileStrength(p.temperature);
        s.inverseTensile = tensile > 0.0 ? 1.0 / tensile : 0.0;
        s.inverseShear = shear > 0.0 ? 1.0 / shear : 0.0;
        s.softeningRatio = p.softeningRatio;
        s.brokenFraction = p.brokenFraction;
        return s;
    }

    //- x = max(sigma_max / sigma_t, tau_max / tau_s): above 1 the bond is past its strength.
    DEM_HD double loadRatio(double N, const Vector3d& S, double twist, const Vector3d& bend,
                            double r, double area, double I, double J) const
    {
        const double sigmaMax = N / area + bend.norm() * r / I;
        const double tauMax = S.norm() / area + std::fabs(twist) * r / J;
        const double tensile = sigmaMax * inverseTensile, shear = tauMax * inverseShear;
        return tensile > shear ? tensile : shear;
    }

    //- Fraction of the onset area A'/A_0 left at load ratio x > 1 (<= 0: broken).
    DEM_HD double areaFraction(double x) const { return (1.0 - softeningRatio * (x - 1.0)) / x; }
};

} // namespace DEM_KERNEL_NS
} // namespace detail
} // namespace dem

"""Closed forms of the fluid-grain drag laws of nsDemFoam
(constant/nsDemProperties, grains/fluidForce/type) and what follows from
them in the two benchmark flows of tests/ns: the pressure gradient through a
frozen uniform bed and the terminal velocity of one sphere.

Model A / set II of Zhou, Kuang, Chu and Yu (2010), "Discrete particle
simulation of particle-fluid flow: model formulations and their
applicability", J. Fluid Mech. 661, 482-510: a grain of volume V and
velocity v feels F = V (-grad p + beta_g (u - v) - rho_f g), beta_g the drag
coefficient per unit grain volume [kg/(m^3 s)], u the interstitial fluid
velocity; the fluid momentum per unit mixture volume carries -eps grad p and
minus the grains' drag (1 - eps) beta_g (u - v). Notation here: eps the
fluid fraction (porosity), d the grain diameter, w = |u - v| the interstitial
slip, Re = eps rho w d / mu (the superficial slip's Reynolds number).

No scipy: the one root (terminal velocity) is found by bisection.
"""

import math

LAWS = ("ErgunWenYu", "DiFelice", "Beetstra")

# Gidaspow's switch from Ergun to Wen-Yu, and the Reynolds number above
# which Schiller-Naumann's C_d is held at 0.44
WEN_YU_POROSITY = 0.8
NEWTON_REYNOLDS = 1000.0


def reynolds(eps, w, rho, mu, d):
    """Re = eps rho w d / mu (superficial slip, grain diameter)."""
    return eps * rho * w * d / mu


def schiller_naumann_cd_times_w(eps, w, rho, mu, d):
    """C_d w of Schiller and Naumann (1933), C_d = 24/Re (1 + 0.15 Re^0.687)
    for Re < 1000 and 0.44 above, Re = eps rho w d/mu: written as C_d w so
    that it stays finite at w = 0 (24 mu/(eps rho d))."""
    re = reynolds(eps, w, rho, mu, d)
    if re < NEWTON_REYNOLDS:
        return 24.0 * mu / (eps * rho * d) * (1.0 + 0.15 * re**0.687)
    return 0.44 * w


def beta_grain(law, eps, w, rho, mu, d):
    """Drag coefficient per unit grain volume beta_g [kg/(m^3 s)] of a
    grain of diameter d at fluid fraction eps and interstitial slip w:

    - ErgunWenYu (Gidaspow 1994, "Multiphase flow and fluidization",
      Academic Press, eqs 5.46-5.47, divided by the solid fraction): for
      eps < 0.8 Ergun (1952), beta_g = 150 (1 - eps) mu/(eps d^2)
      + 1.75 rho w/d; for eps >= 0.8 Wen and Yu (1966),
      beta_g = (3/4) C_d rho w eps^-1.65/d with Schiller-Naumann's C_d at
      Re = eps rho w d/mu.
    - DiFelice (Di Felice 1994, Int. J. Multiphase Flow 20, 153-159):
      beta_g = (3/4) C_d rho w eps^(2 - chi)/d, C_d = (0.63 + 4.8/sqrt(Re))^2
      (Dallavalle), chi = 3.7 - 0.65 exp(-(1.5 - log10 Re)^2/2).
    - Beetstra (Beetstra, van der Hoef and Kuipers 2007, AIChE J. 53,
      489-501, eq 16, monodisperse): beta_g = 18 mu eps F/d^2,
      F = 10 (1 - eps)/eps^2 + eps^2 (1 + 1.5 sqrt(1 - eps))
          + 0.413 Re/(24 eps^2) (1/eps + 3 eps (1 - eps) + 8.4 Re^-0.343)
            / (1 + 10^(3 (1 - eps)) Re^(-(1 + 4 (1 - eps))/2)).
    """
    if not 0.0 < eps <= 1.0:
        raise ValueError(f"porosity {eps} outside (0, 1]")
    w = abs(w)
    re = reynolds(eps, w, rho, mu, d)
    if law == "ErgunWenYu":
        if eps < WEN_YU_POROSITY:
            return 150.0 * (1.0 - eps) * mu / (eps * d * d) + 1.75 * rho * w / d
        return 0.75 * schiller_naumann_cd_times_w(eps, w, rho, mu, d) * rho * eps**-1.65 / d
    if law == "DiFelice":
        if re == 0.0:
            raise ValueError("DiFelice: C_d w diverges as w^-1/2 at zero slip")
        cd = (0.63 + 4.8 / math.sqrt(re))**2
        chi = 3.7 - 0.65 * math.exp(-0.5 * (1.5 - math.log10(re))**2)
        return 0.75 * cd * rho * w * eps**(2.0 - chi) / d
    if law == "Beetstra":
        s = 1.0 - eps
        f = 10.0 * s / eps**2 + eps**2 * (1.0 + 1.5 * math.sqrt(s))
        if re > 0.0:
            k = (1.0 + 4.0 * s) / 2.0
            # times Re^k above and below: finite as Re -> 0
            f += (0.413 * re / (24.0 * eps**2)
                  * (1.0 / eps + 3.0 * eps * s + 8.4 * re**-0.343) * re**k
                  / (re**k + 10.0**(3.0 * s)))
        return 18.0 * mu * eps * f / (d * d)
    raise ValueError(f"unknown drag law {law!r} (valid: {' '.join(LAWS)})")


def pressure_gradient(law, eps, U_s, rho, mu, d):
    """-dp/dz [Pa/m] of a steady uniform flow at superficial velocity U_s
    (interstitial u = U_s/eps) through a frozen bed of fluid fraction eps,
    flowing towards +z: the fluid's balance 0 = -eps dp/dz - (1 - eps)
    beta_g u gives -dp/dz = (1 - eps) beta_g(eps, u) u/eps. For ErgunWenYu
    at eps < 0.8 this is Ergun's equation (ergun below) exactly."""
    u = U_s / eps
    return (1.0 - eps) * beta_grain(law, eps, u, rho, mu, d) * u / eps


def ergun(eps, U_s, rho, mu, d):
    """Ergun (1952), Chem. Eng. Prog. 48, 89-94: -dp/dz = 150 mu (1 - eps)^2
    U_s/(eps^3 d^2) + 1.75 rho (1 - eps) U_s^2/(eps^3 d)."""
    return (150.0 * mu * (1.0 - eps)**2 * U_s / (eps**3 * d * d)
            + 1.75 * rho * (1.0 - eps) * U_s**2 / (eps**3 * d))


def stokes_velocity(rho_p, rho_f, mu, d, g):
    """Stokes (1851) terminal velocity (rho_p - rho_f) g d^2/(18 mu)."""
    return (rho_p - rho_f) * g * d * d / (18.0 * mu)


def terminal_velocity(law, rho_p, rho_f, mu, d, g, eps=1.0, rtol=1e-14):
    """Terminal slip w of a grain at fluid fraction eps, from the balance
    of its submerged weight and its drag per unit volume,
    (rho_p - rho_f) g = beta_g(eps, w) w, by bisection (beta_g w rises with
    w for every law here). ErgunWenYu at eps = 1 is Schiller-Naumann's
    sphere (Clift, Grace and Weber 1978, "Bubbles, drops and particles",
    table 5.2)."""
    load = (rho_p - rho_f) * g

    def excess(w):
        return beta_grain(law, eps, w, rho_f, mu, d) * w - load

    lo, hi = 0.0, stokes_velocity(rho_p, rho_f, mu, d, g)
    while excess(hi) < 0.0:
        lo, hi = hi, 2.0 * hi
    while hi - lo > rtol * hi:
        mid = 0.5 * (lo + hi)
        if excess(mid) < 0.0:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def viscosity_for_settling_reynolds(re, rho_p, rho_f, d, g):
    """The viscosity at which a sphere of diameter d settles at the
    Schiller-Naumann terminal Reynolds number re = rho_f w d/mu (re < 1000):
    with w = re mu/(rho_f d) the balance 18 mu w (1 + 0.15 re^0.687)/d^2 =
    (rho_p - rho_f) g gives mu^2 = (rho_p - rho_f) g rho_f d^3
    /(18 re (1 + 0.15 re^0.687))."""
    return math.sqrt((rho_p - rho_f) * g * rho_f * d**3
                     / (18.0 * re * (1.0 + 0.15 * re**0.687)))


def hasimoto_factor(d, length):
    """Hasimoto (1959), J. Fluid Mech. 5, 317-328: a simple cubic periodic
    array of spheres (period length) settles in Stokes flow at
    1 - 1.7601 c^(1/3) + O(c) of Stokes's velocity, c = (pi/6) d^3/length^3
    the solid fraction. A measure of what a periodic box costs at low Re."""
    c = math.pi / 6.0 * d**3 / length**3
    return 1.0 - 1.7601 * c**(1.0 / 3.0)

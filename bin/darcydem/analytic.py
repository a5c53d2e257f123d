"""Closed-form references of doc/REFERENCES.md (computed, never pasted)."""

import numpy as np


def drained_column(zprime, T, H, terms=200):
    """D2: p/p0 in a column drained at the top (z' = 0), closed at z' = H,
    uniform initial p0; T = D t / H^2."""
    j = np.arange(terms)
    M = (2 * j + 1) * np.pi / 2
    zprime = np.atleast_1d(zprime)[:, None]
    return np.sum(2 / M * np.sin(M * zprime / H) * np.exp(-M**2 * T), axis=1)


def periodic_top(zprime, H, D, omega):
    """D3: complex factor F(z') such that p = A Im[exp(i w t) F]: amplitude
    A|F|, phase arg F, for top pressure A sin(w t) and a closed base."""
    lam = (1 + 1j) * np.sqrt(omega / (2 * D))
    return np.cosh(lam * (H - zprime)) / np.cosh(lam * H)


def undrained_pressure_change(phi0, phi, beta):
    """D4: p - p0 for a uniform porosity change phi0 -> phi, all closed."""
    return -(np.log(phi / (1 - phi)) - np.log(phi0 / (1 - phi0))) / beta


def drained_column_cell_mean(z0, z1, T, H, terms=200):
    """D2 averaged over z' in [z0, z1]: what a finite-volume cell holds."""
    j = np.arange(terms)
    M = (2 * j + 1) * np.pi / 2
    mean_sin = H / M * (np.cos(M * z0 / H) - np.cos(M * z1 / H)) / (z1 - z0)
    return np.sum(2 / M * mean_sin * np.exp(-M**2 * T))


def degree_of_consolidation(Tv, terms=200):
    """Terzaghi: U(T_v) = 1 - sum 2/M^2 exp(-M^2 T_v), M = (2j+1) pi/2
    (doc/REFERENCES.md section 3)."""
    j = np.arange(terms)
    M = (2 * j + 1) * np.pi / 2
    Tv = np.atleast_1d(Tv)[:, None]
    return 1 - np.sum(2 / M**2 * np.exp(-M**2 * Tv), axis=1)


FLUID_FORCES = ("pressureGradient", "darcy")


def skeleton_share(porosity, fluid_force):
    """Share of the pore-pressure gradient the skeleton carries under the
    fluid force model of the case (doc/EQUATIONS.md section 7): the grains'
    equilibrium reads sigma' + a p = const with a = 1 - phi for eq. 12
    ('pressureGradient', -V grad p per grain) and a = 1 for 'darcy' (-V grad
    p/(1 - phi) per grain: Terzaghi's effective stress sigma' = sigma - p)."""
    if fluid_force == "pressureGradient":
        return 1 - np.asarray(porosity, dtype=float)
    if fluid_force == "darcy":
        return np.ones_like(np.asarray(porosity, dtype=float))
    raise ValueError("fluid force model %r: no consolidation theory (valid: %s)"
                     % (fluid_force, ", ".join(FLUID_FORCES)))


def consolidation_coefficient(k, mu, E_oed, porosity, beta, fluid_force="darcy"):
    """c_v of a DEM-Darcy packing, c_v = (k/mu) / (phi beta + a/E_oed) with a
    the skeleton's share of the pressure gradient (skeleton_share): the
    classical (k/mu)/(phi beta + 1/E_oed) for 'darcy'; for 'pressureGradient'
    (Damsgaard et al. 2015, eq. 12) the skeleton sees only (1 - phi) of the
    gradient and c_v = (k/mu)/(phi beta + (1 - phi)/E_oed)."""
    a = skeleton_share(porosity, fluid_force)
    return (k / mu) / (porosity * beta + a / E_oed)


def undrained_pressure(load, porosity, beta, E_oed, fluid_force="darcy"):
    """Excess pore pressure right after a load step, dp = d_sigma / (a + phi
    beta E_oed): d_sigma/(1 + phi beta E) for 'darcy', d_sigma/((1 - phi) +
    phi beta E) for 'pressureGradient'."""
    return load / (skeleton_share(porosity, fluid_force) + porosity * beta * E_oed)


def instantaneous_settlement(porosity, beta, E_oed, fluid_force="darcy"):
    """Fraction of the final settlement reached at once on loading, while the
    compressible pore fluid is still undrained: U0 = phi beta E/(a + phi beta
    E) (a = 1 for 'darcy', 1 - phi for 'pressureGradient'); the rest follows
    Terzaghi, U = U0 + (1 - U0) U(T_v)."""
    x = porosity * beta * E_oed
    return x / (skeleton_share(porosity, fluid_force) + x)


def load_ramps(ramp):
    """The load history as linear ramps (start, duration, share of the
    load). ramp is either a duration (one linear ramp from 0 to the full
    load) or a table (times, shares) of a piecewise-linear history that
    starts at (0, 0) and ends at share 1, as the lid's normalStress table
    interpolates it. Every response below is linear in the load, so it is
    the sum of its responses to these ramps (Duhamel)."""
    if np.ndim(ramp) == 0:
        return [(0.0, float(ramp), 1.0)]
    times, shares = (np.asarray(a, dtype=float) for a in ramp)
    if times[0] != 0 or shares[0] != 0 or shares[-1] != 1 or np.any(np.diff(times) <= 0):
        raise ValueError("a load table runs from (0, 0) to share 1 at increasing times")
    return [(a, b - a, s1 - s0) for a, b, s0, s1 in
            zip(times[:-1], times[1:], shares[:-1], shares[1:]) if s1 != s0]


def ramp_loaded_consolidation(Tv, Tramp, U0, terms=200):
    """Settlement fraction U and base pressure fraction p_base/p0 for a load
    applied over 0 <= T_v <= Tramp and then held, by superposing (Duhamel)
    the step responses U0 + (1 - U0) U(T) and the base isochrone (Olson 1977
    gives the same for one linear ramp and U0 = 0). Tramp is the ramp's
    length in T_v, or a table (T_v, share of the load) of a
    piecewise-linear load (load_ramps). p0 is the undrained pressure of the
    full load."""
    j = np.arange(terms)
    M = (2 * j + 1) * np.pi / 2
    Tv = np.atleast_1d(np.asarray(Tv, dtype=float))[:, None]
    U = np.zeros(len(Tv))
    p_base = np.zeros(len(Tv))
    for start, length, share in load_ramps(Tramp):
        T = np.maximum(Tv - start, 0.0)  # no response before the ramp starts
        # integral over the loading time of exp(-M^2 (T - s)) ds / length
        s_end = np.minimum(T, length)
        integral = (np.exp(-M**2 * (T - s_end)) - np.exp(-M**2 * T)) / (M**2 * length)
        load = s_end[:, 0] / length
        # U(T) = 1 - sum 2/M^2 exp(-M^2 T): superposed over the ramp
        U_cons = load - np.sum(2 / M**2 * integral, axis=1)
        U += share * (U0 * load + (1 - U0) * U_cons)
        p_base += share * np.sum(2 / M * np.sin(M) * integral, axis=1)
    return U, p_base


def layered_consolidation(t, dz, porosity, E_oed, k_face, mu, beta, load, ramp,
                          drained_top=0.0, E_top=np.inf, fluid_force="darcy"):
    """Consolidation of a column of layers that differ in porosity, stiffness
    and permeability: the finite-volume form, on the layers of the mesh, of
        (phi beta + a/E_oed) dp/dt = d/dz(k/mu dp/dz) + (1/E_oed) dsigma/dt
    (a = 1 for 'darcy', 1 - phi for eq. 12, 'pressureGradient': skeleton_share),
    closed at the base, p = 0 in the cell above the top layer. Layer i has
    thickness dz, porosity[i] and E_oed[i]; k_face[i] is the permeability
    between layer i and i + 1 (the last one towards the drained cell, whose
    centre is dz above the top layer's). The load rises linearly from 0 to
    load over 0 <= t <= ramp and is then held (or, with ramp a table
    (t, share of the load), piecewise linearly: load_ramps). Exact in time (eigenmodes of
    the layer system). A drained layer of thickness drained_top and modulus
    E_top on top (in the drained cell, under the lid) settles with the load.
    Returns (p[time, layer], settlement[time])."""
    porosity, E_oed, k_face = (np.asarray(a, dtype=float) for a in (porosity, E_oed, k_face))
    n = len(porosity)
    a = skeleton_share(porosity, fluid_force)
    storage = porosity * beta + a / E_oed
    cond = k_face / (mu * dz * dz)  # flux per pressure difference, per layer thickness
    A = np.zeros((n, n))
    for i in range(n):
        A[i, i] += cond[i]
        if i + 1 < n:
            A[i, i + 1] -= cond[i]
            A[i + 1, i] -= cond[i]
            A[i + 1, i + 1] += cond[i]
    s = 1 / np.sqrt(storage)
    lam, V = np.linalg.eigh(s[:, None] * A * s[None, :])
    c = V.T @ (s / E_oed)  # modal share of the loading rate
    t = np.atleast_1d(np.asarray(t, dtype=float))[:, None]
    modes = np.zeros((len(t), n))
    sigma = np.zeros(len(t))
    for start, length, share in load_ramps(ramp):
        tau = np.maximum(t - start, 0.0)  # no response before the ramp starts
        tau_end = np.minimum(tau, length)
        # each mode: da/dt = -lam a + c rate while this ramp loads
        modes += c * (share * load / length) * (np.exp(-lam * (tau - tau_end))
                                                - np.exp(-lam * tau)) / lam
        sigma += share * load * tau_end[:, 0] / length
    p = (modes @ V.T) * s
    settlement = dz * np.sum((sigma[:, None] - a * p) / E_oed, axis=1) \
        + drained_top * sigma / E_top
    return p, settlement

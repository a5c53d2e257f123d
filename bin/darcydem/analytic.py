"""Closed-form references of VALIDATION.md (computed, never pasted)."""

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

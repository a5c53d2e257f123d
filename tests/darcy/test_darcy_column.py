"""Darcy pore-pressure solver against exact solutions (doc/REFERENCES.md section 1).

Every test runs blockMesh and darcyDemFoam on a copy of tests/cases/darcyColumn
(a 0.1 m column, 2 x 2 x nz cells, periodic sides, closed base, D = 0.0556 m^2/s).
"""

import numpy as np
import pytest

from darcydem.case import Case
from darcydem.analytic import drained_column_cell_mean, periodic_top, undrained_pressure_change

H = 0.1
K, MU, BETA, PHI = 1e-14, 1e-3, 4.5e-10, 0.4
D = K / (BETA * PHI * MU)


def column(name, nz=50, dt=1e-4, end=0.18, write=90):
    c = Case("darcyColumn", name)
    c.set_variable("system/blockMeshDict", "nz", nz)
    c.set("system/controlDict", "deltaT", dt)
    c.set("system/controlDict", "endTime", end)
    c.set("system/controlDict", "writeInterval", write)
    return c


def test_D1_steady_linear_profile_and_uniform_flux():
    """D1: p fixed at top and base -> linear p, uniform Darcy flux down the gradient."""
    pbot = 1000.0
    c = column("D1_steady", nz=40, dt=1e-3, end=1.8, write=1800)
    c.set("0/p", "boundaryField/bottom", "{ type fixedValue; value uniform %g; }" % pbot)
    c.set("0/p", "internalField", "uniform 0")
    c.run("blockMesh")
    z = c.cell_centres()[:, 2]
    c.run("darcyDemFoam")
    p = c.field("1.8", "p")
    q = c.field("1.8", "qDarcy")
    exact = pbot * (1 - z / H)
    err = np.max(np.abs(p - exact)) / pbot
    print(f"D1 max relative error of p: {err:.2e}")
    assert err < 1e-6
    q_exact = K / MU * pbot / H   # flows from the high-pressure base upwards
    assert np.all(q[:, 2] > 0)
    assert np.max(np.abs(q[:, 2] - q_exact)) / q_exact < 1e-6
    assert np.max(np.abs(q[:, :2])) < 1e-12 * q_exact


def test_D1_zero_pressure_stays_zero():
    """Without forcing and with p = 0 everywhere, p stays exactly 0."""
    c = column("D1_zero", nz=20, dt=1e-3, end=0.05, write=50)
    c.set("0/p", "internalField", "uniform 0")
    c.run("blockMesh")
    c.run("darcyDemFoam")
    p = c.field("0.05", "p")
    assert np.max(np.abs(p)) == 0.0


def drained_base_error(nz, dt):
    """Max |p - exact|/p0 in the bottom cell at T = 0.05 ... 1. A finite-volume
    cell holds the cell mean, so the exact solution is averaged over the cell."""
    c = column(f"D2_nz{nz}", nz=nz, dt=dt, end=0.18, write=10**6)
    dz = H / nz
    c.set("system/controlDict", "functions/probes/probeLocations",
          "((0.005 0.005 %.12g))" % (dz / 2))
    c.run("blockMesh")
    c.run("darcyDemFoam")
    t, p = c.probes("p")
    errors = []
    for T in (0.05, 0.1, 0.2, 0.5, 1.0):
        i = np.argmin(np.abs(t - T * H**2 / D))
        assert abs(t[i] - T * H**2 / D) < 0.5 * dt
        ex = drained_column_cell_mean(H - dz, H, T, H)
        errors.append(abs(p[i, 0] - ex))
        print(f"D2 nz={nz} T={T}: p/p0 = {p[i, 0]:.5f}, exact {ex:.5f}")
    return max(errors)


def test_D2_drained_column_and_refinement():
    """D2: base pressure of a drained column within 1 % of p0; error falls
    when dt and dz are halved (observed order printed)."""
    dt0 = 0.18 / 900  # T = 0.05 is a whole number of steps at every level
    e = [drained_base_error(25 * 2**l, dt0 / 2**l) for l in range(3)]
    orders = [np.log2(e[l] / e[l + 1]) for l in range(2)]
    print(f"D2 errors {e}, observed orders {orders}")
    assert e[1] < 0.01
    assert e[0] > e[1] > e[2]
    assert min(orders) > 1.8  # Crank-Nicolson, central differences


def test_D3_periodic_top_pressure():
    """D3: amplitude and phase of the pressure wave against depth within 2 %."""
    A, f = 1000.0, 10.0
    omega = 2 * np.pi * f
    nz, dt, end = 50, 1e-4, 1.2
    c = column("D3_periodic", nz=nz, dt=dt, end=end, write=10**6)
    c.set("0/p", "internalField", "uniform 0")
    c.set("0/p", "boundaryField/top",
          "{ type uniformFixedValue; uniformValue sine; "
          "uniformValueCoeffs { amplitude 1; frequency %g; scale %g; level 0; } }" % (f, A))
    dz = H / nz
    zs = [H - (i + 0.5) * dz for i in range(0, nz, 5)]
    c.set("system/controlDict", "functions/probes/probeLocations",
          "(" + " ".join("(0.005 0.005 %.12g)" % z for z in zs) + ")")
    c.run("blockMesh")
    c.run("darcyDemFoam")
    t, p = c.probes("p")
    last = t > end - 1 / f - 0.5 * dt
    basis = np.column_stack([np.sin(omega * t[last]), np.cos(omega * t[last]),
                             np.ones(last.sum())])
    worst_amp = worst_phase = 0.0
    for i, z in enumerate(zs):
        (a, b, _), *_ = np.linalg.lstsq(basis, p[last, i], rcond=None)
        amp, phase = np.hypot(a, b), np.arctan2(b, a)
        F = periodic_top(H - z, H, D, omega)
        amp_ex, phase_ex = A * abs(F), np.angle(F)
        amp_err = abs(amp - amp_ex) / amp_ex
        phase_err = abs(phase - phase_ex) / (2 * np.pi)
        print(f"D3 depth {H - z:.4f}: amplitude {amp / A:.4f} (exact {amp_ex / A:.4f}),"
              f" phase {phase:.4f} (exact {phase_ex:.4f}) rad")
        worst_amp, worst_phase = max(worst_amp, amp_err), max(worst_phase, phase_err)
    print(f"D3 worst amplitude error {worst_amp:.2e}, worst phase error"
          f" {worst_phase:.2e} of a period")
    assert worst_amp < 0.02
    assert worst_phase < 0.02


@pytest.mark.parametrize("phi0,phi1", [(0.35, 0.40), (0.40, 0.35)])
def test_D4_undrained_dilation(phi0, phi1):
    """D4: closed box, imposed uniform porosity change; dilation lowers p."""
    c = column(f"D4_{phi0}_{phi1}", nz=10, dt=1e-3, end=1.0, write=250)
    c.set("0/p", "internalField", "uniform 0")
    c.set("0/p", "boundaryField/top", "{ type zeroGradient; }")
    c.set("constant/darcyProperties", "solidPhase",
          "{ type uniformPorosity; porosity table ((0 %g) (2 %g)); }"
          % (phi0, phi0 + 2 * (phi1 - phi0)))  # beyond end: rate stays centred
    c.run("blockMesh")
    c.run("darcyDemFoam")
    for t_num, t_name in c.times():
        p = c.field(t_name, "p")
        phi = phi0 + (phi1 - phi0) * t_num
        ex = undrained_pressure_change(phi0, phi, BETA)
        err = np.max(np.abs(p - ex)) / abs(ex)
        print(f"D4 t={t_num}: p = {p.mean():.6e}, exact {ex:.6e}, rel. error {err:.2e}")
        assert err < 0.005
        assert np.sign(p.mean()) == -np.sign(phi1 - phi0)

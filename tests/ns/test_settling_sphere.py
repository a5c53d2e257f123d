"""nsDemFoam, one sphere settling (issue 25): a free sphere (d = 1 mm,
rho_p = 2000, in water-density fluid rho_f = 1000, g = 9.81) falls from rest
in a box periodic in x and y and closed at the bottom and the top
(tests/cases/settlingSphere); its terminal velocity against the
Schiller-Naumann sphere, the ErgunWenYu law at porosity -> 1
(bin/darcydem/drag.py), at terminal Reynolds numbers 0.1, 1, 10 and 100 (the
viscosity chosen per Re in closed form), and at Re 0.1 against Stokes.

Measured: the sphere's centre from <time>/grains at the write times; the
time it takes to cross whole cells (between two cell-centre planes, by
linear interpolation of z(t) between write times), after a transient stretch
of at least 6 particle relaxation times rho_p d^2/(18 mu f(Re)) of fall at the
terminal velocity and two cells. The force on the sphere depends on where it
is in its cell (the deposit and the interpolation use the same trilinear
weights), so only whole cells give its mean. The sphere starts at a cell
centre laterally: there its reaction goes to its column of cells alone, the
largest self-interaction of any lateral position.

Why the cell size matters (unresolved CFD-DEM): the drag uses the fluid
velocity at the sphere's centre, interpolated from cells that hold the
sphere's own reaction; that fluid is dragged along with the sphere, the slip
is smaller than the sphere's velocity and the sphere settles too fast. In
Stokes flow the reaction F = 3 pi mu d w spread over a region of size R ~ h
drives the fluid there at about F/(4 pi mu R), a fraction ~ (3/4) d/h of w:
15 % at h = 5 d, 2.5 % at h = 30 d. At larger Re the disturbance is advected
away (the Oseen length d/Re falls below h) and the error falls. Measured at
Re 0.1 (box 10 cells across): +15.8 % at h = 5 d, +8.1 % at 10 d, +3.6 % at
20 d, +2.1 % at 30 d, i.e. 0.64-0.81 d/h; at h = 5 d: Re 1 +10.1 %, Re 10
+2.3 %, Re 100 +0.3 %. So the asserted runs use h = H_OVER_D = 30 d at every
Re (the Stokes-regime estimate 2.5 % below the 3 %, and smaller at higher
Re), the box 10 cells = 300 d across (a periodic array's hindrance,
Hasimoto 1959, 1 - 1.76 c^(1/3), is 0.3 % at that period). The solver has no
correction of this self-induced velocity; with one, coarser cells would do.
test_error_falls_with_the_cell_size prints h = 5 d and 10 d at Re 0.1; the
tutorial tutorials/nsDemFoam/settlingSphere runs the whole series, h = 2 d
(the issue's question) included: there the sphere fills 6.5 % of its cell
(+29 % at Re 0.1, +0.6 % at Re 100, measured with the solver of this
commit).

Tolerance 3 % (the issue's) on the mean over the last stretch; the stretch
before it must agree within 1 % (terminal velocity reached: the slow part
of the transient is the fluid's disturbance building up around the sphere).
Stokes at Re 0.1: Schiller-Naumann's correction is itself 1 + 0.15 Re^0.687
= 1.031 there, so the test asserts v/v_Stokes against 1/1.031 within 3 %,
and also v against Stokes within 3 % (a sphere at exactly Schiller-Naumann's
velocity is 2.99 % below Stokes: that check has no room of its own).
"""

import math
import time

import pytest

from darcydem import drag
from darcydem.case import Case
from darcydem.settling import measure_fall

D = 1e-3
RHO_P, RHO_F, G = 2000.0, 1000.0, 9.81
LAW = "ErgunWenYu"

H_OVER_D = 30             # cell size / sphere diameter of the asserted runs
N_LAT = 10                # cells across the periodic box
STEPS_PER_CELL = 40       # fluid steps while the sphere crosses a cell
WRITES_PER_CELL = 4       # write times per cell crossed
MARGIN = 5                # cells kept between the sphere's end and the bottom


def dem_substeps(dt_fluid, tau):
    """DEM steps per fluid step: the drag is explicit in the DEM step;
    5 steps per relaxation time tau (stable; at terminal velocity the
    step is exact)."""
    return max(1, math.ceil(dt_fluid / (tau / 5)))


def settle(re, h_over_d=H_OVER_D, n_lat=N_LAT, steps_per_cell=STEPS_PER_CELL,
           name=None):
    """Run one sphere at terminal Reynolds number re; returns the measured
    terminal velocity (mean over the last stretch of whole cells), that of
    the stretch before it, the reference and the run's wall time."""
    mu = drag.viscosity_for_settling_reynolds(re, RHO_P, RHO_F, D, G)
    w_sn = drag.terminal_velocity(LAW, RHO_P, RHO_F, mu, D, G)
    tau = RHO_P * D * D / (18 * mu * (1 + 0.15 * re**0.687))
    h = h_over_d * D
    # cells of transient (>= 6 tau of fall at w_sn, >= 2 cells) and of each
    # of the two measured stretches (>= 10 d, >= 2 cells)
    n_tr = max(2, math.ceil(6 * tau * w_sn / h))
    n_meas = max(2, math.ceil(10 * D / h))
    fall = n_tr + 2 * n_meas
    nz = 2 + fall + MARGIN + 1
    dt = h / (steps_per_cell * w_sn)
    sub = dem_substeps(dt, tau)
    dt = sub * (dt / sub)
    steps = math.ceil((fall + 0.5) * steps_per_cell * 1.1)   # + 10 %: the start

    c = Case("settlingSphere", name or f"settling_Re{re:g}_h{h_over_d:g}d")
    c.set_variable("system/blockMeshDict", "L", "%.17g" % (n_lat * h))
    c.set_variable("system/blockMeshDict", "H", "%.17g" % (nz * h))
    c.set_variable("system/blockMeshDict", "n", n_lat)
    c.set_variable("system/blockMeshDict", "nz", nz)
    c.set("constant/nsDemProperties", "mu", "[1 -1 -1 0 0 0 0] %.17g" % mu)
    c.set("constant/demProperties", "timeStep", "%.17g" % (dt / sub))
    c.set("system/controlDict", "deltaT", "%.17g" % dt)
    c.set("system/controlDict", "endTime", "%.17g" % (steps * dt))
    c.set("system/controlDict", "writeInterval", steps_per_cell // WRITES_PER_CELL)
    x0 = (n_lat // 2 + 0.5) * h
    z0 = (nz - 2.5) * h          # a cell centre, two cells below the lid's cell
    with open(c.file("0/grains"), "w") as f:
        f.write("# one sphere\n%.17g %.17g %.17g %.17g\n" % (x0, x0, z0, D / 2))
    c.run("blockMesh")
    start = time.time()
    c.run("nsDemFoam")
    wall = time.time() - start

    # z falls monotonically; crossing times of cell-centre planes
    v_last, v_before, per_cell, _, _ = measure_fall(c, z0, h, fall, n_meas, c.path)
    out = dict(re=re, mu=mu, w_sn=w_sn, v=v_last, v_before=v_before,
               err=v_last / w_sn - 1, wall=wall, cells=n_lat * n_lat * nz,
               steps=steps, sub=sub, h_over_d=h_over_d, per_cell=per_cell,
               n_tr=n_tr, n_meas=n_meas)
    print(f"\nRe {re:g}, h = {h_over_d:g} d, {n_lat}x{n_lat}x{nz} cells, mu {mu:.5g} Pa s, "
          f"{steps} fluid steps of {dt:.3g} s x {sub} DEM steps: v {v_last:.6g} m/s "
          f"(stretch before {v_before:.6g}), Schiller-Naumann {w_sn:.6g}, error "
          f"{out['err']:+.2%}; run {wall:.1f} s")
    print("  cell by cell " + " ".join(f"{v / w_sn:.4f}" for v in per_cell))
    return out


@pytest.mark.parametrize("re", [0.1, 1.0, 10.0, 100.0])
def test_terminal_velocity_against_schiller_naumann(re):
    r = settle(re)
    # terminal: the two stretches agree well within the tolerance
    drift = r["v"] / r["v_before"] - 1
    print(f"  drift between the last two stretches {drift:+.2%}")
    assert abs(drift) < 0.01
    assert abs(r["err"]) < 0.03
    if re == 0.1:
        stokes = drag.stokes_velocity(RHO_P, RHO_F, r["mu"], D, G)
        expected_ratio = 1 / (1 + 0.15 * re**0.687)
        print(f"  Stokes {stokes:.6g} m/s: v/v_Stokes {r['v'] / stokes:.4f}, "
              f"Schiller-Naumann's {expected_ratio:.4f}")
        assert abs(r["v"] / stokes - expected_ratio) < 0.03
        assert abs(r["v"] / stokes - 1) < 0.03


def test_error_falls_with_the_cell_size():
    """Re 0.1, cells of 5 d and 10 d (the box 50 d and 100 d across): the
    self-induced slip makes the sphere too fast by about 0.75 d/h (the
    estimate in the module's docstring); printed for the note, and asserted
    only in its sign and trend."""
    errors = [settle(0.1, h_over_d=k)["err"] for k in (5, 10)]
    print(f"  Re 0.1: error {errors[0]:+.2%} at h = 5 d, {errors[1]:+.2%} at h = 10 d, "
          f"ratio {errors[0] / errors[1]:.2f} (first order in d/h: 2)")
    assert errors[0] > errors[1] > 0

"""Walls on any axis, free walls and gravity as a Function1 of time (issue 11).
Case: tests/cases/wallBox, demFoam: 4 grains on the floor touching the x
walls of a box with wall patches on x (the DEM box is closed there), cyclic
y, and a free lid (mass 0.05 kg) released at z = 0.09 m while gravity ramps
linearly from zero to (0 0 -9.81) over 0.05 s; it lands at about 0.15 s.
Bad 'walls' and 'gravity' entries stop naming the file, the entry and the
valid choices."""

import filecmp
import os
import shutil

import numpy as np
import pytest

from darcydem.case import Case, fatal_message
from darcydem.foamfiles import read_grains

DEM = "constant/demProperties"
G, RAMP, LID_Z0, LID_MASS = 9.81, 0.05, 0.09, 0.05
K = 1e6          # linearSpring normal stiffness of the case [N/m]
DT_DEM, DT_FLUID = 1e-5, 1e-4
LX = 0.04


def lid_free_fall(t):
    """z of a lid released at rest at LID_Z0 under g(t) = G min(t/RAMP, 1)."""
    ramp = LID_Z0 - G * t**3 / (6 * RAMP)
    s = t - RAMP
    after = LID_Z0 - G * RAMP**2 / 6 - G * RAMP / 2 * s - G / 2 * s**2
    return np.where(t <= RAMP, ramp, after)


@pytest.fixture(scope="module")
def wall_box():
    c = Case("wallBox", "wall_box")
    c.run("blockMesh")
    log = c.run("demFoam")
    d = np.loadtxt(c.file("postProcessing/grainDiagnostics/0/grainDiagnostics.dat"),
                   comments="#")
    return c, log, d


def test_box_is_closed_in_x_and_periodic_in_y(wall_box):
    c, log, d = wall_box
    assert "periodic in x: false, y: true" in log
    assert "wall left: lower x, fixed at x = 0" in log
    assert "wall lid: upper z, free at z = 0.09, mass 0.05 kg" in log


def test_free_lid_falls_under_the_gravity_ramp(wall_box):
    """Before it reaches the grains (t <= 0.12 s, lid above z = 0.044) the lid
    follows z0 - int int g: g t^3 / (6 T) during the ramp, then a constant
    acceleration. The DEM feels each fluid step's gravity (set at its middle)
    from its second half kick on, half a DEM step late: the lid's velocity
    lags by at most G dt/2 and its position by G dt t / 2; the mid-step
    gravity adds (G/T) dt_fluid^2 t / 12. The bound is their sum."""
    c, log, d = wall_box
    t, z = d[:, 0], d[:, 5]
    falling = t <= 0.12
    err = np.max(np.abs(z[falling] - lid_free_fall(t[falling])))
    bound = G * DT_DEM * 0.12 / 2 + G / RAMP * DT_FLUID**2 * 0.12 / 12
    print(f"lid free fall: max |z - closed form| = {err:.3e} m, bound {bound:.3e} m")
    assert err <= bound
    assert np.all(z[falling] > 0.044)  # still above the grains (top 0.016 m)


def test_lid_rests_on_the_grains_with_its_weight(wall_box):
    """At rest (still to 1e-3 of its overlap over the last 0.01 s), the
    frictionless lid carries its weight on the four grains: sum of k_n
    overlap = M g. The overlaps (~1.2e-7 m) are differences of positions
    ~0.016 m written with 17 digits (~1e-18 m each): 1e-9 relative bounds
    that rounding with a wide margin."""
    c, log, d = wall_box
    lid = d[-1, 5]
    drift = np.ptp(d[d[:, 0] >= d[-1, 0] - 0.01, 5])
    g = read_grains(c.file("0.3/grains"))
    top = g["position"][:, 2] + g["radius"]
    overlaps = top[top > lid] - lid
    force = K * overlaps.sum()
    print(f"lid at {lid:.9f} m on {len(overlaps)} grain(s): k sum(overlap) / (M g) - 1 = "
          f"{force / (LID_MASS * G) - 1:.2e}; drift {drift:.1e} m; KE {d[-1, 9]:.1e} J")
    assert len(overlaps) == 4  # one layer of equal grains: the lid rests on all four
    assert drift < 1e-3 * LID_MASS * G / K
    assert force / (LID_MASS * G) == pytest.approx(1.0, abs=1e-9)


def test_grains_stay_between_the_x_walls_and_deposit_conserves_volume(wall_box):
    """No grain is lost or binned outside the mesh on the closed x sides:
    all 4 stay between the x walls (to a contact overlap, < 1e-3 r) and the
    deposit's solid volume equals the grains' volume at every row (the
    stencil mirrors at the x walls; round-off)."""
    c, log, d = wall_box
    g = read_grains(c.file("0.3/grains"))
    x, r = g["position"][:, 0], g["radius"]
    assert len(r) == 4
    print(f"x - r min {np.min(x - r):.2e} m, Lx - x - r min {np.min(LX - x - r):.2e} m")
    assert np.all(x - r > -1e-3 * r) and np.all(LX - x - r > -1e-3 * r)
    err = np.max(np.abs(d[:, 12]))
    print(f"max relative solid-volume error over {len(d)} rows: {err:.1e}")
    assert err < 1e-12


def test_restart_is_bit_identical():
    """Restarted at 0.025 s (gravity half way up its ramp, the lid falling),
    the run ends at 0.2 s (lid on the grains) bit for bit where the
    uninterrupted one ends: the free lid's state, the closed x sides, and
    gravity set again from its Function1 at each fluid step."""
    a = Case("wallBox", "wall_box_restart")
    a.set("system/controlDict", "endTime", 0.2)
    a.set("system/controlDict", "writeInterval", 250)
    a.run("blockMesh")
    a.run("demFoam")
    b_path = a.path + "_restarted"
    shutil.rmtree(b_path, ignore_errors=True)
    shutil.copytree(a.path, b_path)
    for name in os.listdir(b_path):
        if name.replace(".", "", 1).isdigit() and float(name) > 0.025:
            shutil.rmtree(os.path.join(b_path, name))
    shutil.rmtree(os.path.join(b_path, "postProcessing"))
    b = Case.existing(b_path)
    log = b.run("demFoam")
    assert "restart from" in log
    for f in ("demState", "grains"):
        assert filecmp.cmp(a.file("0.2/" + f), b.file("0.2/" + f), shallow=False), f


def failing(name, edit, template="wallBox"):
    c = Case(template, name)
    c.set("system/controlDict", "endTime", 1e-3)
    edit(c)
    c.run("blockMesh")
    return fatal_message(c.run("demFoam", expect_fail=True))


def test_bad_axis_lists_the_valid_ones():
    msg = failing("bad_axis", lambda c: c.set(DEM, "walls/left/axis", "diagonal"))
    assert "Entry 'axis' of wall 'left'" in msg and "demProperties" in msg
    assert "'diagonal'; valid: x y z" in msg


def test_bad_mode_lists_the_valid_ones():
    msg = failing("bad_mode", lambda c: c.set(DEM, "walls/lid/mode", "floating"))
    assert "Entry 'mode' of wall 'lid'" in msg
    assert "'floating'; valid: fixed velocity stress free" in msg


def test_free_wall_needs_a_mass():
    msg = failing("free_no_mass", lambda c: c.remove(DEM, "walls/lid/mass"))
    assert "mass" in msg and "demProperties" in msg


def test_x_wall_on_a_cyclic_side_is_refused():
    """grainColumn's x sides are cyclic: an x wall there is refused."""
    def edit(c):
        c.set(DEM, "walls/side", "{ axis x; side lower; mode fixed; position 0; }")
    msg = failing("x_wall_periodic", edit, template="grainColumn")
    assert "Wall 'side'" in msg and "cyclic" in msg


def test_closed_side_without_its_walls_is_refused():
    msg = failing("x_side_open", lambda c: c.remove(DEM, "walls/right"))
    assert "needs a lower and an upper x wall" in msg


def test_stress_x_wall_needs_z_walls():
    def edit(c):
        c.set(DEM, "walls/right", "{ axis x; side upper; mode stress; position 0.04; "
              "mass 0.1; normalStress 100; }")
        c.remove(DEM, "walls/lid")
    msg = failing("x_stress_no_lid", edit)
    assert "Wall 'right'" in msg and "lower and an upper z wall" in msg


def test_unknown_gravity_function_lists_the_valid_ones():
    msg = failing("bad_gravity", lambda c: c.set(DEM, "gravity", "{ type sloped; }"))
    assert "Unknown Function1 type sloped for gravity" in msg
    assert "scale" in msg and "table" in msg

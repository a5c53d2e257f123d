"""darcyDemFoam with DEM grains: restart, deposit conservation, output files
and refusal of bad input (issue: coupled solver). Case: tests/cases/grainColumn,
256 grains settling under gravity and a stress-controlled lid in a saturated
periodic column."""

import filecmp
import os
import shutil

import numpy as np
import pytest

from darcydem.case import Case
from darcydem.foamfiles import grain_files, read_vtp


def short_column(name, end=0.02, write=100):
    c = Case("grainColumn", name)
    c.set("system/controlDict", "endTime", end)
    c.set("system/controlDict", "writeInterval", write)
    c.run("blockMesh")
    return c


def diagnostics(c):
    path = c.file("postProcessing/grainDiagnostics/0/grainDiagnostics.dat")
    return np.loadtxt(path, comments="#")


def test_restart_is_bit_identical():
    """A run restarted from a written time ends bit for bit where the
    uninterrupted run ends: grains with contact history and walls (demState)
    and the fields, written in binary."""
    a = short_column("restart_full")
    # bit identity is the CPU's (CUDA deposits porosity with atomics in no fixed order)
    a.set("constant/demProperties", "backend", "cpu")
    a.run("darcyDemFoam")
    b_path = a.path + "_restarted"
    shutil.rmtree(b_path, ignore_errors=True)
    shutil.copytree(a.path, b_path)
    shutil.rmtree(os.path.join(b_path, "0.02"))
    # the function objects' output goes; the grains' files (postProcessing/grains,
    # written at the times) stay, as they would after a crash
    post = os.path.join(b_path, "postProcessing")
    for name in os.listdir(post):
        if name != "grains":
            shutil.rmtree(os.path.join(post, name))
    b = Case.existing(b_path)
    log = b.run("darcyDemFoam")
    assert "restart from" in log
    for f in ("demState", "p", "porosity", "Us", "ddt0(p)"):
        assert filecmp.cmp(a.file("0.02/" + f), b.file("0.02/" + f), shallow=False), f
    # the grains' file series lists the rewritten time once
    assert [t for t, _ in grain_files(b.path)] == [0.01, 0.02]


def test_deposit_conserves_solid_volume_every_step():
    """Sum over cells of the deposited solid volume equals the grains'
    volume at every fluid step (before the porosity clamp)."""
    c = short_column("deposit_every_step", end=0.01)
    c.set("system/controlDict", "functions/grainDiagnostics/writeInterval", 1)
    c.run("darcyDemFoam")
    d = diagnostics(c)
    assert len(d) == 100
    err = np.max(np.abs(d[:, 12]))
    print(f"max relative solid-volume error over {len(d)} fluid steps: {err:.1e}")
    assert err < 1e-12


def test_paraview_output():
    """postProcessing/grains/grains_<time>.vtp at each write time with the
    documented arrays, listed with their times in the file series
    grains.vtp.series beside them; the
    grains' count matches the input file."""
    c = short_column("vtk_output")
    c.run("darcyDemFoam")
    files = grain_files(c.path)
    assert [(t, os.path.basename(f)) for t, f in files] == [
        (0.01, "grains_0.01.vtp"), (0.02, "grains_0.02.vtp")]
    g = read_vtp(files[-1][1])
    assert len(g["position"]) == 256
    for name in ("radius", "velocity", "angularVelocity", "displacement", "force",
                 "fluidForce", "contactCount", "flag"):
        assert name in g, name


def failing(name, edit, app="darcyDemFoam"):
    c = Case("grainColumn", name)
    c.set("system/controlDict", "endTime", 1e-3)
    edit(c)
    c.run("blockMesh")
    return c.run(app, expect_fail=True)


DEM = "constant/demProperties"


def test_unknown_backend_lists_valid_names():
    log = failing("bad_backend", lambda c: c.set(DEM, "backend", "gpu"))
    assert "gpu" in log and "auto" in log and "cpu" in log and "cuda" in log


def test_negative_stiffness():
    log = failing("bad_stiffness", lambda c: c.set(DEM, "contact/normalStiffness", "-1e6"))
    assert "Entry 'normalStiffness'" in log and "must be > 0" in log


def test_time_step_above_critical():
    log = failing("bad_dt", lambda c: c.set(DEM, "timeStep", "1e-3"))
    assert "Entry 'timeStep'" in log and "stable limit" in log


def test_fluid_step_not_a_multiple_of_dem_step():
    log = failing("bad_ratio", lambda c: c.set("system/controlDict", "deltaT", "1.5e-5"))
    assert "whole multiple" in log


def test_grain_outside_mesh():
    def edit(c):
        with open(c.file("0/grains"), "a") as f:
            f.write("0.05 0.05 0.5 0.01\n")
    log = failing("bad_grain", edit)
    assert "lies outside the mesh" in log and "grains" in log


def test_unknown_wall_mode():
    log = failing("bad_wall", lambda c: c.set(DEM, "walls/top/mode", "pressure"))
    assert "pressure" in log and "stress" in log and "velocity" in log


def test_non_uniform_mesh_refused():
    def edit(c):
        text = open(c.file("system/blockMeshDict")).read()
        text = text.replace("simpleGrading (1 1 1)", "simpleGrading (1 1 3)")
        open(c.file("system/blockMeshDict"), "w").write(text)
    log = failing("bad_mesh", edit)
    assert "not a uniform Cartesian mesh" in log


def test_dry_run_with_demFoam():
    """The same case format runs dry with demFoam (no darcyProperties, no p)."""
    c = short_column("dry_demFoam", end=0.01)
    os.remove(c.file("constant/darcyProperties"))
    os.remove(c.file("0/p"))
    log = c.run("demFoam")
    assert "End" in log
    assert os.path.exists(c.file("0.01/demState"))
    d = diagnostics(c)
    assert np.all(d[:, 6:9] == 0)  # no pore pressure in a dry run


def step_timer_table(log):
    """{phase: seconds} and the loop's grain-steps/s from the table the
    solvers print at the end of the run (stepTimers)."""
    lines = log[log.index("Step timers (wall clock"):].splitlines()
    steps = int(lines[0].split("time loop, ")[1].split()[0])
    seconds = {}
    for line in lines[2:]:
        if line.strip().startswith("whole loop:"):
            rate = float(line.split("whole loop:")[1].split()[0])
            break
        *name, s, _, _ = line.split()
        seconds[" ".join(name)] = float(s)
    return steps, seconds, rate


@pytest.mark.parametrize("app", ["darcyDemFoam", "demFoam"])
def test_step_timers_account_for_the_loop(app):
    """Both solvers end their log with the wall clock of the loop split by
    phase: the phases and the remainder add up to the total (to the printed
    digits), and the loop's grain-steps/s times the total is the grains x
    DEM sub-steps x fluid steps of the run (exact bookkeeping, to the
    printed digits: 4 of the rate, milliseconds of the total)."""
    c = short_column(f"timers_{app}", end=0.01)
    if app == "demFoam":
        os.remove(c.file("constant/darcyProperties"))
        os.remove(c.file("0/p"))
    log = c.run(app)
    steps, seconds, rate = step_timer_table(log)
    phases = ["DEM steps", "deposit", "momentum", "pressure", "gradient", "exchange", "write", "other"]
    print(f"{app}: {steps} fluid steps, {seconds}, {rate:.4g} grain-steps/s")
    assert steps == 100  # 0.01 s of 1e-4 s fluid steps
    assert sorted(seconds) == sorted(phases + ["total"])
    assert abs(sum(seconds[p] for p in phases) - seconds["total"]) <= 4e-3  # 7 x 5e-4 rounding
    grains, sub_steps = 256, 10  # deltaT 1e-4 s / timeStep 1e-5 s
    printed = 5e-4 + 5e-4 / seconds["total"]  # relative rounding of rate and total
    assert rate * seconds["total"] == pytest.approx(grains * sub_steps * steps, rel=printed)
    if app == "demFoam":  # no fluid: nothing timed in the fluid's phases
        assert seconds["momentum"] == seconds["pressure"] == seconds["gradient"] == seconds["exchange"] == 0

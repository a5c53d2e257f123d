"""Crash-safe output and restart (issue 14): darcyDemFoam killed with SIGKILL
in the middle of writing a time restarts with 'startFrom latestTime' from
the latest complete time, loses nothing written before, and ends bit for bit
where an uninterrupted run ends (CPU backend: the restart itself is exact,
see test_coupled_machinery.py). Damaged or foreign demState files and a run
that leaves the numbers stop with a clear message.

Kill points come from the writer's test hook DARCYDEM_TEST_KILL_AT=<point>@<n>
(SIGKILL at the n-th time the point is reached; see atomicFile.H). Case:
tests/cases/grainColumn, 256 grains, written every 20 fluid steps (0.002,
0.004, 0.006 s)."""

import filecmp
import os
import re
import shutil

import pytest

from darcydem.case import Case, fatal_message

END = 0.006
RESTART_FILES = ("demState", "grains", "p", "porosity", "Us")


def column(name, end=END):
    c = Case("grainColumn", name)
    # bit identity is the CPU's (CUDA deposits porosity with atomics in no fixed order);
    # the DEM's own restart on CUDA is bit-identical in demTests' Restart/cuda
    c.set("constant/demProperties", "backend", "cpu")
    c.set("system/controlDict", "endTime", end)
    c.set("system/controlDict", "writeInterval", 20)
    c.run("blockMesh")
    return c


def same_files(a, b, time_name, names=RESTART_FILES):
    """Names of the files of a time that differ between two cases (bytes):
    the time's own files and the grains' ParaView file of that time."""
    paths = [f"{time_name}/{f}" for f in names] + [f"postProcessing/grains/grains_{time_name}.vtp"]
    return [f for f in paths
            if not filecmp.cmp(a.file(f), b.file(f), shallow=False)]


@pytest.fixture(scope="module")
def reference():
    """The uninterrupted run."""
    c = column("crash_reference")
    c.run("darcyDemFoam")
    return c


def copy_of(case, name, keep):
    """A copy of a finished case with only the time directories in keep."""
    path = os.path.join(os.path.dirname(case.path), name)
    shutil.rmtree(path, ignore_errors=True)
    shutil.copytree(case.path, path, ignore=shutil.ignore_patterns("postProcessing", "log.*"))
    for _, d in Case.existing(path).times():
        if d not in keep:
            shutil.rmtree(os.path.join(path, d))
    return Case.existing(path)


@pytest.mark.parametrize("point,complete", [
    ("amongFields", False),     # some of OpenFOAM's field files of 0.004 written
    ("beforeDemState", False),  # every field and the grains' files written, no demState
    ("inDemState", False),      # half of demState.tmp written
    ("afterDemState", True),    # demState renamed into place: 0.004 is complete
])
def test_killed_mid_write_restarts_from_the_last_complete_time(reference, monkeypatch,
                                                               point, complete):
    c = column("crash_" + point)
    monkeypatch.setenv("DARCYDEM_TEST_KILL_AT", point + "@2")  # while writing 0.004
    log = c.run("darcyDemFoam", expect_fail=True)
    monkeypatch.delenv("DARCYDEM_TEST_KILL_AT")
    assert f"SIGKILL at {point} (2)" in log
    assert [d for _, d in c.times()] == ["0.002", "0.004"]

    # Nothing written before is lost or touched
    differ = same_files(reference, c, "0.002")
    assert differ == [], differ

    log = c.run("darcyDemFoam")
    if complete:
        assert "incomplete" not in log
        assert not os.path.exists(c.file("0.004.incomplete"))
    else:
        assert "Time 0.004 is incomplete" in log
        assert "restarting from the latest complete time 0.002" in log
        assert os.path.isdir(c.file("0.004.incomplete"))  # set aside, not deleted

    # The end (and the rewritten 0.004) bit for bit as the uninterrupted run
    for t in ("0.004", "0.006"):
        differ = same_files(reference, c, t)
        print(f"{point}: files of {t} differing from the uninterrupted run: {differ}")
        assert differ == [], (t, differ)
    series = "postProcessing/grains/grains.vtp.series"
    assert open(c.file(series)).read() == open(reference.file(series)).read()


def test_truncated_demState_is_refused(reference):
    c = copy_of(reference, "crash_truncated", keep=("0.002",))
    state = c.file("0.002/demState")
    size = os.path.getsize(state)
    with open(state, "r+b") as f:
        f.truncate(size // 2)
    c.set("system/controlDict", "startFrom", "startTime")
    c.set("system/controlDict", "startTime", 0.002)
    log = c.run("darcyDemFoam", expect_fail=True)
    assert "FOAM FATAL ERROR" in fatal_message(log)
    assert "Cannot read the grain state file" in log and "0.002/demState" in log
    assert "truncated" in log


def test_demState_of_another_grain_count_is_refused(reference):
    """The grains file written beside a demState lists its grains; one that
    disagrees (here: a line removed) means the two come from different runs."""
    c = copy_of(reference, "crash_grain_count", keep=("0.002",))
    lines = open(c.file("0.002/grains")).read().splitlines(True)
    open(c.file("0.002/grains"), "w").writelines(lines[:-1])
    log = c.run("darcyDemFoam", expect_fail=True)
    assert "0.002/demState\" holds 256 grains" in log and "lists 255" in log


def test_demState_of_another_box_is_refused(reference):
    c = copy_of(reference, "crash_other_box", keep=("0.002",))
    c.set_variable("system/blockMeshDict", "L", "0.12")
    c.run("blockMesh")
    log = c.run("darcyDemFoam", expect_fail=True)
    assert "was written for another case" in log
    assert "its periodic box is x in [0, 0.1]" in log
    assert "this mesh's is x in [0, 0.12]" in log


def test_blown_up_grains_stop_with_the_grain_named():
    """Explicit drag with c dt/m ~ 1e3 makes the velocities grow a
    thousandfold per DEM step: the step stops at the first non-finite grain,
    named, and nothing is written over the start time."""
    c = column("blowup_grains", end=0.002)
    c.set("constant/demProperties", "viscousDrag", 1e6)
    log = c.run("darcyDemFoam", expect_fail=True)
    assert "FOAM FATAL ERROR" in fatal_message(log)
    assert "left the numbers" in log and "position (" in log
    assert "constant/demProperties" in log
    assert c.times() == []


def test_non_finite_pressure_stops_with_the_cell_named(reference, monkeypatch):
    """p at the top ramps to 1e300 between 0.0021 and 0.0023 s, which overflows the
    pressure solve (squares in the solver). With OpenFOAM's floating-point traps off
    (FOAM_SIGFPE=false; on, OpenFOAM itself stops with SIGFPE) the check
    after the solve names the cell, and the time written before (0.002) is
    kept as it was."""
    c = column("blowup_p", end=0.004)
    text = open(c.file("0/p")).read()
    text, n = re.subn(r"top\s*\{[^}]*\}", "top { type uniformFixedValue; uniformValue "
                      "table ((0 0) (0.0021 0) (0.0023 1e300)); }", text)
    assert n == 1
    open(c.file("0/p"), "w").write(text)
    monkeypatch.setenv("FOAM_SIGFPE", "false")
    log = c.run("darcyDemFoam", expect_fail=True)
    fatal_message(log)
    assert "Field p is" in log and "in cell" in log and "(centre (" in log
    assert "Stopped before writing this time" in log
    assert [d for _, d in c.times()] == ["0.002"]
    differ = same_files(reference, c, "0.002", ("demState", "grains", "porosity"))
    assert differ == [], differ

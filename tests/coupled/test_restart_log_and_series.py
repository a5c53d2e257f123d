"""What a restart shows the user (issue 24 items 2 and 3), on the real
solvers: tests/cases/grainColumn (256 grains, 10 DEM steps per fluid step)
run to 0.02 s, written at 0.01 and 0.02, then restarted from 0.01 with
endTime 0.03.

- The progress line's per cent is of this run, (t - t_start)/(t_end -
  t_start), not t/endTime (which said 33 % at the restart's first step).
- Every fluid step prints 'Time = <t>' (demFoam printed only write times).
- The grains' file series lists each time as its directory is named (0.03,
  not 0.029999999999999999), after the restart too.
- The grains' ParaView files are in postProcessing/grains, which
  'foamToVTK -overwrite' (it removes VTK/ whole) leaves alone."""

import json
import math
import os
import re

import pytest

from darcydem.case import Case, fatal_message
from darcydem.foamfiles import GRAINS_DIR

CTL = "system/controlDict"
DEM = "constant/demProperties"
START, FIRST_END, END, DT = 0.01, 0.02, 0.03, 1e-4

PROGRESS = re.compile(r"^Progress: t = (\S+) s, (\d+) %, (\S+) particle-steps/s, "
                      r"about (\d+) s left(?: \(.*\))?$", re.M)
TIME = re.compile(r"^Time = (\S+)$", re.M)


def restarted(solver):
    """The case after its first run and the restart; (case, restart log)."""
    c = Case("grainColumn", "restart_log_" + solver)
    c.set(CTL, "startFrom", "startTime")
    c.set(CTL, "endTime", FIRST_END)
    c.set(CTL, "writeInterval", round(START / DT))
    # a progress line every fluid step (default: every 5 s of wall time)
    c.set(DEM, "output", "{ format ascii; progressInterval 0; }")
    c.run("blockMesh")
    c.run(solver)
    c.set(CTL, "startTime", START)
    c.set(CTL, "endTime", END)
    return c, c.run(solver)


@pytest.fixture(scope="module", params=("demFoam", "darcyDemFoam"))
def run(request):
    c, log = restarted(request.param)
    return request.param, c, log


def test_progress_is_of_this_run(run):
    solver, c, log = run
    lines = PROGRESS.findall(log)
    steps = round((END - START) / DT)
    print(f"{solver}: {len(lines)} progress lines, first {lines[0]}, last {lines[-1]}")
    assert len(lines) == steps
    for t, percent, rate, left in lines:
        share = 100 * ((float(t) - START) / (END - START))
        # the solver truncates its own double (t accumulated step by step):
        # either side of a whole per cent within round-off
        assert int(percent) in {math.floor(share - 1e-6), math.floor(share + 1e-6)}, (t, percent)
        assert float(rate) > 0
    assert lines[0][:2] == ("0.0101", "0")   # t/endTime said 33 %
    assert lines[-1][:2] == ("0.03", "100")


def test_every_step_prints_its_time(run):
    solver, c, log = run
    times = TIME.findall(log)
    assert len(times) == round((END - START) / DT)
    assert times[0] == "0.0101" and times[-1] == "0.03"
    assert log.count("ExecutionTime = ") == len(times)


def test_series_names_times_as_the_time_directories(run):
    """The series ParaView opens: the times as written in the JSON text are
    the time names, the first from the first run, read back on restart."""
    solver, c, log = run
    path = c.file(os.path.join(GRAINS_DIR, "grains.vtp.series"))
    text = open(path).read()
    print(text)
    assert re.findall(r'"time" : ([^ ]+) }', text) == ["0.01", "0.02", "0.03"]
    files = json.loads(text)["files"]
    assert [f["name"] for f in files] == ["grains_0.01.vtp", "grains_0.02.vtp", "grains_0.03.vtp"]
    for name in ("0.01", "0.02", "0.03"):
        assert os.path.isdir(c.file(name))


def test_foamToVTK_overwrite_leaves_the_grains(run):
    solver, c, log = run
    grains = c.file(GRAINS_DIR)
    before = sorted(os.listdir(grains))
    c.run("foamToVTK")
    c.run("foamToVTK", "-overwrite")
    assert sorted(os.listdir(grains)) == before
    assert set(before) >= {"grains.vtp.series", "grains_0.01.vtp", "grains_0.02.vtp",
                           "grains_0.03.vtp"}
    assert os.listdir(c.file("VTK"))  # the fields, converted again


def test_negative_progress_interval_is_refused():
    c = Case("grainColumn", "progress_interval_negative")
    c.set(CTL, "endTime", 0)
    c.set(DEM, "output", "{ progressInterval -1; }")
    c.run("blockMesh")
    text = fatal_message(c.run("demFoam", expect_fail=True))
    assert "output/progressInterval" in text and "must be >= 0" in text

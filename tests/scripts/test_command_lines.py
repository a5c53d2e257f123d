"""The user scripts of bin/ on their command line (issue 24): --help prints
usage and creates nothing; a missing or mistyped folder is one line naming
it, a non-zero exit, and nothing created (a study used to make
<typo>/stages, then end in a traceback); makeGrains refuses a random
packing that cannot fit before placing any grain; a study's first stage
line reaches a pipe at once, without PYTHONUNBUFFERED, and a stage relays
its solver's progress (simulated time, per cent, rate, time left) while it
runs.

Every script runs with a fresh temporary directory as its working
directory, and "creates nothing" is checked by listing that directory."""

import os
import re
import select
import shutil
import signal
import subprocess
import sys
import time

import pytest

PROJECT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BIN = os.path.join(PROJECT, "bin")

# script -> the arguments that come besides the folder (makeGrains takes a
# file to write, whose folder is what can be mistyped)
FOLDER_SCRIPTS = {
    "shearStudy": [],
    "consolidationStudy": [],
    "settlementStudy": [],
    "plotGrains": [],
    "plotDrainedColumn": [],
}
MAKE_GRAINS_ARGS = ["--box", "0.1", "0.1", "--z", "0", "0.1", "--radius", "0.004", "0.005",
                    "--layout", "random"]


def run(args, cwd, timeout=60, env=None):
    return subprocess.run([os.path.join(BIN, args[0]), *args[1:]], cwd=cwd, env=env,
                          capture_output=True, text=True, timeout=timeout)


@pytest.mark.parametrize("script", [*FOLDER_SCRIPTS, "makeGrains", "benchPeers",
                                    "benchRanks", "gpuCheck", "gpuRuntime"])
def test_help_prints_usage_and_creates_nothing(script, tmp_path):
    r = run([script, "--help"], tmp_path)
    assert r.returncode == 0, r.stderr
    assert r.stdout.startswith("usage: " + script), r.stdout[:200]
    assert os.listdir(tmp_path) == [], "--help created " + " ".join(os.listdir(tmp_path))


@pytest.mark.parametrize("script", FOLDER_SCRIPTS)
@pytest.mark.parametrize("folder", ["typo", "empty"])
def test_missing_folder_is_one_line(script, folder, tmp_path):
    """'typo' does not exist; 'empty' exists but holds no case: the line
    names the folder and the files it should hold."""
    if folder == "empty":
        os.mkdir(tmp_path / "empty")
    r = run([script, folder, *FOLDER_SCRIPTS[script]], tmp_path)
    print(r.stderr)
    assert r.returncode != 0
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in r.stderr, r.stderr
    assert folder in lines[0] and script in lines[0]
    assert any(name in lines[0] for name in ("system/controlDict",
                                             "postProcessing/grains/capsules.vtp.series",
                                             "constant/darcyProperties"))
    left = sorted(os.listdir(tmp_path))
    assert left == ([] if folder == "typo" else ["empty"]), left
    if folder == "empty":
        assert os.listdir(tmp_path / "empty") == []


def copy_study(tmp_path, solver, tutorial, name="study"):
    """The tutorial's case files as tmp_path/name, without anything a run
    left there; returns that folder."""
    study = tmp_path / name
    shutil.copytree(os.path.join(PROJECT, "tutorials", solver, tutorial), study,
                    ignore=shutil.ignore_patterns("stages", "*.png", "results*.json", "log.*"))
    return study


@pytest.mark.parametrize("option, message", [
    ("--weak-bonds", "settlementStudy: --weak-bonds 0: the scale must be > 0"),
    ("--strength-scale", "settlementStudy: --strength-scale 0: the scale must be > 0"),
    ("--preparation-viscosity",
     "settlementStudy: --preparation-viscosity 0: the contact viscosity must be > 0 Pa s"),
    ("--preparation-rate",
     "settlementStudy: --preparation-rate 0: the contraction's strain rate must be < 0 1/s")])
def test_settlement_scales_must_be_positive(tmp_path, option, message):
    """settlementStudy --weak-bonds 0 or --strength-scale 0 (a bond strength of
    zero), --preparation-viscosity 0 (bonds without viscosity) or
    --preparation-rate 0 (no contraction): one line
    naming the option, before any folder is looked at or made."""
    copy_study(tmp_path, "demFoam", "snowSettlement")
    r = run(["settlementStudy", "study", option, "0"], tmp_path)
    print(r.stderr)
    assert r.returncode != 0 and "Traceback" not in r.stderr
    assert r.stderr.strip() == message
    assert not os.path.exists(tmp_path / "study" / "stages")


def test_settlement_bond_point_names_the_valid_ones(tmp_path):
    """settlementStudy --bond-point sticky: refused naming both valid models,
    before any folder is made."""
    copy_study(tmp_path, "demFoam", "snowSettlement")
    r = run(["settlementStudy", "study", "--bond-point", "sticky"], tmp_path)
    print(r.stderr)
    assert r.returncode != 0 and "Traceback" not in r.stderr
    assert "--bond-point" in r.stderr and "'sticky'" in r.stderr
    assert "closestPoints" in r.stderr and "bodyFixedPatches" in r.stderr
    assert not os.path.exists(tmp_path / "study" / "stages")


@pytest.mark.parametrize("script, solver, tutorial, message", [
    ("shearStudy", "darcyDemFoam", "shear", "shearStudy: --jobs 0: give 1 or more stages at once"),
    ("settlementStudy", "demFoam", "snowSettlement",
     "settlementStudy: --jobs 0: give 1 or more runs at once"),
    ("consolidationStudy", "darcyDemFoam", "consolidation",
     "consolidationStudy: --jobs 0: give 1 or more stages at once")])
def test_study_jobs_must_be_positive(tmp_path, script, solver, tutorial, message):
    """shearStudy / settlementStudy / consolidationStudy --jobs 0 (no stage could run): one line
    naming the option, before any folder is looked at or made."""
    copy_study(tmp_path, solver, tutorial)
    r = run([script, "study", "--jobs", "0"], tmp_path)
    print(r.stderr)
    assert r.returncode != 0 and "Traceback" not in r.stderr
    assert r.stderr.strip() == message
    assert not os.path.exists(tmp_path / "study" / "stages")


def test_make_grains_missing_output_folder(tmp_path):
    start = time.monotonic()
    r = run(["makeGrains", *MAKE_GRAINS_ARGS, "--count", "10", "-o", "typo/grains"], tmp_path)
    print(r.stderr)
    assert r.returncode != 0 and "typo" in r.stderr and "Traceback" not in r.stderr
    assert os.listdir(tmp_path) == []
    assert time.monotonic() - start < 10


def test_make_grains_impossible_count_fails_fast(tmp_path):
    """1500 grains of r 4-5 mm with clearance 1.1 in 1e-3 m^3 need 0.78 of
    the box; random placement stops near 0.38. Refused before placing (the
    try budget ran for minutes before saying so)."""
    start = time.monotonic()
    r = run(["makeGrains", *MAKE_GRAINS_ARGS, "--count", "1500", "-o", "grains"], tmp_path)
    seconds = time.monotonic() - start
    print(r.stderr, f"({seconds:.1f} s)")
    assert r.returncode != 0
    assert "1500 grains" in r.stderr and "0.38" in r.stderr and "0.77" in r.stderr
    assert seconds < 10
    assert os.listdir(tmp_path) == []


def test_make_grains_fitting_count_still_placed(tmp_path):
    """The check refuses only what cannot fit: 150 grains (0.078 of the
    box with their clearance) are placed."""
    r = run(["makeGrains", *MAKE_GRAINS_ARGS, "--count", "150", "-o", "grains"], tmp_path)
    assert r.returncode == 0, r.stderr
    assert sum(1 for l in open(tmp_path / "grains") if not l.startswith("#")) == 150


def test_study_stage_line_reaches_a_pipe_at_once(tmp_path):
    """shearStudy --size test into a pipe, PYTHONUNBUFFERED unset: its first
    stage line (printed before the first solver starts) is read within the
    time makeGrains and blockMesh take, while demFoam runs the stage, not
    when the study ends; then the study is killed. Needs demFoam: without
    it the study would stop right after the line, and Python's flush at
    exit would bring the line out even unflushed."""
    missing = [app for app in ("foamDictionary", "blockMesh", "demFoam")
               if shutil.which(app) is None]
    if missing:
        pytest.skip("not on PATH: " + " ".join(missing) + " (source etc/bashrc after"
                    " ./Allwmake, or the bashrc of a built checkout)")
    study = copy_study(tmp_path, "darcyDemFoam", "shear", "shear")
    env = {k: v for k, v in os.environ.items() if k != "PYTHONUNBUFFERED"}
    p = subprocess.Popen([os.path.join(BIN, "shearStudy"), "--size", "test", str(study)],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env,
                         start_new_session=True)   # its own group: the kill takes demFoam too
    start = time.monotonic()
    try:
        ready, _, _ = select.select([p.stdout], [], [], 120)
        line = p.stdout.readline().decode() if ready else ""
        seconds = time.monotonic() - start
        running = p.poll() is None   # the line came while the stage ran, not at exit
    finally:
        os.killpg(p.pid, signal.SIGKILL)
        p.wait()
    print(f"first line after {seconds:.1f} s: {line.strip()}")
    if not line:
        sys.stderr.write(p.stderr.read().decode()[-2000:])
    assert line.startswith("shearStudy: stage settle: "), line
    assert "to t = " in line
    assert running, "the study had ended when its first line came"


def test_stage_progress_is_relayed_while_the_solver_runs():
    """A study's stage relays the solver's progress lines (simulated time,
    per cent, rate, time left) while the solver runs, not only the stage's
    first and last lines: darcyDemFoam on the grain column for a few seconds,
    progress written every 0.2 s, relayed every 0.5 s. A failing solver
    still stops the study with its error."""
    if shutil.which("darcyDemFoam") is None:
        pytest.skip("darcyDemFoam not on PATH (source etc/bashrc after ./Allwmake)")
    sys.path.insert(0, BIN)
    from darcydem.case import Case, RunError
    from darcydem.cli import StageClock

    case = Case("grainColumn", "stage_progress")
    case.set("constant/demProperties", "output/progressInterval", 0.2)
    case.set("system/controlDict", "endTime", 0.3)
    case.mesh()
    lines = []
    StageClock("study", lines.append, relay_interval=0.5).run(case, "darcyDemFoam", "column",
                                                              "a grain column", 0.3)
    print("\n".join(lines))
    assert lines[0] == "study: stage column: a grain column, to t = 0.3 s"
    assert lines[-1].startswith("study: stage column done in ")
    relayed = lines[1:-1]
    assert relayed, "no progress line while the solver ran"
    times = []
    for line in relayed:
        # (threads 0: the adaptive team's count of steps on all threads after it)
        m = re.fullmatch(r"study: stage column: t = (\S+) s, (\d+) %, \S+ particle-steps/s, "
                         r"about (\d+) s left(?: \(\d+ of \d+ DEM steps on \d+ threads, "
                         r"the rest on 1\))?", line)
        assert m, line
        times.append(float(m.group(1)))
    assert times == sorted(times) and 0 < times[0] and times[-1] <= 0.3

    case.set("constant/demProperties", "timeStep", -1)
    with pytest.raises(RunError, match="timeStep"):
        StageClock("study", lines.append, relay_interval=0.5).run(case, "darcyDemFoam",
                                                                  "broken", "a bad case", 0.3)

"""nsDemFoam's input and restart: -help says what it solves; a fluid force
that is not a drag law, a missing grains dictionary, an unknown
depositAtWalls and a non-positive viscosity stop before the first step, naming the file, the entry and the
valid choices; a drag law used outside the porosity of its data says so once
in the log (and the run goes on); a restart from a written time is exact. Real binary on tests/cases/fixedBed (a frozen bed in a
column); the mistyped entries of nsDemProperties are in
tests/input/test_unknown_entries.py."""

import filecmp
import os
import shutil
import subprocess

from darcydem.case import Case, fatal_message

NS = "constant/nsDemProperties"
DRAG_LAWS = ("Beetstra", "DiFelice", "ErgunWenYu")


def failing(name, edit):
    c = Case("fixedBed", name)
    c.set("system/controlDict", "endTime", 0.01)
    edit(c)
    c.run("blockMesh")
    return fatal_message(c.run("nsDemFoam", expect_fail=True))


def test_help_says_what_it_solves():
    out = subprocess.run(["nsDemFoam", "-help"], stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, text=True, timeout=60).stdout
    assert "Navier-Stokes" in out and "drag law" in out


def test_darcy_model_is_refused_naming_the_drag_laws():
    msg = failing("ns_darcy_model", lambda c: c.set(NS, "grains/fluidForce/type", "darcy"))
    assert "Entry 'type'" in msg and "nsDemProperties" in msg
    assert "'darcy' is not a drag law" in msg
    assert all(law in msg.split("takes one of")[1] for law in DRAG_LAWS)


def test_missing_grains_dictionary_names_the_file_and_the_laws():
    msg = failing("ns_no_grains", lambda c: c.remove(NS, "grains"))
    assert "Dictionary 'grains' not found" in msg and "nsDemProperties" in msg
    assert all(law in msg for law in DRAG_LAWS)


def test_unknown_deposit_at_walls_lists_the_choices():
    msg = failing("ns_bad_wall_deposit",
                  lambda c: c.set(NS, "grains/depositAtWalls", "mirror"))
    assert "mirror" in msg and "depositAtWalls" in msg and "nsDemProperties" in msg
    assert "inside" in msg and "across" in msg


def test_non_positive_viscosity_is_refused():
    msg = failing("ns_bad_mu", lambda c: c.set(NS, "mu", "[1 -1 -1 0 0 0 0] 0"))
    assert "mu" in msg and "nsDemProperties" in msg


def test_law_outside_its_porosity_range_says_so_once():
    """Beetstra's simulations span porosities 0.4-0.9: the bed's ends, where
    the deposit thins out (porosity 0.94 in the cells next to it), are
    outside, and the log says so once in a run of many steps."""
    c = Case("fixedBed", "ns_range_once")
    c.set("system/controlDict", "endTime", 0.02)
    c.set(NS, "grains/fluidForce/type", "Beetstra")
    c.run("blockMesh")
    log = c.run("nsDemFoam")
    lines = [line for line in log.splitlines() if "outside the law's range" in line]
    print("\n".join(lines))
    porosity = [line for line in lines if "porosity" in line]
    assert len(porosity) == 1 and "Beetstra" in porosity[0] and "[0.4, 0.9]" in porosity[0]
    assert log.count("Time = ") >= 10  # the run went on


def test_restart_is_exact():
    """A settling sphere (tests/cases/settlingSphere: the grain falls, the
    fluid moves) run to 0.1 s in one go, and run to 0.05 s then restarted
    from the written 0.05: the fields and the grains of 0.1 are the same
    bytes (CPU backend; binary files at 17 digits). The flow, the deposit's
    old time, the drag coefficient and the grains' loads are all rebuilt
    from what a time holds."""
    whole = Case("settlingSphere", "ns_restart_whole")
    whole.set("system/controlDict", "endTime", 0.1)
    whole.set("system/controlDict", "writeInterval", 5)
    whole.run("blockMesh")
    whole.run("nsDemFoam")

    path = os.path.join(os.path.dirname(whole.path), "ns_restart_resumed")
    shutil.rmtree(path, ignore_errors=True)
    shutil.copytree(whole.path, path, ignore=shutil.ignore_patterns("postProcessing", "log.*"))
    resumed = Case.existing(path)
    shutil.rmtree(resumed.file("0.1"))
    log = resumed.run("nsDemFoam")
    assert "Time = 0.06" in log and "Time = 0.01\n" not in log  # resumed at 0.05

    names = ("U", "p", "phi", "porosity", "Us", "dragCoefficient", "grainReaction",
             "grains", "demState")
    differ = [n for n in names
              if not filecmp.cmp(whole.file(f"0.1/{n}"), resumed.file(f"0.1/{n}"),
                                 shallow=False)]
    assert differ == [], differ

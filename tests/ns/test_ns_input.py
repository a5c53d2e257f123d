"""nsDemFoam's input: -help says what it solves; a fluid force that is not
a drag law, a missing grains dictionary and a non-positive viscosity stop
before the first step, naming the file, the entry and the valid choices; a
drag law used outside the porosity of its data says so once in the log (and
the run goes on). Real binary on tests/cases/fixedBed (a frozen bed in a
column); the mistyped entries of nsDemProperties are in
tests/input/test_unknown_entries.py."""

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

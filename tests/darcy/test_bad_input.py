"""darcyDemFoam refuses bad input with a message naming the file, the entry
and the valid choices (DEVELOPERS.md: bad input gets a clear error)."""

import pytest

from darcydem.case import Case

PROPS = "constant/darcyProperties"


def failing_run(name, edit):
    c = Case("darcyColumn", name)
    c.set("system/controlDict", "endTime", 1e-3)
    edit(c)
    c.run("blockMesh")
    return c.run("darcyDemFoam", expect_fail=True)


def test_unknown_permeability_model_lists_valid_names():
    log = failing_run("bad_perm", lambda c: c.set(PROPS, "permeability/type", "kozeny"))
    assert "Unknown permeability model type kozeny" in log
    for name in ("constant", "kozenyCarman", "kozenyCarmanGrainSize"):
        assert name in log.split("Valid permeability model types")[1]
    assert "darcyProperties" in log


def test_unknown_solid_phase_lists_valid_names():
    log = failing_run("bad_solid", lambda c: c.set(PROPS, "solidPhase/type", "grains"))
    assert "Unknown solid phase type grains" in log
    for name in ("staticPorosity", "uniformPorosity"):
        assert name in log.split("Valid solid phase types")[1]


@pytest.mark.parametrize("entry,rule", [("mu", "> 0"), ("beta", "> 0"), ("rho", ">= 0")])
def test_negative_fluid_property(entry, rule):
    log = failing_run(f"bad_{entry}", lambda c: c.set(PROPS, entry, "-1"))
    assert f"Entry '{entry}'" in log and f"must be {rule}, found -1" in log
    assert "darcyProperties" in log


def test_missing_fluid_property():
    log = failing_run("missing_beta", lambda c: c.remove(PROPS, "beta"))
    assert "Entry 'beta' not found" in log and "darcyProperties" in log


def test_porosity_outside_unit_interval():
    log = failing_run("bad_porosity", lambda c: c.set("0/porosity", "internalField", "uniform 1.2"))
    assert "Porosity 1.2" in log and "outside (0, 1)" in log and "porosity" in log


def test_porosity_clamp_must_be_ordered():
    def edit(c):
        c.set(PROPS, "permeability",
              "{ type kozenyCarman; kc 1e-13; porosityMin 0.8; porosityMax 0.2; }")
    log = failing_run("bad_clamp", edit)
    assert "porosityMin" in log and "porosityMax" in log and "must satisfy" in log


def test_negative_permeability_prefactor():
    def edit(c):
        c.set(PROPS, "permeability",
              "{ type kozenyCarman; kc -1e-13; porosityMin 0.1; porosityMax 0.9; }")
    log = failing_run("bad_kc", edit)
    assert "Entry 'kc'" in log and "must be > 0" in log

"""The 'bonds' dictionary of constant/demProperties (issue 11): one run-time
selected model per mechanism family (creep, compressiveCreep, strength,
sintering, formation) and of where a bond sits (point). A missing or unknown type stops naming the valid
ones, a value out of range stops naming the file, the entry, the value and
the range, an unknown entry in 'bonds' stops naming the valid entries.
Case: tests/cases/grainColumn run by demFoam (stops before the first step)."""

import re

import pytest

from darcydem.case import Case, fatal_message

DEM = "constant/demProperties"
FAMILIES = {
    "creep": ["maxwell", "none"],
    "compressiveCreep": ["none", "powerLaw"],
    "strength": ["constant", "iceTemperature", "none"],
    "sintering": ["none", "pressureSintering"],
    "formation": ["frozenOnContact", "none"],
    "point": ["bodyFixedPatches", "closestPoints"],
}
# Every mechanism on: the entries each test spoils one by one
VALID = {
    "creep": "type maxwell; contactViscosity 1600; shear yes; twist yes; bend yes;",
    "compressiveCreep": "type powerLaw;",
    "strength": "type iceTemperature; scale 1e-3; softeningRatio 1; brokenFraction 0.05;",
    "sintering": "type pressureSintering;",
    "formation": "type frozenOnContact; areaFraction (0.03125 0.09375); interval 10; seed 1;",
    "point": "type bodyFixedPatches;",
}


def bonds_entry(constants="youngsModulus 9e6; temperature -10;", **mechanisms):
    """A 'bonds' dictionary: the constants, then every mechanism (VALID
    unless given; None leaves it out)."""
    parts = [constants]
    for key, entries in {**VALID, **mechanisms}.items():
        if entries is not None:
            parts.append(f"{key} {{ {entries} }}")
    return "{ " + " ".join(parts) + " }"


def run(name, bonds, expect_fail=True):
    c = Case("grainColumn", f"bonds_{name}")
    c.set("system/controlDict", "endTime", 1e-3)
    c.set(DEM, "bonds", bonds)
    c.run("blockMesh")
    log = c.run("demFoam", expect_fail=expect_fail)
    return fatal_message(log) if expect_fail else log


def test_every_mechanism_is_read():
    """All five mechanisms on and the patches body-fixed: the run starts and
    the log names each model."""
    log = run("all_on", bonds_entry(), expect_fail=False)
    for family, model in [("creep", "maxwell"), ("compressive creep", "powerLaw"),
                          ("strength", "iceTemperature"), ("sintering", "pressureSintering"),
                          ("formation", "frozenOnContact"), ("point", "bodyFixedPatches")]:
        assert f"bond {family} {model}" in log


def test_zero_strength_switches_one_failure_mode_off():
    """A bond that fails only in shear: tensileStrength 0 is accepted."""
    run("tension_never_fails", bonds_entry(
        strength="type constant; tensileStrength 0; shearStrength 1e5;"), expect_fail=False)


def test_left_out_mechanism_is_off_and_logged():
    log = run("creep_left_out", bonds_entry(creep=None, point=None), expect_fail=False)
    assert "bond creep none (no 'creep' entry)" in log
    assert "bond point closestPoints (no 'point' entry)" in log


@pytest.mark.parametrize("family", FAMILIES)
def test_unknown_model_lists_the_valid_ones(family):
    msg = run(f"unknown_{family}", bonds_entry(**{family: "type sticky;"}))
    assert "FOAM FATAL IO ERROR" in msg and "type sticky" in msg
    assert f"demProperties.bonds.{family}" in msg   # the file and the entry
    valid = msg.split("Valid")[1]
    assert all(model in valid for model in FAMILIES[family])


@pytest.mark.parametrize("family", FAMILIES)
def test_missing_type_lists_the_valid_ones(family):
    msg = run(f"missing_type_{family}", bonds_entry(**{family: "interval 3;"}))
    assert "Entry 'type' not found" in msg and f"demProperties.bonds.{family}" in msg
    assert all(model in msg for model in FAMILIES[family])


def test_unknown_entry_in_bonds_names_the_valid_ones():
    """A misspelt mechanism would otherwise be off without a word."""
    msg = run("misspelt", bonds_entry("youngsModulus 9e6; creeps { type maxwell; }"))
    assert "Unknown entry 'creeps'" in msg and "demProperties.bonds" in msg
    assert "creep" in msg and "youngsModulus" in msg and "formation" in msg


def test_mechanism_must_be_a_dictionary():
    msg = run("not_a_dict", bonds_entry("youngsModulus 9e6; sintering none;", sintering=None))
    assert "Entry 'sintering'" in msg and "must be a dictionary" in msg


@pytest.mark.parametrize("constants,rule", [
    ("temperature -10;", "Entry 'youngsModulus' not found"),   # required
    ("youngsModulus 0;", "Entry 'youngsModulus' in .* must be > 0, found 0"),
    ("youngsModulus 9e6; shearToNormalStiffness 1.5;",
     "Entry 'shearToNormalStiffness' in .* must lie in (0, 1], found 1.5"),
    ("youngsModulus 9e6; shearToNormalStiffness 0;",
     "Entry 'shearToNormalStiffness' in .* must lie in (0, 1], found 0"),
    ("youngsModulus 9e6; normalDampingRatio -0.1;",
     "Entry 'normalDampingRatio' in .* must lie in [0, 1], found -0.1"),
    ("youngsModulus 9e6; shearDampingRatio 2;",
     "Entry 'shearDampingRatio' in .* must lie in [0, 1], found 2"),
    ("youngsModulus 9e6; temperature 5;",
     "Entry 'temperature' in .* must lie in (-273.15, 0], found 5"),
    ("youngsModulus 9e6; temperature -273.15;",
     "Entry 'temperature' in .* must lie in (-273.15, 0], found -273.1"),
])
def test_constant_out_of_range(constants, rule):
    msg = run(re.sub(r"\W+", "_", "constant " + constants).strip("_"), bonds_entry(constants))
    assert "demProperties.bonds" in msg
    head, tail = rule.split(" in .* ") if " in .* " in rule else (rule, "")
    assert head in msg and tail in msg


@pytest.mark.parametrize("family,entries,rule", [
    ("creep", "type maxwell;", "Entry 'contactViscosity' not found"),
    ("creep", "type maxwell; contactViscosity 0;", "must be > 0, found 0"),
    ("compressiveCreep", "type powerLaw; prefactor -1;", "must be > 0, found -1"),
    ("compressiveCreep", "type powerLaw; activationEnergy -5;", "must be >= 0, found -5"),
    ("compressiveCreep", "type powerLaw; prefactor 1e-12; exponent 1;",
     "must lie in (1, 10], found 1"),
    ("compressiveCreep", "type powerLaw; exponent 2;",
     "holds for exponent 3 only. Give prefactor in s^-1 Pa^-n for n = 2"),
    ("strength", "type iceTemperature; scale 0;", "must be > 0, found 0"),
    ("strength", "type iceTemperature; softeningRatio -1;", "must be > 0, found -1"),
    ("strength", "type iceTemperature; brokenFraction 1.5;", "must lie in [0, 1), found 1.5"),
    ("strength", "type iceTemperature; brokenFraction 1;", "must lie in [0, 1), found 1"),
    ("strength", "type constant; shearStrength 1e5;", "Entry 'tensileStrength' not found"),
    ("strength", "type constant; tensileStrength 1e5; shearStrength -1;",
     "must be >= 0, found -1"),
    ("formation", "type frozenOnContact; areaFraction (0.2 0.1);",
     "0 < min <= max <= 1, found (0.2 0.1)"),
    ("formation", "type frozenOnContact; areaFraction (0 0.1);",
     "0 < min <= max <= 1, found (0 0.1)"),
    ("formation", "type frozenOnContact; areaFraction (0.5 1.5);",
     "0 < min <= max <= 1, found (0.5 1.5)"),
    ("formation", "type frozenOnContact; interval 0;", "must be >= 1, found 0"),
    ("formation", "type frozenOnContact; seed -1;", "must be >= 0, found -1"),
])
def test_model_entry_out_of_range(family, entries, rule):
    name = re.sub(r"\W+", "_", f"{family} {entries}".replace("type ", "")).strip("_")
    msg = run(name, bonds_entry(**{family: entries}))
    entry = entries.split(";")[-2].split()[0] if "not found" not in rule else None
    assert f"demProperties.bonds.{family}" in msg and rule in msg
    if entry:
        assert f"Entry '{entry}'" in msg

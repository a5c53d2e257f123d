"""The contact law is a run-time selected family (issue 10): 'contact { type
linearSpring | snow; ... }' in constant/demProperties, the same family for
'wallContact'. An unknown or missing type stops naming the valid ones, an
out-of-range constant stops naming the file, the entry, the value and the
range. Case: tests/cases/grainColumn (stops before the first step)."""

import numpy as np
import pytest

from darcydem.case import Case, fatal_message

DEM = "constant/demProperties"
LAWS = ("linearSpring", "snow")


def failing(name, edit):
    c = Case("grainColumn", name)
    c.set("system/controlDict", "endTime", 1e-3)
    edit(c)
    c.run("blockMesh")
    return fatal_message(c.run("darcyDemFoam", expect_fail=True))


def snow(c, key, entries):
    c.set(DEM, key, "{ type snow; " + entries + " }")


@pytest.mark.parametrize("key", ["contact", "wallContact"])
def test_unknown_law_lists_the_valid_ones(key):
    def edit(c):
        c.set(DEM, key, "{ type springy; normalStiffness 1e6; }")
    msg = failing(f"law_unknown_{key}", edit)
    assert "FOAM FATAL IO ERROR" in msg and "Unknown contact law type springy" in msg
    valid = msg.split("Valid contact law types")[1]
    assert all(law in valid for law in LAWS)
    assert f"demProperties.{key}" in msg   # the file and the dictionary


def test_missing_type_names_the_law_to_add():
    msg = failing("law_missing_type", lambda c: c.remove(DEM, "contact/type"))
    assert "Entry 'type' not found" in msg and "demProperties.contact" in msg
    assert "type linearSpring;" in msg and all(law in msg for law in LAWS)


@pytest.mark.parametrize("entry,value,rule", [
    ("tangentialToNormalStiffness", 1.5, "must lie in [0, 1], found 1.5"),
    ("normalDampingRatio", -0.1, "must lie in [0, 1], found -0.1"),
    ("tangentialDampingRatio", 2, "must lie in [0, 1], found 2"),
    ("friction", -0.5, "must be >= 0, found -0.5"),
])
def test_snow_constant_out_of_range(entry, value, rule):
    msg = failing(f"law_snow_{entry}",
                  lambda c: snow(c, "contact", f"youngsModulus 1e7; {entry} {value};"))
    assert f"Entry '{entry}' in" in msg and "demProperties.contact" in msg and rule in msg


def test_snow_needs_a_positive_youngs_modulus():
    msg = failing("law_snow_E", lambda c: snow(c, "wallContact", "youngsModulus 0;"))
    assert "Entry 'youngsModulus'" in msg and "demProperties.wallContact" in msg
    assert "must be > 0, found 0" in msg


def test_linear_spring_negative_damping():
    msg = failing("law_linear_damping", lambda c: c.set(DEM, "contact/normalDamping", -1))
    assert "Entry 'normalDamping' in" in msg and "must be >= 0, found -1" in msg


def time_step_ratio(log):
    """dt / sqrt(m_min/k_max) as the solver prints it (17 digits)."""
    line = next(l for l in log.splitlines() if "DEM time step" in l)
    return float(line.split("=")[1].split()[0])


@pytest.mark.parametrize("law", LAWS)
def test_selected_law_reaches_the_library(law):
    """The selected law's stiffness is the one the DEM library uses: its
    critical step sqrt(m_min/k_max) (spheres: m_min the lightest grain) has
    k_max = k_n = 1e6 N/m for linearSpring and k_n = E pi R_max/2 for snow
    (E = 2e8 Pa, R_max the largest radius; k_t = 0.6 k_n is smaller). The
    printed ratio dt/sqrt(m_min/k_max) must match to round-off (1e-12)."""
    c = Case("grainColumn", f"law_reaches_library_{law}")
    c.set("system/controlDict", "endTime", 1e-3)
    youngs = 2e8
    if law == "snow":
        c.set(DEM, "contact", "{ type snow; youngsModulus %g; normalDampingRatio 0.2;"
                              " friction 0.5; }" % youngs)
        c.set(DEM, "timeStep", 2e-6)
    c.run("blockMesh")
    log = c.run("darcyDemFoam")
    grains = np.loadtxt(c.file("0/grains"), comments="#", ndmin=2)
    r = grains[:, 3]
    m_min = 2600 * 4 / 3 * np.pi * r.min()**3
    k = 1e6 if law == "linearSpring" else youngs * np.pi * r.max() / 2
    dt = 1e-5 if law == "linearSpring" else 2e-6
    expected = dt / np.sqrt(m_min / k)
    found = time_step_ratio(log)
    print(f"{law}: dt/sqrt(m_min/k_max) printed {found:.15g}, expected {expected:.15g}")
    assert found == pytest.approx(expected, rel=1e-12)

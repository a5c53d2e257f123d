"""Fluid force on a grain, as the fluidForce model of constant/darcyProperties
makes it (doc/EQUATIONS.md 7), with grad(p) interpolated to the grain by the
deposit's weights. A single fixed grain in a saturated column:
  - pressureGradient (Damsgaard et al. 2015, eq. 12): with p = 0 exactly the
    buoyancy -rho_f V g; in a steady linear pressure field (p fixed at top and
    base) -V grad(p) - rho_f V g;
  - darcy: -V grad(p)/(1 - phi) - rho_f V g, phi the deposited porosity (here
    held uniform by the clamp porosityMax, which the lone grain's cells
    exceed);
  - none: no force at all.
A missing fluidForce or an unknown type stops naming the file, the entry and
the valid types."""

import numpy as np
import pytest

from darcydem.case import Case
from darcydem.foamfiles import read_vtp

RHO_F, G, R = 1000.0, 9.81, 0.01
V = 4 / 3 * np.pi * R**3
H = 0.4


def held_grain(name, p_base, model="pressureGradient", porosity_max=0.9):
    c = Case("grainColumn", name)
    c.set("constant/darcyProperties", "solidPhase/fluidForce/type", model)
    c.set("constant/darcyProperties", "solidPhase/porosityMax", porosity_max)
    with open(c.file("0/grains"), "w") as f:
        f.write("# one grain\n0.03 0.07 0.21 %g\n" % R)
    c.set("constant/demProperties", "grainFlags", "{ all { flag fixed; } }")
    c.set("constant/demProperties", "walls", "{ bottom { side lower; mode fixed; position 0; } }")
    c.set("constant/darcyProperties", "permeability", "{ type constant; k 1e-10; }")
    c.set("constant/darcyProperties", "beta", 1e-12)   # steady within a step
    c.set("system/fvSchemes", "ddtSchemes/default", "Euler")
    c.set("system/controlDict", "endTime", 0.002)
    c.set("system/controlDict", "writeInterval", 20)
    c.set("0/p", "boundaryField/bottom", "{ type fixedValue; value uniform %g; }" % p_base)
    c.run("blockMesh")
    c.run("darcyDemFoam")
    # The lone grain's cells are emptier than the clamp: the porosity is
    # porosityMax everywhere, so 1 - phi in the darcy force is exact
    assert np.all(c.field("0.002", "porosity") == porosity_max)
    return read_vtp(c.file("postProcessing/grains/grains_0.002.vtp"))["fluidForce"][0]


def test_buoyancy_only_when_p_is_zero():
    f = held_grain("force_buoyancy", 0.0)
    expected = np.array([0, 0, RHO_F * V * G])
    print(f"fluid force {f}, expected {expected}")
    assert np.allclose(f, expected, rtol=1e-12, atol=1e-15)


@pytest.mark.parametrize("p_base", [2500.0, -800.0])
def test_uniform_pressure_gradient(p_base):
    f = held_grain(f"force_gradient_{p_base:g}", p_base)
    grad_p = (0.0 - p_base) / H
    expected = np.array([0, 0, -V * grad_p + RHO_F * V * G])
    err = np.max(np.abs(f - expected)) / np.max(np.abs(expected))
    print(f"fluid force {f}, expected {expected}, relative error {err:.1e}")
    assert err < 1e-9


@pytest.mark.parametrize("p_base", [2500.0, -800.0])
def test_darcy_force_is_the_whole_skeleton_force(p_base):
    phi = 0.7
    f = held_grain(f"force_darcy_{p_base:g}", p_base, "darcy", porosity_max=phi)
    grad_p = (0.0 - p_base) / H
    expected = np.array([0, 0, -V * grad_p / (1 - phi) + RHO_F * V * G])
    err = np.max(np.abs(f - expected)) / np.max(np.abs(expected))
    print(f"fluid force {f}, expected {expected}, relative error {err:.1e}")
    assert err < 1e-9


def test_no_fluid_force():
    f = held_grain("force_none", 2500.0, "none")
    print(f"fluid force {f}")
    assert np.all(f == 0)


def failing_column(name, edit):
    c = Case("grainColumn", name)
    c.set("system/controlDict", "endTime", 0.001)
    edit(c)
    c.run("blockMesh")
    return c.run("darcyDemFoam", expect_fail=True)


VALID = ("darcy", "none", "pressureGradient")


def test_missing_fluid_force_lists_the_models():
    log = failing_column("force_missing",
                         lambda c: c.remove("constant/darcyProperties", "solidPhase/fluidForce"))
    assert "'fluidForce' not found" in log and "darcyProperties" in log
    assert all(name in log for name in VALID)


def test_unknown_fluid_force_lists_the_models():
    log = failing_column("force_unknown", lambda c: c.set(
        "constant/darcyProperties", "solidPhase/fluidForce/type", "stokes"))
    assert "Unknown fluid force type stokes" in log and "darcyProperties" in log
    assert all(name in log.split("Valid fluid force types")[1] for name in VALID)


def test_drag_law_is_refused_by_the_darcy_solver():
    """A drag law needs the fluid velocity of a solver with fluid momentum
    (nsDemFoam): darcyDemFoam stops naming the entry and its own models."""
    log = failing_column("force_drag_law", lambda c: c.set(
        "constant/darcyProperties", "solidPhase/fluidForce/type", "ErgunWenYu"))
    assert "Entry 'type'" in log and "darcyProperties" in log and "ErgunWenYu" in log
    assert "is a drag law" in log and "nsDemFoam" in log
    assert all(name in log.split("a Darcy solver takes one of")[1] for name in VALID)

"""Fluid force on a grain (Damsgaard et al. 2015, eq. 12): f = -V grad(p) -
rho_f V g, with grad(p) interpolated to the grain by the deposit's weights.
A single fixed grain in a saturated column: with p = 0 it feels exactly the
buoyancy -rho_f V g; in a steady linear pressure field (p fixed at top and
base) it feels -V grad(p) - rho_f V g."""

import numpy as np
import pytest

from darcydem.case import Case
from darcydem.foamfiles import read_vtp

RHO_F, G, R = 1000.0, 9.81, 0.01
V = 4 / 3 * np.pi * R**3
H = 0.4


def held_grain(name, p_base):
    c = Case("grainColumn", name)
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
    return read_vtp(c.file("VTK/grains_0.002.vtp"))["fluidForce"][0]


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

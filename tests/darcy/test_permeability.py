"""Permeability models (Damsgaard et al. 2015, eqs 10-11) as the solver
writes them: k = kc phi^3/(1 - phi)^2 with the case's porosity clamp and cap."""

import numpy as np
import pytest

from darcydem.case import Case


def written_k(name, porosity, model):
    c = Case("darcyColumn", name)
    c.set("system/controlDict", "endTime", 1e-4)
    c.set("system/controlDict", "writeInterval", 1)
    c.set("0/porosity", "internalField", "uniform %g" % porosity)
    c.set("constant/darcyProperties", "permeability", model)
    c.run("blockMesh")
    c.run("darcyDemFoam")
    return c.field("0.0001", "k")


def kc_law(kc, phi):
    return kc * phi**3 / (1 - phi) ** 2


@pytest.mark.parametrize("phi,phi_used", [(0.35, 0.35), (0.95, 0.9), (0.05, 0.1)])
def test_kozeny_carman_with_clamp(phi, phi_used):
    k = written_k(f"kc_{phi}", phi, "{ type kozenyCarman; kc 3.5e-13; "
                  "porosityMin 0.1; porosityMax 0.9; }")
    assert np.allclose(k, kc_law(3.5e-13, phi_used), rtol=1e-10)


def test_kozeny_carman_cap():
    k = written_k("kc_cap", 0.35, "{ type kozenyCarman; kc 3.5e-13; "
                  "porosityMin 0.1; porosityMax 0.9; kMax 1e-14; }")
    assert np.allclose(k, 1e-14, rtol=1e-12)


def test_kozeny_carman_from_grain_size():
    d = 0.02
    k = written_k("kc_d", 0.35, "{ type kozenyCarmanGrainSize; d %g; "
                  "porosityMin 0.1; porosityMax 0.9; }" % d)
    assert np.allclose(k, kc_law(d**2 / 180, 0.35), rtol=1e-10)


def test_constant():
    k = written_k("k_const", 0.35, "{ type constant; k 2e-12; }")
    assert np.allclose(k, 2e-12, rtol=1e-12)

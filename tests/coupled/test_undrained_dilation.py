"""Closed box, grains dilated by an imposed uniform expansion (doc/REFERENCES.md
D4 with grains): with no flow between cells each cell is undrained and
    p - p0 = -(1/beta) [ln(phi/(1 - phi))] from phi0 to phi,
so dilation lowers p. The expansion is imposed kinematically: grains on a
regular lattice, no gravity, no contacts, so heavy that the fluid force does
not deflect them, move with v_z = rate (z - zc); in the cells inside the
lattice the solid fraction falls as (1 - phi0)/(1 + rate t).

Checked in the cells whose neighbours also lie inside the lattice (so that
grad(porosity) vanishes there): the deposited porosity follows the affine
expansion to 1e-3 (the lattice drifts off the cell spacing, a small aliasing
of the trilinear deposit), and p follows D4 for the deposited porosity to
0.5 %. Measured: 2.5e-8 relative; against the affine porosity the error is
0.5 % per 0.5 % of strain, all of it the deposit's aliasing."""

import numpy as np
import pytest

from darcydem.analytic import undrained_pressure_change
from darcydem.case import Case
from darcydem.lattices import expanding_lattice

BETA = 1e-8
DZ = 0.02            # cubic cells
ZC = 0.12            # centre of the expansion


@pytest.mark.parametrize("rate", [0.2, -0.2])
def test_undrained_dilation_with_grains(rate):
    c = Case("closedBox", f"closed_box_{rate:+g}")
    with open(c.file("0/grains"), "w") as f:
        f.write("# x y z r vx vy vz\n")
        for row in expanding_lattice(rate, ZC):
            f.write(" ".join("%.12g" % v for v in row) + "\n")
    c.set("system/controlDict", "endTime", 0.05)
    c.set("system/controlDict", "writeInterval", 125)
    c.run("blockMesh")
    C = c.cell_centres()
    c.run("darcyDemFoam")

    # cells whose neighbours' trilinear neighbourhoods stay inside the lattice
    interior = (C[:, 2] > 0.10) & (C[:, 2] < 0.14)
    solid0 = 8 * 4 / 3 * np.pi * 0.004**3 / DZ**3
    worst = 0.0
    for t, name in c.times():
        p = c.field(name, "p")[interior]
        phi = c.field(name, "porosity")[interior]
        phi_affine = 1 - solid0 / (1 + rate * t)
        ex = undrained_pressure_change(1 - solid0, phi, BETA)
        err = np.max(np.abs(p - ex) / np.abs(ex))
        phi_err = np.max(np.abs(phi - phi_affine))
        print(f"rate {rate:+g} t={t}: p = {p.mean():.6e} (D4 {ex.mean():.6e}), rel. error "
              f"{err:.1e}; porosity {phi.mean():.6f}, affine {phi_affine:.6f}")
        worst = max(worst, err)
        assert np.sign(p.mean()) == -np.sign(rate)   # dilation lowers p
        assert phi_err < 1e-3
    print(f"worst relative error {worst:.2e}")
    assert worst < 0.005

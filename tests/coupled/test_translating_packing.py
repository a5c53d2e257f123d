"""A rigidly translating non-uniform packing leaves p ~ 0 (issue 14: the
Darcy solver's defects).

Every grain moves with the same velocity v, so the solid fraction is carried
unchanged: d(phi)/dt + v . grad(phi) = 0, the forcing of the pressure
equation vanishes and p stays 0, however non-uniform the packing. Neither
term vanishes alone: dropping the advection term Us . grad(phi) leaves each
undrained cell with D4 of its own porosity change, p - p0 = -(1/beta)
Delta ln(phi/(1 - phi)).

Case: tests/cases/closedBox with 16 x 2 x 12 cells (dx = 0.0025 m across the
periodic 0.04 m width), k = 1e-30 m^2 (each cell undrained, so nothing hides
an error by diffusing it away). Heavy grains (contact stiffness 1 N/m, so
their overlaps push them by < 1e-9 m) fill the box on a lattice of spacing
h = dx/2 in x and dz/2 in y and z (the trilinear deposit of a uniform
lattice of such spacing is exactly uniform at any shift, and mirrored at the
closed base and top); their volumes vary as 1 + a cos(kappa x), kappa =
2 pi/0.04 m, one Fourier mode of the periodic width, so the packing has no
edges. All move along x at v = 0.2 m/s for 0.1 s (half the width).

Discretisation: the deposited porosity is the profile F(x - v t) of the
lattice; the time derivative (eq. 9, central over v 2 dt = 8e-5 m) follows
F' and the gradient (Gauss linear, central over 2 dx) sees F' times
sin(kappa dx)/(kappa dx) = 1 - (kappa dx)^2/6, so the forcing keeps
v F' (kappa dx)^2/6 = 0.026 of v F' (the time part is 1e-5 of it). Between
grain nodes the deposit is piecewise linear (nodes h apart), so the rate
follows its segment slopes, off F' by up to kappa h/2 ~ 0.1 of it, but that
part alternates in sign from one segment to the next and sums to the
secant's (kappa h)^2/24 = 1.6e-3 over each segment crossed. Tolerance on
max |p| over max |p without the advection term|: 2 (kappa dx)^2/6 = 0.051.
Measured: 0.0252 (estimate 0.0257); without the advection term the ratio
would be 1."""

import numpy as np

from darcydem.analytic import undrained_pressure_change
from darcydem.case import Case

BETA = 1e-8
WIDTH = 0.04        # periodic x and y
NX = 16             # cells across x
DX = WIDTH / NX
HEIGHT = 0.24
V = 0.2             # velocity of every grain, along x [m/s]
DURATION = 0.1
DT = 2e-4
SOLID = 0.3         # mean solid fraction
AMPLITUDE = 0.5     # relative modulation of the grain volume


def packing():
    """Lattice of spacing DX/2 in x and 0.01 m (half the 0.02 m cells) in y and z,
    8 grains per cell, grain volume SOLID V_cell/8 (1 + a cos(kappa x))."""
    hx, hyz = DX / 2, 0.01
    cell = DX * 0.02 * 0.02
    rows = []
    for k in range(round(HEIGHT / hyz)):
        for j in range(round(WIDTH / hyz)):
            for i in range(round(WIDTH / hx)):
                x = (i + 0.5) * hx
                volume = SOLID * cell / 8 * (1 + AMPLITUDE * np.cos(2 * np.pi * x / WIDTH))
                r = (3 * volume / (4 * np.pi)) ** (1 / 3)
                rows.append((x, (j + 0.5) * hyz, (k + 0.5) * hyz, r, V, 0.0, 0.0))
    return rows


def test_translating_packing_keeps_p_zero():
    c = Case("closedBox", "translating_packing")
    with open(c.file("0/grains"), "w") as f:
        for row in packing():
            f.write(" ".join("%.17g" % v for v in row) + "\n")
    mesh = open(c.file("system/blockMeshDict")).read()
    assert "($n $n $nz)" in mesh
    open(c.file("system/blockMeshDict"), "w").write(mesh.replace("($n $n $nz)", f"({NX} $n $nz)"))
    for entry in ("normalStiffness", "tangentialStiffness"):
        c.set("constant/demProperties", f"contact/{entry}", 1)
    c.set("constant/demProperties", "contact/normalDamping", 0)
    # the lattice overlaps on purpose (soft, heavy grains: a moving solid
    # fraction, not a packing), so the start-state check is opened
    c.set("constant/demProperties", "maxInitialOverlap", 10)
    c.set("constant/demProperties", "timeStep", DT)
    c.set("system/controlDict", "deltaT", DT)
    c.set("system/controlDict", "endTime", DURATION)
    c.set("system/controlDict", "writeInterval", round(DURATION / DT / 4))
    c.run("blockMesh")
    c.run("darcyDemFoam")

    worst_p = worst_dropped = 0.0
    phi_start = None
    for t, name in c.times():
        p = c.field(name, "p")
        phi = c.field(name, "porosity")
        if phi_start is None:
            # without the advection term: D4 from the first written porosity on
            phi_start = phi
            continue
        dropped = undrained_pressure_change(phi_start, phi, BETA)
        worst_p = max(worst_p, np.max(np.abs(p)))
        worst_dropped = max(worst_dropped, np.max(np.abs(dropped)))
        print(f"t = {t}: max |p| {np.max(np.abs(p)):.4e} Pa; without the advection term "
              f"{np.max(np.abs(dropped)):.4e} Pa")
    kappa = 2 * np.pi / WIDTH
    estimate = (kappa * DX) ** 2 / 6
    ratio = worst_p / worst_dropped
    print(f"max |p| / max |p without advection| = {ratio:.4f} "
          f"(truncation estimate (kappa dx)^2/6 = {estimate:.4f})")
    assert worst_dropped > 1e4           # the terms are large: the cancellation is real
    assert ratio < 2 * estimate

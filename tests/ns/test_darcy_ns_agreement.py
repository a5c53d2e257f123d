"""The Darcy and the Navier-Stokes solver on one packing (issue 26 item 2):
the frozen lattice of tests/cases/fixedBed filling a whole column, the same
pressure drop imposed at Re_p << 1, solved by darcyDemFoam (Kozeny-Carman
permeability) and by nsDemFoam (ErgunWenYu), give the same superficial flux
once the two are made consistent: the viscous limit of Ergun's equation,
-dp/dz = 150 mu (1 - phi)^2 U_s/(phi^3 d^2), is Darcy's law with
k = phi^3 d^2/(150 (1 - phi)^2), i.e. kozenyCarman with kc = d^2/150
(Carman's 180 is the grainSize model's; doc/EQUATIONS.md section 11).

Both solvers see the same deposited porosity (the same grains, the same
deposit, which mirrors at the column's closed ends: the lattice's porosity
in every layer, asserted), so they solve the same uniform 1-D resistance;
what separates them is Ergun's inertial term, which Darcy's law lacks:
1.75 Re_p/(150 (1 - phi)) = 2.2e-4 of the viscous one at Re_p = 0.01.
Tolerance 2 % (the issue's)."""

import math

import numpy as np

from darcydem import drag
from darcydem.case import Case

D = 1e-3
SPACING = 1.0001 * D
PER_CELL = 3
H_CELL = PER_CELL * SPACING
N_LAT, NZ = 2, 12
RHO, MU = 1000.0, 1e-3
EPS = 1 - math.pi / 6 * (D / SPACING)**3
RE = 0.01
U_S = RE * MU / (RHO * D)
# The pressure drop Ergun's equation gives that flux in the column
DP = drag.ergun(EPS, U_S, RHO, MU, D) * NZ * H_CELL
KC = D * D / 150


def column(name):
    c = Case("fixedBed", name)
    c.set_variable("system/blockMeshDict", "L", "%.17g" % (N_LAT * H_CELL))
    c.set_variable("system/blockMeshDict", "H", "%.17g" % (NZ * H_CELL))
    c.set_variable("system/blockMeshDict", "n", N_LAT)
    c.set_variable("system/blockMeshDict", "nz", NZ)
    n = N_LAT * PER_CELL
    with open(c.file("0/grains"), "w") as f:
        f.write("# the lattice of tests/cases/fixedBed filling the column\n")
        for k in range(NZ * PER_CELL):
            for j in range(n):
                for i in range(n):
                    f.write("%r %r %r %r\n" % ((i + 0.5) * SPACING, (j + 0.5) * SPACING,
                                               (k + 0.5) * SPACING, D / 2))
    c.set("0/p", "boundaryField/inlet", "{ type fixedValue; value uniform %.17g; }" % DP)
    return c


def darcy_flux():
    c = column("agree_darcy")
    with open(c.file("constant/darcyProperties"), "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class dictionary;"
                " object darcyProperties; }\n"
                "mu [1 -1 -1 0 0 0 0] %r;\nbeta [-1 1 2 0 0 0 0] 4.5e-10;\n"
                "rho [1 -3 0 0 0 0 0] %r;\n"
                "permeability { type kozenyCarman; kc %r; porosityMin 0.2;"
                " porosityMax 0.9999999; }\n"
                "solidPhase { type demGrains; porosityMin 0.2; porosityMax 0.9999999;"
                " topPressure 0; fluidForce { type none; } }\n" % (MU, RHO, KC))
    c.set("system/controlDict", "endTime", 0.01)
    c.set("system/controlDict", "writeInterval", 5)
    c.run("blockMesh")
    c.run("darcyDemFoam")
    last = c.times()[-1][1]
    return c.field(last, "qDarcy")[:, 2], c.field(last, "porosity")


def ns_flux():
    c = column("agree_ns")
    c.set("0/U", "boundaryField/inlet", "{ type pressureInletOutletVelocity;"
          " value uniform (0 0 0); }")
    c.set("system/controlDict", "endTime", 1.0)
    c.set("system/controlDict", "writeInterval", 250)
    c.run("blockMesh")
    c.run("nsDemFoam")
    (_, prev), (_, last) = c.times()[-2:]
    eps = c.field(last, "porosity")
    q = eps * c.field(last, "U")[:, 2]
    q_prev = c.field(prev, "porosity") * c.field(prev, "U")[:, 2]
    return q, q_prev, eps


def test_darcy_and_navier_stokes_give_the_same_flux():
    q_darcy, eps_darcy = darcy_flux()
    q_ns, q_ns_prev, eps_ns = ns_flux()
    # One packing, one deposit: the same bits on the CPU; on CUDA the deposit adds
    # with atomics in no fixed order, so the two runs agree to round-off only.
    assert np.max(np.abs(eps_darcy - eps_ns)) < 1e-12
    print(f"porosity {eps_ns.min():.12f}-{eps_ns.max():.12f} (lattice {EPS:.12f})")
    assert np.max(np.abs(eps_ns - EPS)) < 1e-12
    d, n = q_darcy.mean(), q_ns.mean()
    print(f"pressure drop {DP:.6g} Pa over {NZ * H_CELL:.6g} m; superficial flux: Darcy "
          f"{d:.8g} m/s (spread {np.ptp(q_darcy) / d:.1e}), Navier-Stokes {n:.8g} m/s "
          f"(spread {np.ptp(q_ns) / n:.1e}, change over the last writes "
          f"{abs(n / q_ns_prev.mean() - 1):.1e}); Ergun in the uniform bed {U_S:.8g}; "
          f"Navier-Stokes/Darcy {n / d:.6f}")
    assert abs(n / q_ns_prev.mean() - 1) < 1e-4  # steady
    assert abs(n / d - 1) < 0.02

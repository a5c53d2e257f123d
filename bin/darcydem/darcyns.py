"""One packing, two fluid solvers (tutorials/nsDemFoam/darcyAndNavierStokes,
issue 26 item 2): the frozen lattice of the fixed-bed tutorial filling a
whole column, a pressure drop imposed between the inlet (z min) and the
outlet (z max), solved by darcyDemFoam (Kozeny-Carman with kc = d^2/150: the
permeability of Ergun's viscous term, doc/EQUATIONS.md section 11) and by
nsDemFoam (ErgunWenYu) at particle Reynolds numbers Re_p = rho U_s d/mu from
0.01 to 10. Darcy's flux is linear in the pressure drop; the Navier-Stokes
flux follows Ergun's equation, whose inertial term 1.75 rho (1 - phi) U_s^2/
(phi^3 d) parts the two as Re_p grows (the flux ratio is the root of
Ergun's quadratic over its viscous part).

The pressure drop of each run is the one Darcy's law needs for the wanted
Re_p: dp = mu U_s L/k. The deposit mirrors at the column's closed ends, so
the porosity is the lattice's 1 - (pi/6)(d/a)^3 in every cell and both
solvers solve a uniform 1-D resistance; the measured superficial flux is the
mean of qDarcy (Darcy) and of porosity x U_z (Navier-Stokes) over the cells.

Every run is a case under <study>/stages/{darcy,ns}_Re<Re>, made from the
template case in <study>; results.json and darcyAndNavierStokes.png are
written into <study>.
"""

import argparse
import json
import math
import os
import time

import numpy as np

from darcydem.case import Case
from darcydem.cli import StageClock, parse_study_args, require_folder, say

D = 1e-3
SPACING = 1.0001 * D
PER_CELL = 3
H_CELL = PER_CELL * SPACING
N_LAT, NZ = 2, 12
LENGTH = NZ * H_CELL
RHO, MU = 1000.0, 1e-3
EPS = 1 - math.pi / 6 * (D / SPACING)**3
K = EPS**3 * D * D / (150 * (1 - EPS)**2)     # Ergun's viscous term as a permeability
REYNOLDS = (0.01, 0.03, 0.1, 0.3, 1.0, 3.0, 10.0)
DT, STEPS, WRITES, MAX_EXTENSIONS = 2e-3, 500, 4, 8
STEADY = 1e-4
TEMPLATE_FILES = ("0/U", "0/p", "constant/nsDemProperties", "constant/darcyProperties",
                  "constant/demProperties", "system/blockMeshDict", "system/controlDict",
                  "system/fvSchemes", "system/fvSolution")


def ergun_flux(dp_over_length):
    """U_s of Ergun's equation at the pressure gradient dp/L: the positive
    root of a U^2 + b U = dp/L."""
    a = 1.75 * RHO * (1 - EPS) / (EPS**3 * D)
    b = 150 * MU * (1 - EPS)**2 / (EPS**3 * D * D)
    return (-b + math.sqrt(b * b + 4 * a * dp_over_length)) / (2 * a)


class Study:
    def __init__(self, study_dir, reynolds=REYNOLDS, log=say):
        self.clock = StageClock("darcyNsStudy", log, relay_interval=30.0)
        self.dir = os.path.abspath(study_dir)
        self.stages = os.path.join(self.dir, "stages")
        os.makedirs(self.stages, exist_ok=True)
        self.reynolds = reynolds
        self.runs = []

    def case(self, name, dp):
        c = Case(os.path.basename(self.dir), name, template_root=os.path.dirname(self.dir),
                 run_root=self.stages)
        c.set_variable("system/blockMeshDict", "L", "%.17g" % (N_LAT * H_CELL))
        c.set_variable("system/blockMeshDict", "H", "%.17g" % LENGTH)
        c.set_variable("system/blockMeshDict", "n", N_LAT)
        c.set_variable("system/blockMeshDict", "nz", NZ)
        c.set("0/p", "boundaryField/inlet/value", "uniform %.17g" % dp)
        c.set("system/controlDict", "deltaT", DT)
        c.set("constant/demProperties", "timeStep", DT)
        n = N_LAT * PER_CELL
        with open(c.file("0/grains"), "w") as f:
            f.write(f"# simple cubic lattice filling the column, d = {D!r} m, "
                    f"spacing {SPACING!r} m\n")
            for k in range(NZ * PER_CELL):
                for j in range(n):
                    for i in range(n):
                        f.write("%r %r %r %r\n" % ((i + 0.5) * SPACING, (j + 0.5) * SPACING,
                                                   (k + 0.5) * SPACING, D / 2))
        c.run("blockMesh")
        return c

    def darcy(self, re, dp):
        name = f"darcy_Re{re:g}"
        c = self.case(name, dp)
        c.set("system/controlDict", "endTime", 10 * DT)
        c.set("system/controlDict", "writeInterval", 5)
        wall = self.clock.run(c, "darcyDemFoam", name, f"Darcy, pressure drop {dp:.4g} Pa",
                              10 * DT)
        last = c.times()[-1][1]
        q = c.field(last, "qDarcy")[:, 2]
        return float(q.mean()), float(np.ptp(q) / q.mean()), \
            float(c.field(last, "porosity").mean()), wall

    def ns(self, re, dp):
        name = f"ns_Re{re:g}"
        c = self.case(name, dp)
        c.set("system/controlDict", "writeInterval", STEPS // WRITES)
        wall, end = 0.0, STEPS * DT
        for extension in range(MAX_EXTENSIONS + 1):
            c.set("system/controlDict", "endTime", "%.10g" % end)
            wall += self.clock.run(c, "nsDemFoam", name,
                                   f"Navier-Stokes, pressure drop {dp:.4g} Pa"
                                   + (" (not steady, continued)" if extension else ""), end)
            (_, prev), (_, last) = c.times()[-2:]

            def flux(t):
                return c.field(t, "porosity") * c.field(t, "U")[:, 2]
            q, q_prev = flux(last), flux(prev)
            change = abs(q.mean() / q_prev.mean() - 1)
            if change < STEADY:
                break
            end += STEPS * DT
        return float(q.mean()), float(np.ptp(q) / q.mean()), change, wall

    def run(self):
        start = time.monotonic()
        for re in self.reynolds:
            u_darcy = re * MU / (RHO * D)
            dp = MU * u_darcy * LENGTH / K
            qd, spread_d, eps, wall_d = self.darcy(re, dp)
            qn, spread_n, change, wall_n = self.ns(re, dp)
            ergun = ergun_flux(dp / LENGTH)
            r = {"Re_p": re, "pressureDrop": dp, "darcy": qd, "navierStokes": qn,
                 "ergun": ergun, "darcyLaw": u_darcy, "porosity": eps,
                 "navierStokesOverDarcy": qn / qd, "ergunOverDarcyLaw": ergun / u_darcy,
                 "navierStokesOverErgun": qn / ergun, "darcyOverDarcyLaw": qd / u_darcy,
                 "spreadDarcy": spread_d, "spreadNavierStokes": spread_n,
                 "steadyChange": change, "wall_s": wall_d + wall_n}
            self.runs.append(r)
            say(f"darcyNsStudy: Re_p {re:g}: pressure drop {dp:.6g} Pa, flux Darcy {qd:.8g}, "
                f"Navier-Stokes {qn:.8g} m/s, ratio {qn / qd:.6f} (Ergun's {ergun / u_darcy:.6f})")
        self.results = {"setup": {"d": D, "latticeSpacing": SPACING, "cell": H_CELL,
                                  "mesh": [N_LAT, N_LAT, NZ], "length": LENGTH, "rho": RHO,
                                  "mu": MU, "porosityLattice": EPS, "permeability": K,
                                  "kc": D * D / 150, "deltaT": DT},
                        "runs": self.runs, "wall_s": time.monotonic() - start}
        with open(os.path.join(self.dir, "results.json"), "w") as f:
            json.dump(self.results, f, indent=2)
        return self.results

    def table(self):
        lines = ["Re_p    dp [Pa]       Darcy [m/s]   N-S [m/s]     N-S/Darcy  Ergun/Darcy  "
                 "N-S/Ergun"]
        for r in self.runs:
            lines.append(f"{r['Re_p']:<7g} {r['pressureDrop']:<13.6g} {r['darcy']:<13.8g} "
                         f"{r['navierStokes']:<13.8g} {r['navierStokesOverDarcy']:.6f}   "
                         f"{r['ergunOverDarcyLaw']:.6f}     {r['navierStokesOverErgun']:.6f}")
        return "\n".join(lines)

    def plot(self):
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, (a1, a2) = plt.subplots(1, 2, figsize=(12, 4.8))
        dp = np.array([r["pressureDrop"] for r in self.runs])
        line = np.logspace(np.log10(dp.min()) - 0.2, np.log10(dp.max()) + 0.2, 200)
        a1.plot(line, K * line / (MU * LENGTH), "k-", lw=1,
                label="Darcy's law, k = phi^3 d^2/(150 (1-phi)^2)")
        a1.plot(line, [ergun_flux(x / LENGTH) for x in line], "k--", lw=1,
                label="Ergun (1952)")
        a1.plot(dp, [r["darcy"] for r in self.runs], "s", mfc="none", ms=9,
                label="darcyDemFoam (kozenyCarman, kc = d^2/150)")
        a1.plot(dp, [r["navierStokes"] for r in self.runs], "o", ms=5,
                label="nsDemFoam (ErgunWenYu)")
        a1.set_xscale("log")
        a1.set_yscale("log")
        a1.set_xlabel("pressure drop over the column [Pa]")
        a1.set_ylabel("superficial flux U_s [m/s]")
        a1.set_title(f"One packing (porosity {EPS:.4f}), two solvers", fontsize=10)
        a1.legend(fontsize=8)
        a1.grid(True, which="both", alpha=0.3)
        re = np.array([r["Re_p"] for r in self.runs])
        re_line = np.logspace(np.log10(re.min()) - 0.2, np.log10(re.max()) + 0.2, 200)
        a2.plot(re_line, [ergun_flux(MU * (x * MU / (RHO * D)) / K) / (x * MU / (RHO * D))
                          for x in re_line], "k--", lw=1, label="Ergun / Darcy's law")
        a2.plot(re, [r["navierStokesOverDarcy"] for r in self.runs], "o",
                label="nsDemFoam / darcyDemFoam")
        a2.axhspan(0.98, 1.02, color="0.9", label="±2 %")
        a2.set_xscale("log")
        a2.set_xlabel("Re_p = rho U_s d / mu of the Darcy flux")
        a2.set_ylabel("flux ratio")
        a2.set_title("Where they part: Ergun's inertial term", fontsize=10)
        a2.legend(fontsize=8)
        a2.grid(True, which="both", alpha=0.3)
        fig.tight_layout()
        out = os.path.join(self.dir, "darcyAndNavierStokes.png")
        fig.savefig(out, dpi=120)
        plt.close(fig)
        return out


def main(argv):
    ap = argparse.ArgumentParser(
        prog="darcyNsStudy",
        description="One frozen packing, darcyDemFoam and nsDemFoam at the same pressure "
                    "drops (bin/darcydem/darcyns.py); writes results.json and "
                    "darcyAndNavierStokes.png into STUDY_DIR and each run's case under "
                    "STUDY_DIR/stages.")
    ap.add_argument("study_dir", metavar="STUDY_DIR",
                    help="the template case, e.g. tutorials/nsDemFoam/darcyAndNavierStokes")
    ap.add_argument("--reynolds", nargs="+", type=float, default=list(REYNOLDS),
                    help="Re_p of the Darcy flux (default: %(default)s)")
    a = parse_study_args(ap, argv)
    require_folder("darcyNsStudy", a.study_dir, TEMPLATE_FILES)
    study = Study(a.study_dir, reynolds=a.reynolds)
    results = study.run()
    out = study.plot()
    say(study.table())
    say(f"darcyNsStudy: study {results['wall_s']:.0f} s (wall); wrote {out} and "
        f"{os.path.join(study.dir, 'results.json')}; the runs' cases in {study.stages}")

"""Flow through a fixed bed with nsDemFoam (tutorials/nsDemFoam/fixedBed):
steady flow up through a frozen simple-cubic lattice of equal spheres in a
periodic column, for each drag law (ErgunWenYu, DiFelice, Beetstra) and
particle Reynolds numbers Re_p = rho U_s d/mu from 0.1 to 100 (the inlet's
superficial velocity U_s varied, mu fixed). Measured in each run: the
pressure gradient in the bed's interior (a line fitted through the layer
means of p) and the bed's porosity (the deposited porosity of the same
layers); compared with the law's closed form at that porosity
(bin/darcydem/drag.py pressure_gradient) and with Ergun's equation.

The bed (as tests/ns/test_fixed_bed.py, where the reasons are spelt out):
spheres of d = 1 mm on a simple cubic lattice of spacing a = 1.0001 d (no
two touch), 6 x 6 per layer in a column of 2 x 2 cells with cyclic sides,
60 layers = 20 cell layers of h = 3 a, with 3 empty cell layers below
(inlet, fixed U) and 3 above (outlet, p = 0). The trilinear deposit of a
lattice of spacing h/3 is exactly the lattice's porosity 1 - (pi/6)(d/a)^3
= 0.476558 in every cell with whole lattice neighbourhoods. Near the bed's
ends the porosity changes over about two cells and the interpolation of
grad p to the grains and the deposit of their reaction smooth it: grad p
reaches its uniform value only a few cells inside (6 % low one cell in,
0.01 % five cells in), so the fit takes the 8 layers at least EDGE = 6
cells from the bed's ends.

Steady state: each run goes 1000 fluid steps of 2e-3 s (2 s, written every
0.5 s) and is continued by 1 s at a time until the fitted gradient changes
by less than 1e-4 relative between its last two write times.

Also reported per run: the momentum balance of the column, (p_in - p_out) A
against the grains' fluid force less their buoyancy (0.06-0.2 %: the
solver's momentum equations hold face by face, and cell by cell only to the
discretisation error where the porosity steps, doc/EQUATIONS.md section 11).

Every run is a case under <study>/stages/<law>_Re<Re>, made from the
template case in <study> (0/, constant/, system/); results.json and
fixedBed.png are written into <study>.
"""

import argparse
import json
import math
import os
import shutil
import subprocess
import time

import numpy as np

from darcydem import drag
from darcydem.case import Case
from darcydem.cli import StageClock, parse_study_args, require_folder, say
from darcydem.foamfiles import read_vtp

D = 1e-3                  # sphere diameter [m]
SPACING = 1.0001 * D      # lattice spacing a
PER_CELL = 3              # lattice sites per cell width: h = 3 a
H_CELL = PER_CELL * SPACING
N_LAT = 2                 # cells across (cyclic)
N_BELOW, N_BED, N_ABOVE = 3, 20, 3
NZ = N_BELOW + N_BED + N_ABOVE
EDGE = 6                  # cells between the bed's edge and the fitted layers
RHO, MU, G = 1000.0, 1e-3, 9.81
DT = 2e-3                 # fluid (and DEM) step [s]
STEPS, WRITES = 1000, 4   # first stretch of a run, and its writes
EXTEND = 500              # steps added while not steady
MAX_EXTENSIONS = 6
STEADY = 1e-4             # relative change of the gradient between the last two writes

LAWS = drag.LAWS
REYNOLDS = (0.1, 0.3, 1.0, 3.0, 10.0, 30.0, 100.0)
PROFILE_RE = 1.0          # Re_p of the figure's p(z), porosity(z) panel

EPS_BED = 1 - math.pi / 6 * (D / SPACING)**3
AREA = (N_LAT * H_CELL)**2

TEMPLATE_FILES = ("system/controlDict", "system/blockMeshDict", "constant/demProperties",
                  "constant/nsDemProperties", "0/U", "0/p")


def lattice_rows():
    """'x y z r' of the bed: N_LAT * PER_CELL sites across, N_BED * PER_CELL
    layers from the top of the N_BELOW empty cell layers."""
    n_lat, n_z = N_LAT * PER_CELL, N_BED * PER_CELL
    z0 = N_BELOW * H_CELL
    return [((i + 0.5) * SPACING, (j + 0.5) * SPACING, z0 + (k + 0.5) * SPACING, D / 2)
            for k in range(n_z) for j in range(n_lat) for i in range(n_lat)]


def write_grains(path):
    with open(path, "w") as f:
        f.write(f"# fixedBed: simple cubic lattice, d = {D!r} m, spacing {SPACING!r} m, "
                f"{len(lattice_rows())} grains\n")
        for row in lattice_rows():
            f.write(" ".join(repr(v) for v in row) + "\n")


def layers(field):
    """A cell field (n,) as (nz, cells per layer): blockMesh numbers x
    fastest, then y, then z."""
    return np.asarray(field).reshape(NZ, N_LAT * N_LAT)


FITTED = np.arange(N_BELOW + EDGE, N_BELOW + N_BED - EDGE)


def fitted_gradient(case, time_name):
    """-dp/dz of a line through the layer means of p over the fitted
    layers, the layer means of p and porosity over the whole column, and
    the largest residual of the line in units of a cell's drop."""
    p = layers(case.field(time_name, "p")).mean(axis=1)
    eps = layers(case.field(time_name, "porosity")).mean(axis=1)
    z = (FITTED + 0.5) * H_CELL
    slope, intercept = np.polyfit(z, p[FITTED], 1)
    residual = np.max(np.abs(p[FITTED] - (slope * z + intercept))) / abs(slope * H_CELL)
    return -slope, p, eps, residual


def solver_version():
    """Which nsDemFoam made the numbers: the git commit of the project, the
    solver sources changed since it (the binary is built from the working
    tree), and the binary's modification time."""
    project = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

    def git(*args):
        try:
            return subprocess.run(["git", "-C", project, *args], capture_output=True,
                                  text=True, check=True).stdout.strip()
        except (OSError, subprocess.CalledProcessError):
            return ""
    binary = shutil.which("nsDemFoam")
    return {"commit": git("rev-parse", "HEAD"),
            "uncommittedSources": git("status", "--porcelain", "--", "src",
                                      "applications").splitlines(),
            "binary": binary,
            "binaryModified": time.strftime("%Y-%m-%d %H:%M:%S UTC",
                                            time.gmtime(os.path.getmtime(binary)))
            if binary else None}


class Study:
    def __init__(self, study_dir, laws=LAWS, reynolds=REYNOLDS, log=say):
        self.clock = StageClock("fixedBedStudy", log, relay_interval=30.0)
        self.dir = os.path.abspath(study_dir)
        self.stages = os.path.join(self.dir, "stages")
        self.template_root = os.path.dirname(self.dir)
        self.template = os.path.basename(self.dir)
        os.makedirs(self.stages, exist_ok=True)
        self.laws, self.reynolds = laws, reynolds
        self.runs = []
        self.profile = None

    def run_one(self, law, re):
        u_s = re * MU / (RHO * D)
        name = f"{law}_Re{re:g}"
        c = Case(self.template, name, template_root=self.template_root,
                 run_root=self.stages)
        c.set_variable("system/blockMeshDict", "L", "%.17g" % (N_LAT * H_CELL))
        c.set_variable("system/blockMeshDict", "H", "%.17g" % (NZ * H_CELL))
        c.set_variable("system/blockMeshDict", "n", N_LAT)
        c.set_variable("system/blockMeshDict", "nz", NZ)
        c.set("constant/nsDemProperties", "mu", "[1 -1 -1 0 0 0 0] %.17g" % MU)
        c.set("constant/nsDemProperties", "rho", "[1 -3 0 0 0 0 0] %.17g" % RHO)
        c.set("constant/nsDemProperties", "grains/fluidForce/type", law)
        c.set("0/U", "boundaryField/inlet/value", "uniform (0 0 %.17g)" % u_s)
        c.set("system/controlDict", "deltaT", DT)
        c.set("constant/demProperties", "timeStep", DT)
        c.set("system/controlDict", "writeInterval", STEPS // WRITES)
        write_grains(c.file("0/grains"))
        c.run("blockMesh")
        wall, end = 0.0, STEPS * DT
        for extension in range(MAX_EXTENSIONS + 1):
            c.set("system/controlDict", "endTime", "%.10g" % end)
            what = (f"{law}, Re_p {re:g}, U_s {u_s:.4g} m/s" if extension == 0
                    else f"{law}, Re_p {re:g}: not steady, continued")
            wall += self.clock.run(c, "nsDemFoam", name, what, end)
            (_, prev), (_, last) = c.times()[-2:]
            grad, p, eps, residual = fitted_gradient(c, last)
            change = abs(grad / fitted_gradient(c, prev)[0] - 1)
            if change < STEADY:
                break
            end += EXTEND * DT
        steady = bool(change < STEADY)

        eps_bed = float(eps[FITTED].mean())
        v = read_vtp(c.file(f"postProcessing/grains/grains_{last}.vtp"))
        force = float(np.sum(v["fluidForce"][:, 2] - RHO * v["volume"] * G))
        p_in = float(p[0])
        closed = drag.pressure_gradient(law, eps_bed, u_s, RHO, MU, D)
        ergun = drag.ergun(eps_bed, u_s, RHO, MU, D)
        r = {"law": law, "Re_p": re, "U_s": u_s, "mu": MU, "rho": RHO, "d": D,
             "porosity": eps_bed, "porosityLattice": EPS_BED,
             "porositySpread": float(np.ptp(eps[FITTED])),
             "dpdz": grad, "closedForm": closed, "ergun": ergun,
             "errorClosedForm": grad / closed - 1, "overErgun": grad / ergun,
             "closedFormOverErgun": closed / ergun,
             "steadyChange": change, "steady": steady, "endTime": float(last),
             "lineResidual": residual,
             "pressureDrop": p_in, "grainForceLessBuoyancy": force,
             "momentumBalance": force / (p_in * AREA) - 1,
             "wall_s": wall, "case": os.path.relpath(c.path, self.dir)}
        self.runs.append(r)
        say(f"fixedBedStudy: {law} Re_p {re:g}: -dp/dz {grad:.6g} Pa/m, closed form "
            f"{closed:.6g} ({r['errorClosedForm']:+.2e}), Ergun {ergun:.6g}, porosity "
            f"{eps_bed:.6f}, change {change:.1e}, momentum {r['momentumBalance']:+.1e}")
        if re == PROFILE_RE:
            zc = (np.arange(NZ) + 0.5) * H_CELL
            prof = self.profile or {"z": zc.tolist(), "bed": [N_BELOW * H_CELL,
                                                               (N_BELOW + N_BED) * H_CELL],
                                    "fitted": [float(FITTED[0] * H_CELL),
                                               float((FITTED[-1] + 1) * H_CELL)],
                                    "porosity": eps.tolist(), "p": {}, "closedForm": {}}
            prof["p"][law] = p.tolist()
            prof["closedForm"][law] = closed
            self.profile = prof
        return r

    def run(self):
        start = time.monotonic()
        for law in self.laws:
            for re in self.reynolds:
                self.run_one(law, re)
        self.results = {
            "setup": {"d": D, "latticeSpacing": SPACING, "cell": H_CELL,
                      "mesh": [N_LAT, N_LAT, NZ], "bedLayers": N_BED,
                      "grains": len(lattice_rows()),
                      "fittedLayers": [int(FITTED[0]), int(FITTED[-1])],
                      "rho": RHO, "mu": MU, "deltaT": DT,
                      "steadyCriterion": STEADY},
            "solver": solver_version(),
            "runs": self.runs,
            "profile": self.profile,
            "wall_s": time.monotonic() - start}
        with open(os.path.join(self.dir, "results.json"), "w") as f:
            json.dump(self.results, f, indent=2)
        return self.results

    def table(self):
        lines = ["law         Re_p   U_s [m/s]  porosity   -dp/dz [Pa/m]  closed form    "
                 "error      /Ergun  closed/Ergun  steady   momentum"]
        for r in self.runs:
            lines.append(f"{r['law']:<11} {r['Re_p']:<6g} {r['U_s']:<10.4g} "
                         f"{r['porosity']:.6f}  {r['dpdz']:<13.6g}  {r['closedForm']:<13.6g} "
                         f"{r['errorClosedForm']:+.2e}  {r['overErgun']:.4f}  "
                         f"{r['closedFormOverErgun']:.4f}        {r['steadyChange']:.0e}  "
                         f"{r['momentumBalance']:+.1e}")
        return "\n".join(lines)

    def plot(self):
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, (a1, a2) = plt.subplots(1, 2, figsize=(12, 4.8))
        colours = {"ErgunWenYu": "C0", "DiFelice": "C1", "Beetstra": "C2"}
        eps = float(np.mean([r["porosity"] for r in self.runs]))
        re_line = np.logspace(np.log10(min(self.reynolds)) - 0.2,
                              np.log10(max(self.reynolds)) + 0.2, 200)
        a1.axhline(1.0, color="k", lw=1.5, label="Ergun (1952)")
        for law in self.laws:
            u = re_line * MU / (RHO * D)
            ratio = [drag.pressure_gradient(law, eps, ui, RHO, MU, D)
                     / drag.ergun(eps, ui, RHO, MU, D) for ui in u]
            a1.plot(re_line, ratio, "-", color=colours[law], lw=1,
                    label=f"{law}, closed form")
            rs = [r for r in self.runs if r["law"] == law]
            a1.plot([r["Re_p"] for r in rs], [r["overErgun"] for r in rs], "o",
                    color=colours[law], mfc="none", ms=8, label=f"{law}, nsDemFoam")
        a1.set_xscale("log")
        a1.set_xlabel("Re_p = rho U_s d / mu")
        a1.set_ylabel("-dp/dz / Ergun")
        worst = max(abs(r["errorClosedForm"]) for r in self.runs)
        a1.set_title(f"Bed interior, porosity {eps:.4f}: largest error against "
                     f"the closed form {worst:.1e}", fontsize=10)
        a1.legend(fontsize=8)
        a1.grid(True, which="both", alpha=0.3)

        prof = self.profile
        if prof:
            z = np.array(prof["z"]) * 1e3
            for law, p in prof["p"].items():
                a2.plot(p, z, ".-", color=colours[law], label=f"p, {law}")
                # the closed form's slope through the fitted layers' mean
                k = FITTED
                zf = np.array(prof["z"])[k]
                p0 = np.mean(np.array(p)[k]) + prof["closedForm"][law] * np.mean(zf)
                zz = np.array(prof["bed"])
                a2.plot(p0 - prof["closedForm"][law] * zz, zz * 1e3, ":",
                        color=colours[law], lw=1)
            a2.axhspan(prof["fitted"][0] * 1e3, prof["fitted"][1] * 1e3, color="0.9",
                       label="fitted layers")
            for zb in prof["bed"]:
                a2.axhline(zb * 1e3, color="0.5", lw=0.8, ls="--")
            a2.set_xlabel("p (layer mean) [Pa]; dotted: closed-form slope")
            a2.set_ylabel("z [mm]")
            a2.legend(fontsize=8, loc="lower left")
            b = a2.twiny()
            b.plot(prof["porosity"], z, "k.-", lw=1, ms=4)
            b.set_xlabel("porosity (layer mean, black)")
            b.set_xlim(0.4, 1.02)
            a2.set_title(f"Re_p = {PROFILE_RE:g}: p(z) and porosity(z); dashed: bed's ends",
                         fontsize=10)
        fig.tight_layout()
        out = os.path.join(self.dir, "fixedBed.png")
        fig.savefig(out, dpi=120)
        plt.close(fig)
        return out


def main(argv):
    ap = argparse.ArgumentParser(
        prog="fixedBedStudy",
        description="Run the fixed-bed study of a tutorial directory "
                    "(bin/darcydem/fixedbed.py): nsDemFoam through a frozen lattice bed for "
                    "each drag law and Re_p; writes results.json and fixedBed.png there and "
                    "each run's case under STUDY_DIR/stages.")
    ap.add_argument("study_dir", metavar="STUDY_DIR",
                    help="the template case (0/, constant/, system/), e.g. "
                         "tutorials/nsDemFoam/fixedBed")
    ap.add_argument("--laws", nargs="+", default=list(LAWS), choices=LAWS,
                    help="drag laws (default: all three)")
    ap.add_argument("--reynolds", nargs="+", type=float, default=list(REYNOLDS),
                    help="Re_p = rho U_s d/mu (default: %(default)s)")
    a = parse_study_args(ap, argv)
    require_folder("fixedBedStudy", a.study_dir, TEMPLATE_FILES)
    study = Study(a.study_dir, laws=a.laws, reynolds=a.reynolds)
    results = study.run()
    out = study.plot()
    say(study.table())
    say(f"fixedBedStudy: all runs steady: {all(r['steady'] for r in study.runs)}; "
        f"study {results['wall_s']:.0f} s (wall)")
    say(f"fixedBedStudy: wrote {out} and {os.path.join(study.dir, 'results.json')}; "
        f"the runs' cases in {study.stages}")

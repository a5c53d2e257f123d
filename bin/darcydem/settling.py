"""One sphere settling with nsDemFoam (tutorials/nsDemFoam/settlingSphere):
a free sphere (d = 1 mm, rho_p = 2000 kg/m^3, in a fluid of rho_f = 1000,
g = 9.81) falls from rest in a box periodic in x and y and closed at the
bottom and the top; its terminal velocity against Schiller and Naumann's
(the ErgunWenYu law at porosity -> 1, bin/darcydem/drag.py) and Stokes's.

Two series:
  - Reynolds: cells of h = 20 d, the box 6 cells = 120 d across, terminal
    Reynolds numbers Re = rho_f w d/mu of 0.1, 1, 10 and 100, the viscosity
    chosen so that Schiller-Naumann's sphere settles at that Re
    (drag.viscosity_for_settling_reynolds);
  - cell size: Re = 1, h/d = 2, 5, 10 and 20, the box kept 60 d across
    (30, 12, 6 and 3 cells; at 120 d, 60 x 60 cells across at h = 2 d,
    that run alone would take about 25 minutes on 2 cores). The Re = 1,
    h = 20 d runs of the two series differ only in the box: what halving
    it costs.

Measured: the sphere's centre z at the write times (<time>/grains, four
writes per cell crossed); the times at which it crosses the cell-centre
planes (z(t) interpolated linearly between writes); the terminal velocity
as whole cells over the time to cross them, for the last stretch of the
fall (at least 2 cells and 10 d; before it at least 6 cells and 40 d of fall
from rest), and for the stretch before it (the
drift between the two says whether the sphere had reached its terminal
velocity). The force on an unresolved sphere depends on where it is in its
cell (the deposit of its reaction and the interpolation of the fluid
velocity use the same trilinear weights), so only whole cells give its
mean. The sphere starts at rest at a cell centre, laterally at a cell
centre (its reaction goes to one column of cells: the largest
self-interaction of any lateral position), two cells below the lid.

Why h = 20 d: the drag uses the fluid velocity at the sphere's centre,
interpolated from cells that hold the sphere's own reaction, so the fluid
there is dragged along with the sphere, the slip is smaller than the
sphere's velocity and the sphere settles too fast: in Stokes flow by about
d/h (the reaction 3 pi mu d w spread over cells of size h drives their
fluid at a fraction ~ d/h of w); at larger Re the disturbance is carried
away and the error falls. The periodic box is a lattice of spheres 120 d
apart: Hasimoto's Stokes-flow hindrance 1 - 1.76 c^(1/3) is 1.2 % there
(drag.hasimoto_factor), less at larger Re.

Every run is a case under <study>/stages/Re<Re>_h<h/d>d, made from the
template case in <study> (0/, constant/, system/); results.json and
settlingSphere.png are written into <study>.
"""

import argparse
import json
import math
import os
import time

import numpy as np

from darcydem import drag
from darcydem.case import Case
from darcydem.cli import StageClock, parse_study_args, require_folder, say
from darcydem.fixedbed import solver_version
from darcydem.foamfiles import read_grains

D = 1e-3
RHO_P, RHO_F, G = 2000.0, 1000.0, 9.81
LAW = "ErgunWenYu"
BOX = 120 * D             # the periodic box's width, Reynolds series
SIZE_BOX = 60 * D         # ... cell-size series
H_OVER_D = 20             # cell size of the Reynolds series
REYNOLDS = (0.1, 1.0, 10.0, 100.0)
SIZE_RE = 1.0             # Re of the cell-size series
SIZES = (2, 5, 10, 20)
STEPS_PER_CELL = 20       # fluid steps while the sphere crosses a cell (at most)
MAX_DT = 1e-2             # largest fluid step [s]
WRITES_PER_CELL = 4
TRANSIENT_CELLS = 6       # cells of fall before the measured stretches (at least)
TRANSIENT_D = 40          # ... and diameters
MEASURED_D = 10           # each measured stretch: whole cells, at least this many d
MARGIN_CELLS = 5          # cells kept between the sphere's lowest point and the bottom
MARGIN_D = 20             # ... and diameters
BAND = 0.03               # the figure's band about Schiller-Naumann

TEMPLATE_FILES = ("system/controlDict", "system/blockMeshDict", "constant/demProperties",
                  "constant/nsDemProperties", "0/U", "0/p")


def relaxation_time(re, mu):
    """rho_p d^2/(18 mu f(Re)), f Schiller-Naumann's correction."""
    return RHO_P * D * D / (18 * mu * (1 + 0.15 * re**0.687))



def measure_fall(case, z0, h, fall, n_meas, name):
    """The sphere's fall from z0 in a finished run: its z at the write
    times (<time>/grains), the times it crosses the cell-centre planes
    z0 - k h, k = 0..fall (z interpolated linearly between writes), the
    terminal velocity over the last n_meas cells and over the n_meas before
    them, and the velocity over each cell crossed. Returns (v_last,
    v_before, per_cell, crossing, t)."""
    t = np.array([0.0] + [tt for tt, _ in case.times()])
    z = np.array([z0] + [read_grains(case.file(os.path.join(n, "grains")))["position"][0, 2]
                         for _, n in case.times()])
    planes = z0 - h * np.arange(fall + 1)
    if z[-1] > planes[-1]:
        raise RuntimeError(f"{name}: the sphere fell only to z = {z[-1]:.4g} m, not to "
                           f"{planes[-1]:.4g} m ({fall} cells) by t = {t[-1]:.3g} s")
    crossing = np.interp(-planes, -z, t)
    v_last = n_meas * h / (crossing[fall] - crossing[fall - n_meas])
    v_before = n_meas * h / (crossing[fall - n_meas] - crossing[fall - 2 * n_meas])
    return v_last, v_before, h / np.diff(crossing), crossing, t

class Study:
    def __init__(self, study_dir, reynolds=REYNOLDS, sizes=SIZES, log=say):
        self.clock = StageClock("settlingSphereStudy", log, relay_interval=30.0)
        self.dir = os.path.abspath(study_dir)
        self.stages = os.path.join(self.dir, "stages")
        self.template_root = os.path.dirname(self.dir)
        self.template = os.path.basename(self.dir)
        os.makedirs(self.stages, exist_ok=True)
        self.reynolds, self.sizes = reynolds, sizes
        self.runs = {}

    def settle(self, re, h_over_d, box=BOX, key=None):
        key = key or f"Re{re:g}_h{h_over_d:g}d"
        mu = drag.viscosity_for_settling_reynolds(re, RHO_P, RHO_F, D, G)
        w_sn = drag.terminal_velocity(LAW, RHO_P, RHO_F, mu, D, G)
        w_st = drag.stokes_velocity(RHO_P, RHO_F, mu, D, G)
        tau = relaxation_time(re, mu)
        h = h_over_d * D
        n_lat = max(1, round(box / h))
        n_tr = max(TRANSIENT_CELLS, math.ceil(TRANSIENT_D * D / h),
                   math.ceil(6 * tau * w_sn / h))
        n_meas = max(2, math.ceil(MEASURED_D * D / h))
        fall = n_tr + 2 * n_meas
        margin = max(MARGIN_CELLS, math.ceil(MARGIN_D * D / h))
        nz = 2 + fall + margin + 1
        steps_per_cell = max(STEPS_PER_CELL, math.ceil(h / (w_sn * MAX_DT)))
        steps_per_cell = WRITES_PER_CELL * math.ceil(steps_per_cell / WRITES_PER_CELL)
        dt = h / (steps_per_cell * w_sn)
        sub = max(1, math.ceil(dt / (tau / 10)))   # 10 DEM steps per relaxation time
        steps = math.ceil((fall + 1) * steps_per_cell * 1.15)   # + the start's
        end = steps * dt

        c = Case(self.template, key, template_root=self.template_root, run_root=self.stages)
        c.set_variable("system/blockMeshDict", "L", "%.17g" % (n_lat * h))
        c.set_variable("system/blockMeshDict", "H", "%.17g" % (nz * h))
        c.set_variable("system/blockMeshDict", "n", n_lat)
        c.set_variable("system/blockMeshDict", "nz", nz)
        c.set("constant/nsDemProperties", "mu", "[1 -1 -1 0 0 0 0] %.17g" % mu)
        c.set("constant/nsDemProperties", "rho", "[1 -3 0 0 0 0 0] %.17g" % RHO_F)
        c.set("constant/nsDemProperties", "grains/fluidForce/type", LAW)
        c.set("constant/demProperties", "density", "%.17g" % RHO_P)
        c.set("constant/demProperties", "timeStep", "%.17g" % (dt / sub))
        c.set("system/controlDict", "deltaT", "%.17g" % dt)
        c.set("system/controlDict", "endTime", "%.17g" % end)
        c.set("system/controlDict", "writeInterval", steps_per_cell // WRITES_PER_CELL)
        x0 = (n_lat // 2 + 0.5) * h
        z0 = (nz - 2.5) * h
        with open(c.file("0/grains"), "w") as f:
            f.write("# one sphere at rest, at a cell centre\n%.17g %.17g %.17g %.17g\n"
                    % (x0, x0, z0, D / 2))
        c.run("blockMesh")
        wall = self.clock.run(
            c, "nsDemFoam", key,
            f"Re {re:g}, h = {h_over_d:g} d, {n_lat}x{n_lat}x{nz} cells, mu {mu:.4g} Pa s, "
            f"{steps} steps of {dt:.3g} s x {sub} DEM steps", end)

        v_last, v_before, per_cell, crossing, _ = measure_fall(c, z0, h, fall, n_meas, key)
        r = {"Re": re, "h_over_d": h_over_d, "mu": mu, "tau": tau,
             "mesh": [n_lat, n_lat, nz], "box": n_lat * h, "cell": h,
             "deltaT": dt, "demSubsteps": sub, "steps": steps, "endTime": end,
             "transientCells": n_tr, "measuredCells": n_meas,
             "measuredFrom_t": float(crossing[fall - n_meas]),
             "measuredTo_t": float(crossing[fall]),
             "v": v_last, "vBefore": v_before, "drift": v_last / v_before - 1,
             "schillerNaumann": w_sn, "stokes": w_st,
             "overSchillerNaumann": v_last / w_sn, "overStokes": v_last / w_st,
             "stokesOverSchillerNaumann": w_st / w_sn,
             "reMeasured": RHO_F * v_last * D / mu,
             "hasimoto": drag.hasimoto_factor(D, n_lat * h),
             "perCellOverSchillerNaumann": (per_cell / w_sn).tolist(),
             "wall_s": wall, "case": os.path.relpath(c.path, self.dir)}
        self.runs[key] = r
        say(f"settlingSphereStudy: Re {re:g}, h = {h_over_d:g} d: v {v_last:.6g} m/s, "
            f"Schiller-Naumann {w_sn:.6g} (v/v_SN {v_last / w_sn:.4f}), Stokes {w_st:.6g} "
            f"(v/v_Stokes {v_last / w_st:.4f}), drift over the stretch before "
            f"{r['drift']:+.2e}")
        return r

    def run(self):
        start = time.monotonic()
        for re in self.reynolds:
            self.settle(re, H_OVER_D)
        for k in self.sizes:
            self.settle(SIZE_RE, k, box=SIZE_BOX, key=f"size_h{k:g}d")
        self.results = {
            "setup": {"d": D, "rho_p": RHO_P, "rho_f": RHO_F, "g": G, "law": LAW,
                      "box": BOX, "sizeSeriesBox": SIZE_BOX, "h_over_d": H_OVER_D,
                      "sizeSeriesRe": SIZE_RE,
                      "writesPerCell": WRITES_PER_CELL},
            "solver": solver_version(),
            "reynoldsSeries": [self.runs[f"Re{re:g}_h{H_OVER_D:g}d"] for re in self.reynolds],
            "sizeSeries": [self.runs[f"size_h{k:g}d"] for k in self.sizes],
            "wall_s": time.monotonic() - start}
        with open(os.path.join(self.dir, "results.json"), "w") as f:
            json.dump(self.results, f, indent=2)
        return self.results

    def table(self):
        lines = ["run            Re     h/d  cells        mu [Pa s]   v [m/s]     "
                 "v_SN [m/s]  v/v_SN   v/v_Stokes  v_Stokes/v_SN  drift      wall [s]"]
        for r in self.runs.values():
            m = r["mesh"]
            lines.append(f"{r['case'].split('/')[-1]:<14} {r['Re']:<6g} {r['h_over_d']:<4g} "
                         f"{m[0]}x{m[1]}x{m[2]:<6} "
                         f"{r['mu']:<11.5g} {r['v']:<11.5g} {r['schillerNaumann']:<11.5g} "
                         f"{r['overSchillerNaumann']:.4f}   {r['overStokes']:.4f}      "
                         f"{r['stokesOverSchillerNaumann']:.4f}         {r['drift']:+.1e}   "
                         f"{r['wall_s']:.0f}")
        return "\n".join(lines)

    def plot(self):
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, (a1, a2) = plt.subplots(1, 2, figsize=(12, 4.8))
        res = self.results["reynoldsSeries"]
        re_line = np.logspace(-1.5, 2.5, 200)
        a1.fill_between(re_line, 1 - BAND, 1 + BAND, color="0.9",
                        label=f"Schiller-Naumann ±{BAND:.0%}")
        a1.axhline(1.0, color="k", lw=1.5, label="Schiller-Naumann (1933)")
        a1.plot(re_line, 1 + 0.15 * re_line**0.687, "k--", lw=1,
                label="Stokes / Schiller-Naumann")
        a1.plot([r["Re"] for r in res], [r["overSchillerNaumann"] for r in res], "o",
                color="C0", ms=8, label=f"nsDemFoam, h = {H_OVER_D} d, box {BOX / D:.0f} d")
        a1.set_xscale("log")
        a1.set_ylim(0.9, 1.2)
        a1.set_xlabel("Re = rho_f w d / mu (Schiller-Naumann's terminal)")
        a1.set_ylabel("terminal velocity / Schiller-Naumann's")
        a1.set_title("One sphere settling: terminal velocity", fontsize=10)
        a1.legend(fontsize=8, loc="upper right")
        a1.grid(True, which="both", alpha=0.3)

        sz = self.results["sizeSeries"]
        k = np.array([r["h_over_d"] for r in sz])
        err = np.array([r["overSchillerNaumann"] - 1 for r in sz])
        a2.plot(k, 100 * err, "o-", color="C0", label=f"nsDemFoam, Re {SIZE_RE:g}, "
                                                      f"box {SIZE_BOX / D:.0f} d")
        same = [r for r in self.results["reynoldsSeries"] if r["Re"] == SIZE_RE]
        if same:
            a2.plot([H_OVER_D], [100 * (same[0]["overSchillerNaumann"] - 1)], "s",
                    color="C1", label=f"the same, box {BOX / D:.0f} d")
        kk = np.linspace(1.5, 25, 100)
        a2.plot(kk, 50 / kk, "k:", lw=1, label="d/(2h) (first order)")
        a2.plot(kk, 300 / kk**2, "k--", lw=1, label="3 (d/h)^2 (second order)")
        a2.axhline(100 * BAND, color="0.5", lw=1, label=f"{BAND:.0%}")
        a2.set_xscale("log")
        a2.set_yscale("log")
        a2.set_xticks(list(k))
        a2.set_xticklabels([f"{v:g}" for v in k])
        a2.set_xlabel("cell size h / d")
        a2.set_ylabel("v / v_SN - 1 [%]")
        a2.set_title(f"Error against the cell size at Re {SIZE_RE:g}", fontsize=10)
        a2.legend(fontsize=8)
        a2.grid(True, which="both", alpha=0.3)
        fig.tight_layout()
        out = os.path.join(self.dir, "settlingSphere.png")
        fig.savefig(out, dpi=120)
        plt.close(fig)
        return out


def main(argv):
    ap = argparse.ArgumentParser(
        prog="settlingSphereStudy",
        description="Run the settling-sphere study of a tutorial directory "
                    "(bin/darcydem/settling.py): one sphere's terminal velocity with "
                    "nsDemFoam against Schiller-Naumann for several Re and cell sizes; writes "
                    "results.json and settlingSphere.png there and each run's case under "
                    "STUDY_DIR/stages.")
    ap.add_argument("study_dir", metavar="STUDY_DIR",
                    help="the template case (0/, constant/, system/), e.g. "
                         "tutorials/nsDemFoam/settlingSphere")
    ap.add_argument("--reynolds", nargs="+", type=float, default=list(REYNOLDS),
                    help="terminal Re of the series at h = %d d (default: %%(default)s)"
                         % H_OVER_D)
    ap.add_argument("--sizes", nargs="+", type=float, default=list(SIZES),
                    help="h/d of the series at Re %g (default: %%(default)s)" % SIZE_RE)
    a = parse_study_args(ap, argv)
    require_folder("settlingSphereStudy", a.study_dir, TEMPLATE_FILES)
    study = Study(a.study_dir, reynolds=a.reynolds, sizes=a.sizes)
    results = study.run()
    out = study.plot()
    say(study.table())
    say(f"settlingSphereStudy: study {results['wall_s']:.0f} s (wall)")
    say(f"settlingSphereStudy: wrote {out} and {os.path.join(study.dir, 'results.json')}; "
        f"the runs' cases in {study.stages}")

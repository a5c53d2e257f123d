"""The snow settlement experiment of Johnson and Hopkins (2005, J. Glaciol.
51(174), 432), its section "DEM simulation of snow creep settlement" and
Figs 5-10, run through real case directories:

  1. contract  demFoam, no gravity: a loose random gas of capsules
               (makeGrains --layout random --periodic y) in a box 1.5 x wider
               (x) and taller (z) than the paper's, every grain moving with a
               homogeneous contracting strain-rate field (--strain-rate) about
               the box middle, the four walls closing on it 1/0.9 x faster
               until they make the paper's box (0.019 x 0.016 x 0.019 m):
               Cundall and Strack's contraction of space, the walls sweeping
               the outermost grains onto the rest. Every pair that touches
               freezes at once (bonds formation frozenOnContact), so the grains
               end as a bonded, loose skeleton touching every wall;
  2. relax     the walls stopped, a global viscous drag takes out the
               contraction's remaining momentum, a light stress-controlled lid
               closes the gap the skeleton leaves as it springs back; its
               demState is the sample every settlement run starts from;
  3. settle    the lid becomes free (0.125 kg), gravity ramps up from zero,
               one run per contact viscosity nu_s (0.0016, 0.016, 0.16 and
               1 MPa s), and optionally one with a creep mechanism off.

The measurements come from the function objects wallStress (lid stress
P_zz, side stress P_xx), packingStatistics (density, coordination number,
bond counts, lid motion, bulk viscosity) and bondCreep (the bonds' creep
per mechanism); the figures mirror the paper's Figs 6-10. Every stage is a case directory under <study>/stages/<stage>,
made from the template case in <study>; DARCYDEM_BACKEND=cpu|cuda|auto sets
the DEM backend (bin/darcydem/case.py). Sizes: SIZES below.
"""

import argparse
import json
import os
import subprocess
import sys

import numpy as np

from darcydem.case import Case, default_jobs, run_side_by_side
from darcydem.cli import StageClock, add_jobs_option, parse_study_args, require_folder, say
from darcydem.foamfiles import grain_files, read_columns, read_scalar_entry, read_vtp_lines
from darcydem.smoothing import hanning_smooth

BIN = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# The paper's set-up (the text of its settlement section; its Table 1 is lost)
PAPER_BOX = (0.019, 0.016, 0.019)       # x, y, z [m]
LID_MASS = 0.125                         # [kg]
PAPER_VISCOSITIES = (1.6e3, 1.6e4, 1.6e5, 1.0e6)   # contact viscosity nu_s [Pa s]
ICE_DENSITY = 917.0
# Load scaled with the stiffness (1e-3): gravity 9.81e-3 m/s^2 under the real lid
GRAVITY = 9.81e-3
GRAVITY_RAMP = 0.1                       # [s] from zero to GRAVITY
TIME_STEP = 1e-5                         # the paper's DEM step [s]
STEPS_PER_FLUID_STEP = 20

# what a study folder (the template of every stage) must hold; checked
# before stages/ is made in it
TEMPLATE_FILES = ("system/controlDict", "system/blockMeshDict", "constant/demProperties")

SIZES = {
    # The paper: 1000 grains in its box, 3 s of settlement per contact viscosity.
    "paper": dict(count=1000, box=PAPER_BOX, settleTime=3.0, viscosities=PAPER_VISCOSITIES,
                  seed=1),
    # The same sample, a third of the settlement time.
    "quick": dict(count=1000, box=PAPER_BOX, settleTime=1.0, viscosities=PAPER_VISCOSITIES,
                  seed=1),
    # For the tests: 250 grains in a box a quarter of the paper's (half in x and z).
    "test": dict(count=250, box=(0.0095, 0.016, 0.0095), settleTime=0.5,
                 viscosities=(1.6e5, 1.0e6), seed=2),
}

# Preparation: grains R in [0.4, 0.6] mm, aspect (length / width) in [2, 4]
RADIUS = (4e-4, 6e-4)
ASPECT = (2.0, 4.0)
CONTRACTION = 1.5      # the loose box is this much wider (x) and taller (z)
SWEEP = 0.9            # the grains' contraction rate over the walls'
# The preparation's wall strain rate [1/s] (--preparation-rate), every size: a Maxwell bond
# of the preparation (tau = nu_s / E, 0.2-0.3 ms) is viscous on the contraction's time scale
# and carries about nu_s times its rate of deformation, so nu_s x rate sets the bonds' loads.
# At the paper's strength (sigma_ice x 1e-3) and 1600 Pa s, -1 1/s broke 89 % of the bonds
# frozen in the contraction (quick size), -0.1 1/s 13 %; README "At the paper's strength".
PREPARATION_RATE = -0.1
RELAX_TIME = 0.1        # [s] with the drag below
RELAX_LID_MASS = 1e-3   # [kg]: the lid closes a gap of 0.1 mm in about 0.02 s
RELAX_LID_STRESS = 0.25  # of the real lid's weight over the area
RELAX_DRAG = 3e-4       # [N s/m]: m/c about 5 ms for a grain of 1.6e-6 kg
# Contact viscosity of the bonds while the sample is made (contract, relax): the lowest of the
# settlement runs (--preparation-viscosity).
PREPARATION_VISCOSITY = PAPER_VISCOSITIES[0]
# --preparation-sweep: the contraction alone at these contact viscosities at SWEEP_RATE, and
# at SWEEP_SLOW_VISCOSITY with SWEEP_RATE times each SWEEP_SLOWER (the preparation's
# --preparation-rate does not change the sweep)
SWEEP_RATE = -1.0
SWEEP_VISCOSITIES = (16.0, 160.0, 1600.0, 16000.0)
SWEEP_SLOW_VISCOSITY = 1600.0
SWEEP_SLOWER = (0.3, 0.1)

# Write times of a settlement run: the bonds' .vtp at each gives the stress per mode
SETTLE_WRITES = 20
# Function objects' output, as written by wallStress, packingStatistics and bondCreep
WALL_STRESS = "postProcessing/wallStress/0/wallStress.dat"
PACKING = "postProcessing/packingStatistics/0/packing.dat"
CREEP = "postProcessing/bondCreep/0/creep.dat"
# The paper's Figs 8a-c: shear, bending and twisting creep (bondCreep's columns)
CREEP_MECHANISMS = (("shear", "(a) shear creep rate per bond [m/s]"),
                    ("bend", "(b) bending creep rate per bond [rad/s]"),
                    ("twist", "(c) twisting creep rate per bond [rad/s]"))


def label(nu):
    return "%g MPa s" % (nu / 1e6)


class Run:
    """The measurements of one settlement run (the .dat files; bondCreep's
    only where the run wrote it)."""

    def __init__(self, case_dir, nu, ly):
        self.case_dir = case_dir
        self.nu = nu
        self.ly = ly    # the periodic length in y [m]
        w = read_columns(os.path.join(case_dir, WALL_STRESS))
        p = read_columns(os.path.join(case_dir, PACKING))
        n = min(len(w["time"]), len(p["time"]))
        self.t = p["time"][:n]
        # compression positive: an upper wall is pushed along +axis, a lower one along -axis
        self.pzz = w["lid_stress"][:n]
        self.pxx = 0.5 * (w["right_stress"][:n] - w["left_stress"][:n])
        self.p = {k: v[:n] for k, v in p.items()}
        self.w = {k: v[:n] for k, v in w.items()}
        self.density = self.p["density"]
        formed0 = self.p["bondsFormed"][0]
        broken0 = self.p["bondsBroken"][0]
        self.formed = self.p["bondsFormed"] - formed0    # new frozen bonds since the start
        self.broken = self.p["bondsBroken"] - broken0
        path = os.path.join(case_dir, CREEP)
        self.creep = None
        if os.path.exists(path):
            c = read_columns(path)
            if np.array_equal(c["time"][:n], self.t):    # rows in step with packing.dat
                self.creep = {k: v[:n] for k, v in c.items()}

    def mode_stresses(self):
        """Mean stress per deformation mode over the intact bonds at each
        write time, from the bonds' .vtp (the peak stresses the strength
        check compares, doc/EQUATIONS.md section 10): (times, {"normal":
        |N|/A, "shear": |S|/A, "twist": |M_t| r_b/J, "bend": |M_b| r_b/I}),
        J = 2 I = pi r_b^4 / 2; None when the run wrote no bonds. Read once
        (the results and the figures both ask)."""
        if not hasattr(self, "_mode_stresses"):
            self._mode_stresses = self._read_mode_stresses()
        return self._mode_stresses

    def _read_mode_stresses(self):
        try:
            files = grain_files(self.case_dir, "bonds")
        except OSError:
            return None
        times, modes = [], {m: [] for m in ("normal", "shear", "twist", "bend")}
        for t, path in files:
            stresses = bond_mode_stresses(path)
            if stresses is None or len(stresses["normal"]) == 0:
                continue
            times.append(t)
            for m in modes:
                modes[m].append(np.mean(stresses[m]))
        if not times:
            return None
        return np.array(times), {m: np.array(v) for m, v in modes.items()}

    def mechanism_rates(self, width=None):
        """{mechanism: creep rate per intact bond} (normal, shear: m/s;
        twist, bend: rad/s): the rate of the sample's Hanning-smoothed creep
        sum (broken bonds' creep stays in it) over the intact bonds; None
        without bondCreep's file."""
        if self.creep is None:
            return None
        width = width or max(5, len(self.t) // 40)
        bonds = np.maximum(self.creep["bondsIntact"], 1)
        rates = {}
        for mechanism in ("normal", "shear", "twist", "bend"):
            rate = np.gradient(hanning_smooth(self.creep[mechanism], width), self.t) / bonds
            rate[:width // 2] = np.nan
            rate[len(rate) - width // 2:] = np.nan
            rates[mechanism] = rate
        return rates

    def creep_rates(self, width=None):
        """(axial strain rate, bulk viscosity) from the Hanning-smoothed lid
        height H: strain rate -dH/dt / H, viscosity smoothed P_zz / rate.
        The packingStatistics columns hold the same from the instantaneous
        lid velocity, which rings with the lid on its elastic skeleton."""
        width = width or max(5, len(self.t) // 40)
        lid = hanning_smooth(self.p["lidPosition"], width)
        bottom = self.w["bottom_position"]
        height = lid - bottom
        rate = -np.gradient(lid, self.t) / height
        # the smoothing window is cut short at both ends: no rate there
        rate[:width // 2] = np.nan
        rate[len(rate) - width // 2:] = np.nan
        pzz = hanning_smooth(self.pzz, width)
        with np.errstate(divide="ignore", invalid="ignore"):
            viscosity = np.where(rate > 0, pzz / rate, np.nan)
        return rate, viscosity

    def loaded(self):
        """Rows after the gravity ramp."""
        return self.t >= GRAVITY_RAMP

    def creeping(self):
        """Rows from the first time the smoothed lid stress reaches the lid's
        weight over the area on: the lid has caught up with the sample and
        sinks as the skeleton creeps (before, it falls onto the sample and
        P_zz / strain rate is no viscosity)."""
        area = (self.w["right_position"][0] - self.w["left_position"][0]) * self.ly
        weight = LID_MASS * GRAVITY / area
        smooth = hanning_smooth(self.pzz, max(5, len(self.t) // 40))
        reached = np.flatnonzero(self.loaded() & (smooth >= weight))
        mask = np.zeros(len(self.t), dtype=bool)
        if len(reached):
            mask[reached[0]:] = True
        return mask


class SettlementStudy:
    def __init__(self, study_dir, size="quick", log=say,
                 preparation_viscosity=PREPARATION_VISCOSITY, strength_scale=None,
                 bond_point=None, contract_y=False, preparation_rate=PREPARATION_RATE,
                 jobs=None):
        if size not in SIZES:
            sys.exit(f"settlementStudy: unknown size '{size}'; valid: {' '.join(SIZES)}")
        self.s = dict(SIZES[size])
        self.size = size
        self.log = log
        # settlement runs at once after the sample (run_side_by_side): by default one per
        # core the solvers' ranks leave free
        self.jobs = jobs or default_jobs()
        self.clock = StageClock("settlementStudy", log)
        self.dir = os.path.abspath(study_dir)
        self.stages = os.path.join(self.dir, "stages")
        os.makedirs(self.stages, exist_ok=True)
        lx, ly, lz = self.s["box"]
        # the loose box, and the mesh around it (the walls bound the grains)
        self.loose = (lx * CONTRACTION, ly, lz * CONTRACTION)
        self.preparation_viscosity = preparation_viscosity
        self.strength_scale = strength_scale   # None: the template's
        self.bond_point = bond_point           # None: the template's (closestPoints)
        self.results = {"size": size, "settings": dict(self.s), "runs": {}}
        self.results["settings"]["preparationViscosity"] = preparation_viscosity
        self.results["settings"]["strengthScale"] = strength_scale
        self.results["settings"]["bondPoint"] = bond_point
        # --contract-y: the periodic y length contracts with the walls (boxLengthRate)
        self.contract_y = contract_y
        self.results["settings"]["contractY"] = contract_y
        # --preparation-rate: the contraction's wall strain rate [1/s]
        self.preparation_rate = preparation_rate
        self.results["settings"]["preparationRate"] = preparation_rate

    # ---- stages ---------------------------------------------------------------------------
    def stage(self, name, state_from=None, ly=None):
        """The case of stage `name` on the loose box (its periodic length ly, default the
        paper's), started from state_from (else 0/grains)."""
        c = Case(os.path.basename(self.dir), name, template_root=os.path.dirname(self.dir),
                 run_root=self.stages)
        block = "system/blockMeshDict"
        lx, ly_paper, lz = self.loose
        ly = ly_paper if ly is None else ly
        cell = 3e-3   # about a capsule's length
        for key, value in (("Lx", lx), ("Ly", ly), ("H", lz)):
            c.set_variable(block, key, "%.12g" % value)
        c.set_variable(block, "nx", c.cells_along_x(lx / cell))
        for key, value in (("ny", ly), ("nz", lz)):
            c.set_variable(block, key, max(1, round(value / cell)))
        os.makedirs(c.file("0"), exist_ok=True)
        if self.strength_scale is not None:
            c.set("constant/demProperties", "bonds/strength/scale", "%g" % self.strength_scale)
        if self.bond_point is not None:
            c.set("constant/demProperties", "bonds/point", "{ type %s; }" % self.bond_point)
        return c.mesh(state_from)

    def final_walls(self):
        """(left, right, bottom, lid) of the paper's box in the middle of the loose box."""
        lx, _, lz = self.s["box"]
        x0 = 0.5 * (self.loose[0] - lx)
        z0 = 0.5 * (self.loose[2] - lz)
        return x0, x0 + lx, z0, z0 + lz

    def set_walls(self, c, moving, rate=None):
        """The walls of case c: closing at wall strain rate `rate` (moving),
        or still at the paper's box."""
        dem = "constant/demProperties"
        if moving:
            # the walls close on the middle of the loose box at the wall strain rate and
            # reach the paper's box when (1 + rate t) = 1 / CONTRACTION; the grains' field
            # is SWEEP x slower, so the walls catch the outermost grains and press them onto
            # the skeleton: it ends touching every wall
            lx, _, lz = self.loose
            for wall, position, middle in (("left", 0.0, lx / 2), ("right", lx, lx / 2),
                                           ("bottom", 0.0, lz / 2), ("lid", lz, lz / 2)):
                c.set(dem, f"walls/{wall}/mode", "velocity")
                c.set(dem, f"walls/{wall}/position", "%.12g" % position)
                c.set(dem, f"walls/{wall}/velocity", "%.12g" % (rate * (position - middle)))
            c.remove(dem, "walls/lid/mass")
        else:
            for wall, position in zip(("left", "right", "bottom", "lid"), self.final_walls()):
                c.set(dem, f"walls/{wall}/position", "%.12g" % position)

    def controls(self, c, end, writes, rows=2000):
        """endTime, write times and the function objects' rows (about `rows`);
        returns the last write time (the state the next stage starts from)."""
        ctl = "system/controlDict"
        fluid_dt = STEPS_PER_FLUID_STEP * TIME_STEP
        steps = round(end / fluid_dt)
        every = max(1, steps // writes)
        # the function objects' interval divides the write interval, so that they have a row
        # at every write (the bonds' .vtp beside their counts): the largest divisor of it
        # not above the interval that gives about `rows`
        wanted = max(1, steps // rows)
        sample = max(d for d in range(1, min(wanted, every) + 1) if every % d == 0)
        c.set(ctl, "deltaT", "%.12g" % fluid_dt)
        c.set(ctl, "endTime", "%.12g" % (steps * fluid_dt))
        c.set(ctl, "writeInterval", every)
        for fo in ("wallStress", "packingStatistics", "bondCreep"):
            c.set(ctl, f"functions/{fo}/writeInterval", sample)
        c.set(ctl, "functions/grainDiagnostics/writeInterval", max(1, steps // 200))
        return (steps // every) * every * fluid_dt

    @staticmethod
    def contraction_time(rate):
        return (1 / CONTRACTION - 1) / rate

    def contract(self, name, viscosity, rate):
        """The contraction at wall strain rate `rate` with the bonds' contact
        viscosity `viscosity`: the case of stage `name`."""
        s = self.s
        dem = "constant/demProperties"
        lx, ly, lz = self.loose
        # With --contract-y the periodic length shrinks from CONTRACTION ly to ly in the
        # same time as the walls close, the grains' y velocities on its own field (no walls
        # to sweep there: the field of the periodic cell, v(y + L) = v(y) + dL/dt)
        ly_start = ly * CONTRACTION if self.contract_y else ly
        a = self.stage(name, ly=ly_start)
        grain_rate = SWEEP * rate
        y_rate = rate if self.contract_y else 0
        subprocess.run([os.path.join(BIN, "makeGrains"), "--box", "%.12g" % lx,
                        "%.12g" % ly_start,
                        "--z", "0", "%.12g" % lz, "--radius", str(RADIUS[0]), str(RADIUS[1]),
                        "--layout", "random", "--count", str(s["count"]),
                        "--capsule-fraction", "1", "--aspect", str(ASPECT[0]), str(ASPECT[1]),
                        "--periodic", "y", "--gap", "0.05",
                        "--strain-rate", str(grain_rate), str(y_rate), str(grain_rate),
                        "--strain-origin", "%.12g" % (lx / 2), "%.12g" % (ly_start / 2),
                        "%.12g" % (lz / 2),
                        "--seed", str(s["seed"]), "-o", a.file("0/grains")],
                       check=True, stdout=subprocess.DEVNULL)
        self.set_walls(a, moving=True, rate=rate)
        a.set(dem, "gravity", "(0 0 0)")
        a.set(dem, "bonds/creep/contactViscosity", "%.12g" % viscosity)
        end = self.contraction_time(rate)
        last_write = self.controls(a, end, 4, rows=400)
        if self.contract_y:
            # the paper's ly at the last write, the state the next stage starts from (its
            # mesh, which that start checks the demState's box against)
            a.set(dem, "boxLengthRate", "(0 %.17g 0)" % ((ly - ly_start) / last_write))
        self.timed_run(a, name, f"{s['count']} capsules contract by {CONTRACTION}"
                       f" in x, {'y, ' if self.contract_y else ''}z, contact viscosity"
                       f" {label(viscosity)}", end)
        return a

    def prepare(self):
        s = self.s
        dem = "constant/demProperties"
        a = self.contract("contract", self.preparation_viscosity, self.preparation_rate)

        b = self.stage("relax", state_from=self.last_state(a))
        self.set_walls(b, moving=False)
        # the skeleton springs back from the lid when the walls stop: a light lid
        # pressing at a quarter of the real lid's stress closes that gap (the free lid
        # of the settlement would fall through it)
        lid_stress = LID_MASS * GRAVITY / (s["box"][0] * s["box"][1])
        b.set(dem, "walls/lid/mode", "stress")
        b.set(dem, "walls/lid/mass", RELAX_LID_MASS)
        b.set(dem, "walls/lid/normalStress", "%.12g" % (RELAX_LID_STRESS * lid_stress))
        b.set(dem, "gravity", "(0 0 0)")
        b.set(dem, "viscousDrag", RELAX_DRAG)
        b.set(dem, "bonds/creep/contactViscosity", "%.12g" % self.preparation_viscosity)
        self.controls(b, RELAX_TIME, 1, rows=100)
        self.timed_run(b, "relax", f"drag {RELAX_DRAG} N s/m", RELAX_TIME)
        self.prepared = self.last_state(b)
        start = read_columns(b.file(PACKING))
        # bondsFormed and bondsBroken count from the contraction's start: the preparation's
        self.results["prepare"] = {k: float(start[k][-1]) for k in
                                   ("density", "solidFraction", "coordinationNumber",
                                    "bondsIntact", "meanPatchRadius", "bondsFormed",
                                    "bondsBroken")}

    def preparation_sweep(self):
        """The contraction alone at each of SWEEP_VISCOSITIES (at SWEEP_RATE)
        and at SWEEP_SLOW_VISCOSITY contracting SWEEP_SLOWER times as fast,
        with the study's bonds (--strength-scale, else the template's
        strength): how many bonds froze and broke, and the bonds' stress per
        mode at the end (settlementPreparation.png, results.json
        "preparationSweep")."""
        rate = SWEEP_RATE
        cases = [(nu, rate) for nu in SWEEP_VISCOSITIES]
        cases += [(SWEEP_SLOW_VISCOSITY, rate * f) for f in SWEEP_SLOWER]
        rows = []
        for nu, r in cases:
            name = "contract_nu%g" % nu + ("" if r == rate else "_rate%g" % r)
            a = self.contract(name, nu, r)
            end = read_columns(a.file(PACKING))
            row = {"viscosity": nu, "strainRate": r,
                   "wallSeconds": self.results["wallSeconds"][name]}
            row.update({k: float(end[k][-1]) for k in
                        ("bondsFormed", "bondsBroken", "bondsIntact", "coordinationNumber")})
            files = grain_files(a.path, "bonds")
            stresses = bond_mode_stresses(files[-1][1]) if files else None
            row["modeStress95"] = {m: float(np.percentile(v, 95)) if len(v) else 0.0
                                   for m, v in (stresses or {}).items() if m != "normal"}
            self.log(f"settlementStudy: {name}: {row['bondsFormed']:.0f} bonds frozen,"
                     f" {row['bondsBroken']:.0f} broken, coordination number"
                     f" {row['coordinationNumber']:.2f}")
            rows.append(row)
        self.results["preparationSweep"] = rows
        plot_preparation_sweep(rows, self.dir, rate, self.strength(), self.contract_y)
        self.write_results()
        return rows

    def strength(self):
        """The bonds' tensile strength of the stages [Pa]: sigma_ice(T) times
        the scale (--strength-scale, else the template's; doc/EQUATIONS.md
        section 10, the paper's fit)."""
        path = os.path.join(self.dir, "constant", "demProperties")
        temperature = read_scalar_entry(path, "bonds/temperature")
        scale = (read_scalar_entry(path, "bonds/strength/scale")
                 if self.strength_scale is None else self.strength_scale)
        return scale * (0.99648 - 0.045904 * temperature) * 1e6

    @staticmethod
    def last_state(case):
        return case.file(os.path.join(case.times()[-1][1], "demState"))

    def timed_run(self, case, name, what, end):
        seconds = self.clock.run(case, "demFoam", name, what, end)
        self.results.setdefault("wallSeconds", {})[name] = seconds
        return seconds

    def settle(self, nu, creep_off=None, strength_scale=None, threads=None):
        """One settlement run; creep_off: the creep mechanism (shear, twist,
        bend) switched off in it; strength_scale: the bonds' strength scale
        during the settlement (the sample keeps the one it was prepared
        with); threads: its DEM threads (None: the template's)."""
        name = ("settle_nu%g" % nu + ("" if creep_off is None else "_no" + creep_off.title())
                + ("" if strength_scale is None else "_strength%g" % strength_scale))
        c = self.stage(name, state_from=self.prepared)
        self.set_walls(c, moving=False)
        if threads is not None:
            c.set("constant/demProperties", "threads", threads)
        c.set("constant/demProperties", "bonds/creep/contactViscosity", "%g" % nu)
        if creep_off is not None:
            c.set("constant/demProperties", f"bonds/creep/{creep_off}", "no")
        if strength_scale is not None:
            c.set("constant/demProperties", "bonds/strength/scale", "%g" % strength_scale)
        self.controls(c, self.s["settleTime"], SETTLE_WRITES)
        seconds = self.timed_run(c, name, f"settle, contact viscosity {label(nu)}"
                                 + ("" if creep_off is None else f", {creep_off} creep off")
                                 + ("" if strength_scale is None
                                    else f", strength scale {strength_scale:g}"),
                                 self.s["settleTime"])
        steps = round(self.s["settleTime"] / TIME_STEP)
        run = Run(c.path, nu, self.s["box"][1])
        run.creep_off = creep_off
        run.strength_scale = strength_scale
        rate, viscosity = run.creep_rates()
        loaded = run.loaded()
        self.results["runs"][name] = {
            "contactViscosity": nu,
            "grainStepsPerSecond": self.s["count"] * steps / seconds,
            "densityStart": float(run.density[0]),
            "densityEnd": float(run.density[-1]),
            "coordinationEnd": float(run.p["coordinationNumber"][-1]),
            "bondsFormed": float(run.formed[-1]),
            "bondsBroken": float(run.broken[-1]),
            "meanPzzLoaded": float(np.mean(run.pzz[loaded])),
            "meanPxxLoaded": float(np.mean(run.pxx[loaded])),
            "meanStrainRateLoaded": float(np.nanmean(rate[loaded])),
        }
        stresses = run.mode_stresses()
        if stresses is not None:
            # mean stress per mode over the intact bonds, first and last write [Pa]
            t, modes = stresses
            self.results["runs"][name]["meanModeStress"] = {
                "times": [float(t[0]), float(t[-1])],
                **{m: [float(v[0]), float(v[-1])] for m, v in modes.items()}}
        if run.creep is not None:
            # creep per intact bond over the loaded rows (the paper's Figs 8a-c)
            rates = run.mechanism_rates()
            self.results["runs"][name]["meanCreepRatePerBondLoaded"] = {
                m: float(np.nanmean(rates[m][loaded])) for m in ("normal", "shear", "twist", "bend")}
            self.results["runs"][name]["creepPerBondEnd"] = {
                m: float(run.creep[m][-1] / max(run.creep["bondsIntact"][-1], 1))
                for m in ("normal", "shear", "twist", "bend")}
        return run

    def run(self, creep_off=(), keep_sample=False, weak_bonds=None):
        """The preparation (unless keep_sample and stages/relax has run), the
        settlement runs, and one more run at the lowest contact viscosity for
        each mechanism in creep_off, with that creep mechanism off; with
        weak_bonds (a strength scale), the lowest contact viscosity again with
        every creep on and with each mechanism of creep_off off, the bonds'
        strength scaled by weak_bonds while settling."""
        relax = os.path.join(self.stages, "relax")
        if keep_sample and os.path.exists(relax) and Case.existing(relax).times():
            self.prepared = self.last_state(Case.existing(relax))
            self.log(f"settlementStudy: the sample of {relax}")
        else:
            self.prepare()
        # every settlement run starts from the sample: self.jobs at a time
        lowest = min(self.s["viscosities"])
        specs = ([(nu, None, None) for nu in self.s["viscosities"]]
                 + [(lowest, m, None) for m in creep_off]
                 + ([(lowest, m, weak_bonds) for m in [None] + list(creep_off)]
                    if weak_bonds is not None else []))
        done = run_side_by_side([lambda threads, spec=spec: self.settle(*spec, threads=threads)
                                 for spec in specs], self.jobs, self.log,
                                f"settlementStudy: {len(specs)} settlement runs")
        runs = done[:len(self.s["viscosities"])]
        variants = done[len(runs):len(runs) + len(creep_off)]
        self.variants = variants
        weak = done[len(runs) + len(creep_off):]
        self.results["lidStressExpected"] = LID_MASS * GRAVITY / (
            self.s["box"][0] * self.s["box"][1])
        self.plot(runs)
        if variants:
            plot_creep_off(runs[int(np.argmin([r.nu for r in runs]))], variants, self.dir)
        if weak:
            plot_creep_off(weak[0], weak[1:], self.dir, "settlementWeakBonds.png")
        self.write_results()
        return runs

    def existing_runs(self):
        """The settlement runs already in stages/ (for --plot-only)."""
        runs = []
        for nu in self.s["viscosities"]:
            path = os.path.join(self.stages, "settle_nu%g" % nu)
            if os.path.exists(os.path.join(path, PACKING)):
                runs.append(Run(path, nu, self.s["box"][1]))
        return runs

    def write_results(self):
        with open(os.path.join(self.dir, "results.json"), "w") as f:
            json.dump(self.results, f, indent=2)

    # ---- figures --------------------------------------------------------------------------
    def plot(self, runs):
        plot_figures(runs, self.dir, self.s["box"], self.results)


def bond_mode_stresses(path):
    """Per intact bond of a bonds .vtp, the peak stress of each mode that the
    strength check compares (doc/EQUATIONS.md section 10): {"normal": |N|/A,
    "shear": |S|/A, "twist": |M_t| r_b/J, "bend": |M_b| r_b/I}, J = 2 I =
    pi r_b^4 / 2, and "tension": max(N, 0)/A (what the strength check adds to
    the bending stress; compression never breaks a bond); None for a file
    without the moments."""
    b = read_vtp_lines(path)
    if "bendMoment" not in b:
        return None
    rb = b["patchRadius"]
    area, inertia = np.pi * rb**2, np.pi * rb**4 / 4
    return {"normal": np.abs(b["normalForce"]) / area,
            "tension": np.maximum(b["normalForce"], 0.0) / area,
            "shear": b["shearForce"] / area,
            "twist": np.abs(b["twistMoment"]) * rb / (2 * inertia),
            "bend": b["bendMoment"] * rb / inertia}


def plot_preparation_sweep(rows, out_dir, rate, strength, contract_y=False):
    """settlementPreparation.png (settlementPreparationContractY.png with
    --contract-y): bonds frozen and broken in the contraction, and the 95th
    percentile of the intact bonds' stress per mode at its end, against the
    contact viscosity; the slower contractions as open marks."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(1, 2, figsize=(11, 4.5))
    base = [r for r in rows if r["strainRate"] == rate]
    slow = [r for r in rows if r["strainRate"] != rate]
    nu = [r["viscosity"] for r in base]
    ax[0].loglog(nu, [r["bondsFormed"] for r in base], "ko-", label="frozen")
    ax[0].loglog(nu, [max(r["bondsBroken"], 0.5) for r in base], "rs-", label="broken")
    for r in slow:
        ax[0].loglog(r["viscosity"], r["bondsFormed"], "o", mfc="none", mec="k")
        ax[0].loglog(r["viscosity"], max(r["bondsBroken"], 0.5), "s", mfc="none", mec="r")
        ax[0].annotate(f"{r['strainRate']:g} 1/s", (r["viscosity"], r["bondsBroken"]),
                       textcoords="offset points", xytext=(6, -10), fontsize=7)
    ax[0].set_xlabel("contact viscosity while contracting ν_s [Pa s]")
    ax[0].set_ylabel("bonds in the contraction")
    ax[0].set_title(f"contracting x, {'y, ' if contract_y else ''}z; filled: strain rate"
                    f" {rate:g} 1/s; open: slower", fontsize=9)
    ax[0].legend(fontsize=8)
    for mode, mark in (("tension", "v"), ("shear", "^"), ("twist", "D"), ("bend", "o")):
        ax[1].loglog(nu, [max(r["modeStress95"].get(mode, 0.0), 1e-3) for r in base],
                     marker=mark, label=mode)
    ax[1].axhline(strength, color="k", ls="--", lw=0.8, label="strength")
    ax[1].set_xlabel("contact viscosity while contracting ν_s [Pa s]")
    ax[1].set_ylabel("95th percentile of the intact bonds' stress [Pa]")
    ax[1].legend(fontsize=8)
    fig.tight_layout()
    name = "settlementPreparationContractY.png" if contract_y else "settlementPreparation.png"
    fig.savefig(os.path.join(out_dir, name), dpi=120)
    plt.close(fig)


def reference_density(runs, wanted=300.0):
    """A density every run passes through while creeping: `wanted` (the
    paper's Fig. 10 uses 300 kg/m^3) when all reach it, else the middle of
    the range all share (None when they share none)."""
    spans = [r.density[r.creeping()] for r in runs]
    if any(len(d) == 0 for d in spans):
        return None
    reached = min(np.max(d) for d in spans)
    start = max(np.min(d) for d in spans)
    if start > reached:
        return None
    return wanted if start <= wanted <= reached else 0.5 * (start + reached)


def viscosity_at(run, density):
    """Bulk viscosity of a run at a density: the median over the creeping
    rows within 0.5 % of it (the smoothed viscosity still scatters)."""
    _, viscosity = run.creep_rates()
    rows = run.creeping() & (np.abs(run.density - density) <= 0.005 * density)
    values = viscosity[rows]
    values = values[np.isfinite(values)]
    return float(np.median(values)) if len(values) else float("nan")


def plot_figures(runs, out_dir, box, results=None):
    """settlementTime.png (Fig. 6), settlementDensity.png (Fig. 7),
    settlementCreep.png (Fig. 8), settlementViscosity.png (Fig. 9),
    settlementScaling.png (Fig. 10) in out_dir."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    results = {} if results is None else results
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    lid_stress = LID_MASS * GRAVITY / (box[0] * box[1])

    def save(fig, name):
        fig.tight_layout()
        fig.savefig(os.path.join(out_dir, name), dpi=110)
        plt.close(fig)

    # Fig. 6: against time
    fig, ax = plt.subplots(5, 1, figsize=(6.5, 12), sharex=True)
    for k, r in enumerate(runs):
        c = colours[k % len(colours)]
        ax[0].plot(r.t, r.pzz, color=c, lw=0.8, label="P_zz, " + label(r.nu))
        ax[0].plot(r.t, r.pxx, color=c, lw=0.8, ls="--")
        ax[1].plot(r.t, r.density, color=c, label=label(r.nu))
        ax[2].plot(r.t, r.p["coordinationNumber"], color=c)
        ax[3].plot(r.t, r.broken, color=c)
        ax[4].plot(r.t, r.formed, color=c)
    ax[0].axhline(lid_stress, color="k", lw=0.6, ls=":", label="lid weight / area")
    ax[0].set_ylabel("(a) P_zz (solid), P_xx (dashed) [Pa]")
    ax[0].legend(fontsize=7)
    ax[1].set_ylabel("(b) density [kg/m³]")
    ax[2].set_ylabel("(c) coordination number")
    ax[3].set_ylabel("(d) broken bonds")
    ax[4].set_ylabel("(e) new frozen bonds")
    ax[4].set_xlabel("time [s]")
    save(fig, "settlementTime.png")

    # Fig. 7: against density (after the gravity ramp)
    fig, ax = plt.subplots(2, 2, figsize=(10, 7))
    ax = ax.ravel()
    for k, r in enumerate(runs):
        c = colours[k % len(colours)]
        m = r.loaded()
        ax[0].plot(r.density[m], r.pzz[m], color=c, lw=0.8, label="P_zz, " + label(r.nu))
        ax[0].plot(r.density[m], r.pxx[m], color=c, lw=0.8, ls="--")
        ax[1].plot(r.density[m], r.p["coordinationNumber"][m], color=c, label=label(r.nu))
        ax[2].plot(r.density[m], r.formed[m], color=c)
        ax[3].plot(r.density[m], r.broken[m], color=c)
    ax[0].set_ylabel("(a) P_zz (solid), P_xx (dashed) [Pa]")
    ax[0].legend(fontsize=7)
    ax[1].set_ylabel("(b) coordination number")
    ax[1].legend(fontsize=7)
    ax[2].set_ylabel("(c) new frozen bonds")
    ax[3].set_ylabel("(d) broken bonds")
    for a in ax:
        a.set_xlabel("density [kg/m³]")
    save(fig, "settlementDensity.png")

    # Fig. 8: (a-c) creep rate per bond of each mechanism, (d) bulk axial strain rate,
    # against density (the whole loaded run)
    fig, ax = plt.subplots(2, 2, figsize=(10, 7))
    ax = ax.ravel()
    for k, r in enumerate(runs):
        c = colours[k % len(colours)]
        m = r.loaded()
        rates = r.mechanism_rates()
        for a, (mechanism, _) in zip(ax[:3], CREEP_MECHANISMS):
            if rates is not None:
                rate = rates[mechanism][m]
                a.semilogy(r.density[m], np.where(rate > 0, rate, np.nan), color=c,
                           label=label(r.nu))
        rate, _ = r.creep_rates()
        ax[3].semilogy(r.density[m], np.where(rate[m] > 0, rate[m], np.nan), color=c,
                       label=label(r.nu))
    for a, (_, title) in zip(ax[:3], CREEP_MECHANISMS):
        a.set_ylabel(title)
    ax[3].set_ylabel("(d) bulk axial strain rate [1/s]")
    for a in ax:
        a.set_xlabel("density [kg/m³]")
    ax[3].legend(fontsize=7)
    save(fig, "settlementCreep.png")

    # Fig. 9: bulk viscosity against density, once the lid rests on the creeping sample
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    for k, r in enumerate(runs):
        _, viscosity = r.creep_rates()
        m = r.creeping()
        ax.semilogy(r.density[m], viscosity[m], color=colours[k % len(colours)],
                    label=label(r.nu))
    ax.set_xlabel("density [kg/m³]")
    ax.set_ylabel("bulk viscosity P_zz / strain rate [Pa s]")
    ax.legend(fontsize=7)
    save(fig, "settlementViscosity.png")

    # Fig. 10: bulk viscosity at one density against contact viscosity. Where the runs
    # share no density while creeping (the fast ones have compacted before their lid
    # rests on them), each run's viscosity where it starts creeping, densities noted.
    if len(runs) >= 2:
        rho = reference_density(runs)
        nu = np.array([r.nu for r in runs])
        if rho is not None:
            at = np.full(len(runs), rho)
        else:
            at = np.array([r.density[r.creeping()][0] if r.creeping().any() else np.nan
                           for r in runs])
        eta = np.array([viscosity_at(r, d) if np.isfinite(d) else np.nan
                        for r, d in zip(runs, at)])
        ok = np.isfinite(eta) & (eta > 0)
        fig, ax = plt.subplots(figsize=(5.5, 4.5))
        ax.loglog(nu[ok], eta[ok], "o", label=(f"at {rho:.0f} kg/m³" if rho is not None else
                                                "where each run starts creeping"))
        for n, e, d in zip(nu[ok], eta[ok], at[ok]):
            ax.annotate(f"{d:.0f} kg/m³", (n, e), fontsize=7, xytext=(4, -10),
                        textcoords="offset points")
        if np.count_nonzero(ok) >= 2:
            slope, intercept = np.polyfit(np.log10(nu[ok]), np.log10(eta[ok]), 1)
            fit = 10 ** (intercept + slope * np.log10(nu[ok]))
            ax.loglog(nu[ok], fit, "k--", lw=0.8, label=f"fit: slope {slope:.2f}")
            results["scaling"] = {"density": at.tolist(), "contactViscosity": nu.tolist(),
                                  "bulkViscosity": eta.tolist(), "logSlope": slope}
        ax.set_xlabel("contact viscosity ν_s [Pa s]")
        ax.set_ylabel("bulk viscosity [Pa s]")
        ax.legend(fontsize=7)
        save(fig, "settlementScaling.png")


def plot_creep_off(reference, variants, out_dir, name="settlementCreepOff.png"):
    """settlementCreepOff.png: lid stress, density, broken bonds and the
    bonds' mean stress in each mode (normal, shear, twist, bend) against time
    with every creep mechanism on and with one off."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    modes = (("normal", "|N|/A"), ("shear", "|S|/A"), ("twist", "|M_t| r_b/J"),
             ("bend", "|M_b| r_b/I"))
    fig, ax = plt.subplots(4, 2, figsize=(10, 10), sharex=True)
    ax = ax.T.ravel()    # left column: lid, density, broken, new bonds; right: the modes
    for r in [reference] + list(variants):
        what = "all creep on" if getattr(r, "creep_off", None) is None else (
            f"{r.creep_off} creep off")
        if getattr(r, "strength_scale", None) is not None:
            what += f", strength x {r.strength_scale:g}"
        ax[0].plot(r.t, r.pzz, lw=0.8, label=f"{what}, {label(r.nu)}")
        ax[1].plot(r.t, r.density)
        ax[2].plot(r.t, r.broken)
        ax[3].plot(r.t, r.formed)
        stresses = r.mode_stresses()
        if stresses is not None:
            t, values = stresses
            for a, (mode, _) in zip(ax[4:], modes):
                a.plot(t, values[mode], marker=".", lw=0.8)
    ax[0].set_ylabel("P_zz [Pa]")
    ax[0].legend(fontsize=7)
    ax[1].set_ylabel("density [kg/m³]")
    ax[2].set_ylabel("broken bonds")
    ax[3].set_ylabel("new frozen bonds")
    for a, (mode, formula) in zip(ax[4:], modes):
        a.set_ylabel(f"mean {mode} stress\n{formula} [Pa]")
    ax[3].set_xlabel("time [s]")
    ax[-1].set_xlabel("time [s]")
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, name), dpi=110)
    plt.close(fig)


def main(argv):
    ap = argparse.ArgumentParser(prog="settlementStudy", description=__doc__.split("\n")[0])
    ap.add_argument("study_dir")
    ap.add_argument("--size", default="quick", choices=sorted(SIZES))
    ap.add_argument("--paper", action="store_true", help="the same as --size paper")
    ap.add_argument("--plot-only", action="store_true",
                    help="redraw the figures from the runs already in stages/")
    ap.add_argument("--creep-off", action="append", default=[],
                    choices=("shear", "twist", "bend"),
                    help="one more run at the lowest contact viscosity with this creep"
                         " mechanism off (may be repeated)")
    ap.add_argument("--keep-sample", action="store_true",
                    help="start from the sample already in stages/relax")
    ap.add_argument("--weak-bonds", type=float, metavar="SCALE",
                    help="the lowest contact viscosity again, all creep on and each"
                         " --creep-off mechanism off, with the bonds' strength scale SCALE"
                         " while settling (settlementWeakBonds.png)")
    ap.add_argument("--preparation-viscosity", type=float, metavar="NU",
                    default=PREPARATION_VISCOSITY,
                    help="the bonds' contact viscosity while the sample is made [Pa s]"
                         " (default %(default)g)")
    ap.add_argument("--preparation-rate", type=float, metavar="RATE", default=PREPARATION_RATE,
                    help="the walls' strain rate while the sample is contracted [1/s], < 0"
                         " (default %(default)g)")
    ap.add_argument("--strength-scale", type=float, metavar="SCALE",
                    help="the bonds' strength scale (of sigma_ice) in every stage, instead of"
                         " the template's (the paper's scaling, 1e-3)")
    ap.add_argument("--bond-point", choices=("closestPoints", "bodyFixedPatches"),
                    help="where the bonds sit in every stage (doc/CASE-FORMAT.md, bonds point;"
                         " the template's: closestPoints)")
    ap.add_argument("--contract-y", action="store_true",
                    help="contract the periodic y length too (boxLengthRate), as the paper"
                         " contracted all of space; else only x and z contract")
    add_jobs_option(ap, "runs",
                    help="settlement runs at once after the sample, each on its share of the"
                         " cores (default: the cores over the ranks of -parallel, so two"
                         " 1-thread runs on 2 cores); 1: one after the other")
    ap.add_argument("--preparation-sweep", action="store_true",
                    help="only the contraction, at several contact viscosities and"
                         " strain rates: bonds frozen and broken (settlementPreparation.png)")
    a = parse_study_args(ap, argv)
    if not a.preparation_viscosity > 0:
        sys.exit(f"settlementStudy: --preparation-viscosity {a.preparation_viscosity:g}:"
                 " the contact viscosity must be > 0 Pa s")
    if not a.preparation_rate < 0:
        sys.exit(f"settlementStudy: --preparation-rate {a.preparation_rate:g}: the contraction's"
                 " strain rate must be < 0 1/s")
    if a.strength_scale is not None and not a.strength_scale > 0:
        sys.exit(f"settlementStudy: --strength-scale {a.strength_scale:g}: the scale must be > 0")
    if a.weak_bonds is not None and not a.weak_bonds > 0:
        sys.exit(f"settlementStudy: --weak-bonds {a.weak_bonds:g}: the scale must be > 0")
    require_folder("settlementStudy", a.study_dir, TEMPLATE_FILES)
    study = SettlementStudy(a.study_dir, "paper" if a.paper else a.size,
                            preparation_viscosity=a.preparation_viscosity,
                            strength_scale=a.strength_scale, bond_point=a.bond_point,
                            contract_y=a.contract_y, preparation_rate=a.preparation_rate,
                            jobs=a.jobs)
    if a.preparation_sweep:
        study.preparation_sweep()
        return
    if a.plot_only:
        # keep what the runs recorded (preparation, timings); the figures' numbers update
        previous = os.path.join(study.dir, "results.json")
        if os.path.exists(previous):
            study.results = json.load(open(previous))
        study.plot(study.existing_runs())
        study.write_results()
        return
    study.run(creep_off=a.creep_off, keep_sample=a.keep_sample, weak_bonds=a.weak_bonds)

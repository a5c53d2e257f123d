"""The shear experiment of Damsgaard et al. (2015, The Cryosphere 9, 2183),
sections 2.4 and 3, run through real case directories:

  1. settle       demFoam: a loose random gas of grains (makeGrains --layout
                  random) falls under gravity with a viscous drag into a
                  dense, disordered bed;
  2. consolidate  demFoam: the stress-controlled top wall at sigma0 presses
                  the bed until it is at rest; its demState is the packing
                  every shear case starts from (identical for all). Both
                  with frictionless grains (preparationFriction) for a
                  dense random packing; the shear cases restore mu = 0.5;
  3. shear        the bottom layer fixed, the top layer moved at the shear
                  velocity (free vertically, no rotation) under the top wall
                  at sigma0, periodic x and y (Fig. 3): dry (demFoam), and
                  saturated (darcyDemFoam, p fixed at the top and at/above
                  the top wall, no flow through the base) for each kc;
  4. rate series  the impermeable case with mu_f = 1, 0.1, 0.01 x mu_ref,
                  the paper's stand-in for shearing 1, 10, 100 x slower.

The fluid's force on the grains of the saturated stages (darcyProperties
solidPhase/fluidForce, doc/EQUATIONS.md section 7) is the template's,
pressureGradient (-V grad p per grain, the seed's eq 12), unless fluid_force
(--fluid-force) names another: darcy (-V grad p/(1 - porosity), the whole
Darcy force on the skeleton). A non-default model is set in every saturated
stage, and its name is a suffix of those stages (stages/permeable-darcy,
...), of the results file (results-darcy.json) and of the figures
(shearFriction-darcy.png, ...), so runs of the two models sit side by side;
settle, consolidate and dry do not depend on it and keep their names (a
rerun overwrites them). results*.json record the model as 'fluidForce'. With reuse
(--reuse-packing) finished settle, consolidate and dry stages of an earlier
run of the same size are read instead of run again: the second model then
shears exactly the same packing.

Every stage is a case directory under <study>/stages/<stage>, made from the
template case in <study> (0/, constant/, system/); DARCYDEM_BACKEND=cpu|cuda|auto
sets the DEM backend of every stage (bin/darcydem/case.py), else the
template's 'backend' holds. Sizes: SIZES below.
"""

import argparse
import filecmp
import json
import math
import os
import re
import shutil
import subprocess
import sys

import numpy as np

from darcydem.case import Case, default_jobs, run_side_by_side
from darcydem.cli import StageClock, add_jobs_option, parse_study_args, require_folder, say
from darcydem.foamfiles import (GRAIN_DIAGNOSTICS, grain_files, read_columns, read_scalar_entry,
                                read_vtp, time_dirs)
from darcydem.smoothing import hanning_smooth

BIN = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# Reference values of the seed paper (Table 1)
PAPER_MU = 1.797e-6            # scaled pore-water viscosity [Pa s]
PAPER_BETA = 1.426e-8          # scaled fluid compressibility [1/Pa]
PAPER_KN = 1.16e9              # grain stiffness [N/m]
PAPER_SHEAR_VELOCITY = 2.32e-2  # [m/s]
PAPER_HEIGHT = 0.5             # consolidated bed height, about [m]
WATER_MU = 1.797e-3            # water at 0 C [Pa s]
# The fluid bulk modulus scales with the grain stiffness as in the paper's
# code (doc/REFERENCES.md section 4): K_w = (2.2e9/36.4e9) k_n as a pressure.
BULK_MODULUS_PER_STIFFNESS = 2.2e9 / 36.4e9


def scaled_beta(kn):
    """Fluid compressibility scaled with the grain stiffness [1/Pa]."""
    return 1.0 / (BULK_MODULUS_PER_STIFFNESS * kn)


# Profiles p(z) per shear case, for the p(z, strain) maps (Fig. 11)
PROFILES_PER_CASE = 100
# the rate series: the impermeable shear again at these multiples of mu_f
RATE_SERIES = (0.1, 0.01)

# The fluid force models shearStudy offers (solidPhase/fluidForce/type); the
# first is the template's and the default.
FLUID_FORCES = ("pressureGradient", "darcy")

# The wall time of a dry shear stage per simulated second, over a saturated one's: the quick
# size's dry stage took 0.94 (AMD EPYC, 6 Dec 2026: 310 s against 319 and 343 s) and 0.95
# (Intel Xeon, 5 Dec 2026: 215 s against 224 and 230 s) of the saturated ones' (no pressure
# equation, no fluid force); the rate-series stages cost what the impermeable one costs per
# simulated second. Used to order the stages that run side by side (shear_all).
DRY_STEP_COST = 0.94

# kc of the two saturated cases [m^2]
PERMEABLE_KC = 3.5e-13
IMPERMEABLE_KC = 3.5e-15

# what a study folder (the template of every stage) must hold; checked
# before stages/ is made in it
TEMPLATE_FILES = ("system/controlDict", "system/blockMeshDict", "constant/demProperties",
                  "constant/darcyProperties")

SIZES = {
    # Table 1 of the seed paper: meant for a GPU (days on 2 CPU cores).
    "paper": dict(box=(0.52, 0.26), cells=(12, 6), radius=(0.01, 0.01), count=9600,
                  kn=PAPER_KN, timeStep=2.14e-7, subSteps=200, wallMass=280.0,
                  sigma0=2e4, shearVelocity=PAPER_SHEAR_VELOCITY, strain=0.25,
                  rateStrain=0.25, writes=20, settleTime=1.5, consolidateTime=1.5,
                  drag=1.0, dampingRatio=0.0, preparationFriction=0.0, seed=1),
    # An eighth of the paper's bed (half in x, y and z), contacts 100 x
    # softer and lightly damped (damping ratio 0.1 of a grain pair, restitution
    # 0.73): with 8 x fewer grains the undamped rattling of the bed and the
    # top wall dominates friction and pore pressure (README.md).
    "quick": dict(box=(0.26, 0.13), cells=(6, 3), radius=(0.01, 0.01), count=1200,
                  kn=PAPER_KN / 100, timeStep=2e-6, subSteps=200, wallMass=70.0,
                  sigma0=2e4, inertialNumber=5e-4, strain=0.25, rateStrain=0.15,
                  writes=10, settleTime=1.0, consolidateTime=1.2, drag=1.0,
                  dampingRatio=0.1, preparationFriction=0.0, seed=1),
    # For the tests: a small bed, a short strain.
    "test": dict(box=(0.26, 0.0867), cells=(6, 2), radius=(0.01, 0.01), count=600,
                 kn=PAPER_KN / 100, timeStep=2e-6, subSteps=200, wallMass=47.0,
                 sigma0=2e4, inertialNumber=5e-4, strain=0.15, rateStrain=0.1,
                 writes=6, settleTime=0.8, consolidateTime=1.0, drag=1.0,
                 dampingRatio=0.1, preparationFriction=0.0, seed=3),
}

# The study's short names for the columns of the grainDiagnostics table
# (foamfiles.GRAIN_DIAGNOSTICS, doc/CASE-FORMAT.md)
DIAGNOSTICS_COLUMNS = dict(
    t="time", strain="shearStrain", tau="tau", friction="tauOverSigma0", dilation="dilation",
    wall="topWall", pMin="pMin", pMean="pMean", pMax="pMax", kinetic="kineticEnergy",
    contacts="contactsPerGrain", throughput="particleStepsPerS",
    solidVolumeError="solidVolumeError")


class ShearStudy:
    def __init__(self, study_dir, size="quick", rate_series=True, log=say,
                 fluid_force=FLUID_FORCES[0], reuse=False, jobs=None):
        if size not in SIZES:
            sys.exit(f"shearStudy: unknown size '{size}'; valid: {' '.join(SIZES)}")
        if fluid_force not in FLUID_FORCES:
            sys.exit(f"shearStudy: unknown fluid force '{fluid_force}'; "
                     f"valid: {' '.join(FLUID_FORCES)}")
        self.fluid_force = fluid_force
        self.reuse = reuse
        # shear stages run at once (shear_all): by default one per core the
        # solvers' ranks leave free, so that on 2 cores two 1-thread stages
        # run side by side (a bed of ~1000 grains gains nothing from a second
        # thread of one process: src/dem/README.md, Benchmark)
        self.jobs = jobs or default_jobs()
        # suffix of the saturated stages, the results file and the figures
        self.suffix = "" if fluid_force == FLUID_FORCES[0] else "-" + fluid_force
        self.s = dict(SIZES[size])
        self.size = size
        self.rate_series = rate_series
        self.log = log
        self.clock = StageClock("shearStudy", log)
        self.dir = os.path.abspath(study_dir)
        self.stages = os.path.join(self.dir, "stages")
        os.makedirs(self.stages, exist_ok=True)
        s = self.s
        self.dx = s["box"][0] / s["cells"][0]
        self.d = 2 * s["radius"][1]
        self.beta = scaled_beta(s["kn"])
        self.results = {"size": size, "settings": dict(s), "beta": self.beta,
                        "fluidForce": fluid_force}

    def normal_damping(self):
        """gamma_n = 2 zeta sqrt(m* k_n) for two grains of the largest radius."""
        m = 2600.0 * 4.0 / 3.0 * math.pi * self.s["radius"][1] ** 3
        return 2 * self.s["dampingRatio"] * math.sqrt(0.5 * m * self.s["kn"])

    # ---- stages ---------------------------------------------------------------------------
    def stage(self, name, app, height_cells, state_from=None):
        c = Case(os.path.basename(self.dir), name, template_root=os.path.dirname(self.dir),
                 run_root=self.stages)
        s = self.s
        block = "system/blockMeshDict"
        c.set_variable(block, "Lx", s["box"][0])
        c.set_variable(block, "Ly", s["box"][1])
        c.set_variable(block, "nx", s["cells"][0])
        c.set_variable(block, "ny", s["cells"][1])
        c.set_variable(block, "nz", height_cells)
        c.set_variable(block, "H", "%.12g" % (height_cells * self.dx))
        dem = "constant/demProperties"
        for key in ("normalStiffness", "tangentialStiffness"):
            c.set(dem, "contact/" + key, s["kn"])
        c.set(dem, "contact/normalDamping", "%.12g" % self.normal_damping())
        c.set(dem, "timeStep", s["timeStep"])
        c.set(dem, "walls/top/mass", s["wallMass"])
        c.set(dem, "walls/top/normalStress", s["sigma0"])
        c.set("system/controlDict", "application", app)
        c.set("system/controlDict", "deltaT", "%.12g" % (s["subSteps"] * s["timeStep"]))
        if app == "demFoam":
            os.remove(c.file("constant/darcyProperties"))
            os.remove(c.file("0/p"))
        return c.mesh(state_from)

    @staticmethod
    def last_time(case):
        return case.times()[-1][1]

    @staticmethod
    def diagnostics(case):
        """grainDiagnostics' columns under the study's short names."""
        d = read_columns(case.file(GRAIN_DIAGNOSTICS))
        return {short: d[name] for short, name in DIAGNOSTICS_COLUMNS.items()}

    def end_and_writes(self, case, end, writes):
        c = "system/controlDict"
        case.set(c, "endTime", "%.12g" % end)
        case.set(c, "writeInterval", "%.12g" % (end / writes))

    def profiles_every(self, case, end, count=PROFILES_PER_CASE):
        """horizontalProfiles at least count times over the case, every so
        many fluid steps (an adjustableRunTime interval would let OpenFOAM
        adjust deltaT, which must stay a whole number of DEM steps)."""
        steps = round(end / (self.s["subSteps"] * self.s["timeStep"]))
        c = "system/controlDict"
        case.set(c, "functions/profiles/writeControl", "timeStep")
        case.set(c, "functions/profiles/writeInterval", max(1, steps // count))

    def prepare(self):
        """Settle a loose lattice, then consolidate at sigma0 until at rest."""
        s = self.s
        r0, r1 = s["radius"]
        # random loose gas at solid fraction 0.25: settles into a disordered bed
        lattice_top = s["count"] * 4 / 3 * math.pi * r1**3 / (0.25 * s["box"][0] * s["box"][1])
        settle_cells = int(math.ceil((lattice_top + 2 * self.d) / self.dx))
        a = self.stage("settle", "demFoam", settle_cells)
        subprocess.run([os.path.join(BIN, "makeGrains"), "--box", str(s["box"][0]),
                        str(s["box"][1]), "--z", "0", str(lattice_top), "--radius", str(r0),
                        str(r1), "--layout", "random", "--gap", "0.02", "--count",
                        str(s["count"]), "--seed",
                        str(s["seed"]), "-o", a.file("0/grains")],
                       check=True, stdout=subprocess.DEVNULL)
        dem = "constant/demProperties"
        a.set(dem, "walls/top/mode", "fixed")
        a.set(dem, "walls/top/position", "%.12g" % (settle_cells * self.dx - 1e-3))
        a.set(dem, "viscousDrag", 0.1 * s["drag"])  # falls at about 1 m/s
        a.set(dem, "contact/friction", s["preparationFriction"])
        self.end_and_writes(a, s["settleTime"], 1)
        self.clock.run(a, "demFoam", "settle", f"{s['count']} grains settle",
                       s["settleTime"])
        grains = np.loadtxt(a.file(os.path.join(self.last_time(a), "grains")), comments="#")
        top = float(np.max(grains[:, 2] + grains[:, 3]))

        self.cells_z = int(math.ceil((top + 3 * self.d) / self.dx))
        b = self.stage("consolidate", "demFoam", self.cells_z)
        shutil.copy(a.file(os.path.join(self.last_time(a), "grains")), b.file("0/grains"))
        b.set(dem, "walls/top/position", "%.12g" % (top + 1e-3))
        b.set(dem, "viscousDrag", s["drag"])
        b.set(dem, "contact/friction", s["preparationFriction"])
        self.end_and_writes(b, s["consolidateTime"], 1)
        self.clock.run(b, "demFoam", "consolidate", f"at sigma0 = {s['sigma0']:g} Pa",
                       s["consolidateTime"])
        d = self.diagnostics(b)
        self.prepared = b.file(os.path.join(self.last_time(b), "demState"))
        self.height = float(d["wall"][-1])  # bottom wall at z = 0
        self.results["prepare"] = {
            "grains": int(len(grains)), "height": self.height,
            "kineticEnergyEnd": float(d["kinetic"][-1]),
            "contactsPerGrain": float(d["contacts"][-1]),
            "meshCellsZ": self.cells_z}

    def finished(self, name, end):
        """The stage stages/<name> if it ran to end (its last write, within
        one fluid step: endTime is written to 6 digits), else None."""
        path = os.path.join(self.stages, name)
        if not os.path.isdir(path):
            return None
        c = Case.existing(path)
        times = c.times()
        step = self.s["subSteps"] * self.s["timeStep"]
        if not times or abs(times[-1][0] - end) > step * (1 + 1e-6) or not os.path.exists(
                c.file(GRAIN_DIAGNOSTICS)):
            return None
        return c

    def reuse_prepared(self):
        """Take the packing from a finished consolidate stage of the same size
        (count, box, stiffness, time step) instead of preparing it; False if
        there is none."""
        s = self.s
        b = self.finished("consolidate", s["consolidateTime"])
        if b is None:
            return False
        state = b.file(os.path.join(self.last_time(b), "demState"))
        grains = np.loadtxt(b.file("0/grains"), comments="#", ndmin=2)
        block = b.file("system/blockMeshDict")
        dem = b.file("constant/demProperties")

        def number(path, entry):
            try:
                return read_scalar_entry(path, entry)
            except KeyError:
                return None

        pairs = ((number(block, "Lx"), s["box"][0]), (number(block, "Ly"), s["box"][1]),
                 (number(dem, "contact/normalStiffness"), s["kn"]),
                 (number(dem, "timeStep"), s["timeStep"]))
        same = len(grains) == s["count"] and all(
            a is not None and math.isclose(a, b, rel_tol=1e-9) for a, b in pairs)
        if not same or not os.path.exists(state):
            return False
        d = self.diagnostics(b)
        self.cells_z = int(number(block, "nz"))
        self.prepared = state
        self.height = float(d["wall"][-1])
        self.results["prepare"] = {
            "grains": int(len(grains)), "height": self.height,
            "kineticEnergyEnd": float(d["kinetic"][-1]),
            "contactsPerGrain": float(d["contacts"][-1]),
            "meshCellsZ": self.cells_z, "reused": True}
        self.log(f"shearStudy: reuse the packing of {b.path}")
        return True

    def reused_dry(self):
        """The summary of a finished dry stage sheared from this packing, or None."""
        v = self.shear_velocity()
        c = self.finished("dry", self.shear_end())
        # (a decomposed stage keeps its start state per rank: not reused)
        if c is None or not os.path.exists(c.file("0/demState")) or not filecmp.cmp(
                c.file("0/demState"), self.prepared, shallow=False):
            return None
        self.log(f"shearStudy: reuse the dry shear of {c.path}")
        return self.summarise(c, "dry", None, None, v)

    def shear_velocity(self):
        s = self.s
        if "shearVelocity" in s:
            return s["shearVelocity"]
        # I = gammaDot d / sqrt(sigma0/rho) (GDR MiDi 2004, doc/REFERENCES.md section 4)
        gamma_dot = s["inertialNumber"] * math.sqrt(s["sigma0"] / 2600.0) / self.d
        return gamma_dot * self.height

    def shear_end(self, velocity_factor=1.0, strain=None):
        """End time of a shear to strain (default the size's) at velocity_factor
        x the shear velocity: strain = top-layer displacement / current
        height, allowing one diameter of dilation."""
        v = self.shear_velocity() * velocity_factor
        return (strain or self.s["strain"]) * (self.height + self.d) / v

    def reference_viscosity(self):
        """mu_f of the reference velocity. Paper size: the paper's 1.797e-6.
        Smaller sizes: the velocity scaling of the paper applied so that the
        ratio of the pore-pressure diffusion time to the shear time,
        H^2 beta phi mu gammaDot / k, equals the paper's for the same kc."""
        if self.size == "paper":
            return PAPER_MU
        gamma_dot = self.shear_velocity() / self.height
        paper_gamma_dot = PAPER_SHEAR_VELOCITY / PAPER_HEIGHT
        return PAPER_MU * (PAPER_HEIGHT**2 * PAPER_BETA * paper_gamma_dot) / (
            self.height**2 * self.beta * gamma_dot)

    def shear(self, name, kc=None, mu_factor=1.0, velocity_factor=1.0, strain=None,
              threads=None):
        """One shear case from the prepared packing; kc None: dry. A
        saturated case runs in stages/<name><suffix> (fluid force model).
        threads: the stage's DEM threads (demProperties threads; None: the
        template's)."""
        s = self.s
        app = "demFoam" if kc is None else "darcyDemFoam"
        stage = name if kc is None else name + self.suffix
        c = self.stage(stage, app, self.cells_z, self.prepared)
        v = self.shear_velocity() * velocity_factor
        strain = strain or s["strain"]
        dem = "constant/demProperties"
        c.set(dem, "viscousDrag", 0)
        if threads is not None:
            c.set(dem, "threads", threads)
        c.set(dem, "walls/top/position", "%.12g" % self.height)  # as in the demState
        c.set(dem, "grainFlags",
              "{ base { flag fixed; zMax %.12g; } top { flag prescribedVelocity; zMin %.12g;"
              " velocity (%.12g 0); } }" % (self.d, self.height - self.d, v))
        mu = None
        if kc is not None:
            mu = self.reference_viscosity() * mu_factor
            props = "constant/darcyProperties"
            c.set(props, "mu", "[1 -1 -1 0 0 0 0] %.12g" % mu)
            c.set(props, "beta", "[-1 1 2 0 0 0 0] %.12g" % self.beta)
            c.set(props, "permeability/kc", kc)
            if self.suffix:  # the template's default stays untouched
                c.set(props, "solidPhase/fluidForce/type", self.fluid_force)
        end = self.shear_end(velocity_factor, strain)
        self.end_and_writes(c, end, s["writes"])
        self.profiles_every(c, end)
        self.clock.run(c, app, stage, f"shear at v = {v:.4g} m/s to strain {strain}"
                       + ("" if kc is None else f", kc = {kc:g} m^2, mu_f = {mu:.4g} Pa s")
                       + ("" if kc is None or not self.suffix
                          else f", fluid force {self.fluid_force}"), end)
        return self.summarise(c, name, kc, mu, v)

    def summarise(self, c, name, kc, mu, v):
        d = self.diagnostics(c)
        strain, friction = d["strain"], d["friction"]
        width = max(3, len(friction) // 25)
        smooth = hanning_smooth(friction, width)
        p_min, p_mean, p_max = (hanning_smooth(d[k], width) for k in ("pMin", "pMean", "pMax"))
        steady = strain >= 0.6 * strain[-1]
        steady_blocks = np.array_split(friction[steady], 8)
        early = (strain >= 0.005) & (strain <= 0.12)  # the first row is instantaneous
        if not early.any():  # a run too short for the window (smoke tests)
            early = np.ones_like(strain, dtype=bool)
        dilating = (strain >= 0.02) & (strain <= 0.1)
        out = {
            "kc": kc, "mu": mu, "shearVelocity": v,
            "inertialNumber": v / self.height * self.d / math.sqrt(self.s["sigma0"] / 2600),
            "peakFriction": float(smooth[early].max()),
            "peakFrictionStrain": float(strain[early][np.argmax(smooth[early])]),
            "dilationPhaseFriction": float(friction[dilating].mean()),
            "steadyFriction": float(friction[steady].mean()),
            "steadyFrictionStd": float(friction[steady].std()),
            # standard error of the steady mean from 8 block means
            "steadyFrictionStdErr": float(np.std([b.mean() for b in steady_blocks], ddof=1)
                                          / math.sqrt(len(steady_blocks))),
            "maxDilation": float(d["dilation"].max()),
            "pMin": float(d["pMin"].min()), "pMax": float(d["pMax"].max()),
            "pMinSmoothed": float(p_min.min()), "pMaxSmoothed": float(p_max.max()),
            "pMeanSmoothedMin": float(p_mean.min()),
            # the bed-mean pore pressure averaged while dilating: less noisy than extremes
            "pMeanWhileDilating": float(d["pMean"][dilating].mean()),
            "strainEnd": float(strain[-1]),
            "throughput": float(d["throughput"][-1]),
        }
        out.update(self.loop_rate(c))
        if kc is not None:
            k = kc * 0.35**3 / 0.65**2
            out["diffusivityAtPorosity0.35"] = k / (self.beta * 0.35 * mu)
        self.curves[name] = {"d": d, "smooth": smooth, "case": c}
        return out

    @staticmethod
    def loop_rate(c):
        """The run's grain-steps per second over its whole time loop and in
        its DEM steps alone, from the step timers' last table in the log
        (src/demCoupling/stepTimers); {} for a log without one."""
        for app in ("darcyDemFoam", "demFoam"):
            log = c.file("log." + app)
            if os.path.exists(log):
                found = re.findall(r"whole loop: (\S+) grain-steps/s \(DEM steps alone: (\S+)\)",
                                   open(log).read())
                if found:
                    return {"grainStepsPerSecond": float(found[-1][0]),
                            "demGrainStepsPerSecond": float(found[-1][1])}
        return {}

    def coupling_cost(self):
        """Grain-steps per second of the saturated shears over the dry one's
        (whole time loop): what the coupling costs per grain-step. Printed
        and kept in the results; a timing, so never asserted (stages of one
        study are not a controlled comparison: the machine's load changes
        over minutes, and a saturated bed is another bed)."""
        r = self.results
        dry = r["dry"].get("grainStepsPerSecond")
        if not dry:
            return
        ratios = {name: r[name]["grainStepsPerSecond"] / dry
                  for name in ("permeable", "impermeable")
                  if r.get(name, {}).get("grainStepsPerSecond")}
        r["saturatedOverDryGrainStepsPerSecond"] = ratios
        self.log("shearStudy: grain-steps/s of the whole loop: dry %.3g; "
                 % dry + ", ".join("%s %.3g (%.2f of dry)" % (n, dry * q, q)
                                   for n, q in ratios.items()))

    # ---- the experiment -------------------------------------------------------------------
    def shear_all(self, cases):
        """Run the shear cases {key: (name, shear() keywords)}, each from the
        prepared packing, self.jobs at a time (they depend on nothing but
        the packing); returns {key: summary}. Side by side they start in the
        order that ends the soonest by their estimated cost (run_side_by_side):
        the simulated time, a dry one's at DRY_STEP_COST of a saturated one's
        (one at a time: dearest first). With more than one job each stage's DEM runs
        on its share of the cores (demProperties threads): a stage's results
        do not depend on its thread count (the library's sums run in a fixed
        order), so they are those of one at a time."""
        def cost(key):
            keywords = cases[key][1]
            end = self.shear_end(keywords.get("velocity_factor", 1.0), keywords.get("strain"))
            return end * (1.0 if "kc" in keywords else DRY_STEP_COST)

        costs = {key: cost(key) for key in cases}
        order = sorted(cases, key=lambda key: -costs[key])  # one at a time: dearest first
        results = run_side_by_side(
            [lambda threads, key=key: self.shear(cases[key][0], threads=threads, **cases[key][1])
             for key in order], self.jobs, self.log, f"shearStudy: {len(cases)} shear stages",
            [costs[key] for key in order])
        return dict(zip(order, results))

    def shear_cases(self, checks=False):
        """run()'s shear cases {key: (stage name, shear() keywords)}, in the
        order shear_all breaks ties in: the three shears, the rate series
        (rate_series) and with checks the cases the shear test compares."""
        # the rate series and the checks' velocity-scaling pair shear to rateStrain
        rate = dict(kc=IMPERMEABLE_KC, strain=self.s["rateStrain"])
        cases = {"permeable": ("permeable", dict(kc=PERMEABLE_KC)),
                 "impermeable": ("impermeable", dict(kc=IMPERMEABLE_KC)),
                 "dry": ("dry", {})}
        for factor in RATE_SERIES if self.rate_series else ():
            cases["mu%g" % factor] = ("impermeable_mu%g" % factor, dict(rate, mu_factor=factor))
        if checks:
            # twice, not half the velocity: I = 1e-3 is still quasi-static (mu(I) moves by
            # about 5e-4 from 5e-4, far below the test's bound) and the stage costs a quarter
            # of the half-velocity one, the longest of the test's shear stages
            cases["dryDoubleVelocity"] = ("dry_double", dict(velocity_factor=2.0))
            cases["impermeableHalfMu"] = ("impermeable_halfMu", dict(rate, mu_factor=0.5))
            # the same mu_f v at eight times the velocity (mu_f/16), not at half the velocity:
            # I = 4e-3 is still quasi-static (mu(I) moves by 3e-3 from I = 5e-4), the stage
            # costs a sixteenth of the half-velocity one, and a p equation not scaling with
            # mu_f gammaDot would see a factor 8, not 2 (tests/shear/test_shear.py)
            cases["impermeableEightfoldVelocity"] = (
                "impermeable_eightfoldVelocity", dict(rate, mu_factor=1 / 16, velocity_factor=8.0))
        return cases

    def run(self, checks=False):
        """The study: packing, the three shears and (rate_series) the rate
        series; with checks also the cases the shear test compares beside
        them: the dry shear at twice the velocity (rate independence) and
        the velocity-scaling pair (impermeable at v with mu_f/2, and at 8v
        with mu_f/16)."""
        self.curves = {}
        reused = self.reuse and self.reuse_prepared()
        if not reused:
            self.prepare()
        r = self.results
        r["shearVelocity"] = self.shear_velocity()
        r["referenceViscosity"] = self.reference_viscosity()
        dry = reused and self.reused_dry()
        cases = self.shear_cases(checks)
        if dry:
            del cases["dry"]
        done = self.shear_all(cases)
        r["dry"] = dry or done["dry"]
        r["permeable"], r["impermeable"] = done["permeable"], done["impermeable"]
        if self.rate_series:
            r["rate"] = {"1": r["impermeable"]}
            for factor in RATE_SERIES:
                r["rate"]["%g" % factor] = done["mu%g" % factor]
        self.coupling_cost()
        if checks:
            for key in ("dryDoubleVelocity", "impermeableHalfMu", "impermeableEightfoldVelocity"):
                r[key] = done[key]
        self.write_results()
        return r

    def run_with_checks(self):
        """run() with the cases the shear test compares beside it."""
        return self.run(checks=True)

    def results_name(self):
        return "results%s.json" % self.suffix

    def write_results(self):
        with open(os.path.join(self.dir, self.results_name()), "w") as f:
            json.dump(self.results, f, indent=2)

    # ---- figures --------------------------------------------------------------------------
    def profiles(self, name):
        """(strain of each profile, z, p[profile, z]) from every profile the
        horizontalProfiles function object wrote (profiles_every)."""
        c = self.curves[name]["case"]
        d = self.curves[name]["d"]
        rows = []
        for t, tname in time_dirs(c.file(os.path.join("postProcessing", "profiles"))):
            path = c.file(os.path.join("postProcessing", "profiles", tname, "profiles.dat"))
            rows.append((np.interp(t, d["t"], d["strain"]), np.loadtxt(path, ndmin=2)))
        strain = np.array([r[0] for r in rows])
        z = rows[0][1][:, 0]
        p = np.array([r[1][:, 1] for r in rows])
        return strain, z, p

    def displacement_profile(self, name):
        """Mean x-displacement of the grains in bins one diameter thick at
        the last write (strain at the end of the case), from its grains file."""
        c = self.curves[name]["case"]
        g = read_vtp(grain_files(c.path)[-1][1])
        z, ux = g["position"][:, 2], g["displacement"][:, 0]
        edges = np.arange(0, self.height + self.d, self.d)
        centres, means = [], []
        for lo, hi in zip(edges[:-1], edges[1:]):
            sel = (z >= lo) & (z < hi)
            if sel.any():
                centres.append(0.5 * (lo + hi))
                means.append(ux[sel].mean())
        return np.array(centres), np.array(means), g

    def plot(self):
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        out = []
        cases = [("dry", "dry"), ("permeable", "kc = 3.5e-13 m²"),
                 ("impermeable", "kc = 3.5e-15 m²")]

        # Fig. 7: friction, dilation, pressure against strain
        fig, ax = plt.subplots(3, 3, figsize=(13, 9), sharex=True, sharey="row")
        for j, (name, title) in enumerate(cases):
            d, smooth = self.curves[name]["d"], self.curves[name]["smooth"]
            ax[0, j].plot(d["strain"], d["friction"], color="0.7", lw=0.6, label="raw")
            ax[0, j].plot(d["strain"], smooth, "k-", lw=1.5, label="Hanning smoothed")
            ax[0, j].set_title(title)
            ax[1, j].plot(d["strain"], d["dilation"], "k-")
            for key, style in (("pMin", "b-"), ("pMean", "k-"), ("pMax", "r-")):
                ax[2, j].plot(d["strain"], d[key] / 1e3, style, lw=1, label=key)
            ax[2, j].set_xlabel("shear strain [-]")
        ax[0, 0].set_ylabel("shear friction τ/σ0 [-]")
        ax[1, 0].set_ylabel("dilation [grain diameters]")
        ax[2, 0].set_ylabel("pore pressure [kPa]")
        ax[0, 0].legend(loc="lower right")
        ax[2, 2].legend(loc="lower right")
        fig.suptitle(f"Shear experiment ({self.size} size): dry, permeable, impermeable"
                     + ("" if not self.suffix else f"; fluid force {self.fluid_force}"))
        fig.tight_layout()
        out.append(self.save(fig, "shearFriction.png"))

        # Fig. 11: horizontally averaged p(z, strain)
        fig, ax = plt.subplots(1, 2, figsize=(12, 4.5), sharey=True)
        for a, (name, title) in zip(ax, cases[1:]):
            strain, z, p = self.profiles(name)
            inside = z < self.height
            m = a.pcolormesh(strain, z[inside], p[:, inside].T / 1e3, shading="nearest",
                             cmap="RdBu_r", vmin=-np.abs(p).max() / 1e3,
                             vmax=np.abs(p).max() / 1e3)
            fig.colorbar(m, ax=a, label="p [kPa]")
            a.set_title(title)
            a.set_xlabel("shear strain [-]")
        ax[0].set_ylabel("height above base [m]")
        fig.tight_layout()
        out.append(self.save(fig, "shearPressureMaps.png"))

        # Fig. 8: x-displacement profiles at the end strain
        fig, ax = plt.subplots(1, 2, figsize=(10, 5), sharey=True)
        for name, title in cases:
            z, ux, _ = self.displacement_profile(name)
            ax[0].plot(ux / ux.max(), z, "o-", ms=3, label=title)
        ax[0].set_title("different permeabilities")
        if self.rate_series and "rate" in self.results:
            for factor in ("1", "0.1", "0.01"):
                name = "impermeable" if factor == "1" else "impermeable_mu" + factor
                z, ux, _ = self.displacement_profile(name)
                ax[1].plot(ux / ux.max(), z, "o-", ms=3, label=f"μ_f × {factor}")
        ax[1].set_title("impermeable, rate series")
        for a in ax:
            a.set_xlabel("x-displacement / top displacement [-]")
            a.legend()
        ax[0].set_ylabel("height above base [m]")
        fig.tight_layout()
        out.append(self.save(fig, "shearDisplacementProfiles.png"))

        # Fig. 9: the grains coloured by x-displacement, seen along y (far ones first)
        from matplotlib.collections import PatchCollection
        from matplotlib.patches import Circle
        fig, ax = plt.subplots(1, 3, figsize=(14, 5), sharey=True)
        for a, (name, title) in zip(ax, cases):
            _, _, g = self.displacement_profile(name)
            x, y, z = g["position"].T
            order = np.argsort(y)[::-1]
            circles = PatchCollection([Circle((x[i], z[i]), g["radius"][i]) for i in order],
                                      cmap="viridis", edgecolor="k", linewidth=0.2)
            circles.set_array(g["displacement"][order, 0])
            a.add_collection(circles)
            a.set_xlim(0, self.s["box"][0])
            a.set_ylim(0, self.height + self.d)
            a.set_aspect("equal")
            a.set_title(title)
            a.set_xlabel("x [m]")
            fig.colorbar(circles, ax=a, shrink=0.7, label="x-displacement [m]")
        ax[0].set_ylabel("z [m]")
        fig.tight_layout()
        out.append(self.save(fig, "shearGrains.png"))

        # Fig. 6: peak friction against the equivalent shear velocity
        if self.rate_series and "rate" in self.results:
            fig, a = plt.subplots(figsize=(6, 4.5))
            # mu_ref stands for the paper's natural velocity 2.32e-2 m/s x 1e-3
            # (mu_f = mu_water v_natural / v_sim): mu_f x f stands for f x v_natural
            v_natural = PAPER_SHEAR_VELOCITY * PAPER_MU / WATER_MU * 3.156e7  # [m/a]
            factors = np.array([1.0, 0.1, 0.01])
            peaks = [self.results["rate"]["%g" % f]["peakFriction"] for f in factors]
            a.semilogx(factors * v_natural, peaks, "ko-", label="impermeable (kc = 3.5e-15 m²)")
            a.axhline(self.results["dry"]["peakFriction"], color="0.5", ls="--",
                      label="dry")
            a.set_xlabel("equivalent shear velocity [m/a]")
            a.set_ylabel("peak shear friction [-]")
            a.legend()
            fig.tight_layout()
            out.append(self.save(fig, "shearPeakFriction.png"))
        return out

    def save(self, fig, name):
        import matplotlib.pyplot as plt
        stem, ext = os.path.splitext(name)
        path = os.path.join(self.dir, stem + self.suffix + ext)
        fig.savefig(path, dpi=110)
        plt.close(fig)
        return path


def main(argv):
    ap = argparse.ArgumentParser(prog="shearStudy", description="Run the shear experiment of a tutorial "
                                 "directory (bin/darcydem/shear.py).")
    ap.add_argument("study_dir")
    ap.add_argument("--size", default="quick", choices=sorted(SIZES))
    ap.add_argument("--no-rate-series", action="store_true")
    ap.add_argument("--fluid-force", default=FLUID_FORCES[0], choices=FLUID_FORCES,
                    help="fluid force on the grains of the saturated stages "
                    "(solidPhase/fluidForce/type; default %(default)s, the seed's eq 12); "
                    "a non-default model suffixes the saturated stages, the results "
                    "file and the figures with -MODEL")
    ap.add_argument("--reuse-packing", action="store_true",
                    help="take the packing and the dry shear from finished stages of an "
                    "earlier run of the same size (e.g. the default model's) instead of "
                    "running them again")
    add_jobs_option(ap, "stages",
                    help="shear stages run at once after the packing, each on its share "
                    "of the cores (default: the cores over the ranks of -parallel, so "
                    "two 1-thread stages on 2 cores); 1: one after the other")
    a = parse_study_args(ap, argv)
    require_folder("shearStudy", a.study_dir, TEMPLATE_FILES)
    study = ShearStudy(a.study_dir, a.size, rate_series=not a.no_rate_series,
                       fluid_force=a.fluid_force, reuse=a.reuse_packing, jobs=a.jobs)
    results = study.run()
    figures = study.plot()
    say(json.dumps({k: v for k, v in results.items() if k != "settings"}, indent=2))
    say("shearStudy: figures " + " ".join(os.path.basename(f) for f in figures)
        + " and " + study.results_name() + " in " + study.dir)

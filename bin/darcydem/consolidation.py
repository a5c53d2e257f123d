"""Coupled consolidation of a saturated grain packing against Terzaghi
(doc/REFERENCES.md section 3), the procedure of Catalano et al. (2014):

  1. prepare   demFoam: grains settle under gravity and a stress-controlled
               lid at sigma0 (viscous drag to come to rest), then rest
               under the load steps' damping until the lid stops rocking;
  2. oedometer demFoam: dry load step sigma0 -> sigma0 + dsigma on the same
               packing gives the constrained modulus E_oed;
  3. permeability  darcyDemFoam with every grain fixed and a pressure drop
               over the packing gives its permeability k from the flux;
  4. consolidation darcyDemFoam: the same load step, saturated, drained at
               the top, closed at the base; settlement and base pressure
               against Terzaghi with c_v from E_oed and k (the load is ramped
               over RAMP seconds, smoothly, and the theory superposed over
               the ramp;
               a compressible fluid takes a share U0 of the settlement at once);
               the theory follows the case's fluidForce model (darcy:
               Terzaghi's effective stress; pressureGradient, eq. 12: the
               skeleton carries (1 - phi) of the gradient; analytic.skeleton_share);
  5. the same with half the fluid (coupling) step (beside stage 4 where the
               cores allow: run_side_by_side, --jobs).

The comparisons: settlement and base pressure against Terzaghi and against
the layered column (each mesh layer's measured E_oed, porosity and the
permeability between layers), and the undrained start (the base pressure at
the end of the ramp over the theory's).

Every stage is a case directory under <study>/stages/<stage>, made from the
template case in <study> (0/, constant/, system/); DARCYDEM_BACKEND=cpu|cuda|auto
sets the DEM backend of every stage (bin/darcydem/case.py), else the
template's 'backend' holds.
"""

import argparse
import json
import os
import shutil
import subprocess

import numpy as np

from darcydem.analytic import (consolidation_coefficient, instantaneous_settlement,
                               layered_consolidation, ramp_loaded_consolidation,
                               skeleton_share, undrained_pressure)
from darcydem.case import Case, default_jobs, run_side_by_side
from darcydem.cli import StageClock, add_jobs_option, parse_study_args, require_folder, say
from darcydem.foamfiles import (GRAIN_DIAGNOSTICS, read_columns, read_entry,
                                read_internal_field, read_probes, read_scalar_entry)

SIGMA0 = 2e4        # prepared stress on the lid [Pa]
# Load step [Pa]: a tenth of sigma0, where the skeleton answers linearly as
# Terzaghi presumes. At half of sigma0 (1e4, before) the secant E_oed was
# 8.8 MPa against 9.9 MPa at 2e3 on the same packing, and the saturated
# column drained fast at first and slowly later, no single E_oed fitting it:
# base pressure 0.12 rms off the layered column with the measured E_oed and
# k of each layer, against 0.006 at 2e3 (issue 23 item 3).
LOAD = 2e3
DRAG = 0.01         # viscous drag while preparing [N s/m]
# Background damping of the load steps (dry and wet) [N s/m]. It resists
# every grain's motion, so a grain column of n grains moving at a mean v
# holds n c v of the load it carries (dsigma d^2 = 0.16 N for d = 9 mm):
# while the load rises, the grains sink at up to 8e-4 m/s at the lid (4e-4
# mean), and at c = 0.5 (before) the drag of a column of 17 grains held 2 %
# of the load step, the base pressure lagging the theory by as much. At 0.1
# it holds 0.4 %, and the smooth ramp below leaves little vibration to damp
# (the fluid damps the rest). The same in the oedometer and the
# consolidation, so that both load the packing alike.
QUASI_STATIC_DRAG = 0.1
# Damping of the rest after the preparation [N s/m]: halves the lid's
# rocking every period.
REST_DRAG = 0.5
# The load is applied over this time [s] (five periods of the lid-on-packing
# vibration, 6 ms saturated, 8 ms dry) with a rate shaped as a raised cosine,
# share(t) = t/RAMP - sin(2 pi t/RAMP)/(2 pi), in RAMP_SEGMENTS linear pieces
# of the lid's normalStress table; the theory superposes Terzaghi over the
# same pieces. Why: a load history leaves the lid ringing with the amplitude
# |integral of its rate times exp(-i w t) dt|, w its angular frequency
# (a sum in closed form over the linear pieces). A linear ramp
# over 0.02 s, before, left 8 % of the load at the 6-ms period: the base
# pressure at the end of the ramp was 0.966 of the theory's and rose to 1.03
# half a period later. This one leaves at most 0.8 % for any period from 4
# to 10 ms (0.5 % at 8 ms, 0 at 6 ms), before damping.
RAMP = 0.03
RAMP_SEGMENTS = 30
# The prepared packing rests this long [s] under REST_DRAG before
# the load steps: the preparation (DRAG) leaves the lid rocking by ~1e-6 m,
# 5 % of the undrained settlement, and that drag halves it every period.
REST = 0.05
# what a study folder (the template of every stage) must hold; checked
# before stages/ is made in it
TEMPLATE_FILES = ("system/controlDict", "system/blockMeshDict", "constant/demProperties",
                  "constant/darcyProperties", "0/p")


def load_table(ramp, segments=RAMP_SEGMENTS):
    """(times, shares of LOAD) of the load ramp (rate a raised cosine: no
    jump in the rate or in its change at either end), the corners of its
    linear pieces."""
    times = np.linspace(0.0, ramp, segments + 1)
    return times, times / ramp - np.sin(2 * np.pi * times / ramp) / (2 * np.pi)


def load_history(table):
    """The lid's stress as an OpenFOAM table: sigma0, raised by LOAD along
    a load table (load_table), then held."""
    times, shares = table
    return "table (%s)" % " ".join("(%.9g %.9g)" % (t, SIGMA0 + LOAD * f)
                                   for t, f in zip(times, shares))


class Study:
    def __init__(self, study_dir, log=say, jobs=None):
        self.clock = StageClock("consolidationStudy", log)
        self.log = log
        # the two consolidation stages at once where the cores allow (results as one at a time)
        self.jobs = jobs or default_jobs()
        self.dir = os.path.abspath(study_dir)
        self.stages = os.path.join(self.dir, "stages")
        self.template_root = os.path.dirname(self.dir)
        self.template = os.path.basename(self.dir)
        os.makedirs(self.stages, exist_ok=True)
        self.ramp = RAMP
        self.load = load_table(RAMP)  # the lid's load history, as the theory superposes it
        # extra (file, entry, value) settings of the consolidation stages
        self.consolidation_settings = []
        self.coupling_steps = (("consolidation", 1e-4), ("consolidationHalfStep", 5e-5))
        block = os.path.join(self.dir, "system", "blockMeshDict")
        self.L = read_scalar_entry(block, "L")
        self.dz = read_scalar_entry(block, "H") / read_scalar_entry(block, "nz")
        props = os.path.join(self.dir, "constant", "darcyProperties")
        self.mu = read_scalar_entry(props, "mu")
        self.beta = read_scalar_entry(props, "beta")
        # the theory follows the case's fluid force model (analytic.skeleton_share)
        self.fluid_force = read_entry(props, "solidPhase/fluidForce/type")
        skeleton_share(0.4, self.fluid_force)  # no theory for this model: stop here

    def stage(self, name, app, state_from=None):
        c = Case(self.template, name, template_root=self.template_root, run_root=self.stages)
        c.set("system/controlDict", "application", app)
        return c.mesh(state_from)

    @staticmethod
    def last_state(case):
        t, name = case.times()[-1]
        return case.file(os.path.join(name, "demState"))

    @staticmethod
    def diagnostics(case):
        """grainDiagnostics' columns (doc/CASE-FORMAT.md) the study uses."""
        d = read_columns(case.file(GRAIN_DIAGNOSTICS))
        return {"t": d["time"], "wall": d["topWall"], "kinetic": d["kineticEnergy"],
                "pBaseMax": d["pMax"]}

    # 1 ------------------------------------------------------------------
    def prepare(self, settle_time=0.5, load_time=0.3):
        """Settle a loose lattice under gravity (lid out of the way), then
        start afresh from the settled grains with the lid just above them
        at sigma0, so that the lid does not fall onto the packing."""
        a = self.stage("settle", "demFoam")
        subprocess.run([os.path.join(os.path.dirname(os.path.dirname(__file__)), "makeGrains"),
                        "--box", str(self.L), str(self.L), "--z", "0", "0.30",
                        "--radius", "0.004", "0.005", "--gap", "0.05", "--seed", "7",
                        "-o", a.file("0/grains")], check=True, stdout=subprocess.DEVNULL)
        self.dry(a, settle_time, drag=DRAG)
        a.set("constant/demProperties", "walls/top/mode", "fixed")
        self.clock.run(a, "demFoam", "settle", "grains settle, lid fixed", settle_time)
        grains = np.loadtxt(a.file(os.path.join(a.times()[-1][1], "grains")))

        b = self.stage("prepare", "demFoam")
        shutil.copy(a.file(os.path.join(a.times()[-1][1], "grains")), b.file("0/grains"))
        self.dry(b, load_time, drag=DRAG)
        lid = float(np.max(grains[:, 2] + grains[:, 3])) + 0.001
        b.set("constant/demProperties", "walls/top/position", lid)
        b.set("constant/demProperties", "walls/top/normalStress", SIGMA0)
        self.clock.run(b, "demFoam", "prepare", f"lid at sigma0 = {SIGMA0:g} Pa", load_time)
        d = self.diagnostics(b)

        c = self.stage("rest", "demFoam", self.last_state(b))
        self.dry(c, REST, drag=REST_DRAG)
        c.set("constant/demProperties", "walls/top/normalStress", SIGMA0)
        self.clock.run(c, "demFoam", "rest", "the lid stops rocking", REST)
        rest = self.diagnostics(c)
        self.prepared = self.last_state(c)
        self.prepared_grains = c.file(os.path.join(c.times()[-1][1], "grains"))
        return {"grains": len(grains), "lidHeight": rest["wall"][-1],
                "kineticEnergyEnd": rest["kinetic"][-1],
                # the lid's rocking: its swing over the last 40 % of each stage
                "lidSwingPrepared": float(np.ptp(d["wall"][d["t"] > 0.6 * load_time])),
                "lidSwingRested": float(np.ptp(rest["wall"][rest["t"] > 0.6 * REST]))}

    @staticmethod
    def dry(case, end, drag=0.0):
        """Make a stage a dry demFoam run of the given length."""
        case.set("constant/demProperties", "viscousDrag", drag)
        case.set("system/controlDict", "endTime", end)
        case.set("system/controlDict", "writeInterval", end)
        os.remove(case.file("constant/darcyProperties"))
        os.remove(case.file("0/p"))

    # 2 ------------------------------------------------------------------
    def oedometer(self, end=0.08):
        c = self.stage("oedometer", "demFoam", self.prepared)
        self.dry(c, end, drag=QUASI_STATIC_DRAG)
        # the grains at 16 times: the mean over the tail gives the strain profile
        c.set("system/controlDict", "writeInterval", end / 16)
        c.set("constant/demProperties", "walls/top/normalStress", load_history(self.load))
        self.clock.run(c, "demFoam", "oedometer", f"dry load step +{LOAD:g} Pa", end)
        self.oedometer_case = c
        d = self.diagnostics(c)
        h0 = self.height0 = d["wall"][0]  # lid height above the base at the first step
        tail = d["wall"][d["t"] > 0.75 * end]
        settle = h0 - tail.mean()  # the lid still rocks a little on the packing
        self.E_oed = LOAD * h0 / settle
        self.oedometer_settlement = settle
        return {"E_oed": self.E_oed, "settlement": settle, "height": h0,
                "tailDrift": float(tail.max() - tail.min())}

    def stiffness_profile(self, end=0.08):
        """E_oed of each mesh layer below the lid's cell, and of the part of
        the packing in the lid's cell, from the grains' settlement in the
        oedometer (mean over the writes of its tail, t > 0.75 end): the
        load step adds the same stress LOAD at every height, so a layer
        that shortens by s is E = LOAD dz / s. The settlement at each layer
        boundary is a linear fit through the grains within dz/2 of it (its
        standard error is the measurement error); zero at the base, the
        lid's at the top."""
        z0 = np.loadtxt(self.prepared_grains, comments="#")[:, 2]
        c = self.oedometer_case
        tail = [name for t, name in c.times() if t > 0.75 * end + 1e-12]
        u = np.mean([z0 - np.loadtxt(c.file(os.path.join(n, "grains")), comments="#")[:, 2]
                     for n in tail], axis=0)
        nl = self.k_wall
        edges = [0.0]
        u_edge, u_err = [0.0], [0.0]
        for e in range(1, nl + 1):
            ze = e * self.dz
            near = np.abs(z0 - ze) < self.dz / 2
            X = np.column_stack([np.ones(near.sum()), z0[near] - ze])
            coef, res, _, _ = np.linalg.lstsq(X, u[near], rcond=None)
            cov = np.linalg.inv(X.T @ X) * float(res[0]) / (near.sum() - 2)
            edges.append(ze)
            u_edge.append(coef[0])
            u_err.append(np.sqrt(cov[0, 0]))
        edges.append(self.height0)
        u_edge.append(self.oedometer_settlement)
        u_err.append(0.0)
        edges, u_edge, u_err = (np.array(a) for a in (edges, u_edge, u_err))
        shortening = u_edge[1:] - u_edge[:-1]
        shortening_err = np.hypot(u_err[1:], u_err[:-1])
        if np.any(shortening <= 2 * shortening_err):
            raise RuntimeError("consolidation: a layer of the oedometer does not shorten "
                               "measurably: %s m" % shortening)
        E = LOAD * np.diff(edges) / shortening
        self.E_layers, self.E_layers_relErr = E, shortening_err / shortening
        return {"layerTops": edges[1:].tolist(), "E_oed": E.tolist(),
                "E_oed_relErr": self.E_layers_relErr.tolist()}

    # 3 ------------------------------------------------------------------
    def permeability(self, dp=1000.0):
        c = self.stage("permeability", "darcyDemFoam", self.prepared)
        c.set("constant/demProperties", "grainFlags", "{ all { flag fixed; } }")
        c.set("system/fvSchemes", "ddtSchemes/default", "Euler")
        # steady flow does not depend on the storage: a stiff fluid gets there
        # within the few steps of this stage
        c.set("constant/darcyProperties", "beta", 1e-12)
        c.set("system/controlDict", "endTime", 0.002)
        c.set("system/controlDict", "writeInterval", 0.002)
        c.set("0/p", "boundaryField/bottom", "{ type fixedValue; value uniform %g; }" % dp)
        self.clock.run(c, "darcyDemFoam", "permeability",
                       f"steady flow, grains fixed, dp = {dp:g} Pa", 0.002)
        name = c.times()[-1][1]
        C = c.cell_centres()
        q = read_internal_field(c.file(os.path.join(name, "qDarcy")))
        phi = read_internal_field(c.file(os.path.join(name, "porosity")))
        wall = self.diagnostics(c)["wall"][-1]
        k_wall = int(np.floor(wall / self.dz))
        drained_at = (k_wall + 0.5) * self.dz       # first cell with p fixed
        inside = C[:, 2] < (k_wall - 1) * self.dz  # cells below the lid's cell and its neighbour
        q_mean = q[inside, 2].mean()
        self.k_wall = k_wall
        self.layer_permeability(c, name, C)
        # The packing's k is that of its interior, the layer boundaries below
        # the top packing layer in series. The drained boundary the mesh
        # realises is not the fixed cell's centre: the top packing layer
        # sits against the nearly empty lid cell, whose porosity clamped at
        # porosityMax gives its faces a k ~100 times the packing's, so that
        # layer is all but drained. Its position is where the interior
        # pressure line of the steady flow reaches the drained pressure:
        # H_dr = dp / (mu q / k) from the base. (Measured: k of the whole
        # column to the fixed cell's centre 1.46e-11, interior 1.27e-11;
        # H_dr 0.130 m against the cell centre's 0.150 and the lid's 0.143.)
        self.k_column = self.mu * q_mean * drained_at / dp
        self.k = float(len(self.k_faces) - 1) / float(np.sum(1 / self.k_faces[:-1]))
        self.drainage_length = dp * self.k / (self.mu * q_mean)
        self.porosity = float(phi[inside].mean())
        return {"k": self.k, "drainageLength": self.drainage_length,
                "k_toFixedCellCentre": self.k_column, "fixedCellCentre": drained_at,
                "porosity": self.porosity, "fluxSpread": float(q[inside, 2].std() / q_mean)}

    def layer_permeability(self, c, name, C):
        """Porosity of each mesh layer below the lid's cell and the
        permeability between layers from the steady flow: the flux through
        each layer boundary (the solver's face permeability, the mean of the
        two cells' k, times the pressure difference, summed over the
        columns of cells) over the difference of the layers' mean pressures.
        At steady state every layer boundary carries the same flux; its
        spread over the boundaries is the measurement error."""
        p = read_internal_field(c.file(os.path.join(name, "p")))
        k = read_internal_field(c.file(os.path.join(name, "k")))
        phi = read_internal_field(c.file(os.path.join(name, "porosity")))
        layer = np.floor(C[:, 2] / self.dz + 1e-9).astype(int)
        column = np.round(C[:, 0] * 1e6).astype(np.int64) * 10**9 + np.round(C[:, 1] * 1e6)
        columns = np.unique(column)
        nl = self.k_wall

        def at(field, i):  # field[column, layer i], columns in a fixed order
            return np.array([field[(column == col) & (layer == i)][0] for col in columns])

        flux, k_face = [], []
        for i in range(nl):
            dp_col = at(p, i) - at(p, i + 1)
            q = np.mean(0.5 * (at(k, i) + at(k, i + 1)) * dp_col) / (self.mu * self.dz)
            flux.append(q)
            k_face.append(self.mu * q * self.dz / dp_col.mean())
        flux = np.array(flux)
        self.phi_layers = np.array([at(phi, i).mean() for i in range(nl)])
        self.k_layers = np.array([at(k, i).mean() for i in range(nl)])
        self.k_faces = np.array(k_face)
        self.k_faces_relErr = float(flux.std() / flux.mean())
        self.layer_results = {"porosity": self.phi_layers.tolist(),
                              "k_face": self.k_faces.tolist(),
                              "k": self.k_layers.tolist(),
                              "fluxSpread": self.k_faces_relErr}

    # 4, 5 ---------------------------------------------------------------
    def consolidate(self, name, dt, end, threads=None):
        """Stage 4 or 5: the saturated load step at fluid step dt; threads: its
        DEM threads (demProperties threads; None: the template's)."""
        c = self.stage(name, "darcyDemFoam", self.prepared)
        if threads is not None:
            c.set("constant/demProperties", "threads", threads)
        c.set("constant/demProperties", "walls/top/normalStress", load_history(self.load))
        c.set("constant/demProperties", "viscousDrag", QUASI_STATIC_DRAG)
        c.set("system/controlDict", "deltaT", dt)
        c.set("system/controlDict", "endTime", end)
        c.set("system/controlDict", "writeInterval", end)
        c.set("system/controlDict", "functions/baseProbe/probeLocations",
              "((%g %g %g))" % (self.L / 4, self.L / 4, self.dz / 2))
        for rel, entry, value in self.consolidation_settings:
            c.set(rel, entry, value)
        self.clock.run(c, "darcyDemFoam", name,
                       f"saturated load step +{LOAD:g} Pa, fluid step {dt:g} s", end)
        d = self.diagnostics(c)
        t, p = read_probes(c.file("postProcessing/baseProbe/0/p"))
        return d["t"], d["wall"], t, p

    def run(self):
        return self.consolidation_runs(self.measure())

    def measure(self):
        """Stages 1-3: the packing, its E_oed and k (and those of its layers)."""
        results = {"sigma0": SIGMA0, "load": LOAD}
        results["prepare"] = self.prepare()
        results["oedometer"] = self.oedometer()
        results["permeability"] = self.permeability()
        results["layers"] = dict(self.stiffness_profile(), **self.layer_results)
        return results

    def consolidation_runs(self, results):
        """Stages 4-5 on the measured packing, and the comparisons."""
        results = json.loads(json.dumps(results))
        ff = self.fluid_force
        cv = consolidation_coefficient(self.k, self.mu, self.E_oed, self.porosity, self.beta, ff)
        H = self.drainage_length
        end = 1.5 * H**2 / cv
        p0 = undrained_pressure(LOAD, self.porosity, self.beta, self.E_oed, ff)
        s_inf = LOAD * self.height0 / self.E_oed
        results["theory"] = {"fluidForce": ff, "c_v": cv, "H_dr": H, "t(Tv=1)": H**2 / cv,
                             "p0_undrained": p0, "finalSettlement": s_inf}
        curves = {}
        # both stages start from the prepared packing and depend on nothing else
        runs = run_side_by_side(
            [lambda threads, name=name, dt=dt: self.consolidate(name, dt, end, threads=threads)
             for name, dt in self.coupling_steps], self.jobs, self.log,
            f"consolidationStudy: {len(self.coupling_steps)} consolidation stages")
        for (name, dt), (tw, wall, tp, p) in zip(self.coupling_steps, runs):
            Tv = cv * tw / H**2
            U = (wall[0] - wall) / s_inf
            Tp = cv * tp / H**2
            curves[name] = {"Tv": Tv, "U": U, "Tp": Tp, "p": p[:, 0] / p0}
        ref = curves["consolidation"]
        window = (ref["Tv"] >= 0.05) & (ref["Tv"] <= 1.5)
        U0 = self.U0 = instantaneous_settlement(self.porosity, self.beta, self.E_oed, ff)
        times, shares = self.load
        self.Tramp = (cv * times / H**2, shares)
        results["theory"]["instantaneousSettlement"] = U0
        results["theory"]["Tv_ramp"] = float(self.Tramp[0][-1])
        U_exact, _ = ramp_loaded_consolidation(ref["Tv"], self.Tramp, U0)
        misfit = ref["U"] - U_exact
        half = curves.get("consolidationHalfStep", ref)
        U_half = np.interp(ref["Tv"], half["Tv"], half["U"])
        pwin = (ref["Tp"] >= 0.05) & (ref["Tp"] <= 1.5)
        _, p_exact = ramp_loaded_consolidation(ref["Tp"], self.Tramp, U0)
        results["comparison"] = {
            "U_rmsError(0.05<=Tv<=1.5)": float(np.sqrt(np.mean(misfit[window] ** 2))),
            "U_maxError(0.05<=Tv<=1.5)": float(np.max(np.abs(misfit[window]))),
            "U_at_Tv1": float(np.interp(1.0, ref["Tv"], ref["U"])),
            "basePressure_rmsError": float(np.sqrt(np.mean((ref["p"][pwin] - p_exact[pwin]) ** 2))),
            "basePressureMax/p0": float(ref["p"].max()),
            "basePressureEnd/p0": float(ref["p"][-1]),
            "halfStepMaxChange": float(np.max(np.abs(U_half[window] - ref["U"][window]))),
        }
        results["comparison"].update(self.undrained_start(ref, cv, H))
        results["comparison"].update(self.layered_comparison(ref, half, p0, s_inf, cv, H))
        results["layers"]["c_v"] = results["comparison"].pop("c_v_layers")
        self.curves = curves
        self.results = results
        with open(os.path.join(self.dir, "results.json"), "w") as f:
            json.dump(results, f, indent=2)
        return results

    def undrained_start(self, ref, cv, H):
        """The base pressure at the end of the load ramp against the theory's
        (ramp-superposed; the base has barely drained by then, so this is the
        undrained pressure p0 = dsigma/(a + phi beta E_oed), dsigma/(1 + phi
        beta E_oed) for 'darcy'). The theory's own uncertainty is that of
        p0 under the measurement error of E_oed: dp0/p0 = x/(a + x) dE/E,
        x = phi beta E, with dE/E the rms of the layers' fit errors."""
        Tend = cv * self.ramp / H**2
        _, p_th = ramp_loaded_consolidation([Tend], self.Tramp, self.U0)
        p_meas = float(np.interp(Tend, ref["Tp"], ref["p"]))
        x = self.porosity * self.beta * self.E_oed
        a = float(skeleton_share(self.porosity, self.fluid_force))
        dE = float(np.sqrt(np.mean(self.E_layers_relErr[:-1] ** 2)))
        p_lay = float(self.layered([self.ramp])[0][0]) / undrained_pressure(
            LOAD, self.porosity, self.beta, self.E_oed, self.fluid_force)
        return {"undrainedStart_measured/p0": p_meas,
                "undrainedStart_theory/p0": float(p_th[0]),
                "undrainedStart_ratio": p_meas / float(p_th[0]),
                "undrainedStart_theoryRelErr": x / (a + x) * dE,
                "undrainedStart_layered/p0": p_lay,
                "undrainedStart_layeredRatio": p_meas / p_lay}

    def layered(self, t, E=None, k_face=None):
        """The layered column's (base pressure, settlement) at times t."""
        E = self.E_layers if E is None else E
        k_face = self.k_faces if k_face is None else k_face
        p, s = layered_consolidation(t, self.dz, self.phi_layers, E[:-1], k_face, self.mu,
                                     self.beta, LOAD, self.load,
                                     drained_top=self.height0 - self.k_wall * self.dz,
                                     E_top=E[-1], fluid_force=self.fluid_force)
        return p[:, 0], s

    def layered_comparison(self, ref, half, p0, s_inf, cv, H, draws=300):
        """Base pressure and settlement against the layered column with the
        measured E_oed and k of each layer. Tolerance: three times the rms
        (over the compared window) of the standard deviation of the
        prediction under the measurement errors of E_oed (the fits' standard
        errors) and k (the spread of the steady flux over the layer
        boundaries, and the change of k with the porosity as the packing
        settles), and of the change of the measured curve with half the
        coupling step (time discretisation and the grains' chaotic noise)."""
        tp, tw = ref["Tp"] * H**2 / cv, ref["Tv"] * H**2 / cv
        pwin = (ref["Tp"] >= 0.05) & (ref["Tp"] <= 1.5)
        uwin = (ref["Tv"] >= 0.05) & (ref["Tv"] <= 1.5)
        p_lay, _ = self.layered(tp[pwin])
        _, s_lay = self.layered(tw[uwin])
        # Kozeny-Carman k ~ phi^3/(1 - phi)^2: the settling packing loses
        # dphi = (1 - phi) LOAD/E of porosity, dk/k = (3/phi + 2/(1 - phi)) dphi
        phi = self.phi_layers
        dk_settling = np.max((3 / phi + 2 / (1 - phi)) * (1 - phi) * LOAD / self.E_layers[:-1])
        k_rel = float(np.hypot(self.k_faces_relErr, dk_settling))
        rng = np.random.default_rng(1)
        ps, ss = [], []
        for _ in range(draws):
            E = self.E_layers * (1 + self.E_layers_relErr * rng.standard_normal(len(self.E_layers)))
            k = self.k_faces * (1 + k_rel * rng.standard_normal(len(self.k_faces)))
            ps.append(self.layered(tp[pwin], E, k)[0])
            ss.append(self.layered(tw[uwin], E, k)[1])
        p_sd = np.sqrt(np.mean(np.std(ps, axis=0) ** 2)) / p0
        s_sd = np.sqrt(np.mean(np.std(ss, axis=0) ** 2)) / s_inf
        p_half = np.interp(ref["Tp"][pwin], half["Tp"], half["p"])
        p_step = np.sqrt(np.mean((p_half - ref["p"][pwin]) ** 2))
        U_half = np.interp(ref["Tv"][uwin], half["Tv"], half["U"])
        U_step = np.sqrt(np.mean((U_half - ref["U"][uwin]) ** 2))
        # the spread a single c_v can have: c_v of each layer (its cells' k,
        # Kozeny-Carman of their porosity), Terzaghi with the smallest and largest
        cv_layers = consolidation_coefficient(self.k_layers, self.mu, self.E_layers[:-1], phi,
                                              self.beta, self.fluid_force)
        Tp = ref["Tp"][pwin]
        U0 = self.U0
        T_table, shares = self.Tramp
        p_lo = ramp_loaded_consolidation(Tp * cv_layers.min() / cv,
                                         (T_table * cv_layers.min() / cv, shares), U0)[1]
        p_hi = ramp_loaded_consolidation(Tp * cv_layers.max() / cv,
                                         (T_table * cv_layers.max() / cv, shares), U0)[1]
        self.layered_curves = {"Tp": ref["Tp"][pwin], "p": p_lay / p0,
                               "Tv": ref["Tv"][uwin], "U": s_lay / s_inf}
        return {
            "layered_basePressure_rmsError": float(np.sqrt(np.mean(
                (ref["p"][pwin] - p_lay / p0) ** 2))),
            "layered_basePressure_tolerance": float(3 * np.hypot(p_sd, p_step)),
            "layered_basePressure_measurementSd": float(p_sd),
            "layered_basePressure_halfStepRms": float(p_step),
            "layered_U_rmsError": float(np.sqrt(np.mean((ref["U"][uwin] - s_lay / s_inf) ** 2))),
            "layered_U_tolerance": float(3 * np.hypot(s_sd, U_step)),
            "layered_U_measurementSd": float(s_sd),
            "layered_k_relErr": k_rel,
            "c_v_layers": cv_layers.tolist(),
            "terzaghi_cvMinMax_basePressure_rmsDistance": float(np.sqrt(np.mean(
                (p_hi - p_lo) ** 2))),
        }

    def plot(self):
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4.5))
        Tv = np.linspace(0, 1.5, 300)
        U_th, p_th = ramp_loaded_consolidation(Tv, self.Tramp, self.U0)
        a1.plot(Tv, U_th, "k-", lw=2, label="Terzaghi (ramp load, U0 at once)")
        a2.plot(Tv, p_th, "k-", lw=2, label="Terzaghi, base")
        for name, style in (("consolidation", "-"), ("consolidationHalfStep", "--")):
            c = self.curves[name]
            lab = "darcyDemFoam" + (", half coupling step" if "Half" in name else "")
            a1.plot(c["Tv"], c["U"], style, label=lab)
            a2.plot(c["Tp"], c["p"], style, label=lab)
        cmp_ = self.results["comparison"]
        a1.set_xlabel("T_v = c_v t / H_dr^2")
        a1.set_ylabel("settlement / final settlement U")
        a1.set_title("Settlement; rms misfit %.3f" % cmp_["U_rmsError(0.05<=Tv<=1.5)"])
        a1.set_xlim(0, 1.5)
        lay = getattr(self, "layered_curves", None)
        if lay:
            a1.plot(lay["Tv"], lay["U"], "r:", lw=2, label="layered column, measured E_oed, k")
            a2.plot(lay["Tp"], lay["p"], "r:", lw=2, label="layered column, measured E_oed, k")
        a1.legend()
        a2.set_xlabel("T_v")
        a2.set_ylabel("excess pore pressure at the base / p0")
        a2.set_title("Base pressure; p0 = dsigma/(%s + phi beta E)"
                     % ("1" if self.fluid_force == "darcy" else "(1-phi)"))
        a2.set_xlim(0, 1.5)
        a2.legend()
        fig.tight_layout()
        out = os.path.join(self.dir, "consolidation.png")
        fig.savefig(out, dpi=120)
        return out


def main(argv):
    ap = argparse.ArgumentParser(
        prog="consolidationStudy",
        description="Run the consolidation study of a tutorial directory "
                    "(bin/darcydem/consolidation.py): prepare, oedometer, permeability, "
                    "consolidation twice; writes results.json and consolidation.png there "
                    "and each stage's case under STUDY_DIR/stages.")
    ap.add_argument("study_dir", metavar="STUDY_DIR",
                    help="the template case (0/, constant/, system/), e.g. "
                         "tutorials/darcyDemFoam/consolidation")
    add_jobs_option(ap, "stages",
                    help="consolidation stages at once (default: one per core that the "
                         "solvers' MPI ranks leave free; 1: one after the other, same results)")
    a = parse_study_args(ap, argv)
    require_folder("consolidationStudy", a.study_dir, TEMPLATE_FILES)
    study = Study(a.study_dir, jobs=a.jobs)
    results = study.run()
    out = study.plot()
    say(json.dumps(results, indent=2))
    say(f"consolidationStudy: wrote {out} and results.json")

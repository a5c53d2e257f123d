"""A liquid-fluidised bed with nsDemFoam (tutorials/nsDemFoam/fluidisedBed;
the short version with its assertions: tests/ns/test_fluidised_bed.py).

2000 glass beads (d = 1 mm, 2500 kg/m^3) in water (1000 kg/m^3, 1e-3 Pa s),
a column 9 x 9 mm periodic in x and y, 3 x 3 x 30 cells of h = 3 mm,
ErgunWenYu drag. The grains (a loose random packing, bin/makeGrains) settle
in still water for 0.8 s onto a DEM wall two cells above the inlet (the
fluid passes it), then the inflow (a table on the inlet U) steps through
the velocities, each held for STAGE s; everything is averaged over the last
AVERAGE s of each stage (writes every 0.02 s).

Measured per velocity: the pressure drop dp = p(first cell layer, below the
bed) - p(outlet) (p minus hydrostatic); the bed height H = 2 (mean z of the
grains - z_wall) and the porosity 1 - N V_g/(A H); the interior -dp/dz (the
cell layers at least 1.5 cells inside the bed) and the deposited porosity
there. References: Ergun's drop times H at the packed bed's porosity; the
buoyant weight per area W = N V_g (rho_p - rho) g/A; u_mf from Ergun at the
packed porosity and from Wen & Yu (1966); Richardson & Zaki's
U/u_t = phi^n with u_t Schiller-Naumann's terminal velocity and n from
Garside & Al-Dibouni (1977) (and Rowe 1987, dashed).
"""

import argparse
import json
import math
import os
import re
import shutil
import subprocess
import time

import numpy as np

from darcydem import drag
from darcydem.case import Case, PROJECT
from darcydem.cli import parse_study_args, say
from darcydem.foamfiles import read_vtp

D, RHO_P, RHO, MU, G = 1e-3, 2500.0, 1000.0, 1e-3, 9.81
N_GRAINS = 2000
L, NXY, NZ, H_CELL = 0.009, 3, 30, 0.003
AREA = L * L
Z_WALL = 0.006
SETTLE = 0.8
STAGE = 1.0
AVERAGE = 0.4
VELOCITIES = (0.002, 0.004, 0.006, 0.008, 0.010, 0.012, 0.015, 0.018, 0.027, 0.036, 0.045)


def solve(f, lo, hi):
    """The root of f between lo and hi (f(lo), f(hi) of opposite sign), by
    bisection to round-off."""
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if f(lo) * f(mid) <= 0.0:
            hi = mid
        else:
            lo = mid
    return 0.5 * (lo + hi)


def inflow_table(velocities, stage):
    rows = [(0.0, 0.0), (SETTLE, 0.0)]
    for k, u in enumerate(velocities):
        start = SETTLE + k * stage
        rows += [(start + 1e-3, u), (start + stage, u)]
    rows.append((1000.0, velocities[-1]))
    return "table (%s)" % " ".join("(%r (0 0 %r))" % r for r in rows)


def richardson_zaki():
    u_t = drag.terminal_velocity("ErgunWenYu", RHO_P, RHO, MU, D, G)
    re_t = RHO * u_t * D / MU
    a = 0.1 * re_t**0.9
    n_gad = (5.1 + 2.7 * a) / (1 + a)
    n_rowe = (4.7 + 0.41 * re_t**0.75) / (1 + 0.175 * re_t**0.75)
    return u_t, re_t, n_gad, n_rowe


def run(study_dir, velocities, stage):
    stages = os.path.join(study_dir, "stages")
    os.makedirs(stages, exist_ok=True)
    template = os.path.join(stages, "template")
    shutil.rmtree(template, ignore_errors=True)
    os.makedirs(template)
    for sub in ("0", "constant", "system"):
        shutil.copytree(os.path.join(study_dir, sub), os.path.join(template, sub))
    c = Case("template", "run", template_root=stages, run_root=stages)
    shutil.rmtree(template)
    subprocess.run([f"{PROJECT}/bin/makeGrains", "--box", str(L), str(L),
                    "--z", str(Z_WALL + D / 2), "0.085", "--radius", str(D / 2),
                    "--count", str(N_GRAINS), "--layout", "random", "--periodic", "xy",
                    "--seed", "1", "-o", c.file("0/grains")],
                   check=True, stdout=subprocess.DEVNULL)
    text = open(c.file("0/U")).read()
    text = re.sub(r"table \(\(0 \(0 0 0\)\) \(100 \(0 0 0\)\)\)",
                  inflow_table(velocities, stage), text)
    open(c.file("0/U"), "w").write(text)
    c.set("system/controlDict", "endTime", SETTLE + len(velocities) * stage)
    c.run("blockMesh")
    say(f"fluidisedBedStudy: nsDemFoam, {len(velocities)} velocities x {stage} s ...")
    start = time.time()
    c.run("nsDemFoam")
    return c, time.time() - start


def measure(c, velocities, stage):
    rows = {u: [] for u in velocities}
    for t, name in c.times():
        for k, u in enumerate(velocities):
            end = SETTLE + (k + 1) * stage
            if end - AVERAGE - 1e-9 <= t <= end + 1e-9:
                p = c.field(name, "p").reshape(NZ, NXY * NXY).mean(axis=1)
                eps = c.field(name, "porosity").reshape(NZ, NXY * NXY).mean(axis=1)
                v = read_vtp(c.file(f"postProcessing/grains/grains_{name}.vtp"))
                z = v["position"][:, 2]
                height = 2.0 * (z.mean() - Z_WALL)
                volume = v["volume"].sum()
                on_wall = int(np.sum(z - v["radius"] < Z_WALL + 1e-5))
                rows[u].append((p, eps, height, volume, on_wall))
    out = []
    centres = (np.arange(NZ) + 0.5) * H_CELL
    for u in velocities:
        r = rows[u]
        p = np.mean([q[0] for q in r], axis=0)
        eps = np.mean([q[1] for q in r], axis=0)
        height = float(np.mean([q[2] for q in r]))
        volume = r[0][3]
        k = np.nonzero((centres >= Z_WALL + 1.5 * H_CELL)
                       & (centres <= Z_WALL + height - 1.5 * H_CELL))[0]
        out.append(dict(U=u, dp=float(p[0]), dp_std=float(np.std([q[0][0] for q in r])),
                        height=height, porosity=1.0 - volume / (AREA * height),
                        interior_gradient=float((p[k[0]] - p[k[-1]])
                                                / (centres[k[-1]] - centres[k[0]])),
                        interior_porosity=float(eps[k[0]:k[-1] + 1].mean()),
                        grains_on_wall=float(np.mean([q[4] for q in r])), samples=len(r)))
    return out, volume


def main(argv):
    ap = argparse.ArgumentParser(prog="fluidisedBedStudy", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("study_dir", help="the tutorial directory (0/, constant/, system/); "
                    "results.json and fluidisedBed.png there, the run in stages/run")
    ap.add_argument("--velocities", type=float, nargs="+", default=list(VELOCITIES))
    ap.add_argument("--stage", type=float, default=STAGE)
    args = parse_study_args(ap, argv)
    study_dir = os.path.abspath(args.study_dir)
    c, wall = run(study_dir, args.velocities, args.stage)
    points, volume = measure(c, args.velocities, args.stage)

    weight = volume * (RHO_P - RHO) * G / AREA
    load = (RHO_P - RHO) * G
    packed = points[0]
    phi_mf, h_mf = packed["porosity"], packed["height"]
    phi_in = packed["interior_porosity"]
    u_mf_ergun = solve(lambda u: drag.ergun(phi_mf, u, RHO, MU, D) - (1 - phi_mf) * load,
                       1e-6, 1.0)
    u_mf_ergun_in = solve(lambda u: drag.ergun(phi_in, u, RHO, MU, D) - (1 - phi_in) * load,
                          1e-6, 1.0)
    ar = RHO * (RHO_P - RHO) * G * D**3 / MU**2
    u_mf_wen_yu = (math.sqrt(33.7**2 + 0.0408 * ar) - 33.7) * MU / (RHO * D)
    u_t, re_t, n_gad, n_rowe = richardson_zaki()
    # u_mf measured, the interior: the packed interior gradient (Ergun's
    # U-dependence through it) meets (1 - phi)(rho_p - rho) g
    g0 = packed["interior_gradient"] / drag.ergun(phi_in, packed["U"], RHO, MU, D)
    u_mf_interior = solve(lambda u: g0 * drag.ergun(phi_in, u, RHO, MU, D)
                          - (1 - phi_in) * load, 1e-6, 1.0)
    # and the classical construction on the whole drop: the packed branch
    # through the first point meets the mean drop of the points above 2 u_mf
    plateau = float(np.mean([q["dp"] for q in points if q["U"] > 2 * u_mf_ergun]))
    d0 = packed["dp"] / drag.ergun(phi_mf, packed["U"], RHO, MU, D)
    u_mf_whole = solve(lambda u: d0 * drag.ergun(phi_mf, u, RHO, MU, D) - plateau, 1e-6, 1.0)

    for q in points:
        q["dp_over_W"] = q["dp"] / weight
        q["ergun_dp"] = drag.ergun(phi_mf, q["U"], RHO, MU, D) * h_mf
        q["richardson_zaki_porosity"] = (q["U"] / u_t)**(1 / n_gad)
        q["rowe_porosity"] = (q["U"] / u_t)**(1 / n_rowe)
    say(f"{'U m/s':>7} {'dp Pa':>8} {'dp/W':>6} {'Ergun H':>8} {'H mm':>7} {'phi':>6} "
        f"{'phi RZ':>6} {'-dpdz in':>8} {'(1-e)dg':>8} {'eps in':>6} {'wall':>5}")
    for q in points:
        say(f"{q['U']:7.4f} {q['dp']:8.3f} {q['dp_over_W']:6.3f} {q['ergun_dp']:8.2f} "
            f"{q['height'] * 1e3:7.3f} {q['porosity']:6.4f} {q['richardson_zaki_porosity']:6.4f} "
            f"{q['interior_gradient']:8.1f} {(1 - q['interior_porosity']) * load:8.1f} "
            f"{q['interior_porosity']:6.4f} {q['grains_on_wall']:5.1f}")
    results = dict(
        grains=N_GRAINS, d=D, rho_p=RHO_P, rho=RHO, mu=MU, g=G, buoyant_weight_per_area=weight,
        packed_porosity=phi_mf, packed_height=h_mf, packed_interior_porosity=phi_in,
        u_mf_ergun=u_mf_ergun, u_mf_ergun_interior=u_mf_ergun_in, u_mf_wen_yu=u_mf_wen_yu,
        u_mf_measured_interior=u_mf_interior, u_mf_measured_whole_drop=u_mf_whole,
        plateau=plateau, archimedes=ar, u_t=u_t, re_t=re_t, n_garside_al_dibouni=n_gad,
        n_rowe=n_rowe, run_seconds=wall, stage=args.stage, average=AVERAGE, points=points)
    with open(os.path.join(study_dir, "results.json"), "w") as f:
        json.dump(results, f, indent=2)
    say(f"W {weight:.3f} Pa; packed porosity {phi_mf:.4f} (interior deposit {phi_in:.4f}), "
        f"H {h_mf * 1e3:.2f} mm; u_mf Ergun {u_mf_ergun:.5f} (interior porosity "
        f"{u_mf_ergun_in:.5f}), Wen-Yu {u_mf_wen_yu:.5f}, measured: interior "
        f"{u_mf_interior:.5f}, whole drop {u_mf_whole:.5f} m/s; u_t {u_t:.4f} m/s, Re_t "
        f"{re_t:.1f}, n {n_gad:.3f} (Rowe {n_rowe:.3f}); nsDemFoam {wall:.0f} s")
    plot(study_dir, points, results)


def plot(study_dir, points, r):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    u = np.array([q["U"] for q in points])
    uu = np.linspace(0, u.max() * 1.05, 300)
    fig, (a, b) = plt.subplots(2, 1, figsize=(7, 8), sharex=True)
    a.plot(u * 1e3, [q["dp"] for q in points], "ko", label="nsDemFoam: p(inlet) - p(outlet)")
    a.plot(uu * 1e3, drag.ergun(r["packed_porosity"], uu, RHO, MU, D) * r["packed_height"],
           "b--", label=f"Ergun x H, packed porosity {r['packed_porosity']:.3f}")
    a.axhline(r["buoyant_weight_per_area"], color="r", label="buoyant weight per area")
    for val, style, lab in ((r["u_mf_ergun"], "b:", "u_mf Ergun"),
                            (r["u_mf_wen_yu"], "g:", "u_mf Wen & Yu"),
                            (r["u_mf_measured_whole_drop"], "k:", "u_mf measured (whole drop)")):
        a.axvline(val * 1e3, linestyle=style[1:], color=style[0], label=lab)
    a.set_ylim(0, 1.3 * r["buoyant_weight_per_area"])
    a.set_ylabel("pressure drop [Pa]")
    a.legend(fontsize=8, loc="lower right")
    a.set_title("Liquid-fluidised bed: 2000 glass beads d = 1 mm in water")
    b.plot(u * 1e3, [q["height"] * 1e3 for q in points], "ko", label="nsDemFoam: 2 (mean z - z_wall)")
    vol = r["buoyant_weight_per_area"] / ((RHO_P - RHO) * G)
    ufl = uu[uu > r["u_mf_ergun"]]
    b.plot(ufl * 1e3, vol / (1 - (ufl / r["u_t"])**(1 / r["n_garside_al_dibouni"])) * 1e3,
           "r-", label=f"Richardson-Zaki, n = {r['n_garside_al_dibouni']:.2f} "
           "(Garside & Al-Dibouni)")
    b.plot(ufl * 1e3, vol / (1 - (ufl / r["u_t"])**(1 / r["n_rowe"])) * 1e3,
           "r--", label=f"Richardson-Zaki, n = {r['n_rowe']:.2f} (Rowe)")
    b.axhline(r["packed_height"] * 1e3, color="b", linestyle="--", label="packed bed")
    b.axvline(r["u_mf_ergun"] * 1e3, color="b", linestyle=":")
    b.set_xlabel("inflow (superficial) velocity [mm/s]")
    b.set_ylabel("bed height [mm]")
    b.legend(fontsize=8, loc="upper left")
    fig.tight_layout()
    out = os.path.join(study_dir, "fluidisedBed.png")
    fig.savefig(out, dpi=120)
    say(f"fluidisedBedStudy: wrote {out} and {os.path.join(study_dir, 'results.json')}")

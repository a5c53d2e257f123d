"""A short snow settlement run (tutorials/demFoam/snowSettlement through
settlementStudy, size 'test': 250 capsules in a box half the paper's in x
and z, contracted with bonds freezing on contact, then contact viscosities
0.16 and 1 MPa s settling under the free lid for 0.5 s, and 0.16 MPa s with
bending creep off). Checks the lid's momentum balance, the conservation of
grain mass in the density, the bond bookkeeping, that settlement and each
creep mechanism slow with the contact viscosity, and that stress builds up
in the mode whose creep is off."""

import os
import shutil

import numpy as np
import pytest

from darcydem.case import PROJECT, TEST_RUNS
from darcydem.foamfiles import read_grains
from darcydem import settlement as S

TUTORIAL = os.path.join(PROJECT, "tutorials", "demFoam", "snowSettlement")


@pytest.fixture(scope="module")
def study():
    return run_study("snow_settlement")


def run_study(name):
    """The study at size 'test' in tests/run/name: (study, runs)."""
    path = os.path.join(TEST_RUNS, name)
    shutil.rmtree(path, ignore_errors=True)
    shutil.copytree(TUTORIAL, path, ignore=shutil.ignore_patterns(
        "stages", "*.png", "results.json", "log.*"))
    s = S.SettlementStudy(path, "test")
    runs = s.run(creep_off=("bend",))
    return s, runs


def test_lid_stress_is_the_lid_weight(study):
    """Momentum of the lid (mass m, free along z): m dv/dt = F - m g, so over
    an interval the mean grain force on the lid is m g + m (v1 - v0)/(t1 - t0).
    Over the last 0.1 s (the lid has caught up with the sample 0.4 s in), the
    mean lid stress P_zz is its weight over the area within the measured
    inertial term plus 4 standard errors of the mean of the sampled stress
    (from 10 block means: the force is sampled every 100 DEM steps)."""
    s, runs = study
    box = s.s["box"]
    area = box[0] * box[1]
    weight = S.LID_MASS * S.GRAVITY / area
    for r in runs:
        m = r.t >= r.t[-1] - 0.1
        t, pzz, v = r.t[m], r.pzz[m], r.p["lidVelocity"][m]
        inertial = S.LID_MASS * abs(v[-1] - v[0]) / (t[-1] - t[0]) / area
        blocks = [b.mean() for b in np.array_split(pzz, 10)]
        stderr = np.std(blocks, ddof=1) / np.sqrt(len(blocks))
        print(f"nu_s {r.nu:g}: mean P_zz {pzz.mean():.5g} Pa, lid weight/area {weight:.5g} Pa,"
              f" inertial term {inertial:.2e} Pa, standard error {stderr:.2e} Pa")
        assert abs(pzz.mean() - weight) <= inertial + 4 * stderr


def test_density_is_grain_mass_over_enclosed_volume(study):
    """density x (x gap) Ly (lid - bottom) is the grains' mass (V = pi r^2 2h
    + 4/3 pi r^3 each, ice 917 kg/m^3) at every row: mass is conserved and
    the density is the enclosed one. Tolerance 1e-12: round-off (the .dat
    files carry 17 digits)."""
    s, runs = study
    g = read_grains(os.path.join(s.stages, "contract", "0", "grains"))
    r, h = g["radius"], g["coreHalfLength"]
    mass = S.ICE_DENSITY * np.sum(np.pi * r**2 * 2 * h + 4 / 3 * np.pi * r**3)
    for run in runs:
        w = run.w
        volume = ((w["right_position"] - w["left_position"]) * s.s["box"][1]
                  * (w["lid_position"] - w["bottom_position"]))
        error = np.max(np.abs(run.density * volume / mass - 1))
        print(f"nu_s {run.nu:g}: grain mass {mass:.6e} kg, largest relative error of"
              f" density x volume {error:.1e}")
        assert error < 1e-12


def test_bond_bookkeeping(study):
    """Bonds are neither lost nor made silently: intact(t) - intact(0) =
    formed since 0 - broken since 0 at every row (integers, exact). The
    coordination number counts every intact bond's pair: at least
    2 intact / N."""
    s, runs = study
    n = s.s["count"]
    for r in runs:
        intact = r.p["bondsIntact"]
        balance = intact - intact[0] - (r.formed - r.broken)
        coordination = r.p["coordinationNumber"]
        print(f"nu_s {r.nu:g}: intact {intact[0]:.0f} -> {intact[-1]:.0f}, formed"
              f" {r.formed[-1]:.0f}, broken {r.broken[-1]:.0f}; coordination"
              f" {coordination[0]:.3f} -> {coordination[-1]:.3f}")
        assert np.all(balance == 0)
        assert np.all(coordination >= 2 * intact / n - 1e-12)


def test_settlement_slows_with_contact_viscosity(study):
    """The paper's first finding: the settlement rate falls as the contact
    viscosity rises. Both runs start from the same sample; their lids first
    fall onto it under the gravity ramp alike (inertia, not creep, sets the
    first 0.3 s), then the viscous skeleton takes the weight. Over the last
    0.1 s the lid of the 6.25 x more viscous run sinks more slowly (the
    ratio of the mean strain rates is printed: linear creep would give 6.25
    in steady creep, which 0.5 s does not reach at 1 MPa s, tau_bend 0.11 s),
    and both samples are denser than they started."""
    s, runs = study
    rates = []
    for r in runs:
        m = r.t >= r.t[-1] - 0.1
        lid, bottom = r.p["lidPosition"][m], r.w["bottom_position"][m]
        rates.append((lid[0] - lid[-1]) / (r.t[m][-1] - r.t[m][0]) / np.mean(lid - bottom))
        print(f"nu_s {r.nu:g}: strain rate over the last 0.1 s {rates[-1]:.4g} 1/s; density"
              f" {r.density[0]:.2f} -> {r.density[-1]:.2f} kg/m^3")
        assert r.density[-1] > r.density[0]
    print(f"strain rate ratio {rates[0] / rates[1]:.2f} for a viscosity ratio"
          f" {runs[1].nu / runs[0].nu:.2f}")
    assert rates[0] > rates[1]


def test_each_creep_mechanism_slows_with_contact_viscosity(study):
    """The paper's Figs 8a-c: shear, bending and twisting creep all act, and
    each is slower at the higher contact viscosity. bondCreep's sums over
    the last 0.1 s (the lid resting on the skeleton, as above), per intact
    bond: every mechanism creeps in both runs, and less in the 6.25 x more
    viscous one; the sums never decrease; no normal creep (no power law in
    the tutorial). The ratios are printed (Maxwell creep at the same loads
    would give 6.25)."""
    s, runs = study
    increments = []
    for r in runs:
        assert r.creep is not None, "bondCreep's creep.dat missing or out of step"
        m = r.t >= r.t[-1] - 0.1
        bonds = np.mean(r.creep["bondsIntact"][m])
        step = {k: (r.creep[k][m][-1] - r.creep[k][m][0]) / bonds
                for k in ("shear", "bend", "twist")}
        increments.append(step)
        print(f"nu_s {r.nu:g}: creep per bond over the last 0.1 s: shear {step['shear']:.4e} m,"
              f" bend {step['bend']:.4e} rad, twist {step['twist']:.4e} rad")
        for k in ("normal", "shear", "bend", "twist"):
            assert np.all(np.diff(r.creep[k]) >= 0)
        assert np.all(r.creep["normal"] == 0)
        assert all(v > 0 for v in step.values())
    for k in ("shear", "bend", "twist"):
        print(f"{k}: ratio {increments[0][k] / increments[1][k]:.2f} for a viscosity ratio"
              f" {runs[1].nu / runs[0].nu:.2f}")
        assert increments[0][k] > increments[1][k]


def test_stress_builds_up_in_the_mode_without_creep(study):
    """The paper: with a creep mechanism off, stress builds up in the mode
    that cannot creep. Bending creep off at 0.16 MPa s (tau_bend = nu_s / E
    = 0.018 s): a Maxwell element's bending stress stays below k I theta_dot
    tau / (I / r_b) whatever the rotation, an elastic one grows with the
    rotation itself, so over the 0.4 s after the gravity ramp the ratio is
    of order t / tau = 22 for a steady rotation. The bonds' mean bending
    stress |M_b| r_b / I at the end (their .vtp) with bending creep off is
    more than twice that of the run with every creep on, from the same
    sample: without the effect the two runs would be the same (ratio 1
    exactly, the runs are deterministic), rotations that reverse bring it
    below the steady estimate, and 2 asks for a clear build-up. The bending
    creep sum stays what the preparation left (to round-off, 1e-12), the
    other modes' creep grows. The numbers are printed."""
    s, runs = study
    reference = next(r for r in runs if r.nu == min(x.nu for x in runs))
    bend_off = s.variants[0]
    assert bend_off.creep_off == "bend"
    t_on, on = reference.mode_stresses()
    t_off, off = bend_off.mode_stresses()
    assert t_on[-1] == t_off[-1] == pytest.approx(reference.t[-1])
    ratio = off["bend"][-1] / on["bend"][-1]
    print(f"mean bending stress at {t_on[-1]:g} s: {off['bend'][-1]:.4g} Pa with bending creep"
          f" off, {on['bend'][-1]:.4g} Pa with it on (ratio {ratio:.1f}); twist"
          f" {off['twist'][-1]:.4g} against {on['twist'][-1]:.4g} Pa, shear {off['shear'][-1]:.4g}"
          f" against {on['shear'][-1]:.4g} Pa")
    assert ratio > 2
    # constant to round-off: a bond that breaks moves its creep from the intact bonds' sum
    # to the broken ones', which adds in another order
    bend_sum = bend_off.creep["bend"]
    assert np.all(np.abs(bend_sum - bend_sum[0]) <= 1e-12 * bend_sum[0])
    assert bend_off.creep["shear"][-1] > bend_off.creep["shear"][0]
    assert bend_off.creep["twist"][-1] > bend_off.creep["twist"][0]


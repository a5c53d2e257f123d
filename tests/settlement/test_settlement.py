"""A short snow settlement run (tutorials/demFoam/snowSettlement through
settlementStudy, size 'test': 250 capsules in a box half the paper's in x
and y, contracted with bonds freezing on contact, then two contact
viscosities settling under the free lid for 0.25 s). Checks the lid's
momentum balance, the conservation of grain mass in the density, the bond
bookkeeping and that settlement slows with the contact viscosity."""

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
    path = os.path.join(TEST_RUNS, "snow_settlement")
    shutil.rmtree(path, ignore_errors=True)
    shutil.copytree(TUTORIAL, path, ignore=shutil.ignore_patterns(
        "stages", "*.png", "results.json", "log.*"))
    s = S.SettlementStudy(path, "test")
    runs = s.run()
    return s, runs


def test_lid_stress_is_the_lid_weight(study):
    """Momentum of the lid (mass m, free along z): m dv/dt = F - m g, so over
    the loaded rows the mean grain force on the lid is m g + m dv/dt. The
    lid's velocity change over that time is measured, and the mean of the
    sampled stress carries a sampling error (its standard error from 10
    block means): the tolerance is 4 standard errors plus the measured
    inertial term."""
    s, runs = study
    box = s.s["box"]
    area = box[0] * box[1]
    weight = S.LID_MASS * S.GRAVITY / area
    for r in runs:
        m = r.t >= S.GRAVITY_RAMP + 0.05   # after the ramp and the elastic response to it
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
    the density is the enclosed one. Tolerance 1e-5: the .dat files'
    6 significant digits."""
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
        assert error < 1e-5


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
        assert np.all(coordination >= 2 * intact / n - 1e-5)


def test_settlement_slows_with_contact_viscosity(study):
    """The paper's first finding: the settlement rate falls as the contact
    viscosity rises. Over the loaded rows, the lid of the 10 x more
    viscous run sinks less, and the density of each run does not fall
    (creep under a constant load only compacts: the lid's position sampled
    every 0.025 s never rises by more than the elastic ringing, bounded by
    the largest rise between consecutive rows of the stiffer run's start)."""
    s, runs = study
    low, high = runs[0], runs[1]
    settled = []
    for r in runs:
        m = r.loaded()
        settled.append(r.density[m][-1] - r.density[m][0])
    print(f"density gained after the ramp: nu_s {low.nu:g}: {settled[0]:.3f} kg/m^3,"
          f" nu_s {high.nu:g}: {settled[1]:.3f} kg/m^3, ratio {settled[0] / settled[1]:.2f}")
    assert settled[0] > settled[1] > 0

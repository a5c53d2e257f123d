"""The shear experiment of Damsgaard et al. (2015), short version: 600
grains, strain 0.15, through the same study script as the tutorial
(tutorials/darcyDemFoam/shear, bin/darcydem/shear.py, size 'test'), real
demFoam / darcyDemFoam runs from one prepared packing.

References:
- Dry steady-state friction of monodisperse spheres with interparticle
  friction 0.5 in quasi-static shear: 0.3 to 0.6. Published: about 0.38 in
  homogeneous simple shear of frictional spheres (Chialvo, Sun & Sundaresan
  2012, Phys. Rev. E 85, 021305, mu_p >= 0.4), and about 0.4 to 0.55 in
  boundary-driven shear cells like this one (Damsgaard et al. 2013, JGR
  Earth Surface 118, 2230; the seed paper's dry run, Fig. 7).
- Saturated: pore-pressure diffusion against dilation (seed section 3): the
  impermeable case (kc = 3.5e-15 m^2) reaches a lower minimum p than the
  permeable one (kc = 3.5e-13), whose friction while it dilates (strain
  0.02 to 0.1) stays close to the dry friction.
- Rate: dry friction at two velocities in the quasi-static range (I = 5e-4
  and 1e-3) agrees (mu(I) of GDR MiDi 2004 / Jop et al. 2006, mu_s 0.38,
  mu_2 0.64, I_0 0.28, moves by 5e-4 between them: far below the bound, a
  few hundredths); in the impermeable rate series (mu_f x 1, 0.1, 0.01:
  1, 10, 100 x slower) the minimum p rises with the falling equivalent
  velocity.
- Velocity scaling: the p equation depends on mu_f and the shear rate only
  through mu_f gammaDot (write it in terms of strain), so shearing at v with
  mu_f/2 and at 8v with mu_f/16 agree while the grains stay quasi-static
  (I = 5e-4 and 4e-3: mu(I) moves by 3e-3): compared is the bed-mean p
  averaged while dilating (strain 0.02 to 0.1).
Pressures are compared Hanning-smoothed over strain, as the paper smooths
the friction: the raw extremes are single-cell, single-sample spikes of the
grains' rattling.

Noise and margins. A 600-grain bed is chaotic: another packing (makeGrains
seed) or another round-off gives another trajectory. The spread of every
compared quantity was measured over packings from several seeds and the
same seed under two code revisions (tests/shear/measure_noise.py; numbers
in tests/README.md). A comparison is asserted only where its effect is at
least K = 3.09 noise standard deviations from the bound, so that chance
flips it with probability below 1e-3 (one-sided normal quantile; 3.29 for
a two-sided bound). Pressure minima vary by a common factor between
trajectories while their ratios barely move, so they are compared as
ratios. Impermeable above permeable friction while dilating (strain 0.02
to 0.1) is asserted since seven trajectories put it 3.5 SD above zero; the
other friction differences between the saturated cases (peak friction;
rate series: faster above slower) are 0.06 to 0.17 with a noise of about
half their size: printed, not asserted (a bed and strain large enough to
resolve them cost more than this suite's budget)."""

import json
import math

import pytest

from darcydem.case import copy_tutorial
from darcydem.shear import ShearStudy

K_ONE_SIDED = 3.09  # P(N(0,1) < -3.09) = 1e-3
K_TWO_SIDED = 3.29  # P(|N(0,1)| > 3.29) = 1e-3
# Noise (standard deviations) from the few trajectories of tests/README.md,
# rounded up (1.2 to 3 x the sample values) for the uncertainty of a
# standard deviation estimated from 2 to 4 samples:
DRY_FRICTION_SD = 0.05        # dry steady friction (measured 0.036)
LOG_P_RATIO_SD = 0.2          # ln of a ratio of two smoothed pressure minima (0.11-0.16)
PERM_DRY_FRICTION_SD = 0.022  # permeable minus dry friction while dilating (rms 0.018)
IMP_PERM_FRICTION_SD = 0.033  # impermeable minus permeable friction while dilating (0.027)
SCALING_LN_SD = 0.1           # ln of the velocity-scaling pair's ratio of mean p (rms 0.076)


@pytest.fixture(scope="module")
def study():
    path = copy_tutorial("shear", "shear")
    s = ShearStudy(path, "test")
    r = s.run_with_checks()
    s.plot()
    print(json.dumps({k: v for k, v in r.items() if k != "settings"}, indent=1))
    return r


def test_packing_is_prepared(study):
    p = study["prepare"]
    assert p["grains"] == 600
    assert p["contactsPerGrain"] > 3.5  # a dense, jammed packing
    assert all(study[c]["inertialNumber"] < 1e-3 for c in ("dry", "permeable", "impermeable"))


def test_dry_steady_friction_in_published_range(study):
    # the range is the physics; one 600-grain run knows its friction only
    # to DRY_FRICTION_SD: assert that the range is not excluded by more
    # than the two-sided margin
    mu = study["dry"]["steadyFriction"]
    margin = K_TWO_SIDED * DRY_FRICTION_SD
    print(f"dry steady friction {mu:.3f}; published 0.3-0.6, noise margin {margin:.3f}")
    assert 0.3 - margin < mu < 0.6 + margin


def test_impermeable_pressure_lower_than_permeable(study):
    perm, imp, dry = study["permeable"], study["impermeable"], study["dry"]
    sigma0 = study["settings"]["sigma0"]
    ratio = imp["pMinSmoothed"] / perm["pMinSmoothed"]
    print(f"smoothed pMin permeable {perm['pMinSmoothed']:.0f} Pa "
          f"({perm['pMinSmoothed'] / sigma0:.3f} sigma0), impermeable "
          f"{imp['pMinSmoothed']:.0f} Pa: ratio {ratio:.1f}; smoothed pMax permeable "
          f"{perm['pMaxSmoothed']:.0f} Pa")
    print(f"not asserted (within noise): peak friction (Hanning-smoothed) dry "
          f"{dry['peakFriction']:.3f}, permeable {perm['peakFriction']:.3f}, impermeable "
          f"{imp['peakFriction']:.3f}")
    # impermeable at least twice as low: ln(ratio) is LN_RATIO_IMP_PERM
    # (mean of the trajectories), K_ONE_SIDED * LOG_P_RATIO_SD above ln 2 and more
    assert perm["pMinSmoothed"] < 0 and ratio > 2


def test_impermeable_stronger_than_permeable_while_dilating(study):
    # the seed paper's dilatant strengthening: suction in the impermeable bed
    # raises the effective stress while it dilates. Seven trajectories: mean
    # difference 0.115, sample SD 0.027; 0.115 is K_ONE_SIDED * IMP_PERM_FRICTION_SD
    # above 0 and more (3.5 SD)
    perm, imp, dry = study["permeable"], study["impermeable"], study["dry"]
    diff = imp["dilationPhaseFriction"] - perm["dilationPhaseFriction"]
    print(f"friction while dilating (strain 0.02-0.1) dry {dry['dilationPhaseFriction']:.3f}, "
          f"permeable {perm['dilationPhaseFriction']:.3f}, impermeable "
          f"{imp['dilationPhaseFriction']:.3f}: impermeable - permeable {diff:.3f}")
    assert diff > 0


def test_permeable_friction_follows_dry(study):
    perm, dry = study["permeable"], study["dry"]
    diff = perm["dilationPhaseFriction"] - dry["dilationPhaseFriction"]
    bound = K_TWO_SIDED * PERM_DRY_FRICTION_SD
    print(f"friction while dilating permeable - dry {diff:.3f} (noise bound {bound:.3f})")
    assert abs(diff) < bound


def test_dry_friction_is_rate_independent(study):
    # |difference| within a two-sided 1e-3 quantile of the block-mean
    # standard errors; each SE comes from 8 blocks (7 degrees of freedom,
    # 14 for the pair), so Student's t: 4.14
    a, b = study["dry"], study["dryDoubleVelocity"]
    err = math.hypot(a["steadyFrictionStdErr"], b["steadyFrictionStdErr"])
    diff = abs(a["steadyFriction"] - b["steadyFriction"])
    print(f"dry steady friction {a['steadyFriction']:.3f} (I = {a['inertialNumber']:.1e}) "
          f"and {b['steadyFriction']:.3f} (I = {b['inertialNumber']:.1e}): difference "
          f"{diff:.3f}, 4.14 standard errors (block means) {4.14 * err:.3f}")
    assert diff < 4.14 * err


def test_impermeable_pressure_rises_with_slower_equivalent_velocity(study):
    rate = study["rate"]
    p = [rate[f]["pMinSmoothed"] for f in ("1", "0.1", "0.01")]
    f = [rate[f]["dilationPhaseFriction"] for f in ("1", "0.1", "0.01")]
    peak = [rate[f]["peakFriction"] for f in ("1", "0.1", "0.01")]
    print(f"mu_f x 1, 0.1, 0.01: smoothed pMin {p}, ratios {p[0] / p[1]:.2f}, "
          f"{p[1] / p[2]:.2f}; not asserted (within noise): friction while dilating {f}, "
          f"peak friction {peak}")
    # ln(p[0]/p[1]), ln(p[1]/p[2]) are LN_RATIOS_RATE (mean of the
    # trajectories), over K_ONE_SIDED * LOG_P_RATIO_SD above 0
    assert p[0] < p[1] < p[2] < 0


def test_velocity_scaling_equivalence(study):
    # |ln ratio| of the mean p while dilating within K_TWO_SIDED noise SDs (0.33:
    # a factor 1.39). A p equation in which mu_f and gammaDot do not enter as
    # their product would see a factor 8 in one of them: at the rate series'
    # p ~ (mu_f gammaDot)^0.53 (ln(p_x1 / p_x0.1) = 1.23) a factor 3 in p, ln 1.1.
    # The extremes (smoothed minimum p and minimum of the mean p) are noisier
    # (rms of ln 0.13 against 0.076): printed, not asserted.
    a, b = study["impermeableHalfMu"], study["impermeableEightfoldVelocity"]
    for key in ("pMinSmoothed", "pMeanSmoothedMin"):
        print(f"{key} at v with mu/2 {a[key]:.0f} Pa, at 8v with mu/16 {b[key]:.0f} Pa: "
              f"ln ratio {math.log(a[key] / b[key]):.3f} (not asserted)")
    key = "pMeanWhileDilating"
    ln_ratio = math.log(a[key] / b[key])
    bound = K_TWO_SIDED * SCALING_LN_SD
    print(f"{key} at v with mu/2 {a[key]:.0f} Pa (I = {a['inertialNumber']:.1e}), at 8v with "
          f"mu/16 {b[key]:.0f} Pa (I = {b['inertialNumber']:.1e}): ln ratio {ln_ratio:.3f}, "
          f"bound {bound:.3f}")
    assert a[key] < 0 and b[key] < 0 and abs(ln_ratio) < bound

"""The shear experiment of Damsgaard et al. (2015), short version: 600
grains, strain 0.15, through the same study script as the tutorial
(tutorials/darcyDemFoam/shear, bin/darcydem/shear.py, size 'test'), real
demFoam / darcyDemFoam runs from one prepared packing.

References and tolerances (measured values in tests/README.md):
- Dry steady-state friction of monodisperse spheres with interparticle
  friction 0.5 in quasi-static shear: 0.3 to 0.6. Published: about 0.38 in
  homogeneous simple shear of frictional spheres (Chialvo, Sun & Sundaresan
  2012, Phys. Rev. E 85, 021305, mu_p >= 0.4), and about 0.4 to 0.55 in
  boundary-driven shear cells like this one (Damsgaard et al. 2013, JGR
  Earth Surface 118, 2230; the seed paper's dry run, Fig. 7).
- Saturated: pore-pressure diffusion against dilation (seed section 3): the
  impermeable case (kc = 3.5e-15 m^2) reaches a lower minimum p and a
  higher friction while it dilates (mean over strain 0.02 to 0.1) than the
  permeable one (kc = 3.5e-13), whose p stays within 5 % of sigma0 and whose friction stays within 0.05
  of the dry friction.
- Rate: dry friction at two velocities in the quasi-static range (I = 5e-4
  and 2.5e-4) agrees within 3 standard errors of the difference (from block
  means); in the
  impermeable rate series (mu_f x 1, 0.1, 0.01: 1, 10, 100 x slower) the
  minimum p and the friction while dilating fall with the equivalent
  velocity.
- Velocity scaling: the p equation depends on mu_f and the shear rate only
  through mu_f gammaDot (write it in terms of strain), so shearing at v with
  mu_f/2 and at v/2 with mu_f agree (minimum p and minimum of the mean p,
  Hanning-smoothed like the friction, within 20 %).
Pressures are compared Hanning-smoothed over strain, as the paper smooths
the friction: the raw extremes are single-cell, single-sample spikes of the
grains' rattling."""

import json
import math

import pytest

from darcydem.case import copy_tutorial
from darcydem.shear import IMPERMEABLE_KC, ShearStudy


@pytest.fixture(scope="module")
def study():
    path = copy_tutorial("shear", "shear")
    s = ShearStudy(path, "test")
    r = s.run()
    r["dryHalfVelocity"] = s.shear("dry_half", velocity_factor=0.5)
    r["impermeableHalfMu"] = s.shear("impermeable_halfMu", kc=IMPERMEABLE_KC, mu_factor=0.5,
                                     strain=s.s["rateStrain"])
    r["impermeableHalfVelocity"] = s.shear("impermeable_halfVelocity", kc=IMPERMEABLE_KC,
                                           velocity_factor=0.5, strain=s.s["rateStrain"])
    s.write_results()
    s.plot()
    print(json.dumps({k: v for k, v in r.items() if k != "settings"}, indent=1))
    return r


def test_packing_is_prepared(study):
    p = study["prepare"]
    assert p["grains"] == 600
    assert p["contactsPerGrain"] > 3.5  # a dense, jammed packing
    assert all(study[c]["inertialNumber"] < 1e-3 for c in ("dry", "permeable", "impermeable"))


def test_dry_steady_friction_in_published_range(study):
    mu = study["dry"]["steadyFriction"]
    print(f"dry steady friction {mu:.3f}")
    assert 0.3 < mu < 0.6


def test_impermeable_lower_pressure_and_stronger_than_permeable(study):
    perm, imp, dry = study["permeable"], study["impermeable"], study["dry"]
    sigma0 = study["settings"]["sigma0"]
    print(f"smoothed pMin permeable {perm['pMinSmoothed']:.0f} Pa, impermeable "
          f"{imp['pMinSmoothed']:.0f} Pa; smoothed pMax permeable {perm['pMaxSmoothed']:.0f} Pa;"
          f" friction while dilating dry {dry['dilationPhaseFriction']:.3f}, permeable "
          f"{perm['dilationPhaseFriction']:.3f}, impermeable {imp['dilationPhaseFriction']:.3f}")
    assert imp["pMinSmoothed"] < 2 * perm["pMinSmoothed"] < 0
    assert abs(perm["pMinSmoothed"]) < 0.05 * sigma0
    assert abs(perm["pMaxSmoothed"]) < 0.05 * sigma0
    print(f"peak friction (Hanning-smoothed) dry {dry['peakFriction']:.3f}, permeable "
          f"{perm['peakFriction']:.3f}, impermeable {imp['peakFriction']:.3f}")
    assert imp["peakFriction"] > perm["peakFriction"]
    assert imp["dilationPhaseFriction"] > perm["dilationPhaseFriction"]
    assert abs(perm["dilationPhaseFriction"] - dry["dilationPhaseFriction"]) < 0.05


def test_dry_friction_is_rate_independent(study):
    a, b = study["dry"], study["dryHalfVelocity"]
    err = math.hypot(a["steadyFrictionStdErr"], b["steadyFrictionStdErr"])
    diff = abs(a["steadyFriction"] - b["steadyFriction"])
    print(f"dry steady friction {a['steadyFriction']:.3f} (I = {a['inertialNumber']:.1e}) "
          f"and {b['steadyFriction']:.3f} (I = {b['inertialNumber']:.1e}): difference "
          f"{diff:.3f}, 3 standard errors (block means) {3 * err:.3f}")
    assert diff < 3 * err


def test_impermeable_strength_rises_with_equivalent_velocity(study):
    rate = study["rate"]
    p = [rate[f]["pMinSmoothed"] for f in ("1", "0.1", "0.01")]
    f = [rate[f]["dilationPhaseFriction"] for f in ("1", "0.1", "0.01")]
    peak = [rate[f]["peakFriction"] for f in ("1", "0.1", "0.01")]
    print(f"mu_f x 1, 0.1, 0.01: smoothed pMin {p}, friction while dilating {f}, "
          f"peak friction {peak}")
    assert p[0] < p[1] < p[2] < 0
    assert f[0] > f[2]
    assert peak[0] > peak[2]


def test_velocity_scaling_equivalence(study):
    a, b = study["impermeableHalfMu"], study["impermeableHalfVelocity"]
    for key in ("pMinSmoothed", "pMeanSmoothedMin"):
        rel = abs(a[key] - b[key]) / abs(b[key])
        print(f"{key} at v with mu/2 {a[key]:.0f} Pa, at v/2 with mu {b[key]:.0f} Pa: "
              f"relative difference {rel:.3f}")
        assert rel < 0.2

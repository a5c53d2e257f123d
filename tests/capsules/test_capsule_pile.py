"""The tutorial tutorials/demFoam/capsulePile run as it is (Allrun): 300
grains, half capsules, dropped onto a wall and settled. The pile comes to
rest on the wall, nothing sinks through it, the deposit conserves the
grains' true volume, and the figure is made."""

import os
import shutil
import subprocess

import numpy as np

from darcydem.case import PROJECT, TEST_RUNS, apply_backend
from darcydem.foamfiles import capsule_axes, grain_files, read_vtp

TUTORIAL = os.path.join(PROJECT, "tutorials", "demFoam", "capsulePile")
G = 9.81


def test_capsule_pile_settles_on_the_wall():
    """The tutorial on one process: see settled_pile_checks."""
    settled_pile_checks("capsule_pile")


def settled_pile_checks(name, *allrun_args):
    """Run the tutorial's Allrun (with allrun_args) in tests/run/name, then:
    At rest: the rms over the grains of their speed at the end below 1e-3
    of sqrt(g r) (the speed of a grain rearranging by its own radius under
    gravity; the drop reaches about 100 sqrt(g r)), where a grain touching
    the wall counts with the speed of its lowest point, its slip on the
    wall: a sphere rolling on the wall without slipping feels no force
    (the contact law has no rolling resistance) and rolls on for ever, a
    steady motion, not a pile still settling (a few of the spheres that
    reach the wall do; their speed, mm/s, depends on how the fall went).
    On the wall: the lowest point of every grain (z - r - h |a_z|) no
    deeper than 1 % of r below it (a contact under the pile's weight
    compresses by about 0.05 % of r). Deposit: sum of (1 - porosity)
    V_cell equals the grains' true volume at every diagnostics row
    (round-off, 1e-12)."""
    path = os.path.join(TEST_RUNS, name)
    shutil.rmtree(path, ignore_errors=True)
    shutil.copytree(TUTORIAL, path, ignore=shutil.ignore_patterns(
        "*.png", "log.*", "VTK", "processor*", "postProcessing"))
    apply_backend(path)
    subprocess.run([os.path.join(path, "Allrun"), *allrun_args], check=True,
                   stdout=subprocess.DEVNULL)
    assert os.path.getsize(os.path.join(path, "capsulePile.png")) > 10000

    d = np.loadtxt(os.path.join(path, "postProcessing/grainDiagnostics/0/grainDiagnostics.dat"),
                   comments="#")
    t, g = grain_files(path)[-1]
    g = read_vtp(g)
    r = g["radius"]
    scale = np.sqrt(G * np.mean(r))
    axes = capsule_axes(g["orientation"])
    # the lowest point: the lower end of the core, then r down
    offset = -g["coreHalfLength"][:, None] * np.sign(axes[:, 2])[:, None] * axes
    offset[:, 2] -= r
    lowest = g["position"][:, 2] + offset[:, 2]
    on_wall = lowest < 0.01 * r
    speed = np.linalg.norm(np.where(on_wall[:, None],
                                    g["velocity"] + np.cross(g["angularVelocity"], offset),
                                    g["velocity"]), axis=1)
    rms = np.sqrt(np.mean(speed**2))
    rolling = np.sum(on_wall & (np.linalg.norm(g["velocity"], axis=1) > 1e-3 * scale))
    volume_error = np.max(np.abs(d[:, 12]))
    print(f"t = {t}: rms speed (slip on the wall) {rms:.2e} m/s = {rms / scale:.1e} sqrt(g r);"
          f" {rolling} grains rolling on the wall faster than that bound; peak kinetic"
          f" energy {d[:, 9].max():.3e} J, end {d[-1, 9]:.3e} J; contacts per grain"
          f" {d[-1, 10]:.2f}; deepest grain {-lowest.min() / np.mean(r):.2e} r below the"
          f" wall; solid volume error {volume_error:.1e}")
    assert rms < 1e-3 * scale
    assert lowest.min() > -0.01 * np.min(r)
    assert volume_error < 1e-12
    return path

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
    """At rest: the grains' rms speed at the end below 1e-3 of sqrt(g r)
    (the speed of a grain rearranging by its own radius under gravity;
    the drop reaches about 100 sqrt(g r)). On the wall: the lowest point
    of every grain (z - r - h |a_z|) no deeper than 1 % of r below it (a
    contact under the pile's weight compresses by about 0.05 % of r).
    Deposit: sum of (1 - porosity) V_cell equals the grains' true volume
    at every diagnostics row (round-off, 1e-12)."""
    path = os.path.join(TEST_RUNS, "capsule_pile")
    shutil.rmtree(path, ignore_errors=True)
    shutil.copytree(TUTORIAL, path, ignore=shutil.ignore_patterns("*.png", "log.*", "VTK",
                                                               "postProcessing"))
    apply_backend(path)
    subprocess.run([os.path.join(path, "Allrun")], check=True, stdout=subprocess.DEVNULL)
    assert os.path.getsize(os.path.join(path, "capsulePile.png")) > 10000

    d = np.loadtxt(os.path.join(path, "postProcessing/grainDiagnostics/0/grainDiagnostics.dat"),
                   comments="#")
    t, g = grain_files(path)[-1]
    g = read_vtp(g)
    r = g["radius"]
    rms = np.sqrt(np.mean(np.sum(g["velocity"]**2, axis=1)))
    scale = np.sqrt(G * np.mean(r))
    lowest = g["position"][:, 2] - r - g["coreHalfLength"] * np.abs(capsule_axes(g["orientation"])[:, 2])
    volume_error = np.max(np.abs(d[:, 12]))
    print(f"t = {t}: rms speed {rms:.2e} m/s = {rms / scale:.1e} sqrt(g r); peak kinetic"
          f" energy {d[:, 9].max():.3e} J, end {d[-1, 9]:.3e} J; contacts per grain"
          f" {d[-1, 10]:.2f}; deepest grain {-lowest.min() / np.mean(r):.2e} r below the"
          f" wall; solid volume error {volume_error:.1e}")
    assert rms < 1e-3 * scale
    assert lowest.min() > -0.01 * np.min(r)
    assert volume_error < 1e-12

"""The shell-driven tutorials with `./Allrun -parallel` (etc/RunFunctions:
decomposePar with the tutorial's decomposeParDict, mpirun -np 2 <solver>
-parallel, reconstructPar), held to what their one-process runs are held to.
(The study-driven tutorials take the same option through their study
scripts: test_consolidation_parallel.py, test_settlement_parallel.py.)"""

import os
import shutil
import subprocess
import sys

import numpy as np
import pytest

from darcydem.analytic import drained_column_cell_mean
from darcydem.case import PROJECT, TEST_RUNS
from darcydem.foamfiles import read_internal_field, read_probes, read_scalar_entry, time_dirs

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "capsules"))
from test_capsule_pile import settled_pile_checks  # noqa: E402

pytestmark = pytest.mark.skipif(shutil.which("mpirun") is None,
                                reason="needs mpirun (openmpi-bin)")


def test_capsule_pile_on_two_ranks():
    """The capsule pile dropped and settled on two ranks (the 4 x 4 cell
    columns cut in two along x, the grains crossing the cut as they fall):
    at rest on the wall, nothing through it, the grains' volume deposited
    exactly (the serial test's criteria), and the log shows the split."""
    path = settled_pile_checks("capsule_pile_parallel", "-parallel")
    log = open(os.path.join(path, "log.demFoam")).read()
    assert "Grains split over 2 ranks as the mesh: 2 x 1 boxes" in log
    assert os.path.isdir(os.path.join(path, "processor1"))


def run_drained_column(name, *allrun_args):
    path = os.path.join(TEST_RUNS, name)
    shutil.rmtree(path, ignore_errors=True)
    shutil.copytree(os.path.join(PROJECT, "tutorials", "darcyDemFoam", "drainedColumn"), path,
                    ignore=shutil.ignore_patterns("*.png", "log.*", "VTK", "processor*",
                                                  "postProcessing", "[1-9]*", "0.*"))
    subprocess.run([os.path.join(path, "Allrun"), *allrun_args], check=True,
                   stdout=subprocess.DEVNULL)
    assert os.path.getsize(os.path.join(path, "drainedColumn.png")) > 10000
    return path


def test_drained_column_tutorial_serial_and_parallel():
    """The drained-column tutorial as a user runs it, on one process and with
    -parallel (its 2 x 2 x 50 cells cut in two along x): the base pressure
    follows the cell-averaged Terzaghi series within 1 % of p0 (the D2
    criterion of tests/README.md) in both, and the two runs' fields agree
    within what the pressure solver leaves: the decomposed PCG
    preconditions each part alone, so each step's solution differs by up
    to about cond(A) x tolerance (A = I + D dt Laplacian: cond about
    1 + 4 D dt/dz^2), and diffusion does not amplify old differences, so
    after n steps at most n cond(A) tolerance p0."""
    serial = run_drained_column("drained_column_tutorial")
    parallel = run_drained_column("drained_column_tutorial_parallel", "-parallel")
    log = open(os.path.join(parallel, "log.darcyDemFoam")).read()
    assert "nProcs : 2" in log

    props = os.path.join(serial, "constant", "darcyProperties")
    mu, beta = read_scalar_entry(props, "mu"), read_scalar_entry(props, "beta")
    k = read_scalar_entry(props, "permeability/k")
    phi = read_internal_field(os.path.join(serial, "0", "porosity"))[0]
    p0 = read_internal_field(os.path.join(serial, "0", "p"))[0]
    mesh = os.path.join(serial, "system", "blockMeshDict")
    H, nz = read_scalar_entry(mesh, "H"), int(read_scalar_entry(mesh, "nz"))
    control = os.path.join(serial, "system", "controlDict")
    dt = read_scalar_entry(control, "deltaT")
    tol = read_scalar_entry(os.path.join(serial, "system", "fvSolution"), "solvers/p/tolerance")
    D, dz = k / (beta * phi * mu), H / nz
    for path in (serial, parallel):
        t, p = read_probes(os.path.join(path, "postProcessing", "probes", "0", "p"))
        exact = np.array([drained_column_cell_mean(H - dz, H, D * ti / H**2, H) for ti in t])
        error = np.max(np.abs(p[:, 0] / p0 - exact))
        print(f"{os.path.basename(path)}: base pressure within {error:.2e} p0 of the series")
        assert error < 0.01

    times = time_dirs(serial)
    assert [name for _, name in times] == [name for _, name in time_dirs(parallel)]
    steps = round(times[-1][0] / dt)
    bound = steps * (1 + 4 * D * dt / dz**2) * tol * p0
    difference = max(np.max(np.abs(read_internal_field(os.path.join(serial, name, "p"))
                                   - read_internal_field(os.path.join(parallel, name, "p"))))
                     for _, name in times)
    print(f"serial vs 2 ranks: p within {difference:.2e} Pa over {steps} steps"
          f" (bound {bound:.2e} Pa)")
    assert difference <= bound

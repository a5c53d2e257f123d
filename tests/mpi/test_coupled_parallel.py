"""darcyDemFoam on a decomposed case (decomposePar, mpirun -np 2 ... -parallel,
reconstructPar) against the same case on one process.

Case: tests/cases/grainColumn (256 grains settling in a saturated periodic
column of 2 x 2 x 10 cells under a stress-controlled lid), cut in x into two
parts of 1 x 2 x 10 cells (method simple, n (2 1 1)); the grains' boxes
follow the parts. The grains start from the case directory's serial grains
file (a serial packing starts a parallel run).

- Agreement with one process: the two runs part only by round-off (a pair
  across the cut is evaluated on both ranks, the deposit's cell sums and the
  function objects' sums are added in another order), which the settling
  grains amplify. The tolerance is that growth, measured as in
  tests/coupled/test_backend_agreement.py: a second one-process run starts
  from grains moved by eta0 = (DEM steps) x 4 ulp of the largest coordinate;
  while differences stay small they grow linearly, so the parallel run
  cannot end further from the one-process run than that one (grain
  positions, p, porosity at the end; the grainDiagnostics columns of the
  grains at every row, with the rounding of their sums over the ranks,
  2 (n - 1) eps relative). The perturbed run also solves p with another
  solver (PBiCGStab/FDIC for PCG/DIC; the parallel solve preconditions each
  rank's part alone). Not asserted: the early rows' pMean and pMax, which
  differ from one process by up to 3.3e-12 relative (5.5e-9 Pa of 1673 Pa
  at t = 3e-4 s, against 2.3e-9 Pa between the serial runs): there the
  solves' round-off (eps times the condition number of the nearly
  incompressible pressure equation) is not yet below the grains'
  difference; by the end the field differs by 2e-6 Pa against 9.7e-4 Pa.
- Conservation: every grain written once (ids 0..255 in the gathered grains
  file), the deposited solid volume equal to the grains' at every row of
  grainDiagnostics within the rounding of its sums.
- A restart from a decomposed time (each rank's demState) continues bit for
  bit as the uninterrupted parallel run.
- nsDemFoam (tests/cases/fixedBed: fixed grains, flow through them, 2 x 2 x
  26 cells) on 2 ranks: U and p within the distance of a one-process run
  with another pressure solver (the parallel solve differs from the serial
  one by its path, not by physics), porosity within the rounding of the
  deposit's sums.
- Misuse: mpirun without -parallel, a decomposition the grains cannot follow
  (cut in z): each stops with its message.
"""
import math
import os
import re
import shutil
import subprocess

import numpy as np
import pytest

from darcydem.case import Case
from darcydem.foamfiles import read_dem_state, read_internal_field, write_dem_state

MPIRUN = shutil.which("mpirun")
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMP_NUM_THREADS="1")
END = 0.03          # s: 300 fluid steps of 1e-4 s
DEM_STEPS = 3000    # DEM time step 1e-5 s
LENGTH = 0.1        # the column's periodic side (blockMeshDict $L)
EPS = np.finfo(float).eps
P_TOLERANCE = 1e-15  # the pressure solver's (normalised residual)

pytestmark = pytest.mark.skipif(MPIRUN is None, reason="needs mpirun (openmpi-bin)")

DECOMPOSE = """FoamFile {{ version 2.0; format ascii; class dictionary; object decomposeParDict; }}
numberOfSubdomains 2;
method simple;
coeffs {{ n ({n}); }}
"""


def column(name, end=END, write_steps=None, grains=None, cut="2 1 1", other_solver=False):
    c = Case("grainColumn", name)
    c.set("constant/demProperties", "threads", 1)
    c.set("system/controlDict", "endTime", end)
    c.set("system/controlDict", "writeInterval", write_steps or round(end / 1e-4))
    c.set("system/controlDict", "writeFormat", "ascii")
    c.set("system/fvSolution", "solvers/p/tolerance", P_TOLERANCE)
    if other_solver:
        c.set("system/fvSolution", "solvers/p/solver", "PBiCGStab")
        c.set("system/fvSolution", "solvers/p/preconditioner", "FDIC")
    with open(c.file("system/decomposeParDict"), "w") as out:
        out.write(DECOMPOSE.format(n=cut))
    if grains is not None:
        with open(c.file("0/grains"), "w") as out:
            out.write("# grainColumn with every grain moved by eta0\n")
            np.savetxt(out, grains, fmt="%.17g")
    c.run("blockMesh")
    return c


def run_parallel(c, *args, expect_fail=False, parallel=True):
    """mpirun -np 2 darcyDemFoam [-parallel] in the case; its log text."""
    cmd = [MPIRUN, "-np", "2", "--oversubscribe", "darcyDemFoam", "-case", c.path, *args]
    if parallel:
        cmd.append("-parallel")
    result = subprocess.run(cmd, capture_output=True, text=True, env=ENV, timeout=600)
    log = result.stdout + result.stderr
    with open(c.file("log.darcyDemFoam.parallel"), "w") as out:
        out.write(log)
    if expect_fail:
        assert result.returncode != 0, log[-2000:]
    else:
        assert result.returncode == 0, log[-3000:]
    return log


def read_grains(c, time_name):
    return np.loadtxt(c.file(time_name + "/grains"), comments="#")


def diagnostics(c, start="0"):
    path = c.file(f"postProcessing/grainDiagnostics/{start}/grainDiagnostics.dat")
    header = [line for line in open(path) if line.startswith("#")][-1].split()[1:]
    return dict(zip(header, np.loadtxt(path, comments="#", ndmin=2).T))


def periodic_difference(a, b):
    d = a[:, :3] - b[:, :3]
    d[:, :2] -= LENGTH * np.round(d[:, :2] / LENGTH)
    return np.max(np.abs(d))


def three_runs(prefix, prepare=lambda c: None):
    """The column on one process, again from grains moved by eta0 (and with
    another pressure solver), and on two ranks (reconstructed)."""
    serial = column(prefix + "_serial")
    prepare(serial)
    serial.run("darcyDemFoam")
    start = read_grains(serial, "0")
    eta0 = DEM_STEPS * 4 * math.ulp(np.max(np.abs(start[:, :3])))
    u = np.random.default_rng(3).normal(size=(len(start), 3))
    moved = start.copy()
    moved[:, :3] += eta0 * u / np.linalg.norm(u, axis=1)[:, None]
    perturbed = column(prefix + "_serial_perturbed", grains=moved, other_solver=True)
    prepare(perturbed)
    perturbed.run("darcyDemFoam")
    split = column(prefix + "_split")
    prepare(split)
    split.run("decomposePar")
    log = run_parallel(split)
    split.run("reconstructPar", "-latestTime")
    return serial, perturbed, split, log, eta0


@pytest.fixture(scope="module")
def runs():
    return three_runs("parallel")


def test_split_run_follows_one_process_within_round_off_growth(runs):
    serial, perturbed, split, log, eta0 = runs
    assert "Grains split over 2 ranks as the mesh: 2 x 1 boxes of 1 x 2 x 10 cells" in log
    # the load balance at each write: 256 grains over the two ranks
    per_rank = re.findall(r"Grains per rank: (\d+) to (\d+) \(the most over the mean: (\S+)\)",
                          log)
    assert per_rank, log[-2000:]
    fewest, most, ratio = per_rank[-1]
    assert int(fewest) <= 128 <= int(most) and float(ratio) == pytest.approx(int(most) / 128)
    t = serial.times()[-1][1]
    assert split.times()[-1][1] == t
    g_one, g_pert, g_split = (read_grains(c, t) for c in (serial, perturbed, split))
    tol_x = periodic_difference(g_pert, g_one)
    dx = periodic_difference(g_split, g_one)
    fields = {}
    for name in ("p", "porosity"):
        one = serial.field(t, name)
        tol = np.max(np.abs(perturbed.field(t, name) - one))
        diff = np.max(np.abs(split.field(t, name) - one))
        fields[name] = (diff, tol)
    print(f"eta0 = {eta0:.3g} m; grains split vs one process {dx:.3g} m (tolerance "
          f"{tol_x:.3g}); p {fields['p'][0]:.3g} Pa (tolerance {fields['p'][1]:.3g}); "
          f"porosity {fields['porosity'][0]:.3g} (tolerance {fields['porosity'][1]:.3g})")
    assert 0 < tol_x < 1e-8  # still the round-off regime: a millionth of a radius
    assert dx <= tol_x
    for name, (diff, tol) in fields.items():
        assert diff <= tol, name


def test_grain_flags_follow_one_process():
    """A fixed base and a lid layer driven sideways (grainFlags), the shear
    carried across the cut: each rank flags its own grains."""
    def flags(c):
        c.set("constant/demProperties", "grainFlags",
              "{ base { flag fixed; zMax 0.03; } "
              "lid { flag prescribedVelocity; zMin 0.3; velocity (0.05 0); } }")
    serial, perturbed, split, log, _ = three_runs("parallel_flags", flags)
    assert "grain flags lid: prescribedVelocity for" in log
    t = serial.times()[-1][1]
    g_one, g_pert, g_split = (read_grains(c, t) for c in (serial, perturbed, split))
    tol_x, dx = periodic_difference(g_pert, g_one), periodic_difference(g_split, g_one)
    print(f"flags: grains split vs one process {dx:.3g} m (tolerance {tol_x:.3g})")
    assert 0 < tol_x < 1e-8 and dx <= tol_x
    # the driven grains moved with the lid layer: as far as one process's
    lid = g_one[:, 2] > 0.3
    assert np.any(lid)
    assert np.max(np.abs(g_split[lid, 0] - g_one[lid, 0])) <= tol_x


def test_function_objects_sum_over_the_ranks(runs):
    serial, perturbed, split, _, _ = runs
    one, pert, par = diagnostics(serial), diagnostics(perturbed), diagnostics(split)
    n = 256  # the sums run over the grains: their rounding, 2 (n - 1) eps of the terms' sum
    for column_name in ("kineticEnergy", "contactsPerGrain", "dilation", "topWall"):
        growth = np.abs(pert[column_name] - one[column_name])
        rounding = 2 * (n - 1) * EPS * np.abs(one[column_name])
        worst = np.max(np.abs(par[column_name] - one[column_name]) - growth - rounding)
        assert worst <= 0, (column_name, worst)
    assert np.any(par["contactsPerGrain"] > 0)
    assert len(par["kineticEnergy"]) == len(one["kineticEnergy"])


def test_every_grain_once_and_solid_volume_conserved(runs):
    serial, _, split, _, _ = runs
    t = split.times()[-1][1]
    grains = read_grains(split, t)
    assert grains.shape == read_grains(serial, "0").shape  # 256 grains, written once each
    # the deposit summed over the ranks against the grains' volume summed over the ranks
    error = diagnostics(split)["solidVolumeError"]
    assert np.max(np.abs(error)) <= 2 * (256 + 40) * EPS, np.max(np.abs(error))
    # each rank's part of the time beside the case's own grains
    for rank in (0, 1):
        assert os.path.isfile(split.file(f"processor{rank}/{t}/demState"))


def test_restart_from_a_decomposed_time_is_exact():
    straight = column("parallel_straight", end=0.02, write_steps=100)
    straight.run("decomposePar")
    run_parallel(straight)
    restarted = column("parallel_restarted", end=0.01, write_steps=100)
    restarted.run("decomposePar")
    run_parallel(restarted)
    restarted.set("system/controlDict", "endTime", 0.02)
    log = run_parallel(restarted)
    assert "restart from" in log and "processor0/0.01/demState" in log, log[-2000:]
    with open(straight.file("0.02/grains")) as a, open(restarted.file("0.02/grains")) as b:
        assert a.read() == b.read()
    for rank in (0, 1):
        p_a = read_internal_field(straight.file(f"processor{rank}/0.02/p"))
        p_b = read_internal_field(restarted.file(f"processor{rank}/0.02/p"))
        assert np.array_equal(p_a, p_b)


def same_restart_end(reference, c, end):
    """The grains file and every rank's p of time end, byte for byte."""
    with open(reference.file(f"{end}/grains")) as a, open(c.file(f"{end}/grains")) as b:
        assert a.read() == b.read()
    for rank in (0, 1):
        assert np.array_equal(read_internal_field(reference.file(f"processor{rank}/{end}/p")),
                              read_internal_field(c.file(f"processor{rank}/{end}/p")))


@pytest.fixture(scope="module")
def written_every_20_steps():
    """The column on two ranks to 0.006 s, written at 0.002, 0.004, 0.006."""
    c = column("parallel_crash_reference", end=0.006, write_steps=20)
    c.run("decomposePar")
    run_parallel(c)
    return c


def test_time_complete_on_one_rank_only_is_set_aside_everywhere(written_every_20_steps):
    """A run killed while writing 0.004 after rank 0 had finished its part
    and rank 1 had not (made on disk: rank 1's demState half written as
    demState.tmp, its write mark still there; 0.006 not reached): with
    startFrom latestTime every rank restarts from 0.002, the latest time
    complete on every rank; rank 1's 0.004, rank 0's complete one and the
    case directory's grains of 0.004 are set aside as 0.004.incomplete;
    the run then ends bit for bit as the uninterrupted one."""
    reference = written_every_20_steps
    path = reference.path.replace("crash_reference", "crash_one_rank")
    shutil.rmtree(path, ignore_errors=True)
    shutil.copytree(reference.path, path, ignore=shutil.ignore_patterns("log.*"))
    c = Case.existing(path)
    for where in ("", "processor0/", "processor1/"):
        shutil.rmtree(c.file(where + "0.006"))
    state = c.file("processor1/0.004/demState")
    text = open(state, "rb").read()
    os.remove(state)
    with open(state + ".tmp", "wb") as out:
        out.write(text[:len(text) // 2])
    open(c.file("processor1/0.004/.writeInProgress"), "w").close()
    log = run_parallel(c)
    assert "restarting from the latest complete time 0.002" in log, log[-2000:]
    assert "complete on every rank" in log
    for where in ("", "processor0/", "processor1/"):
        assert os.path.isdir(c.file(where + "0.004.incomplete")), where
    same_restart_end(reference, c, "0.006")


def test_killed_parallel_run_restarts_from_the_last_complete_time(written_every_20_steps):
    """A real kill: the master SIGKILLed (the writer's test hook) in the
    middle of its demState of 0.004 (its third demState: at each time it
    writes its part and the gathered one), the other rank stopped by mpirun
    once the master died, with its part of 0.004 complete or not: the
    restart with startFrom latestTime continues from 0.002, the latest time
    complete on every rank, and ends bit for bit as the uninterrupted
    run."""
    reference = written_every_20_steps
    c = column("parallel_crash_killed", end=0.006, write_steps=20)
    c.run("decomposePar")
    env = dict(ENV, DARCYDEM_TEST_KILL_AT="inDemState@3")
    result = subprocess.run([MPIRUN, "-np", "2", "--oversubscribe", "darcyDemFoam", "-case",
                             c.path, "-parallel"], capture_output=True, text=True, env=env,
                            timeout=600)
    assert result.returncode != 0
    assert "SIGKILL at inDemState (3)" in result.stdout + result.stderr
    assert not os.path.exists(c.file("processor0/0.006"))
    log = run_parallel(c)
    assert "restarting from the latest complete time 0.002" in log, log[-2000:]
    assert os.path.isdir(c.file("processor0/0.004.incomplete"))
    same_restart_end(reference, c, "0.006")


def test_restart_from_a_reconstructed_time():
    """A decomposed run writes, besides each rank's demState, the whole
    system as one process's state into the case directory's time (gathered
    on the master: grains in id order, each contact's history and bond
    once, walls, clock). After reconstructPar a run on one process
    continues from it ('restart from', no warning) and follows the decomposed
    run's own continuation within the growth of round-off over its 500 DEM
    steps, bounded as above by a one-process continuation from the same
    state with every grain moved by eta0 = 500 x 4 ulp. With the ranks' own
    demState files removed the decomposed case starts from the same
    one-process state, which the library distributes over the ranks at the
    first step, and follows the ranks' own continuation within the same
    bound. Decomposed afresh along the other axis (n (1 2 1)) the run takes
    that state too, writes every grain once and deposits their volume to
    the rounding of its sums; its grains are not compared, because
    decomposing the reconstructed fields afresh changes the fluid's first
    steps by itself (measured: the same cut, the same grains' state, fields
    through reconstructPar and decomposePar: 7.5e-8 m after 500 steps,
    against 1e-16 m with the solver's own processor fields)."""
    first = column("parallel_reconstructed", end=0.01, write_steps=50)
    first.run("decomposePar")
    run_parallel(first)
    first.run("reconstructPar")
    assert os.path.isfile(first.file("0.01/demState"))

    def copy(name):
        path = first.path + "_" + name
        shutil.rmtree(path, ignore_errors=True)
        keep_parts = name in ("decomposed", "distributed")
        skip = ["postProcessing", "log.*"] + ([] if keep_parts else ["processor*"])
        shutil.copytree(first.path, path, ignore=shutil.ignore_patterns(*skip))
        c = Case.existing(path)
        c.set("system/controlDict", "endTime", 0.015)
        return c

    decomposed, distributed, serial, perturbed, recut = (
        copy(n) for n in ("decomposed", "distributed", "serial", "perturbed", "recut"))
    run_parallel(decomposed)
    log = serial.run("darcyDemFoam")
    assert "restart from" in log and "0.01/demState" in log, log[-2000:]
    assert "No demState" not in log and "one-process state" not in log

    reals, integers = read_dem_state(perturbed.file("0.01/demState"))
    x = reals["grain.position"].reshape(3, -1)  # component-blocked: x of every grain, then y, z
    steps = 500
    eta0 = steps * 4 * math.ulp(np.max(np.abs(x)))
    u = np.random.default_rng(5).normal(size=x.shape)
    x += eta0 * u / np.linalg.norm(u, axis=0)
    reals["grain.position"] = x.ravel()
    write_dem_state(perturbed.file("0.01/demState"), reals, integers)
    perturbed.run("darcyDemFoam")
    g_split, g_one, g_pert = (read_grains(c, "0.015") for c in (decomposed, serial, perturbed))
    tol = periodic_difference(g_pert, g_one)
    dx = periodic_difference(g_one, g_split)
    print(f"one process from the gathered state vs the decomposed run after {steps} steps:"
          f" {dx:.3g} m (tolerance {tol:.3g} m, eta0 {eta0:.3g} m)")
    assert 0 < tol < 1e-8
    assert dx <= tol

    # the ranks' own parts removed: the same fields, the grains from the one-process state
    for rank in (0, 1):
        os.remove(distributed.file(f"processor{rank}/0.01/demState"))
    log = run_parallel(distributed)
    assert "one-process state" in log and "distributed over the ranks" in log, log[-2000:]
    assert "restart from" in log and "No demState" not in log
    dx_distributed = periodic_difference(read_grains(distributed, "0.015"), g_split)
    print(f"the one-process state distributed over the ranks vs the ranks' own parts:"
          f" {dx_distributed:.3g} m (tolerance {tol:.3g} m)")
    assert dx_distributed <= tol

    with open(recut.file("system/decomposeParDict"), "w") as out:
        out.write(DECOMPOSE.format(n="1 2 1"))
    recut.run("decomposePar", "-force")
    log = run_parallel(recut)
    assert "Grains split over 2 ranks as the mesh: 1 x 2 boxes" in log
    assert "one-process state" in log and "distributed over the ranks" in log, log[-2000:]
    assert "restart from" in log and "No demState" not in log
    assert read_grains(recut, "0.015").shape == read_grains(first, "0").shape  # each once
    error = diagnostics(recut, start="0.01")["solidVolumeError"]
    assert np.max(np.abs(error)) <= 2 * (256 + 40) * EPS, np.max(np.abs(error))


def test_navier_stokes_solver_on_two_ranks():
    def fixed_bed(name, other_solver=False):
        c = Case("fixedBed", name)
        c.set("constant/demProperties", "threads", 1)
        c.set("system/controlDict", "endTime", 0.1)
        c.set("system/controlDict", "writeInterval", 50)
        c.set("system/controlDict", "writeFormat", "ascii")
        if other_solver:
            c.set("system/fvSolution", "solvers/(p|pFinal)/solver", "PBiCGStab")
            c.set("system/fvSolution", "solvers/(p|pFinal)/preconditioner", "FDIC")
        with open(c.file("system/decomposeParDict"), "w") as out:
            out.write(DECOMPOSE.format(n="2 1 1"))
        c.run("blockMesh")
        return c
    one, other, split = (fixed_bed("parallel_ns_serial"),
                         fixed_bed("parallel_ns_other_solver", other_solver=True),
                         fixed_bed("parallel_ns_split"))
    one.run("nsDemFoam")
    other.run("nsDemFoam")
    split.run("decomposePar")
    subprocess.run([MPIRUN, "-np", "2", "--oversubscribe", "nsDemFoam", "-case", split.path,
                    "-parallel"], check=True, capture_output=True, env=ENV, timeout=600)
    split.run("reconstructPar", "-latestTime")
    t = one.times()[-1][1]
    n = len(np.loadtxt(one.file("0/grains"), comments="#", ndmin=2))
    for name in ("U", "p"):
        a, b, c = (x.field(t, name) for x in (one, split, other))
        diff, tol = np.max(np.abs(b - a)), np.max(np.abs(c - a))
        print(f"nsDemFoam {name}: 2 ranks vs one process {diff:.3g}, another p solver {tol:.3g}"
              f" (of {np.max(np.abs(a)):.3g})")
        assert 0 < tol < 1e-9 * np.max(np.abs(a)) and diff <= tol, name
    phi_one, phi_split = one.field(t, "porosity"), split.field(t, "porosity")
    assert np.max(np.abs(phi_split - phi_one)) <= 2 * (n - 1) * EPS


def test_misuse_is_refused_with_a_clear_message():
    c = column("parallel_misuse", end=1e-4)
    log = run_parallel(c, expect_fail=True, parallel=False)
    assert "Started by mpirun with 2 processes but without -parallel" in log, log[-2000:]

    c = column("parallel_cut_in_z", end=1e-4, cut="1 1 2")
    c.run("decomposePar")
    log = run_parallel(c, expect_fail=True)
    assert "The mesh decomposition (system/decomposeParDict) cannot be followed" in log, \
        log[-2000:]
    assert "n (NX NY 1)" in log


"""darcyDemFoam on the CUDA backend against the same case on the CPU
(tests/cases/grainColumn: 256 grains settling in a saturated periodic column
under a stress-controlled lid, 300 fluid steps of 10 DEM steps each: the
lowest grains meet the floor and each other, and the perturbed CPU run below
has drifted 2000 times eta0 away by then, 1.5e-9 m; 0.05 s would be past the
small-difference regime, millimetres apart).
Skipped when no CUDA device answers.

Why not bit for bit: nvcc fuses a*b+c into one rounding, the GPU deposits the
grains' volume into cells with atomic additions in no fixed order, and sums
the lid's force in another order, so every step may differ in the last bit.
The grains' settling is chaotic and such differences grow. The tolerance is
measured on the CPU alone, as in the DEM library's CpuVsCuda test: a second
CPU run starts from grains moved by eta0 = (DEM steps) x 4 ulp of the largest
coordinate, the sum of every step's worst-case difference (a position's
drift rounds differently by at most an ulp; a porosity summed in another
order moves p as little as a shift of 1e-18 m would), in a random direction.
While differences stay small they evolve linearly, and one entering later has
had less time to grow, so CUDA's run cannot end further from the CPU run than
the perturbed one: grain positions, p and porosity within the perturbed run's
differences (checked first: those are far below the grains' overlaps, i.e.
still round-off growing, not a different packing)."""

import math

import numpy as np
import pytest

from darcydem.case import Case

END = 0.03          # s: 300 fluid steps of 1e-4 s
DEM_STEPS = 3000    # DEM time step 1e-5 s (grainColumn's demProperties)


def read_grains(path):
    """(n, 4) array x y z r of a 'grains' file."""
    return np.loadtxt(path, comments="#")


def run_column(name, backend, grains=None, expect_fail=False):
    c = Case("grainColumn", name)
    c.set("constant/demProperties", "backend", backend)
    c.set("system/controlDict", "endTime", END)
    c.set("system/controlDict", "writeInterval", round(END / 1e-4))
    c.set("system/controlDict", "writeFormat", "ascii")
    if grains is not None:
        with open(c.file("0/grains"), "w") as out:
            out.write("# grainColumn with every grain moved by eta0\n")
            np.savetxt(out, grains, fmt="%.17g")
    c.run("blockMesh")
    log = c.run("darcyDemFoam", expect_fail=expect_fail)
    return c, log


def final_state(c):
    time_name = c.times()[-1][1]
    return (read_grains(c.file(time_name + "/grains")), c.field(time_name, "p"),
            c.field(time_name, "porosity"))


def periodic_difference(a, b, length):
    """Largest |a - b| of grain positions, x and y taken across the periodic
    seams (a grain may sit just across one in one run and not the other)."""
    d = a[:, :3] - b[:, :3]
    d[:, :2] -= length * np.round(d[:, :2] / length)
    return np.max(np.abs(d))


def test_cuda_run_agrees_with_cpu_run_within_round_off_growth():
    try:
        cuda, _ = run_column("backend_cuda", "cuda")
    except Exception as error:  # RunError with the solver's log tail
        reason = [line for line in str(error).splitlines()
                  if "no CUDA device answers" in line or "has no CUDA backend" in line]
        if reason:
            pytest.skip("no CUDA device: " + reason[0].strip()[:200])
        raise
    cpu, _ = run_column("backend_cpu", "cpu")

    start = read_grains(cpu.file("0/grains"))
    ulp = math.ulp(np.max(np.abs(start[:, :3])))
    eta0 = DEM_STEPS * 4 * ulp
    rng = np.random.default_rng(1)
    u = rng.normal(size=(len(start), 3))
    moved = start.copy()
    moved[:, :3] += eta0 * u / np.linalg.norm(u, axis=1)[:, None]
    pert, _ = run_column("backend_cpu_perturbed", "cpu", grains=moved)

    length = 0.1  # the column's periodic side (blockMeshDict $L)
    g_cpu, p_cpu, phi_cpu = final_state(cpu)
    g_pert, p_pert, phi_pert = final_state(pert)
    g_cuda, p_cuda, phi_cuda = final_state(cuda)
    tol_x = periodic_difference(g_pert, g_cpu, length)
    tol_p = np.max(np.abs(p_pert - p_cpu))
    tol_phi = np.max(np.abs(phi_pert - phi_cpu))
    dx = periodic_difference(g_cuda, g_cpu, length)
    dp = np.max(np.abs(p_cuda - p_cpu))
    dphi = np.max(np.abs(phi_cuda - phi_cpu))
    print(f"eta0 = {eta0:.3g} m; |x_cuda - x_cpu| = {dx:.3g} m (tolerance {tol_x:.3g}), "
          f"|p_cuda - p_cpu| = {dp:.3g} Pa (tolerance {tol_p:.3g}, p up to "
          f"{np.max(np.abs(p_cpu)):.3g} Pa), |phi_cuda - phi_cpu| = {dphi:.3g} "
          f"(tolerance {tol_phi:.3g})")

    # the calibration is in the round-off regime (1e-8 m: a millionth of a radius)
    assert 0 < tol_x < 1e-8
    assert dx <= tol_x
    assert dp <= tol_p
    assert dphi <= tol_phi

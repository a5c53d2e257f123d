"""A deforming periodic box (demProperties 'boxLengthRate', doc/CASE-FORMAT.md)
run by the real demFoam on a real case: the mesh follows the box (its y extent
at every write time is L0 + rate t), the grains' porosity on the moved mesh
holds their volume (sum of (1 - porosity) V_cell = sum of V_grain), a restart
from a written time continues the box's motion and ends bit for bit where the
uninterrupted run ends (its mesh to round-off), and the entry is refused, naming the file and the
entry, where a side cannot deform. The contact physics across the moving side
is the library's (demTests DeformingBox).

Case: tests/cases/grainColumn (256 spheres under a stress-controlled lid,
periodic in x and y, L = 0.1 m), its y length shrinking at 0.5 m/s for
0.02 s (to 0.09 m)."""

import filecmp
import math
import os
import shutil

import numpy as np
import pytest

from darcydem.case import Case, fatal_message

DEM = "constant/demProperties"
CTL = "system/controlDict"
RATE = -0.5  # [m/s]
END = 0.02
WRITE_EVERY = 50  # fluid steps of 1e-4 s: writes at 0.005, 0.01, 0.015, 0.02
L0 = 0.1
HEIGHT = 0.4
CELLS = (2, 2, 10)


def column(name, rate=RATE, end=END):
    c = Case("grainColumn", name)
    c.set(DEM, "backend", "cpu")  # the restart's bit identity is the CPU's
    c.set(DEM, "boxLengthRate", f"(0 {rate} 0)")
    c.set(CTL, "endTime", end)
    c.set(CTL, "writeInterval", WRITE_EVERY)
    c.run("blockMesh")
    return c


def grain_volume(case):
    radius = np.loadtxt(case.file("0/grains"), comments=("#", "/"), usecols=3)
    return float(np.sum(4.0 / 3.0 * math.pi * radius ** 3))


@pytest.fixture(scope="module")
def whole():
    c = column("deforming_box_whole")
    c.run("demFoam")
    return c


def test_mesh_follows_the_box_and_the_porosity_holds_the_grains(whole):
    log = open(whole.file("log.demFoam")).read()
    assert "periodic box: lengths change at (0 -0.5 0) m/s" in log
    solid = grain_volume(whole)
    times = whole.times()
    assert [n for _, n in times] == ["0.005", "0.01", "0.015", "0.02"]
    for t, name in times:
        lower, upper = whole.bounding_box(name)
        expected = L0 + RATE * t
        print(f"t = {name}: y extent {upper[1] - lower[1]:.17g} m, expected {expected:.17g}")
        # the mesh's points scaled from the points read: round-off of a few 1e-17 m
        assert abs((upper[1] - lower[1]) - expected) < 1e-14
        assert abs(upper[0] - L0) < 1e-15 and abs(upper[2] - HEIGHT) < 1e-15
        # the deposit's weights sum to one in every grain (mirrored at the z walls,
        # wrapped across the periodic sides at their current length)
        porosity = whole.field(name, "porosity")
        cell = L0 * expected * HEIGHT / (CELLS[0] * CELLS[1] * CELLS[2])
        deposited = float(np.sum(1.0 - porosity)) * cell
        print(f"    solid on the mesh {deposited:.15g} m3, grains {solid:.15g} m3")
        assert abs(deposited - solid) < 1e-12 * solid


def test_restart_reads_the_moved_mesh_and_continues_bit_for_bit(whole):
    path = os.path.join(os.path.dirname(whole.path), "deforming_box_restart")
    shutil.rmtree(path, ignore_errors=True)
    shutil.copytree(whole.path, path, ignore=shutil.ignore_patterns("postProcessing", "log.*"))
    c = Case.existing(path)
    for _, name in c.times():
        if name != "0.01":
            shutil.rmtree(c.file(name))
    c.set(CTL, "startFrom", "latestTime")
    log = c.run("demFoam")
    assert "restart from" in log
    # the box the restart starts from is the written mesh's, 0.095 m
    assert "y 0.095" in log
    # the DEM continues the box's motion as the run left it (demCloud.boxMotion in the
    # demState), not the written mesh's, which is that box to round-off only
    for f in ("demState", "grains", "porosity"):
        assert filecmp.cmp(c.file(f"0.02/{f}"), whole.file(f"0.02/{f}"), shallow=False), f
    a, b = c.bounding_box("0.02"), whole.bounding_box("0.02")
    assert np.allclose(a[1], b[1], rtol=0, atol=1e-15)


def test_z_is_refused():
    c = column("deforming_box_refused", rate=0)
    c.set(DEM, "boxLengthRate", "(0 0 -0.1)")
    message = fatal_message(c.run("demFoam", expect_fail=True))
    assert "Entry 'boxLengthRate'" in message and "demProperties" in message
    assert "changes z, which is never periodic" in message


def test_a_wall_bounded_side_is_refused():
    c = Case("wallBox", "deforming_box_walls")
    c.set(DEM, "boxLengthRate", "(-0.1 0 0)")
    c.run("blockMesh")
    message = fatal_message(c.run("demFoam", expect_fail=True))
    assert "Entry 'boxLengthRate'" in message
    assert "changes x, whose mesh sides are not cyclic patches" in message


def test_a_fluid_keeps_its_box():
    c = column("deforming_box_darcy")
    message = fatal_message(c.run("darcyDemFoam", expect_fail=True))
    assert "Entry 'boxLengthRate'" in message
    assert "runs without a fluid only (demFoam)" in message

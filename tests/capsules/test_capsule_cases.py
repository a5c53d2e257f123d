"""Capsules and spheres mixed in a case, from a grains file written by
bin/makeGrains (issue 10): the written grains carry each grain's shape and
current orientation and a new case reads them back; a demState restart
stays bit-identical; a bad capsule line stops naming the line; and
darcyDemFoam runs capsules mixed with spheres with the deposit conserving
their true volume. Case: tests/cases/grainColumn (a periodic column
0.1 x 0.1 x 0.4 m, bottom wall and a stress-controlled lid), 60 grains,
about half capsules of aspect 1.5-2.5, radius 7-8 mm (the periodic box must hold twice
the longest grain)."""

import filecmp
import os
import re
import shutil
import subprocess

import numpy as np

from darcydem.case import Case, fatal_message
from darcydem.foamfiles import grain_files, read_grains, read_vtp

DEM = "constant/demProperties"
COUNT = 60


def mixed_column(name, dry=True, end=0.02, write=100, z=(0.05, 0.36)):
    c = Case("grainColumn", name)
    if dry:
        os.remove(c.file("constant/darcyProperties"))
        os.remove(c.file("0/p"))
    c.set("system/controlDict", "endTime", end)
    c.set("system/controlDict", "writeInterval", write)
    c.set(DEM, "timeStep", 5e-6)   # capsules turn: a shorter critical step
    subprocess.run([os.path.join(os.environ["DARCYDEM_PROJECT"], "bin", "makeGrains"),
                    "--box", "0.1", "0.1", "--z", str(z[0]), str(z[1]),
                    "--radius", "0.007", "0.008", "--layout", "random", "--count", str(COUNT),
                    "--capsule-fraction", "0.5", "--aspect", "1.5", "2.5", "--seed", "2",
                    "-o", c.file("0/grains")], check=True, stdout=subprocess.DEVNULL)
    c.run("blockMesh")
    return c


def test_written_grains_carry_shape_and_orientation():
    """At a write time the grains file holds each grain as the ParaView file
    of the same time does (position, r, h, q: exact, 17 digits); a case
    started from it without gravity (grains at rest, apart) writes them
    back unchanged: positions, r and h exactly, q to the round-off of its
    normalisation on reading (2 ulp)."""
    a = mixed_column("capsule_grains_written", end=0.01)
    a.run("demFoam")
    written = read_grains(a.file("0.01/grains"))
    shown = read_vtp(grain_files(a.path)[-1][1])
    capsules = written["coreHalfLength"] > 0
    print(f"{len(capsules)} grains, {np.count_nonzero(capsules)} capsules written")
    for key in ("position", "radius", "coreHalfLength"):
        assert np.array_equal(written[key], shown[key]), key
    assert np.array_equal(written["orientation"][capsules], shown["orientation"][capsules])

    b = Case("grainColumn", "capsule_grains_read_back")
    os.remove(b.file("constant/darcyProperties"))
    os.remove(b.file("0/p"))
    shutil.copy(a.file("0.01/grains"), b.file("0/grains"))
    b.set(DEM, "gravity", "(0 0 0)")
    b.set(DEM, "timeStep", 5e-6)
    b.set("system/controlDict", "endTime", 1e-4)
    b.set("system/controlDict", "writeInterval", 1)
    b.run("blockMesh")
    b.run("demFoam")
    again = read_grains(b.file("0.0001/grains"))
    for key in ("position", "radius", "coreHalfLength"):
        assert np.array_equal(again[key], written[key]), key
    q_error = np.max(np.abs(again["orientation"] - written["orientation"]))
    print(f"orientation read back: largest change {q_error:.1e}")
    assert q_error <= 2 * np.finfo(float).eps


def test_restart_is_bit_identical_with_capsules():
    """Restarted from its first write time, the mixed column ends bit for
    bit where the uninterrupted run ends (demState: grains with shape,
    orientation and angular momentum, contact history, walls)."""
    a = mixed_column("capsule_restart_full")
    a.set(DEM, "backend", "cpu")   # bit identity is the CPU backend's
    a.run("demFoam")
    b_path = a.path + "_restarted"
    shutil.rmtree(b_path, ignore_errors=True)
    shutil.copytree(a.path, b_path)
    shutil.rmtree(os.path.join(b_path, "0.02"))
    b = Case.existing(b_path)
    log = b.run("demFoam")
    assert "restart from" in log
    for f in ("demState", "grains"):
        assert filecmp.cmp(a.file("0.02/" + f), b.file("0.02/" + f), shallow=False), f


def bad_line(name, line):
    c = mixed_column(name, end=1e-3)
    with open(c.file("0/grains"), "a") as f:
        f.write(line + "\n")
    return fatal_message(c.run("demFoam", expect_fail=True))


def test_bad_capsule_lines_name_the_line():
    """The 60 grains sit on lines 3 to 62: the appended line is 63."""
    msg = bad_line("capsule_bad_quaternion", "0.05 0.05 0.3 0.008 0.01 2 0 0 0")
    assert "0/grains" in msg and "line 63" in msg and "must be a unit quaternion" in msg
    assert "|q| = 2" in msg
    msg = bad_line("capsule_bad_length", "0.05 0.05 0.3 0.008 -0.01 1 0 0 0")
    assert "line 63" in msg and "core half-length h (5th column) must be >= 0" in msg
    msg = bad_line("capsule_bad_columns", "0.05 0.05 0.3 0.008 0.01 1 0 0")
    assert "line 63" in msg and "'x y z r h qw qx qy qz'" in msg


def test_darcy_dem_foam_runs_capsules_and_spheres():
    """The saturated column with 60 grains, half capsules, for 0.02 s. The
    deposit conserves the grains' true solid volume at every fluid step
    (sum over cells of (1 - porosity) V_cell against sum of
    pi r^2 2h + 4/3 pi r^3: round-off, 1e-12 as for spheres). A grain
    that touches nothing falls with g (1 - rho_f/rho_s), whatever its
    shape, only if its buoyancy rho_f V g uses the same true volume as its
    mass: velocity Verlet is exact for a constant acceleration, so the
    drop is (1 - rho_f/rho_s) g t^2/2 to round-off (spheres in this column
    match to 1e-13); the median over the capsules (some are pushed by the
    lid or meet a neighbour) must match to 1e-9."""
    c = mixed_column("capsule_darcy", dry=False)
    c.set("system/controlDict", "functions/grainDiagnostics/writeInterval", 1)
    c.run("darcyDemFoam")
    d = np.loadtxt(c.file("postProcessing/grainDiagnostics/0/grainDiagnostics.dat"),
                   comments="#")
    start = read_grains(c.file("0/grains"))
    end = read_vtp(grain_files(c.path)[-1][1])
    capsules = start["coreHalfLength"] > 0
    drop = start["position"][capsules, 2] - end["position"][capsules, 2]
    buoyant_fall = 0.5 * 9.81 * 0.02**2 * (1 - 1000 / 2600)
    fall_error = np.median(np.abs(drop / buoyant_fall - 1))
    err = np.max(np.abs(d[:, 12]))
    print(f"max relative solid-volume error over {len(d)} fluid steps: {err:.1e};"
          f" capsules' drop / buoyant free fall - 1, median of |.|: {fall_error:.1e}")
    assert len(d) == 200 and err < 1e-12
    assert fall_error < 1e-9


C = np.sqrt(0.5)   # cos 45 deg = sin 45 deg
ALONG_X = f"{C!r} 0 {C!r} 0"    # q: 90 deg about y, the body z axis onto x
ALONG_Y = f"{C!r} {-C!r} 0 0"   # q: -90 deg about x, onto y


def two_capsules(name, second):
    """Two capsules r = 8 mm, h = 10 mm: one along x at (0.05, 0.05, 0.2),
    the other as given (line 3 and 4 of the file)."""
    c = Case("grainColumn", name)
    os.remove(c.file("constant/darcyProperties"))
    os.remove(c.file("0/p"))
    c.set("system/controlDict", "endTime", 1e-3)
    with open(c.file("0/grains"), "w") as f:
        f.write("# two capsules\n# x y z r h qw qx qy qz\n")
        f.write(f"0.05 0.05 0.2 0.008 0.01 {ALONG_X}\n{second}\n")
    c.run("blockMesh")
    return c


def test_start_overlap_of_capsules_is_measured_on_their_shapes():
    """Crossing capsules, one 12 mm above the other: their cores cross at
    12 mm, overlap 2r - 12 mm = 4 mm = 50 % of r: refused, naming both.
    Side by side along x, 17 mm apart: apart (17 > 2r = 16 mm) though their
    bounding spheres (r + h = 18 mm) overlap by 19 mm: accepted."""
    c = two_capsules("capsule_start_crossing", f"0.05 0.05 0.212 0.008 0.01 {ALONG_Y}")
    msg = fatal_message(c.run("demFoam", expect_fail=True))
    assert "grain 0 (line 3)" in msg and "grain 1 (line 4)" in msg
    found = float(re.search(r"overlap ([0-9.e+-]+) % of the smaller radius", msg).group(1))
    print(f"crossing capsules: overlap reported {found} % of r, expected 50 %")
    assert abs(found - 50) < 1e-6   # 10 digits of 4 mm / 8 mm, round-off of the geometry
    c = two_capsules("capsule_start_side_by_side", f"0.05 0.067 0.2 0.008 0.01 {ALONG_X}")
    log = c.run("demFoam")
    assert "End" in log

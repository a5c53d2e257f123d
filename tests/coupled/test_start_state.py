"""The grains a run starts from are checked (issue 14): a duplicated line
(two coincident grains), an overlap above maxInitialOverlap (5 % of the
smaller radius), a grain outside the periodic box (refused unless
'wrapGrains yes;') or beyond a wall stop with the file, the grains (index,
line, position) named. An exception of the DEM library ends as an OpenFOAM
FATAL ERROR with its message. Case: tests/cases/grainColumn (256 grains,
header of two comment lines, so grain i is on line i + 3)."""

import re

import pytest

from darcydem.case import Case, fatal_message

GRAINS = "0/grains"


def column(name):
    c = Case("grainColumn", name)
    c.set("system/controlDict", "endTime", 1e-3)
    c.set("system/controlDict", "writeInterval", 10)
    c.run("blockMesh")
    return c


def grain_lines(c):
    """(comment lines, grain lines as lists of floats)."""
    text = open(c.file(GRAINS)).read().splitlines()
    head = [l for l in text if l.startswith("#")]
    return head, [[float(v) for v in l.split()] for l in text if not l.startswith("#")]


def write_grains(c, head, grains):
    with open(c.file(GRAINS), "w") as f:
        f.write("\n".join(head) + "\n")
        for g in grains:
            f.write(" ".join("%.12g" % v for v in g) + "\n")


def test_duplicated_line_is_refused_naming_both_grains():
    c = column("start_duplicate")
    head, grains = grain_lines(c)
    write_grains(c, head, grains[:11] + [grains[10]] + grains[11:])  # grain 10 twice
    msg = fatal_message(c.run("darcyDemFoam", expect_fail=True))
    assert "FOAM FATAL IO ERROR" in msg and "0/grains" in msg
    assert "grain 10 (line 13)" in msg and "grain 11 (line 14)" in msg
    # overlap = r + r at distance 0, as a fraction of r
    assert "coincident, overlap 200 % of the smaller radius" in msg


def test_big_overlap_is_refused_with_its_size():
    """Grain 1 moved to half a radius sum from grain 0: overlap
    (r0 + r1)/2 / min(r0, r1), printed as a percentage."""
    c = column("start_overlap")
    head, grains = grain_lines(c)
    (x0, y0, z0, r0), (_, _, _, r1) = grains[0], grains[1]
    grains[1] = [x0 + 0.5 * (r0 + r1), y0, z0, r1]
    write_grains(c, head, grains)
    msg = fatal_message(c.run("darcyDemFoam", expect_fail=True))
    expected = 100 * 0.5 * (r0 + r1) / min(r0, r1)
    found = float(re.search(r"overlap ([0-9.e+-]+) % of the smaller radius", msg).group(1))
    print(f"overlap reported {found} %, expected {expected} %")
    assert found == pytest.approx(expected, rel=1e-8)  # printed with 10 digits
    assert "grain 0 (line 3)" in msg and "grain 1 (line 4)" in msg
    assert "maxInitialOverlap = 0.05" in msg


def test_grain_outside_the_periodic_box_is_refused_unless_wrapped():
    c = column("start_outside")
    head, grains = grain_lines(c)
    grains[5][0] += 7.4  # 74 box lengths to the right (a user's x = 7.5 m)
    write_grains(c, head, grains)
    msg = fatal_message(c.run("darcyDemFoam", expect_fail=True))
    assert "grain 5 (line 8)" in msg and "outside the periodic box, x in [0, 0.1)" in msg
    assert "wrapGrains yes;" in msg

    c.set("constant/demProperties", "wrapGrains", "yes")
    log = c.run("darcyDemFoam")
    assert "wrapGrains: 1 coordinate(s)" in log
    x = [float(l.split()[0]) for l in open(c.file("0.001/grains")) if not l.startswith("#")]
    assert all(0 <= v < 0.1 for v in x)


def test_grain_above_the_top_wall_is_refused():
    c = column("start_above_wall")
    head, grains = grain_lines(c)
    grains[7][2] = 0.39  # the lid is at z = 0.38, the mesh ends at 0.4
    write_grains(c, head, grains)
    msg = fatal_message(c.run("darcyDemFoam", expect_fail=True))
    assert "grain 7 (line 10)" in msg and "above the upper wall at z = 0.38" in msg


def test_dem_library_exception_is_a_foam_fatal_error():
    """A neighbour skin that makes the cells wider than half the periodic
    box: the DEM library throws; the solver reports it and exits normally
    with an error (no std::terminate, no abort)."""
    c = column("start_library_throws")
    c.set("constant/demProperties", "neighbourSkin", 0.05)
    log = c.run("darcyDemFoam", expect_fail=True)
    msg = fatal_message(log)
    assert "FOAM FATAL ERROR" in msg and "periodic box length" in msg
    assert "terminate called" not in log and "Aborted" not in log

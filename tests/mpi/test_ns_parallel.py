"""nsDemFoam with moving grains on several ranks: the liquid-fluidised bed
of tests/ns/test_fluidised_bed.py (2000 beads settling, then fluidised at
three inflow velocities) decomposed over three MPI ranks, held to the serial
test's criteria (its check(), imported: Ergun in the packed bed, the
buoyant weight once fluidised, u_mf, Richardson-Zaki expansion). Three
ranks: the column's 3 x 3 cells split into equal whole columns only by 3
(or 9); the beads cross the two cuts and the periodic sides as they
settle and circulate. On a machine with fewer cores the ranks share them
(slower, not different)."""

import os
import shutil
import sys

import pytest

from darcydem.case import ranks_for_solvers

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "ns"))
from test_fluidised_bed import check, run_bed  # noqa: E402

pytestmark = pytest.mark.skipif(shutil.which("mpirun") is None,
                                reason="needs mpirun (openmpi-bin)")


def test_fluidised_bed_on_three_ranks():
    with ranks_for_solvers(3):
        c, wall = run_bed("fluidisedBed_parallel")
    log = open(c.file("log.nsDemFoam")).read()
    assert "Grains split over 3 ranks as the mesh: 3 x 1 boxes" in log
    assert "Grains per rank: " in log
    check(c, wall)

"""The consolidation study of tests/coupled/test_consolidation.py with every
stage decomposed over two MPI ranks (DARCYDEM_RANKS=2: decomposePar, mpirun
-np 2 <solver> -parallel, reconstructPar; each stage started from the
previous stage's per-rank demState), held to the serial test's criteria: the
same test functions, imported, against Terzaghi and the layered column with
the tolerances they carry (the issue: the consolidation case on 2 ranks
follows the serial curve within the serial test's tolerance). The packing is
settled afresh on two ranks, so it is not the serial run's grain for grain
(the settling is chaotic: round-off grows), but a packing of the same
preparation, measured (E_oed, k) and consolidated the same way.

Measured (5 Dec 2026, the study alone, 2 ranks x 1 thread, 266 s): settlement against
Terzaghi rms 0.023 (serial 0.026, tolerance 0.05); base pressure 0.008 (serial
0.009, tolerance 0.05); against the layered column 0.0036 / 0.0026 (tolerances
0.031 / 0.011); undrained start 0.9998 of the layered column's; halving the
coupling step changes the settlement by 0.05 %."""

import json
import os
import sys

import pytest

from darcydem.case import copy_tutorial, ranks_for_solvers
from darcydem.consolidation import Study

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "coupled"))
from test_consolidation import (test_excess_pressure_dissipates_as_terzaghi,  # noqa: E402,F401
                                test_halving_the_coupling_interval,
                                test_layered_column_base_pressure,
                                test_layered_column_settlement,
                                test_packing_is_prepared_and_measured,
                                test_settlement_follows_terzaghi, test_undrained_start)

pytestmark = pytest.mark.skipif(
    __import__("shutil").which("mpirun") is None, reason="needs mpirun (openmpi-bin)")


@pytest.fixture(scope="module")
def study():
    path = copy_tutorial("consolidation", "consolidation_parallel")
    with ranks_for_solvers(2):
        s = Study(path)
        s.run()
        s.plot()
    log = open(os.path.join(path, "stages", "consolidation", "log.darcyDemFoam")).read()
    assert "Grains split over 2 ranks as the mesh: 2 x 1 boxes" in log
    assert os.path.isfile(os.path.join(path, "stages", "consolidation", "processor1", "0",
                                       "demState"))
    print(json.dumps(s.results["comparison"], indent=1))
    return s.results

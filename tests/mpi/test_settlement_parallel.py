"""The snow settlement study of tests/settlement/test_settlement.py (size
'test': 250 bonded capsules contracted, relaxed, settled at two contact
viscosities and once with bending creep off) with every demFoam run
decomposed over two MPI ranks (-parallel 2: decomposePar, mpirun -np 2
demFoam -parallel, reconstructPar), held to the serial test's criteria: the
same test functions, imported (the lid's momentum balance, grain mass in the
density, bond bookkeeping, settlement and each creep mechanism slowing with
the contact viscosity, stress building up in the mode whose creep is off).
The bonds' files are gathered from the ranks: checked here against the
packing statistics at every write, and against a one-process run at the
first write, before round-off has changed any contact (the runs are chaotic:
later their bonds differ by a few per cent, as two serial runs on other
thread counts would).

The mesh along x has an even cell count on two ranks (4 cells against the
serial study's 5: the ranks' boxes are whole columns of equal size; demFoam
has no fluid, the mesh only sets the boxes and the porosity output)."""

import glob
import os
import shutil
import sys

import numpy as np
import pytest

from darcydem.case import Case, TEST_RUNS, ranks_for_solvers
from darcydem.foamfiles import read_columns, read_vtp_lines
from darcydem import settlement as S

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "settlement"))
from test_settlement import (run_study, test_bond_bookkeeping,  # noqa: E402,F401
                             test_density_is_grain_mass_over_enclosed_volume,
                             test_each_creep_mechanism_slows_with_contact_viscosity,
                             test_lid_stress_is_the_lid_weight,
                             test_settlement_slows_with_contact_viscosity,
                             test_stress_builds_up_in_the_mode_without_creep)

pytestmark = pytest.mark.skipif(shutil.which("mpirun") is None,
                                reason="needs mpirun (openmpi-bin)")


@pytest.fixture(scope="module")
def study():
    with ranks_for_solvers(2):
        s, runs = run_study("snow_settlement_parallel")
    log = open(os.path.join(s.stages, "contract", "log.demFoam")).read()
    assert "Grains split over 2 ranks as the mesh: 2 x 1 boxes" in log
    assert "Grains per rank: " in log
    return s, runs


def stage_dirs(s):
    return sorted(d for d in glob.glob(os.path.join(s.stages, "*")) if os.path.isdir(d))


def test_every_bond_written_once(study):
    """At every write of every stage the gathered bonds' .vtp lists each
    intact bond once (no pair twice: each rank reports the bonds of the
    grains it owns) and as many as packingStatistics counts over the ranks
    at that time (exact: integers)."""
    s, _ = study
    checked = 0
    for stage in stage_dirs(s):
        packing = read_columns(os.path.join(stage, S.PACKING))
        for vtp in glob.glob(os.path.join(stage, "postProcessing", "grains", "bonds_*.vtp")):
            t = float(os.path.basename(vtp)[len("bonds_"):-len(".vtp")])
            row = np.flatnonzero(np.isclose(packing["time"], t, rtol=0, atol=1e-9))
            assert row.size == 1, f"{vtp}: no packing row at t = {t}"
            bonds = read_vtp_lines(vtp)
            pairs = set(zip(bonds["first"].tolist(), bonds["second"].tolist()))
            assert len(pairs) == len(bonds["lines"]), f"{vtp}: a bond written twice"
            assert len(pairs) == packing["bondsIntact"][row[0]], vtp
            checked += 1
    print(f"{checked} bond files, each bond once, counts as packingStatistics'")
    assert checked >= 20


def test_gathered_bonds_are_the_serial_runs_at_the_first_write(study):
    """The contraction's first write (bonds frozen on contact for 0.04 s)
    from two ranks against the same start run on one process: the same
    bonds (the pairs of grains' ids, in the same order) formed at the same
    steps (their ages), exactly: formation is a discrete event of the contact geometry, which
    two decompositions of the same grains give alike until round-off has
    grown; the bonds' ends (the grains' centres) within 1e-12 m."""
    s, _ = study
    parallel = os.path.join(s.stages, "contract")
    first = sorted(glob.glob(os.path.join(parallel, "postProcessing", "grains", "bonds_*.vtp")),
                   key=lambda p: float(os.path.basename(p)[6:-4]))[0]
    time_name = os.path.basename(first)[len("bonds_"):-len(".vtp")]
    serial = os.path.join(TEST_RUNS, "snow_settlement_serial_start")
    shutil.rmtree(serial, ignore_errors=True)
    os.makedirs(serial)
    for part in ("0", "constant", "system"):
        shutil.copytree(os.path.join(parallel, part), os.path.join(serial, part))
    os.remove(os.path.join(serial, "system", "decomposeParDict"))
    with ranks_for_solvers(1):
        c = Case.existing(serial)
        c.set("system/controlDict", "endTime", time_name)
        c.run("demFoam")
    a = read_vtp_lines(first)
    b = read_vtp_lines(os.path.join(serial, "postProcessing", "grains", f"bonds_{time_name}.vtp"))
    print(f"t = {time_name} s: {len(a['lines'])} bonds on two ranks, {len(b['lines'])} on one")
    assert len(a["lines"]) > 0
    for name in ("first", "second", "age"):
        assert np.array_equal(a[name], b[name]), name
    assert np.max(np.abs(a["points"] - b["points"])) <= 1e-12

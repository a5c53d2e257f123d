"""The snow sample contracted in all of space (settlementStudy --contract-y,
size 'test': 250 capsules, the periodic y length shrinking from 1.5 times the
paper's to the paper's with the walls, demProperties boxLengthRate), then
relaxed from its demState: the contraction ends at the paper's y length when
the state the next stage starts from is written (its mesh, which that start
checks the state's box against), and grain mass is conserved in the density
the function objects write from the moving box."""

import os
import re
import shutil

import numpy as np
import pytest

from darcydem.case import PROJECT, TEST_RUNS, Case
from darcydem.foamfiles import read_grains
from darcydem import settlement as S

TUTORIAL = os.path.join(PROJECT, "tutorials", "demFoam", "snowSettlement")


@pytest.fixture(scope="module")
def prepared():
    path = os.path.join(TEST_RUNS, "snow_contract_y")
    shutil.rmtree(path, ignore_errors=True)
    shutil.copytree(TUTORIAL, path, ignore=shutil.ignore_patterns(
        "stages", "*.png", "results.json", "log.*"))
    s = S.SettlementStudy(path, "test", contract_y=True)
    s.prepare()
    return s


def y_extent(case, time_name):
    lower, upper = case.bounding_box(time_name)
    return upper[1] - lower[1]


def test_the_contraction_ends_at_the_papers_box(prepared):
    """At the contraction's last write the mesh's y extent is the paper's Ly
    (1e-12 m: the rate is set for that time, the points scaled once from the
    ones read), and the relaxation, on the paper's mesh, starts from that
    state (its start would stop on another box)."""
    s = prepared
    contract = Case.existing(os.path.join(s.stages, "contract"))
    last = contract.times()[-1][1]
    ly = s.s["box"][1]
    start = y_extent(contract, contract.times()[0][1])
    print(f"y extent {start:.6g} m at the first write, {y_extent(contract, last):.17g} m at"
          f" {last} s; the paper's {ly:g} m")
    assert abs(y_extent(contract, last) - ly) < 1e-12
    assert start > ly * 1.1   # still contracting then
    relax = open(os.path.join(s.stages, "relax", "log.demFoam")).read()
    assert "packing prepared by another run" in relax and "End" in relax


def test_density_is_grain_mass_over_the_moving_box(prepared):
    """density x (x gap) Ly(t) (lid - bottom) is the grains' mass at every
    row of the contraction, Ly(t) = 1.5 Ly + (dLy/dt) t, and of the
    relaxation with the paper's Ly: the function objects measure the box as
    it is. Tolerance per row: 1e-12 for the round-off of the products (the
    .dat files carry 17 digits), plus the round-off of a time summed step by
    step: t after n = t/dt additions is off by at most n u t (u the unit
    round-off), which moves Ly(t) by |dLy/dt| n u t, relative to Ly(t)."""
    s = prepared
    g = read_grains(os.path.join(s.stages, "contract", "0", "grains"))
    r, h = g["radius"], g["coreHalfLength"]
    mass = S.ICE_DENSITY * np.sum(np.pi * r**2 * 2 * h + 4 / 3 * np.pi * r**3)
    contract = os.path.join(s.stages, "contract")
    rate = float(re.search(r"boxLengthRate\s+\(\s*0\s+(\S+)\s+0\s*\)", open(
        os.path.join(contract, "constant", "demProperties")).read()).group(1))
    ly0 = s.s["box"][1] * S.CONTRACTION
    for stage, ly_start, ly_rate in (("contract", ly0, rate), ("relax", s.s["box"][1], 0.0)):
        run = S.Run(os.path.join(s.stages, stage), 0, s.s["box"][1])
        w = run.w
        ly = ly_start + ly_rate * run.t
        volume = ((w["right_position"] - w["left_position"]) * ly
                  * (w["lid_position"] - w["bottom_position"]))
        error = np.abs(run.density * volume / mass - 1)
        steps = run.t / S.TIME_STEP
        clock = abs(ly_rate) * steps * (np.finfo(float).eps / 2) * run.t / ly
        print(f"{stage}: density {run.density[0]:.5g} -> {run.density[-1]:.5g} kg/m3, largest"
              f" relative error of density x volume {error.max():.1e} (bound at the end"
              f" {1e-12 + clock[-1]:.1e})")
        assert np.all(error < 1e-12 + clock)

"""Measure the seed-to-seed noise of the shear test's comparisons: runs the
study of tests/shear/test_shear.py (size 'test') from packings made with
other makeGrains seeds and writes tests/run/shearNoise_seed<N>/results.json.
Not a test (minutes per seed); its numbers are in tests/README.md.

usage: python3 tests/shear/measure_noise.py SEED [SEED ...]
       python3 tests/shear/measure_noise.py SEED CASE   (dry, permeable, impermeable,
                                          impermeable_halfMu, impermeable_eightfoldVelocity)
       (one case on the packing a first run prepared for SEED)
(after `source etc/bashrc`; run at most two at a time on two cores)"""

import json
import os
import sys

from darcydem.case import TEST_RUNS, Case, copy_tutorial
from darcydem.foamfiles import read_scalar_entry
from darcydem.shear import ShearStudy


def run_seed(seed):
    s = ShearStudy(copy_tutorial("shear", "shearNoise_seed%d" % seed), "test")
    s.s["seed"] = s.results["settings"]["seed"] = seed
    s.run_with_checks()


def run_case_from_prepared(seed, case):
    """One case (dry, permeable, impermeable, impermeable_halfMu,
    impermeable_eightfoldVelocity) on the packing that
    run_seed prepared for this seed (its consolidate stage), so that the
    cases of one seed can run side by side."""
    s = ShearStudy.__new__(ShearStudy)
    path = os.path.join(TEST_RUNS, "shearNoise_seed%d" % seed)
    ShearStudy.__init__(s, path, "test")
    s.s["seed"] = seed
    s.curves = {}
    b = Case.existing(os.path.join(s.stages, "consolidate"))
    s.prepared = b.file(os.path.join(s.last_time(b), "demState"))
    s.height = float(s.diagnostics(b)["wall"][-1])
    # the mesh of the consolidate stage
    s.cells_z = int(read_scalar_entry(b.file("system/blockMeshDict"), "nz"))
    kwargs = dict(s.shear_cases(checks=True).values())[case]
    r = s.shear(case + "_parallel", **kwargs)
    with open(os.path.join(path, "results_%s.json" % case), "w") as f:
        json.dump(r, f, indent=2)


if __name__ == "__main__":
    if len(sys.argv) == 3 and not sys.argv[2].isdigit():
        run_case_from_prepared(int(sys.argv[1]), sys.argv[2])
    else:
        for a in sys.argv[1:]:
            run_seed(int(a))

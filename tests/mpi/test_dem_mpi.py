"""The DEM benchmark split over two MPI ranks (demBench --decompose under
mpirun) against the same benchmark on one process.

The standard benchmark (src/dem/bench/README.md: the 10,000-grain packing,
1000 relaxation steps with drag, 2000 timed steps) must end with the same
translational kinetic energy within 1e-6 relative on 1 and 2 ranks, for a
cut across x and one across y (the MPI issue's criterion: a pair across a
rank boundary is evaluated on both ranks and summed in another order, so the
runs part by round-off, which the dense bed amplifies; measured 3.5e-7 and
7.6e-8). The flowing benchmark (grains poured at 10 m/s, neighbour lists
rebuilt, grains migrating between the ranks with their contact histories)
must agree to the same 1e-6. Misuse: a decomposition whose box count is not
the number of ranks is refused with a message that says what to run.
"""
import os
import re
import shutil
import subprocess

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
PACKING = os.path.join(os.path.dirname(HERE), "..", "src", "dem", "bench", "packings",
                       "packing_10000.txt")
MPIRUN = shutil.which("mpirun")
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMP_NUM_THREADS="1")

pytestmark = pytest.mark.skipif(MPIRUN is None or shutil.which("demBench") is None,
                                reason="needs mpirun (openmpi-bin) and demBench (Allwmake)")


def bench(args, ranks=1):
    cmd = ["demBench", "--backend", "cpu", "--threads", "1", *args]
    if ranks > 1:
        cmd = [MPIRUN, "-np", str(ranks), "--oversubscribe", *cmd]
    return subprocess.run(cmd, capture_output=True, text=True, env=ENV, timeout=600)


def final_energy(result):
    assert result.returncode == 0, result.stdout + result.stderr
    match = re.search(r"final translational kinetic energy (\S+) J", result.stdout)
    assert match, result.stdout
    return float(match.group(1))


@pytest.mark.parametrize("args", [["--packing", PACKING], ["--pour", "--grains", "10000"]],
                         ids=["standard", "flowing"])
def test_two_ranks_end_with_the_one_process_energy(args):
    one = final_energy(bench(args))
    for boxes in ("2x1", "1x2"):
        split = bench([*args, "--decompose", boxes], ranks=2)
        energy = final_energy(split)
        assert abs(energy - one) <= 1e-6 * abs(one), (boxes, energy, one)
        # every grain owned by one rank, the load balanced by the equal boxes
        match = re.search(r"grains per rank (\S+) \(min\) (\S+) \(max\)", split.stdout)
        assert match and float(match.group(1)) + float(match.group(2)) == 10000, split.stdout


def test_box_count_must_match_the_ranks():
    alone = bench(["--packing", PACKING, "--decompose", "2x1", "--steps", "1"])
    assert alone.returncode != 0
    assert "--decompose 2x1 needs mpirun -np 2, not 1 rank(s)" in alone.stderr, alone.stderr
    wrong = bench(["--packing", PACKING, "--decompose", "3x1", "--steps", "1"], ranks=2)
    assert wrong.returncode != 0
    assert "--decompose 3x1 needs mpirun -np 3, not 2 rank(s)" in wrong.stderr, wrong.stderr

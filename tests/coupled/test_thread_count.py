"""darcyDemFoam's results do not depend on the DEM's thread count: the same
case on 1 and on 2 threads ends with the same bits, and so does the adaptive
team of `threads 0` (AdaptiveThreads.h), whose steps switch between 1 and 2
threads as it times them.

The DEM library sums every grain's loads in a fixed order and the CPU
backend's reductions over fixed blocks (src/dem/src/backends/OmpExecution.h),
so the thread count changes no result; the grain-to-fluid deposit runs on one
thread. `shearStudy` relies on it when it runs its shear stages side by side
on one thread each (--jobs): their results are then those of one stage at a
time on all cores. The library's own test (ThreadCount in RestartTest.cpp)
steps a DEM system; this one runs the coupled solver on a real case.

The case: tests/cases/grainColumn with 5000 smaller grains (makeGrains,
random, r = 3-3.5 mm, DEM step 2e-6 s) falling in the saturated column onto
the floor under the stress-controlled lid, 0.02 s (10,000 DEM steps): about
7600 listed pairs and 140 touching at the end. 5000 grains and 7600 pairs are
above the CPU backend's kParallelThreshold (1024), so every kernel of the step
(pair pass, per-grain pass, neighbour search) runs on both threads."""

import os
import re
import subprocess

from darcydem.case import Case

END = 0.02  # s: 200 fluid steps of 1e-4 s, 50 DEM steps each
GRAINS = 5000
PARALLEL_THRESHOLD = 1024  # OmpExecution::kParallelThreshold


def run_on(threads):
    c = Case("grainColumn", f"threads{threads}")
    c.set("constant/demProperties", "output/progressInterval", 0)  # a line per fluid step
    subprocess.run(["makeGrains", "--box", "0.1", "0.1", "--z", "0.0", "0.36", "--radius",
                    "0.003", "0.0035", "--layout", "random", "--count", str(GRAINS), "--gap",
                    "0.0001", "--seed", "2", "-o", c.file("0/grains")],
                   check=True, stdout=subprocess.DEVNULL)
    c.set("constant/demProperties", "timeStep", 2e-6)  # 0.12 sqrt(m/k) for r = 3 mm
    c.set("constant/demProperties", "threads", threads)
    c.set("system/controlDict", "endTime", END)
    c.set("system/controlDict", "writeInterval", round(END / 1e-4))
    c.run("blockMesh")
    log = c.run("darcyDemFoam")
    assert f"{GRAINS} grains" in log and f"{threads or 2} thread(s)" in log, log[-2000:]
    c.log = log
    return c


def same_bits(one, other, what):
    end = one.times()[-1][1]
    assert other.times()[-1][1] == end and float(end) == END
    for name in ("grains", "demState", "p", "porosity"):
        a, b = (open(c.file(os.path.join(end, name)), "rb").read() for c in (one, other))
        assert a == b, f"{end}/{name} differs between 1 thread and {what}"


def test_one_and_two_threads_end_with_the_same_bits(monkeypatch):
    assert GRAINS >= PARALLEL_THRESHOLD
    one, two = run_on(1), run_on(2)
    same_bits(one, two, "2 threads")
    # threads 0: OpenMP's default (2 here), each step's team chosen between 1 and 2. Its
    # first probe comes after two windows of 0.05 s (AdaptiveThreads::kWindowSeconds), well
    # within the run, so some steps ran on each team size: the last progress line counts them
    monkeypatch.setenv("OMP_NUM_THREADS", "2")
    adaptive = run_on(0)
    assert "(adaptive: 1 or 2 per step" in adaptive.log, adaptive.log[-2000:]
    counts = re.findall(r"\((\d+) of (\d+) DEM steps on 2 threads, the rest on 1\)",
                        adaptive.log)
    on_two, steps = map(int, counts[-1])
    print(f"adaptive team: {on_two} of {steps} DEM steps on 2 threads")
    assert steps == round(END / 2e-6) and 0 < on_two < steps
    same_bits(one, adaptive, "the adaptive team")

"""Run real OpenFOAM case directories and read their output.

A Case is a copy of a template case; entries are changed with Debian's
foamDictionary (at 17 digits, see foamfiles.py: a process start of about
15 ms per entry, and the file rewritten without its comments),
applications are run with their log kept in the case, and fields (ascii
or binary) / probes are read back as numpy arrays. Used by the tests (templates
in tests/cases, copies in tests/run) and by the tutorials' study scripts.
"""

import contextlib
import heapq
import itertools
import os
import re
import shutil
import subprocess
from concurrent.futures import ThreadPoolExecutor

import numpy as np

from darcydem.foamfiles import FOAM_DICTIONARY, read_internal_field, read_probes, time_dirs

PROJECT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
TEST_TEMPLATES = os.path.join(PROJECT, "tests", "cases")
TEST_RUNS = os.path.join(PROJECT, "tests", "run")

# DARCYDEM_BACKEND=cpu|cuda|auto sets the DEM backend of every case copied here
# (constant/demProperties 'backend'), so the tests and the studies run on
# either backend unchanged; unset, a case keeps its template's backend.
BACKEND_VARIABLE = "DARCYDEM_BACKEND"
BACKENDS = ("cpu", "cuda", "auto")


def backend_override():
    """The backend named by DARCYDEM_BACKEND, or None when it is unset."""
    value = os.environ.get(BACKEND_VARIABLE, "").strip()
    if not value:
        return None
    if value not in BACKENDS:
        raise ValueError(f"{BACKEND_VARIABLE}={value!r} is not a DEM backend "
                         f"(valid: {' '.join(BACKENDS)})")
    return value


def apply_backend(case_dir):
    """Set 'backend' in case_dir/constant/demProperties from DARCYDEM_BACKEND
    (nothing when the variable is unset or the case has no grains)."""
    backend = backend_override()
    path = os.path.join(case_dir, "constant", "demProperties")
    if backend is None or not os.path.exists(path):
        return
    # By text when the line is there: foamDictionary would rewrite the whole
    # file (comments dropped, numbers at its write precision).
    text = open(path).read()
    new, n = re.subn(r"(?m)^(backend\s+)\w+\s*;", r"\g<1>%s;" % backend, text)
    if n == 1:
        open(path, "w").write(new)
        return
    subprocess.run([*FOAM_DICTIONARY, "-entry", "backend", "-set", backend, path],
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)


def copy_tutorial(tutorial, name):
    """Copy tutorials/darcyDemFoam/<tutorial> without its output to
    tests/run/<name> (replacing it); returns the path."""
    path = os.path.join(TEST_RUNS, name)
    shutil.rmtree(path, ignore_errors=True)
    shutil.copytree(os.path.join(PROJECT, "tutorials", "darcyDemFoam", tutorial), path,
                    ignore=shutil.ignore_patterns("stages", "*.png", "results*.json", "log.*"))
    apply_backend(path)
    return path


# DARCYDEM_RANKS=N (N > 1) runs every solver of a Case over N MPI ranks, as an
# OpenFOAM user would: decomposePar before its first run (system/decomposeParDict
# made when the case has none: method simple, n (N 1 1)), mpirun -np N <solver>
# -parallel, then reconstructPar, so that the studies read the case directory as
# after a serial run. A stage started from another stage's demState takes each
# rank's part from that stage's processor directories.
RANKS_VARIABLE = "DARCYDEM_RANKS"
SOLVERS = ("darcyDemFoam", "demFoam", "nsDemFoam")
MPI_ENVIRONMENT = {"OMPI_ALLOW_RUN_AS_ROOT": "1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1"}


def usable_cores():
    """The cores this process may run on (its CPU affinity; else os.cpu_count())."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:
        return os.cpu_count() or 1


def cores_per_rank(ranks):
    """The usable cores over a solver's MPI ranks, at least 1: the threads of
    one process of a stage that has the machine to itself."""
    return max(1, usable_cores() // ranks)


def default_jobs():
    """Independent stages a study runs at once by default: one per core the
    solvers' MPI ranks leave free (2 one-process stages on 2 cores)."""
    return cores_per_rank(ranks_override())


def run_side_by_side(calls, jobs, log, what, costs=None):
    """Run the independent stages calls (each call(threads) -> result, threads
    the DEM threads to set in its demProperties, None: the template's), jobs
    at a time, each on its share of the cores (threads_per_stage); returns the
    results in the order of calls. When they run side by side, says so through
    log (what: the study's name for them, e.g. "shearStudy: 8 shear stages").
    A stage's results do not depend on its thread count (the DEM library's
    sums run in a fixed order), so they are those of one stage at a time. Side
    by side each stage gets a fixed share (threads 1 on 2 cores: the adaptive
    team of threads 0 would probe the busy cores, src/dem/README.md, "Threads
    (CPU backend)"). costs (estimated, one per call, any unit): the stages
    start in the order that ends soonest on jobs workers if they cost that
    (start_order); without, in the order of calls. One at a time, the
    template's threads and the order of calls."""
    if jobs == 1 or len(calls) <= 1:
        return [call(None) for call in calls]
    threads = threads_per_stage(jobs, len(calls))
    log(f"{what}, {jobs} at a time, {threads} DEM thread{'s' if threads > 1 else ''} each"
        " (--jobs)")
    order = range(len(calls)) if costs is None else start_order(costs, jobs)
    with ThreadPoolExecutor(max_workers=jobs) as pool:
        futures = {k: pool.submit(calls[k], threads) for k in order}
        try:
            return [futures[k].result() for k in range(len(calls))]
        except BaseException:
            for f in futures.values():  # the stages not started yet
                f.cancel()
            raise


def threads_per_stage(jobs, stages):
    """DEM threads of each of the stages run jobs at a time: the cores shared
    by the processes that run at once, each stage's MPI ranks counted
    (DARCYDEM_RANKS), so that 2 stages of 2 ranks on 4 cores run 1 thread per
    rank, not 2 (which would put 8 threads on 4 cores); at least 1."""
    return max(1, cores_per_rank(ranks_override()) // min(jobs, stages))


def makespan(costs, order, jobs):
    """When the last of the stages (costs) ends if jobs workers take them in
    order, each the next as soon as it is free (a ThreadPoolExecutor)."""
    free = [0.0] * jobs
    for k in order:
        heapq.heapreplace(free, free[0] + costs[k])
    return max(free)


def start_order(costs, jobs, exhaustive_up_to=8):
    """The order to start stages of these costs in on jobs workers: of all
    orders (up to exhaustive_up_to stages; beyond, longest first) the first
    that ends soonest (makespan), so that equal costs keep the given order.
    Longest first alone can leave a stage running alone at the end: the
    quick shear's five stages (costs 3.9, 3.9, 3.7, 2.3, 2.3 s of shear)
    end at 8.6 that way and at 8.4 with the dry one beside the rate series."""
    n = len(costs)
    if n > exhaustive_up_to:
        return sorted(range(n), key=lambda k: -costs[k])
    return list(min(itertools.permutations(range(n)),
                    key=lambda order: makespan(costs, order, jobs)))


def ranks_override():
    """The MPI rank count named by DARCYDEM_RANKS (1 when unset)."""
    value = os.environ.get(RANKS_VARIABLE, "").strip() or "1"
    if not value.isdigit() or int(value) < 1:
        raise ValueError(f"{RANKS_VARIABLE}={value!r} is not a rank count (1, 2, ...)")
    return int(value)


@contextlib.contextmanager
def ranks_for_solvers(ranks):
    """Within the block, every Case made runs its solvers over this many MPI
    ranks (DARCYDEM_RANKS set, then restored): for tests that run a whole
    study decomposed."""
    saved = os.environ.get(RANKS_VARIABLE)
    os.environ[RANKS_VARIABLE] = str(ranks)
    try:
        yield
    finally:
        if saved is None:
            del os.environ[RANKS_VARIABLE]
        else:
            os.environ[RANKS_VARIABLE] = saved


class RunError(RuntimeError):
    """An application exited non-zero; carries the tail of its log."""


def fatal_message(log):
    """The FOAM FATAL (IO) ERROR part of a solver's log, printed (its start)
    so that the test log records what the user would read."""
    text = log[log.find("FOAM FATAL"):]
    print(text[:700])
    return text


class Case:
    def __init__(self, template, name, template_root=TEST_TEMPLATES, run_root=TEST_RUNS):
        """Copy template_root/template to run_root/name (replacing it)."""
        self.path = os.path.join(run_root, name)
        shutil.rmtree(self.path, ignore_errors=True)
        shutil.copytree(os.path.join(template_root, template), self.path,
                        ignore=shutil.ignore_patterns("stages", "*.png", "log.*"))
        apply_backend(self.path)
        self.ranks = ranks_override()
        self.state_source = None  # decomposed: the demState this case starts from

    @classmethod
    def existing(cls, path):
        """A Case for a directory that is already there."""
        case = cls.__new__(cls)
        case.path = os.path.abspath(path)
        case.ranks = ranks_override()
        case.state_source = None
        return case

    def file(self, rel):
        return os.path.join(self.path, rel)

    def set(self, rel, entry, value):
        """Set a dictionary entry (slash-separated path) to a value string."""
        subprocess.run(
            [*FOAM_DICTIONARY, "-entry", entry, "-set", str(value), self.file(rel)],
            check=True, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)

    def set_variable(self, rel, name, value):
        """Set a top-level 'name value;' line by text substitution; for
        variables that other entries use through $name (foamDictionary
        would expand them when it rewrites the file)."""
        path = self.file(rel)
        text = open(path).read()
        new, n = re.subn(r"(?m)^(%s\s+)[^;]*;" % re.escape(name), r"\g<1>%s;" % value, text)
        if n != 1:
            raise KeyError(f"variable {name} not found once in {path}")
        open(path, "w").write(new)

    def remove(self, rel, entry):
        subprocess.run(
            [*FOAM_DICTIONARY, "-entry", entry, "-remove", self.file(rel)],
            check=True, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)

    def run(self, app, *args, expect_fail=False):
        """Run an application in the case; return its log text. A solver of a
        case with ranks > 1 runs decomposed (see DARCYDEM_RANKS)."""
        parallel = app in SOLVERS and self.ranks > 1
        if parallel and not os.path.isdir(self.file("processor0")):
            self.decompose()
        command = [app, "-case", self.path, *args]
        env = None
        if parallel:
            mpirun = shutil.which("mpirun")
            if mpirun is None:
                raise RunError(f"{RANKS_VARIABLE}={self.ranks}: mpirun not found "
                               "(install openmpi-bin)")
            command = [mpirun, "-np", str(self.ranks), "--oversubscribe", *command, "-parallel"]
            env = dict(os.environ, **MPI_ENVIRONMENT)
            # the cores shared among the ranks, unless set
            env.setdefault("OMP_NUM_THREADS", str(cores_per_rank(self.ranks)))
        log = self.file("log." + app)
        with open(log, "w") as out:
            rc = subprocess.call(command, stdout=out, stderr=subprocess.STDOUT, env=env)
        text = open(log).read()
        if expect_fail:
            if rc == 0:
                raise RunError(f"{app} succeeded but was expected to fail")
            return text
        if rc != 0:
            raise RunError(f"{app} failed (exit {rc}) in {self.path}:\n" + text[-3000:])
        if parallel:
            self.run("reconstructPar")
        return text

    def decompose(self):
        """decomposePar (a decomposeParDict made if there is none), then each
        rank's part of the demState this case starts from."""
        dict_path = self.file("system/decomposeParDict")
        if not os.path.exists(dict_path):
            nx, ny = self.column_split()
            with open(dict_path, "w") as out:
                out.write("FoamFile { version 2.0; format ascii; class dictionary; "
                          "object decomposeParDict; }\n"
                          f"numberOfSubdomains {self.ranks};\nmethod simple;\n"
                          f"coeffs {{ n ({nx} {ny} 1); }}\n")
        self.run("decomposePar", "-force")
        if self.state_source:
            time_dir = os.path.dirname(self.state_source)
            source_case, time_name = os.path.dirname(time_dir), os.path.basename(time_dir)
            for rank in range(self.ranks):
                part = os.path.join(source_case, f"processor{rank}", time_name, "demState")
                if not os.path.exists(part):
                    raise RunError(f"{self.state_source}: no part {part} for rank {rank} "
                                   f"(the stage it comes from ran on another rank count?)")
                # (a case without fields has no processor<N>/0 yet)
                os.makedirs(self.file(f"processor{rank}/0"), exist_ok=True)
                shutil.copy(part, self.file(f"processor{rank}/0/demState"))

    def column_split(self):
        """(NX, NY), NX NY = ranks, that cut the mesh into equal whole columns
        (NX dividing its cell count in x, NY in y; the grains' boxes follow
        the parts), cut along x where it can: for a single-block
        blockMeshDict; (ranks, 1) when none fits or the mesh is not one
        block (the solver then names the parts that do not fit)."""
        text = subprocess.run([*FOAM_DICTIONARY, "-expand", self.file("system/blockMeshDict")],
                              capture_output=True, text=True).stdout
        blocks = re.findall(r"hex\s*\([^)]*\)\s*\(\s*(\d+)\s+(\d+)\s+\d+\s*\)", text)
        if len(blocks) == 1:
            cells_x, cells_y = (int(c) for c in blocks[0])
            for nx in range(self.ranks, 0, -1):
                ny = self.ranks // nx
                if nx * ny == self.ranks and cells_x % nx == 0 and cells_y % ny == 0:
                    return nx, ny
        return self.ranks, 1

    def cells_along_x(self, cells):
        """The cell count nearest cells (at least one per rank) that the
        case's ranks split into equal whole columns (decomposePar's simple
        n (ranks 1 1), which the grains' boxes follow); on one process the
        nearest whole count, so a serial study keeps its mesh."""
        return max(1, round(cells / self.ranks)) * self.ranks

    def mesh(self, state_from=None):
        """blockMesh; then, if given, a demState from another run into 0/ (the
        grains start from that prepared packing with this case's settings)."""
        self.run("blockMesh")
        if state_from is not None and self.ranks > 1:
            self.state_source = state_from  # each rank's part, at decomposePar
        elif state_from is not None:
            shutil.copy(state_from, self.file("0/demState"))
        return self

    def times(self):
        """Written time directories after 0 as sorted (time, name) pairs."""
        return time_dirs(self.path)

    def bounding_box(self, time_name):
        """The mesh's (lower, upper) corners at a time (a moving mesh's points of that
        time), as checkMesh prints them (the case's writePrecision)."""
        log = self.run("checkMesh", "-time", time_name)
        m = re.search(r"Overall domain bounding box \(([^)]*)\) \(([^)]*)\)", log)
        return [np.array(v.split(), float) for v in m.groups()]

    def field(self, time_name, name):
        return read_internal_field(os.path.join(self.path, time_name, name))

    def probes(self, field, start="0"):
        """(times, values[time, probe]) of a probes function object."""
        return read_probes(os.path.join(self.path, "postProcessing", "probes", start, field))

    def cell_centres(self):
        """Cell centres from 'postProcess -func writeCellCentres' at time 0."""
        self.run("postProcess", "-func", "writeCellCentres", "-time", "0")
        return read_internal_field(os.path.join(self.path, "0", "C"))

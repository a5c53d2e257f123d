"""What the user scripts in bin/ share on their command line: a folder
checked before anything is written, and progress lines that reach a pipe
at once.

Why: a typo in a study folder used to create <typo>/stages and end in a
traceback, and `shearStudy ... | tee log` showed nothing for minutes
because Python buffers stdout when it is not a terminal.
"""

import os
import sys
import threading
import time


_SAY_LOCK = threading.Lock()


def say(message):
    """Print a progress line now, also into a pipe (tee, a test); whole
    lines from concurrent stages (shearStudy --jobs): print() writes the
    text and its newline separately, so two threads could mix them."""
    with _SAY_LOCK:
        sys.stdout.write(f"{message}\n")
        sys.stdout.flush()


def require_folder(prog, folder, needs):
    """Exit with one line (status 1) unless folder is a directory holding
    every relative path in needs; called before a script writes anything,
    so that a mistyped folder leaves nothing behind."""
    if not os.path.isdir(folder):
        sys.exit(f"{prog}: no folder {folder} (expected a case folder with "
                 f"{', '.join(needs)})")
    missing = [rel for rel in needs if not os.path.exists(os.path.join(folder, rel))]
    if missing:
        sys.exit(f"{prog}: {folder} is not a case folder for {prog}: no "
                 f"{', '.join(missing)} in it")


class StageClock:
    """Stage lines: 'PROG: stage NAME: WHAT, to t = END s' when a stage
    starts, the solver's latest progress line (simulated time, per cent,
    particle-steps/s, time left) every relay_interval seconds while it
    runs, and 'PROG: stage NAME done in N s (wall)' when it ends, so that a
    terminal or a log shows which solver run is going, how far it is and
    how long each one took. The solvers write their progress into the
    stage's log.<app>; a stage of the quick shear runs for minutes."""

    def __init__(self, prog, log=say, relay_interval=30.0):
        self.prog = prog
        self.log = log
        self.relay_interval = relay_interval
        self.seconds = {}

    def run(self, case, app, name, what, end):
        """case.run(app) between the two lines, relaying its progress;
        returns its wall seconds."""
        self.log(f"{self.prog}: stage {name}: {what}, to t = {end:.4g} s")
        start = time.monotonic()
        failure = []

        def solve():
            try:
                case.run(app)
            except BaseException as e:  # re-raised below, in the caller's thread
                failure.append(e)

        solver = threading.Thread(target=solve, daemon=True)
        solver.start()
        progress = ProgressReader(case.file("log." + app))
        relayed = None
        while True:
            solver.join(self.relay_interval)
            if not solver.is_alive():
                break
            line = progress.latest()
            if line and line != relayed:
                self.log(f"{self.prog}: stage {name}: {line}")
                relayed = line
        if failure:
            raise failure[0]
        seconds = self.seconds[name] = time.monotonic() - start
        self.log(f"{self.prog}: stage {name} done in {seconds:.0f} s (wall)")
        return seconds


class ProgressReader:
    """The latest 'Progress: ...' line of a growing solver log, without the
    word ('t = 0.169 s, 49 %, 7.3e+06 particle-steps/s, about 5 s left').
    Reads only what was added since the last call: the solvers print
    `Time =` and their step lines every fluid step, so between two progress
    lines a log grows by tens of kB."""

    def __init__(self, log):
        self.log = log
        self.offset = 0
        self.partial = ""
        self.line = None

    def latest(self):
        """The last progress line so far, or None (none yet, or no log)."""
        try:
            with open(self.log, "rb") as f:
                f.seek(self.offset)
                chunk = f.read()
        except FileNotFoundError:
            return self.line
        self.offset += len(chunk)
        lines = (self.partial + chunk.decode(errors="replace")).split("\n")
        self.partial = lines.pop()  # a line still being written
        for ln in lines:
            if ln.startswith("Progress: "):
                self.line = ln[len("Progress: "):].strip()
        return self.line


def add_jobs_option(parser, unit, help):
    """`--jobs N`: how many of the study's independent stages (unit: what
    the study calls them, e.g. "stages") run at once (darcydem.case
    run_side_by_side; None: default_jobs). parse_study_args refuses N < 1."""
    parser.add_argument("--jobs", type=int, default=None, help=help)
    parser.set_defaults(jobs_unit=unit)


def parse_study_args(parser, argv):
    """parser.parse_args(argv) with the option every study shares:
    `-parallel [N]` (N = 2 when omitted), spelt as OpenFOAM's solvers spell
    it, runs each solver of the study decomposed over N MPI ranks
    (decomposePar, mpirun -np N <solver> -parallel, reconstructPar: see
    DARCYDEM_RANKS in case.py), so that `./Allrun -parallel` of every
    tutorial only passes its arguments on. A `--jobs` of add_jobs_option
    below 1 stops with one line naming the option, before any folder is
    looked at."""
    from darcydem.case import RANKS_VARIABLE  # case.py imports nothing of ours back

    parser.add_argument(
        "-parallel", nargs="?", type=int, const=2, default=None, metavar="N",
        help="run every solver decomposed over N MPI ranks (default N: 2): decomposePar, "
             "mpirun -np N <solver> -parallel, reconstructPar")
    args = parser.parse_args(argv)
    if args.parallel is not None:
        if args.parallel < 1:
            parser.error(f"-parallel {args.parallel}: the rank count must be 1 or more")
        os.environ[RANKS_VARIABLE] = str(args.parallel)
    if getattr(args, "jobs", None) is not None and args.jobs < 1:
        sys.exit(f"{parser.prog}: --jobs {args.jobs}: give 1 or more {args.jobs_unit} at once")
    return args

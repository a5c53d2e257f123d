"""What the user scripts in bin/ share on their command line: a folder
checked before anything is written, and progress lines that reach a pipe
at once.

Why: a typo in a study folder used to create <typo>/stages and end in a
traceback, and `shearStudy ... | tee log` showed nothing for minutes
because Python buffers stdout when it is not a terminal.
"""

import os
import sys
import time


def say(message):
    """Print a progress line now, also into a pipe (tee, a test)."""
    print(message, flush=True)


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
    starts, 'PROG: stage NAME done in N s (wall)' when it ends, so that a
    log shows which solver run is going and how long each one took."""

    def __init__(self, prog, log=say):
        self.prog = prog
        self.log = log
        self.seconds = {}

    def run(self, case, app, name, what, end):
        """case.run(app) between the two lines; returns its wall seconds."""
        self.log(f"{self.prog}: stage {name}: {what}, to t = {end:.4g} s")
        start = time.monotonic()
        case.run(app)
        seconds = self.seconds[name] = time.monotonic() - start
        self.log(f"{self.prog}: stage {name} done in {seconds:.0f} s (wall)")
        return seconds

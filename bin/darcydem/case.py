"""Run real OpenFOAM case directories and read their output.

A Case is a copy of a template case; entries are changed with Debian's
foamDictionary (at 17 digits, see foamfiles.py: a process start of about
15 ms per entry, and the file rewritten without its comments),
applications are run with their log kept in the case, and fields (ascii
or binary) / probes are read back as numpy arrays. Used by the tests (templates
in tests/cases, copies in tests/run) and by the tutorials' study scripts.
"""

import os
import re
import shutil
import subprocess

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

    @classmethod
    def existing(cls, path):
        """A Case for a directory that is already there."""
        case = cls.__new__(cls)
        case.path = os.path.abspath(path)
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
        """Run an application in the case; return its log text."""
        log = self.file("log." + app)
        with open(log, "w") as out:
            rc = subprocess.call([app, "-case", self.path, *args],
                                 stdout=out, stderr=subprocess.STDOUT)
        text = open(log).read()
        if expect_fail:
            if rc == 0:
                raise RunError(f"{app} succeeded but was expected to fail")
            return text
        if rc != 0:
            raise RunError(f"{app} failed (exit {rc}) in {self.path}:\n" + text[-3000:])
        return text

    def mesh(self, state_from=None):
        """blockMesh; then, if given, a demState from another run into 0/ (the
        grains start from that prepared packing with this case's settings)."""
        self.run("blockMesh")
        if state_from is not None:
            shutil.copy(state_from, self.file("0/demState"))
        return self

    def times(self):
        """Written time directories after 0 as sorted (time, name) pairs."""
        return time_dirs(self.path)

    def field(self, time_name, name):
        return read_internal_field(os.path.join(self.path, time_name, name))

    def probes(self, field, start="0"):
        """(times, values[time, probe]) of a probes function object."""
        return read_probes(os.path.join(self.path, "postProcessing", "probes", start, field))

    def cell_centres(self):
        """Cell centres from 'postProcess -func writeCellCentres' at time 0."""
        self.run("postProcess", "-func", "writeCellCentres", "-time", "0")
        return read_internal_field(os.path.join(self.path, "0", "C"))

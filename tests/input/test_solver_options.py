"""The command line a new user tries (issue 24 item 3, issue 28): every
solver's -help offers -parallel (decomposed runs, tests/mpi) but not -dry-run
(OpenFOAM's dry run swaps the mesh for a one-dimensional column the grains'
box cannot take); started by mpirun with more than one process but without
-parallel (every process would run the whole case), or given -dry-run, the
solver stops at once saying why and what to do instead. Real binaries on
tests/cases/grainColumn (nsDemFoam: tests/cases/fixedBed)."""

import os
import subprocess

import pytest

from darcydem.case import Case, fatal_message

SOLVERS = ("darcyDemFoam", "demFoam", "nsDemFoam")
TEMPLATES = {"darcyDemFoam": "grainColumn", "demFoam": "grainColumn", "nsDemFoam": "fixedBed"}

# The launcher variables solverOptions reads (Open MPI, MPICH/Intel MPI, MVAPICH)
MPI_SIZE_VARIABLES = ("OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "MV2_COMM_WORLD_SIZE")


@pytest.fixture(scope="module")
def cases():
    """A valid case per template: runs with endTime = startTime (read and
    checked, no step)."""
    made = {}
    for template in sorted(set(TEMPLATES.values())):
        c = Case(template, f"solver_options_{template}")
        c.set("system/controlDict", "endTime", 0)
        c.run("blockMesh")
        made[template] = c
    return made


@pytest.fixture
def case(cases, solver):
    return cases[TEMPLATES[solver]]


def call(args, env_extra=None):
    """Run a command line; (exit code, stdout and stderr together)."""
    env = {k: v for k, v in os.environ.items() if k not in MPI_SIZE_VARIABLES}
    env.update(env_extra or {})
    r = subprocess.run(args, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                       env=env, timeout=120)
    return r.returncode, r.stdout


@pytest.mark.parametrize("solver", SOLVERS)
@pytest.mark.parametrize("help_option", ("-help", "-help-full"))
def test_help_offers_parallel_and_no_dry_run(solver, help_option):
    rc, out = call([solver, help_option])
    assert rc == 0, out
    assert "-case" in out  # the help itself
    assert "-parallel" in out
    for option in ("-dry-run", "-dry-run-write"):
        assert option not in out, (option, out)


@pytest.mark.parametrize("solver", SOLVERS)
def test_the_valid_case_runs(case, solver):
    """The case the refusals below are given: nothing wrong with it."""
    rc, out = call([solver, "-case", case.path])
    assert rc == 0, out[-2000:]
    # mpirun -np 1 sets the size to 1: a serial run, allowed
    rc, out = call([solver, "-case", case.path], {"OMPI_COMM_WORLD_SIZE": "1"})
    assert rc == 0, out[-2000:]


@pytest.mark.parametrize("solver", SOLVERS)
@pytest.mark.parametrize("variable", MPI_SIZE_VARIABLES)
def test_mpirun_without_parallel_is_refused(case, solver, variable):
    """mpirun -np 4 <solver> (no -parallel) would run four copies of the
    serial case writing the same files; the launcher's process count (set
    here as mpirun sets it) stops it."""
    rc, out = call([solver, "-case", case.path], {variable: "4"})
    text = fatal_message(out)
    assert rc != 0
    assert "Started by mpirun with 4 processes but without -parallel" in text
    assert "overwrite the others' files" in text
    assert f"mpirun -np 4 {solver} -parallel" in text and "decomposePar" in text
    assert f"run '{solver}' alone on the undecomposed case" in text


@pytest.mark.parametrize("solver", SOLVERS)
@pytest.mark.parametrize("option", ("-dry-run", "-dry-run-write"))
def test_dry_run_is_refused_saying_how_to_check_a_case(case, solver, option):
    rc, out = call([solver, "-case", case.path, option])
    text = fatal_message(out)
    assert rc != 0
    assert f"-dry-run is not supported by {solver}" in text
    assert "endTime equal to startTime" in text

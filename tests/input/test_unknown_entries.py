"""Every dictionary the solvers read refuses an entry it does not know
(issue 24 item 1): a mistyped name would otherwise run silently with the
default. The message names the file, the dictionary's scope in it, the
entry, the entry's own line, the valid names and, for a near miss, the name
probably meant. One mistyped entry per dictionary and sub-dictionary, each
run by the real solver on a real case (it stops while reading, before the
first step); then every tutorial and test case as it is must pass the check.
"""

import os
import re
import shutil
import subprocess

import pytest

from darcydem.case import PROJECT, TEST_RUNS, Case, apply_backend, fatal_message

DEM = "constant/demProperties"
DARCY = "constant/darcyProperties"
CTL = "system/controlDict"
NS = "constant/nsDemProperties"

# Every bond mechanism on, so that each mechanism's dictionary is read
BONDS = ("{ youngsModulus 9e6; temperature -10;"
         " creep { type maxwell; contactViscosity 1600; }"
         " compressiveCreep { type powerLaw; }"
         " strength { type iceTemperature; scale 1e-2; }"
         " sintering { type pressureSintering; }"
         " formation { type frozenOnContact; interval 10; } }")

# Set before the mistyped entry goes in: (file, entry, value) each
WITH_BONDS = [(DEM, "bonds", BONDS)]
WITH_SNOW = [(DEM, "contact", "{ type snow; youngsModulus 5e5; friction 0.5; }")]
WITH_FLAGS = [(DEM, "grainFlags", "{ base { flag fixed; zMax 0.02; } }")]
WITH_GRAIN_SIZE = [(DARCY, "permeability", "{ type kozenyCarmanGrainSize; d 1e-4;"
                    " porosityMin 0.1; porosityMax 0.9; }")]
WITH_STATS = [(CTL, "functions/stats", '{ type packingStatistics; libs ("libdemCoupling.so"); }'),
              (CTL, "functions/walls", '{ type wallStress; libs ("libdemCoupling.so"); }'),
              (CTL, "functions/creep", '{ type bondCreep; libs ("libdemCoupling.so"); }')]
WITH_UNIFORM = [(DARCY, "solidPhase", "{ type uniformPorosity; porosity 0.4; }")]

# id: template, solver, set-up, file, scope ('' the top level), the mistyped
# entry and its value, the name suggested (None: no valid name is near)
MISTYPED = {
    "demProperties": ("grainColumn", "demFoam", [], DEM, "", "neighborSkin", "0.002",
                      "neighbourSkin"),
    "demProperties-case": ("grainColumn", "demFoam", [], DEM, "", "ViscousDrag", "5",
                           "viscousDrag"),
    "contact-linearSpring": ("grainColumn", "demFoam", [], DEM, "contact", "frictoin", "0.5",
                             "friction"),
    "contact-snow": ("grainColumn", "demFoam", WITH_SNOW, DEM, "contact", "youngModulus", "5e5",
                     "youngsModulus"),
    "wallContact": ("wallBox", "demFoam", [], DEM, "wallContact", "normalDampnig", "100",
                    "normalDamping"),
    "walls-bottom": ("grainColumn", "demFoam", [], DEM, "walls/bottom", "frictionl", "yes",
                     "frictional"),
    "walls-top": ("grainColumn", "demFoam", [], DEM, "walls/top", "normalStres", "1e4",
                  "normalStress"),
    "output": ("grainColumn", "demFoam", [], DEM, "output", "fromat", "ascii", "format"),
    "grainFlags": ("grainColumn", "demFoam", WITH_FLAGS, DEM, "grainFlags/base", "zmax", "0.03",
                   "zMax"),
    "bonds": ("grainColumn", "demFoam", WITH_BONDS, DEM, "bonds", "youngModulus", "9e6",
              "youngsModulus"),
    "bonds-creep": ("grainColumn", "demFoam", WITH_BONDS, DEM, "bonds/creep", "contactViscosty",
                    "1600", "contactViscosity"),
    "bonds-compressiveCreep": ("grainColumn", "demFoam", WITH_BONDS, DEM,
                               "bonds/compressiveCreep", "prefator", "1e-3", "prefactor"),
    "bonds-strength": ("grainColumn", "demFoam", WITH_BONDS, DEM, "bonds/strength",
                       "brokenFracton", "0.05", "brokenFraction"),
    "bonds-sintering": ("grainColumn", "demFoam", WITH_BONDS, DEM, "bonds/sintering",
                        "sinterRate", "1", None),
    "bonds-formation": ("grainColumn", "demFoam", WITH_BONDS, DEM, "bonds/formation", "seeed",
                        "1", "seed"),
    "darcyProperties": ("grainColumn", "darcyDemFoam", [], DARCY, "", "Beta", "1e-8", "beta"),
    "permeability-kozenyCarman": ("grainColumn", "darcyDemFoam", [], DARCY, "permeability",
                                  "porosityMn", "0.1", "porosityMin"),
    "permeability-grainSize": ("darcyColumn", "darcyDemFoam", WITH_GRAIN_SIZE, DARCY,
                               "permeability", "kMx", "1e-12", "kMax"),
    "permeability-constant": ("darcyColumn", "darcyDemFoam", [], DARCY, "permeability", "kk",
                              "1e-14", "k"),
    "solidPhase-demGrains": ("grainColumn", "darcyDemFoam", [], DARCY, "solidPhase",
                             "topPresure", "0", "topPressure"),
    "solidPhase-fluidForce": ("grainColumn", "darcyDemFoam", [], DARCY, "solidPhase/fluidForce",
                              "coefficient", "1", None),
    "solidPhase-staticPorosity": ("darcyColumn", "darcyDemFoam", [], DARCY, "solidPhase",
                                  "porosity", "0.4", None),
    "solidPhase-uniformPorosity": ("darcyColumn", "darcyDemFoam", WITH_UNIFORM, DARCY,
                                   "solidPhase", "porsity", "0.4", "porosity"),
    "nsDemProperties": ("fixedBed", "nsDemFoam", [], NS, "", "Mu", "1e-3", "mu"),
    "nsDemProperties-grains": ("fixedBed", "nsDemFoam", [], NS, "grains", "porosityMx", "0.9",
                               "porosityMax"),
    "nsDemProperties-fluidForce": ("fixedBed", "nsDemFoam", [], NS, "grains/fluidForce",
                                   "diametr", "1e-3", "diameter"),
    "functions-grainDiagnostics": ("grainColumn", "demFoam", [], CTL,
                                   "functions/grainDiagnostics", "writeIntervl", "10",
                                   "writeInterval"),
    "functions-horizontalProfiles": ("grainColumn", "darcyDemFoam", [], CTL, "functions/profiles",
                                     "layers", "10", None),
    "functions-packingStatistics": ("grainColumn", "demFoam", WITH_STATS, CTL, "functions/stats",
                                    "Log", "yes", "log"),
    "functions-wallStress": ("grainColumn", "demFoam", WITH_STATS, CTL, "functions/walls",
                             "timeStrat", "0", "timeStart"),
    "functions-bondCreep": ("grainColumn", "demFoam", WITH_STATS, CTL, "functions/creep",
                            "writeIntrval", "10", "writeInterval"),
}


def entry_line(path, key):
    """The line number (from 1) of the one line that holds entry key."""
    lines = [n for n, line in enumerate(open(path), 1)
             if re.match(r"\s*%s\s" % re.escape(key), line)]
    assert len(lines) == 1, f"{key} on lines {lines} of {path}"
    return lines[0]


@pytest.mark.parametrize("name", MISTYPED)
def test_mistyped_entry_stops_naming_file_entry_line_and_suggestion(name):
    template, solver, setup, rel, scope, key, value, suggestion = MISTYPED[name]
    c = Case(template, f"unknown_{name}")
    c.set("system/controlDict", "endTime", 1e-3)
    for file, entry, text in setup:
        c.set(file, entry, text)
    c.set(rel, f"{scope}/{key}" if scope else key, value)
    line = entry_line(c.file(rel), key)
    c.run("blockMesh")
    log = c.run(solver, expect_fail=True)
    if rel == CTL:
        # OpenFOAM's function object list prints the error and exits 1
        # (no FOAM FATAL header)
        msg = log[log.find("Unknown entry"):]
    else:
        msg = fatal_message(log)
        assert "FOAM FATAL IO ERROR" in msg
    where = f"Unknown entry '{key}'" + (f" in '{scope}'" if scope else "")
    assert f"{where} at line {line} of {c.file(rel)}" in msg
    if suggestion is None:
        assert "did you mean" not in msg
    else:
        assert f"did you mean '{suggestion}'?" in msg
    valid = msg.split("Valid entries")[1].split("\n")[0].split()
    assert key not in valid
    if suggestion is not None:
        assert suggestion in valid


def test_range_message_prints_numbers_short():
    """At writePrecision 17 a value out of range still reads as written
    (1.1, not 1.1000000000000001)."""
    c = Case("grainColumn", "unknown_short_numbers")
    c.set("system/controlDict", "endTime", 1e-3)
    c.set("system/controlDict", "writePrecision", 17)
    c.set(DEM, "bonds", "{ youngsModulus 9e6; normalDampingRatio 1.1; }")
    c.run("blockMesh")
    msg = fatal_message(c.run("demFoam", expect_fail=True))
    assert re.search(r"must lie in \[0, 1\], found 1\.1$", msg, re.M)


# Every tutorial and test case with the solver that runs it: its
# dictionaries hold only valid names
CASES = [
    ("tutorials/darcyDemFoam/consolidation", "darcyDemFoam"),
    ("tutorials/darcyDemFoam/shear", "darcyDemFoam"),
    ("tutorials/darcyDemFoam/drainedColumn", "darcyDemFoam"),
    ("tutorials/demFoam/capsulePile", "demFoam"),
    ("tutorials/demFoam/snowSettlement", "demFoam"),
    ("tutorials/nsDemFoam/fixedBed", "nsDemFoam"),
    ("tutorials/nsDemFoam/settlingSphere", "nsDemFoam"),
    ("tutorials/nsDemFoam/darcyAndNavierStokes", "nsDemFoam"),
    ("tutorials/nsDemFoam/darcyAndNavierStokes", "darcyDemFoam"),
    ("tests/cases/darcyColumn", "darcyDemFoam"),
    ("tests/cases/closedBox", "darcyDemFoam"),
    ("tests/cases/grainColumn", "darcyDemFoam"),
    ("tests/cases/grainColumn", "demFoam"),
    ("tests/cases/wallBox", "demFoam"),
    ("tests/cases/fixedBed", "nsDemFoam"),
    ("tests/cases/settlingSphere", "nsDemFoam"),
]


@pytest.mark.parametrize("case,solver", CASES, ids=[f"{c}-{s}" for c, s in CASES])
def test_every_case_dictionary_holds_valid_names(case, solver):
    """Run with endTime = startTime: no step. A case whose grains a script
    makes (Allrun) stops when it reads them, after every dictionary."""
    path = os.path.join(TEST_RUNS, "valid_" + case.replace("/", "_") + "_" + solver)
    shutil.rmtree(path, ignore_errors=True)
    shutil.copytree(os.path.join(PROJECT, case), path,
                    ignore=shutil.ignore_patterns("stages", "*.png", "results*.json", "log.*",
                                                  "VTK", "postProcessing", "processor*"))
    apply_backend(path)
    c = Case.existing(path)
    c.set("system/controlDict", "endTime", 0)
    c.set("system/controlDict", "startFrom", "startTime")
    c.set("system/controlDict", "startTime", 0)
    c.run("blockMesh")
    log = os.path.join(path, "log." + solver)
    with open(log, "w") as out:
        rc = subprocess.call([solver, "-case", path], stdout=out, stderr=subprocess.STDOUT)
    text = open(log).read()
    assert "Unknown entry" not in text, fatal_message(text)
    if os.path.exists(os.path.join(path, DEM)):
        # The DEM dictionaries are all read before the grains
        assert "contact law" in text, text[-2000:]
    if rc != 0:
        assert not os.path.exists(os.path.join(path, "0", "grains")), text[-3000:]
        assert "grains" in fatal_message(text)

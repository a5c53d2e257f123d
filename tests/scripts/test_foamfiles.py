"""The Python helpers' reading and writing of OpenFOAM files (issue 24):
a field written in binary reads back as the same doubles as foamFormatConvert's
ascii of it (writePrecision 17), bit for bit; Case.set and read_entry pass
numbers through foamDictionary unrounded (its default 6 digits would round
every number of a file it rewrites); a function object's table reads by
its column names. Case: tests/cases/darcyColumn meshed (200 cells), its
cell centres and volumes written by postProcess: no solver run."""

import os
import shutil

import numpy as np
import pytest

from darcydem.case import Case
from darcydem.foamfiles import read_columns, read_entry, read_internal_field, read_scalar_entry

# nonuniform fields from postProcess -func writeCellCentres / writeCellVolumes,
# and p, uniform in the template (a uniform value is text in either format)
FIELDS = {"C": (200, 3), "Cx": (200,), "V": (200,), "p": (1,)}


def header_format(path):
    with open(path, "rb") as f:
        head = f.read(1000)
    return "binary" if b"format      binary;" in head else "ascii"


@pytest.fixture(scope="module")
def binary_and_ascii():
    """The same time 0 written in binary, then a copy converted to ascii."""
    c = Case("darcyColumn", "foamfiles_binary")
    c.set("system/controlDict", "writeFormat", "binary")
    c.set("system/controlDict", "writePrecision", 17)
    c.run("blockMesh")
    c.run("postProcess", "-func", "writeCellCentres", "-time", "0")
    c.run("postProcess", "-func", "writeCellVolumes", "-time", "0")
    c.run("foamFormatConvert", "-time", "0")   # the template's p, too
    ascii_path = c.path + "_ascii"
    shutil.rmtree(ascii_path, ignore_errors=True)
    shutil.copytree(c.path, ascii_path)
    a = Case.existing(ascii_path)
    a.set("system/controlDict", "writeFormat", "ascii")
    a.run("foamFormatConvert", "-time", "0")
    return c, a


@pytest.mark.parametrize("name", FIELDS)
def test_binary_field_reads_as_its_ascii(binary_and_ascii, name):
    """Each field, binary and ascii, has its shape, and equal bytes: the
    17 ascii digits of a double read back as that double, so any
    difference is the binary reader's."""
    c, a = binary_and_ascii
    binary_file, ascii_file = c.file(f"0/{name}"), a.file(f"0/{name}")
    assert (header_format(binary_file), header_format(ascii_file)) == ("binary", "ascii")
    b, t = read_internal_field(binary_file), read_internal_field(ascii_file)
    print(f"{name}: {b.shape}, first {b.reshape(len(b), -1)[0]}")
    assert b.shape == t.shape == FIELDS[name]
    assert b.dtype == t.dtype == np.float64
    assert b.tobytes() == t.tobytes()


def test_cell_centres_span_the_mesh(binary_and_ascii):
    """The binary cell centres are the mesh's (not bytes read from the
    wrong offset): darcyColumn is 2 x 2 x 50 cells of 0.01 x 0.01 x 0.002 m."""
    c, _ = binary_and_ascii
    C = read_internal_field(c.file("0/C"))
    assert np.allclose(C.min(axis=0), [0.005, 0.005, 0.001], rtol=0, atol=1e-15)
    assert np.allclose(C.max(axis=0), [0.015, 0.015, 0.099], rtol=0, atol=1e-15)
    assert np.allclose(read_internal_field(c.file("0/V")), 2e-7, rtol=1e-12, atol=0)


def test_set_and_read_keep_every_digit(tmp_path):
    """A number set with 17 digits reads back as the same double, and
    stays so when the file is rewritten for another entry; dimensioned and
    nested entries read by path; a missing entry is a KeyError."""
    c = Case("darcyColumn", "foamfiles_set")
    end, step = 0.1 + 1 / 3, 1e-4 / 3
    c.set("system/controlDict", "endTime", repr(end))
    c.set("system/controlDict", "deltaT", repr(step))
    control = c.file("system/controlDict")
    assert read_scalar_entry(control, "endTime") == end
    assert read_scalar_entry(control, "deltaT") == step
    props = c.file("constant/darcyProperties")
    assert read_scalar_entry(props, "mu") == 1e-3
    assert read_scalar_entry(props, "permeability/k") == 1e-14
    assert read_entry(props, "solidPhase/type") == "staticPorosity"
    with pytest.raises(KeyError):
        read_entry(props, "solidPhase/fluidForce")


def test_columns_by_name(tmp_path):
    """Columns named by the last '#' line before the rows; a table without
    rows gives empty columns (a run stopped before its first row)."""
    path = os.path.join(tmp_path, "table.dat")
    with open(path, "w") as f:
        f.write("# packing statistics\n# time  lidPosition  count\n0.1 0.25 3\n\n0.2 0.5 3\n")
    d = read_columns(path)
    assert list(d) == ["time", "lidPosition", "count"]
    assert d["lidPosition"].tolist() == [0.25, 0.5]
    with open(path, "w") as f:
        f.write("# time  lidPosition\n")
    assert read_columns(path)["time"].shape == (0,)

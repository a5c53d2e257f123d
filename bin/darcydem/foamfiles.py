"""Read OpenFOAM output into numpy: fields (ascii or binary), probes,
function objects' tables and dictionary entries, and the grains' VTK files
(ASCII or binary, through VTK's own reader).

Which library reads what, and why:
- Dictionary entries: OpenFOAM's own foamDictionary (Debian's
  openfoam package, already installed for the solver), so that an entry
  is found as the solver finds it (sub-dictionaries, #include, comments).
  A call costs a process start, 14-17 ms measured here; studies make a
  few dozen. It prints and rewrites numbers at 6 digits unless told
  otherwise: every call passes -precision 17, so that a number goes
  through it as the same double (FOAM_DICTIONARY below).
- Fields: read here with numpy. foamDictionary v1912 cannot read a binary
  field (it stops at the first byte of the list: "Expected a '(' while
  reading VectorSpace"), and foamFormatConvert would have to rewrite the
  case's time directories as ascii first (changing the case, a mesh-sized
  run per read). The binary format is small: an ascii header and list
  sizes around a block of raw doubles whose byte order and width the
  header's 'arch' names; tests/scripts/test_foamfiles.py checks the binary
  reading against foamFormatConvert's ascii of the same field, bit for bit.
- Not foamlib: it is on PyPI only (not in Debian 12), and
  bin/install-dependencies installs from apt alone; pip on Debian 12's
  system Python is blocked (PEP 668) and a venv for one package is more
  for a new user to set up than this module's few lines."""

import json
import os
import re
import subprocess

import numpy as np

# foamDictionary as every helper calls it: numbers at 17 digits, which read
# back as the same double (at its default 6, '-set' would round every number
# of the file it rewrites, and '-value' the one it prints)
FOAM_DICTIONARY = ["foamDictionary", "-precision", "17"]

# the grainDiagnostics function object's table in a case (doc/CASE-FORMAT.md)
GRAIN_DIAGNOSTICS = "postProcessing/grainDiagnostics/0/grainDiagnostics.dat"

# components of OpenFOAM's field types
COMPONENTS = {"scalar": 1, "vector": 3, "sphericalTensor": 1, "symmTensor": 6, "tensor": 9}


def read_entry(path, entry):
    """The value of a dictionary entry (slash-separated path, e.g.
    "solidPhase/fluidForce/type") as foamDictionary prints it; KeyError when
    the dictionary has no such entry."""
    result = subprocess.run([*FOAM_DICTIONARY, "-entry", entry, "-value", path],
                            capture_output=True, text=True)
    if result.returncode != 0:
        if "Cannot find entry" in result.stdout + result.stderr:
            raise KeyError(f"{entry} not found in {path}")
        raise RuntimeError(f"foamDictionary could not read {entry} of {path}:\n"
                           + result.stdout + result.stderr)
    return result.stdout.strip()


def read_scalar_entry(path, entry):
    """A number entry 'key value;' or dimensioned 'key [dims] value;' as a float."""
    return float(read_entry(path, entry).split()[-1])


def read_internal_field(path):
    """internalField of a volField written in ascii or binary: (n,) for
    scalars, (n, components) otherwise; a uniform field gives one value."""
    data = open(path, "rb").read()
    header = re.search(rb"FoamFile\s*\{([^}]*)\}", data)
    binary = header is not None and re.search(rb"\bformat\s+binary\s*;", header.group(1))
    start = data.index(b"internalField")
    m = re.compile(rb"internalField\s+uniform\s+([^;]+);").match(data, start)
    if m:
        # a uniform value is written as text in either format
        value = m.group(1).decode().strip()
        if value.startswith("("):
            return np.array([[float(v) for v in value.strip("()").split()]])
        return np.array([float(value)])
    m = re.compile(rb"internalField\s+nonuniform\s+List<(\w+)>\s*(\d+)\s*\(").match(data, start)
    if not m or m.group(1).decode() not in COMPONENTS:
        raise ValueError(f"cannot parse internalField of {path}")
    kind, n = m.group(1).decode(), int(m.group(2))
    components = COMPONENTS[kind]
    if binary:
        dtype = binary_scalar(header.group(1), path)
        end = m.end() + n * components * dtype.itemsize
        if data[end:end + 1] != b")":
            raise ValueError(f"{path}: the binary list of {n} {kind} does not end where "
                             "its size says")
        arr = np.frombuffer(data, dtype, n * components, m.end()).astype(float)
    else:
        values = data[m.end():data.index(b";", m.end())].decode().rstrip().rstrip(")")
        arr = np.array([float(v) for v in values.replace("(", " ").replace(")", " ").split()])
    return arr if components == 1 else arr.reshape(n, components)


def binary_scalar(header, path):
    """numpy type of the scalars of a binary file from its header's arch,
    e.g. "LSB;label=32;scalar=64" (little-endian doubles)."""
    m = re.search(rb'arch\s+"([^"]*)"', header)
    arch = m.group(1).decode() if m else "LSB;label=32;scalar=64"
    order = {"LSB": "<", "MSB": ">"}.get(arch.split(";")[0])
    bits = re.search(r"scalar=(\d+)", arch)
    if order is None or bits is None or bits.group(1) not in ("32", "64"):
        raise ValueError(f"{path}: binary arch {arch!r} not understood")
    return np.dtype(order + "f" + str(int(bits.group(1)) // 8))


def read_probes(path):
    """(times, values[time, probe]) of a probes function object file."""
    rows = []
    for line in open(path):
        if line.startswith("#") or not line.strip():
            continue
        rows.append([float(v) for v in line.replace("(", " ").replace(")", " ").split()])
    data = np.array(rows)
    return data[:, 0], data[:, 1:]


def time_dirs(case):
    """Written time directories after 0 as sorted (time, name) pairs."""
    out = []
    for d in os.listdir(case):
        try:
            t = float(d)
        except ValueError:
            continue
        if t > 0:
            out.append((t, d))
    return sorted(out)


def read_vtp(path):
    """Points and point arrays of a VTK XML PolyData file (.vtp, ASCII or
    binary), read by VTK's vtkXMLPolyDataReader, the reader ParaView uses:
    {"position": (n, 3), name: (n,) or (n, components)}."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
    reader = vtkXMLPolyDataReader()
    if not os.path.isfile(path) or not reader.CanReadFile(path):
        raise ValueError(f"{path} is not a VTK XML PolyData file")
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    # copies: the numpy views would outlive the reader that owns the memory
    out = {"position": np.array(vtk_to_numpy(data.GetPoints().GetData())).reshape(-1, 3)}
    point_data = data.GetPointData()
    for i in range(point_data.GetNumberOfArrays()):
        array = point_data.GetArray(i)
        out[array.GetName()] = np.array(vtk_to_numpy(array))
    return out


def read_vtp_lines(path):
    """Points, line cells and cell arrays of a VTK XML PolyData file of
    lines (the bonds' .vtp), read by VTK's vtkXMLPolyDataReader:
    {"points": (n, 3), "lines": (m, 2) point indices, name: (m,) or
    (m, components)}."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
    reader = vtkXMLPolyDataReader()
    if not os.path.isfile(path) or not reader.CanReadFile(path):
        raise ValueError(f"{path} is not a VTK XML PolyData file")
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    points = data.GetPoints()
    out = {"points": np.zeros((0, 3)) if points is None
           else np.array(vtk_to_numpy(points.GetData())).reshape(-1, 3)}
    lines = []
    cells = data.GetLines()
    cells.InitTraversal()
    from vtkmodules.vtkCommonCore import vtkIdList
    ids = vtkIdList()
    while cells.GetNextCell(ids):
        lines.append([ids.GetId(k) for k in range(ids.GetNumberOfIds())])
    out["lines"] = np.array(lines, dtype=int).reshape(-1, 2)
    cell_data = data.GetCellData()
    for i in range(cell_data.GetNumberOfArrays()):
        array = cell_data.GetArray(i)
        out[array.GetName()] = np.array(vtk_to_numpy(array))
    return out


def read_columns(path):
    """A function object's table (postProcessing/<name>/<time>/<file>.dat):
    {column name: values}, the names from the last '#' line before the
    data ('# time name ...'); a table without rows gives empty columns."""
    names = None
    rows = []
    for line in open(path):
        if line.startswith("#"):
            if not rows:
                names = line[1:].split()
        elif line.strip():
            rows.append(line.split())
    if names is None:
        raise ValueError(f"{path}: no header line naming the columns")
    data = np.array(rows, dtype=float).reshape(-1, len(names))
    return {name: data[:, k] for k, name in enumerate(names)}


# Folder of the grains' ParaView files (grains, capsules, bonds and their
# series) in a case; not VTK/, which 'foamToVTK -overwrite' removes whole
GRAINS_DIR = os.path.join("postProcessing", "grains")


def grain_files(case, series_name="grains"):
    """(time, path) of the grains' .vtp files in the order of the VTK file
    series <case>/postProcessing/grains/grains.vtp.series (JSON) that
    ParaView opens (series_name "capsules": the grains' surfaces,
    capsules_<time>.vtp)."""
    series = os.path.join(case, GRAINS_DIR, series_name + ".vtp.series")
    with open(series) as f:
        entries = json.load(f)["files"]
    return [(e["time"], os.path.join(os.path.dirname(series), e["name"])) for e in entries]


def read_grains(path):
    """A grains file (<time>/grains) as {"position" (n, 3), "radius" (n,),
    "coreHalfLength" (n,), "orientation" (n, 4) (w x y z), "velocity"
    (n, 3)}: sphere lines 'x y z r [vx vy vz]' (h = 0, q = 1), capsule lines
    'x y z r h qw qx qy qz [vx vy vz]'."""
    rows = [[float(v) for v in line.split()] for line in open(path)
            if line.strip() and not line.lstrip().startswith("#")]
    out = {k: [] for k in ("position", "radius", "coreHalfLength", "orientation", "velocity")}
    for v in rows:
        if len(v) not in (4, 7, 9, 12):
            raise ValueError(f"{path}: a line of {len(v)} columns")
        capsule = len(v) in (9, 12)
        out["position"].append(v[:3])
        out["radius"].append(v[3])
        out["coreHalfLength"].append(v[4] if capsule else 0.0)
        out["orientation"].append(v[5:9] if capsule else [1.0, 0.0, 0.0, 0.0])
        out["velocity"].append(v[-3:] if len(v) in (7, 12) else [0.0, 0.0, 0.0])
    return {k: np.array(v, dtype=float) for k, v in out.items()}


def capsule_axes(q):
    """Unit capsule axes R(q) e_z of quaternions q (n, 4), (w, x, y, z)."""
    w, x, y, z = np.asarray(q, dtype=float).T
    return np.stack([2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)], axis=1)


DEM_STATE_MAGIC = b"darcyDem-state 1\n"


def read_dem_state(path):
    """A <time>/demState (doc/CASE-FORMAT.md: the magic line, then the
    named real arrays and the named 64-bit integer arrays, each a uint64
    count of arrays and per array a uint64 name length, the name, a uint64
    length and the values, little-endian): ({name: float64 array},
    {name: int64 array})."""
    data = open(path, "rb").read()
    if not data.startswith(DEM_STATE_MAGIC):
        raise ValueError(f"{path} is not a demState file")
    at = len(DEM_STATE_MAGIC)
    groups = []
    for dtype in ("<f8", "<i8"):
        arrays = {}
        count = int(np.frombuffer(data, "<u8", 1, at)[0])
        at += 8
        for _ in range(count):
            length = int(np.frombuffer(data, "<u8", 1, at)[0])
            name = data[at + 8:at + 8 + length].decode()
            at += 8 + length
            size = int(np.frombuffer(data, "<u8", 1, at)[0])
            arrays[name] = np.frombuffer(data, dtype, size, at + 8).copy()
            at += 8 + 8 * size
        groups.append(arrays)
    if at != len(data):
        raise ValueError(f"{path}: {len(data) - at} bytes after the arrays")
    return groups[0], groups[1]


def write_dem_state(path, reals, integers):
    """Write what read_dem_state reads (for tests that alter a state)."""
    with open(path, "wb") as out:
        out.write(DEM_STATE_MAGIC)
        for arrays, dtype in ((reals, "<f8"), (integers, "<i8")):
            out.write(np.uint64(len(arrays)).astype("<u8").tobytes())
            for name, values in arrays.items():
                out.write(np.uint64(len(name)).astype("<u8").tobytes() + name.encode())
                values = np.asarray(values, dtype=dtype)
                out.write(np.uint64(values.size).astype("<u8").tobytes() + values.tobytes())

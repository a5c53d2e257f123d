"""Read OpenFOAM output into numpy: ASCII fields, probes and plain entries,
and the grains' VTK files (ASCII or binary, through VTK's own reader)."""

import json
import os
import re

import numpy as np


def read_internal_field(path):
    """internalField of an ASCII volField: (n,) scalars or (n, 3) vectors;
    a uniform field gives one value."""
    text = open(path).read()
    body = text[text.index("internalField"):]
    m = re.match(r"internalField\s+uniform\s+([^;]+);", body[:300])
    if m:
        value = m.group(1).strip()
        if value.startswith("("):
            return np.array([[float(v) for v in value.strip("()").split()]])
        return np.array([float(value)])
    m = re.match(r"internalField\s+nonuniform\s+List<(\w+)>\s*(\d+)\s*\(", body)
    if not m:
        raise ValueError(f"cannot parse internalField of {path}")
    n = int(m.group(2))
    values = body[m.end():body.index(";", m.end())].rstrip().rstrip(")")
    arr = np.array([float(v) for v in values.replace("(", " ").replace(")", " ").split()])
    return arr.reshape(n, 3) if m.group(1) == "vector" else arr


def read_probes(path):
    """(times, values[time, probe]) of a probes function object file."""
    rows = []
    for line in open(path):
        if line.startswith("#") or not line.strip():
            continue
        rows.append([float(v) for v in line.replace("(", " ").replace(")", " ").split()])
    data = np.array(rows)
    return data[:, 0], data[:, 1:]


def read_scalar_entry(path, key):
    """Value of the first 'key [dims] value;' entry anywhere in a dictionary."""
    text = open(path).read()
    m = re.search(r"(?m)^\s*%s\s+(?:\[[^\]]*\]\s*)?([-+0-9.eE]+)\s*;" % re.escape(key), text)
    if not m:
        raise KeyError(f"{key} not found in {path}")
    return float(m.group(1))


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
    data ('# time name ...')."""
    names = None
    for line in open(path):
        if line.startswith("#"):
            names = line[1:].split()
        else:
            break
    values = np.loadtxt(path, comments="#", ndmin=2)
    return {name: values[:, k] for k, name in enumerate(names)}


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

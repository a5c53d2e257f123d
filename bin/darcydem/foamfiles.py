"""Read ASCII OpenFOAM output (fields, probes, plain entries) into numpy."""

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

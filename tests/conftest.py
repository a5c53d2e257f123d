"""pytest set-up: bin/ (the darcydem Python package: case handling,
analytic solutions, OpenFOAM file readers) becomes importable, and the DEM
backend of every case defaults to the CPU (reproducible values; run the suite
on the GPU with DARCYDEM_BACKEND=cuda bin/runTests)."""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "bin"))

os.environ.setdefault("DARCYDEM_BACKEND", "cpu")

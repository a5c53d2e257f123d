"""pytest set-up: bin/ (the darcydem Python package: case handling,
analytic solutions, OpenFOAM file readers) becomes importable."""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "bin"))

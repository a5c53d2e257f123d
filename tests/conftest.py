"""pytest set-up: tests/lib (case helpers) and bin/ (the darcydem Python
package: analytic solutions, plotting) become importable."""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "lib"))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "bin"))

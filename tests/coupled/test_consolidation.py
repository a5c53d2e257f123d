"""Coupled consolidation against Terzaghi (doc/REFERENCES.md section 3): runs the
study of tutorials/darcyDemFoam/consolidation (prepare a packing, measure
E_oed with a dry load step and k with steady flow through the fixed grains,
then load it saturated, drained at the top, closed at the base) and compares
settlement and base pressure with Terzaghi's solution for the same c_v.

Theory for this model (bin/darcydem/analytic.py): the grains feel -V grad p
(eq. 12), so c_v = (k/mu)/(phi beta + (1 - phi)/E_oed), the undrained pressure
is dsigma/((1 - phi) + phi beta E_oed), and a share U0 = phi beta E/((1 - phi)
+ phi beta E) of the settlement happens at once; the load is ramped over
0.02 s and the theory superposed over the ramp.

Tolerances (measured values in tests/README.md): settlement within 0.08 of
the final settlement (rms over 0.05 <= T_v <= 1.5; measured 0.053), base
pressure within 0.15 p0 (rms; measured 0.135), and halving the coupling
interval changes the settlement curve by less than 2 % of the final
settlement (measured 0.07 %). The base pressure falls faster than Terzaghi
at first and slower in the tail (tests/README.md): one c_v from one secant
E_oed and one k cannot describe a packing whose stiffness and permeability
are not uniform over its 14 grain layers."""

import json

import pytest

from darcydem.case import copy_tutorial
from darcydem.consolidation import Study


@pytest.fixture(scope="module")
def study():
    path = copy_tutorial("consolidation", "consolidation")
    s = Study(path)
    s.run()
    s.plot()
    print(json.dumps(s.results, indent=1))
    return s.results


def test_packing_is_prepared_and_measured(study):
    assert study["prepare"]["kineticEnergyEnd"] < 1e-4
    assert 1e6 < study["oedometer"]["E_oed"] < 1e8
    assert 0.3 < study["permeability"]["porosity"] < 0.5
    assert study["permeability"]["k"] > 0


def test_settlement_follows_terzaghi(study):
    assert study["comparison"]["U_rmsError(0.05<=Tv<=1.5)"] < 0.08


def test_excess_pressure_dissipates_as_terzaghi(study):
    cmp_ = study["comparison"]
    assert cmp_["basePressure_rmsError"] < 0.15
    assert cmp_["basePressureEnd/p0"] < 0.1


def test_halving_the_coupling_interval(study):
    assert study["comparison"]["halfStepMaxChange"] < 0.02

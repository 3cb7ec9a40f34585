"""One interface for results of one kind, checked against the literature:

- operating points of a rolling model: the velocities the constraints
  determine follow from those given (rolling without slipping: the contact
  point moves at r*spin along the heading), and the one they leave free
  (the heading rate) is named;
- a rolling (nonholonomic) model is pointed to ``steady_motions``, not to
  ``Lagrangian.reduce`` (which nonholonomic models refuse).

The disk is the thin disk of tests/test_nonholonomic.py (Routh, Advanced
Rigid Dynamics, art. 244; K. T. McDonald, arXiv:physics/0008227).
"""
import copy

import pytest
from sage.all import SR, cos, sin

from sage_dynsym import stationary_motions, DynSymError
from sage_dynsym.analysis.operating_point import OperatingPoint
from sage_dynsym.analysis.steady import steady_motions, steady_linearization
from sage_dynsym.description import model_from_dict
from sage_dynsym.errors import AnalysisError

DISK = {
    'kind': 'mechanical', 'name': 'rolling disk',
    'parameters': ['m', 'r', 'A', 'C', 'g', 'W'], 'coordinates': ['x', 'y', 'psi', 'theta', 'phi'],
    'positive': ['m', 'r', 'A', 'C', 'g'],
    'force_function': {'uniform_gravity': [0, 0, '-g']},
    'bodies': [
        {'name': 'frame', 'joint': ['x', 'y', 0], 'rotations': [[3, 'psi'], [1, 'theta']]},
        {'name': 'disk', 'parent': 'frame', 'joint': [0, 0, 'r'], 'rotations': [[2, 'phi']],
         'mass': 'm', 'inertia': [['A', 0, 0], [0, 'C', 0], [0, 0, 'A']]}],
    'rolling': [{'body': 'disk', 'radius': 'r', 'axle': 2}]}

x, y, psi, theta, phi, dx, dy, dpsi, dphi, m, r, A, C, g, W = (
    SR.var(n) for n in 'x y psi theta phi dx dy dpsi dphi m r A C g W'.split())


def disk():
    return model_from_dict(copy.deepcopy(DISK))


def test_operating_point_derives_the_velocities_the_constraints_determine():
    S = disk()
    motion = steady_linearization(S.equations_record(),
                                  OperatingPoint('upright', {theta: 0}, {dphi: W, dpsi: 0}),
                                  [theta, psi])
    v = motion.velocities()
    # rolling without slipping: the contact point moves along the heading at r*W
    assert (v[dx] * sin(psi) - v[dy] * cos(psi)).simplify_full().is_zero()
    assert (v[dx] ** 2 + v[dy] ** 2 - r ** 2 * W ** 2).simplify_full().is_zero()
    # the heading rate is left free by the constraints: named alone, with the calls that work
    with pytest.raises(AnalysisError) as error:
        steady_linearization(S.equations_record(),
                             OperatingPoint('upright', {theta: 0}, {dphi: W}), [theta, psi])
    message = str(error.value)
    assert "the constraints determine dx, dy but not dpsi" in message
    assert "dpsi: 0" in message and "fix psi" in message


def test_rolling_model_is_pointed_to_steady_motions():
    S = disk()
    for model in (S, S.lagrangian()):
        with pytest.raises(AnalysisError) as error:
            stationary_motions(model)
        assert "steady_motions" in str(error.value)
        assert "Lagrangian.reduce" not in str(error.value)
    # and the call suggested works: the upright disk spinning at W runs straight
    Omega = SR.var('Omega')
    solutions = steady_motions(S, OperatingPoint('upright', {theta: 0}, {dphi: W, dpsi: Omega}),
                               [Omega], positive=[m, r, A, C, g, W])
    assert [s.values() for s in solutions] == [{Omega: 0}]

"""One interface for results of one kind, checked against the literature:

- stationary and steady motions answer point(), values(), conditions() and
  stability() with the same meaning: the conical motions of the spherical
  pendulum (Goldstein, Classical Mechanics, sec. 3.11: Omega^2 = g/(l cos a)
  with a the angle from the downward vertical, p = m l^2 sin^2 a Omega; the
  conical motions are stable, Routh's theorem) and the upright rolling disk
  (straight, Omega = 0; stable iff C (C + m r^2) W^2 > m g r A, for a
  uniform disk W^2 > g/(3 r));
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
import math

import pytest
from sage.all import SR, QQ, cos, sin

from sage_dynsym import load

from sage_dynsym import stationary_motions, DynSymError
from sage_dynsym.analysis.operating_point import OperatingPoint
from sage_dynsym.analysis.steady import steady_linearization
from sage_dynsym.analysis.steady_solutions import steady_motions
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


def _conical():
    R = load('examples/spherical_pendulum.yaml').lagrangian().routh([psi])
    return stationary_motions(R, solve_for=R.momenta(), positive=[m, SR.var('l'), g])


def _upright():
    S = disk().subs({A: m * r ** 2 / 4, C: m * r ** 2 / 2})
    Omega = SR.var('Omega')
    point = OperatingPoint('upright', {theta: 0}, {dphi: W, dpsi: Omega},
                           coordinates=[theta, psi])
    return steady_motions(S, point, [Omega], positive=[m, r, g]), Omega


def test_stationary_and_steady_motions_answer_the_same_four_calls():
    l, p = SR.var('l'), SR.var('p_psi')
    conical = _conical()
    rolling, Omega = _upright()
    answers = {}
    for name, motions in (('conical', conical), ('rolling', rolling)):
        for s in motions:
            point, values, conditions, verdict = (s.point(), s.values(), s.conditions(),
                                                  s.stability())
            assert isinstance(point, dict) and isinstance(values, dict)
            assert isinstance(conditions, list) and verdict.verdict()
            answers.setdefault(name, []).append((point, values, conditions, verdict))
    # the conical motions: both senses of rotation, the textbook momentum, below the support
    numbers = {m: 1.3, l: 0.7, g: 9.81}
    for a in (0.2, 1.0, 1.4):                   # angle from the downward vertical
        th = math.pi - a
        omega = math.sqrt(9.81 / (0.7 * math.cos(a)))
        expected = 1.3 * 0.7 ** 2 * math.sin(a) ** 2 * omega
        found = sorted(float(pt[p].subs({**numbers, theta: th}))
                       for pt, _, _, _ in answers['conical'])
        assert abs(found[0] + expected) < 1e-12 * expected
        assert abs(found[1] - expected) < 1e-12 * expected
    for point, values, conditions, verdict in answers['conical']:
        assert point == values                       # solved for the momentum alone
        assert all(bool(c.subs({theta: 2.5})) for c in conditions)       # below: exists
        assert not all(bool(c.subs({theta: 1.0})) for c in conditions)   # above: does not
        assert verdict.verdict() == 'stable'
    # the upright disk runs straight: heading rate zero, spin as given
    (point, values, conditions, verdict), = answers['rolling']
    assert point == {theta: 0, dpsi: 0, dphi: W} and values == {Omega: 0}
    assert conditions == []
    critical = math.sqrt(9.81 / (3 * 0.5))          # W^2 = g/(3 r) for a uniform disk
    numbers = {m: 1, r: QQ(1) / 2, g: 9.81}
    assert verdict.at({**numbers, W: 0.9 * critical}) == 'unstable'
    assert verdict.at({**numbers, W: 1.1 * critical}) == 'stable in first approximation'
    assert verdict.at({**numbers, W: -1.1 * critical}) == 'stable in first approximation'

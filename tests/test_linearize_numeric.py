"""
``linearize(system, state, values=...)`` at a state that is not an
equilibrium (analysis/linear.py through the model's compiled Jacobian):
a double pendulum with an offset mass centre under gravity, checked against
central differences of the numerical right-hand side.
"""
import numpy as np
import pytest

from sage.all import var, diagonal_matrix, pi

from sage_dynsym import MechanicalSystem, RigidBody, UniformGravity
from sage_dynsym.analysis.linear import linearize
from sage_dynsym.errors import AnalysisError


def _double_pendulum():
    a, b, m1, m2, l1, l2, g = var('a b m1 m2 l1 l2 g')
    upper = RigidBody('upper', rotations=[(1, a)], mass=m1, mass_center=[0, 0, -l1 / 2],
                      inertia=diagonal_matrix([m1 * l1**2 / 3, m1 * l1**2 / 3, 0]))
    lower = RigidBody('lower', parent='upper', joint=[0, 0, -l1], rotations=[(1, b)], mass=m2,
                      mass_center=[0, 0.1, -l2 / 2],
                      inertia=diagonal_matrix([m2 * l2**2 / 3, m2 * l2**2 / 3, 0.01]))
    S = MechanicalSystem([upper, lower], [a, b], force_function=UniformGravity([0, 0, -g]))
    return S, (a, b), {m1: 1.0, m2: 0.7, l1: 1.2, l2: 0.9, g: 9.81}


def test_linearize_at_any_state_matches_central_differences():
    S, (a, b), values = _double_pendulum()
    x0 = np.array([0.7, -1.1, 0.4, 1.3])        # moving, far from the equilibria
    state = {a: x0[0], b: x0[1], 'da': x0[2], 'db': x0[3]}
    A = linearize(S, state, values=values)
    f = S.numerical_rhs(values)
    h = 1e-6
    reference = np.column_stack([(f(0.0, x0 + h * e) - f(0.0, x0 - h * e)) / (2 * h)
                                 for e in np.eye(4)])
    A = A.numpy()
    assert np.abs(A - reference).max() < 1e-7 * max(1.0, np.abs(reference).max())
    assert np.abs(A[2:, :2]).max() > 1        # the gravity terms are there


def test_linearize_without_values_points_to_the_numeric_call():
    S, (a, b), _ = _double_pendulum()
    with pytest.raises(AnalysisError, match=r"values=\{parameter: number\}"):
        linearize(S, {a: 0.7, b: -1.1})

"""
One rigid-body recursion, two arithmetics (issue 31): the kinematic pass,
Newton-Euler, the composite-body and the articulated-body algorithms of
numerics/ run over Sage's symbolic ring and over the compiled expression
graph, and the symbolic equations of the mechanics use them.

The reference is the textbook planar double pendulum (point masses m1, m2
on massless rods l1, l2, relative angles q1, q2, gravity g along -y): its
mass matrix, velocity terms and gravity terms written out here by hand.
"""
import random

import numpy as np
import pytest

from sage.all import SR, var, cos, sin, diagonal_matrix, matrix, vector

from sage_dynsym import MechanicalSystem, RigidBody, UniformGravity
from sage_dynsym.algebra.trigonometric import SymbolicBackend
from sage_dynsym.mechanics.kinematics import Kinematics
from sage_dynsym.numerics.articulated_body import articulated_accelerations
from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
from sage_dynsym.numerics.composite_body import mass_matrix
from sage_dynsym.numerics.newton_euler import generalized_bias_forces
from sage_dynsym.numerics.recursive import RecursiveForm, tree_accelerations
from sage_dynsym.numerics.spatial import SymbolicArithmetic
from sage_dynsym.numerics.tree_kinematics import TreeKinematics

q1, q2, dq1, dq2, m1, m2, l1, l2, g = var('q1 q2 dq1 dq2 m1 m2 l1 l2 g')


def _point_mass(m, l):
    # a point mass m at (l, 0, 0): inertia about the joint
    return dict(mass=m, mass_center=[l, 0, 0], inertia=diagonal_matrix([0, m * l**2, m * l**2]))


def _tree():
    return BodyTree([TreeBody(0, rotations=[(3, q1)], **_point_mass(m1, l1)),
                     TreeBody(1, joint=[l1, 0, 0], rotations=[(3, q2)], **_point_mass(m2, l2))],
                    [q1, q2], gravity=[0, -g, 0])


#: the textbook equations M ddq + h = 0 of the double pendulum
M_REF = matrix(SR, [[(m1 + m2) * l1**2 + m2 * l2**2 + 2 * m2 * l1 * l2 * cos(q2),
                     m2 * l2**2 + m2 * l1 * l2 * cos(q2)],
                    [m2 * l2**2 + m2 * l1 * l2 * cos(q2), m2 * l2**2]])
H_REF = vector(SR, [-m2 * l1 * l2 * sin(q2) * (2 * dq1 * dq2 + dq2**2)
                    + (m1 + m2) * g * l1 * cos(q1) + m2 * g * l2 * cos(q1 + q2),
                    m2 * l1 * l2 * sin(q2) * dq1**2 + m2 * g * l2 * cos(q1 + q2)])


def _zero(e):
    return SR(e).simplify_full().is_zero()


def test_symbolic_arithmetic_gives_the_textbook_mass_matrix_and_terms():
    kin = TreeKinematics(_tree(), SymbolicArithmetic())
    M = mass_matrix(kin)
    h = generalized_bias_forces(kin)
    for i in range(2):
        assert _zero(h[i] - H_REF[i])
        for j in range(2):
            assert _zero(M.get((i, j), 0) - M_REF[i, j])


@pytest.mark.parametrize('solver', ['articulated', 'ltdl'])
def test_symbolic_accelerations_solve_the_textbook_equations(solver):
    kin = TreeKinematics(_tree(), SymbolicArithmetic())
    ddq, _, used = tree_accelerations(kin, solver)
    assert used == solver
    residual = M_REF * vector(SR, ddq) + H_REF
    point = {q1: 0.3, q2: -1.1, dq1: 0.7, dq2: 0.2, m1: 1.5, m2: 0.8, l1: 1.2, l2: 0.9, g: 9.81}
    assert all(abs(float(r.subs(point))) < 1e-12 for r in residual)


def test_articulated_body_in_both_arithmetics():
    kin = TreeKinematics(_tree(), SymbolicArithmetic())
    symbolic, _ = articulated_accelerations(kin, [0, 0])
    kernel = RecursiveForm(_tree()).kernel('python')
    parameters = RecursiveForm(_tree()).parameters()
    rng = random.Random(31)
    for _ in range(3):
        values = {p: rng.uniform(0.5, 2) for p in parameters}
        x = [rng.uniform(-2, 2) for _ in range(4)]
        state = dict(zip([q1, q2, dq1, dq2], x))
        compiled = kernel(0.0, x, [values[p] for p in parameters])
        point = {**state, **values}
        reference = np.linalg.solve([[float(e.subs(point)) for e in row] for row in M_REF],
                                    [-float(e.subs(point)) for e in H_REF])
        assert np.allclose(compiled[2:], reference, rtol=1e-10, atol=1e-12)
        assert np.allclose([float(e.subs(point)) for e in symbolic], reference,
                           rtol=1e-10, atol=1e-12)


def test_the_mechanics_equations_use_the_same_recursion():
    # the same pendulum as a MechanicalSystem: its recursive equations are
    # the textbook ones, and its kinematics reads the tree of its own bodies
    bodies = [RigidBody('one', rotations=[(3, q1)], **_point_mass(m1, l1)),
              RigidBody('two', parent='one', joint=[l1, 0, 0], rotations=[(3, q2)],
                        **_point_mass(m2, l2))]
    S = MechanicalSystem(bodies, [q1, q2], force_function=UniformGravity([0, -g, 0]))
    K = Kinematics(S, SymbolicBackend())
    assert [b is c for b, c in zip(K.body_tree().bodies(), S.bodies())] == [True, True]
    A, A1, T0, h = K.recursive_equations((0, -g, 0))
    assert all(_zero(A[i][j] - M_REF[i, j]) for i in range(2) for j in range(2))
    assert all(_zero(h[i] - H_REF[i]) for i in range(2))
    assert A1 == [0, 0] and T0 == 0


def test_inverse_dynamics_is_the_textbook_left_hand_side():
    from sage_dynsym.numerics.newton_euler import inverse_dynamics
    ddq1, ddq2 = var('ddq1 ddq2')
    tau = inverse_dynamics(_tree().kinematics('symbolic'), [ddq1, ddq2])
    reference = M_REF * vector(SR, [ddq1, ddq2]) + H_REF
    assert all(_zero(a - b) for a, b in zip(tau, reference))

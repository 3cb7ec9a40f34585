"""
One rigid-body recursion, two arithmetics (issue 31): the kinematic pass,
Newton-Euler, the composite-body and the articulated-body algorithms of
numerics/ run over Sage's symbolic ring and over the compiled expression
graph, and the symbolic equations of the mechanics use them.

The reference is the textbook planar double pendulum (point masses m1, m2
on massless rods l1, l2, relative angles q1, q2, gravity g along -y): its
mass matrix, velocity terms and gravity terms written out here by hand.
Prescribed joint velocities are checked against SymPy's LagrangesMethod
(reference.sympy_chain) and a textbook equation, the projection of loads
against the virtual work by central differences (sections below).
"""
import math
import random

import numpy as np
import pytest

from sage.all import SR, var, cos, sin, sqrt, diagonal_matrix, matrix, vector

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


@pytest.mark.parametrize('method', ['auto', 'polynomial', 'symbolic', 'recursive'])
def test_each_calculus_method_of_the_model_gives_the_textbook_equations(method):
    # the strategy is chosen on the model: its Lagrangian, its numerical
    # right-hand side (built after the choice) and its substituted copies
    # follow it, and every method gives the textbook equations
    bodies = [RigidBody('one', rotations=[(3, q1)], **_point_mass(m1, l1)),
              RigidBody('two', parent='one', joint=[l1, 0, 0], rotations=[(3, q2)],
                        **_point_mass(m2, l2))]
    S = MechanicalSystem(bodies, [q1, q2], force_function=UniformGravity([0, -g, 0]))
    values = {'m1': 1.5, 'm2': 0.8, 'l1': 1.2, 'l2': 0.9, 'g': 9.81}
    before = S.numerical_rhs(values, backend='python', algorithm='equations')
    S.set_calculus_method(method)
    assert S.calculus_method() == method and S.subs({g: 1}).calculus_method() == method
    reference = M_REF * vector(SR, var('ddq1 ddq2')) + H_REF     # the accelerations' names
    assert all(_zero(a - b) for a, b in zip(S.lagrangian().lagrange_equations(), reference))
    after = S.numerical_rhs(values, backend='python', algorithm='equations')
    x = np.array([0.3, -1.1, 0.7, 0.2])
    assert np.allclose(after(0.0, x), before(0.0, x), rtol=1e-12, atol=1e-12)


def test_the_calculus_method_is_checked():
    from sage_dynsym.errors import ModelError
    with pytest.raises(ModelError, match="calculus_method: expected one of"):
        MechanicalSystem([RigidBody('b', rotations=[(3, q1)])], [q1], calculus_method='sympy')


def test_inverse_dynamics_is_the_textbook_left_hand_side():
    from sage_dynsym.numerics.newton_euler import inverse_dynamics
    ddq1, ddq2 = var('ddq1 ddq2')
    tau = inverse_dynamics(_tree().kinematics('symbolic'), [ddq1, ddq2])
    reference = M_REF * vector(SR, [ddq1, ddq2]) + H_REF
    assert all(_zero(a - b) for a, b in zip(tau, reference))


# ----------------------------------------------------------------------
# Prescribed joint velocities: a relative velocity v_{0k} that is not the
# derivative of the joint point. The recursive equations (symbolic) and the
# compiled right-hand side take Lagrange's equations of the kinetic energy,
# not Kane's form; the reference is SymPy's LagrangesMethod on the same
# plain data (reference.sympy_chain) and, for the pendulum, the textbook
# equation.

PSD = [['2.5', '0.1', '0'], ['0.1', '3', '0.2'], ['0', '0.2', '2']]
# exact numbers, for the symbolic identity on a chain (no rounding residues)
PSD_EXACT = [['5/2', '1/10', '0'], ['1/10', '3', '1/5'], ['0', '1/5', '2']]
PRESCRIBED = {
    # a nut on a screw of pitch p (v = p dphi along the axis, the joint point
    # fixed) on a turntable turning at the prescribed rate w, with a slider
    # on the nut; gravity along the screw
    'screw on a turntable': dict(
        coordinates=['phi', 'x'], parameters=['w', 'p', 'm', 'g'], gravity=['0', '0', '-g'],
        values={'w': 0.7, 'p': 0.4, 'm': 1.5, 'g': 9.81},
        bodies=[dict(parent=0, rotations=[(3, 'w*t')], joint=['0', '0', '0'],
                     mass_center=['0.2', '0', '0'], mass='2', inertia=PSD),
                dict(parent=1, rotations=[(3, 'phi')], joint=['0', '0', '0'],
                     velocity=['0', '0', 'p*dphi'], mass='m', mass_center=['0.3', '0', '0.1'],
                     inertia=PSD),
                dict(parent=2, rotations=[], joint=['x', '0', '0.5'], mass='0.5',
                     mass_center=['0', '0', '0.2'],
                     inertia=[['0.1', '0', '0'], ['0', '0.1', '0'], ['0', '0', '0.05']])]),
    # a pendulum whose support moves with the given velocity V sin(W t)
    # (its position is not needed: the field is uniform)
    'pendulum on a moving support': dict(
        coordinates=['phi'], parameters=['V', 'W', 'm', 'l', 'g'], gravity=['0', '0', '-g'],
        values={'V': 0.8, 'W': 2.0, 'm': 1.3, 'l': 0.7, 'g': 9.81},
        bodies=[dict(parent=0, rotations=[], joint=['0', '0', '0'],
                     velocity=['0', 'V*sin(W*t)', '0'], mass='0', mass_center=['0', '0', '0'],
                     inertia=[['0'] * 3] * 3),
                dict(parent=1, rotations=[(1, 'phi')], joint=['0', '0', '0'], mass='m',
                     mass_center=['0', '0', '-l'],
                     inertia=[['m*l**2', '0', '0'], ['0', 'm*l**2', '0'], ['0', '0', '0']])]),
    # a screw joint (v = p dq3 along the axis, the joint point fixed) in the
    # middle of a chain of hinges: its correction is projected through the
    # turning frames above it and reads the momentum of the link below it
    'screw in a chain': dict(
        coordinates=['q1', 'q2', 'q3', 'q4'], parameters=['p', 'g'], gravity=['0', '-g', '0'],
        values={'p': 0.4, 'g': 9.81},
        bodies=[dict(parent=0, rotations=[(3, 'q1')], joint=['0', '0', '0'], mass='1',
                     mass_center=['1/2', '0', '0'], inertia=PSD_EXACT),
                dict(parent=1, rotations=[(1, 'q2')], joint=['1', '0', '0'], mass='6/5',
                     mass_center=['1/2', '1/10', '0'], inertia=PSD_EXACT),
                dict(parent=2, rotations=[(3, 'q3')], joint=['1', '0', '0'],
                     velocity=['0', '0', 'p*dq3'], mass='4/5', mass_center=['2/5', '0', '1/10'],
                     inertia=PSD_EXACT),
                dict(parent=3, rotations=[(2, 'q4')], joint=['1', '0', '0'], mass='3/5',
                     mass_center=['3/10', '0', '0'], inertia=PSD_EXACT)]),
    # a velocity field on a skate that is not integrable, on the nut
    'skate on a screw': dict(
        coordinates=['phi', 'x', 'y'], parameters=['p', 'g'], gravity=['0', '-1', '-g'],
        values={'p': 0.4, 'g': 9.8},
        bodies=[dict(parent=0, rotations=[(3, 'phi')], joint=['0', '0', '0'],
                     velocity=['0', '0', 'p*dphi'], mass='1.5',
                     mass_center=['0.3', '0', '0.1'], inertia=PSD),
                dict(parent=1, rotations=[(1, 'x')], joint=['x', 'y', '0'],
                     velocity=['dx', 'dy + x*dx*cos(phi)', '0'], mass='2',
                     mass_center=['0', '0.5', '0.2'],
                     inertia=[['1', '0', '0.1'], ['0', '2', '0'], ['0.1', '0', '1.5']])]),
}


#: the chain takes some seconds: in the slow suite
PRESCRIBED_CASES = [pytest.param(name, marks=pytest.mark.slow) if name == 'screw in a chain'
                    else name for name in sorted(PRESCRIBED)]


def _prescribed_system(desc):
    # test-authored text, parsed by Sage's symbolic ring
    bodies = []
    for k, b in enumerate(desc['bodies'], 1):
        fields = dict(parent=b['parent'], rotations=[(a, SR(e)) for a, e in b['rotations']],
                      joint=[SR(e) for e in b['joint']], mass=SR(b['mass']),
                      mass_center=[SR(e) for e in b['mass_center']],
                      inertia=matrix(SR, [[SR(e) for e in row] for row in b['inertia']]))
        if 'velocity' in b:
            fields['velocity'] = [SR(e) for e in b['velocity']]
        bodies.append(RigidBody(f'b{k}', **fields))
    return MechanicalSystem(bodies, [SR.var(c) for c in desc['coordinates']],
                            force_function=UniformGravity([SR(e) for e in desc['gravity']]))


@pytest.mark.parametrize('name', PRESCRIBED_CASES)
def test_prescribed_velocities_recursive_equations_are_lagrange_equations(name):
    S = _prescribed_system(PRESCRIBED[name])
    assert S.kinematics().symbolic().recursive_applies()
    recursive = S.lagrangian('recursive').lagrange_equations()
    symbolic = S.lagrangian('symbolic').lagrange_equations()
    assert all(_zero(a - b) for a, b in zip(recursive, symbolic))


@pytest.mark.parametrize('name', PRESCRIBED_CASES)
def test_prescribed_velocities_compiled_rhs_against_sympy(name):
    import sympy
    from reference.sympy_chain import SympyChain
    from sage_dynsym.mechanics.recursive_numerics import body_tree
    from sage_dynsym.numerics.compiler import compiler
    from sage_dynsym.numerics.rhs import RightHandSide
    desc = PRESCRIBED[name]
    chain = SympyChain(desc['bodies'], desc['coordinates'], desc['gravity'], desc['parameters'])
    E = chain.lagrange_equations()
    names = desc['coordinates']
    q, dq, ddq = (sympy.symbols([prefix + c for c in names]) for prefix in ('', 'd', 'dd'))
    t = sympy.Symbol('t')
    values = {sympy.Symbol(k): v for k, v in desc['values'].items()}
    at_rest = {a: 0 for a in ddq}
    M = sympy.lambdify([t] + q + dq, sympy.Matrix([[e.diff(a) for a in ddq] for e in E])
                       .subs(values))
    F = sympy.lambdify([t] + q + dq, sympy.Matrix([-e.subs(at_rest) for e in E]).subs(values))
    S = _prescribed_system(desc)
    backend = 'c' if compiler() else 'python'
    rng = random.Random(7)
    n = len(names)
    for solver in ('articulated', 'ltdl'):
        f = RightHandSide(RecursiveForm(body_tree(S), solver=solver), desc['values'], backend)
        for _ in range(3):
            x = [rng.uniform(-1.5, 1.5) for _ in range(2 * n)]
            time = rng.uniform(0, 2)
            reference = np.linalg.solve(np.array(M(time, *x), dtype=float),
                                        np.array(F(time, *x), dtype=float).ravel())
            assert np.allclose(f(time, np.array(x))[n:], reference, rtol=1e-10, atol=1e-12)
            if name == 'pendulum on a moving support':
                # m l^2 phi'' + m l cos(phi) v'(t) + m g l sin(phi) = 0
                V, W, l, grav = (desc['values'][k] for k in 'V W l g'.split())
                phi = x[0]
                textbook = -(grav * np.sin(phi) + V * W * np.cos(W * time) * np.cos(phi)) / l
                assert reference[0] == pytest.approx(textbook, rel=1e-12, abs=1e-12)


# ----------------------------------------------------------------------
# One projection of loads: the generalized forces of point forces, torques,
# springs and dampers are those of the backward Newton-Euler pass
# (load_forces + generalized_forces), over the symbolic ring for the
# Lagrange equations and over the expression graph for the compiled code.
# The reference is the virtual work, with central differences of the
# positions and orientations of the bodies computed here with NumPy.

def _rotation(axis, angle):
    # the new axes (columns) in the old ones
    c, s = math.cos(angle), math.sin(angle)
    return {1: np.array([[1, 0, 0], [0, c, -s], [0, s, c]]),
            2: np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]]),
            3: np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])}[axis]


def _frames(q, t):
    """(joint point, axes) of the cart, the arm and the slider of _loaded()."""
    x, a, s, b = q
    cart = (np.array([x, 0, 0]), np.eye(3))
    arm_axes = _rotation(3, a) @ _rotation(2, 0.3 * t)
    arm = (cart[0] + np.array([0, 0, 0.1]), arm_axes)
    slider = (arm[0] + arm_axes @ np.array([s, 0, 0]), arm_axes @ _rotation(1, b))
    return [cart, arm, slider]


def _loaded():
    x, a, s, b, dx, da, ds, db = var('x a s b dx da ds db')
    t = var('t')
    cart = RigidBody('cart', joint=[x, 0, 0], mass=2)
    arm = RigidBody('arm', parent='cart', joint=[0, 0, 0.1], rotations=[(3, a), (2, 0.3 * t)],
                    mass=1, mass_center=[0.5, 0, 0], inertia=diagonal_matrix([0.1, 0.3, 0.3]))
    slider = RigidBody('slider', parent='arm', joint=[s, 0, 0], rotations=[(1, b)], mass=0.5,
                       mass_center=[0, 0.1, 0], inertia=diagonal_matrix([0.02, 0.01, 0.02]))
    # the slider's joint point in the inertial axes (by hand) and its velocity
    P = vector(SR, [x, 0, 0.1]) + matrix(SR, [[cos(a), -sin(a), 0], [sin(a), cos(a), 0],
                                              [0, 0, 1]]) * matrix(SR, [
        [cos(0.3 * t), 0, sin(0.3 * t)], [0, 1, 0], [-sin(0.3 * t), 0, cos(0.3 * t)]]) \
        * vector(SR, [s, 0, 0])
    dP = vector(SR, [sum(e.diff(u) * v for u, v in zip((x, a, s), (dx, da, ds))) + e.diff(t)
                     for e in P])
    anchor = vector(SR, [0, 1, 0])
    d = P - anchor
    stretch = sqrt(d * d)
    loads = [
        # a point force on the arm, in the inertial axes
        {'body': 'arm', 'point': [0.8, 0.1, -0.2], 'force': [1.5, -0.7, 2.0 * sin(t)]},
        # a follower force and torque on the slider, in its own axes
        {'body': 'slider', 'point': [0, 0.2, 0.1], 'force': [0.3, 0, -1], 'axes': 'slider'},
        {'body': 'slider', 'torque': [0.4, -0.2, 0.9 * s], 'axes': 'slider'},
        # a torque on the arm in the cart's axes
        {'body': 'arm', 'torque': [0, 0, -1.2 * a], 'axes': 'cart'},
        # a spring of stiffness 3 and rest length 0.5 from the inertial
        # anchor (0, 1, 0) to the slider's joint point
        {'body': 'slider', 'force': list(-3 * (stretch - 0.5) * d / stretch)},
        # a spring between the cart's joint point and the slider's (two
        # opposite loads) and a damper at the slider's joint point
        {'body': 'slider', 'force': list(-2 * (P - vector(SR, [x, 0, 0])))},
        {'body': 'cart', 'force': list(2 * (P - vector(SR, [x, 0, 0])))},
        {'body': 'slider', 'force': list(-0.7 * dP)},
        # a rotational damper on the slider's hinge, in the arm's axes
        {'body': 'slider', 'torque': [-0.4 * db, 0, 0], 'axes': 'arm'},
    ]
    return MechanicalSystem([cart, arm, slider], [x, a, s, b], loads=loads)


def _virtual_work_forces(S, q, dq, t, h=1e-6):
    """Q_i = sum F . d r_P/d q_i + M . w_i, the partial angular velocity w_i
    read off d R/d q_i R^T, by central differences of _frames."""
    names = ['cart', 'arm', 'slider']
    state = dict(zip(S.coordinates() + S.velocities(), q + dq)) | {var('t'): t}
    Q = np.zeros(len(q))
    for i in range(len(q)):
        up, down = list(q), list(q)
        up[i] += h
        down[i] -= h
        plus, minus, here = _frames(up, t), _frames(down, t), _frames(q, t)
        for load in S.loads():
            k = names.index(load.body())
            axes = np.eye(3) if load.axes() == 0 else here[names.index(load.axes())][1]
            point = np.array([float(c) for c in load.point()])
            if load.force() is not None:
                F = axes @ np.array([float(SR(c).subs(state)) for c in load.force()])
                drdq = ((plus[k][0] + plus[k][1] @ point)
                        - (minus[k][0] + minus[k][1] @ point)) / (2 * h)
                Q[i] += F @ drdq
            if load.torque() is not None:
                M = axes @ np.array([float(SR(c).subs(state)) for c in load.torque()])
                W = (plus[k][1] - minus[k][1]) / (2 * h) @ here[k][1].T
                Q[i] += M @ np.array([W[2, 1], W[0, 2], W[1, 0]])
    return Q


def test_loads_project_alike_in_both_arithmetics():
    from sage_dynsym.mechanics.recursive_numerics import body_tree
    from sage_dynsym.numerics.compiler import run_python
    from sage_dynsym.numerics.newton_euler import generalized_forces, load_forces
    S = _loaded()
    symbolic = S.generalized_forces()
    K = body_tree(S).kinematics('graph')
    assert not body_tree(S).parameters()
    compiled = run_python(K.G.python_source(generalized_forces(K, load_forces(K))), '_graph')
    rng = random.Random(33)
    for _ in range(4):
        q = [rng.uniform(-1.5, 1.5) for _ in range(4)]
        dq = [rng.uniform(-1, 1) for _ in range(4)]
        t = rng.uniform(0, 3)
        state = dict(zip(S.coordinates() + S.velocities(), q + dq)) | {var('t'): t}
        reference = _virtual_work_forces(S, q, dq, t)
        assert np.allclose([float(e.subs(state)) for e in symbolic], reference,
                           rtol=1e-7, atol=1e-8)
        assert np.allclose(compiled(t, q + dq, []), reference, rtol=1e-7, atol=1e-8)

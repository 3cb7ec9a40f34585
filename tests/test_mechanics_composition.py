"""A mechanical system is composed of objects built from explicit data (its
kinematics, constraint set, physical conditions, Lagrangian builder): each
works on its own, against references computed here independently (NumPy
rotation matrices, the pendulum's equation of motion), and the system keeps
every public method it had when it was assembled from mixins."""
import numpy as np
import pytest
from sage.all import SR, diagonal_matrix, sin, cos, var

from sage_dynsym import MechanicalSystem, RigidBody, UniformGravity
from sage_dynsym.mechanics.constraint_set import ConstraintSet
from sage_dynsym.mechanics.loads import Load
from sage_dynsym.mechanics.system_checks import PhysicalConditions
from sage_dynsym.mechanics.system_kinematics import SystemKinematics
from sage_dynsym.mechanics.system_lagrangian import LagrangianBuilder

#: the public methods of MechanicalSystem before it was composed (its mixins
#: SystemChecks, SystemKinematics, SystemLagrangian, SystemConstraints,
#: SystemOperatingPoints, MechanicalFormat, MechanicalNumerics and Model)
PUBLIC_METHODS = [
    'angular_velocity', 'angular_velocity_vector', 'bodies', 'body_decomposition', 'body_frame',
    'characteristic_functions', 'code', 'conditions', 'constraint_set', 'constraints',
    'coordinates', 'decomposition', 'direction_cosines', 'dissipation', 'equation_forms',
    'equations', 'equations_record', 'euler_poisson', 'force_field', 'force_function',
    'force_terms', 'frame_tree', 'free_linear_system', 'from_dict', 'generalized_forces',
    'given_forces', 'joint_position', 'joint_velocity', 'joint_velocity_vector',
    'kinetic_energy', 'lagrangian', 'loads', 'mass_center_position', 'name',
    'nonholonomic_constraints', 'numerical_linearization', 'numerical_rhs', 'operating_point',
    'operating_points', 'parameters', 'parent_index', 'positive_parameters',
    'relative_angular_velocity', 'report_sections', 'report_title', 'result_symbols',
    'results', 'simulate', 'subs', 'to_dict', 'to_linearizer', 'velocities']


def _rotation(axis, angle):
    # the elementary rotation about a coordinate axis (1, 2 or 3), columns the
    # rotated axes in the old ones
    c, s = np.cos(angle), np.sin(angle)
    i, j = [(1, 2), (2, 0), (0, 1)][axis - 1]
    R = np.eye(3)
    R[i, i], R[i, j], R[j, i], R[j, j] = c, -s, s, c
    return R


@pytest.fixture
def arm():
    a, b, l, m = var('a b l m')
    bodies = [RigidBody('tip', parent='base', rotations=[(1, b)], joint=[l, 0, 0], mass=m),
              RigidBody('base', rotations=[(3, a)])]
    return bodies, [a, b]


def test_the_system_keeps_its_public_methods(arm):
    S = MechanicalSystem(*arm)
    missing = [name for name in PUBLIC_METHODS if not callable(getattr(S, name, None))]
    assert not missing


def test_the_kinematics_on_its_own_against_rotation_matrices(arm):
    bodies, (a, b) = arm
    K = SystemKinematics(bodies, [a, b])
    assert [body.name() for body in K.bodies()] == ['base', 'tip']
    assert K.given_names() == ['tip', 'base'] and K.parent_index(2) == 1
    rng = np.random.default_rng(31)
    for _ in range(3):
        va, vb = rng.uniform(-3, 3, 2)
        expected = _rotation(3, va) @ _rotation(1, vb)
        alpha = np.array([[float(e) for e in row]
                          for row in K.direction_cosines(2).subs({a: va, b: vb}).rows()])
        assert np.allclose(alpha, expected, atol=1e-14)
        # the joint of the tip sits at l along the base's turned x axis
        position = K.joint_position(2).components(0)
        assert np.allclose([float(SR(c).subs({a: va, var('l'): 2})) for c in position],
                           2 * _rotation(3, va)[:, 0], atol=1e-14)


def test_the_system_receives_the_same_kinematics_as_its_loads(arm):
    S = MechanicalSystem(*arm)
    K = S.kinematics()
    assert S.angular_velocity(2) == K.angular_velocity(2)
    F = var('F')
    # a force F along the inertial x axis at the tip's joint: Q_a = -F l sin(a)
    Q = Load('tip', force=[F, 0, 0]).generalized_forces(K)
    assert bool(Q[0] == -F * var('l') * sin(var('a'))) and Q[1] == 0


def test_the_builder_of_a_pendulum_from_explicit_data():
    # m l^2 phi'' + m g l sin(phi) = 0 for a point mass on a massless rod
    phi, m, l, g = var('phi m l g')
    rod = RigidBody('rod', rotations=[(1, phi)], mass=m, mass_center=[0, 0, -l],
                    inertia=diagonal_matrix([m * l**2, m * l**2, 0]))
    K = SystemKinematics([rod], [phi])
    B = LagrangianBuilder(K, force_function=UniformGravity([0, 0, -g]))
    E = B.lagrangian().lagrange_equations()[0]
    assert bool(E == m * l**2 * var('ddphi') + m * g * l * sin(phi))
    assert bool(B.kinetic_energy() == m * l**2 * var('dphi')**2 / 2)
    assert bool(B.force_function() == m * g * l * cos(phi))


def test_the_constraints_and_conditions_from_explicit_data():
    x, y, th, dx, dy, A, C = var('x y theta dx dy A C')
    blade = RigidBody('blade', joint=[x, y, 0], rotations=[(3, th)], mass=1,
                      inertia=diagonal_matrix([A, A, C]))
    K = SystemKinematics([blade], [x, y, th])
    constraints = ConstraintSet(K, [], [sin(th) * dx - cos(th) * dy], [])
    assert constraints.nonholonomic() == [sin(th) * dx - cos(th) * dy]
    # the triangle inequality of the moments A, A, C: 2A - C >= 0
    assert [str(c) for c in PhysicalConditions(K, [A, C]).conditions()] == ['2*A - C >= 0']

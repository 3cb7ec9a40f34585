"""Classical nonholonomic systems against the literature and SymPy's KanesMethod:

- the knife edge on an inclined plane (Bloch, Nonholonomic Mechanics and
  Control, 2003, section 1.6: the closed-form motion, the lateral force);
- the Chaplygin sleigh (Bloch, section 1.7: v' = a w^2,
  w' = -m a v w / (J + m a^2), straight motion stable in first approximation
  for a v > 0);
- the thin disk rolling on a plane (Routh, Advanced Rigid Dynamics, art. 244;
  K. T. McDonald, The rolling motion of a disk on a horizontal plane, 2000,
  arXiv:physics/0008227, sec. 2.5: upright rolling at the spin rate W is
  stable iff C (C + m r^2) W^2 > m g r A, for a uniform disk v^2 > g r / 3).

Each model is also built independently in sympy.physics.mechanics (frames,
points, KanesMethod with dependent speeds) and the accelerations are compared
at random states that satisfy the constraints.
"""
import functools
import math
import random

import numpy as np
import pytest
import sympy as sm
import sympy.physics.mechanics as me

from sage.all import SR, QQ, CDF, cos, sin

from sage_dynsym import linearize, load, save, DynSymError
from sage_dynsym.analysis.operating_point import OperatingPoint
from sage_dynsym.algebra.trigonometric import trig_rational_simplify
from sage_dynsym.description import model_from_dict
from sage_dynsym.symbols import acceleration

KNIFE = {
    'kind': 'mechanical', 'name': 'knife edge on an inclined plane',
    'parameters': ['m', 'Iz', 'g', 'alpha'], 'coordinates': ['x', 'y', 'theta'],
    # x runs down the slope of angle alpha: the weight's component along it
    'force_function': {'expression': 'm*g*sin(alpha)*x'},
    'nonholonomic': ['sin(theta)*dx - cos(theta)*dy'],
    'bodies': [{'name': 'blade', 'joint': ['x', 'y', 0], 'rotations': [[3, 'theta']],
                'mass': 'm', 'inertia': [['Iz/2', 0, 0], [0, 'Iz/2', 0], [0, 0, 'Iz']]}]}

SLEIGH = {
    'kind': 'mechanical', 'name': 'Chaplygin sleigh',
    'parameters': ['m', 'J', 'a', 'v'], 'coordinates': ['x', 'y', 'theta'],
    'nonholonomic': ['sin(theta)*dx - cos(theta)*dy'],
    # the blade at (x, y), the mass centre a ahead of it; inertia about the
    # blade: J about the mass centre, shifted (a plate: J/2, J/2, J)
    'bodies': [{'name': 'sleigh', 'joint': ['x', 'y', 0], 'rotations': [[3, 'theta']],
                'mass_center': ['a', 0, 0], 'mass': 'm',
                'inertia': [['J/2', 0, 0], [0, 'J/2 + m*a^2', 0], [0, 0, 'J + m*a^2']]}],
    'operating_points': {'straight': {'at': {'theta': 0}, 'velocities': {'dx': 'v'},
                                      'coordinates': ['theta']}}}

DISK = {
    'kind': 'mechanical', 'name': 'rolling disk',
    'parameters': ['m', 'r', 'A', 'C', 'g', 'W'], 'coordinates': ['x', 'y', 'psi', 'theta', 'phi'],
    'force_function': {'uniform_gravity': [0, 0, '-g']},
    'bodies': [
        # the contact point, the heading psi, the tilt theta from the vertical
        {'name': 'frame', 'joint': ['x', 'y', 0], 'rotations': [[3, 'psi'], [1, 'theta']]},
        # the disk, its centre r above the contact point, spinning about its axle y
        {'name': 'disk', 'parent': 'frame', 'joint': [0, 0, 'r'], 'rotations': [[2, 'phi']],
         'mass': 'm', 'inertia': [['A', 0, 0], [0, 'C', 0], [0, 0, 'A']]}],
    'rolling': [{'body': 'disk', 'radius': 'r', 'axle': 2}],
    'operating_points': {'upright': {'at': {'theta': 0}, 'velocities': {'dphi': 'W', 'dpsi': 0},
                                     'coordinates': ['theta', 'psi']}}}


def system(data):
    return model_from_dict(data)


def symbols(*names):
    return [SR.var(n) for n in names]


# ---------------------------------------------------------------------------
# SymPy: the same models, written by hand
# ---------------------------------------------------------------------------

@functools.lru_cache(maxsize=None)
def sympy_knife():
    x, y, th = me.dynamicsymbols('x y theta')
    ux, uy, uth = me.dynamicsymbols('ux uy utheta')
    m, I, g, al = sm.symbols('m Iz g alpha')
    N = me.ReferenceFrame('N')
    B = N.orientnew('B', 'Axis', [th, N.z])
    B.set_ang_vel(N, uth * N.z)
    P = me.Point('P')
    P.set_vel(N, ux * N.x + uy * N.y)
    blade = me.RigidBody('blade', P, B, m, (me.inertia(B, I / 2, I / 2, I), P))
    constraints = [sm.sin(th) * ux - sm.cos(th) * uy]
    KM = me.KanesMethod(N, [x, y, th], [ux, uth], kd_eqs=[ux - x.diff(), uy - y.diff(),
                                                           uth - th.diff()],
                        u_dependent=[uy], velocity_constraints=constraints)
    KM.kanes_equations([blade], [(P, m * g * sm.sin(al) * N.x)])
    return KM, constraints, [m, I, g, al]


@functools.lru_cache(maxsize=None)
def sympy_sleigh():
    x, y, th = me.dynamicsymbols('x y theta')
    ux, uy, uth = me.dynamicsymbols('ux uy utheta')
    m, J, a = sm.symbols('m J a')
    N = me.ReferenceFrame('N')
    B = N.orientnew('B', 'Axis', [th, N.z])
    B.set_ang_vel(N, uth * N.z)
    P = me.Point('P')
    P.set_vel(N, ux * N.x + uy * N.y)
    G = P.locatenew('G', a * B.x)
    G.v2pt_theory(P, N, B)
    sleigh = me.RigidBody('sleigh', G, B, m, (me.inertia(B, J / 2, J / 2, J), G))
    constraints = [sm.sin(th) * ux - sm.cos(th) * uy]
    KM = me.KanesMethod(N, [x, y, th], [ux, uth], kd_eqs=[ux - x.diff(), uy - y.diff(),
                                                           uth - th.diff()],
                        u_dependent=[uy], velocity_constraints=constraints)
    KM.kanes_equations([sleigh], [])
    return KM, constraints, [m, J, a]


@functools.lru_cache(maxsize=None)
def sympy_disk():
    x, y, psi, th, phi = me.dynamicsymbols('x y psi theta phi')
    ux, uy, upsi, uth, uphi = me.dynamicsymbols('ux uy upsi utheta uphi')
    m, r, A, C, g = sm.symbols('m r A C g')
    N = me.ReferenceFrame('N')
    Y = N.orientnew('Y', 'Axis', [psi, N.z])
    L = Y.orientnew('L', 'Axis', [th, Y.x])
    R = L.orientnew('R', 'Axis', [phi, L.y])
    R.set_ang_vel(N, upsi * N.z + uth * Y.x + uphi * L.y)
    P = me.Point('P')                      # the contact point on the ground
    P.set_vel(N, ux * N.x + uy * N.y)
    D = P.locatenew('D', r * L.z)          # the centre
    D.set_vel(N, ux * N.x + uy * N.y + (upsi * N.z + uth * Y.x).cross(r * L.z))
    # the material point of the disk at the contact
    slip = D.vel(N) + R.ang_vel_in(N).cross(-r * L.z)
    constraints = [slip.dot(N.x), slip.dot(N.y)]
    disk = me.RigidBody('disk', D, R, m, (me.inertia(L, A, C, A), D))
    kd = [ux - x.diff(), uy - y.diff(), upsi - psi.diff(), uth - th.diff(), uphi - phi.diff()]
    KM = me.KanesMethod(N, [x, y, psi, th, phi], [upsi, uth, uphi], kd_eqs=kd,
                        u_dependent=[ux, uy], velocity_constraints=constraints)
    KM.kanes_equations([disk], [(D, -m * g * N.z)])
    return KM, constraints, [m, r, A, C, g]


def _numerical_rhs(KM, parameters):
    # (q', u') of Kane's equations, the full mass matrix solved numerically
    q, u = list(KM.q), list(KM.u)
    blocks = sm.lambdify(q + u + parameters, [KM.mass_matrix_full, KM.forcing_full], 'numpy')

    def rhs(*args):
        M, F = blocks(*args)
        return np.linalg.solve(np.array(M, dtype=float), np.array(F, dtype=float).ravel())
    return rhs


def compare_with_sympy(S, build, values, seed, states=4):
    r"""The accelerations of ``S`` (numerical right-hand side, with its
    velocity constraints) and of the SymPy model at random states."""
    KM, constraints, parameters = build()
    q, u = list(KM.q), list(KM.u)
    names = [str(qi).replace('(t)', '') for qi in q]
    p_values = [values[str(p)] for p in parameters]
    rhs = _numerical_rhs(KM, parameters)
    rows = sm.Matrix(constraints)
    A = sm.lambdify(q + parameters, rows.jacobian(u), 'numpy')
    f = S.numerical_rhs({k: v for k, v in values.items()})
    order = [str(x) for x in S.coordinates()]
    rng = random.Random(seed)
    dependent = [i for i, ui in enumerate(u) if ui in KM._udep]
    free = [i for i in range(len(u)) if i not in dependent]
    for _ in range(states):
        qv = [rng.uniform(-1, 1) for _ in q]
        uv = np.array([rng.uniform(-1, 1) for _ in u])
        M = np.array(A(*qv, *p_values), dtype=float)
        uv[dependent] = np.linalg.solve(M[:, dependent], -M[:, free] @ uv[free])
        theirs = np.array(rhs(*qv, *uv, *p_values), dtype=float).ravel()
        # the speed u_<q> is the velocity of q
        by_name = {name: value for name, value in zip(names, qv)}
        rates = {str(ui).replace('(t)', ''): value for ui, value in zip(u, uv)}
        state = [by_name[n] for n in order] + [rates['u' + n] for n in order]
        ours = f(0, state)
        accelerations = {str(ui).replace('(t)', ''): theirs[len(q) + i]
                         for i, ui in enumerate(u)}
        for k, n in enumerate(order):
            assert abs(ours[len(order) + k] - accelerations['u' + n]) < 1e-9, (n, state)


# ---------------------------------------------------------------------------
# The knife edge
# ---------------------------------------------------------------------------

def test_knife_edge_follows_the_closed_form_motion():
    # theta = w t; x = g' sin(w t)^2 / (2 w^2), y = g' (w t - sin(2 w t)/2) / (2 w^2),
    # g' = g sin(alpha) (Bloch 2003, section 1.6)
    S = system(KNIFE)
    m, Iz, g, alpha = symbols('m', 'Iz', 'g', 'alpha')
    values = {m: 2, Iz: QQ(3) / 10, g: QQ(981) / 100, alpha: QQ(1) / 5}
    w = 1.3
    x, y, th = S.coordinates()
    T = S.simulate(values, {x: 0, y: 0, th: 0, 'dx': 0, 'dy': 0, 'dtheta': w}, 4, points=41)
    gs = 9.81 * math.sin(0.2)
    for t_k, xk, yk, tk in zip(T.times(), T.values(x), T.values(y), T.values(th)):
        assert abs(tk - w * t_k) < 1e-9
        assert abs(xk - gs * math.sin(w * t_k) ** 2 / (2 * w ** 2)) < 1e-8
        assert abs(yk - gs * (w * t_k - math.sin(2 * w * t_k) / 2) / (2 * w ** 2)) < 1e-8
    residual, = T.constraint_residuals().values()
    assert max(abs(residual)) < 1e-10
    assert T.energy_drift() < 1e-8


def test_knife_edge_lateral_force():
    # Newton across the blade: -lambda = m v theta' + m g' sin(theta), v the
    # speed along the blade
    S = system(KNIFE)
    L = S.lagrangian()
    x, y, th, dx, dy, dth = symbols('x', 'y', 'theta', 'dx', 'dy', 'dtheta')
    m, g, alpha = symbols('m', 'g', 'alpha')
    mu, = L.multipliers()
    assert L.nonholonomic_constraints() == [-dy * cos(th) + dx * sin(th)]
    solved = L.accelerations_and_multipliers()
    v = dx * cos(th) + dy * sin(th)
    assert trig_rational_simplify(solved[mu] + m * v * dth + m * g * sin(alpha) * sin(th)).is_zero()
    # the equations with the multiplier hold: M ddq = F + A^T mu
    E = [e.subs(solved) for e in L.lagrange_equations()]
    assert all(trig_rational_simplify(e).is_zero() for e in E)


def test_knife_edge_against_sympy():
    compare_with_sympy(system(KNIFE), sympy_knife,
                       {'m': 1.7, 'Iz': 0.4, 'g': 9.81, 'alpha': 0.3}, seed=1)


# ---------------------------------------------------------------------------
# The Chaplygin sleigh
# ---------------------------------------------------------------------------

def test_sleigh_equations_are_those_of_bloch():
    # in the body velocities v = x' cos + y' sin (along the blade), w = theta':
    # v' = a w^2, w' = -m a v w / (J + m a^2)
    S = system(SLEIGH)
    solved = S.lagrangian().accelerations_and_multipliers()
    x, y, th, dx, dy, dth, m, J, a, v = symbols('x', 'y', 'theta', 'dx', 'dy', 'dtheta', 'm',
                                                'J', 'a', 'v')
    along = {dx: v * cos(th), dy: v * sin(th)}          # the constraint holds
    ddx, ddy, ddth = (solved[acceleration(q)].subs(along) for q in (x, y, th))
    dv = ddx * cos(th) + ddy * sin(th)          # + theta' (-x' sin + y' cos) = 0
    assert trig_rational_simplify(dv - a * dth ** 2).is_zero()
    assert trig_rational_simplify(ddth + m * a * v * dth / (J + m * a ** 2)).is_zero()


def test_sleigh_straight_motion_linearized():
    S = system(SLEIGH)
    m, J, a, v, lam = symbols('m', 'J', 'a', 'v', 'lam')
    linear = linearize(S, S.operating_point('straight'))
    assert linear.M() == SR(J + m * a ** 2) * linear.M().parent().identity_matrix()
    assert bool(linear.S()[0, 0] == m * a * v) and linear.W().is_zero()
    # a zero root (the heading) and -m a v / (J + m a^2): stable for a v > 0
    poly = linear.characteristic_polynomial(lam)
    assert bool((poly - lam * ((J + m * a ** 2) * lam + m * a * v)).expand() == 0)
    motion = linear.steady_motion()
    assert [str(q) for q in motion.dropped()] == ['x', 'y']


def test_sleigh_simulation_straightens_out():
    S = system(SLEIGH)
    x, y, th = S.coordinates()
    values = {'m': 1, 'J': QQ(1) / 5, 'a': QQ(1) / 2, 'v': 1}
    T = S.simulate(values, {x: 0, y: 0, th: 0, 'dx': 1, 'dy': 0, 'dtheta': 2}, 20, points=201)
    turning = [abs(w) for w in T.values('dtheta')]
    assert turning[-1] < 1e-3 * turning[0]
    assert T.energy_drift() < 1e-8
    assert max(abs(r) for r in T.constraint_residuals()[S.nonholonomic_constraints()[0]]) < 1e-9


def test_sleigh_reduced_equations_are_chaplygins():
    S = system(SLEIGH)
    R = S.lagrangian().reduced_equations([SR.var('dx'), SR.var('dtheta')])
    assert R.is_chaplygin()
    x, y = SR.var('x'), SR.var('y')
    assert not any(e.has(x) or e.has(y) for e in R.equations())
    assert [str(u) for u in R.speeds()] == ['dx', 'dtheta']


def test_sleigh_against_sympy():
    compare_with_sympy(system(SLEIGH), sympy_sleigh, {'m': 1.3, 'J': 0.25, 'a': 0.4, 'v': 1},
                       seed=2)


# ---------------------------------------------------------------------------
# The rolling disk
# ---------------------------------------------------------------------------

def test_disk_contact_conditions():
    S = system(DISK)
    contact, = S.constraint_set().contacts()
    assert contact.imposed_by_coordinates()
    x, y, psi, phi, r = symbols('x', 'y', 'psi', 'phi', 'r')
    dx, dy, dphi = symbols('dx', 'dy', 'dphi')
    assert contact.point() == (x, y, 0)
    # the contact point rolls along the heading: x' = r phi' cos(psi), ...
    assert contact.no_slip() == [dx - r * dphi * cos(psi), dy - r * dphi * sin(psi)]
    assert S.constraints() == []


def _upright_polynomial(S, point='upright'):
    lam = SR.var('lam')
    linear = linearize(S, S.operating_point(point))
    return linear, linear.characteristic_polynomial(lam), lam


def test_disk_upright_rolling_is_routhian():
    # lam^2 (A (A + m r^2) lam^2 + C (C + m r^2) W^2 - m g r A), up to a factor
    S = system(DISK)
    linear, poly, lam = _upright_polynomial(S)
    m, r, A, C, g, W = symbols('m', 'r', 'A', 'C', 'g', 'W')
    expected = lam ** 2 * (A * (A + m * r ** 2) * lam ** 2 + C * (C + m * r ** 2) * W ** 2
                           - m * g * r * A)
    ratio = trig_rational_simplify(poly / expected)
    assert not ratio.variables() and ratio != 0
    assert [str(q) for q in linear.variables()] == ['theta', 'psi']
    assert [str(q) for q in linear.steady_motion().dropped()] == ['x', 'y', 'phi']


def test_uniform_disk_is_stable_above_the_third_of_g_r():
    # A = m r^2/4, C = m r^2/2: stable (purely imaginary roots) iff v^2 = r^2 W^2 > g r / 3
    S = system(DISK)
    m, r, A, C, g, W = symbols('m', 'r', 'A', 'C', 'g', 'W')
    S = S.subs({A: m * r ** 2 / 4, C: m * r ** 2 / 2})
    _, poly, lam = _upright_polynomial(S)
    values = {m: 1, r: QQ(1) / 2, g: QQ(981) / 100}
    critical = math.sqrt(9.81 / (3 * 0.5))
    for spin, stable in ((0.9 * critical, False), (1.1 * critical, True)):
        p = poly.subs(values).subs({W: spin}).expand()
        coefficients = [float(p.coefficient(lam, k)) for k in range(4, -1, -1)]
        roots = np.roots(coefficients)
        assert sum(abs(z) < 1e-9 for z in roots) == 2           # the neutral pair
        assert all(abs(z.real) < 1e-9 for z in roots) == stable, (spin, roots)


def test_disk_with_its_height_as_a_coordinate():
    # the centre's height h a coordinate: the contact condition becomes a
    # holonomic constraint, solved to first order; the same linearization
    data = dict(DISK, coordinates=['x', 'y', 'h', 'psi', 'theta', 'phi'])
    data['bodies'] = [dict(DISK['bodies'][0]), dict(DISK['bodies'][1])]
    data['bodies'][0] = dict(data['bodies'][0], rotations=[[3, 'psi']])
    data['bodies'][1] = {'name': 'tilted', 'parent': 'frame', 'joint': [0, 0, 'h'],
                         'rotations': [[1, 'theta']]}
    data['bodies'].append(dict(DISK['bodies'][1], parent='tilted', joint=[0, 0, 0]))
    data['operating_points'] = {'upright': {'at': {'theta': 0, 'h': 'r'},
                                            'velocities': {'dphi': 'W', 'dpsi': 0},
                                            'coordinates': ['theta', 'psi']}}
    S = system(data)
    contact, = S.constraint_set().contacts()
    assert not contact.imposed_by_coordinates()
    _, poly, lam = _upright_polynomial(S)
    _, expected, _ = _upright_polynomial(system(DISK))
    assert not trig_rational_simplify(poly / expected).variables()


def test_disk_against_sympy():
    compare_with_sympy(system(DISK), sympy_disk,
                       {'m': 1.2, 'r': 0.3, 'A': 0.03, 'C': 0.055, 'g': 9.81, 'W': 1}, seed=3)


def test_disk_simulation_keeps_rolling():
    S = system(DISK).subs({'A': QQ(1) / 40, 'C': QQ(1) / 20})
    x, y, psi, th, phi = S.coordinates()
    values = {'m': 1, 'r': QQ(1) / 2, 'g': QQ(981) / 100, 'W': 0}
    # upright, spinning fast, a small tilt rate: it wobbles and stays up
    T = S.simulate(values, {x: 0, y: 0, psi: 0, th: 0, phi: 0, 'dx': 4, 'dy': 0, 'dpsi': 0,
                            'dtheta': 0.05, 'dphi': 8}, 5, points=51)
    assert max(abs(a) for a in T.values(th)) < 0.1
    assert T.energy_drift() < 1e-8
    assert max(max(abs(r)) for r in T.constraint_residuals().values()) < 1e-9


# ---------------------------------------------------------------------------
# Description files and errors
# ---------------------------------------------------------------------------

def test_round_trip_through_a_file(tmp_path):
    S = system(DISK)
    path = str(tmp_path / 'disk.yaml')
    save(S, path)
    S2 = load(path)
    assert S2.nonholonomic_constraints() == S.nonholonomic_constraints()
    assert S2.operating_point('upright') == S.operating_point('upright')
    assert S2.to_dict() == S.to_dict()


@pytest.mark.parametrize("change, message", [
    (lambda d: d['rolling'][0].update(body='wheel'),
     "rolling[0].body: unknown body 'wheel'; known bodies are: frame, disk"),
    (lambda d: d['rolling'][0].update(radius='r*dx'),
     "rolling[0].radius: dx is the velocity of the coordinate x, which cannot appear in "
     "positions"),
    (lambda d: d['rolling'][0].update(axle=4),
     "rolling[0].axle: expected 1, 2 or 3"),
    (lambda d: d['rolling'][0].pop('axle'), "rolling[0]: missing key 'axle'"),
    (lambda d: d.update(nonholonomic=['ddx']),
     "nonholonomic[0]: ddx is the acceleration of the coordinate x"),
    (lambda d: d.update(nonholonomic=['dx^2 - dy']),
     "nonholonomic[0]: the constraint dx^2 - dy == 0 is not linear in the velocities"),
    (lambda d: d.update(nonholonomic=['dx - r*dphi*cos(psi)']),
     "rolling: the constraints are not independent"),
    (lambda d: d['operating_points']['upright']['at'].update(z=0),
     "operating_points.upright.at: z is not a coordinate"),
    (lambda d: d['operating_points']['upright']['velocities'].update(dphi='W*theta'),
     "operating_points.upright.velocities.dphi: theta is a coordinate"),
])
def test_errors_name_the_entry(change, message):
    import copy
    data = copy.deepcopy(DISK)
    change(data)
    with pytest.raises(DynSymError) as err:
        system(data)
    assert message in str(err.value)


def test_linearize_refuses_what_is_not_a_steady_motion():
    S = system(SLEIGH)
    th, v = SR.var('theta'), SR.var('v')
    # a turning sleigh at constant rates is not a motion of the model
    point = OperatingPoint('turning', {}, {SR.var('dtheta'): 1, SR.var('dx'): v})
    with pytest.raises(DynSymError, match="not a steady motion"):
        linearize(S, point, coordinates=[th])
    # the heading cannot be left out when the speeds couple to it
    with pytest.raises(DynSymError, match="add it to the coordinates|add its coordinate"):
        linearize(system(DISK), system(DISK).operating_point('upright'), coordinates=[SR.var('theta')])


def test_disk_turning_steady_motion_against_sympy():
    # a disk rolling on a circle: the steady-motion condition (Routh, art. 244)
    # solved for the spin rate; at that state SymPy's speeds do not change, and
    # the linearization about it has the eigenvalues of SymPy's reduced
    # dynamics (numerical Jacobian)
    from sage.all import solve
    from sage_dynsym.analysis.steady import steady_motion_conditions
    S = system(DISK)
    m, r, A, C, g, th, psi, phi = symbols('m', 'r', 'A', 'C', 'g', 'theta', 'psi', 'phi')
    th0, Om, om = symbols('theta0', 'Omega', 'omega')
    point = OperatingPoint('turning', {th: th0}, {SR.var('dpsi'): Om, SR.var('dphi'): om})
    conditions = steady_motion_conditions(S, point)
    spin = solve(conditions[SR.var('dtheta')], om)[0].rhs()
    assert trig_rational_simplify(spin - (-(g * m * r + (m * r ** 2 - A + C) * Om ** 2 * cos(th0))
                                          * sin(th0) / ((m * r ** 2 + C) * Om * cos(th0)))).is_zero()
    values = {m: QQ(6) / 5, r: QQ(3) / 10, A: QQ(3) / 100, C: QQ(11) / 200, g: QQ(981) / 100}
    angle, rate = QQ(1) / 4, QQ(5)
    spin_value = spin.subs(values).subs({th0: angle, Om: rate})
    steady = OperatingPoint('turning', {th: angle}, {SR.var('dpsi'): rate, SR.var('dphi'): spin_value})
    linear = linearize(S.subs(values), steady, coordinates=[th, psi, phi])
    ours = [complex(z) for z in linear.jacobian().change_ring(CDF).eigenvalues()]
    KM, constraints, parameters = sympy_disk()
    p = [float(values[SR.var(str(s))]) for s in parameters]
    q, u = list(KM.q), list(KM.u)
    rhs = _numerical_rhs(KM, parameters)
    A_u = sm.lambdify(q + parameters, sm.Matrix(constraints).jacobian(u), 'numpy')
    index = {str(v).replace('(t)', ''): i for i, v in enumerate(u)}
    free = [index['upsi'], index['utheta'], index['uphi']]
    dependent = [index['ux'], index['uy']]

    def reduced(state):
        # (theta, u_psi, u_theta, u_phi) -> their derivatives (psi = 0, x = y = 0)
        theta, *speeds = state
        qv = [0, 0, 0, theta, 0]
        uv = np.zeros(len(u))
        uv[free] = speeds
        M = np.array(A_u(*qv, *p), dtype=float)
        uv[dependent] = np.linalg.solve(M[:, dependent], -M[:, free] @ uv[free])
        out = np.array(rhs(*qv, *uv, *p), dtype=float).ravel()
        return np.array([uv[index['utheta']]] + [out[len(q) + i] for i in free])

    x0 = np.array([float(angle), float(rate), 0.0, float(spin_value)])
    assert np.max(np.abs(reduced(x0)[1:])) < 1e-10          # a steady motion
    h = 1e-6
    jacobian = np.array([(reduced(x0 + h * e) - reduced(x0 - h * e)) / (2 * h)
                         for e in np.eye(4)]).T
    theirs = list(np.linalg.eigvals(jacobian))
    nonzero = [z for z in ours if abs(z) > 1e-6]
    assert len(nonzero) == 2 and all(abs(z) < 1e-6 for z in ours if z not in nonzero)
    theirs_nonzero = [z for z in theirs if abs(z) > 1e-4]
    assert len(theirs_nonzero) == 2
    for a, b in zip(sorted(nonzero, key=lambda z: (z.real, z.imag)),
                    sorted(theirs_nonzero, key=lambda z: (z.real, z.imag))):
        assert abs(a - b) < 1e-6, (nonzero, theirs)

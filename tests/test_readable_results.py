"""
Readable characteristic functions: Lagrangians, Routh functions and
Hamiltonians come back reduced modulo cos^2 + sin^2 = 1 (for every angle,
including known functions of time) and compact.

Expected values come from outside the code under test:

- the heavy symmetric top (Euler angles psi, theta, phi; A, A, C about the
  fixed point): Goldstein, Classical Mechanics (3rd ed.), section 5.7, and
  Landau & Lifshitz, Mechanics, section 35. With the package's sign
  convention R = L - sum c dq_cyc (Goldstein section 8.3 and Landau section
  41 define the Routhian with the opposite sign):
  R = A/2 dtheta^2 - (p_psi - p_phi cos theta)^2/(2 A sin^2 theta)
      - p_phi^2/(2 C) - m g l cos theta,
  H = p_theta^2/(2A) + (p_psi - p_phi cos theta)^2/(2 A sin^2 theta)
      + p_phi^2/(2C) + m g l cos theta;
- a bead on a hoop turning at the constant rate w about its vertical
  diameter (theta from the lowest point): L = m R^2/2 (dtheta^2 +
  w^2 sin^2 theta) + m g R cos theta (J. R. Taylor, Classical Mechanics,
  Example 7.6, with U = -V);
- kinetic energies computed here directly from Cartesian positions
  (1/2 m |d r/dt|^2 by SR differentiation, no trigonometric reduction);
- Routh functions and Hamiltonians computed here numerically: cyclic
  velocities (resp. all velocities) from the momenta by numpy's linear
  solver, then R = L - c.dq_cyc and H = p.dq - L at that point.
"""
import math
import random
import sys
from pathlib import Path

import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))

from sage.all import SR, RDF, var, diagonal_matrix, cos, sin, pi, sqrt, matrix  # noqa: E402

from sage_dynsym import Lagrangian, MechanicalSystem, RigidBody, UniformGravity  # noqa: E402
from sage_dynsym.symbols import t  # noqa: E402

psi, theta, phi, A, C, m, g, l, w, R, a = var('psi theta phi A C m g l w R a')
dpsi, dtheta, dphi = var('dpsi dtheta dphi')
p_psi, p_theta, p_phi = var('p_psi p_theta p_phi')

TOP_ROUTH = (A / 2 * dtheta**2 - (p_psi - p_phi * cos(theta))**2 / (2 * A * sin(theta)**2)
             - p_phi**2 / (2 * C) - m * g * l * cos(theta))
TOP_HAMILTONIAN = (p_theta**2 / (2 * A) + (p_psi - p_phi * cos(theta))**2
                   / (2 * A * sin(theta)**2) + p_phi**2 / (2 * C) + m * g * l * cos(theta))


def top_typed():
    L = (A / 2 * (dtheta**2 + sin(theta)**2 * dpsi**2) + C / 2 * (dphi + cos(theta) * dpsi)**2
         - m * g * l * cos(theta))
    return Lagrangian(L, [psi, theta, phi])


def top_system():
    body = RigidBody('top', rotations=[(3, psi), (1, theta), (3, phi)], mass=m,
                     mass_center=[0, 0, l], inertia=diagonal_matrix([A, A, C]))
    return MechanicalSystem([body], [psi, theta, phi], parameters=[m, l, g, A, C],
                            force_function=UniformGravity([0, 0, -g]))


def hoop_system(rate=w * t):
    # the hoop (massless) turns about the vertical z; the bead sits at angle
    # theta on it, measured about the hoop's y axis from the lowest point
    hoop = RigidBody('hoop', rotations=[(3, rate)])
    bead = RigidBody('bead', parent='hoop', rotations=[(2, theta)], mass=m,
                     mass_center=[0, 0, -R], inertia=diagonal_matrix([m * R**2, m * R**2, 0]))
    return MechanicalSystem([hoop, bead], [theta], parameters=[w, m, R, g, a],
                            force_function=UniformGravity([0, 0, -g]))


def platform_system(extra_rotations=()):
    # a pendulum (point mass m on a massless rod l) hinged at distance R from
    # the axis of a platform turning uniformly about the vertical; it swings
    # in the plane through the axis
    platform = RigidBody('platform', rotations=[(3, w * t)] + list(extra_rotations))
    pendulum = RigidBody('pendulum', parent='platform', joint=[R, 0, 0],
                         rotations=[(2, theta)], mass=m, mass_center=[0, 0, -l],
                         inertia=diagonal_matrix([m * l**2, m * l**2, 0]))
    return MechanicalSystem([platform, pendulum], [theta], parameters=[w, m, R, g, l],
                            force_function=UniformGravity([0, 0, -g]))


def cartesian_lagrangian(position, coordinates, mass, gravity=g):
    """1/2 m |dr/dt|^2 - m g z from the inertial position r(q, t), by SR only."""
    velocity = [c.diff(t) + sum(c.diff(q) * var('d' + str(q)) for q in coordinates)
                for c in position]
    return mass * sum(v**2 for v in velocity) / 2 - mass * gravity * position[2]


def values(rng, symbols):
    return {s: rng.uniform(0.3, 1.3) for s in symbols}


def numerically_equal(e1, e2, symbols, rng, trials=6, tol=1e-10):
    for _ in range(trials):
        point = values(rng, symbols)
        x1, x2 = float(SR(e1).subs(point)), float(SR(e2).subs(point))
        assert math.isclose(x1, x2, rel_tol=tol, abs_tol=tol), (e1, e2, point, x1, x2)


def reduces_to_zero(expr):
    """An independent zero test: Maxima's trigonometric simplification."""
    return bool(SR(expr).simplify_trig().simplify_full() == 0)


# ---------------------------------------------------------------------------
# the heavy symmetric top

@pytest.mark.parametrize('build', [top_typed, lambda: top_system().lagrangian()],
                         ids=['typed', 'mechanical-system'])
def test_heavy_top_routh_function_is_the_textbook_one(build):
    L = build()
    Rf = L.routh([psi, phi])
    text = str(Rf.expr())
    assert len(text) < 600, text
    assert Rf.momenta() == [p_psi, p_phi]
    assert reduces_to_zero(Rf.expr() - TOP_ROUTH)
    numerically_equal(Rf.expr(), TOP_ROUTH, [theta, dtheta, p_psi, p_phi, A, C, m, g, l],
                      random.Random(1))


def test_heavy_top_routh_function_equals_independent_routh_reduction():
    # R = L - c.dq_cyc with the cyclic velocities solved numerically from
    # p_psi = dL/d(dpsi), p_phi = dL/d(dphi) (the package's sign convention)
    S = top_system()
    L = S.lagrangian()
    Rf = L.routh([psi, phi])
    L_expr = top_typed().expr()
    rng = random.Random(2)
    for _ in range(5):
        point = values(rng, [theta, dtheta, A, C, m, g, l, p_psi, p_phi])
        grad = [[float(L_expr.diff(u, v).subs(point)) for v in (dpsi, dphi)]
                for u in (dpsi, dphi)]
        rhs = [float(c.subs(point)) - float(L_expr.diff(u).subs(point).subs({dpsi: 0, dphi: 0}))
               for c, u in ((p_psi, dpsi), (p_phi, dphi))]
        x = np.linalg.solve(np.array(grad), np.array(rhs))
        velocities = {dpsi: x[0], dphi: x[1]}
        expected = float(L_expr.subs(point).subs(velocities)) - float(
            (p_psi * x[0] + p_phi * x[1]).subs(point))
        assert float(Rf.expr().subs(point)) == pytest.approx(expected, rel=1e-10, abs=1e-10)
        for v, value in zip(Rf.cyclic_velocities(), x):
            assert float(v.subs(point)) == pytest.approx(value, rel=1e-10, abs=1e-10)


@pytest.mark.parametrize('build', [top_typed, lambda: top_system().lagrangian()],
                         ids=['typed', 'mechanical-system'])
def test_heavy_top_hamiltonian_is_the_textbook_one(build):
    H = build().hamiltonian()
    text = str(H.expr())
    assert len(text) < 300, text
    assert reduces_to_zero(H.expr() - TOP_HAMILTONIAN)
    numerically_equal(H.expr(), TOP_HAMILTONIAN,
                      [theta, p_psi, p_theta, p_phi, A, C, m, g, l], random.Random(3))


def test_heavy_top_lagrangian_of_the_system_is_the_typed_one():
    L = top_system().lagrangian().expr()
    assert len(str(L)) < 200
    assert reduces_to_zero(L - top_typed().expr())


# ---------------------------------------------------------------------------
# rotating frames: the angle w*t of a known rotation

def test_bead_on_rotating_hoop_is_autonomous_and_textbook():
    L = hoop_system().lagrangian()
    textbook = m * R**2 / 2 * (dtheta**2 + w**2 * sin(theta)**2) + m * g * R * cos(theta)
    assert not L.expr().has(t), L.expr()
    assert reduces_to_zero(L.expr() - textbook)
    numerically_equal(L.expr(), textbook, [theta, dtheta, m, R, w, g], random.Random(4))
    # and from the inertial Cartesian position of the bead
    r = R * sin(theta)
    position = [-r * cos(w * t), -r * sin(w * t), -R * cos(theta)]
    direct = cartesian_lagrangian(position, [theta], m)
    assert direct.has(t)      # unreduced: cos(t*w)^2 + sin(t*w)^2 pairs
    numerically_equal(L.expr(), direct, [theta, dtheta, m, R, w, g, t], random.Random(5))


def test_pendulum_on_rotating_platform_is_autonomous():
    S = platform_system()
    L = S.lagrangian()
    assert not L.expr().has(t), L.expr()
    assert len(str(L.expr())) < 120, L.expr()
    # rotating frame: the pendulum's point is at (R - l sin theta, 0, -l cos theta)
    rho = R - l * sin(theta)
    direct = cartesian_lagrangian([rho * cos(w * t), rho * sin(w * t), -l * cos(theta)],
                                  [theta], m)
    numerically_equal(L.expr(), direct, [theta, dtheta, m, R, w, g, l, t], random.Random(6))
    E = L.lagrange_equations()
    assert not any(e.has(t) for e in E)
    # Lagrange's equation of the textbook Lagrangian m/2 (l^2 dtheta^2 +
    # w^2 (R - l sin)^2) + m g l cos (the rotating-frame form)
    expected = (m * l**2 * var('ddtheta') + m * w**2 * (R - l * sin(theta)) * l * cos(theta)
                + m * g * l * sin(theta))
    assert reduces_to_zero(E[0] - expected)


@pytest.mark.parametrize('rate', [w * t, w * t / 2, 3 * t, w * t + a],
                         ids=['w*t', 'w*t/2', '3*t', 'w*t+a'])
def test_rotating_frame_angle_reduced(rate):
    L = hoop_system(rate).lagrangian().expr()
    assert not L.has(t), L
    assert 'cos(' + str(rate) not in str(L)


def test_constant_tilt_and_known_motion_of_a_joint():
    # a hoop turning about z, tilted by the constant pi/6 (sqrt(3) appears)
    hoop = RigidBody('hoop', rotations=[(3, w * t), (1, pi / 6)])
    bead = RigidBody('bead', parent='hoop', rotations=[(2, theta)], mass=m,
                     mass_center=[0, 0, -R], inertia=diagonal_matrix([m * R**2, m * R**2, 0]))
    S = MechanicalSystem([hoop, bead], [theta], parameters=[w, m, R, g],
                         force_function=UniformGravity([0, 0, -g]))
    L = S.lagrangian().expr()
    assert not L.has(t) and len(str(L)) < 130, L
    # the same bead from its Cartesian position
    c, s = cos(w * t), sin(w * t)
    body = [-R * sin(theta), 0, -R * cos(theta)]              # in the hoop's axes
    tilt = matrix(SR, [[1, 0, 0], [0, sqrt(3) / 2, -1 / SR(2)], [0, 1 / SR(2), sqrt(3) / 2]])
    turn = matrix(SR, [[c, -s, 0], [s, c, 0], [0, 0, 1]])
    position = list(turn * tilt * matrix(SR, body).transpose())
    position = [e[0] for e in position]
    numerically_equal(L, cartesian_lagrangian(position, [theta], m),
                      [theta, dtheta, m, R, w, g, t], random.Random(7))

    # a pendulum hinged at a point moving on a circle, (a cos wt, a sin wt, 0):
    # genuinely time dependent, but cos^2 + sin^2 of wt is reduced
    pend = RigidBody('pendulum', joint=[a * cos(w * t), a * sin(w * t), 0],
                     rotations=[(1, theta)], mass=m, mass_center=[0, 0, -l],
                     inertia=diagonal_matrix([m * l**2, m * l**2, 0]))
    S = MechanicalSystem([pend], [theta], parameters=[w, m, g, a, l],
                         force_function=UniformGravity([0, 0, -g]))
    L = S.lagrangian().expr()
    assert 'sin(t*w)^2' not in str(L) and 'cos(t*w)^2' not in str(L), L
    assert len(str(L)) < 100, L
    position = [a * cos(w * t), a * sin(w * t) + l * sin(theta), -l * cos(theta)]
    numerically_equal(L, cartesian_lagrangian(position, [theta], m),
                      [theta, dtheta, m, a, w, g, l, t], random.Random(8))


def test_rotating_platform_with_cyclic_coordinate_routh_and_hamiltonian():
    # a pendulum on a rotating platform plus a free rotor turning about the
    # pendulum rod: a cyclic angle coupled to the positional one
    platform = RigidBody('platform', rotations=[(3, w * t)])
    pendulum = RigidBody('pendulum', parent='platform', joint=[R, 0, 0],
                         rotations=[(2, theta), (3, phi)], mass=m, mass_center=[0, 0, -l],
                         inertia=diagonal_matrix([A, A, C]))
    S = MechanicalSystem([platform, pendulum], [theta, phi],
                         parameters=[w, m, R, g, l, A, C],
                         force_function=UniformGravity([0, 0, -g]))
    L = S.lagrangian()
    assert not L.expr().has(t)
    Rf = L.routh([phi])
    H = L.hamiltonian()
    assert not Rf.expr().has(t) and not H.expr().has(t)
    assert len(str(Rf.expr())) < 400, Rf.expr()
    _check_routh_and_hamiltonian_numerically(L, Rf, H, [m, R, g, l, A, C, w], random.Random(9))


def _check_routh_and_hamiltonian_numerically(L, Rf, H, parameters, rng, trials=4):
    """R = L - c.dq_cyc and H = p.dq - L at random points, velocities solved by numpy."""
    q, dq = L.coordinates(), L.velocities()
    expr = L.expr()
    hessian = [[expr.diff(u, v) for v in dq] for u in dq]
    momenta = [expr.diff(v) for v in dq]
    cyclic = [q.index(c) for c in Rf.cyclic_coordinates()]
    positional = [i for i in range(len(q)) if i not in cyclic]
    for _ in range(trials):
        point = values(rng, parameters + q + [t])
        state = dict(point)
        state.update({dq[i]: rng.uniform(-1, 1) for i in range(len(q))})
        # Hamiltonian: momenta at a random state, H(q, p) = p.dq - L
        p = [float(e.subs(state)) for e in momenta]
        h = sum(pi * float(state[v]) for pi, v in zip(p, dq)) - float(expr.subs(state))
        hpoint = dict(point)
        hpoint.update(dict(zip(H.momenta(), p)))
        assert float(H.expr().subs(hpoint)) == pytest.approx(h, rel=1e-9, abs=1e-9)
        # Routh function: cyclic velocities from the cyclic momenta
        c = [p[i] for i in cyclic]
        M = np.array([[float(hessian[i][j].subs(point)) for j in cyclic] for i in cyclic])
        at_zero = {v: 0 for v in [dq[i] for i in cyclic]}
        # p_cyc = M dq_cyc + (the rest, at dq_cyc = 0)
        rest = np.array([float(momenta[i].subs(at_zero).subs(state)) for i in cyclic])
        x = np.linalg.solve(M, np.array(c) - rest)
        rstate = dict(state)
        rstate.update({dq[i]: xi for i, xi in zip(cyclic, x)})
        expected = float(expr.subs(rstate)) - sum(ci * xi for ci, xi in zip(c, x))
        rpoint = dict(point)
        rpoint.update({dq[i]: state[dq[i]] for i in positional})
        rpoint.update(dict(zip(Rf.momenta(), c)))
        assert float(Rf.expr().subs(rpoint)) == pytest.approx(expected, rel=1e-9, abs=1e-9)


def _regular_random_chains(count):
    """Random chains (first rotation about the gravity axis, so q1 is cyclic)
    with a regular mass matrix (two successive rotations about one axis make
    it singular) and at most 4 coordinates (the Legendre transform of bigger
    ones takes minutes), by increasing seed."""
    from test_lagrangian_identities import random_chain
    from sage_dynsym.errors import ModelError
    seed = 200
    while count:
        rng = random.Random(seed)
        seed += 1
        try:
            S, q = random_chain(rng, 2)
        except ModelError:      # an unphysical random inertia tensor
            continue
        if len(q) > 4:
            continue
        M = S.decomposition()[0]
        point = {v: 0.1 * k + 0.3 for k, v in enumerate(q)}
        if abs(M.subs(point).change_ring(RDF).det()) > 1e-6:
            count -= 1
            yield S, q


@pytest.mark.parametrize('S, q', list(_regular_random_chains(3)))
def test_random_chains_routh_and_hamiltonian_numerically(S, q):
    L = S.lagrangian()
    assert q[0] in L.cyclic_coordinates()
    Rf, H = L.routh([q[0]]), L.hamiltonian()
    _check_routh_and_hamiltonian_numerically(L, Rf, H, [g], random.Random(10 + len(q)))


def test_hamiltonian_not_larger_than_before_on_a_chain():
    # the spatial chain of bench/bench_chain.py with 2 links: the adjugate
    # form of the Legendre transform gave about 326,000 characters
    from reference.chains import spatial_chain
    from test_mechanics_crosscheck import sage_system
    desc = spatial_chain(2)
    L = sage_system(desc).lagrangian()
    H = L.hamiltonian()
    assert len(str(H.expr())) < 10000
    Rf = L.routh([L.coordinates()[0]])
    assert len(str(Rf.expr())) < 10000
    params = [SR.var(p) for p in desc['parameters']]
    _check_routh_and_hamiltonian_numerically(L, Rf, H, params, random.Random(11), trials=2)


def test_inexact_data_still_reduced():
    # decimal data (as typed in a description file) keep the polynomial
    # arithmetic: no unreduced 0.5*cos(b)^2 + 1.0*sin(b)^2 pair
    body = RigidBody('p', rotations=[(3, psi), (1, theta)], mass=0.5,
                     mass_center=[0, 0, 1.5], inertia=diagonal_matrix([1.25, 1.0, 0.5]))
    S = MechanicalSystem([body], [psi, theta], force_function=UniformGravity([0, 0, -g]))
    L = S.lagrangian().expr()
    assert 'cos(theta)^2' not in str(L) or 'sin(theta)^2' not in str(L), L
    # T = 1/2 W.Theta W with W = (dtheta, dpsi sin, dpsi cos) (the body's axes)
    W = [dtheta, dpsi * sin(theta), dpsi * cos(theta)]
    direct = (1.25 * W[0]**2 + 1.0 * W[1]**2 + 0.5 * W[2]**2) / 2 - 0.5 * g * 1.5 * cos(theta)
    numerically_equal(L, direct, [theta, dpsi, dtheta, g], random.Random(12), tol=1e-12)

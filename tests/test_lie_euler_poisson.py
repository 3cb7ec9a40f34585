"""Euler-Poisson equations from a heavy-top description against the Lagrange
equations in Euler angles of the same description (issue 12, must-show 1).

Independent path: the Lagrange equations come from the package's Lagrangian
(kinetic energy and force function of the description, a different
derivation); the map from (angles, rates) to (M, gamma) is written out here
from rotation matrices (Goldstein, Classical Mechanics, 3rd ed., §4.4:
body angular velocity from Omega^ = R^T dR/dt, M = I Omega, gamma = R^T e3).
At random states the accelerations are solved numerically (numpy) from the
Lagrange equations, the time derivative of (M, gamma) is formed by the
chain rule and compared with the Euler-Poisson right-hand sides. This also
checks the sign convention of the Lie-Poisson bracket against the canonical
one (Lie-Poisson reduction: Marsden & Ratiu, Introduction to Mechanics and
Symmetry, §15.7).
"""
import random

import numpy as np
import pytest
from sage.all import SR, var, matrix, vector, cos, sin, diagonal_matrix

from sage_dynsym import MechanicalSystem, RigidBody, UniformGravity
from sage_dynsym.description import mechanical_system_from_dict
from sage_dynsym.lie import euler_poisson

psi, theta, phi = var('psi theta phi')
dpsi, dtheta, dphi = var('dpsi dtheta dphi')
ddpsi, ddtheta, ddphi = var('ddpsi ddtheta ddphi')
Q, DQ, DDQ = [psi, theta, phi], [dpsi, dtheta, dphi], [ddpsi, ddtheta, ddphi]
A, B, C, D, m, g, x0, y0, z0 = var('A B C D m g x0 y0 z0')
PARAMS = [A, B, C, D, m, g, x0, y0, z0]


def Rz(a):
    return matrix(SR, [[cos(a), -sin(a), 0], [sin(a), cos(a), 0], [0, 0, 1]])


def Rx(a):
    return matrix(SR, [[1, 0, 0], [0, cos(a), -sin(a)], [0, sin(a), cos(a)]])


def independent_map(inertia, axis=2):
    """(M, gamma) from angles and rates via R = Rz(psi) Rx(theta) Rz(phi)."""
    R = Rz(psi) * Rx(theta) * Rz(phi)
    dR = sum((R.apply_map(lambda e: e.diff(q)) * dq for q, dq in zip(Q, DQ)), matrix(SR, 3, 3))
    W = (R.transpose() * dR).simplify_trig()
    omega = vector(SR, [W[2, 1], W[0, 2], W[1, 0]])
    return list(inertia * omega) + list(R.row(axis))


def top(inertia, center, field=(0, 0, -1)):
    body = RigidBody('top', rotations=[(3, psi), (1, theta), (3, phi)], mass=m,
                     mass_center=center, inertia=inertia)
    return MechanicalSystem([body], Q, parameters=PARAMS,
                            force_function=UniformGravity([c * g for c in field]))


def compare(system, inertia, seed, axis=2, samples=4):
    S = euler_poisson(system)
    L = system.lagrangian()
    E = L.lagrange_equations()
    mapping = independent_map(inertia, axis)
    variables = S.variables()
    rng = random.Random(seed)
    worst = 0.0
    for _ in range(samples):
        # a physical body: principal moments obeying the triangle inequality
        vals = {A: rng.uniform(2, 3), B: rng.uniform(2, 3), C: rng.uniform(2, 3),
                D: rng.uniform(-0.3, 0.3), m: rng.uniform(0.5, 2), g: 9.81,
                x0: rng.uniform(-1, 1), y0: rng.uniform(-1, 1), z0: rng.uniform(-1, 1)}
        vals.update({q: rng.uniform(0.3, 2.8) for q in Q})
        vals.update({dq: rng.uniform(-2, 2) for dq in DQ})
        # accelerations from the Lagrange equations E(q, dq, ddq) = 0 (linear in ddq)
        Mm = np.array([[float(e.diff(a).subs(vals)) for a in DDQ] for e in E])
        rhs = -np.array([float(e.subs(vals).subs({a: 0 for a in DDQ})) for e in E])
        acc = dict(zip(DDQ, np.linalg.solve(Mm, rhs)))
        state = {x: float(f.subs(vals)) for x, f in zip(variables, mapping)}
        for x, f, X in zip(variables, mapping, S.equations()):
            chain = sum(float(f.diff(q).subs(vals)) * vals[dq] for q, dq in zip(Q, DQ)) + \
                sum(float(f.diff(dq).subs(vals)) * acc[a] for dq, a in zip(DQ, DDQ))
            predicted = float(SR(X).subs(state).subs(vals))
            worst = max(worst, abs(chain - predicted))
    return worst


def test_general_heavy_body_agrees_with_lagrange_equations():
    # a non-principal inertia tensor (product of inertia D) and a general
    # centre of mass: every term of H and of the bracket is exercised
    inertia = matrix(SR, [[A, D, 0], [D, B, 0], [0, 0, C]])
    assert compare(top(inertia, [x0, y0, z0]), inertia, seed=1) < 1e-9


def test_symmetric_top_agrees_with_lagrange_equations():
    inertia = diagonal_matrix(SR, [A, A, C])
    assert compare(top(inertia, [0, 0, z0]), inertia, seed=2) < 1e-9


def test_field_along_another_axis():
    # gravity along -y: gamma is the body components of the inertial e2
    inertia = diagonal_matrix(SR, [A, B, C])
    system = top(inertia, [x0, y0, z0], field=(0, -1, 0))
    assert compare(system, inertia, seed=3, axis=1, samples=2) < 1e-9


def test_reduction_map_is_the_independent_one():
    inertia = matrix(SR, [[A, D, 0], [D, B, 0], [0, 0, C]])
    S = euler_poisson(top(inertia, [x0, y0, z0]))
    rng = random.Random(4)
    mapping = independent_map(inertia)
    for _ in range(3):
        vals = {s: rng.uniform(0.3, 2.5) for s in Q + DQ + [A, B, C, D]}
        for x, f in zip(S.variables(), mapping):
            assert abs(float(S.reduction()[x].subs(vals)) - float(f.subs(vals))) < 1e-12


def test_hamiltonian_is_the_energy():
    # H(M(q, dq), gamma(q)) = T + V of the Lagrangian description
    inertia = diagonal_matrix(SR, [A, B, C])
    system = top(inertia, [x0, y0, z0])
    S = euler_poisson(system)
    L = system.lagrangian().expr()
    energy = sum(L.diff(dq) * dq for dq in DQ) - L
    H = S.hamiltonian().subs(S.reduction())
    rng = random.Random(5)
    for _ in range(3):
        vals = {s: rng.uniform(0.3, 2.5) for s in Q + DQ + PARAMS}
        assert abs(float(H.subs(vals)) - float(energy.subs(vals))) < 1e-10


def test_from_a_description_file_mapping():
    d = {'kind': 'mechanical', 'name': 'heavy top', 'parameters': ['A', 'C', 'm', 'g', 'l'],
         'coordinates': ['psi', 'theta', 'phi'],
         'force_function': {'uniform_gravity': [0, 0, '-g']},
         'bodies': [{'name': 'top', 'rotations': [[3, 'psi'], [1, 'theta'], [3, 'phi']],
                     'mass_center': [0, 0, 'l'], 'mass': 'm',
                     'inertia': [['A', 0, 0], [0, 'A', 0], [0, 0, 'C']]}]}
    S = euler_poisson(mechanical_system_from_dict(d))
    M1, M2, M3, g1, g2, g3 = S.variables()
    l, = var('l'),
    assert bool(S.hamiltonian() == (M1**2 + M2**2) / (2 * A) + M3**2 / (2 * C) + m * g * l * g3)
    assert S.name() == 'heavy top'


def test_massless_carriers_for_the_euler_angles():
    # precession and nutation frames as massless bodies, the top on them
    inertia = diagonal_matrix(SR, [A, B, C])
    bodies = [RigidBody('precession', rotations=[(3, psi)]),
              RigidBody('nutation', parent='precession', rotations=[(1, theta)]),
              RigidBody('top', parent='nutation', rotations=[(3, phi)], mass=m,
                        mass_center=[x0, y0, z0], inertia=inertia)]
    system = MechanicalSystem(bodies, Q, parameters=PARAMS,
                              force_function=UniformGravity([0, 0, -g]))
    assert compare(system, inertia, seed=6, samples=2) < 1e-9


def test_refusals():
    inertia = diagonal_matrix(SR, [A, B, C])
    moving = RigidBody('top', rotations=[(3, psi)], joint=[0, 0, z0], mass=m, inertia=inertia)
    with pytest.raises(ValueError, match="fixed point"):
        euler_poisson(MechanicalSystem([moving], [psi]))
    damped = MechanicalSystem([RigidBody('top', rotations=[(3, psi)], mass=m, inertia=inertia)],
                              [psi], dissipation=dpsi**2)
    with pytest.raises(ValueError, match="conservative"):
        euler_poisson(damped)


def test_the_map_to_m_and_gamma_is_a_poisson_map():
    # Lie-Poisson reduction (Marsden & Ratiu, Thm. 13.1.1 / §15.7): with the
    # canonical bracket of the Euler angles and their momenta, M(q, p) and
    # gamma(q) have exactly the brackets of e(3) used by the package:
    # {M_i, M_j} = -eps_ijk M_k, {M_i, gamma_j} = -eps_ijk gamma_k, {gamma_i, gamma_j} = 0
    from sage_dynsym.lie import lie_algebra
    R = Rz(psi) * Rx(theta) * Rz(phi)
    dR = sum((R.apply_map(lambda e: e.diff(q)) * dq for q, dq in zip(Q, DQ)), matrix(SR, 3, 3))
    W = (R.transpose() * dR).simplify_trig()
    omega = vector(SR, [W[2, 1], W[0, 2], W[1, 0]])
    Wq = matrix(SR, [[w.diff(dq) for dq in DQ] for w in omega])     # omega = Wq dq
    p = vector(SR, var('p_psi p_theta p_phi'))
    Mq = Wq.transpose().inverse() * p                               # p = Wq^T M
    gamma = list(R.row(2))
    funcs = list(Mq) + gamma
    E = lie_algebra('e3')
    rng = random.Random(10)
    for _ in range(3):
        vals = {s: rng.uniform(0.3, 2.8) for s in Q + list(p)}
        point = dict(zip(E.variables(), [float(f.subs(vals)) for f in funcs]))
        for i in range(6):
            for j in range(6):
                canonical = sum(funcs[i].diff(q) * funcs[j].diff(pq) -
                                funcs[i].diff(pq) * funcs[j].diff(q) for q, pq in zip(Q, p))
                expected = float(SR(E.matrix()[i, j]).subs(point))
                assert abs(float(canonical.subs(vals)) - expected) < 1e-9, (i, j)

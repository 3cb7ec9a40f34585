"""Identities between the forms of the equations of motion, and the textbook
Dirac constraint chains. Expected values come from the mathematics (the
Lagrange equations, known Dirac brackets), not from the code under test."""
import random

import pytest
from sage.all import SR, var, QQ, vector

from sage_dynsym import Lagrangian, MechanicalSystem, RigidBody, UniformGravity
from sage_dynsym.symbols import velocity


def numeric(expr, values):
    return float(SR(expr).subs(values))


def random_rational(rng, low=-2, high=2):
    return QQ(rng.randint(low * 8, high * 8)) / 8 or QQ(1) / 3


def random_chain(rng, n_bodies):
    """A chain whose first rotation is about the gravity axis: that angle is cyclic."""
    coordinates, bodies = [], []
    for k in range(1, n_bodies + 1):
        axes = [3] if k == 1 else []
        axes += [rng.choice([1, 2, 3]) for _ in range(rng.randint(1, 2))]
        rotations = []
        for a in axes:
            q = var(f'q{len(coordinates) + 1}')
            coordinates.append(q)
            rotations.append((a, q))
        m = QQ(rng.randint(1, 5))
        c = [random_rational(rng) for _ in range(3)]
        # principal moments in [6, 9]: the triangle inequality holds
        diag = [QQ(rng.randint(6, 9)) for _ in range(3)]
        off = [random_rational(rng, -1, 1) / 2 for _ in range(3)]
        inertia = [[diag[0], off[0], off[1]], [off[0], diag[1], off[2]], [off[1], off[2], diag[2]]]
        joint = [0, 0, 0] if k == 1 else [random_rational(rng) for _ in range(3)]
        bodies.append(RigidBody(f'b{k}', parent=k - 1, rotations=rotations, joint=joint,
                                mass_center=c, mass=m, inertia=inertia))
    g = var('g')
    system = MechanicalSystem(bodies, coordinates, force_function=UniformGravity([0, 0, -g]))
    return system, coordinates


@pytest.mark.parametrize("seed", range(4))
def test_structured_equals_direct(seed):
    rng = random.Random(seed)
    system, q = random_chain(rng, rng.randint(1, 3))
    L = system.lagrangian()
    structured = L.lagrange_equations("structured")
    # the direct form differentiates the expression of L, independently of (5)
    direct = Lagrangian(L.expr(), q).lagrange_equations("direct")
    for _ in range(3):
        values = {v: rng.uniform(-1.5, 1.5) for v in q + L.velocities() + L.accelerations()}
        values[var('g')] = 9.81
        for s, d in zip(structured, direct):
            assert numeric(s, values) == pytest.approx(numeric(d, values), rel=1e-9, abs=1e-9)


def solve_accelerations(equations, accelerations, values):
    """Numeric accelerations from equations linear in them."""
    rows, rhs = [], []
    for e in equations:
        e = SR(e).subs(values)
        rows.append([float(e.coefficient(a)) for a in accelerations])
        rhs.append(-float(e.subs({a: 0 for a in accelerations})))
    import numpy
    return list(numpy.linalg.solve(numpy.array(rows), numpy.array(rhs)))


@pytest.mark.parametrize("seed", range(3))
def test_routh_equations_agree_with_lagrange(seed):
    rng = random.Random(100 + seed)
    system, q = random_chain(rng, rng.randint(1, 2))
    L = system.lagrangian()
    assert q[0] in L.cyclic_coordinates()
    R = L.routh([q[0]])
    dq, ddq = L.velocities(), L.accelerations()
    for _ in range(3):
        state = {v: rng.uniform(-1.2, 1.2) for v in q + dq}
        state[var('g')] = 9.81
        lagrange = solve_accelerations(L.lagrange_equations(), ddq, state)
        p = numeric(L.generalized_momenta()[0], state)
        routh_state = {v: state[v] for v in q[1:] + dq[1:]}
        routh_state.update({R.momenta()[0]: p, var('g'): 9.81})
        routh = solve_accelerations(R.equations(), ddq[1:], routh_state)
        for a, b in zip(lagrange[1:], routh):
            assert a == pytest.approx(b, rel=1e-8, abs=1e-8)
        # the cyclic velocity is recovered from the momentum
        assert numeric(R.cyclic_velocities()[0], routh_state) == pytest.approx(state[dq[0]])


def test_dirac_first_order_lagrangian_gives_lagrange_equations():
    # L = (x dy - y dx)/2 - V: Lagrange gives dx/dt = -V_y, dy/dt = V_x
    x, y, dx, dy = var('x y dx dy')
    V = x**2 * y + y**4 + 3 * x
    H = Lagrangian((x * dy - y * dx) / 2 - V, [x, y]).hamiltonian()
    D = H.constraints()
    assert H.is_singular() and len(D.second_class()) == 2 and not D.first_class()
    assert D.dirac_bracket(x, y) == -1
    (xdot, _), (ydot, _) = H.equations()
    assert bool(xdot == -V.diff(y)) and bool(ydot == V.diff(x))


def test_dirac_gauge_lagrangian_first_class_chain():
    # L = (dx - y)^2/2: p_y = 0 primary, p_x = 0 secondary, both first class
    x, y, dx, dy = var('x y dx dy')
    D = Lagrangian((dx - y)**2 / 2, [x, y]).hamiltonian().constraints()
    p_x, p_y = var('p_x p_y')
    assert D.primary() == [p_y]
    assert [bool(c**2 == p_x**2) for c in D.secondary()] == [True]
    assert len(D.first_class()) == 2 and not D.second_class()


def test_dirac_particle_on_sphere_brackets():
    # Dirac (1964): a particle on the unit sphere, {x_i, p_j}_D = delta_ij - x_i x_j
    x, y, z, lam = var('x y z lam')
    q = [x, y, z]
    dq = [velocity(v) for v in q]
    L = Lagrangian(sum(d**2 for d in dq) / 2 + lam * (x**2 + y**2 + z**2 - 1), q + [lam])
    D = L.hamiltonian().constraints()
    assert len(D.constraints()) == 4 and len(D.second_class()) == 4
    p = [var(f'p_{v}') for v in q]
    rng = random.Random(7)
    for _ in range(3):
        # a point on the constraint surface: |r| = 1, r.p = 0
        r = vector([rng.uniform(-1, 1) for _ in range(3)]); r = r / r.norm()
        w = vector([rng.uniform(-1, 1) for _ in range(3)]); w = w - (w * r) * r
        point = dict(zip(q + p, list(r) + list(w)))
        point[lam] = -(w * w) / 2        # the last constraint fixes the multiplier
        for i in range(3):
            for j in range(3):
                expected = (1 if i == j else 0) - r[i] * r[j]
                got = numeric(D.dirac_bracket(q[i], p[j]), point)
                assert got == pytest.approx(expected, abs=1e-10)
        # constraints are Casimirs of the Dirac bracket
        for chi in D.constraints():
            for f in q + p:
                assert numeric(D.dirac_bracket(chi, f), point) == pytest.approx(0, abs=1e-10)

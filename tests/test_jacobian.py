"""
The compiled Jacobian of the recursive right-hand side
(``numerical_rhs(values, jacobian=True)``), checked against

- the Jacobian of the symbolic right-hand side of a double pendulum whose
  Lagrangian is written here by hand (positions of the mass centres, kinetic
  energy by Koenig's theorem, Lagrange's equations and the Jacobian by Sage's
  differentiation, evaluated at random states) -- independent of the package;
- central differences of the compiled right-hand side, on random trees of
  ``reference/chains.py`` (branching, offsets, full inertia tensors), on an
  N-link chain, on a floating-base tree (a free base by three translations and
  three rotations, two branches), with applied forces (spring, dampers,
  forces of the state), and with constraints (the LTDL solver);

all to 1e-7 relative. The inverse dynamics through which the Jacobian is
differentiated equals the Lagrange equations of the hand-written double
pendulum. Implicit integration (Radau) takes the Jacobian and agrees with an
explicit one.
"""
import sys
from pathlib import Path

import numpy as np
import pytest
from sage.all import SR, diff, matrix, vector, cos, sin, jacobian as sage_jacobian

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from reference.chains import random_chain, offset_chain  # noqa: E402
from reference.numerics import central_differences  # noqa: E402
from sage_chains import sage_chain  # noqa: E402
from sage_dynsym import MechanicalSystem, RigidBody, UniformGravity  # noqa: E402
from sage_dynsym.numerics import rhs as rhs_module  # noqa: E402

TOLERANCE = 1e-7


def relative_error(J, reference):
    return np.max(np.abs(J - reference)) / max(1.0, np.max(np.abs(reference)))


def random_states(n, count, seed):
    rng = np.random.default_rng(seed)
    return [np.concatenate([rng.uniform(-1.5, 1.5, n), rng.uniform(-1, 1, n)])
            for _ in range(count)]


def double_pendulum():
    """The model and, by hand, the Jacobian of its symbolic right-hand side."""
    a, b, da, db = SR.var('a b da db')
    m1, m2, l1, c1, c2, A1, A2, g = SR.var('m1 m2 l1 c1 c2 A1 A2 g')

    def rx(angle, v):      # rotation about x
        return vector([v[0], cos(angle) * v[1] - sin(angle) * v[2],
                       sin(angle) * v[1] + cos(angle) * v[2]])
    t = SR.var('t')
    path = {a: SR('fa(t)'), b: SR('fb(t)')}
    G1 = rx(a, vector([0, 0, -c1]))
    G2 = rx(a, vector([0, 0, -l1])) + rx(a + b, vector([0, 0, -c2]))

    def speed2(G):
        v = [diff(c.subs(path), t) for c in G]
        v = [e.subs({diff(path[a], t): da, diff(path[b], t): db}).subs(
            {path[a]: a, path[b]: b}) for e in v]
        return sum(e ** 2 for e in v)
    # Koenig: T = m v_G^2/2 + I_G w^2/2, I_G = A - m c^2 (A about the joint)
    T = (m1 * speed2(G1) + (A1 - m1 * c1 ** 2) * da ** 2
         + m2 * speed2(G2) + (A2 - m2 * c2 ** 2) * (da + db) ** 2) / 2
    V = g * (m1 * G1[2] + m2 * G2[2])
    q, dq = [a, b], [da, db]
    L = T - V
    M = matrix([[diff(L, u, w) for w in dq] for u in dq])
    # d/dt dL/ddq = M ddq + sum_j d2L/(ddq dq_j) dq_j
    F = vector([diff(L, q[i]) - sum(diff(L, dq[i], q[j]) * dq[j] for j in range(2))
                for i in range(2)])
    ddq = M.solve_right(F)
    rhs = list(dq) + list(ddq)
    J = sage_jacobian(rhs, q + dq)
    bodies = [RigidBody('upper', rotations=[(1, a)], mass=m1, mass_center=[0, 0, -c1],
                        inertia=matrix.diagonal([A1, A1, 0])),
              RigidBody('lower', parent='upper', joint=[0, 0, -l1], rotations=[(1, b)],
                        mass=m2, mass_center=[0, 0, -c2], inertia=matrix.diagonal([A2, A2, 0]))]
    S = MechanicalSystem(bodies, q, force_function=UniformGravity([0, 0, -g]))
    values = {m1: 1.3, m2: 0.7, l1: 1.1, c1: 0.6, c2: 0.5, A1: 0.6, A2: 0.3, g: 9.81}
    return S, J, q + dq, values


def test_jacobian_equals_the_symbolic_one_of_a_double_pendulum():
    S, J, state, values = double_pendulum()
    f, jac = S.numerical_rhs(values, jacobian=True)
    assert [str(v) for v in jac.variables()] == [str(v) for v in state]
    J = J.subs(values)
    for x in random_states(2, 4, seed=3):
        reference = np.array(J.subs(dict(zip(state, x))).n(), dtype=float)
        assert relative_error(jac(0.0, x), reference) < 1e-12


def test_inverse_dynamics_equals_lagrange_of_a_double_pendulum():
    # tau(q, dq, ddq) = M ddq - F of the Lagrangian written by hand: the
    # Newton-Euler pass with the accelerations that the Jacobian differentiates
    from sage_dynsym.mechanics.recursive_numerics import numerical_form
    from sage_dynsym.numerics.compiler import run_python
    from sage_dynsym.numerics.recursive import RecursiveForm
    from sage_dynsym.numerics.rnea_derivatives import inverse_dynamics_graph
    S, _, state, values = double_pendulum()
    a, b, da, db = state
    dda, ddb = SR.var('dda ddb')
    L = S.lagrangian().expr()
    q, dq = [a, b], [da, db]
    M = matrix([[diff(L, u, w) for w in dq] for u in dq])
    F = vector([diff(L, q[i]) - sum(diff(L, dq[i], q[j]) * dq[j] for j in range(2))
                for i in range(2)])
    tau = (M * vector([dda, ddb]) - F).subs(values)
    form = RecursiveForm(numerical_form(S, 'recursive').tree(), values=values)
    G, nodes = inverse_dynamics_graph(form)
    evaluate = run_python(G.python_source(nodes), '_graph')
    rng = np.random.default_rng(5)
    for x in random_states(2, 3, seed=5):
        ddq = rng.uniform(-2, 2, 2)
        reference = np.array([float(e.subs(dict(zip(state + [dda, ddb], list(x) + list(ddq)))))
                              for e in tau])
        assert relative_error(np.array(evaluate(0.0, list(x) + list(ddq), [])), reference) < 1e-12


def test_jacobian_with_applied_forces_against_central_differences():
    # a slider on a turning arm with a spring, dampers and a force that
    # depends on the state: the applied forces enter the inverse dynamics
    phi, r, k, c = SR.var('phi r k c')
    dphi, dr = SR.var('dphi dr')
    S = MechanicalSystem([RigidBody('arm', rotations=[(3, phi)], mass=1,
                                    mass_center=[SR(1) / 2, 0, 0],
                                    inertia=matrix.diagonal([0, 1, 1])),
                          RigidBody('slider', parent='arm', joint=[r, 0, 0], mass=2,
                                    inertia=matrix.diagonal([1, 1, 1]) / 10)],
                         [phi, r], force_function=-k * (r - 1) ** 2 / 2,
                         dissipation=c * (dr ** 2 + dphi ** 2 / 4) / 2,
                         forces=[-r * dphi * sin(phi), cos(phi) * dr])
    f, jac = S.numerical_rhs({k: 40.0, c: 0.7}, jacobian=True)
    assert f.form().solver() == 'articulated'
    for x in random_states(2, 3, seed=11):
        assert relative_error(jac(0.0, x), central_differences(f, x)) < TOLERANCE


@pytest.mark.parametrize('seed', [1, 10, 13, 18])
def test_jacobian_of_random_trees_against_central_differences(seed):
    desc = random_chain(seed, n_bodies=4, symbolic=True)
    S = sage_chain(desc)
    f, jac = S.numerical_rhs(desc['values'], jacobian=True)
    n = len(desc['coordinates'])
    for x in random_states(n, 2, seed):
        assert relative_error(jac(0.0, x), central_differences(f, x)) < TOLERANCE


def test_jacobian_python_backend_equals_c():
    desc = random_chain(22, n_bodies=4, symbolic=True)
    S = sage_chain(desc)
    _, jac_c = S.numerical_rhs(desc['values'], jacobian=True, backend='c')
    _, jac_python = S.numerical_rhs(desc['values'], jacobian=True, backend='python')
    for x in random_states(len(desc['coordinates']), 2, 22):
        assert relative_error(jac_python(0.0, x), jac_c(0.0, x)) < 1e-13


def floating_base_tree(values):
    """A free base (x, y, z and three rotations) carrying two arms of two
    links each, and a head: branches from the base."""
    x, y, z, psi, theta, phi = SR.var('x y z psi theta phi')
    coordinates = [x, y, z, psi, theta, phi]
    rng = np.random.default_rng(4)

    def inertia():
        A = matrix(SR, 3, 3, [SR(round(v, 3)) for v in rng.uniform(-0.2, 0.2, 9)])
        return A * A.transpose() + matrix.identity(3) / 2
    bodies = [RigidBody('base', joint=[x, y, z], rotations=[(3, psi), (2, theta), (1, phi)],
                        mass=SR.var('m0'), mass_center=[0, 0, SR(1) / 10], inertia=inertia())]
    for side, offset in (('left', SR(1) / 4), ('right', -SR(1) / 4)):
        parent = 'base'
        for k in (1, 2):
            a, b = SR.var(f'{side}_a{k}'), SR.var(f'{side}_b{k}')
            coordinates += [a, b]
            bodies.append(RigidBody(f'{side}{k}', parent=parent,
                                    joint=[0, offset, 0] if k == 1 else [0, 0, -SR(3) / 10],
                                    rotations=[(2, a), (1, b)], mass=1 + SR(k) / 4,
                                    mass_center=[SR(1) / 20, 0, -SR(3) / 20], inertia=inertia()))
            parent = f'{side}{k}'
    head = SR.var('head')
    coordinates.append(head)
    bodies.append(RigidBody('head', parent='base', joint=[0, 0, SR(3) / 10],
                            rotations=[(3, head)], mass=SR(1) / 2, inertia=inertia()))
    values[SR.var('m0')] = 3.0
    values[SR.var('g')] = 9.81
    return MechanicalSystem(bodies, coordinates,
                            force_function=UniformGravity([0, 0, -SR.var('g')]))


def test_jacobian_of_a_floating_base_tree_against_central_differences():
    values = {}
    S = floating_base_tree(values)
    f, jac = S.numerical_rhs(values, jacobian=True)
    assert jac.variables()[:6] == S.coordinates()[:6]
    for x in random_states(len(S.coordinates()), 2, 9):
        x[4] = 0.3 * x[4]          # away from the singular attitudes theta = +-pi/2
        assert relative_error(jac(0.0, x), central_differences(f, x)) < TOLERANCE


def test_jacobian_with_constraints_ltdl_against_central_differences():
    # a point on a circle x^2 + y^2 = 1 in gravity, with a damper on x
    x, y, m, g = SR.var('x y m g')
    S = MechanicalSystem([RigidBody('p', joint=[x, y, 0], mass=m)], [x, y],
                         force_function=UniformGravity([0, -g, 0]),
                         dissipation=SR.var('dx') ** 2 / 5, constraints=[x ** 2 + y ** 2 - 1])
    f, jac = S.numerical_rhs({m: 2.0, g: 9.81}, jacobian=True)
    assert f.form().solver() == 'ltdl'
    for state in ([0.6, 0.8, 0.8, -0.6], [0.0, -1.0, 1.5, 0.0]):
        assert relative_error(jac(0.0, state), central_differences(f, state)) < TOLERANCE


@pytest.mark.slow
@pytest.mark.parametrize('links', [20, 50])
def test_jacobian_of_a_long_chain_against_central_differences(links):
    desc = offset_chain(links)
    S = sage_chain(desc)
    f, jac = S.numerical_rhs({'g': 9.81}, jacobian=True)
    x = random_states(2 * links, 1, links)[0]
    assert relative_error(jac(0.0, x), central_differences(f, x)) < TOLERANCE


def test_compiled_in_parallel_units(monkeypatch, tmp_path):
    # large models are compiled as several translation units at once: the
    # split code computes what the Python evaluation of the graph does
    from sage_dynsym.numerics import compiler
    monkeypatch.setattr(compiler, 'PARALLEL_PARTS', 2)
    monkeypatch.setattr(compiler.os, 'cpu_count', lambda: 2)
    monkeypatch.setenv('SAGE_DYNSYM_CACHE', str(tmp_path))
    S = sage_chain(offset_chain(6))
    f, jac = S.numerical_rhs({'g': 9.81}, backend='c', jacobian=True)
    source = compiler.graph_c_source(*f.form().graph()[:2], 'test', pivots=f.form().graph()[2])
    assert source.count(compiler.UNIT) == 1
    python, jac_python = S.numerical_rhs({'g': 9.81}, backend='python', jacobian=True)
    for x in random_states(12, 2, seed=6):
        assert relative_error(f(0.0, x), python(0.0, x)) < 1e-13
        assert relative_error(jac(0.0, x), jac_python(0.0, x)) < 1e-13


def test_radau_takes_the_compiled_jacobian(monkeypatch):
    S, _, state, values = double_pendulum()
    calls = []
    original = rhs_module.StateJacobian.__call__

    def counted(self, t, x):
        calls.append(t)
        return original(self, t, x)
    monkeypatch.setattr(rhs_module.StateJacobian, '__call__', counted)
    initial = dict(zip(state, [1.0, -0.5, 0.0, 0.3]))
    radau = S.simulate(values, initial, 3, points=4, method='Radau', rtol=1e-10, atol=1e-12)
    assert calls
    reference = S.simulate(values, initial, 3, points=4, method='DOP853', rtol=1e-12,
                           atol=1e-13)
    assert np.max(np.abs(radau.states() - reference.states())) < 1e-7

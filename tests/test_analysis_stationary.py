"""Routh-Lyapunov stationary solutions: every solution annuls the
right-hand sides, second-variation conditions agree with eigenvalues of the
linearization, non-conserved integrals are rejected, Example 3 identities."""
import random

import numpy as np
import pytest
from sage.all import SR, QQ, RDF, var, cos, matrix, function

from sage_dynsym import load
from sage_dynsym.analysis import (stationary_solutions, stationary_motions,
                                  ModifiedRouthLyapunov, linearize)
from sage_dynsym.errors import AnalysisError


def euler_body():
    M1, M2, M3, A1, A2, A3 = var('M1 M2 M3 A1 A2 A3')
    X = [(A2 - A3) / (A2 * A3) * M2 * M3, (A3 - A1) / (A3 * A1) * M3 * M1,
         (A1 - A2) / (A1 * A2) * M1 * M2]
    H = (M1**2 / A1 + M2**2 / A2 + M3**2 / A3) / 2
    V = M1**2 + M2**2 + M3**2
    return [M1, M2, M3], [A1, A2, A3], X, H, V


def test_euler_permanent_rotations_annul_rhs_and_stability_matches_spectrum():
    x, A, X, H, V = euler_body()
    sols = stationary_solutions([H, V], x, equations=X)
    assert len(sols) == 4
    rng = random.Random(21)
    for s in sols:
        pt = s.point()
        assert [SR(e).subs(pt).simplify_full() for e in X] == [0, 0, 0]
        if all(v == 0 for v in pt.values()):
            continue
        free = [v for v in pt.values() if v != 0][0]
        axis = [i for i, v in enumerate(pt.values()) if v != 0][0]
        cpos = s.stability_conditions(positive=A)
        cneg = s.stability_conditions(positive=A, sign='negative')
        for _ in range(15):
            vals = {a: QQ(rng.uniform(0.5, 3)) for a in A}
            vals[free] = QQ(1)
            # a rotation about the largest or smallest axis is stable;
            # about the middle one the linearization has a positive root
            J = matrix(SR, [[e.diff(v) for v in x] for e in X]).subs(pt).subs(vals)
            ev = np.linalg.eigvals(J.change_ring(RDF).numpy())
            middle = sorted(vals[a] for a in A)[1] == vals[A[axis]]
            definite = all(float(SR(c).subs(vals)) > 0 for c in cpos) or \
                all(float(SR(c).subs(vals)) > 0 for c in cneg)
            assert definite == (not middle)
            assert (np.max(ev.real) > 1e-9) == middle


def test_non_conserved_integral_is_an_error():
    x, A, X, H, V = euler_body()
    with pytest.raises(AnalysisError, match="not conserved"):
        stationary_solutions([H, x[0]], x, equations=X)


def test_double_pendulum_equilibria_from_routh_free_lagrangian():
    from sage_dynsym import Lagrangian
    t1, t2, d1, d2, m, l, g = var('theta1 theta2 dtheta1 dtheta2 m l g')
    # equal masses and lengths (Merkin ch. 3)
    L = Lagrangian(m * l**2 * (d1**2 + d2**2 / 2 + d1 * d2 * cos(t1 - t2))
                   + m * g * l * (2 * cos(t1) + cos(t2)), [t1, t2])
    sols = stationary_motions(L)
    eqs = sols.equations()
    # exactly the four equilibria, each annulling the equations at rest
    from sage.all import pi
    assert sorted(str(s.point()) for s in sols) == sorted(
        str({t1: a, t2: b}) for a in (0, pi) for b in (0, pi))
    for s in sols:
        assert [SR(e).subs(s.point()) for e in eqs] == [0, 0]
        linearize(L, s.point())


def test_example3_invariant_manifolds_are_invariant():
    L = load('examples/spherical_pendulum.yaml').lagrangian()
    psi, theta = L.coordinates()
    R = L.routh([psi])
    MR = ModifiedRouthLyapunov(R)
    f = function('f')
    # each explicit solution solves the degeneracy ODE
    ode = MR.degeneracy_condition()
    for sol in MR.solve_degeneracy():
        lhs = ode.lhs().subs({f(theta).diff(theta): sol.rhs().diff(theta)})
        rhs = ode.rhs().subs({f(theta): sol.rhs()})
        assert (lhs - rhs).simplify_full() == 0
    # along the Routh equation the manifold dtheta = phi(theta) is invariant:
    # d/dt(dtheta - phi) = ddtheta - phi' dtheta vanishes on it
    dth = R.velocities()[0]
    ddth = R.accelerations()[0]
    (E,) = R.equations()
    acc = SR(E).solve(ddth)[0].rhs()
    for im in MR.invariant_manifolds():
        phi = im.rhs()
        expr = (acc - phi.diff(theta) * dth).subs({dth: phi})
        m, l, g, C, p = var('m l g _C p_psi')
        rng = random.Random(3)
        for _ in range(5):
            vals = {m: rng.uniform(0.5, 2), l: rng.uniform(0.5, 2), g: 9.81,
                    p: rng.uniform(0.1, 1), theta: rng.uniform(1.7, 2.5), C: 200.0}
            assert abs(complex(expr.subs(vals).n())) < 1e-8

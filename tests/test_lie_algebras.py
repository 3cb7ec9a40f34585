"""Poisson structures of the named Lie algebras and of users' algebras, their
Casimirs, and refused input (issue 12, must-shows 3 and 5).

Expected values:
- brackets written out here from the definitions (epsilon symbols: the
  minus Lie-Poisson bracket, Arnold, Mathematical Methods of Classical
  Mechanics, App. 2; Borisov & Mamaev, Rigid Body Dynamics, §1.6, the pencil
  {gamma_i, gamma_j} = -kappa eps_ijk M_k for e(3), so(4), so(3,1));
- Casimirs from the same sources: so(3) M^2; e(3) gamma^2, M.gamma;
  so(4) M^2 + p^2, M.p; so(3,1) M^2 - p^2, M.p; e(4) p^2 and |w|^2 with
  w_i = eps_ijkl M_jk p_l / 2; sl(2) h^2 + 4xy (Humphreys, Introduction to
  Lie Algebras, §22.3); Heisenberg z;
- the number of Casimirs is the corank of J at a random point (numpy rank);
- the Jacobi identity is checked here by its own loop.
"""
import itertools
import random

import numpy as np
import pytest
from sage.all import SR, QQ, var, matrix, PolynomialRing

from sage_dynsym.errors import ModelError
from sage_dynsym.lie import (LiePoissonSystem, PoissonStructure, lie_algebra,
                             poisson_structure, casimirs)


def eps(i, j, k):
    return (i - j) * (j - k) * (k - i) // 2


def pencil_matrix(M, g, kappa):
    n = 6
    J = matrix(SR, n, n)
    for i, j, k in itertools.product(range(3), repeat=3):
        J[i, j] -= eps(i, j, k) * M[k]
        J[i, 3 + j] -= eps(i, j, k) * g[k]
        J[3 + i, j] -= eps(i, j, k) * g[k]
        J[3 + i, 3 + j] -= kappa * eps(i, j, k) * M[k]
    return J


def jacobi_ok(J, x):
    n = len(x)
    for i, j, k in itertools.combinations(range(n), 3):
        e = sum(J[i, l] * J[j, k].diff(x[l]) + J[j, l] * J[k, i].diff(x[l]) +
                J[k, l] * J[i, j].diff(x[l]) for l in range(n))
        if not e.expand().is_zero():
            return False
    return True


def annihilates(J, x, C):
    grad = [C.diff(v) for v in x]
    return all(sum(grad[i] * J[i, j] for i in range(len(x))).expand().is_zero()
               for j in range(len(x)))


def corank(J, x, seed=0):
    rng = random.Random(seed)
    vals = {v: rng.uniform(-2, 2) for v in x}
    return len(x) - np.linalg.matrix_rank(np.array([[float(c.subs(vals)) for c in row]
                                                    for row in J.rows()]))


def same_span(found, expected, x):
    """The polynomials span the same space (ranks of coefficient matrices)."""
    R = PolynomialRing(QQ, [str(v) for v in x])
    polys = [R(SR(f)) for f in found + expected]
    monos = sorted({m for f in polys for m in f.monomials()})
    rows = [[f.monomial_coefficient(m) for m in monos] for f in polys]
    r_found = matrix(QQ, rows[:len(found)]).rank()
    r_exp = matrix(QQ, rows[len(found):]).rank()
    return r_found == r_exp == matrix(QQ, rows).rank()


M = list(var('M1 M2 M3'))
G = list(var('gamma1 gamma2 gamma3'))
P = list(var('p1 p2 p3'))


@pytest.mark.parametrize('name, kappa, second', [('e3', 0, G), ('so4', 1, P), ('so31', -1, P)])
def test_pencil_brackets_casimirs_and_corank(name, kappa, second):
    A = lie_algebra(name)
    x = M + second
    J = pencil_matrix(M, second, kappa)
    assert A.variables() == x
    assert A.matrix() == J
    assert jacobi_ok(J, x)
    found = casimirs(A)
    dot = sum(a * b for a, b in zip(M, second))
    norm = sum(b**2 for b in second) + kappa * sum(a**2 for a in M)
    assert len(found) == corank(J, x) == 2
    assert all(annihilates(J, x, C) for C in found)
    assert same_span(found, [dot, norm], x)


def test_so3():
    A = lie_algebra('so3')
    J = matrix(SR, 3, 3, lambda i, j: -sum(eps(i, j, k) * M[k] for k in range(3)))
    assert A.matrix() == J and jacobi_ok(J, M)
    found = casimirs(A)
    assert len(found) == corank(J, M) == 1
    assert same_span(found, [sum(m**2 for m in M)], M)


def test_e3_with_p_coordinates():
    assert lie_algebra('e3', variables=['M', 'p']).variables() == M + P
    assert lie_algebra('e(3)', variables=M + P).matrix() == pencil_matrix(M, P, 0)


def test_e4_casimirs_and_its_e3_subalgebra():
    A = lie_algebra('e4')
    x = A.variables()
    J = A.matrix()
    assert jacobi_ok(J, x)
    Mv = {(i, j): v for (i, j), v in zip([(1, 2), (1, 3), (1, 4), (2, 3), (2, 4), (3, 4)], x[:6])}
    p = x[6:]

    def Mij(i, j):
        return Mv[i, j] if i < j else (-Mv[j, i] if i > j else 0)

    def eps4(*idx):
        perm = list(idx)
        if len(set(perm)) < 4:
            return 0
        sign = 1
        for a in range(4):
            for b in range(a + 1, 4):
                if perm[a] > perm[b]:
                    sign = -sign
        return sign
    w = [sum(eps4(i, j, k, l) * Mij(j, k) * p[l - 1] for j in range(1, 5) for k in range(1, 5)
             for l in range(1, 5)) / 2 for i in range(1, 5)]
    C1 = sum(v**2 for v in p)
    C2 = sum(v**2 for v in w)
    assert annihilates(J, x, C1) and annihilates(J, x, C2)
    found = casimirs(A, degree=4)
    assert len(found) == corank(J, x) == 2
    assert all(annihilates(J, x, C) for C in found)
    assert same_span(found + [found[0]**2], [C1, C2, C1**2], x)
    # M1 = M23, M2 = -M13, M3 = M12 and p1..p3 satisfy the brackets of e(3)
    e3 = pencil_matrix(M, G, 0)
    sub = [Mv[2, 3], -Mv[1, 3], Mv[1, 2]] + p[:3]
    index = {v: k for k, v in enumerate(x)}
    for a in range(6):
        for b in range(6):
            def coord(e):   # the e(4) coordinate (with sign) behind sub[a]
                return (-1, index[-e]) if (-e) in index else (1, index[e])
            sa, ia = coord(sub[a])
            sb, ib = coord(sub[b])
            expected = e3[a, b].subs(dict(zip(M + G, sub)))
            assert (sa * sb * J[ia, ib] - expected).expand().is_zero(), (a, b)


def test_user_structure_constants_sl2():
    h, X, Y = var('h x y')
    A = poisson_structure({(h, X): {X: 2}, (h, Y): {Y: -2}, (X, Y): {h: 1}}, [h, X, Y])
    assert jacobi_ok(A.matrix(), [h, X, Y])
    found = casimirs(A)
    assert len(found) == 1 and same_span(found, [h**2 + 4 * X * Y], [h, X, Y])
    # the nested-list form gives the same matrix
    c = [[[0] * 3 for _ in range(3)] for _ in range(3)]
    c[0][1][1], c[1][0][1] = 2, -2
    c[0][2][2], c[2][0][2] = -2, 2
    c[1][2][0], c[2][1][0] = 1, -1
    assert poisson_structure(c, [h, X, Y]).matrix() == A.matrix()


def test_user_heisenberg_and_a_parameter_family():
    X, Y, Z = var('x y z')
    H = poisson_structure({(X, Y): {Z: 1}}, [X, Y, Z])
    assert casimirs(H) == [Z]
    # the pencil as a user's Poisson matrix with a parameter kappa
    kappa = var('kappa')
    A = PoissonStructure(pencil_matrix(M, P, kappa), M + P)
    found = casimirs(A)
    expected = [sum(a * b for a, b in zip(M, P)),
                sum(b**2 for b in P) + kappa * sum(a**2 for a in M)]
    assert len(found) == 2 and all(annihilates(A.matrix(), M + P, C) for C in found)
    for C in expected:     # each expected Casimir is a multiple of a found one
        assert any(((C / f).simplify_full()).is_constant() or
                   not set((C / f).simplify_full().variables()) & set(M + P) for f in found)


def test_non_poisson_matrices_are_refused():
    X, Y, Z = var('x y z')
    with pytest.raises(ModelError, match="Jacobi identity"):
        PoissonStructure([[0, X, 0], [-X, 0, Y], [0, -Y, 0]], [X, Y, Z])
    with pytest.raises(ModelError, match="not skew-symmetric"):
        PoissonStructure([[0, Z, 0], [Z, 0, 0], [0, 0, 0]], [X, Y, Z])
    with pytest.raises(ModelError, match="not skew-symmetric"):
        poisson_structure({(X, Y): {Z: 1}, (Y, X): {Z: 1}}, [X, Y, Z])
    # structure constants breaking Jacobi: [x, y] = x, [y, z] = y, [x, z] = 0
    with pytest.raises(ModelError, match="Jacobi identity"):
        poisson_structure({(X, Y): {X: 1}, (Y, Z): {Y: 1}}, [X, Y, Z])


def test_bad_input_errors():
    M1, M2, M3, g1 = var('M1 M2 M3 gamma1')
    with pytest.raises(ModelError, match="unknown Lie algebra 'se3'.*so3, e3, so4, so31, e4"):
        LiePoissonSystem('se3', M1**2)
    with pytest.raises(ModelError, match="gamma1, which is not a variable of so3"):
        LiePoissonSystem('so3', M1**2 + g1)
    with pytest.raises(ModelError, match="undeclared symbol k"):
        LiePoissonSystem('so3', M1**2 + var('k') * M2, parameters=[var('A')])
    with pytest.raises(ModelError, match="e3 has 6 coordinates.*got 3 variables"):
        LiePoissonSystem('e3', M1**2, variables=[M1, M2, M3])
    with pytest.raises(ModelError, match="so4 has 6 coordinates.*got 7 variables"):
        LiePoissonSystem('so4', M1**2, variables=var('a b c d e f h'))
    X, Y, Z = var('x y z')
    with pytest.raises(ModelError, match="Jacobi identity"):
        LiePoissonSystem([[0, X, 0], [-X, 0, Y], [0, -Y, 0]], X, variables=[X, Y, Z])
    with pytest.raises(ModelError, match="square 3x3"):
        LiePoissonSystem([[0, X], [-X, 0]], X, variables=[X, Y, Z])
    # a declared parameter is fine, also with a coordinate-like name
    S = LiePoissonSystem('so3', M1**2 + g1 * M2, parameters=[g1])
    assert S.parameters() == [g1]

"""Routh-Hurwitz, Liénard-Chipart and the real-negative-roots criterion,
checked against numerically computed roots (numpy) at random points."""
import random

import numpy as np
import pytest
from sage.all import SR, QQ, PolynomialRing, expand, matrix, var

from sage_dynsym.analysis.hurwitz import (
    hurwitz_conditions, lienard_chipart_conditions, hurwitz_determinants,
    hurwitz_matrix, real_negative_roots_conditions, conservative_stability_conditions,
    simplify_conditions)
from sage_dynsym.errors import AnalysisError

lam = SR.var('lam')


def holds(conditions, point):
    return all(float(SR(c).subs(point)) > 0 for c in conditions)


def roots(poly, point, var=lam):
    p = SR(poly).subs(point)
    coeffs = [float(p.coefficient(var, k)) for k in range(p.degree(var), -1, -1)]
    return np.roots(coeffs)


def hurwitz_numerically(poly, point):
    r = roots(poly, point)
    return bool(np.all(r.real < -1e-9))


def generic(n):
    a = [SR.var('a%d' % i) for i in range(n + 1)]
    return sum(a[i] * lam ** (n - i) for i in range(n + 1)), a


@pytest.mark.parametrize("n", [2, 3, 4, 5, 6])
def test_generic_polynomials_against_roots(n):
    poly, a = generic(n)
    hc = hurwitz_conditions(poly, lam)
    lc = lienard_chipart_conditions(poly, lam)
    rng = random.Random(n)
    agree = {True: 0, False: 0}
    for _ in range(150):
        # random roots: mostly stable, sometimes not, then expand
        rs = [complex(-rng.uniform(0.05, 3) if rng.random() < 0.85 else rng.uniform(0.05, 2), 0)
              for _ in range(n)]
        if n >= 2 and rng.random() < 0.5:
            re, im = rs[0].real, rng.uniform(0.1, 3)
            rs[0], rs[1] = complex(re, im), complex(re, -im)
        c = np.poly(rs).real * rng.uniform(0.5, 2)
        point = {a[i]: QQ(float(c[i])) for i in range(n + 1)}
        truth = hurwitz_numerically(poly, point)
        assert holds(hc, point) == truth
        assert holds(lc, point) == truth
        agree[truth] += 1
    assert agree[True] > 10 and agree[False] > 10


def test_known_roots():
    # (lam+1)(lam+2)(lam+3): stable; (lam-1)(lam^2+4 lam+5): not (Gantmacher)
    assert hurwitz_conditions(expand((lam + 1) * (lam + 2) * (lam + 3)), lam) == []
    assert lienard_chipart_conditions(expand((lam - 1) * (lam**2 + 4 * lam + 5)), lam) == [-1]
    # (lam^2 + a lam + 1)(lam + 1): stable iff a > 0
    a = var('a')
    conds = hurwitz_conditions(expand((lam**2 + a * lam + 1) * (lam + 1)), lam)
    for av in [QQ(-2), QQ(-1) / 3, QQ(1) / 10, QQ(5)]:
        assert holds(conds, {a: av}) == (av > 0)


def test_determinants_equal_minors_of_hurwitz_matrix():
    poly, a = generic(6)
    H = hurwitz_matrix(poly, lam)
    D = hurwitz_determinants(poly, lam)
    for k in range(1, 7):
        assert (D[k - 1] - H[:k, :k].det()).expand() == 0
    # unexpanded determinants (tiny budget) are the same polynomials
    E = hurwitz_determinants(poly, lam, budget=1)
    for k in range(1, 7):
        assert (E[k - 1] - D[k - 1]).expand() == 0


def test_polynomial_ring_input_and_denominators():
    R = PolynomialRing(QQ, 'm,c,k,lam')
    m, c, k, l = R.gens()
    assert hurwitz_conditions(m * l**2 + c * l + k, 'lam') == [SR('m'), SR('c'), SR('k')]
    mm, cc = var('m c')
    # denominators are cleared (here m > 0 declared)
    assert hurwitz_conditions(lam**2 + cc / mm * lam + 1, lam, positive=[mm]) == [cc]


def test_chain_damped_is_stable_at_random_positive_points():
    # 2-mass chain with positive parameters: conditions hold at random points
    m1, m2, k1, k2, k3, c1, c2, c3 = var('m1 m2 k1 k2 k3 c1 c2 c3')
    M = matrix([[m1, 0], [0, m2]])
    C = matrix([[c1 + c2, -c2], [-c2, c2 + c3]])
    K = matrix([[k1 + k2, -k2], [-k2, k2 + k3]])
    p = (M * lam**2 + C * lam + K).det().expand()
    params = [m1, m2, k1, k2, k3, c1, c2, c3]
    conds = lienard_chipart_conditions(p, lam, positive=params)
    rng = random.Random(7)
    for _ in range(30):
        pt = {v: QQ(rng.uniform(0.1, 5)) for v in params}
        assert holds(conds, pt) and hurwitz_numerically(p, pt)
    # with a negative damper the verdict follows the roots
    for _ in range(30):
        pt = {v: QQ(rng.uniform(0.1, 5)) for v in params}
        pt[c2] = QQ(-rng.uniform(0.1, 5))
        all_conds = lienard_chipart_conditions(p, lam)
        assert holds(all_conds, pt) == hurwitz_numerically(p, pt)


@pytest.mark.parametrize("m", [2, 3, 4])
def test_real_negative_roots_against_numpy(m):
    mu = SR.var('mu')
    b = [SR.var('b%d' % i) for i in range(m + 1)]
    h = sum(b[i] * mu ** (m - i) for i in range(m + 1))
    conds = real_negative_roots_conditions(h, mu)
    rng = random.Random(100 + m)
    seen = {True: 0, False: 0}
    for _ in range(100):
        rs = [-rng.uniform(0.1, 4) for _ in range(m)]
        if rng.random() < 0.4:
            rs[0] = complex(rs[0], rng.uniform(0.2, 2))
            rs[1] = rs[0].conjugate()
        if rng.random() < 0.2:
            rs[-1] = rng.uniform(0.1, 2)
        c = np.poly(rs).real
        pt = {b[i]: QQ(float(c[i])) for i in range(m + 1)}
        r = roots(h, pt, mu)
        truth = bool(np.all(np.abs(r.imag) < 1e-9) and np.all(r.real < 0))
        assert holds(conds, pt) == truth
        seen[truth] += 1
    assert seen[True] > 5 and seen[False] > 5


def test_conservative_gyroscopic_against_roots():
    g, k1, k2 = var('g k1 k2')
    p = matrix([[lam**2 + k1, -g * lam], [g * lam, lam**2 + k2]]).det()
    conds = conservative_stability_conditions(p, lam)
    rng = random.Random(3)
    for _ in range(100):
        pt = {g: QQ(rng.uniform(0, 4)), k1: QQ(rng.uniform(-3, 3)), k2: QQ(rng.uniform(-3, 3))}
        # lam^2 = mu: the roots in mu must be real, negative and simple
        q = SR(p).subs(pt).expand()
        h = [float(q.coefficient(lam, 4)), float(q.coefficient(lam, 2)), float(q.coefficient(lam, 0))]
        r = np.roots(h)
        truth = bool(np.all(np.abs(r.imag) < 1e-12) and np.all(r.real < 0)
                     and abs(r[0] - r[1]) > 1e-9)
        assert holds(conds, pt) == truth


def test_bad_input():
    with pytest.raises(AnalysisError):
        hurwitz_conditions(lam**2 + SR('sin(x)'), lam)
    with pytest.raises(AnalysisError):
        hurwitz_conditions(1 / lam + 1, lam)
    with pytest.raises(AnalysisError):
        conservative_stability_conditions(lam**2 + lam + 1, lam)
    # an even polynomial is never Hurwitz: said, with the way to go
    k, m = var('k m')
    for even in (lam**2 + 1, m * lam**4 + k * lam**2 + 1, lam**6 - lam**2):
        with pytest.raises(AnalysisError, match="conservative_stability_conditions"):
            hurwitz_conditions(even, lam)


def test_simplify_conditions_keeps_equivalence():
    a, b, m = var('a b m')
    conds = [m**2 * (a - b), 2 * m * a, a * b]
    simple = simplify_conditions(conds, positive=[m])
    rng = random.Random(5)
    for _ in range(50):
        pt = {a: QQ(rng.uniform(-2, 2)), b: QQ(rng.uniform(-2, 2)), m: QQ(rng.uniform(0.1, 2))}
        assert holds(simple, pt) == holds(conds, pt)

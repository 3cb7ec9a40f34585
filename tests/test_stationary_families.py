"""
Implicit families of stationary solutions made explicit by their free
variables (sage_dynsym.algebra.solving._branches), against independent
computations.

Kirchhoff's equations in Clebsch's case, H = (sum a_i M_i^2 + theta a_j a_k
p_i^2)/2 (Clebsch's condition holds for b_i = theta a_j a_k; Borisov and
Mamaev, Rigid Body Dynamics, §2.5), with the Casimirs p.p and M.p: besides the
rest point and the rotations about the axes, the stationary set has a
3-parameter family. By hand, its equations a_i M_i^2 = theta a_j a_k p_i^2 and
M_i M_j a_i a_j = theta a1 a2 a3 p_i p_j give two branches

    M_i = s sqrt(theta a1 a2 a3) p_i / a_i,   s = +-1,

real exactly where theta a1 a2 a3 > 0, on which K = H + l1 p.p + l2 M.p is
stationary with l1 = 0, l2 = -s sqrt(theta a1 a2 a3). The gradient of K is
written here with NumPy.
"""
import numpy as np
import pytest

from sage.all import SR, var, vector
from sage_dynsym.analysis.stationary import stationary_solutions

M = list(var('M1 M2 M3'))
P = list(var('p1 p2 p3'))
a1, a2, a3, theta = var('a1 a2 a3 theta')
A = [a1, a2, a3]


def clebsch():
    b = [theta * a2 * a3, theta * a1 * a3, theta * a1 * a2]
    H = sum(A[i] * M[i]**2 + b[i] * P[i]**2 for i in range(3)) / 2
    Mv, pv = vector(SR, M), vector(SR, P)
    w = vector(SR, [H.diff(x) for x in M])
    u = vector(SR, [H.diff(x) for x in P])
    X = list(Mv.cross_product(w) + pv.cross_product(u)) + list(pv.cross_product(w))
    return stationary_solutions([H, pv * pv, Mv * pv], M + P, equations=X)


def gradient_K(a, th, m, p, l1, l2):
    """dK/dM and dK/dp for K = H + l1 p.p + l2 M.p (by hand)."""
    a = np.asarray(a, float)
    b = th * np.array([a[1] * a[2], a[0] * a[2], a[0] * a[1]])
    return np.concatenate([a * m + l2 * p, b * p + 2 * l1 * p + l2 * m])


@pytest.fixture(scope='module')
def families():
    return [s for s in clebsch() if s.dimension() == 3]


def test_clebsch_family_is_explicit_with_its_reality_condition(families):
    # two branches, explicit, each real exactly where theta a1 a2 a3 > 0
    assert len(families) == 2 and all(s.is_explicit() for s in families)
    rng = np.random.default_rng(2)
    signs = set()
    for _ in range(8):
        # exact values: the conditions are decided exactly at them
        a = rng.integers(1, 4, size=3) * rng.choice([-1, 1], size=3)
        th = int(rng.integers(1, 3) * rng.choice([-1, 1]))
        m = rng.integers(1, 4, size=3)
        values = {x: SR(int(v)) for x, v in zip(A + [theta] + M, list(a) + [th] + list(m))}
        for s in families:
            # the conditions at the family's point over these M (p real or not)
            at = {**values, **{x: SR(s.point()[x]).subs(values) for x in P}}
            holds = all(bool(SR(c).subs(at)) for c in s.conditions())
            assert holds == (th * np.prod(a) > 0)
        signs.add(bool(th * np.prod(a) > 0))
        if th * np.prod(a) <= 0:
            continue
        found = []
        for s in families:
            p = np.array([float(SR(s.point()[x]).subs(values)) for x in P])
            mult = s.multipliers()
            l1, l2 = (float(SR(mult[v]).subs(values)) for v in sorted(mult, key=str))
            assert np.allclose(gradient_K(a, th, m, p, l1, l2), 0, atol=1e-9)
            found.append(p)
        # the hand formula's two branches, p_i = s a_i M_i / sqrt(theta a1 a2 a3)
        k = np.sqrt(th * np.prod(a))
        for sign in (1, -1):
            assert sum(np.allclose(p, sign * a * m / k) for p in found) == 1
    assert signs == {True, False}      # both sides of theta a1 a2 a3 = 0 were sampled


@pytest.mark.slow
def test_clebsch_family_stability_is_a_verdict(families):
    # never an exception: a verdict with its region (here the first
    # approximation does not decide on the family)
    for s in families:
        v = s.stability()
        assert v.verdict() in ('undecided', 'stable', 'unstable', 'depends on the parameters',
                               'stable in first approximation')
        for case in v.cases() or [v]:
            assert case.region() is None or isinstance(case.region(), list)

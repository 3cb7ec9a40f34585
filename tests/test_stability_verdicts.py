"""Verdicts for M q'' + (D + 2G) q' + (K + P) q = 0: each classical result
against its literature value, and every verdict region against numpy
eigenvalues of the state matrix at random parameter points."""
import random

import numpy as np
import pytest
from sage.all import SR, QQ, matrix, identity_matrix, zero_matrix, diagonal_matrix, var, sqrt

from sage_dynsym.analysis import kelvin_chetaev, small_damping_limit, spectrum_regions

J = matrix([[0, 1], [-1, 0]])
Z = zero_matrix(SR, 2)
I2 = identity_matrix(SR, 2)


def numeric_class(M, S, W, point, tol=1e-7):
    """'asymptotic', 'marginal' or 'unstable' from the eigenvalues of the
    state matrix; None when too close to a boundary to tell."""
    M, S, W = (X.subs(point).numpy(dtype=float) for X in (M, S, W))
    n = M.shape[0]
    Mi = np.linalg.inv(M)
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-Mi @ W, -Mi @ S]])
    top = max(np.linalg.eigvals(A).real)
    if top < -1e-5:
        return 'asymptotic'
    if top > 1e-5:
        return 'unstable'
    return 'marginal' if abs(top) < tol else None


EXPECTED = {'asymptotically stable': 'asymptotic', 'stable': 'marginal',
            'stable in first approximation': 'marginal', 'unstable': 'unstable'}


def check_against_eigenvalues(v, M, D, G, K, P, sample, n=60, seed=0):
    rng = random.Random(seed)
    seen = set()
    for _ in range(n):
        point = sample(rng)
        truth = numeric_class(M, D + 2 * G, K + P, point)
        verdict = v.at(point)
        if truth is None or verdict is None:
            continue
        assert EXPECTED[verdict] == truth, (point, verdict, truth)
        seen.add(verdict)
    return seen


# -- Ziegler's column ---------------------------------------------------------
# Two rigid rods of length l, springs k at both joints, masses 2m (middle)
# and m (free end), follower load P at the end (Ziegler 1952; Kirillov 2013,
# ch. 1): M = m l^2 [[3, 1], [1, 1]], K + P = [[2k - Pl, Pl - k], [-k, k]].
P_, k, l, m, d = var('P k l m d')
ZM = m * l**2 * matrix([[3, 1], [1, 1]])
ZW = matrix([[2 * k - P_ * l, P_ * l - k], [-k, k]])
ZK, ZP = (ZW + ZW.transpose()) / 2, (ZW - ZW.transpose()) / 2
ZD0 = matrix([[2, -1], [-1, 1]])        # equal dampers d at both joints


def test_ziegler_flutter_load_undamped():
    v = kelvin_chetaev(ZM, Z, Z, ZK, ZP, positive=[k, l, m])
    assert [c.verdict() for c in v.cases()] == ['stable in first approximation', 'unstable']
    # Ziegler (1952): P_cr = (7/2 - sqrt(2)) k/l
    (crit,) = v.critical_values(P_)
    assert bool((crit - (QQ(7) / 2 - sqrt(2)) * k / l).simplify_full() == 0)
    # numpy: on the imaginary axis just below, a root with Re > 0 just above
    pcr = 3.5 - 2**0.5
    values = {k: 1, l: 1, m: 1}
    assert numeric_class(ZM, Z, ZW, {**values, P_: QQ(pcr - 1e-3)}) == 'marginal'
    assert numeric_class(ZM, Z, ZW, {**values, P_: QQ(pcr + 1e-3)}) == 'unstable'
    assert 'flutter' in v.boundaries()
    seen = check_against_eigenvalues(
        v, ZM, Z, Z, ZK, ZP, lambda r: {P_: QQ(r.uniform(-3, 7)), k: QQ(r.uniform(0.2, 2)),
                                        l: QQ(r.uniform(0.2, 2)), m: QQ(r.uniform(0.2, 2))})
    assert seen == {'stable in first approximation', 'unstable'}


def test_ziegler_destabilization_paradox():
    lim = small_damping_limit(ZM, ZD0, Z, ZK, ZP, positive=[k, l, m])
    crit = lim.critical_values(P_)
    # Ziegler (1952): with equal small dampers the critical load tends to
    # 41/28 k/l (about 1.46 k/l), not to the undamped 2.09 k/l
    assert crit['small damping limit'] == [QQ(41) / 28 * k / l]
    assert len(crit['undamped']) == 1
    # independently: numpy bisection of the critical load at tiny damping
    values = {k: 1, l: 1, m: 1}

    def top(p, dd):
        pt = {**values, P_: p}
        M, S, W = (X.subs(pt).numpy(dtype=float) for X in (ZM, dd * ZD0, ZW))
        Mi = np.linalg.inv(M)
        A = np.block([[np.zeros((2, 2)), np.eye(2)], [-Mi @ W, -Mi @ S]])
        return max(np.linalg.eigvals(A).real)

    lo, hi = 0.5, 2.0
    for _ in range(40):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if top(mid, 1e-4) < 0 else (lo, mid)
    assert abs(lo - 41 / 28) < 1e-3


def test_ziegler_damped_regions_against_eigenvalues():
    v = kelvin_chetaev(ZM, d * ZD0, Z, ZK, ZP, positive=[k, l, m, d])
    seen = check_against_eigenvalues(
        v, ZM, d * ZD0, Z, ZK, ZP,
        lambda r: {P_: QQ(r.uniform(-1, 5)), k: 1, l: 1, m: 1, d: QQ(r.uniform(0.01, 1))},
        n=80, seed=3)
    assert seen == {'asymptotically stable', 'unstable'}


# -- gyroscopic forces (Thomson-Tait-Chetaev) ---------------------------------

def test_gyroscopic_systems_every_sign_of_the_potential():
    # x'' + 2g y' + k1 x = 0, y'' - 2g x' + k2 y = 0 (Merkin, ch. 6): stable
    # for K > 0 (Kelvin), stabilized for k1, k2 < 0 when 2|g| > sqrt(-k1) +
    # sqrt(-k2), unstable for an odd degree of instability (k1 k2 < 0)
    g, k1, k2 = var('g k1 k2')
    K = diagonal_matrix([k1, k2])
    v = kelvin_chetaev(I2, Z, g * J, K)
    verdicts = [c.verdict() for c in v.cases()]
    assert verdicts == ['stable', 'stable in first approximation', 'unstable']
    seen = check_against_eigenvalues(
        v, I2, Z, g * J, K, Z,
        lambda r: {g: QQ(r.uniform(-3, 3)), k1: QQ(r.uniform(-2, 2)), k2: QQ(r.uniform(-2, 2))},
        n=150, seed=4)
    assert seen == set(verdicts)
    rng = random.Random(5)
    for _ in range(40):
        pt = {g: QQ(rng.uniform(0, 3)), k1: -QQ(rng.uniform(0.1, 2)), k2: -QQ(rng.uniform(0.1, 2))}
        stabilized = 2 * float(pt[g]) > float(-pt[k1])**0.5 + float(-pt[k2])**0.5
        assert (v.at(pt) == 'stable in first approximation') == stabilized
        pt[k2] = -pt[k2]                 # odd degree of instability: never
        assert v.at(pt) == 'unstable'


def test_odd_degree_of_instability_with_any_gyroscopic_and_dissipative_forces():
    g, c, a, b = var('g c a b')
    v = kelvin_chetaev(I2, diagonal_matrix([c, 0]), g * J, diagonal_matrix([-a, b]),
                       positive=[a, b, c])
    assert v.verdict() == 'unstable' and '3rd theorem' in v.reason()


def test_complete_dissipation_destroys_gyroscopic_stabilization():
    g, c = var('g c')
    v = kelvin_chetaev(I2, c * I2, g * J, -I2, positive=[c, g])
    assert v.verdict() == 'unstable' and '4th theorem' in v.reason()
    # while without damping the same system is stabilized for g > 1
    assert kelvin_chetaev(I2, Z, g * J, -I2, positive=[g]).at({g: 2}) == \
        'stable in first approximation'


# -- circulatory forces ---------------------------------------------------------

def test_circulatory_with_damping_against_eigenvalues():
    dd, kk, p = var('dd kk p')
    K, P, D = diagonal_matrix([1, kk]), p * J, dd * I2
    v = kelvin_chetaev(I2, D, Z, K, P, positive=[dd])
    seen = check_against_eigenvalues(
        v, I2, D, Z, K, P,
        lambda r: {dd: QQ(r.uniform(0.01, 2)), kk: QQ(r.uniform(-1, 3)), p: QQ(r.uniform(-2, 2))},
        n=100, seed=6)
    assert seen == {'asymptotically stable', 'unstable'}
    # undamped: flutter where the discriminant vanishes, divergence at k + p^2 = 0
    w = kelvin_chetaev(I2, Z, Z, K, P)
    assert set(w.boundaries()) == {'flutter', 'divergence'}
    seen = check_against_eigenvalues(
        w, I2, Z, Z, K, P,
        lambda r: {kk: QQ(r.uniform(-1, 3)), p: QQ(r.uniform(-1, 1))}, n=100, seed=7)
    assert seen == {'stable in first approximation', 'unstable'}


def test_gyroscopic_and_circulatory_without_damping_are_unstable():
    # only where g p = 0 can the roots be on the imaginary axis
    g, p = var('g p')
    v = kelvin_chetaev(I2, Z, g * J, diagonal_matrix([1, 2]), p * J)
    rng = random.Random(8)
    for _ in range(30):
        pt = {g: QQ(rng.uniform(0.1, 2)), p: QQ(rng.uniform(0.1, 2))}
        assert v.at(pt) == 'unstable'
        assert numeric_class(I2, 2 * g * J, diagonal_matrix([1, 2]) + p * J, pt) == 'unstable'
    assert v.at({g: 1, p: 0}) == 'stable in first approximation'


# -- partial dissipation, zero roots ------------------------------------------------

def test_partial_dissipation_and_zero_roots():
    c, k1, k2 = var('c k1 k2')
    v = kelvin_chetaev(I2, diagonal_matrix([c, 0]), Z, diagonal_matrix([k1, k2]),
                       positive=[c])
    assert [x.verdict() for x in v.cases()] == ['stable', 'unstable']
    check_against_eigenvalues(
        v, I2, diagonal_matrix([c, 0]), Z, diagonal_matrix([k1, k2]), Z,
        lambda r: {c: QQ(r.uniform(0.1, 2)), k1: QQ(r.uniform(-2, 2)), k2: QQ(r.uniform(-2, 2))},
        n=60, seed=9)
    # a free particle: a double zero root with one eigenvector (x = a + b t)
    free = kelvin_chetaev(matrix([[1]]), matrix([[0]]), matrix([[0]]), matrix([[0]]))
    assert free.verdict() == 'undecided' and 'not semisimple' in free.reason()
    # with damping the zero root is simple: stable, not asymptotically
    damped = kelvin_chetaev(matrix([[1]]), matrix([[c]]), matrix([[0]]), matrix([[0]]),
                            positive=[c])
    assert damped.verdict() == 'stable in first approximation'


def test_spectrum_regions_against_roots():
    # a polynomial with a symmetric factor and a damped one
    lam, a, b = var('lam a b')
    S = spectrum_regions(((lam**2 + a * lam - 1) * (lam**4 + b * lam**2 + 1)).expand(), lam)
    assert S.symmetric_degree() == 4
    rng = random.Random(10)
    for _ in range(50):
        pt = {a: QQ(rng.uniform(-1, 3)), b: QQ(rng.uniform(-3, 3))}
        roots = np.roots([1, float(pt[a]), -1])
        # lam^2 + a lam - 1 always has a positive root: never stable
        assert max(roots.real) > 0
        assert not any(all(bool(r.subs(pt)) for r in alt) for alt in S.marginal() or [])


def test_bad_input():
    from sage_dynsym.errors import AnalysisError
    with pytest.raises(AnalysisError, match="expected 2x2"):
        kelvin_chetaev(I2, Z, Z, matrix([[1]]))
    with pytest.raises(AnalysisError, match="zero"):
        small_damping_limit(I2, Z, Z, I2)

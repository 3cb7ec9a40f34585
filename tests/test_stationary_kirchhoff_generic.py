"""
The stationary set of a generic Kirchhoff Hamiltonian (B != 0), at rational
parameter values, against an independent construction with NumPy.

H = (M.A M)/2 + M.B p + (p.C p)/2 on e(3)*, A diagonal, B and C symmetric
(C diagonal here), with the Casimirs p.p and M.p: a point is stationary for
K = H + l1 p.p + l2 M.p exactly where

    A M + (B + l2 I) p = 0,   (B + l2 I) M + (C + 2 l1 I) p = 0.

With A invertible, M = -A^{-1} (B + l2 I) p and p is a kernel vector of
C + 2 l1 I - (B + l2 I) A^{-1} (B + l2 I): for every l2, the l1 are minus half
the eigenvalues of S = C - (B + l2 I) A^{-1} (B + l2 I) (symmetric: real) and
p their eigenvectors. Every such point must lie on a solution returned, with
the multipliers it reports; every returned point must annul the equations of
motion (by substitution).
"""
import numpy as np
import pytest

from sage.all import SR, var, vector, matrix

from sage_dynsym.analysis.stationary import stationary_solutions

M = list(var('M1 M2 M3'))
P = list(var('p1 p2 p3'))
A = np.diag([3.0, 5.0, 7.0])
B = np.array([[1, 2, -1], [2, 3, 1], [-1, 1, 2]], float)
C = np.diag([11.0, 13.0, 17.0])


def kirchhoff():
    Mv, pv = vector(SR, M), vector(SR, P)
    As, Bs, Cs = (matrix(SR, [[SR(int(x)) for x in row] for row in X]) for X in (A, B, C))
    H = (Mv * As * Mv + 2 * Mv * Bs * pv + pv * Cs * pv) / 2
    w = vector(SR, [H.diff(x) for x in M])
    u = vector(SR, [H.diff(x) for x in P])
    X = list(Mv.cross_product(w) + pv.cross_product(u)) + list(pv.cross_product(w))
    return [H, pv * pv, Mv * pv], X


def independent_points(l2_values):
    """(M, p, l1, l2) on the stationary set, from the eigenproblem above."""
    Ainv = np.linalg.inv(A)
    for l2 in l2_values:
        Bl = B + l2 * np.eye(3)
        vals, vecs = np.linalg.eigh(C - Bl @ Ainv @ Bl)
        for k in range(3):
            p = vecs[:, k]
            yield -Ainv @ Bl @ p, p, -vals[k] / 2, l2


@pytest.mark.slow
def test_generic_kirchhoff_stationary_set():
    integrals, X = kirchhoff()
    sols = stationary_solutions(integrals, M + P, equations=X)
    # every returned point annuls the equations of motion: the explicit
    # ones by exact substitution
    explicit = [s for s in sols if s.is_explicit()]
    for s in explicit:
        assert all(SR(e).subs(s.point()).simplify_rational() == 0 for e in X)
    # the independent points: each lies on a returned implicit family (its
    # equations vanish there) whose multipliers are the ones of the point
    # (the part p3 = 0, where the family's multipliers are not defined, is
    # listed apart)
    families = [s for s in sols if not s.is_explicit() and not SR(s.point()[P[2]]).is_zero()]
    assert families
    found = 0
    for m, p, l1, l2 in independent_points([-2.0, -0.5, 0.0, 0.7, 3.0]):
        if abs(p[2]) < 1e-3:
            continue    # the family holds where p3 != 0 (its multipliers divide by p3)
        at = dict(zip(M + P, [float(x) for x in np.concatenate([m, p])]))
        # the construction itself annuls the equations of motion
        assert all(abs(float(SR(e).subs(at))) < 1e-8 for e in X)
        for s in families:
            if all(abs(float(SR(e).subs(at))) < 1e-8 for e in s.equations()):
                mult = {str(k): float(SR(v).subs(at)) for k, v in s.multipliers().items()}
                assert mult['lambda1'] == pytest.approx(l1, rel=1e-6, abs=1e-6)
                assert mult['lambda2'] == pytest.approx(l2, rel=1e-6, abs=1e-6)
                found += 1
                break
        else:
            pytest.fail(f"the stationary point {at} lies on no solution returned")
    assert found == 14
    # and the rest point M = p = 0 is returned
    zero = {x: 0 for x in M + P}
    assert any(s.is_explicit() and all(SR(v).subs(zero) == 0 for v in s.point().values())
               for s in sols)

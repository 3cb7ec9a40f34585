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

from sage.all import SR, var, vector, matrix, identity_matrix

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


# Brun's problem: a rigid body with a fixed point in a quadratic potential on
# e(3)* (p the unit vertical), H = (M.A M)/2 + epsilon/2 (p.A^{-1} p), with the
# extra integral F = (M.M)/2 - epsilon/(2 a1 a2 a3) (p.A p) (the Clebsch case
# of Kirchhoff's equations, c_i = epsilon/a_i; Borisov & Mamaev, Rigid Body
# Dynamics, 2018). Its stationary set on the level M.p = 0, p.p = 1, with
# symbolic a_i and epsilon, specialized at rational values, against the
# direct solve at those values and against the stationarity equations.

a = list(var('a1 a2 a3'))
epsilon = var('epsilon')
BRUN_VALUES = {a[0]: 2, a[1]: 3, a[2]: 7, epsilon: SR(5) / 3}


def brun():
    Mv, pv = vector(SR, M), vector(SR, P)
    H = sum(a[i] * M[i]**2 + epsilon * P[i]**2 / a[i] for i in range(3)) / 2
    F = (Mv * Mv - epsilon * sum(a[i] * P[i]**2 for i in range(3)) / (a[0] * a[1] * a[2])) / 2
    w = vector(SR, [H.diff(x) for x in M])
    u = vector(SR, [H.diff(x) for x in P])
    X = list(Mv.cross_product(w) + pv.cross_product(u)) + list(pv.cross_product(w))
    return [H, F, pv * pv, Mv * pv], X


def stationarity(integrals, multipliers, c=0):
    """dK/dx for K = H + sum lambda_j V_j, and the levels p.p = 1, M.p = c."""
    K = integrals[0] + sum(l * V for l, V in zip(multipliers, integrals[1:]))
    return [K.diff(x) for x in M + P] + [integrals[2] - 1, integrals[3] - c]


def isolated_points(sols, subs):
    # the explicit ones: the slices of a family that its conditions on the
    # unknowns exclude are listed as solutions of their own, implicit ones
    # of dimension 0 over the parameters included (their completeness is
    # checked in test_solution_completeness.py)
    return sorted(tuple(SR(s.point()[x]).subs(subs) for x in M + P)
                  for s in sols if s.dimension() == 0 and s.is_explicit())


@pytest.mark.slow
def test_brun_stationary_set_symbolic_against_values():
    integrals, X = brun()
    symbolic = stationary_solutions(integrals, M + P, equations=X, levels=[None, 1, 0])
    at = [f.subs(BRUN_VALUES) for f in integrals]
    direct = stationary_solutions(at, M + P, equations=[e.subs(BRUN_VALUES) for e in X],
                                  levels=[None, 1, 0])
    assert symbolic.is_complete() and direct.is_complete()
    # the same isolated points (the rest points p = +-e_i, M = 0)
    assert isolated_points(symbolic, BRUN_VALUES) == isolated_points(direct, {})
    assert len(isolated_points(direct, {})) == 6
    # every explicit family, at the values and random values of its free
    # unknowns, annuls the stationarity equations with its multipliers and
    # lies on a family of the direct solve (the same components: the
    # symbolic solve splits a family into its branches p3 = +-sqrt(...))
    families = [s for s in direct if s.dimension() > 0]
    rng = np.random.default_rng(1)
    # (six families by branches, and the slices that their conditions on the
    # unknowns exclude, listed as solutions of their own)
    explicit = [s for s in symbolic if s.is_explicit() and s.dimension() > 0]
    assert len(explicit) >= 6
    for s in explicit:
        free = {x: SR(float(rng.uniform(-0.9, 0.9))) for x in M + P
                if str(s.point()[x]) == str(x)}
        point = {x: SR(v).subs(BRUN_VALUES).subs(free) for x, v in s.point().items()}
        mult = {SR(k): SR(v).subs(BRUN_VALUES).subs(point) for k, v in s.multipliers().items()}
        for e in stationarity(at, list(mult)):
            value = complex(SR(e).subs(mult).subs(point))
            assert abs(value) < 1e-9, (s, e, value)
        assert any(all(abs(complex(SR(e).subs(mult).subs(point))) < 1e-9 for e in d.equations())
                   for d in families), s
    # and the one implicit family of each
    assert sum(1 for s in symbolic if not s.is_explicit()) == 1
    assert sum(1 for s in direct if s.dimension() > 0) == 4


@pytest.mark.slow
def test_brun_stationary_set_on_a_nonzero_level():
    """The level M.p = c with c symbolic: the same isolated points as the
    direct solve at values (the permanent rotations M = c p, p = +-e_i),
    each a solution of the stationarity equations with its multipliers, and
    the same number of families."""
    c = var('c')
    values = dict(BRUN_VALUES, **{'c': SR(3) / 2})
    values = {SR(k): v for k, v in values.items()}
    integrals, X = brun()
    symbolic = stationary_solutions(integrals, M + P, equations=X, levels=[None, 1, c])
    at = [f.subs(values) for f in integrals]
    direct = stationary_solutions(at, M + P, equations=[e.subs(values) for e in X],
                                  levels=[None, 1, values[c]])
    assert symbolic.is_complete() and direct.is_complete()
    assert isolated_points(symbolic, values) == isolated_points(direct, {})
    expected = sorted(tuple([values[c] * s * e for e in row] + [s * e for e in row])
                      for row in identity_matrix(3).rows() for s in (1, -1))
    assert isolated_points(direct, {}) == expected
    for s in symbolic:
        if s.dimension() == 0 and s.is_explicit():
            point = {x: SR(v).subs(values) for x, v in s.point().items()}
            mult = {SR(k): SR(v).subs(values).subs(point) for k, v in s.multipliers().items()}
            free = {k: SR(1) / 3 for k, v in mult.items() if v.is_symbol()}
            for e in stationarity(at, list(mult), values[c]):
                assert SR(e).subs(mult).subs(free).subs(point).simplify_full() == 0
    assert sum(1 for s in symbolic if s.dimension() > 0) >= \
        sum(1 for s in direct if s.dimension() > 0)


# The generic Hamiltonian with its 12 coefficients symbolic: the stationary
# set is solved over their field (in the block order of the unknowns and
# the multipliers, which the solver finds by trying), and checked at
# rational values against the eigenvector construction above: every
# constructed point (M, p, l1, l2) lies on the component of dimension 2
# (its prime's generators vanish there) and has its multipliers.

SYMBOLIC_A = list(var('a1 a2 a3'))
SYMBOLIC_C = list(var('c1 c2 c3'))
SYMBOLIC_B = matrix(SR, 3, 3, lambda i, j: SR.var(f"b{min(i, j) + 1}{max(i, j) + 1}"))


def symbolic_kirchhoff():
    Mv, pv = vector(SR, M), vector(SR, P)
    H = (sum(SYMBOLIC_A[i] * M[i]**2 + SYMBOLIC_C[i] * P[i]**2 for i in range(3)) / 2
         + Mv * SYMBOLIC_B * pv)
    w = vector(SR, [H.diff(x) for x in M])
    u = vector(SR, [H.diff(x) for x in P])
    X = list(Mv.cross_product(w) + pv.cross_product(u)) + list(pv.cross_product(w))
    return [H, pv * pv, Mv * pv], X


def vanishes_at(poly, T, at, params):
    """Whether a polynomial of the solver's ring vanishes at the point ``at``
    (values of its unknowns by name) and the parameter values ``params``,
    relative to the size of its terms (200-bit arithmetic)."""
    from sage.all import RealField
    R = RealField(200)
    ring_values = {}
    for u in T.unknowns():
        (g,) = T.generators_of(u)
        ring_values[str(g)] = R(at[str(u)])
    pvals = [R(params[str(a)]) for a in T.parameters()]
    names = poly.parent().variable_names()
    total, size = R(0), R(0)
    for exps, c in poly.dict().items():
        term = R(c.numerator()(*pvals)) / R(c.denominator()(*pvals))
        for name, e in zip(names, exps):
            term *= ring_values[name] ** e
        total += term
        size += abs(term)
    return abs(total) <= 1e-8 * max(size, 1)


@pytest.mark.slow
def test_generic_kirchhoff_symbolic_parameters():
    integrals, X = symbolic_kirchhoff()
    sols = stationary_solutions(integrals, M + P, equations=X)
    family = [s for s in sols if s.dimension() == 2]
    assert len(family) == 1
    solution = family[0].solution()
    T, prime = solution.translation(), solution.ideal()
    # the rest point M = p = 0
    zero = {x: 0 for x in M + P}
    assert any(s.is_explicit() and all(SR(v).subs(zero) == 0 for v in s.point().values())
               for s in sols)
    rng = np.random.default_rng(7)
    for _ in range(2):
        a = rng.integers(1, 9, 3).astype(float)
        b = rng.integers(-3, 4, (3, 3)).astype(float)
        b = (b + b.T) / 2
        c = rng.integers(1, 19, 3).astype(float)
        params = {f"a{i + 1}": a[i] for i in range(3)}
        params.update({f"c{i + 1}": c[i] for i in range(3)})
        params.update({f"b{i + 1}{j + 1}": b[i, j] for i in range(3) for j in range(i, 3)})
        Ainv = np.diag(1 / a)
        checked = 0
        for l2 in (-1.5, 0.3, 2.0):
            Bl = b + l2 * np.eye(3)
            vals, vecs = np.linalg.eigh(np.diag(c) - Bl @ Ainv @ Bl)
            for k in range(3):
                p = vecs[:, k]
                if abs(p[0]) < 1e-3:
                    continue    # the family's multipliers divide by p1
                m = -Ainv @ Bl @ p
                at = dict(zip(['M1', 'M2', 'M3', 'p1', 'p2', 'p3'], np.concatenate([m, p])))
                at.update(lambda1=-vals[k] / 2, lambda2=l2)
                assert all(vanishes_at(g, T, at, params) for g in prime.gens())
                # the check tells a point off the family (p moved along it)
                assert not all(vanishes_at(g, T, dict(at, p2=at['p2'] + 1e-3), params)
                               for g in prime.gens())
                subs = {SR.var(k): v for k, v in list(params.items()) + list(at.items())
                        if not k.startswith('lambda')}
                mult = {str(k): float(SR(v).subs(subs)) for k, v in
                        family[0].multipliers().items()}
                assert mult['lambda1'] == pytest.approx(-vals[k] / 2, rel=1e-6, abs=1e-6)
                assert mult['lambda2'] == pytest.approx(l2, rel=1e-6, abs=1e-6)
                checked += 1
        assert checked >= 6

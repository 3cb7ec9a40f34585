"""
Completeness of the listed solutions: every real point of the zero set of
the equations lies on some listed solution whose conditions hold there. A
family written as rational functions of its free unknowns comes with
conditions `u != 0` (a denominator of a value or of a multiplier); the points
of its component where `u = 0` must be listed by another solution.

The real points are found here independently: the equations are written
here as polynomials over QQ (for Brun's problem and Clebsch's case the
gradient of K = H + sum l_j V_j written by hand), sliced by setting subsets
of the unknowns to zero and others to random rationals until the slice is
zero-dimensional, and the slice is solved exactly by Singular over the real
algebraic numbers (``variety(AA)``) -- the coordinate hyperplanes are where
the conditions `u != 0` on unknowns are.

Brun's problem (1893), with I = diag(1, 2, 3), epsilon = 1 and his integral
F = (M, M) - epsilon det(I) (gamma, I^-1 gamma): K = H + l1 F + l2 gamma.gamma
+ l3 M.gamma is stationary at M = (M1, 0, 0), gamma = 0 with l1 = -1/2,
l3 = 0 and l2 free (by hand: dK/dM = M/I + 2 l1 M + l3 gamma,
dK/dgamma = eps I gamma - 2 l1 eps det(I) I^-1 gamma + 2 l2 gamma + l3 M);
these points were lost behind the condition gamma1 != 0 of the family
M = (M1, 0, 0), gamma = (gamma1, 0, 0). Likewise the points where two
branches x +- sqrt(D) of a family meet (D = 0) were lost behind D > 0.
"""
import itertools

import numpy as np
import pytest

from sage.all import SR, QQ, AA, PolynomialRing, var, vector
from sage_dynsym.algebra.conditions import holds
from sage_dynsym.algebra.solving import solve_exactly
from sage_dynsym.analysis.stationary import stationary_solutions


def real_points(equations, unknowns, seed=1, orders=2, places=()):
    """Real points of the zero set of ``equations`` (polynomials over QQ in
    ``unknowns``), exactly: on each slice where a subset of the unknowns (and
    of the polynomials ``places``: where to look) is zero and others are
    fixed at random rationals (as long as the dimension drops), by Singular
    over AA."""
    names = [str(u) for u in unknowns]
    R = PolynomialRing(QQ, names)
    eqs = [R(str(SR(e).expand())) for e in equations]
    rng = np.random.default_rng(seed)
    points = []
    hyperplanes = list(R.gens()) + [R(str(SR(e).expand())) for e in places]
    for k in range(len(hyperplanes) + 1):
        for zero in itertools.combinations(hyperplanes, k):
            base = R.ideal(eqs + list(zero))
            if base.is_one():
                continue
            rest = [g for g in R.gens() if g not in zero]
            for _ in range(orders):
                J = base
                for g in rng.permutation(len(rest)):
                    if J.dimension() == 0:
                        break
                    value = QQ(int(rng.integers(1, 7)) * int(rng.choice([-1, 1]))) / \
                        int(rng.integers(1, 4))
                    trial = J + R.ideal([rest[g] - value])
                    if not trial.is_one() and trial.dimension() < J.dimension():
                        J = trial
                if J.dimension() == 0:
                    points += [{n: float(p[R(n)]) for n in names} for p in J.variety(AA)]
    return points


def covers(values, equations, conditions, point, at=None, tol=1e-7):
    """Whether the solution (``values`` of the unknowns, a free one mapped to
    itself; implicit ``equations``; ``conditions``) contains the point."""
    subs = {SR.var(n): v for n, v in point.items()}
    subs.update(at or {})
    try:
        for u, v in values.items():
            if abs(float(SR(v).subs(subs)) - point[str(u)]) > tol:
                return False
        if any(abs(float(SR(e).subs(subs))) > tol for e in equations):
            return False
        return all(holds(c, subs) for c in conditions)
    except (ZeroDivisionError, ValueError, TypeError, RuntimeError):
        return False        # a value not defined at the point


def assert_complete(solutions, points, at=None):
    assert points
    for p in points:
        assert any(covers(values, eqs, conds, p, at) for values, eqs, conds in solutions), p


def exact_solutions(sols):
    return [(s.values(), s.equations(), s.conditions()) for s in sols]


def stationary(sols):
    return [({**s.point(), **s.multipliers()}, s.equations(), s.conditions()) for s in sols]


x, y, z, w, a = var('x y z w a')


def test_a_line_behind_a_denominator():
    # x z = y over (x, y): z = y/x for x != 0, and the line x = y = 0
    sols = solve_exactly([x * z - y], [x, y, z])
    assert_complete(exact_solutions(sols), real_points([x * z - y], [x, y, z]))
    line = [s for s in sols if s.dimension() == 1]
    assert [s.values() for s in line] == [{x: 0, y: 0, z: z}]


@pytest.mark.parametrize("equations", [
    [x**2 - a * y**2, z * x - y],
    # two branches y = x +- sqrt(x^2 - a), real for x^2 > a, meet at x^2 = a
    [y**2 - 2 * x * y + a, z * y - 1],
    [y**2 - 2 * x * y * z + a * z, z * x - 1],
])
@pytest.mark.parametrize("value", [2, -3, QQ(1) / 2])
def test_families_with_a_parameter(equations, value):
    sols = solve_exactly(equations, [x, y, z])
    # the slices where the strict conditions on unknowns fail are looked at
    places = [c.lhs().subs(a=value) for s in sols for c in s.conditions()
              if c.lhs().has(x) or c.lhs().has(y) or c.lhs().has(z)]
    points = real_points([e.subs(a=value) for e in equations], [x, y, z], places=places)
    assert_complete(exact_solutions(sols), points, at={a: value})


def random_system(rng):
    """Two equations in x, y, z, w with small random integer coefficients,
    each with a product u v of unknowns (so that the surfaces are written
    with denominators), one of them reducible."""
    U = [x, y, z, w]

    def linear():
        c = rng.integers(-2, 3, size=4)
        c[rng.integers(4)] = int(rng.choice([-1, 1]))
        return sum(int(k) * u for k, u in zip(c, U)) + int(rng.integers(-1, 2))

    def product():
        i, j = rng.choice(4, size=2, replace=False)
        return U[i] * U[j]

    return [(product() - linear()) * linear(), product() - linear()]


@pytest.mark.parametrize("seed", [2, 3, 4, 5])
def test_random_systems(seed):
    rng = np.random.default_rng(seed)
    equations = random_system(rng)
    sols = solve_exactly(equations, [x, y, z, w])
    # the slices where the conditions u != 0 of the solutions fail are looked at
    places = {c.lhs() for s in sols for c in s.conditions()}
    assert places
    assert_complete(exact_solutions(sols),
                    real_points(equations, [x, y, z, w], seed=seed, places=places))


# --- Brun's problem and Clebsch's case ------------------------------------------

M = list(var('M1 M2 M3'))
G = list(var('g1 g2 g3'))
L = list(var('lambda1 lambda2 lambda3'))


def euler_poisson(H):
    Mv, gv = vector(SR, M), vector(SR, G)
    dM = vector(SR, [H.diff(v) for v in M])
    dg = vector(SR, [H.diff(v) for v in G])
    return list(Mv.cross_product(dM) + gv.cross_product(dg)) + list(gv.cross_product(dM))


def gradient(integrals):
    """grad K for K = V0 + sum l_j V_j (written out; the multipliers lambda_j)."""
    K = integrals[0] + sum(l * V for l, V in zip(L, integrals[1:]))
    return [K.diff(v) for v in M + G]


@pytest.mark.slow
@pytest.mark.parametrize("with_integral", [False, True])
def test_brun_problem(with_integral):
    iv, eps = [1, 2, 3], 1
    H = sum(M[i]**2 / iv[i] for i in range(3)) / 2 + eps * sum(
        iv[i] * G[i]**2 for i in range(3)) / 2
    F = sum(m**2 for m in M) - eps * 6 * sum(G[i]**2 / iv[i] for i in range(3))
    casimirs = [sum(g**2 for g in G), sum(m * g for m, g in zip(M, G))]
    integrals = [H, F] + casimirs if with_integral else [H] + casimirs
    sols = stationary_solutions(integrals, M + G, equations=euler_poisson(H))
    unknowns = M + G + L[:len(integrals) - 1]
    assert_complete(stationary(sols), real_points(gradient(integrals), unknowns))
    if with_integral:
        # the rotations about the axes with gamma = 0 (by hand, see above)
        for k in range(3):
            point = {**{str(u): 0.0 for u in unknowns}, str(M[k]): 2.0,
                     'lambda1': -1 / (2 * iv[k]), 'lambda2': 5.0}
            assert any(covers(*s, point) for s in stationary(sols))


@pytest.mark.slow
def test_clebsch_case():
    # Kirchhoff's equations in Clebsch's case, H = (sum a_i M_i^2 + theta
    # a_j a_k p_i^2)/2 with a = (1, 2, 4), theta = 1 (the momenta named
    # g1, g2, g3 here): the rotations M_i = +-sqrt(8) p_i/a_i with p3 = 0
    # were lost behind the condition p3 != 0 of the 3-parameter family
    # (its multiplier l2 = -4 M3/p3)
    A, theta = [1, 2, 4], 1
    b = [theta * A[1] * A[2], theta * A[0] * A[2], theta * A[0] * A[1]]
    H = sum(A[i] * M[i]**2 + b[i] * G[i]**2 for i in range(3)) / 2
    integrals = [H, sum(g**2 for g in G), sum(m * g for m, g in zip(M, G))]
    sols = stationary_solutions(integrals, M + G, equations=euler_poisson(H))
    assert_complete(stationary(sols), real_points(gradient(integrals), M + G + L[:2]))

"""
Stationary solutions without noise: no branch without real points, no point
listed apart that a listed branch contains (issue 33).

Expected values from outside the package:

- Brun's problem (H = (M, I^-1 M)/2 + eps (gamma, I gamma)/2, I = diag(1, 2, 3),
  eps = 1) on the leaf (gamma, gamma) = 1, (M, gamma) = c: six isolated
  relative equilibria, the rotations about the principal axes, on every leaf;
  for sqrt(eps) I1 < |c| < sqrt(eps) I3 also Brun's uniform rotations
  M = sign(c) sqrt(eps) I gamma, a curve (Borisov & Mamaev, Rigid Body
  Dynamics, Brun's case). Checked here by least squares on the stationary
  equations from many random starts (SciPy), the solutions clustered.
- A symmetric body I1 = I2 on the sphere |M| = 1: the rotations about the
  symmetry axis (two points) and the circle M3 = 0.
- Small systems whose real solutions are known by hand.
"""
import numpy as np
import pytest
from scipy.optimize import least_squares

from sage.all import QQ, var, vector
from sage_dynsym.algebra import solving
from sage_dynsym.algebra.solving import solve_exactly
from sage_dynsym.analysis.stationary import stationary_solutions

INERTIA = np.array([1.0, 2.0, 3.0])


def brun_field(x):
    """The Euler-Poisson field of Brun's H, eps = 1 (NumPy)."""
    M, G = np.split(x, 2)
    return np.concatenate([np.cross(M, M / INERTIA) + np.cross(G, INERTIA * G),
                           np.cross(G, M / INERTIA)])


def least_squares_equilibria(c, starts=150, seed=3):
    """The relative equilibria on the leaf, by least squares, clustered:
    (isolated points, points off the axes)."""
    rng = np.random.default_rng(seed)

    def residual(x):
        G = x[3:]
        return np.concatenate([brun_field(x), [G @ G - 1, x[:3] @ G - c]])
    found = []
    for _ in range(starts):
        fit = least_squares(residual, rng.normal(size=6) * (1 + abs(c)),
                            xtol=1e-15, ftol=1e-15, gtol=1e-15)
        if fit.cost < 1e-24:
            found.append(fit.x)
    on_axis = lambda x: any(abs(abs(x[3 + k]) - 1) < 1e-7 for k in range(3))
    axes = {tuple(np.round(x, 6) + 0.0) for x in found if on_axis(x)}
    return sorted(axes), [x for x in found if not on_axis(x)]


def brun_solutions(c):
    M1, M2, M3, g1, g2, g3 = var('M1 M2 M3 gamma1 gamma2 gamma3')
    x = [M1, M2, M3, g1, g2, g3]
    M, g = vector(x[:3]), vector(x[3:])
    H = sum(m**2 / (2 * int(i)) for m, i in zip(M, INERTIA)) + \
        sum(int(i) * gg**2 for i, gg in zip(INERTIA, g)) / 2
    dM, dg = vector([H.diff(v) for v in M]), vector([H.diff(v) for v in g])
    field = list(M.cross_product(dM) + g.cross_product(dg)) + list(g.cross_product(dM))
    return x, stationary_solutions([H, M * g, g * g], x, equations=field, levels=[c, 1])


@pytest.mark.slow       # two leaves, a few seconds each, and the least squares
@pytest.mark.parametrize("c", [QQ(3) / 2, QQ(1) / 2])
def test_brun_leaves_against_least_squares(c):
    x, sols = brun_solutions(c)
    points = sorted(tuple(float(s.point()[v]) for v in x) for s in sols if s.dimension() == 0)
    axes, others = least_squares_equilibria(float(c))
    assert len(axes) == 6
    # exactly the six rotations about the axes are listed as points
    assert len(points) == 6 and np.allclose(points, axes, atol=1e-6)
    families = [s.solution() for s in sols if s.dimension() > 0]
    # Brun's rotations for 1 < |c| < 3: one curve (in branches, or one
    # implicit family where a real point of it was found at random), none
    # for |c| < 1; the curve is M = I gamma with (I gamma, gamma) = c
    assert bool(others) == bool(families) == (1 < c < 3)
    M, g = x[:3], x[3:]
    for s in families:
        assert all(s.contains(M[k] - int(INERTIA[k]) * g[k]) for k in range(3))
        assert s.contains(sum(int(i) * gg**2 for i, gg in zip(INERTIA, g)) - c)
    for p in others:
        assert np.allclose(p[:3], INERTIA * p[3:], atol=1e-7)
        assert abs(p[3:] @ (INERTIA * p[3:]) - float(c)) < 1e-7


def test_symmetric_body_circle():
    M1, M2, M3 = var('M1 M2 M3')
    H = (M1**2 + M2**2) / 2 + M3**2 / 6
    X = [-M2 * M3 / 3 + M3 * M2, M1 * M3 / 3 - M3 * M1, 0]
    sols = stationary_solutions([H, M1**2 + M2**2 + M3**2], [M1, M2, M3], equations=X,
                                levels=[1])
    points = sorted(tuple(s.point()[v] for v in (M1, M2, M3)) for s in sols
                    if s.dimension() == 0)
    assert points == [(0, 0, -1), (0, 0, 1)]
    circle, = [s for s in sols if s.dimension() > 0]
    # on the circle M3 = 0, M1^2 + M2^2 = 1: a rotation about an equatorial axis
    assert circle.solution().contains(M3) and circle.solution().contains(M1**2 + M2**2 - 1)


def test_branch_real_only_for_negative_parameter():
    # y^2 = x - a, z^2 = -x - a: real exactly where a < x < -a, i.e. for a < 0
    x, y, z, a = var('x y z a')
    eqs = [y**2 - x + a, z**2 + x + a]
    assert len(solve_exactly(eqs, [x, y, z], positive=[a])) == 0
    undeclared = solve_exactly(eqs, [x, y, z])
    branches = [s for s in undeclared if s.dimension() == 1]
    assert len(branches) == 4       # the signs of y and z; real for a < 0, kept
    for s in branches:
        assert all(bool(c.subs({a: -1, x: QQ(1) / 2})) for c in s.conditions())


@pytest.fixture
def branches_forced():
    """Curves without parameters written in branches (their reality left
    undecided by the random fibres and quantifier elimination)."""
    saved = solving.REAL_POINT_SAMPLES, solving.REALITY_QE_VARIABLES
    solving.REAL_POINT_SAMPLES, solving.REALITY_QE_VARIABLES = 0, 0
    yield
    solving.REAL_POINT_SAMPLES, solving.REALITY_QE_VARIABLES = saved


def test_branch_ends_contained(branches_forced):
    # y^2 = x - 1, z^2 = 3 - x: real for 1 <= x <= 3, its ends included
    x, y, z = var('x y z')
    sols = solve_exactly([y**2 - x + 1, z**2 + x - 3], [x, y, z])
    assert all(s.dimension() == 1 for s in sols) and len(sols) == 4
    for end in (1, 3):
        for sy in (1, -1):
            for sz in (1, -1):
                p = {x: end, y: sy * np.sqrt(end - 1), z: sz * np.sqrt(3 - end)}
                assert any(all(bool(c.subs({x: end})) for c in s.conditions()) and
                           all(abs(float(s.values()[v].subs({x: end})) - p[v]) < 1e-12
                               for v in (y, z)) for s in sols)
    # y^2 = x - 1, z^2 = -x - 1 has no real point
    assert len(solve_exactly([y**2 - x + 1, z**2 + x + 1], [x, y, z])) == 0


def test_branch_end_not_contained_is_kept(branches_forced):
    # the curve y^2 = x - 1, y z = 1 and the point (1, 0, 0) at its end,
    # where z = 1/y is infinite: the point is a solution of its own
    x, y, z = var('x y z')
    C, Q = [y**2 - x + 1, y * z - 1], [x - 1, y, z]
    sols = solve_exactly([c * q for c in C for q in Q], [x, y, z])
    points = [s.values() for s in sols if s.dimension() == 0]
    assert points == [{x: 1, y: 0, z: 0}]
    assert len([s for s in sols if s.dimension() == 1]) == 2


def on_listed(sols, point, at=None):
    """Whether some listed explicit solution has the values ``point`` (a
    dict of unknowns) with its conditions holding (``at``: parameter values)."""
    at = at or {}
    for s in sols:
        if not s.is_explicit() or any(v not in point for v in s.free_unknowns()):
            continue
        free = {v: point[v] for v in s.free_unknowns()}
        subs = {**at, **free}
        try:
            if all(bool(c.subs(subs)) for c in s.conditions()) and \
                    all(abs(float(s.values()[v].subs(subs)) - float(point[v])) < 1e-12
                        for v in point):
                return True
        except (TypeError, ValueError):
            continue
    return False


@pytest.mark.parametrize("a", [QQ(-3) / 2, 0, QQ(2) / 7])
def test_branch_ends_contained_with_a_parameter(a):
    # y^2 = x - a (by hand): real for x >= a, y = +-sqrt(x - a), its only
    # point with y = 0 the end (a, 0); likewise with z free (a surface whose
    # points with y = 0 are the line x = a): the ends are on the branches,
    # nothing is listed apart
    x, y, z, p = var('x y z a')
    for unknowns in ([x, y], [x, y, z]):
        sols = solve_exactly([y**2 - x + p], unknowns)
        assert len(sols) == 2 and all(s.dimension() == len(unknowns) - 1 for s in sols)
        for zv in ([0] if len(unknowns) == 2 else [QQ(5), QQ(-1) / 3]):
            end = {x: a, y: 0, z: zv} if len(unknowns) == 3 else {x: a, y: 0}
            assert on_listed(sols, end, {p: a})
            for sign in (1, -1):
                inner = {**end, x: a + 2, y: sign * np.sqrt(2.0)}
                assert on_listed(sols, inner, {p: a})


def test_branch_end_at_infinity_with_a_parameter_is_kept():
    # y^2 = x - a, z = w y: for y != 0, w = z/y; the line x = a, y = z = 0
    # (w free) is a solution (by hand: both equations hold) that no branch
    # reaches (w = z/y is infinite there), so it is listed
    x, y, z, w, a = var('x y z w a')
    sols = solve_exactly([y**2 - x + a, z - w * y], [x, y, z, w])
    line = [s for s in sols if s.dimension() == 1]
    assert len(line) == 1 and line[0].values() == {x: a, y: 0, z: 0, w: w}


@pytest.mark.slow       # Brun's problem with symbolic parameters (a few seconds)
def test_brun_symbolic_level_zero_axes_on_circles():
    # Brun's problem on (gamma, gamma) = 1, (M, gamma) = 0 with symbolic a_i,
    # eps, its integral F = (M, M)/2 - eps (gamma, A gamma)/(2 a1 a2 a3) free
    # (H = (M, A M)/2 + eps (gamma, A^-1 gamma)/2): the stationary set holds
    # the sets M = m e_k, gamma on the unit circle orthogonal to e_k; the
    # lines M = m e_k, gamma = +-e_j (j != k) lie on those circles (by hand:
    # e_j is a unit vector orthogonal to e_k; on such a set the equations for
    # the multipliers do not depend on gamma: lambda3 = 0, lambda1 and lambda2
    # fixed by a_k), so no 1-dimensional set is listed apart, and each such
    # line is on a listed circle
    M, P, A = list(var('M1 M2 M3')), list(var('p1 p2 p3')), list(var('a1 a2 a3'))
    eps = var('epsilon')
    H = sum(A[i] * M[i]**2 + eps * P[i]**2 / A[i] for i in range(3)) / 2
    F = (sum(m**2 for m in M) - eps * sum(A[i] * P[i]**2 for i in range(3))
         / (A[0] * A[1] * A[2])) / 2
    Mv, pv = vector(M), vector(P)
    dM, dp = vector([H.diff(v) for v in M]), vector([H.diff(v) for v in P])
    X = list(Mv.cross_product(dM) + pv.cross_product(dp)) + list(pv.cross_product(dM))
    sols = stationary_solutions([H, F, pv * pv, Mv * pv], M + P, equations=X,
                                levels=[None, 1, 0])
    assert not [s for s in sols if s.dimension() == 1]
    at = {var(n): v for n, v in (('a1', 1), ('a2', 2), ('a3', 3), ('epsilon', 1))}
    for k in range(3):
        for j in range(3):
            for sign in ((1, -1) if j != k else ()):
                point = {v: 0 for v in M + P}
                point[M[k]], point[P[j]] = QQ(7) / 5, sign
                assert on_listed([s.solution() for s in sols], point, at), (k, j, sign)


def test_branch_end_where_the_equation_is_undefined():
    # (y^2 - x + a)/y = 0 (by hand): y = +-sqrt(x - a) with y != 0, so x > a;
    # the end (a, 0) is not a solution (the equation is not defined there):
    # neither listed nor added to the branches
    x, y, a = var('x y a')
    sols = solve_exactly([(y**2 - x + a) / y], [x, y])
    assert len(sols) == 2 and all(s.dimension() == 1 for s in sols)
    assert not on_listed(sols, {x: QQ(1) / 3, y: 0}, {a: QQ(1) / 3})
    assert on_listed(sols, {x: QQ(4) / 3, y: 1}, {a: QQ(1) / 3})

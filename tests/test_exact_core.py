"""The exact solving core (solve_exactly) on polynomial systems whose
solution sets are known by construction, and the bad inputs of issue 9.

Random systems: the union of k chosen points and a chosen curve or plane
(the product of their ideals, built here by multiplying generators, so its
zero set is exactly the union). The expected components, their dimensions
and the chosen points come from the construction, not from the code under
test. Families are checked at rational points of the chosen curve
(rational parametrisations of lines, conics with square semi-axes,
parabolas, planes).
"""
import itertools
import random

import numpy as np
import pytest
from sage.all import (SR, QQ, var, sqrt, sin, cos, matrix, function, diff, identity_matrix)

from sage_dynsym import Lagrangian
from sage_dynsym.algebra.conditions import holds, region_holds
from sage_dynsym.analysis.linear import LinearSystem, linearize
from sage_dynsym.algebra.solving import solve_exactly
from sage_dynsym.analysis.stationary import stationary_solutions
from sage_dynsym.errors import AnalysisError, DynSymError

x, y, z, a = var('x y z a')


# ---------------------------------------------------------------------------
# construction of the random systems
# ---------------------------------------------------------------------------

def rational(rng, lo=-5, hi=5, den=4):
    return QQ(rng.randint(lo * den, hi * den)) / den


def nonzero_rational(rng, lo=1, hi=3, den=2):
    v = QQ(rng.randint(lo * den, hi * den)) / den
    return v if rng.random() < 0.5 else -v


def product_of_ideals(ideals):
    """Generators of the product of ideals (each a list of generators):
    its zero set is the union of their zero sets."""
    return [_prod([SR(g) for g in combo]) for combo in itertools.product(*ideals)]


def _prod(factors):
    result = SR(1)
    for f in factors:
        result *= f
    return result


def random_curve_2d(rng):
    """(generators, sampler of rational points, kind): a line, an ellipse or
    a hyperbola with rational semi-axes, or a parabola in the plane."""
    kind = rng.choice(['line', 'ellipse', 'hyperbola', 'parabola'])
    x0, y0 = rational(rng), rational(rng)
    if kind == 'line':
        al, be = rational(rng), rational(rng)
        if rng.random() < 0.3:             # a vertical line
            return [x - x0], lambda t: {x: x0, y: t}, kind
        return [y - al * x - be], lambda t: {x: t, y: al * t + be}, kind
    if kind == 'parabola':
        al, be = nonzero_rational(rng), rational(rng)
        return [y - al * x**2 - be * x - y0], \
            lambda t: {x: t, y: al * t**2 + be * t + y0}, kind
    r, s = abs(nonzero_rational(rng)), abs(nonzero_rational(rng))
    if kind == 'ellipse':
        f = (x - x0)**2 / r**2 + (y - y0)**2 / s**2 - 1
        pt = lambda t: {x: x0 + r * (1 - t**2) / (1 + t**2), y: y0 + s * 2 * t / (1 + t**2)}
    else:
        f = (x - x0)**2 / r**2 - (y - y0)**2 / s**2 - 1
        pt = lambda t: {x: x0 + r * (t + 1 / t) / 2, y: y0 + s * (t - 1 / t) / 2}
    return [(f * r**2 * s**2).expand()], pt, kind


def random_variety_3d(rng):
    """A line (two planes through a chosen point along a chosen direction),
    a plane, or a circle-like conic in a plane, in space."""
    kind = rng.choice(['line', 'plane', 'conic'])
    P = [rational(rng) for _ in range(3)]
    if kind == 'line':
        D = [nonzero_rational(rng) for _ in range(3)]
        # two independent normals orthogonal to D
        n1 = [D[1], -D[0], 0]
        n2 = [0, D[2], -D[1]]
        gens = [sum(n[i] * (v - P[i]) for i, v in enumerate((x, y, z))) for n in (n1, n2)]
        return gens, lambda t, u: {x: P[0] + t * D[0], y: P[1] + t * D[1],
                                   z: P[2] + t * D[2]}, 1
    if kind == 'plane':
        n = [nonzero_rational(rng) for _ in range(3)]
        # z from the plane equation
        return [n[0] * (x - P[0]) + n[1] * (y - P[1]) + n[2] * (z - P[2])], \
            lambda t, u: {x: t, y: u, z: P[2] - (n[0] * (t - P[0]) + n[1] * (u - P[1])) / n[2]}, 2
    r = abs(nonzero_rational(rng))
    gens = [z - P[2], (x - P[0])**2 + (y - P[1])**2 - r**2]
    return gens, lambda t, u: {x: P[0] + r * (1 - t**2) / (1 + t**2),
                               y: P[1] + r * 2 * t / (1 + t**2), z: P[2]}, 1


def random_points(rng, k, unknowns, avoid):
    """k distinct rational points, not on the variety (``avoid`` evaluates
    its generators)."""
    pts = []
    while len(pts) < k:
        p = {u: rational(rng) for u in unknowns}
        if p not in pts and any(SR(g).subs(p) != 0 for g in avoid):
            pts.append(p)
    return pts


def point_ideal(p):
    return [u - v for u, v in p.items()]


# ---------------------------------------------------------------------------
# checks against the construction
# ---------------------------------------------------------------------------

def same_value(v, w):
    return (SR(v) - SR(w)).simplify_rational() == 0


def isolated_solution_for(sols, p):
    """The isolated solutions whose values are the point ``p``."""
    return [s for s in sols if s.dimension() == 0 and s.is_explicit()
            and all(same_value(s.values()[u], v) for u, v in p.items())]


def lies_on(s, p):
    """Whether the point ``p`` (a dict over all unknowns) is a point of the
    solution ``s``: explicit values agree, remaining equations vanish,
    conditions hold."""
    values = s.values()
    return all(same_value(SR(values[u]).subs(p), v) for u, v in p.items()) and \
        all(SR(e).subs(p).simplify_rational() == 0 for e in s.equations()) and \
        all(holds(c, p) for c in s.conditions())


@pytest.mark.parametrize("seed", range(20))
def test_points_and_a_plane_curve(seed):
    rng = random.Random(1000 + seed)
    curve, sample, kind = random_curve_2d(rng)
    k = rng.randint(1, 3)
    pts = random_points(rng, k, [x, y], curve)
    sols = solve_exactly(product_of_ideals([point_ideal(p) for p in pts] + [curve]), [x, y])
    assert sorted(s.dimension() for s in sols) == [0] * k + [1], (kind, pts, list(sols))
    for p in pts:
        assert len(isolated_solution_for(sols, p)) == 1, (p, list(sols))
    family = [s for s in sols if s.dimension() == 1][0]
    for t in (QQ(1) / 3, QQ(2), QQ(-5) / 7):
        assert lies_on(family, sample(t)), (kind, family, sample(t))


@pytest.mark.parametrize("seed", range(10))
def test_points_and_a_variety_in_space(seed):
    rng = random.Random(2000 + seed)
    gens, sample, dim = random_variety_3d(rng)
    k = rng.randint(1, 2)
    pts = random_points(rng, k, [x, y, z], gens)
    sols = solve_exactly(product_of_ideals([point_ideal(p) for p in pts] + [gens]), [x, y, z])
    assert sorted(s.dimension() for s in sols) == [0] * k + [dim], (gens, pts, list(sols))
    for p in pts:
        assert len(isolated_solution_for(sols, p)) == 1, (p, list(sols))
    family = [s for s in sols if s.dimension() == dim][0]
    for t, u in ((QQ(1) / 3, QQ(2)), (QQ(-3), QQ(1) / 5)):
        assert lies_on(family, sample(t, u)), (gens, family, sample(t, u))


@pytest.mark.parametrize("seed", range(6))
def test_points_depending_on_a_parameter(seed):
    # points whose coordinates are polynomials in a parameter a, and the
    # line y = c*a*x: the solutions over Q(a) are these points, generically
    rng = random.Random(3000 + seed)
    pts = []
    for _ in range(rng.randint(1, 2)):
        pts.append({x: rational(rng) + rng.randint(-2, 2) * a,
                    y: rational(rng) + rng.randint(1, 2) * a**2})
    cf = nonzero_rational(rng)
    line = [y - cf * a * x]
    sols = solve_exactly(product_of_ideals([point_ideal(p) for p in pts] + [line]), [x, y])
    assert sorted(s.dimension() for s in sols) == [0] * len(pts) + [1], (pts, list(sols))
    for p in pts:
        assert len(isolated_solution_for(sols, p)) == 1, (p, list(sols))
    family = [s for s in sols if s.dimension() == 1][0]
    for av, t in ((QQ(2), QQ(1) / 3), (QQ(-1) / 2, QQ(3))):
        p = {x: t, y: cf * av * t}
        assert all(same_value(SR(family.values()[u]).subs({a: av}).subs(p), v)
                   for u, v in p.items())


def test_irrational_and_complex_points():
    # (x^2 - d, y - e) has the real points (+-sqrt(d), e); (x^2 + d, y) none
    rng = random.Random(4000)
    for _ in range(5):
        d, e = abs(nonzero_rational(rng)) + QQ(1) / 7, rational(rng)
        sols = solve_exactly(product_of_ideals([[x**2 - d, y - e], [x**2 + d, y - 1]]), [x, y])
        assert len(sols) == 2 and all(s.dimension() == 0 for s in sols)
        got = sorted(float(s.values()[x]) for s in sols)
        assert got == pytest.approx([-float(sqrt(d)), float(sqrt(d))])
        assert all(same_value(s.values()[y], e) for s in sols)
        assert all(same_value(s.values()[x]**2, d) for s in sols)


def test_curve_without_real_points_is_dropped():
    # x^2 + y^2 + 1 > 0 everywhere on R^2: no real solution
    assert solve_exactly([x**2 + y**2 + 1], [x, y]).is_empty()


def test_quartic_well_has_one_isolated_equilibrium():
    # V = (x^2 + y^2)^2 / 4: grad V = (x^2 + y^2)*(x, y) vanishes on R^2 only
    # at the origin (x^2 + y^2 > 0 elsewhere)
    sols = stationary_solutions([(x**2 + y**2)**2 / 4], [x, y])
    assert [(s.dimension(), s.point()) for s in sols] == [(0, {x: 0, y: 0})]


# ---------------------------------------------------------------------------
# bad input
# ---------------------------------------------------------------------------

def test_inconsistent_levels_give_an_empty_result():
    # M1 + M2 = 1 and 2*(M1 + M2) = 3 contradict each other
    M1, M2, M3, A1, A2, A3 = var('M1 M2 M3 A1 A2 A3')
    H = (M1**2 / A1 + M2**2 / A2 + M3**2 / A3) / 2
    sols = stationary_solutions([H, M1 + M2, 2 * M1 + 2 * M2], [M1, M2, M3], levels=[1, 3])
    assert sols.is_empty() and len(sols) == 0
    assert "No stationary solutions" in repr(sols) and "inconsistent" in repr(sols)
    # a level no real point reaches: |M|^2 = -1
    V = M1**2 + M2**2 + M3**2
    assert stationary_solutions([H, V], [M1, M2, M3], levels=[-1],
                                positive=[A1, A2, A3]).is_empty()


def test_transcendental_without_solution_formula_is_a_clear_error():
    # a pendulum with a torsion spring: V = k*x^2/2 - m*g*l*cos(x); the
    # equilibria solve k*x + m*g*l*sin(x) = 0 -- not algebraic, and Maxima
    # has no closed form
    k, m, g, l = var('k m g l')
    with pytest.raises(AnalysisError, match="not algebraic") as err:
        stationary_solutions([k * x**2 / 2 - m * g * l * cos(x)], [x])
    assert "Maxima" in str(err.value)
    with pytest.raises(AnalysisError, match="not algebraic"):
        solve_exactly([x - cos(x)], [x], transcendental=True)


def test_characteristic_polynomial_with_unspecified_derivative():
    # x' = y - f(x), y' = -x at (0, f(0)): J = [[-f'(0), 1], [-1, 0]] and
    # det(lam*I - J) = lam^2 + f'(0)*lam + 1 (by hand)
    f = function('f')
    lam, s = var('lam s')
    lin = linearize([y - f(x), -x], {x: 0, y: f(0)}, [x, y])
    p = lin.characteristic_polynomial(lam)
    fp = diff(f(x), x).subs(x=0)
    assert (p.subs({fp: s}) - (lam**2 + s * lam + 1)).expand() == 0
    # a symbolic Jacobian with f'(u) among parameters
    u, b = var('u b')
    J = matrix(SR, [[diff(f(u), u), 1], [-1, b]])
    p = LinearSystem([x, y], J=J).characteristic_polynomial(lam)
    ref = (lam * identity_matrix(SR, 2) - J.subs({diff(f(u), u): s})).det()
    assert (p.subs({diff(f(u), u): s}) - ref).expand() == 0
    # through a stability verdict: x'' + k x = 0 with the stiffness k = f'(c)
    # of an unspecified characteristic is a centre for k > 0 (energy
    # y^2/2 + k x^2/2 definite), a saddle for k < 0 (numpy eigenvalues)
    k = diff(f(u), u)
    sols = stationary_solutions([y**2 / 2 + k * x**2 / 2], [x, y], equations=[y, -k * x])
    v = sols[0].stability()
    cases = v.cases() if v.verdict() == 'depends on the parameters' else [v]
    for kv in (QQ(3), QQ(-2)):
        ev = np.linalg.eigvals(np.array([[0.0, 1.0], [-float(kv), 0.0]]))
        got = [(cs.verdict(), cs.method()) for cs in cases if region_holds(cs.region(), {k: kv})]
        if max(ev.real) > 1e-9:
            assert got == [('unstable', 'first approximation')]
        else:
            assert got == [('stable', 'Routh-Lyapunov')]


def test_heavy_top_in_euler_angles_at_theta_zero_names_theta():
    # Lagrange top (Goldstein, Classical Mechanics, 3rd ed., §5.7): the
    # Euler-angle chart is singular at theta = 0
    psi, th, phi, dpsi, dth, dphi, A, C, m, g, l = \
        var('psi theta phi dpsi dtheta dphi A C m g l')
    L = Lagrangian(A / 2 * (dth**2 + sin(th)**2 * dpsi**2)
                   + C / 2 * (dphi + cos(th) * dpsi)**2 - m * g * l * cos(th), [psi, th, phi])
    with pytest.raises(AnalysisError, match="theta") as err:
        linearize(L, {psi: 0, th: 0, phi: 0})
    assert isinstance(err.value, DynSymError)

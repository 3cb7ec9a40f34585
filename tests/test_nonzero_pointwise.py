r"""
``solve_exactly``: a solution holds only at points where the equations are
defined and the expressions required nonzero do not vanish.

Random systems in two symbols, a free one `t` (the first unknown, or a
parameter) and a bound one `u`, with an equation `F/d = 0` and an
expression `n` required nonzero. The expected values come from outside the
solver, in exact arithmetic over ``AA`` with polynomials the test builds:

- at random rational `t` where a solution's conditions hold, its value of
  `u` satisfies `F = 0` with `d \ne 0` and `n \ne 0`;
- the points where `d` or `n` vanishes on `F = 0` lie over the real roots
  of the resultants `\mathrm{Res}_u(F, d)`, `\mathrm{Res}_u(F, n)`; at each
  such point that a solution's values pass through, its conditions fail.

A deliberately wrong condition set (the conditions dropped) is caught by
the same check (negative control).
"""
import operator
import random

import pytest
from sage.all import AA, QQ, SR, PolynomialRing, cos, sin, var

import sage_dynsym.algebra.solving as solving
from sage_dynsym.algebra.solving import solve_exactly

R = PolynomialRing(QQ, ['t', 'u'])
RT, RU = R.gens()


def _random_poly(rng, variable, degree):
    return sum(rng.randint(-3, 3) * variable ** k for k in range(degree)) + \
        rng.choice([-2, -1, 1, 2]) * variable ** degree


def _random_linear(rng, free_weight=True):
    a, b = rng.choice([-2, -1, 1, 2]), rng.choice([-2, -1, 1, 2])
    return (a if free_weight else 0) * RT + b * RU + rng.randint(-3, 3)


def _rational_system(rng):
    # F = (u - r(t)) (u + t - c): two rational families over t
    F = (RU - _random_poly(rng, RT, rng.randint(1, 2))) * (RU + RT - rng.randint(-3, 3))
    return F, _random_linear(rng), _random_linear(rng)


def _branch_system(rng):
    # F = u^2 - q(t): branches u = +-sqrt(q(t)); n = u - k vanishes on one
    q = _random_poly(rng, RT, 2)
    d = RT - rng.randint(-3, 3)
    return RU ** 2 - q, d, RU - rng.randint(-2, 2)


def _parameter_system(rng):
    # F = (u - p(t)) (u - c), t a parameter: points with conditions on it
    F = (RU - _random_poly(rng, RT, rng.randint(1, 2))) * (RU - rng.randint(-3, 3))
    return F, RU - rng.randint(-3, 3), _random_linear(rng)


def _solve(F, d, n, t_is_unknown):
    t, u = var('t u')
    equation = SR(F)(t=t, u=u) / SR(d)(t=t, u=u)
    unknowns = [t, u] if t_is_unknown else [u]
    return solve_exactly([equation], unknowns, nonzero=[SR(n)(t=t, u=u)])


def _holds(conditions, at):
    r"""Whether all conditions hold at ``t = at`` (exact, in ``AA``); a
    condition undefined or not real there does not hold."""
    for c in conditions:
        try:
            value = AA(SR(c.lhs() - c.rhs()).subs({SR.var('t'): at}))
        except (ValueError, TypeError, ZeroDivisionError, ArithmeticError):
            return False
        if not c.operator()(value, 0):
            return False
    return True


def _value(solution, at):
    r"""The solution's value of `u` at ``t = at`` in ``AA``, or ``None``
    where it is not defined or not real."""
    try:
        return AA(SR(solution.values()[SR.var('u')]).subs({SR.var('t'): at}))
    except (ValueError, TypeError, ZeroDivisionError, ArithmeticError):
        return None


def _violations(F, d, n, solutions, conditions_of, rng):
    r"""The points (``(t, u)``) where a solution, with the conditions
    ``conditions_of(solution)``, claims a point that is no solution, and
    the number of sample points checked."""
    found, checked = [], 0
    samples = {QQ((rng.randint(-40, 40), rng.randint(1, 7))) for _ in range(25)}
    for s in solutions:
        assert s.is_explicit()
        conditions = conditions_of(s)
        for at in samples:
            if not _holds(conditions, at):
                continue
            v = _value(s, at)
            checked += 1
            if v is None or F(at, v) != 0 or d(at, v) == 0 or n(at, v) == 0:
                found.append((at, v))
        for b in (d, n):
            res = F.resultant(b, RU)
            if res == 0:
                continue
            for at, _ in res.univariate_polynomial().roots(AA):
                v = _value(s, at)
                if v is not None and F(at, v) == 0 and b(at, v) == 0 and \
                        _holds(conditions, at):
                    found.append((at, v))
    return found, checked


SYSTEMS = [(_rational_system, True), (_branch_system, True), (_parameter_system, False)]


@pytest.mark.parametrize("seed", range(6))
@pytest.mark.parametrize("system", range(len(SYSTEMS)))
def test_no_point_where_a_required_expression_vanishes(system, seed, monkeypatch):
    # a curve without parameters is written in branches only where its
    # reality is not decided otherwise: the other ways switched off
    monkeypatch.setattr(solving, "REAL_POINT_SAMPLES", 0)
    monkeypatch.setattr(solving, "REALITY_QE_VARIABLES", 0)
    make, t_is_unknown = SYSTEMS[system]
    rng = random.Random(1000 * system + seed)
    F, d, n = make(rng)
    solutions = _solve(F, d, n, t_is_unknown)
    assert _violations(F, d, n, solutions, lambda s: s.conditions(), rng)[0] == []


def test_samples_are_checked(monkeypatch):
    # the sampling is not vacuous: every system has sample points checked
    monkeypatch.setattr(solving, "REAL_POINT_SAMPLES", 0)
    monkeypatch.setattr(solving, "REALITY_QE_VARIABLES", 0)
    for make, t_is_unknown in SYSTEMS:
        rng = random.Random(7)
        F, d, n = make(rng)
        assert _violations(F, d, n, _solve(F, d, n, t_is_unknown), lambda s: s.conditions(),
                           rng)[1] > 0


def test_negative_control_without_the_conditions():
    # (u - t)/u with u required nonzero too: u = t only for t != 0; without
    # its conditions the family claims the point (0, 0)
    F, d, n = RU - RT, RU, RU + 0 * RT
    solutions = _solve(F, d, n, True)
    rng = random.Random(0)
    assert _violations(F, d, n, solutions, lambda s: s.conditions(), rng)[0] == []
    assert (0, 0) in _violations(F, d, n, solutions, lambda s: [], rng)[0]


def test_negative_control_widened_branch(monkeypatch):
    monkeypatch.setattr(solving, "REAL_POINT_SAMPLES", 0)
    monkeypatch.setattr(solving, "REALITY_QE_VARIABLES", 0)
    # the branches u = +-sqrt(t - 1) with u required nonzero: widened to
    # t - 1 >= 0 they would claim (1, 0)
    F, d, n = RU ** 2 - RT + 1, R(1), RU
    solutions = _solve(F, d, n, True)
    rng = random.Random(0)
    wide = {operator.gt: operator.ge, operator.lt: operator.le}

    def widened(s):
        return [wide.get(c.operator(), c.operator())(c.lhs(), c.rhs()) for c in s.conditions()]
    assert _violations(F, d, n, solutions, lambda s: s.conditions(), rng)[0] == []
    assert (1, 0) in _violations(F, d, n, solutions, widened, rng)[0]


def test_point_where_required_expression_vanishes_is_dropped():
    # u (u - 1) = 0 with u required nonzero: u = 0 is no solution; with
    # u - t required nonzero (t a parameter) u = 1 exists only for t != 1
    # and u = 0 only for t != 0
    t, u = var('t u')
    assert [s.values() for s in solve_exactly([u * (u - 1)], [u], nonzero=[u])] == [{u: 1}]
    sols = solve_exactly([u * (u - 1)], [u], nonzero=[u - t])
    for s in sols:
        v = s.values()[u]
        assert _holds(s.conditions(), 2)
        assert not _holds(s.conditions(), v)
    # a point inside the zero set of a denominator for all parameter values
    assert len(solve_exactly([u * (u - 1) / u], [u])) == 1


def test_excluded_part_inside_the_zero_set_is_dropped():
    # x z = y is z = y/x for x != 0; its points with x = 0 are the line
    # x = y = 0 (a part solved on its own): where x + y is required
    # nonzero, the line is no solution, and the family needs x + y != 0
    x, y, z = var('x y z')
    sols = solve_exactly([x * z - y], [x, y, z], nonzero=[x + y])
    assert [s.values() for s in sols] == [{x: x, y: y, z: y / x}]
    conditions = sols[0].conditions()
    for point, expected in (({x: 1, y: 2}, True), ({x: 1, y: -1}, False), ({x: 0, y: 1}, False)):
        assert all(bool(c.subs(point)) for c in conditions) is expected


def test_implicit_family_condition_on_its_free_unknown():
    # cos q = x with sin q in a denominator: the family over x is implicit
    # (q bound); sin q = 0 exactly at x = +-1 on it, so its conditions must
    # fail there and hold at every other x in (-1, 1)
    x, q = var('x q')
    (s,) = solve_exactly([(x - cos(q)) / sin(q)], [x, q])
    assert not s.is_explicit() and s.free_unknowns() == [x]
    for at, expected in ((1, False), (-1, False), (QQ((1, 3)), True), (0, True)):
        assert all(bool(c.subs({x: at})) for c in s.conditions()) is expected

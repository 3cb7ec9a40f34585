"""
An implicit family without parameters whose real points the search could
not find (no smooth real point on random fibres) and could not rule out
(quantifier elimination too large or over its time) is never taken for
real: its reality is 'not decided', with :meth:`conditions` the region
where it may be real, and the stationary solutions, their report and
their stability say so. It used to be 'decided', with no condition: a
claim that the family has real points.

The expected facts are elementary: `\\sum x_i^2 + 1 > 0`, and
`t^6 + t + x^6 + x + 3 > 0` (each `s^6 + s` is at least `-5/6^{6/5} > -1`),
so neither zero set has a real point.
"""
from sage.all import var

import sage_dynsym.algebra.solving as solving
from sage_dynsym.algebra.solving import solve_exactly
from sage_dynsym.analysis.stationary import stationary_solutions

t, x = var('t x')
CURVE = t**6 + t + x**6 + x + 3        # no real point


def test_a_family_with_no_real_point_is_not_declared_real():
    unknowns = list(var('x1 x2 x3 x4 x5 x6'))     # beyond quantifier elimination
    sols = solve_exactly([sum(u**2 for u in unknowns) + 1], unknowns)
    assert not [s for s in sols if s.is_reality_decided() and not s.conditions()]


def test_an_undecided_family_without_parameters(monkeypatch):
    # quantifier elimination out of reach: the random fibres find no real
    # point, and nothing proves there is none
    monkeypatch.setattr(solving, 'REALITY_QE_VARIABLES', 0)
    monkeypatch.setattr(solving, 'FAMILY_QE_VARIABLES', 0)
    s, = solve_exactly([CURVE], [t, x])
    assert s.dimension() == 1 and not s.is_explicit()
    assert not s.is_reality_decided()
    assert s.conditions() == []
    assert "where it is real not decided" in repr(s)
    sols = stationary_solutions([CURVE**2 / 2], [t, x])
    family, = [s for s in sols if s.dimension() == 1]
    assert not family.is_reality_decided()
    assert "where it is real not decided" in repr(family)
    assert any("where it is real: not decided" in line for line in sols.report_lines())
    verdict = family.stability()
    assert "not decided" in verdict.reason()

r"""
Critical values of a parameter on the boundary of a stable set

A stable set is given by a region (see :mod:`~sage_dynsym.algebra.regions`)
and its boundaries, polynomial equations `f = 0` (the flutter and
divergence boundaries of :mod:`~sage_dynsym.analysis.spectrum`). Along one
parameter `p`, the stability can change only at a root of a boundary
factor: each root, an exact expression in the other parameters, is a
candidate, and it is critical if the region holds on one side of it and
not on the other. That is decided at sample points of the other
parameters; an answer that differs between samples is refused (the
critical values then depend on the other parameters in a way a list
cannot express). A parameter declared positive has only positive critical
values.

The roots are given in radicals up to degree four (Cardano, Ferrari;
biquadratics denested, `\sqrt a + \sqrt b`: see
:mod:`~sage_dynsym.algebra.radicals`); a factor of higher degree, or a
cubic or quartic that is not biquadratic when every other parameter has a
value, gives exact real algebraic numbers (Sage's ``AA``, printed to any
precision) -- any degree, as long as the other parameters have values.

EXAMPLES: `a x^2 + b x + c` with the condition that both roots are real
and negative, along `b`::

    sage: from sage_dynsym.analysis.critical import critical_values
    sage: b, c = var('b c')
    sage: critical_values([[b > 0, b^2 - 4*c > 0]], {'double root': [b^2 - 4*c == 0]}, b,
    ....:                 positive=[c])
    [2*sqrt(c)]
"""
import random

from sage.rings.rational_field import QQ
from sage.symbolic.ring import SR

from ..arguments import expression_argument
from ..errors import AnalysisError, brief
from ..algebra.conditions import region_holds
from ..algebra.radicals import roots_in_radicals, real_algebraic_roots

__all__ = ['critical_values']


def _candidates(boundaries, parameter, values, complete):
    r"""The roots in ``parameter`` of the boundary factors: in radicals up to
    degree four (with the other parameters given, a cubic or a quartic that
    is not biquadratic as exact real algebraic numbers instead: its radicals
    are complex), otherwise real algebraic numbers when every other
    parameter has a value."""
    found = []
    for relations in boundaries.values():
        for r in relations:
            f = SR(r.lhs() - r.rhs()) if SR(r).is_relational() else SR(r)
            if complete and not _rational(f.subs(values), parameter):
                # irrational coefficients (a number field): exact real roots
                roots = real_algebraic_roots(f.subs(values), parameter,
                                             entry="critical_values")
                found += [v for v in roots if all(v != w for w in found)]
                continue
            for factor, _ in f.factor_list():
                if not factor.has(parameter):
                    continue
                degree = factor.degree(parameter) if factor.is_polynomial(parameter) else None
                biquadratic = degree == 4 and all(factor.coefficient(parameter, k).is_zero()
                                                  for k in (1, 3))
                if degree is not None and (degree <= 2 or biquadratic or
                                           (degree <= 4 and not complete)):
                    roots = roots_in_radicals(factor, parameter, entry="critical_values")
                elif complete:
                    roots = real_algebraic_roots(factor.subs(values), parameter,
                                                 entry="critical_values")
                else:
                    raise AnalysisError(f"the boundary factor {factor} has degree {degree} in "
                                        f"{parameter}: give values to the other parameters "
                                        "(values=) for its roots as exact real algebraic "
                                        "numbers", entry="critical_values")
                found += [v for v in roots if all(str(v) != str(w) for w in found)]
    return found


def _rational(f, parameter):
    try:
        return all(SR(c).pyobject() in QQ for c, _ in f.coefficients(parameter))
    except (TypeError, ValueError):
        return False


def _at(value, point):
    return value.subs(point) if hasattr(value, 'subs') else value


def _real(value):
    try:
        return float(value)
    except (TypeError, ValueError):
        z = complex(value)
        if abs(z.imag) > 1e-12 * (1 + abs(z.real)):
            return None
        return z.real


def critical_values(region, boundaries, parameter, positive=(), values=None, samples=3,
                    seed=0):
    r"""
    The values of ``parameter`` at which it crosses the boundary of
    ``region`` (see the module documentation).

    INPUT:

    - ``region`` -- the stable set, a list of alternatives
    - ``boundaries`` -- dict ``{kind: [f == 0, ...]}``
    - ``parameter`` -- the symbol that varies
    - ``positive`` -- symbols declared positive (sampled positive)
    - ``values`` -- (optional) dict of values of the other parameters; a
      parameter neither given nor declared positive is an error
    - ``samples`` -- (default: 3) the number of sample points
    - ``seed`` -- (default: 0) the seed of the sample points

    OUTPUT: a list of expressions (or of elements of ``AA``), by increasing
    value at the first sample

    EXAMPLES::

        sage: from sage_dynsym.analysis.critical import critical_values
        sage: p, k = var('p k')
        sage: critical_values([[k - p > 0]], {'divergence': [k - p == 0]}, p, positive=[k])
        [k]

    Only inside the declared signs::

        sage: critical_values([[k - p^2 > 0]], {'divergence': [k - p^2 == 0]}, p, positive=[k])
        [-sqrt(k), sqrt(k)]
        sage: critical_values([[k - p^2 > 0]], {'divergence': [k - p^2 == 0]}, p,
        ....:                 positive=[k, p])
        [sqrt(k)]

    A boundary of degree five, the other parameter given::

        sage: critical_values([[p^5 + p - k < 0]], {'divergence': [p^5 + p - k == 0]}, p,
        ....:                 values={k: 3})
        [1.132997565885066?]

    TESTS::

        sage: critical_values([[k - p > 0]], {'divergence': [k - p == 0]}, p)
        Traceback (most recent call last):
        ...
        AnalysisError: critical_values: give a value to k in values= (not declared positive)
        sage: critical_values([[k - p > 0]], {'divergence': [k - p == 0]}, 'p')
        Traceback (most recent call last):
        ...
        AnalysisError: critical_values: expected a parameter (a symbol), got 'p' (str)
        sage: critical_values([[k - p > 0]], {'divergence': [k - p == 0]}, p, values=[1])
        Traceback (most recent call last):
        ...
        AnalysisError: critical_values: values= must be a dict {parameter: number}, got [1]
        sage: critical_values([[p^5 + p - k < 0]], {'divergence': [p^5 + p - k == 0]}, p,
        ....:                 positive=[k])
        Traceback (most recent call last):
        ...
        AnalysisError: critical_values: the boundary factor p^5 - k + p has degree 5 in p: give values to the other parameters (values=) for its roots as exact real algebraic numbers
    """
    parameter = expression_argument(parameter, "critical_values", AnalysisError,
                                    expected="a parameter (a symbol)")
    if not isinstance(values, (dict, type(None))):
        raise AnalysisError(f"values= must be a dict {{parameter: number}}, got {brief(values)}",
                            entry="critical_values")
    symbols = set()
    for alt in region:
        for r in alt:
            symbols |= set(SR(r.lhs() - r.rhs()).variables())
    for relations in boundaries.values():
        for r in relations:
            symbols |= set(SR(r.lhs() - r.rhs()).variables())
    values = {SR(k): v for k, v in (values or {}).items()}
    declared = {str(SR(p)) for p in positive}
    others = sorted((s for s in symbols if s != parameter and s not in values), key=str)
    missing = [s for s in others if str(s) not in declared]
    if missing:
        names = ' and '.join(map(str, missing))
        raise AnalysisError(f"give a value to {names} in values= (not declared positive)",
                            entry="critical_values")
    rng = random.Random(seed)
    points = []
    for _ in range(samples if others else 1):
        point = dict(values)
        point.update({s: QQ(rng.randint(50, 200)) / 100 for s in others})
        points.append(point)
    kept = []
    declared_positive = str(parameter) in declared
    for value in _candidates(boundaries, parameter, values, not others):
        answers = []
        for point in points:
            x = _real(_at(value, point))
            if x is None or (declared_positive and x <= 0):
                answers.append(False)
                continue
            h = 1e-6 * max(1.0, abs(x))
            sides = [region_holds(region, {**point, parameter: y})
                     for y in (x - h, x + h)]
            answers.append(sides[0] != sides[1])
        if len(set(answers)) > 1:
            raise AnalysisError(f"whether {parameter} = {value} is critical depends on the "
                                "other parameters; give their values in values=",
                                entry="critical_values")
        if answers[0]:
            kept.append(_at(value, values) if values else value)
    return sorted(kept, key=lambda v: _real(_at(v, points[0])))

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
cannot express).

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
from ..algebra.radicals import roots_in_radicals


def _candidates(boundaries, parameter):
    found = []
    for relations in boundaries.values():
        for r in relations:
            f = SR(r.lhs() - r.rhs()) if SR(r).is_relational() else SR(r)
            for factor, _ in f.factor_list():
                if factor.has(parameter):
                    roots = roots_in_radicals(factor, parameter, entry="critical_values")
                    found += [v for v in roots if all(str(v) != str(w) for w in found)]
    return found


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

    OUTPUT: a list of expressions, by increasing value at the first sample

    EXAMPLES::

        sage: from sage_dynsym.analysis.critical import critical_values
        sage: p, k = var('p k')
        sage: critical_values([[k - p > 0]], {'divergence': [k - p == 0]}, p, positive=[k])
        [k]

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
    for value in _candidates(boundaries, parameter):
        answers = []
        for point in points:
            x = _real(value.subs(point))
            if x is None:
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
            kept.append(value.subs(values) if values else value)
    return sorted(kept, key=lambda v: _real(v.subs(points[0])))

r"""
Regions of parameter space: disjunctions of conjunctions of relations

A *region* is a list of alternatives, each a list of relations (Sage
relationals such as ``a - b > 0``, ``g*nu == 0``); it is the union of the
alternatives, each the intersection of its relations. ``[[]]`` is the
whole space, ``[]`` the empty set. The stability verdicts partition the
parameter space into such regions, one per verdict (the boundaries, where
a strict condition is zero, belong to none of them: they are sets of
measure zero where the first approximation changes).

The helpers here join, negate and partition regions, simplifying each
conjunction with :func:`~sage_dynsym.algebra.conditions.simplify_conjunction`
(signs known from one relation are used in the others, contradictions
drop the alternative, declared positive symbols are used).

EXAMPLES::

    sage: from sage_dynsym.algebra.regions import negation, intersection, partition
    sage: a, b = var('a b')
    sage: negation([[a > 0, b > 0]])
    [[a < 0], [b < 0]]
    sage: intersection([[a > 0]], [[a < 0], [b < 0]])
    [[a > 0, b < 0]]
    sage: partition([('inside', [[a > 0, b > 0]])], rest='outside')
    [('inside', [[a > 0, b > 0]]), ('outside', [[a < 0], [b < 0]])]
"""
import random

from sage.ext.fast_callable import fast_callable
from sage.rings.rational_field import QQ
from sage.symbolic.ring import SR

from ..errors import AnalysisError
from .conditions import simplify_conjunction, holds

__all__ = ['WITNESS_SAMPLES', 'EMPTINESS_TIMEOUT', 'MAX_ALTERNATIVES', 'simplify_region',
           'intersection', 'negation', 'prune_empty', 'partition', 'MAX_REDUNDANCY_RELATIONS',
           'drop_redundant']

#: Random points tried for a witness of an alternative before quantifier
#: elimination is asked whether it is empty.
WITNESS_SAMPLES = 400

#: Seconds of processor time given to QEPCAD to decide that an alternative
#: is empty.
EMPTINESS_TIMEOUT = 20

#: More alternatives than this in one region are not simplified further:
#: the negation of a long disjunction grows as a product.
MAX_ALTERNATIVES = 400

_FLIP = {'gt': lambda e: e < 0, 'lt': lambda e: e > 0, 'ge': lambda e: e < 0,
         'le': lambda e: e > 0, 'eq': lambda e: e != 0}


def _parts(relation):
    r = SR(relation)
    if not r.is_relational():
        return r, 'gt'
    return r.lhs() - r.rhs(), r.operator().__name__


def simplify_region(alternatives, positive=()):
    r"""
    Each alternative simplified, impossible ones dropped, duplicates and
    alternatives implied by a weaker one (a subset of its relations)
    removed; ``[[]]`` as soon as one alternative always holds.

    INPUT:

    - ``alternatives`` -- a region (list of lists of relations)
    - ``positive`` -- symbols declared positive

    OUTPUT: a region

    EXAMPLES::

        sage: from sage_dynsym.algebra.regions import simplify_region
        sage: a, b, m = var('a b m')
        sage: simplify_region([[a > 0, a < 0], [m*b > 0], [b > 0, a > 1]], positive=[m])
        [[b > 0]]
        sage: simplify_region([[m > 0]], positive=[m])
        [[]]
    """
    result, keys = [], []
    for alt in alternatives:
        simple = simplify_conjunction(list(alt), positive)
        if simple is None or _contradictory(simple):
            continue
        if not simple:
            return [[]]
        key = frozenset(map(str, simple))
        if any(k <= key for k in keys):
            continue
        kept = [(r, k) for r, k in zip(result, keys) if not key <= k]
        result, keys = [r for r, _ in kept] + [simple], [k for _, k in kept] + [key]
    return result


def _contradictory(relations):
    r"""Whether relations on the same expression exclude each other
    (``e == 0`` and ``e != 0``; ``e > 0`` and ``e == 0``; ...), or bounds
    on one variable leave an empty interval."""
    signs = {}
    low, high = {}, {}
    for e, op in map(_parts, relations):
        e = e.expand()
        allowed = {'gt': {1}, 'lt': {-1}, 'ge': {0, 1}, 'le': {-1, 0}, 'eq': {0},
                   'ne': {-1, 1}}[op]
        key = str(e)
        if key not in signs and str(-e) in signs:
            key, allowed = str(-e), {-s for s in allowed}
        signs[key] = signs.get(key, {-1, 0, 1}) & allowed
        if not signs[key]:
            return True
        variables = e.variables()
        if len(variables) == 1 and op in ('gt', 'lt') and e.is_polynomial(variables[0]) \
                and e.degree(variables[0]) == 1:
            x = variables[0]
            c, d = e.coefficient(x, 1), e.coefficient(x, 0)
            if not (c.is_numeric() and d.is_numeric()):
                continue
            bound, above = (-d / c).pyobject(), (op == 'gt') == bool(c > 0)
            name = str(x)
            if above:
                low[name] = max(low.get(name, bound), bound)
            else:
                high[name] = min(high.get(name, bound), bound)
            if name in low and name in high and low[name] >= high[name]:
                return True
    return False


def intersection(first, second, positive=()):
    r"""
    The intersection of two regions (distributed, then simplified).

    EXAMPLES::

        sage: from sage_dynsym.algebra.regions import intersection
        sage: a, b = var('a b')
        sage: intersection([[a > 0], [b > 0]], [[a < 0]])
        [[b > 0, a < 0]]
        sage: intersection([[]], [[a > 0]]), intersection([], [[a > 0]])
        ([[a > 0]], [])
    """
    return simplify_region([list(x) + list(y) for x in first for y in second], positive)


def negation(alternatives, positive=()):
    r"""
    The complement of a region up to its boundary: ``f > 0`` becomes
    ``f < 0`` (the zero set of `f`, of measure zero, is left out), ``f >=
    0`` becomes ``f < 0``, ``f == 0`` becomes ``f != 0``; ``f != 0`` holds
    up to a set of measure zero, so its complement is left out.

    OUTPUT: a region; ``None`` if it would have more than
    :data:`MAX_ALTERNATIVES` alternatives

    EXAMPLES::

        sage: from sage_dynsym.algebra.regions import negation
        sage: a, b = var('a b')
        sage: negation([[a > 0], [b == 0, a < 1]])
        [[a < 0, b != 0]]
        sage: negation([[]]), negation([]), negation([[a != 0]])
        ([], [[]], [])
    """
    result = [[]]
    for alt in alternatives:
        options = [_FLIP[op](e) for e, op in map(_parts, alt) if op != 'ne']
        result = simplify_region([r + [o] for r in result for o in options], positive)
        if len(result) > MAX_ALTERNATIVES:
            return None
    return result


_HOLDS = {'gt': lambda x: x > 0, 'lt': lambda x: x < 0, 'ge': lambda x: x >= 0,
          'le': lambda x: x <= 0, 'ne': lambda x: x != 0, 'eq': lambda x: x == 0}


def _witness(alternative, positive, rng):
    r"""A point (rational values) where ``alternative`` holds, found by
    sampling (positive symbols positive, the others of both signs, over
    four orders of magnitude), or ``None``."""
    parts = [_parts(r) for r in alternative]
    if any(op == 'eq' for _, op in parts):
        return None
    variables = sorted({v for e, _ in parts for v in e.variables()}, key=str)
    if not variables:
        return {}
    declared = {str(SR(p)) for p in positive}
    try:
        functions = [(fast_callable(e, vars=variables, domain=float), _HOLDS[op])
                     for e, op in parts]
    except (TypeError, ValueError, NotImplementedError):
        return None
    for _ in range(WITNESS_SAMPLES):
        point = [10 ** rng.uniform(-2, 2) * (1 if str(v) in declared else rng.choice((-1, 1)))
                 for v in variables]
        try:
            if not all(test(f(*point)) for f, test in functions):
                continue
        except (ValueError, ZeroDivisionError, OverflowError):
            continue
        exact = {v: QQ(x) for v, x in zip(variables, point)}
        try:
            if all(holds(r, exact) for r in alternative):
                return exact
        except (TypeError, ValueError, ZeroDivisionError):
            continue
    return None


def prune_empty(alternatives, positive=(), seed=0, timeout=EMPTINESS_TIMEOUT):
    r"""
    Drop the alternatives that are empty: an alternative is kept when a
    sample point satisfies it (checked exactly), dropped when quantifier
    elimination (QEPCAD, with the positive symbols positive) proves that
    no point does, and kept when neither decides (an equation among its
    relations, QEPCAD unavailable or out of time).

    INPUT:

    - ``alternatives`` -- a region
    - ``positive`` -- symbols declared positive
    - ``seed`` -- (default: 0) the seed of the sampling
    - ``timeout`` -- (default: :data:`EMPTINESS_TIMEOUT`) seconds allowed
      to QEPCAD for each alternative

    OUTPUT: a region

    EXAMPLES: with `a, b > 0` the first alternative is empty, because
    `(a - b)^2 < (a + b)^2`::

        sage: from sage_dynsym.algebra.regions import prune_empty
        sage: a, b, x = var('a b x')
        sage: prune_empty([[x - a - b > 0, 2*(a + b)*x - (a - b)^2 < 0], [x > 0]],
        ....:             positive=[a, b])
        [[x > 0]]
    """
    from .quantifier_elimination import exists
    rng = random.Random(seed)
    kept = []
    for alt in alternatives:
        if not alt or _witness(alt, positive, rng) is not None:
            kept.append(alt)
            continue
        variables = sorted({v for r in alt for v in _parts(r)[0].variables()}, key=str)
        declared = [v for v in variables if str(v) in {str(SR(p)) for p in positive}]
        try:
            if exists(variables, list(alt) + [v > 0 for v in declared],
                      timeout=timeout) == []:
                continue
        except AnalysisError:
            pass
        kept.append(alt)
    return kept


def partition(parts, rest=None, domain=((),), positive=()):
    r"""
    Make the regions of ``parts`` disjoint: each keeps what the earlier
    parts did not take; the part ``rest`` (if named) gets the complement
    of all of them. Everything is taken inside ``domain``.

    INPUT:

    - ``parts`` -- list of pairs ``(name, region)``, by precedence
    - ``rest`` -- (optional) the name of the part that gets the rest
    - ``domain`` -- (default: everywhere) a region
    - ``positive`` -- symbols declared positive

    OUTPUT: list of pairs ``(name, region)`` with nonempty regions, in the
    given order; the region of ``rest`` is ``None`` if the complement is too
    large to write out (see :func:`negation`)

    EXAMPLES::

        sage: from sage_dynsym.algebra.regions import partition
        sage: a, b = var('a b')
        sage: partition([('A', [[a > 0]]), ('B', [[b > 0]])], rest='C', domain=[[b != 1]])
        [('A', [[a > 0, b - 1 != 0]]),
         ('B', [[b > 0, a < 0, b - 1 != 0]]),
         ('C', [[a < 0, b < 0, b - 1 != 0]])]
    """
    domain = simplify_region([list(d) for d in domain], positive)
    taken = []          # the parts' own regions, without the domain
    result = []
    for name, region in parts:
        if region is None:
            continue
        own = intersection(domain, region, positive)
        for earlier in taken:
            if not own:
                break
            complement = negation(earlier, positive)
            own = intersection(own, complement, positive) if complement is not None else own
        if own:
            result.append((name, own))
            taken.append(simplify_region(region, positive))
    if rest is not None:
        own = domain
        for earlier in taken:
            complement = negation(earlier, positive)
            if complement is None:
                own = None
                break
            own = intersection(own, complement, positive)
        if own is None or own:
            result.append((rest, own))
    return result


#: Regions with more relations than this are not searched for redundant
#: ones (each test may ask quantifier elimination).
MAX_REDUNDANCY_RELATIONS = 8


def drop_redundant(alternatives, positive=()):
    r"""
    The region without redundant parts, up to sets of measure zero: a
    strict relation implied by the others of its alternative is dropped,
    then an alternative contained in another one. Each implication is
    proved by :func:`prune_empty` (the alternative with the relation
    flipped is empty); what is not proved is kept. Regions with more than
    :data:`MAX_REDUNDANCY_RELATIONS` relations are returned as they are.

    EXAMPLES: `x > 4ab` implies `2x > ab` when `a, b > 0`::

        sage: from sage_dynsym.algebra.regions import drop_redundant
        sage: a, b, x = var('a b x')
        sage: drop_redundant([[x - 4*a*b > 0, 2*x - a*b > 0]], positive=[a, b])
        [[-4*a*b + x > 0]]
        sage: drop_redundant([[2*x - a*b < 0], [x - 4*a*b < 0]], positive=[a, b])
        [[-4*a*b + x < 0]]
        sage: drop_redundant([[x > 0], [a - x > 0]])
        [[x > 0], [a - x > 0]]
    """
    alternatives = [list(alt) for alt in alternatives]
    if sum(len(alt) for alt in alternatives) > MAX_REDUNDANCY_RELATIONS:
        return alternatives

    def empty(relations):
        return relations and not prune_empty([relations], positive)

    result = []
    for alt in alternatives:
        kept = list(alt)
        for r in alt:
            e, op = _parts(r)
            others = [s for s in kept if s is not r]
            if op in ('gt', 'lt') and others and empty(others + [_FLIP[op](e)]):
                kept = others
        result.append(kept)
    final = []
    for k, alt in enumerate(result):
        # contained in a kept alternative, or in a later one: the earlier
        # of two equal alternatives goes, the later stays
        if not any(other and all(empty(alt + c) for c in (negation([other], positive) or [[]]))
                   for other in final + result[k + 1:]):
            final.append(alt)
    return final

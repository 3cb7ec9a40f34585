r"""
Conditions on parameters, as Sage relationals

A *condition* is a relational such as ``R*w^2 - g > 0`` or ``A1 != 0``.
The helpers here turn "this expression must be positive / nonzero" into a
short list of factored relationals, using what is declared positive:

- constant positive factors and factors that are positive because all their
  coefficients are positive in variables declared positive are dropped;
- factors of even multiplicity are dropped (only their zero set, a
  boundary, is lost), so ``m^2*(a - b) > 0`` becomes ``a - b > 0``;
- a condition that can never hold is reported as such (``None``), one that
  always holds gives ``[]``.

Non-polynomial parts (``cos(alpha)``, ``sqrt(g*l)``, derivatives of
unspecified functions) are kept as atoms; square roots count as positive
(they are taken where they are real).

Lists of conditions ``f > 0`` on polynomials (the Hurwitz and
Liénard--Chipart conditions) are simplified without leaving the polynomial
rings by :func:`reduce_conditions` (:func:`simplify_conditions` for
symbolic input).

EXAMPLES::

    sage: from sage_dynsym.algebra.conditions import positive_conditions, nonzero_conditions
    sage: R, w, g, m = var('R w g m')
    sage: positive_conditions(R^2*w^4 - g^2, positive=[R, w, g])
    [R*w^2 - g > 0]
    sage: positive_conditions(-m^2*g, positive=[g]) is None
    True
    sage: positive_conditions(m^2 + 1)
    []
    sage: positive_conditions(-cos(R))
    [cos(R) < 0]
    sage: nonzero_conditions(2*m*(R - g)^2, positive=[m])
    [R - g != 0]
"""
from sage.misc.misc_c import prod
from sage.rings.rational_field import QQ
from sage.structure.element import Element
from sage.symbolic.ring import SR

from .polynomials import (positive_polynomial, odd_factors, parameter_ring, to_ring, to_sr,
                          is_constant, constant_value, is_polynomial_ring, FACTOR_LIMIT)
from .translation import translate_expressions

__all__ = ['Unexpanded', 'simplify_conditions', 'reduce_conditions', 'conditions_as_expressions',
           'positive_conditions', 'positive_conditions_all', 'nonzero_conditions',
           'simplify_conjunction', 'conjunction', 'holds', 'region_holds', 'as_relational']


def _relational(T, factors, op):
    r"""``prod(factors) op 0``, factored, with a positive leading
    coefficient on the left (``-f > 0`` is written ``f < 0``)."""
    flip = {'>': '<', '<': '>', '!=': '!=', '==': '=='}
    p = prod(factors)
    if not is_constant(p) and p.lc() < 0:
        p, op = -p, flip[op]
    e = T.factored(p)
    return {'>': e > 0, '<': e < 0, '!=': e != 0, '==': e == 0}[op]


# ---------------------------------------------------------------------------
# lists of polynomial conditions f > 0, in the polynomial rings
# ---------------------------------------------------------------------------

class Unexpanded:
    r"""
    A condition ``expr > 0`` kept as a symbolic expression, not expanded
    into a polynomial (a Hurwitz determinant over the budget, written in
    the coefficients): :func:`reduce_conditions` passes it through as it
    is.

    EXAMPLES::

        sage: from sage_dynsym.algebra.conditions import (Unexpanded, reduce_conditions,
        ....:                                             conditions_as_expressions)
        sage: a, b = var('a b')
        sage: R.<a, b> = QQ[]
        sage: entries = reduce_conditions([a*b^2, Unexpanded(SR('(a - 1)*(b + 1)'))], [])
        sage: conditions_as_expressions(entries)
        [a, (a - 1)*(b + 1)]
    """

    def __init__(self, expr):
        self.expr = expr


def _positive_names(positive):
    return {str(p) for p in positive}


def _simplify_one(f, positive):
    r"""
    Reduce the condition ``f > 0`` to ``g > 0`` (a polynomial or unexpanded
    expression), or ``None`` if it always holds. Returns ``(g, factors)``
    where ``factors`` is the set of odd-power factors kept.
    """
    if isinstance(f, Unexpanded):
        return f.expr, None
    if is_constant(f):
        c = constant_value(f)
        return (None, None) if c > 0 else (f.parent()(c.sign()), None)
    if positive_polynomial(f, positive):
        return None, None
    if positive_polynomial(-f, positive):
        return f.parent()(-1), None
    if len(f.dict()) > FACTOR_LIMIT:
        return f, frozenset([f])
    sign, kept = odd_factors(f.factor(), positive)
    if not kept:
        return (None, None) if sign > 0 else (f.parent()(-1), None)
    product = sign
    for g in kept:
        product *= g
    if len(kept) == 1 and sign < 0:
        kept = [-kept[0]]
        sign = 1
    return product, (frozenset(kept) if sign > 0 else frozenset([product]))


def simplify_conditions(conditions, positive=()):
    r"""
    Simplify a list of polynomial conditions ``f > 0``.

    INPUT:

    - ``conditions`` -- list of polynomials (or symbolic expressions
      polynomial in their variables)
    - ``positive`` -- (default: ``()``) variables known to be positive

    OUTPUT: list of symbolic expressions, all to be ``> 0``, equivalent to
    the input (up to the zero sets of even-power factors); if a condition
    can never hold the list is just one nonpositive constant

    EXAMPLES::

        sage: from sage_dynsym.algebra.conditions import simplify_conditions
        sage: a, b, m = var('a b m')
        sage: simplify_conditions([m^2*(a - b), 2*m*a, a - b, a*b], positive=[m])
        [a - b, a, b]
        sage: simplify_conditions([a, -3*m, a*b], positive=[m])
        [-1]
        sage: simplify_conditions([a, b, 4*a*b], positive=[m])
        [a, b]

    A condition implied by another one (their difference is positive on
    the positive variables) is removed::

        sage: simplify_conditions([a^2 - 2*m*b, a^2 - 4*m*b, b], positive=[m, b])
        [a^2 - 4*b*m]
    """
    native = lambda f: isinstance(f, Unexpanded) or (
        isinstance(f, Element) and is_polynomial_ring(f.parent()))
    symbols = set()
    for f in conditions:
        if not native(f):
            symbols |= set(SR(f).variables())
    ring = parameter_ring(symbols)
    polys = [f if native(f) else to_ring(SR(f), ring, "condition") for f in conditions]
    return conditions_as_expressions(reduce_conditions(polys, positive))


def reduce_conditions(polys, positive):
    r"""
    The conditions ``f > 0`` for ``f`` in ``polys`` (polynomials over `\QQ`,
    or :class:`Unexpanded`), simplified as :func:`simplify_conditions`
    does, without leaving the polynomial rings.

    INPUT:

    - ``polys`` -- a list of polynomials (or :class:`Unexpanded`)
    - ``positive`` -- the variables (or their names) known to be positive

    OUTPUT: a list of entries, each a tuple of factors (their product is
    required ``> 0``) or an :class:`Unexpanded`; a single entry with one
    nonpositive constant when the conditions cannot hold

    EXAMPLES::

        sage: from sage_dynsym.algebra.conditions import reduce_conditions
        sage: R.<a, b, m> = QQ[]
        sage: reduce_conditions([m^2*(a - b), 2*m*a, a*b], ['m'])
        [(a - b,), (a,), (b,)]
        sage: reduce_conditions([a, -m], ['m'])
        [(-1,)]
    """
    positive = _positive_names(positive)
    result = []
    known = []          # single factors already required to be positive
    for f in polys:
        g, fs = _simplify_one(f, positive)
        if g is None:
            continue
        if fs is None:
            result.append(Unexpanded(g) if isinstance(f, Unexpanded) else (g,))
            continue
        rest = [h for h in fs if h not in known]
        if not rest:
            continue
        if len(rest) == 1:
            known.append(rest[0])
        result.append(tuple(sorted(rest, key=_order_key)))
    impossible = [e for e in result if not isinstance(e, Unexpanded)
                  and len(e) == 1 and is_constant(e[0])]
    return impossible[:1] if impossible else _drop_implied(result, positive)


def _drop_implied(entries, positive):
    r"""
    Remove single-factor conditions `f > 0` implied by another one
    `g > 0`: when `f - c g` (for some `c > 0`) has only positive
    coefficients and only variables known to be positive.
    """
    single = [e[0] for e in entries if not isinstance(e, Unexpanded) and len(e) == 1]

    def implied_by(f, g):
        if f.parent() is not g.parent() or len(g.dict()) > 50:
            return False
        # the multiple c of g must cancel every term of f outside the
        # positive variables: try the ratios of common coefficients
        for monomial, coefficient in g.dict().items():
            c = f.dict().get(monomial, 0) / coefficient
            if c <= 0:
                continue
            d = f - c * g
            if (not d.is_zero() and all(str(v) in positive for v in d.variables())
                    and all(a > 0 for a in d.coefficients())):
                return True
        return False

    dropped = {i for i, f in enumerate(single)
               if any(j != i and implied_by(f, g) for j, g in enumerate(single))}
    drop = [single[i] for i in dropped]
    return [e for e in entries if isinstance(e, Unexpanded) or len(e) != 1
            or e[0] not in drop]


def _order_key(f):
    n = len(f.dict())
    return (n, str(f) if n < 1000 else '')


def conditions_as_expressions(entries):
    r"""
    The entries of :func:`reduce_conditions` as symbolic expressions (each
    ``> 0``): the product of an entry's factors, an unexpanded one as it is.

    EXAMPLES::

        sage: from sage_dynsym.algebra.conditions import (reduce_conditions,
        ....:                                             conditions_as_expressions)
        sage: R.<a, b> = QQ[]
        sage: conditions_as_expressions(reduce_conditions([a^3*b], []))
        [a*b]
    """
    return [e.expr if isinstance(e, Unexpanded) else prod(to_sr(h) for h in e)
            for e in entries]


# ---------------------------------------------------------------------------
# conditions on symbolic expressions, as relationals
# ---------------------------------------------------------------------------

def positive_conditions(expr, positive=()):
    r"""
    The condition ``expr > 0`` as a list of relationals (all must hold),
    ``[]`` if it always holds, ``None`` if it never holds.

    INPUT:

    - ``expr`` -- a symbolic expression, rational in its symbols (other
      parts are atoms)
    - ``positive`` -- symbols declared positive

    EXAMPLES::

        sage: from sage_dynsym.algebra.conditions import positive_conditions
        sage: a, b = var('a b')
        sage: positive_conditions((a - b)/b^3)
        [(a - b)*b > 0]
        sage: positive_conditions((a - b)/b^3, positive=[b])
        [a - b > 0]
    """
    return positive_conditions_all([expr], positive)


def positive_conditions_all(expressions, positive=(), nonzero=()):
    r"""
    The conjunction of ``e > 0`` for every ``e`` in ``expressions`` (and of
    ``e != 0`` for every ``e`` in ``nonzero``): simplified relationals,
    ``[]`` if they always hold, ``None`` if they cannot all hold.
    Conditions implied by others are dropped.

    EXAMPLES::

        sage: from sage_dynsym.algebra.conditions import positive_conditions_all
        sage: a, b, m = var('a b m')
        sage: positive_conditions_all([a, a*b, m*b], positive=[m])
        [a > 0, b > 0]
        sage: positive_conditions_all([a, -a^2 - 1]) is None
        True
    """
    if not expressions and not nonzero:
        return []
    T, fractions = translate_expressions(list(expressions) + list(nonzero))
    required = fractions[len(expressions):]
    fractions = fractions[:len(expressions)]
    polys = [f.numerator() * f.denominator() for f in fractions]
    flat = T.flat_ring()
    if flat is None:
        return [] if all(QQ(p) > 0 for p in polys) and all(f != 0 for f in required) \
            else None
    names = T.positive_names(positive)
    odd, nonzero = [], []
    for f in required:
        num = flat(f.numerator())
        if num == 0:
            return None
        if not is_constant(num):
            for g, _ in num.factor():
                g = g if g.lc() > 0 else -g
                if not positive_polynomial(g, names) and all(g != h for h in nonzero):
                    nonzero.append(g)
    for p in map(flat, polys):
        part, even = _split_even_factors(p, names)
        odd.append(part)
        for g in even:
            if all(g != h for h in nonzero):
                nonzero.append(g)
    entries = reduce_conditions(odd, names) if odd else []
    if len(entries) == 1 and len(entries[0]) == 1 and is_constant(entries[0][0]):
        if constant_value(entries[0][0]) <= 0:
            return None
        entries = []
    entries = _propagate_signs(entries, nonzero, names)
    if entries is None:
        return None
    return [_relational(T, [sign * prod(factors)], '>') for sign, factors in entries] + \
        [_relational(T, [g], '!=') for g in nonzero]


def _propagate_signs(entries, nonzero, names):
    r"""
    Simplify a conjunction of conditions ``product > 0`` (``entries`` from
    :func:`reduce_conditions`) with the signs that
    other conditions fix: in ``a < 0, a*b > 0`` the second becomes
    ``b < 0`` (likewise for a product of several factors whose sign is
    known); a factor that is a sum of even powers with positive
    coefficients is positive once one of its terms is known nonzero.
    Returns a list of ``(sign, factors)``, or ``None`` if impossible; the
    factors of even multiplicity in ``nonzero`` that occur in a strict
    condition are removed from it (they are nonzero anyway).
    """
    work = []
    for entry in entries:
        F = prod(entry).factor()
        sign = QQ(F.unit()).sign()
        factors = []
        for g, _ in F:
            if g.lc() < 0:
                g, sign = -g, -sign
            factors.append(g)
        work.append([sign, factors])
    changed = True
    while changed:
        changed = False
        known = [(w[0], set(map(str, w[1]))) for w in work if w[1]]
        in_conditions = {str(g) for w in work for g in w[1]}
        nonzero_vars = {str(g) for g in list(nonzero) if g.is_gen()} | \
            {str(g) for w in work for g in w[1] if g.is_gen()}
        for w in work:
            names_w = set(map(str, w[1]))
            for sign, k in known:
                if k and k < names_w:
                    w[1] = [g for g in w[1] if str(g) not in k]
                    w[0] *= sign
                    names_w -= k
                    changed = True
            kept = [g for g in w[1] if not _nonnegative(g, names, nonzero_vars)]
            if kept != w[1] and (kept or len(w[1]) > 0):
                w[1] = kept
                changed = True
        nonzero[:] = [g for g in nonzero if str(g) not in in_conditions]
    result, seen = [], {}
    for sign, factors in work:
        if not factors:
            if sign <= 0:
                return None
            continue
        key = tuple(sorted(str(g) for g in factors))
        if key in seen:
            if seen[key] != sign:
                return None
            continue
        seen[key] = sign
        result.append((sign, factors))
    return result


def _nonnegative(f, names, nonzero_vars):
    r"""Whether ``f`` is positive: positive coefficients, even powers of the
    variables not declared positive, and a term whose variables are all
    positive or known nonzero."""
    if any(c <= 0 for c in f.coefficients()):
        return False
    gens = [str(g) for g in f.parent().gens()]
    strict = False
    for exps in f.exponents():
        exps = (exps,) if isinstance(exps, int) else exps
        if any(e % 2 for k, e in enumerate(exps) if gens[k] not in names):
            return False
        if all(gens[k] in names or gens[k] in nonzero_vars for k, e in enumerate(exps) if e):
            strict = True
    return strict


def _split_even_factors(p, names):
    r"""``p`` without its factors of even multiplicity (that are not
    positive by the declarations), and those factors: `f^2 g > 0` iff
    `g > 0` and `f \ne 0`."""
    if is_constant(p) or len(p.dict()) > FACTOR_LIMIT:
        return p, []
    F = p.factor()
    rest, even = p.parent()(F.unit()), []
    for g, e in F:
        if e % 2 == 0 and not positive_polynomial(g, names) and \
                not positive_polynomial(-g, names):
            even.append(g if g.lc() > 0 else -g)
        else:
            rest *= g ** e
    return rest, even


def nonzero_conditions(expr, positive=()):
    r"""
    The condition ``expr != 0`` as relationals ``factor != 0`` (one per
    distinct factor not known to be nonzero); ``[]`` if it always holds,
    ``None`` if ``expr`` is zero.

    EXAMPLES::

        sage: from sage_dynsym.algebra.conditions import nonzero_conditions
        sage: a, b = var('a b')
        sage: nonzero_conditions(a^2*b/(a + 1))
        [b != 0, a != 0]
        sage: nonzero_conditions(SR(0)) is None, nonzero_conditions(3)
        (True, [])
    """
    T, (f,) = translate_expressions([expr])
    num = f.numerator()
    if num == 0:
        return None
    flat = T.flat_ring()
    if flat is None or is_constant(flat(num)):
        return []
    names = T.positive_names(positive)
    result = []
    for factor, _ in flat(num).factor():
        if positive_polynomial(factor, names) or positive_polynomial(-factor, names):
            continue
        result.append(_relational(T, [factor], '!='))
    return result


def simplify_conjunction(conditions, positive=()):
    r"""
    Simplify a conjunction of relationals together (signs fixed by one
    condition are used in the others, implied conditions dropped):
    ``[]`` if it always holds, ``None`` if it never does.

    EXAMPLES::

        sage: from sage_dynsym.algebra.conditions import simplify_conjunction
        sage: a, b = var('a b')
        sage: simplify_conjunction([a < 0, a*b > 0, b != 1])
        [a < 0, b < 0, b - 1 != 0]
        sage: simplify_conjunction([a > 0, a < 0]) is None
        True
    """
    strict, nonzero, others = [], [], []
    for c in conditions:
        c = as_relational(c)
        e = c.lhs() - c.rhs()
        op = c.operator().__name__
        if op == 'gt':
            strict.append(e)
        elif op == 'lt':
            strict.append(-e)
        elif op == 'ne':
            nonzero.append(e)
        else:
            others.append(c)
    kept = positive_conditions_all(strict, positive, nonzero)
    if kept is None:
        return None
    rest = []
    for c in others:
        e = c.lhs() - c.rhs()
        op = c.operator().__name__
        if op == 'eq' and e.is_numeric():
            if not e.is_zero():
                return None
        elif op in ('ge', 'le') and e.is_numeric():
            if not (e >= 0 if op == 'ge' else e <= 0):
                return None
        else:
            rest.append(c)
    return conjunction(kept, rest)


def conjunction(*lists):
    r"""
    Join condition lists (``None`` -- impossible -- absorbs), removing
    duplicates.

    EXAMPLES::

        sage: from sage_dynsym.algebra.conditions import conjunction
        sage: a = var('a')
        sage: conjunction([a > 0], [a > 0, a != 1]), conjunction([a > 0], None)
        ([a > 0, a != 1], None)
    """
    result, seen = [], set()
    for conds in lists:
        if conds is None:
            return None
        for c in conds:
            key = str(c)
            if key not in seen:
                seen.add(key)
                result.append(c)
    return result


def holds(condition, values):
    r"""
    Whether a relational holds at numerical ``values`` (a dict); used to
    test regions at sample points.

    EXAMPLES::

        sage: from sage_dynsym.algebra.conditions import holds
        sage: a, b = var('a b')
        sage: holds(a - b > 0, {a: 2, b: 1}), holds(a != 1, {a: 1})
        (True, False)
    """
    lhs = float((condition.lhs() - condition.rhs()).subs(values))
    op = condition.operator()
    return bool(op(lhs, 0))


def region_holds(alternatives, values):
    r"""
    Whether a disjunction of conjunctions of relationals holds at ``values``.

    EXAMPLES::

        sage: from sage_dynsym.algebra.conditions import region_holds
        sage: a = var('a')
        sage: region_holds([[a > 1], [a < -1]], {a: -2}), region_holds([], {a: 0})
        (True, False)
    """
    return any(all(holds(c, values) for c in alt) for alt in alternatives)


def as_relational(expr):
    r"""
    An expression ``e`` (meaning ``e > 0``, the convention of the criteria)
    as the relational ``e > 0``; relationals pass unchanged.

    EXAMPLES::

        sage: from sage_dynsym.algebra.conditions import as_relational
        sage: a = var('a')
        sage: as_relational(a - 1), as_relational(a != 0)
        (a - 1 > 0, a != 0)
    """
    e = SR(expr)
    return e if e.is_relational() else e > 0

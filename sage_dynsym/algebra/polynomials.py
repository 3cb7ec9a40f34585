r"""
Conversions between symbolic expressions and Sage polynomial rings

The heavy algebra of the package is done over polynomial rings with
rational coefficients (Singular), and only the results are converted back
to ``SR``. This module holds the conversions, a few tests on ring elements
and the guard around Maxima's questions about signs.

EXAMPLES::

    sage: from sage_dynsym.algebra.polynomials import parameter_ring, to_ring, to_sr
    sage: a, b = var('a b')
    sage: R = parameter_ring([a, b]); f = to_ring(a^2 - b/2, R); f, f.parent() is R
    (a^2 - 1/2*b, True)
    sage: to_sr(f)
    a^2 - 1/2*b
"""
from sage.rings.polynomial.multi_polynomial_ring_base import MPolynomialRing_base
from sage.rings.polynomial.polynomial_ring import PolynomialRing_generic
from sage.rings.polynomial.polynomial_ring_constructor import PolynomialRing
from sage.rings.rational_field import QQ
from sage.symbolic.ring import SR
from sage.structure.element import Element

import re
from contextlib import contextmanager, nullcontext

from ..errors import AnalysisError

__all__ = ['FACTOR_LIMIT', 'parameter_ring', 'to_ring', 'to_sr', 'polynomial_to_sr',
           'is_polynomial_ring', 'is_constant', 'constant_value', 'positive_polynomial',
           'odd_factors', 'maxima_without_questions']

#: Polynomials with more terms than this are not factored.
FACTOR_LIMIT = 3000


def parameter_ring(symbols, extra=()):
    r"""
    The polynomial ring over `\QQ` in the given symbols (sorted by name).

    EXAMPLES::

        sage: from sage_dynsym.algebra.polynomials import parameter_ring
        sage: parameter_ring([var('b'), var('a')])
        Multivariate Polynomial Ring in a, b over Rational Field
    """
    names = sorted({str(s) for s in symbols}) + [str(s) for s in extra]
    if not names:
        return QQ
    return PolynomialRing(QQ, names, len(names))


def to_ring(expr, ring, what="expression"):
    r"""
    Convert a symbolic expression that is polynomial in the generators of
    ``ring`` into an element of ``ring``; raise :class:`AnalysisError`
    otherwise.

    EXAMPLES::

        sage: from sage_dynsym.algebra.polynomials import to_ring
        sage: R = PolynomialRing(QQ, 'x,y')
        sage: to_ring(SR('x^2/2 + y'), R)
        1/2*x^2 + y
        sage: to_ring(sin(x), R, "right-hand side")
        Traceback (most recent call last):
        ...
        AnalysisError: right-hand side: expected a polynomial in x, y with rational coefficients, got sin(x)
    """
    if isinstance(expr, Element) and expr.parent() is ring:
        return expr
    try:
        return ring(SR(expr).expand()) if ring is QQ else SR(expr).polynomial(ring=ring)
    except (TypeError, ValueError, NotImplementedError, AttributeError) as err:
        gens = ', '.join(map(str, ring.gens())) if ring is not QQ else 'constants'
        raise AnalysisError(f"expected a polynomial in {gens} with rational "
                            f"coefficients, got {expr}", entry=what) from err


def to_sr(poly):
    r"""
    Convert a polynomial (or a constant) back to ``SR``.

    Builds the sum in one step: ``SR(poly)`` adds the terms one by one,
    which is quadratic in the number of terms (18 s instead of 0.8 s for
    20000 terms).

    EXAMPLES::

        sage: from sage_dynsym.algebra.polynomials import to_sr
        sage: R.<x,y> = QQ[]
        sage: e = to_sr(x*y^2 - 1/2); e, e.parent()
        (x*y^2 - 1/2, Symbolic Ring)
        sage: to_sr(QQ(3))
        3
    """
    parent = poly.parent() if hasattr(poly, 'parent') else None
    if parent is None or not hasattr(parent, 'gens') or parent is QQ or \
            not hasattr(poly, 'dict') or parent.ngens() == 1:
        return SR(poly)
    return polynomial_to_sr(poly, [SR.var(str(v)) for v in parent.gens()])


def polynomial_to_sr(poly, images):
    r"""
    A polynomial over `\QQ` as a symbolic expression, its generators
    replaced by ``images``, built in one sum.

    EXAMPLES::

        sage: from sage_dynsym.algebra.polynomials import polynomial_to_sr
        sage: R.<a, b> = QQ[]
        sage: polynomial_to_sr(a^2*b - 3, [sin(x), 2])
        2*sin(x)^2 - 3
    """
    if poly.parent() is QQ or not hasattr(poly, 'dict'):
        return SR(poly)
    terms = []
    for exps, c in poly.dict().items():
        term = SR(c)
        for k, e in enumerate((exps,) if isinstance(exps, int) else exps):
            if e:
                term = term * images[k] ** e
        terms.append(term)
    return SR.sum(terms) if terms else SR(0)


def is_polynomial_ring(parent):
    r"""
    Whether ``parent`` is `\QQ` or a polynomial ring (not ``SR``).

    EXAMPLES::

        sage: from sage_dynsym.algebra.polynomials import is_polynomial_ring
        sage: is_polynomial_ring(QQ['x, y']), is_polynomial_ring(QQ), is_polynomial_ring(SR)
        (True, True, False)
        sage: is_polynomial_ring(None)
        False
    """
    return parent is not None and parent is not SR and \
        (parent is QQ or isinstance(parent, (PolynomialRing_generic, MPolynomialRing_base)))


def is_constant(f):
    r"""
    Whether the polynomial (or rational number) ``f`` is a constant.

    EXAMPLES::

        sage: from sage_dynsym.algebra.polynomials import is_constant
        sage: R.<a> = QQ[]
        sage: is_constant(R(3)), is_constant(a), is_constant(QQ(1/2))
        (True, False, True)
    """
    return f.parent() is QQ or f.is_constant()


def constant_value(f):
    r"""
    The rational value of a constant polynomial (or rational number) ``f``.

    EXAMPLES::

        sage: from sage_dynsym.algebra.polynomials import constant_value
        sage: R.<a> = QQ[]
        sage: v = constant_value(R(-3/2)); v, v.parent()
        (-3/2, Rational Field)
    """
    return QQ(f) if f.parent() is QQ else QQ(f.constant_coefficient())


def positive_polynomial(f, positive):
    r"""
    Whether the polynomial ``f`` is positive for all positive values of the
    variables named in ``positive`` and all real values of the others:
    every coefficient is positive, every other variable occurs only to even
    powers, and some term (e.g. a constant) uses positive variables only.

    EXAMPLES::

        sage: from sage_dynsym.algebra.polynomials import positive_polynomial
        sage: R.<a,b> = QQ[]
        sage: positive_polynomial(a*b + 2, {'a', 'b'}), positive_polynomial(a - b, {'a', 'b'})
        (True, False)
        sage: positive_polynomial(a^2 + 1, set()), positive_polynomial(a^2*b, {'b'})
        (True, False)
    """
    if f == 0:
        return False
    if f.parent() is QQ or f.is_constant():
        return QQ(f) > 0
    if any(c <= 0 for c in f.coefficients()):
        return False
    names = [str(v) for v in f.parent().gens()]
    free = [k for k, n in enumerate(names) if n not in positive]
    strict = False
    for exps in f.exponents():
        exps = (exps,) if isinstance(exps, int) else exps
        if any(exps[k] % 2 for k in free):
            return False
        if not any(exps[k] for k in free):
            strict = True
    return strict



def odd_factors(factorization, positive):
    r"""
    What decides the sign of a factored polynomial: its factors of odd
    multiplicity that are not positive (:func:`positive_polynomial`), and
    a sign.

    INPUT:

    - ``factorization`` -- the factorization of a polynomial `f`
      (``f.factor()``)
    - ``positive`` -- the names of the variables declared positive

    OUTPUT: a pair ``(sign, odd)``, ``sign`` `\pm 1` and ``odd`` a list of
    factors, each with a positive leading coefficient (so that equal factors
    of different polynomials compare equal): wherever `f` is not zero, it
    has the sign of ``sign * prod(odd)``; ``odd`` is empty when the sign of
    `f` is ``sign`` everywhere

    EXAMPLES::

        sage: from sage_dynsym.algebra.polynomials import odd_factors
        sage: R.<a, b, m> = QQ[]
        sage: odd_factors((-3*m*(b - a)*(a - 2)^2).factor(), {'m'})
        (1, [a - b])
        sage: odd_factors((-m^2 - 1).factor(), set())
        (-1, [])
    """
    sign = QQ(factorization.unit()).sign()
    odd = []
    for g, e in factorization:
        if positive_polynomial(g, positive):
            continue
        if positive_polynomial(-g, positive):
            sign *= (-1) ** e
            continue
        if e % 2:
            if g.lc() < 0:
                g, sign = -g, -sign
            odd.append(g)
    return sign, odd

@contextmanager
def maxima_without_questions(entry, positive=()):
    r"""
    Run Maxima (``desolve``, ``solve``, ``simplify_full``, ...) with the
    declared signs as assumptions; when Maxima still asks for a sign, raise
    :class:`AnalysisError` saying which one instead of its raw error.

    EXAMPLES::

        sage: from sage_dynsym.algebra.polynomials import maxima_without_questions
        sage: q, a = var('q a')
        sage: with maxima_without_questions("integral"):
        ....:     integrate(1/(q^2 + a), q)
        Traceback (most recent call last):
        ...
        AnalysisError: integral: Maxima needs the sign of a: declare it with positive=[a]
        sage: with maxima_without_questions("integral", positive=[a]):
        ....:     integrate(1/(q^2 + a), q)
        arctan(q/sqrt(a))/sqrt(a)
    """
    from sage.symbolic.assumptions import assuming
    conditions = [SR(p) > 0 for p in positive]
    try:
        with assuming(*conditions) if conditions else nullcontext():
            yield
    except (TypeError, ValueError) as err:
        text = str(err)
        if "Maxima requested additional constraints" not in text:
            raise
        found = re.search(r"Is (.+?) (positive|negative|zero|an integer|nonzero)", text) or \
            re.search(r"assume\((.+?)>0\)", text)
        what = found.group(1).strip() if found else "an expression"
        symbol = re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*", what)
        hint = (f"declare it with positive=[{what}]" if symbol else
                "its sign does not follow from the declarations (substitute values, "
                "or declare the symbols it is made of)")
        raise AnalysisError(f"Maxima needs the sign of {what}: {hint}", entry=entry) from err

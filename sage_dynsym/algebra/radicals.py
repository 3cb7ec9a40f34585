r"""
Roots in radicals of a polynomial of degree one or two in one unknown

The coefficients are any symbolic expressions free of the unknown (other
parameters, functions of the coordinates); the roots come from the formulas
`-a_0/a_1` and `(-a_1 \pm \sqrt{a_1^2 - 4 a_2 a_0})/(2 a_2)`, with the
square factors of the discriminant taken out of the root and the rational
parts in Sage's normal form -- polynomial arithmetic, no equation solver
(Maxima's ``solve`` is kept for equations that are not algebraic:
:func:`~sage_dynsym.algebra.solving.solve_transcendental`).

EXAMPLES::

    sage: from sage_dynsym.algebra.radicals import roots_in_radicals
    sage: p, k, l = var('p k l')
    sage: roots_in_radicals(4*p^2*l^2 - 28*p*k*l + 41*k^2, p)
    [-sqrt(2)*k/l + 7/2*k/l, sqrt(2)*k/l + 7/2*k/l]
"""
from sage.misc.functional import sqrt
from sage.rings.rational_field import QQ
from sage.symbolic.ring import SR

from ..errors import AnalysisError


def roots_in_radicals(f, x, entry="roots_in_radicals"):
    r"""
    The roots in ``x`` of ``f``, a polynomial of degree one or two in ``x``.

    INPUT:

    - ``f`` -- a symbolic expression, polynomial in ``x``
    - ``x`` -- the unknown
    - ``entry`` -- (optional) the entry point named in errors

    OUTPUT: a list of symbolic expressions, one root of a linear ``f``, the
    two roots of a quadratic one (equal or complex ones included), the one
    written with `-\sqrt{\ }` first, as Maxima's ``solve`` lists them. A
    polynomial of higher degree, or an ``f`` that is not polynomial in
    ``x``, is an :class:`~sage_dynsym.errors.AnalysisError`: no root is ever
    left out silently.

    EXAMPLES::

        sage: from sage_dynsym.algebra.radicals import roots_in_radicals
        sage: p, k, l, q = var('p k l q')
        sage: roots_in_radicals(p*l - k, p)
        [k/l]
        sage: roots_in_radicals(p^2 - 2*k*p - l^2, p)    # the root of 4 (k^2 + l^2)
        [k - sqrt(k^2 + l^2), k + sqrt(k^2 + l^2)]
        sage: roots_in_radicals(p^2 - k^2*l^2, p)        # a square comes out of the root
        [-k*l, k*l]
        sage: roots_in_radicals(p^2 - 2*k*p/l + 1/l^2, p)   # a square denominator too
        [k/l - sqrt(k^2 - 1)/l, k/l + sqrt(k^2 - 1)/l]

    The formulas hold::

        sage: all(bool((p^2*cos(q) - 2*p + sin(q)).subs(p=r) == 0)
        ....:     for r in roots_in_radicals(p^2*cos(q) - 2*p + sin(q), p))
        True

    TESTS::

        sage: roots_in_radicals(p^3 - k, p)
        Traceback (most recent call last):
        ...
        AnalysisError: roots_in_radicals: p^3 - k has degree 3 in p: only roots of degrees one and two are given by formulas
        sage: roots_in_radicals(exp(p) - k, p)
        Traceback (most recent call last):
        ...
        AnalysisError: roots_in_radicals: -k + e^p is not a polynomial in p
        sage: roots_in_radicals(k, p)
        Traceback (most recent call last):
        ...
        AnalysisError: roots_in_radicals: k does not depend on p
    """
    f, x = SR(f), SR(x)
    if not f.has(x):
        raise AnalysisError(f"{f} does not depend on {x}", entry=entry)
    if not f.is_polynomial(x):
        raise AnalysisError(f"{f} is not a polynomial in {x}", entry=entry)
    degree = f.degree(x)
    if degree > 2:
        raise AnalysisError(f"{f} has degree {degree} in {x}: only roots of degrees one and two "
                            "are given by formulas", entry=entry)
    a = [f.coefficient(x, k) for k in range(degree + 1)]
    if degree == 1:
        return [(-a[0] / a[1]).normalize()]
    square, content, rest = _square_part(a[1]**2 - 4 * a[2] * a[0])
    middle = (-a[1] / (2 * a[2])).normalize()
    half_width = (square / (2 * a[2])).normalize() * sqrt(content)
    if str(half_width).startswith('-'):
        half_width = -half_width    # both roots are listed: written with - first, then +
    return [middle + e * half_width * sqrt(rest) for e in (-1, 1)]


def _square_part(discriminant):
    r"""``(s, c, r)`` with ``discriminant = s^2 c r``: ``s`` the factors of
    even multiplicity (negative ones too: denominators), halved; ``c`` the
    positive rational content of the others when it is a square (else 1),
    ``r`` the rest, expanded."""
    square, odd, other = SR(1), SR(1), SR(1)
    for factor, m in SR(discriminant).factor_list():
        m = QQ(m)
        if m.is_integer():
            m = int(m)          # not in QQ, where // is exact division
            square, odd = square * factor**(m // 2), odd * factor**(m % 2)
        else:
            other *= factor**m
    odd = odd.expand()
    content = _content(odd)
    if not content.is_square():             # its root would only split the radical
        content = QQ(1)
    return square, content, (odd / content).expand() * other


def _content(f):
    r"""The positive rational gcd of the numerical coefficients of the terms
    of the sum ``f`` (1 when there is none to take)."""
    from sage.arith.misc import gcd
    from sage.symbolic.operators import add_vararg, mul_vararg
    coefficients = []
    for term in (f.operands() if f.operator() is add_vararg else [f]):
        if term.is_numeric():
            coefficients.append(term)
        elif term.operator() is mul_vararg:
            numeric = [o for o in term.operands() if o.is_numeric()]
            coefficients.append(numeric[0] if numeric else 1)
        else:
            coefficients.append(1)
    try:
        return abs(gcd([QQ(c) for c in coefficients])) or QQ(1)
    except (TypeError, ValueError):
        return QQ(1)

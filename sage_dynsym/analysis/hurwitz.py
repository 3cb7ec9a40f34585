r"""
Routh--Hurwitz and Liénard--Chipart conditions with symbolic coefficients

For a real polynomial

.. MATH::

    p(\lambda) = a_0 \lambda^n + a_1 \lambda^{n-1} + \dots + a_n,
    \qquad a_0 > 0,

all roots lie in the open left half-plane (the zero solution of a linear
system with characteristic polynomial `p` is asymptotically stable) iff the
Hurwitz determinants `\Delta_1, \dots, \Delta_n` are positive
(Routh--Hurwitz), or -- with about half as many determinants -- iff
`a_n, a_{n-2}, a_{n-4}, \dots > 0` (or `a_n, a_{n-1}, a_{n-3}, \dots > 0`)
and `\Delta_{n-1}, \Delta_{n-3}, \dots > 0` (Liénard--Chipart).

The determinants are computed fraction-free over a polynomial ring in the
parameters (Singular), with the *fraction-free Routh scheme*: with
`G_0 = (a_0, a_2, \dots)`, `G_1 = (a_1, a_3, \dots)` and

.. MATH::

    G_{k+1}[j] = \frac{G_k[0]\, G_{k-1}[j+1] - G_{k-1}[0]\, G_k[j+1]}
                      {\Delta_{k-2}}

(the division is exact; `\Delta_0 = \Delta_{-1} = 1`), the first entries are
the Hurwitz determinants, `\Delta_k = G_k[0]`. One pass costs a few
products per determinant instead of a determinant each. `\Delta_n =
a_n \Delta_{n-1}` is never formed.

Expanded Hurwitz determinants grow very fast with the number of parameters
(for a chain of four masses with symbolic masses, springs and dampers,
`\Delta_5` already has 642840 terms). When the next product would exceed
``budget`` term multiplications, the remaining determinants are returned
*unexpanded*: the generic Hurwitz determinant as a polynomial in the
coefficients `a_i`, with every `a_i` replaced by its (expanded) polynomial
-- an exact, compact expression that can be evaluated, substituted into or
expanded later.

Conditions are returned as lists of symbolic expressions that must all be
``> 0``; they are simplified: factored (small ones), constant positive
factors and factors that are positive because all their coefficients are
positive in variables declared ``positive`` are removed, even powers are
dropped (only their zero set -- a bifurcation boundary -- is lost), and
conditions implied by others (a product of factors that are themselves
conditions, duplicates) are removed.

EXAMPLES:

A cubic with roots `-1, -2, -3` and one with roots `1, -2 \pm i`::

    sage: from sage_dynsym.analysis.hurwitz import hurwitz_conditions
    sage: lam = var('lam')
    sage: hurwitz_conditions(expand((lam + 1)*(lam + 2)*(lam + 3)), lam)
    []
    sage: hurwitz_conditions(expand((lam - 1)*(lam^2 + 4*lam + 5)), lam)
    [-1]

(a nonpositive constant alone means that the conditions cannot hold).

The general cubic: `a_1 a_2 - a_0 a_3 > 0` is the only condition beyond
positivity of the coefficients::

    sage: a0, a1, a2, a3 = var('a0 a1 a2 a3')
    sage: hurwitz_conditions(a0*lam^3 + a1*lam^2 + a2*lam + a3, lam)
    [a0, a1, a1*a2 - a0*a3, a3]
    sage: from sage_dynsym.analysis.hurwitz import lienard_chipart_conditions
    sage: lienard_chipart_conditions(a0*lam^3 + a1*lam^2 + a2*lam + a3, lam)
    [a0, a3, a1, a1*a2 - a0*a3]

REFERENCES:

- F. R. Gantmacher, *The Theory of Matrices*, vol. 2, Chelsea, 1959,
  ch. XV, §6 (Routh's scheme), §§12--13 (Hurwitz and Liénard--Chipart
  criteria), §17 (Hermite--Biehler theorem).
- D. R. Merkin, *Introduction to the Theory of Stability*, Springer, 1997,
  ch. 5 (Hurwitz and Liénard--Chipart criteria, conservative systems).
"""
from sage.matrix.constructor import matrix
from sage.rings.polynomial.polynomial_ring_constructor import PolynomialRing
from sage.rings.rational_field import QQ
from sage.symbolic.ring import SR
from sage.structure.element import Element

from ..arguments import expression_argument
from ..errors import AnalysisError, brief
from ..algebra.conditions import Unexpanded, reduce_conditions, conditions_as_expressions
# simplify_conditions and FACTOR_LIMIT moved to the algebra; their old place still serves them
from ..algebra.conditions import simplify_conditions
from ..algebra.polynomials import FACTOR_LIMIT
from ..algebra.polynomials import (parameter_ring, to_sr, is_constant, constant_value,
                                   is_polynomial_ring)

__all__ = ['DEFAULT_BUDGET', 'polynomial_coefficients', 'polynomial_arguments', 'hurwitz_matrix',
           'hurwitz_determinants', 'routh_scheme_fits', 'hurwitz_conditions',
           'lienard_chipart_conditions', 'real_negative_roots_conditions',
           'conservative_stability_conditions', 'simplify_conditions', 'FACTOR_LIMIT']

#: Default limit on the term multiplications of one product in the
#: fraction-free Routh scheme before determinants are left unexpanded.
DEFAULT_BUDGET = 5 * 10**6


# ---------------------------------------------------------------------------
# coefficients
# ---------------------------------------------------------------------------

def polynomial_coefficients(poly, var):
    r"""
    The coefficients `[a_0, \dots, a_n]` of ``poly`` in ``var``, highest
    power first, as elements of a polynomial ring over `\QQ` in the other
    variables (denominators that do not contain ``var`` are cleared).

    INPUT:

    - ``poly`` -- a symbolic expression polynomial in ``var``, or an
      element of a polynomial ring one of whose generators is named ``var``
    - ``var`` -- a symbolic variable (or its name)

    OUTPUT: a pair ``(coefficients, denominator)``; ``poly`` equals
    `\sum a_i\, var^{n-i}` divided by ``denominator``

    EXAMPLES::

        sage: from sage_dynsym.analysis.hurwitz import polynomial_coefficients
        sage: lam, m, c = var('lam m c')
        sage: polynomial_coefficients(m*lam^2 + c*lam + 1/m, lam)
        ([m^2, c*m, 1], m)

    TESTS::

        sage: polynomial_coefficients(lam^2 + sin(m), lam)
        Traceback (most recent call last):
        ...
        AnalysisError: characteristic polynomial: expected a polynomial in lam with coefficients rational in the parameters, got lam^2 + sin(m)
        sage: polynomial_coefficients(1/lam + 1, lam)
        Traceback (most recent call last):
        ...
        AnalysisError: characteristic polynomial: expected a polynomial in lam (no lam in a denominator), got 1/lam + 1
        sage: polynomial_coefficients(m, lam)
        Traceback (most recent call last):
        ...
        AnalysisError: characteristic polynomial: expected a polynomial of degree at least 1 in lam, got m
    """
    poly, name = polynomial_arguments(poly, var)
    parent = poly.parent() if isinstance(poly, Element) else None
    if is_polynomial_ring(parent) and name in parent.variable_names():
        names = parent.variable_names()
        if len(names) == 1:
            coeffs = poly.list()[::-1]
            if len(coeffs) < 2:
                raise AnalysisError(f"expected a polynomial of degree at least 1 in "
                                    f"{name}, got {poly}", entry="characteristic polynomial")
            return coeffs, parent.base_ring().one()
        ring = parameter_ring([v for v in names if v != name])
        idx = names.index(name)
        gens = [None if v == name else ring(v) for v in names]
        by_power = {}
        for exps, c in poly.dict().items():
            mono = QQ(c)
            for g, e in zip(gens, exps):
                if g is not None and e:
                    mono *= g ** e
            by_power[exps[idx]] = by_power.get(exps[idx], 0) + mono
        den = ring(1)
    else:
        expr = SR(poly)
        var = SR.var(name)
        params = [v for v in expr.variables() if str(v) != name]
        ring = parameter_ring(params, extra=[name])
        what = "characteristic polynomial"
        try:
            num, den = (expr.numerator_denominator(normalize=True)
                        if expr.variables() else (expr, SR(1)))
            num, den = num.polynomial(ring=ring), den.polynomial(ring=ring)
        except (TypeError, ValueError, NotImplementedError, AttributeError) as err:
            raise AnalysisError(
                f"expected a polynomial in {name} with coefficients rational "
                f"in the parameters, got {expr}", entry=what) from err
        if den.degree(ring.gen(ring.ngens() - 1)) > 0:
            raise AnalysisError(
                f"expected a polynomial in {name} (no {name} in a denominator), "
                f"got {expr}", entry=what)
        base = parameter_ring(params)
        by_power = {}
        for exps, c in num.dict().items():
            exps = tuple(exps)
            mono = base.monomial(*exps[:-1]) if base is not QQ else QQ(1)
            by_power[exps[-1]] = by_power.get(exps[-1], 0) + c * mono
        den = base(den) if base is not QQ else QQ(den)
        ring = base
    n = max(by_power) if by_power else 0
    if n < 1:
        raise AnalysisError(f"expected a polynomial of degree at least 1 in "
                            f"{name}, got {poly}", entry="characteristic polynomial")
    coeffs = [ring(by_power.get(n - i, 0)) for i in range(n + 1)]
    return coeffs, den


def polynomial_arguments(poly, var):
    r"""
    The arguments ``(poly, var)`` of the functions of a characteristic
    polynomial, checked: ``poly`` a symbolic expression or an element of a
    polynomial ring, ``var`` a symbolic variable, a generator or a name;
    returns ``poly`` (a symbolic expression unless it is a ring element)
    and the name of ``var``.

    EXAMPLES::

        sage: from sage_dynsym.analysis.hurwitz import polynomial_arguments
        sage: lam = var('lam')
        sage: polynomial_arguments(lam^2 + 1, lam)
        (lam^2 + 1, 'lam')
        sage: polynomial_arguments(lam^2 + 1, 42)
        Traceback (most recent call last):
        ...
        AnalysisError: var: expected the variable of the polynomial (a symbolic variable or its name), got 42
        sage: polynomial_arguments('lam^2 + 1', lam)
        Traceback (most recent call last):
        ...
        AnalysisError: poly: expected a polynomial (a symbolic expression or an element of a polynomial ring), got 'lam^2 + 1' (str); write it with var('lam'), e.g. lam^2 + 1
    """
    name = str(var)
    is_variable = isinstance(var, str) or (callable(getattr(var, 'is_symbol', None)) and
                                           var.is_symbol()) or (
        callable(getattr(var, 'is_gen', None)) and var.is_gen())
    if not is_variable or not name.isidentifier():
        raise AnalysisError("expected the variable of the polynomial (a symbolic variable or "
                            f"its name), got {brief(var)}", entry="var")
    if isinstance(poly, Element) and is_polynomial_ring(poly.parent()):
        return poly, name
    poly = expression_argument(poly, "poly", AnalysisError, expected="a polynomial (a symbolic "
                               "expression or an element of a polynomial ring)",
                               hint=f"write it with var('{name}'), e.g. {name}^2 + 1")
    return poly, name


def _normalized_coefficients(poly, var):
    a, _ = polynomial_coefficients(poly, var)
    if is_constant(a[0]) and constant_value(a[0]) < 0:
        a = [-c for c in a]
    return a


# ---------------------------------------------------------------------------
# Hurwitz matrix and determinants
# ---------------------------------------------------------------------------

def _hurwitz_matrix_of(a):
    n = len(a) - 1
    base = a[0].parent()
    return matrix(base, n, n,
                  lambda i, j: a[2 * j - i + 1] if 0 <= 2 * j - i + 1 <= n else 0)


def hurwitz_matrix(poly, var):
    r"""
    The Hurwitz matrix of ``poly`` in ``var``: `H_{ij} = a_{2j-i}`
    (1-based, `a_k = 0` outside `0..n`).

    INPUT:

    - ``poly`` -- a polynomial in ``var`` (symbolic or in a polynomial ring)
    - ``var`` -- the variable

    OUTPUT: an `n \times n` matrix over ``SR``; its leading principal minors
    are the Hurwitz determinants

    EXAMPLES::

        sage: from sage_dynsym.analysis.hurwitz import hurwitz_matrix
        sage: lam, a0, a1, a2, a3 = var('lam a0 a1 a2 a3')
        sage: hurwitz_matrix(a0*lam^3 + a1*lam^2 + a2*lam + a3, lam)
        [a1 a3  0]
        [a0 a2  0]
        [ 0 a1 a3]
    """
    a, _ = polynomial_coefficients(poly, var)
    return _hurwitz_matrix_of(a).change_ring(SR)


def _generic_determinants(n, upto):
    # Hurwitz determinants of the generic polynomial with coefficients h_i:
    # small, and the pivots never vanish.
    H = PolynomialRing(QQ, ['h%d' % i for i in range(n + 1)])
    deltas, _ = _routh_scheme(list(H.gens()), upto, budget=None)
    return H, deltas


def _routh_scheme(a, upto, budget):
    r"""
    Hurwitz determinants ``[None, Delta_1, ..., Delta_upto]`` by the
    fraction-free Routh scheme; stops early (returns the index reached) when
    a pivot vanishes or the budget is exceeded.
    """
    zero = a[0].parent().zero()
    rows = [list(a[0::2]), list(a[1::2])]
    deltas = [None, rows[1][0]]
    k = 1
    while k < upto:
        Gk, Gkm = rows[k], rows[k - 1]
        if Gk[0] == 0:
            return deltas, k
        if budget is not None and len(Gkm) > 1:
            nterms = lambda f: len(f.dict()) if hasattr(f, 'dict') else 1
            cost = (nterms(Gk[0]) * nterms(Gkm[1])
                    + nterms(Gkm[0]) * (nterms(Gk[1]) if len(Gk) > 1 else 0))
            if cost > budget:
                return deltas, k
        div = rows[k - 2][0] if k >= 3 else None
        new = []
        for j in range(len(Gkm) - 1):
            x = Gk[0] * Gkm[j + 1] - Gkm[0] * (Gk[j + 1] if j + 1 < len(Gk) else zero)
            new.append(x // div if div is not None else x)
        if not new:
            new = [zero]
        rows.append(new)
        deltas.append(new[0])
        k += 1
    return deltas, k


def hurwitz_determinants(poly, var, upto=None, budget=DEFAULT_BUDGET):
    r"""
    The Hurwitz determinants `\Delta_1, \dots, \Delta_{upto}` of ``poly``.

    INPUT:

    - ``poly``, ``var`` -- as in :func:`hurwitz_matrix`
    - ``upto`` -- (default: `n`) the last determinant wanted
    - ``budget`` -- (default: ``5*10^6``) the largest number of term
      multiplications of one product in the fraction-free Routh scheme;
      determinants beyond it are returned unexpanded (see the module
      documentation); ``None`` -- always expand

    OUTPUT: a list of symbolic expressions, `\Delta_1` first

    EXAMPLES::

        sage: from sage_dynsym.analysis.hurwitz import hurwitz_determinants, hurwitz_matrix
        sage: lam = var('lam'); a = var('a0 a1 a2 a3 a4')
        sage: p = sum(a[i]*lam^(4 - i) for i in range(5))
        sage: D = hurwitz_determinants(p, lam)
        sage: H = hurwitz_matrix(p, lam)
        sage: all(bool(D[k - 1] == H[:k, :k].det().expand()) for k in range(1, 5))
        True
        sage: D[3]
        a1*a2*a3*a4 - a0*a3^2*a4 - a1^2*a4^2

    With a tiny budget the later determinants stay unexpanded, but are the
    same polynomials::

        sage: E = hurwitz_determinants(p, lam, budget=1)
        sage: E[2]
        a1*a2*a3 - a0*a3^2 - a1^2*a4
        sage: bool(E[3].expand() == D[3])
        True

    A vanishing pivot (here `a_1 = 0`) is handled by direct determinants::

        sage: hurwitz_determinants(lam^3 + 2*lam + 1, lam)
        [0, -1, -1]
    """
    a = _normalized_coefficients(poly, var)
    return [to_sr(d) if not isinstance(d, Unexpanded) else d.expr
            for d in _determinants(a, upto or len(a) - 1, budget)[1:]]


def routh_scheme_fits(poly, var, budget=DEFAULT_BUDGET):
    r"""
    Whether the fraction-free Routh scheme gives every Hurwitz determinant
    `\Delta_1, \dots, \Delta_{n-1}` of ``poly`` expanded within ``budget``
    -- no product of more than ``budget`` pairs of terms --, checked by
    running the scheme with that budget (the costly products are not
    made). A vanishing pivot (the determinants then come from the Hurwitz
    matrix directly) and numeric coefficients count as fitting.

    INPUT: as for :func:`hurwitz_determinants`

    OUTPUT: a boolean

    EXAMPLES::

        sage: from sage_dynsym.analysis.hurwitz import routh_scheme_fits
        sage: lam = var('lam'); a = var('a0 a1 a2 a3 a4')
        sage: p = sum(a[i]*lam^(4 - i) for i in range(5))
        sage: routh_scheme_fits(p, lam), routh_scheme_fits(p, lam, budget=1)
        (True, False)
        sage: routh_scheme_fits(lam^3 + 2*lam + 1, lam, budget=1)
        True
    """
    a = _normalized_coefficients(poly, var)
    n = len(a) - 1
    if n < 2 or a[0].parent() is QQ:
        return True
    deltas, reached = _routh_scheme(a, n - 1, budget)
    return reached >= n - 1 or deltas[reached] == 0


def _determinants(a, upto, budget):
    n = len(a) - 1
    upto = min(upto, n)
    if a[0].parent() is QQ:
        budget = None
    deltas, reached = _routh_scheme(a, upto, budget)
    if reached < upto:
        if deltas[reached] == 0:   # singular case of Routh's scheme
            H = _hurwitz_matrix_of(a)
            deltas += [H[:k, :k].det() for k in range(reached + 1, upto + 1)]
        else:
            hring, generic = _generic_determinants(n, upto)
            subs = {SR.var("h%d" % i): to_sr(c) for i, c in enumerate(a)}
            deltas += [Unexpanded(SR(generic[k]).subs(subs))
                       for k in range(reached + 1, upto + 1)]
    return deltas


# ---------------------------------------------------------------------------
# the criteria
# ---------------------------------------------------------------------------

def hurwitz_conditions(poly, var, positive=(), budget=DEFAULT_BUDGET):
    r"""
    Routh--Hurwitz conditions: all roots of ``poly`` in ``var`` have
    negative real parts.

    INPUT:

    - ``poly`` -- a polynomial in ``var`` whose coefficients are polynomials
      (or rational functions) in parameters, symbolic or in a polynomial ring
    - ``var`` -- the variable
    - ``positive`` -- (default: ``()``) parameters known to be positive;
      factors that are positive because of that are dropped
    - ``budget`` -- see :func:`hurwitz_determinants`

    OUTPUT: a list of symbolic expressions which must all be ``> 0``:
    the leading coefficient `a_0` (left out when it is positive), the
    Hurwitz determinants `\Delta_1..\Delta_{n-1}`, and `a_n` (replacing
    `\Delta_n = a_n \Delta_{n-1}`), simplified (see the module
    documentation). Denominators of the coefficients are cleared first;
    the conditions are those for the numerator with a positive leading
    coefficient.

    EXAMPLES:

    A damped oscillator `m \ddot x + c \dot x + k x = 0`::

        sage: from sage_dynsym.analysis.hurwitz import hurwitz_conditions
        sage: lam, m, c, k = var('lam m c k')
        sage: hurwitz_conditions(m*lam^2 + c*lam + k, lam)
        [m, c, k]
        sage: hurwitz_conditions(m*lam^2 + c*lam + k, lam, positive=[m, k])
        [c]

    Known roots: `(\lambda+1)(\lambda+2)(\lambda^2 + a\lambda + 1)` is
    stable iff `a > 0`::

        sage: a = var('a')
        sage: hurwitz_conditions(expand((lam + 1)*(lam + 2)*(lam^2 + a*lam + 1)), lam)
        [a + 3, 3*a^2 + 10*a + 6, (2*a + 5)*(a + 2)*a]
        sage: hurwitz_conditions(expand((lam + 1)*(lam + 2)*(lam^2 + a*lam + 1)), lam,
        ....:                    positive=[a])
        []

    (all conditions together are equivalent to `a > 0`; this function does
    no semi-algebraic reasoning beyond sign patterns of coefficients.)

    A polynomial even in the variable (every coefficient of an odd power
    zero: a conservative or gyroscopic system) can never be Hurwitz -- its
    roots come in pairs `\pm\lambda` --; that is an error, pointing to the
    conditions for a spectrum on the imaginary axis::

        sage: hurwitz_conditions(m*lam^4 + c*lam^2 + k, lam)
        Traceback (most recent call last):
        ...
        AnalysisError: hurwitz_conditions: every coefficient of an odd power of lam is zero in lam^4*m + c*lam^2 + k: its roots come in pairs +-lam, so they are never all in the left half-plane (no asymptotic stability); for roots on the imaginary axis use conservative_stability_conditions

    TESTS::

        sage: hurwitz_conditions(-lam - 1, lam)
        []
        sage: hurwitz_conditions(lam^3 + lam, lam)
        [0]
    """
    a = _normalized_coefficients(poly, var)
    n = len(a) - 1
    if all(a[i] == 0 for i in range(n + 1) if (n - i) % 2):
        raise AnalysisError(f"every coefficient of an odd power of {var} is zero in {poly}: "
                            f"its roots come in pairs +-{var}, so they are never all in the "
                            "left half-plane (no asymptotic stability); for roots on the "
                            "imaginary axis use conservative_stability_conditions",
                            entry="hurwitz_conditions")
    deltas = _determinants(a, n - 1, budget)
    conds = [a[0]] + deltas[1:n] + [a[n]]
    return conditions_as_expressions(reduce_conditions(conds, positive))


def lienard_chipart_conditions(poly, var, positive=(), budget=DEFAULT_BUDGET):
    r"""
    Liénard--Chipart conditions: all roots of ``poly`` in ``var`` have
    negative real parts.

    With `a_0 > 0`: `a_n > 0, a_{n-2} > 0, \dots` (or
    `a_n > 0, a_{n-1} > 0, a_{n-3} > 0, \dots`, whichever leaves fewer
    conditions after simplification) and `\Delta_{n-1} > 0,
    \Delta_{n-3} > 0, \dots` -- about half of the Hurwitz determinants.

    INPUT: as for :func:`hurwitz_conditions`

    OUTPUT: a list of symbolic expressions which must all be ``> 0``:
    `a_0` (unless positive), the chosen coefficients, then the
    determinants, lowest order first

    EXAMPLES:

    Degree 4: `a_4, a_2 > 0` and `\Delta_3 > 0` (and `\Delta_1 = a_1`)::

        sage: from sage_dynsym.analysis.hurwitz import lienard_chipart_conditions
        sage: lam = var('lam'); a = var('a0 a1 a2 a3 a4')
        sage: lienard_chipart_conditions(sum(a[i]*lam^(4 - i) for i in range(5)), lam)
        [a0, a4, a2, a1, a1*a2*a3 - a0*a3^2 - a1^2*a4]

    With positive parameters, only `\Delta_3` of the damped double
    oscillator is left; it has a negative term, yet it is positive
    (Kelvin--Chetaev: complete dissipation and a stable potential give
    asymptotic stability, see :mod:`sage_dynsym.analysis.kelvin_chetaev`)::

        sage: m1, m2, k1, k2, c1, c2 = var('m1 m2 k1 k2 c1 c2')
        sage: M = matrix([[m1, 0], [0, m2]]); C = matrix([[c1 + c2, -c2], [-c2, c2]])
        sage: K = matrix([[k1 + k2, -k2], [-k2, k2]])
        sage: p = (M*lam^2 + C*lam + K).det()
        sage: [D3] = lienard_chipart_conditions(p, lam, positive=[m1, m2, k1, k2, c1, c2])
        sage: D3.coefficient(c1*c2*k1*k2*m1*m2)
        -2

    TESTS: a coefficient of the wrong sign settles it, whichever set of
    coefficients is shorter::

        sage: c, a = var('c a')
        sage: lienard_chipart_conditions(lam^4 + 2*c*lam^3 + a*lam^2 - c*lam + 1, lam,
        ....:                            positive=[c])
        [-1]
    """
    a = _normalized_coefficients(poly, var)
    n = len(a) - 1
    det_idx = list(range(n - 1, 0, -2))[::-1]
    deltas = _determinants(a, n - 1, budget) if det_idx else [None]
    first = [a[i] for i in range(n, -1, -2)]
    second = [a[n]] + [a[i] for i in range(n - 1, -1, -2)]
    reduced = [reduce_conditions([a[0]] + cs, positive) for cs in (first, second)]
    for r in reduced:
        # a coefficient of the wrong sign in either set: no root test needed
        if len(r) == 1 and not isinstance(r[0], Unexpanded) and len(r[0]) == 1 \
                and is_constant(r[0][0]):
            return conditions_as_expressions(r)
    coeffs = first if len(reduced[0]) <= len(reduced[1]) else second
    return conditions_as_expressions(reduce_conditions([a[0]] + coeffs + [deltas[k] for k in det_idx], positive))


# ---------------------------------------------------------------------------
# conservative systems
# ---------------------------------------------------------------------------

def real_negative_roots_conditions(poly, var, positive=(), budget=DEFAULT_BUDGET):
    r"""
    Conditions for all roots of ``poly`` in ``var`` to be real, negative and
    simple.

    By the Hermite--Biehler theorem, `h(\mu)` has only real, negative,
    simple roots iff `f(\lambda) = h(\lambda^2) + \lambda\, h'(\lambda^2)`
    is a Hurwitz polynomial: the roots of `h'` interlace those of `h`
    exactly when those of `h` are real (Rolle). The conditions are the
    Liénard--Chipart conditions of `f`.

    INPUT: as for :func:`hurwitz_conditions`

    OUTPUT: a list of symbolic expressions which must all be ``> 0``

    EXAMPLES::

        sage: from sage_dynsym.analysis.hurwitz import real_negative_roots_conditions
        sage: mu, b, c = var('mu b c')
        sage: real_negative_roots_conditions(mu^2 + b*mu + c, mu)
        [c, b, b^2 - 4*c]
        sage: real_negative_roots_conditions(expand((mu + 1)*(mu + 2)*(mu + 5)), mu)
        []
        sage: real_negative_roots_conditions(mu^2 + 1, mu)
        [0]

    REFERENCES:

    - Gantmacher, *The Theory of Matrices*, vol. 2, ch. XV, §17.
    """
    a = _normalized_coefficients(poly, var)
    m = len(a) - 1
    ring = a[0].parent()
    # f(lambda) = h(lambda^2) + lambda*h'(lambda^2), highest power first
    f = []
    for i in range(m + 1):
        f.append(a[i])
        if i < m:
            f.append((m - i) * a[i])
    L = PolynomialRing(ring, 'lambda_')
    return lienard_chipart_conditions(L(f[::-1]), 'lambda_', positive, budget)


def conservative_stability_conditions(poly, var, positive=(), budget=DEFAULT_BUDGET):
    r"""
    Conditions for a characteristic polynomial with only even powers (a
    conservative system, possibly with gyroscopic forces) to have only
    simple purely imaginary roots: the polynomial in `\mu = \lambda^2`
    must have only real, negative, simple roots.

    INPUT: as for :func:`hurwitz_conditions`

    OUTPUT: a list of symbolic expressions which must all be ``> 0``

    EXAMPLES:

    A gyroscopic system `\ddot x - g \dot y + k_1 x = 0`,
    `\ddot y + g \dot x + k_2 y = 0` (Merkin, ch. 6)::

        sage: from sage_dynsym.analysis.hurwitz import conservative_stability_conditions
        sage: lam, g, k1, k2 = var('lam g k1 k2')
        sage: p = matrix([[lam^2 + k1, -g*lam], [g*lam, lam^2 + k2]]).det()
        sage: conservative_stability_conditions(p, lam)
        [k1*k2, g^2 + k1 + k2, g^4 + 2*g^2*k1 + 2*g^2*k2 + k1^2 - 2*k1*k2 + k2^2]

    TESTS::

        sage: conservative_stability_conditions(lam^2 + lam + 1, lam)
        Traceback (most recent call last):
        ...
        AnalysisError: characteristic polynomial: a conservative system has only even powers of lam, got lam^2 + lam + 1
    """
    a = _normalized_coefficients(poly, var)
    n = len(a) - 1
    if n % 2 or any(a[i] != 0 for i in range(1, n + 1, 2)):
        raise AnalysisError(f"a conservative system has only even powers of "
                            f"{var}, got {poly}", entry="characteristic polynomial")
    ring = a[0].parent()
    L = PolynomialRing(ring, 'mu_')
    return real_negative_roots_conditions(L(a[0::2][::-1]), 'mu_', positive, budget)

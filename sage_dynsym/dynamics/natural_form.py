r"""
The natural form of a characteristic function

A Lagrangian that is quadratic in the velocities is *natural*:
`L = \tfrac12 \sum A_{ij}\dot q_i \dot q_j + \sum A_i \dot q_i + A_0`
((4) of :doc:`the method </method>`). The helpers here read that form off
an expression, decide whether the mass matrix `A` is singular, and
eliminate with it symmetrically -- the common ground of the Lagrangian, the
Routh function (which solves the momentum equations of the cyclic
coordinates) and the Hamiltonian (the Legendre transform). They work on
plain symbolic expressions and matrices.

EXAMPLES::

    sage: from sage_dynsym.dynamics.natural_form import natural_form
    sage: x, dx, m, k = var('x dx m k')
    sage: natural_form(matrix([[m]]), [0], -k*x^2/2, [dx])
    1/2*dx^2*m - 1/2*k*x^2
"""
import random

from sage.matrix.constructor import matrix
from sage.misc.misc_c import prod
from sage.rings.real_double import RDF
from sage.symbolic.ring import SR

from ..arguments import expression_list
from ..errors import ModelError
from ..algebra.trigonometric import trig_rational_simplify

__all__ = ['LAGRANGIAN_METHODS', 'LAGRANGIAN_HINT', 'symbol_list', 'is_at_most_quadratic',
           'natural_form', 'linear_collected', 'is_singular', 'has_full_row_rank', 'Elimination',
           'natural_decomposition']

#: How the functions taking a Lagrangian recognise one (and the calls that
#: give one, for their messages).
LAGRANGIAN_METHODS = ('coordinates', 'velocities', 'lagrange_equations', 'is_natural')
LAGRANGIAN_HINT = "model.lagrangian(), or Lagrangian(expr, coordinates)"


def symbol_list(symbols, what):
    r"""
    ``symbols`` as a list of distinct symbolic variables; raises
    :class:`~sage_dynsym.errors.ModelError` naming ``what`` otherwise.

    EXAMPLES::

        sage: from sage_dynsym.dynamics.natural_form import symbol_list
        sage: x, y = var('x y')
        sage: symbol_list([x, 'y'], 'coordinates')
        [x, y]
        sage: symbol_list([x, x], 'coordinates')
        Traceback (most recent call last):
        ...
        ModelError: coordinates must be distinct, got [x, x]
        sage: symbol_list([x^2], 'coordinates')
        Traceback (most recent call last):
        ...
        ModelError: coordinates must be symbolic variables, got x^2
        sage: symbol_list(None, 'coordinates')
        Traceback (most recent call last):
        ...
        ModelError: coordinates: expected a list of symbolic variables, got None (NoneType)
    """
    if isinstance(symbols, (list, tuple)):      # names are symbols too
        symbols = [SR.var(s) if isinstance(s, str) and s.isidentifier() else s for s in symbols]
    symbols = expression_list(symbols, what, expected="a list of symbolic variables")
    for s in symbols:
        if not s.is_symbol():
            raise ModelError(f"{what} must be symbolic variables, got {s}")
    if len(set(symbols)) != len(symbols):
        raise ModelError(f"{what} must be distinct, got {symbols}")
    return symbols


def is_at_most_quadratic(expr, velocities):
    r"""
    Whether ``expr`` is a polynomial of total degree at most 2 in ``velocities``.

    EXAMPLES::

        sage: from sage_dynsym.dynamics.natural_form import is_at_most_quadratic
        sage: x, dx, dy, m, a = var('x dx dy m a')
        sage: is_at_most_quadratic(m*dx^2/2 + a*dx*dy + x, [dx, dy])
        True
        sage: is_at_most_quadratic(dx^3, [dx, dy]), is_at_most_quadratic(sin(dx), [dx])
        (False, False)
    """
    if not velocities:
        return True
    s = SR.symbol()
    scaled = expr.subs({v: s * v for v in velocities})
    return bool(scaled.is_polynomial(s)) and bool(scaled.degree(s) <= 2)


def natural_form(A, A1, A0, velocities):
    r"""
    `\tfrac12 \dot q^T A \dot q + A_1\cdot\dot q + A_0`, each
    off-diagonal pair written once.

    EXAMPLES::

        sage: from sage_dynsym.dynamics.natural_form import natural_form
        sage: x, dx, dy, m, a = var('x dx dy m a')
        sage: natural_form(matrix([[m, a], [a, m]]), [x, 0], -x^2, [dx, dy])
        a*dx*dy + 1/2*dx^2*m + 1/2*dy^2*m + dx*x - x^2
    """
    n = len(velocities)
    v = velocities
    quadratic = sum((A[i, i] * v[i] ** 2 / 2 for i in range(n)), SR(0)) + sum(
        (A[i, j] * v[i] * v[j] for i in range(n) for j in range(i + 1, n)), SR(0))
    return quadratic + sum((A1[i] * v[i] for i in range(n)), SR(0)) + SR(A0)


def natural_decomposition(expr, velocities):
    r"""
    The decomposition (4) of ``expr``, a polynomial of degree at most two
    in ``velocities`` (checked with :func:`is_at_most_quadratic`):
    `\tfrac12 \sum A_{ij} \dot q_i \dot q_j + \sum A_i \dot q_i + A_0`.

    OUTPUT: a triple ``(A, A1, A0)``: the symmetric matrix `A_{ij}`
    (immutable), the vector `A_i` and the expression `A_0`

    EXAMPLES::

        sage: from sage_dynsym.dynamics.natural_form import natural_decomposition
        sage: x, y, dx, dy, w = var('x y dx dy w')
        sage: A, A1, A0 = natural_decomposition(((dx - w*y)^2 + (dy + w*x)^2)/2, [dx, dy])
        sage: A, A1, A0
        (
        [1 0]
        [0 1], (-w*y, w*x), 1/2*w^2*x^2 + 1/2*w^2*y^2
        )

    TESTS::

        sage: natural_decomposition(dx^4, [dx])
        Traceback (most recent call last):
        ...
        ModelError: the Lagrangian is not quadratic in the velocities (dx)
    """
    if not is_at_most_quadratic(expr, velocities):
        names = ", ".join(map(str, velocities))
        raise ModelError(f"the Lagrangian is not quadratic in the velocities ({names})")
    zero = {v: 0 for v in velocities}
    gradient = [expr.diff(v) for v in velocities]
    n = len(velocities)
    A = matrix(SR, n, n)
    for i in range(n):
        for j in range(i, n):
            A[i, j] = A[j, i] = gradient[i].diff(velocities[j])
    A1 = matrix(SR, [g.subs(zero) for g in gradient]).row(0) if n else matrix(SR, 0, 0)
    A0 = expr.subs(zero)
    A.set_immutable()
    return A, A1, A0


def linear_collected(expr, symbols):
    r"""
    ``expr``, linear in ``symbols``, as `\sum_s c_s s + c_0` with every
    coefficient simplified by
    :func:`~sage_dynsym.algebra.trigonometric.trig_rational_simplify`.

    EXAMPLES::

        sage: from sage_dynsym.dynamics.natural_form import linear_collected
        sage: a, m, p, q = var('a m p q')
        sage: linear_collected((p - q)*cos(a)^2 + (p - q)*sin(a)^2 + a*q + m, [p, q])
        (a - 1)*q + m + p
    """
    expr = SR(expr)
    rest = trig_rational_simplify(expr.subs({s: 0 for s in symbols}))
    return SR(0).add(*[trig_rational_simplify(expr.diff(s)) * s for s in symbols], rest)


def is_singular(A):
    r"""
    Whether the square symbolic matrix ``A`` is singular identically.

    It is regular if its determinant at a random point is clearly nonzero
    in floating point (relative to Hadamard's bound, the product of the row
    norms); otherwise Sage's exact rank decides. (The symbolic rank alone
    can take minutes on the mass matrix of a chain of bodies.)

    EXAMPLES::

        sage: from sage_dynsym.dynamics.lagrangian import is_singular
        sage: a, m = var('a m')
        sage: is_singular(matrix([[m, m*cos(a)], [m*cos(a), m]]))
        False
        sage: is_singular(matrix([[cos(a)^2, cos(a)], [1 - sin(a)^2, cos(a)]]))
        True
        sage: is_singular(matrix(SR, 0, 0))
        False
    """
    n = A.nrows()
    if n == 0:
        return False
    try:
        variables = sorted(set().union(*(SR(e).variables() for e in A.list())), key=str)
        rng = random.Random(1)
        point = {v: rng.uniform(0.3, 1.7) for v in variables}
        N = A.subs(point).change_ring(RDF)
        bound = prod(row.norm() for row in N.rows())
        if bound > 0 and abs(N.det()) > 1e-8 * bound:
            return False
    except (TypeError, ValueError, ArithmeticError):
        pass   # not numerical at the point (unknown functions, poles, ...)
    return A.rank() < n


def has_full_row_rank(rows):
    r"""
    Whether the symbolic matrix ``rows`` (a matrix or a list of rows) has
    full row rank at a generic point: at a random point, when the Gram
    determinant `\det(C C^H)` is clearly nonzero in 200-bit arithmetic
    (rounding errors, even of terms that cancel, stay near `10^{-60}`
    relative); else exactly (modulo `\cos^2 + \sin^2 = 1`, see
    :mod:`~sage_dynsym.algebra.trig_linear`). Cheaper than
    :func:`is_singular` of `C C^T` on large entries: the product is never
    formed symbolically.

    EXAMPLES::

        sage: from sage_dynsym.dynamics.natural_form import has_full_row_rank
        sage: x, y = var('x y')
        sage: has_full_row_rank([[2*x, 2*y]]), has_full_row_rank([[x, y], [2*x, 2*y]])
        (True, False)
        sage: has_full_row_rank([[cos(x)^2 + sin(x)^2 - 1, 0]])
        False
        sage: has_full_row_rank([])
        True
    """
    from sage.rings.complex_mpfr import ComplexField
    rows = [list(row) for row in rows]
    if not rows:
        return True
    variables = sorted(set().union(*(SR(e).variables() for row in rows for e in row)), key=str)
    rng = random.Random(1)
    CF = ComplexField(200)
    point = {v: CF(rng.uniform(0.3, 1.7)) for v in variables}
    try:
        C = matrix(CF, [[CF(SR(e).subs(point)) for e in row] for row in rows])
        gram = C * C.conjugate_transpose()
        norms = [gram[i, i].real() for i in range(gram.nrows())]
        # a row of cancelling terms is left with rounding errors near 1e-60
        if min(norms) > 1e-80 and abs(gram.det()) > 1e-40 * prod(norms):
            return True
    except (TypeError, ValueError, ArithmeticError):
        pass    # not numerical at the point (unknown functions, poles, ...)
    from ..errors import AnalysisError
    from ..algebra.trig_linear import TrigFractionField
    try:
        K = TrigFractionField([e for row in rows for e in row])
        return K.rank(K.matrix(rows)) == len(rows)
    except AnalysisError:   # not rational in the sines and cosines
        return matrix(SR, rows).rank() == len(rows)


class Elimination:
    r"""
    Symmetric Gaussian elimination `P A P^T = L D L^T` of a symmetric
    invertible matrix `A`, with diagonal pivots (the shortest nonzero
    one first) and every entry simplified modulo `\cos^2+\sin^2 = 1`.

    It writes the quadratic form of `A^{-1}` as a sum of squares
    (Lagrange's reduction), `u^T A^{-1} u = \sum_k y_k^2 / D_k` with
    `L y = P u`: for the heavy symmetric top,
    `p_\varphi^2/C + (p_\psi - p_\varphi\cos\theta)^2/(A\sin^2\theta)`.
    If only zero diagonal entries remain, the rest of the matrix is
    inverted as a block (adjugate over determinant).

    INPUT:

    - ``A`` -- a symmetric invertible matrix over ``SR``
    - ``simplify`` -- (default: :func:`~sage_dynsym.algebra.trigonometric.trig_rational_simplify`
      with ``strict=True``) the simplification of every entry, which must
      turn zero into zero (the pivots are tested); the default raises
      :class:`~sage_dynsym.algebra.trigonometric.NotPolynomial` where it cannot decide
      (inexact numbers, too large fractions)

    EXAMPLES::

        sage: from sage_dynsym.dynamics.lagrangian import Elimination
        sage: from sage_dynsym.algebra.trigonometric import trig_rational_simplify
        sage: a, A, C, p, q = var('a A C p q')
        sage: E = Elimination(matrix([[A*sin(a)^2 + C*cos(a)^2, C*cos(a)], [C*cos(a), C]]))
        sage: E.squares([p, q])
        [q^2/C, (q*cos(a) - p)^2/(A*sin(a)^2)]
        sage: sum(E.products([p, q], [1, 0]))   # first entry of A^{-1} (p, q)
        -(q*cos(a) - p)/(A*sin(a)^2)

    TESTS::

        sage: E = Elimination(matrix([[0, 1], [1, 0]]))
        sage: E.squares([p, q]), sum(E.products([p, q], [1, 0]))
        ([2*p*q], q)
        sage: Elimination(matrix([[0.5*sin(a)^2]]))
        Traceback (most recent call last):
        ...
        NotPolynomial: 0.500000000000000 is not a rational number
        sage: E = Elimination(matrix([[0.5*sin(a)^2]]), simplify=lambda e: e.normalize())
        sage: E.squares([p])
        [2.00000000000000*p^2/sin(a)^2]
    """

    def __init__(self, A, simplify=None):
        if simplify is None:
            def simplify(e):
                return trig_rational_simplify(e, strict=True)
        n = A.nrows()
        self._n = n
        S = {(i, j): simplify(A[i, j]) for i in range(n) for j in range(i, n)}

        def entry(i, j):
            return S[min(i, j), max(i, j)]

        remaining = list(range(n))
        self._order, self._pivots, self._multipliers = [], [], {}
        self._block, self._block_inverse = [], None
        while remaining:
            nonzero = [i for i in remaining if not entry(i, i).is_trivial_zero()]
            if not nonzero:
                block = matrix(SR, [[entry(i, j) for j in remaining] for i in remaining])
                det = simplify(block.det())
                self._block = remaining
                self._block_inverse = block.adjugate().apply_map(lambda e: simplify(e / det))
                break
            k = min(nonzero, key=lambda i: len(str(entry(i, i))))
            remaining.remove(k)
            d = entry(k, k)
            self._order.append(k)
            self._pivots.append(d)
            for i in remaining:
                self._multipliers[i, k] = simplify(entry(i, k) / d)
            for a, i in enumerate(remaining):
                for j in remaining[a:]:
                    key = min(i, j), max(i, j)
                    S[key] = simplify(S[key] - self._multipliers[i, k] * entry(k, j))

    def _reduced(self, u):
        # forward substitution L y = P u (the block indices last)
        y = {}
        for i in self._order + self._block:
            y[i] = u[i] - SR(0).add(*[self._multipliers[i, m] * y[m] for m in self._order
                                      if (i, m) in self._multipliers])
        return y

    def products(self, u, w):
        r"""
        The terms of `u^T A^{-1} w`.

        EXAMPLES: for the heavy symmetric top, the entries of `A^{-1}
        (p, q)`::

            sage: from sage_dynsym.dynamics.natural_form import Elimination
            sage: a, A, C, p, q = var('a A C p q')
            sage: E = Elimination(matrix([[A*sin(a)^2 + C*cos(a)^2, C*cos(a)], [C*cos(a), C]]))
            sage: sum(E.products([p, q], [1, 0])), sum(E.products([p, q], [0, 1]))
            (-(q*cos(a) - p)/(A*sin(a)^2), q/C + (q*cos(a) - p)*cos(a)/(A*sin(a)^2))
        """
        yu, yw = self._reduced(u), self._reduced(w)
        terms = [yu[k] * yw[k] / d for k, d in zip(self._order, self._pivots)]
        for a, i in enumerate(self._block):
            for b, j in enumerate(self._block):
                terms.append(yu[i] * self._block_inverse[a, b] * yw[j])
        return terms

    def squares(self, u, collect=()):
        r"""
        The terms of `u^T A^{-1} u`: `y_k^2/D_k`, with each `y_k` collected
        in the symbols ``collect`` (in which ``u`` is linear).

        EXAMPLES: for the heavy symmetric top, `u^T A^{-1} u` at `u = (p - k,
        q)` as a sum of squares::

            sage: from sage_dynsym.dynamics.natural_form import Elimination
            sage: a, A, C, p, q, k = var('a A C p q k')
            sage: E = Elimination(matrix([[A*sin(a)^2 + C*cos(a)^2, C*cos(a)], [C*cos(a), C]]))
            sage: E.squares([p - k*cos(a)^2 - k*sin(a)^2, q], collect=[p, q])
            [q^2/C, (q*cos(a) + k - p)^2/(A*sin(a)^2)]
        """
        y = {i: linear_collected(v, collect) for i, v in self._reduced(u).items()}
        terms = [y[k] ** 2 / d for k, d in zip(self._order, self._pivots)]
        if self._block:
            quadratic = SR(0).add(*[y[i] * self._block_inverse[a, b] * y[j]
                                    for a, i in enumerate(self._block)
                                    for b, j in enumerate(self._block)])
            terms.append(trig_rational_simplify(quadratic))
        return terms

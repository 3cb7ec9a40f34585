r"""
Exact linear algebra over rational functions of sines and cosines

Matrices met in mechanics -- the velocity constraints of rolling wheels,
kinetic matrices at a point -- have entries that are rational functions of
parameters and of the sines and cosines of angles. Solving them in the
symbolic ring is slow (every pivot goes through a general simplifier) and
can miss a zero hidden by `\cos^2 + \sin^2 = 1`. :class:`TrigFractionField`
writes every entry as a fraction of polynomials of a
:class:`~sage_dynsym.algebra.trigonometric.TrigPolynomialRing` (Singular's
arithmetic, greatest common divisors cancelled), reduces numerators and
denominators modulo `\cos^2 + \sin^2 - 1` after every operation -- a normal
form, so that an entry is zero exactly when it is zero as a function -- and
eliminates with pivots tested that way. The ideal is prime (the polynomial
`c^2 + s^2 - 1` is irreducible), so the fractions form a field and the
elimination is exact.

Inexact numbers (Python floats substituted for parameters) are replaced by
the simplest rationals that round to them.

EXAMPLES::

    sage: from sage_dynsym.algebra.trig_linear import TrigFractionField
    sage: a, r = var('a r')
    sage: K = TrigFractionField([cos(a), sin(a), r])
    sage: A = K.matrix([[cos(a), -sin(a)], [sin(a), cos(a)]])
    sage: X = K.solve_right(A, K.matrix([[r], [0]])); K.expressions(X)
    [[r*cos(a)], [-r*sin(a)]]
    sage: K.rank(K.matrix([[cos(a)^2, 1 - sin(a)^2], [1, 1]]))
    1
"""
from sage.symbolic.ring import SR

from ..errors import AnalysisError
from .trigonometric import TrigPolynomialRing, NotPolynomial, circle_reduce
from .translation import exact_rational

__all__ = ['exact_numbers', 'TrigFractionField']


def exact_numbers(expr):
    r"""
    ``expr`` with every inexact number replaced by the simplest rational
    that rounds to it (see :func:`~sage_dynsym.algebra.translation.exact_rational`).

    EXAMPLES::

        sage: from sage_dynsym.algebra.trig_linear import exact_numbers
        sage: exact_numbers(0.25*var('x') + sin(0.5*var('y')))
        1/4*x + sin(1/2*y)
    """
    expr = SR(expr)
    operator = expr.operator()
    if operator is None:
        if expr.is_numeric() and not expr.is_exact():
            return SR(exact_rational(expr))
        return expr
    operands = [exact_numbers(x) for x in expr.operands()]
    return operator(*operands)


def _terms(x):
    # the size of a fraction (its field is QQ when there are no symbols)
    return sum(getattr(part, 'number_of_terms', lambda: 1)()
               for part in (x.numerator(), x.denominator()))


class TrigFractionField:
    r"""
    Rational functions of the symbols, sines and cosines of ``expressions``,
    exact modulo `\cos^2 + \sin^2 = 1` (see the module documentation).

    INPUT:

    - ``expressions`` -- every expression that will be converted (they fix
      the generators)

    Elements are fractions of Sage's polynomial ring; matrices are lists
    of rows.

    EXAMPLES::

        sage: from sage_dynsym.algebra.trig_linear import TrigFractionField
        sage: b, m = var('b m')
        sage: K = TrigFractionField([m*cos(b)^2 + m*sin(b)^2 - m])
        sage: K.is_zero(K(m*cos(b)^2 + m*sin(b)^2 - m)), K.expression(K(m/sin(b))*K(sin(b)))
        (True, m)

    TESTS::

        sage: TrigFractionField([sqrt(var('x'))])(var('y'))
        Traceback (most recent call last):
        ...
        AnalysisError: linearize: y is not a rational function of the symbols and sines and cosines of the equations
    """

    def __init__(self, expressions):
        self._ring = TrigPolynomialRing.for_expressions(
            [exact_numbers(e) for e in expressions], fractions=True)
        self._field = self._ring.ring.fraction_field()
        self._pairs = list(self._ring._pairs.values())
        self.zero, self.one = self._field.zero(), self._field.one()

    def _reduced(self, polynomial):
        return circle_reduce(polynomial, self._pairs, self._ring.zero)

    def normal(self, x):
        r"""
        ``x`` with numerator and denominator reduced modulo
        `\cos^2 + \sin^2 = 1` and their common factors cancelled.

        EXAMPLES::

            sage: from sage_dynsym.algebra.trig_linear import TrigFractionField
            sage: a = var('a'); K = TrigFractionField([cos(a)])
            sage: c, s = K(cos(a)), K(sin(a))
            sage: K.normal(c^2 + s^2) == K.one
            True
        """
        return (self._field(self._reduced(x.numerator()))
                / self._field(self._reduced(x.denominator())))

    def __call__(self, expr):
        try:
            numerator, denominator = self._ring.fraction(exact_numbers(expr))
        except NotPolynomial as err:
            raise AnalysisError(f"{expr} is not a rational function of the symbols and sines "
                                "and cosines of the equations", entry="linearize") from err
        return self.normal(self._field(numerator) / self._field(denominator))

    def is_zero(self, x):
        r"""
        Whether ``x`` is zero as a function (its reduced numerator is).

        EXAMPLES::

            sage: from sage_dynsym.algebra.trig_linear import TrigFractionField
            sage: a = var('a'); K = TrigFractionField([cos(a)])
            sage: K.is_zero(K(cos(a))^2 + K(sin(a))^2 - 1)
            True
        """
        return self._reduced(x.numerator()).is_zero()

    def expression(self, x):
        r"""
        ``x`` as a symbolic expression, in the shortest form found (see
        :meth:`~sage_dynsym.algebra.trigonometric.TrigPolynomialRing.simplest_fraction`).

        EXAMPLES::

            sage: from sage_dynsym.algebra.trig_linear import TrigFractionField
            sage: a, r = var('a r'); K = TrigFractionField([r*cos(a)])
            sage: K.expression(K(r*cos(a)) / K(r))
            cos(a)
        """
        return self._ring.simplest_fraction(x.numerator(), x.denominator())

    def matrix(self, rows):
        r"""
        The rows of symbolic expressions ``rows`` (a list of lists or a
        matrix) converted.

        EXAMPLES::

            sage: from sage_dynsym.algebra.trig_linear import TrigFractionField
            sage: K = TrigFractionField([var('x')])
            sage: K.expressions(K.matrix(matrix([[x, 1]])))
            [[x, 1]]
        """
        if hasattr(rows, 'rows'):
            rows = rows.rows()
        return [[self(e) for e in row] for row in rows]

    def expressions(self, A):
        r"""
        The matrix ``A`` (a list of rows) as lists of symbolic expressions.

        EXAMPLES: see :meth:`matrix`.
        """
        return [[self.expression(x) for x in row] for row in A]

    def product(self, A, B):
        r"""
        The matrix product `AB` of two lists of rows.

        EXAMPLES::

            sage: from sage_dynsym.algebra.trig_linear import TrigFractionField
            sage: a = var('a'); K = TrigFractionField([cos(a)])
            sage: R = K.matrix([[cos(a), -sin(a)], [sin(a), cos(a)]])
            sage: Rt = K.matrix([[cos(a), sin(a)], [-sin(a), cos(a)]])
            sage: K.expressions(K.product(R, Rt))
            [[1, 0], [0, 1]]
        """
        columns = list(zip(*B)) if B else []
        return [[self.normal(sum((a * b for a, b in zip(row, column)), self.zero))
                 for column in columns] for row in A]

    def _eliminate(self, A, B=None):
        # Gauss--Jordan elimination; pivots are the shortest nonzero entries
        # of their column (less growth). Returns the reduced rows, the
        # right-hand sides and the pivot columns.
        A = [list(row) for row in A]
        B = [list(row) for row in B] if B is not None else [[] for _ in A]
        pivots, top = [], 0
        width = len(A[0]) if A else 0
        for j in range(width):
            rows = [i for i in range(top, len(A)) if not self.is_zero(A[i][j])]
            if not rows:
                continue
            p = min(rows, key=lambda i: _terms(A[i][j]))
            A[top], A[p] = A[p], A[top]
            B[top], B[p] = B[p], B[top]
            inverse = self.one / A[top][j]
            A[top] = [self.normal(x * inverse) for x in A[top]]
            B[top] = [self.normal(x * inverse) for x in B[top]]
            for i in range(len(A)):
                if i != top and not self.is_zero(A[i][j]):
                    f = A[i][j]
                    A[i] = [self.normal(x - f * y) for x, y in zip(A[i], A[top])]
                    B[i] = [self.normal(x - f * y) for x, y in zip(B[i], B[top])]
            pivots.append(j)
            top += 1
        return A, B, pivots

    def rank(self, A):
        r"""
        The rank of ``A`` (a list of rows) as a matrix of functions.

        EXAMPLES: see the module documentation.
        """
        return len(self._eliminate(A)[2]) if A else 0

    def solve_right(self, A, B):
        r"""
        The solution `X` of `AX = B` (lists of rows); `A` must have full
        column rank and the system must be consistent, else ``None``.

        EXAMPLES::

            sage: from sage_dynsym.algebra.trig_linear import TrigFractionField
            sage: x = var('x'); K = TrigFractionField([x])
            sage: A = K.matrix([[1, 0], [0, x], [1, x]])
            sage: K.expressions(K.solve_right(A, K.matrix([[1], [x], [1 + x]])))
            [[1], [1]]
            sage: K.solve_right(A, K.matrix([[1], [x], [0]])) is None
            True
            sage: K.solve_right(K.matrix([[1, 1], [1, 1]]), K.matrix([[1], [1]])) is None
            True
        """
        width = len(A[0]) if A else 0
        R, S, pivots = self._eliminate(A, B)
        if len(pivots) < width:
            return None
        if any(not self.is_zero(x) for row in S[width:] for x in row):
            return None
        return [S[k] for k in range(width)]

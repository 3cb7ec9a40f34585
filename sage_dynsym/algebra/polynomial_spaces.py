r"""
Polynomials over the field of the parameters, and linear algebra on them

A search for polynomials with a linear property (the polynomial integrals
of :mod:`~sage_dynsym.lie.integrals`, the Casimir functions) is a linear
problem in the coefficients of an unknown polynomial: the *image* of each
monomial under a linear map (`F \mapsto \{F, H\}`, `F \mapsto J\nabla F`)
is computed in one Singular
ring `\mathbb{Q}[a, x]` (parameters `a` first, then the variables `x`),
and its coefficients are polynomials in the parameters. The matrix of the
map is block diagonal after a permutation: monomials that share no image
monomial never meet. The blocks (found by union--find) are the weight
spaces of whatever grading the problem has -- the quasi-homogeneous degree
of a heavy top, the weights of a Cartan subalgebra --, each a small matrix
over `\mathbb{Q}(a)`.

Vectors are dictionaries ``{monomial: coefficient}`` (a monomial is the
exponent tuple over the variables, a coefficient an element of
`\mathbb{Q}(a)`); :class:`Reducer` keeps a basis of a growing span.

EXAMPLES::

    sage: from sage_dynsym.algebra.polynomial_spaces import PolynomialContext
    sage: x, y, a = var('x y a')
    sage: P = PolynomialContext([x, y], [a])
    sage: f, d = P.element(x^2/a + y, 'F'); f, d
    (x^2 + a*y, a)
    sage: P.split(f)
    {(0, 1): a, (2, 0): 1}
"""
from sage.arith.functions import lcm
from sage.arith.misc import gcd
from sage.libs.singular.function import singular_function
from sage.matrix.constructor import matrix
from sage.rings.polynomial.polynomial_ring_constructor import PolynomialRing
from sage.rings.rational_field import QQ
from sage.symbolic.ring import SR

from ..errors import AnalysisError

__all__ = ['MAX_MINORS', 'PolynomialContext', 'monomial_expression', 'degree', 'primitive',
           'Reducer', 'blocks', 'LinearProblem', 'minors', 'schur_after_constant_pivots',
           'rank_modulo', 'products', 'generic_point']

#: Most minors of one block the rank-drop conditions may enumerate.
MAX_MINORS = 200_000


class PolynomialContext:
    r"""
    Polynomials in ``variables`` with coefficients in `\mathbb{Q}(a)`,
    `a` the ``parameters``.

    EXAMPLES::

        sage: from sage_dynsym.algebra.polynomial_spaces import PolynomialContext
        sage: P = PolynomialContext(var('x y'), [])
        sage: P.monomials(2)
        [(2, 0), (1, 1), (0, 2), (1, 0), (0, 1)]
        sage: P.to_sr({(1, 1): 3, (1, 0): -1})
        3*x*y - x

    TESTS::

        sage: P.element(sin(var('x')), 'H')
        Traceback (most recent call last):
        ...
        AnalysisError: H: expected a polynomial in x, y (coefficients rational in the parameters), got sin(x)
        sage: P.element(1/var('x'), 'H')
        Traceback (most recent call last):
        ...
        AnalysisError: H: expected a polynomial in x, y (coefficients rational in the parameters), got 1/x
    """

    def __init__(self, variables, parameters):
        self.variables = [SR(v) for v in variables]
        self.parameters = [SR(a) for a in parameters]
        self.np, self.nv = len(self.parameters), len(self.variables)
        names = [str(a) for a in self.parameters] + [str(v) for v in self.variables]
        self.ring = PolynomialRing(QQ, len(names), names, order='degrevlex')
        gens = self.ring.gens()
        self.parameter_gens, self.variable_gens = gens[:self.np], gens[self.np:]
        if self.np:
            self.coefficients = PolynomialRing(QQ, self.np, names[:self.np], order='degrevlex')
            self.field = self.coefficients.fraction_field()
        else:
            self.coefficients = self.field = QQ

    # -- conversions ---------------------------------------------------------

    def element(self, expr, entry):
        r"""
        ``expr`` as a pair ``(f, d)``: ``f`` in the ring, ``d`` a nonzero
        polynomial in the parameters, ``expr = f/d``. Raises
        :class:`AnalysisError` if ``expr`` is not a polynomial in the
        variables with coefficients rational in the parameters.

        EXAMPLES::

            sage: from sage_dynsym.algebra.polynomial_spaces import PolynomialContext
            sage: x, y, a = var('x y a'); P = PolynomialContext([x, y], [a])
            sage: P.element(x*y/(a + 1) - x, 'F')
            (-a*x + x*y - x, a + 1)
        """
        def refuse():
            return AnalysisError(
                f"expected a polynomial in {', '.join(map(str, self.variables))} "
                f"(coefficients rational in the parameters), got {expr}", entry=entry)
        try:
            f = self.ring.fraction_field()(SR(expr))
        except (TypeError, ValueError, ArithmeticError) as err:
            raise refuse() from err
        num, den = f.numerator(), f.denominator()
        if any(den.degree(v) > 0 for v in self.variable_gens):
            raise refuse()
        return num, self.coefficient(den)

    def coefficient(self, f):
        r"""A ring element free of the variables, as a coefficient.

        EXAMPLES::

            sage: from sage_dynsym.algebra.polynomial_spaces import PolynomialContext
            sage: x, y, a = var('x y a'); P = PolynomialContext([x, y], [a])
            sage: c = P.coefficient(P.ring('a^2 - 1')); c, c.parent() is P.coefficients
            (a^2 - 1, True)
        """
        if not self.np:
            return QQ(f.constant_coefficient())
        return self.coefficients({e[:self.np]: c for e, c in f.dict().items()})

    def lift(self, c):
        r"""A coefficient (a polynomial in the parameters) as a ring element.

        EXAMPLES::

            sage: from sage_dynsym.algebra.polynomial_spaces import PolynomialContext
            sage: x, a = var('x a')
            sage: P = PolynomialContext([x], [a])
            sage: f = P.lift(P.field('a^2 + 1')); f, f.parent() is P.ring
            (a^2 + 1, True)
            sage: P.lift(P.field('1/a'))
            Traceback (most recent call last):
            ...
            AnalysisError: coefficient: expected a polynomial in the parameters, got 1/a
        """
        if self.np:
            c = self.field(c)
            if c.denominator() != 1:
                raise AnalysisError(f"expected a polynomial in the parameters, got {c}",
                                    entry="coefficient")
            c = c.numerator()
        return self.ring(c)

    def split(self, f):
        r"""
        ``f`` as ``{monomial: coefficient}``, coefficients polynomials in
        the parameters.

        EXAMPLES::

            sage: from sage_dynsym.algebra.polynomial_spaces import PolynomialContext
            sage: x, y, a = var('x y a'); P = PolynomialContext([x, y], [a])
            sage: sorted(P.split(P.ring('a*x^2 + x^2 - y')).items())
            [((0, 1), -1), ((2, 0), a + 1)]
        """
        out = {}
        np = self.np
        for e, c in f.dict().items():
            key = tuple(e[np:])
            if np:
                out.setdefault(key, {})[tuple(e[:np])] = c
            else:
                out[key] = out.get(key, 0) + c
        if np:
            return {k: self.coefficients(v) for k, v in out.items()}
        return {k: QQ(v) for k, v in out.items() if v}

    def degree(self, f):
        r"""The total degree of a ring element in the variables.

        EXAMPLES::

            sage: from sage_dynsym.algebra.polynomial_spaces import PolynomialContext
            sage: x, y, a = var('x y a'); P = PolynomialContext([x, y], [a])
            sage: P.degree(P.ring('a^5*x + y^2'))
            2
        """
        return max((sum(e[self.np:]) for e in f.exponents()), default=0)

    def monomial(self, m):
        r"""The ring element `x^m`.

        EXAMPLES::

            sage: from sage_dynsym.algebra.polynomial_spaces import PolynomialContext
            sage: x, y, a = var('x y a'); P = PolynomialContext([x, y], [a])
            sage: P.monomial((1, 2))
            x*y^2
        """
        r = self.ring.one()
        for g, k in zip(self.variable_gens, m):
            if k:
                r *= g**k
        return r

    def monomials(self, degree):
        r"""
        Exponent tuples of degree `1, \dots,` ``degree``, by decreasing
        degree (then lexicographically decreasing): the column order.

        EXAMPLES::

            sage: from sage_dynsym.algebra.polynomial_spaces import PolynomialContext
            sage: x, y, a = var('x y a'); P = PolynomialContext([x, y], [a])
            sage: P.monomials(2)
            [(2, 0), (1, 1), (0, 2), (1, 0), (0, 1)]
        """
        out = []
        for d in range(degree, 0, -1):
            out.extend(sorted((m for m in _compositions(d, self.nv)), reverse=True))
        return out

    def polynomial(self, vector):
        r"""A vector with polynomial coefficients as a ring element.

        EXAMPLES::

            sage: from sage_dynsym.algebra.polynomial_spaces import PolynomialContext
            sage: x, y, a = var('x y a'); P = PolynomialContext([x, y], [a])
            sage: P.polynomial({(1, 0): P.field('a'), (0, 2): 1})
            a*x + y^2
        """
        return sum((self.lift(c) * self.monomial(m) for m, c in vector.items()),
                   self.ring.zero())

    def vector(self, f):
        r"""A ring element as a vector over the field, constant term dropped.

        EXAMPLES::

            sage: from sage_dynsym.algebra.polynomial_spaces import PolynomialContext
            sage: x, y, a = var('x y a'); P = PolynomialContext([x, y], [a])
            sage: P.vector(P.ring('a*x + 3'))
            {(1, 0): a}
        """
        return {m: self.field(c) for m, c in self.split(f).items() if any(m)}

    def to_sr(self, vector):
        r"""A vector as a symbolic expression.

        EXAMPLES::

            sage: from sage_dynsym.algebra.polynomial_spaces import PolynomialContext
            sage: x, y, a = var('x y a'); P = PolynomialContext([x, y], [a])
            sage: P.to_sr({(1, 1): P.field('1/a'), (0, 1): 2})
            x*y/a + 2*y
        """
        return sum((SR(c) * monomial_expression(self.variables, m) for m, c in vector.items()),
                   SR(0))


def _compositions(d, n):
    if n == 0:
        if d == 0:
            yield ()
        return
    for k in range(d, -1, -1):
        for rest in _compositions(d - k, n - 1):
            yield (k,) + rest


def monomial_expression(variables, m):
    r"""
    The monomial with exponent tuple ``m`` in the symbolic ``variables``.

    EXAMPLES::

        sage: from sage_dynsym.algebra.polynomial_spaces import monomial_expression
        sage: monomial_expression(var('x y z'), (2, 0, 1))
        x^2*z
    """
    r = SR(1)
    for v, k in zip(variables, m):
        if k:
            r *= v**k
    return r


def degree(m):
    r"""Total degree of an exponent tuple.

    EXAMPLES::

        sage: from sage_dynsym.algebra.polynomial_spaces import degree
        sage: degree((2, 0, 1))
        3
    """
    return sum(m)


# -- vectors ---------------------------------------------------------------

def primitive(vector, field):
    r"""
    ``vector`` scaled to coprime polynomial coefficients, its first
    (highest) coefficient with a positive leading coefficient.

    EXAMPLES::

        sage: from sage_dynsym.algebra.polynomial_spaces import primitive
        sage: F = PolynomialRing(QQ, 'a').fraction_field(); a = F.gen()
        sage: sorted(primitive({(2,): -1/a, (1,): 2/a^2}, F).items())
        [((1,), -2), ((2,), a)]
    """
    if not vector:
        return {}
    keys = sorted(vector, key=lambda m: (degree(m), m), reverse=True)
    if field is QQ:
        den = lcm([QQ(c).denominator() for c in vector.values()])
        nums = [QQ(c) * den for c in vector.values()]
        g = gcd(nums)
        scale = den / g
        if QQ(vector[keys[0]]) * scale < 0:
            scale = -scale
        return {m: QQ(vector[m]) * scale for m in keys}
    den = lcm([c.denominator() for c in vector.values()])
    nums = [(c * den).numerator() for c in vector.values()]
    g = gcd(nums)
    scaled = {m: (vector[m] * den / g).numerator() for m in keys}
    rationals = [QQ(r) for c in scaled.values() for r in c.coefficients()]
    content = gcd([r.numerator() for r in rationals]) / lcm([r.denominator() for r in rationals])
    if scaled[keys[0]].lc() < 0:
        content = -content
    return {m: c / content for m, c in scaled.items()}


def _rows(A, columns):
    return [{columns[j]: c for j, c in enumerate(row) if c} for row in A.rows()]


class Reducer:
    r"""
    Incremental Gaussian elimination: :meth:`add` keeps a vector if it is
    independent of those kept so far.

    EXAMPLES::

        sage: from sage_dynsym.algebra.polynomial_spaces import Reducer
        sage: R = Reducer(QQ)
        sage: R.add({(2,): 1, (1,): 1}), R.add({(2,): 2, (1,): 2}), R.add({(1,): 1}), R.rank()
        (True, False, True, 2)
    """

    def __init__(self, field):
        self.field = field
        self.rows = []

    def rank(self):
        r"""The number of vectors kept.

        EXAMPLES::

            sage: from sage_dynsym.algebra.polynomial_spaces import Reducer
            sage: R = Reducer(QQ); R.add({(1,): 1}); R.rank()
            True
            1
        """
        return len(self.rows)

    def reduce(self, v):
        r"""``v`` reduced by the vectors kept: ``{}`` iff ``v`` is in their span.

        EXAMPLES::

            sage: from sage_dynsym.algebra.polynomial_spaces import Reducer
            sage: R = Reducer(QQ); R.add({(2,): 1, (1,): 1})
            True
            sage: R.reduce({(2,): 3, (1,): 3}), R.reduce({(2,): 1})
            ({}, {(1,): -1})
        """
        v = {m: self.field(c) for m, c in v.items() if c}
        for p, e in self.rows:
            c = v.get(p)
            if c:
                for m, x in e.items():
                    y = v.get(m, 0) - c * x
                    if y:
                        v[m] = y
                    else:
                        v.pop(m, None)
        return v

    def add(self, v):
        r"""Keep ``v`` if it is independent of the vectors kept; whether it was.

        EXAMPLES::

            sage: from sage_dynsym.algebra.polynomial_spaces import Reducer
            sage: R = Reducer(QQ)
            sage: R.add({(1, 0): 1}), R.add({(1, 0): -2}), R.add({(0, 1): 1})
            (True, False, True)
        """
        v = self.reduce(v)
        if not v:
            return False
        # pivot: the highest degree, then the highest power of the last
        # coordinates (representatives modulo the products then avoid
        # them: Kovalevskaya's integral, free of M3 and gamma3^2, comes out
        # as she wrote it)
        p = max(v, key=lambda m: (degree(m), m[::-1]))
        c = v[p]
        self.rows.append((p, {m: x / c for m, x in v.items()}))
        return True


# -- kernels by blocks -----------------------------------------------------

def blocks(images):
    r"""
    The connected components of the columns of a sparse matrix given by
    ``images`` (a list of ``{row_key: coefficient}``): lists of column
    indices; two columns meet if they share a row.

    EXAMPLES::

        sage: from sage_dynsym.algebra.polynomial_spaces import blocks
        sage: blocks([{'a': 1}, {'b': 1}, {'a': 2, 'c': 1}, {}])
        [[0, 2], [1], [3]]
    """
    parent = list(range(len(images)))

    def find(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    owner = {}
    for j, image in enumerate(images):
        for key in image:
            if key in owner:
                a, b = find(owner[key]), find(j)
                if a != b:
                    parent[max(a, b)] = min(a, b)
            else:
                owner[key] = j
    groups = {}
    for j in range(len(images)):
        groups.setdefault(find(j), []).append(j)
    return sorted(groups.values())


class LinearProblem:
    r"""
    The matrix of a linear map on the polynomials of degree `1..d`, by
    blocks.

    INPUT:

    - ``context`` -- a :class:`PolynomialContext`
    - ``columns`` -- the monomials (column order)
    - ``images`` -- for each column, ``{row_key: coefficient}`` with
      polynomial coefficients in the parameters

    EXAMPLES: the integrals of degree `\le 2` of `\dot x = y,\ \dot y = -x`::

        sage: from sage_dynsym.algebra.polynomial_spaces import PolynomialContext, LinearProblem
        sage: x, y = var('x y'); P = PolynomialContext([x, y], [])
        sage: X = [P.element(y, 'X')[0], P.element(-x, 'X')[0]]
        sage: cols = P.monomials(2)
        sage: images = [P.split(sum(m[i] * P.monomial(tuple(k - (j == i) for j, k in enumerate(m)))
        ....:                       * X[i] for i in range(2) if m[i])) for m in cols]
        sage: L = LinearProblem(P, cols, images)
        sage: [P.to_sr(v) for v in L.kernel()]
        [x^2 + y^2]
    """

    def __init__(self, context, columns, images):
        self.context = context
        self.columns = list(columns)
        self.images = images
        self.blocks = blocks(images)
        self._kernel = self._rational = None

    def block_matrix(self, block, ring=None):
        r"""The matrix of one block (rows in a fixed order) over ``ring``.

        EXAMPLES::

            sage: from sage_dynsym.algebra.polynomial_spaces import PolynomialContext, LinearProblem
            sage: P = PolynomialContext(var('x y'), [])
            sage: L = LinearProblem(P, [(1, 0), (0, 1)], [{'u': 1}, {'u': 2, 'v': 1}])
            sage: L.blocks, L.block_matrix([0, 1])
            (
                        [1 2]
            [[0, 1]],   [0 1]
            )
        """
        ring = ring or self.context.field
        rows = sorted({k for j in block for k in self.images[j]}, key=repr)
        index = {k: i for i, k in enumerate(rows)}
        A = matrix(ring, len(rows), len(block))
        for col, j in enumerate(block):
            for k, c in self.images[j].items():
                A[index[k], col] = c
        return A

    def kernel(self):
        r"""
        A basis of the kernel (a list of vectors), block by block. Over
        `\mathbb{Q}` in reduced echelon form; with parameters, independent
        generators of the module of syzygies over `\mathbb{Q}[a]`
        (Singular's ``syz``: fraction-free, no growth of rational
        functions), which span the kernel over `\mathbb{Q}(a)`. Cached.

        EXAMPLES: the kernel of `(c_1, c_2) \mapsto c_1 a - c_2` over
        `\mathbb{Q}(a)`::

            sage: from sage_dynsym.algebra.polynomial_spaces import PolynomialContext, LinearProblem
            sage: P = PolynomialContext(var('x y'), [var('a')])
            sage: L = LinearProblem(P, [(1, 0), (0, 1)], [{'u': P.coefficients('a')}, {'u': -1}])
            sage: [P.to_sr(v) for v in L.kernel()]
            [a*y + x]
        """
        if self._kernel is None:
            out = []
            for block in self.blocks:
                cols = [self.columns[j] for j in block]
                if not any(self.images[j] for j in block):
                    out.extend({m: self.context.field.one()} for m in cols)
                elif not self.context.np:
                    K = self.block_matrix(block).right_kernel_matrix(basis='echelon')
                    out.extend(_rows(K, cols))
                else:
                    A = self.block_matrix(block, self.context.coefficients)
                    independent = Reducer(self.context.field)
                    for z in _syzygies(A):
                        v = {m: self.context.field(c) for m, c in zip(cols, z) if c}
                        if independent.add(v):
                            out.append(v)
            self._kernel = out
        return self._kernel

    def rational_kernel(self):
        r"""
        A basis of the kernel vectors with rational coefficients (integrals
        for all parameter values): the common kernel of the coefficients
        of each power product of the parameters. Cached.

        EXAMPLES::

            sage: from sage_dynsym.algebra.polynomial_spaces import PolynomialContext, LinearProblem
            sage: P = PolynomialContext(var('x y'), [var('a')])
            sage: c = P.coefficients('a')
            sage: L = LinearProblem(P, [(1, 0), (0, 1)], [{'u': c}, {'u': c^0}])
            sage: L.rational_kernel()
            []
            sage: L = LinearProblem(P, [(1, 0), (0, 1)], [{'u': c}, {'u': -c}])
            sage: [P.to_sr(v) for v in L.rational_kernel()]
            [x + y]
        """
        if self._rational is None:
            out = []
            for block in self.blocks:
                images = [self.images[j] for j in block]
                if not any(images):
                    out.extend({self.columns[j]: 1} for j in block)
                    continue
                rows = {}
                for col, image in enumerate(images):
                    for key, c in image.items():
                        for e, q in (c.dict().items() if self.context.np else [((), c)]):
                            rows.setdefault((key, tuple(e)), {})[col] = q
                A = matrix(QQ, len(rows), len(block), sparse=True)
                for i, entries in enumerate(rows.values()):
                    for col, q in entries.items():
                        A[i, col] = q
                K = A.right_kernel_matrix(basis='echelon')
                cols = [self.columns[j] for j in block]
                out.extend(_rows(K, cols))
            self._rational = [{m: self.context.field(c) for m, c in v.items()} for v in out if v]
        return self._rational


def _syzygies(A):
    # generators of {v : A v = 0} over the polynomial ring
    Z = singular_function('syz')(A)
    return [list(z) for z in (Z.columns() if hasattr(Z, 'columns') else Z) if any(z)]


def minors(S, r):
    r"""
    The nonzero `r \times r` minors of the polynomial matrix ``S``
    (Singular's ``minor``: Bareiss elimination).

    EXAMPLES::

        sage: from sage_dynsym.algebra.polynomial_spaces import minors
        sage: R.<a, b> = QQ[]
        sage: S = matrix(R, [[a, b], [0, a]])
        sage: minors(S, 2), minors(S, 1)
        ([a^2], [a, b, a])
    """
    if r == 1:
        return [c for c in S.list() if c]
    return [m for m in singular_function('minor')(S, r) if m]


def schur_after_constant_pivots(A):
    r"""
    Eliminate with every nonzero constant entry as a pivot; return the
    remaining matrix (rows and columns without a pivot) and the number of
    pivots, or ``(None, k)`` when nothing remains.

    EXAMPLES::

        sage: from sage_dynsym.algebra.polynomial_spaces import schur_after_constant_pivots
        sage: R.<a> = QQ[]
        sage: schur_after_constant_pivots(matrix(R, [[1, a], [a, 1]]))
        ([-a^2 + 1], 1)
    """
    A = A.__copy__()
    rows, cols = list(range(A.nrows())), list(range(A.ncols()))
    pivots = 0
    while True:
        found = None
        for i in rows:
            for j in cols:
                c = A[i, j]
                if c and c.is_constant():
                    found = (i, j)
                    break
            if found:
                break
        if not found:
            break
        i, j = found
        p = A[i, j]
        for k in rows:
            if k != i and A[k, j]:
                A.add_multiple_of_row(k, i, -A[k, j] / p)
        rows.remove(i)
        cols.remove(j)
        pivots += 1
    if not rows or not cols:
        return None, pivots
    return A.matrix_from_rows_and_columns(rows, cols), pivots


def rank_modulo(A, prime):
    r"""
    The rank of the polynomial matrix ``A`` over the function field of the
    variety of the prime ideal ``prime``: fraction-free elimination with
    entries reduced to normal forms (an entry is zero on the component iff
    its normal form is zero; the quotient is a domain).

    EXAMPLES::

        sage: from sage_dynsym.algebra.polynomial_spaces import rank_modulo
        sage: R.<a, b> = QQ[]
        sage: A = matrix(R, [[a, b], [b, a]])
        sage: rank_modulo(A, R.ideal(0)), rank_modulo(A, R.ideal(a - b)), rank_modulo(A, R.ideal(a, b))
        (2, 1, 0)
    """
    G = prime.groebner_basis()

    def nf(f):
        return f.reduce(G) if f else f
    rows = [[nf(c) for c in row] for row in A.rows()]
    rank = 0
    ncols = A.ncols()
    for j in range(ncols):
        pivot = next((i for i in range(rank, len(rows)) if rows[i][j]), None)
        if pivot is None:
            continue
        rows[rank], rows[pivot] = rows[pivot], rows[rank]
        p = rows[rank][j]
        for i in range(rank + 1, len(rows)):
            c = rows[i][j]
            if c:
                rows[i] = [nf(p * x - c * y) for x, y in zip(rows[i], rows[rank])]
        rank += 1
    return rank


def products(generators, max_degree):
    r"""
    All products of the ring elements ``generators`` (with repetition) of
    total degree at most ``max_degree``, the generators themselves
    included. Each generator is a pair ``(ring_element, degree)``.

    EXAMPLES::

        sage: from sage_dynsym.algebra.polynomial_spaces import products
        sage: R.<x, y> = QQ[]
        sage: products([(x, 1), (y^2, 2)], 3)
        [x, x^2, x^3, x*y^2, y^2]
    """
    out = []

    def extend(start, current, deg):
        for i in range(start, len(generators)):
            g, d = generators[i]
            if d + deg <= max_degree:
                f = g if current is None else current * g
                out.append(f)
                extend(i, f, deg + d)
    extend(0, None, 0)
    return out


def generic_point(parameters, seed=0):
    r"""
    A reproducible random rational point for the parameters (used only to
    test functional independence, where a zero is a probability-zero event).

    EXAMPLES::

        sage: from sage_dynsym.algebra.polynomial_spaces import generic_point
        sage: a, b = var('a b')
        sage: generic_point([a, b]) == generic_point([a, b]), sorted(generic_point([a, b]))
        (True, [a, b])
    """
    import random
    rng = random.Random(seed)
    return {a: QQ(rng.randint(2, 97)) / rng.randint(1, 13) for a in parameters}


r"""
The arithmetic of the rigid-body recursions, and their vectors

The recursive algorithms of rigid-body dynamics
(:mod:`~sage_dynsym.numerics.tree_kinematics`,
:mod:`~sage_dynsym.numerics.newton_euler`,
:mod:`~sage_dynsym.numerics.composite_body`,
:mod:`~sage_dynsym.numerics.articulated_body`) are written once, over an
*arithmetic* chosen by the caller -- a strategy object, in the spirit of
SageManifolds' ``calc_method``, with the scalars ``zero`` and ``one`` and
the operations ``add``, ``sub``, ``mul``, ``div``, ``neg``, ``dot``,
``sum``, ``call``, ``constant`` and ``is_zero``:

- an :class:`~sage_dynsym.numerics.graph.ExpressionGraph`, whose nodes are
  compiled (:mod:`~sage_dynsym.numerics.recursive`);
- :class:`SymbolicArithmetic`: Sage's symbolic expressions.

The functions of this module are the vector operations of the recursions
(3-vectors as tuples of scalars of the arithmetic, 3x3 matrices as lists
of rows).

EXAMPLES: the rotation of a vector given in the axes of a frame turned by
`a` about the third axis, into the axes before the turn, in both
arithmetics::

    sage: from sage_dynsym.numerics.spatial import SymbolicArithmetic, rotate
    sage: a, x = var('a x')
    sage: S = SymbolicArithmetic()
    sage: rotate(S, 3, cos(a), sin(a), (x, 0, 0))
    (x*cos(a), x*sin(a), 0)
    sage: from sage_dynsym.numerics.graph import ExpressionGraph
    sage: G = ExpressionGraph(); c, s, y = (G.input('x', i) for i in range(3))
    sage: [G.show(e) for e in rotate(G, 3, c, s, (y, G.zero, G.zero))]
    ['x[0]*x[2]', 'x[1]*x[2]', '0.0']
"""
from sage.symbolic.operators import add_vararg
from sage.symbolic.ring import SR

__all__ = ['SymbolicArithmetic', 'held_product', 'cross', 'add', 'scale', 'matvec', 'skew', 'rotate',
           'rotate_matrix']


def held_product(a, b):
    r"""
    `a b`, left unevaluated when a factor is a sum (and none a number): the
    product of :class:`SymbolicArithmetic`. Sage's
    evaluation of a product of large nested sums costs far more than the
    product itself (tenths of a second each for the chain of 15 links with
    numerical data of ``bench/bench_pipeline.py``), and the recursive
    equations multiply such sums throughout.

    EXAMPLES::

        sage: from sage_dynsym.numerics.spatial import held_product
        sage: x, y = var('x y')
        sage: held_product(x + y, x - y), held_product(x, y), held_product(2, x + y)
        ((x + y)*(x - y), x*y, 2*x + 2*y)
    """
    a, b = SR(a), SR(b)
    if a.is_numeric() or b.is_numeric() or not (a.operator() is add_vararg
                                                or b.operator() is add_vararg):
        return a * b
    return a.mul(b, hold=True)


class SymbolicArithmetic:
    r"""
    The arithmetic of Sage's symbolic ring for the recursive algorithms
    (see the module documentation): the same operations as an
    :class:`~sage_dynsym.numerics.graph.ExpressionGraph`, on symbolic
    expressions.

    EXAMPLES::

        sage: from sage_dynsym.numerics.spatial import SymbolicArithmetic
        sage: S = SymbolicArithmetic(); x, y = var('x y')
        sage: S.dot([x, 0, y], [y, x, 1]), S.sum([x, y, x]), S.call('abs', -x)
        (x*y + y, 2*x + y, abs(x))
        sage: S.is_zero(S.sub(x, x)), S.is_zero(S.constant(0.0)), S.div(S.one, x)
        (True, True, 1/x)
        sage: bool(S.add(x, S.neg(S.mul(S.zero, y))) == x)
        True
    """

    zero = SR.zero()
    one = SR.one()

    def constant(self, value):
        r"""The number ``value`` as a symbolic expression.

        EXAMPLES: see the class documentation.
        """
        return SR(value)

    def add(self, a, b):
        r"""`a + b`.

        EXAMPLES: see the class documentation.
        """
        return a + b

    def sub(self, a, b):
        r"""`a - b`.

        EXAMPLES: see the class documentation.
        """
        return a - b

    def mul(self, a, b):
        r"""`a b`, held when a factor is a sum (see :func:`held_product`).

        EXAMPLES: see the class documentation.
        """
        return held_product(a, b)

    def div(self, a, b):
        r"""`a / b`.

        EXAMPLES: see the class documentation.
        """
        return a / b

    def neg(self, a):
        r"""`-a`.

        EXAMPLES: see the class documentation.
        """
        return -a

    def dot(self, u, w):
        r"""`\sum_i u_i w_i` (the products with a zero factor left out).

        EXAMPLES: see the class documentation.
        """
        return SR.zero().add(*[held_product(a, b) for a, b in zip(u, w)
                               if not (SR(a).is_trivial_zero() or SR(b).is_trivial_zero())])

    def sum(self, terms):
        r"""The sum of ``terms``.

        EXAMPLES: see the class documentation.
        """
        return SR.zero().add(*terms)

    def call(self, name, *args):
        r"""The function ``name`` of Sage's symbolic ring applied to ``args``.

        EXAMPLES: see the class documentation.
        """
        from sage.symbolic.function_factory import function
        from sage.functions.other import abs_symbolic
        known = {'abs': abs_symbolic}
        f = known.get(name) or function(name)
        return f(*args)

    def is_zero(self, a):
        r"""Whether ``a`` is zero as it stands (no simplification is tried).

        EXAMPLES: see the class documentation.
        """
        return SR(a).is_trivial_zero()


def cross(G, u, w):
    r"""
    The cross product `u\times w` in the arithmetic ``G``.

    EXAMPLES::

        sage: from sage_dynsym.numerics.spatial import SymbolicArithmetic, cross
        sage: cross(SymbolicArithmetic(), (1, 0, 0), (0, 1, 0))
        (0, 0, 1)
    """
    return (G.sub(G.mul(u[1], w[2]), G.mul(u[2], w[1])),
            G.sub(G.mul(u[2], w[0]), G.mul(u[0], w[2])),
            G.sub(G.mul(u[0], w[1]), G.mul(u[1], w[0])))


def add(G, *vectors):
    r"""
    The sum of 3-vectors in the arithmetic ``G``.

    EXAMPLES::

        sage: from sage_dynsym.numerics.spatial import SymbolicArithmetic, add
        sage: x = var('x'); add(SymbolicArithmetic(), (x, 0, 1), (x, 1, 0), (0, 0, 1))
        (2*x, 1, 2)
    """
    return tuple(G.sum(parts) for parts in zip(*vectors))


def scale(G, s, v):
    r"""
    The 3-vector ``v`` times the scalar ``s`` in the arithmetic ``G``.

    EXAMPLES::

        sage: from sage_dynsym.numerics.spatial import SymbolicArithmetic, scale
        sage: m = var('m'); scale(SymbolicArithmetic(), m, (1, 0, 2))
        (m, 0, 2*m)
    """
    return tuple(G.mul(s, a) for a in v)


def matvec(G, A, v):
    r"""
    The product `A v` of a 3x3 matrix (a list of rows) and a 3-vector.

    EXAMPLES::

        sage: from sage_dynsym.numerics.spatial import SymbolicArithmetic, matvec
        sage: x = var('x'); matvec(SymbolicArithmetic(), [[1, 0, 0], [0, 2, 0], [0, 0, x]], (1, 1, 1))
        (1, 2, x)
    """
    return tuple(G.dot(row, v) for row in A)


def skew(G, r):
    r"""
    The matrix `[r]` of the cross product `r\times\cdot` (a list of rows).

    EXAMPLES::

        sage: from sage_dynsym.numerics.spatial import SymbolicArithmetic, skew
        sage: x = var('x'); skew(SymbolicArithmetic(), (x, 0, 1))
        [[0, -1, 0], [1, 0, -x], [0, x, 0]]
    """
    return [[G.zero, G.neg(r[2]), r[1]], [r[2], G.zero, G.neg(r[0])],
            [G.neg(r[1]), r[0], G.zero]]


_PLANE = {1: (1, 2), 2: (2, 0), 3: (0, 1)}


def rotate(G, axis, c, s, v, inverse=False):
    r"""
    The components `R v` in the old frame of the vector ``v`` given in the
    new one, or the converse `R^T v` with ``inverse``; `R` is the
    elementary rotation about ``axis`` (1, 2 or 3) by the angle of cosine
    ``c`` and sine ``s``.

    EXAMPLES: see the module documentation; and back::

        sage: from sage_dynsym.numerics.spatial import SymbolicArithmetic, rotate
        sage: a = var('a'); S = SymbolicArithmetic()
        sage: v = rotate(S, 3, cos(a), sin(a), (1, 0, 0))
        sage: [SR(e).simplify_trig() for e in rotate(S, 3, cos(a), sin(a), v, inverse=True)]
        [1, 0, 0]
    """
    i, j = _PLANE[axis]
    if inverse:
        s = G.neg(s)
    out = list(v)
    out[i] = G.sub(G.mul(c, v[i]), G.mul(s, v[j]))
    out[j] = G.add(G.mul(s, v[i]), G.mul(c, v[j]))
    return tuple(out)


def rotate_matrix(G, axis, c, s, A, symmetric=True):
    r"""
    `R A R^T` of a 3x3 matrix ``A`` (a list of rows) given in the new frame
    of the elementary rotation `R` (see :func:`rotate`); with
    ``symmetric``, ``A`` is taken as symmetric and only the upper triangle
    of the result is computed.

    EXAMPLES::

        sage: from sage_dynsym.numerics.spatial import SymbolicArithmetic, rotate_matrix
        sage: rotate_matrix(SymbolicArithmetic(), 3, 0, 1, [[1, 0, 0], [0, 2, 0], [0, 0, 3]])
        [[2, 0, 0], [0, 1, 0], [0, 0, 3]]
    """
    # R A R^T = (R (R A)^T)^T
    columns = [rotate(G, axis, c, s, [A[r][col] for r in range(3)]) for col in range(3)]
    RA = [[columns[col][r] for col in range(3)] for r in range(3)]
    rows = [rotate(G, axis, c, s, RA[r]) for r in range(3)]
    if symmetric:
        return [[rows[min(r, col)][max(r, col)] for col in range(3)] for r in range(3)]
    return [list(row) for row in rows]

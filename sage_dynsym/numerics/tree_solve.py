r"""
Solving for the accelerations of a tree: factorizations with checked pivots

:func:`ltdl` factorizes a mass matrix `M = L^T D L` in the order of the
tree, leaves first, which creates no fill-in for a tree ([Fea2008]_,
Section 6.5, "LTDL"); :func:`dense_solve` and :func:`inverse` solve the
small dense systems of the constraint multipliers and of the joints of the
articulated-body algorithm. Every pivot `d` leaves its margin `|d| -
\epsilon |s|` against a scale `s` (see :data:`PIVOT_TOLERANCE`) in the list
``pivots``: the compiled code refuses the states where a margin is not
positive. All work in either arithmetic of :mod:`~sage_dynsym.numerics.spatial`.

EXAMPLES::

    sage: from sage_dynsym.numerics.spatial import SymbolicArithmetic
    sage: from sage_dynsym.numerics.tree_solve import dense_solve, ltdl
    sage: S = SymbolicArithmetic(); pivots = []
    sage: dense_solve(S, [[2, 1], [1, 3]], [3, 4], pivots, [1, 1])
    [1, 1]
    sage: solve = ltdl(S, {(0, 0): 2, (0, 1): 1, (1, 0): 1, (1, 1): 3}, [0, 1], pivots)
    sage: solve([3, 4]), len(pivots)
    ([1, 1], 4)
"""
__all__ = ['PIVOT_TOLERANCE', 'pivot', 'inverse', 'dense_solve', 'ltdl']

#: a pivot at most this fraction of its scale is taken as zero: the system
#: is singular or as close to it as rounding can tell (a rotation chart
#: within about 1e-6 of its singular set)
PIVOT_TOLERANCE = 1e-12


def pivot(G, d, scale, pivots):
    r"""
    Append the margin `|d| - \epsilon |s|` of the pivot ``d`` against its
    ``scale`` `s` (`\epsilon` = :data:`PIVOT_TOLERANCE`) to ``pivots``.

    EXAMPLES::

        sage: from sage_dynsym.numerics.spatial import SymbolicArithmetic
        sage: from sage_dynsym.numerics.tree_solve import pivot
        sage: pivots = []; pivot(SymbolicArithmetic(), var('d'), 2, pivots); pivots
        [abs(d) - 2e-12]
    """
    pivots.append(G.sub(G.call('abs', d), G.mul(G.constant(PIVOT_TOLERANCE),
                                                 G.call('abs', scale))))


def inverse(G, A, pivots, scales):
    r"""
    The inverse of a small symmetric positive definite matrix ``A`` (a list
    of rows; Gauss--Jordan without pivoting), the margins of its pivots
    against ``scales`` appended to ``pivots``.

    EXAMPLES::

        sage: from sage_dynsym.numerics.spatial import SymbolicArithmetic
        sage: from sage_dynsym.numerics.tree_solve import inverse
        sage: inverse(SymbolicArithmetic(), [[2, 0], [0, 4]], [], [1, 1])
        [[1/2, 0], [0, 1/4]]
    """
    m = len(A)
    if m == 1:
        pivot(G, A[0][0], scales[0], pivots)
        return [[G.div(G.one, A[0][0])]]
    columns = [[G.one if i == j else G.zero for i in range(m)] for j in range(m)]
    return [list(x) for x in zip(*[dense_solve(G, A, b, pivots if j == 0 else [], scales)
                                   for j, b in enumerate(columns)])]


def dense_solve(G, A, b, pivots, scales):
    r"""
    The solution of a small symmetric positive definite system `A x = b`
    (Gaussian elimination without pivoting), the margins of its pivots
    against ``scales`` appended to ``pivots``.

    EXAMPLES: see the module documentation.
    """
    m = len(b)
    A = [list(row) for row in A]
    b = list(b)
    for c in range(m):
        pivot(G, A[c][c], scales[c], pivots)
        for r in range(c + 1, m):
            factor = G.div(A[r][c], A[c][c])
            for k in range(c + 1, m):
                A[r][k] = G.sub(A[r][k], G.mul(factor, A[c][k]))
            b[r] = G.sub(b[r], G.mul(factor, b[c]))
    x = [None] * m
    for r in range(m - 1, -1, -1):
        x[r] = G.div(G.sub(b[r], G.dot(A[r][r + 1:], x[r + 1:])), A[r][r])
    return x


def ltdl(G, M, order, pivots):
    r"""
    The factorization `M = L^T D L` of the mass matrix ``M`` (a dict
    ``(i, j) -> entry`` of both triangles, zeros absent) in the tree
    ``order`` of the coordinates (see
    :func:`~sage_dynsym.numerics.tree_kinematics.tree_order`), as the
    function solving `M x = b` for a list ``b``; the margins of the pivots
    (against the diagonal of ``M``) are appended to ``pivots``.

    EXAMPLES: see the module documentation.
    """
    n = len(order)
    position = {i: a for a, i in enumerate(order)}
    # H: the lower triangle of M in tree order, overwritten by L and D
    H = {}
    for (i, j), value in M.items():
        a, b = position[i], position[j]
        if a >= b and not G.is_zero(value):
            H[a, b] = value
    rows = [sorted(b for (a2, b) in H if a2 == a and b < a) for a in range(n)]
    for k in range(n - 1, -1, -1):
        d = H.get((k, k), G.zero)
        pivot(G, d, M.get((order[k], order[k]), G.zero), pivots)
        below = rows[k]
        for i in reversed(below):
            factor = G.div(H[k, i], d)
            for j in below:
                if j > i:
                    break
                update = G.sub(H.get((i, j), G.zero), G.mul(factor, H[k, j]))
                if (i, j) not in H:
                    rows[i].append(j)
                    rows[i].sort()
                H[i, j] = update
            H[k, i] = factor
    D = [H.get((k, k), G.zero) for k in range(n)]

    def solve(b):
        y = [b[i] for i in order]
        for k in range(n - 1, -1, -1):
            for i in rows[k]:
                y[i] = G.sub(y[i], G.mul(H[k, i], y[k]))
        x = [G.div(y[k], D[k]) for k in range(n)]
        for k in range(n):
            x[k] = G.sub(x[k], G.dot([H[k, i] for i in rows[k]], [x[i] for i in rows[k]]))
        out = [None] * n
        for a, i in enumerate(order):
            out[i] = x[a]
        return out
    return solve

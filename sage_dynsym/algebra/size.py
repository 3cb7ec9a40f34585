r"""
Size estimates of symbolic computations

A computation whose result would have too many polynomial terms is refused
*before* it runs (see :class:`~sage_dynsym.errors.BudgetError`): the
reports and the analysis estimate the size of what they are about to
create from the trees of their inputs, without expanding anything.

EXAMPLES::

    sage: from sage_dynsym.algebra.size import polynomial_terms
    sage: x, y = var('x y')
    sage: polynomial_terms((x + y)^200)
    201
"""
import operator

from sage.symbolic.operators import add_vararg, mul_vararg
from sage.symbolic.ring import SR

__all__ = ['TERMS_CAP', 'PERMANENT_STATES', 'polynomial_terms', 'determinant_terms',
           'matrix_terms']

#: Term counts beyond this are reported as this (they are over any budget).
TERMS_CAP = 10**30

#: Largest number of partial states of the permanent bound of
#: :func:`determinant_terms` before the cruder product bound is used.
PERMANENT_STATES = 20_000


def polynomial_terms(expr):
    r"""
    An upper bound of the number of terms of ``expr`` once expanded, from
    its tree alone (nothing is expanded): sums add, products multiply, a
    power `a^n` with a positive integer `n` counts the monomials of degree
    `n` in the terms of `a`; functions and other powers are single atoms.
    Capped at `10^{30}`.

    EXAMPLES::

        sage: from sage_dynsym.algebra.size import polynomial_terms
        sage: x, y, z = var('x y z')
        sage: polynomial_terms((x + y)*(x + z + 1)), ((x + y)*(x + z + 1)).expand().number_of_operands()
        (6, 6)
        sage: polynomial_terms((x + y + z)^10), len(((x + y + z)^10).expand().operands())
        (66, 66)
        sage: polynomial_terms(sin(x + y)/(x + y)), polynomial_terms(SR(0))
        (1, 0)
    """
    try:
        return min(_terms(SR(expr), {}), TERMS_CAP)
    except RecursionError:
        return TERMS_CAP


def _terms(e, seen):
    # ``seen``: the counts of the subexpressions met so far, by structural
    # hash (large expressions repeat their factors: ten times faster)
    key = hash(e)
    for other, count in seen.get(key, ()):
        if e.is_trivially_equal(other):
            return count
    count = _count(e, seen)
    seen.setdefault(key, []).append((e, count))
    return count


def _count(e, seen):
    op = e.operator()
    if op is None:
        return 0 if e.is_zero() else 1
    if op is add_vararg:
        return min(sum(_terms(x, seen) for x in e.operands()), TERMS_CAP)
    if op is mul_vararg:
        count = 1
        for x in e.operands():
            count = min(count * _terms(x, seen), TERMS_CAP)
        return count
    if op is operator.pow:
        base, exponent = e.operands()
        if exponent.is_integer() and exponent > 0:
            from sage.arith.misc import binomial
            k, n = _terms(base, seen), int(min(exponent, 10**6))
            return min(binomial(k + n - 1, n), TERMS_CAP) if k > 1 else k
    return 1


def determinant_terms(counts):
    r"""
    An upper bound of the number of terms of the expanded determinant of a
    matrix whose entries have ``counts[i][j]`` terms: the permanent of the
    counts (each permutation contributes the product of its entries' term
    counts), computed row by row over the open columns; when that needs
    too many partial states, the smaller of the products of the row sums
    and of the column sums.

    EXAMPLES::

        sage: from sage_dynsym.algebra.size import determinant_terms
        sage: determinant_terms([[2, 1], [1, 3]])
        7
        sage: determinant_terms([[1, 1, 0], [1, 1, 1], [0, 1, 1]])   # tridiagonal
        3
        sage: determinant_terms([[1] * 8 for _ in range(8)]) == factorial(8)
        True
        sage: determinant_terms([[1] * 40 for _ in range(40)])   # the product bound, capped
        1000000000000000000000000000000
        sage: determinant_terms([[1, 0], [1, 0]])
        0
    """
    n = len(counts)
    last = {}
    for j in range(n):
        rows = [i for i in range(n) if counts[i][j]]
        if not rows:
            return 0
        last[j] = rows[-1]
    states = {frozenset(): 1}
    for i in range(n):
        closing = {j for j in range(n) if last[j] == i}
        new = {}
        for used, value in states.items():
            for j in range(n):
                c = counts[i][j]
                if c and j not in used:
                    key = used | {j}
                    if closing <= key:
                        key -= closing
                        new[key] = new.get(key, 0) + value * c
        states = new
        if len(states) > PERMANENT_STATES:
            rows = 1
            for row in counts:
                rows = min(rows * sum(row), TERMS_CAP)
            cols = 1
            for j in range(n):
                cols = min(cols * sum(counts[i][j] for i in range(n)), TERMS_CAP)
            return min(rows, cols)
    return min(sum(states.values()), TERMS_CAP)


def matrix_terms(M):
    r"""
    The term counts (:func:`polynomial_terms`) of the entries of the matrix
    ``M``, row by row (what :func:`determinant_terms` bounds).

    EXAMPLES::

        sage: from sage_dynsym.algebra.size import matrix_terms
        sage: x, y = var('x y')
        sage: matrix_terms(matrix([[x + y, 0], [1, x*y]]))
        [[2, 0], [1, 1]]
    """
    return [[polynomial_terms(e) for e in row] for row in M.rows()]

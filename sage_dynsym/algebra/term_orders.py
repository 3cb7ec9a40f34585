r"""
Term orders for the stationary systems: a block order by kind of unknown,
its restriction to fewer variables, and the order chosen by trying

A Gröbner basis over a field of many parameters can take a fraction of a
second in one term order and minutes in another. The Lagrange system of a
Lie--Poisson Hamiltonian with symbolic coefficients (Kirchhoff's equations
of a body in a fluid with a generic Hamiltonian, 12 parameters) is the
example met: in ``degrevlex`` (in any order of the variables tried) its
basis takes 7 to over 15 seconds; in the block order with the unknowns
before the Lagrange multipliers, each block in the order the unknowns were
given, it takes a fraction of a second, and in the same block order with
the two multipliers swapped it takes 21 seconds. No rule predicts which;
Singular's own advice is to try. :func:`fastest_order` tries the
candidates in forked processes, with budgets that grow, and returns the
first that finishes.

The variables of the ring keep their places: a block order over variables
that are not consecutive is written as a matrix order
(:func:`block_order`), so every polynomial, index and translation of the
ring stays valid. :func:`restricted_order` gives the order of a subring
(the variables left after some were eliminated).

EXAMPLES:

The unknowns `x, y` before the multiplier `l`, with `l` the first
variable of the ring::

    sage: from sage_dynsym.algebra.term_orders import block_order
    sage: R = PolynomialRing(QQ, 'l, x, y', order=block_order([[1, 2], [0]], 3))
    sage: l, x, y = R.gens()
    sage: l^5 < x, x^2 > x*y > y^2
    (True, True)

REFERENCES:

- G.-M. Greuel, G. Pfister, *A Singular Introduction to
  Commutative Algebra*, 2nd ed., Springer 2008, §1.2 (matrix orders,
  block orders) and §1.8.2 (elimination orders).
"""
from sage.matrix.constructor import matrix
from sage.misc.verbose import verbose
from sage.rings.integer_ring import ZZ
from sage.rings.polynomial.term_order import TermOrder

from .forked import forked

__all__ = ['ORDER_TRIAL_SECONDS', 'ORDER_ROUNDS', 'block_order', 'restricted_order',
           'reverse_block', 'fastest_order']

#: Seconds of processor time each candidate order gets in the first round
#: of :func:`fastest_order`; every round gives each four times more.
#: Processor time, not wall-clock time: the choice must not depend on the
#: machine's load. Timed by the clock, a first candidate that needs a
#: fraction of a second (Brun's problem on M.gamma = 0 in ``degrevlex``)
#: lost its 2 s once under a loaded test run, and the order chosen instead
#: made a later step run for over half an hour.
ORDER_TRIAL_SECONDS = 3

#: Rounds of :func:`fastest_order` before it gives up on the candidates.
ORDER_ROUNDS = 3


def block_order(blocks, n):
    r"""
    The block order on a ring of ``n`` variables whose blocks are the lists
    of variable positions ``blocks`` (the first block the largest), each
    block ``degrevlex`` in the order its positions are listed.

    The positions need not be consecutive: the order is the matrix order
    whose rows are, for each block, its total degree and then minus the
    exponents of its variables from the last to the second. Every variable
    must be in one block.

    EXAMPLES::

        sage: from sage_dynsym.algebra.term_orders import block_order
        sage: block_order([[2, 0], [1]], 3).matrix()
        [ 1  0  1]
        [-1  0  0]
        [ 0  1  0]
    """
    rows = []
    for block in blocks:
        rows.append([1 if k in block else 0 for k in range(n)])
        for k in reversed(block[1:]):
            rows.append([-1 if j == k else 0 for j in range(n)])
    return TermOrder(matrix(ZZ, rows))


def restricted_order(order, positions):
    r"""
    The term order ``order`` of a polynomial ring restricted to the
    variables at ``positions`` (increasing): it compares two monomials in
    these variables as ``order`` does.

    A matrix order keeps the columns of the variables and, of its rows,
    those independent of the rows before them: a row that depends on
    earlier ones takes equal values on two monomials wherever they do, so
    it never decides a comparison. A block order given by names (its
    blocks do not fit fewer variables) becomes ``degrevlex``; the other
    orders do not depend on the number of variables.

    EXAMPLES: the degree in `x, y` first, then `z`; restricted to `x, z`
    it is the degree in `x`, then `z`::

        sage: from sage_dynsym.algebra.term_orders import restricted_order
        sage: o = TermOrder(matrix([[1, 1, 0], [0, -1, 0], [0, 0, 1]]))
        sage: restricted_order(o, [0, 2]).matrix()
        [1 0]
        [0 1]
        sage: restricted_order(TermOrder('lex'), [0, 2])
        Lexicographic term order
    """
    if order.name() == 'matrix':
        rows = []
        for row in order.matrix().matrix_from_columns(positions).rows():
            if matrix(rows + [row]).rank() > len(rows):
                rows.append(row)
        return TermOrder(matrix(rows))
    if order.is_block_order():
        return TermOrder('degrevlex', len(positions))
    return order


def reverse_block(order, n):
    r"""
    The variables of the first block of ``order`` (on ``n`` variables) in
    which it is a degree reverse lexicographic order, from the last (the
    smallest) to the first, or ``None``: all of them for ``degrevlex``, the
    first block of a block order if it is ``degrevlex``; for a matrix
    order, the variables of its first row if that row is 1 on
    them and 0 elsewhere and the next rows are minus the unit vectors of
    all of them but one (as :func:`block_order` writes it).

    On a polynomial homogeneous in these variables (the others of degree
    0) such an order takes the leading monomial among those with the
    least power of the last variable, which is what Bayer's criterion for
    saturation needs (:func:`~sage_dynsym.algebra.decomposition.homogeneous_parts`).

    EXAMPLES::

        sage: from sage_dynsym.algebra.term_orders import block_order, reverse_block
        sage: reverse_block(block_order([[2, 0], [1]], 3), 3)
        [0, 2]
        sage: reverse_block(TermOrder('degrevlex'), 3)
        [2, 1, 0]
        sage: reverse_block(TermOrder('degrevlex', 2) + TermOrder('lex', 1), 3)
        [1, 0]
        sage: reverse_block(TermOrder('lex'), 3) is None
        True
    """
    if order.name() == 'degrevlex':
        return list(reversed(range(n)))
    if order.is_block_order():
        first = order.blocks()[0]
        return list(reversed(range(len(first)))) if first.name() == 'degrevlex' else None
    if order.name() != 'matrix':
        return None
    rows = order.matrix().rows()
    block = [k for k in range(n) if rows[0][k]]
    if any(rows[0][k] != 1 for k in block):
        return None
    last = []
    for row in rows[1:len(block)]:
        units = [k for k in block if row[k] == -1]
        if len(units) != 1 or any(row[k] for k in range(n) if k != units[0]):
            return None
        last.append(units[0])
    return last + [k for k in block if k not in last]


def fastest_order(ideal, candidates):
    r"""
    The first of the term orders ``candidates`` in which a Gröbner basis of
    ``ideal`` is found, trying each in turn in a forked process within
    :data:`ORDER_TRIAL_SECONDS` of processor time, then four and sixteen
    times as long (:data:`ORDER_ROUNDS` rounds); ``None`` if none finished
    (or the ring's own order, given as ``None``, finished first, or a
    trial failed other than by its budget).

    The budgets are processor time of the child, so the order chosen is
    the same on a busy machine as on an idle one (a busy machine only
    makes the trials take longer).

    A candidate ``None`` stands for the ring's own order. The caller
    computes the basis again in the order returned: it cannot be brought
    back from the child cheaper than that, and the time wasted is at most
    that of the winner plus the budgets of the candidates that lost. A
    process killed at its budget leaves nothing behind (an alarm stopping
    Singular here would leave its state broken).

    INPUT:

    - ``ideal`` -- an ideal of a multivariate polynomial ring
    - ``candidates`` -- term orders for the ring's variables, or ``None``

    OUTPUT: a term order of ``candidates``, or ``None``

    EXAMPLES::

        sage: from sage_dynsym.algebra.term_orders import fastest_order
        sage: R.<x, y> = QQ[]
        sage: fastest_order(R.ideal([x^2 - y, y^2 - x]), [TermOrder('lex')])
        Lexicographic term order
    """
    P = ideal.ring()
    budget = ORDER_TRIAL_SECONDS
    for _ in range(ORDER_ROUNDS):
        for order in candidates:
            R = P if order is None else P.change_ring(order=order)
            J = R.ideal([R(g) for g in ideal.gens()])
            _, (how, why) = forked(lambda send: len(J.groebner_basis()), cpu_seconds=budget)
            if how == 'value':
                verbose(f"Groebner basis within {budget} s of processor time in the term "
                        f"order {order}",
                        level=1, caller_name="fastest_order")
                return order
            if how != 'cpu':
                # a child that failed says nothing about the orders: the
                # ring's own order, where the error (if any) is raised
                verbose(f"the trial of the term order {order} failed ({how}: {why}): the "
                        "ring's own order", level=1, caller_name="fastest_order")
                return None
        budget *= 4
    return None

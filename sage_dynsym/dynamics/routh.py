r"""
Cyclic coordinates and the Routh reduction

:func:`cyclic_coordinates` gives the cyclic coordinates of a
:class:`~sage_dynsym.dynamics.lagrangian.Lagrangian`, those whose momentum
is conserved (:func:`why_not_cyclic` says why a coordinate is not).
:func:`routh_reduction`
eliminates the velocities of cyclic coordinates through their constant
momenta, the computation behind
:class:`~sage_dynsym.dynamics.lagrangian.RouthFunction` (see the module
documentation of :mod:`~sage_dynsym.dynamics.lagrangian` for the sign
convention).

EXAMPLES::

    sage: from sage_dynsym import Lagrangian
    sage: r, phi, dr, dphi, m, mu = var('r phi dr dphi m mu')
    sage: L = Lagrangian(m*(dr^2 + r^2*dphi^2)/2 + m*mu/r, [r, phi])
    sage: L.cyclic_coordinates()
    [phi]
    sage: L.routh([phi]).expr()
    1/2*dr^2*m + m*mu/r - 1/2*p_phi^2/(m*r^2)
"""
from sage.matrix.constructor import matrix
from sage.modules.free_module_element import vector
from sage.symbolic.ring import SR

from ..errors import ModelError
from ..algebra.trigonometric import trig_rational_simplify, NotPolynomial
from .natural_form import natural_form, linear_collected, is_singular, Elimination

__all__ = ['cyclic_coordinates', 'why_not_cyclic', 'check_cyclic', 'routh_reduction']


def cyclic_coordinates(lagrangian):
    r"""
    The coordinates `q_l` of ``lagrangian`` whose momentum is conserved,
    exactly those the Routh reduction accepts (see :func:`why_not_cyclic`).

    EXAMPLES::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.dynamics.routh import cyclic_coordinates
        sage: r, phi, dr, dphi = var('r phi dr dphi')
        sage: cyclic_coordinates(Lagrangian((dr^2 + r^2*dphi^2)/2 + 1/r, [r, phi]))
        [phi]
    """
    return [q for q in lagrangian.coordinates() if why_not_cyclic(lagrangian, q) is None]


def why_not_cyclic(lagrangian, q):
    r"""
    Why the coordinate ``q`` of ``lagrangian`` is not cyclic, or ``None`` if
    it is: `q_l` appears neither in `L` nor in the dissipation function,
    the generalized forces or the constraints, the dissipation function does
    not depend on `\dot q_l`, no generalized force acts on `q_l`, and no
    velocity constraint involves `q_l` or `\dot q_l`.

    EXAMPLES::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.dynamics.routh import why_not_cyclic
        sage: x, y, dx, dy, c = var('x y dx dy c')
        sage: L = Lagrangian((dx^2 + dy^2)/2 + cos(y), [x, y], dissipation=c*dx^2/2)
        sage: why_not_cyclic(L, x), why_not_cyclic(L, y)
        ('the dissipation function depends on its velocity, so its momentum is not conserved',
         'the Lagrangian depends on it')
    """
    i = lagrangian.coordinates().index(q)
    dq = lagrangian.velocities()[i]
    dissipation, forces = lagrangian.dissipation(), lagrangian.generalized_forces()
    if lagrangian.expr().has(q):
        return "the Lagrangian depends on it"
    if dissipation.diff(dq) != 0:
        return ("the dissipation function depends on its velocity, so its momentum "
                "is not conserved")
    if forces[i] != 0:
        return "a generalized force acts on it"
    for what, parts in (("the dissipation function", [dissipation]),
                        ("a generalized force", forces),
                        ("a constraint", lagrangian.constraints())):
        if any(p.has(q) for p in parts):
            return f"{what} depends on it"
    if any(g.has(q) or g.has(dq) for g in lagrangian.nonholonomic_constraints()):
        return "a velocity constraint involves it or its velocity"
    return None


def check_cyclic(lagrangian, cyclic):
    r"""
    Check that the coordinates ``cyclic`` of ``lagrangian`` are cyclic
    (see :func:`why_not_cyclic`) and that the Lagrangian is natural and has
    no velocity constraints, as the Routh reduction needs.

    EXAMPLES::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.dynamics.routh import check_cyclic
        sage: x, y, dx, dy = var('x y dx dy')
        sage: check_cyclic(Lagrangian((dx^2 + dy^2)/2 - x^2, [x, y]), [y])
        sage: check_cyclic(Lagrangian((dx^2 + dy^2)/2 - x^2, [x, y]), [x])
        Traceback (most recent call last):
        ...
        ModelError: cyclic: x is not cyclic: the Lagrangian depends on it
    """
    if lagrangian.nonholonomic_constraints():
        raise ModelError("Routh's reduction does not apply with velocity constraints; use "
                         "reduced_equations() (Kane's equations in independent speeds)",
                         entry="nonholonomic")
    coordinates = lagrangian.coordinates()
    velocities = dict(zip(coordinates, lagrangian.velocities()))
    for c in cyclic:
        c = SR(c)
        if c not in velocities:
            raise ModelError(f"{c} is not a coordinate of the Lagrangian; "
                             f"coordinates are {coordinates}", entry="cyclic")
        reason = why_not_cyclic(lagrangian, c)
        if reason is not None:
            raise ModelError(f"{c} is not cyclic: {reason}", entry="cyclic")
        if not lagrangian.is_natural():
            raise ModelError("Routh reduction needs a Lagrangian quadratic in the "
                             "velocities", entry="lagrangian")


def routh_reduction(lagrangian, cyclic, momenta):
    r"""
    The Routh function of the natural ``lagrangian`` for the coordinates
    ``cyclic`` (checked by :func:`check_cyclic`), their constant momenta
    written ``momenta``: `R = L - c\cdot\dot q_{cyc}` with the cyclic
    velocities eliminated.

    OUTPUT: a tuple ``(coordinates, velocities, decomposition,
    cyclic_velocities, dissipation, forces)``: the positional coordinates
    and their velocities, the decomposition (4) ``(A, A1, A0)`` of `R`, the
    cyclic velocities `-\partial R/\partial c_l`, and the dissipation
    function and generalized forces of the positional coordinates with the
    cyclic velocities substituted.

    EXAMPLES::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.dynamics.routh import routh_reduction
        sage: r, phi, dr, dphi, p = var('r phi dr dphi p')
        sage: L = Lagrangian((dr^2 + r^2*dphi^2)/2, [r, phi])
        sage: q, dq, (A, A1, A0), solved, R, Q = routh_reduction(L, [phi], [p])
        sage: q, dq, A, A0, solved
        ([r], [dr], [1], -1/2*p^2/r^2, [p/r^2])

    TESTS::

        sage: routh_reduction(Lagrangian((dr + dphi)^2, [r, phi]), [r, phi], [p, var('s')])
        Traceback (most recent call last):
        ...
        ModelError: cyclic: the momentum equations cannot be solved for the cyclic velocities (the block of the mass matrix is singular)
    """
    q_all, dq_all = lagrangian.coordinates(), lagrangian.velocities()
    index = [q_all.index(c) for c in cyclic]
    positional = [i for i in range(len(q_all)) if i not in index]
    A, A1, A0 = lagrangian.decomposition()
    # p_cyc = A_cc dq_c + A_cp dq_p + A1_c = c; with u = c - A1_c - A_cp dq_p,
    # dq_c = A_cc^{-1} u and R = L - c.dq_c = 1/2 dq_p A_pp dq_p + A1_p.dq_p
    # + A0 - 1/2 u A_cc^{-1} u, collected by the positional velocities:
    # each coefficient simplified, the momentum part as a sum of squares
    A_cc = A.matrix_from_rows_and_columns(index, index)
    if is_singular(A_cc):
        raise ModelError("the momentum equations cannot be solved for the cyclic "
                         "velocities (the block of the mass matrix is singular)",
                         entry="cyclic")
    try:
        elimination = Elimination(A_cc)
    except NotPolynomial:
        # inexact numbers, or entries too large to simplify: GiNaC's
        # normalization (it may miss zero pivots modulo cos^2+sin^2 = 1)
        elimination = Elimination(A_cc, simplify=lambda e: SR(e).normalize())
    dq_p = [dq_all[j] for j in positional]
    v = [c - A1[i] for c, i in zip(momenta, index)]
    X = {j: [A[i, j] for i in index] for j in positional}
    n = len(positional)
    M = matrix(SR, n, n)
    for a, j in enumerate(positional):
        for b in range(a, n):
            k = positional[b]
            M[a, b] = M[b, a] = trig_rational_simplify(
                A[j, k] - SR(0).add(*elimination.products(X[j], X[k])))
    M.set_immutable()
    B = vector(SR, [linear_collected(A1[j] + SR(0).add(*elimination.products(X[j], v)),
                                      momenta) for j in positional])
    R0 = trig_rational_simplify(A0) - SR(0).add(*elimination.squares(v, momenta)) / 2
    # dq_c = A_cc^{-1} u = -dR/dc, in the (compact) form of R
    routh = natural_form(M, B, R0, dq_p)
    solved = [-routh.diff(c) for c in momenta]
    substitution = dict(zip([dq_all[i] for i in index], solved))
    dissipation = lagrangian.dissipation().subs(substitution)
    forces = [lagrangian.generalized_forces()[i].subs(substitution) for i in positional]
    return [q_all[i] for i in positional], dq_p, (M, B, R0), solved, dissipation, forces

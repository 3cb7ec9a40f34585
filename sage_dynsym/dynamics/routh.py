r"""
Cyclic coordinates and the Routh reduction

:class:`CyclicCoordinates` is a base class of
:class:`~sage_dynsym.dynamics.lagrangian.Lagrangian`: its cyclic
coordinates, those whose momentum is conserved. :func:`routh_reduction`
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

__all__ = ['CyclicCoordinates', 'check_cyclic', 'routh_reduction']


class CyclicCoordinates:
    r"""
    The cyclic coordinates of a
    :class:`~sage_dynsym.dynamics.lagrangian.Lagrangian` (a base class of
    it, see the module documentation).

    EXAMPLES: see :class:`~sage_dynsym.dynamics.lagrangian.Lagrangian`.
    """

    def cyclic_coordinates(self):
        r"""
        The coordinates `q_l` whose momentum is conserved, exactly those
        :meth:`routh` accepts: `q_l` appears neither in `L` nor in the
        dissipation function, the generalized forces or the constraints,
        the dissipation function does not depend on `\dot q_l`, and no
        generalized force acts on `q_l`.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: r, phi, dr, dphi = var('r phi dr dphi')
            sage: Lagrangian((dr^2 + r^2*dphi^2)/2 + 1/r, [r, phi]).cyclic_coordinates()
            [phi]

        A damper on a cart makes its position non-cyclic::

            sage: x, dx, c = var('x dx c')
            sage: L = Lagrangian((dx^2 + dphi^2)/2 + cos(phi), [x, phi], dissipation=c*dx^2/2)
            sage: L.cyclic_coordinates()
            []
        """
        return [q for q in self._coordinates if self._not_cyclic(q) is None]

    def _not_cyclic(self, q):
        r"""
        Why the coordinate ``q`` is not cyclic, or ``None`` if it is.
        """
        i = self._coordinates.index(q)
        if self._expr.has(q):
            return "the Lagrangian depends on it"
        if self._dissipation.diff(self._velocities[i]) != 0:
            return ("the dissipation function depends on its velocity, so its momentum "
                    "is not conserved")
        if self._forces[i] != 0:
            return "a generalized force acts on it"
        for what, parts in (("the dissipation function", [self._dissipation]),
                            ("a generalized force", self._forces),
                            ("a constraint", self._constraints)):
            if any(p.has(q) for p in parts):
                return f"{what} depends on it"
        return None


def check_cyclic(lagrangian, cyclic):
    r"""
    Check that the coordinates ``cyclic`` of ``lagrangian`` are cyclic
    (see :meth:`~CyclicCoordinates.cyclic_coordinates`) and that the
    Lagrangian is natural, as the Routh reduction needs.

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
    coordinates = lagrangian.coordinates()
    velocities = dict(zip(coordinates, lagrangian.velocities()))
    for c in cyclic:
        c = SR(c)
        if c not in velocities:
            raise ModelError(f"{c} is not a coordinate of the Lagrangian; "
                             f"coordinates are {coordinates}", entry="cyclic")
        reason = lagrangian._not_cyclic(c)
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

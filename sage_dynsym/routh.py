r"""
Routh functions: reduction by cyclic coordinates

For cyclic coordinates `q_1, \dots, q_m` (absent from `L`, from the
dissipation function and from the generalized forces) the momenta
`p_l = \partial L/\partial \dot q_l` are constants `c_l`. The Routh function

.. MATH::

    R(q_{m+1..n}, \dot q_{m+1..n}, c) = L - \sum_{l \le m} c_l \dot q_l,

with the cyclic velocities eliminated through `p_l = c_l`, is a Lagrangian
of the positional coordinates only (sign convention of
:doc:`the method </method>`: `R = L - c \cdot \dot q_{cyc}`). Its Lagrange
equations are the Routh equations; the cyclic velocities are recovered as
`\dot q_l = -\partial R/\partial c_l`.

EXAMPLES:

The Kepler problem in polar coordinates::

    sage: from sage_dynsym import Lagrangian
    sage: r, phi, dr, dphi, m, mu = var('r phi dr dphi m mu')
    sage: L = Lagrangian(m*(dr^2 + r^2*dphi^2)/2 + m*mu/r, [r, phi])
    sage: R = L.routh([phi]); R
    Routh function in coordinates (r) with cyclic momenta (p_phi) : 1/2*dr^2*m + m*mu/r - 1/2*p_phi^2/(m*r^2)
    sage: R.equations()
    [ddr*m + m*mu/r^2 - p_phi^2/(m*r^3)]
    sage: R.cyclic_velocities()
    [p_phi/(m*r^2)]
"""
from sage.matrix.constructor import matrix
from sage.misc.cachefunc import cached_method
from sage.modules.free_module_element import vector
from sage.symbolic.ring import SR

from .errors import ModelError
from .expressions import momentum
from .lagrangian import (Lagrangian, _Elimination, _is_singular, _linear_collected,
                         _natural_form)
from .trig import trig_rational_simplify, NotPolynomial


class RouthFunction(Lagrangian):
    r"""
    The Routh function of a Lagrangian for given cyclic coordinates.

    Being itself a :class:`~sage_dynsym.lagrangian.Lagrangian` of the
    positional coordinates (with the cyclic momenta as constant parameters),
    it supports everything a Lagrangian does: equations, Hamiltonian,
    linearization, further reduction.

    INPUT:

    - ``lagrangian`` -- a natural :class:`~sage_dynsym.lagrangian.Lagrangian`
    - ``cyclic`` -- list of coordinates of ``lagrangian`` that are cyclic
    - ``momenta`` -- (default: ``p_<q>``) symbols for the constant cyclic
      momenta

    EXAMPLES::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.routh import RouthFunction
        sage: x, y, dx, dy = var('x y dx dy')
        sage: R = RouthFunction(Lagrangian((dx^2 + dy^2)/2 - x^2/2, [x, y]), [y])
        sage: R.expr(), R.momenta(), R.coordinates(), R.cyclic_coordinates()
        (1/2*dx^2 - 1/2*p_y^2 - 1/2*x^2, [p_y], [x], [y])

    TESTS::

        sage: RouthFunction(Lagrangian((dx^2 + dy^2)/2 - x*y, [x, y]), [y])
        Traceback (most recent call last):
        ...
        ModelError: cyclic: y is not cyclic: the Lagrangian depends on it
        sage: RouthFunction(Lagrangian((dx^2 + dy^2)/2, [x, y], dissipation=dy^2), [y])
        Traceback (most recent call last):
        ...
        ModelError: cyclic: y is not cyclic: the dissipation function depends on its velocity, so its momentum is not conserved
        sage: RouthFunction(Lagrangian((dx^2 + dy^2)/2, [x, y]), [var('z')])
        Traceback (most recent call last):
        ...
        ModelError: cyclic: z is not a coordinate of the Lagrangian; coordinates are [x, y]
        sage: RouthFunction(Lagrangian((dx + dy)^2, [x, y]), [x, y])
        Traceback (most recent call last):
        ...
        ModelError: cyclic: the momentum equations cannot be solved for the cyclic velocities (the block of the mass matrix is singular)
    """

    def __init__(self, lagrangian, cyclic, momenta=None):
        if not isinstance(lagrangian, Lagrangian):
            raise ModelError("expected a Lagrangian object", entry="lagrangian")
        self._check_cyclic(lagrangian, cyclic)
        q_all, dq_all = lagrangian.coordinates(), lagrangian.velocities()
        self._cyclic = [SR(c) for c in cyclic]
        index = [q_all.index(c) for c in self._cyclic]
        positional = [i for i in range(len(q_all)) if i not in index]
        if momenta is None:
            momenta = [momentum(c) for c in self._cyclic]
        self._momenta = [SR(c) for c in momenta]
        self._lagrangian = lagrangian

        A, A1, A0 = lagrangian.decomposition()
        # p_cyc = A_cc dq_c + A_cp dq_p + A1_c = c; with u = c - A1_c - A_cp dq_p,
        # dq_c = A_cc^{-1} u and R = L - c.dq_c = 1/2 dq_p A_pp dq_p + A1_p.dq_p
        # + A0 - 1/2 u A_cc^{-1} u, collected by the positional velocities:
        # each coefficient simplified, the momentum part as a sum of squares
        A_cc = A.matrix_from_rows_and_columns(index, index)
        if _is_singular(A_cc):
            raise ModelError("the momentum equations cannot be solved for the cyclic "
                             "velocities (the block of the mass matrix is singular)",
                             entry="cyclic")
        try:
            elimination = _Elimination(A_cc)
        except NotPolynomial:
            # inexact numbers, or entries too large to simplify: GiNaC's
            # normalization (it may miss zero pivots modulo cos^2+sin^2 = 1)
            elimination = _Elimination(A_cc, simplify=lambda e: SR(e).normalize())
        dq_p = [dq_all[j] for j in positional]
        v = [c - A1[i] for c, i in zip(self._momenta, index)]
        X = {j: [A[i, j] for i in index] for j in positional}
        n = len(positional)
        M = matrix(SR, n, n)
        for a, j in enumerate(positional):
            for b in range(a, n):
                k = positional[b]
                M[a, b] = M[b, a] = trig_rational_simplify(
                    A[j, k] - SR(0).add(*elimination.products(X[j], X[k])))
        M.set_immutable()
        B = vector(SR, [_linear_collected(A1[j] + SR(0).add(*elimination.products(X[j], v)),
                                          self._momenta) for j in positional])
        R0 = trig_rational_simplify(A0) - SR(0).add(
            *elimination.squares(v, self._momenta)) / 2
        # dq_c = A_cc^{-1} u = -dR/dc, in the (compact) form of R
        routh = _natural_form(M, B, R0, dq_p)
        self._solved_velocities = [-routh.diff(c) for c in self._momenta]
        cyclic_velocities = [dq_all[i] for i in index]
        substitution = dict(zip(cyclic_velocities, self._solved_velocities))
        dissipation = lagrangian.dissipation().subs(substitution)
        forces = [lagrangian.generalized_forces()[i].subs(substitution) for i in positional]
        Lagrangian.__init__(self, None, [q_all[i] for i in positional], dq_p,
                            dissipation=dissipation, forces=forces, name=lagrangian.name(),
                            decomposition=(M, B, R0))

    @staticmethod
    def _check_cyclic(lagrangian, cyclic):
        coordinates = lagrangian.coordinates()
        velocities = dict(zip(coordinates, lagrangian.velocities()))
        for c in cyclic:
            c = SR(c)
            if c not in velocities:
                raise ModelError(f"{c} is not a coordinate of the Lagrangian; "
                                 f"coordinates are {coordinates}", entry="cyclic")
            if lagrangian.expr().has(c):
                raise ModelError(f"{c} is not cyclic: the Lagrangian depends on it",
                                 entry="cyclic")
            if lagrangian.dissipation().diff(velocities[c]) != 0:
                raise ModelError(f"{c} is not cyclic: the dissipation function depends "
                                 "on its velocity, so its momentum is not conserved",
                                 entry="cyclic")
            if lagrangian.generalized_forces()[coordinates.index(c)] != 0:
                raise ModelError(f"{c} is not cyclic: a generalized force acts on it",
                                 entry="cyclic")
            if not lagrangian.is_natural():
                raise ModelError("Routh reduction needs a Lagrangian quadratic in the "
                                 "velocities", entry="lagrangian")

    def _repr_(self):
        coords = ", ".join(map(str, self.coordinates()))
        momenta = ", ".join(map(str, self._momenta))
        return (f"Routh function in coordinates ({coords}) with cyclic momenta "
                f"({momenta}) : {self.expr()}")

    def _latex_(self):
        from sage.misc.latex import latex
        return "R = " + latex(self.expr())

    def _derived(self, expr, **changes):
        # substitution etc. give a plain Lagrangian of the positional coordinates
        return Lagrangian(expr, changes.pop('coordinates', self.coordinates()),
                          **{'velocities': self.velocities(),
                             'dissipation': self.dissipation(),
                             'forces': self.generalized_forces(),
                             'name': self.name(), **changes})

    def momenta(self):
        r"""
        The symbols of the constant cyclic momenta, in the order of
        :meth:`cyclic_coordinates`.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, y, dx, dy = var('x y dx dy')
            sage: Lagrangian((dx^2 + dy^2)/2, [x, y]).routh([y]).momenta()
            [p_y]
        """
        return list(self._momenta)

    def cyclic_coordinates(self):
        r"""
        The cyclic coordinates that were eliminated.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, y, dx, dy = var('x y dx dy')
            sage: Lagrangian((dx^2 + dy^2)/2, [x, y]).routh([y]).cyclic_coordinates()
            [y]
        """
        return list(self._cyclic)

    def lagrangian(self):
        r"""
        The Lagrangian this Routh function was obtained from.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, y, dx, dy = var('x y dx dy')
            sage: L = Lagrangian((dx^2 + dy^2)/2, [x, y])
            sage: L.routh([y]).lagrangian() is L
            True
        """
        return self._lagrangian

    def cyclic_velocities(self):
        r"""
        The cyclic velocities as functions of the positional variables and
        the cyclic momenta (equal to `-\partial R/\partial c_l`).

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: r, phi, dr, dphi = var('r phi dr dphi')
            sage: R = Lagrangian((dr^2 + r^2*dphi^2)/2, [r, phi]).routh([phi])
            sage: R.cyclic_velocities()
            [p_phi/r^2]
            sage: [-R.expr().diff(c) for c in R.momenta()]
            [p_phi/r^2]
        """
        return list(self._solved_velocities)

    @cached_method
    def equations(self):
        r"""
        The Routh equations: the Lagrange equations of `R` in the positional
        coordinates (a list of expressions `E_i`, meaning `E_i = 0`).

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: r, phi, dr, dphi = var('r phi dr dphi')
            sage: R = Lagrangian((dr^2 + r^2*dphi^2)/2, [r, phi]).routh([phi])
            sage: R.equations()
            [ddr - p_phi^2/r^3]
        """
        return self.lagrange_equations()


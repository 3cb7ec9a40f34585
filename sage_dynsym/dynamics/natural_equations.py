r"""
The Lagrange equations (5) of a natural Lagrangian, over a choice of calculus

The equations (5) of :doc:`the method </method>`: for
`L = \tfrac12 \sum A_{ij}\dot q_i\dot q_j + \sum A_i\dot q_i + A_0`
the equations are assembled term by term,

.. MATH::

    E_i = \sum_r A_{ir}\ddot q_r
        + \sum_{r \le j} \Gamma_{i,rj}\, \dot q_r \dot q_j
        + \sum_j \Big(\frac{\partial A_i}{\partial q_j}
                      - \frac{\partial A_j}{\partial q_i}\Big)\dot q_j
        + \sum_r \frac{\partial A_{ir}}{\partial t}\dot q_r
        + \frac{\partial A_i}{\partial t} - \frac{\partial A_0}{\partial q_i},

with the Christoffel coefficients
`\Gamma_{i,rr} = \partial_r A_{ir} - \tfrac12 \partial_i A_{rr}` and
`\Gamma_{i,rj} = \partial_j A_{ir} + \partial_r A_{ij} - \partial_i A_{rj}`
(`r < j`). Each coefficient is computed and simplified *before* it is
multiplied by its velocity monomial, so the result keeps the structure of
(5): mass-matrix entries times accelerations, compact coefficients times
products of velocities. Nothing is expanded.

The coefficients live in the ring of a *calculus*: :class:`SymbolicCalculus`
(any expressions), or :class:`~sage_dynsym.algebra.trigonometric.RingCalculus` (polynomials
in the sines and cosines of the angles, where the combination of the three
derivatives in `\Gamma` cancels exactly).

EXAMPLES::

    sage: from sage_dynsym.dynamics.natural_equations import natural_equations, SymbolicCalculus
    sage: r, phi, m, k = var('r phi m k')
    sage: A = [[m, 0], [0, m*r^2]]
    sage: natural_equations(A, [0, 0], -k*r^2/2, [r, phi], var('dr dphi'), var('ddr ddphi'),
    ....:                   SymbolicCalculus([r, phi]))
    [-dphi^2*m*r + ddr*m + k*r, 2*dphi*dr*m*r + ddphi*m*r^2]
"""
from sage.misc.verbose import verbose
from sage.symbolic.ring import SR

from ..symbols import t

__all__ = ['SymbolicCalculus', 'natural_equations']


class SymbolicCalculus:
    r"""
    Derivatives of symbolic expressions with respect to the coordinates and
    time (structural zero tests only: a full zero test would simplify large
    expressions).

    EXAMPLES::

        sage: from sage_dynsym.dynamics.natural_equations import SymbolicCalculus
        sage: x, y, t = var('x y t')
        sage: C = SymbolicCalculus([x, y])
        sage: C.dependencies(x*t + 1), C.derivative(x*t, 0), C.derivative(x*t, None)
        ({0}, t, x)
    """

    def __init__(self, coordinates):
        self._coordinates = [SR(q) for q in coordinates]
        self._position = {q: k for k, q in enumerate(self._coordinates)}
        self.zero = SR(0)

    def convert(self, expr):
        r"""``expr`` as an element of the calculus: a symbolic expression.

        EXAMPLES::

            sage: from sage_dynsym.dynamics.natural_equations import SymbolicCalculus
            sage: x, y, t, a = var('x y t a'); C = SymbolicCalculus([x, y])
            sage: C.convert(1).parent()
            Symbolic Ring
        """
        return SR(expr)

    def dependencies(self, element):
        r"""The set of the indices of the coordinates ``element`` depends on.

        EXAMPLES::

            sage: from sage_dynsym.dynamics.natural_equations import SymbolicCalculus
            sage: x, y, t, a = var('x y t a'); C = SymbolicCalculus([x, y])
            sage: C.dependencies(x*y*t + a), C.dependencies(a*t)
            ({0, 1}, set())
        """
        return {self._position[v] for v in SR(element).variables() if v in self._position}

    def depends_on_time(self, element):
        r"""Whether ``element`` depends explicitly on the time ``t``.

        EXAMPLES::

            sage: from sage_dynsym.dynamics.natural_equations import SymbolicCalculus
            sage: x, y, t, a = var('x y t a'); C = SymbolicCalculus([x, y])
            sage: C.depends_on_time(x*t), C.depends_on_time(x*a)
            (True, False)
        """
        return SR(element).has(t)

    def derivative(self, element, k):
        r"""
        `\partial/\partial q_k`, or `\partial/\partial t` for ``k = None``.

        EXAMPLES::

            sage: from sage_dynsym.dynamics.natural_equations import SymbolicCalculus
            sage: x, y, t, a = var('x y t a'); C = SymbolicCalculus([x, y])
            sage: C.derivative(x^2*y*t, 0), C.derivative(x^2*y*t, None)
            (2*t*x*y, x^2*y)
        """
        return SR(element).diff(t if k is None else self._coordinates[k])

    def is_zero(self, element):
        r"""Whether ``element`` is zero structurally (no simplification).

        EXAMPLES::

            sage: from sage_dynsym.dynamics.natural_equations import SymbolicCalculus
            sage: x, y, t, a = var('x y t a'); C = SymbolicCalculus([x, y])
            sage: C.is_zero(x - x), C.is_zero(sin(x)^2 + cos(x)^2 - 1)
            (True, False)
        """
        return SR(element).is_trivial_zero()

    def symbolic(self, element):
        r"""``element`` as a symbolic expression.

        EXAMPLES::

            sage: from sage_dynsym.dynamics.natural_equations import SymbolicCalculus
            sage: x, y, t, a = var('x y t a'); C = SymbolicCalculus([x, y])
            sage: C.symbolic(2).parent()
            Symbolic Ring
        """
        return SR(element)


def natural_equations(A, A1, A0, coordinates, velocities, accelerations, calculus,
                      mass_matrix=None):
    r"""
    The equations (5) (without dissipation and generalized forces) from the
    decomposition of a natural Lagrangian, see the module documentation.

    INPUT:

    - ``A``, ``A1``, ``A0`` -- the decomposition (4) as a nested list, a
      list and an element of the calculus' ring
    - ``coordinates``, ``velocities``, ``accelerations`` -- symbols
    - ``calculus`` -- a :class:`SymbolicCalculus` or
      :class:`~sage_dynsym.algebra.trigonometric.RingCalculus`
    - ``mass_matrix`` -- (optional) the symbolic form of ``A``, if the
      caller has it already (it saves converting every entry again)

    OUTPUT: a list of symbolic expressions `E_i`

    Progress is reported through Sage's ``verbose`` at level 1::

        sage: from sage_dynsym.dynamics.natural_equations import natural_equations, SymbolicCalculus
        sage: x = var('x')
        sage: set_verbose(1)
        sage: natural_equations([[1]], [0], -x^2/2, [x], [var('dx')], [var('ddx')],
        ....:                   SymbolicCalculus([x]))
        verbose 1 (...) Lagrange equation 1 of 1 (x)
        [ddx + x]
        sage: set_verbose(0)

    TESTS::

        sage: natural_equations([], [], 0, [], [], [], SymbolicCalculus([]))
        []
    """
    n = len(coordinates)
    C = calculus
    zero = C.zero
    # dA[i, j] = {k: dA_ij/dq_k}, only for the coordinates A_ij depends on
    dA = {(i, j): {k: C.derivative(A[i][j], k) for k in C.dependencies(A[i][j])}
          for i in range(n) for j in range(i, n)}
    dA1 = [{k: C.derivative(A1[i], k) for k in C.dependencies(A1[i])} for i in range(n)]

    def dA_(k, i, j):
        return dA[min(i, j), max(i, j)].get(k, zero)

    def term(coefficient, factor):
        return None if C.is_zero(coefficient) else C.symbolic(coefficient) * factor

    if mass_matrix is None:
        symbolic = {(i, j): C.symbolic(A[i][j]) for i in range(n) for j in range(i, n)}
        mass_matrix = [[symbolic[min(i, j), max(i, j)] for j in range(n)] for i in range(n)]
    equations = []
    for i in range(n):
        # progress of long derivations: set_verbose(1) to see it
        verbose(f"Lagrange equation {i + 1} of {n} ({coordinates[i]})", level=1)
        terms = [None if C.is_zero(A[i][r]) else mass_matrix[i][r] * accelerations[r]
                 for r in range(n)]
        for r in range(n):
            terms.append(term(dA_(r, i, r) - dA_(i, r, r) / 2, velocities[r] ** 2))
            for j in range(r + 1, n):
                terms.append(term(dA_(j, i, r) + dA_(r, i, j) - dA_(i, r, j),
                                  velocities[r] * velocities[j]))
        for j in range(n):  # gyroscopic terms
            terms.append(term(dA1[i].get(j, zero) - dA1[j].get(i, zero), velocities[j]))
        for r in range(n):  # non-stationary terms
            if C.depends_on_time(A[i][r]):
                terms.append(term(C.derivative(A[i][r], None), velocities[r]))
        if C.depends_on_time(A1[i]):
            terms.append(term(C.derivative(A1[i], None), 1))
        if i in C.dependencies(A0):
            terms.append(term(-C.derivative(A0, i), 1))
        terms = [x for x in terms if x is not None]
        equations.append(SR(0).add(*terms) if terms else SR(0))
    return equations

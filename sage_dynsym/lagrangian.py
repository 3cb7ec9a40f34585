r"""
Lagrangians and the Lagrange equations of the second kind

A :class:`Lagrangian` is an immutable snapshot of a characteristic function
`L(q, \dot q, t)` together with the non-potential forces of the model: a
Rayleigh dissipation function `R(q, \dot q)` and generalized forces `Q_i`.
It comes from a mechanical system (:meth:`MechanicalSystem.lagrangian
<sage_dynsym.mechanical_system.MechanicalSystem.lagrangian>`), a linear
circuit, or directly from an expression, e.g. one copied from a paper.

Convention: `L = T + U` with `U` the force function (minus the potential
energy), and the equations are returned as expressions `E_i`, meaning
`E_i = 0`, with

.. MATH::

    E_i = \frac{d}{dt}\frac{\partial L}{\partial \dot q_i}
          - \frac{\partial L}{\partial q_i}
          + \frac{\partial R}{\partial \dot q_i} - Q_i .

When `L` is quadratic in the velocities (a *natural* Lagrangian, (4) of
:doc:`the method </method>`), the equations are assembled from the
decomposition
`L = \tfrac12 \sum A_{ij}\dot q_i \dot q_j + \sum A_i \dot q_i + A_0`
in the structured form (5): mass-matrix entries times accelerations, Christoffel
coefficients times products of velocities, gyroscopic and non-stationary
terms; nothing is expanded. Any other Lagrangian is differentiated directly.

EXAMPLES:

A particle on a rotating hoop, given directly::

    sage: from sage_dynsym import Lagrangian
    sage: theta, m, a, g, Omega = var('theta m a g Omega')
    sage: dtheta = var('dtheta')
    sage: L = Lagrangian(m*a^2/2*(dtheta^2 + Omega^2*sin(theta)^2)
    ....:                + m*g*a*cos(theta), [theta]); L
    Lagrangian in coordinates (theta) : 1/2*(Omega^2*sin(theta)^2 + dtheta^2)*a^2*m + a*g*m*cos(theta)
    sage: L.lagrange_equations()
    [-Omega^2*a^2*m*cos(theta)*sin(theta) + a^2*ddtheta*m + a*g*m*sin(theta)]
    sage: L.mass_matrix()
    [a^2*m]

Dissipation and forces enter the equations::

    sage: x, dx, k, c, F = var('x dx k c F')
    sage: L = Lagrangian(m*dx^2/2 - k*x^2/2, [x], dissipation=c*dx^2/2, forces=[F])
    sage: L.lagrange_equations()
    [c*dx + ddx*m + k*x - F]
"""
import random

from sage.matrix.constructor import matrix
from sage.misc.cachefunc import cached_method
from sage.misc.latex import latex
from sage.misc.misc_c import prod
from sage.rings.real_double import RDF
from sage.structure.sage_object import SageObject
from sage.symbolic.ring import SR

from .errors import ModelError
from .expressions import velocity, acceleration, time_derivative, t
from .natural_equations import natural_equations, SymbolicCalculus
from .trig import trig_rational_simplify


def _symbol_list(symbols, what):
    symbols = [SR(s) for s in symbols]
    for s in symbols:
        if not s.is_symbol():
            raise ModelError(f"{what} must be symbolic variables, got {s}")
    if len(set(symbols)) != len(symbols):
        raise ModelError(f"{what} must be distinct, got {symbols}")
    return symbols


def _is_at_most_quadratic(expr, velocities):
    r"""
    Whether ``expr`` is a polynomial of total degree at most 2 in ``velocities``.
    """
    if not velocities:
        return True
    s = SR.symbol()
    scaled = expr.subs({v: s * v for v in velocities})
    return bool(scaled.is_polynomial(s)) and bool(scaled.degree(s) <= 2)


def _natural_form(A, A1, A0, velocities):
    r"""
    `\tfrac12 \dot q^T A \dot q + A_1\cdot\dot q + A_0`, each
    off-diagonal pair written once.
    """
    n = len(velocities)
    v = velocities
    quadratic = sum((A[i, i] * v[i] ** 2 / 2 for i in range(n)), SR(0)) + sum(
        (A[i, j] * v[i] * v[j] for i in range(n) for j in range(i + 1, n)), SR(0))
    return quadratic + sum((A1[i] * v[i] for i in range(n)), SR(0)) + SR(A0)


def _linear_collected(expr, symbols):
    r"""
    ``expr``, linear in ``symbols``, as `\sum_s c_s s + c_0` with every
    coefficient simplified by
    :func:`~sage_dynsym.trig.trig_rational_simplify`.
    """
    expr = SR(expr)
    rest = trig_rational_simplify(expr.subs({s: 0 for s in symbols}))
    return SR(0).add(*[trig_rational_simplify(expr.diff(s)) * s for s in symbols], rest)


def _is_singular(A):
    r"""
    Whether the square symbolic matrix ``A`` is singular identically.

    It is regular if its determinant at a random point is clearly nonzero
    in floating point (relative to Hadamard's bound, the product of the row
    norms); otherwise Sage's exact rank decides. (The symbolic rank alone
    can take minutes on the mass matrix of a chain of bodies.)

    EXAMPLES::

        sage: from sage_dynsym.lagrangian import _is_singular
        sage: a, m = var('a m')
        sage: _is_singular(matrix([[m, m*cos(a)], [m*cos(a), m]]))
        False
        sage: _is_singular(matrix([[cos(a)^2, cos(a)], [1 - sin(a)^2, cos(a)]]))
        True
        sage: _is_singular(matrix(SR, 0, 0))
        False
    """
    n = A.nrows()
    if n == 0:
        return False
    try:
        variables = sorted(set().union(*(SR(e).variables() for e in A.list())), key=str)
        rng = random.Random(1)
        point = {v: rng.uniform(0.3, 1.7) for v in variables}
        N = A.subs(point).change_ring(RDF)
        bound = prod(row.norm() for row in N.rows())
        if bound > 0 and abs(N.det()) > 1e-8 * bound:
            return False
    except (TypeError, ValueError, ArithmeticError):
        pass   # not numerical at the point (unknown functions, poles, ...)
    return A.rank() < n


class _Elimination:
    r"""
    Symmetric Gaussian elimination `P A P^T = L D L^T` of a symmetric
    invertible matrix `A`, with diagonal pivots (the shortest nonzero
    one first) and every entry simplified modulo `\cos^2+\sin^2 = 1`.

    It writes the quadratic form of `A^{-1}` as a sum of squares
    (Lagrange's reduction), `u^T A^{-1} u = \sum_k y_k^2 / D_k` with
    `L y = P u`: for the heavy symmetric top,
    `p_\varphi^2/C + (p_\psi - p_\varphi\cos\theta)^2/(A\sin^2\theta)`.
    If only zero diagonal entries remain, the rest of the matrix is
    inverted as a block (adjugate over determinant).

    INPUT:

    - ``A`` -- a symmetric invertible matrix over ``SR``
    - ``simplify`` -- (default: :func:`~sage_dynsym.trig.trig_rational_simplify`
      with ``strict=True``) the simplification of every entry, which must
      turn zero into zero (the pivots are tested); the default raises
      :class:`~sage_dynsym.trig.NotPolynomial` where it cannot decide
      (inexact numbers, too large fractions)

    EXAMPLES::

        sage: from sage_dynsym.lagrangian import _Elimination
        sage: from sage_dynsym.trig import trig_rational_simplify
        sage: a, A, C, p, q = var('a A C p q')
        sage: E = _Elimination(matrix([[A*sin(a)^2 + C*cos(a)^2, C*cos(a)], [C*cos(a), C]]))
        sage: E.squares([p, q])
        [q^2/C, (q*cos(a) - p)^2/(A*sin(a)^2)]
        sage: sum(E.products([p, q], [1, 0]))   # first entry of A^{-1} (p, q)
        -(q*cos(a) - p)/(A*sin(a)^2)

    TESTS::

        sage: E = _Elimination(matrix([[0, 1], [1, 0]]))
        sage: E.squares([p, q]), sum(E.products([p, q], [1, 0]))
        ([2*p*q], q)
        sage: _Elimination(matrix([[0.5*sin(a)^2]]))
        Traceback (most recent call last):
        ...
        NotPolynomial: 0.500000000000000 is not a rational number
        sage: E = _Elimination(matrix([[0.5*sin(a)^2]]), simplify=lambda e: e.normalize())
        sage: E.squares([p])
        [2.00000000000000*p^2/sin(a)^2]
    """

    def __init__(self, A, simplify=None):
        if simplify is None:
            def simplify(e):
                return trig_rational_simplify(e, strict=True)
        n = A.nrows()
        self._n = n
        S = {(i, j): simplify(A[i, j]) for i in range(n) for j in range(i, n)}

        def entry(i, j):
            return S[min(i, j), max(i, j)]

        remaining = list(range(n))
        self._order, self._pivots, self._multipliers = [], [], {}
        self._block, self._block_inverse = [], None
        while remaining:
            nonzero = [i for i in remaining if not entry(i, i).is_trivial_zero()]
            if not nonzero:
                block = matrix(SR, [[entry(i, j) for j in remaining] for i in remaining])
                det = simplify(block.det())
                self._block = remaining
                self._block_inverse = block.adjugate().apply_map(lambda e: simplify(e / det))
                break
            k = min(nonzero, key=lambda i: len(str(entry(i, i))))
            remaining.remove(k)
            d = entry(k, k)
            self._order.append(k)
            self._pivots.append(d)
            for i in remaining:
                self._multipliers[i, k] = simplify(entry(i, k) / d)
            for a, i in enumerate(remaining):
                for j in remaining[a:]:
                    key = min(i, j), max(i, j)
                    S[key] = simplify(S[key] - self._multipliers[i, k] * entry(k, j))

    def _reduced(self, u):
        # forward substitution L y = P u (the block indices last)
        y = {}
        for i in self._order + self._block:
            y[i] = u[i] - SR(0).add(*[self._multipliers[i, m] * y[m] for m in self._order
                                      if (i, m) in self._multipliers])
        return y

    def products(self, u, w):
        r"""
        The terms of `u^T A^{-1} w`.
        """
        yu, yw = self._reduced(u), self._reduced(w)
        terms = [yu[k] * yw[k] / d for k, d in zip(self._order, self._pivots)]
        for a, i in enumerate(self._block):
            for b, j in enumerate(self._block):
                terms.append(yu[i] * self._block_inverse[a, b] * yw[j])
        return terms

    def squares(self, u, collect=()):
        r"""
        The terms of `u^T A^{-1} u`: `y_k^2/D_k`, with each `y_k` collected
        in the symbols ``collect`` (in which ``u`` is linear).
        """
        y = {i: _linear_collected(v, collect) for i, v in self._reduced(u).items()}
        terms = [y[k] ** 2 / d for k, d in zip(self._order, self._pivots)]
        if self._block:
            quadratic = SR(0).add(*[y[i] * self._block_inverse[a, b] * y[j]
                                    for a, i in enumerate(self._block)
                                    for b, j in enumerate(self._block)])
            terms.append(trig_rational_simplify(quadratic))
        return terms


class Lagrangian(SageObject):
    r"""
    A Lagrangian `L(q, \dot q, t)` with its dissipation function and
    generalized forces.

    INPUT:

    - ``expr`` -- symbolic expression in coordinates, velocities, parameters
      and ``t``
    - ``coordinates`` -- list of symbolic variables `q_i`
    - ``velocities`` -- (default: ``d<q>`` for each coordinate) list of
      velocity symbols
    - ``dissipation`` -- (default: 0) Rayleigh function `R(q, \dot q)`
    - ``forces`` -- (default: zeros) list of generalized forces `Q_i`
    - ``name`` -- (optional) a name used in the representation
    - ``decomposition`` -- (optional) a triple ``(A, A1, A0)`` for a
      Lagrangian of the form (4) already known in that form (as computed
      by a mechanical system); then ``expr`` may be ``None``, and the
      structure is kept instead of being recovered by differentiation
    - ``equation_builder`` -- (optional, with ``decomposition``) a function
      without arguments returning the equations (5) without dissipation and
      forces, computed in a faster arithmetic by the caller

    EXAMPLES::

        sage: from sage_dynsym import Lagrangian
        sage: x, y, dx, dy = var('x y dx dy')
        sage: L = Lagrangian((dx^2 + dy^2)/2 - (x^2 + y^2)/2, [x, y], name="oscillator")
        sage: L
        Lagrangian of oscillator in coordinates (x, y) : 1/2*dx^2 + 1/2*dy^2 - 1/2*x^2 - 1/2*y^2
        sage: L.coordinates(), L.velocities(), L.accelerations()
        ([x, y], [dx, dy], [ddx, ddy])
        sage: latex(L)
        L = \frac{1}{2} \, ...

    TESTS::

        sage: Lagrangian(dx^2, [x, x])
        Traceback (most recent call last):
        ...
        ModelError: coordinates must be distinct, got [x, x]
        sage: Lagrangian(dx^2, [x], forces=[1, 2])
        Traceback (most recent call last):
        ...
        ModelError: forces: expected 1 generalized force(s), one per coordinate, got 2
        sage: Lagrangian(dx^2, [x^2])
        Traceback (most recent call last):
        ...
        ModelError: coordinates must be symbolic variables, got x^2
    """

    def __init__(self, expr, coordinates, velocities=None, *, dissipation=0,
                 forces=None, name=None, decomposition=None, equation_builder=None):
        self._coordinates = _symbol_list(coordinates, "coordinates")
        if velocities is None:
            velocities = [velocity(q) for q in self._coordinates]
        self._velocities = _symbol_list(velocities, "velocities")
        if len(self._velocities) != len(self._coordinates):
            raise ModelError("expected one velocity per coordinate")
        self._accelerations = [acceleration(q) for q in self._coordinates]
        self._structure = None
        self._equation_builder = equation_builder
        if decomposition is not None:
            A, A1, A0 = decomposition
            self._structure = (A, A1, SR(A0))
            if expr is None:
                expr = _natural_form(A, A1, A0, self._velocities)
        self._expr = SR(expr)
        self._dissipation = SR(dissipation)
        n = len(self._coordinates)
        if forces is None:
            forces = [0] * n
        forces = list(forces)
        if len(forces) != n:
            raise ModelError(f"expected {n} generalized force(s), one per "
                             f"coordinate, got {len(forces)}", entry="forces")
        self._forces = [SR(f) for f in forces]
        self._name = name

    # ------------------------------------------------------------------
    # accessors

    def expr(self):
        r"""
        The Lagrangian as a symbolic expression.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, dx = var('x dx')
            sage: Lagrangian(dx^2/2 - x^4, [x]).expr()
            -x^4 + 1/2*dx^2
        """
        return self._expr

    def coordinates(self):
        r"""
        The generalized coordinates `q` (a new list).

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: Lagrangian(var('dx')^2, [var('x')]).coordinates()
            [x]
        """
        return list(self._coordinates)

    def velocities(self):
        r"""
        The velocity symbols `\dot q`, in the order of the coordinates.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: Lagrangian(var('dx')^2, [var('x')]).velocities()
            [dx]
        """
        return list(self._velocities)

    def accelerations(self):
        r"""
        The acceleration symbols `\ddot q`, in the order of the coordinates.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: Lagrangian(var('dx')^2, [var('x')]).accelerations()
            [ddx]
        """
        return list(self._accelerations)

    def dissipation(self):
        r"""
        The Rayleigh dissipation function `R(q, \dot q)`.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, dx, c = var('x dx c')
            sage: Lagrangian(dx^2, [x], dissipation=c*dx^2/2).dissipation()
            1/2*c*dx^2
        """
        return self._dissipation

    def generalized_forces(self):
        r"""
        The non-potential generalized forces `Q_i` (a new list).

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, dx, t = var('x dx t')
            sage: Lagrangian(dx^2, [x], forces=[sin(t)]).generalized_forces()
            [sin(t)]
        """
        return list(self._forces)

    def name(self):
        r"""
        The name given at construction (or ``None``).

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: Lagrangian(var('dx')^2, [var('x')], name="free").name()
            'free'
        """
        return self._name

    def _repr_(self):
        coords = ", ".join(str(q) for q in self._coordinates)
        of = f" of {self._name}" if self._name else ""
        return f"Lagrangian{of} in coordinates ({coords}) : {self._expr}"

    def _latex_(self):
        return "L = " + latex(self._expr)

    def _derived(self, expr, **changes):
        r"""
        A Lagrangian of the same kind with a new expression (and options).
        """
        options = dict(velocities=self._velocities, dissipation=self._dissipation,
                       forces=self._forces, name=self._name)
        options.update(changes)
        coordinates = options.pop('coordinates', self._coordinates)
        return Lagrangian(expr, coordinates, **options)

    def subs(self, *args, **kwds):
        r"""
        Substitute values for parameters (in `L`, `R` and `Q`).

        Coordinates and velocities must not be substituted: that would change
        the dynamics in a way this method cannot track.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, dx, m, k = var('x dx m k')
            sage: Lagrangian(m*dx^2/2 - k*x^2/2, [x]).subs(m=2, k=8)
            Lagrangian in coordinates (x) : dx^2 - 4*x^2

        TESTS::

            sage: Lagrangian(m*dx^2/2, [x]).subs(x=1)
            Traceback (most recent call last):
            ...
            ModelError: cannot substitute for the coordinate or velocity x
        """
        probe = SR.var('_probe_')
        protected = set(self._coordinates) | set(self._velocities) | {t}
        for v in protected:
            if (v + probe).subs(*args, **kwds) != v + probe:
                raise ModelError(f"cannot substitute for the coordinate or velocity {v}")
        return self._derived(self._expr.subs(*args, **kwds),
                             dissipation=self._dissipation.subs(*args, **kwds),
                             forces=[f.subs(*args, **kwds) for f in self._forces])

    # ------------------------------------------------------------------
    # structure

    def is_natural(self):
        r"""
        Whether `L` is a polynomial of degree at most two in the velocities,
        i.e. of the form (4): `\tfrac12 \dot q^T A \dot q + A_1 \cdot \dot q + A_0`.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, dx = var('x dx')
            sage: Lagrangian(dx^2/2 + x*dx - x^2, [x]).is_natural()
            True
            sage: Lagrangian(-sqrt(1 - dx^2), [x]).is_natural()
            False
        """
        if self._structure is not None:
            return True
        return _is_at_most_quadratic(self._expr, self._velocities)

    @cached_method
    def decomposition(self):
        r"""
        The decomposition (4) `L = \tfrac12 \sum A_{ij} \dot q_i \dot q_j +
        \sum A_i \dot q_i + A_0`.

        OUTPUT: a triple ``(A, A1, A0)``: the symmetric matrix `A_{ij}`, the
        vector `A_i` and the expression `A_0`, functions of `q` and `t`.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, y, dx, dy, w = var('x y dx dy w')
            sage: L = Lagrangian(((dx - w*y)^2 + (dy + w*x)^2)/2, [x, y])
            sage: A, A1, A0 = L.decomposition()
            sage: A, A1, A0
            (
            [1 0]
            [0 1], (-w*y, w*x), 1/2*w^2*x^2 + 1/2*w^2*y^2
            )

        TESTS::

            sage: Lagrangian(dx^4, [x]).decomposition()
            Traceback (most recent call last):
            ...
            ModelError: the Lagrangian is not quadratic in the velocities (dx)
        """
        if self._structure is not None:
            return self._structure
        if not self.is_natural():
            names = ", ".join(map(str, self._velocities))
            raise ModelError(f"the Lagrangian is not quadratic in the velocities ({names})")
        zero = {v: 0 for v in self._velocities}
        gradient = [self._expr.diff(v) for v in self._velocities]
        n = len(self._coordinates)
        A = matrix(SR, n, n)
        for i in range(n):
            for j in range(i, n):
                A[i, j] = A[j, i] = gradient[i].diff(self._velocities[j])
        A1 = matrix(SR, [g.subs(zero) for g in gradient]).row(0) if n else matrix(SR, 0, 0)
        A0 = self._expr.subs(zero)
        A.set_immutable()
        return A, A1, A0

    def mass_matrix(self):
        r"""
        The matrix `A_{ij} = \partial^2 L / \partial \dot q_i \partial \dot q_j`
        (for a mechanical system: the inertia matrix).

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, dx, m = var('x dx m')
            sage: Lagrangian(m*dx^2/2, [x]).mass_matrix()
            [m]
        """
        if self.is_natural():
            return self.decomposition()[0]
        n = len(self._coordinates)
        return matrix(SR, n, n, lambda i, j:
                      self._expr.diff(self._velocities[i], self._velocities[j]))

    def is_singular(self):
        r"""
        Whether `\det(\partial^2 L/\partial \dot q^2) = 0` identically: then
        the Legendre transform is not invertible and
        :meth:`hamiltonian` applies Dirac's scheme.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, y, dx, dy = var('x y dx dy')
            sage: Lagrangian(x*dy - y*dx - x^2 - y^2, [x, y]).is_singular()
            True
            sage: Lagrangian(dx^2 + dy^2, [x, y]).is_singular()
            False
        """
        return _is_singular(self.mass_matrix())

    def generalized_momenta(self):
        r"""
        The expressions `p_i = \partial L / \partial \dot q_i`.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, dx, m, e, A = var('x dx m e A')
            sage: Lagrangian(m*dx^2/2 + e*A*x*dx, [x]).generalized_momenta()
            [A*e*x + dx*m]
        """
        return [self._expr.diff(v) for v in self._velocities]

    def energy(self):
        r"""
        The generalized energy (Jacobi integral)
        `h = \sum \dot q_i \partial L/\partial \dot q_i - L`;
        conserved when `L` does not depend on `t` and there are no
        non-potential forces. For a natural Lagrangian `h = T_2 - T_0 - U`.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, dx, m, k = var('x dx m k')
            sage: Lagrangian(m*dx^2/2 - k*x^2/2, [x]).energy()
            1/2*dx^2*m + 1/2*k*x^2
        """
        h = sum(v * p for v, p in zip(self._velocities, self.generalized_momenta()))
        return (h - self._expr).expand() if self.is_natural() else h - self._expr

    def cyclic_coordinates(self):
        r"""
        The coordinates that do not appear in `L`, `R` and `Q`.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: r, phi, dr, dphi = var('r phi dr dphi')
            sage: Lagrangian((dr^2 + r^2*dphi^2)/2 + 1/r, [r, phi]).cyclic_coordinates()
            [phi]
        """
        parts = [self._expr, self._dissipation] + self._forces
        return [q for q in self._coordinates
                if all(not p.has(q) for p in parts)]

    # ------------------------------------------------------------------
    # equations

    def _nonpotential_terms(self):
        return [self._dissipation.diff(v) - Q
                for v, Q in zip(self._velocities, self._forces)]

    @cached_method
    def lagrange_equations(self, form=None):
        r"""
        The Lagrange equations of the second kind (5), with dissipation and
        generalized forces: a list of expressions `E_i` meaning `E_i = 0`.

        INPUT:

        - ``form`` -- (default: ``"structured"`` for a natural Lagrangian,
          ``"direct"`` otherwise) ``"structured"`` assembles (5) from the
          decomposition (4); ``"direct"`` differentiates
          `d/dt (\partial L/\partial \dot q_i) - \partial L/\partial q_i`.
          Both are equal as functions.

        EXAMPLES:

        The structured form keeps the mass matrix entries as factors of the
        accelerations::

            sage: from sage_dynsym import Lagrangian
            sage: r, phi, dr, dphi, m, k = var('r phi dr dphi m k')
            sage: L = Lagrangian(m*(dr^2 + r^2*dphi^2)/2 - k*r^2/2, [r, phi])
            sage: L.lagrange_equations()
            [-dphi^2*m*r + ddr*m + k*r, 2*dphi*dr*m*r + ddphi*m*r^2]

        A relativistic particle (not natural) is differentiated directly::

            sage: x, dx = var('x dx')
            sage: Lagrangian(-sqrt(1 - dx^2), [x]).lagrange_equations()
            [ddx*(dx^2/(-dx^2 + 1)^(3/2) + 1/sqrt(-dx^2 + 1))]

        TESTS::

            sage: t = var('t')
            sage: L = Lagrangian(m*(dr^2 + r^2*dphi^2)/2 + r*dphi*t, [r, phi])
            sage: S, D = L.lagrange_equations('structured'), L.lagrange_equations('direct')
            sage: all(bool((s - d).expand() == 0) for s, d in zip(S, D))
            True
            sage: L.lagrange_equations('nonsense')
            Traceback (most recent call last):
            ...
            ValueError: form must be 'structured' or 'direct', got 'nonsense'
        """
        if form is None:
            form = "structured" if self.is_natural() else "direct"
        if form == "structured":
            equations = self._structured_equations()
        elif form == "direct":
            equations = self._direct_equations()
        else:
            raise ValueError(f"form must be 'structured' or 'direct', got {form!r}")
        return [e + extra for e, extra in zip(equations, self._nonpotential_terms())]

    def _direct_equations(self):
        q, dq, ddq = self._coordinates, self._velocities, self._accelerations
        return [time_derivative(p, q, dq, ddq) - self._expr.diff(qi)
                for qi, p in zip(q, self.generalized_momenta())]

    def _structured_equations(self):
        r"""
        Equations (5) from `A, A_1, A_0`, see
        :mod:`~sage_dynsym.natural_equations`.
        """
        if self._equation_builder is not None:
            return self._equation_builder()
        A, A1, A0 = self.decomposition()
        return natural_equations([list(row) for row in A.rows()], list(A1), A0,
                                 self._coordinates, self._velocities, self._accelerations,
                                 SymbolicCalculus(self._coordinates))

    def accelerations_solved(self):
        r"""
        The equations solved for the accelerations: a list of expressions
        `\ddot q_i = f_i(q, \dot q, t)` (only for natural Lagrangians with an
        invertible mass matrix).

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, dx, m, k = var('x dx m k')
            sage: Lagrangian(m*dx^2/2 - k*x^2/2, [x]).accelerations_solved()
            [-k*x/m]

        TESTS::

            sage: y, dy = var('y dy')
            sage: Lagrangian(dx^2 + x*dy, [x, y]).accelerations_solved()
            Traceback (most recent call last):
            ...
            ModelError: the mass matrix is singular: the accelerations cannot be solved for
        """
        A = self.mass_matrix()
        if _is_singular(A):
            raise ModelError("the mass matrix is singular: the accelerations cannot be solved for")
        zero = {a: 0 for a in self._accelerations}
        rest = matrix(SR, [[-e.subs(zero)] for e in self.lagrange_equations()])
        solution = A.solve_right(rest)
        return [solution[i, 0].simplify_rational() for i in range(A.nrows())]

    def first_order_system(self):
        r"""
        The equations as a first-order system `\dot x = F(x, t)` with state
        `x = (q, \dot q)`.

        OUTPUT: a pair ``(state, rhs)`` of lists.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, dx, m, k = var('x dx m k')
            sage: Lagrangian(m*dx^2/2 - k*x^2/2, [x]).first_order_system()
            ([x, dx], [dx, -k*x/m])
        """
        state = self._coordinates + self._velocities
        return state, list(self._velocities) + self.accelerations_solved()

    # ------------------------------------------------------------------
    # other forms

    def routh(self, cyclic):
        r"""
        The Routh function for the given cyclic coordinates.

        See :class:`~sage_dynsym.routh.RouthFunction`.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: r, phi, dr, dphi, m, k = var('r phi dr dphi m k')
            sage: L = Lagrangian(m*(dr^2 + r^2*dphi^2)/2 - k*r^2/2, [r, phi])
            sage: R = L.routh([phi]); R.expr()
            1/2*dr^2*m - 1/2*k*r^2 - 1/2*p_phi^2/(m*r^2)
        """
        from .routh import RouthFunction
        return RouthFunction(self, cyclic)

    def hamiltonian(self):
        r"""
        The Hamiltonian by the Legendre transform; for a singular Lagrangian
        the result carries Dirac's constraint analysis.

        See :class:`~sage_dynsym.hamiltonian.Hamiltonian`.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, dx, m, k = var('x dx m k')
            sage: Lagrangian(m*dx^2/2 - k*x^2/2, [x]).hamiltonian().expr()
            1/2*k*x^2 + 1/2*p_x^2/m
        """
        from .hamiltonian import Hamiltonian
        return Hamiltonian(self)

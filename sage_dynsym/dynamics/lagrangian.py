r"""
Lagrangians, Routh functions and the Lagrange equations of the second kind

A :class:`Lagrangian` is an immutable snapshot of a characteristic function
`L(q, \dot q, t)` together with the non-potential forces of the model: a
Rayleigh dissipation function `R(q, \dot q)` and generalized forces `Q_i`.
It comes from a mechanical system (:meth:`MechanicalSystem.lagrangian
<sage_dynsym.mechanics.system.MechanicalSystem.lagrangian>`), a linear
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

A Lagrangian is its expression, its coordinates and the data of the model
it is given (dissipation, forces, its constraint set), read through its
methods. What is computed from it is done by method objects and functions
that take it, which its methods call: the equations
(:class:`~sage_dynsym.dynamics.lagrange_equations.LagrangeEquations`),
with the constraint set and its multipliers
(:class:`~sage_dynsym.dynamics.holonomic.HolonomicConstraints`), the
momenta, energy and Legendre transform
(:mod:`~sage_dynsym.dynamics.legendre`), the cyclic coordinates and the
Routh reduction (:mod:`~sage_dynsym.dynamics.routh`), and the numerics
(:class:`~sage_dynsym.numerics.methods.NumericalMethods`).

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

Holonomic constraints
---------------------

With holonomic constraints `f_j(q, t) = 0` (``constraints=[f_1, ...]``) the
equations are Lagrange's equations of the first kind: one multiplier `\mu_j`
per constraint (:meth:`~Lagrangian.multipliers`), and

.. MATH::

    E_i = \frac{d}{dt}\frac{\partial L}{\partial \dot q_i}
          - \frac{\partial L}{\partial q_i}
          + \frac{\partial R}{\partial \dot q_i} - Q_i
          - \sum_j \mu_j \frac{\partial f_j}{\partial q_i},

i.e. `M\ddot q = F + J^T\mu` with `J = \partial f/\partial q`: `J^T\mu` is
the generalized constraint force. Together with the twice-differentiated
constraints `J\ddot q + \dot J\dot q + \dots = 0` they determine the
accelerations and the multipliers (:meth:`~Lagrangian.accelerations_and_multipliers`).

EXAMPLES:

A pendulum in Cartesian coordinates; `-2\mu_1 l` is the tension of the rod::

    sage: from sage_dynsym import Lagrangian
    sage: x, y, dx, dy, m, g, l = var('x y dx dy m g l')
    sage: L = Lagrangian(m*(dx^2 + dy^2)/2 - m*g*y, [x, y], constraints=[x^2 + y^2 - l^2])
    sage: L.lagrange_equations()
    [ddx*m - 2*mu1*x, ddy*m + g*m - 2*mu1*y]
    sage: L.accelerations_and_multipliers()[L.multipliers()[0]]
    1/2*(g*m*y - (dx^2 + dy^2)*m)/(x^2 + y^2)

Routh functions
---------------

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

TESTS:

The checks of the constructor of :class:`Lagrangian`::

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
    sage: Lagrangian(dx^2 + dy^2, [x, y], constraints=[x - y, 2*y - 2*x])
    Traceback (most recent call last):
    ...
    ModelError: constraints: the 2 constraints are not independent: their Jacobian with respect to the coordinates has rank less than 2 at a generic point; remove the redundant ones
    sage: Lagrangian(dx^2 + dy^2, [x, y], constraints=[x - y, var('l') - 1])
    Traceback (most recent call last):
    ...
    ModelError: constraints[1]: the constraint l - 1 == 0 does not depend on the coordinates x, y
    sage: Lagrangian(dx^2 + dy^2, [x, y], constraints=[dx - y])
    Traceback (most recent call last):
    ...
    ModelError: constraints[0]: a holonomic constraint f(q, t) cannot depend on the velocity dx
    sage: Lagrangian(dx^2 + dy^2, [x, y], constraints=[x == y]).constraints()
    [x - y]
    sage: Lagrangian(dx^2 + dy^2, [x, y], constraints=[x < y])
    Traceback (most recent call last):
    ...
    ModelError: constraints[0]: expected an expression f meaning f = 0 or an equation, got the relation x < y

The parameters declared positive of a model are checked where values are
given::

    sage: from sage_dynsym import load
    sage: from sage_dynsym.description import example_path
    sage: L = load(example_path('spherical_pendulum.yaml')).lagrangian()
    sage: L.positive_parameters()
    [m, l, g]
    sage: values = {'m': 1, 'l': 1, 'g': 9.81}
    sage: L.simulate(dict(values, m=-1), {'theta': 1, 'psi': 0, 'dtheta': 0, 'dpsi': 0}, 1)
    Traceback (most recent call last):
    ...
    ModelError: values: m is declared positive, got -1
    sage: L.subs(g=-9.81)
    Traceback (most recent call last):
    ...
    ModelError: subs: g is declared positive, got -981/100
    sage: L.subs(g=9.81).positive_parameters(), L.routh([var('psi')]).positive_parameters()
    ([m, l], [m, l, g])

Lagrangians are values, pickled by content (a structured form of the
equations, where one was attached, is recomputed after unpickling)::

    sage: x, dx, m, k = var('x dx m k')
    sage: L = Lagrangian(m*dx^2/2 - k*x^2/2, [x], dissipation=var('c')*dx^2/2)
    sage: loads(dumps(L)) == L
    True
    sage: C = Lagrangian(m*dx^2/2, [x], constraints=[x - k]); loads(dumps(C)) == C
    True
    sage: C == Lagrangian(m*dx^2/2, [x]), C
    (False, Lagrangian in coordinates (x) : 1/2*dx^2*m, subject to -k + x == 0)
    sage: latex(C)
    L = \frac{1}{2} \, {\dot{x}}^{2} m , \quad -k + x = 0
    sage: len({Lagrangian(dx^2/2, [x]), Lagrangian(dx^2/2, [x])})
    1

The conserved energy of a mechanical system, from its decomposition::

    sage: L = load(example_path('spherical_pendulum.yaml')).lagrangian()
    sage: L.conserved_energy()
    1/2*dpsi^2*l^2*m*sin(theta)^2 + 1/2*dtheta^2*l^2*m + g*l*m*cos(theta)
"""
from sage.matrix.constructor import matrix
from sage.misc.cachefunc import cached_method
from sage.misc.latex import latex
from sage.structure.sage_object import SageObject
from sage.symbolic.ring import SR

from ..arguments import expression_argument, expression_list, symbol_arguments
from ..errors import ModelError, brief
from ..symbols import velocity, acceleration, momentum, t, exact_decimals
from ..numerics.methods import NumericalMethods
from ..numerics.values import check_model_values
from ..numerics.expressions import symbols_and_functions
from .holonomic import HolonomicConstraints, independent_coordinates
from .lagrange_equations import LagrangeEquations
from .legendre import generalized_momenta, energy, legendre
from .natural_form import symbol_list, is_at_most_quadratic, natural_form, natural_decomposition
from .routh import check_cyclic, routh_reduction, cyclic_coordinates
# names earlier versions of this module held, importable from it as before
from .compact import equations_cse
from .natural_equations import natural_equations, SymbolicCalculus
from .natural_form import linear_collected, is_singular, has_full_row_rank, Elimination

__all__ = ['Lagrangian', 'RouthFunction', 'equations_cse', 'natural_equations', 'SymbolicCalculus',
           'symbol_list', 'is_at_most_quadratic', 'natural_form', 'linear_collected',
           'is_singular', 'has_full_row_rank', 'Elimination', 'substitution', 'substituted']


class Lagrangian(NumericalMethods, SageObject):
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
    - ``constraints`` -- (default: none) holonomic constraints `f_j(q, t)`,
      each meaning `f_j = 0` (or equations ``a == b``, meaning `a - b = 0`),
      independent at a generic point (see the module documentation)
    - ``positive`` -- (optional) the parameters declared positive (those
      of the model it comes from): values given to :meth:`subs`,
      :meth:`numerical_rhs` and :meth:`simulate` must respect them (see
      :meth:`positive_parameters`)

    EXAMPLES::

        sage: from sage_dynsym import Lagrangian
        sage: x, y, dx, dy = var('x y dx dy')
        sage: L = Lagrangian((dx^2 + dy^2)/2 - (x^2 + y^2)/2, [x, y], name="oscillator")
        sage: L
        Lagrangian of oscillator in coordinates (x, y) : 1/2*dx^2 + 1/2*dy^2 - 1/2*x^2 - 1/2*y^2
        sage: L.coordinates(), L.velocities(), L.accelerations()
        ([x, y], [dx, dy], [ddx, ddy])
        sage: L.expr(), L.name(), L.equation_builder()
        (1/2*dx^2 + 1/2*dy^2 - 1/2*x^2 - 1/2*y^2, 'oscillator', None)
        sage: latex(L)
        L = \frac{1}{2} \, ...
        sage: t, c = var('t c')
        sage: D = Lagrangian(dx^2/2, [x], dissipation=c*dx^2/2, forces=[sin(t)])
        sage: D.dissipation(), D.generalized_forces()
        (1/2*c*dx^2, [sin(t)])

    TESTS: a Lagrangian is a value (pickled by content) whose conserved
    energy is an integral of its equations (``_test_energy``)::

        sage: TestSuite(L).run()
    """

    def __init__(self, expr, coordinates, velocities=None, *, dissipation=0,
                 forces=None, name=None, decomposition=None, equation_builder=None,
                 constraints=(), positive=()):
        self._coordinates = symbol_list(coordinates, "coordinates")
        self._positive = symbol_arguments(positive, 'positive')
        if velocities is None:
            velocities = [velocity(q) for q in self._coordinates]
        self._velocities = symbol_list(velocities, "velocities")
        if len(self._velocities) != len(self._coordinates):
            raise ModelError("expected one velocity per coordinate")
        self._accelerations = [acceleration(q) for q in self._coordinates]
        self._structure = None
        self._equation_builder = equation_builder
        if decomposition is not None:
            A, A1, A0 = decomposition
            self._structure = (A, A1, SR(A0))
        # with a decomposition, L itself is formed only when asked for (the
        # equations of a large model do not need it)
        self._expression = None if expr is None and decomposition is not None else \
            expression_argument(expr, "expr", expected="the Lagrangian as a symbolic expression",
                                hint="e.g. Lagrangian(m*dx^2/2 - k*x^2/2, [x])")
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
        # the multipliers avoid the symbols of the model
        self._constraint_set = HolonomicConstraints(
            self._coordinates, self._velocities, constraints,
            taken=lambda: [self._expr, self._dissipation] + self._forces)

    @property
    def _expr(self):
        if self._expression is None:
            A, A1, A0 = self._structure
            self._expression = natural_form(A, A1, A0, self._velocities)
        return self._expression

    # ------------------------------------------------------------------
    # accessors

    def expr(self):
        r"""
        The Lagrangian as a symbolic expression.

        EXAMPLES: see the class documentation.
        """
        return self._expr

    def coordinates(self):
        r"""
        The generalized coordinates `q` (a new list).

        EXAMPLES: see the class documentation.
        """
        return list(self._coordinates)

    def velocities(self):
        r"""
        The velocity symbols `\dot q`, in the order of the coordinates.

        EXAMPLES: see the class documentation.
        """
        return list(self._velocities)

    def accelerations(self):
        r"""
        The acceleration symbols `\ddot q`, in the order of the coordinates.

        EXAMPLES: see the class documentation.
        """
        return list(self._accelerations)

    def dissipation(self):
        r"""
        The Rayleigh dissipation function `R(q, \dot q)`.

        EXAMPLES: see the class documentation.
        """
        return self._dissipation

    def generalized_forces(self):
        r"""
        The non-potential generalized forces `Q_i` (a new list).

        EXAMPLES: see the class documentation.
        """
        return list(self._forces)

    def name(self):
        r"""
        The name given at construction (or ``None``).

        EXAMPLES: see the class documentation.
        """
        return self._name

    def positive_parameters(self):
        r"""
        The parameters declared positive (``positive=``, or the declared
        signs of the model the Lagrangian comes from). They are not part of
        the Lagrangian's value (``==``), but the values given to
        :meth:`subs`, :meth:`numerical_rhs` and :meth:`simulate` must
        respect them.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, dx, m, k = var('x dx m k')
            sage: L = Lagrangian(m*dx^2/2 - k*x^2/2, [x], positive=[m, k])
            sage: L.positive_parameters(), L.subs(k=2).positive_parameters()
            ([m, k], [m])
        """
        return list(self._positive)

    # ------------------------------------------------------------------
    # value semantics

    def _content(self):
        return (type(self).__name__, self._expr, tuple(self._coordinates),
                tuple(self._velocities), self._dissipation, tuple(self._forces),
                tuple(self.constraints()))

    def __eq__(self, other):
        # values: equal when their contents are structurally the same
        if type(self) is not type(other):
            return False
        return all(_same(a, b) for a, b in zip(self._content(), other._content()))

    def __ne__(self, other):
        return not self == other

    def __hash__(self):
        # consistent with ==: structural hashes of the expressions
        return hash(tuple(_hashable(a) for a in self._content()))

    def __reduce__(self):
        # by content (see the module documentation)
        return (_rebuild_lagrangian,
                (self._expr, self._coordinates, self._velocities,
                 {'dissipation': self._dissipation, 'forces': self._forces,
                  'name': self._name, 'decomposition': self._structure,
                  'constraints': self.constraints(), 'positive': self._positive}))

    def _repr_(self):
        coords = ", ".join(str(q) for q in self._coordinates)
        of = f" of {self._name}" if self._name else ""
        return f"Lagrangian{of} in coordinates ({coords}) : {self._expr}{self._subject_to()}"

    def _latex_(self):
        return "L = " + latex(self._expr) + "".join(
            r", \quad " + latex(f) + " = 0" for f in self.constraints())

    def _derived(self, expr, **changes):
        # a Lagrangian of the same kind with a new expression (and options)
        options = dict(velocities=self._velocities, dissipation=self._dissipation,
                       forces=self._forces, name=self._name, constraints=self.constraints(),
                       positive=self._positive)
        options.update(changes)
        coordinates = options.pop('coordinates', self._coordinates)
        return Lagrangian(expr, coordinates, **options)

    def subs(self, *args, **kwds):
        r"""
        Substitute values for parameters (in `L`, `R`, `Q` and the
        constraints), see :func:`substituted`.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, dx, m, k = var('x dx m k')
            sage: L = Lagrangian(m*dx^2/2 - k*x^2/2, [x]).subs(m=2, k=8); L
            Lagrangian in coordinates (x) : dx^2 - 4*x^2
            sage: L.accelerations_solved(), L.first_order_system()
            ([-4*x], ([x, dx], [dx, -4*x]))
        """
        return self._derived(**substituted(self, *args, **kwds))

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
        return is_at_most_quadratic(self._expr, self._velocities)

    @cached_method
    def decomposition(self):
        r"""
        The decomposition (4) `L = \tfrac12 \sum A_{ij} \dot q_i \dot q_j +
        \sum A_i \dot q_i + A_0`: a triple ``(A, A1, A0)`` of functions of
        `q` and `t` (see
        :func:`~sage_dynsym.dynamics.natural_form.natural_decomposition`).

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, dx, w = var('x dx w')
            sage: Lagrangian((dx - w*x)^2/2, [x]).decomposition()
            ([1], (-w*x), 1/2*w^2*x^2)
        """
        if self._structure is not None:
            return self._structure
        return natural_decomposition(self._expr, self._velocities)

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
        :meth:`hamiltonian` applies Dirac's scheme.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, y, dx, dy = var('x y dx dy')
            sage: Lagrangian(x*dy - y*dx - x^2 - y^2, [x, y]).is_singular()
            True
        """
        return is_singular(self.mass_matrix())

    def equation_builder(self):
        r"""
        The function given as ``equation_builder``, or ``None``.

        EXAMPLES: see the class documentation.
        """
        return self._equation_builder

    # ------------------------------------------------------------------
    # constraints (the constraint set: dynamics.holonomic)

    def constraint_set(self):
        r"""
        The constraint set: the constraints with their multipliers
        (:class:`~sage_dynsym.dynamics.holonomic.HolonomicConstraints`).

        EXAMPLES: see :class:`~sage_dynsym.dynamics.lagrange_equations.LagrangeEquations`.
        """
        return self._constraint_set

    def constraints(self):
        r"""
        The holonomic constraints `f_j(q, t)`, each meaning `f_j = 0` (a new
        list, empty if none).

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, y, dx, dy, l = var('x y dx dy l')
            sage: Lagrangian((dx^2 + dy^2)/2, [x, y], constraints=[x^2 + y^2 - l^2]).constraints()
            [-l^2 + x^2 + y^2]
        """
        return self._constraint_set.expressions()

    def multipliers(self):
        r"""
        The multipliers of the constraints: symbols ``mu1, mu2, ...`` that
        occur nowhere else in the model (see
        :func:`~sage_dynsym.symbols.constraint_multipliers`). The equations
        contain `-\sum_j \mu_j \partial f_j/\partial q_i`.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, y, dx, dy, mu1 = var('x y dx dy mu1')
            sage: Lagrangian((dx^2 + dy^2)/2 + mu1*x, [x, y], constraints=[x - y]).multipliers()
            [mu2]
        """
        return self._constraint_set.multipliers()

    def nonholonomic_constraints(self):
        r"""
        The constraints on the velocities (see
        :class:`~sage_dynsym.dynamics.nonholonomic.NonholonomicLagrangian`).

        EXAMPLES: see :mod:`~sage_dynsym.dynamics.nonholonomic`.
        """
        return self._constraint_set.velocity_constraints()

    def velocity_multipliers(self):
        r"""
        The multipliers of the constraints on the velocities.

        EXAMPLES: see :mod:`~sage_dynsym.dynamics.nonholonomic`.
        """
        return self._constraint_set.velocity_multipliers()

    def _subject_to(self):
        if not self.constraints():
            return ""
        return ", subject to " + ", ".join(f"{f} == 0" for f in self.constraints())

    def reduce(self, independent, parametrization):
        r"""
        The Lagrangian in the coordinates ``independent``, the others given
        by ``parametrization`` (see
        :func:`~sage_dynsym.dynamics.holonomic.independent_coordinates`).

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, y, dx, dy, m, g, l, th = var('x y dx dy m g l theta')
            sage: L = Lagrangian(m*(dx^2 + dy^2)/2 - m*g*y, [x, y], constraints=[x^2 + y^2 - l^2])
            sage: L.reduce([th], {x: l*sin(th), y: -l*cos(th)}).equations()[0].simplify_full()
            ddtheta*l^2*m + g*l*m*sin(theta)
        """
        expr, coordinates, velocities, dissipation, forces = \
            independent_coordinates(self, independent, parametrization)
        # a plain Lagrangian, whatever the kind of this one
        return self._derived(expr, coordinates=coordinates, velocities=velocities,
                             dissipation=dissipation, forces=forces, constraints=())

    # ------------------------------------------------------------------
    # equations (the method object: dynamics.lagrange_equations)

    @cached_method
    def _equations_method(self):
        return LagrangeEquations(self, self._constraint_set)

    def lagrange_equations(self, form=None):
        r"""
        The Lagrange equations (5), with dissipation, generalized forces and
        constraint forces: a list of expressions `E_i` meaning `E_i = 0`
        (see :meth:`LagrangeEquations.equations
        <sage_dynsym.dynamics.lagrange_equations.LagrangeEquations.equations>`
        for ``form``).

        EXAMPLES:

        The structured form keeps the mass matrix entries as factors of the
        accelerations; a relativistic particle (not natural) is
        differentiated directly::

            sage: from sage_dynsym import Lagrangian
            sage: r, phi, dr, dphi, m, k = var('r phi dr dphi m k')
            sage: Lagrangian(m*(dr^2 + r^2*dphi^2)/2 - k*r^2/2, [r, phi]).lagrange_equations()
            [-dphi^2*m*r + ddr*m + k*r, 2*dphi*dr*m*r + ddphi*m*r^2]
            sage: x, dx = var('x dx')
            sage: Lagrangian(-sqrt(1 - dx^2), [x]).lagrange_equations()
            [ddx*(dx^2/(-dx^2 + 1)^(3/2) + 1/sqrt(-dx^2 + 1))]
        """
        return self._equations_method().equations(form)

    def equations(self):
        r"""
        The equations of motion: :meth:`lagrange_equations` (the name every
        model and characteristic function of the package shares).

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, dx = var('x dx')
            sage: Lagrangian(dx^2/2 - x^2/2, [x]).equations()
            [ddx + x]
        """
        return self.lagrange_equations()

    def equations_cse(self):
        r"""
        The Lagrange equations written with their common subexpressions (see
        :func:`~sage_dynsym.dynamics.compact.equations_cse`).

        EXAMPLES: see :func:`~sage_dynsym.dynamics.compact.equations_cse`.
        """
        return equations_cse(self.lagrange_equations())

    def equations_record(self):
        r"""
        The equations as neutral data for the analysis (see
        :meth:`~sage_dynsym.dynamics.lagrange_equations.LagrangeEquations.record`).

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, y, dx, dy = var('x y dx dy')
            sage: Lagrangian((dx^2 + dy^2)/2, [x, y], constraints=[x - y]).equations_record()
            Second-order equations in (x, y): [ddx - mu1, ddy + mu1] == 0 with constraints [x - y] == 0
        """
        return self._equations_method().record()

    def accelerations_and_multipliers(self):
        r"""
        The accelerations and the multipliers solved together with the
        constraints differentiated (Lagrange's equations of the first kind):
        a dict ``{ddq_i: ..., mu_j: ...}`` (see
        :meth:`~sage_dynsym.dynamics.lagrange_equations.LagrangeEquations.accelerations_and_multipliers`).

        EXAMPLES: see the module documentation.
        """
        return dict(self._equations_method().accelerations_and_multipliers())

    def accelerations_solved(self):
        r"""
        The equations solved for the accelerations `\ddot q_i = f_i(q, \dot
        q, t)` (see
        :meth:`~sage_dynsym.dynamics.lagrange_equations.LagrangeEquations.accelerations_solved`).

        EXAMPLES: see :meth:`subs`.
        """
        return self._equations_method().accelerations_solved()

    def first_order_system(self):
        r"""
        The equations as a first-order system `\dot x = F(x, t)`, `x = (q,
        \dot q)`: a pair ``(state, rhs)`` of lists.

        EXAMPLES: see :meth:`subs`.
        """
        return self._equations_method().first_order_system()

    # ------------------------------------------------------------------
    # momenta, energy, Hamiltonian (dynamics.legendre)

    def generalized_momenta(self):
        r"""
        The momenta `p_i = \partial L / \partial \dot q_i` (see
        :func:`~sage_dynsym.dynamics.legendre.generalized_momenta`).

        EXAMPLES: see :mod:`~sage_dynsym.dynamics.legendre`.
        """
        return generalized_momenta(self)

    def energy(self):
        r"""
        The generalized energy `h = \sum \dot q_i \partial L/\partial \dot
        q_i - L` (see :func:`~sage_dynsym.dynamics.legendre.energy`).

        EXAMPLES: see :mod:`~sage_dynsym.dynamics.legendre`.
        """
        return energy(self)

    def conserved_energy(self):
        r"""
        The generalized energy (:meth:`energy`) when it is an integral of
        the motion -- no explicit time in `L` or the constraints, no
        dissipation or generalized forces, velocity constraints homogeneous
        and stationary --, else ``None``; what ``simulate(...).energy_drift()``
        measures. From a decomposition given, `T_2 - T_0 - U` unexpanded.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, dx, c = var('x dx c')
            sage: Lagrangian(dx^2/2 - x^2/2, [x]).conserved_energy()
            1/2*dx^2 + 1/2*x^2
            sage: Lagrangian(dx^2/2, [x], dissipation=c*dx^2/2).conserved_energy() is None
            True
        """
        velocities = self._velocities
        # velocity constraints do no work when homogeneous and stationary
        if any(g.has(t) or not SR(g).subs({v: 0 for v in velocities}).is_zero()
               for g in self.nonholonomic_constraints()):
            return None
        if self._structure is not None:
            # h = T_2 - T_0 - U from the decomposition: nothing expanded (a
            # memoized walk looks for t: large models share subexpressions)
            A, A1, A0 = self._structure
            if str(t) in symbols_and_functions(list(A.list()) + list(A1) + [A0])[0]:
                return None
            h = natural_form(A, [0] * len(velocities), -A0, velocities)
        elif self._expr.has(t):
            return None
        else:
            h = None
        if (not self._dissipation.is_zero() or any(not f.is_zero() for f in self._forces)
                or any(SR(f).has(t) for f in self.constraints())):
            return None
        return self.energy() if h is None else h

    def _conserved_energy(self):
        # the hook of NumericalMethods
        return self.conserved_energy()

    def hamiltonian(self):
        r"""
        The Hamiltonian by the Legendre transform; for a singular Lagrangian
        the result carries Dirac's constraint analysis (see
        :func:`~sage_dynsym.dynamics.legendre.legendre`).

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, dx, m, k = var('x dx m k')
            sage: Lagrangian(m*dx^2/2 - k*x^2/2, [x]).hamiltonian().expr()
            1/2*k*x^2 + 1/2*p_x^2/m
        """
        return legendre(self)

    # ------------------------------------------------------------------
    # cyclic coordinates and the Routh function (dynamics.routh)

    def cyclic_coordinates(self):
        r"""
        The coordinates whose momentum is conserved, those :meth:`routh`
        accepts (see :func:`~sage_dynsym.dynamics.routh.why_not_cyclic`).

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: r, phi, dr, dphi = var('r phi dr dphi')
            sage: Lagrangian((dr^2 + r^2*dphi^2)/2 + 1/r, [r, phi]).cyclic_coordinates()
            [phi]
        """
        return cyclic_coordinates(self)

    def routh(self, cyclic):
        r"""
        The Routh function for the given cyclic coordinates (see
        :class:`~sage_dynsym.dynamics.lagrangian.RouthFunction` and the
        module documentation).

        EXAMPLES: see :class:`~sage_dynsym.dynamics.lagrangian.RouthFunction`.
        """
        return RouthFunction(self, cyclic)


class RouthFunction(Lagrangian):
    r"""
    The Routh function of a Lagrangian for given cyclic coordinates.

    Being itself a :class:`~sage_dynsym.dynamics.lagrangian.Lagrangian` of the
    positional coordinates (with the cyclic momenta as constant parameters),
    it supports everything a Lagrangian does: equations, Hamiltonian,
    linearization, further reduction.

    INPUT:

    - ``lagrangian`` -- a natural :class:`~sage_dynsym.dynamics.lagrangian.Lagrangian`
    - ``cyclic`` -- list of coordinates of ``lagrangian`` that are cyclic
    - ``momenta`` -- (default: ``p_<q>``) symbols for the constant cyclic
      momenta

    EXAMPLES::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.dynamics.lagrangian import RouthFunction
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
        sage: RouthFunction(Lagrangian((dx^2 + dy^2)/2, [x, y], constraints=[x - y]), [y])
        Traceback (most recent call last):
        ...
        ModelError: cyclic: y is not cyclic: a constraint depends on it

    Constraints between the positional coordinates are kept::

        sage: z, dz = var('z dz')
        sage: RouthFunction(Lagrangian((dx^2 + dy^2 + dz^2)/2, [x, y, z], constraints=[x - y]), [z])
        Routh function in coordinates (x, y) with cyclic momenta (p_z) : 1/2*dx^2 + 1/2*dy^2 - 1/2*p_z^2, subject to x - y == 0
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
            raise ModelError(f"expected a Lagrangian object, got {brief(lagrangian)}; e.g. "
                             "model.lagrangian().routh(cyclic)", entry="lagrangian")
        cyclic = expression_list(cyclic, "cyclic", expected="a list of cyclic coordinates")
        check_cyclic(lagrangian, cyclic)
        self._cyclic = [SR(c) for c in cyclic]
        if momenta is None:
            momenta = [momentum(c) for c in self._cyclic]
        self._momenta = [SR(c) for c in momenta]
        self._lagrangian = lagrangian
        coordinates, velocities, decomposition, self._solved_velocities, dissipation, forces = \
            routh_reduction(lagrangian, self._cyclic, self._momenta)
        super().__init__(None, coordinates, velocities, dissipation=dissipation,
                         forces=forces, name=lagrangian.name(), decomposition=decomposition,
                         constraints=lagrangian.constraints(),
                         positive=lagrangian.positive_parameters())

    def _repr_(self):
        coords = ", ".join(map(str, self.coordinates()))
        momenta = ", ".join(map(str, self._momenta))
        return (f"Routh function in coordinates ({coords}) with cyclic momenta "
                f"({momenta}) : {self.expr()}{self._subject_to()}")

    def _content(self):
        return ('RouthFunction', self._lagrangian, tuple(self._cyclic), tuple(self._momenta))

    def __reduce__(self):
        r"""
        Pickling: the Lagrangian and the cyclic coordinates.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: r, phi, dr, dphi = var('r phi dr dphi')
            sage: R = Lagrangian((dr^2 + r^2*dphi^2)/2, [r, phi]).routh([phi])
            sage: loads(dumps(R)) == R
            True
            sage: TestSuite(R).run()
        """
        return (RouthFunction, (self._lagrangian, self._cyclic, self._momenta))

    def _latex_(self):
        from sage.misc.latex import latex
        return "R = " + latex(self.expr())

    def _derived(self, expr, **changes):
        # substitution etc. give a plain Lagrangian of the positional coordinates
        return Lagrangian(expr, changes.pop('coordinates', self.coordinates()),
                          **{'velocities': self.velocities(),
                             'dissipation': self.dissipation(),
                             'forces': self.generalized_forces(),
                             'name': self.name(), 'constraints': self.constraints(),
                             'positive': self.positive_parameters(), **changes})

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



def substituted(lagrangian, *args, **kwds):
    r"""
    The parts of ``lagrangian`` with values substituted for parameters, what
    :meth:`Lagrangian.subs` makes a Lagrangian of: a dict with the keys
    ``expr``, ``dissipation``, ``forces``, ``constraints`` and
    ``positive`` (the parameters declared positive that were not
    substituted).

    A number given for a parameter declared positive
    (:meth:`Lagrangian.positive_parameters`) must be positive. Coordinates
    and velocities must not be substituted: that would change the dynamics
    in a way this function cannot track. A float is the exact decimal it
    prints as (``0.3`` is `3/10`: see
    :func:`~sage_dynsym.symbols.exact_decimals`).

    EXAMPLES::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.dynamics.lagrangian import substituted
        sage: x, dx, m, k = var('x dx m k')
        sage: substituted(Lagrangian(m*dx^2/2 - k*x^2/2, [x], positive=[m]), m=2)
        {'constraints': [], 'dissipation': 0, 'expr': -1/2*k*x^2 + dx^2, 'forces': [0],
         'positive': []}
        sage: L = Lagrangian(m*dx^2/2 - k*x^2/2, [x]).subs({m: float(2), k: 8})
        sage: L.first_order_system()
        ([x, dx], [dx, -4*x])

    TESTS::

        sage: Lagrangian(m*dx^2/2, [x]).subs(x=1)
        Traceback (most recent call last):
        ...
        ModelError: cannot substitute for the coordinate or velocity x
        sage: Lagrangian(m*dx^2/2 - k*x^2/2, [x]).subs({'k': 2}, m == 1)
        Lagrangian in coordinates (x) : 1/2*dx^2 - x^2
        sage: Lagrangian(m*dx^2/2, [x]).subs(2)
        Traceback (most recent call last):
        ...
        ModelError: subs: expected a dict {parameter: value} or equations parameter == value, got 2
    """
    args = [substitution(a) for a in args]
    kwds = {k: exact_decimals(v) for k, v in kwds.items()}
    probe = SR.var('_probe_')
    protected = set(lagrangian.coordinates()) | set(lagrangian.velocities()) | {t}
    for v in protected:
        if (v + probe).subs(*args, **kwds) != v + probe:
            raise ModelError(f"cannot substitute for the coordinate or velocity {v}")
    positive = lagrangian.positive_parameters()
    given = {p: p.subs(*args, **kwds) for p in positive}
    given = {p: v for p, v in given.items() if not v.is_trivially_equal(p)}
    check_model_values(lagrangian, given, entry="subs")
    return dict(expr=lagrangian.expr().subs(*args, **kwds),
                dissipation=lagrangian.dissipation().subs(*args, **kwds),
                forces=[f.subs(*args, **kwds) for f in lagrangian.generalized_forces()],
                constraints=[f.subs(*args, **kwds) for f in lagrangian.constraints()],
                positive=[p for p in positive if p not in given])


def substitution(arg):
    r"""
    A positional argument of :meth:`Lagrangian.subs`: a dict (symbols or
    their names as keys) or an equation ``parameter == value``, with each
    float the exact decimal it prints as; anything else is a
    :class:`~sage_dynsym.errors.ModelError`.

    EXAMPLES::

        sage: from sage_dynsym.dynamics.lagrangian import substitution
        sage: substitution({'k': 1.5r}), substitution(var('m') == 2)
        ({k: 3/2}, m == 2)
        sage: substitution('k = 1')
        Traceback (most recent call last):
        ...
        ModelError: subs: expected a dict {parameter: value} or equations parameter == value, got 'k = 1'
    """
    if isinstance(arg, dict):
        return {SR.var(k) if isinstance(k, str) and k.isidentifier() else k: v
                for k, v in exact_decimals(arg).items()}
    if getattr(arg, 'is_relational', lambda: False)():
        return exact_decimals(arg)
    raise ModelError(f"expected a dict {{parameter: value}} or equations parameter == value, "
                     f"got {brief(arg)}", entry="subs")


def _same(a, b):
    if isinstance(a, tuple):
        return len(a) == len(b) and all(_same(x, y) for x, y in zip(a, b))
    if hasattr(a, 'is_trivially_equal'):
        return a.is_trivially_equal(b)
    return a == b


def _hashable(a):
    if isinstance(a, tuple):
        return tuple(_hashable(x) for x in a)
    return hash(a)


def _rebuild_lagrangian(expr, coordinates, velocities, keywords):
    return Lagrangian(expr, coordinates, velocities, **keywords)

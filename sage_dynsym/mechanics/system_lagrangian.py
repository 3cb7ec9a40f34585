r"""
The energies and the Lagrangian of a mechanical system

A :class:`LagrangianBuilder` builds the Lagrangian of a
:class:`~sage_dynsym.mechanics.system.MechanicalSystem` (which composes one,
see its :meth:`~sage_dynsym.mechanics.system.MechanicalSystem.lagrangian_builder`)
from the system's kinematics, force function, dissipation function,
generalized forces, loads and constraints: the decomposition (4) of the
kinetic energy of each body and of the system, the force function, the
generalized forces, and the Lagrangian with the strategy that forms the
Christoffel coefficients of its equations (5): as polynomials in the sines
and cosines of the angles, from the symbolic mass matrix, or body by body
(see :meth:`LagrangianBuilder.lagrangian`).

EXAMPLES::

    sage: from sage_dynsym import load
    sage: from sage_dynsym.description import example_path
    sage: S = load(example_path('spherical_pendulum.yaml'))
    sage: B = S.lagrangian_builder(); B
    Builder of the Lagrangian of spherical pendulum: 1 body, coordinates (psi, theta)
    sage: B.kinetic_energy()
    1/2*dpsi^2*l^2*m*sin(theta)^2 + 1/2*dtheta^2*l^2*m
"""
from sage.matrix.constructor import matrix
from sage.misc.cachefunc import cached_method
from sage.misc.verbose import verbose
from sage.modules.free_module_element import vector
from sage.structure.sage_object import SageObject
from sage.symbolic.ring import SR

from ..errors import ModelError
from ..symbols import acceleration, t, time_derivative
from ..algebra.trigonometric import TrigPolynomialRing, NotPolynomial, trig_rational_simplify
from ..dynamics.lagrangian import Lagrangian
from ..dynamics.nonholonomic import NonholonomicLagrangian
from ..dynamics.natural_equations import natural_equations
from ..dynamics.natural_form import natural_form
from .force_functions import force_terms, split_force_terms, UniformGravity
from .frames import held_product
from .kinematics import Kinematics

# Above this many terms in the mass matrix, converting the polynomial
# Christoffel coefficients back to symbolic expressions dominates the
# derivation (see bench/bench_chain.py); see lagrangian().
_POLYNOMIAL_CHRISTOFFEL_TERMS = 10000

#: The calculus methods of a mechanical system: how its kinematics and the
#: equations of its Lagrangian are computed (see :meth:`LagrangianBuilder.lagrangian`).
CALCULUS_METHODS = ('auto', 'polynomial', 'symbolic', 'recursive')

__all__ = ['CALCULUS_METHODS', 'check_calculus_method', 'LagrangianBuilder']


def check_calculus_method(method, entry="calculus_method"):
    r"""
    ``method`` if it is one of :data:`CALCULUS_METHODS`, else a
    :class:`~sage_dynsym.errors.ModelError` naming ``entry``.

    EXAMPLES::

        sage: from sage_dynsym.mechanics.system_lagrangian import check_calculus_method
        sage: check_calculus_method('symbolic')
        'symbolic'
        sage: check_calculus_method('sympy')
        Traceback (most recent call last):
        ...
        ModelError: calculus_method: expected one of 'auto', 'polynomial', 'symbolic', 'recursive', got 'sympy'
    """
    if method not in CALCULUS_METHODS:
        raise ModelError(f"expected one of {', '.join(map(repr, CALCULUS_METHODS))}, got "
                         f"{method!r}", entry=entry)
    return method


class LagrangianBuilder(SageObject):
    r"""
    The builder of the Lagrangian of a mechanical system, and of its
    energies (see the module documentation).

    INPUT:

    - ``kinematics`` -- the
      :class:`~sage_dynsym.mechanics.system_kinematics.SystemKinematics` of
      the system
    - ``force_function`` -- (optional) the force function as given to the
      system (a field, an expression, or a list of those)
    - ``dissipation`` -- (default: 0) the Rayleigh function
    - ``forces`` -- (optional) the generalized forces given, one per
      coordinate
    - ``loads`` -- (optional) the checked
      :class:`~sage_dynsym.mechanics.loads.Load` objects
    - ``constraints`` -- (optional) the
      :class:`~sage_dynsym.mechanics.constraint_set.ConstraintSet` of the
      system
    - ``name`` -- (optional) the name of the Lagrangian
    - ``positive`` -- (optional) the parameters declared positive
    - ``calculus_method`` -- (default: ``'auto'``) one of
      :data:`CALCULUS_METHODS`: the default way :meth:`lagrangian` forms
      the equations; with ``'symbolic'`` the kinematics is computed in
      Sage's symbolic ring too, not in the polynomial ring of the sines and
      cosines (:class:`~sage_dynsym.algebra.trigonometric.SymbolicBackend`
      instead of :class:`~sage_dynsym.algebra.trigonometric.TrigPolynomialRing`)

    EXAMPLES::

        sage: from sage_dynsym import RigidBody
        sage: from sage_dynsym.mechanics.system_kinematics import SystemKinematics
        sage: from sage_dynsym.mechanics.system_lagrangian import LagrangianBuilder
        sage: x, m, k = var('x m k')
        sage: K = SystemKinematics([RigidBody('b', joint=[x, 0, 0], mass=m)], [x])
        sage: B = LagrangianBuilder(K, force_function=-k*x^2/2, name='spring'); B
        Builder of the Lagrangian of spring: 1 body, coordinates (x)
        sage: B.lagrangian().lagrange_equations()
        [ddx*m + k*x]
    """

    def __init__(self, kinematics, force_function=None, dissipation=0, forces=None, loads=(),
                 constraints=None, name=None, positive=(), calculus_method='auto'):
        self._kinematics = kinematics
        self._method = check_calculus_method(calculus_method)
        self._coordinates = kinematics.coordinates()
        self._velocities = kinematics.velocities()
        self._terms = force_terms(force_function)
        self._dissipation = SR(dissipation)
        self._forces = ([SR(0)] * len(self._coordinates) if forces is None
                        else [SR(f) for f in forces])
        self._loads = list(loads)
        self._holonomic = [] if constraints is None else constraints.holonomic()
        self._nonholonomic = [] if constraints is None else constraints.nonholonomic()
        self._name = name
        self._positive = list(positive)

    def calculus_method(self):
        r"""
        The calculus method (one of :data:`CALCULUS_METHODS`), see the
        class documentation.

        EXAMPLES::

            sage: from sage_dynsym import RigidBody
            sage: from sage_dynsym.mechanics.system_kinematics import SystemKinematics
            sage: from sage_dynsym.mechanics.system_lagrangian import LagrangianBuilder
            sage: K = SystemKinematics([RigidBody('b', rotations=[(3, var('a'))])], [var('a')])
            sage: LagrangianBuilder(K).calculus_method()
            'auto'
        """
        return self._method

    def _repr_(self):
        n = len(self._kinematics.bodies())
        return (f"Builder of the Lagrangian{' of ' + self._name if self._name else ''}: "
                f"{n} bod{'y' if n == 1 else 'ies'}, coordinates "
                f"({', '.join(map(str, self._coordinates))})")

    @cached_method
    def body_decomposition(self, k):
        r"""
        The decomposition (4) of the kinetic energy of body ``k``:
        `T_k = \tfrac12 \sum A_{ij}\dot q_i\dot q_j + \sum A_i \dot q_i + A_0`.

        Built from the velocity Jacobians: every column of `W_k` is a rotation
        axis in its own frame, every column of `V_{0k}` a sum of
        `e \times r` terms, so each `A_{ij}` involves only the rotations
        between the frames concerned and needs no simplification.

        OUTPUT: a triple ``(A, A1, A0)`` (matrix, vector, expression)

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem, RigidBody
            sage: a, b, m, l = var('a b m l')
            sage: S = MechanicalSystem([RigidBody('b', rotations=[(3, a), (1, b)], mass=m,
            ....:                                 mass_center=[0, 0, l],
            ....:                                 inertia=diagonal_matrix([m*l^2, m*l^2, 0]))],
            ....:                      [a, b])
            sage: A, A1, A0 = S.body_decomposition(1); A
            [l^2*m*sin(b)^2              0]
            [             0          l^2*m]
        """
        self._kinematics.check_index(k)
        kinematics = self._polynomial_kinematics()
        if kinematics is None:
            kinematics, to_symbolic = self._kinematics.symbolic(), trig_rational_simplify
        else:
            to_symbolic = kinematics.backend().simplest_fraction
        A, A1, A0 = kinematics.body_decomposition(k)
        A = matrix(SR, [[to_symbolic(e) for e in row] for row in A])
        A.set_immutable()
        return A, vector(SR, [to_symbolic(e) for e in A1]), to_symbolic(A0)

    @cached_method
    def _polynomial_kinematics(self):
        r"""
        The kinematics over a :class:`~sage_dynsym.algebra.trigonometric.TrigPolynomialRing`
        when the model is polynomial in the sines and cosines of its angles
        and in its parameters (the usual case) and the calculus method is
        not ``'symbolic'``, else ``None``.
        """
        if self._method == 'symbolic':
            return None
        dynamic = self._coordinates + self._velocities + [t]
        data = list(dynamic)
        for body in self._kinematics.bodies():
            for _, angle in body.rotations():
                # the sines and cosines of constant angles may be numbers
                # (sqrt(3)/2 at pi/6: an atom of the ring); rates enter W_k
                data += [SR(angle).cos(), SR(angle).sin(),
                         time_derivative(angle, self._coordinates, self._velocities)]
            data += list(body.joint()) + [time_derivative(c, self._coordinates,
                                                          self._velocities)
                                          for c in body.joint()]
            data += list(body.velocity() or ()) + list(body.mass_center())
            data += [body.mass()] + body.inertia().list()
        try:
            # sines and cosines of every angle, including known functions of
            # time and parameters, are generators: their squares reduce
            ring = TrigPolynomialRing.for_expressions(data, dynamic)
            kinematics = Kinematics(self._kinematics, ring)
            for k in range(1, len(self._kinematics.bodies()) + 1):
                kinematics.body_decomposition(k)
        except NotPolynomial:
            return None
        return kinematics

    @cached_method
    def decomposition(self):
        r"""
        The decomposition (4) of the kinetic energy of the whole system,
        with the force function added to `A_0` (see :meth:`body_decomposition`).

        EXAMPLES::

            sage: from sage_dynsym import load
            sage: from sage_dynsym.description import example_path
            sage: A, A1, A0 = load(example_path('spherical_pendulum.yaml')).decomposition()
            sage: A, A0
            (
            [l^2*m*sin(theta)^2                  0]
            [                 0              l^2*m], -g*l*m*cos(theta)
            )
        """
        data = self._polynomial_decomposition()
        if data is None:
            n = len(self._coordinates)
            parts = [self.body_decomposition(k)
                     for k in range(1, len(self._kinematics.bodies()) + 1)]
            A = sum((p[0] for p in parts), matrix(SR, n, n)).apply_map(trig_rational_simplify)
            A1 = sum((p[1] for p in parts), vector(SR, n)).apply_map(trig_rational_simplify)
            A0 = trig_rational_simplify(sum((p[2] for p in parts), SR(0))) + self.force_function()
        else:
            # the shortest of the reduced forms (entries of a big mass matrix
            # just get the canonical recursive form, see simplest_fraction)
            to_symbolic = data[0].ring.simplest_fraction
            n = len(data[1])
            A = matrix(SR, n, n)
            for i in range(n):
                verbose(f"mass matrix row {i + 1} of {n}", level=1)
                for j in range(i, n):
                    A[i, j] = A[j, i] = to_symbolic(data[1][i][j])
            A1 = vector(SR, [to_symbolic(e) for e in data[2]])
            A0 = to_symbolic(data[3]) + self.force_function()
        A.set_immutable()
        return A, A1, A0

    @cached_method
    def _polynomial_decomposition(self):
        r"""
        ``(calculus, A, A1, T0)`` of the kinetic energy of the whole system
        in the polynomial ring of :meth:`_polynomial_kinematics`, or ``None``
        when the model is not polynomial there. (The force function stays
        symbolic: it may hold any expression, e.g. `1/r^3`.)
        """
        kinematics = self._polynomial_kinematics()
        if kinematics is None:
            return None
        try:
            calculus = kinematics.backend().calculus(self._coordinates)
        except NotPolynomial:
            return None
        # sum the polynomials first: contributions of the bodies combine
        n = len(self._coordinates)
        parts = [kinematics.body_decomposition(k)
                 for k in range(1, len(self._kinematics.bodies()) + 1)]
        zero, reduce = calculus.zero, kinematics.backend().reduce
        A = [[None] * n for _ in range(n)]
        for i in range(n):
            for j in range(i, n):
                A[i][j] = A[j][i] = reduce(sum((p[0][i][j] for p in parts), zero))
        A1 = [reduce(sum((p[1][i] for p in parts), zero)) for i in range(n)]
        T0 = reduce(sum((p[2] for p in parts), zero))
        return calculus, A, A1, T0

    @cached_method
    def kinetic_energy(self, k=None):
        r"""
        The kinetic energy (1): of body ``k``, or of the whole system.

        `T_k = \tfrac12 m_k V_{0k}^2 + \tfrac12 W_k\cdot\Theta^k W_k
        + m_k (V_{0k}\times W_k)\cdot r^k_{ck}`.

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem, RigidBody
            sage: x, m = var('x m')
            sage: MechanicalSystem([RigidBody('b', joint=[x, 0, 0], mass=m)], [x]).kinetic_energy()
            1/2*dx^2*m
        """
        if k is None:
            A, A1, A0 = self.decomposition()
            A0 -= self.force_function()
        else:
            self._kinematics.check_index(k)
            A, A1, A0 = self.body_decomposition(k)
        return natural_form(A, A1, A0, self._velocities)

    @cached_method
    def force_function(self):
        r"""
        The force function `U` (minus the potential energy) of the field
        given at construction (0 if none).

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem
            sage: x = var('x')
            sage: MechanicalSystem([], [x], force_function=-x^2/2).force_function()
            -1/2*x^2
        """
        terms = self._terms
        if len(terms) == 1 and not hasattr(terms[0], 'evaluate'):
            return SR(terms[0])
        total = SR(0)
        for term in terms:
            total += (term.evaluate(self._kinematics).expand() if hasattr(term, 'evaluate')
                      else SR(term))
        return trig_rational_simplify(total) if terms else total

    @cached_method
    def generalized_forces(self):
        r"""
        The generalized non-potential forces `Q_i`: those given plus those
        of the loads (see :mod:`~sage_dynsym.mechanics.loads` for the sign
        convention).

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem, RigidBody
            sage: x, F = var('x F')
            sage: S = MechanicalSystem([RigidBody('b', joint=[x, 0, 0])], [x], forces=[1],
            ....:                      loads=[{'body': 'b', 'force': [F, 0, 0]}])
            sage: S.lagrangian_builder().generalized_forces()
            [F + 1]
        """
        forces = list(self._forces)
        for i, load in enumerate(self._loads):
            forces = [a + b for a, b in
                      zip(forces, load.generalized_forces(self._kinematics, f"loads[{i}]"))]
        return forces

    @cached_method
    def lagrangian(self, christoffel=None):
        r"""
        The Lagrangian `L = T + U`, with the system's dissipation function and
        generalized forces.

        INPUT:

        - ``christoffel`` -- how the equations (5) of the Lagrangian get their
          Christoffel coefficients `\Gamma_{i,rj}` (see
          :mod:`~sage_dynsym.dynamics.natural_equations`):

          - ``'polynomial'`` -- combine the three derivatives of the mass
            matrix as polynomials in the sines and cosines, where they
            cancel, and convert each coefficient to its canonical recursive
            form: the most compact equations, but the conversion back to
            symbolic expressions costs time in proportion to the number of
            terms (minutes for the chain of 6 spatial links of
            ``bench/bench_chain.py``, which prints the times);
          - ``'symbolic'`` -- differentiate the (already compact) symbolic
            mass matrix: fast even for large systems, but the equations are
            larger, about 1.4 times, since the three derivatives do not
            cancel;
          - ``'recursive'`` -- assemble the equations body by body
            (Newton--Euler recursion, see
            :meth:`~sage_dynsym.mechanics.kinematics.Kinematics.recursive_equations`):
            the mass matrix times the accelerations plus nested terms in the
            velocities, never expanded; the fastest and, for long chains of
            bodies, the shortest form (for the spatial chain of 6 links of
            ``bench/bench_chain.py``: a quarter of the ``'symbolic'`` one, in
            a fraction of a second); needs bodies of constant mass, mass
            centre and inertia (prescribed relative velocities linear in the
            velocities, as the kinetic energy (4) needs, are taken into
            account), else ``'symbolic'`` is used;
          - ``'auto'`` (default) -- ``'polynomial'`` unless some body lies
            more than 8 elementary rotations away from the inertial frame or
            the mass matrix has more than 10,000 polynomial terms (for the
            spatial chains of ``bench/``: up to 4 links), then
            ``'recursive'``.

          - ``None`` (default) -- the calculus method of the builder (of
            the system: see :meth:`calculus_method`).

          Models that are not polynomial in the sines and cosines of their
          angles use ``'symbolic'`` instead of ``'polynomial'``.

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem, RigidBody
            sage: x, m, k, c = var('x m k c')
            sage: S = MechanicalSystem([RigidBody('b', joint=[x, 0, 0], mass=m)], [x],
            ....:                      force_function=-k*x^2/2, dissipation=c*var('dx')^2/2)
            sage: S.lagrangian().lagrange_equations()
            [c*dx + ddx*m + k*x]

        Both ways of forming the Christoffel coefficients give the equations
        (9) of the spherical pendulum of Example 1, multiplied by
        `m l^2 \sin^2\theta` and `m l`:
        `\ddot\psi + 2\cot\theta\,\dot\theta\dot\psi = 0` and
        `l\ddot\theta - l\cos\theta\sin\theta\,\dot\psi^2
        - g\sin\theta = 0`::

            sage: from sage_dynsym import load
            sage: from sage_dynsym.description import example_path
            sage: S = load(example_path('spherical_pendulum.yaml'))
            sage: E = S.lagrangian('polynomial').lagrange_equations(); E
            [2*dpsi*dtheta*l^2*m*cos(theta)*sin(theta) + ddpsi*l^2*m*sin(theta)^2,
             -dpsi^2*l^2*m*cos(theta)*sin(theta) + ddtheta*l^2*m - g*l*m*sin(theta)]
            sage: S.lagrangian('symbolic').lagrange_equations() == E
            True
            sage: S.lagrangian('recursive').lagrange_equations() == E
            True

        TESTS::

            sage: S.lagrangian('fast')
            Traceback (most recent call last):
            ...
            ModelError: christoffel: expected one of 'auto', 'polynomial', 'symbolic', 'recursive', got 'fast'

        A chain of 9 planar links takes the recursive form (compared with
        the other forms in ``tests/test_compact_equations.py``), and so does a
        body with a prescribed relative velocity (here the kinetic energy
        `2 m\dot x^2`; more in ``tests/test_one_recursion.py``)::

            sage: a = [var(f'a{k}') for k in range(1, 10)]
            sage: links = [RigidBody(f'b{k}', parent=k - 1, rotations=[(3, a[k - 1])],
            ....:                    joint=[1 if k > 1 else 0, 0, 0], mass_center=[1/2, 0, 0],
            ....:                    mass=1) for k in range(1, 10)]
            sage: S = MechanicalSystem(links, a)
            sage: S.lagrangian().lagrange_equations() == S.lagrangian('recursive').lagrange_equations()
            True
            sage: x, m = var('x m')
            sage: b = RigidBody('b', joint=[x, 0, 0], velocity=[2*var('dx'), 0, 0], mass=m)
            sage: MechanicalSystem([b], [x]).lagrangian('recursive').lagrange_equations()
            [4*ddx*m]
        """
        christoffel = (self._method if christoffel is None
                       else check_calculus_method(christoffel, entry="christoffel"))
        kinematics, bodies = self._kinematics.symbolic(), self._kinematics.bodies()
        if christoffel == 'recursive' and not kinematics.recursive_applies():
            christoffel = 'symbolic'
        if christoffel == 'auto':
            # deep bodies: the polynomial forms grow faster than the nested
            # ones, and even computing them costs seconds (bench/bench_chain.py)
            depth = max((len(kinematics.tree.path_to_root(kinematics.body_frame(k))) - 1
                         for k in range(1, len(bodies) + 1)), default=0)
            if depth > 8 and kinematics.recursive_applies():
                christoffel = 'recursive'
        data = None if christoffel == 'recursive' else self._polynomial_decomposition()
        if data is not None and christoffel == 'auto':
            terms = sum(e.number_of_terms() for i, row in enumerate(data[1]) for e in row[i:])
            christoffel = ('polynomial' if terms <= _POLYNOMIAL_CHRISTOFFEL_TERMS else
                           'recursive' if kinematics.recursive_applies() else 'symbolic')
        if christoffel == 'recursive':
            # gravity enters the recursion; only the other terms, not
            # expanded, are differentiated (nothing of the size of the tree is)
            gravity, rest = split_force_terms(self._terms, self._kinematics)
            A, A1, T0, h = kinematics.recursive_equations(gravity)
            ddq = [acceleration(q) for q in self._coordinates]
            U = rest + sum((term.evaluate(self._kinematics) for term in self._terms
                            if isinstance(term, UniformGravity)), SR(0))

            def recursive_equations():
                return [SR(0).add(*[held_product(a, x) for a, x in zip(row, ddq)
                                    if not a.is_trivial_zero()])
                        + e - rest.diff(q) for row, e, q in zip(A, h, self._coordinates)]
            A = matrix(SR, A)
            A.set_immutable()
            decomposition = (A, vector(SR, A1), T0 + U)
            builder = recursive_equations
        else:
            U = self.force_function()
            decomposition = self.decomposition()

        def ring_equations():
            kinetic = natural_equations(data[1], data[2], data[3], self._coordinates,
                                        self._velocities,
                                        [acceleration(q) for q in self._coordinates], data[0],
                                        mass_matrix=self.decomposition()[0])
            return [e - U.diff(q) for e, q in zip(kinetic, self._coordinates)]

        if christoffel != 'recursive':
            use_ring = data is not None and christoffel == 'polynomial'
            builder = ring_equations if use_ring else None
        options = dict(decomposition=decomposition, dissipation=self._dissipation,
                       forces=self.generalized_forces(), name=self._name,
                       equation_builder=builder, constraints=self._holonomic,
                       positive=self._positive)
        if self._nonholonomic:
            return NonholonomicLagrangian(None, self._coordinates, self._velocities,
                                          nonholonomic=self._nonholonomic, **options)
        return Lagrangian(None, self._coordinates, self._velocities, **options)

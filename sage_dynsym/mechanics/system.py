r"""
Mechanical systems of rigid bodies

A :class:`MechanicalSystem` is the *description* of a system of rigid bodies
(see :doc:`the method </method>`): its bodies, generalized coordinates,
parameters, force function and non-potential forces. From it the kinematics
(direction cosines, angular velocities, joint velocities), the kinetic
energy (1), the force function ((2) or (3)) and the Lagrangian (4) are
derived; the Lagrangian object then gives the Lagrange, Routh and Hamilton
equations.

The system holds its description and is composed of objects with public
interfaces, each built from explicit data: its
:class:`~sage_dynsym.mechanics.system_kinematics.SystemKinematics` (the
bodies, parents first, with the coordinates: what loads, force fields and
rolling disks receive; :meth:`MechanicalSystem.kinematics`), its
:class:`~sage_dynsym.mechanics.constraint_set.ConstraintSet`
(:meth:`MechanicalSystem.constraint_set`), the
:class:`~sage_dynsym.mechanics.system_checks.PhysicalConditions` of its data
(:meth:`MechanicalSystem.conditions`) and the
:class:`~sage_dynsym.mechanics.system_lagrangian.LagrangianBuilder` of its
energies and Lagrangian (:meth:`MechanicalSystem.lagrangian_builder`); the
methods of the same names on the system delegate to them. The description
format (:mod:`~sage_dynsym.mechanics.format`) and the numerics
(:mod:`~sage_dynsym.mechanics.system_numerics`) are base classes that use
only the public methods.

EXAMPLES:

Example 1 of :doc:`the method </method>`, the spherical pendulum::

    sage: from sage_dynsym import MechanicalSystem, RigidBody, UniformGravity
    sage: psi, theta, m, l, g = var('psi theta m l g')
    sage: pendulum = RigidBody('pendulum', rotations=[(3, psi), (1, theta)],
    ....:                      mass_center=[0, 0, l], mass=m,
    ....:                      inertia=diagonal_matrix([m*l^2, m*l^2, 0]))
    sage: S = MechanicalSystem([pendulum], [psi, theta], parameters=[m, l, g],
    ....:                      force_function=UniformGravity([0, 0, -g]),
    ....:                      name="spherical pendulum"); S
    Mechanical system 'spherical pendulum': 1 body, coordinates (psi, theta)
    sage: S.angular_velocity(1)
    (dtheta, dpsi*sin(theta), dpsi*cos(theta))
    sage: S.kinetic_energy()
    1/2*dpsi^2*l^2*m*sin(theta)^2 + 1/2*dtheta^2*l^2*m
    sage: S.force_function()
    -g*l*m*cos(theta)
    sage: L = S.lagrangian()
    sage: bool(2*L.expr() == m*l^2*(sin(theta)^2*var('dpsi')^2 + var('dtheta')^2)
    ....:                    - 2*m*g*l*cos(theta))
    True

TESTS:

The checks of the construction::

    sage: from sage_dynsym import MechanicalSystem, RigidBody
    sage: m = var('m')
    sage: MechanicalSystem([RigidBody('arm', parent='nothing')], [])
    Traceback (most recent call last):
    ...
    ModelError: bodies[0].parent: unknown parent body 'nothing'; known bodies are: arm
    sage: MechanicalSystem([RigidBody('p', parent='q'), RigidBody('q', parent='p')], [])
    Traceback (most recent call last):
    ...
    ModelError: bodies: the parents form a cycle: p -> q -> p
    sage: MechanicalSystem([RigidBody('p', parent=2)], [])
    Traceback (most recent call last):
    ...
    ModelError: bodies[0].parent: body index 2 out of range 1..1
    sage: MechanicalSystem([RigidBody('p', mass=m), RigidBody('p')], [])
    Traceback (most recent call last):
    ...
    ModelError: bodies[1].name: duplicate body name 'p'
    sage: MechanicalSystem([RigidBody('p', mass=m*var('k'))], [], parameters=[m])
    Traceback (most recent call last):
    ...
    ModelError: p.mass: undeclared symbol k; declared are: m, t

Names that clash with the package's own symbols, and force functions
that depend on velocities, are refused::

    sage: x = var('x')
    sage: MechanicalSystem([RigidBody('p', mass=m)], [x], parameters=[var('dx')])
    Traceback (most recent call last):
    ...
    ModelError: parameters[0]: the name 'dx' is the velocity of the coordinate 'x' (coordinates[0]); choose another name
    sage: MechanicalSystem([RigidBody('p', mass=m)], [x], force_function=var('dx')^2)
    Traceback (most recent call last):
    ...
    ModelError: force_function: the force function U(q, t) cannot depend on the velocity dx; velocity-dependent forces belong in the dissipation function or the generalized forces

Several force-function terms are added together (gravity and a
spring)::

    sage: from sage_dynsym import UniformGravity
    sage: z, k, g = var('z k g')
    sage: S = MechanicalSystem([RigidBody('p', joint=[0, 0, z], mass=m)], [z],
    ....:                      force_function=[UniformGravity([0, 0, -g]), -k*z^2/2])
    sage: S.force_function()
    -g*m*z - 1/2*k*z^2

Loads on unknown bodies, and constraints that are not holonomic
relations between the coordinates, are refused::

    sage: MechanicalSystem([RigidBody('p', mass=m)], [z], loads=[{'body': 'q', 'force': [1, 0, 0]}])
    Traceback (most recent call last):
    ...
    ModelError: loads[0].body: unknown body 'q'; known bodies are: p
    sage: MechanicalSystem([RigidBody('p', mass=m)], [z], constraints=[k - 1])
    Traceback (most recent call last):
    ...
    ModelError: constraints[0]: the constraint k - 1 == 0 does not depend on the coordinates z
    sage: MechanicalSystem([RigidBody('p', mass=m)], [z], constraints=[z - var('dz')])
    Traceback (most recent call last):
    ...
    ModelError: constraints[0]: a holonomic constraint f(q, t) cannot depend on the velocity dz
"""
from sage.misc.cachefunc import cached_method
from sage.symbolic.ring import SR

from ..errors import ModelError
from ..symbols import momentum, t, check_mechanical_names, exact_decimals
from ..arguments import symbol_arguments
from ..dynamics.holonomic import check_constraints
from ..dynamics.model import Model
from ..numerics.methods import object_cache
from ..numerics.values import check_model_values
from .force_functions import check_force_function, force_terms
from .constraint_set import ConstraintSet
from .format import MechanicalFormat
from .loads import load_list
from .operating_points import checked_operating_points
from .report import report_title, report_sections
from .system_checks import check_declared_symbols, checked_load, PhysicalConditions
from .system_kinematics import SystemKinematics
from .system_lagrangian import LagrangianBuilder
from .system_numerics import MechanicalNumerics

__all__ = ['MechanicalSystem', 'check_constraints', 'DelegatedMethod']


class DelegatedMethod:
    r"""
    A method of a system that is a method of one of its composed objects:
    in the body of a class, ``angular_velocity = DelegatedMethod('kinematics',
    SystemKinematics)`` makes ``S.angular_velocity`` the bound method
    ``S.kinematics().angular_velocity`` (so its documentation and examples
    are those of :meth:`SystemKinematics.angular_velocity
    <sage_dynsym.mechanics.system_kinematics.SystemKinematics.angular_velocity>`).

    INPUT:

    - ``part`` -- the name of the system's method that gives the composed
      object
    - ``cls`` -- the class of the composed object (what the class attribute
      documents)
    - ``target`` -- (default: the attribute's own name) the name of the
      method of the composed object

    EXAMPLES::

        sage: from sage_dynsym import MechanicalSystem, RigidBody
        sage: from sage_dynsym.mechanics.system_kinematics import SystemKinematics
        sage: a = var('a')
        sage: S = MechanicalSystem([RigidBody('b', rotations=[(3, a)])], [a])
        sage: S.angular_velocity(1), S.angular_velocity == S.kinematics().angular_velocity
        ((0, 0, da), True)
        sage: MechanicalSystem.angular_velocity is SystemKinematics.angular_velocity
        True
        sage: MechanicalSystem.__dict__['constraints']
        Method holonomic of the constraint_set() of the object
    """

    def __init__(self, part, cls, target=None):
        self._part, self._class, self._target = part, cls, target

    def __set_name__(self, owner, name):
        if self._target is None:
            self._target = name

    def __repr__(self):
        return f"Method {self._target} of the {self._part}() of the object"

    def __get__(self, obj, owner=None):
        if obj is None:
            return getattr(self._class, self._target)
        return getattr(getattr(obj, self._part)(), self._target)


class MechanicalSystem(MechanicalFormat, MechanicalNumerics, Model):
    r"""
    A system of rigid bodies.

    INPUT:

    - ``bodies`` -- list of :class:`~sage_dynsym.mechanics.rigid_body.RigidBody`
      (any order: parents are resolved by name, index or object)
    - ``coordinates`` -- list of symbolic variables, the generalized
      coordinates
    - ``parameters`` -- (optional) list of the symbolic parameters; when
      given, every symbol of the model must be a coordinate, a velocity
      ``d<q>``, a parameter or ``t``
    - ``force_function`` -- (optional)
      :class:`~sage_dynsym.mechanics.force_functions.UniformGravity`,
      :class:`~sage_dynsym.mechanics.force_functions.NewtonianField`, any
      expression `U(q, t)`, or a list of those (terms added together)
    - ``dissipation`` -- (default: 0) Rayleigh function `R(q, \dot q)`
    - ``forces`` -- (optional) generalized forces, one per coordinate
    - ``loads`` -- (optional) list of
      :class:`~sage_dynsym.mechanics.loads.Load` (or dictionaries with its
      keywords): forces at body points and torques, turned into generalized
      forces by virtual power and added to ``forces``
    - ``constraints`` -- (optional) list of holonomic constraints `f(q, t)`
      (each meaning `f = 0`), passed on to the Lagrangian (Lagrange
      equations of the first kind, one multiplier per constraint)
    - ``nonholonomic`` -- (optional) list of constraints on the velocities,
      linear in them (each meaning `= 0`); the Lagrangian is then a
      :class:`~sage_dynsym.dynamics.nonholonomic.NonholonomicLagrangian`
    - ``rolling`` -- (optional) list of
      :class:`~sage_dynsym.mechanics.rolling.RollingDisk` (or dicts with
      the keys ``body``, ``radius``, ``axle``): thin disks rolling without
      slipping on the plane `z = 0`, see :mod:`~sage_dynsym.mechanics.rolling`
    - ``operating_points`` -- (optional) dict ``{name: point}`` of steady
      motions (see :mod:`~sage_dynsym.mechanics.operating_points`)
    - ``name`` -- (optional) a name
    - ``positive`` -- (optional) parameters known to be positive; the
      analysis (stationary motions and their stability in reports) assumes
      no other sign
    - ``calculus_method`` -- (default: ``'auto'``) how the kinematics and
      the equations are computed: ``'polynomial'``, ``'symbolic'``,
      ``'recursive'`` or ``'auto'`` (see :meth:`set_calculus_method`)

    EXAMPLES::

        sage: from sage_dynsym import MechanicalSystem, RigidBody
        sage: a, b, m = var('a b m')
        sage: base = RigidBody('base', rotations=[(3, a)])
        sage: arm = RigidBody('arm', parent='base', rotations=[(1, b)], mass=m,
        ....:                 mass_center=[0, 1, 0])
        sage: S = MechanicalSystem([arm, base], [a, b]); S.bodies()
        [Rigid body 'base' (parent 0, rotations [(3, a)], mass 0),
         Rigid body 'arm' (parent base, rotations [(1, b)], mass m)]

    TESTS: its description reads back, its positive parameters are its
    parameters, and its conserved energy is an integral of its equations::

        sage: TestSuite(S).run()
    """

    def __init__(self, bodies, coordinates, parameters=None, force_function=None,
                 dissipation=0, forces=None, name=None, positive=(), loads=(), constraints=(),
                 nonholonomic=(), rolling=(), operating_points=None, calculus_method='auto'):
        self._kinematics = kinematics = SystemKinematics(bodies, coordinates)
        q = kinematics.coordinates()
        self._parameters = None if parameters is None else [SR(p) for p in parameters]
        check_mechanical_names(q, self._parameters or (), ModelError)
        check_force_function(force_function, q)
        if isinstance(force_function, (list, tuple)):
            force_function = list(force_function)
        self._force = force_function
        self._dissipation = SR(dissipation)
        self._forces = [SR(0)] * len(q) if forces is None else [SR(f) for f in forces]
        if len(self._forces) != len(q):
            raise ModelError(f"expected {len(q)} generalized forces, one per coordinate, got "
                             f"{len(self._forces)}", entry="forces")
        self._name = name
        self._positive = symbol_arguments(positive, 'positive')
        if self._parameters is not None:
            check_declared_symbols(kinematics, self._parameters, self._dissipation,
                                   self._forces, self._force)
            names = {str(p) for p in self._parameters}
            for p in self._positive:
                if str(p) not in names:
                    raise ModelError(f"{p} is not a declared parameter", entry="positive")
        self._loads = [checked_load(load, f"loads[{i}]", kinematics, self._parameters)
                       for i, load in enumerate(load_list(loads))]
        self._constraint_set = ConstraintSet(
            kinematics, check_constraints(constraints, q, self._parameters), nonholonomic,
            rolling, self._parameters)
        self._operating_points = checked_operating_points(
            operating_points, q, kinematics.velocities(), self._parameters)
        self._physical = PhysicalConditions(kinematics, self._positive,
                                            self._constraint_set.rolling(), self.force_terms())
        self._builder = self._lagrangian_builder(calculus_method)

    def _lagrangian_builder(self, calculus_method):
        return LagrangianBuilder(self._kinematics, self._force, self._dissipation, self._forces,
                                 self._loads, self._constraint_set, self._name, self._positive,
                                 calculus_method=calculus_method)

    # ------------------------------------------------------------------
    # the model interface

    kind = 'mechanical'


    def equations(self):
        r"""
        The equations of motion: the Lagrange equations of :meth:`lagrangian`.

        EXAMPLES::

            sage: from sage_dynsym import load
            sage: from sage_dynsym.description import example_path
            sage: load(example_path('spherical_pendulum.yaml')).equations()[1]
            -dpsi^2*l^2*m*cos(theta)*sin(theta) + ddtheta*l^2*m - g*l*m*sin(theta)
        """
        return self.lagrangian().lagrange_equations()

    def characteristic_functions(self):
        r"""
        The characteristic functions of the system: its Lagrangian and
        Hamiltonian (builders of no argument).

        EXAMPLES::

            sage: from sage_dynsym import load
            sage: from sage_dynsym.description import example_path
            sage: S = load(example_path('spherical_pendulum.yaml'))
            sage: S.characteristic_functions()['hamiltonian']().expr()
            g*l*m*cos(theta) + 1/2*p_theta^2/(l^2*m) + 1/2*p_psi^2/(l^2*m*sin(theta)^2)
        """
        return {'lagrangian': self.lagrangian,
                'hamiltonian': lambda: self.lagrangian().hamiltonian()}

    def equation_forms(self):
        r"""
        The forms of the system's equations: Lagrange, Routh and Hamilton
        (see :mod:`~sage_dynsym.dynamics.derivations`).

        EXAMPLES::

            sage: from sage_dynsym import load
            sage: from sage_dynsym.description import example_path
            sage: S = load(example_path('spherical_pendulum.yaml'))
            sage: S.equation_forms()['Hamilton']().equations[0]
            ('\\dot{\\psi}', p_psi/(l^2*m*sin(theta)^2))
        """
        from ..dynamics.derivations import lagrangian_forms
        return lagrangian_forms(self.lagrangian)

    def subs(self, values):
        r"""
        The system with parameter values substituted: in the bodies, the
        force-function terms, the loads, the dissipation function, the
        generalized forces and the constraints. The substituted parameters
        leave :meth:`parameters` and the ``positive`` list.

        INPUT:

        - ``values`` -- a dictionary ``{parameter: value}`` (keys symbols or
          names); values exact numbers (rationals, radicals, ``cos(pi/10)``),
          expressions, or floating-point numbers, each taken as the exact
          decimal it prints as (``9.81`` is `981/100`: see
          :func:`~sage_dynsym.symbols.exact_decimals`)

        EXAMPLES::

            sage: from sage_dynsym import load
            sage: from sage_dynsym.description import example_path
            sage: S = load(example_path('spherical_pendulum.yaml'))
            sage: m, l, g = var('m l g')
            sage: S1 = S.subs({m: 1, l: 2, 'g': 9.81}); S1.parameters()
            []
            sage: S1.lagrangian().lagrange_equations()[1]
            -4*dpsi^2*cos(theta)*sin(theta) + 4*ddtheta - 981/50*sin(theta)

        TESTS::

            sage: S.subs({var('theta'): 0})
            Traceback (most recent call last):
            ...
            ModelError: subs: cannot substitute for theta, a coordinate, velocity or t
            sage: S.subs({'k': 1})
            Traceback (most recent call last):
            ...
            ModelError: subs: k is not a parameter of the system; its parameters are: m, l, g
            sage: S.subs({'g': -9.81})
            Traceback (most recent call last):
            ...
            ModelError: subs: g is declared positive, got -981/100
        """
        if not isinstance(values, dict):
            raise ModelError(f"expected a dictionary {{parameter: value}}, got {values!r}",
                             entry="subs")
        values = exact_decimals(values)
        check_model_values(self, values, entry="subs")
        K = self._kinematics
        protected = set(K.coordinates()) | set(K.velocities()) | {t}
        protected |= set(K.accelerations()) | {momentum(q) for q in K.coordinates()}
        substitution = {}
        for key, value in values.items():
            symbol = SR.var(key) if isinstance(key, str) else SR(key)
            if not symbol.is_symbol() or symbol in protected:
                raise ModelError(f"cannot substitute for {symbol}, a coordinate, velocity or t",
                                 entry="subs")
            if self._parameters is not None and symbol not in self._parameters:
                raise ModelError(f"{symbol} is not a parameter of the system; its parameters "
                                 f"are: {', '.join(map(str, self._parameters)) or '(none)'}",
                                 entry="subs")
            substitution[symbol] = SR(exact_decimals(value))

        def sub(e):
            return SR(e).subs(substitution)

        terms = [term.subs(substitution) if hasattr(term, 'evaluate') else sub(term)
                 for term in self.force_terms()]
        force = terms if isinstance(self._force, list) else (terms[0] if terms else None)
        kept = [p for p in self._parameters if p not in substitution] \
            if self._parameters is not None else None
        bodies = [b.subs(substitution, parent=K.bodies()[K.parent_index(k) - 1].name()
                         if K.parent_index(k) else 0)
                  for k, b in enumerate(K.bodies(), 1)]
        return MechanicalSystem(bodies, K.coordinates(), calculus_method=self.calculus_method(),
                                parameters=kept, force_function=force,
                                dissipation=sub(self._dissipation),
                                forces=[sub(f) for f in self._forces], name=self._name,
                                positive=[p for p in self._positive if p not in substitution],
                                loads=[load.subs(substitution) for load in self._loads],
                                constraints=[sub(f) for f in
                                             self._constraint_set.given_holonomic()],
                                nonholonomic=[sub(g) for g in
                                              self._constraint_set.given_nonholonomic()],
                                rolling=[disk.subs(substitution)
                                         for disk in self._constraint_set.rolling()],
                                operating_points={name: point.subs(substitution) for name, point
                                                  in self._operating_points.items()})

    def euler_poisson(self, names=None):
        r"""
        The Euler--Poisson system of a heavy body with a fixed point: the
        angular momentum and the vertical in the body's axes on e(3), see
        :func:`~sage_dynsym.lie.builders.euler_poisson`.

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem, RigidBody, UniformGravity
            sage: psi, theta, phi, A, C, m, g, l = var('psi theta phi A C m g l')
            sage: top = RigidBody('top', rotations=[(3, psi), (1, theta), (3, phi)],
            ....:                 mass_center=[0, 0, l], mass=m, inertia=diagonal_matrix([A, A, C]))
            sage: S = MechanicalSystem([top], [psi, theta, phi], force_function=UniformGravity([0, 0, -g]))
            sage: S.euler_poisson().hamiltonian()
            g*gamma3*l*m + 1/2*M1^2/A + 1/2*M2^2/A + 1/2*M3^2/C
        """
        from ..lie.builders import euler_poisson
        return euler_poisson(self, names)

    # ------------------------------------------------------------------
    # the system's data

    def _repr_(self):
        n = len(self._kinematics.bodies())
        name = f" {self._name!r}" if self._name else ""
        return (f"Mechanical system{name}: {n} bod{'y' if n == 1 else 'ies'}, coordinates "
                f"({', '.join(map(str, self._kinematics.coordinates()))})")

    def name(self):
        r"""
        The system's name (or ``None``).

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem
            sage: MechanicalSystem([], [], name="empty").name()
            'empty'
        """
        return self._name

    def parameters(self):
        r"""
        The declared parameters (``None`` if not declared).

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem
            sage: MechanicalSystem([], [], parameters=[var('m')]).parameters()
            [m]
        """
        return None if self._parameters is None else list(self._parameters)

    def force_terms(self):
        r"""
        The terms of the force function (a list, empty if none): fields
        (:class:`~sage_dynsym.mechanics.force_functions.UniformGravity`,
        :class:`~sage_dynsym.mechanics.force_functions.NewtonianField`) and
        expressions `U(q, t)`, added together in :meth:`force_function`.

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem, UniformGravity
            sage: x, k = var('x k')
            sage: MechanicalSystem([], [x], force_function=[UniformGravity([0, 0, -1]),
            ....:                                            -k*x^2/2]).force_terms()
            [uniform gravity field g = (0, 0, -1), -1/2*k*x^2]
            sage: MechanicalSystem([], [x], force_function=-k*x^2/2).force_terms()
            [-1/2*k*x^2]
        """
        return force_terms(self._force)

    def conditions(self):
        r"""
        The conditions on the parameters for the model to be physical that
        its data and its declared signs leave open: masses and moments of
        inertia non-negative, the moments of inertia satisfying the
        triangle inequality, the radii of rolling disks positive (see
        :mod:`~sage_dynsym.mechanics.system_checks`), and those of its
        force fields (the direction of a Newtonian field with symbolic
        direction cosines a unit vector, its distance positive; see
        :meth:`~sage_dynsym.mechanics.force_functions.NewtonianField.conditions`).
        Values given to :meth:`simulate` and :meth:`numerical_rhs` must
        satisfy them.

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem, RigidBody, NewtonianField
            sage: phi, nu, r, e1, e2 = var('phi nu r e1 e2')
            sage: S = MechanicalSystem([RigidBody('b', rotations=[(3, phi)], mass=1)], [phi],
            ....:                      force_function=NewtonianField(nu, r, [e1, e2, 0]))
            sage: S.conditions()
            [e1^2 + e2^2 == 1, r > 0]

        What the declared signs decide is not a condition; what they
        contradict is refused (see
        :class:`~sage_dynsym.mechanics.system_checks.PhysicalConditions`).
        """
        return self._physical.conditions()

    def report_title(self):
        r"""The heading of the system's report (see :mod:`~sage_dynsym.mechanics.report`).

        EXAMPLES::

            sage: from sage_dynsym import load
            sage: from sage_dynsym.description import example_path
            sage: load(example_path('spherical_pendulum.yaml')).report_title()
            '== spherical pendulum (mechanical system: 1 body, coordinates psi, theta) =='
        """
        return report_title(self)

    def report_sections(self):
        r"""The sections of the system's report (see
        :mod:`~sage_dynsym.mechanics.report`).

        EXAMPLES::

            sage: from sage_dynsym import load
            sage: from sage_dynsym.description import example_path
            sage: [s.name for s in load(example_path('spherical_pendulum.yaml')).report_sections()][1:4]
            ['Lagrangian', 'Constraints', 'Lagrange equations']
        """
        return report_sections(self)

    def free_linear_system(self, at=None):
        r"""
        The Lagrangian (dissipation included) linearized around the
        coordinates ``at`` (a dict; by default all coordinates 0), at rest:
        what :func:`~sage_dynsym.scale.maps.stability_map` maps.

        EXAMPLES: a damped cart pendulum around its lower equilibrium::

            sage: from sage_dynsym import load
            sage: from sage_dynsym.description import example_path
            sage: S = load(example_path('cart_pendulum_spring_damper.yaml'))
            sage: S.free_linear_system().order(), S.free_linear_system().variables()
            (2, [y, theta])
        """
        from ..analysis import linearize
        from ..dynamics.model import linearization_point
        L = self.lagrangian()
        return linearize(L, linearization_point(at, L.coordinates(), "coordinate"))

    def loads(self):
        r"""
        The loads on the bodies (:class:`~sage_dynsym.mechanics.loads.Load`;
        body references by name).

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem, RigidBody
            sage: x = var('x')
            sage: MechanicalSystem([RigidBody('b', joint=[x, 0, 0])], [x],
            ....:                  loads=[{'body': 1, 'force': [1, 0, 0]}]).loads()
            [Load on 'b' at (0, 0, 0): force (1, 0, 0), in the inertial axes]
        """
        return list(self._loads)

    def equations_record(self):
        r"""
        The equations as neutral data for the analysis: those of
        :meth:`lagrangian`.

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem, RigidBody
            sage: x, m = var('x m')
            sage: MechanicalSystem([RigidBody('b', joint=[x, 0, 0], mass=m)], [x]).equations_record()
            Second-order equations in (x): [ddx*m] == 0
        """
        return self.lagrangian().equations_record()

    def force_field(self):
        r"""
        The force-function description given at construction (a list when
        several terms were given, see :meth:`force_terms`).

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem, UniformGravity
            sage: MechanicalSystem([], [], force_function=UniformGravity([0, 0, -1])).force_field()
            uniform gravity field g = (0, 0, -1)
        """
        return self._force

    def dissipation(self):
        r"""
        The Rayleigh dissipation function.

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem
            sage: x, dx = var('x dx')
            sage: MechanicalSystem([], [x], dissipation=dx^2).dissipation()
            dx^2
        """
        return self._dissipation

    def given_forces(self):
        r"""
        The generalized forces given as ``forces`` (zeros if none), without
        those of the :meth:`loads`.

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem, RigidBody
            sage: x, F = var('x F')
            sage: MechanicalSystem([RigidBody('b', joint=[x, 0, 0])], [x], forces=[1],
            ....:                  loads=[{'body': 'b', 'force': [F, 0, 0]}]).given_forces()
            [1]
        """
        return list(self._forces)


    # ------------------------------------------------------------------
    # the composed objects, and the methods that delegate to them

    def kinematics(self):
        r"""
        The :class:`~sage_dynsym.mechanics.system_kinematics.SystemKinematics`
        of the system: its bodies with its coordinates, and their kinematics
        (what its loads, force fields and rolling disks are evaluated on).

        EXAMPLES::

            sage: from sage_dynsym import load
            sage: from sage_dynsym.description import example_path
            sage: K = load(example_path('spherical_pendulum.yaml')).kinematics(); K
            Kinematics of 1 body in coordinates (psi, theta)
            sage: K.angular_velocity(1)
            (dtheta, dpsi*sin(theta), dpsi*cos(theta))
        """
        return self._kinematics

    def lagrangian_builder(self):
        r"""
        The :class:`~sage_dynsym.mechanics.system_lagrangian.LagrangianBuilder`
        of the system: its energies and its Lagrangian.

        EXAMPLES::

            sage: from sage_dynsym import load
            sage: from sage_dynsym.description import example_path
            sage: load(example_path('spherical_pendulum.yaml')).lagrangian_builder()
            Builder of the Lagrangian of spherical pendulum: 1 body, coordinates (psi, theta)
        """
        return self._builder


    # the kinematics: the methods of the kinematics of the same names
    bodies = DelegatedMethod('kinematics', SystemKinematics)
    parent_index = DelegatedMethod('kinematics', SystemKinematics)
    coordinates = DelegatedMethod('kinematics', SystemKinematics)
    velocities = DelegatedMethod('kinematics', SystemKinematics)
    frame_tree = DelegatedMethod('kinematics', SystemKinematics)
    tree_kinematics = DelegatedMethod('kinematics', SystemKinematics)
    body_frame = DelegatedMethod('kinematics', SystemKinematics)
    direction_cosines = DelegatedMethod('kinematics', SystemKinematics)
    angular_velocity_vector = DelegatedMethod('kinematics', SystemKinematics)
    angular_velocity = DelegatedMethod('kinematics', SystemKinematics)
    relative_angular_velocity = DelegatedMethod('kinematics', SystemKinematics)
    joint_velocity_vector = DelegatedMethod('kinematics', SystemKinematics)
    joint_velocity = DelegatedMethod('kinematics', SystemKinematics)
    joint_position = DelegatedMethod('kinematics', SystemKinematics)
    mass_center_position = DelegatedMethod('kinematics', SystemKinematics)

    # the energies: the methods of the builder of the Lagrangian
    body_decomposition = DelegatedMethod('lagrangian_builder', LagrangianBuilder)
    decomposition = DelegatedMethod('lagrangian_builder', LagrangianBuilder)
    kinetic_energy = DelegatedMethod('lagrangian_builder', LagrangianBuilder)
    force_function = DelegatedMethod('lagrangian_builder', LagrangianBuilder)
    generalized_forces = DelegatedMethod('lagrangian_builder', LagrangianBuilder)

    # the constraints: those of the constraint set
    constraints = DelegatedMethod('constraint_set', ConstraintSet, 'holonomic')
    nonholonomic_constraints = DelegatedMethod('constraint_set', ConstraintSet, 'nonholonomic')

    def calculus_method(self):
        r"""
        How the system computes its kinematics and its equations: one of
        ``'auto'`` (the default), ``'polynomial'``, ``'symbolic'`` and
        ``'recursive'`` (see :meth:`set_calculus_method`).

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem, RigidBody
            sage: a = var('a')
            sage: MechanicalSystem([RigidBody('b', rotations=[(3, a)])], [a]).calculus_method()
            'auto'
        """
        return self._builder.calculus_method()

    def set_calculus_method(self, method):
        r"""
        Choose how the system computes its kinematics and its equations, as
        a manifold of Sage chooses its calculus method (see REFERENCES
        below): the strategy of the system, not part of its
        description (the equations are the same; their form and the time
        they take differ). What was computed with the former method is
        forgotten.

        INPUT:

        - ``method`` -- one of

          - ``'polynomial'`` -- the kinematics in the polynomial ring of the
            sines and cosines of the angles
            (:class:`~sage_dynsym.algebra.trigonometric.TrigPolynomialRing`),
            the Christoffel coefficients of the equations combined there;
          - ``'symbolic'`` -- the kinematics in Sage's symbolic ring
            (:class:`~sage_dynsym.algebra.trigonometric.SymbolicBackend`),
            the mass matrix differentiated there;
          - ``'recursive'`` -- the equations assembled body by body by the
            Newton--Euler recursion;
          - ``'auto'`` -- the polynomial kinematics where the model is
            polynomial in the sines and cosines, and the form of the
            equations chosen by the size of the system

          (the details: :meth:`LagrangianBuilder.lagrangian
          <sage_dynsym.mechanics.system_lagrangian.LagrangianBuilder.lagrangian>`,
          whose ``christoffel`` it is by default)

        EXAMPLES: the planar double pendulum (point masses `m` at the ends
        of two rods of length `l`, gravity along `-y`): its second equation
        `m l^2 (1 + \cos b)\ddot a + m l^2\ddot b + m l^2\sin b\,\dot a^2
        + m g l\cos(a + b) = 0` expanded, and assembled body by body::

            sage: from sage_dynsym import MechanicalSystem, RigidBody, UniformGravity
            sage: a, b, m, l, g = var('a b m l g')
            sage: point_mass = dict(mass=m, mass_center=[l, 0, 0],
            ....:                   inertia=diagonal_matrix([0, m*l^2, m*l^2]))
            sage: S = MechanicalSystem([RigidBody('b1', rotations=[(3, a)], **point_mass),
            ....:                       RigidBody('b2', parent='b1', rotations=[(3, b)],
            ....:                                 joint=[l, 0, 0], **point_mass)],
            ....:                      [a, b], force_function=UniformGravity([0, -g, 0]))
            sage: E = S.lagrangian().lagrange_equations(); E[1]
            da^2*l^2*m*sin(b) + dda*l^2*m*(cos(b) + 1) + (cos(a)*cos(b) - sin(a)*sin(b))*g*l*m + ddb*l^2*m
            sage: S.set_calculus_method('recursive'); S.calculus_method()
            'recursive'
            sage: R = S.lagrangian().lagrange_equations(); R[1]
            ddb*l^2*m + (g*cos(a)*cos(b) + (-da^2*l + g*sin(a))*(-sin(b)))*(l*m) + (l^2*m*cos(b) + l^2*m)*dda
            sage: all(bool((r - e).expand() == 0) for r, e in zip(R, E))
            True

        The kinematics in the symbolic ring gives the same kinetic energy::

            sage: T = S.kinetic_energy(); S.set_calculus_method('symbolic')
            sage: bool(S.kinetic_energy() == T), str(S.lagrangian().lagrange_equations()) == str(E)
            (True, True)

        TESTS::

            sage: S.set_calculus_method('sympy')
            Traceback (most recent call last):
            ...
            ModelError: calculus_method: expected one of 'auto', 'polynomial', 'symbolic', 'recursive', got 'sympy'
            sage: S.calculus_method(), S.subs({g: 1}).calculus_method()
            ('symbolic', 'symbolic')

        REFERENCES:

        - the model of this method: the calculus method of Sage's manifolds,
          ``sage.manifolds.manifold.TopologicalManifold.set_calculus_method``
          (SageManifolds), chosen on the manifold and passed to its charts
        """
        # the builder checks the method (before the caches below are touched)
        self._builder = self._lagrangian_builder(method)
        self.lagrangian.clear_cache()
        # the numerical forms made of the former equations
        object_cache(self).clear()

    @cached_method
    def lagrangian(self, christoffel=None):
        r"""
        The Lagrangian `L = T + U`, with the system's dissipation function,
        generalized forces and constraints; ``christoffel`` chooses how the
        equations get their Christoffel coefficients (default: as the
        :meth:`calculus_method` of the system; see
        :meth:`LagrangianBuilder.lagrangian
        <sage_dynsym.mechanics.system_lagrangian.LagrangianBuilder.lagrangian>`).

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem, RigidBody
            sage: x, m, k, c = var('x m k c')
            sage: S = MechanicalSystem([RigidBody('b', joint=[x, 0, 0], mass=m)], [x],
            ....:                      force_function=-k*x^2/2, dissipation=c*var('dx')^2/2)
            sage: S.lagrangian().lagrange_equations()
            [c*dx + ddx*m + k*x]
            sage: S.lagrangian() is S.lagrangian()
            True
        """
        return self._builder.lagrangian(christoffel)

    def constraint_set(self):
        r"""
        All the constraints with their origins: the
        :class:`~sage_dynsym.mechanics.constraint_set.ConstraintSet` (the
        rolling contacts, which conditions are holonomic).

        EXAMPLES: see :mod:`~sage_dynsym.mechanics.constraint_set`.
        """
        return self._constraint_set

    def operating_points(self):
        r"""
        The named operating points (a dict ``{name: OperatingPoint}``, see
        :mod:`~sage_dynsym.mechanics.operating_points`).

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem, RigidBody
            sage: x, v = var('x v')
            sage: MechanicalSystem([RigidBody('b', joint=[x, 0, 0])], [x],
            ....:                  operating_points={'moving': {'velocities': {'dx': v}}}).operating_points()
            {'moving': Operating point 'moving': dx = v}
        """
        return dict(self._operating_points)

    def operating_point(self, name):
        r"""
        The operating point ``name``, for
        :func:`~sage_dynsym.analysis.linear.linearize`.

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem, RigidBody, linearize
            sage: x, m, v = var('x m v')
            sage: S = MechanicalSystem([RigidBody('b', joint=[x, 0, 0], mass=m)], [x],
            ....:                      operating_points={'moving': {'velocities': {'dx': v}}})
            sage: linearize(S, S.operating_point('moving'), coordinates=[x]).M()
            [m]
            sage: S.operating_point('resting')
            Traceback (most recent call last):
            ...
            ModelError: operating_points: no operating point 'resting'; the operating points are moving
        """
        if not isinstance(name, str) or name not in self._operating_points:
            raise ModelError(f"no operating point {name!r}; the operating points are "
                             f"{', '.join(self._operating_points) or '(none)'}",
                             entry="operating_points")
        return self._operating_points[name]

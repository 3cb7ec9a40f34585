r"""
Mechanical systems of rigid bodies

A :class:`MechanicalSystem` is the *description* of a system of rigid bodies
(see :doc:`the method </method>`): its bodies, generalized coordinates,
parameters, force function and non-potential forces. From it the kinematics
(direction cosines, angular velocities, joint velocities), the kinetic
energy (1), the force function ((2) or (3)) and the Lagrangian (4) are
derived; the Lagrangian object then gives the Lagrange, Routh and Hamilton
equations.

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
"""
import numbers

from sage.matrix.constructor import matrix
from sage.misc.cachefunc import cached_method
from sage.misc.verbose import verbose
from sage.modules.free_module_element import vector
from sage.structure.sage_object import SageObject
from sage.symbolic.ring import SR

from ..errors import ModelError
from ..symbols import (velocity, acceleration, t, time_derivative, check_mechanical_names,
                       sage_numbers)
from ..arguments import symbol_arguments
from ..io.fields import text as _text
from .report import report_title, report_sections
from ..analysis.trigonometric import (SymbolicBackend, TrigPolynomialRing, NotPolynomial,
                                      trig_rational_simplify)
from ..dynamics.lagrangian import Lagrangian
from ..dynamics.holonomic import check_constraints
from ..dynamics.nonholonomic import NonholonomicLagrangian
from ..dynamics.model import Model
from ..dynamics.natural_equations import natural_equations
from ..dynamics.natural_form import natural_form, is_singular, has_full_row_rank
from ..numerics.values import check_model_values
from .force_functions import check_force_function, split_force_terms, UniformGravity
from .constraint_set import ConstraintSet
from .format import read_mechanical_system
from .frames import held_product
from .kinematics import Kinematics
from .loads import load_list
from .operating_points import checked_operating_points, operating_point_to_dict
from .rigid_body import RigidBody

# Above this many terms in the mass matrix, converting the polynomial
# Christoffel coefficients back to symbolic expressions dominates the
# derivation (see bench/bench_chain.py); see lagrangian().
_POLYNOMIAL_CHRISTOFFEL_TERMS = 10000


class MechanicalSystem(Model):
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

    EXAMPLES::

        sage: from sage_dynsym import MechanicalSystem, RigidBody
        sage: a, b, m = var('a b m')
        sage: base = RigidBody('base', rotations=[(3, a)])
        sage: arm = RigidBody('arm', parent='base', rotations=[(1, b)], mass=m,
        ....:                 mass_center=[0, 1, 0])
        sage: S = MechanicalSystem([arm, base], [a, b]); S.bodies()
        [Rigid body 'base' (parent 0, rotations [(3, a)], mass 0),
         Rigid body 'arm' (parent base, rotations [(1, b)], mass m)]

    TESTS::

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

    def __init__(self, bodies, coordinates, parameters=None, force_function=None,
                 dissipation=0, forces=None, name=None, positive=(), loads=(), constraints=(),
                 nonholonomic=(), rolling=(), operating_points=None):
        bodies = list(bodies)
        given_names = [b.name() if isinstance(b, RigidBody) else None for b in bodies]
        for i, body in enumerate(bodies):
            if not isinstance(body, RigidBody):
                raise ModelError(f"expected a RigidBody, got {body!r}", entry=f"bodies[{i}]")
        self._bodies = self._sorted_by_parents(bodies)
        self._coordinates = [SR(q) for q in coordinates]
        for q in self._coordinates:
            if not q.is_symbol():
                raise ModelError(f"coordinates must be symbolic variables, got {q}",
                                 entry="coordinates")
        self._velocities = [velocity(q) for q in self._coordinates]
        self._parameters = None if parameters is None else [SR(p) for p in parameters]
        check_mechanical_names(self._coordinates, self._parameters or (), ModelError)
        check_force_function(force_function, self._coordinates)
        if isinstance(force_function, (list, tuple)):
            force_function = list(force_function)
        self._force = force_function
        self._dissipation = SR(dissipation)
        n = len(self._coordinates)
        self._forces = [SR(0)] * n if forces is None else [SR(f) for f in forces]
        if len(self._forces) != n:
            raise ModelError(f"expected {n} generalized forces, one per coordinate, got "
                             f"{len(self._forces)}", entry="forces")
        self._name = name
        self._positive = symbol_arguments(positive, 'positive')
        if self._parameters is not None:
            self._check_symbols()
            names = {str(p) for p in self._parameters}
            for p in self._positive:
                if str(p) not in names:
                    raise ModelError(f"{p} is not a declared parameter", entry="positive")
        self._symbolic = Kinematics(self, SymbolicBackend())
        self._tree = self._symbolic.tree
        self._loads = [self._checked_load(load, f"loads[{i}]", given_names)
                       for i, load in enumerate(load_list(loads))]
        self._constraints = check_constraints(constraints, self._coordinates, self._parameters)
        self._constraint_set = ConstraintSet(self, self._constraints, nonholonomic, rolling,
                                             given_names)
        self._operating_points = checked_operating_points(
            operating_points, self._coordinates, self._velocities, self._parameters)


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

    @classmethod
    def from_dict(cls, data, source=None):
        r"""
        The mechanical system of a description mapping (``kind: mechanical``); ``source``
        names the file in errors. The format is read by
        :func:`~sage_dynsym.mechanics.format.read_mechanical_system`.

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem
            sage: S = MechanicalSystem.from_dict({'kind': 'mechanical', 'coordinates': ['x'],
            ....:     'parameters': ['m'], 'bodies': [{'name': 'cart', 'joint': ['x', 0, 0], 'mass': 'm'}]})
            sage: S.lagrangian().expr()
            1/2*dx^2*m
        """
        return read_mechanical_system(cls, data, source)

    def to_dict(self):
        r"""
        The description mapping of the system (the inverse of
        :func:`~sage_dynsym.mechanics.description.mechanical_system_from_dict`).

        EXAMPLES::

            sage: from sage_dynsym import load
            sage: from sage_dynsym.description import example_path
            sage: d = load(example_path('spherical_pendulum.yaml')).to_dict()
            sage: d['bodies'][0]['rotations'], d['force_function']
            ([[3, 'psi'], [1, 'theta']], {'uniform_gravity': ['0', '0', '-g']})
        """
        from .force_functions import force_term_to_dict
        out = {'kind': 'mechanical'}
        if self.name():
            out['name'] = self.name()
        if self.parameters() is not None:
            out['parameters'] = [str(p) for p in self.parameters()]
        if self._positive:
            out['positive'] = [str(p) for p in self._positive]
        out['coordinates'] = [str(q) for q in self.coordinates()]
        terms = [force_term_to_dict(field, _text) for field in self.force_terms()]
        if terms:
            # one term keeps the single-mapping form
            out['force_function'] = terms if isinstance(self._force, list) else terms[0]
        if not self.dissipation().is_zero():
            out['dissipation'] = _text(self.dissipation())
        if any(not f.is_zero() for f in self._forces):
            out['forces'] = [_text(f) for f in self._forces]
        if self._loads:
            out['loads'] = [load.to_dict() for load in self._loads]
        if self._constraints:
            out['constraints'] = [_text(f) for f in self._constraints]
        constraints = self._constraint_set
        if constraints.given_nonholonomic():
            out['nonholonomic'] = [_text(g) for g in constraints.given_nonholonomic()]
        if constraints.rolling():
            out['rolling'] = [disk.to_dict() for disk in constraints.rolling()]
        if self._operating_points:
            out['operating_points'] = {name: operating_point_to_dict(point)
                                       for name, point in self._operating_points.items()}
        bodies = []
        for k, body in enumerate(self.bodies(), 1):
            entry = {'name': body.name(), 'parent': self.parent_index(k),
                     'rotations': [[axis, _text(angle)] for axis, angle in body.rotations()],
                     'joint': [_text(c) for c in body.joint()],
                     'mass_center': [_text(c) for c in body.mass_center()],
                     'mass': _text(body.mass()),
                     'inertia': [[_text(c) for c in row] for row in body.inertia().rows()]}
            if body.velocity() is not None:
                entry['velocity'] = [_text(c) for c in body.velocity()]
            bodies.append(entry)
        out['bodies'] = bodies
        return out

    def results(self):
        r"""
        The ``results:`` section of a saved description: the Lagrangian and
        the Lagrange equations, as text and LaTeX.

        EXAMPLES::

            sage: from sage_dynsym import load
            sage: from sage_dynsym.description import example_path
            sage: sorted(load(example_path('spherical_pendulum.yaml')).results())
            ['lagrange_equations', 'lagrange_equations_latex', 'lagrangian', 'lagrangian_latex']
        """
        from sage.misc.latex import latex
        L = self.lagrangian()
        equations = L.lagrange_equations()
        return {'lagrangian': _text(L.expr()), 'lagrangian_latex': str(latex(L.expr())),
                'lagrange_equations': [_text(e) for e in equations],
                'lagrange_equations_latex': [str(latex(e)) for e in equations]}

    def result_symbols(self, results):
        r"""
        The names a ``results:`` section of this system may use: the
        parameters (or the symbols of the Lagrangian), the coordinates,
        their velocities, accelerations and momenta; no functions.

        EXAMPLES::

            sage: from sage_dynsym import load
            sage: from sage_dynsym.description import example_path
            sage: symbols, functions = load(example_path('spherical_pendulum.yaml')).result_symbols({})
            sage: sorted(symbols)[:6], functions
            (['ddpsi', 'ddtheta', 'dpsi', 'dtheta', 'g', 'l'], ())
        """
        from ..symbols import momentum
        q = [str(v) for v in self.coordinates()]
        symbols = [str(p) for p in self.parameters() or []]
        if self.parameters() is None:
            symbols += sorted({str(v) for v in self.lagrangian().expr().variables()})
        symbols += q + [str(velocity(SR(v))) for v in q] + [str(acceleration(SR(v))) for v in q]
        symbols += [str(momentum(SR(v))) for v in q]
        if self.constraints() or self.nonholonomic_constraints():
            # the Lagrange equations of the first kind hold the multipliers
            symbols += [str(mu) for mu in self.lagrangian().multipliers()]
        return symbols, ()

    def subs(self, values):
        r"""
        The system with parameter values substituted: in the bodies, the
        force-function terms, the loads, the dissipation function, the
        generalized forces and the constraints. The substituted parameters
        leave :meth:`parameters` and the ``positive`` list.

        INPUT:

        - ``values`` -- a dictionary ``{parameter: value}`` (keys symbols or
          names); values exact or floating-point numbers, or expressions

        EXAMPLES::

            sage: from sage_dynsym import load
            sage: from sage_dynsym.description import example_path
            sage: S = load(example_path('spherical_pendulum.yaml'))
            sage: m, l, g = var('m l g')
            sage: S1 = S.subs({m: 1, l: 2, 'g': 9.81}); S1.parameters()
            []
            sage: S1.lagrangian().lagrange_equations()[1]
            -4*dpsi^2*cos(theta)*sin(theta) + 4*ddtheta - 19.6200000000000*sin(theta)

        TESTS::

            sage: S.subs({var('theta'): 0})
            Traceback (most recent call last):
            ...
            ModelError: subs: cannot substitute for theta, a coordinate, velocity or t
            sage: S.subs({'k': 1})
            Traceback (most recent call last):
            ...
            ModelError: subs: k is not a parameter of the system; its parameters are: m, l, g
        """
        from ..symbols import momentum
        if not isinstance(values, dict):
            raise ModelError(f"expected a dictionary {{parameter: value}}, got {values!r}",
                             entry="subs")
        protected = set(self._coordinates) | set(self._velocities) | {t}
        protected |= set(self._accelerations()) | {momentum(q) for q in self._coordinates}
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
            substitution[symbol] = SR(sage_numbers(value))

        def sub(e):
            return SR(e).subs(substitution)

        terms = [term.subs(substitution) if hasattr(term, 'evaluate') else sub(term)
                 for term in self.force_terms()]
        force = terms if isinstance(self._force, list) else (terms[0] if terms else None)
        kept = [p for p in self._parameters if p not in substitution] \
            if self._parameters is not None else None
        bodies = [b.subs(substitution, parent=self._bodies[self._parents[k] - 1].name()
                         if self._parents[k] else 0)
                  for k, b in enumerate(self._bodies, 1)]
        return MechanicalSystem(bodies, self._coordinates,
                                parameters=kept, force_function=force,
                                dissipation=sub(self._dissipation),
                                forces=[sub(f) for f in self._forces], name=self._name,
                                positive=[p for p in self._positive if p not in substitution],
                                loads=[load.subs(substitution) for load in self._loads],
                                constraints=[sub(f) for f in self._constraints],
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
    # construction helpers

    # numerics: the system's Lagrange equations run through its Lagrangian

    def numerical_rhs(self, values, backend='auto', algorithm='auto'):
        r"""
        The compiled right-hand side `\dot x = f(t, x)`, `x = (q, \dot q)`,
        with the parameter values ``values``: by the recursive algorithms
        of rigid-body dynamics (``algorithm='recursive'``), from the
        Lagrange equations of :meth:`lagrangian` (``'equations'``), or the
        first when it applies (``'auto'``); see
        :mod:`~sage_dynsym.mechanics.recursive_numerics` and
        :func:`~sage_dynsym.numerics.rhs.numerical_rhs`.

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem, RigidBody
            sage: x, m, k = var('x m k')
            sage: S = MechanicalSystem([RigidBody('b', joint=[x, 0, 0], mass=m)], [x],
            ....:                      force_function=-k*x^2/2)
            sage: S.numerical_rhs({m: 2, k: 8})(0, [1.0, 0.5])
            array([ 0.5, -4. ])
            sage: S.numerical_rhs({m: 2, k: 8}, algorithm='equations')(0, [1.0, 0.5])
            array([ 0.5, -4. ])
        """
        from ..numerics.rhs import RightHandSide
        from .recursive_numerics import numerical_form
        check_model_values(self, values)
        return RightHandSide(numerical_form(self, algorithm), values, backend)

    def simulate(self, values, initial, t_end, *args, algorithm='auto', **options):
        r"""
        A simulation of the system (see
        :meth:`~sage_dynsym.numerics.methods.NumericalMethods.simulate`:
        the same arguments), its right-hand side computed by ``algorithm``
        (see :meth:`numerical_rhs`).

        EXAMPLES: a mass on a spring, `x(t) = \cos 2t`::

            sage: from sage_dynsym import MechanicalSystem, RigidBody
            sage: x, m, k = var('x m k')
            sage: S = MechanicalSystem([RigidBody('b', joint=[x, 0, 0], mass=m)], [x],
            ....:                      force_function=-k*x^2/2)
            sage: T = S.simulate({m: 2, k: 8}, {x: 1, 'dx': 0}, pi, points=3)
            sage: T.values(x).round(8), T.energy_drift() < 1e-9
            (array([ 1., -1.,  1.]), True)

        TESTS::

            sage: S = MechanicalSystem([RigidBody('b', joint=[x, 0, 0], mass=m)], [x],
            ....:                      force_function=-k*x^2/2, positive=[m, k])
            sage: S.simulate({m: -2, k: 8}, {x: 1, 'dx': 0}, pi)
            Traceback (most recent call last):
            ...
            ModelError: values: m is declared positive, got -2
        """
        from ..numerics.simulate import simulate
        from .recursive_numerics import numerical_form
        check_model_values(self, values)
        options.setdefault('name', self._name)
        return simulate(numerical_form(self, algorithm), values, initial, t_end, *args, **options)

    def code(self, language='python', cse=True):
        r"""
        Generated source of the mass matrix and forcing of :meth:`lagrangian`
        (see :meth:`~sage_dynsym.numerics.methods.NumericalMethods.code`).

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem, RigidBody
            sage: x, m, k = var('x m k')
            sage: S = MechanicalSystem([RigidBody('b', joint=[x, 0, 0], mass=m)], [x],
            ....:                      force_function=-k*x^2/2)
            sage: 'k*x' in str(S.code())
            True
        """
        return self.lagrangian().code(language=language, cse=cse)

    def _sorted_by_parents(self, bodies):
        names = {}
        for i, body in enumerate(bodies):
            if body.name() in names:
                raise ModelError(f"duplicate body name {body.name()!r}", entry=f"bodies[{i}].name")
            names[body.name()] = i
        parent_of = []
        for i, body in enumerate(bodies):
            parent = body.parent()
            entry = f"bodies[{i}].parent"
            if isinstance(parent, RigidBody):
                parent = parent.name()
            if isinstance(parent, str):
                if parent not in names:
                    raise ModelError(f"unknown parent body {parent!r}; known bodies are: "
                                     f"{', '.join(names)}", entry=entry)
                parent_of.append(names[parent])
            elif isinstance(parent, numbers.Integral) and not isinstance(parent, bool):
                parent = int(parent)
                if parent == 0:
                    parent_of.append(None)
                elif 1 <= parent <= len(bodies):
                    parent_of.append(parent - 1)
                else:
                    raise ModelError(f"body index {parent} out of range 1..{len(bodies)}",
                                     entry=entry)
            else:
                raise ModelError("expected 0 (inertial frame), a body name or a 1-based "
                                 f"body index, got {parent!r}", entry=entry)
        order, state = [], [0] * len(bodies)   # 0 new, 1 in progress, 2 done

        def visit(i, trail):
            if state[i] == 2:
                return
            if state[i] == 1:
                cycle = trail[trail.index(i):] + [i]
                raise ModelError("the parents form a cycle: " +
                                 " -> ".join(bodies[j].name() for j in cycle), entry="bodies")
            state[i] = 1
            if parent_of[i] is not None:
                visit(parent_of[i], trail + [i])
            state[i] = 2
            order.append(i)

        for i in range(len(bodies)):
            visit(i, [])
        position = {i: k for k, i in enumerate(order, 1)}
        self._parents = [None] + [0 if parent_of[i] is None else position[parent_of[i]]
                                  for i in order]
        return [bodies[i] for i in order]

    def _check_symbols(self):
        declared = set(self._coordinates) | set(self._velocities) | set(self._parameters) | {t}
        names = ", ".join(sorted(map(str, set(self._parameters) | {t})))

        def check(expr, entry):
            for v in SR(expr).variables():
                if v not in declared:
                    raise ModelError(f"undeclared symbol {v}; declared are: {names}", entry=entry)

        for body in self._bodies:
            n = body.name()
            for i, (_, angle) in enumerate(body.rotations()):
                check(angle, f"{n}.rotations[{i}]")
            for field in ("joint", "velocity", "mass_center"):
                for c in getattr(body, field)() or ():
                    check(c, f"{n}.{field}")
            check(body.mass(), f"{n}.mass")
            for c in body.inertia().list():
                check(c, f"{n}.inertia")
        check(self._dissipation, "dissipation")
        for i, f in enumerate(self._forces):
            check(f, f"forces[{i}]")
        for i, term in enumerate(self.force_terms()):
            if not hasattr(term, 'evaluate'):
                check(term, "force_function" if not isinstance(self._force, list)
                      else f"force_function[{i}]")

    def _checked_load(self, load, entry, given_names):
        from .loads import Load, body_index
        load = Load.from_value(load, entry)
        # a body index counts in the order the bodies were given (as parent
        # indices do); keep names, which do not depend on the order
        names = {}
        for key in ('body', 'axes'):
            ref = getattr(load, key)()
            if isinstance(ref, int) and ref > 0:
                if ref > len(given_names):
                    raise ModelError(f"body index {ref} out of range 1..{len(given_names)}",
                                     entry=f"{entry}.{key}")
                ref = given_names[ref - 1]
            if ref != 0:
                body_index(self, ref, f"{entry}.{key}")
            names[key] = ref
        load = Load(names['body'], point=load.point(), force=load.force(),
                    torque=load.torque(), axes=names['axes'])
        accelerations = self._accelerations()
        for field in ('point', 'force', 'torque'):
            for c in getattr(load, field)() or ():
                for v in SR(c).variables():
                    if v in accelerations or (field == 'point' and v in self._velocities):
                        what = 'point of application' if field == 'point' else field
                        raise ModelError(f"the {what} cannot depend on {v}",
                                         entry=f"{entry}.{field}")
        if self._parameters is not None:
            declared = set(self._coordinates) | set(self._velocities) | set(self._parameters) | {t}
            names = ", ".join(sorted(map(str, set(self._parameters) | {t})))
            for field in ('point', 'force', 'torque'):
                for c in getattr(load, field)() or ():
                    for v in SR(c).variables():
                        if v not in declared:
                            raise ModelError(f"undeclared symbol {v}; declared are: {names}",
                                             entry=f"{entry}.{field}")
        return load

    def _accelerations(self):
        return [acceleration(q) for q in self._coordinates]

    # ------------------------------------------------------------------
    # description

    def _repr_(self):
        n = len(self._bodies)
        name = f" {self._name!r}" if self._name else ""
        return (f"Mechanical system{name}: {n} bod{'y' if n == 1 else 'ies'}, coordinates "
                f"({', '.join(map(str, self._coordinates))})")

    def name(self):
        r"""
        The system's name (or ``None``).

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem
            sage: MechanicalSystem([], [], name="empty").name()
            'empty'
        """
        return self._name

    def bodies(self):
        r"""
        The bodies, parents before children; body `k` (1-based) is
        ``bodies()[k-1]``.

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem, RigidBody
            sage: MechanicalSystem([RigidBody('b')], []).bodies()
            [Rigid body 'b' (parent 0, rotations [], mass 0)]
        """
        return list(self._bodies)

    def parent_index(self, k):
        r"""
        The 1-based index of the parent of body ``k`` (0: inertial frame).

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem, RigidBody
            sage: S = MechanicalSystem([RigidBody('a'), RigidBody('b', parent='a')], [])
            sage: S.parent_index(2), S.parent_index(1)
            (1, 0)
        """
        return self._parents[k]

    def coordinates(self):
        r"""
        The generalized coordinates.

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem
            sage: MechanicalSystem([], [var('x')]).coordinates()
            [x]
        """
        return list(self._coordinates)

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
        if self._force is None:
            return []
        return list(self._force) if isinstance(self._force, list) else [self._force]

    def conditions(self):
        r"""
        The conditions on the parameters for the model to be physical that
        are not decided by its data: those of its force fields (the
        direction of a Newtonian field with symbolic direction cosines a
        unit vector, its distance positive; see
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
        """
        return [c for term in self.force_terms() if hasattr(term, 'conditions')
                for c in term.conditions()]

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

    def constraints(self):
        r"""
        The holonomic constraints `f_j(q, t)` (each meaning `f_j = 0`): those
        given, then the contact conditions of rolling disks that the
        coordinates do not impose (see :meth:`constraint_set`).

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem
            sage: x, y, l = var('x y l')
            sage: MechanicalSystem([], [x, y], constraints=[x^2 + y^2 == l^2]).constraints()
            [-l^2 + x^2 + y^2]
        """
        return self._constraint_set.holonomic()

    def nonholonomic_constraints(self):
        r"""
        The constraints on the velocities (each meaning `= 0`): those given,
        then the no-slip conditions of the rolling disks (see
        :meth:`constraint_set`).

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem, RigidBody
            sage: x, y, th = var('x y theta')
            sage: S = MechanicalSystem([RigidBody('blade', joint=[x, y, 0], rotations=[(3, th)])],
            ....:                      [x, y, th], nonholonomic=['sin(theta)*dx - cos(theta)*dy'])
            Traceback (most recent call last):
            ...
            ModelError: nonholonomic[0]: expected an expression or a relation, got 'sin(theta)*dx - cos(theta)*dy'
            sage: dx, dy = var('dx dy')
            sage: S = MechanicalSystem([RigidBody('blade', joint=[x, y, 0], rotations=[(3, th)])],
            ....:                      [x, y, th], nonholonomic=[sin(th)*dx - cos(th)*dy])
            sage: S.nonholonomic_constraints(), S.lagrangian().nonholonomic_constraints()
            ([-dy*cos(theta) + dx*sin(theta)], [-dy*cos(theta) + dx*sin(theta)])
        """
        return self._constraint_set.nonholonomic()

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
        The named operating points (a dict ``{name: OperatingPoint}``).

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

        TESTS::

            sage: S.operating_point('resting')
            Traceback (most recent call last):
            ...
            ModelError: operating_points: no operating point 'resting'; the operating points are moving
        """
        if name not in self._operating_points:
            raise ModelError(f"no operating point {name!r}; the operating points are "
                             f"{', '.join(self._operating_points) or '(none)'}",
                             entry="operating_points")
        return self._operating_points[name]

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

    @cached_method
    def generalized_forces(self):
        r"""
        The generalized non-potential forces `Q_i`: those given as
        ``forces`` plus those of the :meth:`loads` (see
        :mod:`~sage_dynsym.mechanics.loads` for the sign convention).

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem, RigidBody
            sage: x, F = var('x F')
            sage: MechanicalSystem([], [x], forces=[1]).generalized_forces()
            [1]
            sage: MechanicalSystem([RigidBody('b', joint=[x, 0, 0])], [x], forces=[1],
            ....:                  loads=[{'body': 'b', 'force': [F, 0, 0]}]).generalized_forces()
            [F + 1]
        """
        forces = list(self._forces)
        for i, load in enumerate(self._loads):
            forces = [a + b for a, b in zip(forces, load.generalized_forces(self, f"loads[{i}]"))]
        return forces

    # ------------------------------------------------------------------
    # kinematics

    def frame_tree(self):
        r"""
        The :class:`~sage_dynsym.mechanics.frames.FrameTree` of all elementary
        rotations.

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem, RigidBody
            sage: S = MechanicalSystem([RigidBody('b', rotations=[(3, var('a'))])], [])
            sage: S.frame_tree().angle(S.body_frame(1))
            a
        """
        return self._tree

    def body_frame(self, k):
        r"""
        The frame of body ``k`` in :meth:`frame_tree` (``0`` for ``k = 0``).

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem, RigidBody
            sage: a, b = var('a b')
            sage: S = MechanicalSystem([RigidBody('b', rotations=[(3, a), (1, b)])], [])
            sage: S.body_frame(0), S.body_frame(1)
            (0, 2)
        """
        return self._symbolic.body_frame(k)

    def velocities(self):
        r"""
        The velocity symbols ``d<q>`` of the coordinates.

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem
            sage: MechanicalSystem([], [var('x')]).velocities()
            [dx]
        """
        return list(self._velocities)

    def _check_index(self, k):
        if not 1 <= k <= len(self._bodies):
            raise ModelError(f"body index {k} out of range 1..{len(self._bodies)}")

    def direction_cosines(self, k, j=0):
        r"""
        The direction-cosine matrix `\alpha^{jk}`: columns are the axes of
        body ``k`` in the axes of body ``j`` (``j = 0``: inertial frame).

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem, RigidBody
            sage: a = var('a')
            sage: S = MechanicalSystem([RigidBody('b', rotations=[(3, a)])], [a])
            sage: S.direction_cosines(1)
            [ cos(a) -sin(a)       0]
            [ sin(a)  cos(a)       0]
            [      0       0       1]
        """
        self._check_index(k)
        return self._tree.direction_cosines(self.body_frame(k), self.body_frame(j))

    def angular_velocity_vector(self, k):
        r"""
        The absolute angular velocity `W_k` as a
        :class:`~sage_dynsym.mechanics.frames.FrameVector` (each rotation rate about its
        own axis, in its own frame).

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem, RigidBody
            sage: a = var('a')
            sage: S = MechanicalSystem([RigidBody('b', rotations=[(3, a)])], [a])
            sage: S.angular_velocity_vector(1).parts()
            {1: (0, 0, da)}
        """
        return self._symbolic.angular_velocity(k)

    def angular_velocity(self, k):
        r"""
        `W_k`, the absolute angular velocity of body ``k`` in its own axes.

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem, RigidBody
            sage: a, b = var('a b')
            sage: S = MechanicalSystem([RigidBody('b', rotations=[(3, a), (1, b)])], [a, b])
            sage: S.angular_velocity(1)
            (db, da*sin(b), da*cos(b))
        """
        self._check_index(k)
        return self.angular_velocity_vector(k).components(self.body_frame(k))

    def relative_angular_velocity(self, k):
        r"""
        `\omega_k`, the angular velocity of body ``k`` relative to its
        parent, in the axes of body ``k``.

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem, RigidBody
            sage: a, b = var('a b')
            sage: S = MechanicalSystem([RigidBody('p', rotations=[(3, a)]),
            ....:                       RigidBody('c', parent='p', rotations=[(1, b)])], [a, b])
            sage: S.relative_angular_velocity(2), S.angular_velocity(2)
            ((db, 0, 0), (db, da*sin(b), da*cos(b)))
        """
        self._check_index(k)
        own = self.angular_velocity_vector(k) - self.angular_velocity_vector(self._parents[k])
        return own.components(self.body_frame(k))

    def joint_velocity_vector(self, k):
        r"""
        The absolute velocity `V_{0k} = V_{0j} + W_j \times r^j_{0k} +
        v^j_{0k}` of the joint point of body ``k``, as a
        :class:`~sage_dynsym.mechanics.frames.FrameVector`.

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem, RigidBody
            sage: a, l = var('a l')
            sage: S = MechanicalSystem([RigidBody('p', rotations=[(3, a)]),
            ....:                       RigidBody('c', parent='p', joint=[l, 0, 0])], [a])
            sage: S.joint_velocity_vector(2).parts()
            {1: (0, da*l, 0)}
        """
        return self._symbolic.joint_velocity(k)

    def joint_velocity(self, k):
        r"""
        `V_{0k}` in the axes of body ``k``.

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem, RigidBody
            sage: z = var('z')
            sage: MechanicalSystem([RigidBody('s', joint=[0, 0, z])], [z]).joint_velocity(1)
            (0, 0, dz)
        """
        self._check_index(k)
        return self.joint_velocity_vector(k).components(self.body_frame(k))

    def joint_position(self, k):
        r"""
        The position of the joint point `O_k` relative to the inertial origin,
        as a :class:`~sage_dynsym.mechanics.frames.FrameVector`.

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem, RigidBody
            sage: a, l = var('a l')
            sage: S = MechanicalSystem([RigidBody('p', rotations=[(3, a)]),
            ....:                       RigidBody('c', parent='p', joint=[l, 0, 0])], [a])
            sage: S.joint_position(2).components(0)
            (l*cos(a), l*sin(a), 0)
        """
        return self._symbolic.joint_position(k)

    def mass_center_position(self, k):
        r"""
        The position of the mass centre `C_k` relative to the inertial
        origin, as a :class:`~sage_dynsym.mechanics.frames.FrameVector`.

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem, RigidBody
            sage: a, l = var('a l')
            sage: S = MechanicalSystem([RigidBody('p', rotations=[(3, a)], mass_center=[l, 0, 0])], [a])
            sage: S.mass_center_position(1).components(0)
            (l*cos(a), l*sin(a), 0)
        """
        self._check_index(k)
        return self._symbolic.mass_center_position(k)

    # ------------------------------------------------------------------
    # energies and the Lagrangian

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
        self._check_index(k)
        kinematics = self._polynomial_kinematics()
        if kinematics is None:
            kinematics, to_symbolic = self._symbolic, trig_rational_simplify
        else:
            to_symbolic = kinematics.backend().simplest_fraction
        A, A1, A0 = kinematics.body_decomposition(k)
        A = matrix(SR, [[to_symbolic(e) for e in row] for row in A])
        A.set_immutable()
        return A, vector(SR, [to_symbolic(e) for e in A1]), to_symbolic(A0)

    @cached_method
    def _polynomial_kinematics(self):
        r"""
        The kinematics over a :class:`~sage_dynsym.analysis.trigonometric.TrigPolynomialRing`
        when the model is polynomial in the sines and cosines of its angles
        and in its parameters (the usual case), else ``None``.
        """
        dynamic = self._coordinates + self._velocities + [t]
        data = list(dynamic)
        for body in self._bodies:
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
            kinematics = Kinematics(self, ring)
            for k in range(1, len(self._bodies) + 1):
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
            parts = [self.body_decomposition(k) for k in range(1, len(self._bodies) + 1)]
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
        parts = [kinematics.body_decomposition(k) for k in range(1, len(self._bodies) + 1)]
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
            self._check_index(k)
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
        terms = self.force_terms()
        if len(terms) == 1 and not hasattr(terms[0], 'evaluate'):
            return SR(terms[0])
        total = SR(0)
        for term in terms:
            total += term.evaluate(self).expand() if hasattr(term, 'evaluate') else SR(term)
        return trig_rational_simplify(total) if terms else total

    @cached_method
    def lagrangian(self, christoffel='auto'):
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
            centre and inertia and no prescribed relative velocity, else
            ``'symbolic'`` is used;
          - ``'auto'`` (default) -- ``'polynomial'`` unless some body lies
            more than 8 elementary rotations away from the inertial frame or
            the mass matrix has more than 10,000 polynomial terms (for the
            spatial chains of ``bench/``: up to 4 links), then
            ``'recursive'``.

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
            ModelError: christoffel must be 'auto', 'polynomial', 'recursive' or 'symbolic', got 'fast'

        A chain of 9 planar links takes the recursive form (compared with
        the other forms in ``tests/test_compact_equations.py``); a body with a
        prescribed relative velocity cannot, and gets the symbolic form::

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
        if christoffel not in ('auto', 'polynomial', 'recursive', 'symbolic'):
            raise ModelError("christoffel must be 'auto', 'polynomial', 'recursive' or "
                             f"'symbolic', got {christoffel!r}")
        kinematics = self._symbolic
        if christoffel == 'recursive' and not kinematics.recursive_applies():
            christoffel = 'symbolic'
        if christoffel == 'auto':
            # deep bodies: the polynomial forms grow faster than the nested
            # ones, and even computing them costs seconds (bench/bench_chain.py)
            depth = max((len(self._tree.path_to_root(kinematics.body_frame(k))) - 1
                         for k in range(1, len(self._bodies) + 1)), default=0)
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
            gravity, rest = split_force_terms(self)
            A, A1, T0, h = kinematics.recursive_equations(gravity)
            ddq = [acceleration(q) for q in self._coordinates]
            U = rest + sum((term.evaluate(self) for term in self.force_terms()
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
                       equation_builder=builder, constraints=self.constraints())
        if self.nonholonomic_constraints():
            return NonholonomicLagrangian(None, self._coordinates, self._velocities,
                                          nonholonomic=self.nonholonomic_constraints(), **options)
        return Lagrangian(None, self._coordinates, self._velocities, **options)


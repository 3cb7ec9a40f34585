r"""
The numerical methods every model has: right-hand side, simulation, code

:class:`NumericalMethods` is a base class of the models. It works only
through the model's ``equations_record()`` (one of the records of
:mod:`sage_dynsym.analysis.motion`) and the optional hook
``_conserved_energy()`` (a symbolic energy in the state variables and the
parameters, or ``None``), and gives

- :meth:`~NumericalMethods.numerical_rhs` (see :mod:`~sage_dynsym.numerics.rhs`),
- :meth:`~NumericalMethods.simulate` (see :mod:`~sage_dynsym.numerics.simulate`),
- :meth:`~NumericalMethods.code` (see :mod:`~sage_dynsym.numerics.codegen`).

The parameter values given are checked against the model's declared signs
and physical conditions when it has them (see
:mod:`~sage_dynsym.numerics.values`).

The numerical form of the equations (and its compiled code) is built once
per model object.

EXAMPLES::

    sage: from sage_dynsym.analysis.motion import SecondOrderEquations
    sage: from sage_dynsym.numerics.methods import NumericalMethods
    sage: x, dx, ddx, k = var('x dx ddx k')
    sage: class Oscillator(NumericalMethods):
    ....:     def equations_record(self):
    ....:         return SecondOrderEquations([ddx + k*x], [x], [dx], [ddx])
    ....:     def _conserved_energy(self):
    ....:         return (dx^2 + k*x^2)/2
    sage: T = Oscillator().simulate({k: 1}, {x: 1, dx: 0}, 20)
    sage: T.energy_drift() < 1e-9
    True
"""
import weakref

from sage.matrix.constructor import matrix
from sage.modules.free_module_element import vector
from sage.symbolic.ring import SR

from ..algebra.solving import vanishes
from ..analysis.motion import FirstOrderEquations
from ..symbols import time_derivative
from ..errors import ModelError
from .codegen import generate_code
from .form import NumericalForm
from .rhs import RightHandSide, StateJacobian
from .simulate import simulate as _simulate
from .values import check_model_values

__all__ = ['object_cache', 'energy_rate', 'NumericalMethods']

_CACHES = {}


def object_cache(obj):
    r"""
    A dict of computed data attached to ``obj`` for its lifetime, kept
    outside the object (so that pickling it does not carry compiled code);
    a new empty dict for objects without weak references.

    EXAMPLES::

        sage: from sage_dynsym.numerics.methods import object_cache
        sage: class Thing:
        ....:     pass
        sage: a = Thing(); object_cache(a)['x'] = 1
        sage: object_cache(a), object_cache(Thing())
        ({'x': 1}, {})
    """
    key = id(obj)
    cached = _CACHES.get(key)
    if cached is not None and cached[0]() is obj:
        return cached[1]
    cache = {}
    try:
        ref = weakref.ref(obj, lambda _, key=key: _CACHES.pop(key, None))
    except TypeError:       # objects without weak references: no cache
        return cache
    _CACHES[key] = (ref, cache)
    return cache


def energy_rate(record, energy):
    r"""
    The rate of change of ``energy`` along the equations of ``record`` (a
    record of :mod:`~sage_dynsym.analysis.motion`), the accelerations or
    derivatives solved from them; ``None`` for equations with constraints
    (their multipliers are not solved here).

    EXAMPLES::

        sage: from sage_dynsym.numerics.methods import energy_rate
        sage: from sage_dynsym.analysis.motion import FirstOrderEquations, SecondOrderEquations
        sage: x, dx, ddx, y, c = var('x dx ddx y c')
        sage: energy_rate(SecondOrderEquations([ddx + c*dx + x], [x], [dx], [ddx]), (dx^2 + x^2)/2)
        -c*dx^2
        sage: energy_rate(FirstOrderEquations([y, -x], [x, y], [2, 1]), (x^2 + y^2)/2)
        -1/2*x*y
    """
    energy = SR(energy)
    if isinstance(record, FirstOrderEquations):
        x = record.variables()
        derivatives = record.lhs_matrix().solve_right(vector(SR, record.rhs()))
        return sum(energy.diff(v) * d for v, d in zip(x, derivatives)).expand()
    if record.constraints() or record.velocity_constraints():
        return None
    equations, ddq = record.equations(), record.accelerations()
    M = matrix(SR, [[e.diff(a) for a in ddq] for e in equations])
    rest = vector(SR, [e.subs({a: 0 for a in ddq}) for e in equations])
    accelerations = M.solve_right(-rest)
    rate = time_derivative(energy, record.coordinates(), record.velocities(), ddq)
    return rate.subs(dict(zip(ddq, accelerations))).expand()


class NumericalMethods:
    r"""
    Mixin of the models: numerical right-hand side, simulation and code
    generation from ``equations_record()`` (see the module documentation).

    EXAMPLES: see the module documentation.
    """

    def _conserved_energy(self):
        r"""The conserved energy of the model, or ``None`` (the default)."""
        return None

    def _test_energy(self, **options):
        r"""The conserved energy, when the model has one, is an integral of
        its equations: its rate along them vanishes identically.

        EXAMPLES: run by ``TestSuite`` (see the models)::

            sage: from sage_dynsym.numerics.methods import NumericalMethods
            sage: from sage_dynsym.analysis.motion import SecondOrderEquations
            sage: x, dx, ddx, k = var('x dx ddx k')
            sage: class Oscillator(NumericalMethods):
            ....:     def equations_record(self):
            ....:         return SecondOrderEquations([ddx + k*x], [x], [dx], [ddx])
            ....:     def _conserved_energy(self):
            ....:         return (dx^2 + k*x^2)/2 + self.error
            sage: Oscillator.error = 0; Oscillator()._test_energy()
            sage: Oscillator.error = x*dx; Oscillator()._test_energy()
            Traceback (most recent call last):
            ...
            AssertionError: the energy 1/2*k*x^2 + 1/2*dx^2 + dx*x changes at the rate -k*x^2 + dx^2
        """
        from sage.misc.sage_unittest import instance_tester
        tester = instance_tester(self, **options)
        energy = self._conserved_energy()
        if energy is None:
            return
        rate = energy_rate(self.equations_record(), energy)
        if rate is not None:
            tester.assertTrue(vanishes(rate), f"the energy {energy} changes at the rate {rate}")

    def to_linearizer(self):
        r"""
        The same as ``equations_record()``, the neutral record of the
        equations (the name of earlier versions, after SymPy's mechanics).

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, dx = var('x dx')
            sage: L = Lagrangian(dx^2/2 - x^2/2, [x])
            sage: L.to_linearizer().equations() == L.equations_record().equations()
            True
        """
        return self.equations_record()

    #: the ways :meth:`numerical_form` computes the right-hand side (a kind
    #: of model with several overrides :meth:`numerical_form`)
    ALGORITHMS = ('auto', 'equations')

    def numerical_form(self, algorithm='auto'):
        r"""
        The numerical form of ``equations_record()`` (built once per
        object, see :class:`~sage_dynsym.numerics.form.NumericalForm`), with
        the model's conserved energy, computed only if a trajectory's drift
        asks for it. ``algorithm``: one of :attr:`ALGORITHMS` (here the
        equations themselves; a mechanical system also has the recursive
        algorithms of rigid-body dynamics).

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, dx, k = var('x dx k')
            sage: L = Lagrangian(dx^2/2 - k*x^2/2, [x])
            sage: L.numerical_form(), L.numerical_form() is L.numerical_form()
            (Numerical form M x'' = F in (x), parameters (k), True)

        TESTS::

            sage: L.numerical_form('recursive')
            Traceback (most recent call last):
            ...
            ModelError: algorithm: expected one of ('auto', 'equations'), got 'recursive'
        """
        if algorithm not in self.ALGORITHMS:
            raise ModelError(f"expected one of {self.ALGORITHMS}, got {algorithm!r}",
                             entry="algorithm")
        cache = object_cache(self)
        if 'form' not in cache:
            # the energy is computed only if a trajectory's drift asks for it
            cache['form'] = NumericalForm(self.equations_record(), energy=self._conserved_energy)
        return cache['form']

    def numerical_rhs(self, values, backend='auto', algorithm='auto', jacobian=False):
        r"""
        A callable ``f(t, x)`` returning `\dot x` as a NumPy array, ``x``
        over the state variables (coordinates then velocities for
        second-order equations), with the parameter values ``values`` (a
        dict, symbols or names as keys); compiled, solving the linear
        system of the equations at each call (see
        :func:`~sage_dynsym.numerics.rhs.numerical_rhs`), from the numerical
        form of ``algorithm`` (:meth:`numerical_form`).

        With ``jacobian=True``: the pair ``(f, jac)``, ``jac(t, x)`` the
        dense Jacobian of ``f`` with respect to the state, generated and
        compiled like ``f`` (a :class:`~sage_dynsym.numerics.rhs.StateJacobian`;
        for ``solve_ivp(..., jac=jac)`` and linearizations at any state,
        :meth:`numerical_linearization`).

        EXAMPLES::

            sage: from sage_dynsym.analysis.motion import FirstOrderEquations
            sage: from sage_dynsym.numerics.methods import NumericalMethods
            sage: x, y, w = var('x y w')
            sage: class Rotation(NumericalMethods):
            ....:     def equations_record(self):
            ....:         return FirstOrderEquations([-w*y, w*x], [x, y])
            sage: f = Rotation().numerical_rhs({'w': 2}); f(0, [1.0, 1.0])
            array([-2.,  2.])
            sage: f.variables()
            [x, y]
        """
        check_model_values(self, values)
        form = self.numerical_form(algorithm)
        f = RightHandSide(form, values, backend)
        return (f, StateJacobian(form, values, backend)) if jacobian else f

    def numerical_linearization(self, values, state, t=0, backend='auto', algorithm='auto'):
        r"""
        The linearization of `\dot x = f(t, x)` at any state ``state`` (not
        only at equilibria): the Jacobian `\partial f/\partial x` there, as
        a matrix over ``RDF``, from the compiled Jacobian of
        :meth:`numerical_rhs` (``jacobian=True``). ``state`` is a dict over
        the state variables or a sequence in their order. For the exact
        linearization about equilibria and steady motions, see
        :func:`~sage_dynsym.analysis.linear.linearize`.

        EXAMPLES: a pendulum, `\ddot\varphi = -(g/l)\sin\varphi`, at
        `\varphi = \pi/3`: `\partial\ddot\varphi/\partial\varphi =
        -(g/l)\cos\varphi`::

            sage: from sage_dynsym import MechanicalSystem, RigidBody, UniformGravity
            sage: phi, m, l, g = var('phi m l g')
            sage: P = MechanicalSystem([RigidBody('rod', rotations=[(1, phi)], mass=m,
            ....:                      mass_center=[0, 0, -l], inertia=diagonal_matrix([m*l^2, m*l^2, 0]))],
            ....:                      [phi], force_function=UniformGravity([0, 0, -g]))
            sage: A = P.numerical_linearization({m: 1, l: 2, g: 9.81}, {phi: pi/3, 'dphi': 0})
            sage: A.parent(), bool(abs(A[1, 0] + 9.81*cos(pi/3)/2) < 1e-14)
            (Full MatrixSpace of 2 by 2 dense matrices over Real Double Field, True)
            sage: w = A.eigenvalues()[0]    # a centre there: +-i sqrt(g cos(phi)/l)
            sage: bool(abs(abs(w) - sqrt(9.81*cos(pi/3)/2)) < 1e-14), w.real()
            (True, 0.0)

        TESTS::

            sage: P.numerical_linearization({m: 1, l: 2, g: 9.81}, {phi: 0})
            Traceback (most recent call last):
            ...
            ModelError: state: no value for dphi (the state is the coordinates and the velocities)
        """
        from sage.matrix.constructor import matrix
        from sage.rings.real_double import RDF
        _, jac = self.numerical_rhs(values, backend=backend, algorithm=algorithm, jacobian=True)
        if isinstance(state, dict):
            by_name = {str(k): v for k, v in state.items()}
            missing = [str(v) for v in jac.variables() if str(v) not in by_name]
            if missing:
                raise ModelError(f"no value for {', '.join(missing)} (the state is the "
                                 "coordinates and the velocities)", entry="state")
            state = [by_name[str(v)] for v in jac.variables()]
        return matrix(RDF, jac(t, state))

    def simulate(self, values, initial, t_end, points=101, t0=0, method='auto', rtol=1e-10,
                 atol=1e-12, backend='auto', *, algorithm='auto', **options):
        r"""
        The motion from ``initial`` (a dict over the state variables) at
        ``t0`` to ``t_end``, sampled at ``points`` times (both ends
        included), as a :class:`~sage_dynsym.numerics.trajectory.Trajectory`;
        ``values`` the parameter values. See
        :func:`~sage_dynsym.numerics.simulate.simulate` for the integrators
        (``method='auto'``, ``'stiff'``, or a method of SciPy's
        ``solve_ivp``), the tolerances, ``events=[expr, ...]`` (zero
        crossings, :meth:`~sage_dynsym.numerics.trajectory.Trajectory.events`),
        the limits (``max_points=``, ``max_evaluations=``) and the
        constraints (``project=``); the right-hand side from the numerical
        form of ``algorithm`` (:meth:`numerical_form`).

        EXAMPLES::

            sage: from sage_dynsym.analysis.motion import FirstOrderEquations
            sage: from sage_dynsym.numerics.methods import NumericalMethods
            sage: x, a = var('x a')
            sage: class Decay(NumericalMethods):
            ....:     def equations_record(self):
            ....:         return FirstOrderEquations([-a*x], [x])
            sage: T = Decay().simulate({a: 1}, {x: 1}, 1, points=3, method='stiff')
            sage: bool(abs(T.values(x)[-1] - exp(-1.)) < 1e-8)
            True
            sage: T.energy_drift()
            Traceback (most recent call last):
            ...
            ModelError: energy_drift: the model has no energy integral (explicit time, dissipation or non-potential forces)
        """
        check_model_values(self, values)
        if callable(getattr(self, 'name', None)):
            options.setdefault('name', self.name())
        return _simulate(self.numerical_form(algorithm), values, initial, t_end, points=points,
                         t0=t0, method=method, rtol=rtol, atol=atol, backend=backend, **options)

    def code(self, language='python', cse=True):
        r"""
        Readable source code of the equations in ``language``
        (``'python'`` or ``'c'``): the mass matrix and the forcing
        (second-order equations) or the right-hand side and the matrix of
        the left-hand side (first order); see
        :func:`~sage_dynsym.numerics.codegen.generate_code`.

        EXAMPLES::

            sage: from sage_dynsym.analysis.motion import FirstOrderEquations
            sage: from sage_dynsym.numerics.methods import NumericalMethods
            sage: x, a = var('x a')
            sage: class Decay(NumericalMethods):
            ....:     def equations_record(self):
            ....:         return FirstOrderEquations([-a*x], [x])
            sage: print(Decay().code('c'))
            /* Right-hand side F of the equations dx/dt = F in x = (x),
               generated by sage_dynsym. Matrices are flat arrays, row by row.
               x_ = (x), p = (a) */
            #include <math.h>
            <BLANKLINE>
            void rhs(double t, const double *x_, const double *p,
                     double *F)
            {
                const double x = x_[0];
                const double a = p[0];
                F[0] = -a*x;
            }
        """
        return generate_code(self.numerical_form('equations'), language=language, cse=cse)

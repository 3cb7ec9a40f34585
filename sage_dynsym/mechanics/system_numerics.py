r"""
The numerics of a mechanical system

:class:`MechanicalNumerics` is a base class of
:class:`~sage_dynsym.mechanics.system.MechanicalSystem`: the numerical
methods every model has (see
:class:`~sage_dynsym.numerics.methods.NumericalMethods`, the same
arguments), with the right-hand side computed by the recursive algorithms
of rigid-body dynamics or from the Lagrange equations (the keyword
``algorithm``, see :mod:`~sage_dynsym.mechanics.recursive_numerics`).

EXAMPLES::

    sage: from sage_dynsym import MechanicalSystem, RigidBody
    sage: x, m, k = var('x m k')
    sage: S = MechanicalSystem([RigidBody('b', joint=[x, 0, 0], mass=m)], [x],
    ....:                      force_function=-k*x^2/2)
    sage: S.numerical_rhs({m: 1, k: 1}, algorithm='recursive')(0, [1.0, 0.0])
    array([ 0., -1.])
"""
from ..errors import ModelError
from ..numerics.rhs import RightHandSide, StateJacobian
from ..numerics.simulate import simulate as _simulate
from ..numerics.values import check_model_values
from .recursive_numerics import numerical_form

__all__ = ['MechanicalNumerics']


class MechanicalNumerics:
    r"""
    The numerical methods of a
    :class:`~sage_dynsym.mechanics.system.MechanicalSystem` (a base class
    of it, see the module documentation).

    EXAMPLES: see :class:`~sage_dynsym.mechanics.system.MechanicalSystem`.
    """

    def numerical_rhs(self, values, backend='auto', algorithm='auto', jacobian=False):
        r"""
        The compiled right-hand side `\dot x = f(t, x)`, `x = (q, \dot q)`,
        with the parameter values ``values``: by the recursive algorithms
        of rigid-body dynamics (``algorithm='recursive'``), from the
        Lagrange equations of :meth:`lagrangian` (``'equations'``), or the
        first when it applies (``'auto'``); see
        :mod:`~sage_dynsym.mechanics.recursive_numerics` and
        :func:`~sage_dynsym.numerics.rhs.numerical_rhs`.

        With ``jacobian=True``: the pair ``(f, jac)``, ``jac(t, x)`` the
        dense Jacobian of ``f`` with respect to the state, generated from
        the recursive algorithms differentiated and compiled like ``f``
        (a :class:`~sage_dynsym.numerics.rhs.StateJacobian`; for
        ``solve_ivp(..., jac=jac)``, linearizations at any state).

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem, RigidBody
            sage: x, m, k = var('x m k')
            sage: S = MechanicalSystem([RigidBody('b', joint=[x, 0, 0], mass=m)], [x],
            ....:                      force_function=-k*x^2/2)
            sage: S.numerical_rhs({m: 2, k: 8})(0, [1.0, 0.5])
            array([ 0.5, -4. ])
            sage: S.numerical_rhs({m: 2, k: 8}, algorithm='equations')(0, [1.0, 0.5])
            array([ 0.5, -4. ])

        The Jacobian of a pendulum, `\ddot\varphi = -(g/l)\sin\varphi`,
        at `\varphi = \pi/3`, and its eigenvalues there (a saddle: the
        state is not an equilibrium, the linearization is local)::

            sage: from sage_dynsym import UniformGravity
            sage: phi, l, g = var('phi l g')
            sage: P = MechanicalSystem([RigidBody('rod', rotations=[(1, phi)], mass=m,
            ....:                      mass_center=[0, 0, -l], inertia=diagonal_matrix([m*l^2, m*l^2, 0]))],
            ....:                      [phi], force_function=UniformGravity([0, 0, -g]))
            sage: f, jac = P.numerical_rhs({m: 1, l: 1, g: 9.81}, jacobian=True)
            sage: A = jac(0, [pi.n()/3, 0.0]); A
            array([[ 0.   ,  1.   ],
                   [-4.905,  0.   ]])
            sage: bool(abs(A[1, 0] + 9.81*cos(pi/3)) < 1e-14)
            True
        """
        check_model_values(self, values)
        form = numerical_form(self, algorithm)
        f = RightHandSide(form, values, backend)
        return (f, StateJacobian(form, values, backend)) if jacobian else f

    def numerical_linearization(self, values, state, t=0, backend='auto', algorithm='auto'):
        r"""
        The linearization of `\dot x = f(t, x)` at any state ``state`` (not
        only at equilibria): the Jacobian `\partial f/\partial x` there, as
        a matrix over ``RDF``, from the compiled Jacobian of
        :meth:`numerical_rhs` (``jacobian=True``). ``state`` is a dict over
        the coordinates and velocities or a sequence in the order
        `x = (q, \dot q)`. For the exact linearization about equilibria and
        steady motions, see :func:`~sage_dynsym.analysis.linear.linearize`.

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
        check_model_values(self, values)
        options.setdefault('name', self.name())
        return _simulate(numerical_form(self, algorithm), values, initial, t_end, points=points,
                         t0=t0, method=method, rtol=rtol, atol=atol, backend=backend, **options)

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

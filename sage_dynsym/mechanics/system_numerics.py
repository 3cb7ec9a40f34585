r"""
The numerics of a mechanical system

:class:`MechanicalNumerics` is a base class of
:class:`~sage_dynsym.mechanics.system.MechanicalSystem`: the numerical
methods every model has (:class:`~sage_dynsym.numerics.methods.NumericalMethods`:
right-hand side and its Jacobian, linearization at any state, simulation,
code), with one more way to compute the right-hand side: the recursive
algorithms of rigid-body dynamics besides the Lagrange equations (the
keyword ``algorithm``, see :mod:`~sage_dynsym.mechanics.recursive_numerics`).

EXAMPLES::

    sage: from sage_dynsym import MechanicalSystem, RigidBody
    sage: x, m, k = var('x m k')
    sage: S = MechanicalSystem([RigidBody('b', joint=[x, 0, 0], mass=m)], [x],
    ....:                      force_function=-k*x^2/2)
    sage: S.numerical_rhs({m: 1, k: 1}, algorithm='recursive')(0, [1.0, 0.0])
    array([ 0., -1.])
    sage: S.numerical_rhs({m: 2, k: 8}, algorithm='equations')(0, [1.0, 0.5])
    array([ 0.5, -4. ])

The Jacobian of a pendulum, `\ddot\varphi = -(g/l)\sin\varphi`, at
`\varphi = \pi/3` (generated from the recursive algorithms
differentiated)::

    sage: from sage_dynsym import UniformGravity
    sage: phi, l, g = var('phi l g')
    sage: P = MechanicalSystem([RigidBody('rod', rotations=[(1, phi)], mass=m,
    ....:                      mass_center=[0, 0, -l], inertia=diagonal_matrix([m*l^2, m*l^2, 0]))],
    ....:                      [phi], force_function=UniformGravity([0, 0, -g]))
    sage: f, jac = P.numerical_rhs({m: 1, l: 1, g: 9.81}, jacobian=True)
    sage: A = jac(0, [pi.n()/3, 0.0]); A
    array([[ 0.   ,  1.   ],
           [-4.905,  0.   ]])

A simulation (a mass on a spring, `x(t) = \cos 2t`) and the code of the
Lagrange equations::

    sage: T = S.simulate({m: 2, k: 8}, {x: 1, 'dx': 0}, pi, points=3)
    sage: T.values(x).round(8), T.energy_drift() < 1e-9
    (array([ 1., -1.,  1.]), True)
    sage: 'k*x' in str(S.code())
    True

TESTS::

    sage: S = MechanicalSystem([RigidBody('b', joint=[x, 0, 0], mass=m)], [x],
    ....:                      force_function=-k*x^2/2, positive=[m, k])
    sage: S.simulate({m: -2, k: 8}, {x: 1, 'dx': 0}, pi)
    Traceback (most recent call last):
    ...
    ModelError: values: m is declared positive, got -2
"""
from ..numerics.methods import NumericalMethods
from .recursive_numerics import ALGORITHMS, numerical_form

__all__ = ['MechanicalNumerics']


class MechanicalNumerics(NumericalMethods):
    r"""
    The numerical methods of a
    :class:`~sage_dynsym.mechanics.system.MechanicalSystem` (a base class
    of it, see the module documentation): those of every model, from the
    numerical form the system's ``algorithm`` chooses.

    EXAMPLES: see the module documentation.
    """

    ALGORITHMS = ALGORITHMS

    def numerical_form(self, algorithm='auto'):
        r"""
        The numerical form for ``algorithm``: ``'recursive'`` (the
        recursive algorithms of rigid-body dynamics, a
        :class:`~sage_dynsym.numerics.recursive.RecursiveForm`),
        ``'equations'`` (the Lagrange equations of :meth:`lagrangian`) or
        ``'auto'`` (the first where it applies); built once per system and
        algorithm (see :func:`~sage_dynsym.mechanics.recursive_numerics.numerical_form`).

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem, RigidBody
            sage: x, m = var('x m')
            sage: S = MechanicalSystem([RigidBody('b', joint=[x, 0, 0], mass=m)], [x])
            sage: S.numerical_form('equations')
            Numerical form M x'' = F in (x), parameters (m)
        """
        return numerical_form(self, algorithm)

r"""
The constraints of a mechanical system

:class:`SystemConstraints` is a base class of
:class:`~sage_dynsym.mechanics.system.MechanicalSystem`: its holonomic
constraints (checked by
:func:`~sage_dynsym.dynamics.holonomic.check_constraints`), its
constraints on the velocities, and the
:class:`~sage_dynsym.mechanics.constraint_set.ConstraintSet` that holds
them with their origins (given, or the contact of a rolling disk).

EXAMPLES::

    sage: from sage_dynsym import MechanicalSystem
    sage: x, y, l = var('x y l')
    sage: S = MechanicalSystem([], [x, y], constraints=[x^2 + y^2 == l^2])
    sage: S.constraints(), S.lagrangian().multipliers()
    ([-l^2 + x^2 + y^2], [mu1])
"""

__all__ = ['SystemConstraints']


class SystemConstraints:
    r"""
    The constraints of a
    :class:`~sage_dynsym.mechanics.system.MechanicalSystem` (a base class
    of it, see the module documentation).

    EXAMPLES: see :class:`~sage_dynsym.mechanics.system.MechanicalSystem`.
    """

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

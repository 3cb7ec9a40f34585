r"""
The kinematics of a mechanical system

:class:`SystemKinematics` is a base class of
:class:`~sage_dynsym.mechanics.system.MechanicalSystem`: the frames of its
bodies, their direction cosines, angular velocities, joint velocities and
positions, read from the system's
:class:`~sage_dynsym.mechanics.kinematics.Kinematics` (the rules are
those of :doc:`the method </method>`).

EXAMPLES::

    sage: from sage_dynsym import MechanicalSystem, RigidBody
    sage: a, b = var('a b')
    sage: S = MechanicalSystem([RigidBody('b', rotations=[(3, a), (1, b)])], [a, b])
    sage: S.direction_cosines(1)        # the body's axes in the inertial ones
    [        cos(a) -cos(b)*sin(a)  sin(a)*sin(b)]
    [        sin(a)  cos(a)*cos(b) -cos(a)*sin(b)]
    [             0         sin(b)         cos(b)]
"""

__all__ = ['SystemKinematics']


class SystemKinematics:
    r"""
    The kinematics of a
    :class:`~sage_dynsym.mechanics.system.MechanicalSystem` (a base class
    of it, see the module documentation).

    EXAMPLES: see :class:`~sage_dynsym.mechanics.system.MechanicalSystem`.
    """

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
        self._check_index(k, inertial=True)
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
        self._check_index(k, inertial=True)
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
        self._check_index(k, inertial=True)
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
        self._check_index(k, inertial=True)
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

r"""
The kinematics of a system of rigid bodies

A :class:`SystemKinematics` holds the bodies of a mechanical system, parents
before children, with its generalized coordinates, and gives the frames of
the bodies, their direction cosines, angular velocities, joint velocities
and positions (the rules are those of :doc:`the method </method>`), read
from a :class:`~sage_dynsym.mechanics.kinematics.Kinematics` over the
symbolic ring. It is what loads
(:meth:`~sage_dynsym.mechanics.loads.Load.generalized_forces`), force fields
(:meth:`~sage_dynsym.mechanics.force_functions.UniformGravity.evaluate`) and
rolling disks (:func:`~sage_dynsym.mechanics.rolling.rolling_contact`)
receive: the geometry of the system, not the whole system. A
:class:`~sage_dynsym.mechanics.system.MechanicalSystem` composes one (see
its :meth:`~sage_dynsym.mechanics.system.MechanicalSystem.kinematics`).

EXAMPLES::

    sage: from sage_dynsym.mechanics.system_kinematics import SystemKinematics
    sage: from sage_dynsym import RigidBody
    sage: a, b = var('a b')
    sage: K = SystemKinematics([RigidBody('b', rotations=[(3, a), (1, b)])], [a, b]); K
    Kinematics of 1 body in coordinates (a, b)
    sage: K.direction_cosines(1)        # the body's axes in the inertial ones
    [        cos(a) -cos(b)*sin(a)  sin(a)*sin(b)]
    [        sin(a)  cos(a)*cos(b) -cos(a)*sin(b)]
    [             0         sin(b)         cos(b)]
"""
import numbers

from sage.misc.cachefunc import cached_method
from sage.structure.sage_object import SageObject

from ..algebra.trigonometric import SymbolicBackend
from ..arguments import expression_list, is_integer
from ..errors import ModelError, brief
from ..symbols import acceleration, velocity
from .kinematics import Kinematics
from .rigid_body import RigidBody

__all__ = ['SystemKinematics', 'sorted_by_parents']


def sorted_by_parents(bodies):
    r"""
    ``(ordered, parents)``: the bodies ``bodies`` (any order, parents given
    by name, 1-based index in ``bodies`` or object) ordered parents first,
    and the 1-based parent index of each in that order (``parents[k]`` for
    body `k`, 0 for the inertial frame; ``parents[0]`` is ``None``).
    Unknown parents, duplicate names and cycles are refused.

    EXAMPLES::

        sage: from sage_dynsym import RigidBody
        sage: from sage_dynsym.mechanics.system_kinematics import sorted_by_parents
        sage: sorted_by_parents([RigidBody('c', parent='p'), RigidBody('p')])
        ([Rigid body 'p' (parent 0, rotations [], mass 0),
          Rigid body 'c' (parent p, rotations [], mass 0)],
         [None, 0, 1])
        sage: sorted_by_parents([RigidBody('p', parent='q'), RigidBody('q', parent='p')])
        Traceback (most recent call last):
        ...
        ModelError: bodies: the parents form a cycle: p -> q -> p
    """
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
    parents = [None] + [0 if parent_of[i] is None else position[parent_of[i]] for i in order]
    return [bodies[i] for i in order], parents


class SystemKinematics(SageObject):
    r"""
    The bodies of a mechanical system with its coordinates, and their
    kinematics (see the module documentation).

    INPUT:

    - ``bodies`` -- list of :class:`~sage_dynsym.mechanics.rigid_body.RigidBody`
      (any order: parents are resolved by name, index or object)
    - ``coordinates`` -- list of symbolic variables, the generalized
      coordinates

    Body `k` (1-based) is the `k`-th of :meth:`bodies`, parents before
    children; body 0 is the inertial frame.

    EXAMPLES::

        sage: from sage_dynsym import RigidBody
        sage: from sage_dynsym.mechanics.system_kinematics import SystemKinematics
        sage: a, l = var('a l')
        sage: K = SystemKinematics([RigidBody('c', parent='p', joint=[l, 0, 0]),
        ....:                       RigidBody('p', rotations=[(3, a)])], [a]); K
        Kinematics of 2 bodies in coordinates (a)
        sage: K.bodies(), K.given_names()
        ([Rigid body 'p' (parent 0, rotations [(3, a)], mass 0),
          Rigid body 'c' (parent p, rotations [], mass 0)],
         ['c', 'p'])
        sage: K.joint_velocity(2)
        (0, da*l, 0)

    TESTS::

        sage: K.angular_velocity(3)
        Traceback (most recent call last):
        ...
        ModelError: body index 3 out of range 1..2
        sage: SystemKinematics([RigidBody('b')], [a^2])
        Traceback (most recent call last):
        ...
        ModelError: coordinates: coordinates must be symbolic variables, got a^2
        sage: SystemKinematics(RigidBody('b'), [])
        Traceback (most recent call last):
        ...
        ModelError: bodies: expected a list of RigidBody, got Rigid body 'b' (parent 0, rotations [], mass 0); e.g. MechanicalSystem([RigidBody('b', joint=[x, 0, 0], mass=m)], [x])
        sage: SystemKinematics([RigidBody('b', velocity=[var('da')^2, 0, 0])], [a])
        Traceback (most recent call last):
        ...
        ModelError: b.velocity: the relative velocity must be linear in the velocities (da), got da^2
    """

    def __init__(self, bodies, coordinates):
        if not isinstance(bodies, (list, tuple)):
            raise ModelError(f"expected a list of RigidBody, got {brief(bodies)}; e.g. "
                             "MechanicalSystem([RigidBody('b', joint=[x, 0, 0], mass=m)], [x])",
                             entry="bodies")
        bodies = list(bodies)
        for i, body in enumerate(bodies):
            if not isinstance(body, RigidBody):
                raise ModelError(f"expected a RigidBody, got {body!r}", entry=f"bodies[{i}]")
        self._given_names = [b.name() for b in bodies]
        self._bodies, self._parents = sorted_by_parents(bodies)
        self._coordinates = expression_list(coordinates, "coordinates",
                                            expected="a list of symbolic variables")
        for q in self._coordinates:
            if not q.is_symbol():
                raise ModelError(f"coordinates must be symbolic variables, got {q}",
                                 entry="coordinates")
        self._velocities = [velocity(q) for q in self._coordinates]
        for body in self._bodies:
            # the kinetic energy must have the form (4), quadratic in the velocities
            for u in body.velocity() or ():
                if any(not u.diff(a, b).is_zero() for a in self._velocities
                       for b in self._velocities):
                    raise ModelError(f"the relative velocity must be linear in the velocities "
                                     f"({', '.join(map(str, self._velocities))}), got {u}",
                                     entry=f"{body.name()}.velocity")

    def _repr_(self):
        n = len(self._bodies)
        return (f"Kinematics of {n} bod{'y' if n == 1 else 'ies'} in coordinates "
                f"({', '.join(map(str, self._coordinates))})")

    def bodies(self):
        r"""
        The bodies, parents before children; body `k` (1-based) is
        ``bodies()[k-1]``.

        EXAMPLES: see :class:`SystemKinematics`.
        """
        return list(self._bodies)

    def given_names(self):
        r"""
        The body names in the order the bodies were given (a 1-based body
        index in the data of a system, for a load or a rolling disk, counts
        in this order).

        EXAMPLES: see :class:`SystemKinematics`.
        """
        return list(self._given_names)

    def parent_index(self, k):
        r"""
        The 1-based index of the parent of body ``k`` (0: inertial frame).

        EXAMPLES::

            sage: from sage_dynsym import RigidBody
            sage: from sage_dynsym.mechanics.system_kinematics import SystemKinematics
            sage: K = SystemKinematics([RigidBody('a'), RigidBody('b', parent='a')], [])
            sage: K.parent_index(2), K.parent_index(1)
            (1, 0)
        """
        self.check_index(k, inertial=True)
        return self._parents[k]

    def coordinates(self):
        r"""
        The generalized coordinates.

        EXAMPLES::

            sage: from sage_dynsym.mechanics.system_kinematics import SystemKinematics
            sage: SystemKinematics([], [var('x')]).coordinates()
            [x]
        """
        return list(self._coordinates)

    def velocities(self):
        r"""
        The velocity symbols ``d<q>`` of the coordinates.

        EXAMPLES::

            sage: from sage_dynsym.mechanics.system_kinematics import SystemKinematics
            sage: SystemKinematics([], [var('x')]).velocities()
            [dx]
        """
        return list(self._velocities)

    def accelerations(self):
        r"""
        The acceleration symbols ``dd<q>`` of the coordinates.

        EXAMPLES::

            sage: from sage_dynsym.mechanics.system_kinematics import SystemKinematics
            sage: SystemKinematics([], [var('x')]).accelerations()
            [ddx]
        """
        return [acceleration(q) for q in self._coordinates]

    def check_index(self, k, inertial=False):
        r"""
        Refuse ``k`` unless it is a 1-based body index (or 0, the inertial
        frame, where ``inertial``).

        EXAMPLES::

            sage: from sage_dynsym import RigidBody
            sage: from sage_dynsym.mechanics.system_kinematics import SystemKinematics
            sage: K = SystemKinematics([RigidBody('b')], [])
            sage: K.check_index(1); K.check_index(0, inertial=True)
            sage: K.check_index(0)
            Traceback (most recent call last):
            ...
            ModelError: body index 0 out of range 1..1
            sage: K.check_index('b')
            Traceback (most recent call last):
            ...
            ModelError: k: expected a body index 1..1, got 'b'
        """
        low = 0 if inertial else 1
        if not is_integer(k):
            raise ModelError(f"expected a body index {low}..{len(self._bodies)}"
                             f"{' (0: the inertial frame)' if inertial else ''}, got {brief(k)}",
                             entry="k")
        if not low <= k <= len(self._bodies):
            raise ModelError(f"body index {k} out of range {low}..{len(self._bodies)}")

    @cached_method
    def symbolic(self):
        r"""
        The :class:`~sage_dynsym.mechanics.kinematics.Kinematics` of the
        bodies over the symbolic ring (built once).

        EXAMPLES::

            sage: from sage_dynsym import RigidBody
            sage: from sage_dynsym.mechanics.system_kinematics import SystemKinematics
            sage: K = SystemKinematics([RigidBody('b', rotations=[(3, var('a'))])], [var('a')])
            sage: K.symbolic().recursive_applies()
            True
        """
        return Kinematics(self, SymbolicBackend())

    def tree_kinematics(self):
        r"""
        The kinematic pass of the recursive algorithms over the tree of the
        bodies, in the symbolic arithmetic (see
        :meth:`~sage_dynsym.mechanics.kinematics.Kinematics.tree_kinematics`):
        what loads are projected with.

        EXAMPLES::

            sage: from sage_dynsym import RigidBody
            sage: from sage_dynsym.mechanics.system_kinematics import SystemKinematics
            sage: a = var('a')
            sage: K = SystemKinematics([RigidBody('b', rotations=[(3, a)])], [a])
            sage: K.tree_kinematics().partial_angular_velocities(1)
            {0: (0, 0, 1)}
        """
        return self.symbolic().tree_kinematics()

    def frame_tree(self):
        r"""
        The :class:`~sage_dynsym.mechanics.frames.FrameTree` of all elementary
        rotations.

        EXAMPLES::

            sage: from sage_dynsym import RigidBody
            sage: from sage_dynsym.mechanics.system_kinematics import SystemKinematics
            sage: K = SystemKinematics([RigidBody('b', rotations=[(3, var('a'))])], [])
            sage: K.frame_tree().angle(K.body_frame(1))
            a
        """
        return self.symbolic().tree

    def body_frame(self, k):
        r"""
        The frame of body ``k`` in :meth:`frame_tree` (``0`` for ``k = 0``).

        EXAMPLES::

            sage: from sage_dynsym import RigidBody
            sage: from sage_dynsym.mechanics.system_kinematics import SystemKinematics
            sage: a, b = var('a b')
            sage: K = SystemKinematics([RigidBody('b', rotations=[(3, a), (1, b)])], [])
            sage: K.body_frame(0), K.body_frame(1)
            (0, 2)
        """
        self.check_index(k, inertial=True)
        return self.symbolic().body_frame(k)

    def direction_cosines(self, k, j=0):
        r"""
        The direction-cosine matrix `\alpha^{jk}`: columns are the axes of
        body ``k`` in the axes of body ``j`` (``j = 0``: inertial frame).

        EXAMPLES::

            sage: from sage_dynsym import RigidBody
            sage: from sage_dynsym.mechanics.system_kinematics import SystemKinematics
            sage: a = var('a')
            sage: SystemKinematics([RigidBody('b', rotations=[(3, a)])], [a]).direction_cosines(1)
            [ cos(a) -sin(a)       0]
            [ sin(a)  cos(a)       0]
            [      0       0       1]
        """
        self.check_index(k)
        return self.frame_tree().direction_cosines(self.body_frame(k), self.body_frame(j))

    def angular_velocity_vector(self, k):
        r"""
        The absolute angular velocity `W_k` as a
        :class:`~sage_dynsym.mechanics.frames.FrameVector` (each rotation rate
        about its own axis, in its own frame).

        EXAMPLES::

            sage: from sage_dynsym import RigidBody
            sage: from sage_dynsym.mechanics.system_kinematics import SystemKinematics
            sage: a = var('a')
            sage: K = SystemKinematics([RigidBody('b', rotations=[(3, a)])], [a])
            sage: K.angular_velocity_vector(1).parts()
            {1: (0, 0, da)}
        """
        self.check_index(k, inertial=True)
        return self.symbolic().angular_velocity(k)

    def angular_velocity(self, k):
        r"""
        `W_k`, the absolute angular velocity of body ``k`` in its own axes.

        EXAMPLES::

            sage: from sage_dynsym import RigidBody
            sage: from sage_dynsym.mechanics.system_kinematics import SystemKinematics
            sage: a, b = var('a b')
            sage: K = SystemKinematics([RigidBody('b', rotations=[(3, a), (1, b)])], [a, b])
            sage: K.angular_velocity(1)
            (db, da*sin(b), da*cos(b))
        """
        self.check_index(k)
        return self.angular_velocity_vector(k).components(self.body_frame(k))

    def relative_angular_velocity(self, k):
        r"""
        `\omega_k`, the angular velocity of body ``k`` relative to its
        parent, in the axes of body ``k``.

        EXAMPLES::

            sage: from sage_dynsym import RigidBody
            sage: from sage_dynsym.mechanics.system_kinematics import SystemKinematics
            sage: a, b = var('a b')
            sage: K = SystemKinematics([RigidBody('p', rotations=[(3, a)]),
            ....:                       RigidBody('c', parent='p', rotations=[(1, b)])], [a, b])
            sage: K.relative_angular_velocity(2), K.angular_velocity(2)
            ((db, 0, 0), (db, da*sin(b), da*cos(b)))
        """
        self.check_index(k)
        own = self.angular_velocity_vector(k) - self.angular_velocity_vector(self._parents[k])
        return own.components(self.body_frame(k))

    def joint_velocity_vector(self, k):
        r"""
        The absolute velocity `V_{0k} = V_{0j} + W_j \times r^j_{0k} +
        v^j_{0k}` of the joint point of body ``k``, as a
        :class:`~sage_dynsym.mechanics.frames.FrameVector`.

        EXAMPLES::

            sage: from sage_dynsym import RigidBody
            sage: from sage_dynsym.mechanics.system_kinematics import SystemKinematics
            sage: a, l = var('a l')
            sage: K = SystemKinematics([RigidBody('p', rotations=[(3, a)]),
            ....:                       RigidBody('c', parent='p', joint=[l, 0, 0])], [a])
            sage: K.joint_velocity_vector(2).parts()
            {1: (0, da*l, 0)}
        """
        self.check_index(k, inertial=True)
        return self.symbolic().joint_velocity(k)

    def joint_velocity(self, k):
        r"""
        `V_{0k}` in the axes of body ``k``.

        EXAMPLES::

            sage: from sage_dynsym import RigidBody
            sage: from sage_dynsym.mechanics.system_kinematics import SystemKinematics
            sage: z = var('z')
            sage: SystemKinematics([RigidBody('s', joint=[0, 0, z])], [z]).joint_velocity(1)
            (0, 0, dz)
        """
        self.check_index(k)
        return self.joint_velocity_vector(k).components(self.body_frame(k))

    def joint_position(self, k):
        r"""
        The position of the joint point `O_k` relative to the inertial
        origin, as a :class:`~sage_dynsym.mechanics.frames.FrameVector`.

        EXAMPLES::

            sage: from sage_dynsym import RigidBody
            sage: from sage_dynsym.mechanics.system_kinematics import SystemKinematics
            sage: a, l = var('a l')
            sage: K = SystemKinematics([RigidBody('p', rotations=[(3, a)]),
            ....:                       RigidBody('c', parent='p', joint=[l, 0, 0])], [a])
            sage: K.joint_position(2).components(0)
            (l*cos(a), l*sin(a), 0)
        """
        self.check_index(k, inertial=True)
        return self.symbolic().joint_position(k)

    def mass_center_position(self, k):
        r"""
        The position of the mass centre `C_k` relative to the inertial
        origin, as a :class:`~sage_dynsym.mechanics.frames.FrameVector`.

        EXAMPLES::

            sage: from sage_dynsym import RigidBody
            sage: from sage_dynsym.mechanics.system_kinematics import SystemKinematics
            sage: a, l = var('a l')
            sage: K = SystemKinematics([RigidBody('p', rotations=[(3, a)], mass_center=[l, 0, 0])],
            ....:                      [a])
            sage: K.mass_center_position(1).components(0)
            (l*cos(a), l*sin(a), 0)
        """
        self.check_index(k)
        return self.symbolic().mass_center_position(k)

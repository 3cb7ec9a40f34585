r"""
Trees of rigid bodies as neutral data for the recursive numerics

The recursive right-hand side (:mod:`~sage_dynsym.numerics.recursive`)
does not know the classes that describe mechanical systems: a model hands
over its bodies and forces as a :class:`BodyTree` of :class:`TreeBody`
records -- the fields of a body in :doc:`the method </method>` (parent,
elementary rotations, joint point, relative velocity, mass centre, mass,
inertia tensor about the joint point) -- with the forces acting on them:
uniform gravity, loads (:class:`TreeLoad`), a force function given only as
an expression, a Rayleigh dissipation function, generalized forces,
holonomic constraints and constraints on the velocities (rolling without
slipping).

EXAMPLES: a pendulum of length `l` turning about the `x` axis::

    sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
    sage: phi, m, l, g = var('phi m l g')
    sage: rod = TreeBody(0, rotations=[(1, phi)], mass=m, mass_center=[0, 0, -l])
    sage: T = BodyTree([rod], [phi], gravity=[0, 0, -g]); T
    Tree of 1 body in (phi), parameters (g, l, m)
    sage: T.bodies()[0].mass_center()
    (0, 0, -l)
"""
from sage.matrix.constructor import matrix
from sage.structure.sage_object import SageObject
from sage.symbolic.ring import SR

from ..errors import AnalysisError
from ..symbols import velocity, t as _t

__all__ = ['TreeBody', 'TreeLoad', 'BodyTree']


def _vector(value, entry):
    try:
        components = [SR(c) for c in value]
    except TypeError:
        components = []
    if len(components) != 3:
        raise AnalysisError(f"expected 3 components, got {value!r}", entry=entry)
    return tuple(components)


class TreeBody(SageObject):
    r"""
    One body of a :class:`BodyTree`.

    INPUT:

    - ``parent`` -- 0 (the inertial frame) or the 1-based index of the
      parent body, which comes earlier in the tree
    - ``rotations`` -- list of pairs ``(axis, angle)``: elementary rotations
      about the new axis 1, 2 or 3, from the parent's axes to the body's;
      the angles are expressions in the coordinates, parameters and `t`
    - ``joint`` -- the joint point `r_{0k}` in the parent's axes
    - ``velocity`` -- (optional) the relative velocity `v_{0k}` of the
      joint point in the parent's axes, linear in the velocities; default
      the time derivative of ``joint``
    - ``mass``, ``mass_center`` (in the body's axes), ``inertia`` (about the
      joint point, in the body's axes)
    - ``name`` -- (optional) a name for messages

    EXAMPLES::

        sage: from sage_dynsym.numerics.body_tree import TreeBody
        sage: x = var('x')
        sage: B = TreeBody(0, joint=[x, 0, 0], mass=2, name='slider'); B
        Tree body 'slider' (parent 0, rotations [])
        sage: B.joint(), B.velocity(), B.inertia()
        (
                                [0 0 0]
                                [0 0 0]
        (x, 0, 0), None, [0 0 0]
        )
    """

    def __init__(self, parent, rotations=(), joint=(0, 0, 0), velocity=None, mass=0,
                 mass_center=(0, 0, 0), inertia=None, name=None):
        self._parent = int(parent)
        self._rotations = [(int(axis), SR(angle)) for axis, angle in rotations]
        for axis, _ in self._rotations:
            if axis not in (1, 2, 3):
                raise AnalysisError(f"rotation axis must be 1, 2 or 3, got {axis}",
                                    entry="body tree")
        self._joint = _vector(joint, "joint")
        self._velocity = None if velocity is None else _vector(velocity, "velocity")
        self._mass = SR(mass)
        self._mass_center = _vector(mass_center, "mass_center")
        self._inertia = matrix(SR, 3, 3) if inertia is None else matrix(SR, inertia)
        self._name = name

    def _repr_(self):
        name = f" {self._name!r}" if self._name else ""
        return (f"Tree body{name} (parent {self._parent}, rotations "
                f"{[(a, e) for a, e in self._rotations]})")

    def parent(self):
        r"""The 1-based index of the parent, 0 for the inertial frame.

        EXAMPLES::

            sage: from sage_dynsym.numerics.body_tree import TreeBody
            sage: TreeBody(0).parent()
            0
        """
        return self._parent

    def rotations(self):
        r"""The elementary rotations, pairs ``(axis, angle)``.

        EXAMPLES::

            sage: from sage_dynsym.numerics.body_tree import TreeBody
            sage: TreeBody(0, rotations=[(3, var('a'))]).rotations()
            [(3, a)]
        """
        return list(self._rotations)

    def joint(self):
        r"""The joint point in the parent's axes.

        EXAMPLES: see the class documentation.
        """
        return self._joint

    def velocity(self):
        r"""The prescribed relative velocity of the joint point (``None``:
        the time derivative of :meth:`joint`).

        EXAMPLES: see the class documentation.
        """
        return self._velocity

    def mass(self):
        r"""The mass.

        EXAMPLES::

            sage: from sage_dynsym.numerics.body_tree import TreeBody
            sage: TreeBody(0, mass=var('m')).mass()
            m
        """
        return self._mass

    def mass_center(self):
        r"""The mass centre in the body's axes.

        EXAMPLES: see the module documentation.
        """
        return self._mass_center

    def inertia(self):
        r"""The inertia tensor about the joint point, in the body's axes.

        EXAMPLES: see the class documentation.
        """
        return self._inertia

    def name(self):
        r"""The name (``None`` if none).

        EXAMPLES: see the class documentation.
        """
        return self._name

    def expressions(self):
        r"""
        Every expression of the body (angles, joint, velocity, mass, mass
        centre, inertia), for finding its symbols.

        EXAMPLES::

            sage: from sage_dynsym.numerics.body_tree import TreeBody
            sage: len(TreeBody(0).expressions())
            16
        """
        out = [angle for _, angle in self._rotations] + list(self._joint)
        out += list(self._velocity or ()) + [self._mass] + list(self._mass_center)
        return out + self._inertia.list()


class TreeLoad(SageObject):
    r"""
    A force at a point of a body and/or a torque on it, as in
    :class:`~sage_dynsym.mechanics.loads.Load`: ``body`` the 1-based body
    index, ``point`` in the body's axes, ``force`` and ``torque`` (or
    ``None``) with components in the axes of ``axes`` (0: inertial, else a
    body index). The components may depend on the coordinates, the
    velocities and `t`.

    EXAMPLES::

        sage: from sage_dynsym.numerics.body_tree import TreeLoad
        sage: F = var('F')
        sage: TreeLoad(1, point=[0, 0, 1], force=[F, 0, 0])
        Tree load on body 1 at (0, 0, 1): force (F, 0, 0), torque None, axes 0
    """

    def __init__(self, body, point=(0, 0, 0), force=None, torque=None, axes=0):
        self.body, self.axes = int(body), int(axes)
        self.point = _vector(point, "load point")
        self.force = None if force is None else _vector(force, "load force")
        self.torque = None if torque is None else _vector(torque, "load torque")

    def _repr_(self):
        def text(v):
            return 'None' if v is None else f"({', '.join(map(str, v))})"
        return (f"Tree load on body {self.body} at {text(self.point)}: force "
                f"{text(self.force)}, torque {text(self.torque)}, axes {self.axes}")

    def expressions(self):
        r"""The expressions of the load, for finding its symbols.

        EXAMPLES::

            sage: from sage_dynsym.numerics.body_tree import TreeLoad
            sage: TreeLoad(1, torque=[0, 0, var('M')]).expressions()
            [0, 0, 0, 0, 0, M]
        """
        return list(self.point) + list(self.force or ()) + list(self.torque or ())


class BodyTree(SageObject):
    r"""
    A tree of rigid bodies with its forces (see the module documentation).

    INPUT:

    - ``bodies`` -- list of :class:`TreeBody`, parents before children
    - ``coordinates`` -- the generalized coordinates (symbols); the
      velocities are their ``d<q>`` symbols
    - ``gravity`` -- (optional) the acceleration of a uniform gravity field
      in the inertial axes
    - ``loads`` -- (optional) list of :class:`TreeLoad`
    - ``potential`` -- (default 0) a force function `U(q, t)` added to the
      one of gravity, given as an expression (its gradient is used)
    - ``dissipation`` -- (default 0) Rayleigh function `R(q, \dot q, t)`
    - ``forces`` -- (optional) generalized forces `Q_i`, one per coordinate
    - ``constraints`` -- (optional) holonomic constraints `f_j(q, t) = 0`
    - ``velocity_constraints`` -- (optional) constraints on the velocities
      `g_k = A_k(q, t)\dot q + b_k(q, t) = 0`, linear in them
    - ``parameters`` -- (optional) the parameters in the order wanted;
      default the other symbols, sorted by name

    The equations are those of the Lagrangian `T + U` (`U` of gravity and
    ``potential``) with `\partial R/\partial \dot q_i - Q_i` and the
    constraint forces added (`J^T\mu` and `A^T\lambda`, the multipliers
    eliminated).

    EXAMPLES: see the module documentation.

    TESTS::

        sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
        sage: BodyTree([TreeBody(2)], [])
        Traceback (most recent call last):
        ...
        AnalysisError: body tree: the parent of body 1 must be an earlier body or 0, got 2
        sage: x, dx = var('x dx')
        sage: BodyTree([], [x], velocity_constraints=[dx^2 - 1])
        Traceback (most recent call last):
        ...
        AnalysisError: body tree: the velocity constraint dx^2 - 1 is not linear in the velocities (dx)
    """

    def __init__(self, bodies, coordinates, gravity=None, loads=(), potential=0, dissipation=0,
                 forces=None, constraints=(), velocity_constraints=(), parameters=None):
        self._bodies = list(bodies)
        for k, body in enumerate(self._bodies, 1):
            if not 0 <= body.parent() < k:
                raise AnalysisError(f"the parent of body {k} must be an earlier body or 0, got "
                                    f"{body.parent()}", entry="body tree")
        self._q = [SR(q) for q in coordinates]
        self._dq = [velocity(q) for q in self._q]
        self._gravity = None if gravity is None else _vector(gravity, "gravity")
        self._loads = list(loads)
        self._potential = SR(potential)
        self._dissipation = SR(dissipation)
        n = len(self._q)
        self._forces = [SR(0)] * n if forces is None else [SR(f) for f in forces]
        if len(self._forces) != n:
            raise AnalysisError(f"expected {n} generalized forces, got {len(self._forces)}",
                                entry="body tree")
        self._constraints = [SR(f) for f in constraints]
        self._velocity_constraints = [SR(g) for g in velocity_constraints]
        for g in self._velocity_constraints:
            if any(not g.diff(a, b).is_zero() for a in self._dq for b in self._dq):
                raise AnalysisError(f"the velocity constraint {g} is not linear in the "
                                    f"velocities ({', '.join(map(str, self._dq))})",
                                    entry="body tree")
        if parameters is None:
            hidden = {str(v) for v in self._q + self._dq + [_t]}
            found = {}
            for e in self.expressions():
                for v in SR(e).variables():
                    if str(v) not in hidden:
                        found[str(v)] = v
            parameters = [found[k] for k in sorted(found)]
        self._parameters = [SR(p) for p in parameters]

    def _repr_(self):
        n = len(self._bodies)
        return (f"Tree of {n} bod{'y' if n == 1 else 'ies'} in "
                f"({', '.join(map(str, self._q))}), parameters "
                f"({', '.join(map(str, self._parameters))})")

    def bodies(self):
        r"""The :class:`TreeBody` records, parents first.

        EXAMPLES: see the module documentation.
        """
        return list(self._bodies)

    def coordinates(self):
        r"""The coordinates.

        EXAMPLES::

            sage: from sage_dynsym.numerics.body_tree import BodyTree
            sage: x = var('x'); BodyTree([], [x]).coordinates(), BodyTree([], [x]).velocities()
            ([x], [dx])
        """
        return list(self._q)

    def velocities(self):
        r"""The velocity symbols ``d<q>``.

        EXAMPLES: see :meth:`coordinates`.
        """
        return list(self._dq)

    def parameters(self):
        r"""The parameters (symbols other than the coordinates, velocities and `t`).

        EXAMPLES: see the module documentation.
        """
        return list(self._parameters)

    def gravity(self):
        r"""The acceleration of uniform gravity (``None`` if none).

        EXAMPLES::

            sage: from sage_dynsym.numerics.body_tree import BodyTree
            sage: BodyTree([], [], gravity=[0, 0, -10]).gravity()
            (0, 0, -10)
        """
        return self._gravity

    def loads(self):
        r"""The :class:`TreeLoad` records.

        EXAMPLES::

            sage: from sage_dynsym.numerics.body_tree import BodyTree
            sage: BodyTree([], []).loads()
            []
        """
        return list(self._loads)

    def potential(self):
        r"""The force function given as an expression (besides gravity).

        EXAMPLES::

            sage: from sage_dynsym.numerics.body_tree import BodyTree
            sage: x = var('x'); BodyTree([], [x], potential=-x^2/2).potential()
            -1/2*x^2
        """
        return self._potential

    def dissipation(self):
        r"""The Rayleigh dissipation function.

        EXAMPLES::

            sage: from sage_dynsym.numerics.body_tree import BodyTree
            sage: x, dx = var('x dx'); BodyTree([], [x], dissipation=dx^2/2).dissipation()
            1/2*dx^2
        """
        return self._dissipation

    def forces(self):
        r"""The generalized forces, one per coordinate.

        EXAMPLES::

            sage: from sage_dynsym.numerics.body_tree import BodyTree
            sage: BodyTree([], [var('x')]).forces()
            [0]
        """
        return list(self._forces)

    def constraints(self):
        r"""The holonomic constraints `f_j(q, t)` (each ``== 0``).

        EXAMPLES::

            sage: from sage_dynsym.numerics.body_tree import BodyTree
            sage: x, y = var('x y'); BodyTree([], [x, y], constraints=[x - y]).constraints()
            [x - y]
        """
        return list(self._constraints)

    def velocity_constraints(self):
        r"""The constraints on the velocities `g_k(q, \dot q, t)` (each ``== 0``).

        EXAMPLES::

            sage: from sage_dynsym.numerics.body_tree import BodyTree
            sage: x, y, dx, dy = var('x y dx dy')
            sage: BodyTree([], [x, y], velocity_constraints=[y*dx - dy]).velocity_constraints()
            [dx*y - dy]
        """
        return list(self._velocity_constraints)

    def expressions(self):
        r"""Every expression of the tree, for finding its symbols.

        EXAMPLES::

            sage: from sage_dynsym.numerics.body_tree import BodyTree
            sage: x, k = var('x k'); BodyTree([], [x], potential=-k*x^2).expressions()
            [-k*x^2, 0]
        """
        out = []
        for body in self._bodies:
            out += body.expressions()
        for load in self._loads:
            out += load.expressions()
        out += list(self._gravity or ()) + [self._potential, self._dissipation]
        out += [f for f in self._forces if not f.is_zero()]
        return out + self._constraints + self._velocity_constraints

r"""
Trees of rigid bodies: the description the rigid-body recursions read

A :class:`BodyTree` is the one description of a tree of rigid bodies that
the recursive algorithms (:meth:`BodyTree.kinematics`, in the arithmetic
chosen) read, for the compiled right-hand side
(:mod:`~sage_dynsym.numerics.recursive`) and for the symbolic recursive
equations of :mod:`~sage_dynsym.mechanics.kinematics` alike. It does not
know the classes that describe mechanical systems: it holds bodies with the
fields of a body in :doc:`the method </method>` (elementary rotations,
joint point, relative velocity, mass centre, mass, inertia tensor about the
joint point): :class:`TreeBody` objects -- such as a system's own
:class:`~sage_dynsym.mechanics.rigid_body.RigidBody` objects, a subclass --
with their parents' indices and the forces
acting on them:
uniform gravity, loads (:class:`TreeLoad` objects -- such as a system's
own :class:`~sage_dynsym.mechanics.loads.Load` objects), a force function given only as
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
import numbers

from sage.matrix.constructor import matrix
from sage.structure.sage_object import SageObject
from sage.symbolic.ring import SR

from ..errors import AnalysisError
from ..symbols import velocity, t as _t

__all__ = ['TreeBody', 'TreeLoad', 'BodyTree', 'body_expressions', 'body_reference_index']


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
    One rigid body of a tree: the fields that the recursive algorithms read
    (the fields of a body in :doc:`the method </method>`).

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

    The bodies of a mechanical system,
    :class:`~sage_dynsym.mechanics.rigid_body.RigidBody`, are tree bodies
    with a name, a parent given by name and checks of their data: the
    fields are converted by the methods ``_parent_of``, ``_rotation_of``,
    ``_vector_of``, ``_mass_of`` and ``_inertia_of``, which a subclass
    overrides to check more and to name the entry of the description in
    its errors.

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

    TESTS::

        sage: TreeBody(0, rotations=[(4, x)])
        Traceback (most recent call last):
        ...
        AnalysisError: body tree: rotation axis must be 1, 2 or 3, got 4
        sage: TreeBody(0, joint=[x, 0])
        Traceback (most recent call last):
        ...
        AnalysisError: joint: expected 3 components, got [x, 0]
        sage: TreeBody(0).inertia().is_immutable()
        True
    """

    def __init__(self, parent, rotations=(), joint=(0, 0, 0), velocity=None, mass=0,
                 mass_center=(0, 0, 0), inertia=None, name=None):
        self._name = name
        self._parent = self._parent_of(parent)
        self._rotations = [self._rotation_of(i, rotation) for i, rotation in enumerate(rotations)]
        self._joint = self._vector_of(joint, "joint")
        self._velocity = None if velocity is None else self._vector_of(velocity, "velocity")
        self._mass_center = self._vector_of(mass_center, "mass_center")
        self._mass = self._mass_of(mass)
        self._inertia = self._inertia_of(inertia)

    # the conversions of the fields (a subclass checks more) ------------------

    def _parent_of(self, parent):
        return int(parent)

    def _rotation_of(self, i, rotation):
        axis, angle = int(rotation[0]), SR(rotation[1])
        if axis not in (1, 2, 3):
            raise AnalysisError(f"rotation axis must be 1, 2 or 3, got {axis}",
                                entry="body tree")
        return axis, angle

    def _vector_of(self, value, field):
        return _vector(value, field)

    def _mass_of(self, mass):
        return SR(mass)

    def _inertia_of(self, inertia):
        tensor = matrix(SR, 3, 3) if inertia is None else matrix(SR, inertia)
        tensor.set_immutable()
        return tensor

    def _repr_(self):
        name = f" {self._name!r}" if self._name else ""
        return (f"Tree body{name} (parent {self._parent}, rotations "
                f"{[(a, e) for a, e in self._rotations]})")

    def parent(self):
        r"""The parent: the 1-based index of the parent body, 0 for the
        inertial frame (a :class:`~sage_dynsym.mechanics.rigid_body.RigidBody`
        keeps it as given: also a name or the parent body, which its system
        turns into the index, see
        :meth:`~sage_dynsym.mechanics.system_kinematics.SystemKinematics.parent_index`).

        EXAMPLES::

            sage: from sage_dynsym.numerics.body_tree import TreeBody
            sage: TreeBody(0).parent(), TreeBody(2).parent()
            (0, 2)
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
        return body_expressions(self)

    def is_massless(self):
        r"""Whether mass and inertia are both zero (a body that only carries a frame).

        EXAMPLES::

            sage: from sage_dynsym.numerics.body_tree import TreeBody
            sage: TreeBody(0).is_massless(), TreeBody(0, mass=1).is_massless()
            (True, False)
        """
        return self._mass.is_zero() and self._inertia.is_zero()


def body_expressions(body):
    r"""
    Every expression of ``body`` (a :class:`TreeBody`, such as a
    :class:`~sage_dynsym.mechanics.rigid_body.RigidBody`):
    angles, joint, velocity, mass, mass centre, inertia, for finding its
    symbols.

    EXAMPLES::

        sage: from sage_dynsym.numerics.body_tree import TreeBody, body_expressions
        sage: body_expressions(TreeBody(0, rotations=[(3, var('a'))], mass=var('m')))[:5]
        [a, 0, 0, 0, m]
    """
    out = [angle for _, angle in body.rotations()] + list(body.joint())
    out += list(body.velocity() or ()) + [body.mass()] + list(body.mass_center())
    return out + body.inertia().list()


def body_reference_index(bodies, reference, entry, inertial=True):
    r"""
    The 1-based index among ``bodies`` (a list of :class:`TreeBody`) of the
    body ``reference``: its index, or its name (:meth:`TreeBody.name`);
    ``0`` is the inertial frame when ``inertial``.
    :class:`~sage_dynsym.errors.AnalysisError` naming ``entry`` if there is
    no such body.

    EXAMPLES::

        sage: from sage_dynsym.numerics.body_tree import TreeBody, body_reference_index
        sage: bodies = [TreeBody(0, name='cart'), TreeBody(1, name='arm')]
        sage: body_reference_index(bodies, 'arm', 'load'), body_reference_index(bodies, 0, 'axes')
        (2, 0)
        sage: body_reference_index(bodies, 'slider', 'load')
        Traceback (most recent call last):
        ...
        AnalysisError: load: unknown body 'slider'; known bodies are: cart, arm
        sage: body_reference_index(bodies, 0, 'load', inertial=False)
        Traceback (most recent call last):
        ...
        AnalysisError: load: body index 0 out of range 1..2
    """
    if isinstance(reference, str):
        for k, body in enumerate(bodies, 1):
            if body.name() == reference:
                return k
        names = ', '.join(str(body.name()) for body in bodies)
        raise AnalysisError(f"unknown body {reference!r}; known bodies are: "
                            f"{names or '(none)'}", entry=entry)
    low = 0 if inertial else 1
    if not low <= reference <= len(bodies):
        raise AnalysisError(f"body index {reference} out of range {low}..{len(bodies)}",
                            entry=entry)
    return int(reference)


class TreeLoad(SageObject):
    r"""
    A force at a point of a body and/or a torque on it: the fields of a
    load that the recursive algorithms read
    (:func:`~sage_dynsym.numerics.newton_euler.load_forces`).

    INPUT:

    - ``body`` -- the loaded body: its 1-based index in the tree or its
      name (:meth:`TreeBody.name`)
    - ``point`` -- (default: the joint point) the point of application, in
      the body's axes
    - ``force``, ``torque`` -- (default: none) the components of the force
      and of the torque, in ``axes``
    - ``axes`` -- (default: 0) the axes of the components, fixed in them:
      0 for the inertial frame, or a body (index or name)

    The components may depend on the coordinates, the velocities, the
    parameters and `t`. A :class:`BodyTree` finds the bodies named by its
    loads (:meth:`BodyTree.body_index`).

    The loads of a mechanical system,
    :class:`~sage_dynsym.mechanics.loads.Load`, are tree loads with the
    checks of a description: the fields are converted by the methods
    ``_reference_of`` and ``_vector_of``, which a subclass overrides to
    check more and to name the entry of the description in its errors.

    EXAMPLES::

        sage: from sage_dynsym.numerics.body_tree import TreeLoad
        sage: F = var('F')
        sage: P = TreeLoad(1, point=[0, 0, 1], force=[F, 0, 0]); P
        Tree load on body 1 at (0, 0, 1): force (F, 0, 0), torque None, axes 0
        sage: P.body(), P.point(), P.force(), P.torque(), P.axes()
        (1, (0, 0, 1), (F, 0, 0), None, 0)
        sage: TreeLoad('arm', torque=[0, 0, F], axes='arm').subs({F: 2})
        Tree load on body 'arm' at (0, 0, 0): force None, torque (0, 0, 2), axes 'arm'

    TESTS::

        sage: TreeLoad(0, force=[1, 0, 0])
        Traceback (most recent call last):
        ...
        AnalysisError: load body: expected a body index >= 1 or a body name, got 0
        sage: TreeLoad(1, force=[1, 0])
        Traceback (most recent call last):
        ...
        AnalysisError: load force: expected 3 components, got [1, 0]
    """

    def __init__(self, body, point=(0, 0, 0), force=None, torque=None, axes=0):
        self._body = self._reference_of(body, "body")
        self._point = self._vector_of((0, 0, 0) if point is None else point, "point")
        self._force = None if force is None else self._vector_of(force, "force")
        self._torque = None if torque is None else self._vector_of(torque, "torque")
        self._axes = self._reference_of(axes, "axes")

    # the conversions of the fields (a subclass checks more) ------------------

    def _reference_of(self, reference, field):
        if isinstance(reference, str):
            return reference
        low = 0 if field == 'axes' else 1
        if not isinstance(reference, numbers.Integral) or reference < low:
            raise AnalysisError(f"expected a body index >= {low} or a body name, got "
                                f"{reference!r}", entry=f"load {field}")
        return int(reference)

    def _vector_of(self, value, field):
        return _vector(value, f"load {field}")

    def _repr_(self):
        def text(v):
            return 'None' if v is None else f"({', '.join(map(str, v))})"
        return (f"Tree load on body {self._body!r} at {text(self._point)}: force "
                f"{text(self._force)}, torque {text(self._torque)}, axes {self._axes!r}")

    def body(self):
        r"""The loaded body, as given: its name or 1-based index.

        EXAMPLES: see the class documentation.
        """
        return self._body

    def point(self):
        r"""The point of application, in the body's axes.

        EXAMPLES: see the class documentation.
        """
        return self._point

    def force(self):
        r"""The force components in :meth:`axes` (``None`` if no force).

        EXAMPLES: see the class documentation.
        """
        return self._force

    def torque(self):
        r"""The torque components in :meth:`axes` (``None`` if no torque).

        EXAMPLES: see the class documentation.
        """
        return self._torque

    def axes(self):
        r"""The axes of the components: ``0`` (inertial), or a body's name or index.

        EXAMPLES: see the class documentation.
        """
        return self._axes

    def expressions(self):
        r"""The expressions of the load (point, force, torque components),
        for finding its symbols.

        EXAMPLES::

            sage: from sage_dynsym.numerics.body_tree import TreeLoad
            sage: TreeLoad(1, torque=[0, 0, var('M')]).expressions()
            [0, 0, 0, 0, 0, M]
        """
        return list(self._point) + list(self._force or ()) + list(self._torque or ())

    def subs(self, values):
        r"""
        The load (of the same class) with ``values`` (a dictionary
        ``{symbol: value}``) substituted.

        EXAMPLES: see the class documentation.
        """
        def sub(v):
            return None if v is None else [SR(c).subs(values) for c in v]
        return type(self)(self._body, point=sub(self._point), force=sub(self._force),
                          torque=sub(self._torque), axes=self._axes)


class BodyTree(SageObject):
    r"""
    A tree of rigid bodies with its forces (see the module documentation).

    INPUT:

    - ``bodies`` -- list of :class:`TreeBody`, parents before children
      (also the :class:`~sage_dynsym.mechanics.rigid_body.RigidBody`
      objects of a mechanical system: the tree holds them, it does not
      copy them)
    - ``coordinates`` -- the generalized coordinates (symbols); the
      velocities are their ``d<q>`` symbols
    - ``gravity`` -- (optional) the acceleration of a uniform gravity field
      in the inertial axes
    - ``loads`` -- (optional) list of :class:`TreeLoad` (also the
      :class:`~sage_dynsym.mechanics.loads.Load` objects of a mechanical
      system, which name their bodies: the tree holds them, it does not
      copy them)
    - ``potential`` -- (default 0) a force function `U(q, t)` added to the
      one of gravity, given as an expression (its gradient is used)
    - ``dissipation`` -- (default 0) Rayleigh function `R(q, \dot q, t)`
    - ``forces`` -- (optional) generalized forces `Q_i`, one per coordinate
    - ``constraints`` -- (optional) holonomic constraints `f_j(q, t) = 0`
    - ``velocity_constraints`` -- (optional) constraints on the velocities
      `g_k = A_k(q, t)\dot q + b_k(q, t) = 0`, linear in them
    - ``parameters`` -- (optional) the parameters in the order wanted;
      default the other symbols, sorted by name
    - ``parents`` -- (optional) per body the 1-based index of its parent,
      0 for the inertial frame; default the bodies' own ``parent()``

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
                 forces=None, constraints=(), velocity_constraints=(), parameters=None,
                 parents=None):
        self._bodies = list(bodies)
        self._parents = [body.parent() for body in self._bodies] if parents is None else [
            int(j) for j in parents]
        for k, j in enumerate(self._parents, 1):
            if not (isinstance(j, int) and 0 <= j < k):
                raise AnalysisError(f"the parent of body {k} must be an earlier body or 0, got "
                                    f"{j}", entry="body tree")
        self._q = [SR(q) for q in coordinates]
        self._dq = [velocity(q) for q in self._q]
        self._gravity = None if gravity is None else _vector(gravity, "gravity")
        self._loads = list(loads)
        for i, load in enumerate(self._loads):
            self.body_index(load.body(), f"loads[{i}].body")
            self.body_index(load.axes(), f"loads[{i}].axes")
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
        # found when first asked for: the symbolic kinematics never needs them
        self._parameters = None if parameters is None else [SR(p) for p in parameters]

    def _repr_(self):
        n = len(self._bodies)
        return (f"Tree of {n} bod{'y' if n == 1 else 'ies'} in "
                f"({', '.join(map(str, self._q))}), parameters "
                f"({', '.join(map(str, self.parameters()))})")

    def bodies(self):
        r"""The :class:`TreeBody` records, parents first.

        EXAMPLES: see the module documentation.
        """
        return list(self._bodies)

    def body_index(self, reference, entry="load"):
        r"""
        The 1-based index of the body ``reference`` (its index or its name,
        as a load gives it; 0: the inertial frame), see
        :func:`body_reference_index`.

        EXAMPLES::

            sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody, TreeLoad
            sage: x = var('x')
            sage: T = BodyTree([TreeBody(0, name='cart'), TreeBody(1, joint=[x, 0, 0], name='bob')],
            ....:              [x], loads=[TreeLoad('bob', force=[1, 0, 0], axes='cart')])
            sage: [(T.body_index(P.body()), T.body_index(P.axes())) for P in T.loads()]
            [(2, 1)]

        TESTS::

            sage: BodyTree([TreeBody(0, name='cart')], [], loads=[TreeLoad('bob', force=[1, 0, 0])])
            Traceback (most recent call last):
            ...
            AnalysisError: loads[0].body: unknown body 'bob'; known bodies are: cart
        """
        return body_reference_index(self._bodies, reference, entry)

    def with_forces(self, **forces):
        r"""
        The tree of the same bodies (not copied) and coordinates with the
        forces ``forces`` (the keywords of the class: ``gravity``,
        ``loads``, ``potential``, ...) instead of these.

        EXAMPLES::

            sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
            sage: x = var('x'); T = BodyTree([TreeBody(0, joint=[x, 0, 0], mass=1)], [x])
            sage: U = T.with_forces(gravity=[-10, 0, 0]); U
            Tree of 1 body in (x), parameters ()
            sage: U.gravity(), U.bodies()[0] is T.bodies()[0]
            ((-10, 0, 0), True)
        """
        return BodyTree(self._bodies, self._q, parents=self._parents, **forces)

    def parent(self, k):
        r"""The index of the parent of body ``k`` (1-based; 0: the inertial frame).

        EXAMPLES::

            sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
            sage: T = BodyTree([TreeBody(0), TreeBody(1), TreeBody(1)], [])
            sage: [T.parent(k) for k in (1, 2, 3)]
            [0, 1, 1]
        """
        return self._parents[k - 1]

    def kinematics(self, arithmetic='symbolic', values=None):
        r"""
        The kinematic pass of the recursive algorithms over this tree (a
        :class:`~sage_dynsym.numerics.tree_kinematics.TreeKinematics`), in
        the arithmetic chosen (as SageManifolds' ``calc_method``):

        - ``'symbolic'`` -- Sage's symbolic expressions
          (:class:`~sage_dynsym.numerics.spatial.SymbolicArithmetic`), as
          the symbolic equations of motion use it;
        - ``'graph'`` -- a new
          :class:`~sage_dynsym.numerics.graph.ExpressionGraph`, to be
          compiled (see :func:`~sage_dynsym.numerics.recursive.graph_kinematics`;
          ``values``: parameters folded into it as numbers);
        - or an arithmetic object (see :mod:`~sage_dynsym.numerics.spatial`).

        EXAMPLES: the Newton--Euler terms of a pendulum in both arithmetics::

            sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
            sage: from sage_dynsym.numerics.newton_euler import generalized_bias_forces
            sage: phi, m, l, g = var('phi m l g')
            sage: T = BodyTree([TreeBody(0, rotations=[(1, phi)], mass=m, mass_center=[0, 0, -l])],
            ....:              [phi], gravity=[0, 0, -g])
            sage: generalized_bias_forces(T.kinematics())
            [g*l*m*sin(phi)]
            sage: K = T.kinematics('graph', {g: 9.81})
            sage: [K.G.show(e) for e in generalized_bias_forces(K)]
            ['(9.81*sin(x[0]))*(p[0]*p[1])']

        TESTS::

            sage: T.kinematics('numbers')
            Traceback (most recent call last):
            ...
            AnalysisError: arithmetic: must be 'symbolic', 'graph' or an arithmetic object, got 'numbers'
        """
        from .tree_kinematics import TreeKinematics
        if arithmetic == 'graph':
            from .recursive import graph_kinematics
            return graph_kinematics(self, values)
        if arithmetic == 'symbolic':
            from .spatial import SymbolicArithmetic
            arithmetic = SymbolicArithmetic()
        elif isinstance(arithmetic, str) or not hasattr(arithmetic, 'mul'):
            raise AnalysisError(f"must be 'symbolic', 'graph' or an arithmetic object, got "
                                f"{arithmetic!r}", entry="arithmetic")
        return TreeKinematics(self, arithmetic)

    def varying_inertia(self):
        r"""
        The index of the first body whose mass, mass centre or inertia
        depends on the coordinates, the velocities or `t` (``None`` if
        none does: the recursive algorithms need constant inertias).

        EXAMPLES::

            sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
            sage: x, m = var('x m')
            sage: BodyTree([TreeBody(0, joint=[x, 0, 0], mass=m)], [x]).varying_inertia() is None
            True
            sage: BodyTree([TreeBody(0), TreeBody(1, mass=m*x)], [x]).varying_inertia()
            2
        """
        dynamic = set(self._q) | set(self._dq) | {_t}
        for k, body in enumerate(self._bodies, 1):
            data = [body.mass()] + list(body.mass_center()) + body.inertia().list()
            if any(dynamic.intersection(SR(e).variables()) for e in data):
                return k
        return None

    def nonlinear_velocity(self):
        r"""
        The index of the first body whose prescribed relative velocity is
        not linear in the velocities (``None`` if every one is: the
        recursive algorithms need linear ones, see
        :meth:`~sage_dynsym.numerics.tree_kinematics.TreeKinematics.columns`).

        EXAMPLES::

            sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
            sage: x, dx = var('x dx')
            sage: screw = TreeBody(0, joint=[x, 0, 0], velocity=[2*dx, 0, x*dx])
            sage: BodyTree([screw], [x]).nonlinear_velocity() is None
            True
            sage: BodyTree([screw, TreeBody(1, velocity=[dx^2, 0, 0])], [x]).nonlinear_velocity()
            2
        """
        for k, body in enumerate(self._bodies, 1):
            if body.velocity() is not None and any(
                    not SR(u).diff(a, b).is_zero() for u in body.velocity()
                    for a in self._dq for b in self._dq):
                return k
        return None

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
        if self._parameters is None:
            hidden = {str(v) for v in self._q + self._dq + [_t]}
            found = {}
            for e in self.expressions():
                for v in SR(e).variables():
                    if str(v) not in hidden:
                        found[str(v)] = v
            self._parameters = [found[k] for k in sorted(found)]
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
        r"""The loads (:class:`TreeLoad` objects), as given.

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
            out += body_expressions(body)
        for load in self._loads:
            out += load.expressions()
        out += list(self._gravity or ()) + [self._potential, self._dissipation]
        out += [f for f in self._forces if not f.is_zero()]
        return out + self._constraints + self._velocity_constraints

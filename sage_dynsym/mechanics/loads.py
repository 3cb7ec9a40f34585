r"""
Loads on bodies: forces at body points and torques

A :class:`Load` is a force applied at a point of a body and/or a torque
(a couple) on that body. The point is given in the body's own axes; the
force and torque components are given in the axes of the inertial frame
(``axes=0``) or of a named body: they stay fixed in those axes (dead loads;
a follower force on a body is given in that body's axes).

A load enters the Lagrange equations through its generalized forces, by
virtual power: with `v_P` the absolute velocity of the point `P` and `W_k`
the absolute angular velocity of the body,

.. MATH::

    Q_i = F \cdot \frac{\partial v_P}{\partial \dot q_i}
        + M \cdot \frac{\partial W_k}{\partial \dot q_i},

and `Q_i` appears on the right-hand side of the Lagrange equations with the
same sign as the generalized forces given directly
(``forces=`` of :class:`~sage_dynsym.mechanics.system.MechanicalSystem`):

.. MATH::

    \frac{d}{dt}\frac{\partial L}{\partial \dot q_i}
    - \frac{\partial L}{\partial q_i}
    + \frac{\partial R}{\partial \dot q_i} = Q_i .

An interaction force between two bodies (a spring or an actuator between
them) is two opposite loads, one on each body.

EXAMPLES:

A force `F` along the inertial `y` axis at the tip of a rod pendulum of
length `l` hanging from a pivot (the rod turned by `\theta` about the
`x` axis) has the moment `F l \cos\theta` about the pivot::

    sage: from sage_dynsym import MechanicalSystem, RigidBody
    sage: from sage_dynsym.mechanics.loads import Load
    sage: theta, l, m, F = var('theta l m F')
    sage: rod = RigidBody('rod', rotations=[(1, theta)], mass_center=[0, 0, -l/2], mass=m)
    sage: tip = Load('rod', point=[0, 0, -l], force=[0, F, 0])
    sage: S = MechanicalSystem([rod], [theta], loads=[tip])
    sage: S.generalized_forces()
    [F*l*cos(theta)]

Two opposite loads: a spring of stiffness `k` between two sliders on the
`x` axis (the force on ``b`` is `-k(x_b - x_a)`, the one on ``a`` its
opposite); the generalized forces are those of the potential
`-k(x_b - x_a)^2/2`::

    sage: xa, xb, k = var('xa xb k')
    sage: a = RigidBody('a', joint=[xa, 0, 0], mass=m)
    sage: b = RigidBody('b', joint=[xb, 0, 0], mass=m)
    sage: spring = [Load('b', force=[-k*(xb - xa), 0, 0]), Load('a', force=[k*(xb - xa), 0, 0])]
    sage: MechanicalSystem([a, b], [xa, xb], loads=spring).generalized_forces()
    [-k*(xa - xb), k*(xa - xb)]
"""
import numbers

from ..errors import AnalysisError, ModelError
from ..io.fields import check_mapping
from ..numerics.body_tree import TreeLoad, body_reference_index
from .rigid_body import RigidBody, as_vector3

__all__ = ['LOAD_KEYS', 'Load', 'load_list', 'body_index']

#: The keys of a load (in a description file or a dictionary).
LOAD_KEYS = ('body', 'point', 'force', 'torque', 'axes')


def _check_reference(value, entry, inertial):
    # 0 (when the inertial frame is allowed), a body name, a 1-based index or a body
    if isinstance(value, RigidBody):
        return value.name()
    if isinstance(value, str) and value:
        return value
    if isinstance(value, numbers.Integral) and not isinstance(value, bool) and (
            value > 0 or (inertial and value == 0)):
        return int(value)
    expected = "0 (the inertial frame), a body name or a 1-based body index" if inertial \
        else "a body name or a 1-based body index"
    raise ModelError(f"expected {expected}, got {value!r}", entry=entry)


class Load(TreeLoad):
    r"""
    A force at a point of a body and/or a torque on it: a
    :class:`~sage_dynsym.numerics.body_tree.TreeLoad` (the fields that the
    recursions read, with their accessors) with its bodies given by name,
    index or object and the checks of a description.

    INPUT:

    - ``body`` -- the body: its name, its 1-based index, or the
      :class:`~sage_dynsym.mechanics.rigid_body.RigidBody`
    - ``point`` -- (default: the joint point `O_k`) the point of application,
      in the body's own axes
    - ``force`` -- (default: none) the force components, in ``axes``
    - ``torque`` -- (default: none) the torque components, in ``axes``
    - ``axes`` -- (default: 0) the axes of the force and torque
      components: ``0`` for the inertial frame, or a body (name, index or
      object); the components are fixed in those axes

    The components may depend on the coordinates, the velocities, the
    parameters and ``t``.

    EXAMPLES::

        sage: from sage_dynsym.mechanics.loads import Load
        sage: Load('arm', point=[0, 0, 1], force=[var('F'), 0, 0])
        Load on 'arm' at (0, 0, 1): force (F, 0, 0), in the inertial axes
        sage: Load('arm', torque=[0, 0, var('M')], axes='arm')
        Load on 'arm' at (0, 0, 0): torque (0, 0, M), in the axes of 'arm'

    The fields and their accessors are those of a tree load, which the
    recursive algorithms read::

        sage: from sage_dynsym.numerics.body_tree import TreeLoad
        sage: F, l = var('F l')
        sage: P = Load('b', point=[0, 0, l], force=[F, 0, 0]); isinstance(P, TreeLoad)
        True
        sage: P.body(), P.point(), P.force(), P.torque(), P.axes(), P.expressions()
        ('b', (0, 0, l), (F, 0, 0), None, 0, [0, 0, l, F, 0, 0])
        sage: P.subs({F: 2})
        Load on 'b' at (0, 0, l): force (2, 0, 0), in the inertial axes

    TESTS::

        sage: Load('arm', force=[1, 2])
        Traceback (most recent call last):
        ...
        ModelError: force: expected a list of 3 components, got 2
        sage: Load('arm')
        Traceback (most recent call last):
        ...
        ModelError: force: a load needs a force, a torque or both
        sage: Load(0, force=[1, 0, 0])
        Traceback (most recent call last):
        ...
        ModelError: body: expected a body name or a 1-based body index, got 0
    """

    def __init__(self, body, point=(0, 0, 0), force=None, torque=None, axes=0):
        super().__init__(body, point=point, force=force, torque=torque, axes=axes)
        if self._force is None and self._torque is None:
            raise ModelError("a load needs a force, a torque or both", entry="force")

    # the conversions of TreeLoad, with the checks of a description and the
    # entries named as there

    def _reference_of(self, reference, field):
        return _check_reference(reference, field, inertial=field == 'axes')

    def _vector_of(self, value, field):
        return as_vector3(value, field)

    @classmethod
    def from_value(cls, value, entry):
        r"""
        A :class:`Load` from a :class:`Load` or a dictionary with the keys
        ``body``, ``point``, ``force``, ``torque``, ``axes``; errors name
        ``entry`` (e.g. ``loads[2]``).

        EXAMPLES::

            sage: from sage_dynsym.mechanics.loads import Load
            sage: Load.from_value({'body': 'b', 'force': [1, 0, 0]}, 'loads[0]')
            Load on 'b' at (0, 0, 0): force (1, 0, 0), in the inertial axes
            sage: Load.from_value({'body': 'b', 'pont': [1, 0, 0]}, 'loads[1]')
            Traceback (most recent call last):
            ...
            ModelError: loads[1]: unknown key 'pont'; a load has the keys body, point, force, torque, axes
            sage: Load.from_value({'body': 'b', 'point': [1, 0], 'force': [1, 0, 0]}, 'loads[2]')
            Traceback (most recent call last):
            ...
            ModelError: loads[2].point: expected a list of 3 components, got 2
        """
        if isinstance(value, Load):
            return value
        check_mapping(value, LOAD_KEYS, "a load", entry, "a Load or a dictionary")
        if 'body' not in value:
            raise ModelError("missing key 'body'", entry=entry)
        try:
            return cls(**value)
        except ModelError as err:
            raise type(err)(err.message, entry=f"{entry}.{err.entry}") from err

    def _repr_(self):
        parts = []
        if self._force is not None:
            parts.append("force ({})".format(", ".join(map(str, self._force))))
        if self._torque is not None:
            parts.append("torque ({})".format(", ".join(map(str, self._torque))))
        axes = "the inertial axes" if self._axes == 0 else f"the axes of {self._axes!r}"
        return "Load on {!r} at ({}): {}, in {}".format(
            self._body, ", ".join(map(str, self._point)), ", ".join(parts), axes)

    def to_dict(self):
        r"""
        The description mapping of the load (expressions as text).

        EXAMPLES::

            sage: from sage_dynsym.mechanics.loads import Load
            sage: Load('b', point=[0, 0, var('l')], torque=[0, 0, 1], axes='b').to_dict()
            {'axes': 'b', 'body': 'b', 'point': ['0', '0', 'l'], 'torque': ['0', '0', '1']}
        """
        from ..io.fields import text
        out = {'body': self._body}
        if any(not c.is_zero() for c in self._point):
            out['point'] = [text(c) for c in self._point]
        if self._force is not None:
            out['force'] = [text(c) for c in self._force]
        if self._torque is not None:
            out['torque'] = [text(c) for c in self._torque]
        out['axes'] = self._axes
        return out

    def _forces(self, kinematics, entry):
        # the force about the joint point of the loaded body, in the
        # kinematic pass of the recursions over the symbolic ring (whose tree
        # holds the bodies of ``kinematics``); the bodies checked there first,
        # so that errors name the entry of the description
        from ..numerics.newton_euler import load_forces
        body_index(kinematics, self._body, f"{entry}.body")
        if self._axes != 0:
            body_index(kinematics, self._axes, f"{entry}.axes")
        kin = kinematics.tree_kinematics()
        return kin, load_forces(kin, [self])

    def power(self, kinematics, entry="load"):
        r"""
        The power `F \cdot v_P + M \cdot W_k` of the load on the bodies of
        ``kinematics`` (a :class:`~sage_dynsym.mechanics.system_kinematics.SystemKinematics`,
        or a :class:`~sage_dynsym.mechanics.system.MechanicalSystem`), by
        :func:`~sage_dynsym.numerics.newton_euler.power`.

        EXAMPLES: a torque `M` about the axis of a rotor turned by `a`::

            sage: from sage_dynsym import MechanicalSystem, RigidBody
            sage: from sage_dynsym.mechanics.loads import Load
            sage: a, M = var('a M')
            sage: S = MechanicalSystem([RigidBody('rotor', rotations=[(3, a)])], [a])
            sage: Load('rotor', torque=[0, 0, M]).power(S.kinematics())
            M*da
            sage: Load('rotor', point=[1, 0, 0], force=[0, 1, 0]).power(S)
            da*cos(a)
        """
        from ..numerics.newton_euler import power
        return power(*self._forces(kinematics, entry))

    def generalized_forces(self, kinematics, entry="load"):
        r"""
        The generalized forces `Q_i = F \cdot \partial v_P/\partial \dot q_i
        + M \cdot \partial W_k/\partial \dot q_i` of the load on the bodies of
        ``kinematics`` (as in :meth:`power`; see the module documentation for
        the sign convention). The force and torque may depend on the
        velocities (a drag force).

        They are those the compiled right-hand side uses: the load moved to
        the joint point (:func:`~sage_dynsym.numerics.newton_euler.load_forces`)
        and projected on the joints by the backward pass of the recursive
        Newton--Euler algorithm
        (:func:`~sage_dynsym.numerics.newton_euler.generalized_forces`),
        here over the symbolic ring.

        EXAMPLES: a force along the inertial `x` axis at the point `(l, 0, 0)`
        of a body turned by `a` about the `z` axis::

            sage: from sage_dynsym import MechanicalSystem, RigidBody
            sage: from sage_dynsym.mechanics.loads import Load
            sage: a, l, F = var('a l F')
            sage: S = MechanicalSystem([RigidBody('arm', rotations=[(3, a)])], [a])
            sage: Load('arm', point=[l, 0, 0], force=[F, 0, 0]).generalized_forces(S.kinematics())
            [-F*l*sin(a)]

        A linear drag `-c\, v_P` at that point gives
        `-\partial R/\partial \dot a` with `R = \tfrac12 c\, l^2 \dot a^2`::

            sage: c, da = var('c da')
            sage: drag = Load('arm', point=[l, 0, 0], force=[c*l*da*sin(a), -c*l*da*cos(a), 0])
            sage: drag.generalized_forces(S.kinematics())
            [-c*da*l^2]
        """
        from ..algebra.trigonometric import trig_rational_simplify
        from ..numerics.newton_euler import generalized_forces
        return [trig_rational_simplify(Q)
                for Q in generalized_forces(*self._forces(kinematics, entry))]


def load_list(loads):
    r"""
    ``loads`` as a list (of :class:`Load` objects or dictionaries, checked
    one by one by the system); a :class:`~sage_dynsym.errors.ModelError`
    for anything that is not a list.

    EXAMPLES::

        sage: from sage_dynsym.mechanics.loads import load_list
        sage: load_list(())
        []
        sage: load_list(0)
        Traceback (most recent call last):
        ...
        ModelError: loads: expected a list of loads, got 0
    """
    if isinstance(loads, (str, bytes, dict)) or not hasattr(loads, '__iter__'):
        raise ModelError(f"expected a list of loads, got {loads!r}", entry="loads")
    return list(loads)


def body_index(system, reference, entry):
    r"""
    The 1-based index in ``system`` (anything with the method ``bodies()``:
    a :class:`~sage_dynsym.mechanics.system_kinematics.SystemKinematics`
    or a :class:`~sage_dynsym.mechanics.system.MechanicalSystem`) of the
    body ``reference`` (a name, a
    1-based index or a :class:`~sage_dynsym.mechanics.rigid_body.RigidBody`);
    :class:`~sage_dynsym.errors.ModelError` naming ``entry`` if there is no
    such body.

    EXAMPLES::

        sage: from sage_dynsym import MechanicalSystem, RigidBody
        sage: from sage_dynsym.mechanics.loads import body_index
        sage: S = MechanicalSystem([RigidBody('a'), RigidBody('b', parent='a')], [])
        sage: body_index(S, 'b', 'loads[0].body'), body_index(S, 1, 'loads[0].body')
        (2, 1)
        sage: body_index(S, 'c', 'loads[0].body')
        Traceback (most recent call last):
        ...
        ModelError: loads[0].body: unknown body 'c'; known bodies are: a, b
        sage: body_index(S, 3, 'loads[0].body')
        Traceback (most recent call last):
        ...
        ModelError: loads[0].body: body index 3 out of range 1..2
    """
    if isinstance(reference, RigidBody):
        reference = reference.name()
    try:
        return body_reference_index(system.bodies(), reference, entry, inertial=False)
    except AnalysisError as err:
        raise ModelError(err.message, entry=entry) from err

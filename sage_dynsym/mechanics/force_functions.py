r"""
Force functions of potential fields

The force function `U` (minus the potential energy) enters the Lagrangian
`L = T + U`. Two fields of :doc:`the method </method>` are provided:

- :class:`UniformGravity`: `U_k = m_k\, g \cdot r^0_{ck}` (formula (3));
- :class:`NewtonianField`: the attraction of a distant centre expanded to
  second order in (size of the system)/(distance) (formula (2)), which gives
  the gravity-gradient torques of satellite dynamics.

A force function object is a description; the system evaluates it with its
kinematics (a :class:`~sage_dynsym.mechanics.system_kinematics.SystemKinematics`)
through :meth:`~sage_dynsym.mechanics.system.MechanicalSystem.force_function`.

EXAMPLES::

    sage: from sage_dynsym import UniformGravity, NewtonianField
    sage: UniformGravity([0, 0, -var('g')])
    uniform gravity field g = (0, 0, -g)
    sage: NewtonianField(var('nu'), var('r'), [1, 0, 0])
    Newtonian central field nu = nu, distance r, direction (1, 0, 0)
"""
from sage.structure.sage_object import SageObject
from sage.symbolic.ring import SR

from ..errors import ModelError
from .rigid_body import as_vector3, as_scalar

__all__ = ['UniformGravity', 'NewtonianField', 'split_force_terms', 'UNIT_TOLERANCE',
           'check_force_function', 'force_term_data', 'force_term_to_dict', 'force_terms']


class UniformGravity(SageObject):
    r"""
    A uniform field of acceleration `g` (a vector in the inertial frame).

    `U = \sum_k m_k\, (g \cdot r^0_{ck})`, `r^0_{ck}` the position of the
    mass centre of body `k` in the inertial frame.

    EXAMPLES::

        sage: from sage_dynsym import UniformGravity
        sage: UniformGravity([0, 0, -981/100]).acceleration()
        (0, 0, -981/100)
    """

    def __init__(self, acceleration):
        self._g = as_vector3(acceleration, "uniform_gravity")

    def _repr_(self):
        return "uniform gravity field g = ({})".format(", ".join(map(str, self._g)))

    def acceleration(self):
        r"""
        The acceleration vector `g` in the inertial frame.

        EXAMPLES::

            sage: from sage_dynsym import UniformGravity
            sage: UniformGravity([0, -var('g'), 0]).acceleration()
            (0, -g, 0)
        """
        return self._g

    def subs(self, values):
        r"""
        The field with ``values`` (a dictionary) substituted.

        EXAMPLES::

            sage: from sage_dynsym import UniformGravity
            sage: g = var('g')
            sage: UniformGravity([0, 0, -g]).subs({g: 9.81})
            uniform gravity field g = (0, 0, -9.81000000000000)
        """
        return UniformGravity([SR(c).subs(values) for c in self._g])

    def evaluate(self, kinematics):
        r"""
        The force function in this field of the bodies of ``kinematics``
        (a :class:`~sage_dynsym.mechanics.system_kinematics.SystemKinematics`,
        or a :class:`~sage_dynsym.mechanics.system.MechanicalSystem`).

        EXAMPLES::

            sage: from sage_dynsym import RigidBody, MechanicalSystem, UniformGravity
            sage: z, m, g = var('z m g')
            sage: S = MechanicalSystem([RigidBody('ball', joint=[0, 0, z], mass=m)], [z])
            sage: UniformGravity([0, 0, -g]).evaluate(S.kinematics())
            -g*m*z
        """
        from .frames import FrameVector
        g = FrameVector(kinematics.frame_tree(), {0: self._g})
        return sum((body.mass() * g.dot(kinematics.mass_center_position(k))
                    for k, body in enumerate(kinematics.bodies(), 1)
                    if not body.mass().is_zero()), SR(0))


class NewtonianField(SageObject):
    r"""
    The Newtonian field of an attracting centre `O`, to second order.

    INPUT:

    - ``nu`` -- gravitational parameter `\nu`
    - ``distance`` -- `r = |OO_1|`, from the centre to the joint point of
      the carrier (a constant, a coordinate or a function of ``t``)
    - ``direction`` -- unit vector `e` from `O` to `O_1`, in the inertial
      axes (its direction cosines; may depend on ``t``)

    For body `k`, with `a_k = O_1 O_k` and `c_k = r^k_{ck}` (formula (2))

    .. MATH::

        U_k = \frac{\nu m_k}{r} - \frac{\nu m_k}{r^2}\, e\cdot(a_k + c_k)
        + \frac{\nu}{2r^3}\Big[m_k\big(3(e\cdot a_k)^2 - a_k^2\big)
        + 6 m_k (e\cdot a_k)(e\cdot c_k) - 2 m_k\, a_k\cdot c_k
        + \operatorname{tr}\Theta^k - 3\,\gamma^k\cdot\Theta^k\gamma^k\Big],

    `\gamma^k` the components of `e` in the body's axes.

    EXAMPLES:

    A dumbbell of two unit masses at `\pm b` on the body's `x` axis,
    turned by `\varphi` from the local vertical `e`; its inertia tensor
    about the centre is `\operatorname{diag}(0, 2b^2, 2b^2)`::

        sage: from sage_dynsym import RigidBody, MechanicalSystem, NewtonianField
        sage: phi, b, nu, r = var('phi b nu r')
        sage: body = RigidBody('dumbbell', rotations=[(3, phi)], mass=2,
        ....:                  inertia=diagonal_matrix([0, 2*b^2, 2*b^2]))
        sage: S = MechanicalSystem([body], [phi], force_function=NewtonianField(nu, r, [1, 0, 0]))
        sage: U = S.force_function(); U
        ((3*cos(phi)^2 - 1)*b^2 + 2*r^2)*nu/r^3

    This is the expansion of the exact `\nu/|R_1| + \nu/|R_2|`,
    `|R_{1,2}|^2 = r^2 \pm 2 r b\cos\varphi + b^2`, to order `b^2/r^3`
    (classical gravity-gradient term, maximal force function along the
    vertical)::

        sage: exact = nu/sqrt(r^2 + 2*r*b*cos(phi) + b^2) + nu/sqrt(r^2 - 2*r*b*cos(phi) + b^2)
        sage: bool(exact.taylor(b, 0, 2) == U)
        True
    """

    def __init__(self, nu, distance, direction):
        self._nu = as_scalar(nu, "newtonian.nu")
        self._r = as_scalar(distance, "newtonian.r")
        if direction is None:
            raise ModelError("expected the direction of the field, a list of 3 components",
                             entry="newtonian.direction")
        self._e = as_vector3(direction, "newtonian.direction")
        self._conditions = _field_conditions(self._r, self._e)

    def _repr_(self):
        return "Newtonian central field nu = {}, distance {}, direction ({})".format(
            self._nu, self._r, ", ".join(map(str, self._e)))

    def parameters(self):
        r"""
        The triple `(\nu, r, e)`.

        EXAMPLES::

            sage: from sage_dynsym import NewtonianField
            sage: NewtonianField(1, 2, [0, 1, 0]).parameters()
            (1, 2, (0, 1, 0))
        """
        return self._nu, self._r, self._e

    def conditions(self):
        r"""
        The conditions on the parameters that the data of the field leave
        open: the direction cosines of a unit vector (`e_1^2 + e_2^2 +
        e_3^2 = 1` when they are symbols), a positive distance (when it is a
        symbol). Numbers are checked when the field is made: the distance
        positive, the direction a unit vector (exactly, or to rounding for
        floating-point components).

        EXAMPLES::

            sage: from sage_dynsym import NewtonianField
            sage: nu, r, a, b = var('nu r a b')
            sage: NewtonianField(nu, r, [a, b, 0]).conditions()
            [a^2 + b^2 == 1, r > 0]
            sage: NewtonianField(nu, 1, [cos(a), sin(a), 0]).conditions()
            []

        TESTS::

            sage: NewtonianField(nu, 0, [1, 0, 0])
            Traceback (most recent call last):
            ...
            ModelError: newtonian.r: the distance from the attracting centre must be positive, got 0
            sage: NewtonianField(nu, r, [2, 0, 0])
            Traceback (most recent call last):
            ...
            ModelError: newtonian.direction: the direction must be a unit vector, got (2, 0, 0) of length 2
            sage: NewtonianField(nu, r, [0, 0, 0])
            Traceback (most recent call last):
            ...
            ModelError: newtonian.direction: the direction must be a unit vector, got the zero vector
            sage: NewtonianField(nu, 1, [0.6, 0.8, 0]).conditions()
            []
            sage: NewtonianField(nu, r, [0.6, 0.8000001, 0])
            Traceback (most recent call last):
            ...
            ModelError: newtonian.direction: the direction must be a unit vector, got (0.600000000000000, 0.800000100000000, 0) of length 1.00000008
            sage: NewtonianField(nu, r, [var('t'), 0, 0])
            Traceback (most recent call last):
            ...
            ModelError: newtonian.direction: the direction must be a unit vector at all times, got (t, 0, 0) (its squared length is t^2)
        """
        return list(self._conditions)

    def subs(self, values):
        r"""
        The field with ``values`` (a dictionary) substituted.

        EXAMPLES::

            sage: from sage_dynsym import NewtonianField
            sage: nu, r = var('nu r')
            sage: NewtonianField(nu, r, [1, 0, 0]).subs({nu: 1})
            Newtonian central field nu = 1, distance r, direction (1, 0, 0)
        """
        return NewtonianField(self._nu.subs(values), self._r.subs(values),
                              [SR(c).subs(values) for c in self._e])

    def evaluate(self, kinematics):
        r"""
        The force function (2) in this field of the bodies of ``kinematics``
        (a :class:`~sage_dynsym.mechanics.system_kinematics.SystemKinematics`,
        or a :class:`~sage_dynsym.mechanics.system.MechanicalSystem`).

        EXAMPLES::

            sage: from sage_dynsym import RigidBody, MechanicalSystem, NewtonianField
            sage: m, nu, r = var('m nu r')
            sage: S = MechanicalSystem([RigidBody('point', mass=m)], [])
            sage: NewtonianField(nu, r, [0, 0, 1]).evaluate(S.kinematics())
            m*nu/r
        """
        from .frames import FrameVector
        tree = kinematics.frame_tree()
        e = FrameVector(tree, {0: self._e})
        origin = kinematics.joint_position(1)
        nu, r = self._nu, self._r
        U = SR(0)
        for k, body in enumerate(kinematics.bodies(), 1):
            if body.is_massless():
                continue
            m, frame = body.mass(), kinematics.body_frame(k)
            a = kinematics.joint_position(k) - origin
            c = FrameVector(tree, {frame: body.mass_center()})
            ea, ec = e.dot(a), e.dot(c)
            gamma = e.components(frame)
            Theta = body.inertia()
            gradient = (m * (3 * ea ** 2 - a.dot(a)) + 6 * m * ea * ec - 2 * m * a.dot(c)
                        + Theta.trace()
                        - 3 * sum(gamma[i] * Theta[i, j] * gamma[j]
                                  for i in range(3) for j in range(3)))
            U += nu * m / r - nu * m / r ** 2 * (ea + ec) + nu / (2 * r ** 3) * gradient
        return U


def force_terms(force_function):
    r"""
    The terms of a force function as given to a
    :class:`~sage_dynsym.mechanics.system.MechanicalSystem` (``None``, a
    field or an expression, or a list of those): a list, empty if none.

    EXAMPLES::

        sage: from sage_dynsym import UniformGravity
        sage: from sage_dynsym.mechanics.force_functions import force_terms
        sage: x = var('x')
        sage: force_terms(None), force_terms(-x^2), force_terms([UniformGravity([0, 0, -1]), x])
        ([], [-x^2], [uniform gravity field g = (0, 0, -1), x])
    """
    if force_function is None:
        return []
    return list(force_function) if isinstance(force_function, list) else [force_function]


def split_force_terms(terms, kinematics):
    r"""
    The terms ``terms`` of a force function (see :func:`force_terms`) in two
    parts: the summed acceleration of the uniform gravity fields (``None``
    if there is none) and the sum of the other terms' force functions on the
    bodies of ``kinematics`` (a
    :class:`~sage_dynsym.mechanics.system_kinematics.SystemKinematics`), not
    expanded. Recursive assemblies take gravity as an acceleration of the
    inertial frame and differentiate only the rest.

    EXAMPLES::

        sage: from sage_dynsym import MechanicalSystem, RigidBody, UniformGravity
        sage: from sage_dynsym.mechanics.force_functions import split_force_terms
        sage: z, m, g, k = var('z m g k')
        sage: S = MechanicalSystem([RigidBody('b', joint=[0, 0, z], mass=m)], [z],
        ....:                      force_function=[UniformGravity([0, 0, -g]), -k*z^2/2,
        ....:                                      UniformGravity([1, 0, 0])])
        sage: split_force_terms(S.force_terms(), S.kinematics())
        ((1, 0, -g), -1/2*k*z^2)
    """
    gravity, rest = None, SR(0)
    for term in terms:
        if isinstance(term, UniformGravity):
            g = term.acceleration()
            gravity = g if gravity is None else tuple(a + b for a, b in zip(gravity, g))
        elif hasattr(term, 'evaluate'):
            rest += term.evaluate(kinematics)
        else:
            rest += SR(term)
    return gravity, rest


#: How far from 1 the squared length of a direction given by floating-point
#: components may be (rounding).
UNIT_TOLERANCE = 1e-12


def _field_conditions(r, e):
    r"""Check the distance ``r`` and the direction ``e`` of a Newtonian field
    where they are numbers; return the conditions left on the parameters."""
    from ..errors import ModelError
    from ..symbols import is_exact, t
    conditions = []
    if not r.variables():
        try:
            positive = bool(r > 0) if is_exact(r) else float(r) > 0
        except (TypeError, ValueError):
            positive = False
        if not positive:
            raise ModelError(f"the distance from the attracting centre must be positive, got "
                             f"{r}", entry="newtonian.r")
    shown = f"({', '.join(map(str, e))})"
    if all(SR(c).is_zero() for c in e):
        raise ModelError("the direction must be a unit vector, got the zero vector",
                         entry="newtonian.direction")
    square = sum(SR(c) ** 2 for c in e)
    excess = (square - 1).simplify_full() if is_exact(square) else square - 1
    if not excess.variables():
        if is_exact(excess):
            unit = excess.is_zero() or bool(excess == 0)
        else:
            unit = abs(float(excess)) <= UNIT_TOLERANCE
        if not unit:
            length = float(square) ** 0.5
            raise ModelError(f"the direction must be a unit vector, got {shown} of length "
                             f"{length:.9g}", entry="newtonian.direction")
    elif excess.has(t):
        raise ModelError(f"the direction must be a unit vector at all times, got {shown} (its "
                         f"squared length is {square})", entry="newtonian.direction")
    else:
        conditions.append(square == 1)
    if r.variables():
        conditions.append(r > 0)
    return conditions


def check_force_function(force_function, coordinates, entry="force_function"):
    r"""
    Refuse a force function that depends on velocities or accelerations.

    The force function `U(q, t)` enters the Lagrangian as a potential:
    a velocity in it (``k*dx^2``) would silently become a term of the
    kinetic energy. Velocity-dependent forces belong in the Rayleigh
    dissipation function or the generalized forces.

    INPUT:

    - ``force_function`` -- ``None``, a
      :class:`UniformGravity`, a :class:`NewtonianField`, an expression, or
      a list of those (terms added together)
    - ``coordinates`` -- the generalized coordinates
    - ``entry`` -- (default: ``"force_function"``) for the message

    EXAMPLES::

        sage: from sage_dynsym.mechanics.force_functions import check_force_function, UniformGravity
        sage: x, k, g = var('x k g')
        sage: check_force_function(-k*x^2/2, [x])
        sage: check_force_function(-k*var('dx')^2, [x])
        Traceback (most recent call last):
        ...
        ModelError: force_function: the force function U(q, t) cannot depend on the velocity dx; velocity-dependent forces belong in the dissipation function or the generalized forces
        sage: check_force_function([UniformGravity([0, 0, -g*var('ddx')])], [x])
        Traceback (most recent call last):
        ...
        ModelError: force_function[0]: the force function U(q, t) cannot depend on the acceleration ddx; velocity-dependent forces belong in the dissipation function or the generalized forces
        sage: check_force_function([-k*x^2, None], [x])
        Traceback (most recent call last):
        ...
        ModelError: force_function[1]: expected a force field or an expression U(q, t), got None
    """
    from ..errors import ModelError
    from ..symbols import velocity, acceleration
    if force_function is None:
        return
    if isinstance(force_function, (list, tuple)):
        for i, term in enumerate(force_function):
            if term is None or isinstance(term, (list, tuple)):
                raise ModelError("expected a force field or an expression U(q, t), got "
                                 f"{term!r}", entry=f"{entry}[{i}]")
            check_force_function(term, coordinates, f"{entry}[{i}]")
        return
    forbidden = {}
    for q in coordinates:
        forbidden[velocity(q)] = f"the velocity {velocity(q)}"
        forbidden[acceleration(q)] = f"the acceleration {acceleration(q)}"
    try:
        parts = force_term_data(force_function)
    except (TypeError, ValueError) as err:
        raise ModelError("expected a force field or an expression U(q, t), got "
                         f"{force_function!r}", entry=entry) from err
    for part in parts:
        for v in SR(part).variables():
            if v in forbidden:
                raise ModelError(f"the force function U(q, t) cannot depend on {forbidden[v]}; "
                                 "velocity-dependent forces belong in the dissipation function "
                                 "or the generalized forces", entry=entry)


def force_term_data(term):
    r"""
    The expressions a force-function term is made of: the acceleration of
    a :class:`UniformGravity`, the parameters of a :class:`NewtonianField`,
    or the expression itself (what the checks and the size estimates read).

    EXAMPLES::

        sage: from sage_dynsym.mechanics.force_functions import (force_term_data,
        ....:                                                    UniformGravity, NewtonianField)
        sage: g, nu, r, k, x = var('g nu r k x')
        sage: force_term_data(UniformGravity([0, 0, -g])), force_term_data(-k*x^2/2)
        ([0, 0, -g], [-1/2*k*x^2])
        sage: force_term_data(NewtonianField(nu, r, [0, 0, 1]))
        [nu, r, 0, 0, 1]
    """
    if isinstance(term, UniformGravity):
        return list(term.acceleration())
    if isinstance(term, NewtonianField):
        nu, r, e = term.parameters()
        return [nu, r] + list(e)
    return [SR(term)]


def force_term_to_dict(term, text=str):
    r"""
    A force-function term as an entry of the ``force_function`` key of a
    description file; ``text`` writes an expression.

    EXAMPLES::

        sage: from sage_dynsym.mechanics.force_functions import force_term_to_dict, UniformGravity
        sage: g, k, x = var('g k x')
        sage: force_term_to_dict(UniformGravity([0, 0, -g])), force_term_to_dict(-k*x^2/2)
        ({'uniform_gravity': ['0', '0', '-g']}, {'expression': '-1/2*k*x^2'})
    """
    if isinstance(term, UniformGravity):
        return {'uniform_gravity': [text(c) for c in term.acceleration()]}
    if isinstance(term, NewtonianField):
        nu, r, e = term.parameters()
        return {'newtonian': {'nu': text(nu), 'r': text(r), 'direction': [text(c) for c in e]}}
    return {'expression': text(term)}

r"""
Thin disks rolling without slipping on the plane `z = 0`

A :class:`RollingDisk` says that a body of a mechanical system is (or
carries) a thin disk of radius `r`, centred at the body's joint point
`O_k`, its axle along one axis of the body, rolling without slipping on the
ground plane `z = 0` of the inertial frame (normal `+z`; gravity, if any,
along `-z`). :func:`rolling_contact` derives its contact conditions from
the kinematics of the system [NF1972]_.

With the centre `c` and the unit vector `a` of the axle (inertial axes),
`n = e_z`, the point of the rim lowest in `z` is

.. MATH::

    P = c - r\,\frac{n - (n\cdot a)\,a}{\lvert n - (n\cdot a)\,a\rvert},
    \qquad \lvert n - (n\cdot a)\,a\rvert = \sqrt{1 - a_z^2}

(defined while the disk is not flat on the plane). The disk touches the
plane where `P_z = c_z - r\sqrt{1 - a_z^2} = 0`: a *holonomic* condition.
It holds by the choice of coordinates when the centre's height is written
through them (a wheel's centre at `r\cos\varphi` above its contact point,
`\varphi` the lean): the package recognises this (`c_z^2 = r^2(1 - a_z^2)`
identically, the centre above the plane) and then writes
`\sqrt{1 - a_z^2} = c_z/r`; otherwise the condition is added to the
system's holonomic constraints (the front wheel of a bicycle: it ties the
pitch of the frame to the lean and the steering angle). Rolling without
slipping says that the material point of the disk at `P` is at rest,

.. MATH::

    v_P = V_c + W\times(P - c) = 0,

of which the horizontal components are the two *nonholonomic* constraints
(linear in the velocities, not integrable); the vertical component is the
time derivative of the contact condition.

EXAMPLES:

A disk rolling on the plane: contact point `(x, y)`, heading `\psi`,
tilt `\theta` (from the vertical), spin `\varphi`, the centre at the height
`r\cos\theta` above the contact point::

    sage: from sage_dynsym import MechanicalSystem, RigidBody
    sage: from sage_dynsym.mechanics.rolling import RollingDisk, rolling_contact
    sage: x, y, psi, th, phi, r, m = var('x y psi theta phi r m')
    sage: frame = RigidBody('frame', joint=[x, y, 0], rotations=[(3, psi), (1, th)])
    sage: disk = RigidBody('disk', parent='frame', joint=[0, 0, r], rotations=[(2, phi)],
    ....:                  mass=m, inertia=diagonal_matrix([m*r^2/4, m*r^2/2, m*r^2/4]))
    sage: S = MechanicalSystem([frame, disk], [x, y, psi, th, phi])
    sage: C = rolling_contact(S.kinematics(), RollingDisk('disk', r, 2)); C
    rolling contact of disk: holonomic condition imposed by the coordinates, 2 nonholonomic constraints
    sage: C.point()
    (x, y, 0)
    sage: C.no_slip()
    [-dphi*r*cos(psi) + dx, -dphi*r*sin(psi) + dy]
"""
import numbers

from sage.structure.sage_object import SageObject
from sage.symbolic.ring import SR

from ..errors import ModelError
from ..io.fields import check_mapping
from ..algebra.trigonometric import trig_rational_simplify, NotPolynomial, TrigPolynomialRing
from .frames import cross
from .rigid_body import RigidBody, as_scalar

__all__ = ['RollingDisk', 'RollingContact', 'rolling_contact']


class RollingDisk(SageObject):
    r"""
    A thin disk rolling without slipping on the plane `z = 0` (see the
    module documentation).

    INPUT:

    - ``body`` -- the body (its name, its 1-based index or the
      :class:`~sage_dynsym.mechanics.rigid_body.RigidBody`): the disk's
      centre is its joint point
    - ``radius`` -- the radius (an expression in the parameters)
    - ``axle`` -- 1, 2 or 3: the axis of the body along the disk's axle

    EXAMPLES::

        sage: from sage_dynsym.mechanics.rolling import RollingDisk
        sage: RollingDisk('wheel', var('r'), 2)
        thin disk of radius r on 'wheel', axle along its axis 2
        sage: RollingDisk.from_value({'body': 'wheel', 'radius': 1, 'axle': 2}, 'rolling[0]').to_dict()
        {'axle': 2, 'body': 'wheel', 'radius': '1'}

    TESTS::

        sage: RollingDisk('wheel', 1, 4)
        Traceback (most recent call last):
        ...
        ModelError: rolling.axle: expected 1, 2 or 3 (the axis of the body along the axle), got 4
        sage: RollingDisk.from_value({'body': 'wheel', 'radius': 1}, 'rolling[0]')
        Traceback (most recent call last):
        ...
        ModelError: rolling[0]: missing key 'axle' (a rolling disk has the keys axle, body, radius)
        sage: RollingDisk('wheel', -1, 2)
        Traceback (most recent call last):
        ...
        ModelError: rolling.radius: the radius must be positive, got -1
    """

    KEYS = ('axle', 'body', 'radius')

    def __init__(self, body, radius, axle, entry="rolling"):
        if isinstance(body, RigidBody):
            body = body.name()
        if not isinstance(body, (str, numbers.Integral)) or isinstance(body, bool):
            raise ModelError(f"expected a body name or a 1-based body index, got {body!r}",
                             entry=f"{entry}.body")
        self._body = body if isinstance(body, str) else int(body)
        self._radius = as_scalar(radius, f"{entry}.radius")
        if self._radius.is_numeric() and not self._radius > 0:
            raise ModelError(f"the radius must be positive, got {self._radius}",
                             entry=f"{entry}.radius")
        if isinstance(axle, bool) or axle not in (1, 2, 3):
            raise ModelError(f"expected 1, 2 or 3 (the axis of the body along the axle), got "
                             f"{axle!r}", entry=f"{entry}.axle")
        self._axle = int(axle)

    @classmethod
    def from_value(cls, value, entry):
        r"""
        A :class:`RollingDisk` from one, or from a dict with the keys
        ``body``, ``radius`` and ``axle``; errors name ``entry``.

        EXAMPLES: see the class documentation.
        """
        if isinstance(value, RollingDisk):
            return value
        check_mapping(value, cls.KEYS, "a rolling disk", entry, "a dict")
        for key in cls.KEYS:
            if key not in value:
                raise ModelError(f"missing key {key!r} (a rolling disk has the keys "
                                 f"{', '.join(cls.KEYS)})", entry=entry)
        return cls(value['body'], value['radius'], value['axle'], entry=entry)

    def _repr_(self):
        return (f"thin disk of radius {self._radius} on {self._body!r}, axle along its axis "
                f"{self._axle}")

    def body(self):
        r"""The body (a name, or a 1-based index as given).

        EXAMPLES::

            sage: from sage_dynsym.mechanics.rolling import RollingDisk
            sage: RollingDisk('wheel', 1, 2).body()
            'wheel'
        """
        return self._body

    def radius(self):
        r"""The radius.

        EXAMPLES::

            sage: from sage_dynsym.mechanics.rolling import RollingDisk
            sage: RollingDisk('wheel', var('r'), 2).radius()
            r
        """
        return self._radius

    def axle(self):
        r"""The axis (1, 2 or 3) of the body along the axle.

        EXAMPLES::

            sage: from sage_dynsym.mechanics.rolling import RollingDisk
            sage: RollingDisk('wheel', 1, 3).axle()
            3
        """
        return self._axle

    def with_body(self, body):
        r"""
        The same disk on ``body`` (a name): how a system keeps references
        that do not depend on the order of the bodies.

        EXAMPLES::

            sage: from sage_dynsym.mechanics.rolling import RollingDisk
            sage: RollingDisk(1, 1, 2).with_body('wheel').body()
            'wheel'
        """
        return RollingDisk(body, self._radius, self._axle)

    def subs(self, values):
        r"""
        The disk with ``values`` substituted in its radius.

        EXAMPLES::

            sage: from sage_dynsym.mechanics.rolling import RollingDisk
            sage: r = var('r'); RollingDisk('wheel', r, 2).subs({r: 1/2}).radius()
            1/2
        """
        return RollingDisk(self._body, self._radius.subs(values), self._axle)

    def to_dict(self):
        r"""
        The description mapping of the disk (see the class documentation).

        EXAMPLES: see the class documentation.
        """
        from ..io.fields import text
        return {'axle': self._axle, 'body': self._body, 'radius': text(self._radius)}

    def __eq__(self, other):
        return (isinstance(other, RollingDisk) and self._body == other._body
                and self._axle == other._axle
                and self._radius.is_trivially_equal(other._radius))

    def __ne__(self, other):
        return not self == other

    def __hash__(self):
        return hash((self._body, self._axle))


class RollingContact(SageObject):
    r"""
    The contact conditions of a :class:`RollingDisk` in a system (built by
    :func:`rolling_contact`).

    EXAMPLES: see the module documentation.
    """

    def __init__(self, disk, point, holonomic, no_slip):
        self._disk, self._point = disk, point
        self._holonomic, self._no_slip = holonomic, no_slip

    def _repr_(self):
        how = ("imposed by the coordinates" if self._holonomic is None else
               "a holonomic constraint")
        return (f"rolling contact of {self._disk.body()}: holonomic condition {how}, "
                f"{len(self._no_slip)} nonholonomic constraints")

    def disk(self):
        r"""The :class:`RollingDisk`.

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem, RigidBody
            sage: from sage_dynsym.mechanics.rolling import RollingDisk, rolling_contact
            sage: x, r = var('x r')
            sage: S = MechanicalSystem([RigidBody('disk', joint=[x, 0, r], rotations=[(2, x/r)])], [x])
            sage: rolling_contact(S.kinematics(), RollingDisk('disk', r, 2)).disk()
            thin disk of radius r on 'disk', axle along its axis 2
        """
        return self._disk

    def point(self):
        r"""The contact point `P` (its components in the inertial axes).

        EXAMPLES: see the module documentation.
        """
        return self._point

    def holonomic(self):
        r"""
        The contact condition `P_z = 0` as an expression, or ``None`` when
        the coordinates impose it.

        EXAMPLES: a disk whose height is a coordinate `z`::

            sage: from sage_dynsym import MechanicalSystem, RigidBody
            sage: from sage_dynsym.mechanics.rolling import RollingDisk, rolling_contact
            sage: x, z, r = var('x z r')
            sage: S = MechanicalSystem([RigidBody('disk', joint=[x, 0, z])], [x, z])
            sage: rolling_contact(S.kinematics(), RollingDisk('disk', r, 2)).holonomic()
            -r + z
        """
        return self._holonomic

    def imposed_by_coordinates(self):
        r"""Whether the coordinates keep the disk on the plane.

        EXAMPLES: see the module documentation.
        """
        return self._holonomic is None

    def no_slip(self):
        r"""
        The two horizontal components of the velocity of the disk's material
        point at `P` (each ``== 0``): the nonholonomic constraints.

        EXAMPLES: see the module documentation.
        """
        return list(self._no_slip)


def _simplified(expr):
    # the reduced fraction modulo cos^2 + sin^2 = 1 (the first normal form:
    # the shortest printed one costs seconds on a front wheel's expressions)
    expr = SR(expr)
    try:
        ring = TrigPolynomialRing.for_expressions([expr], fractions=True)
        return ring.simplest_fraction(*ring.fraction(expr))
    except NotPolynomial:
        return expr


def _is_zero(expr):
    try:
        return trig_rational_simplify(expr, strict=True).is_zero()
    except NotPolynomial:
        return False


def rolling_contact(kinematics, disk, entry="rolling"):
    r"""
    The contact point, the holonomic contact condition and the no-slip
    constraints of ``disk`` (a :class:`RollingDisk` whose body is one of
    ``kinematics``, a
    :class:`~sage_dynsym.mechanics.system_kinematics.SystemKinematics`),
    see the module documentation.

    EXAMPLES: see the module documentation.

    TESTS:

    The centre of a disk written below the plane is refused::

        sage: from sage_dynsym import MechanicalSystem, RigidBody
        sage: from sage_dynsym.mechanics.rolling import RollingDisk, rolling_contact
        sage: x, th, r = var('x theta r')
        sage: S = MechanicalSystem([RigidBody('f', joint=[x, 0, 0], rotations=[(1, th)]),
        ....:                       RigidBody('disk', parent='f', joint=[0, 0, -r])], [x, th])
        sage: rolling_contact(S.kinematics(), RollingDisk('disk', r, 2), 'rolling[0]')
        Traceback (most recent call last):
        ...
        ModelError: rolling[0]: the centre of the disk on 'disk' is below the plane z = 0 (its height is -r*cos(theta) when it touches); write its height as r*sqrt(1 - a_z^2) above the contact point
    """
    from .loads import body_index
    k = body_index(kinematics, disk.body(), f"{entry}.body")
    r = disk.radius()
    frame = kinematics.body_frame(k)
    e = [0, 0, 0]
    e[disk.axle() - 1] = 1
    a = [SR(x) for x in kinematics.frame_tree().express(e, frame, 0)]
    c = [SR(x) for x in kinematics.joint_position(k).components(0)]
    az = _simplified(a[2])
    d = [-az * a[0], -az * a[1], _simplified(1 - az ** 2)]
    if _is_zero(c[2] ** 2 - r ** 2 * (1 - az ** 2)):
        s = _simplified(c[2] / r)
        at_rest = _simplified(s.subs({q: 0 for q in kinematics.coordinates()}))
        if at_rest.is_numeric() and at_rest < 0:
            raise ModelError(f"the centre of the disk on {disk.body()!r} is below the plane "
                             f"z = 0 (its height is {_simplified(c[2])} when it touches); "
                             "write its height as r*sqrt(1 - a_z^2) above the contact point",
                             entry=entry)
        holonomic = None
    else:
        s = (1 - az ** 2).sqrt()
        holonomic = _simplified(c[2]) - r * s
    arm = [-r * x / s for x in d]
    point = tuple(_simplified(ci + xi) for ci, xi in zip(c, arm))
    V = kinematics.joint_velocity_vector(k).components(0)
    W = kinematics.angular_velocity_vector(k).components(0)
    spin = cross(W, arm)
    no_slip = [_simplified(SR(V[i]) + spin[i]) for i in range(2)]
    return RollingContact(disk, point, holonomic, no_slip)

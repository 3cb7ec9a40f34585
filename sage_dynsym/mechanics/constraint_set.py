r"""
All the constraints of a mechanical system, and where each comes from

A mechanical system may be constrained in three ways: holonomic constraints
`f(q, t) = 0` given as such (``constraints``), velocity constraints given
as such (``nonholonomic``), and disks rolling on the ground plane
(``rolling``, see :mod:`~sage_dynsym.mechanics.rolling`), each of which
brings a holonomic contact condition -- unless the coordinates impose it --
and two nonholonomic no-slip constraints. :class:`ConstraintSet` derives
the rolling contacts, checks everything together (no redundant
constraint) and keeps the origin of every constraint for the reports.

EXAMPLES::

    sage: from sage_dynsym import MechanicalSystem, RigidBody
    sage: x, y, psi, th, phi, r, m = var('x y psi theta phi r m')
    sage: frame = RigidBody('frame', joint=[x, y, 0], rotations=[(3, psi), (1, th)])
    sage: disk = RigidBody('disk', parent='frame', joint=[0, 0, r], rotations=[(2, phi)],
    ....:                  mass=m, inertia=diagonal_matrix([m*r^2/4, m*r^2/2, m*r^2/4]))
    sage: S = MechanicalSystem([frame, disk], [x, y, psi, th, phi],
    ....:                      rolling=[{'body': 'disk', 'radius': r, 'axle': 2}])
    sage: C = S.constraint_set(); C
    Constraint set: 0 holonomic, 2 on the velocities (1 rolling disk)
    sage: for line in C.lines(): print(line)
    rolling[0] (disk): contact with the plane z = 0 held by the coordinates
    rolling[0] (disk): no slip, 0 = -dphi*r*cos(psi) + dx
    rolling[0] (disk): no slip, 0 = -dphi*r*sin(psi) + dy
"""
from sage.structure.sage_object import SageObject

from ..errors import ModelError
from ..dynamics.nonholonomic import check_velocity_constraints
from .loads import body_index
from .rolling import RollingDisk, rolling_contact

__all__ = ['ConstraintSet']


class ConstraintSet(SageObject):
    r"""
    The constraints of a mechanical system (see the module documentation).

    INPUT:

    - ``kinematics`` -- the
      :class:`~sage_dynsym.mechanics.system_kinematics.SystemKinematics` of
      the system (its bodies, in the order given for a 1-based body index,
      its coordinates and velocities)
    - ``holonomic`` -- the holonomic constraints given (already checked)
    - ``nonholonomic`` -- the velocity constraints given
    - ``rolling`` -- :class:`~sage_dynsym.mechanics.rolling.RollingDisk`
      objects or dicts with their keys
    - ``parameters`` -- (optional) the declared parameters (``None``: not
      declared)

    EXAMPLES: see the module documentation; on its own, a skate (a blade
    that cannot move sideways)::

        sage: from sage_dynsym import RigidBody
        sage: from sage_dynsym.mechanics.system_kinematics import SystemKinematics
        sage: from sage_dynsym.mechanics.constraint_set import ConstraintSet
        sage: x, y, th, dx, dy = var('x y theta dx dy')
        sage: K = SystemKinematics([RigidBody('blade', joint=[x, y, 0], rotations=[(3, th)])],
        ....:                      [x, y, th])
        sage: C = ConstraintSet(K, [], [sin(th)*dx - cos(th)*dy], []); C
        Constraint set: 0 holonomic, 1 on the velocities
        sage: C.nonholonomic()
        [-dy*cos(theta) + dx*sin(theta)]

    TESTS::

        sage: from sage_dynsym import MechanicalSystem, RigidBody
        sage: x, dx = var('x dx')
        sage: MechanicalSystem([RigidBody('b', joint=[x, 0, 1])], [x],
        ....:                  rolling=[{'body': 'c', 'radius': 1, 'axle': 2}])
        Traceback (most recent call last):
        ...
        ModelError: rolling[0].body: unknown body 'c'; known bodies are: b
        sage: MechanicalSystem([RigidBody('b', joint=[x, 0, 1])], [x], nonholonomic=[dx, 2*dx])
        Traceback (most recent call last):
        ...
        ModelError: nonholonomic: the constraints are not independent: with the holonomic ones differentiated, their matrix of velocity coefficients has rank less than 2 at a generic point; remove the redundant ones
    """

    def __init__(self, kinematics, holonomic, nonholonomic, rolling, parameters=None):
        q, dq = kinematics.coordinates(), kinematics.velocities()
        given_names = kinematics.given_names()
        self._given = check_velocity_constraints(nonholonomic, q, dq, holonomic, parameters)
        self._rolling, self._contacts = [], []
        for i, disk in enumerate(rolling):
            entry = f"rolling[{i}]"
            disk = RollingDisk.from_value(disk, entry)
            body = disk.body()
            if isinstance(body, int) and 0 < body <= len(given_names):
                body = given_names[body - 1]
            body_index(kinematics, body, f"{entry}.body")
            disk = disk.with_body(body)
            if parameters is not None:
                undeclared = set(disk.radius().variables()) - set(parameters)
                if undeclared:
                    raise ModelError(f"undeclared symbol {sorted(map(str, undeclared))[0]}; "
                                 f"declared are: {', '.join(map(str, parameters))}",
                                 entry=f"{entry}.radius")
            if any(disk.radius().has(v) for v in q + dq):
                raise ModelError("the radius cannot depend on the coordinates or velocities",
                                 entry=f"{entry}.radius")
            self._rolling.append(disk)
            self._contacts.append(rolling_contact(kinematics, disk, entry))
        self._given_holonomic = list(holonomic)
        self._holonomic = list(holonomic) + [c.holonomic() for c in self._contacts
                                             if c.holonomic() is not None]
        self._velocity = list(self._given) + [g for c in self._contacts for g in c.no_slip()]
        if self._contacts:
            # the rolling conditions with the rest: none redundant
            check_velocity_constraints(self._velocity, q, dq, self._holonomic, None,
                                       entry="rolling")

    def _repr_(self):
        disks = len(self._rolling)
        rolling = f" ({disks} rolling disk{'' if disks == 1 else 's'})" if disks else ""
        return (f"Constraint set: {len(self._holonomic)} holonomic, {len(self._velocity)} on "
                f"the velocities{rolling}")

    def holonomic(self):
        r"""
        Every holonomic constraint: the ones given, then the contact
        conditions of the rolling disks that the coordinates do not impose.

        EXAMPLES: see the module documentation.
        """
        return list(self._holonomic)

    def nonholonomic(self):
        r"""
        Every velocity constraint: the ones given, then two no-slip
        conditions per rolling disk.

        EXAMPLES: see the module documentation.
        """
        return list(self._velocity)

    def given_holonomic(self):
        r"""The holonomic constraints given (``constraints``).

        EXAMPLES: see the module documentation.
        """
        return list(self._given_holonomic)

    def given_nonholonomic(self):
        r"""The velocity constraints given (``nonholonomic``).

        EXAMPLES: see the module documentation.
        """
        return list(self._given)

    def rolling(self):
        r"""The rolling disks (body references by name).

        EXAMPLES: see the module documentation.
        """
        return list(self._rolling)

    def contacts(self):
        r"""The :class:`~sage_dynsym.mechanics.rolling.RollingContact` of every
        rolling disk.

        EXAMPLES: see the module documentation.
        """
        return list(self._contacts)

    def lines(self):
        r"""
        One line per constraint, saying where it comes from and whether it
        is holonomic (for reports).

        EXAMPLES: see the module documentation.
        """
        out = [f"constraints[{i}]: holonomic, 0 = {f}"
               for i, f in enumerate(self._given_holonomic)]
        out += [f"nonholonomic[{i}]: on the velocities, 0 = {g}"
                for i, g in enumerate(self._given)]
        for i, contact in enumerate(self._contacts):
            head = f"rolling[{i}] ({contact.disk().body()})"
            if contact.holonomic() is None:
                out.append(f"{head}: contact with the plane z = 0 held by the coordinates")
            else:
                out.append(f"{head}: contact with the plane z = 0, holonomic, "
                           f"0 = {contact.holonomic()}")
            out += [f"{head}: no slip, 0 = {g}" for g in contact.no_slip()]
        return out


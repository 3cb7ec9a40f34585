r"""
Rigid bodies: the geometric and inertial description of one body

A :class:`RigidBody` holds exactly the fields of the description of a body
in :doc:`the method </method>`: the parent body, the elementary rotations
from the parent's frame to the body's frame, the joint point `r^j_{0k}` (in
the parent's axes), its relative velocity `v^j_{0k}`, the mass centre
`r^k_{ck}` (in the body's axes), the mass and the inertia tensor about the
joint point `O_k` (in the body's axes). It is a description only;
kinematics and energies are computed by :class:`~sage_dynsym.mechanics.system.MechanicalSystem`.
The fields and their accessors are those of a
:class:`~sage_dynsym.numerics.body_tree.TreeBody`, the body the recursive
algorithms read: a rigid body adds its name, a parent given by name and the
checks of a description, whose entries its errors name.

EXAMPLES::

    sage: from sage_dynsym import RigidBody
    sage: psi, theta, m, l = var('psi theta m l')
    sage: B = RigidBody('pendulum', parent=0, rotations=[(3, psi), (1, theta)],
    ....:               mass_center=[0, 0, l], mass=m,
    ....:               inertia=diagonal_matrix([m*l^2, m*l^2, 0])); B
    Rigid body 'pendulum' (parent 0, rotations [(3, psi), (1, theta)], mass m)
    sage: B.inertia()
    [l^2*m     0     0]
    [    0 l^2*m     0]
    [    0     0     0]

Bad input is rejected with the offending entry named::

    sage: RigidBody('b', rotations=[(4, psi)])
    Traceback (most recent call last):
    ...
    ModelError: b.rotations[0]: rotation axis must be 1, 2 or 3 (x, y, z), got 4
    sage: RigidBody('b', inertia=[[1, 2, 0], [0, 1, 0], [0, 0, 1]])
    Traceback (most recent call last):
    ...
    ModelError: b.inertia: the inertia tensor must be symmetric; entry (0, 1) is 2 but entry (1, 0) is 0
"""
from itertools import combinations

from sage.matrix.constructor import matrix
from sage.matrix.special import identity_matrix
from sage.rings.real_mpfi import RealIntervalField
from sage.symbolic.ring import SR

from ..errors import ModelError
from ..numerics.body_tree import TreeBody

__all__ = ['as_vector3', 'as_scalar', 'RigidBody']


def as_vector3(value, entry):
    r"""
    Three components as symbolic expressions (``None`` stays ``None``);
    :class:`~sage_dynsym.errors.ModelError` naming ``entry`` otherwise.

    EXAMPLES::

        sage: from sage_dynsym.mechanics.rigid_body import as_vector3
        sage: as_vector3([0, 0, var('l')], 'mass_center')
        (0, 0, l)
        sage: as_vector3([1, 2], 'joint')
        Traceback (most recent call last):
        ...
        ModelError: joint: expected a list of 3 components, got 2
    """
    if value is None:
        return None
    try:
        components = list(value)
    except TypeError as err:
        raise ModelError(f"expected a list of 3 components, got {value!r}", entry=entry) from err
    if len(components) != 3:
        raise ModelError(f"expected a list of 3 components, got {len(components)}", entry=entry)
    return tuple(as_scalar(c, f"{entry}[{i}]") for i, c in enumerate(components))


def as_scalar(value, entry):
    r"""
    One component as a symbolic expression; :class:`~sage_dynsym.errors.ModelError`
    naming ``entry`` otherwise.

    EXAMPLES::

        sage: from sage_dynsym.mechanics.rigid_body import as_scalar
        sage: as_scalar(1/2, 'mass')
        1/2
    """
    try:
        return SR(value)
    except (TypeError, ValueError) as err:
        raise ModelError(f"expected a symbolic expression, got {value!r}", entry=entry) from err


_RIF = RealIntervalField(128)


def _interval(value):
    # an enclosure of a numeric real constant (sqrt(2), pi/3, 1/7), else None
    if value.variables():
        return None
    try:
        return _RIF(value)
    except (TypeError, ValueError, ArithmeticError):
        return None


def _check_real(value, entry, what):
    if value.has(SR.I()) or (value.is_numeric() and not value.is_real()):
        raise ModelError(f"{what} must be real, got {value}", entry=entry)
    if not value.variables() and (value.is_infinity() or str(value) in ('NaN', 'nan')):
        raise ModelError(f"{what} must be a finite number, got {value}", entry=entry)


def _check_nonnegative(value, entry, what):
    _check_real(value, entry, what)
    x = _interval(value)
    if x is not None and x.upper() < 0:
        raise ModelError(f"{what} must be non-negative, got {value}", entry=entry)


def _check_positive_semidefinite(tensor, entry):
    r"""
    The numeric principal minors of ``tensor`` (symmetric 3x3) and of
    `\tfrac12 \operatorname{tr}(J)\, E - J` must not be negative: the
    first says that the tensor is positive semi-definite, the second that
    its principal moments satisfy the triangle inequality
    `J_i \le J_j + J_k` (the eigenvalues of the second matrix are
    `\tfrac12(J_j + J_k - J_i)`). Minors with a symbol in them are not
    judged: symbolic tensors are accepted without assuming signs.
    """
    for i in range(3):
        _check_real(tensor[i, i], entry, "the moments of inertia")
        for j in range(i + 1, 3):
            _check_real(tensor[i, j], entry, "the products of inertia")
    triangle = tensor.trace() / 2 * identity_matrix(SR, 3) - tensor
    for what, M in (("positive semi-definite", tensor), ("triangle", triangle)):
        for size in (1, 2, 3):
            for rows in combinations(range(3), size):
                block = M.matrix_from_rows_and_columns(rows, rows)
                if any(e.variables() for e in block.list()):
                    continue
                x = _interval(SR(block.det()))
                if x is None or not x.upper() < 0:
                    continue
                if what == "triangle":
                    import numpy
                    moments = numpy.linalg.eigvalsh([[float(e) for e in row]
                                                     for row in tensor.rows()])
                    raise ModelError("the principal moments of inertia must satisfy the "
                                     "triangle inequality (none larger than the sum of the "
                                     "other two), got about "
                                     f"{', '.join(f'{m:.6g}' for m in sorted(moments))}",
                                     entry=entry)
                if size == 1:
                    raise ModelError(f"the moments of inertia must be non-negative, got "
                                     f"{M[rows[0], rows[0]]}", entry=entry)
                raise ModelError("the inertia tensor must be positive semi-definite; the "
                                 f"principal minor of rows {', '.join(str(r + 1) for r in rows)}"
                                 f" is {block.det()} < 0", entry=entry)


class RigidBody(TreeBody):
    r"""
    One rigid body of a mechanical system: a
    :class:`~sage_dynsym.numerics.body_tree.TreeBody` (the fields that the
    recursions read, with their accessors) with a name, its parent given by
    name, index or object, and the checks of a description.

    INPUT:

    - ``name`` -- a string
    - ``parent`` -- (default: 0) ``0`` for the inertial frame, or the parent
      body: its name, its 1-based index in the system, or the
      :class:`RigidBody` itself
    - ``rotations`` -- (default: ``[]``) list of pairs ``(axis, angle)``:
      elementary rotations from the parent's frame, each about the *new*
      axis; ``axis`` in ``{1, 2, 3}``; angles may be coordinates, functions
      of ``t`` or constants
    - ``joint`` -- (default: zero) `r^j_{0k}`, the joint point `O_k` in the
      parent's axes
    - ``velocity`` -- (default: ``None``, the time derivative of ``joint``)
      `v^j_{0k}`, the relative velocity of `O_k` in the parent's axes
    - ``mass_center`` -- (default: zero) `r^k_{ck}` in the body's axes
    - ``mass`` -- (default: 0) the mass `m_k`
    - ``inertia`` -- (default: zero) symmetric 3x3 inertia tensor about `O_k`
      in the body's axes

    A massless carrier (``mass=0`` and zero inertia) only defines a frame.

    EXAMPLES::

        sage: from sage_dynsym import RigidBody
        sage: z, dz = var('z dz')
        sage: slider = RigidBody('slider', joint=[0, 0, z], mass=1)
        sage: slider.velocity() is None, slider.joint()
        (True, (0, 0, z))

    The fields and their accessors are those of a tree body, which the
    recursive algorithms read::

        sage: from sage_dynsym.numerics.body_tree import TreeBody
        sage: a, l, m = var('a l m')
        sage: b = RigidBody('b', rotations=[(2, a)], joint=[0, 0, 1], velocity=[0, 0, dz],
        ....:               mass_center=[0, 0, l], mass=m)
        sage: isinstance(b, TreeBody), b.rotations(), b.velocity(), b.mass_center(), b.mass()
        (True, [(2, a)], (0, 0, dz), (0, 0, l), m)
        sage: b.inertia().is_zero(), b.inertia().is_immutable()
        (True, True)

    TESTS::

        sage: RigidBody('b', joint=[1, 2])
        Traceback (most recent call last):
        ...
        ModelError: b.joint: expected a list of 3 components, got 2
        sage: RigidBody('b', mass=-1)
        Traceback (most recent call last):
        ...
        ModelError: b.mass: the mass must be non-negative, got -1
        sage: RigidBody('b', inertia=[[1, 0], [0, 1]])
        Traceback (most recent call last):
        ...
        ModelError: b.inertia: expected a symmetric 3x3 matrix
        sage: RigidBody('b', inertia=diagonal_matrix([1, -1, 1]))
        Traceback (most recent call last):
        ...
        ModelError: b.inertia: the moments of inertia must be non-negative, got -1
        sage: RigidBody('b', rotations=[3])
        Traceback (most recent call last):
        ...
        ModelError: b.rotations[0]: expected a pair (axis, angle), got 3
        sage: RigidBody('b', mass=I*var('m'))
        Traceback (most recent call last):
        ...
        ModelError: b.mass: the mass must be real, got I*m
        sage: RigidBody('b', mass=1 - pi)
        Traceback (most recent call last):
        ...
        ModelError: b.mass: the mass must be non-negative, got -pi + 1
        sage: RigidBody('b', mass=float('nan'))
        Traceback (most recent call last):
        ...
        ModelError: b.mass: the mass must be a finite number, got NaN
        sage: RigidBody('b', inertia=[[1, 2, 0], [2, 1, 0], [0, 0, 1]])
        Traceback (most recent call last):
        ...
        ModelError: b.inertia: the inertia tensor must be positive semi-definite; the principal minor of rows 1, 2 is -3 < 0
        sage: RigidBody('b', inertia=diagonal_matrix([1, 1, 3]))
        Traceback (most recent call last):
        ...
        ModelError: b.inertia: the principal moments of inertia must satisfy the triangle inequality (none larger than the sum of the other two), got about 1, 1, 3

    A massless carrier, a thin rod (`A = B`, `C = 0`) and symbolic tensors
    with products of inertia of any sign are accepted::

        sage: A, B, C, D = var('A B C D')
        sage: RigidBody('carrier', mass=0).is_massless()
        True
        sage: RigidBody('rod', mass=1, inertia=diagonal_matrix([1/3, 1/3, 0])).inertia()[2, 2]
        0
        sage: RigidBody('b', inertia=[[A, -D, 0], [-D, B, 0], [0, 0, C]]).inertia()[0, 1]
        -D
        sage: RigidBody('b', inertia=[[2, sqrt(2), 0], [sqrt(2), 1, 0], [0, 0, 3]]).name()
        'b'
        sage: RigidBody('')
        Traceback (most recent call last):
        ...
        ModelError: name: a body needs a non-empty name
    """

    def __init__(self, name, parent=0, rotations=(), joint=(0, 0, 0), velocity=None,
                 mass_center=(0, 0, 0), mass=0, inertia=None):
        if not isinstance(name, str) or not name:
            raise ModelError("a body needs a non-empty name", entry="name")
        super().__init__(parent, rotations=rotations, joint=joint, velocity=velocity, mass=mass,
                         mass_center=mass_center, inertia=inertia, name=name)

    # the conversions of TreeBody, with the checks of a description and the
    # entries named as there

    def _parent_of(self, parent):
        # resolved by the system (by name, index or object), see sorted_by_parents
        return parent

    def _rotation_of(self, i, rotation):
        entry = f"{self._name}.rotations[{i}]"
        if not isinstance(rotation, (tuple, list)) or len(rotation) != 2:
            raise ModelError(f"expected a pair (axis, angle), got {rotation!r}", entry=entry)
        axis, angle = rotation
        if axis not in (1, 2, 3) or isinstance(axis, bool):
            raise ModelError(f"rotation axis must be 1, 2 or 3 (x, y, z), got {axis!r}",
                             entry=entry)
        return int(axis), as_scalar(angle, entry)

    def _vector_of(self, value, field):
        return as_vector3(value, f"{self._name}.{field}")

    def _mass_of(self, mass):
        entry = f"{self._name}.mass"
        mass = as_scalar(mass, entry)
        _check_nonnegative(mass, entry, "the mass")
        return mass

    def _inertia_of(self, inertia):
        entry = f"{self._name}.inertia"
        if inertia is None:
            return super()._inertia_of(None)
        try:
            tensor = matrix(SR, inertia)
        except (TypeError, ValueError) as err:
            raise ModelError("expected a symmetric 3x3 matrix", entry=entry) from err
        if tensor.dimensions() != (3, 3):
            raise ModelError("expected a symmetric 3x3 matrix", entry=entry)
        for i in range(3):
            for j in range(i + 1, 3):
                if not bool(tensor[i, j] == tensor[j, i]):
                    raise ModelError(
                        f"the inertia tensor must be symmetric; entry ({i}, {j}) is "
                        f"{tensor[i, j]} but entry ({j}, {i}) is {tensor[j, i]}", entry=entry)
        _check_positive_semidefinite(tensor, entry)
        return super()._inertia_of(tensor)

    def _repr_(self):
        return (f"Rigid body {self._name!r} (parent {self.parent_name()}, rotations "
                f"{self._rotations}, mass {self._mass})")

    def parent_name(self):
        r"""
        The parent as a printable name (``0`` for the inertial frame).

        EXAMPLES::

            sage: from sage_dynsym import RigidBody
            sage: base = RigidBody('base')
            sage: RigidBody('arm', parent=base).parent_name(), base.parent_name()
            ('base', 0)
            sage: RigidBody('arm', parent='base').parent(), RigidBody('arm').name()
            ('base', 'arm')
        """
        return self._parent.name() if isinstance(self._parent, RigidBody) else self._parent

    def subs(self, values, parent=None):
        r"""
        The body with ``values`` (a dictionary ``{symbol: value}``)
        substituted in its angles, vectors, mass and inertia; the parent is
        ``parent`` if given, else the same (a body object kept by name).

        EXAMPLES::

            sage: from sage_dynsym import RigidBody
            sage: m, l = var('m l')
            sage: b = RigidBody('b', mass_center=[0, 0, l], mass=m).subs({m: 2, l: 0.5})
            sage: b.mass(), b.mass_center()
            (2, (0, 0, 0.500000000000000))

        TESTS::

            sage: RigidBody('b', mass=m).subs({m: -1})
            Traceback (most recent call last):
            ...
            ModelError: b.mass: the mass must be non-negative, got -1
        """
        def sub(v):
            return None if v is None else [SR(c).subs(values) for c in v]
        if parent is None:
            parent = self.parent_name()
        return RigidBody(self._name, parent=parent,
                         rotations=[(axis, SR(angle).subs(values))
                                    for axis, angle in self._rotations],
                         joint=sub(self._joint), velocity=sub(self._velocity),
                         mass_center=sub(self._mass_center), mass=self._mass.subs(values),
                         inertia=self._inertia.apply_map(lambda e: SR(e).subs(values)))

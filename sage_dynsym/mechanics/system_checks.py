r"""
The checks of a mechanical system's construction

:func:`check_declared_symbols` checks that every symbol of the data of a
:class:`~sage_dynsym.mechanics.system.MechanicalSystem` is declared,
:func:`checked_load` checks a load against the system's kinematics, and
:class:`PhysicalConditions` decides the physical signs of the data with the
declared signs (and nothing else): a mass, a principal moment of inertia (the diagonal
entries and the principal minors of the inertia tensor `J`, and those of
`\operatorname{tr}(J)\,E - 2J` for the triangle inequality), the radius of a
rolling disk, the distance of a Newtonian field. An expression that is
negative under the declared signs (for a mass or a moment of inertia: one
that is not zero and never positive; for a radius or a distance: never
positive) is refused, naming the entry; one that the declared signs do not
decide becomes a condition of :meth:`~sage_dynsym.mechanics.system.MechanicalSystem.conditions`,
printed by the report and checked at the values given to the numerics.

EXAMPLES::

    sage: from sage_dynsym import MechanicalSystem, RigidBody
    sage: MechanicalSystem([RigidBody('p', parent='q'), RigidBody('q', parent='p')], [])
    Traceback (most recent call last):
    ...
    ModelError: bodies: the parents form a cycle: p -> q -> p

A mass negative under the declared signs, and one they leave open::

    sage: z, m, a, b = var('z m a b')
    sage: MechanicalSystem([RigidBody('p', joint=[0, 0, z], mass=-m)], [z], positive=[m])
    Traceback (most recent call last):
    ...
    ModelError: bodies[0].mass: the mass of body 'p' must be non-negative, but -m is negative under the declared signs (m > 0)
    sage: S = MechanicalSystem([RigidBody('p', joint=[0, 0, z], mass=a - b)], [z]); S.conditions()
    [a - b >= 0]
    sage: S.simulate({a: 1, b: 2}, {z: 0, 'dz': 1}, 1)
    Traceback (most recent call last):
    ...
    ModelError: values: the values break the condition a - b >= 0 of the model (it is -1 there)

A tensor with zero moments about two axes needs zero products of inertia
about them::

    sage: A, D = var('A D')
    sage: MechanicalSystem([RigidBody('p', inertia=[[A, D, 0], [D, 0, 0], [0, 0, A]])], [],
    ....:                  positive=[A]).conditions()
    [D == 0]
"""
import operator
from itertools import combinations

from sage.structure.sage_object import SageObject
from sage.symbolic.ring import SR

from ..algebra.conditions import nonzero_conditions, positive_conditions
from ..algebra.polynomials import FACTOR_LIMIT
from ..algebra.size import polynomial_terms
from ..errors import ModelError
from ..symbols import t
from .loads import Load, body_index

__all__ = ['check_declared_symbols', 'checked_load', 'PhysicalConditions']


def _undeclared_check(kinematics, parameters):
    # check(expr, entry): refuses a symbol that is no coordinate, velocity,
    # parameter or t
    declared = (set(kinematics.coordinates()) | set(kinematics.velocities())
                | set(parameters) | {t})
    names = ", ".join(sorted(map(str, set(parameters) | {t})))

    def check(expr, entry):
        for v in SR(expr).variables():
            if v not in declared:
                raise ModelError(f"undeclared symbol {v}; declared are: {names}", entry=entry)
    return check


def check_declared_symbols(kinematics, parameters, dissipation=0, forces=(),
                           force_function=None):
    r"""
    Refuse a symbol in the bodies of ``kinematics`` (a
    :class:`~sage_dynsym.mechanics.system_kinematics.SystemKinematics`), the
    dissipation function, the generalized forces or the expressions of the
    force function that is no coordinate, velocity, parameter of
    ``parameters`` or ``t``.

    EXAMPLES::

        sage: from sage_dynsym import RigidBody
        sage: from sage_dynsym.mechanics.system_kinematics import SystemKinematics
        sage: from sage_dynsym.mechanics.system_checks import check_declared_symbols
        sage: z, m, k = var('z m k')
        sage: K = SystemKinematics([RigidBody('p', joint=[0, 0, z], mass=m)], [z])
        sage: check_declared_symbols(K, [m], force_function=-z^2/2)
        sage: check_declared_symbols(K, [m], force_function=[-k*z^2/2])
        Traceback (most recent call last):
        ...
        ModelError: force_function[0]: undeclared symbol k; declared are: m, t
    """
    from .force_functions import force_terms
    check = _undeclared_check(kinematics, parameters)
    for body in kinematics.bodies():
        n = body.name()
        for i, (_, angle) in enumerate(body.rotations()):
            check(angle, f"{n}.rotations[{i}]")
        for field in ("joint", "velocity", "mass_center"):
            for c in getattr(body, field)() or ():
                check(c, f"{n}.{field}")
        check(body.mass(), f"{n}.mass")
        for c in body.inertia().list():
            check(c, f"{n}.inertia")
    check(dissipation, "dissipation")
    for i, f in enumerate(forces):
        check(f, f"forces[{i}]")
    for i, term in enumerate(force_terms(force_function)):
        if not hasattr(term, 'evaluate'):
            check(term, "force_function" if not isinstance(force_function, list)
                  else f"force_function[{i}]")


def checked_load(load, entry, kinematics, parameters=None):
    r"""
    The load ``load`` (a :class:`~sage_dynsym.mechanics.loads.Load` or a
    dict of its keywords) checked against ``kinematics`` (a
    :class:`~sage_dynsym.mechanics.system_kinematics.SystemKinematics`) and
    the declared ``parameters`` (``None``: not declared), its body
    references as names; ``entry`` names it in errors.

    EXAMPLES::

        sage: from sage_dynsym import RigidBody
        sage: from sage_dynsym.mechanics.system_kinematics import SystemKinematics
        sage: from sage_dynsym.mechanics.system_checks import checked_load
        sage: x, F = var('x F')
        sage: K = SystemKinematics([RigidBody('b', joint=[x, 0, 0])], [x])
        sage: checked_load({'body': 1, 'force': [F, 0, 0]}, 'loads[0]', K)
        Load on 'b' at (0, 0, 0): force (F, 0, 0), in the inertial axes
        sage: checked_load({'body': 1, 'force': [var('ddx'), 0, 0]}, 'loads[0]', K)
        Traceback (most recent call last):
        ...
        ModelError: loads[0].force: the force cannot depend on ddx
    """
    load = Load.from_value(load, entry)
    # a body index counts in the order the bodies were given (as parent
    # indices do); keep names, which do not depend on the order
    given_names = kinematics.given_names()
    names = {}
    for key in ('body', 'axes'):
        ref = getattr(load, key)()
        if isinstance(ref, int) and ref > 0:
            if ref > len(given_names):
                raise ModelError(f"body index {ref} out of range 1..{len(given_names)}",
                                 entry=f"{entry}.{key}")
            ref = given_names[ref - 1]
        if ref != 0:
            body_index(kinematics, ref, f"{entry}.{key}")
        names[key] = ref
    load = Load(names['body'], point=load.point(), force=load.force(),
                torque=load.torque(), axes=names['axes'])
    accelerations, velocities = kinematics.accelerations(), kinematics.velocities()
    for field in ('point', 'force', 'torque'):
        for c in getattr(load, field)() or ():
            for v in SR(c).variables():
                if v in accelerations or (field == 'point' and v in velocities):
                    what = 'point of application' if field == 'point' else field
                    raise ModelError(f"the {what} cannot depend on {v}",
                                     entry=f"{entry}.{field}")
    if parameters is not None:
        check = _undeclared_check(kinematics, parameters)
        for field in ('point', 'force', 'torque'):
            for c in getattr(load, field)() or ():
                check(c, f"{entry}.{field}")
    return load


class PhysicalConditions(SageObject):
    r"""
    The physical signs of the data of a mechanical system, decided with
    the declared signs (see the module documentation): what they contradict
    is refused at construction, what they leave open is
    :meth:`conditions`.

    INPUT:

    - ``kinematics`` -- the
      :class:`~sage_dynsym.mechanics.system_kinematics.SystemKinematics` of
      the system (its bodies, and their names in the order given)
    - ``positive`` -- the parameters declared positive
    - ``rolling`` -- (optional) the :class:`~sage_dynsym.mechanics.rolling.RollingDisk`
      objects (their radii)
    - ``force_terms`` -- (optional) the terms of the force function (the
      conditions of its fields)

    EXAMPLES::

        sage: from sage_dynsym import RigidBody
        sage: from sage_dynsym.mechanics.system_kinematics import SystemKinematics
        sage: from sage_dynsym.mechanics.system_checks import PhysicalConditions
        sage: A, C, m = var('A C m')
        sage: K = SystemKinematics([RigidBody('top', mass=m, inertia=diagonal_matrix([A, A, C]))], [])
        sage: P = PhysicalConditions(K, [A, C]); P
        Physical conditions [m >= 0, 2*A - C >= 0]
        sage: P.conditions()
        [m >= 0, 2*A - C >= 0]
        sage: PhysicalConditions(K, [A, C, m]).conditions()
        [2*A - C >= 0]
        sage: PhysicalConditions(SystemKinematics([RigidBody('p', mass=-m)], []), [m])
        Traceback (most recent call last):
        ...
        ModelError: bodies[0].mass: the mass of body 'p' must be non-negative, but -m is negative under the declared signs (m > 0)

    Within a system (its
    :meth:`~sage_dynsym.mechanics.system.MechanicalSystem.conditions`), with
    the conditions of a Newtonian field::

        sage: from sage_dynsym import MechanicalSystem, NewtonianField
        sage: phi, nu, r = var('phi nu r')
        sage: top = RigidBody('top', rotations=[(3, phi)], mass=1,
        ....:                 inertia=diagonal_matrix([A, A, C]))
        sage: MechanicalSystem([top], [phi], positive=[A, C]).conditions()
        [2*A - C >= 0]
        sage: MechanicalSystem([top], [phi], positive=[A, C],
        ....:                  force_function=NewtonianField(nu, r, [1, 0, 0])).conditions()
        [2*A - C >= 0, r > 0]
        sage: MechanicalSystem([top], [phi], positive=[A, C, r],
        ....:                  force_function=NewtonianField(nu, -r, [1, 0, 0]))
        Traceback (most recent call last):
        ...
        ModelError: force_function: the distance from the attracting centre must be positive, but -r is never positive under the declared signs (A > 0, C > 0, r > 0)
    """

    def __init__(self, kinematics, positive, rolling=(), force_terms=()):
        self._positive = list(positive)
        self._declared = ", ".join(f"{p} > 0" for p in self._positive) or "none"
        self._open, self._listed = [], set()
        given_names = kinematics.given_names()
        for body in kinematics.bodies():
            self._check_body(given_names.index(body.name()), body)
        for k, disk in enumerate(rolling):
            self._require(disk.radius(), f"rolling[{k}].radius", "the radius", strict=True)
        for term in force_terms:
            for condition in getattr(term, 'conditions', list)():
                if condition.operator() is operator.gt:
                    self._require(condition.lhs() - condition.rhs(), "force_function",
                                  "the distance from the attracting centre", strict=True)
                else:
                    self._open.append(condition)

    def _repr_(self):
        return f"Physical conditions {self._open}"

    def conditions(self):
        r"""
        The conditions on the parameters that the declared signs leave
        open (a list of relations, each to hold).

        EXAMPLES: see :class:`PhysicalConditions`.
        """
        return list(self._open)

    def _check_body(self, i, body):
        from sage.matrix.constructor import identity_matrix
        name = body.name()
        self._require(body.mass(), f"bodies[{i}].mass", f"the mass of body {name!r}",
                      nonzero=True)
        J = body.inertia()
        for what, M in (("the moments of inertia", J),
                        ("the triangle inequality of the moments of inertia",
                         J.trace() * identity_matrix(SR, 3) - 2 * J)):
            for size in (1, 2, 3):
                for rows in combinations(range(3), size):
                    block = M.matrix_from_rows_and_columns(rows, rows)
                    if size > 1 and block.is_diagonal():
                        continue        # the product of the 1x1 minors
                    self._require(block.det(), f"bodies[{i}].inertia",
                                  f"{what} of body {name!r}" + (
                                      "" if size == 1 else f" (the principal minor of rows "
                                      f"{', '.join(str(r + 1) for r in rows)})"),
                                  nonzero=size == 1 and M is J)

    def _require(self, expr, entry, what, strict=False, nonzero=False):
        # expr > 0 (strict) or expr >= 0: refused where the declared signs
        # contradict it, a condition where they leave it open
        expr = SR(expr)
        if not expr.variables():
            return                      # numbers: checked where they are given
        if polynomial_terms(expr) > FACTOR_LIMIT:
            # too large to decide quickly: stated, not assumed
            self._open.append(expr > 0 if strict else expr >= 0)
            return
        # positive_conditions(e) is [] where e > 0 always, None where never
        positive = self._positive
        simple = positive_conditions(expr, positive)
        if strict:
            fails = "never positive" if simple is None else None
            holds = simple == []
        else:
            opposite = positive_conditions(-expr, positive)
            fails = ("negative" if opposite == [] else
                     "never positive" if nonzero and simple is None else None)
            holds = opposite is None
        if fails:
            raise ModelError(f"{what} must be {'positive' if strict else 'non-negative'}, "
                             f"but {expr} is {fails} under the declared signs "
                             f"({self._declared})", entry=entry)
        if holds:
            return
        condition = expr > 0 if strict else expr >= 0
        # positive factors dropped (m*(A*C - D^2) >= 0 is A*C - D^2 >= 0)
        if simple is None:          # never positive: expr >= 0 only where it is 0
            zero = nonzero_conditions(expr, positive) or []
            if len(zero) == 1:      # -A*D^2 >= 0 is D == 0
                condition = zero[0].lhs() - zero[0].rhs() == 0
        elif len(simple) == 1 and simple[0].operator() in (operator.gt, operator.lt):
            rel = simple[0]
            expr = (rel.lhs() - rel.rhs()) * (1 if rel.operator() is operator.gt else -1)
            condition = expr > 0 if strict else expr >= 0
        if str(condition) not in self._listed:
            self._listed.add(str(condition))
            self._open.append(condition)

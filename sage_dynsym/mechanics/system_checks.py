r"""
The checks of a mechanical system's construction

:class:`SystemChecks` is a base class of
:class:`~sage_dynsym.mechanics.system.MechanicalSystem`: it orders the
bodies parents first (refusing unknown parents, duplicate names and cycles),
checks that every symbol of the model is declared, checks the loads, and
the body indices given to the kinematics.

It also decides the physical signs of the data with the declared signs
(and nothing else): a mass, a principal moment of inertia (the diagonal
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
import numbers
import operator
from itertools import combinations

from sage.symbolic.ring import SR

from ..algebra.conditions import nonzero_conditions, positive_conditions
from ..algebra.polynomials import FACTOR_LIMIT
from ..algebra.size import polynomial_terms
from ..arguments import is_integer
from ..errors import ModelError, brief
from ..symbols import acceleration, t
from .loads import Load, body_index
from .rigid_body import RigidBody

__all__ = ['SystemChecks']


class SystemChecks:
    r"""
    The construction checks of a
    :class:`~sage_dynsym.mechanics.system.MechanicalSystem` (a base class
    of it, see the module documentation).

    EXAMPLES: see :class:`~sage_dynsym.mechanics.system.MechanicalSystem`.
    """

    def _sorted_by_parents(self, bodies):
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
        self._parents = [None] + [0 if parent_of[i] is None else position[parent_of[i]]
                                  for i in order]
        return [bodies[i] for i in order]

    def _check_symbols(self):
        declared = set(self._coordinates) | set(self._velocities) | set(self._parameters) | {t}
        names = ", ".join(sorted(map(str, set(self._parameters) | {t})))

        def check(expr, entry):
            for v in SR(expr).variables():
                if v not in declared:
                    raise ModelError(f"undeclared symbol {v}; declared are: {names}", entry=entry)

        for body in self._bodies:
            n = body.name()
            for i, (_, angle) in enumerate(body.rotations()):
                check(angle, f"{n}.rotations[{i}]")
            for field in ("joint", "velocity", "mass_center"):
                for c in getattr(body, field)() or ():
                    check(c, f"{n}.{field}")
            check(body.mass(), f"{n}.mass")
            for c in body.inertia().list():
                check(c, f"{n}.inertia")
        check(self._dissipation, "dissipation")
        for i, f in enumerate(self._forces):
            check(f, f"forces[{i}]")
        for i, term in enumerate(self.force_terms()):
            if not hasattr(term, 'evaluate'):
                check(term, "force_function" if not isinstance(self._force, list)
                      else f"force_function[{i}]")

    def _checked_load(self, load, entry, given_names):
        load = Load.from_value(load, entry)
        # a body index counts in the order the bodies were given (as parent
        # indices do); keep names, which do not depend on the order
        names = {}
        for key in ('body', 'axes'):
            ref = getattr(load, key)()
            if isinstance(ref, int) and ref > 0:
                if ref > len(given_names):
                    raise ModelError(f"body index {ref} out of range 1..{len(given_names)}",
                                     entry=f"{entry}.{key}")
                ref = given_names[ref - 1]
            if ref != 0:
                body_index(self, ref, f"{entry}.{key}")
            names[key] = ref
        load = Load(names['body'], point=load.point(), force=load.force(),
                    torque=load.torque(), axes=names['axes'])
        accelerations = self._accelerations()
        for field in ('point', 'force', 'torque'):
            for c in getattr(load, field)() or ():
                for v in SR(c).variables():
                    if v in accelerations or (field == 'point' and v in self._velocities):
                        what = 'point of application' if field == 'point' else field
                        raise ModelError(f"the {what} cannot depend on {v}",
                                         entry=f"{entry}.{field}")
        if self._parameters is not None:
            declared = set(self._coordinates) | set(self._velocities) | set(self._parameters) | {t}
            names = ", ".join(sorted(map(str, set(self._parameters) | {t})))
            for field in ('point', 'force', 'torque'):
                for c in getattr(load, field)() or ():
                    for v in SR(c).variables():
                        if v not in declared:
                            raise ModelError(f"undeclared symbol {v}; declared are: {names}",
                                             entry=f"{entry}.{field}")
        return load

    def _physical_conditions(self, given_names):
        # the signs of the masses, moments of inertia, radii and distances,
        # decided with the declared signs (see the module documentation)
        from sage.matrix.constructor import identity_matrix
        positive = list(self._positive)
        declared = ", ".join(f"{p} > 0" for p in positive) or "none"
        open_conditions, listed = [], set()

        def require(expr, entry, what, strict=False, nonzero=False):
            expr = SR(expr)
            if not expr.variables():
                return                      # numbers: checked where they are given
            if polynomial_terms(expr) > FACTOR_LIMIT:
                # too large to decide quickly: stated, not assumed
                open_conditions.append(expr > 0 if strict else expr >= 0)
                return
            # positive_conditions(e) is [] where e > 0 always, None where never
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
                                 f"({declared})", entry=entry)
            if not holds:
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
                if str(condition) not in listed:
                    listed.add(str(condition))
                    open_conditions.append(condition)

        for body in self._bodies:
            i, name = given_names.index(body.name()), body.name()
            require(body.mass(), f"bodies[{i}].mass", f"the mass of body {name!r}", nonzero=True)
            J = body.inertia()
            for what, M in (("the moments of inertia", J),
                            ("the triangle inequality of the moments of inertia",
                             J.trace() * identity_matrix(SR, 3) - 2 * J)):
                for size in (1, 2, 3):
                    for rows in combinations(range(3), size):
                        block = M.matrix_from_rows_and_columns(rows, rows)
                        if size > 1 and block.is_diagonal():
                            continue        # the product of the 1x1 minors
                        require(block.det(), f"bodies[{i}].inertia",
                                f"{what} of body {name!r}" + (
                                    "" if size == 1 else f" (the principal minor of rows "
                                    f"{', '.join(str(r + 1) for r in rows)})"),
                                nonzero=size == 1 and M is J)
        for k, disk in enumerate(self._constraint_set.rolling()):
            require(disk.radius(), f"rolling[{k}].radius", "the radius", strict=True)
        for term in self.force_terms():
            for condition in getattr(term, 'conditions', list)():
                if condition.operator() is operator.gt:
                    require(condition.lhs() - condition.rhs(), "force_function",
                            "the distance from the attracting centre", strict=True)
                else:
                    open_conditions.append(condition)
        return open_conditions

    def _accelerations(self):
        return [acceleration(q) for q in self._coordinates]

    def _check_index(self, k, inertial=False):
        # a 1-based body index (0, the inertial frame, where ``inertial``)
        low = 0 if inertial else 1
        if not is_integer(k):
            raise ModelError(f"expected a body index {low}..{len(self._bodies)}"
                             f"{' (0: the inertial frame)' if inertial else ''}, got {brief(k)}",
                             entry="k")
        if not low <= k <= len(self._bodies):
            raise ModelError(f"body index {k} out of range {low}..{len(self._bodies)}")


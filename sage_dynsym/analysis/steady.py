r"""
Linearization about steady motions, with holonomic and velocity constraints

A *steady motion* of equations `E(q, \dot q, \ddot q) = C^T\nu` (Lagrange's
equations with the multipliers `\nu` of the constraints, see
:mod:`~sage_dynsym.analysis.motion`) keeps some coordinates fixed and its
independent speeds constant, while the other coordinates move: a bicycle
running straight at the speed `v` (its position, heading and wheel angles
move), a disk rolling upright, a sleigh sliding straight on. It is given by
an :class:`~sage_dynsym.analysis.operating_point.OperatingPoint`.

The constraints are written at the level of velocities,
`\Phi(q, \dot q, t) = C(q, t)\dot q + c(q, t) = 0`: the holonomic ones
`f(q, t) = 0` differentiated once, the velocity constraints as they are.
With `k = n - m` *independent speeds* `u` among the velocities (the
velocities of the coordinates to linearize in, and more chosen so that the
constraints can be solved for the others at the point), the admissible
velocities are `\dot q = B(q)u + \beta(q, t)`, and Kane's equations
[KL1985]_ -- the Voronets equations when, as here, the speeds are
velocities of coordinates -- are `B^T E = 0`: the constraint forces drop out.
The linearization is computed without forming `B(q)` symbolically:
differentiating `C B = 0` gives
`\delta(B^T E) = B_0^T(\delta E - \delta C^T\nu_0)`, with the multipliers
`\nu_0` of the steady motion (`C_0^T\nu_0 = E_0`). The perturbations of the
velocities and accelerations follow from the constraints differentiated once
and twice; those of the coordinates tied by holonomic constraints are
solved to first order from `J\,\delta q = 0`. The coordinates not linearized
in must not appear in the result (they are ignorable: a position on the
plane, a heading, a wheel's angle), nor may the extra speeds feed into the
equations of the listed coordinates; then the linearized equations are, in
the listed coordinates `z`,

.. MATH::

    M\ddot z + S\dot z + W z = 0,

rows being Kane's equations of their velocities. Every step is exact, in
rational functions of the parameters and of the sines and cosines (see
:mod:`~sage_dynsym.algebra.trig_linear`).

EXAMPLES:

A knife edge (a blade at `(x, y)` heading `\theta`, mass `m`, moment of
inertia `I`) sliding straight along `x` at the speed `v`::

    sage: from sage_dynsym.analysis.motion import SecondOrderEquations
    sage: from sage_dynsym.analysis.operating_point import OperatingPoint
    sage: from sage_dynsym.analysis.steady import steady_linearization
    sage: x, y, th, dx, dy, dth, ddx, ddy, ddth = var('x y theta dx dy dtheta ddx ddy ddtheta')
    sage: m, I, v, la = var('m I v la')
    sage: E = SecondOrderEquations([m*ddx - la*sin(th), m*ddy + la*cos(th), I*ddth],
    ....:                          [x, y, th], [dx, dy, dth], [ddx, ddy, ddth],
    ....:                          velocity_constraints=[sin(th)*dx - cos(th)*dy],
    ....:                          velocity_multipliers=[la])
    sage: s = steady_linearization(E, OperatingPoint('straight', {th: 0}, {dx: v}), [th]); s
    Steady motion 'straight' linearized in (theta): speeds (dtheta, dx)
    sage: s.M(), s.S(), s.W()
    ([I], [0], [0])
    sage: s.velocities(), s.dropped(), s.decoupled_speeds()
    ({dx: v, dy: 0, dtheta: 0}, [x, y], [dx])

REFERENCES:

- [KL1985]_ (Kane's equations with dependent speeds)
- J. I. Neimark, N. A. Fufaev, *Dynamics of Nonholonomic Systems*, AMS
  1972, chapter III (Voronets' equations, stability of steady motions)
"""
from sage.matrix.constructor import matrix
from sage.structure.sage_object import SageObject
from sage.symbolic.ring import SR

from ..errors import AnalysisError
from ..symbols import t as _t, time_derivative
from .operating_point import OperatingPoint
from ..algebra.trig_linear import TrigFractionField

__all__ = ['SteadyMotion', 'split_point', 'steady_motion_conditions', 'steady_linearization']


def _names(symbols):
    return ", ".join(map(str, symbols))


class SteadyMotion(SageObject):
    r"""
    A steady motion and its linearization (built by
    :func:`steady_linearization`).

    EXAMPLES: see the module documentation.
    """

    def __init__(self, point, coordinates, speeds, velocities, multipliers, dependent, dropped,
                 decoupled, matrices):
        self._point = point
        self._coordinates = coordinates
        self._speeds = speeds
        self._velocities = velocities
        self._multipliers = multipliers
        self._dependent = dependent
        self._dropped = dropped
        self._decoupled = decoupled
        self._M, self._S, self._W = matrices

    def _repr_(self):
        name = f" {self._point.name()!r}" if self._point.name() else ""
        return (f"Steady motion{name} linearized in ({_names(self._coordinates)}): speeds "
                f"({_names(self._speeds)})")

    def point(self):
        r"""The :class:`~sage_dynsym.analysis.operating_point.OperatingPoint`.

        EXAMPLES: see the module documentation.
        """
        return self._point

    def coordinates(self):
        r"""The coordinates linearized in (the variables of the linear system).

        EXAMPLES: see the module documentation.
        """
        return list(self._coordinates)

    def speeds(self):
        r"""
        The independent speeds: the velocities of :meth:`coordinates` first,
        then those chosen so that the constraints give the other velocities
        at the point.

        EXAMPLES: see the module documentation.
        """
        return list(self._speeds)

    def velocities(self):
        r"""
        Every velocity along the steady motion (a dict; functions of the
        moving coordinates where the motion turns).

        EXAMPLES: see the module documentation.
        """
        return dict(self._velocities)

    def multipliers(self):
        r"""
        The constraint multipliers along the steady motion (a dict; their
        generalized forces are `C^T\nu`, e.g. the normal forces of rolling
        wheels).

        EXAMPLES::

            sage: from sage_dynsym.analysis.motion import SecondOrderEquations
            sage: from sage_dynsym.analysis.operating_point import OperatingPoint
            sage: from sage_dynsym.analysis.steady import steady_linearization
            sage: x, z, dx, dz, ddx, ddz, m, g, mu = var('x z dx dz ddx ddz m g mu')
            sage: E = SecondOrderEquations([m*ddx, m*ddz + m*g - mu], [x, z], [dx, dz], [ddx, ddz],
            ....:                          constraints=[z], multipliers=[mu])
            sage: steady_linearization(E, OperatingPoint('slide', {z: 0}, {dx: 1}), [z]).multipliers()
            Traceback (most recent call last):
            ...
            AnalysisError: linearize: the velocities dz are not independent at the operating point: the constraints tie them; leave out the coordinates they determine
            sage: steady_linearization(E, OperatingPoint('slide', {z: 0}, {dx: 1}), []).multipliers()
            {mu: g*m}
        """
        return dict(self._multipliers)

    def dependent_coordinates(self):
        r"""
        The coordinates tied by holonomic constraints, solved to first order:
        a dict ``{coordinate: value}`` with the value linear in the
        perturbations of :meth:`coordinates` (written with their names).

        EXAMPLES::

            sage: from sage_dynsym.analysis.motion import SecondOrderEquations
            sage: from sage_dynsym.analysis.operating_point import OperatingPoint
            sage: from sage_dynsym.analysis.steady import steady_linearization
            sage: x, y, dx, dy, ddx, ddy, k, mu = var('x y dx dy ddx ddy k mu')
            sage: E = SecondOrderEquations([ddx + k*x - mu, ddy + mu], [x, y], [dx, dy], [ddx, ddy],
            ....:                          constraints=[x + y], multipliers=[mu])
            sage: s = steady_linearization(E, OperatingPoint('rest', {x: 0, y: 0}), [x])
            sage: s.dependent_coordinates(), s.M(), s.W()
            ({y: -x}, [2], [k])
        """
        return dict(self._dependent)

    def dropped(self):
        r"""
        The coordinates left out: absent from the linearized equations
        (ignorable).

        EXAMPLES: see the module documentation.
        """
        return list(self._dropped)

    def decoupled_speeds(self):
        r"""
        The independent speeds beyond the velocities of :meth:`coordinates`:
        their perturbations do not enter the equations of the coordinates
        (their own equations, left out, add their eigenvalues -- typically
        zero, a conserved forward speed).

        EXAMPLES: see the module documentation.
        """
        return list(self._decoupled)

    def M(self):
        r"""The matrix of the accelerations.

        EXAMPLES: see the module documentation.
        """
        return self._M

    def S(self):
        r"""The matrix of the velocities.

        EXAMPLES: see the module documentation.
        """
        return self._S

    def W(self):
        r"""The matrix of the coordinates.

        EXAMPLES: see the module documentation.
        """
        return self._W


def split_point(point, q, dq):
    r"""
    The operating point ``point`` (an
    :class:`~sage_dynsym.analysis.operating_point.OperatingPoint`, or a dict
    over the coordinates ``q``, fixed, and the velocities ``dq``, given).

    EXAMPLES::

        sage: from sage_dynsym.analysis.steady import split_point
        sage: x, dx = var('x dx')
        sage: split_point({x: 0, dx: 1}, [x], [dx])
        Operating point: x = 0, dx = 1
        sage: split_point({var('y'): 0}, [x], [dx])
        Traceback (most recent call last):
        ...
        AnalysisError: linearize: y is neither coordinates nor velocities of the equations
    """
    if isinstance(point, OperatingPoint):
        return point
    if not isinstance(point, dict):
        raise AnalysisError(f"expected an operating point or a dict {{coordinate: value}}, "
                            f"got {point!r}", entry="linearize")
    at = {SR(k): v for k, v in point.items() if SR(k) in q}
    velocities = {SR(k): v for k, v in point.items() if SR(k) in dq}
    other = [k for k in point if SR(k) not in q and SR(k) not in dq]
    if other:
        raise AnalysisError(f"{_names(other)} {'is' if len(other) == 1 else 'are'} neither "
                            "coordinates nor velocities of the equations", entry="linearize")
    return OperatingPoint(None, at, velocities)


def _check_point(point, q, dq, ddq):
    at, given = point.at(), point.velocities()
    for k in at:
        if k not in q:
            raise AnalysisError(f"{k} is not a coordinate; the coordinates are {_names(q)}",
                                entry="linearize")
    for k in given:
        if k not in dq:
            raise AnalysisError(f"{k} is not a velocity; the velocities are {_names(dq)}",
                                entry="linearize")
    dynamic = set(q) | set(dq) | set(ddq)
    for k, value in list(at.items()) + list(given.items()):
        bad = [v for v in value.variables() if v in dynamic]
        if bad:
            raise AnalysisError(f"the value of {k} depends on {_names(bad)}; give values in "
                                "the parameters", entry="linearize")
    for qi, di in zip(q, dq):
        if qi in at and di in given and not given[di].is_zero():
            raise AnalysisError(f"{qi} is fixed at {at[qi]} but its velocity {di} is given as "
                                f"{given[di]}", entry="linearize")


def _undetermined(K, A, rank, unknown, q, dq):
    # the velocities the constraints leave free are named, and those they
    # determine (a velocity is determined iff its column is independent of
    # the others: dropping it lowers the rank)
    free = [v for j, v in enumerate(unknown)
            if K.rank([row[:j] + row[j + 1:] for row in A]) == rank]
    derived = [v for v in unknown if v not in free]
    coordinates = [q[dq.index(v)] for v in free]
    raise AnalysisError(
        (f"the constraints determine {_names(derived)} but not " if derived else
         "the constraints do not determine ") + f"{_names(free)} along the motion; give "
        f"{'it' if len(free) == 1 else 'them'} in the operating point's velocities (e.g. "
        + ", ".join(f"{v}: 0" for v in free) + ") or fix " + _names(coordinates)
        + " in its coordinates (at)", entry="linearize")


class _Linearization:
    r"""The computation of :func:`steady_linearization` step by step."""

    def __init__(self, record, point, coordinates, speeds):
        if not hasattr(record, 'accelerations'):
            raise AnalysisError("steady motions are linearized from second-order equations "
                                "(a Lagrangian)", entry="linearize")
        self.q, self.dq = record.coordinates(), record.velocities()
        self.ddq = record.accelerations()
        self.n = len(self.q)
        zero = {v: 0 for v in record.multipliers() + record.velocity_multipliers()}
        self.E = [SR(e).subs(zero) for e in record.equations()]
        self.f = record.constraints()
        self.multiplier_symbols = record.multipliers() + record.velocity_multipliers()
        rates = [time_derivative(fj, self.q, self.dq, [0] * self.n) for fj in self.f]
        self.Phi = rates + record.velocity_constraints()
        self.m = len(self.Phi)
        self.C = [[g.diff(v) for v in self.dq] for g in self.Phi]
        for row, g in zip(self.C[len(self.f):], record.velocity_constraints()):
            if any(a.has(v) for a in row for v in self.dq + self.ddq):
                raise AnalysisError(f"the velocity constraint {g} == 0 is not linear in the "
                                    "velocities", entry="linearize")
        self.point = split_point(point, self.q, self.dq)
        _check_point(self.point, self.q, self.dq, self.ddq)
        coordinates = self.point.coordinates() if coordinates is None else coordinates
        if coordinates is None:
            raise AnalysisError("give the coordinates to linearize in (coordinates=[...], or "
                                "in the operating point)", entry="linearize")
        self.p = [SR(x) for x in coordinates]
        for x in self.p:
            if x not in self.q:
                raise AnalysisError(f"{x} is not a coordinate; the coordinates are "
                                    f"{_names(self.q)}", entry="linearize")
        self.requested_speeds = None if speeds is None else [SR(s) for s in speeds]
        self.at = self.point.at()
        self.free = [x for x in self.q if x not in self.at]
        # the moving coordinates' values along the motion stay symbols; while
        # differentiating with respect to the coordinates, the velocities of
        # the motion (functions of them) are held by frozen copies
        self.frozen = {z: SR.var(f'dynsym_frozen_{z}') for z in self.free}
        self.thawed = {v: z for z, v in self.frozen.items()}

    def index(self, symbol):
        return self.dq.index(symbol) if symbol in self.dq else self.q.index(symbol)

    # -- the steady motion ----------------------------------------------------

    def steady_velocities(self):
        q, dq, n = self.q, self.dq, self.n
        given = self.point.velocities()
        known = {dq[i]: SR(0) for i in range(n) if q[i] in self.at}
        known.update(given)
        C0 = [[a.subs(self.at) for a in row] for row in self.C]
        c0 = [g.subs({v: 0 for v in dq}).subs(self.at) for g in self.Phi]
        held = [fj.subs(self.at) for fj in self.f]
        K = TrigFractionField([a for row in C0 for a in row] + c0 + held
                              + list(known.values()))
        for j, h in enumerate(held):
            if not K.is_zero(K(h)):
                raise AnalysisError(f"the operating point does not satisfy the constraint "
                                    f"{self.f[j]} == 0: it gives {K.expression(K(h))}",
                                    entry="linearize")
        unknown = [v for v in dq if v not in known]
        A = [[K(row[dq.index(v)]) for v in unknown] for row in C0]
        b = [[-K(ci) - sum((K(row[dq.index(v)]) * K(val) for v, val in known.items()), K.zero)]
             for row, ci in zip(C0, c0)]
        if unknown:
            rank = K.rank(A)
            if rank < len(unknown):
                _undetermined(K, A, rank, unknown, q, dq)
            X = K.solve_right(A, b)
        else:
            X = [] if all(K.is_zero(x[0]) for x in b) else None
        if X is None:
            raise AnalysisError("the velocities of the operating point contradict the "
                                "velocity constraints", entry="linearize")
        velocities = dict(known)
        velocities.update({v: K.expression(x[0]) for v, x in zip(unknown, X)})
        self.vel0 = {v: velocities[v] for v in dq}
        for v, value in self.vel0.items():
            if value.has(_t):
                raise AnalysisError(f"the velocity {v} = {value} of the operating point "
                                    "depends on t: not a steady motion", entry="linearize")
        # accelerations along the motion: the velocities turn with the moving
        # coordinates (a disk rolling on a circle)
        self.acc0 = {a: SR(0).add(*[self.vel0[v].diff(z) * self.vel0[dq[q.index(z)]]
                                    for z in self.free])
                     for a, v in zip(self.ddq, dq)}

    # -- derivatives at the point ---------------------------------------------

    def derivatives(self):
        q, dq, ddq, at = self.q, self.dq, self.ddq, self.at
        frozen, thawed = self.frozen, self.thawed
        motion = {v: val.subs(frozen) for v, val in self.vel0.items()}
        motion.update({a: val.subs(frozen) for a, val in self.acc0.items()})
        values = dict(self.vel0)
        values.update(self.acc0)

        def by_coordinates(expressions):
            # d/dq at the point, the velocities of the motion held
            held = [SR(e).subs(motion) for e in expressions]
            return ([e.subs(at).subs(thawed) for e in held],
                    [[(e.diff(x).subs(at).subs(thawed) if e.has(x) else SR(0)) for x in q]
                     for e in held])

        def by_velocities(expressions, symbols):
            fixed = [SR(e).subs(at) for e in expressions]
            return [[e.diff(v).subs(values) for v in symbols] for e in fixed]

        self.E0, self.Eq = by_coordinates(self.E)
        self.Edq = by_velocities(self.E, dq)
        self.M0 = by_velocities(self.E, ddq)
        if any(a.has(v) for row in self.M0 for a in row for v in ddq):
            raise AnalysisError("the equations are not linear in the accelerations",
                                entry="linearize")
        self.C0 = [[a.subs(at).subs(values) for a in row] for row in self.C]
        _, self.Gq = by_coordinates(self.Phi)
        # the constraints differentiated twice: C ddq + gamma(q, dq, t) = 0
        gamma = [SR(0).add(*[g.diff(x) * v for x, v in zip(q, dq)]) + g.diff(_t)
                 for g in self.Phi]
        _, self.gamma_q = by_coordinates(gamma)
        self.gamma_dq = by_velocities(gamma, dq)
        if any(not a.is_zero() for a in self.acc0.values()):
            # the term (dC/dq) ddq0 of the accelerations' constraint
            _, self.Cacc = by_coordinates([SR(0).add(*[a * motion[v] for a, v in zip(row, ddq)])
                                           for row in self.C])
        else:
            self.Cacc = [[SR(0)] * self.n for _ in range(self.m)]
        self.J = [[fj.diff(x).subs(at) for x in q] for fj in self.f]
        # d C_ri / d q_j, for the term d(C^T nu)/dq of the constraint forces
        self.dC = [[[(a.diff(x).subs(at) if a.has(x) else SR(0)) for x in q] for a in row]
                   for row in self.C]

    # -- exact linear algebra ---------------------------------------------------

    def field(self):
        blocks = [self.E0, self.Eq, self.Edq, self.M0, self.C0, self.Gq, self.gamma_q,
                  self.gamma_dq, self.Cacc, self.J, list(self.vel0.values())]
        blocks += [row for matrix in self.dC for row in matrix]
        flat = []
        for block in blocks:
            for row in block:
                flat.extend(row if isinstance(row, list) else [row])
        self.K = TrigFractionField(flat)

    def choose_speeds(self):
        K, q, dq, n, m = self.K, self.q, self.dq, self.n, self.m
        C0 = K.matrix(self.C0)
        if K.rank(C0) < m:
            raise AnalysisError("the constraints are not independent at the operating point "
                                "(their matrix C in C dq + c = 0 has rank less than "
                                f"{m})", entry="linearize")

        def admissible(speeds):
            rest = [i for i in range(n) if i not in speeds]
            return K.rank([[row[j] for j in rest] for row in C0]) == m

        forced = [q.index(x) for x in self.p]
        if self.requested_speeds is not None:
            chosen = [self.index(s) for s in self.requested_speeds]
            missing = [dq[i] for i in forced if i not in chosen]
            if missing or len(chosen) != n - m or not admissible(chosen):
                raise AnalysisError(f"the speeds {_names(self.requested_speeds)} are not {n - m} "
                                    "independent speeds containing the velocities "
                                    f"{_names([dq[i] for i in forced])}: the constraints "
                                    "must give the other velocities at the operating point",
                                    entry="linearize")
        else:
            if not admissible(forced):
                raise AnalysisError(f"the velocities {_names([dq[i] for i in forced])} are "
                                    "not independent at the operating point: the constraints "
                                    "tie them; leave out the coordinates they determine",
                                    entry="linearize")
            chosen = list(forced)
            driving = [dq.index(v) for v, value in self.point.velocities().items()
                       if not value.is_zero()]
            for i in driving + list(range(n)):
                if len(chosen) == n - m:
                    break
                if i not in chosen and admissible(chosen + [i]):
                    chosen.append(i)
        self.u = chosen
        self.w = [i for i in range(n) if i not in chosen]
        Cw = [[row[j] for j in self.w] for row in C0]
        Cu = [[row[j] for j in self.u] for row in C0]
        # B0: speeds to velocities (identity on the speeds)
        negCu = [[-x for x in row] for row in Cu]
        Bw = K.solve_right(Cw, negCu) if self.w else []
        self.B0 = self._embed(Bw, len(self.u))
        for a, i in enumerate(self.u):
            self.B0[i][a] = K.one
        self.Cw, self.C0m = Cw, C0

    def _embed(self, rows_w, width):
        # an n x width matrix: the given rows at the dependent velocities
        K = self.K
        out = [[K.zero] * width for _ in range(self.n)]
        for a, i in enumerate(self.w):
            out[i] = list(rows_w[a])
        return out

    def _solve_w(self, rhs, width):
        # the dependent rows of X with Cw X = rhs (width columns), embedded
        K = self.K
        if not self.w:
            return [[K.zero] * width for _ in range(self.n)]
        return self._embed(K.solve_right(self.Cw, rhs), width)

    def residuals(self):
        # Kane's equations of the speeds along the motion: (speed, value)
        K = self.K
        Bt = [list(col) for col in zip(*self.B0)]
        residual = K.product(Bt, [[K(e)] for e in self.E0])
        return [(self.dq[self.u[a]], r[0]) for a, r in enumerate(residual)]

    def steady_check(self):
        K = self.K
        E0 = [[K(e)] for e in self.E0]
        bad = [(v, K.expression(r)) for v, r in self.residuals() if not K.is_zero(r)]
        if bad:
            raise AnalysisError("the operating point is not a steady motion: Kane's equations "
                                "of the speeds do not vanish there ("
                                + "; ".join(f"[{v}] {e} != 0" for v, e in bad) + ")",
                                entry="linearize")
        Ct = [list(col) for col in zip(*self.C0m)]
        nu = K.solve_right(Ct, E0) if self.m else []
        self.nu0 = [x[0] for x in nu]

    def dependent_coordinates(self):
        K, q = self.K, self.q
        J = K.matrix(self.J)
        mh = len(self.f)
        listed = [q.index(x) for x in self.p]
        candidates = ([i for i in reversed(range(self.n)) if q[i] in self.at and i not in listed]
                      + [i for i in reversed(range(self.n))
                         if q[i] not in self.at and i not in listed])
        chosen = []
        for i in candidates:
            if len(chosen) == mh:
                break
            if K.rank([[row[j] for j in chosen + [i]] for row in J]) == len(chosen) + 1:
                chosen.append(i)
        if len(chosen) < mh:
            raise AnalysisError("the holonomic constraints cannot be solved for coordinates "
                                f"other than the ones linearized in ({_names(self.p)}) at the "
                                "operating point; leave the coordinates they tie out of the "
                                "list", entry="linearize")
        self.d = chosen
        self.o = [i for i in range(self.n) if i not in chosen]
        # delta q = Q delta q_o
        Q = [[K.zero] * len(self.o) for _ in range(self.n)]
        for a, i in enumerate(self.o):
            Q[i][a] = K.one
        if chosen:
            Jd = [[row[j] for j in chosen] for row in J]
            solved = K.solve_right(Jd, [[-row[j] for j in self.o] for row in J])
            for a, i in enumerate(chosen):
                Q[i] = solved[a]
        self.Q = Q

    def projected(self):
        K, n = self.K, self.n
        k, no = len(self.u), len(self.o)
        zeros = [[K.zero] * k for _ in range(n)]

        def join(*blocks):
            return [sum((list(b[i]) for b in blocks), []) for i in range(n)]

        nu = [(r, x) for r, x in enumerate(self.nu0) if not K.is_zero(x)]
        H = [[K.normal(sum((x * K(self.dC[r][i][j]) for r, x in nu), K.zero))
              for j in range(n)] for i in range(n)]
        dQ = join(self.Q, zeros, zeros)
        Gq = K.matrix(self.Gq)
        Bq = self._solve_w([[-x for x in row] for row in K.product(Gq, self.Q)], no)
        dDQ = join(Bq, self.B0, zeros)
        Dq = [[K.normal(a + b) for a, b in zip(r1, r2)]
              for r1, r2 in zip(K.matrix(self.Cacc), K.matrix(self.gamma_q))]
        rest = [[K.normal(a + b) for a, b in zip(r1, r2)]
                for r1, r2 in zip(K.product(Dq, dQ), K.product(K.matrix(self.gamma_dq), dDQ))]
        # C_w ddq_w = -(C_u ddu + D dq + gamma_dq ddq), the speeds' accelerations last
        Cu = [[row[j] for j in self.u] for row in self.C0m]
        accel = [[K.normal(-a - b) for a, b in zip(r1, [K.zero] * (no + k) + r2)]
                 for r1, r2 in zip(rest, Cu)]
        dDDQ = self._solve_w(accel, no + 2 * k)
        for a, i in enumerate(self.u):
            dDDQ[i][no + k + a] = K.one
        Eq = [[K.normal(K(e) - h) for e, h in zip(row, hrow)]
              for row, hrow in zip(self.Eq, H)]
        total = [[K.normal(a + b + c) for a, b, c in zip(r1, r2, r3)]
                 for r1, r2, r3 in zip(K.product(Eq, dQ), K.product(K.matrix(self.Edq), dDQ),
                                       K.product(K.matrix(self.M0), dDDQ))]
        Bt = [list(col) for col in zip(*self.B0)]
        self.R = K.product(Bt, total)

    def result(self):
        K, q, dq = self.K, self.q, self.dq
        k, no = len(self.u), len(self.o)
        listed = [q.index(x) for x in self.p]
        rows = [self.u.index(i) for i in listed]
        extra = [a for a, i in enumerate(self.u) if i not in listed]
        dropped = [i for i in self.o if i not in listed]
        for i in dropped:
            column = self.o.index(i)
            if any(not K.is_zero(row[column]) for row in self.R):
                raise AnalysisError(f"the linearized equations depend on the perturbation of "
                                    f"{q[i]}; add it to the coordinates", entry="linearize")
        for a in extra:
            if any(not K.is_zero(self.R[r][no + a]) or not K.is_zero(self.R[r][no + k + a])
                   for r in rows):
                raise AnalysisError(f"the perturbation of the speed {dq[self.u[a]]} enters the "
                                    f"equations of {_names(self.p)}; add its coordinate "
                                    f"{q[self.u[a]]} to the coordinates", entry="linearize")

        def block(columns):
            M = matrix(SR, len(rows), len(rows),
                       [[K.expression(self.R[r][c]) for c in columns] for r in rows])
            if any(e.has(_t) for e in M.list()):
                raise AnalysisError("the linearized equations depend on t: the motion is not "
                                    "steady", entry="linearize")
            return M

        W = block([self.o.index(i) for i in listed])
        S, M = block([no + r for r in rows]), block([no + k + r for r in rows])
        dependent = {}
        for i in self.d:
            dependent[q[i]] = SR(0).add(*[K.expression(self.Q[i][self.o.index(j)]) * q[j]
                                          for j in listed])
        multipliers = {mu: K.expression(x) for mu, x in zip(self.multiplier_symbols, self.nu0)}
        return SteadyMotion(self.point, self.p, [dq[i] for i in self.u], self.vel0, multipliers,
                            dependent, [q[i] for i in dropped], [dq[self.u[a]] for a in extra],
                            (M, S, W))


def steady_motion_conditions(system, point, speeds=None):
    r"""
    The conditions for ``point`` to be a steady motion of ``system``:
    Kane's equations of the independent speeds along it (see the module
    documentation), each meaning ``== 0``; the values of the operating point
    may be unknowns (symbols) to solve for, e.g. with
    :func:`~sage_dynsym.algebra.solving.solve_exactly`.

    INPUT:

    - ``system`` -- a :class:`~sage_dynsym.analysis.motion.SecondOrderEquations`
      or anything with ``equations_record()`` giving one (a Lagrangian, a
      mechanical system)
    - ``point`` -- an :class:`~sage_dynsym.analysis.operating_point.OperatingPoint`
      (or a dict over coordinates and velocities)
    - ``speeds`` -- (optional) the independent speeds, see
      :func:`steady_linearization`

    OUTPUT: a dict ``{speed: expression}``

    EXAMPLES:

    A disk (mass `m`, radius `r`, moments `A` about a diameter, `C` about
    its axle) rolling on a circle: tilt `\theta_0`, heading rate `\Omega`,
    spin rate `\omega`. Its steady motions satisfy one relation (Routh,
    *Advanced Rigid Dynamics*, art. 244), here solved for `\omega`::

        sage: from sage_dynsym import MechanicalSystem, RigidBody, UniformGravity
        sage: from sage_dynsym.analysis.operating_point import OperatingPoint
        sage: from sage_dynsym.analysis.steady import steady_motion_conditions
        sage: x, y, psi, th, phi, m, r, A, C, g = var('x y psi theta phi m r A C g')
        sage: frame = RigidBody('frame', joint=[x, y, 0], rotations=[(3, psi), (1, th)])
        sage: disk = RigidBody('disk', parent='frame', joint=[0, 0, r], rotations=[(2, phi)],
        ....:                  mass=m, inertia=diagonal_matrix([A, C, A]))
        sage: S = MechanicalSystem([frame, disk], [x, y, psi, th, phi],
        ....:                      force_function=UniformGravity([0, 0, -g]),
        ....:                      rolling=[{'body': 'disk', 'radius': r, 'axle': 2}])
        sage: th0, Om, om = var('theta0 Omega omega')
        sage: point = OperatingPoint('turning', {th: th0}, {var('dpsi'): Om, var('dphi'): om})
        sage: conditions = steady_motion_conditions(S, point)
        sage: conditions[var('dpsi')], conditions[var('dphi')]
        (0, 0)
        sage: conditions[var('dtheta')]
        -g*m*r*sin(theta0) - ((m*r^2 - A + C)*Omega^2*sin(theta0) + (m*r^2 + C)*Omega*omega)*cos(theta0)
        sage: solve(conditions[var('dtheta')], om)
        [omega == -(g*m*r + (Omega^2*m*r^2 - (A - C)*Omega^2)*cos(theta0))*sin(theta0)/((Omega*m*r^2 + C*Omega)*cos(theta0))]

    The velocities the constraints determine follow from those given (here
    the contact point's); those they leave free must be given::

        sage: point = OperatingPoint('spinning', {th: 0}, {var('dphi'): om})
        sage: steady_motion_conditions(S, point)
        Traceback (most recent call last):
        ...
        AnalysisError: linearize: the constraints determine dx, dy but not dpsi along the motion; give it in the operating point's velocities (e.g. dpsi: 0) or fix psi in its coordinates (at)
        sage: steady_motion_conditions(S, OperatingPoint('straight', {th: 0, psi: 0}, {var('dphi'): om}))
        {dphi: 0, dpsi: 0, dtheta: 0}
    """
    record = system.equations_record() if hasattr(system, 'equations_record') else system
    work = _Linearization(record, point, [], speeds)
    work.steady_velocities()
    work.derivatives()
    work.field()
    work.choose_speeds()
    return {v: work.K.expression(r) for v, r in work.residuals()}


def steady_linearization(record, point, coordinates=None, speeds=None):
    r"""
    The linearization of ``record`` about the steady motion ``point`` (see
    the module documentation).

    INPUT:

    - ``record`` -- a :class:`~sage_dynsym.analysis.motion.SecondOrderEquations`
      (with or without holonomic and velocity constraints)
    - ``point`` -- an :class:`~sage_dynsym.analysis.operating_point.OperatingPoint`,
      or a dict over coordinates (fixed) and velocities (given)
    - ``coordinates`` -- the coordinates to linearize in (default: those of
      the operating point); their velocities are independent speeds
    - ``speeds`` -- (optional) all the independent speeds, velocities of
      coordinates; default: the velocities of ``coordinates``, then velocities
      given nonzero in the operating point, then the others in order, as far
      as the constraints allow

    OUTPUT: a :class:`SteadyMotion`

    Raises :class:`~sage_dynsym.errors.AnalysisError` when the point is not
    a steady motion (the message gives the equations that do not vanish),
    when the constraints do not determine the velocities or fail at the
    point, or when a coordinate or speed left out enters the result.

    EXAMPLES: see the module documentation.

    TESTS::

        sage: from sage_dynsym.analysis.motion import SecondOrderEquations
        sage: from sage_dynsym.analysis.operating_point import OperatingPoint
        sage: from sage_dynsym.analysis.steady import steady_linearization
        sage: x, y, th, dx, dy, dth, ddx, ddy, ddth = var('x y theta dx dy dtheta ddx ddy ddtheta')
        sage: m, I, v, la, F = var('m I v la F')
        sage: E = SecondOrderEquations([m*ddx - la*sin(th) - F, m*ddy + la*cos(th), I*ddth],
        ....:                          [x, y, th], [dx, dy, dth], [ddx, ddy, ddth],
        ....:                          velocity_constraints=[sin(th)*dx - cos(th)*dy],
        ....:                          velocity_multipliers=[la])
        sage: steady_linearization(E, OperatingPoint('p', {th: 0}, {dx: v}), [th])
        Traceback (most recent call last):
        ...
        AnalysisError: linearize: the operating point is not a steady motion: Kane's equations of the speeds do not vanish there ([dx] -F != 0)
        sage: E = E.equations()[:1]
        sage: steady_linearization(SecondOrderEquations([m*ddx], [x], [dx], [ddx]),
        ....:                      OperatingPoint('p', {}, {}), [x])
        Traceback (most recent call last):
        ...
        AnalysisError: linearize: the constraints do not determine dx along the motion; give it in the operating point's velocities (e.g. dx: 0) or fix x in its coordinates (at)
        sage: steady_linearization(SecondOrderEquations([m*ddx], [x], [dx], [ddx]),
        ....:                      OperatingPoint('p', {x: 0}, {dx: 1}), [x])
        Traceback (most recent call last):
        ...
        AnalysisError: linearize: x is fixed at 0 but its velocity dx is given as 1
    """
    work = _Linearization(record, point, coordinates, speeds)
    work.steady_velocities()
    work.derivatives()
    work.field()
    work.choose_speeds()
    work.steady_check()
    work.dependent_coordinates()
    work.projected()
    return work.result()

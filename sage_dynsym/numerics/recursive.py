r"""
Recursive numerical right-hand sides of trees of rigid bodies

For a :class:`~sage_dynsym.numerics.body_tree.BodyTree` the accelerations
are computed without forming the equations of motion symbolically: the
recursive algorithms of rigid-body dynamics [Fea2008]_ are written out
once, symbolically, as an :class:`~sage_dynsym.numerics.graph.ExpressionGraph`
with the model's structure folded in (zero and constant entries, the axes of
the elementary rotations, parameter values when asked), and the graph is
compiled to C:

- the velocities and the accelerations at `\ddot q = 0` frame by frame
  (each joint is a translation by the joint point `r_{0k}(q, t)` followed
  by the body's elementary rotations, whose angles may be coordinates,
  constants or functions of `t`), with uniform gravity as an acceleration
  of the inertial frame;
- the recursive Newton--Euler pass [Fea2008]_ (Table 5.1): forces of the
  bodies about their joint points, summed from the leaves and projected on
  the joints' axes -- the inertial, gravity and load terms of the
  equations at `\ddot q = 0`;
- the composite rigid-body algorithm [Fea2008]_ (Table 6.2) for the mass
  matrix `M`;
- the factorization `M = L^T D L` in the order of the tree, leaves first,
  which creates no fill-in for a tree ([Fea2008]_, Section 6.5, "LTDL"),
  and the solution of `M \ddot q = F` (with holonomic constraints: the
  multipliers from `J M^{-1} J^T \mu = \gamma - J M^{-1} F`; constraints
  on the velocities `A\dot q + b = 0`, such as rolling without slipping,
  add their rows `A\ddot q = \gamma_A` to those of `J`, see
  :mod:`~sage_dynsym.numerics.form`).

The rest of the forcing -- the dissipation `\partial R/\partial \dot q`,
the generalized forces, the gradient of a force function given as an
expression, and for a prescribed joint velocity `v_{0k}` that is not the
derivative of `r_{0k}` the terms by which Lagrange's equations of the
kinetic energy differ from Kane's -- is differentiated symbolically (small
expressions) and added. The equations are the Lagrange equations of
:mod:`~sage_dynsym.dynamics.lagrangian` for the same model; only the way
to the numbers differs.

EXAMPLES: a pendulum `\ddot\varphi = -(g/l)\sin\varphi`::

    sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
    sage: from sage_dynsym.numerics.recursive import RecursiveForm
    sage: phi, m, l, g = var('phi m l g')
    sage: rod = TreeBody(0, rotations=[(1, phi)], mass=m, mass_center=[0, 0, -l],
    ....:                inertia=diagonal_matrix([m*l^2, m*l^2, 0]))
    sage: F = RecursiveForm(BodyTree([rod], [phi], gravity=[0, 0, -g])); F
    Recursive form of a tree of 1 body in (phi), parameters (g, l, m)
    sage: K = F.kernel()
    sage: K(0.0, [pi.n()/2, 0.0], [9.81, 2.0, 1.0])
    array([ 0.   , -4.905])

REFERENCES:

.. [Fea2008] R. Featherstone, *Rigid Body Dynamics Algorithms*, Springer
   2008: chapters 5 (recursive Newton--Euler), 6 (composite rigid body,
   sparse factorization ``LTDL``).
"""
from sage.symbolic.ring import SR

from ..errors import AnalysisError
from ..symbols import t as _t, time_derivative
from .form import deferred
from .graph import ExpressionGraph, SymbolicConverter

__all__ = ['PIVOT_TOLERANCE', 'LARGE_GRAPH', 'optimization', 'check_backend', 'compiled_library',
           'unsupported', 'RecursiveForm']


def _cross(G, u, w):
    return (G.sub(G.mul(u[1], w[2]), G.mul(u[2], w[1])),
            G.sub(G.mul(u[2], w[0]), G.mul(u[0], w[2])),
            G.sub(G.mul(u[0], w[1]), G.mul(u[1], w[0])))


def _add(G, *vectors):
    return tuple(G.sum(parts) for parts in zip(*vectors))


def _scale(G, s, v):
    return tuple(G.mul(s, a) for a in v)


def _matvec(G, A, v):
    return tuple(G.dot(row, v) for row in A)


_PLANE = {1: (1, 2), 2: (2, 0), 3: (0, 1)}


def _rotate(G, axis, c, s, v, inverse=False):
    # components in the old frame of v given in the new one (R v), or the
    # converse (R^T v) with ``inverse``; R an elementary rotation about ``axis``
    i, j = _PLANE[axis]
    if inverse:
        s = G.neg(s)
    out = list(v)
    out[i] = G.sub(G.mul(c, v[i]), G.mul(s, v[j]))
    out[j] = G.add(G.mul(s, v[i]), G.mul(c, v[j]))
    return tuple(out)


def _rotate_matrix(G, axis, c, s, A, symmetric=True):
    # R A R^T of a 3x3 matrix given in the new frame (R A R^T = (R (R A)^T)^T)
    columns = [_rotate(G, axis, c, s, [A[r][col] for r in range(3)]) for col in range(3)]
    RA = [[columns[col][r] for col in range(3)] for r in range(3)]
    rows = [_rotate(G, axis, c, s, RA[r]) for r in range(3)]
    if symmetric:
        return [[rows[min(r, col)][max(r, col)] for col in range(3)] for r in range(3)]
    return [list(row) for row in rows]


def _present(exprs, index):
    # the indices (values of the dict ``index`` of symbols) of the symbols in
    # ``exprs``: the derivatives by the others vanish, and going through all
    # of them would make the build quadratic in the number of coordinates
    found = set()
    for e in exprs:
        found.update(index[v] for v in SR(e).variables() if v in index)
    return sorted(found)


class _Step:
    """One elementary joint: a translation by r (axes unchanged, origin
    moved to the joint point) or a rotation about a coordinate axis."""
    __slots__ = ('body', 'rotation', 'axis', 'c', 's', 'r', 'columns')

    def __init__(self, body, rotation, columns, axis=None, c=None, s=None, r=None):
        self.body, self.rotation, self.columns = body, rotation, columns
        self.axis, self.c, self.s, self.r = axis, c, s, r

    def up(self, G, f, n):
        """The force (f, n) given in this step's frame, in the previous one."""
        if self.rotation:
            return (_rotate(G, self.axis, self.c, self.s, f),
                    _rotate(G, self.axis, self.c, self.s, n))
        return f, _add(G, n, _cross(G, self.r, f))

    def pair(self, G, i, f, n):
        """The power of (f, n) in the partial velocity of coordinate i."""
        if self.rotation:
            return G.mul(self.columns[i], n[self.axis - 1])
        return G.dot(self.columns[i], f)


def _tree_order(steps, n):
    """The coordinates ``0, ..., n - 1`` in the order of the tree (first
    appearance in a joint of ``steps``, parents first), then the others."""
    seen = {}
    for step in steps:
        for i in sorted(step.columns):
            seen.setdefault(i, None)
    return list(seen) + [i for i in range(n) if i not in seen]


class _Assembly:
    r"""
    The graph of the accelerations of a tree: see the module documentation.
    ``values``: parameters folded into the graph as numbers.
    """

    def __init__(self, tree, values=None):
        G = self.G = ExpressionGraph()
        self.tree = tree
        q, dq = tree.coordinates(), tree.velocities()
        self.q, self.dq, self.n = q, dq, len(q)
        self._q_index = {v: i for i, v in enumerate(q)}
        self._dq_index = {v: i for i, v in enumerate(dq)}
        values = values or {}
        inputs = {_t: G.input('t')}
        inputs.update({v: G.input('x', i) for i, v in enumerate(q + dq)})
        self.parameters = [v for v in tree.parameters() if v not in values]
        inputs.update({v: G.input('p', j) for j, v in enumerate(self.parameters)})
        self.convert = SymbolicConverter(G, inputs, values)
        self._zero3 = (G.zero, G.zero, G.zero)
        self._orientation = {}

    # symbolic helpers --------------------------------------------------

    def rate(self, e):
        """d/dt of e at zero accelerations."""
        i = _present([e], self._q_index)
        return time_derivative(e, [self.q[k] for k in i], [self.dq[k] for k in i], [0] * len(i))

    def vector(self, v):
        return tuple(self.convert(c) for c in v)

    def columns(self, exprs, scalar):
        """Partial derivatives of rates by the velocities, nonzero only."""
        out = {}
        for i in _present(exprs, self._dq_index):
            v = self.dq[i]
            d = [SR(e).diff(v) for e in exprs]
            if any(not x.is_trivial_zero() for x in d):
                if _present(d, self._dq_index):
                    return None
                out[i] = self.convert(d[0]) if scalar else self.vector(d)
        return out

    # the kinematics ------------------------------------------------------

    def build_steps(self):
        G = self.G
        gravity = self.tree.gravity()
        self.g0 = self._zero3 if gravity is None else self.vector(gravity)
        base = (self._zero3, self._zero3, self._zero3, tuple(G.neg(a) for a in self.g0))
        # per body frame: (omega, v, alpha, a) in the body's axes, at O_k
        self.state, self.steps, self.body_steps = {0: base}, [], {0: []}
        self.parent = {}
        for k, body in enumerate(self.tree.bodies(), 1):
            j = body.parent()
            self.parent[k] = j
            w, v, alpha, a = self.state[j]
            r = [SR(c) for c in body.joint()]
            rdot = [self.rate(c) for c in r]
            u = list(body.velocity()) if body.velocity() is not None else rdot
            columns = self.columns(u, scalar=False)
            if columns is None:
                raise _Unsupported(f"the relative velocity of body {k} is not linear in the "
                                   "velocities")
            rn, rdn, un = self.vector(r), self.vector(rdot), self.vector(u)
            udn = self.vector([self.rate(c) for c in u])
            v = _add(G, v, _cross(G, w, rn), un)
            a = _add(G, a, _cross(G, alpha, rn), _cross(G, w, _cross(G, w, rn)),
                     _cross(G, w, _add(G, rdn, un)), udn)
            steps = [_Step(k, False, columns, r=rn)]
            for axis, angle in body.rotations():
                theta = SR(angle)
                c, s = self.convert(theta.cos()), self.convert(theta.sin())
                dtheta = self.rate(theta)
                columns = self.columns([dtheta], scalar=True)
                if columns is None:
                    raise _Unsupported(f"the rotation angle {theta} of body {k} depends on the "
                                       "velocities")
                rate, rate2 = self.convert(dtheta), self.convert(self.rate(dtheta))
                w_old = _rotate(G, axis, c, s, w, inverse=True)
                w = list(w_old)
                w[axis - 1] = G.add(w[axis - 1], rate)
                spin = [G.zero] * 3
                spin[axis - 1] = rate
                alpha = list(_rotate(G, axis, c, s, alpha, inverse=True))
                alpha[axis - 1] = G.add(alpha[axis - 1], rate2)
                alpha = _add(G, alpha, _cross(G, w_old, spin))
                v = _rotate(G, axis, c, s, v, inverse=True)
                a = _rotate(G, axis, c, s, a, inverse=True)
                w = tuple(w)
                steps.append(_Step(k, True, columns, axis=axis, c=c, s=s))
            self.state[k] = (w, v, alpha, a)
            self.body_steps[k] = steps
            self.steps += steps
        # the steps from the root to each body's frame
        self.path = {0: []}
        for k in range(1, len(self.tree.bodies()) + 1):
            self.path[k] = self.path[self.parent[k]] + self.body_steps[k]

    def orientation(self, k):
        """Columns: the axes of body k in the inertial axes (rows of R_0k)."""
        if k not in self._orientation:
            G = self.G
            if k == 0:
                R = [[G.one if i == j else G.zero for j in range(3)] for i in range(3)]
            else:
                R = [list(row) for row in self.orientation(self.parent[k])]
                for step in self.body_steps[k][1:]:
                    # R_0,new = R_0,old R_step: each row of R_0 turns as a vector
                    R = [list(_rotate(G, step.axis, step.c, step.s, row, inverse=True))
                         for row in R]
            self._orientation[k] = R
        return self._orientation[k]

    def to_body(self, k, axes, v):
        """Components in body k's axes of v given in the axes of ``axes``."""
        if axes == k:
            return v
        G = self.G
        inertial = v if axes == 0 else _matvec(G, self.orientation(axes), v)
        R = self.orientation(k)
        return tuple(G.dot([R[i][c] for i in range(3)], inertial) for c in range(3))

    # the recursive Newton-Euler pass -----------------------------------

    def inertia(self, body):
        G = self.G
        m = self.convert(body.mass())
        h = _scale(G, m, self.vector(body.mass_center()))
        Theta = [[self.convert(body.inertia()[i, j]) for j in range(3)] for i in range(3)]
        return m, h, Theta

    def body_forces(self):
        r"""
        Per body, the force `(f, n)` (about its joint point, in its axes)
        that its motion at `\ddot q = 0` requires, loads subtracted.
        """
        G = self.G
        forces = {}
        for k, body in enumerate(self.tree.bodies(), 1):
            m, h, Theta = self.inertia(body)
            w, v, alpha, a = self.state[k]
            f = _add(G, _scale(G, m, a), _cross(G, alpha, h), _cross(G, w, _cross(G, w, h)))
            nk = _add(G, _matvec(G, Theta, alpha), _cross(G, w, _matvec(G, Theta, w)),
                      _cross(G, h, a))
            forces[k] = (f, nk)
        for load in self.tree.loads():
            k = load.body
            f, nk = forces[k]
            point = self.vector(load.point)
            if load.force is not None:
                F = self.to_body(k, load.axes, self.vector(load.force))
                f = tuple(G.sub(x, y) for x, y in zip(f, F))
                nk = tuple(G.sub(x, y) for x, y in zip(nk, _cross(G, point, F)))
            if load.torque is not None:
                T = self.to_body(k, load.axes, self.vector(load.torque))
                nk = tuple(G.sub(x, y) for x, y in zip(nk, T))
            forces[k] = (f, nk)
        return forces

    def newton_euler(self):
        r"""The generalized forces of :meth:`body_forces` (summed from the leaves)."""
        G, n = self.G, self.n
        forces = self.body_forces()
        forces[0] = (self._zero3, self._zero3)
        tau = [[] for _ in range(n)]
        for k in range(len(self.tree.bodies()), 0, -1):
            f, nk = forces[k]
            for step in reversed(self.body_steps[k]):
                for i in step.columns:
                    tau[i].append(step.pair(G, i, f, nk))
                f, nk = step.up(G, f, nk)
            j = self.parent[k]
            forces[j] = (_add(G, forces[j][0], f), _add(G, forces[j][1], nk))
        return [G.sum(parts) for parts in tau]

    # the composite rigid-body algorithm --------------------------------

    def mass_matrix(self):
        r"""The entries of `M`: a dict ``(i, j) -> node`` (both triangles)."""
        G = self.G
        composite = {k: self.inertia(body) for k, body in enumerate(self.tree.bodies(), 1)}
        at_step = {}
        for k in range(len(self.tree.bodies()), 0, -1):
            m, h, Theta = composite[k]
            for step in reversed(self.body_steps[k]):
                at_step[id(step)] = (m, h, Theta)
                if step.rotation:
                    h = _rotate(G, step.axis, step.c, step.s, h)
                    Theta = _rotate_matrix(G, step.axis, step.c, step.s, Theta)
                else:
                    r = step.r
                    rr, rh = G.dot(r, r), G.dot(r, h)
                    shifted = [[None] * 3 for _ in range(3)]
                    for i in range(3):
                        for j in range(i, 3):
                            e = G.sub(G.neg(G.mul(m, G.mul(r[i], r[j]))),
                                      G.add(G.mul(r[i], h[j]), G.mul(h[i], r[j])))
                            if i == j:
                                e = G.add(e, G.add(G.mul(m, rr), G.add(rh, rh)))
                            shifted[i][j] = shifted[j][i] = G.add(Theta[i][j], e)
                    h, Theta = _add(G, h, _scale(G, m, r)), shifted
            j = self.parent[k]
            if j:
                mj, hj, Tj = composite[j]
                composite[j] = (G.add(mj, m), _add(G, hj, h),
                                [[G.add(Tj[a][b], Theta[a][b]) for b in range(3)]
                                 for a in range(3)])
        entries = {}

        def accumulate(i, j, value):
            entries[i, j] = G.add(entries.get((i, j), G.zero), value)

        for k in range(1, len(self.tree.bodies()) + 1):
            path = self.path[k]
            for position in range(len(path) - len(self.body_steps[k]), len(path)):
                step = path[position]
                m, h, Theta = at_step[id(step)]
                for i, column in step.columns.items():
                    if step.rotation:
                        w = [G.zero] * 3
                        w[step.axis - 1] = column
                        f, nk = _cross(G, w, h), _matvec(G, Theta, w)
                    else:
                        f, nk = _scale(G, m, column), _cross(G, h, column)
                    for j in step.columns:
                        accumulate(j, i, step.pair(G, j, f, nk))
                    for above in range(position - 1, -1, -1):
                        f, nk = path[above + 1].up(G, f, nk)
                        other = path[above]
                        for j in other.columns:
                            value = other.pair(G, j, f, nk)
                            accumulate(j, i, value)
                            accumulate(i, j, value)
        return entries

    # Lagrange's equations for prescribed joint velocities --------------

    def velocity_corrections(self):
        r"""
        The terms by which Lagrange's equations differ from Kane's when a
        joint velocity `u_k` is prescribed that is not the time derivative of
        the joint point `r_k`, so that `\delta_k = u_k - \dot r_k \ne 0`: every
        point of the subtree of `k` moves with `R_{0j}\delta_k` more than the
        derivative of its position, and (`j` the parent, all in its axes;
        `P_k`, `m_k` the momentum and mass of the subtree, `e_i` the partial
        angular velocity of frame `j`, `D_i = \partial\delta_k/\partial\dot q_i`)

        .. MATH::

            E_i - E_i^{Kane} = P_k\cdot\bigl(\omega_j\times D_i + \dot D_i
            - e_i\times\delta_k - \partial\delta_k/\partial q_i\bigr)
            + m_k\, g\cdot D_i .
        """
        G, n = self.G, self.n
        corrections = [[] for _ in range(n)]
        prescribed = []
        for k, body in enumerate(self.tree.bodies(), 1):
            if body.velocity() is None:
                continue
            delta = [SR(u) - self.rate(r) for u, r in zip(body.velocity(), body.joint())]
            if all(d.is_trivial_zero() or d.expand().is_zero() for d in delta):
                continue
            prescribed.append((k, delta))
        if not prescribed:
            return [G.zero] * n
        # momentum and mass of every subtree, in the parent's axes
        momentum, mass = {}, {}
        for k in range(len(self.tree.bodies()), 0, -1):
            m, h, _ = self.inertia(self.tree.bodies()[k - 1])
            w, v, _, _ = self.state[k]
            p = _add(G, _scale(G, m, v), _cross(G, w, h), *[
                momentum[c] for c in momentum if self.parent[c] == k])
            total = G.sum([m] + [mass[c] for c in mass if self.parent[c] == k])
            for step in reversed(self.body_steps[k][1:]):
                p = _rotate(G, step.axis, step.c, step.s, p)
            momentum[k], mass[k] = p, total
        for k, delta in prescribed:
            j = self.parent[k]
            partial = self.partial_angular_velocities(j)
            g = self.to_body(j, 0, self.g0)
            w = self.state[j][0]
            deltan = self.vector(delta)
            for i, (qi, dqi) in enumerate(zip(self.q, self.dq)):
                D = [d.diff(dqi) for d in delta]
                beta = _add(G, self.vector([self.rate(x) for x in D]),
                            tuple(G.neg(x) for x in self.vector([d.diff(qi) for d in delta])))
                Dn = self.vector(D)
                beta = _add(G, beta, _cross(G, w, Dn))
                if i in partial:
                    beta = tuple(G.sub(x, y) for x, y in zip(beta, _cross(G, partial[i], deltan)))
                corrections[i].append(G.add(G.dot(momentum[k], beta),
                                            G.mul(mass[k], G.dot(g, Dn))))
        return [G.sum(parts) for parts in corrections]

    def partial_angular_velocities(self, k):
        """The partial angular velocities of body k's frame, in its axes
        (dict: coordinate index -> vector; absent ones are zero)."""
        if k == 0:
            return {}
        G, out = self.G, dict(self.partial_angular_velocities(self.parent[k]))
        for step in self.body_steps[k][1:]:
            out = {i: _rotate(G, step.axis, step.c, step.s, e, inverse=True)
                   for i, e in out.items()}
            for i, column in step.columns.items():
                e = list(out.get(i, self._zero3))
                e[step.axis - 1] = G.add(e[step.axis - 1], column)
                out[i] = tuple(e)
        return out

    # the forcing and the solution --------------------------------------

    def applied_forces(self):
        r"""
        The generalized forces besides those of :meth:`body_forces`: the
        given ones, minus `\partial R/\partial\dot q`, plus the gradient of
        the force function given as an expression, minus
        :meth:`velocity_corrections`.
        """
        G, tree = self.G, self.tree
        extra = self.velocity_corrections()
        R, U = tree.dissipation(), tree.potential()
        return [G.sub(self.convert(Q - R.diff(dqi) + U.diff(qi)), e)
                for qi, dqi, Q, e in zip(self.q, self.dq, tree.forces(), extra)]

    def forcing(self):
        r"""`F` of `M\ddot q = F` (nodes), without the constraint forces."""
        G = self.G
        return [G.sub(a, b) for a, b in zip(self.applied_forces(), self.newton_euler())]

    # the articulated-body algorithm ------------------------------------

    def joint_groups(self):
        r"""
        The joints of the articulated-body algorithm: runs of consecutive
        steps of one body that share coordinates, as a dict ``id(last step)
        -> (steps, coordinates)``; ``None`` when a coordinate moves two
        bodies (then only the mass matrix can be formed).
        """
        owner, groups = {}, {}
        for k, steps in self.body_steps.items():
            runs = []
            for position, step in enumerate(steps):
                for i in step.columns:
                    if owner.setdefault(i, k) != k:
                        return None
                    runs.append([position, position, {i}])
            # merge the runs of each coordinate, then the overlapping ones
            merged = []
            for run in sorted(runs):
                for other in merged:
                    if other[2] & run[2] or other[0] <= run[0] <= other[1]:
                        other[0], other[1] = min(other[0], run[0]), max(other[1], run[1])
                        other[2] |= run[2]
                        break
                else:
                    merged.append(run)
            changed = True
            while changed:
                changed = False
                for a in merged:
                    for b in merged:
                        if a is not b and (a[2] & b[2] or not (a[1] < b[0] or b[1] < a[0])):
                            a[0], a[1], a[2] = min(a[0], b[0]), max(a[1], b[1]), a[2] | b[2]
                            merged.remove(b)
                            changed = True
                            break
                    if changed:
                        break
            for first, last, coordinates in merged:
                groups[id(steps[last])] = (steps[first:last + 1], sorted(coordinates))
        return groups

    def _motion_down(self, step, w, v):
        # a motion vector (w, v) of the previous frame, in this step's frame
        G = self.G
        if step.rotation:
            return (_rotate(G, step.axis, step.c, step.s, w, inverse=True),
                    _rotate(G, step.axis, step.c, step.s, v, inverse=True))
        return w, _add(G, v, _cross(G, w, step.r))

    def _inertia_up(self, step, I):
        # a 6x6 inertia (blocks A, B, C: n = A w + B v, f = B^T w + C v) of
        # this step's frame, in the previous frame
        G = self.G
        A, B, C = I
        if step.rotation:
            return tuple(_rotate_matrix(G, step.axis, step.c, step.s, X, symmetric)
                         for X, symmetric in ((A, True), (B, False), (C, True)))
        r = step.r
        rx = [[G.zero, G.neg(r[2]), r[1]], [r[2], G.zero, G.neg(r[0])],
              [G.neg(r[1]), r[0], G.zero]]

        def product(X, Y):
            return [[G.dot(X[i], [Y[k][j] for k in range(3)]) for j in range(3)]
                    for i in range(3)]
        rC = product(rx, C)
        Bnew = [[G.add(B[i][j], rC[i][j]) for j in range(3)] for i in range(3)]
        # A - B [r] + [r] B^T - [r] C [r], symmetric
        Br, rBt, rCr = product(B, rx), product(rx, [list(c) for c in zip(*B)]), product(rC, rx)
        Anew = [[None] * 3 for _ in range(3)]
        for i in range(3):
            for j in range(i, 3):
                Anew[i][j] = Anew[j][i] = G.sub(G.add(G.sub(A[i][j], Br[i][j]), rBt[i][j]),
                                                rCr[i][j])
        return Anew, Bnew, C

    def articulated(self, applied):
        r"""
        `\ddot q` by the articulated-body algorithm ([Fea2008]_, Table 7.1)
        with the bias forces of :meth:`body_forces` and the generalized
        forces ``applied``; ``None`` when :meth:`joint_groups` is.
        """
        G = self.G
        groups = self.joint_groups()
        if groups is None:
            return None
        zero3, pivots = self._zero3, []
        bias = self.body_forces()
        previous, last = {}, {}
        for k, steps in self.body_steps.items():
            if not k:
                continue
            parent_steps = self.body_steps[self.parent[k]]
            previous[id(steps[0])] = parent_steps[-1] if parent_steps else None
            for a, b in zip(steps, steps[1:]):
                previous[id(b)] = a
            last[id(steps[-1])] = k
        zero_inertia = ([[G.zero] * 3 for _ in range(3)],) * 3
        inertia, force, joint = {}, {}, {}
        for step in reversed(self.steps):
            key = id(step)
            I = inertia.pop(key, zero_inertia)
            f, nk = force.pop(key, (zero3, zero3))
            if key in last:
                m, h, Theta = self.inertia(self.tree.bodies()[last[key] - 1])
                hx = [[G.zero, G.neg(h[2]), h[1]], [h[2], G.zero, G.neg(h[0])],
                      [G.neg(h[1]), h[0], G.zero]]
                mE = [[m if i == j else G.zero for j in range(3)] for i in range(3)]
                I = tuple([[G.add(X[i][j], Y[i][j]) for j in range(3)] for i in range(3)]
                          for X, Y in zip(I, (Theta, hx, mE)))
                f, nk = _add(G, f, bias[last[key]][0]), _add(G, nk, bias[last[key]][1])
            if key in groups:
                steps, coordinates = groups[key]
                S = self._joint_columns(steps, coordinates)
                A, B, C = I
                Bt = [list(c) for c in zip(*B)]
                U = [(_add(G, _matvec(G, Bt, w), _matvec(G, C, v)),
                      _add(G, _matvec(G, A, w), _matvec(G, B, v))) for w, v in S]
                D = [[G.add(G.dot(S[r][0], U[c][1]), G.dot(S[r][1], U[c][0]))
                      for c in range(len(S))] for r in range(len(S))]
                u = [G.sub(applied[i], G.add(G.dot(w, nk), G.dot(v, f)))
                     for i, (w, v) in zip(coordinates, S)]
                Dinv = _inverse(G, D, pivots, _pivot_scales(G, A, C, S))
                # U D^-1 (as 6-vectors f, n) and the updated inertia and force
                UD = [(tuple(G.sum([G.mul(U[a][0][x], Dinv[a][b]) for a in range(len(S))])
                             for x in range(3)),
                       tuple(G.sum([G.mul(U[a][1][x], Dinv[a][b]) for a in range(len(S))])
                             for x in range(3))) for b in range(len(S))]

                def update(X, left, right, symmetric):
                    out = [[None] * 3 for _ in range(3)]
                    for i in range(3):
                        for j in range(i if symmetric else 0, 3):
                            out[i][j] = G.sub(X[i][j], G.sum(
                                [G.mul(UD[b][left][i], U[b][right][j]) for b in range(len(S))]))
                            if symmetric:
                                out[j][i] = out[i][j]
                    return out
                I = (update(A, 1, 1, True), update(B, 1, 0, False), update(C, 0, 0, True))
                f = _add(G, f, *[_scale(G, u[b], UD[b][0]) for b in range(len(S))])
                nk = _add(G, nk, *[_scale(G, u[b], UD[b][1]) for b in range(len(S))])
                joint[key] = (S, U, Dinv, u, coordinates)
            before = previous[key]
            if before is not None:
                I = self._inertia_up(step, I)
                f, nk = step.up(G, f, nk)
                if id(before) in inertia:
                    other = inertia[id(before)]
                    I = tuple([[G.add(X[i][j], Y[i][j]) for j in range(3)] for i in range(3)]
                              for X, Y in zip(I, other))
                    of, on = force[id(before)]
                    f, nk = _add(G, f, of), _add(G, nk, on)
                inertia[id(before)], force[id(before)] = I, (f, nk)
        ddq = [G.zero] * self.n
        motion = {}
        for step in self.steps:
            before = previous[id(step)]
            w, v = motion[id(before)] if before is not None else (zero3, zero3)
            w, v = self._motion_down(step, w, v)
            if id(step) in joint:
                S, U, Dinv, u, coordinates = joint[id(step)]
                rest = [G.sub(u[a], G.add(G.dot(U[a][0], v), G.dot(U[a][1], w)))
                        for a in range(len(S))]
                values = [G.dot(row, rest) for row in Dinv]
                for i, value in zip(coordinates, values):
                    ddq[i] = value
                w = _add(G, w, *[_scale(G, x, Sw) for x, (Sw, _) in zip(values, S)])
                v = _add(G, v, *[_scale(G, x, Sv) for x, (_, Sv) in zip(values, S)])
            motion[id(step)] = (w, v)
        return ddq, pivots

    def _joint_columns(self, steps, coordinates):
        # the motion subspace of a joint in the frame of its last step: one
        # motion vector (w, v) per coordinate
        G, columns = self.G, []
        for i in coordinates:
            w, v = self._zero3, self._zero3
            for step in steps:
                w, v = (w, v) if step is steps[0] else self._motion_down(step, w, v)
                if i in step.columns:
                    if step.rotation:
                        e = [G.zero] * 3
                        e[step.axis - 1] = step.columns[i]
                        w = _add(G, w, e)
                    else:
                        v = _add(G, v, step.columns[i])
            columns.append((w, v))
        return columns

    def accelerations(self, solver='auto'):
        r"""
        The nodes of `\ddot q` (in the order of the coordinates) and of the
        pivots of the factorizations (zero when the system is singular),
        and the solver used: ``'articulated'`` (the articulated-body
        algorithm: models without constraints whose coordinates each move
        one body) or ``'ltdl'`` (the mass matrix, factorized).
        """
        from .form import constraint_terms, velocity_constraint_terms
        G = self.G
        self.build_steps()
        constraints = self.tree.constraints()
        velocity_constraints = self.tree.velocity_constraints()
        if solver != 'ltdl' and not constraints and not velocity_constraints:
            result = self.articulated(self.applied_forces())
            if result is not None:
                return result + ('articulated',)
        if solver == 'articulated':
            raise _Unsupported("the articulated-body algorithm needs a model without "
                               "constraints whose coordinates each move one body")
        M = self.mass_matrix()
        F = self.forcing()
        order = _tree_order(self.steps, self.n)
        position = {i: a for a, i in enumerate(order)}
        n = self.n
        # H: the lower triangle of M in tree order, overwritten by L and D
        H = {}
        for (i, j), value in M.items():
            a, b = position[i], position[j]
            if a >= b and not G.is_zero(value):
                H[a, b] = value
        rows = [sorted(b for (a2, b) in H if a2 == a and b < a) for a in range(n)]
        pivots = []
        for k in range(n - 1, -1, -1):
            d = H.get((k, k), G.zero)
            _pivot(G, d, M.get((order[k], order[k]), G.zero), pivots)
            below = rows[k]
            for i in reversed(below):
                factor = G.div(H[k, i], d)
                for j in below:
                    if j > i:
                        break
                    update = G.sub(H.get((i, j), G.zero), G.mul(factor, H[k, j]))
                    if (i, j) not in H:
                        rows[i].append(j)
                        rows[i].sort()
                    H[i, j] = update
                H[k, i] = factor
        D = [H.get((k, k), G.zero) for k in range(n)]

        def solve(b):
            y = [b[i] for i in order]
            for k in range(n - 1, -1, -1):
                for i in rows[k]:
                    y[i] = G.sub(y[i], G.mul(H[k, i], y[k]))
            x = [G.div(y[k], D[k]) for k in range(n)]
            for k in range(n):
                x[k] = G.sub(x[k], G.dot([H[k, i] for i in rows[k]], [x[i] for i in rows[k]]))
            out = [None] * n
            for a, i in enumerate(order):
                out[i] = x[a]
            return out

        ddq = solve(F)
        if constraints or velocity_constraints:
            # the rows J ddq = gamma of the holonomic constraints and A ddq =
            # gamma_A of those on the velocities take the same multipliers'
            # elimination (the constraint forces J^T mu + A^T lambda)
            J, gamma, _ = constraint_terms(constraints, self.q, self.dq)
            A, gamma_A, _ = velocity_constraint_terms(velocity_constraints, self.q, self.dq)
            J = [[self.convert(e) for e in row] for row in J + A]
            gamma = [self.convert(e) for e in gamma + gamma_A]
            Y = [solve(row) for row in J]
            m = len(J)
            S = [[G.dot(J[a], Y[b]) for b in range(m)] for a in range(m)]
            rhs = [G.sub(gamma[a], G.dot(J[a], ddq)) for a in range(m)]
            mu = _dense_solve(G, S, rhs, pivots, [S[a][a] for a in range(m)])
            ddq = [G.add(ddq[i], G.dot([Y[b][i] for b in range(m)], mu)) for i in range(n)]
        return ddq, pivots, 'ltdl'


#: a pivot at most this fraction of its scale is taken as zero: the system
#: is singular or as close to it as rounding can tell (a rotation chart
#: within about 1e-6 of its singular set)
PIVOT_TOLERANCE = 1e-12


def _pivot(G, d, scale, pivots):
    # appends the margin |d| - tol |scale| of the pivot d: the compiled code
    # refuses the state where a margin is not positive
    pivots.append(G.sub(G.call('abs', d), G.mul(G.constant(PIVOT_TOLERANCE),
                                                 G.call('abs', scale))))


def _pivot_scales(G, A, C, S):
    # the scale of each pivot S^T I S of the articulated inertia
    # I = ((A, B), (B^T, C)) and the joint columns S = (w, v): as I is
    # positive semidefinite, S^T I S <= 2 (|w|^2 tr A + |v|^2 tr C), so a
    # pivot small against it is a joint the articulated body cannot move
    # (a singular chart)
    traces = (G.sum([A[i][i] for i in range(3)]), G.sum([C[i][i] for i in range(3)]))
    return [G.add(G.mul(G.dot(w, w), traces[0]), G.mul(G.dot(v, v), traces[1])) for w, v in S]


def _inverse(G, A, pivots, scales):
    # the inverse of a small symmetric positive definite matrix (Gauss-Jordan
    # without pivoting); appends the pivots' margins against ``scales``
    m = len(A)
    if m == 1:
        _pivot(G, A[0][0], scales[0], pivots)
        return [[G.div(G.one, A[0][0])]]
    columns = [[G.one if i == j else G.zero for i in range(m)] for j in range(m)]
    return [list(x) for x in zip(*[_dense_solve(G, A, b, pivots if j == 0 else [], scales)
                                   for j, b in enumerate(columns)])]


def _dense_solve(G, A, b, pivots, scales):
    # Gaussian elimination without pivoting of a small symmetric positive
    # definite system; appends the pivots' margins against ``scales``
    m = len(b)
    A = [list(row) for row in A]
    b = list(b)
    for c in range(m):
        _pivot(G, A[c][c], scales[c], pivots)
        for r in range(c + 1, m):
            factor = G.div(A[r][c], A[c][c])
            for k in range(c + 1, m):
                A[r][k] = G.sub(A[r][k], G.mul(factor, A[c][k]))
            b[r] = G.sub(b[r], G.mul(factor, b[c]))
    x = [None] * m
    for r in range(m - 1, -1, -1):
        x[r] = G.div(G.sub(b[r], G.dot(A[r][r + 1:], x[r + 1:])), A[r][r])
    return x


#: Graphs of more nodes are compiled at ``-O1``: for their straight-line
#: code ``-O2`` takes two to three times as long (100 links: 25 s against
#: 12 s) and the calls are not measurably faster.
LARGE_GRAPH = 20_000


def optimization(graph):
    r"""
    The compiler flags for the code of ``graph``: ``('-O2',)``, or
    ``('-O1',)`` above :data:`LARGE_GRAPH` nodes.

    EXAMPLES::

        sage: from sage_dynsym.numerics.graph import ExpressionGraph
        sage: from sage_dynsym.numerics.recursive import optimization
        sage: optimization(ExpressionGraph())
        ('-O2',)
    """
    return ('-O1',) if graph.size() > LARGE_GRAPH else ('-O2',)


def check_backend(backend, what):
    r"""
    Refuse a ``backend`` other than ``'auto'``, ``'c'`` and ``'python'``
    (``what`` names the call in the error).

    EXAMPLES::

        sage: from sage_dynsym.numerics.recursive import check_backend
        sage: check_backend('c', 'numerical_rhs')
        sage: check_backend(['c'], 'numerical_rhs')
        Traceback (most recent call last):
        ...
        AnalysisError: numerical_rhs: backend must be 'auto', 'c' or 'python', got ['c']
    """
    if not isinstance(backend, str) or backend not in ('auto', 'c', 'python'):
        raise AnalysisError(f"backend must be 'auto', 'c' or 'python', got {backend!r}",
                            entry=what)


def compiled_library(graph, source, backend, what):
    r"""
    The C library of the code of ``graph`` for ``backend``, or ``None``
    where Python evaluates it: with ``backend='python'``, or with
    ``'auto'`` when no C compiler works (said at verbose level 1); with
    ``'c'`` a failure is an error. ``source`` is a function giving the C
    source (only called when C is tried), ``what`` names the code in errors.

    EXAMPLES::

        sage: from sage_dynsym.numerics.graph import ExpressionGraph
        sage: from sage_dynsym.numerics.recursive import compiled_library
        sage: compiled_library(ExpressionGraph(), None, 'python', 'numerical_rhs') is None
        True
        sage: compiled_library(ExpressionGraph(), None, 'fortran', 'numerical_rhs')
        Traceback (most recent call last):
        ...
        AnalysisError: numerical_rhs: backend must be 'auto', 'c' or 'python', got 'fortran'
    """
    from .compiler import compile_c
    from sage.misc.verbose import verbose
    check_backend(backend, what)
    if backend == 'python':
        return None
    try:
        return compile_c(source(), flags=optimization(graph))
    except (AnalysisError, OSError) as error:
        if backend == 'c':
            raise
        verbose(f"C backend unavailable ({error}); using Python", level=1)
        return None


class _Unsupported(Exception):
    """A model the recursive form cannot represent (the reason is the message)."""


def unsupported(tree):
    r"""
    Why the recursive form cannot represent ``tree``, or ``None`` when it
    can: the bodies' masses, mass centres and inertia tensors must be
    constant (parameters only), the prescribed joint velocities linear in
    the velocities, and every function a known one.

    EXAMPLES::

        sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
        sage: from sage_dynsym.numerics.recursive import unsupported
        sage: x, m = var('x m')
        sage: unsupported(BodyTree([TreeBody(0, joint=[x, 0, 0], mass=m)], [x])) is None
        True
        sage: unsupported(BodyTree([TreeBody(0, joint=[x, 0, 0], mass=m*x)], [x]))
        'the mass, mass centre or inertia of body 1 depends on the coordinates, velocities or t'
        sage: unsupported(BodyTree([TreeBody(0, joint=[x, 0, 0], velocity=[var('dx')^2, 0, 0])], [x]))
        'the relative velocity of body 1 is not linear in the velocities'
        sage: unsupported(BodyTree([TreeBody(0, joint=[function('f')(x), 0, 0])], [x]))
        'f is not a known function (the equations take definitions of functions)'
    """
    from .expressions import symbols_and_functions
    dynamic = set(tree.coordinates()) | set(tree.velocities()) | {_t}
    for k, body in enumerate(tree.bodies(), 1):
        data = [body.mass()] + list(body.mass_center()) + body.inertia().list()
        if any(dynamic.intersection(SR(e).variables()) for e in data):
            return (f"the mass, mass centre or inertia of body {k} depends on the "
                    "coordinates, velocities or t")
        if body.velocity() is not None and any(
                not SR(u).diff(a, b).is_zero() for u in body.velocity()
                for a in tree.velocities() for b in tree.velocities()):
            return f"the relative velocity of body {k} is not linear in the velocities"
    functions = symbols_and_functions(tree.expressions())[1]
    if functions:
        return (f"{', '.join(functions)} {'is' if len(functions) == 1 else 'are'} not a known "
                "function (the equations take definitions of functions)")
    return None


class RecursiveForm:
    r"""
    The recursive right-hand side of a
    :class:`~sage_dynsym.numerics.body_tree.BodyTree` (see the module
    documentation), usable wherever a
    :class:`~sage_dynsym.numerics.form.NumericalForm` is: by
    :class:`~sage_dynsym.numerics.rhs.RightHandSide` and
    :func:`~sage_dynsym.numerics.simulate.simulate`.

    INPUT:

    - ``tree`` -- a :class:`~sage_dynsym.numerics.body_tree.BodyTree`
    - ``energy`` -- (optional) a conserved energy, or a function without
      arguments computing it when it is first asked for
    - ``solver`` -- ``'auto'`` (default), ``'articulated'`` or ``'ltdl'``:
      how the accelerations are found, by the articulated-body algorithm
      ([Fea2008]_, Table 7.1; `O(n)` operations, for models without
      constraints whose coordinates each move one body, the default for
      them) or from the mass matrix of the composite rigid-body algorithm
      factorized as `L^T D L`
    - ``values`` -- (optional) values of parameters to write into the code
      as numbers (folded with the rest); the others are inputs of the
      kernel, so that one compilation serves every set of values

    Raises :class:`~sage_dynsym.errors.AnalysisError` when the tree is
    outside the recursive form (see :func:`unsupported`).

    EXAMPLES: see the module documentation; a slider on a turntable turning
    at the prescribed rate `w` (a rheonomic rotation) is pushed outwards by
    the centrifugal force `m w^2 x`::

        sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
        sage: from sage_dynsym.numerics.recursive import RecursiveForm
        sage: x, w, m = var('x w m'); t = var('t')
        sage: table = TreeBody(0, rotations=[(3, w*t)])
        sage: bead = TreeBody(1, joint=[x, 0, 0], mass=m)
        sage: F = RecursiveForm(BodyTree([table, bead], [x]))
        sage: F.kernel('python')(0.0, [2.0, 0.0], [1.0, 3.0])     # m = 1, w = 3
        array([ 0., 18.])
        sage: F.state(), F.parameters(), F.order(), F.solve_size()
        ([x, dx], [m, w], 2, None)

    The same with the rate folded into the code::

        sage: F = RecursiveForm(BodyTree([table, bead], [x]), values={w: 3})
        sage: F.parameters(), F.kernel('python')(0.0, [2.0, 0.0], [1.0])
        ([m], array([ 0., 18.]))

    TESTS::

        sage: RecursiveForm(BodyTree([TreeBody(0, joint=[x, 0, 0], mass=m*t)], [x]))
        Traceback (most recent call last):
        ...
        AnalysisError: numerical_rhs: the recursive form does not apply: the mass, mass centre or inertia of body 1 depends on the coordinates, velocities or t
    """

    def __init__(self, tree, energy=None, solver='auto', values=None):
        reason = unsupported(tree)
        if reason is not None:
            raise AnalysisError(f"the recursive form does not apply: {reason}",
                                entry="numerical_rhs")
        if solver not in ('auto', 'articulated', 'ltdl'):
            raise AnalysisError(f"solver must be 'auto', 'articulated' or 'ltdl', got "
                                f"{solver!r}", entry="numerical_rhs")
        self._solver = solver
        self._tree = tree
        self._values = {}
        if values:
            by_name = {str(k): v for k, v in values.items()}
            self._values = {p: float(by_name[str(p)]) for p in tree.parameters()
                            if str(p) in by_name}
        self._energy = energy
        self._state = tree.coordinates() + tree.velocities()
        self._kernels = {}
        self._graph = None
        self._jacobian = None

    def __repr__(self):
        n = len(self._tree.bodies())
        return (f"Recursive form of a tree of {n} bod{'y' if n == 1 else 'ies'} in "
                f"({', '.join(map(str, self._tree.coordinates()))}), parameters "
                f"({', '.join(map(str, self.parameters()))})")

    def tree(self):
        r"""The :class:`~sage_dynsym.numerics.body_tree.BodyTree`.

        EXAMPLES::

            sage: from sage_dynsym.numerics.body_tree import BodyTree
            sage: from sage_dynsym.numerics.recursive import RecursiveForm
            sage: RecursiveForm(BodyTree([], [])).tree()
            Tree of 0 bodies in (), parameters ()
        """
        return self._tree

    def solver(self):
        r"""
        The solver: ``'articulated'`` or ``'ltdl'`` once the graph is
        built (see the class documentation), else the one asked for.

        EXAMPLES::

            sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
            sage: from sage_dynsym.numerics.recursive import RecursiveForm
            sage: x, y = var('x y')
            sage: F = RecursiveForm(BodyTree([TreeBody(0, joint=[x, y, 0], mass=1)], [x, y]))
            sage: F.solver(), F.graph() is not None, F.solver()
            ('auto', True, 'articulated')
            sage: F = RecursiveForm(BodyTree([TreeBody(0, joint=[x, y, 0], mass=1)], [x, y],
            ....:                            constraints=[x - y^2]))
            sage: F.graph() is not None, F.solver()
            (True, 'ltdl')
        """
        return self._solver

    def order(self):
        r"""2: the equations are of second order.

        EXAMPLES: see the class documentation.
        """
        return 2

    def state(self):
        r"""The coordinates then the velocities.

        EXAMPLES: see the class documentation.
        """
        return list(self._state)

    def parameters(self):
        r"""The parameters, in the order of the parameter array of the kernel.

        EXAMPLES: see the class documentation.
        """
        return [p for p in self._tree.parameters() if p not in self._values]

    def singular_chart(self, x):
        r"""
        The message naming a rotation chart singular at the state ``x`` (a
        body's three successive elementary rotations by coordinates, whose
        angular-velocity matrix has the determinant `\pm\cos` of the middle
        angle when the outer axes differ (Cardan angles) and `\pm\sin` of it
        when they are equal (Euler angles)), or ``None``.

        The compiled right-hand side and Jacobian refuse the states where
        a pivot is small against its scale (see :data:`PIVOT_TOLERANCE`);
        this says why when the cause is the chart.

        EXAMPLES: a free body by the (3, 2, 1) sequence, at `\theta = \pi/2`::

            sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
            sage: from sage_dynsym.numerics.recursive import RecursiveForm
            sage: psi, theta, phi = var('psi theta phi')
            sage: base = TreeBody(0, rotations=[(3, psi), (2, theta), (1, phi)], mass=1,
            ....:                 inertia=diagonal_matrix([1, 2, 3]), name='base')
            sage: F = RecursiveForm(BodyTree([base], [psi, theta, phi]))
            sage: F.singular_chart([0.0, float(pi/2), 0.0, 0, 0, 0])
            "the rotation chart of body 'base' is singular at theta = pi/2 (gimbal lock): ..."
            sage: F.singular_chart([0.0, 1.5, 0.0, 0, 0, 0]) is None
            True
        """
        import math
        position = {q: i for i, q in enumerate(self._tree.coordinates())}
        for k, body in enumerate(self._tree.bodies(), 1):
            rotations = body.rotations()
            for (a1, _), (a2, angle), (a3, _) in zip(rotations, rotations[1:], rotations[2:]):
                if a1 == a2 or a2 == a3 or angle not in position:
                    continue
                value = float(x[position[angle]])
                if abs(math.cos(value) if a1 != a3 else math.sin(value)) > 1e-5:
                    continue
                where = str(SR(round(2 * value / math.pi)) * SR.pi() / 2)
                where = {'1/2*pi': 'pi/2', '-1/2*pi': '-pi/2'}.get(where, where)
                name = repr(body.name()) if body.name() else f"number {k}"
                return (f"the rotation chart of body {name} is singular at {angle} = "
                        f"{where} (gimbal lock): its angular velocity does not determine the "
                        f"rates of the angles (state {list(map(float, x))}); use another "
                        f"sequence of axes for attitudes near this one, e.g. a chart whose "
                        f"middle angle is away from {where} there")
        return None

    def solve_size(self):
        r"""``None``: the kernel solves for the accelerations itself.

        EXAMPLES: see the class documentation.
        """
        return None

    def constraints(self):
        r"""
        The holonomic constraints, their Jacobian and `\partial f/\partial t`
        (as :meth:`NumericalForm.constraints
        <sage_dynsym.numerics.form.NumericalForm.constraints>`).

        EXAMPLES::

            sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
            sage: from sage_dynsym.numerics.recursive import RecursiveForm
            sage: x, y = var('x y')
            sage: RecursiveForm(BodyTree([TreeBody(0, joint=[x, y, 0], mass=1)], [x, y],
            ....:                        constraints=[x^2 + y^2 - 1])).constraints()
            ([x^2 + y^2 - 1], [[2*x, 2*y]], [0])
        """
        from .form import constraint_terms
        f = self._tree.constraints()
        J, _, f_t = constraint_terms(f, self._tree.coordinates(), self._tree.velocities())
        return f, J, f_t

    def velocity_constraints(self):
        r"""
        The constraints on the velocities `g_k = A_k\dot q + b_k`, their
        rows `A` and `b` (as :meth:`NumericalForm.velocity_constraints
        <sage_dynsym.numerics.form.NumericalForm.velocity_constraints>`).

        EXAMPLES: a point that must move along `(1, y)`, pushed along `x`::

            sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
            sage: from sage_dynsym.numerics.recursive import RecursiveForm
            sage: x, y, dx, dy = var('x y dx dy')
            sage: F = RecursiveForm(BodyTree([TreeBody(0, joint=[x, y, 0], mass=1)], [x, y],
            ....:                            forces=[1, 0], velocity_constraints=[y*dx - dy]))
            sage: F.velocity_constraints()
            ([dx*y - dy], [[y, -1]], [0])
            sage: F.kernel('python')(0.0, [0.0, 2.0, 1.0, 2.0], [])   # ddx = (1 - y dx dy)/(1 + y^2)
            array([ 1. ,  2. , -0.6,  0.8])
            sage: F.solver()
            'ltdl'
        """
        from .form import velocity_constraint_terms
        g = self._tree.velocity_constraints()
        A, _, b = velocity_constraint_terms(g, self._tree.coordinates(), self._tree.velocities())
        return g, A, b

    def energy(self):
        r"""The conserved energy (``None`` if none), computed when first asked for.

        EXAMPLES::

            sage: from sage_dynsym.numerics.body_tree import BodyTree
            sage: from sage_dynsym.numerics.recursive import RecursiveForm
            sage: x, dx = var('x dx')
            sage: RecursiveForm(BodyTree([], [x]), energy=lambda: dx^2/2).energy()
            1/2*dx^2
        """
        if deferred(self._energy):
            value = self._energy()
            self._energy = None if value is None else SR(value)
        return self._energy

    def with_functions(self, values):
        r"""``self``: a tree has no unspecified functions.

        EXAMPLES::

            sage: from sage_dynsym.numerics.body_tree import BodyTree
            sage: from sage_dynsym.numerics.recursive import RecursiveForm
            sage: F = RecursiveForm(BodyTree([], [])); F.with_functions({}) is F
            True
        """
        return self

    def graph(self):
        r"""
        ``(graph, outputs, pivots)``: the
        :class:`~sage_dynsym.numerics.graph.ExpressionGraph` of the right-hand
        side, the nodes of `\dot x` and those of the pivots of the
        factorizations (built once).

        EXAMPLES::

            sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
            sage: from sage_dynsym.numerics.recursive import RecursiveForm
            sage: x, k, m = var('x k m')
            sage: F = RecursiveForm(BodyTree([TreeBody(0, joint=[x, 0, 0], mass=m)], [x],
            ....:                            potential=-k*x^2/2))
            sage: G, outputs, pivots = F.graph()
            sage: [G.show(a) for a in outputs]
            ['x[1]', '-((x[0]*p[0])*(1.0/p[1]))']

        The margin of the pivot `m` against its scale, the trace `3m` of
        the translational inertia (see :data:`PIVOT_TOLERANCE`)::

            sage: [G.show(a) for a in pivots]
            ['abs(p[1]) - (1e-12*abs(p[1] + (p[1] + p[1])))']
        """
        if self._graph is None:
            assembly = _Assembly(self._tree, self._values)
            try:
                ddq, pivots, self._solver = assembly.accelerations(self._solver)
            except _Unsupported as error:
                raise AnalysisError(f"the recursive form does not apply: {error}",
                                    entry="numerical_rhs") from error
            n = len(ddq)
            G = assembly.G
            outputs = [G.input('x', n + i) for i in range(n)] + ddq
            self._graph = (G, outputs, pivots)
        return self._graph

    def kernel(self, backend='auto'):
        r"""
        The compiled evaluation of `\dot x` (a
        :class:`~sage_dynsym.numerics.compiler.Kernel`), built once per
        backend: ``'c'`` (the graph as C, see
        :func:`~sage_dynsym.numerics.compiler.graph_c_source`), ``'python'``,
        or ``'auto'`` (C when a compiler works).

        EXAMPLES: see the class documentation.
        """
        from .compiler import Kernel, graph_c_source, run_python
        check_backend(backend, "numerical_rhs")
        if backend in self._kernels:
            return self._kernels[backend]
        G, outputs, pivots = self.graph()
        header = (f"generated by sage_dynsym: recursive right-hand side of a tree of "
                  f"{len(self._tree.bodies())} bodies in "
                  f"({', '.join(map(str, self._tree.coordinates()))})")
        library = compiled_library(G, lambda: graph_c_source(G, outputs, header, pivots=pivots),
                                   backend, "numerical_rhs")
        kernel = None if library is None else Kernel(self, 'c', library.dynsym_rhs)
        if kernel is None:
            function = run_python(G.python_source(outputs + list(pivots)), '_graph')
            m = len(outputs)

            def evaluate(t, x, p):
                values = function(t, x, p)
                if not all(d > 0 for d in values[m:]):
                    raise ZeroDivisionError
                return values[:m], None
            kernel = Kernel(self, 'python', evaluate)
        self._kernels[backend] = kernel
        return kernel

    def jacobian_graph(self):
        r"""
        ``(graph, columns, pivots)``: :meth:`graph` with the derivatives of
        `\dot x` by the state added (forward-mode differentiation of the
        recursive algorithms, see :mod:`~sage_dynsym.numerics.derivatives`),
        for :func:`~sage_dynsym.numerics.compiler.jacobian_c_source`: the
        direction is read from ``x[2n..4n)``; ``columns`` gives the
        derivatives in the directions of the coordinates, then in those of
        the velocities (fewer nodes: the mass matrix and the articulated
        inertias do not depend on the velocities).

        EXAMPLES: a pendulum, `\ddot\varphi = -(g/l)\sin\varphi`::

            sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
            sage: from sage_dynsym.numerics.recursive import RecursiveForm
            sage: phi, m, l, g = var('phi m l g')
            sage: rod = TreeBody(0, rotations=[(1, phi)], mass=m, mass_center=[0, 0, -l],
            ....:                inertia=diagonal_matrix([m*l^2, m*l^2, 0]))
            sage: F = RecursiveForm(BodyTree([rod], [phi], gravity=[0, 0, -g]),
            ....:                   values={g: 9.81, l: 2, m: 1})
            sage: G, columns, pivots = F.jacobian_graph()
            sage: [[G.show(a) for a in nodes] for nodes, first, count in columns]
            [['0.0', '-(0.25*(2.0*(9.81*(cos(x[0])*x[2]))))'], ['x[3]', '0.0']]
        """
        from .derivatives import tangent
        if self._jacobian is None:
            G, outputs, pivots = self.graph()
            m = len(outputs)
            n = m // 2
            columns = []
            for first in (0, n):
                seeds = {G.input('x', first + i): G.input('x', m + first + i) for i in range(n)}
                columns.append((tangent(G, outputs, seeds), first, n))
            self._jacobian = (G, columns, pivots)
        return self._jacobian

    def jacobian_kernel(self, backend='auto'):
        r"""
        The compiled Jacobian of `\dot x` by the state: a function
        ``jac(t, x, p)`` returning a square NumPy array (raises
        :class:`ZeroDivisionError` where the system is singular), built
        once per backend as :meth:`kernel` (``'c'``: see
        :func:`~sage_dynsym.numerics.compiler.jacobian_c_source`;
        ``'python'``: the derivatives in one direction after the other).

        EXAMPLES: a mass on a spring with a cubic term, `\ddot x = -(k x +
        x^3)/m`::

            sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
            sage: from sage_dynsym.numerics.recursive import RecursiveForm
            sage: x, k, m = var('x k m')
            sage: F = RecursiveForm(BodyTree([TreeBody(0, joint=[x, 0, 0], mass=m)], [x],
            ....:                            potential=-k*x^2/2 - x^4/4))
            sage: for backend in ('python', 'c', 'auto'):
            ....:     print(F.jacobian_kernel(backend)(0.0, [2.0, 1.0], [3.0, 0.5]))
            [[  0.   1.]
             [-30.   0.]]
            [[  0.   1.]
             [-30.   0.]]
            [[  0.   1.]
             [-30.   0.]]
        """
        import numpy as np
        from .compiler import jacobian_c_source, run_python, jacobian_function
        check_backend(backend, "numerical_rhs")
        key = ('jacobian', backend)
        if key in self._kernels:
            return self._kernels[key]
        G, columns, pivots = self.jacobian_graph()
        size = 2 * len(self._tree.coordinates())
        header = (f"generated by sage_dynsym: Jacobian of the recursive right-hand side "
                  f"of a tree of {len(self._tree.bodies())} bodies")
        library = compiled_library(G, lambda: jacobian_c_source(G, columns, size, header, pivots),
                                   backend, "numerical_rhs")
        function = None if library is None else jacobian_function(library.dynsym_jac, size)
        if function is None:
            outputs = [a for nodes, _, _ in columns for a in nodes]
            python = run_python(G.python_source(outputs + list(pivots)), '_graph')

            def function(t, x, p):
                out = np.empty((size, size))
                extended = [float(v) for v in x] + [0.0] * size
                begin = 0
                for nodes, first, count in columns:
                    for j in range(first, first + count):
                        extended[size + j] = 1.0
                        values = python(t, extended, p)
                        extended[size + j] = 0.0
                        if not all(d > 0 for d in values[len(outputs):]):
                            raise ZeroDivisionError
                        out[:, j] = values[begin:begin + len(nodes)]
                    begin += len(nodes)
                if not np.isfinite(out).all():
                    raise ZeroDivisionError
                return out
        self._kernels[key] = function
        return function


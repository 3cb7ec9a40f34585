r"""
The kinematic pass of the rigid-body recursions

:class:`TreeKinematics` computes, frame by frame, the velocities of a
:class:`~sage_dynsym.numerics.body_tree.BodyTree` and its accelerations at
`\ddot q = 0`, in the arithmetic chosen by the caller (see
:mod:`~sage_dynsym.numerics.spatial`): each joint is a translation by the
joint point `r_{0k}(q, t)` followed by the body's elementary rotations
(:class:`JointStep`), whose angles may be coordinates, constants or
functions of `t`; uniform gravity is an acceleration `-g` of the inertial
frame ([Fea2008]_, Section 5.3). The algorithms of
:mod:`~sage_dynsym.numerics.newton_euler`,
:mod:`~sage_dynsym.numerics.composite_body` and
:mod:`~sage_dynsym.numerics.articulated_body` run on its steps.

EXAMPLES: a slider on a turntable turning at the rate `w`, in the symbolic
arithmetic: the bead's acceleration at rest on the table is the centripetal
one, `-w^2 x` along the table's first axis::

    sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
    sage: from sage_dynsym.numerics.spatial import SymbolicArithmetic
    sage: from sage_dynsym.numerics.tree_kinematics import TreeKinematics
    sage: x, w, m = var('x w m'); t = var('t')
    sage: tree = BodyTree([TreeBody(0, rotations=[(3, w*t)]),
    ....:                  TreeBody(1, joint=[x, 0, 0], mass=m)], [x])
    sage: K = TreeKinematics(tree, SymbolicArithmetic())
    sage: omega, v, alpha, a = K.state[2]
    sage: omega, v, alpha, a
    ((0, 0, w), (dx, w*x, 0), (0, 0, 0), (-w^2*x, 2*dx*w, 0))
"""
from sage.symbolic.ring import SR

from ..errors import AnalysisError
from ..symbols import time_derivative
from .spatial import add, cross, matvec, rotate

__all__ = ['JointStep', 'TreeKinematics', 'tree_order', 'not_applicable']


def not_applicable(reason):
    r"""
    The error raised when a tree is outside the recursive algorithms
    (``reason`` says why).

    EXAMPLES::

        sage: from sage_dynsym.numerics.tree_kinematics import not_applicable
        sage: not_applicable('a reason')
        AnalysisError('numerical_rhs: the recursive form does not apply: a reason')
    """
    return AnalysisError(f"the recursive form does not apply: {reason}", entry="numerical_rhs")


def _present(exprs, index):
    # the indices (values of the dict ``index`` of symbols) of the symbols in
    # ``exprs``: the derivatives by the others vanish, and going through all
    # of them would make the build quadratic in the number of coordinates
    found = set()
    for e in exprs:
        found.update(index[v] for v in SR(e).variables() if v in index)
    return sorted(found)


class JointStep:
    r"""
    One elementary joint of body ``body``: a translation by ``r`` (axes
    unchanged, origin moved to the joint point) or, with ``rotation``, a
    rotation about the axis ``axis`` by the angle of cosine ``c`` and sine
    ``s``; ``columns`` maps the index of each coordinate that moves the
    step to its partial velocity (a vector for a translation, the rate
    about the axis for a rotation).

    EXAMPLES: see the module documentation; the steps of the slider on the
    turntable, and the power of a force along its joint::

        sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
        sage: from sage_dynsym.numerics.spatial import SymbolicArithmetic
        sage: from sage_dynsym.numerics.tree_kinematics import TreeKinematics
        sage: x, w = var('x w'); t = var('t')
        sage: tree = BodyTree([TreeBody(0, rotations=[(3, w*t)]),
        ....:                  TreeBody(1, joint=[x, 0, 0], mass=1)], [x])
        sage: S = SymbolicArithmetic(); K = TreeKinematics(tree, S)
        sage: [(s.body, s.rotation, s.columns) for s in K.steps]
        [(1, False, {}), (1, True, {}), (2, False, {0: (1, 0, 0)})]
        sage: F = var('F'); K.steps[2].pair(S, 0, (F, 0, 0), (0, 0, 0))
        F
    """
    __slots__ = ('body', 'rotation', 'axis', 'c', 's', 'r', 'columns')

    def __init__(self, body, rotation, columns, axis=None, c=None, s=None, r=None):
        self.body, self.rotation, self.columns = body, rotation, columns
        self.axis, self.c, self.s, self.r = axis, c, s, r

    def up(self, G, f, n):
        r"""The force ``(f, n)`` given in this step's frame, in the previous one.

        EXAMPLES: see the class documentation.
        """
        if self.rotation:
            return (rotate(G, self.axis, self.c, self.s, f),
                    rotate(G, self.axis, self.c, self.s, n))
        return f, add(G, n, cross(G, self.r, f))

    def pair(self, G, i, f, n):
        r"""The power of the force ``(f, n)`` in the partial velocity of coordinate ``i``.

        EXAMPLES: see the class documentation.
        """
        if self.rotation:
            return G.mul(self.columns[i], n[self.axis - 1])
        return G.dot(self.columns[i], f)


def tree_order(steps, n):
    r"""
    The coordinates ``0, ..., n - 1`` in the order of the tree (first
    appearance in a joint of ``steps``, parents first), then the others.

    EXAMPLES::

        sage: from sage_dynsym.numerics.tree_kinematics import JointStep, tree_order
        sage: tree_order([JointStep(1, False, {2: None}), JointStep(2, False, {0: None})], 4)
        [2, 0, 1, 3]
    """
    seen = {}
    for step in steps:
        for i in sorted(step.columns):
            seen.setdefault(i, None)
    return list(seen) + [i for i in range(n) if i not in seen]


class TreeKinematics:
    r"""
    The kinematic pass over a
    :class:`~sage_dynsym.numerics.body_tree.BodyTree` (see the module
    documentation).

    INPUT:

    - ``tree`` -- a :class:`~sage_dynsym.numerics.body_tree.BodyTree`
    - ``arithmetic`` -- the arithmetic (see :mod:`~sage_dynsym.numerics.spatial`)
    - ``convert`` -- (default: ``SR``) a function turning a symbolic
      expression into a scalar of the arithmetic (for an
      :class:`~sage_dynsym.numerics.graph.ExpressionGraph`: a
      :class:`~sage_dynsym.numerics.graph.SymbolicConverter`)

    Attributes read by the algorithms: ``G`` (the arithmetic), ``tree``,
    ``q``, ``dq``, ``n``, ``g0`` (gravity in the inertial axes), ``state``
    (per body: angular velocity, velocity of the joint point, angular
    acceleration and acceleration of the joint point at `\ddot q = 0`, in the
    body's axes), ``steps`` (all :class:`JointStep`, parents first),
    ``body_steps`` and ``path`` (per body: its steps, the steps from the
    root), ``parent`` (per body: its parent's index).

    Raises :class:`~sage_dynsym.errors.AnalysisError` when a relative
    velocity is not linear in the velocities or an angle depends on them.

    EXAMPLES: see the module documentation.
    """

    def __init__(self, tree, arithmetic, convert=SR):
        G = self.G = arithmetic
        self.tree, self.convert = tree, convert
        q, dq = tree.coordinates(), tree.velocities()
        self.q, self.dq, self.n = q, dq, len(q)
        self._q_index = {v: i for i, v in enumerate(q)}
        self._dq_index = {v: i for i, v in enumerate(dq)}
        self.zero3 = (G.zero, G.zero, G.zero)
        self._orientation, self._partial = {}, {False: {0: {}}, True: {0: {}}}
        self._build()

    # symbolic helpers --------------------------------------------------

    def rate(self, e):
        r"""`d/dt` of the symbolic expression ``e`` at zero accelerations.

        EXAMPLES::

            sage: from sage_dynsym.numerics.body_tree import BodyTree
            sage: from sage_dynsym.numerics.spatial import SymbolicArithmetic
            sage: from sage_dynsym.numerics.tree_kinematics import TreeKinematics
            sage: x = var('x'); K = TreeKinematics(BodyTree([], [x]), SymbolicArithmetic())
            sage: K.rate(sin(x)), K.vector([x, 1, 0])
            (dx*cos(x), (x, 1, 0))
        """
        i = _present([e], self._q_index)
        return time_derivative(e, [self.q[k] for k in i], [self.dq[k] for k in i], [0] * len(i))

    def vector(self, v):
        r"""The symbolic 3-vector ``v`` in the arithmetic.

        EXAMPLES: see :meth:`rate`.
        """
        return tuple(self.convert(c) for c in v)

    def columns(self, exprs, scalar):
        r"""
        The partial derivatives of the rates ``exprs`` by the velocities
        (a dict: index -> value, nonzero ones only; one scalar with
        ``scalar``, else a vector), or ``None`` if they depend on the
        velocities.

        EXAMPLES::

            sage: from sage_dynsym.numerics.body_tree import BodyTree
            sage: from sage_dynsym.numerics.spatial import SymbolicArithmetic
            sage: from sage_dynsym.numerics.tree_kinematics import TreeKinematics
            sage: x, y, dx, dy = var('x y dx dy')
            sage: K = TreeKinematics(BodyTree([], [x, y]), SymbolicArithmetic())
            sage: K.columns([y*dx, 0, dy], False), K.columns([dx^2], True)
            ({0: (y, 0, 0), 1: (0, 0, 1)}, None)
        """
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

    def _build(self):
        G = self.G
        gravity = self.tree.gravity()
        self.g0 = self.zero3 if gravity is None else self.vector(gravity)
        base = (self.zero3, self.zero3, self.zero3, tuple(G.neg(a) for a in self.g0))
        # per body frame: (omega, v, alpha, a) in the body's axes, at O_k
        self.state, self.steps, self.body_steps = {0: base}, [], {0: []}
        self.parent = {}
        for k, body in enumerate(self.tree.bodies(), 1):
            j = self.tree.parent(k)
            self.parent[k] = j
            w, v, alpha, a = self.state[j]
            r = [SR(c) for c in body.joint()]
            rdot = [self.rate(c) for c in r]
            u = list(body.velocity()) if body.velocity() is not None else rdot
            columns = self.columns(u, scalar=False)
            if columns is None:
                raise not_applicable(f"the relative velocity of body {k} is not linear in the "
                                     "velocities")
            rn, rdn, un = self.vector(r), self.vector(rdot), self.vector(u)
            udn = self.vector([self.rate(c) for c in u])
            v = add(G, v, cross(G, w, rn), un)
            a = add(G, a, cross(G, alpha, rn), cross(G, w, cross(G, w, rn)),
                    cross(G, w, add(G, rdn, un)), udn)
            steps = [JointStep(k, False, columns, r=rn)]
            for axis, angle in body.rotations():
                theta = SR(angle)
                c, s = self.convert(theta.cos()), self.convert(theta.sin())
                dtheta = self.rate(theta)
                columns = self.columns([dtheta], scalar=True)
                if columns is None:
                    raise not_applicable(f"the rotation angle {theta} of body {k} depends on "
                                         "the velocities")
                rate, rate2 = self.convert(dtheta), self.convert(self.rate(dtheta))
                w_old = rotate(G, axis, c, s, w, inverse=True)
                w = list(w_old)
                w[axis - 1] = G.add(w[axis - 1], rate)
                spin = [G.zero] * 3
                spin[axis - 1] = rate
                alpha = list(rotate(G, axis, c, s, alpha, inverse=True))
                alpha[axis - 1] = G.add(alpha[axis - 1], rate2)
                alpha = add(G, alpha, cross(G, w_old, spin))
                v = rotate(G, axis, c, s, v, inverse=True)
                a = rotate(G, axis, c, s, a, inverse=True)
                w = tuple(w)
                steps.append(JointStep(k, True, columns, axis=axis, c=c, s=s))
            self.state[k] = (w, v, alpha, a)
            self.body_steps[k] = steps
            self.steps += steps
        # the steps from the root to each body's frame
        self.path = {0: []}
        for k in range(1, len(self.tree.bodies()) + 1):
            self.path[k] = self.path[self.parent[k]] + self.body_steps[k]

    def orientation(self, k):
        r"""
        The axes of body ``k`` in the inertial axes (as the columns of the
        list of rows).

        EXAMPLES::

            sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
            sage: from sage_dynsym.numerics.spatial import SymbolicArithmetic
            sage: from sage_dynsym.numerics.tree_kinematics import TreeKinematics
            sage: a = var('a'); tree = BodyTree([TreeBody(0, rotations=[(3, a)])], [a])
            sage: K = TreeKinematics(tree, SymbolicArithmetic()); K.orientation(1)
            [[cos(a), -sin(a), 0], [sin(a), cos(a), 0], [0, 0, 1]]
            sage: K.to_body(1, 0, (1, 0, 0))
            (cos(a), -sin(a), 0)
        """
        if k not in self._orientation:
            G = self.G
            if k == 0:
                R = [[G.one if i == j else G.zero for j in range(3)] for i in range(3)]
            else:
                R = [list(row) for row in self.orientation(self.parent[k])]
                for step in self.body_steps[k][1:]:
                    # R_0,new = R_0,old R_step: each row of R_0 turns as a vector
                    R = [list(rotate(G, step.axis, step.c, step.s, row, inverse=True))
                         for row in R]
            self._orientation[k] = R
        return self._orientation[k]

    def to_body(self, k, axes, v):
        r"""The components in body ``k``'s axes of ``v`` given in the axes of ``axes``.

        EXAMPLES: see :meth:`orientation`.
        """
        if axes == k:
            return v
        G = self.G
        inertial = v if axes == 0 else matvec(G, self.orientation(axes), v)
        R = self.orientation(k)
        return tuple(G.dot([R[i][c] for i in range(3)], inertial) for c in range(3))

    def inertia(self, body):
        r"""
        ``(m, h, Theta)`` of ``body`` in the arithmetic: its mass, first
        moment `m r_c` and inertia tensor about the joint point (rows).

        EXAMPLES::

            sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
            sage: from sage_dynsym.numerics.spatial import SymbolicArithmetic
            sage: from sage_dynsym.numerics.tree_kinematics import TreeKinematics
            sage: m, l = var('m l'); rod = TreeBody(0, mass=m, mass_center=[0, 0, l])
            sage: TreeKinematics(BodyTree([rod], []), SymbolicArithmetic()).inertia(rod)
            (m, (0, 0, l*m), [[0, 0, 0], [0, 0, 0], [0, 0, 0]])
        """
        G = self.G
        m = self.convert(body.mass())
        h = tuple(G.mul(m, a) for a in self.vector(body.mass_center()))
        Theta = [[self.convert(body.inertia()[i, j]) for j in range(3)] for i in range(3)]
        return m, h, Theta

    def partial_angular_velocities(self, k):
        r"""
        The partial angular velocities of body ``k``'s frame, in its axes (a
        dict: coordinate index -> vector; absent ones are zero).

        EXAMPLES::

            sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
            sage: from sage_dynsym.numerics.spatial import SymbolicArithmetic
            sage: from sage_dynsym.numerics.tree_kinematics import TreeKinematics
            sage: a, b = var('a b')
            sage: tree = BodyTree([TreeBody(0, rotations=[(3, a), (1, b)])], [a, b])
            sage: TreeKinematics(tree, SymbolicArithmetic()).partial_angular_velocities(1)
            {0: (0, sin(b), cos(b)), 1: (1, 0, 0)}
        """
        return {i: w for i, (w, _) in self._partials(k, False).items()}

    def partial_velocities(self, k):
        r"""
        The partial velocities of body ``k`` in its axes: a dict mapping the
        index `i` of each coordinate that moves it to the pair
        `(\partial W_k/\partial\dot q_i, \partial V_{0k}/\partial\dot q_i)`
        (angular velocity, velocity of the joint point); built body by body
        from the parent's.

        EXAMPLES: a bead at `x` on a turntable turned by `a`::

            sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
            sage: from sage_dynsym.numerics.spatial import SymbolicArithmetic
            sage: from sage_dynsym.numerics.tree_kinematics import TreeKinematics
            sage: a, x = var('a x')
            sage: tree = BodyTree([TreeBody(0, rotations=[(3, a)]),
            ....:                  TreeBody(1, joint=[x, 0, 0])], [a, x])
            sage: TreeKinematics(tree, SymbolicArithmetic()).partial_velocities(2)
            {0: ((0, 0, 1), (0, x, 0)), 1: ((0, 0, 0), (1, 0, 0))}
        """
        return self._partials(k, True)

    def _partials(self, k, linear):
        # the partial angular velocities of body k, with those of its joint
        # point if ``linear`` (else None), built from the parent's
        if k in self._partial[linear]:
            return self._partial[linear][k]
        G, steps = self.G, self.body_steps[k]
        r = steps[0].r
        out = {i: (w, add(G, v, cross(G, w, r)) if linear else None)
               for i, (w, v) in self._partials(self.parent[k], linear).items()}
        if linear:
            for i, column in steps[0].columns.items():
                w, v = out.get(i, (self.zero3, self.zero3))
                out[i] = (w, add(G, v, column))
        for step in steps[1:]:
            out = {i: (rotate(G, step.axis, step.c, step.s, w, inverse=True),
                       rotate(G, step.axis, step.c, step.s, v, inverse=True) if linear else None)
                   for i, (w, v) in out.items()}
            for i, column in step.columns.items():
                w, v = out.get(i, (self.zero3, self.zero3 if linear else None))
                w = list(w)
                w[step.axis - 1] = G.add(w[step.axis - 1], column)
                out[i] = (tuple(w), v)
        self._partial[linear][k] = out
        return out

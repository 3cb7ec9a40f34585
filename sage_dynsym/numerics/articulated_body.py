r"""
The articulated-body algorithm

:func:`articulated_accelerations` finds `\ddot q` of a tree of rigid bodies
in `O(n)` operations ([Fea2008]_, Table 7.1) over the kinematic pass of a
:class:`~sage_dynsym.numerics.tree_kinematics.TreeKinematics` (in either
arithmetic of :mod:`~sage_dynsym.numerics.spatial`), for models whose
coordinates each move one body (:func:`joint_groups`); the bias forces are
those of :func:`~sage_dynsym.numerics.newton_euler.body_forces`.

EXAMPLES: a pendulum, `\ddot\varphi = -(g/l)\sin\varphi`, in the symbolic
arithmetic::

    sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
    sage: from sage_dynsym.numerics.spatial import SymbolicArithmetic
    sage: from sage_dynsym.numerics.tree_kinematics import TreeKinematics
    sage: from sage_dynsym.numerics.articulated_body import articulated_accelerations
    sage: phi, m, l, g = var('phi m l g')
    sage: rod = TreeBody(0, rotations=[(1, phi)], mass=m, mass_center=[0, 0, -l],
    ....:                inertia=diagonal_matrix([m*l^2, m*l^2, 0]))
    sage: K = TreeKinematics(BodyTree([rod], [phi], gravity=[0, 0, -g]), SymbolicArithmetic())
    sage: ddq, pivots = articulated_accelerations(K, [0])
    sage: ddq[0].simplify_full()
    -g*sin(phi)/l
"""
from .newton_euler import body_forces
from .spatial import add, cross, matvec, rotate, rotate_matrix, scale, skew
from .tree_solve import inverse

__all__ = ['joint_groups', 'articulated_accelerations']


def _merge(runs):
    # the runs [first, last, coordinates] of one body merged where they share
    # a coordinate or overlap
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
    return merged


def joint_groups(kin):
    r"""
    The joints of the articulated-body algorithm: runs of consecutive
    steps of one body that share coordinates, as a dict ``id(last step)
    -> (steps, coordinates)``; ``None`` when a coordinate moves two bodies
    (then only the mass matrix can be formed).

    EXAMPLES::

        sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
        sage: from sage_dynsym.numerics.spatial import SymbolicArithmetic
        sage: from sage_dynsym.numerics.tree_kinematics import TreeKinematics
        sage: from sage_dynsym.numerics.articulated_body import joint_groups
        sage: a, b = var('a b'); S = SymbolicArithmetic()
        sage: K = TreeKinematics(BodyTree([TreeBody(0, rotations=[(3, a), (1, b)])], [a, b]), S)
        sage: [(len(steps), c) for steps, c in joint_groups(K).values()]
        [(1, [0]), (1, [1])]
        sage: K = TreeKinematics(BodyTree([TreeBody(0, rotations=[(3, a)]),
        ....:                              TreeBody(1, rotations=[(3, a)])], [a]), S)
        sage: joint_groups(K) is None
        True
    """
    owner, groups = {}, {}
    for k, steps in kin.body_steps.items():
        runs = []
        for position, step in enumerate(steps):
            for i in step.columns:
                if owner.setdefault(i, k) != k:
                    return None
                runs.append([position, position, {i}])
        for first, last, coordinates in _merge(runs):
            groups[id(steps[last])] = (steps[first:last + 1], sorted(coordinates))
    return groups


def _motion_down(G, step, w, v):
    # a motion vector (w, v) of the previous frame, in this step's frame
    if step.rotation:
        return (rotate(G, step.axis, step.c, step.s, w, inverse=True),
                rotate(G, step.axis, step.c, step.s, v, inverse=True))
    return w, add(G, v, cross(G, w, step.r))


def _product(G, X, Y):
    return [[G.dot(X[i], [Y[k][j] for k in range(3)]) for j in range(3)] for i in range(3)]


def _inertia_up(G, step, I):
    # a 6x6 inertia (blocks A, B, C: n = A w + B v, f = B^T w + C v) of
    # this step's frame, in the previous frame
    A, B, C = I
    if step.rotation:
        return tuple(rotate_matrix(G, step.axis, step.c, step.s, X, symmetric)
                     for X, symmetric in ((A, True), (B, False), (C, True)))
    rx = skew(G, step.r)
    rC = _product(G, rx, C)
    Bnew = [[G.add(B[i][j], rC[i][j]) for j in range(3)] for i in range(3)]
    # A - B [r] + [r] B^T - [r] C [r], symmetric
    Br, rBt = _product(G, B, rx), _product(G, rx, [list(c) for c in zip(*B)])
    rCr = _product(G, rC, rx)
    Anew = [[None] * 3 for _ in range(3)]
    for i in range(3):
        for j in range(i, 3):
            Anew[i][j] = Anew[j][i] = G.sub(G.add(G.sub(A[i][j], Br[i][j]), rBt[i][j]),
                                            rCr[i][j])
    return Anew, Bnew, C


def _pivot_scales(G, A, C, S):
    # the scale of each pivot S^T I S of the articulated inertia
    # I = ((A, B), (B^T, C)) and the joint columns S = (w, v): as I is
    # positive semidefinite, S^T I S <= 2 (|w|^2 tr A + |v|^2 tr C), so a
    # pivot small against it is a joint the articulated body cannot move
    # (a singular chart)
    traces = (G.sum([A[i][i] for i in range(3)]), G.sum([C[i][i] for i in range(3)]))
    return [G.add(G.mul(G.dot(w, w), traces[0]), G.mul(G.dot(v, v), traces[1])) for w, v in S]


def _joint_columns(kin, steps, coordinates):
    # the motion subspace of a joint in the frame of its last step: one
    # motion vector (w, v) per coordinate
    G, columns = kin.G, []
    for i in coordinates:
        w, v = kin.zero3, kin.zero3
        for step in steps:
            w, v = (w, v) if step is steps[0] else _motion_down(G, step, w, v)
            if i in step.columns:
                if step.rotation:
                    e = [G.zero] * 3
                    e[step.axis - 1] = step.columns[i]
                    w = add(G, w, e)
                else:
                    v = add(G, v, step.columns[i])
        columns.append((w, v))
    return columns


def _sum_matrices(G, first, second):
    return tuple([[G.add(X[i][j], Y[i][j]) for j in range(3)] for i in range(3)]
                 for X, Y in zip(first, second))


def _joint(kin, I, f, nk, steps, coordinates, applied, pivots):
    # the articulated inertia and bias force passed on through a joint, and
    # what the forward pass needs of it
    G = kin.G
    S = _joint_columns(kin, steps, coordinates)
    A, B, C = I
    Bt = [list(c) for c in zip(*B)]
    U = [(add(G, matvec(G, Bt, w), matvec(G, C, v)),
          add(G, matvec(G, A, w), matvec(G, B, v))) for w, v in S]
    D = [[G.add(G.dot(S[r][0], U[c][1]), G.dot(S[r][1], U[c][0]))
          for c in range(len(S))] for r in range(len(S))]
    u = [G.sub(applied[i], G.add(G.dot(w, nk), G.dot(v, f)))
         for i, (w, v) in zip(coordinates, S)]
    Dinv = inverse(G, D, pivots, _pivot_scales(G, A, C, S))
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
    f = add(G, f, *[scale(G, u[b], UD[b][0]) for b in range(len(S))])
    nk = add(G, nk, *[scale(G, u[b], UD[b][1]) for b in range(len(S))])
    return I, f, nk, (S, U, Dinv, u, coordinates)


def _previous_steps(kin):
    # per step, the step before it on the way to the root (None at the root),
    # and the last step of each body
    previous, last = {}, {}
    for k, steps in kin.body_steps.items():
        if not k:
            continue
        parent_steps = kin.body_steps[kin.parent[k]]
        previous[id(steps[0])] = parent_steps[-1] if parent_steps else None
        for a, b in zip(steps, steps[1:]):
            previous[id(b)] = a
        last[id(steps[-1])] = k
    return previous, last


def _backward(kin, groups, applied, previous, last, pivots):
    # the pass from the leaves: articulated inertias and bias forces
    G, zero3 = kin.G, kin.zero3
    bias = body_forces(kin)
    zero_inertia = ([[G.zero] * 3 for _ in range(3)],) * 3
    inertia, force, joint = {}, {}, {}
    for step in reversed(kin.steps):
        key = id(step)
        I = inertia.pop(key, zero_inertia)
        f, nk = force.pop(key, (zero3, zero3))
        if key in last:
            m, h, Theta = kin.inertia(kin.tree.bodies()[last[key] - 1])
            mE = [[m if i == j else G.zero for j in range(3)] for i in range(3)]
            I = _sum_matrices(G, I, (Theta, skew(G, h), mE))
            f, nk = add(G, f, bias[last[key]][0]), add(G, nk, bias[last[key]][1])
        if key in groups:
            I, f, nk, joint[key] = _joint(kin, I, f, nk, *groups[key], applied, pivots)
        before = previous[key]
        if before is not None:
            I = _inertia_up(G, step, I)
            f, nk = step.up(G, f, nk)
            if id(before) in inertia:
                I = _sum_matrices(G, I, inertia[id(before)])
                of, on = force[id(before)]
                f, nk = add(G, f, of), add(G, nk, on)
            inertia[id(before)], force[id(before)] = I, (f, nk)
    return joint


def articulated_accelerations(kin, applied):
    r"""
    ``(ddq, pivots)``: `\ddot q` by the articulated-body algorithm
    ([Fea2008]_, Table 7.1) with the bias forces of
    :func:`~sage_dynsym.numerics.newton_euler.body_forces` and the
    generalized forces ``applied``, and the margins of its pivots (see
    :mod:`~sage_dynsym.numerics.tree_solve`); ``None`` when
    :func:`joint_groups` is.

    EXAMPLES: see the module documentation.
    """
    G = kin.G
    groups = joint_groups(kin)
    if groups is None:
        return None
    pivots = []
    previous, last = _previous_steps(kin)
    joint = _backward(kin, groups, applied, previous, last, pivots)
    ddq = [G.zero] * kin.n
    motion = {}
    for step in kin.steps:
        before = previous[id(step)]
        w, v = motion[id(before)] if before is not None else (kin.zero3, kin.zero3)
        w, v = _motion_down(G, step, w, v)
        if id(step) in joint:
            S, U, Dinv, u, coordinates = joint[id(step)]
            rest = [G.sub(u[a], G.add(G.dot(U[a][0], v), G.dot(U[a][1], w)))
                    for a in range(len(S))]
            values = [G.dot(row, rest) for row in Dinv]
            for i, value in zip(coordinates, values):
                ddq[i] = value
            w = add(G, w, *[scale(G, x, Sw) for x, (Sw, _) in zip(values, S)])
            v = add(G, v, *[scale(G, x, Sv) for x, (_, Sv) in zip(values, S)])
        motion[id(step)] = (w, v)
    return ddq, pivots

r"""
The composite rigid-body algorithm

:func:`mass_matrix` forms the mass matrix `M` of a tree of rigid bodies
from the composite inertias of its subtrees ([Fea2008]_, Table 6.2), over
the kinematic pass of a
:class:`~sage_dynsym.numerics.tree_kinematics.TreeKinematics` (in either
arithmetic of :mod:`~sage_dynsym.numerics.spatial`).

EXAMPLES: the spherical pendulum in the symbolic arithmetic (its mass
matrix in equations (9))::

    sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
    sage: from sage_dynsym.numerics.spatial import SymbolicArithmetic
    sage: from sage_dynsym.numerics.tree_kinematics import TreeKinematics
    sage: from sage_dynsym.numerics.composite_body import mass_matrix
    sage: psi, theta, m, l = var('psi theta m l')
    sage: bob = TreeBody(0, rotations=[(3, psi), (1, theta)], mass=m, mass_center=[0, 0, l],
    ....:                inertia=diagonal_matrix([m*l^2, m*l^2, 0]))
    sage: M = mass_matrix(TreeKinematics(BodyTree([bob], [psi, theta]), SymbolicArithmetic()))
    sage: matrix(2, 2, lambda i, j: M.get((i, j), 0)).simplify_full()
    [l^2*m*sin(theta)^2                  0]
    [                 0              l^2*m]
"""
from .spatial import add, cross, matvec, rotate, rotate_matrix, scale

__all__ = ['mass_matrix']


def _composite_inertias(kin):
    # per step, the composite inertia (m, h, Theta) of the subtree beyond it,
    # in the step's frame
    G = kin.G
    composite = {k: kin.inertia(body) for k, body in enumerate(kin.tree.bodies(), 1)}
    at_step = {}
    for k in range(len(kin.tree.bodies()), 0, -1):
        m, h, Theta = composite[k]
        for step in reversed(kin.body_steps[k]):
            at_step[id(step)] = (m, h, Theta)
            if step.rotation:
                h = rotate(G, step.axis, step.c, step.s, h)
                Theta = rotate_matrix(G, step.axis, step.c, step.s, Theta)
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
                h, Theta = add(G, h, scale(G, m, r)), shifted
        j = kin.parent[k]
        if j:
            mj, hj, Tj = composite[j]
            composite[j] = (G.add(mj, m), add(G, hj, h),
                            [[G.add(Tj[a][b], Theta[a][b]) for b in range(3)]
                             for a in range(3)])
    return at_step


def mass_matrix(kin):
    r"""
    The entries of the mass matrix `M`: a dict ``(i, j) -> value`` (both
    triangles; entries that are zero by the structure absent).

    INPUT: ``kin`` -- a :class:`~sage_dynsym.numerics.tree_kinematics.TreeKinematics`

    EXAMPLES: see the module documentation.
    """
    G = kin.G
    at_step = _composite_inertias(kin)
    entries = {}

    def accumulate(i, j, value):
        entries[i, j] = G.add(entries.get((i, j), G.zero), value)

    for k in range(1, len(kin.tree.bodies()) + 1):
        path = kin.path[k]
        for position in range(len(path) - len(kin.body_steps[k]), len(path)):
            step = path[position]
            m, h, Theta = at_step[id(step)]
            for i, column in step.columns.items():
                if step.rotation:
                    w = [G.zero] * 3
                    w[step.axis - 1] = column
                    f, nk = cross(G, w, h), matvec(G, Theta, w)
                else:
                    f, nk = scale(G, m, column), cross(G, h, column)
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

r"""
The recursive Newton--Euler algorithm

Over the kinematic pass of a
:class:`~sage_dynsym.numerics.tree_kinematics.TreeKinematics` (in either
arithmetic of :mod:`~sage_dynsym.numerics.spatial`):
:func:`body_forces` gives per body the force about its joint point that its
motion at `\ddot q = 0` requires, loads subtracted, and
:func:`generalized_bias_forces` sums them from the leaves and projects them
on the joints' axes ([Fea2008]_, Table 5.1): the inertial, gravity and load
terms of the equations at `\ddot q = 0`. The loads enter through
:func:`load_forces`, whose projection (:func:`generalized_forces`) is also
the generalized force of a load in the symbolic equations
(:meth:`~sage_dynsym.mechanics.loads.Load.generalized_forces`), and
:func:`power` their power. :func:`applied_forces` adds what
is differentiated symbolically (dissipation, generalized forces, a force
function given as an expression, and the corrections of
:func:`velocity_corrections` for prescribed joint velocities);
:func:`forcing` is `F` of `M\ddot q = F`.

EXAMPLES: the spherical pendulum in the symbolic arithmetic: the terms of
its equations (9) at `\ddot q = 0` (those of the kinetic energy and of
gravity, with the sign of `M\ddot q + h = 0`)::

    sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
    sage: from sage_dynsym.numerics.spatial import SymbolicArithmetic
    sage: from sage_dynsym.numerics.tree_kinematics import TreeKinematics
    sage: from sage_dynsym.numerics.newton_euler import generalized_bias_forces
    sage: psi, theta, m, l, g = var('psi theta m l g')
    sage: bob = TreeBody(0, rotations=[(3, psi), (1, theta)], mass=m, mass_center=[0, 0, l],
    ....:                inertia=diagonal_matrix([m*l^2, m*l^2, 0]))
    sage: K = TreeKinematics(BodyTree([bob], [psi, theta], gravity=[0, 0, -g]),
    ....:                    SymbolicArithmetic())
    sage: h = generalized_bias_forces(K)
    sage: [e.simplify_full() for e in h]
    [2*dpsi*dtheta*l^2*m*cos(theta)*sin(theta),
     -(dpsi^2*l^2*m*cos(theta) + g*l*m)*sin(theta)]
"""
from sage.symbolic.ring import SR

from .spatial import add, cross, matvec, rotate, scale

__all__ = ['body_forces', 'load_forces', 'power', 'generalized_bias_forces',
           'generalized_forces', 'inverse_dynamics', 'velocity_corrections',
           'applied_forces', 'forcing']


def body_forces(kin):
    r"""
    Per body ``k``, the force ``(f, n)`` (about its joint point, in its
    axes) that its motion at `\ddot q = 0` requires, loads subtracted
    (those of :func:`load_forces`).

    INPUT: ``kin`` -- a :class:`~sage_dynsym.numerics.tree_kinematics.TreeKinematics`

    EXAMPLES: a point mass `m` at rest, hanging in gravity `g`, needs the
    force `m g` upwards::

        sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
        sage: from sage_dynsym.numerics.spatial import SymbolicArithmetic
        sage: from sage_dynsym.numerics.tree_kinematics import TreeKinematics
        sage: from sage_dynsym.numerics.newton_euler import body_forces
        sage: z, m, g = var('z m g')
        sage: tree = BodyTree([TreeBody(0, joint=[0, 0, z], mass=m)], [z], gravity=[0, 0, -g])
        sage: body_forces(TreeKinematics(tree, SymbolicArithmetic()))
        {1: ((0, 0, g*m), (0, 0, 0))}
    """
    G = kin.G
    forces = {}
    for k, body in enumerate(kin.tree.bodies(), 1):
        m, h, Theta = kin.inertia(body)
        w, v, alpha, a = kin.state[k]
        f = add(G, scale(G, m, a), cross(G, alpha, h), cross(G, w, cross(G, w, h)))
        nk = add(G, matvec(G, Theta, alpha), cross(G, w, matvec(G, Theta, w)),
                 cross(G, h, a))
        forces[k] = (f, nk)
    for k, (F, N) in load_forces(kin).items():
        f, nk = forces[k]
        forces[k] = (tuple(G.sub(x, y) for x, y in zip(f, F)),
                     tuple(G.sub(x, y) for x, y in zip(nk, N)))
    return forces


def load_forces(kin, loads=None):
    r"""
    Per loaded body ``k``, the force ``(f, n)`` (about its joint point, in
    its axes) of the loads ``loads``
    (:class:`~sage_dynsym.numerics.body_tree.TreeLoad` objects, their
    bodies found by :meth:`~sage_dynsym.numerics.body_tree.BodyTree.body_index`;
    default: the tree's): forces moved to the joint point, with their moments, and
    torques. :func:`generalized_forces` of them are the loads' generalized
    forces `Q_i = F\cdot\partial v_P/\partial\dot q_i +
    M\cdot\partial W_k/\partial\dot q_i`, the ones that both the
    compiled right-hand side (through :func:`body_forces`) and the symbolic
    equations (:meth:`~sage_dynsym.mechanics.loads.Load.generalized_forces`)
    use.

    EXAMPLES: a force `F` along the inertial `x` axis at the point
    `(l, 0, 0)` of a body turned by `a` about the `z` axis::

        sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody, TreeLoad
        sage: from sage_dynsym.numerics.newton_euler import load_forces, generalized_forces
        sage: a, l, F = var('a l F')
        sage: K = BodyTree([TreeBody(0, rotations=[(3, a)])], [a]).kinematics()
        sage: forces = load_forces(K, [TreeLoad(1, point=[l, 0, 0], force=[F, 0, 0])]); forces
        {1: ((F*cos(a), -F*sin(a), 0), (0, 0, -F*l*sin(a)))}
        sage: generalized_forces(K, forces)
        [-F*l*sin(a)]
    """
    G = kin.G
    forces = {}
    for load in kin.tree.loads() if loads is None else loads:
        k, axes = kin.tree.body_index(load.body()), kin.tree.body_index(load.axes())
        f, nk = forces.get(k, (kin.zero3, kin.zero3))
        if load.force() is not None:
            F = kin.to_body(k, axes, kin.vector(load.force()))
            f = add(G, f, F)
            nk = add(G, nk, cross(G, kin.vector(load.point()), F))
        if load.torque() is not None:
            nk = add(G, nk, kin.to_body(k, axes, kin.vector(load.torque())))
        forces[k] = (f, nk)
    return forces


def power(kin, forces):
    r"""
    The power `\sum_k f_k\cdot V_{0k} + n_k\cdot W_k` of the forces
    ``forces`` (a dict: body `k` -> `(f_k, n_k)` about its joint point, in
    its axes, such as those of :func:`load_forces`) in the motion of the
    bodies.

    EXAMPLES: a torque `M` about the axis of a rotor turned by `a`::

        sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody, TreeLoad
        sage: from sage_dynsym.numerics.newton_euler import load_forces, power
        sage: a, M = var('a M')
        sage: K = BodyTree([TreeBody(0, rotations=[(3, a)])], [a]).kinematics()
        sage: power(K, load_forces(K, [TreeLoad(1, torque=[0, 0, M])]))
        M*da
    """
    G = kin.G
    return G.sum([G.add(G.dot(f, kin.state[k][1]), G.dot(nk, kin.state[k][0]))
                  for k, (f, nk) in sorted(forces.items())])


def generalized_bias_forces(kin):
    r"""
    The generalized forces of :func:`body_forces` (see :func:`project`):
    the terms `h` of `M\ddot q + h` of the kinetic energy, gravity and the
    loads.

    EXAMPLES: see the module documentation.
    """
    return generalized_forces(kin, body_forces(kin))


def generalized_forces(kin, forces):
    r"""
    The generalized forces `\sum_k \partial V_{0k}/\partial\dot q_i\cdot f_k
    + \partial W_k/\partial\dot q_i\cdot n_k` of the forces ``forces`` (a dict:
    body `k` -> `(f_k, n_k)` about its joint point, in its axes; absent
    bodies carry none), summed from
    the leaves and projected on the joints: the backward pass of the
    recursive Newton--Euler algorithm ([Fea2008]_, Table 5.1).

    EXAMPLES: on a bead at `x` on a turntable turned by `a`, a force `F`
    along the table acts on `x` only, a force `F` across it on `a` only,
    with the moment `F x`::

        sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
        sage: from sage_dynsym.numerics.spatial import SymbolicArithmetic
        sage: from sage_dynsym.numerics.tree_kinematics import TreeKinematics
        sage: from sage_dynsym.numerics.newton_euler import generalized_forces
        sage: a, x, F = var('a x F')
        sage: tree = BodyTree([TreeBody(0, rotations=[(3, a)]), TreeBody(1, joint=[x, 0, 0])],
        ....:                 [a, x])
        sage: K = TreeKinematics(tree, SymbolicArithmetic())
        sage: generalized_forces(K, {1: ((0, 0, 0), (0, 0, 0)), 2: ((F, 0, 0), (0, 0, 0))})
        [0, F]
        sage: generalized_forces(K, {1: ((0, 0, 0), (0, 0, 0)), 2: ((0, F, 0), (0, 0, 0))})
        [F*x, 0]
    """
    G, n = kin.G, kin.n
    forces = dict(forces)
    tau = [[] for _ in range(n)]
    for k in range(len(kin.tree.bodies()), 0, -1):
        f, nk = forces.get(k, (kin.zero3, kin.zero3))
        for step in reversed(kin.body_steps[k]):
            for i in step.columns:
                tau[i].append(step.pair(G, i, f, nk))
            f, nk = step.up(G, f, nk)
        j = kin.parent[k]
        if j:
            fj, nj = forces.get(j, (kin.zero3, kin.zero3))
            forces[j] = (add(G, fj, f), add(G, nj, nk))
    return [G.sum(parts) for parts in tau]


def inverse_dynamics(kin, ddq):
    r"""
    The generalized forces `\tau(q, \dot q, \ddot q)` of the motion of the
    bodies with the accelerations ``ddq`` (scalars of the arithmetic),
    loads subtracted: the accelerations that ``ddq`` adds to each frame
    propagated from the root, then :func:`generalized_forces` (the
    recursive Newton--Euler algorithm, [Fea2008]_ Table 5.1). Lagrange's
    equations of the tree are `\tau = Q`, `Q` the applied generalized forces.

    EXAMPLES: a slider of mass 2 on `x`, `\tau = 2\ddot x`; and the
    textbook pendulum `\tau = m l^2\ddot\varphi + m g l\sin\varphi`::

        sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
        sage: from sage_dynsym.numerics.newton_euler import inverse_dynamics
        sage: x, ddx = var('x ddx')
        sage: K = BodyTree([TreeBody(0, joint=[x, 0, 0], mass=2)], [x]).kinematics('graph')
        sage: K.G.show(inverse_dynamics(K, [K.G.input('x', 2)])[0])
        'x[2]*2.0'
        sage: phi, ddphi, m, l, g = var('phi ddphi m l g')
        sage: rod = TreeBody(0, rotations=[(1, phi)], mass=m, mass_center=[0, 0, -l],
        ....:                inertia=diagonal_matrix([m*l^2, m*l^2, 0]))
        sage: K = BodyTree([rod], [phi], gravity=[0, 0, -g]).kinematics()
        sage: inverse_dynamics(K, [ddphi])
        [ddphi*l^2*m + g*l*m*sin(phi)]
    """
    G = kin.G
    forces = body_forces(kin)
    extra = {0: (kin.zero3, kin.zero3)}
    for k, body in enumerate(kin.tree.bodies(), 1):
        alpha, a = extra[kin.parent[k]]
        for step in kin.body_steps[k]:
            if step.rotation:
                alpha = list(rotate(G, step.axis, step.c, step.s, alpha, inverse=True))
                a = rotate(G, step.axis, step.c, step.s, a, inverse=True)
                alpha[step.axis - 1] = G.add(alpha[step.axis - 1], G.sum(
                    [G.mul(column, ddq[i]) for i, column in step.columns.items()]))
                alpha = tuple(alpha)
            else:
                a = add(G, a, cross(G, alpha, step.r),
                        *[scale(G, ddq[i], column) for i, column in step.columns.items()])
        extra[k] = (alpha, a)
        m, h, Theta = kin.inertia(body)
        f, nk = forces[k]
        forces[k] = (add(G, f, scale(G, m, a), cross(G, alpha, h)),
                     add(G, nk, matvec(G, Theta, alpha), cross(G, h, a)))
    return generalized_forces(kin, forces)


def _prescribed(kin):
    # the bodies whose prescribed joint velocity is not the rate of the joint
    # point, with the difference
    out = []
    for k, body in enumerate(kin.tree.bodies(), 1):
        if body.velocity() is None:
            continue
        delta = [SR(u) - kin.rate(r) for u, r in zip(body.velocity(), body.joint())]
        if all(d.is_trivial_zero() or d.expand().is_zero() for d in delta):
            continue
        out.append((k, delta))
    return out


def velocity_corrections(kin):
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

    Only the subtrees of the bodies with a prescribed velocity are summed;
    the terms `-P_k\cdot(e_i\times\delta_k) = e_i\cdot(P_k\times\delta_k)`
    of all `i` are the generalized force of the torque `P_k\times\delta_k`
    on the parent `j`, projected by :func:`generalized_forces` (no partial
    velocities built); the other terms only where `\delta_k` depends on
    `q_i` or `\dot q_i`.

    EXAMPLES: a body of mass `m` whose joint moves with twice the rate of
    its coordinate: the kinetic energy `2 m\dot x^2` gives `4 m\ddot x`
    where Kane's form gives `2 m\ddot x`, and in gravity `g` along `x`
    the force `2 m g` where Kane's gives `m g`::

        sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
        sage: from sage_dynsym.numerics.spatial import SymbolicArithmetic
        sage: from sage_dynsym.numerics.tree_kinematics import TreeKinematics
        sage: from sage_dynsym.numerics.newton_euler import velocity_corrections
        sage: x, dx, m, g = var('x dx m g')
        sage: b = TreeBody(0, joint=[x, 0, 0], velocity=[2*dx, 0, 0], mass=m)
        sage: velocity_corrections(TreeKinematics(BodyTree([b], [x], gravity=[g, 0, 0]),
        ....:                                     SymbolicArithmetic()))
        [g*m]
    """
    G, n = kin.G, kin.n
    corrections = [[] for _ in range(n)]
    prescribed = _prescribed(kin)
    if not prescribed:
        return [G.zero] * n
    # the correction of body k reads the momentum and mass of its subtree
    # only (and, above it, the motion of its parent's frame): they are summed
    # from the leaves over the bodies below a prescribed velocity, in the
    # parent's axes (parents come before their children)
    below = {k for k, _ in prescribed}
    for k in range(1, len(kin.tree.bodies()) + 1):
        if kin.parent[k] in below:
            below.add(k)
    momentum, mass = {}, {}
    for k in sorted(below, reverse=True):
        m, h, _ = kin.inertia(kin.tree.bodies()[k - 1])
        w, v, _, _ = kin.state[k]
        p = add(G, scale(G, m, v), cross(G, w, h), *[
            momentum[c] for c in momentum if kin.parent[c] == k])
        total = G.sum([m] + [mass[c] for c in mass if kin.parent[c] == k])
        for step in reversed(kin.body_steps[k][1:]):
            p = rotate(G, step.axis, step.c, step.s, p)
        momentum[k], mass[k] = p, total
    # -P_k.(e_i x delta_k) = e_i.(P_k x delta_k): over all i, the generalized
    # force of the torque P_k x delta_k on the parent, projected by the
    # backward pass; the other terms only where delta_k depends on q_i, dq_i
    torques = {}
    for k, delta in prescribed:
        j = kin.parent[k]
        g = kin.to_body(j, 0, kin.g0)
        w = kin.state[j][0]
        if j:
            torque = cross(G, momentum[k], kin.vector(delta))
            torques[j] = (kin.zero3, add(G, torques.get(j, (None, kin.zero3))[1], torque))
        names = {str(v) for d in delta for v in d.variables()}
        for i, (qi, dqi) in enumerate(zip(kin.q, kin.dq)):
            if str(qi) not in names and str(dqi) not in names:
                continue
            D = [d.diff(dqi) for d in delta]
            Dn = kin.vector(D)
            beta = add(G, kin.vector([kin.rate(x) for x in D]), cross(G, w, Dn),
                       tuple(G.neg(x) for x in kin.vector([d.diff(qi) for d in delta])))
            corrections[i].append(G.add(G.dot(momentum[k], beta),
                                        G.mul(mass[k], G.dot(g, Dn))))
    return [G.add(G.sum(parts), Q)
            for parts, Q in zip(corrections, generalized_forces(kin, torques))]


def applied_forces(kin):
    r"""
    The generalized forces besides those of :func:`body_forces`: the given
    ones, minus `\partial R/\partial\dot q`, plus the gradient of the force
    function given as an expression, minus :func:`velocity_corrections`.

    EXAMPLES::

        sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
        sage: from sage_dynsym.numerics.spatial import SymbolicArithmetic
        sage: from sage_dynsym.numerics.tree_kinematics import TreeKinematics
        sage: from sage_dynsym.numerics.newton_euler import applied_forces, forcing
        sage: x, dx, m, k, c, Q = var('x dx m k c Q')
        sage: tree = BodyTree([TreeBody(0, joint=[x, 0, 0], mass=m)], [x], forces=[Q],
        ....:                 potential=-k*x^2/2, dissipation=c*dx^2/2)
        sage: K = TreeKinematics(tree, SymbolicArithmetic())
        sage: applied_forces(K), forcing(K)
        ([-c*dx - k*x + Q], [-c*dx - k*x + Q])
    """
    G, tree = kin.G, kin.tree
    extra = velocity_corrections(kin)
    R, U = tree.dissipation(), tree.potential()
    return [G.sub(kin.convert(Q - R.diff(dqi) + U.diff(qi)), e)
            for qi, dqi, Q, e in zip(kin.q, kin.dq, tree.forces(), extra)]


def forcing(kin):
    r"""`F` of `M\ddot q = F`, without the constraint forces.

    EXAMPLES: see :func:`applied_forces`.
    """
    G = kin.G
    return [G.sub(a, b) for a, b in zip(applied_forces(kin), generalized_bias_forces(kin))]

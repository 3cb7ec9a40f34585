r"""
Kinematics of a system of rigid bodies over a choice of arithmetic

:class:`Kinematics` computes, for the bodies of a
:class:`~sage_dynsym.mechanics.system.MechanicalSystem`, the absolute
angular velocities `W_k`, the joint velocities
`V_{0k} = V_{0j} + W_j\times r^j_{0k} + v^j_{0k}`, the positions of joints
and mass centres, and the decomposition (4) of each body's kinetic energy
(1) (formulas of :doc:`the method </method>`), all as
:class:`~sage_dynsym.mechanics.frames.FrameVector` over either the symbolic ring or a
:class:`~sage_dynsym.algebra.trigonometric.TrigPolynomialRing`.

For large systems, :meth:`Kinematics.recursive_equations` assembles the
equations (5) body by body from the same kinematics (Newton--Euler
recursion), keeping the nested form of the kinematic expressions.

EXAMPLES::

    sage: from sage_dynsym import load
    sage: from sage_dynsym.description import example_path
    sage: from sage_dynsym.mechanics.kinematics import Kinematics
    sage: from sage_dynsym.algebra.trigonometric import SymbolicBackend
    sage: K = Kinematics(load(example_path('spherical_pendulum.yaml')), SymbolicBackend())
    sage: K.angular_velocity(1).components(K.body_frame(1))
    (dtheta, dpsi*sin(theta), dpsi*cos(theta))
"""
from sage.misc.cachefunc import cached_method
from sage.misc.verbose import verbose
from sage.rings.rational_field import QQ
from sage.symbolic.ring import SR

from ..numerics.body_tree import BodyTree
from ..numerics.newton_euler import body_forces, velocity_corrections
from ..numerics import spatial
from ..symbols import time_derivative, t
from .frames import FrameTree, FrameVector, cross

__all__ = ['Kinematics']


class Kinematics:
    r"""
    Velocities, positions and kinetic-energy decompositions of the bodies of
    ``system`` (a :class:`~sage_dynsym.numerics.body_tree.BodyTree`, or a
    mechanical system: then the tree of its bodies), with the arithmetic of ``backend``
    (:class:`~sage_dynsym.algebra.trigonometric.SymbolicBackend` or
    :class:`~sage_dynsym.algebra.trigonometric.TrigPolynomialRing`).

    EXAMPLES::

        sage: from sage_dynsym import load
        sage: from sage_dynsym.description import example_path
        sage: from sage_dynsym.mechanics.kinematics import Kinematics
        sage: from sage_dynsym.algebra.trigonometric import TrigPolynomialRing
        sage: S = load(example_path('spherical_pendulum.yaml'))
        sage: R = TrigPolynomialRing([var('psi'), var('theta')],
        ....:                        [var(n) for n in 'm l g dpsi dtheta psi theta t'.split()])
        sage: A, A1, A0 = Kinematics(S, R).body_decomposition(1)
        sage: R.to_symbolic(A[0][0]), R.to_symbolic(A[1][1])
        (l^2*m*sin(theta)^2, l^2*m)
    """

    def __init__(self, system, backend):
        if not isinstance(system, BodyTree):
            bodies = system.bodies()
            system = BodyTree(bodies, system.coordinates(),
                              parents=[system.parent_index(k) for k in range(1, len(bodies) + 1)])
        self._body_tree = system
        self._backend = backend
        self._bodies = system.bodies()
        self._parents = [None] + [system.parent(k) for k in range(1, len(self._bodies) + 1)]
        self._coordinates = system.coordinates()
        self._velocities = system.velocities()
        self.tree = FrameTree(trig=backend.trig, zero=backend.zero)
        self._frames = [0]
        for k, body in enumerate(self._bodies, 1):
            self._frames.append(self.tree.add_rotations(self._frames[self._parents[k]],
                                                        body.rotations()))

    def body_tree(self):
        r"""
        The :class:`~sage_dynsym.numerics.body_tree.BodyTree` whose
        kinematics this is: the system's own bodies with their parents'
        indices and the coordinates, the description the recursive
        numerics read too.

        EXAMPLES::

            sage: from sage_dynsym import load
            sage: from sage_dynsym.description import example_path
            sage: from sage_dynsym.mechanics.kinematics import Kinematics
            sage: from sage_dynsym.algebra.trigonometric import SymbolicBackend
            sage: S = load(example_path('spherical_pendulum.yaml'))
            sage: T = Kinematics(S, SymbolicBackend()).body_tree(); T
            Tree of 1 body in (psi, theta), parameters (l, m)
            sage: T.bodies()[0] is S.bodies()[0]
            True
            sage: Kinematics(T, SymbolicBackend()).angular_velocity(1).components(0)
            (dtheta*cos(psi), dtheta*sin(psi), dpsi)
        """
        return self._body_tree

    @cached_method
    def tree_kinematics(self):
        r"""
        The kinematic pass of the recursive algorithms over
        :meth:`body_tree`, in the symbolic arithmetic (a
        :class:`~sage_dynsym.numerics.tree_kinematics.TreeKinematics`,
        built once): what the loads' generalized forces are projected with
        (:meth:`~sage_dynsym.mechanics.loads.Load.generalized_forces`).

        EXAMPLES: the angular velocity of a body turned by `a` and `b`, in
        its axes::

            sage: from sage_dynsym import MechanicalSystem, RigidBody
            sage: a, b = var('a b')
            sage: S = MechanicalSystem([RigidBody('b', rotations=[(3, a), (1, b)])], [a, b])
            sage: S.kinematics().symbolic().tree_kinematics().state[1][0]
            (db, da*sin(b), da*cos(b))
        """
        return self._body_tree.kinematics('symbolic')

    def backend(self):
        r"""The arithmetic backend (:class:`~sage_dynsym.algebra.trigonometric.SymbolicBackend`
        or :class:`~sage_dynsym.algebra.trigonometric.TrigPolynomialRing`).

        EXAMPLES::

            sage: from sage_dynsym import load
            sage: from sage_dynsym.description import example_path
            sage: from sage_dynsym.mechanics.kinematics import Kinematics
            sage: from sage_dynsym.algebra.trigonometric import SymbolicBackend
            sage: S = load(example_path('spherical_pendulum.yaml'))
            sage: Kinematics(S, SymbolicBackend()).backend()
            <sage_dynsym.algebra.trigonometric.SymbolicBackend object at 0x...>
        """
        return self._backend

    def body_frame(self, k):
        r"""The frame of body ``k`` in :attr:`tree` (``0``: the inertial frame).

        EXAMPLES: the pendulum's frame is the last of its rotations,
        `\theta` about the first axis::

            sage: from sage_dynsym import load
            sage: from sage_dynsym.description import example_path
            sage: from sage_dynsym.mechanics.kinematics import Kinematics
            sage: from sage_dynsym.algebra.trigonometric import SymbolicBackend
            sage: K = Kinematics(load(example_path('spherical_pendulum.yaml')), SymbolicBackend())
            sage: f = K.body_frame(1); K.body_frame(0), K.tree.axis(f), K.tree.angle(f)
            (0, 1, theta)
        """
        return self._frames[k]

    def _vector(self, frame, components):
        return FrameVector(self.tree, {frame: tuple(self._backend.convert(c) for c in components)})

    def _rate(self, angle):
        return self._backend.convert(time_derivative(angle, self._coordinates, self._velocities))

    @cached_method
    def angular_velocity(self, k):
        if k == 0:
            return FrameVector(self.tree)
        parts = {}
        frame, stop = self._frames[k], self._frames[self._parents[k]]
        zero = self._backend.zero
        while frame != stop:
            axis_vector = [zero, zero, zero]
            axis_vector[self.tree.axis(frame) - 1] = self._rate(self.tree.angle(frame))
            parts[frame] = tuple(axis_vector)
            frame = self.tree.parent(frame)
        return self.angular_velocity(self._parents[k]) + FrameVector(self.tree, parts)

    def _relative_velocity(self, k):
        body = self._bodies[k - 1]
        if body.velocity() is not None:
            return body.velocity()
        return tuple(time_derivative(c, self._coordinates, self._velocities)
                     for c in body.joint())

    @cached_method
    def joint_velocity(self, k):
        if k == 0:
            return FrameVector(self.tree)
        j = self._parents[k]
        parent_frame = self._frames[j]
        joint = [self._backend.convert(c) for c in self._bodies[k - 1].joint()]
        V = self.joint_velocity(j) + self._vector(parent_frame, self._relative_velocity(k))
        for frame, w in self.angular_velocity(j).parts().items():
            r = self.tree.express(joint, parent_frame, frame)
            V = V + FrameVector(self.tree, {frame: (w[1] * r[2] - w[2] * r[1],
                                                    w[2] * r[0] - w[0] * r[2],
                                                    w[0] * r[1] - w[1] * r[0])})
        return V

    @cached_method
    def joint_position(self, k):
        if k == 0:
            return FrameVector(self.tree)
        j = self._parents[k]
        return self.joint_position(j) + self._vector(self._frames[j], self._bodies[k - 1].joint())

    def mass_center_position(self, k):
        r"""The position of the mass centre of body ``k`` (a
        :class:`~sage_dynsym.mechanics.frames.FrameVector`).

        EXAMPLES::

            sage: from sage_dynsym import load
            sage: from sage_dynsym.description import example_path
            sage: from sage_dynsym.mechanics.kinematics import Kinematics
            sage: from sage_dynsym.algebra.trigonometric import SymbolicBackend
            sage: K = Kinematics(load(example_path('spherical_pendulum.yaml')), SymbolicBackend())
            sage: r = K.mass_center_position(1)
            sage: r.components(K.body_frame(1)), r.components(0)
            ((0, 0, l), (l*sin(psi)*sin(theta), -l*cos(psi)*sin(theta), l*cos(theta)))
        """
        return self.joint_position(k) + self._vector(self._frames[k],
                                                     self._bodies[k - 1].mass_center())

    def _velocity_split(self, vector):
        backend = self._backend
        columns = [vector.map_components(lambda c, v=v: backend.diff(c, v))
                   for v in self._velocities]
        return columns, vector.map_components(lambda c: backend.at_zero(c, self._velocities))

    @cached_method
    def body_decomposition(self, k):
        r"""
        ``(A, A1, A0)`` of body ``k`` as nested lists of backend elements;
        see :meth:`MechanicalSystem.body_decomposition
        <sage_dynsym.mechanics.system.MechanicalSystem.body_decomposition>`.
        """
        backend = self._backend
        n = len(self._coordinates)
        zero = backend.zero
        body = self._bodies[k - 1]
        verbose(f"kinetic energy of body {k} ({body.name()})", level=1)
        if body.is_massless():
            return [[zero] * n for _ in range(n)], [zero] * n, zero
        frame = self._frames[k]
        m = backend.convert(body.mass())
        Theta = [[backend.convert(e) for e in row] for row in body.inertia().rows()]
        c = [backend.convert(e) for e in body.mass_center()]
        JV, V0 = self._velocity_split(self.joint_velocity(k))
        JW, W0 = self._velocity_split(self.angular_velocity(k))
        JW = [w.components(frame) for w in JW]
        W0 = W0.components(frame)

        def inertia_product(u, w):
            return sum((u[i] * Theta[i][j] * w[j] for i in range(3) for j in range(3)
                        if Theta[i][j]), zero)

        def cross_c(w):
            # w x c, in the body's axes
            return FrameVector(self.tree, {frame: cross(w, c)})

        def bilinear(V1, W1, V2, W2):
            # the symmetric bilinear form whose quadratic form is 2 T_k, see (1)
            return (m * V1.dot(V2) + inertia_product(W1, W2)
                    + m * (V1.dot(cross_c(W2)) + V2.dot(cross_c(W1))))

        A = [[zero] * n for _ in range(n)]
        for i in range(n):
            for j in range(i, n):
                A[i][j] = A[j][i] = bilinear(JV[i], JW[i], JV[j], JW[j])
        A1 = [bilinear(JV[i], JW[i], V0, W0) for i in range(n)]
        A0 = QQ((1, 2)) * bilinear(V0, W0, V0, W0)
        return A, A1, A0

    def recursive_applies(self):
        r"""
        Whether :meth:`recursive_equations` applies: every body has a constant
        mass, mass centre and inertia tensor (no coordinate, velocity or time
        in them) and its prescribed relative velocity, if any, is linear in
        the velocities (as a kinetic energy of the form (4) needs).

        EXAMPLES::

            sage: from sage_dynsym import MechanicalSystem, RigidBody
            sage: from sage_dynsym.mechanics.kinematics import Kinematics
            sage: from sage_dynsym.algebra.trigonometric import SymbolicBackend
            sage: x, m = var('x m')
            sage: S = MechanicalSystem([RigidBody('b', joint=[x, 0, 0], mass=m)], [x])
            sage: Kinematics(S, SymbolicBackend()).recursive_applies()
            True
            sage: S = MechanicalSystem([RigidBody('b', joint=[x, 0, 0], mass=m*x)], [x])
            sage: Kinematics(S, SymbolicBackend()).recursive_applies()
            False
            sage: b = RigidBody('b', joint=[x, 0, 0], velocity=[x*var('dx'), 0, 0], mass=m)
            sage: Kinematics(MechanicalSystem([b], [x]), SymbolicBackend()).recursive_applies()
            True
        """
        return (self._body_tree.varying_inertia() is None
                and self._body_tree.nonlinear_velocity() is None)

    @cached_method
    def recursive_equations(self, gravity=None):
        r"""
        The kinetic part of the equations (5), assembled body by body over the
        symbolic ring (Newton--Euler recursion; see :meth:`recursive_applies`);
        with ``gravity`` (a triple: the acceleration of a uniform field, in the inertial
        axes) also the field's terms `-\partial U/\partial q_i`, as an
        acceleration `-g` of the inertial frame [Fea2008]_ (Section 5.3), so
        that the force function is never differentiated.

        With the partial velocities `\partial V_{0k}/\partial\dot q_i` and
        `\partial W_k/\partial\dot q_i` of the joint and the body, its
        acceleration `a_{0k}` and angular acceleration `\varepsilon_k`, all in
        body `k`'s axes (the quantities of the kinetic energy (1) of
        :doc:`the method </method>` and their time derivatives), Kane's form of the equations
        [KL1985]_ with the momenta about the joint point `O_k`,

        .. MATH::

            \frac{d}{dt}\frac{\partial T}{\partial\dot q_i}
            - \frac{\partial T}{\partial q_i}
            = \sum_k \frac{\partial V_{0k}}{\partial\dot q_i}\cdot
              m_k\big(a_{0k} + \varepsilon_k\times r_{ck}
                      + W_k\times(W_k\times r_{ck})\big)
            + \frac{\partial W_k}{\partial\dot q_i}\cdot
              \big(\Theta_k\varepsilon_k + W_k\times\Theta_k W_k
                   + m_k\, r_{ck}\times a_{0k}\big).

        The accelerations' terms give the mass matrix `A`; the rest, at zero
        accelerations, the terms `h_i` in the velocities (and time). The
        kinematic quantities and the forces on the bodies are those of the
        recursion of the compiled numerics, run in the symbolic arithmetic
        (:class:`~sage_dynsym.numerics.tree_kinematics.TreeKinematics`,
        :func:`~sage_dynsym.numerics.newton_euler.body_forces` over
        :class:`~sage_dynsym.numerics.spatial.SymbolicArithmetic`): built
        frame by frame (one elementary rotation at a time) and never
        expanded, so the equations of a long chain stay far shorter than
        their expanded form. Each body's force is paired with its own
        partial velocities (rather than summed up the tree as the compiled
        code does, whose graph shares the sums): a symbolic expression is a
        tree, and nested sums of forces would grow with the depth.

        A prescribed relative velocity `v^j_{0k}` that is not the time
        derivative of the joint point makes Lagrange's equations of the
        kinetic energy (1) differ from Kane's form; the difference, the
        terms of :func:`~sage_dynsym.numerics.newton_euler.velocity_corrections`
        (the same as the compiled right-hand side adds), is added to `h_i`.

        OUTPUT: a tuple ``(A, A1, T0, h)``: the decomposition (4) of the
        kinetic energy (nested lists and an expression) and the list of `h_i`,
        so that `\sum_r A_{ir}\ddot q_r + h_i` is the kinetic part of `E_i`
        (with the gravity terms when ``gravity`` is given).

        EXAMPLES: the spherical pendulum (equations (9) of Example 1, without
        gravity)::

            sage: from sage_dynsym import load
            sage: from sage_dynsym.description import example_path
            sage: from sage_dynsym.mechanics.kinematics import Kinematics
            sage: from sage_dynsym.algebra.trigonometric import SymbolicBackend
            sage: K = Kinematics(load(example_path('spherical_pendulum.yaml')), SymbolicBackend())
            sage: A, A1, T0, h = K.recursive_equations()
            sage: A, h
            ([[l^2*m*sin(theta)^2, 0], [0, l^2*m]],
             [2*dpsi*dtheta*l^2*m*cos(theta)*sin(theta), -dpsi^2*l^2*m*cos(theta)*sin(theta)])

        With gravity, `-\partial U/\partial\theta = g l m\sin\theta`
        is added::

            sage: K.recursive_equations((0, 0, -var('g')))[3][1]
            -dpsi^2*l^2*m*cos(theta)*sin(theta) - g*l*m*sin(theta)

        TESTS:

        A sliding joint on a turntable turning at the prescribed rate `w`
        (time in the kinematics: `A_1` and `T_0`)::

            sage: from sage_dynsym import MechanicalSystem, RigidBody
            sage: x, w, m = var('x w m'); t = var('t')
            sage: S = MechanicalSystem([RigidBody('table', rotations=[(3, w*t)]),
            ....:                       RigidBody('bead', parent='table', joint=[x, 0, 0],
            ....:                                 mass=m)], [x])
            sage: A, A1, T0, h = Kinematics(S, SymbolicBackend()).recursive_equations()
            sage: A, A1, T0, h
            ([[m]], [0], 1/2*m*w^2*x^2, [-m*w^2*x])

        A body whose joint point moves with twice the rate of its
        coordinate, in gravity `g` along `x`: the kinetic energy
        `2 m\dot x^2` and the force function `m g x` of the joint point
        give `4 m\ddot x - m g` (Kane's form would give `-2 m g`); and a
        pendulum whose support moves with the given velocity `v(t)` along
        `y`, whose equation is `m l^2\ddot\varphi + m l\cos\varphi\,
        \dot v + m g l\sin\varphi = 0`::

            sage: g, dx, l = var('g dx l')
            sage: b = RigidBody('b', joint=[x, 0, 0], velocity=[2*dx, 0, 0], mass=m)
            sage: K = Kinematics(MechanicalSystem([b], [x]), SymbolicBackend())
            sage: A, A1, T0, h = K.recursive_equations((g, 0, 0)); A, h
            ([[4*m]], [-g*m])
            sage: phi, v = var('phi'), function('v')
            sage: S = MechanicalSystem([RigidBody('support', velocity=[0, v(t), 0]),
            ....:                       RigidBody('rod', parent='support', rotations=[(1, phi)],
            ....:                                 mass=m, mass_center=[0, 0, -l],
            ....:                                 inertia=diagonal_matrix([m*l^2, 0, 0]))], [phi])
            sage: A, A1, T0, h = Kinematics(S, SymbolicBackend()).recursive_equations((0, 0, -g))
            sage: A, (h[0] - m*l*cos(phi)*diff(v(t), t) - g*l*m*sin(phi)).simplify_full()
            ([[l^2*m]], 0)
            sage: (A1[0] - m*l*cos(phi)*v(t)).simplify_full(), (T0 - m*v(t)^2/2).simplify_full()
            (0, 0)

        REFERENCES:

        .. [KL1985] T. R. Kane, D. A. Levinson, *Dynamics: Theory and
           Applications*, McGraw-Hill 1985, chapters 5 and 6 (generalized
           inertia forces from partial velocities).
        """
        kin = self._body_tree.with_forces(gravity=gravity).kinematics('symbolic')
        G, n = kin.G, kin.n
        forces = body_forces(kin)
        rest = {v: 0 for v in self._velocities}
        moving = [False]
        for k, body in enumerate(self._bodies, 1):
            own = [angle for _, angle in body.rotations()] + list(body.joint())
            moving.append(moving[self._parents[k]] or any(SR(e).has(t) for e in own)
                          or any(not SR(u).subs(rest).is_zero() for u in body.velocity() or ()))
        A = [[[] for _ in range(n)] for _ in range(n)]
        A1, T0, h = [[] for _ in range(n)], [], [[] for _ in range(n)]
        for k, body in enumerate(self._bodies, 1):
            if body.is_massless():
                continue
            J = kin.partial_velocities(k)
            m, mc, Theta = kin.inertia(body)

            def momentum(W, V, m=m, mc=mc, Theta=Theta):
                # the linear and angular momentum (about O_k) of velocities W, V
                return (spatial.add(G, spatial.scale(G, m, V), spatial.cross(G, W, mc)),
                        spatial.add(G, spatial.matvec(G, Theta, W), spatial.cross(G, mc, V)))

            def pair(motion, P):
                # the power of the force P = (f, n) in the motion (W, V)
                return G.add(G.dot(motion[1], P[0]), G.dot(motion[0], P[1]))

            # the velocities at rest (only a rheonomic joint moves the body)
            motion = (tuple(tuple(SR(x).subs(rest) for x in u) for u in kin.state[k][:2])
                      if moving[k] else (kin.zero3, kin.zero3))
            at_rest = momentum(*motion)
            T0.append(pair(motion, at_rest) / 2)
            for i in sorted(J):
                h[i].append(pair(J[i], forces[k]))
                A1[i].append(pair(J[i], at_rest))
                column = momentum(*J[i])
                for s in sorted(J):
                    if s >= i:
                        A[i][s].append(pair(J[s], column))
        A = [[G.sum(A[min(i, s)][max(i, s)]) for s in range(n)] for i in range(n)]
        h = [G.add(G.sum(x), e) for x, e in zip(h, velocity_corrections(kin))]
        return A, [G.sum(x) for x in A1], G.sum(T0), h

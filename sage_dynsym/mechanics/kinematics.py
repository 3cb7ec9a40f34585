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

from ..symbols import time_derivative, t
from .frames import FrameTree, FrameVector, cross, held_product

__all__ = ['Kinematics']


class Kinematics:
    r"""
    Velocities, positions and kinetic-energy decompositions of the bodies of
    ``system``, with the arithmetic of ``backend``
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
        self._system = system
        self._backend = backend
        self._bodies = system.bodies()
        self._parents = [None] + [system.parent_index(k) for k in range(1, len(self._bodies) + 1)]
        self._coordinates = system.coordinates()
        self._velocities = system.velocities()
        self.tree = FrameTree(trig=backend.trig, zero=backend.zero)
        self._frames = [0]
        for k, body in enumerate(self._bodies, 1):
            self._frames.append(self.tree.add_rotations(self._frames[self._parents[k]],
                                                        body.rotations()))

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
        in them) and no prescribed relative velocity.

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
        """
        dynamic = set(self._coordinates) | set(self._velocities) | {t}
        for body in self._bodies:
            data = [body.mass()] + list(body.mass_center()) + body.inertia().list()
            if body.velocity() is not None or any(
                    dynamic.intersection(SR(e).variables()) for e in data):
                return False
        return True

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
        kinematic quantities are built frame by frame (one elementary
        rotation at a time) and never expanded, so the equations of a long
        chain stay far shorter than their expanded form.

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

        REFERENCES:

        .. [KL1985] T. R. Kane, D. A. Levinson, *Dynamics: Theory and
           Applications*, McGraw-Hill 1985, chapters 5 and 6 (generalized
           inertia forces from partial velocities).
        """
        n = len(self._coordinates)
        tree, zero = self.tree, SR(0)
        no_acceleration = [0] * n

        def rate(expr):
            # time derivative at zero accelerations
            return time_derivative(expr, self._coordinates, self._velocities, no_acceleration)

        def at_rest(expr):
            return SR(expr).subs({v: 0 for v in self._velocities})

        def partials(expr):
            return [SR(expr).diff(v) for v in self._velocities]

        # per frame, in its own axes: W, its value at rest W0, the angular
        # acceleration at zero accelerations, the partial angular velocities
        W, W0, eps, JW = {0: _ZERO3}, {0: _ZERO3}, {0: _ZERO3}, {0: [None] * n}
        # every frame lies on the path of some body; parents come first
        frames = sorted(set().union(*[tree.path_to_root(f) for f in self._frames]) - {0})
        for f in frames:
            p, axis = tree.parent(f), tree.axis(f)

            def down(v, p=p, f=f):
                # components in f of the vector with components v in p
                return tree.express(v, p, f, product=held_product)

            angle_rate = rate(tree.angle(f))
            w = down(W[p])
            W[f] = _plus_axis(w, axis, angle_rate)
            W0[f] = _plus_axis(down(W0[p]), axis, at_rest(angle_rate))
            # d/dt (rate e) = (rate)' e + rate W_parent x e
            spin = _plus_axis(_ZERO3, axis, angle_rate)
            eps[f] = _add(_plus_axis(down(eps[p]), axis, rate(angle_rate)), cross(w, spin))
            JW[f] = [_plus_axis(None if J is None else down(J), axis, d)
                     for J, d in zip(JW[p], partials(angle_rate))]
        # per body, in its own axes: V0k at rest, a0k at zero accelerations,
        # the partial velocities
        base = _ZERO3 if gravity is None else tuple(-SR(g) for g in gravity)
        V0, acc, JV = {0: _ZERO3}, {0: base}, {0: [None] * n}
        A = [[[] for _ in range(n)] for _ in range(n)]
        A1, T0, h = [[] for _ in range(n)], [], [[] for _ in range(n)]
        for k, body in enumerate(self._bodies, 1):
            j = self._parents[k]
            fj, fk = self._frames[j], self._frames[k]
            r = [SR(c) for c in body.joint()]
            dr = [rate(c) for c in r]
            w, e = W[fj], eps[fj]
            a = _add(acc[j], cross(e, r), cross(w, cross(w, r)),
                     [2 * c for c in cross(w, dr)], [rate(c) for c in dr])
            acc[k] = tree.express(a, fj, fk, product=held_product)
            V0[k] = tree.express(_add(V0[j], cross(W0[fj], r), [at_rest(c) for c in dr]),
                                 fj, fk, product=held_product)
            dr_partials = [partials(c) for c in dr]
            JV[k] = []
            for i in range(n):
                parts = [J for J in (JV[j][i], None if JW[fj][i] is None else cross(JW[fj][i], r),
                                     [d[i] for d in dr_partials]) if J is not None]
                J = _add(*parts)
                JV[k].append(None if all(x.is_trivial_zero() for x in J)
                             else tree.express(J, fj, fk, product=held_product))
            if body.is_massless():
                continue
            m = SR(body.mass())
            c = [SR(x) for x in body.mass_center()]
            inertia = body.inertia()

            # the nonzero entries (a symbolic truth test would try to prove them nonzero)
            rows = [[(b, inertia[a, b]) for b in range(3) if not inertia[a, b].is_trivial_zero()]
                    for a in range(3)]

            def Theta(u):
                return [zero.add(*[x * u[b] for b, x in row]) for row in rows]

            def momentum(V, Wv):
                # the linear and angular momentum (about O_k) of velocities V, W
                return [m * x for x in _add(V, cross(Wv, c))], _add(
                    Theta(Wv), [m * x for x in cross(c, V)])

            def pair(V, Wv, P):
                # <(V, W), (F, M)>; None stands for zero
                return zero.add(*[_dot(X, Y) for X, Y in zip((V, Wv), P) if X is not None])

            w, e, a = W[fk], eps[fk], acc[k]
            force = ([m * x for x in _add(a, cross(e, c), cross(w, cross(w, c)))],
                     _add(Theta(e), cross(w, Theta(w)), [m * x for x in cross(c, a)]))
            rest = momentum(V0[k], W0[fk])
            T0.append(pair(V0[k], W0[fk], rest) / 2)
            for i in range(n):
                if JV[k][i] is None and JW[fk][i] is None:
                    continue
                h[i].append(pair(JV[k][i], JW[fk][i], force))
                A1[i].append(pair(JV[k][i], JW[fk][i], rest))
                column = momentum(JV[k][i] or _ZERO3, JW[fk][i] or _ZERO3)
                for s in range(i, n):
                    if JV[k][s] is not None or JW[fk][s] is not None:
                        A[i][s].append(pair(JV[k][s], JW[fk][s], column))
        A = [[zero.add(*A[min(i, s)][max(i, s)]) for s in range(n)] for i in range(n)]
        return A, [zero.add(*x) for x in A1], zero.add(*T0), [zero.add(*x) for x in h]


_ZERO3 = (SR(0), SR(0), SR(0))


def _add(*vectors):
    return tuple(SR(0).add(*components) for components in zip(*vectors))


def _dot(u, w):
    return SR(0).add(*[held_product(a, b) for a, b in zip(u, w)
                       if not (a.is_trivial_zero() or b.is_trivial_zero())])


def _plus_axis(vector, axis, value):
    # ``vector`` (None: zero) plus ``value`` times the unit vector of ``axis``;
    # None if the result is zero
    if vector is None:
        if SR(value).is_trivial_zero():
            return None
        vector = _ZERO3
    vector = list(vector)
    vector[axis - 1] += value
    return tuple(vector)

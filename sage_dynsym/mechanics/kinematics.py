r"""
Kinematics of a system of rigid bodies over a choice of arithmetic

:class:`Kinematics` computes, for the bodies of a
:class:`~sage_dynsym.mechanics.system.MechanicalSystem`, the absolute
angular velocities `W_k`, the joint velocities
`V_{0k} = V_{0j} + W_j\times r^j_{0k} + v^j_{0k}`, the positions of joints
and mass centres, and the decomposition (4) of each body's kinetic energy
(1) (formulas of :doc:`the method </method>`), all as
:class:`~sage_dynsym.mechanics.frames.FrameVector` over either the symbolic ring or a
:class:`~sage_dynsym.analysis.trigonometric.TrigPolynomialRing`.

EXAMPLES::

    sage: from sage_dynsym import load
    sage: from sage_dynsym.description import example_path
    sage: from sage_dynsym.mechanics.kinematics import Kinematics
    sage: from sage_dynsym.analysis.trigonometric import SymbolicBackend
    sage: K = Kinematics(load(example_path('spherical_pendulum.yaml')), SymbolicBackend())
    sage: K.angular_velocity(1).components(K.body_frame(1))
    (dtheta, dpsi*sin(theta), dpsi*cos(theta))
"""
from sage.misc.cachefunc import cached_method
from sage.misc.verbose import verbose
from sage.rings.rational_field import QQ

from ..symbols import time_derivative
from .frames import FrameTree, FrameVector, cross


class Kinematics:
    r"""
    Velocities, positions and kinetic-energy decompositions of the bodies of
    ``system``, with the arithmetic of ``backend``
    (:class:`~sage_dynsym.analysis.trigonometric.SymbolicBackend` or
    :class:`~sage_dynsym.analysis.trigonometric.TrigPolynomialRing`).

    EXAMPLES::

        sage: from sage_dynsym import load
        sage: from sage_dynsym.description import example_path
        sage: from sage_dynsym.mechanics.kinematics import Kinematics
        sage: from sage_dynsym.analysis.trigonometric import TrigPolynomialRing
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
        r"""The arithmetic backend (:class:`~sage_dynsym.analysis.trigonometric.SymbolicBackend`
        or :class:`~sage_dynsym.analysis.trigonometric.TrigPolynomialRing`).

        EXAMPLES::

            sage: from sage_dynsym import load
            sage: from sage_dynsym.description import example_path
            sage: from sage_dynsym.mechanics.kinematics import Kinematics
            sage: from sage_dynsym.analysis.trigonometric import SymbolicBackend
            sage: S = load(example_path('spherical_pendulum.yaml'))
            sage: Kinematics(S, SymbolicBackend()).backend()
            <sage_dynsym.analysis.trigonometric.SymbolicBackend object at 0x...>
        """
        return self._backend

    def body_frame(self, k):
        r"""The frame of body ``k`` in :attr:`tree` (``0``: the inertial frame).

        EXAMPLES: the pendulum's frame is the last of its rotations,
        `\theta` about the first axis::

            sage: from sage_dynsym import load
            sage: from sage_dynsym.description import example_path
            sage: from sage_dynsym.mechanics.kinematics import Kinematics
            sage: from sage_dynsym.analysis.trigonometric import SymbolicBackend
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
            sage: from sage_dynsym.analysis.trigonometric import SymbolicBackend
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

r"""
Frames linked by elementary rotations, and vectors living in several frames

Every body frame `\Sigma^k` is reached from its parent's frame by a sequence
of elementary rotations (axis 1, 2 or 3 = x, y, z, each about the *new*
axis). The frames form a tree rooted at the inertial frame `\Sigma^0`.

A :class:`FrameVector` is a formal sum of 3-vectors, each given by its
components in one frame of the tree. Sums are kept per frame; a component
is rotated only when two parts must meet (dot or cross product), and then
only through the rotations *between* the two frames. This keeps kinetic
energies and force functions in compact trigonometric form: the dot product
of the joint axes of two links involves only the angles between them, never
the absolute orientation.

EXAMPLES::

    sage: from sage_dynsym.mechanics.frames import FrameTree, FrameVector, rotation_matrix
    sage: psi, theta = var('psi theta')
    sage: rotation_matrix(3, psi)
    [ cos(psi) -sin(psi)         0]
    [ sin(psi)  cos(psi)         0]
    [        0         0         1]
    sage: T = FrameTree()
    sage: f = T.add_rotations(0, [(3, psi), (1, theta)]); f
    2
    sage: T.direction_cosines(f)
    [ cos(psi) -cos(theta)*sin(psi)  sin(psi)*sin(theta)]
    [ sin(psi)  cos(psi)*cos(theta) -cos(psi)*sin(theta)]
    [        0           sin(theta)           cos(theta)]
    sage: r = FrameVector(T, {f: (0, 0, 1)})
    sage: r.components(0)
    (sin(psi)*sin(theta), -cos(psi)*sin(theta), cos(theta))
"""
import operator

from sage.matrix.constructor import matrix
from sage.symbolic.ring import SR

from ..algebra.trigonometric import symbolic_trig
from ..numerics.spatial import held_product  # noqa: F401 (the product of its users here)

__all__ = ['rotation_matrix', 'cross', 'held_product', 'FrameTree', 'FrameVector']


def rotation_matrix(axis, angle):
    r"""
    The elementary rotation matrix about ``axis`` (1, 2 or 3) by ``angle``:
    the columns are the rotated axes in the old frame, so that
    `x_{old} = R\, x_{new}`.

    EXAMPLES::

        sage: from sage_dynsym.mechanics.frames import rotation_matrix
        sage: rotation_matrix(1, var('a'))
        [      1       0       0]
        [      0  cos(a) -sin(a)]
        [      0  sin(a)  cos(a)]
    """
    c, s = SR(angle).cos(), SR(angle).sin()
    if axis == 1:
        rows = [[1, 0, 0], [0, c, -s], [0, s, c]]
    elif axis == 2:
        rows = [[c, 0, s], [0, 1, 0], [-s, 0, c]]
    else:
        rows = [[c, -s, 0], [s, c, 0], [0, 0, 1]]
    return matrix(SR, rows)


def cross(u, w):
    r"""
    The vector product of two triples of components in the same axes.

    EXAMPLES::

        sage: from sage_dynsym.mechanics.frames import cross
        sage: cross((1, 0, 0), (0, 1, 0))
        (0, 0, 1)
    """
    return (u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0])


def _rotate(components, axis, trig, inverse=False, product=operator.mul):
    r"""
    Apply the elementary rotation (or its inverse) to a 3-tuple: only the two
    components orthogonal to the axis change. ``trig`` is the pair
    `(\cos, \sin)` of the angle; ``product`` multiplies.
    """
    c, s = trig
    if inverse:
        s = -s
    i, j = {1: (1, 2), 2: (2, 0), 3: (0, 1)}[axis]
    out = list(components)
    # -s, not the product, is negated: negating a held product evaluates it
    out[i] = product(c, components[i]) + product(-s, components[j])
    out[j] = product(s, components[i]) + product(c, components[j])
    return tuple(out)


class FrameTree:
    r"""
    A tree of frames, each obtained from its parent by one elementary
    rotation. Frame ``0`` is the inertial frame.

    INPUT:

    - ``trig`` -- (default:
      :func:`~sage_dynsym.algebra.trigonometric.symbolic_trig`) a function giving the
      pair `(\cos\theta, \sin\theta)` of an angle, as elements of the
      ring the components live in
    - ``zero`` -- (default: ``SR(0)``) the zero of that ring

    EXAMPLES::

        sage: from sage_dynsym.mechanics.frames import FrameTree
        sage: T = FrameTree()
        sage: a = T.add_rotations(0, [(3, var('u'))])
        sage: b = T.add_rotations(a, [(1, var('v'))])
        sage: T.path_to_root(b), T.angle(b), T.axis(b)
        ([2, 1, 0], v, 1)
    """

    def __init__(self, trig=symbolic_trig, zero=None):
        self._parent = [None]
        self._axis = [None]
        self._angle = [None]
        self._trig = [None]
        self._depth = [0]
        self._trig_function = trig
        self.zero = SR(0) if zero is None else zero

    def add_rotations(self, frame, rotations):
        r"""
        Append the frames of a sequence of elementary rotations starting at
        ``frame``; return the last frame (``frame`` itself if the sequence is
        empty).

        EXAMPLES::

            sage: from sage_dynsym.mechanics.frames import FrameTree
            sage: FrameTree().add_rotations(0, [])
            0
        """
        for axis, angle in rotations:
            self._parent.append(frame)
            self._axis.append(axis)
            self._angle.append(SR(angle))
            self._trig.append(self._trig_function(angle))
            self._depth.append(self._depth[frame] + 1)
            frame = len(self._parent) - 1
        return frame

    def parent(self, frame):
        r"""
        The parent frame (``None`` for the inertial frame).

        EXAMPLES::

            sage: from sage_dynsym.mechanics.frames import FrameTree
            sage: T = FrameTree(); T.parent(T.add_rotations(0, [(2, 1)]))
            0
        """
        return self._parent[frame]

    def axis(self, frame):
        r"""
        The axis of the rotation leading to ``frame``.

        EXAMPLES::

            sage: from sage_dynsym.mechanics.frames import FrameTree
            sage: T = FrameTree(); T.axis(T.add_rotations(0, [(2, 1)]))
            2
        """
        return self._axis[frame]

    def angle(self, frame):
        r"""
        The angle of the rotation leading to ``frame``.

        EXAMPLES::

            sage: from sage_dynsym.mechanics.frames import FrameTree
            sage: T = FrameTree(); T.angle(T.add_rotations(0, [(2, var('b'))]))
            b
        """
        return self._angle[frame]

    def path_to_root(self, frame):
        r"""
        The frames from ``frame`` up to the inertial frame, both included.

        EXAMPLES::

            sage: from sage_dynsym.mechanics.frames import FrameTree
            sage: FrameTree().path_to_root(0)
            [0]
        """
        path = [frame]
        while self._parent[path[-1]] is not None:
            path.append(self._parent[path[-1]])
        return path

    def common_ancestor(self, a, b):
        r"""
        The deepest frame that is an ancestor of both ``a`` and ``b``.

        EXAMPLES::

            sage: from sage_dynsym.mechanics.frames import FrameTree
            sage: T = FrameTree()
            sage: a = T.add_rotations(0, [(3, 1), (1, 2)]); b = T.add_rotations(1, [(2, 3)])
            sage: T.common_ancestor(a, b)
            1
        """
        while self._depth[a] > self._depth[b]:
            a = self._parent[a]
        while self._depth[b] > self._depth[a]:
            b = self._parent[b]
        while a != b:
            a, b = self._parent[a], self._parent[b]
        return a

    def express(self, components, source, target, product=operator.mul):
        r"""
        Components in frame ``target`` of the vector with ``components`` in
        frame ``source``; rotates only through the frames between them
        (``product``: the multiplication, e.g.
        :func:`~sage_dynsym.numerics.spatial.held_product`).

        EXAMPLES::

            sage: from sage_dynsym.mechanics.frames import FrameTree
            sage: T = FrameTree(); f = T.add_rotations(0, [(3, var('a'))])
            sage: T.express((1, 0, 0), f, 0)
            (cos(a), sin(a), 0)
            sage: T.express((1, 0, 0), 0, f)
            (cos(a), -sin(a), 0)
        """
        top = self.common_ancestor(source, target)
        v = tuple(components)
        while source != top:
            v = _rotate(v, self._axis[source], self._trig[source], product=product)
            source = self._parent[source]
        down = []
        while target != top:
            down.append(target)
            target = self._parent[target]
        for frame in reversed(down):
            v = _rotate(v, self._axis[frame], self._trig[frame], inverse=True, product=product)
        return v

    def direction_cosines(self, frame, reference=0):
        r"""
        The matrix `\alpha` whose columns are the axes of ``frame`` in the
        axes of ``reference`` (so `x_{reference} = \alpha\, x_{frame}`).

        EXAMPLES::

            sage: from sage_dynsym.mechanics.frames import FrameTree
            sage: T = FrameTree(); f = T.add_rotations(0, [(1, var('a'))])
            sage: T.direction_cosines(f) * T.direction_cosines(0, f)
            [                  1                   0                   0]
            [                  0 cos(a)^2 + sin(a)^2                   0]
            [                  0                   0 cos(a)^2 + sin(a)^2]
        """
        columns = [self.express(e, frame, reference)
                   for e in ((1, 0, 0), (0, 1, 0), (0, 0, 1))]
        return matrix(columns).transpose()


class FrameVector:
    r"""
    A vector given as a sum of parts, each with components in one frame of
    a :class:`FrameTree`.

    INPUT:

    - ``tree`` -- the :class:`FrameTree`
    - ``parts`` -- dictionary ``{frame: 3-tuple of components}``

    EXAMPLES::

        sage: from sage_dynsym.mechanics.frames import FrameTree, FrameVector
        sage: T = FrameTree(); f = T.add_rotations(0, [(3, var('a'))])
        sage: u = FrameVector(T, {0: (1, 0, 0)}); w = FrameVector(T, {f: (1, 0, 0)})
        sage: u.dot(w), (u + w).components(0)
        (cos(a), (cos(a) + 1, sin(a), 0))
        sage: u.cross(w, 0)
        (0, 0, sin(a))
    """

    def __init__(self, tree, parts=None):
        self._tree = tree
        self._parts = {}
        for frame, components in (parts or {}).items():
            self._add_part(frame, components)

    def _add_part(self, frame, components):
        zero = self._tree.zero
        components = tuple(zero + c for c in components)
        if frame in self._parts:
            components = tuple(a + b for a, b in zip(self._parts[frame], components))
        if any(not c.is_zero() for c in components):
            self._parts[frame] = components
        else:
            self._parts.pop(frame, None)

    def parts(self):
        r"""
        The dictionary ``{frame: components}`` (a copy).

        EXAMPLES::

            sage: from sage_dynsym.mechanics.frames import FrameTree, FrameVector
            sage: FrameVector(FrameTree(), {0: (1, 2, 0)}).parts()
            {0: (1, 2, 0)}
        """
        return dict(self._parts)

    def __add__(self, other):
        result = FrameVector(self._tree, self._parts)
        for frame, components in other._parts.items():
            result._add_part(frame, components)
        return result

    def __sub__(self, other):
        return self + other * (-1)

    def __mul__(self, scalar):
        return FrameVector(self._tree, {f: tuple(scalar * c for c in v)
                                        for f, v in self._parts.items()})

    def map_components(self, function):
        r"""
        The vector whose every component is ``function`` of this one's (e.g.
        a partial derivative: all parts are linear in the components).

        EXAMPLES::

            sage: from sage_dynsym.mechanics.frames import FrameTree, FrameVector
            sage: x = var('x')
            sage: FrameVector(FrameTree(), {0: (x^2, x, 1)}).map_components(lambda c: c.diff(x)).parts()
            {0: (2*x, 1, 0)}
        """
        return FrameVector(self._tree, {f: tuple(function(c) for c in v)
                                        for f, v in self._parts.items()})

    def is_zero(self):
        r"""
        Whether no part is left.

        EXAMPLES::

            sage: from sage_dynsym.mechanics.frames import FrameTree, FrameVector
            sage: FrameVector(FrameTree(), {0: (0, 0, 0)}).is_zero()
            True
        """
        return not self._parts

    def components(self, frame):
        r"""
        All parts summed, in the axes of ``frame``.

        EXAMPLES::

            sage: from sage_dynsym.mechanics.frames import FrameTree, FrameVector
            sage: FrameVector(FrameTree(), {}).components(0)
            (0, 0, 0)
        """
        total = [self._tree.zero] * 3
        for f, v in self._parts.items():
            total = [a + b for a, b in zip(total, self._tree.express(v, f, frame))]
        return tuple(total)

    def dot(self, other):
        r"""
        The scalar product: each pair of parts meets in their deepest common
        frame.

        EXAMPLES::

            sage: from sage_dynsym.mechanics.frames import FrameTree, FrameVector
            sage: T = FrameTree(); f = T.add_rotations(0, [(1, var('a'))])
            sage: FrameVector(T, {f: (0, 0, 1)}).dot(FrameVector(T, {0: (0, 0, 1)}))
            cos(a)
        """
        total = self._tree.zero
        for f, u in self._parts.items():
            for g, w in other._parts.items():
                top = self._tree.common_ancestor(f, g)
                uu, ww = self._tree.express(u, f, top), self._tree.express(w, g, top)
                total += sum(a * b for a, b in zip(uu, ww))
        return total

    def cross(self, other, frame):
        r"""
        The vector product, as components in ``frame``.

        EXAMPLES::

            sage: from sage_dynsym.mechanics.frames import FrameTree, FrameVector
            sage: T = FrameTree()
            sage: FrameVector(T, {0: (1, 0, 0)}).cross(FrameVector(T, {0: (0, 1, 0)}), 0)
            (0, 0, 1)
        """
        return cross(self.components(frame), other.components(frame))

r"""
Charts of the orientation of a rigid body: Euler angles

A sequence of three elementary rotations (about the *new* axes, as in
:class:`~sage_dynsym.mechanics.rigid_body.RigidBody`) is a chart of the
rotation group `SO(3)`: the rotation matrix `R = R_1(q_1) R_2(q_2)
R_3(q_3)` (body components to parent components) is its embedding, and
the angular velocity in the body axes is `\omega = E(q)\dot q` with

.. MATH::

    E(q)\dot q = R_3^T R_2^T e_{a_1}\dot q_1 + R_3^T e_{a_2}\dot q_2 + e_{a_3}\dot q_3,

singular where `\det E = 0` (`\cos q_2 = 0` for three different axes,
`\sin q_2 = 0` for Euler's `z, x, z`).

EXAMPLES::

    sage: from sage_dynsym.mechanics.charts import euler_angles
    sage: a, b, c = var('a b c')
    sage: chart = euler_angles([(3, a), (1, b), (2, c)])
    sage: chart.singular_function()
    cos(b)

REFERENCES:

- H. Goldstein, C. Poole, J. Safko, *Classical Mechanics*, 3rd ed.,
  Addison-Wesley, 2002, §4.4 and §4.9.
"""
from sage.matrix.constructor import matrix, vector
from sage.symbolic.ring import SR

from ..errors import ModelError, brief
from ..arguments import model_argument
from ..analysis.charts import ConfigurationChart, default_chart, product_chart
from .frames import rotation_matrix

__all__ = ['EulerAngles', 'euler_angles', 'model_chart']


class EulerAngles(ConfigurationChart):
    r"""
    The chart of `SO(3)` of three elementary rotations; see the module
    documentation. Built by :func:`euler_angles`.

    EXAMPLES::

        sage: from sage_dynsym.mechanics.charts import euler_angles
        sage: a, b, c = var('a b c')
        sage: euler_angles([(3, a), (1, b), (3, c)]).velocity_matrix()
        [sin(b)*sin(c)        cos(c)             0]
        [cos(c)*sin(b)       -sin(c)             0]
        [       cos(b)             0             1]
    """

    def __init__(self, rotations):
        self._rotations = [(int(axis), SR(q)) for axis, q in rotations]
        Rs = [rotation_matrix(axis, q) for axis, q in self._rotations]
        R = Rs[0] * Rs[1] * Rs[2]
        axes = [vector(SR, [1 if i == axis - 1 else 0 for i in range(3)])
                for axis, _ in self._rotations]
        columns = [(Rs[1] * Rs[2]).transpose() * axes[0], Rs[2].transpose() * axes[1], axes[2]]
        E = matrix(SR, columns).transpose()
        self._R = R
        ConfigurationChart.__init__(self, [q for _, q in self._rotations], R.list(), E, sheets=2)

    def _repr_(self):
        return "Euler angles " + ", ".join(f"{q} about axis {a}" for a, q in self._rotations)

    def rotation_matrix(self):
        r"""`R = R_1 R_2 R_3` (body components to parent components).

        EXAMPLES::

            sage: from sage_dynsym.mechanics.charts import euler_angles
            sage: a, b, c = var('a b c')
            sage: euler_angles([(3, a), (1, b), (2, c)]).rotation_matrix()[2]
            (-cos(b)*sin(c), sin(b), cos(b)*cos(c))
        """
        return self._R


def euler_angles(rotations):
    r"""
    The chart of `SO(3)` of three elementary rotations ``[(axis, angle),
    ...]`` (axes 1, 2, 3, consecutive axes different).

    OUTPUT: an :class:`EulerAngles` (a
    :class:`~sage_dynsym.analysis.charts.ConfigurationChart`)

    EXAMPLES::

        sage: from sage_dynsym.mechanics.charts import euler_angles
        sage: a, b, c = var('a b c')
        sage: euler_angles([(3, a), (1, b), (2, c)])
        Euler angles a about axis 3, b about axis 1, c about axis 2

    TESTS::

        sage: euler_angles([(3, a), (3, b), (2, c)])
        Traceback (most recent call last):
        ...
        ModelError: rotations: consecutive rotations must be about different axes (a chart of SO(3)), got axes 3, 3, 2; e.g. [(3, a), (1, b), (3, c)] or [(3, a), (1, b), (2, c)]
        sage: euler_angles([(3, a), (1, b)])
        Traceback (most recent call last):
        ...
        ModelError: rotations: a chart of SO(3) needs three rotations, got 2
    """
    if not isinstance(rotations, (list, tuple)) or not all(
            isinstance(r, (list, tuple)) and len(r) == 2 for r in rotations):
        raise ModelError(f"expected three rotations [(axis, angle), ...], got {brief(rotations)}",
                         entry="rotations")
    rotations = list(rotations)
    if len(rotations) != 3:
        raise ModelError(f"a chart of SO(3) needs three rotations, got {len(rotations)}",
                         entry="rotations")
    axes = [int(a) for a, _ in rotations]
    if any(a not in (1, 2, 3) for a in axes) or axes[0] == axes[1] or axes[1] == axes[2]:
        raise ModelError("consecutive rotations must be about different axes (a chart of "
                         f"SO(3)), got axes {', '.join(map(str, axes))}; e.g. [(3, a), (1, b), "
                         "(3, c)] or [(3, a), (1, b), (2, c)]", entry="rotations")
    return EulerAngles(rotations)


def model_chart(system, coordinates=None):
    r"""
    The chart of the configuration space that a mechanical model's
    coordinates are: each body turned by three elementary rotations through
    three of the coordinates is a chart of `SO(3)` (:func:`euler_angles`);
    every other coordinate that turns a body is an angle (a point of a
    circle), the rest are real numbers.

    INPUT:

    - ``system`` -- a :class:`~sage_dynsym.mechanics.system.MechanicalSystem`
    - ``coordinates`` -- (optional) the coordinates of the chart, e.g. the
      positional coordinates of a Routh function (default: all the model's)

    OUTPUT: a :class:`~sage_dynsym.analysis.charts.ConfigurationChart`, to
    list stationary solutions as points of the configuration space
    (``stationary_motions(R, chart=model_chart(S, R.coordinates()))``)

    EXAMPLES: a heavy rigid body on a fixed point, in Euler angles, and the
    angle of a rotor on it::

        sage: from sage_dynsym import RigidBody, MechanicalSystem
        sage: from sage_dynsym.mechanics.charts import model_chart
        sage: a, b, c, r = var('a b c r')
        sage: body = RigidBody('body', rotations=[(3, a), (1, b), (3, c)])
        sage: rotor = RigidBody('rotor', parent=1, rotations=[(3, r)])
        sage: S = MechanicalSystem([body, rotor], [a, b, c, r])
        sage: C = model_chart(S); C.sheets(), C.singular_function()
        (2, -sin(b))
        sage: model_chart(S, [a, b, c])
        Chart (a, b, c) of a configuration space embedded by [...]
        sage: L = S.lagrangian()

    TESTS::

        sage: model_chart(L)
        Traceback (most recent call last):
        ...
        ModelError: system: expected a mechanical model, got ...
        sage: model_chart(S, [a, var('z')])
        Traceback (most recent call last):
        ...
        ModelError: coordinates: z is not a coordinate of the model; its coordinates are a, b, c, r
    """
    model_argument(system, ['coordinates', 'bodies'], 'system', "a mechanical model",
                   ModelError, hint="e.g. model_chart(MechanicalSystem([...], [...]))")
    model = system.coordinates()
    coordinates = model if coordinates is None else [SR(q) for q in coordinates]
    names = [str(q) for q in coordinates]
    for q in coordinates:
        if str(q) not in {str(u) for u in model}:
            raise ModelError(f"{q} is not a coordinate of the model; its coordinates are "
                             f"{', '.join(map(str, model))}", entry="coordinates")
    charts, used, angles = [], set(), set()
    for body in system.bodies():
        rotations = [(axis, SR(q)) for axis, q in body.rotations()]
        turned = [str(q) for _, q in rotations if SR(q).is_symbol()]
        angles.update(turned)
        axes = [axis for axis, _ in rotations]
        if len(rotations) == 3 and len(set(turned)) == 3 and set(turned) <= set(names) and \
                not used & set(turned) and axes[0] != axes[1] and axes[1] != axes[2]:
            charts.append(euler_angles(rotations))
            used.update(turned)
    rest = [q for q in coordinates if str(q) not in used]
    if rest:
        charts.append(default_chart(rest, [q for q in rest if str(q) in angles]))
    return product_chart(charts, coordinates)

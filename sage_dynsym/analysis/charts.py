r"""
Stationary solutions as points of the configuration space, not of a chart

Coordinates are a *chart* of the configuration space: Euler angles cover
the rotation group `SO(3)` twice, and at a singular point of the chart
(e.g. `\beta = \pm\pi/2` for the angles `z, x, y`) a whole curve of angle
triples describes one orientation. The stationary equations
`\partial W/\partial q = 0` of the chart then give

- each orientation twice (the two covers);
- at a singular point, a *family* of angle triples (the curve over one
  orientation) where the orientation is an equilibrium;
- at a singular point, solutions that are **not** equilibria: there
  `\partial W/\partial q = dW\cdot\partial R/\partial q` misses one
  direction of the rotation group.

A :class:`ConfigurationChart` knows the map to the configuration space (its
*embedding*, e.g. the entries of the rotation matrix) and the matrix
`E(q)` of the angular velocity, `\omega = E(q)\,\dot q`; its singular set
is `\det E = 0`. :func:`configuration_points` turns the solutions of a
chart (at numerical values of the parameters) into distinct points:
solutions with the same image are one point, a family whose image is one
point is that point, and a solution on the singular set is kept only if it
is an equilibrium in the regular formulation, which is decided exactly.

The test at a singular point `q^*` (where `\nabla W(q^*) = 0`): the torque
`\tau = E^{-T}\nabla W` is a smooth function on the configuration space,
so along the line `q^* + s v` (regular for `s \ne 0` when `\nabla\det
E\cdot v \ne 0`), by l'Hospital's rule

.. MATH::

    \tau(q^*) = \frac{\operatorname{adj}(E)^T\, H\, v}{\nabla(\det E)\cdot v},
    \qquad H = \frac{\partial^2 W}{\partial q^2}(q^*),

for every such `v`: the orientation is an equilibrium iff
`\operatorname{adj}(E(q^*))^T H(q^*) = 0`.

EXAMPLES: a function linear in the rotation matrix, `W = \operatorname{tr}(M^T R)`
with `M` generic, has four critical points on `SO(3)`. The angles `z, x, y`
give sixteen solutions: each of the four twice, and eight on the singular
set `\cos b = 0` that are not critical points::

    sage: from sage_dynsym.analysis.charts import configuration_points
    sage: from sage_dynsym.mechanics.charts import euler_angles
    sage: from sage_dynsym.analysis.stationary import stationary_solutions
    sage: a, b, c = var('a b c')
    sage: chart = euler_angles([(3, a), (1, b), (2, c)])
    sage: R = chart.rotation_matrix()
    sage: sols = stationary_solutions([R[0, 0] + 2*R[1, 1] + 3*R[2, 2] + R[2, 1]/3], [a, b, c])
    sage: points = configuration_points(sols, chart)
    sage: len(sols), len(points), sum(1 for s in sols if s.point()[b] in (pi/2, -pi/2))
    (16, 4, 8)
    sage: [len(p.solutions()) for p in points]
    [2, 2, 2, 2]
    sage: points[0].embedding()[:3]
    (-1, 0, 0)

REFERENCES:

- V. I. Arnold, *Mathematical Methods of Classical Mechanics*, Springer,
  1989, §30 (the configuration space of a rigid body).
"""
from sage.matrix.constructor import matrix
from sage.rings.qqbar import AA
from sage.rings.real_mpfi import RealIntervalField
from sage.structure.sage_object import SageObject
from sage.symbolic.ring import SR

from ..errors import AnalysisError
from ..arguments import expression_list, model_argument
from ..algebra.translation import expand_angles
from ..algebra.solving import normalize

__all__ = ['ConfigurationChart', 'ConfigurationPoint', 'algebraic_value', 'configuration_points',
           'default_chart', 'points_of_chart', 'product_chart', 'same_point']


class ConfigurationChart(SageObject):
    r"""
    A chart of the configuration space: coordinates, the map to a space
    where distinct configurations have distinct images (the *embedding*),
    and the matrix `E(q)` with `\omega = E(q)\dot q` whose determinant
    vanishes on the chart's singular set.

    INPUT:

    - ``coordinates`` -- the coordinates of the chart
    - ``embedding`` -- expressions in them: two coordinate tuples describe
      the same configuration iff these have the same values
    - ``velocity_matrix`` -- (optional) `E(q)`, square; default the identity
      (a regular chart)
    - ``sheets`` -- (default: 1) the number of coordinate tuples (in the
      solver's ranges, angles in `(-\pi, \pi]`) over each regular point:
      2 for Euler angles, which cover `SO(3)` twice

    EXAMPLES::

        sage: from sage_dynsym.analysis.charts import ConfigurationChart
        sage: phi = var('phi')
        sage: C = ConfigurationChart([phi], [cos(phi), sin(phi)]); C
        Chart (phi) of a configuration space embedded by [cos(phi), sin(phi)]
        sage: C.singular_function()
        1

    TESTS::

        sage: ConfigurationChart([phi], [phi], velocity_matrix=matrix([[1, 0]]))
        Traceback (most recent call last):
        ...
        AnalysisError: chart: the velocity matrix must be square of size 1 (one row per coordinate), got 1 x 2
    """

    def __init__(self, coordinates, embedding, velocity_matrix=None, sheets=1):
        self._coordinates = expression_list(coordinates, 'coordinates', AnalysisError,
                                            entry="ConfigurationChart", names=True)
        self._embedding = expression_list(embedding, 'embedding', AnalysisError,
                                          entry="ConfigurationChart")
        n = len(self._coordinates)
        E = matrix.identity(SR, n) if velocity_matrix is None else matrix(SR, velocity_matrix)
        if E.nrows() != n or E.ncols() != n:
            raise AnalysisError(f"the velocity matrix must be square of size {n} (one row per "
                                f"coordinate), got {E.nrows()} x {E.ncols()}", entry="chart")
        self._E = E
        self._sheets = int(sheets)

    def _repr_(self):
        return (f"Chart ({', '.join(map(str, self._coordinates))}) of a configuration space "
                f"embedded by {self._embedding}")

    def coordinates(self):
        r"""The coordinates of the chart.

        EXAMPLES::

            sage: from sage_dynsym.analysis.charts import ConfigurationChart
            sage: ConfigurationChart([var('x')], [var('x')]).coordinates()
            [x]
        """
        return list(self._coordinates)

    def embedding(self):
        r"""The expressions whose values identify a configuration.

        EXAMPLES::

            sage: from sage_dynsym.analysis.charts import ConfigurationChart
            sage: ConfigurationChart([var('x')], [var('x')]).embedding()
            [x]
        """
        return list(self._embedding)

    def sheets(self):
        r"""The number of coordinate tuples over each regular point.

        EXAMPLES::

            sage: from sage_dynsym.mechanics.charts import euler_angles
            sage: a, b, c = var('a b c')
            sage: euler_angles([(3, a), (1, b), (2, c)]).sheets()
            2
        """
        return self._sheets

    def velocity_matrix(self):
        r"""The matrix `E(q)` of `\omega = E(q)\dot q`.

        EXAMPLES::

            sage: from sage_dynsym.analysis.charts import ConfigurationChart
            sage: ConfigurationChart([var('x')], [var('x')]).velocity_matrix()
            [1]
        """
        return self._E

    def singular_function(self):
        r"""`\det E(q)`: the chart is singular where it vanishes.

        EXAMPLES::

            sage: from sage_dynsym.mechanics.charts import euler_angles
            sage: a, b, c = var('a b c')
            sage: euler_angles([(3, a), (1, b), (3, c)]).singular_function()
            -sin(b)
        """
        return self._E.det().simplify_trig()

    def equilibrium_obstruction(self, W):
        r"""
        The matrix `\operatorname{adj}(E)^T\,\partial^2 W/\partial q^2`: at a
        singular point of the chart where `\nabla W = 0`, the point is an
        equilibrium of `W` on the configuration space iff it vanishes there
        (see the module documentation).

        EXAMPLES::

            sage: from sage_dynsym.analysis.charts import ConfigurationChart
            sage: x = var('x')
            sage: ConfigurationChart([x], [x]).equilibrium_obstruction(x^3)
            [6*x]
        """
        q = self._coordinates
        H = matrix(SR, [[SR(W).diff(u).diff(v) for v in q] for u in q])
        return self._E.adjugate().transpose() * H


class ConfigurationPoint(SageObject):
    r"""
    One point of the configuration space where some stationary solutions of
    a chart lie: its embedding (exact real algebraic numbers) and the
    solutions of the chart over it, each with an evaluation map.

    Created by :func:`configuration_points`.

    EXAMPLES::

        sage: from sage_dynsym.analysis.charts import configuration_points
        sage: from sage_dynsym.analysis.stationary import stationary_solutions
        sage: x = var('x')
        sage: p = configuration_points(stationary_solutions([x^2 - x], [x]))[0]; p
        Configuration point (1/2) (1 solution of the chart, regular)
        sage: p.embedding(), p.value(x^2)
        ((1/2,), 1/4)
    """

    def __init__(self, embedding, solutions, evaluate, singular):
        self._embedding = embedding
        self._solutions = solutions
        self._evaluate = evaluate
        self._singular = singular

    def _repr_(self):
        n = len(self._solutions)
        return (f"Configuration point ({', '.join(map(str, self._embedding))}) ({n} solution"
                f"{'s' if n != 1 else ''} of the chart, "
                f"{'on its singular set' if self._singular else 'regular'})")

    def embedding(self):
        r"""The point's image in the embedding space, a tuple of real algebraic numbers.

        EXAMPLES: see :class:`ConfigurationPoint`.
        """
        return self._embedding

    def solutions(self):
        r"""The stationary solutions of the chart over this point.

        EXAMPLES::

            sage: from sage_dynsym.analysis.charts import configuration_points
            sage: from sage_dynsym.analysis.stationary import stationary_solutions
            sage: x = var('x')
            sage: configuration_points(stationary_solutions([x^2], [x]))[0].solutions()
            [Stationary solution {x: 0} (isolated)]
        """
        return list(self._solutions)

    def is_singular(self):
        r"""Whether the point lies on the singular set of the chart.

        EXAMPLES: see :func:`configuration_points`.
        """
        return self._singular

    def value(self, expr):
        r"""
        The exact value at the point (a real algebraic number or an exact
        symbolic constant) of an expression in the chart's coordinates and
        the parameters, evaluated on the first solution of the chart over it.

        EXAMPLES: see :class:`ConfigurationPoint`.
        """
        return self._evaluate(expr)


def algebraic_value(value, what):
    r"""
    ``value`` (an exact constant) as a real algebraic number; ``what`` names
    it in the error.

    EXAMPLES::

        sage: from sage_dynsym.analysis.charts import algebraic_value
        sage: algebraic_value(sqrt(2)/2, 'x')
        0.7071067811865475?
        sage: algebraic_value(var('k'), 'x')
        Traceback (most recent call last):
        ...
        AnalysisError: configuration_points: the value k of x is not a real algebraic number that Sage can compare exactly; give numerical values to every parameter (values=...)
    """
    try:
        return AA(value)
    except (TypeError, ValueError, NotImplementedError):
        try:
            return AA(SR(value).simplify_full())
        except (TypeError, ValueError, NotImplementedError):
            raise AnalysisError(f"the value {value} of {what} is not a real algebraic number "
                                "that Sage can compare exactly; give numerical values to every "
                                "parameter (values=...)", entry="configuration_points")


def _evaluators(solution, angles):
    r"""One evaluation map per point of ``solution``: for the real points of
    an implicit component, substitution of its cosines and sines; otherwise
    the solution's own (exact) evaluation."""
    inner = solution.solution()
    points = inner.real_points() if hasattr(inner, 'real_points') else None
    if points is None:
        def evaluate(expr):
            value = inner.evaluate(expr)
            if not _is_constant(value, inner.free_unknowns()) and hasattr(inner, 'reduce'):
                # on a family, the normal form modulo its ideal: cos^2 + sin^2 is 1 there
                reduced = inner.reduce(SR(expr))
                return value if reduced is None else reduced
            return value
        return [evaluate]

    def at(point):
        def evaluate(expr):
            e = expand_angles(SR(expr), angles).subs({SR(k): SR(v) for k, v in point.items()})
            return e.subs({SR(k): SR(v) for k, v in point.items()})
        return evaluate
    return [at(p) for p in points]


def _is_constant(value, unknowns):
    return not any(SR(value).has(u) for u in unknowns)


def configuration_points(solutions, chart=None, families=None):
    r"""
    The distinct points of the configuration space where the stationary
    solutions of a chart lie, at numerical values of the parameters.

    INPUT:

    - ``solutions`` -- a :class:`~sage_dynsym.analysis.stationary.StationarySolutions`
      whose equations have no free parameters
    - ``chart`` -- (optional) a :class:`ConfigurationChart` of the
      solutions' variables; default: every angle is a point of a circle
      (its cosine and sine), every other variable a real number
    - ``families`` -- (optional) a list that receives the solutions that
      are families of configurations (not one point each), which are not
      counted

    OUTPUT: a list of :class:`ConfigurationPoint`, sorted by embedding:
    solutions of the chart with the same image merged, a family whose image
    is a single point made that point, solutions on the chart's singular
    set kept only if they are equilibria (:meth:`ConfigurationChart.equilibrium_obstruction`),
    the real points of implicit zero-dimensional components listed

    EXAMPLES: see the module documentation. A potential of the third body
    axis `e_3` only: every orientation with `e_3` along a critical direction
    is critical, so the stationary set is made of curves of orientations;
    the chart gives them as families (over its regular part), which
    ``families`` receives. The points returned are then only the isolated
    solutions of the chart: here four orientations on those curves, where
    they cross the singular set (a census refuses such a parameter value)::

        sage: from sage_dynsym.analysis.charts import configuration_points
        sage: from sage_dynsym.mechanics.charts import euler_angles
        sage: from sage_dynsym.analysis.stationary import stationary_solutions
        sage: a, b, c = var('a b c')
        sage: chart = euler_angles([(3, a), (1, b), (2, c)])
        sage: R = chart.rotation_matrix()
        sage: families = []
        sage: points = configuration_points(stationary_solutions([R[0, 2] + 2*R[1, 2]^2],
        ....:                                                    [a, b, c]), chart, families)
        sage: len(families) > 0, [p.is_singular() for p in points]
        (True, [True, True, True, True])

    TESTS::

        sage: x, k = var('x k')
        sage: configuration_points(stationary_solutions([x^2 - k*x], [x]))
        Traceback (most recent call last):
        ...
        AnalysisError: configuration_points: the value 1/2*k of x is not a real algebraic number that Sage can compare exactly; give numerical values to every parameter (values=...)
    """
    model_argument(solutions, ['variables', 'stationary_problem', 'chart_solutions'],
                   'solutions', "the stationary solutions of a model",
                   AnalysisError, hint="e.g. configuration_points(stationary_motions(L), chart)")
    return points_of_chart(solutions.chart_solutions(), solutions.variables(),
                           solutions.stationary_problem().function, chart, families)


def default_chart(variables, angles):
    r"""
    The chart where every angle among ``variables`` is a point of a circle
    (its cosine and sine) and every other variable a real number.

    EXAMPLES::

        sage: from sage_dynsym.analysis.charts import default_chart
        sage: x, q = var('x q')
        sage: default_chart([x, q], [q]).embedding()
        [x, cos(q), sin(q)]
    """
    embedding = []
    for q in variables:
        embedding += [q.cos(), q.sin()] if any(str(q) == str(u) for u in angles) else [q]
    return ConfigurationChart(variables, embedding)


def product_chart(charts, coordinates):
    r"""
    The product of charts of the factors of a configuration space, as a
    chart of ``coordinates`` (the union of the factors' coordinates, in any
    order): the embeddings concatenated, `E` block-diagonal, the sheets
    multiplied.

    EXAMPLES: Euler angles of a body and the angle of a rotor on it::

        sage: from sage_dynsym.analysis.charts import product_chart, default_chart
        sage: from sage_dynsym.mechanics.charts import euler_angles
        sage: a, b, c, r = var('a b c r')
        sage: C = product_chart([euler_angles([(3, a), (1, b), (3, c)]),
        ....:                    default_chart([r], [r])], [r, a, b, c])
        sage: C.coordinates(), C.sheets(), C.singular_function()
        ([r, a, b, c], 2, -sin(b))

    TESTS::

        sage: product_chart([default_chart([r], [r])], [a, r])
        Traceback (most recent call last):
        ...
        AnalysisError: chart: the charts' coordinates [r] are not the coordinates [a, r], each once
    """
    coordinates = [SR(q) for q in coordinates]
    names = [str(q) for q in coordinates]
    own = [str(q) for chart in charts for q in chart.coordinates()]
    if sorted(own) != sorted(names) or len(set(names)) != len(names):
        raise AnalysisError(f"the charts' coordinates [{', '.join(own)}] are not the "
                            f"coordinates {coordinates}, each once", entry="chart")
    E = matrix.zero(SR, len(coordinates))
    embedding, sheets = [], 1
    for chart in charts:
        index = [names.index(str(q)) for q in chart.coordinates()]
        F = chart.velocity_matrix()
        for i, k in enumerate(index):
            for j, l in enumerate(index):
                E[k, l] = F[i, j]
        embedding += chart.embedding()
        sheets *= chart.sheets()
    return ConfigurationChart(coordinates, embedding, E, sheets)


def _angles(solutions):
    for s in solutions:
        translation = s.solution().translation()
        if translation is not None:
            return [u for u in translation.unknowns() if translation.is_angle(u)]
    return []


def points_of_chart(solutions, variables, function, chart=None, families=None, artifacts=None,
                    exact=True):
    r"""
    The distinct points of the configuration space where the stationary
    solutions ``solutions`` (a list) of ``function`` in the chart lie:
    the core of :func:`configuration_points`.

    INPUT:

    - ``solutions`` -- a list of
      :class:`~sage_dynsym.analysis.stationary.StationarySolution`
    - ``variables`` -- their variables; ``function`` -- the function whose
      critical points they are (`K` or the amended potential `W`)
    - ``chart``, ``families`` -- as in :func:`configuration_points`
    - ``artifacts`` -- (optional) a list that receives the solutions on the
      chart's singular set that are not equilibria
    - ``exact`` -- (default: ``True``) compare the points as real algebraic
      numbers (every parameter must have a numerical value); ``False``:
      compare the symbolic images (a solution on the singular set is then
      an artifact when the obstruction does not vanish identically in the
      parameters)

    OUTPUT: a list of :class:`ConfigurationPoint`, sorted by embedding when
    ``exact``, in the order found otherwise

    EXAMPLES: with a symbolic parameter, the covers of Euler angles merged
    and the eight solutions on the singular set that are not critical
    points (for `k \ne 0`) left out::

        sage: from sage_dynsym.analysis.charts import points_of_chart
        sage: from sage_dynsym.mechanics.charts import euler_angles
        sage: from sage_dynsym.analysis.stationary import stationary_solutions
        sage: a, b, c, k = var('a b c k')
        sage: chart = euler_angles([(3, a), (1, b), (2, c)])
        sage: R = chart.rotation_matrix(); W = R[0, 0] + 2*R[1, 1] + 3*R[2, 2] + k*R[2, 1]
        sage: sols = stationary_solutions([W], [a, b, c])
        sage: artifacts = []
        sage: points = points_of_chart(list(sols), [a, b, c], W, chart, artifacts=artifacts,
        ....:                          exact=False)
        sage: len(sols), len(points), len(artifacts)
        (16, 4, 8)
    """
    solutions = list(solutions)
    angles = _angles(solutions)
    if chart is None:
        chart = default_chart(variables, angles)
    singular = chart.singular_function()
    obstruction = []
    regular, on_singular = [], {}
    for s in solutions:
        free = s.solution().free_unknowns()
        for evaluate in _evaluators(s, angles):
            image = [evaluate(e) for e in chart.embedding()]
            if not all(_is_constant(v, free) for v in image):
                if families is not None:
                    families.append(s)
                break
            key = tuple(algebraic_value(v, f"{e}") for v, e in zip(image, chart.embedding())) \
                if exact else tuple(SR(v) for v in image)
            if not SR(evaluate(singular)).is_zero():
                regular.append((key, evaluate, s))
                continue
            if not obstruction:
                obstruction = chart.equilibrium_obstruction(function).list()
            if all(normalize(evaluate(m)).is_zero() for m in obstruction):
                # few, with simple values: compared exactly
                on_singular.setdefault(key, (evaluate, []))[1].append(s)
            elif artifacts is not None and s not in artifacts:
                artifacts.append(s)
    groups = _sheets(regular, chart.sheets()) if exact else _symbolic_groups(regular)
    points = [ConfigurationPoint(group[0][0], [s for _, _, s in group], group[0][1], False)
              for group in groups]
    points += [ConfigurationPoint(key, sols, evaluate, True)
               for key, (evaluate, sols) in on_singular.items()]
    if not exact:
        return points
    return sorted(points, key=lambda p: [float(x) for x in p.embedding()])


def _symbolic_groups(found):
    r"""The items ``(embedding, evaluate, solution)`` grouped by equal
    symbolic embeddings (their differences normalize to zero)."""
    groups = []
    for item in found:
        for group in groups:
            if all(normalize(x - y).is_zero() for x, y in zip(item[0], group[0][0])):
                group.append(item)
                break
        else:
            groups.append([item])
    return groups


def same_point(first, second, precisions=(53, 128, 256, 512, 1024)):
    r"""
    The index in the list of :class:`ConfigurationPoint` ``second`` of the
    point equal to ``first`` (``None`` if there is none): by interval
    arithmetic on real algebraic embeddings (the one partner whose intervals
    overlap, at increasing precision; exact comparison as the fallback), by
    symbolic simplification otherwise.

    EXAMPLES::

        sage: from sage_dynsym.analysis.charts import configuration_points, same_point
        sage: from sage_dynsym.analysis.stationary import stationary_solutions
        sage: x, y = var('x y')
        sage: P = configuration_points(stationary_solutions([cos(2*x)], [x]))
        sage: Q = configuration_points(stationary_solutions([cos(2*y)], [y]))
        sage: [same_point(p, Q) for p in P]
        [0, 1, 2, 3]
    """
    key = first.embedding()
    if not all(getattr(v, "parent", lambda: None)() is AA for v in key):
        for j, other in enumerate(second):
            if all(normalize(SR(x) - SR(y)).is_zero() for x, y in zip(key, other.embedding())):
                return j
        return None
    for prec in precisions:
        field = RealIntervalField(prec)
        box = [x.interval(field) for x in key]
        partners = [j for j, other in enumerate(second)
                    if all(a.overlaps(AA(b).interval(field))
                           for a, b in zip(box, other.embedding()))]
        if not partners:
            return None
        if len(partners) == 1:
            # one candidate left: equal only if exactly so
            j = partners[0]
            return j if all(AA(x) == AA(y) for x, y in zip(key, second[j].embedding())) else None
    return next((j for j, other in enumerate(second)
                 if all(AA(x) == AA(y) for x, y in zip(key, other.embedding()))), None)


def _sheets(found, sheets, precisions=(53, 128, 256, 512, 1024)):
    r"""
    The solutions ``found`` (``(embedding, evaluate, solution)``) at regular
    points of a chart grouped by their point: a regular point has exactly
    ``sheets`` solutions over it, so a grouping where every group has
    ``sheets`` members whose embeddings overlap (interval arithmetic) and
    the embeddings of different groups are disjoint is the exact one,
    without comparing algebraic numbers for equality (which can need their
    minimal polynomials); exact comparison is the fallback.
    """
    for prec in precisions:
        field = RealIntervalField(prec)
        boxes = [[x.interval(field) for x in key] for key, _, _ in found]
        groups, seen = [], set()
        for i, box in enumerate(boxes):
            if i in seen:
                continue
            group = [j for j in range(len(boxes)) if j not in seen and
                     all(a.overlaps(b) for a, b in zip(box, boxes[j]))]
            seen.update(group)
            groups.append(group)
        if all(len(g) == sheets for g in groups) and all(
                all(a.overlaps(b) for a, b in zip(boxes[i], boxes[j]))
                for g in groups for i in g for j in g):
            return [[found[i] for i in g] for g in groups]
    exact = {}
    for item in found:
        exact.setdefault(item[0], []).append(item)
    return list(exact.values())

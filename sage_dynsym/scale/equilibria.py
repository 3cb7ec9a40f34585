r"""
The point of linearization of a model's map: what is wrong with it, and a
point that works

A stability map of a model (:func:`~sage_dynsym.scale.maps.stability_map`,
the ``map`` command line) linearizes it around a point, by default every
coordinate (or state variable) 0. When that point is not an equilibrium, or
is a singularity of the coordinates (a chart that degenerates there, as
spherical angles do at the pole), :func:`point_diagnosis` says which
coordinates are at fault and looks for a point that works: the exact
multiples `k\pi/4` of an angle (`0, \pm\pi/4, \pm\pi/2, \pm 3\pi/4, \pi`)
and, first, the exact value a decimal stands for (``3.1416`` for `\pi`),
each kept only if the equations at rest vanish there exactly, the kinetic
matrix is regular there and the model then linearizes.

EXAMPLES:

The cart pendulum of the examples, at a decimal near its inverted
position (``3.1416``, read exactly as the command line reads it)::

    sage: from sage_dynsym import load
    sage: from sage_dynsym.description import example_path
    sage: from sage_dynsym.scale.equilibria import point_diagnosis
    sage: cart = load(example_path('cart_pendulum_spring_damper.yaml'))
    sage: print(point_diagnosis(cart, {'theta': 31416/10000}))
    at: the point {y: 0, theta: 3.1416} is not an equilibrium: the equation of theta does not vanish there (it gives g*l*m*sin(3927/1250)); did you mean theta = pi? The model is at an equilibrium at {y: 0, theta: pi}: at={'theta': pi} (--at theta=pi on the command line)

The spherical pendulum in the angles of its description, whose chart
degenerates at both of its equilibria::

    sage: print(point_diagnosis(load(example_path('spherical_pendulum.yaml')), {}))
    at: the point {psi: 0, theta: 0} (the default: every coordinate 0) is a singularity of the coordinates at theta = 0 (the kinetic matrix is singular there); no equilibrium at rest where the chart is regular was found with theta among 0, pi, pi/2, -pi/2, pi/4, -pi/4, 3*pi/4, -3*pi/4: give one with at= (--at theta=VALUE on the command line; exact constants such as pi/2 are read exactly), or describe the model in coordinates that are regular at its equilibria
"""
from fractions import Fraction
import itertools
import math

from sage.matrix.constructor import matrix
from sage.symbolic.constants import pi
from sage.symbolic.ring import SR

from ..algebra.determinants import fraction_free_det
from ..algebra.solving import vanishes
from ..analysis.linear import equations_of_motion, linearize
from ..analysis.motion import SecondOrderEquations
from ..dynamics.model import linearization_point
from ..errors import AnalysisError, DynSymError
from ..analysis import census
from .cluster import CLUSTER_THRESHOLD, DEFAULT_TIMEOUT, run_in_processes
from .points import number_text

__all__ = ['ANGLES', 'MAX_SEARCHED', 'MAX_COORDINATES', 'NEAR', 'point_diagnosis',
           'equilibrium_census']

#: The values `k\pi/n` tried for an angle, as ``(k, n)`` (after the exact
#: value a decimal stands for, a multiple of `\pi/12`).
ANGLES = [(0, 1), (1, 1), (1, 2), (-1, 2), (1, 4), (-1, 4), (3, 4), (-3, 4)]

#: Most coordinates at fault for which a point is looked for (the
#: candidates are all the combinations of their values).
MAX_SEARCHED = 2

#: Most coordinates for which the kinetic matrix is examined alone.
MAX_COORDINATES = 12

#: How close (relative) a decimal must be to a multiple of `\pi/12` to be
#: taken for it in the question "did you mean ...?" (``3.14`` for `\pi`).
NEAR = 1e-3


def point_diagnosis(model, at):
    r"""
    Why ``model`` cannot be linearized around ``at`` (a dict over its
    coordinates; the others 0), as an
    :class:`~sage_dynsym.errors.AnalysisError` naming the coordinates at
    fault and suggesting a point that works (or saying that none was
    found); ``None`` when the point is a regular equilibrium, the failure
    is of another kind, or the model has no coordinates (a circuit, a
    Lie--Poisson system: the error of
    :func:`~sage_dynsym.analysis.linear.linearize` names the equation).

    INPUT:

    - ``model`` -- a model (:class:`~sage_dynsym.dynamics.model.Model`)
    - ``at`` -- a dict ``{coordinate: value}`` (symbols or names)

    OUTPUT: an :class:`~sage_dynsym.errors.AnalysisError` or ``None``

    EXAMPLES: see the module documentation. A regular equilibrium::

        sage: from sage_dynsym import load
        sage: from sage_dynsym.description import example_path
        sage: from sage_dynsym.scale.equilibria import point_diagnosis
        sage: cart = load(example_path('cart_pendulum_spring_damper.yaml'))
        sage: point_diagnosis(cart, {'theta': pi}) is None
        True

    TESTS:

    The cart pendulum off its equilibria (`\theta = 1`): none of the tried
    angles is near 1, the first one that works is suggested::

        sage: print(point_diagnosis(cart, {'theta': 1}))
        at: the point {y: 0, theta: 1} is not an equilibrium: the equation of theta does not vanish there (it gives g*l*m*sin(1)); the model is at an equilibrium at {y: 0, theta: 0}: at={'theta': 0} (--at theta=0 on the command line)
    """
    try:
        record = equations_of_motion(model)
        if not isinstance(record, SecondOrderEquations):
            return None
        variables = list(record.coordinates())
        rest = {v: 0 for v in list(record.velocities()) + list(record.accelerations())}
        equations = [SR(e).subs(rest) for e in record.equations()]
        kinetic = matrix(SR, [[SR(e).diff(a) for a in record.accelerations()]
                              for e in record.equations()])
        point = linearization_point(at, variables, "coordinate")
    except (DynSymError, TypeError, ValueError, ArithmeticError, RuntimeError):
        return None
    given = {SR.var(k) if isinstance(k, str) else SR(k) for k in (at or {})}
    return _Problem(model, variables, equations, kinetic, point).diagnosis(given)


class _Problem:
    r"""The equations at rest of a model around a point, and the search for
    a regular equilibrium near it."""

    def __init__(self, model, variables, equations, kinetic, point):
        self.model, self.variables, self.equations = model, variables, equations
        self.kinetic, self.point = kinetic, point

    def residual(self, i, point):
        r"""The ``i``-th equation at rest at ``point``, or ``None`` where it
        is not defined there."""
        try:
            return SR(self.equations[i]).subs(point)
        except (ValueError, ZeroDivisionError, RuntimeError, ArithmeticError):
            return None

    def vanishes(self, i, point):
        value = self.residual(i, point)
        return value is not None and vanishes(value, maxima=False)

    def regular(self, point):
        r"""Whether the kinetic matrix is regular at ``point``."""
        if self.kinetic is None:
            return True
        try:
            return not vanishes(fraction_free_det(self.kinetic.subs(point)), maxima=False)
        except (ValueError, ZeroDivisionError, RuntimeError, ArithmeticError):
            return False

    def singular_coordinates(self):
        r"""The coordinates whose value alone makes the kinetic matrix
        singular (the chart degenerates there)."""
        if self.kinetic is None or self.regular(self.point) or \
                len(self.variables) > MAX_COORDINATES:
            return []
        return [v for v in self.variables if not self.regular({v: self.point[v]})]

    def diagnosis(self, given):
        r"""The error for the point, ``None`` if it is a regular equilibrium
        (``given``: the coordinates the caller gave)."""
        wrong = [v for i, v in enumerate(self.variables) if not self.vanishes(i, self.point)]
        singular = [] if wrong else self.singular_coordinates()
        faulty = wrong or singular
        if not faulty:
            return None
        shown = _shown(self.point)
        if not (set(faulty) & given):
            shown += " (the default: every coordinate 0)"
        if wrong:
            message = (f"the point {shown} is not an equilibrium: the equation"
                       f"{'s' if len(wrong) > 1 else ''} of {_names(wrong)} "
                       f"{'do' if len(wrong) > 1 else 'does'} not vanish there")
            value = self.residual(self.variables.index(wrong[0]), self.point)
            if len(wrong) == 1 and value is not None and len(str(value)) <= 40:
                message += f" (it gives {value})"
        else:
            message = (f"the point {shown} is a singularity of the coordinates at "
                       + ", ".join(f"{v} = {number_text(self.point[v])}" for v in singular)
                       + " (the kinetic matrix is singular there)")
        return AnalysisError(message + "; " + self.suggestion(faulty, bool(singular)),
                             entry="at")

    def suggestion(self, faulty, singular):
        r"""The point suggested for the coordinates ``faulty`` (or the values
        tried, or how to give one)."""
        give = (f"give one with at= ({' '.join(f'--at {v}=VALUE' for v in faulty)} on the "
                "command line; exact constants such as pi/2 are read exactly)"
                + (", or describe the model in coordinates that are regular at its "
                   "equilibria" if singular else ""))
        if len(faulty) > MAX_SEARCHED:
            return give
        candidates = [self.candidates(v) for v in faulty]
        for values in itertools.product(*candidates):
            trial = dict(self.point)
            trial.update({v: value for v, (value, _, _) in zip(faulty, values)})
            if self.works(trial):
                return self.found(faulty, values, trial)
        tried = "; ".join(f"{v} among " + ", ".join([number_text(self.point[v])]
                                                    + [text for _, text, _ in c])
                          for v, c in zip(faulty, candidates))
        return f"no equilibrium at rest where the chart is regular was found with {tried}: {give}"

    def found(self, faulty, values, trial):
        r"""The suggestion of ``trial``, a regular equilibrium (``values``:
        the candidates of the coordinates ``faulty``)."""
        near = [f"{v} = {text}" for v, (_, text, is_near) in zip(faulty, values) if is_near]
        head = f"did you mean {', '.join(near)}? The" if near else "the"
        api = "{" + ", ".join(f"'{v}': {text}" for v, (_, text, _) in zip(faulty, values)) + "}"
        line = " ".join(f"--at {v}={text}" for v, (_, text, _) in zip(faulty, values))
        return (f"{head} model is at an equilibrium at {_shown(trial)}: at={api} ({line} on "
                "the command line)")

    def works(self, trial):
        r"""Whether ``trial`` is a regular equilibrium: the equations at rest
        vanish, the kinetic matrix is regular, and the model linearizes."""
        if not all(self.vanishes(i, trial) for i in range(len(self.variables))):
            return False
        if not self.regular(trial):
            return False
        try:
            linearize(self.model, trial, sources=False)
        except (DynSymError, TypeError, ValueError, ArithmeticError, RuntimeError):
            return False
        return True

    def candidates(self, v):
        r"""``(value, text, near)`` tried for ``v``: its exact value if its
        value is a decimal near a multiple of `\pi/12`, then the multiples
        of `\pi/4` for an angle (a coordinate inside a function of the
        equations), else 0."""
        current = SR(self.point[v])
        found, seen = [], {current}
        near = _near_multiple_of_pi(current)
        if near is not None:
            found.append((SR(near[0]) * pi / near[1], _pi_text(*near), True))
        angle = any(not SR(e).is_polynomial(v) for e in self.equations if v in SR(e).variables())
        for k, n in (ANGLES if angle else [(0, 1)]):
            found.append((SR(k) * pi / n, _pi_text(k, n), False))
        unique = []
        for value, text, is_near in found:
            if value not in seen:
                seen.add(value)
                unique.append((value, text, is_near))
        return unique


def _near_multiple_of_pi(value):
    r"""``(k, n)`` with `k\pi/n` (``n`` at most 12) within :data:`NEAR` of
    ``value``, a decimal (not an exact multiple of `\pi`); else ``None``."""
    if not value.is_numeric():
        return None
    try:
        x = float(value)
    except (TypeError, ValueError):
        return None
    if x == 0 or not math.isfinite(x):
        return None
    ratio = Fraction(x / math.pi).limit_denominator(12)
    if abs(x - float(ratio) * math.pi) > NEAR * abs(x):
        return None
    return ratio.numerator, ratio.denominator


def _pi_text(k, n):
    r"""`k\pi/n` as text: ``0``, ``pi``, ``-pi/2``, ``3*pi/4``."""
    if k == 0:
        return "0"
    head = {1: "pi", -1: "-pi"}.get(k, f"{k}*pi")
    return head if n == 1 else f"{head}/{n}"


def _shown(point):
    return "{" + ", ".join(f"{k}: {number_text(v)}" for k, v in point.items()) + "}"


def _names(variables):
    names = [str(v) for v in variables]
    return names[0] if len(names) == 1 else ", ".join(names[:-1]) + " and " + names[-1]


def equilibrium_census(system, parameters, positive=(), values=None, chart=None, regular=None,
                       client=None, workers=None, timeout=DEFAULT_TIMEOUT,
                       threshold=CLUSTER_THRESHOLD, levels=None):
    r"""
    The census of the equilibria of :func:`sage_dynsym.analysis.census.equilibrium_census`,
    its sample points solved on Dask when the work is large.

    INPUT:

    - ``system``, ``parameters``, ``positive``, ``values``, ``chart``,
      ``regular``, ``levels`` -- as for
      :func:`sage_dynsym.analysis.census.equilibrium_census` (``levels``:
      of the Casimirs of a Lie--Poisson system)
    - ``client``, ``workers``, ``timeout``, ``threshold`` -- where the
      sample points are solved, as for
      :func:`~sage_dynsym.scale.cluster.run_in_processes`: by default in
      this process, or in Dask's process pool when the first sample says
      the others take more than ``threshold`` seconds; ``'local'`` for
      that pool; a Dask ``Client`` (or a scheduler address) for its
      workers, each sample solved in the main thread of a child process of
      a worker (a worker runs its tasks in threads, where Sage's PARI
      cannot run), the children kept across samples

    OUTPUT: a :class:`~sage_dynsym.analysis.census.Census`, the same
    wherever the samples were solved

    EXAMPLES: a bead on a hoop turning at the rate `w` (`g = R = 1`)::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.scale import equilibrium_census
        sage: th, dth, w = var('theta dtheta w')
        sage: L = Lagrangian(dth^2/2 + w^2*sin(th)^2/2 + cos(th), [th])
        sage: equilibrium_census(L, [w], positive=[w])
        Census of the equilibria over w > 0: bifurcation set [w - 1]
          0 < w < 1 (sample w = 1/2): 2 equilibria, 1 stable
          1 < w (sample w = 2): 4 equilibria, 2 stable
        sage: equilibrium_census(L, [w], positive=[w], client='local', workers=2)  # long time
        Census of the equilibria over w > 0: bifurcation set [w - 1]
          0 < w < 1 (sample w = 1/2): 2 equilibria, 1 stable
          1 < w (sample w = 2): 4 equilibria, 2 stable

    On a ``dask.distributed`` cluster of one worker of two threads::

        sage: from distributed import Client, LocalCluster
        sage: with LocalCluster(n_workers=1, threads_per_worker=2, processes=True,  # long time
        ....:                   dashboard_address=None) as cluster, Client(cluster) as c:
        ....:     equilibrium_census(L, [w], positive=[w], client=c)
        Census of the equilibria over w > 0: bifurcation set [w - 1]
          0 < w < 1 (sample w = 1/2): 2 equilibria, 1 stable
          1 < w (sample w = 2): 4 equilibria, 2 stable

    A Lie--Poisson system on the levels of its Casimirs (the free rigid
    body on the spheres `|M|^2 = c`)::

        sage: from sage_dynsym import LiePoissonSystem
        sage: M1, M2, M3, c = var('M1 M2 M3 c')
        sage: S = LiePoissonSystem('so3', M1^2/2 + M2^2/4 + M3^2/6)
        sage: equilibrium_census(S, [c], levels=[c], positive=[c], client=False)
        Census of the relative equilibria on the levels M1^2 + M2^2 + M3^2 = c over c > 0: bifurcation set []
          0 < c (sample c = 1): 6 relative equilibria, 4 stable

    TESTS::

        sage: equilibrium_census(L, [w], client=42)
        Traceback (most recent call last):
        ...
        AnalysisError: scale: client must be None (chosen by the cost), 'local' (a local cluster), False (no Dask), a Dask Client or a scheduler address, got 42

    REFERENCES:

    - G. E. Collins, *Quantifier elimination for real closed fields by
      cylindrical algebraic decomposition*, LNCS 33 (1975) 134--183.
    """
    def executor(function, arguments):
        return run_in_processes(function, arguments, client=client, workers=workers,
                                timeout=timeout, threshold=threshold)

    return census.equilibrium_census(system, parameters, positive=positive, values=values,
                                     chart=chart, regular=regular, executor=executor,
                                     levels=levels)

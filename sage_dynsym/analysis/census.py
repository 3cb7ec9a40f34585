r"""
A census of equilibria over the parameter space

For which values of the parameters are there how many equilibria, and how
many of them are stable? :func:`equilibrium_census` answers it exactly for
the stationary motions of a Lagrangian or Routh function (and for the
relative equilibria of a Lie--Poisson system on its symplectic leaves, see
below) whose stationary equations depend on one or two parameters:

1. the *bifurcation set*: the polynomials in the parameters whose zero sets
   bound the regions where the number of real equilibria is constant. With
   `W` the amended potential and `F = \nabla W` the stationary equations
   (in the cosines and sines of the angles, `c_q^2 + s_q^2 = 1`), the
   number of real solutions can change only where a solution is degenerate:
   the discriminant variety is the projection of `\{F = 0,\ \det
   \partial^2 W/\partial q^2 = 0\}` on the parameters, computed by
   elimination (Singular). Routh's sufficient condition of stability (a
   definite Hessian of `W`) changes only where that determinant vanishes
   too, so the same set bounds the stable count;
2. the *cells*: for one parameter, the open intervals between the real
   roots (exact, real algebraic numbers) inside the declared signs; for
   two, the open cells of a cylindrical decomposition (the sections of
   each bifurcation curve over the intervals between the critical values of
   its projection), each with a rational sample point;
3. at each sample point the equilibria are solved exactly, made points of
   the configuration space (:func:`~sage_dynsym.analysis.charts.configuration_points`:
   covers of a chart merged, solutions on its singular set kept only if
   they are equilibria), and the stability of each is decided exactly:
   ``'stable'`` where `W` has a nondegenerate minimum (Routh's theorem),
   ``'unstable'`` where the characteristic polynomial has a root with a
   positive real part, ``'stable in first approximation'`` where all its
   roots are simple and on the imaginary axis, ``'undecided'`` otherwise
   (or at a singular point of the chart when no regular chart is given).

The values where only a chart artifact degenerates (solutions on the
chart's singular set that are not equilibria) are in the bifurcation set
too; the counts on both sides of them are equal.

For a Lie--Poisson system the census is over the relative equilibria on
the levels of its Casimirs, the levels given by ``levels=`` (numbers or
expressions in the parameters): the critical points of `H` on the leaf,
by the same steps with `W = H - \lambda\cdot(C - c)` in the variables and
the multipliers, the stability on the leaf by the energy--Casimir method
and the linearization restricted to the leaf, and the positive-dimensional
families of relative equilibria reported by the cells
(:meth:`CensusCell.families`), not counted:
:mod:`~sage_dynsym.analysis.leaf_census`, the census that the class of the
Lie--Poisson systems registers (:func:`register_census`).

The stable count in first approximation changes also where an equilibrium
stays nondegenerate but its linearization changes (gyroscopic
stabilization: a pair of roots leaves the imaginary axis). Those boundaries
are the relations of the stability regions of the equilibria solved with
the parameters symbolic (:func:`first_approximation_polynomials`); they are
in ``bifurcation_set(first_approximation=True)``, and
``cells(first_approximation=True)`` are the cells adapted to it.

EXAMPLES: a bead on a hoop turning at the rate `w` (`g = R = 1`): two
equilibria below `w^2 = 1`, four above, the bottom stable below and the two
tilted ones above (Goldstein, *Classical Mechanics*, §2.6)::

    sage: from sage_dynsym import Lagrangian
    sage: from sage_dynsym.analysis.census import equilibrium_census
    sage: th, dth, w = var('theta dtheta w')
    sage: L = Lagrangian(dth^2/2 + w^2*sin(th)^2/2 + cos(th), [th])
    sage: census = equilibrium_census(L, [w], positive=[w]); census
    Census of the equilibria over w > 0: bifurcation set [w - 1]
      0 < w < 1 (sample w = 1/2): 2 equilibria, 1 stable
      1 < w (sample w = 2): 4 equilibria, 2 stable
    sage: census.count_at({w: 3})
    (4, 2)
    sage: [c.stable_count(first_approximation=True) for c in census.cells()]
    [1, 2]

The turning saddle, the example of the first approximation that the
functions and methods below refer to: a particle in the saddle potential
`(x^2 - 2y^2)/2` turning at the rate `w`, seen in the turning frame. Its
one equilibrium degenerates only at `w = 1` (the discriminant of its
amended potential has no other positive root); it is stable in first
approximation for `1 < w^2 < 9/8` (gyroscopic stabilization), a boundary
that ``first_approximation=True`` adds::

    sage: from sage_dynsym.analysis.census import (discriminant_polynomials,
    ....:                                          first_approximation_polynomials)
    sage: x, y, dx, dy = var('x y dx dy')
    sage: turning = Lagrangian((dx^2 + dy^2)/2 + w*(x*dy - y*dx) + (w^2 - 1)*x^2/2
    ....:                      + (w^2 + 2)*y^2/2, [x, y])
    sage: discriminant_polynomials(-(w^2 - 1)*x^2/2 - (w^2 + 2)*y^2/2, [x, y], [w])
    [w - 1, w + 1, w^2 + 2]
    sage: first_approximation_polynomials(turning, [w], positive=[w])
    [w - 1, 8*w^2 - 9]
    sage: saddle = equilibrium_census(turning, [w], positive=[w])
    sage: saddle.bifurcation_set(), saddle.bifurcation_set(first_approximation=True)
    ([w - 1], [w - 1, 8*w^2 - 9])
    sage: for cell in saddle.cells(first_approximation=True): print(cell)
    0 < w < 1 (sample w = 1/2): 1 equilibrium, 0 stable
    1 < w < 3/2*sqrt(1/2) (sample w = 18/17): 1 equilibrium, 0 stable, 1 more stable in first approximation
    3/2*sqrt(1/2) < w (sample w = 2): 1 equilibrium, 0 stable

Its plot with ``first_approximation=True`` colours the cells by
``stable_count(first_approximation=True)``: stable on the middle step; the
census passes its own consistency tests (see :class:`Census`)::

    sage: G = saddle.plot(first_approximation=True)
    sage: [p.options()['legend_label'] for p in G]
    ['1 equilibrium, 0 stable (with first approximation)',
     '1 equilibrium, 1 stable (with first approximation)',
     '1 equilibrium, 0 stable (with first approximation)']
    sage: TestSuite(saddle).run(skip='_test_pickling')

REFERENCES:

- D. Lazard, F. Rouillier, *Solving parametric polynomial systems*, J.
  Symbolic Comput. 42 (2007) 636--667 (discriminant varieties).
- G. E. Collins, *Quantifier elimination for real closed fields by
  cylindrical algebraic decomposition*, LNCS 33 (1975) 134--183.
- V. V. Sarychev, S. A. Gutnik, *Relative equilibria of a gyrostat
  satellite*, Cosmic Research 22 (1984) 257--260.
"""
import operator
import warnings

from sage.libs.singular.function_factory import ff
from sage.matrix.constructor import matrix
from sage.rings.rational_field import QQ
from sage.structure.sage_object import SageObject
from sage.symbolic.ring import SR

from ..errors import AnalysisError
from .charts import configuration_points, same_point
from .point_stability import point_verdict, is_gyroscopic
from ._census import (log, census_arguments, check_values, stationary_ideal,
                      add_zero_set_factors, verdict_counts, check_main_thread,
                      polynomials_inside, real_roots, cell_shapes)

__all__ = ['discriminant_polynomials', 'first_approximation_polynomials', 'equilibria_at',
           'CensusCell', 'Census', 'register_census', 'equilibrium_census']

#: the censuses of the objects of classes of higher layers, by class (see
#: :func:`register_census`)
_CENSUSES = {}


# -- the stationary problem -------------------------------------------------------

def _amended_potential(system):
    r"""The coordinates and `W = -R|_{\dot q = 0}` of a Lagrangian or Routh function."""
    from .linear import equations_of_motion
    from .motion import SecondOrderEquations
    data = equations_of_motion(system)
    if not isinstance(data, SecondOrderEquations) or data.function() is None:
        others = "".join(f" or a {cls.__name__}" for cls in _CENSUSES)
        raise AnalysisError(f"expected a Lagrangian or Routh function{others}, got "
                            f"{type(system).__name__}; for a mechanical model pass "
                            "model.lagrangian() (or its routh([...]))",
                            entry="equilibrium_census")
    q = list(data.coordinates())
    return q, -data.function().subs({v: 0 for v in data.velocities()})


def discriminant_polynomials(W, coordinates, parameters):
    r"""
    The discriminant of the stationary equations of `W` with respect to the
    coordinates: the generators of the elimination ideal of `\{\nabla W =
    0,\ \det \partial^2 W/\partial q^2 = 0\}` (in the cosines and sines of
    the angles) in the parameters, as irreducible factors.

    INPUT:

    - ``W`` -- an expression in the coordinates and the parameters only
    - ``coordinates``, ``parameters`` -- lists of symbols

    OUTPUT: a list of symbolic polynomials in the parameters (no constants)

    EXAMPLES: `W = x^3/3 - a x` has two critical points for `a > 0`, none
    for `a < 0`::

        sage: from sage_dynsym.analysis.census import discriminant_polynomials
        sage: x, a = var('x a')
        sage: discriminant_polynomials(x^3/3 - a*x, [x], [a])
        [a]

    TESTS::

        sage: y = var('y')
        sage: discriminant_polynomials((x - a)^2, [x, y], [a])
        Traceback (most recent call last):
        ...
        AnalysisError: equilibrium_census: the stationary equations are degenerate for all values of a (a family of equilibria); the census counts isolated equilibria only
    """
    q = [SR(x) for x in coordinates]
    H = matrix(SR, [[SR(W).diff(x).diff(y) for y in q] for x in q])
    return _projection(W, q, parameters, H.det(),
                       f"the stationary equations are degenerate for all values of "
                       f"{', '.join(map(str, parameters))} (a family of equilibria); "
                       "the census counts isolated equilibria only")


def _projection(W, q, parameters, extra, degenerate):
    r"""The irreducible factors of the projection on the parameters of
    `\{\nabla W = 0,\ extra = 0\}`; ``degenerate`` is the message when a
    component of the stationary set lies in `extra = 0` over every value."""
    T, ideal, state, (other,) = stationary_ideal([SR(W).diff(x) for x in q], q, parameters,
                                                  [extra])
    P = T.ring()
    # split first (Singular's factorizing Groebner basis): eliminating from
    # each part takes milliseconds where the whole ideal can take minutes
    parts = [P.ideal(list(part)) for part in ff.facstd(ideal)]
    log(f"eliminating {len(state)} variables from {len(parts)} parts")
    factors = []
    for part in parts:
        gens = [g for g in (part + P.ideal([other])).elimination_ideal(state).gens()
                if g != 0]
        if not gens:
            raise AnalysisError(degenerate, entry="equilibrium_census")
        add_zero_set_factors(gens, factors)
    return [T.symbolic(f) for f in factors]


def first_approximation_polynomials(system, parameters, positive=()):
    r"""
    The boundaries, in the parameters, of the regions where the stationary
    solutions of a Lagrangian or Routh function are stable (in the sense of
    Lyapunov or in first approximation): the polynomials of the relations
    of the regions of their stability verdicts (Routh's condition, the
    Routh--Hurwitz or spectrum conditions of the first approximation, with
    their :meth:`~sage_dynsym.analysis.verdict.StabilityVerdict.boundaries`),
    solved with the parameters symbolic. A relation in the coordinates of
    an implicit family is projected on the parameters (elimination with
    the stationary equations).

    INPUT:

    - ``system`` -- a Lagrangian or Routh function whose only symbols
      other than its coordinates and velocities are ``parameters``
    - ``parameters`` -- a list of symbols
    - ``positive`` -- symbols declared positive

    OUTPUT: a list of irreducible symbolic polynomials in the parameters

    EXAMPLES: the turning saddle of the module documentation, stable in
    first approximation for `1 < w^2 < 9/8` (``[w - 1, 8*w^2 - 9]``).
    The cusp: the minima of an implicit family end where `3x^2 = a`, on
    the discriminant. Where `3x^2 < a` (the maxima) the verdict is not
    decided with the parameters symbolic: a warning says so (the census
    decides them at its samples)::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.analysis.census import first_approximation_polynomials
        sage: x, dx, a, b = var('x dx a b')
        sage: L = Lagrangian(dx^2/2 - x^4/4 + a*x^2/2 - b*x, [x])
        sage: first_approximation_polynomials(L, [a, b])
        doctest:warning...
        UserWarning: first_approximation: with the parameters symbolic the stability of Stationary solution {x: x} (isolated, implicit: see equations()) where [[3*x^2 - a < 0]] is undecided: the boundaries of its first approximation inside that region are not known
        [4*a^3 - 27*b^2]

    TESTS::

        sage: first_approximation_polynomials(L, [a])
        Traceback (most recent call last):
        ...
        AnalysisError: first_approximation: the system depends on b besides the parameters a: substitute values first, e.g. system.subs({b: 1})
    """
    from .stationary import stationary_motions
    q, W = _amended_potential(system)
    names = {str(v) for v in parameters}
    coordinates = {str(v) for v in q}
    others = sorted(str(v) for v in SR(W).variables() if str(v) not in names | coordinates)
    if others:
        raise AnalysisError(f"the system depends on {', '.join(others)} besides the parameters "
                            f"{', '.join(map(str, parameters))}: substitute values first, "
                            f"e.g. system.subs({{{', '.join(f'{v}: 1' for v in others)}}})",
                            entry="first_approximation")
    found, undecided = [], []
    solutions = stationary_motions(system, positive=positive)
    log(f"the stability of {len(solutions)} stationary solutions, the parameters symbolic")
    for sol in solutions:
        verdict = sol.stability()
        undecided += [f"{sol} where {case.region() or 'the parameters are'}"
                      for case in verdict.cases() if case.verdict() == 'undecided']
        relations = [r for case in verdict.cases() for alt in (case.region() or [])
                     for r in alt]
        relations += [r for rs in verdict.boundaries().values() for r in rs]
        for r in relations:
            f = (SR(r.lhs()) - SR(r.rhs())).numerator()
            used = {str(v) for v in f.variables()}
            if not used <= names | coordinates:
                raise AnalysisError(f"the stability region of {sol} depends on "
                                    f"{', '.join(sorted(used - names - coordinates))}, not a "
                                    "parameter of the census", entry="first_approximation")
            # the angles enter through their cosines and sines (Translation)
            if any(not f.is_polynomial(v) for v in f.variables() if str(v) in names):
                f = _rationalized(f, r, sol)
            if used & coordinates:
                polys = _projection(W, q, parameters, f, f"the stability boundary {f} == 0 "
                                    f"contains a component of the equilibria of {sol}")
            else:
                polys = [g for g, _ in f.factor_list() if SR(g).variables()]
            found += [g for g in polys if all(not bool(g - h == 0) and not bool(g + h == 0)
                                              for h in found)]
    if undecided:
        # the sample points decide these exactly, but a change of their
        # verdict inside the region would not be on a boundary found here
        warnings.warn("first_approximation: with the parameters symbolic the stability of "
                      f"{'; '.join(undecided)} is undecided: the boundaries of its first "
                      "approximation inside that region are not known", stacklevel=2)
    return found


def _rationalized(f, relation, sol):
    r"""
    A polynomial vanishing where ``f`` does: each radical `b^{n/d}` of
    ``f`` (the coordinates of an equilibrium in radicals of the
    parameters) made a variable `t^n` with `t^d = b`, then eliminated by
    resultants (the norm of ``f``: its zero set contains that of ``f``).

    TESTS::

        sage: from sage_dynsym.analysis.census import _rationalized
        sage: p = var('p')
        sage: _rationalized(p*sqrt(1 - 4*p^2) - 1/3, None, None).factor()
        36*p^4 - 9*p^2 + 1
        sage: _rationalized(sin(p) - 1/2, 'sin(p) > 1/2', 'this solution')
        Traceback (most recent call last):
        ...
        AnalysisError: first_approximation: the stability boundary sin(p) > 1/2 of this solution is not algebraic in the parameters (sin(p) - 1/2): take an algebraic function of them as the parameter
    """
    # the radicals keyed by the printed expanded form of their base and
    # their index: comparing symbolic keys tried to prove each equality
    # (numerically, then by Maxima), half the time of this function on the
    # gyrostat; two spellings left apart would only give a norm of higher
    # degree, the expansion merges the usual ones (-(2p + 1)(2p - 1), 1 - 4p^2)
    radicals = {}

    def rebuild(e):
        op = e.operator()
        if op is None:
            return e
        args = [rebuild(a) for a in e.operands()]
        if op is operator.pow and args[1] in QQ and not QQ(args[1]).is_integer():
            n, d = QQ(args[1]).numerator(), QQ(args[1]).denominator()
            key = (str(SR(args[0]).expand()), d)
            if key not in radicals:
                radicals[key] = (args[0], d, SR.var(f"radical{len(radicals)}"))
            return radicals[key][2] ** n
        return op(*args)
    g = rebuild(SR(f)).numerator()
    for base, d, t in reversed(list(radicals.values())):
        num, den = SR(base).numerator_denominator()
        g = SR(g.resultant(t ** d * den - num, t)) if g.has(t) else g
    if any(not g.is_polynomial(v) for v in g.variables()):
        raise AnalysisError(f"the stability boundary {relation} of {sol} is not algebraic in the "
                            f"parameters ({f}): take an algebraic function of them as the "
                            "parameter", entry="first_approximation")
    return g


# -- the equilibria at one point of the parameter space ----------------------------------

def equilibria_at(system, values, chart=None, regular=None, positive=()):
    r"""
    The equilibria (stationary motions) of a Lagrangian or Routh function at
    numerical values of its parameters, as distinct points of the
    configuration space, each with its stability decided exactly.

    INPUT:

    - ``system`` -- a Lagrangian or Routh function
    - ``values`` -- a dict giving every parameter a rational (or exact) value
    - ``chart`` -- (optional) the :class:`~sage_dynsym.analysis.charts.ConfigurationChart`
      of the coordinates (e.g. :func:`~sage_dynsym.mechanics.charts.euler_angles`)
    - ``regular`` -- (optional) a pair ``(system2, chart2)``: the same model
      in a chart that is regular on the singular set of ``chart``; the
      points on that set are decided (existence and stability) there
    - ``positive`` -- symbols declared positive

    OUTPUT: a list of pairs ``(point, verdict)``, ``point`` a
    :class:`~sage_dynsym.analysis.charts.ConfigurationPoint`

    EXAMPLES: the pendulum has two equilibria, the lower one stable::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.analysis.census import equilibria_at
        sage: th, dth, g = var('theta dtheta g')
        sage: L = Lagrangian(dth^2/2 + g*cos(th), [th])
        sage: [(p.embedding(), v) for p, v in equilibria_at(L, {g: 1})]
        [((-1, 0), 'unstable'), ((1, 0), 'stable')]
    """
    from .stationary import stationary_motions
    found = _points(system, values, chart, stationary_motions, positive)
    if regular is not None and any(p.is_singular() for p, _ in found):
        other = _points(regular[0], values, regular[1], stationary_motions, positive)
        if len(other) != len(found):
            raise AnalysisError(f"the two charts give {len(found)} and {len(other)} equilibria: "
                                "they are not charts of the same model", entry="regular")
        points = [p for p, _ in other]
        found = [pv if not pv[0].is_singular() else other[_partner(pv[0], points)]
                 for pv in found]
        if any(p.is_singular() for p, _ in found):
            raise AnalysisError("a point is singular in both charts; give a second chart "
                                "regular on the singular set of the first (for Euler angles "
                                "z, x, y, singular where |R[2, 1]| = 1: z, y, x, singular where "
                                "|R[2, 0]| = 1)", entry="regular")
    return found


def _partner(point, points):
    r"""The index of ``point`` among ``points`` (the same model in another chart)."""
    j = same_point(point, points)
    if j is None:
        raise AnalysisError(f"the equilibrium {point.embedding()} of the first chart is not one "
                            "of the second: they are not charts of the same model",
                            entry="regular")
    return j


def _points(system, values, chart, stationary_motions, positive):
    sols = stationary_motions(system.subs(values), positive=positive)
    families = []
    points = configuration_points(sols, chart, families)
    if families:
        raise AnalysisError(f"at {values} the equilibria form families ({families[0]}); the "
                            "census counts isolated equilibria: this point of the parameter "
                            "space is on the bifurcation set", entry="equilibrium_census")
    problem = sols.stationary_problem()
    gyroscopic = is_gyroscopic(problem)
    return [(p, point_verdict(p, problem, gyroscopic)) for p in points]


def _count_task(system, values, chart, regular, positive):
    r"""One sample point's counts, and no families: the equilibria of a
    Lagrangian are isolated off the bifurcation set (a task: module level,
    picklable arguments)."""
    check_main_thread(values)
    log(f"solving at {values}")
    points = equilibria_at(system, values, chart, regular, positive)
    return verdict_counts([v for _, v in points]), None


class CensusCell(SageObject):
    r"""
    A cell of a census: an open region of the parameter space where the
    numbers of equilibria and of stable ones are constant, with its
    rational sample point and those numbers there. Created by
    :func:`equilibrium_census`.

    INPUT:

    - ``description`` -- the cell as inequalities (text)
    - ``sample`` -- a dict of rational values of the parameters
    - ``counts`` -- the tuple ``(count, stable, stable with those in first
      approximation, undecided)`` at the sample
    - ``bounds`` -- (optional) for one parameter, the bounds of the interval
    - ``families`` -- (default: ``None``) for a census of relative
      equilibria, the dimensions of the families of relative equilibria at
      the sample (``[]`` for none); ``None`` for a census of the equilibria
      of a Lagrangian or Routh function

    EXAMPLES::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.analysis.census import equilibrium_census
        sage: th, dth, w = var('theta dtheta w')
        sage: L = Lagrangian(dth^2/2 + w^2*sin(th)^2/2 + cos(th), [th])
        sage: cell = equilibrium_census(L, [w], positive=[w]).cells()[1]; cell
        1 < w (sample w = 2): 4 equilibria, 2 stable
        sage: cell.sample(), cell.count(), cell.stable_count(), cell.undecided_count()
        ({w: 2}, 4, 2, 0)
    """

    def __init__(self, description, sample, counts, bounds=None, families=None):
        self._description = description
        self._sample = sample
        self._counts = tuple(counts)
        self._bounds = bounds
        self._families = None if families is None else sorted(families)

    def _repr_(self):
        n, stable, linear, undecided = self._counts
        families = self.families()
        noun = "isolated" if families else f"equilibri{'um' if n == 1 else 'a'}"
        if self._families is not None and not families:
            noun = "relative " + noun
        text = f"{self._description} (sample {', '.join(f'{k} = {v}' for k, v in self._sample.items())}): {n} {noun}, {stable} stable"
        if linear > stable:
            text += f", {linear - stable} more stable in first approximation"
        if undecided:
            text += f", {undecided} undecided"
        if families:
            named = {1: ("a curve", "curves"), 2: ("a surface", "surfaces")}
            parts = []
            for d in sorted(set(families)):
                k = families.count(d)
                one, many = named.get(d, (f"a {d}-dimensional family", f"{d}-dimensional families"))
                parts.append(one if k == 1 else f"{k} {many}")
            text += f", and {' and '.join(parts)} of relative equilibria"
        return text

    def families(self):
        r"""
        The dimensions of the positive-dimensional families of relative
        equilibria at the sample (components, irreducible over `\QQ`, with
        real points), sorted; ``[]`` for a census of a Lagrangian or Routh
        function, whose equilibria are isolated off its bifurcation set.

        EXAMPLES::

            sage: from sage_dynsym.analysis.census import CensusCell
            sage: c = var('c')
            sage: cell = CensusCell("1 < c < 2", {c: 3/2}, (6, 0, 2, 0), families=[1]); cell
            1 < c < 2 (sample c = 3/2): 6 isolated, 0 stable, 2 more stable in first approximation, and a curve of relative equilibria
            sage: cell.families()
            [1]
            sage: CensusCell("0 < c", {c: 1}, (6, 4, 4, 0), families=[]), CensusCell("0 < c", {c: 1}, (1, 1, 1, 0))
            (0 < c (sample c = 1): 6 relative equilibria, 4 stable,
             0 < c (sample c = 1): 1 equilibrium, 1 stable)
        """
        return list(self._families or [])

    def description(self):
        r"""The cell as inequalities (text).

        EXAMPLES: see :class:`CensusCell`.
        """
        return self._description

    def bounds(self):
        r"""For one parameter: the pair of bounds of the interval (real
        algebraic numbers, ``None`` for an infinite end).

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: from sage_dynsym.analysis.census import equilibrium_census
            sage: th, dth, w = var('theta dtheta w')
            sage: L = Lagrangian(dth^2/2 + w^2*sin(th)^2/2 + cos(th), [th])
            sage: equilibrium_census(L, [w], positive=[w]).cells()[0].bounds()
            (0, 1)
        """
        return self._bounds

    def sample(self):
        r"""The sample point, a dict of rational values of the parameters.

        EXAMPLES: see :class:`CensusCell`.
        """
        return dict(self._sample)

    def count(self):
        r"""The number of distinct isolated equilibria (points of the
        configuration space, or of the symplectic leaf).

        EXAMPLES: see :class:`CensusCell`.
        """
        return self._counts[0]

    def stable_count(self, first_approximation=False):
        r"""
        The number of equilibria stable in the sense of Lyapunov (Routh's
        theorem); with ``first_approximation=True`` those stable in first
        approximation are added (that number is constant on the cells of
        ``Census.cells(first_approximation=True)``, not always on the others).

        EXAMPLES: see :class:`CensusCell`.
        """
        return self._counts[2] if first_approximation else self._counts[1]

    def undecided_count(self):
        r"""The number of equilibria whose stability was not decided.

        EXAMPLES: see :class:`CensusCell`.
        """
        return self._counts[3]


class Census(SageObject):
    r"""
    The census of the equilibria of a system over one or two parameters:
    its bifurcation set and its cells. Created by :func:`equilibrium_census`
    (and :func:`~sage_dynsym.analysis.leaf_census.leaf_census`), which give
    it what differs between systems; the cells, the solving of their
    samples and the first-approximation refinement are its own.

    INPUT:

    - ``parameters`` -- one or two symbols
    - ``polynomials`` -- the bifurcation set (for one parameter, the
      factors without a zero inside the declared signs are dropped)
    - ``task``, ``arguments_of`` -- ``task(*arguments_of(sample))`` solves a
      sample point (a dict over the parameters) and returns a pair
      ``(counts, families)`` as :class:`CensusCell` takes them; ``task`` is
      what ``executor`` runs (a function at module level)
    - ``boundaries`` -- a function returning the boundaries of the
      stability in first approximation (polynomials in the parameters),
      called the first time they are asked for
    - ``positive`` -- symbols declared positive
    - ``executor`` -- as for :func:`equilibrium_census`
    - ``what`` -- what is counted (text)

    EXAMPLES::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.analysis.census import equilibrium_census
        sage: th, dth, w = var('theta dtheta w')
        sage: L = Lagrangian(dth^2/2 + w^2*sin(th)^2/2 + cos(th), [th])
        sage: census = equilibrium_census(L, [w], positive=[w])
        sage: census.parameters(), census.bifurcation_set(), census.bifurcation_values()
        ([w], [w - 1], [1])

    TESTS:

    A census keeps the function that counts at a point (a closure over the
    system), which cannot be pickled, so the pickling test is skipped; the
    cells are consistent with the bifurcation set and with a recount at
    their samples (the turning saddle's census is tested in the module
    documentation)::

        sage: TestSuite(census).run(skip='_test_pickling')
        sage: x, dx, a, b = var('x dx a b')
        sage: cusp = equilibrium_census(Lagrangian(dx^2/2 - x^4/4 + a*x^2/2 - b*x, [x]), [a, b])
        sage: TestSuite(cusp).run(skip='_test_pickling')
        doctest:warning...
        UserWarning: first_approximation: ... where [[3*x^2 - a < 0]] is undecided: ...

    The first-approximation boundaries are added to the bifurcation set
    once (up to sign), those with a zero inside the declared signs only;
    a sample is solved once::

        sage: from sage_dynsym.analysis.census import Census
        sage: c = var('c')
        sage: solved = []
        sage: def task(sample):
        ....:     solved.append(sample)
        ....:     return (1, 0, 0, 0), None
        sage: census = Census([c], [c - 1], task, lambda s: (s,), lambda: [1 - c, c - 2, c + 5],
        ....:                 [c]); census
        Census of the equilibria over c > 0: bifurcation set [c - 1]
          0 < c < 1 (sample c = 1/2): 1 equilibrium, 0 stable
          1 < c (sample c = 2): 1 equilibrium, 0 stable
        sage: census.bifurcation_set(first_approximation=True)
        [c - 1, c - 2]
        sage: [cell.description() for cell in census.cells(first_approximation=True)], solved
        (['0 < c < 1', '1 < c < 2', '2 < c'], [{c: 1/2}, {c: 2}, {c: 3/2}, {c: 3}])
        sage: Census([c], [c - 1], task, None, None, [c])
        Traceback (most recent call last):
        ...
        AnalysisError: Census: task, arguments_of and boundaries are functions; a census of a system is built by equilibrium_census(system, parameters, ...)
    """

    def __init__(self, parameters, polynomials, task, arguments_of, boundaries, positive,
                 executor=None, what="the equilibria"):
        self._parameters, self._positive, _ = census_arguments(parameters, positive, None)
        if not all(callable(f) for f in (task, arguments_of, boundaries)):
            raise AnalysisError("task, arguments_of and boundaries are functions; a census of "
                                "a system is built by equilibrium_census(system, parameters, "
                                "...)", entry="Census")
        self._what = what
        self._signs = [self._is_positive(p) for p in self._parameters]
        self._task = task
        self._arguments_of = arguments_of
        self._executor = executor
        self._solved = {}
        self._boundaries = boundaries
        self._refined = None
        self._polynomials = polynomials_inside(list(polynomials), self._parameters, self._signs)
        log(f"bifurcation set {self._polynomials}")
        self._cells = self._cells_of(self._polynomials)

    def _solve(self, samples):
        r"""The pairs ``(counts, families)`` at the ``samples``, through the
        executor; a sample solved already is not solved again (the cells of
        an interval that a refinement leaves unchanged keep their samples)."""
        def key(sample):
            return tuple(sorted((str(k), v) for k, v in sample.items()))
        new = [s for s in samples if key(s) not in self._solved]
        log(f"solving at {len(new)} sample points")
        arguments = [self._arguments_of(s) for s in new]
        if self._executor is None or not arguments:
            found = [self._task(*a) for a in arguments]
        elif hasattr(self._executor, 'submit'):
            futures = [self._executor.submit(self._task, *a) for a in arguments]
            found = [f.result() for f in futures]
        else:
            found = list(self._executor(self._task, arguments))
        self._solved.update(zip(map(key, new), found))
        return [self._solved[key(s)] for s in samples]

    def _cells_of(self, polys):
        r"""The cells adapted to ``polys``, with the counts at their samples."""
        shapes = cell_shapes(polys, self._parameters, self._signs)
        found = self._solve([sample for _, sample, _ in shapes])
        return [CensusCell(text, sample, counts, bounds, families)
                for (text, sample, bounds), (counts, families) in zip(shapes, found)]

    def _first_approximation(self):
        r"""The bifurcation set with the boundaries of the stability in first
        approximation appended (those not in it already, up to sign, with a
        zero inside the declared signs for one parameter) and its cells,
        computed once (see :meth:`cells`)."""
        if self._refined is None:
            kept = []
            for f in self._boundaries():
                if all(not bool(SR(f) - g == 0) and not bool(SR(f) + g == 0)
                       for g in self._polynomials + kept):
                    kept.append(f)
            kept = polynomials_inside(kept, self._parameters, self._signs)
            log(f"first-approximation boundaries {kept}")
            polys = self._polynomials + kept
            self._refined = (polys, self._cells_of(polys))
        return self._refined

    def _repr_(self):
        where = " and ".join(f"{p} > 0" for p in self._parameters if self._is_positive(p))
        names = ", ".join(map(str, self._parameters))
        lines = [f"Census of {self._what} over {where or names}: bifurcation set "
                 f"{self._polynomials}"]
        lines += [f"  {c}" for c in self._cells]
        return "\n".join(lines)

    def _test_cells(self, **options):
        r"""Each cell's sample lies off the bifurcation set and inside the
        declared signs, its counts are ordered (stable, then stable in first
        approximation, at most all) and a recount at the sample gives them;
        over one parameter the intervals of the cells follow each other,
        one more than the bifurcation values.

        EXAMPLES: run by ``TestSuite`` (see the class).
        """
        tester = self._tester(**options)
        for cell in self._cells:
            sample = cell.sample()
            tester.assertTrue(all(not SR(f).subs(sample).is_zero() for f in self._polynomials))
            tester.assertTrue(all(v > 0 for k, v in sample.items() if self._is_positive(k)))
            tester.assertTrue(cell.stable_count() <= cell.stable_count(True) <= cell.count())
            tester.assertLessEqual(cell.undecided_count(), cell.count())
            tester.assertEqual(self.count_at(sample), (cell.count(), cell.stable_count()))
        if len(self._parameters) == 1 and all(c.bounds() is not None for c in self._cells):
            tester.assertEqual(len(self._cells), len(self.bifurcation_values()) + 1)
            for left, right in zip(self._cells, self._cells[1:]):
                tester.assertEqual(left.bounds()[1], right.bounds()[0])

    def _test_first_approximation(self, **options):
        r"""The cells adapted to the first-approximation boundaries refine
        the cells: their samples lie off the larger set, and (over one
        parameter) each lies in a cell with the same count and stable count.

        EXAMPLES: run by ``TestSuite`` (see the class).
        """
        tester = self._tester(**options)
        polys = self.bifurcation_set(first_approximation=True)
        tester.assertEqual(polys[:len(self._polynomials)], self._polynomials)
        for cell in self.cells(first_approximation=True):
            tester.assertTrue(all(not SR(f).subs(cell.sample()).is_zero() for f in polys))
            if len(self._parameters) == 1 and cell.bounds() is not None:
                lo, hi = cell.bounds()
                coarse = [c for c in self._cells
                          if (c.bounds()[0] is None or lo is not None and c.bounds()[0] <= lo)
                          and (c.bounds()[1] is None or hi is not None and hi <= c.bounds()[1])]
                tester.assertEqual(len(coarse), 1)
                tester.assertEqual((coarse[0].count(), coarse[0].stable_count()),
                                   (cell.count(), cell.stable_count()))

    def _is_positive(self, p):
        return any(str(p) == str(q) for q in self._positive)

    def parameters(self):
        r"""The parameters of the census.

        EXAMPLES: see :class:`Census`.
        """
        return list(self._parameters)

    def bifurcation_set(self, first_approximation=False):
        r"""
        The polynomials in the parameters whose zero sets bound the cells
        (irreducible over `\QQ`): where an equilibrium is degenerate, in the
        chart or in the regular chart. The count and the Lyapunov stable
        count are constant off this set.

        INPUT:

        - ``first_approximation`` -- (default: ``False``) if ``True``, the
          boundaries of the stability regions of the equilibria (Routh's
          condition and the first approximation: see
          :func:`first_approximation_polynomials`) are appended, those not
          in the set already: the cells of ``cells(first_approximation=True)``,
          where ``stable_count(first_approximation=True)`` is constant too

        EXAMPLES: see :class:`Census`, and the turning saddle of the module
        documentation, stabilized by turning for `1 < w^2 < 9/8`: its
        bifurcation set ``[w - 1]`` becomes ``[w - 1, 8*w^2 - 9]`` with
        ``first_approximation=True``.
        """
        if first_approximation:
            return list(self._first_approximation()[0])
        return list(self._polynomials)

    def bifurcation_values(self, first_approximation=False):
        r"""
        For a census over one parameter: the bifurcation values inside the
        declared signs, exact (real algebraic numbers; ``radical_expression()``
        gives radicals), sorted; with ``first_approximation=True``, those of
        ``bifurcation_set(first_approximation=True)``.

        EXAMPLES: see :class:`Census`.

        TESTS::

            sage: from sage_dynsym import Lagrangian
            sage: from sage_dynsym.analysis.census import equilibrium_census
            sage: x, dx, a, b = var('x dx a b')
            sage: L = Lagrangian(dx^2/2 - x^4/4 + a*x^2/2 - b*x, [x])
            sage: equilibrium_census(L, [a, b], values=None).bifurcation_values()
            Traceback (most recent call last):
            ...
            AnalysisError: bifurcation_values: the census is over 2 parameters (a, b): its bifurcation set is a set of curves, bifurcation_set() gives their equations
        """
        if len(self._parameters) != 1:
            raise AnalysisError(f"the census is over {len(self._parameters)} parameters "
                                f"({', '.join(map(str, self._parameters))}): its bifurcation "
                                "set is a set of curves, bifurcation_set() gives their "
                                "equations", entry="bifurcation_values")
        p = self._parameters[0]
        polys = self.bifurcation_set(first_approximation)
        return [r for r in real_roots(polys, p, self._is_positive(p))
                if r != 0 or any(SR(f).subs({p: 0}).is_zero() for f in polys)]

    def cells(self, first_approximation=False):
        r"""
        The cells (:class:`CensusCell`), each with a sample point and its
        counts.

        INPUT:

        - ``first_approximation`` -- (default: ``False``) if ``True``, the
          cells of ``bifurcation_set(first_approximation=True)``: finer,
          each with a constant ``stable_count(first_approximation=True)``
          (the stability regions are computed with the parameters symbolic
          on the first call)

        EXAMPLES: see :class:`Census`; the turning saddle of the module
        documentation is stable in first approximation in the middle cell
        of its ``cells(first_approximation=True)`` only.
        """
        if first_approximation:
            return list(self._first_approximation()[1])
        return list(self._cells)

    def count_at(self, values):
        r"""
        The number of equilibria and of stable ones at given values of the
        parameters (solved there, exactly).

        OUTPUT: a pair ``(count, stable_count)``

        EXAMPLES: see the module documentation.
        """
        values = {SR(k) if not isinstance(k, str) else SR.var(k): v for k, v in values.items()}
        missing = [p for p in self._parameters if all(str(p) != str(k) for k in values)]
        if missing:
            raise AnalysisError(f"give a value to {', '.join(map(str, missing))}, e.g. "
                                f"count_at({{{', '.join(f'{p}: 1' for p in self._parameters)}}})",
                                entry="count_at")
        (n, stable, _, _), _ = self._task(*self._arguments_of(values))
        return n, stable

    def plot(self, **options):
        r"""
        The cells of a census over two parameters coloured by the number of
        equilibria (the legend gives it, with the stable count), with the
        bifurcation curves in black; over one parameter, the counts as
        steps.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: from sage_dynsym.analysis.census import equilibrium_census
            sage: x, dx, a, b = var('x dx a b')
            sage: L = Lagrangian(dx^2/2 - x^4/4 + a*x^2/2 - b*x, [x])
            sage: census = equilibrium_census(L, [a, b])
            sage: census.plot()
            Graphics object consisting of ... graphics primitives

        With ``first_approximation=True``, the cells of
        ``cells(first_approximation=True)`` coloured by
        ``stable_count(first_approximation=True)``: see the turning saddle of
        the module documentation, stable in first approximation on the
        middle step.
        """
        from .census_plot import census_plot
        return census_plot(self, self._signs, **options)


def register_census(cls, census):
    r"""
    Register ``census`` as the census of :func:`equilibrium_census` for the
    objects of the class ``cls`` and of its subclasses: a class of a higher
    layer, which the analysis does not import (the Lie--Poisson systems of
    :mod:`~sage_dynsym.lie` register theirs, which is
    :func:`~sage_dynsym.analysis.leaf_census.leaf_census`).

    INPUT:

    - ``cls`` -- a class
    - ``census`` -- a function ``census(system, parameters, positive=,
      values=, chart=, regular=, executor=, levels=)`` (the arguments of
      :func:`equilibrium_census`) returning a :class:`Census`, and raising
      the package's error for an option it does not take

    OUTPUT: ``census``

    EXAMPLES: a bead on a hoop turning at a given rate, as an object whose
    census is that of its Lagrangian::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.analysis.census import register_census, equilibrium_census
        sage: class Hoop:
        ....:     def __init__(self, rate):
        ....:         self.rate = rate
        sage: def hoop_census(hoop, parameters, **options):
        ....:     th, dth = var('theta dtheta')
        ....:     L = Lagrangian(dth^2/2 + hoop.rate^2*sin(th)^2/2 + cos(th), [th])
        ....:     return equilibrium_census(L, parameters, **options)
        sage: register_census(Hoop, hoop_census)
        <function hoop_census at ...>
        sage: w = var('w')
        sage: equilibrium_census(Hoop(w), [w], positive=[w])
        Census of the equilibria over w > 0: bifurcation set [w - 1]
          0 < w < 1 (sample w = 1/2): 2 equilibria, 1 stable
          1 < w (sample w = 2): 4 equilibria, 2 stable

    TESTS::

        sage: register_census(Hoop(w), hoop_census)
        Traceback (most recent call last):
        ...
        AnalysisError: register_census: expected a class and a function, got <...Hoop object at ...> and <function hoop_census at ...>
        sage: register_census(Hoop, 42)
        Traceback (most recent call last):
        ...
        AnalysisError: register_census: expected a class and a function, got <class '...Hoop'> and 42
    """
    if not isinstance(cls, type) or not callable(census):
        raise AnalysisError(f"expected a class and a function, got {cls!r} and {census!r}",
                            entry="register_census")
    _CENSUSES[cls] = census
    return census


def equilibrium_census(system, parameters, positive=(), values=None, chart=None,
                       regular=None, executor=None, levels=None):
    r"""
    The census of the equilibria (stationary motions) of a Lagrangian or
    Routh function over one or two parameters: the bifurcation set, the
    cells of the parameter space where the numbers of equilibria and of
    stable ones are constant, and those numbers (see the module
    documentation for the method). For a Lie--Poisson system, the census
    of its relative equilibria on the levels of its Casimirs
    (:func:`~sage_dynsym.analysis.leaf_census.leaf_census`).

    INPUT:

    - ``system`` -- a :class:`~sage_dynsym.dynamics.lagrangian.Lagrangian`
      or :class:`~sage_dynsym.dynamics.lagrangian.RouthFunction` (a
      mechanical model's ``lagrangian()``, or its ``routh([...])``), or an
      object of a class with a census of its own (:func:`register_census`):
      a :class:`~sage_dynsym.lie.system.LiePoissonSystem`
    - ``parameters`` -- one or two symbols: the axes of the census (for a
      Lie--Poisson system, symbols of `H` or of the ``levels``)
    - ``positive`` -- symbols declared positive (a parameter declared
      positive is censused over its positive values only)
    - ``values`` -- a dict of values for the other symbols; every symbol
      other than the coordinates, velocities and ``parameters`` needs one
    - ``chart`` -- (optional) a :class:`~sage_dynsym.analysis.charts.ConfigurationChart`
      of the coordinates (e.g. :func:`~sage_dynsym.mechanics.charts.euler_angles`):
      equilibria are counted as points of the configuration space
    - ``regular`` -- (optional) a pair ``(system2, chart2)``, the same
      model in a chart regular on the singular set of ``chart``; the
      equilibria there, and their stability, are decided in it
    - ``executor`` -- (optional) where the sample points are solved: an
      object with ``submit(f, *args)`` returning futures with ``result()``
      (e.g. a ``concurrent.futures.ProcessPoolExecutor``), or a function
      ``executor(f, arguments)`` returning ``[f(*a) for a in arguments]``
      (e.g. Dask's, through :func:`sage_dynsym.scale.equilibrium_census`);
      default: in this process. Each task must run in the main thread of
      its process: Sage's PARI cannot run in another thread, and a task
      sent to one is an :class:`~sage_dynsym.errors.AnalysisError`. A
      ``dask.distributed`` worker runs its tasks in threads: with a Dask
      ``Client``, use :func:`sage_dynsym.scale.equilibrium_census`, which
      runs them in child processes of the workers
    - ``levels`` -- for a Lie--Poisson system only: the levels of its
      Casimirs, one per Casimir in the order of ``system.casimirs()`` (as
      for its ``stationary_solutions``), numbers or expressions in the
      parameters

    OUTPUT: a :class:`Census`

    Progress is reported through Sage's ``verbose`` (``set_verbose(1)``).

    EXAMPLES: the cusp: `W = x^4/4 - a x^2/2 + b x` has three equilibria
    (two stable) inside `4a^3 > 27 b^2`, one outside (Arnold,
    *Catastrophe Theory*, ch. 1)::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.analysis.census import equilibrium_census
        sage: x, dx, a, b = var('x dx a b')
        sage: L = Lagrangian(dx^2/2 - x^4/4 + a*x^2/2 - b*x, [x])
        sage: census = equilibrium_census(L, [a, b]); census.bifurcation_set()
        [4*a^3 - 27*b^2]
        sage: sorted({(c.count(), c.stable_count()) for c in census.cells()})
        [(1, 1), (3, 2)]
        sage: census.count_at({a: 3, b: 1}), census.count_at({a: 1, b: 1})
        ((3, 2), (1, 1))

    TESTS::

        sage: equilibrium_census(L, [a])
        Traceback (most recent call last):
        ...
        AnalysisError: values: give a value to b (the census is over a), e.g. values={b: 1}
        sage: equilibrium_census(L, [a, b, x])
        Traceback (most recent call last):
        ...
        AnalysisError: parameters: a census is over one or two parameters, got 3 (a, b, x)
        sage: equilibrium_census(L, [x])
        Traceback (most recent call last):
        ...
        AnalysisError: parameters: x is a coordinate of the system, not a parameter; the parameters are a, b

    An executor given as a function; one whose tasks run in threads is
    refused before PARI runs there::

        sage: census = equilibrium_census(L, [a], values={b: 0},
        ....:                             executor=lambda f, args: [f(*x) for x in args])
        sage: [(c.count(), c.stable_count()) for c in census.cells()]
        [(1, 1), (3, 2)]
        sage: from concurrent.futures import ThreadPoolExecutor
        sage: with ThreadPoolExecutor(1) as threads:
        ....:     equilibrium_census(L, [a], values={b: 0}, executor=threads)
        Traceback (most recent call last):
        ...
        AnalysisError: executor: the sample point {a: -1} was sent to a thread (ThreadPoolExecutor-...), where Sage's PARI cannot run; ...client=...

    A Lie--Poisson system: the free rigid body on the spheres `|M|^2 = c^2`
    (see :mod:`~sage_dynsym.analysis.leaf_census`)::

        sage: from sage_dynsym import LiePoissonSystem
        sage: M1, M2, M3, c = var('M1 M2 M3 c')
        sage: S = LiePoissonSystem('so3', M1^2/2 + M2^2/4 + M3^2/6)
        sage: equilibrium_census(S, [c], levels=[c^2], positive=[c])
        Census of the relative equilibria on the levels M1^2 + M2^2 + M3^2 = c^2 over c > 0: bifurcation set []
          0 < c (sample c = 1): 6 relative equilibria, 4 stable
        sage: equilibrium_census(S, [c], levels=[c], chart=1)
        Traceback (most recent call last):
        ...
        AnalysisError: chart: a Lie-Poisson system has no chart or regular chart: its relative equilibria are points of its variables
        sage: equilibrium_census(L, [a], values={b: 0}, levels=[1])
        Traceback (most recent call last):
        ...
        AnalysisError: levels: levels= is for a Lie-Poisson system (the levels of its Casimirs); a Lagrangian's census takes values=

    An object without a census::

        sage: equilibrium_census(42, [a], values={b: 0})
        Traceback (most recent call last):
        ...
        AnalysisError: equilibrium_census: expected a Lagrangian or Routh function ...LiePoissonSystem..., got Integer; for a mechanical model pass model.lagrangian() (or its routh([...]))
    """
    census = next((_CENSUSES[cls] for cls in type(system).__mro__ if cls in _CENSUSES), None)
    if census is not None:
        return census(system, parameters, positive=positive, values=values, chart=chart,
                      regular=regular, executor=executor, levels=levels)
    if levels is not None:
        raise AnalysisError("levels= is for a Lie-Poisson system (the levels of its "
                            "Casimirs); a Lagrangian's census takes values=", entry="levels")
    parameters, positive, values = census_arguments(parameters, positive, values)
    q, W = _amended_potential(system)
    names = {str(x) for x in q}
    symbols = sorted((v for v in SR(W).variables() if str(v) not in names), key=str)
    for p in parameters:
        if str(p) in names:
            raise AnalysisError(f"{p} is a coordinate of the system, not a parameter; the "
                                f"parameters are {', '.join(map(str, symbols))}",
                                entry="parameters")
    check_values(symbols, parameters, values)
    fixed = system.subs(values) if values else system
    polys = discriminant_polynomials(SR(W).subs(values), q, parameters)
    if regular is not None:
        q2, W2 = _amended_potential(regular[0])
        polys += [f for f in discriminant_polynomials(SR(W2).subs(values), q2, parameters)
                  if all(not bool(SR(f) - g == 0) for g in polys)]
    fixed2 = None if regular is None else \
        ((regular[0].subs(values) if values else regular[0]), regular[1])

    def boundaries():
        # solved with the parameters symbolic, only when asked: that can
        # take much longer than the census
        more = []
        for model in [fixed] + ([] if fixed2 is None else [fixed2[0]]):
            more += first_approximation_polynomials(model, parameters, positive)
        return more

    return Census(parameters, polys, _count_task, lambda s: (fixed, s, chart, fixed2, positive),
                  boundaries, positive, executor=executor)

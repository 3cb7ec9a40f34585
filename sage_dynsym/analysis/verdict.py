r"""
Stability verdicts

A :class:`StabilityVerdict` is the answer of a stability test: one of

- ``'asymptotically stable'`` -- every root of the characteristic
  polynomial has a negative real part (or a Lyapunov function with a
  negative definite derivative);
- ``'stable'`` -- stable in the sense of Lyapunov, for the nonlinear system
  too (a definite first integral or Lyapunov function: Lagrange--Dirichlet,
  Kelvin's theorems, Routh--Lyapunov);
- ``'stable in first approximation'`` -- the linearized system is stable,
  not asymptotically: every root on the imaginary axis is simple (or
  semisimple) and the others have negative real parts; the Lyapunov
  stability of the nonlinear system is *not* decided by the linear terms
  (a critical case);
- ``'unstable'`` -- a root with a positive real part (Lyapunov's theorem on
  the first approximation), or a theorem of instability;
- ``'depends on the parameters'`` -- several of the above, each on a part
  of the parameter space: :meth:`StabilityVerdict.cases` gives them, each
  with its :meth:`~StabilityVerdict.region`, and the verdict's own
  :meth:`~StabilityVerdict.region` is the stable set (the union of the
  parts that are stable in one of the three senses);
- ``'undecided'`` -- only where the theory leaves it open (for example a
  multiple root on the imaginary axis that is not semisimple: the
  nonlinear terms decide); :meth:`~StabilityVerdict.reason` says why.

A region is a list of alternatives, each a list of relations (see
:mod:`~sage_dynsym.algebra.regions`).

EXAMPLES::

    sage: from sage_dynsym.analysis.verdict import StabilityVerdict
    sage: a = var('a')
    sage: up = StabilityVerdict('unstable', 'a real positive root', region=[[a < 0]])
    sage: down = StabilityVerdict('stable', 'the energy has a minimum', region=[[a > 0]])
    sage: v = StabilityVerdict('depends on the parameters', 'see cases()', cases=[down, up]); v
    depends on the parameters: see cases()
    sage: v.region()
    [[a > 0]]
    sage: v.at({a: -1})
    'unstable'
"""
from sage.structure.sage_object import SageObject

from ..errors import AnalysisError
from ..symbols import exact_decimals
from ..algebra.conditions import region_holds
from ..algebra.regions import partition, prune_empty, drop_redundant

__all__ = ['STABLE_VERDICTS', 'VERDICTS', 'StabilityVerdict', 'verdict_from_parts',
           'depends_on_parameters']

#: The verdicts that count as stable (the stable set of a verdict that
#: depends on the parameters is the union of their regions).
STABLE_VERDICTS = ('asymptotically stable', 'stable', 'stable in first approximation')

#: All the verdicts, in order of strength.
VERDICTS = STABLE_VERDICTS + ('unstable', 'depends on the parameters', 'undecided')


class StabilityVerdict(SageObject):
    r"""
    The outcome of a stability test: a verdict, where it holds (its region,
    or conditions all ``> 0``), and the reason in plain language with the
    theorem used.

    INPUT:

    - ``verdict`` -- one of the verdicts of the module documentation (older
      tests may also name their own)
    - ``reason`` -- why, in plain language
    - ``conditions`` -- (optional) expressions that must all be ``> 0``
    - ``cases`` -- (optional) the verdicts of the parts, for ``'depends on
      the parameters'``
    - ``method`` -- (optional) the method that decided
    - ``region`` -- (optional) where the verdict holds (a list of
      alternatives, each a list of relations)
    - ``boundaries`` -- (optional) dict naming the boundaries of the stable
      set (``'flutter'``, ``'divergence'``, ...), each a list of relations
      ``f == 0``
    - ``positive`` -- (optional) the symbols declared positive

    EXAMPLES::

        sage: from sage_dynsym.analysis.verdict import StabilityVerdict
        sage: from sage_dynsym.analysis.kelvin_chetaev import kelvin_chetaev
        sage: a = var('a')
        sage: StabilityVerdict('stable', 'the potential energy has a minimum', conditions=[a])
        stable if [a]: the potential energy has a minimum
        sage: kelvin_chetaev(matrix([[1]]), matrix([[0]]), matrix([[0]]), matrix([[-1]]))
        unstable: the potential energy has an odd degree of instability (1): ...

    TESTS:

    The cases of a verdict partition its space::

        sage: up = StabilityVerdict('unstable', 'a real positive root', region=[[a < 0]])
        sage: v = StabilityVerdict('depends on the parameters', 'see cases()',
        ....:                      cases=[StabilityVerdict('stable', 'K > 0', region=[[a > 0]]), up])
        sage: TestSuite(v).run()
        sage: k, p = var('k p')
        sage: w = kelvin_chetaev(identity_matrix(2), zero_matrix(2), zero_matrix(2),
        ....:                    diagonal_matrix([1, k]), matrix([[0, p], [-p, 0]]))
        sage: TestSuite(w).run()
        sage: v == w, v == loads(dumps(v)), v.cases()[1] == up
        (False, True, True)
        sage: overlap = StabilityVerdict('depends on the parameters', 'wrong',
        ....:                            cases=[StabilityVerdict('stable', '', region=[[a > -1]]), up])
        sage: overlap._test_cases()
        Traceback (most recent call last):
        ...
        AssertionError: at {a: -64/71} the cases ['stable', 'unstable'] hold
    """

    def __init__(self, verdict, reason, conditions=(), cases=(), method=None,
                 region=None, boundaries=None, positive=()):
        self._verdict = verdict
        self._reason = reason
        self._conditions = list(conditions)
        self._cases = list(cases)
        self._method = method
        self._region = region
        self._boundaries = dict(boundaries) if boundaries else {}
        self._positive = list(positive)

    def _data(self):
        # the symbolic parts by their printed form: ``==`` of two relations
        # is a relation, not a truth value
        return (self._verdict, self._reason, self._method, str(self._conditions),
                str(self._region), str(sorted(self._boundaries.items())), str(self._positive))

    def __eq__(self, other):
        r"""Verdicts are values: equal when their verdicts, reasons, methods,
        conditions, regions, boundaries, signs and cases are (see the class)."""
        return (isinstance(other, StabilityVerdict) and self._data() == other._data()
                and self._cases == other._cases)

    def __hash__(self):
        return hash((self._verdict, self._reason))

    def method(self):
        r"""The method that decided the verdict (``None`` if not recorded).

        EXAMPLES::

            sage: from sage_dynsym.analysis.verdict import StabilityVerdict
            sage: StabilityVerdict('stable', 'K > 0', method='Routh-Lyapunov').method()
            'Routh-Lyapunov'
        """
        return self._method

    def region(self):
        r"""
        Where the verdict holds: a list of alternatives, each a list of
        relations (``[[]]``: everywhere). For ``'depends on the
        parameters'`` the stable set: the union of the regions of the
        cases that are stable (asymptotically, in the sense of Lyapunov, or
        in first approximation). ``None`` if not recorded.

        EXAMPLES::

            sage: from sage_dynsym.analysis.verdict import StabilityVerdict
            sage: a = var('a')
            sage: StabilityVerdict('stable', 'K > 0', region=[[a > 0]]).region()
            [[a > 0]]
        """
        if self._region is None and self._verdict == 'depends on the parameters':
            union = []
            for case in self._cases:
                if case.verdict() in STABLE_VERDICTS and case.region() is not None:
                    union += [alt for alt in case.region() if alt not in union]
            return union
        return None if self._region is None else [list(alt) for alt in self._region]

    def verdict(self):
        r"""The verdict (a string).

        EXAMPLES::

            sage: from sage_dynsym.analysis.kelvin_chetaev import kelvin_chetaev
            sage: v = kelvin_chetaev(matrix([[1]]), matrix([[0]]), matrix([[0]]), matrix([[-1]]))
            sage: v.verdict()
            'unstable'
        """
        return self._verdict

    def reason(self):
        r"""Why, in plain language, with the theorem used.

        EXAMPLES::

            sage: from sage_dynsym.analysis.kelvin_chetaev import kelvin_chetaev
            sage: v = kelvin_chetaev(matrix([[1]]), matrix([[0]]), matrix([[0]]), matrix([[-1]]))
            sage: v.reason()
            'the potential energy has an odd degree of instability (1): ...'
        """
        return self._reason

    def conditions(self):
        r"""Conditions (expressions ``> 0``) under which the verdict holds,
        when it was stated that way (see :meth:`region` otherwise).

        EXAMPLES::

            sage: from sage_dynsym.analysis.verdict import StabilityVerdict
            sage: StabilityVerdict('stable', 'K > 0', conditions=[var('k')]).conditions()
            [k]
        """
        return list(self._conditions)

    def cases(self):
        r"""The possible cases (each a :class:`StabilityVerdict` with its
        region); ``[self]`` when there is one.

        EXAMPLES::

            sage: from sage_dynsym.analysis.kelvin_chetaev import kelvin_chetaev
            sage: v = kelvin_chetaev(matrix([[1]]), matrix([[0]]), matrix([[0]]), matrix([[-1]]))
            sage: len(v.cases())
            1
        """
        return list(self._cases) if self._cases else [self]

    def case(self, verdict):
        r"""The case with the verdict ``verdict`` (``None`` if there is none).

        EXAMPLES::

            sage: from sage_dynsym.analysis.kelvin_chetaev import kelvin_chetaev
            sage: k = var('k')
            sage: v = kelvin_chetaev(matrix([[1]]), matrix([[0]]), matrix([[0]]), matrix([[k]]))
            sage: v.case('stable').region(), v.case('asymptotically stable')
            ([[k > 0]], None)
        """
        return next((c for c in self.cases() if c.verdict() == verdict), None)

    def boundaries(self):
        r"""
        The boundaries of the stable set by kind: a dict, e.g.
        ``'flutter'`` (a pair of roots meets on the imaginary axis and
        leaves it) and ``'divergence'`` (a real root passes through zero),
        each a list of relations ``f == 0``; empty if none were recorded.

        EXAMPLES: an undamped oscillator with a circulatory force of the
        follower type (see :mod:`~sage_dynsym.analysis.kelvin_chetaev`)::

            sage: from sage_dynsym.analysis.kelvin_chetaev import kelvin_chetaev
            sage: k, p = var('k p')
            sage: v = kelvin_chetaev(identity_matrix(2), zero_matrix(2), zero_matrix(2),
            ....:                    diagonal_matrix([1, k]), matrix([[0, p], [-p, 0]]))
            sage: v.boundaries()
            {'divergence': [p^2 + k == 0], 'flutter': [k - 2*p - 1 == 0, k + 2*p - 1 == 0]}
        """
        if not self._boundaries and self._cases:
            found = {}
            for case in self._cases:
                for kind, relations in case.boundaries().items():
                    found.setdefault(kind, [])
                    found[kind] += [r for r in relations if str(r) not in map(str, found[kind])]
            return found
        return {k: list(v) for k, v in self._boundaries.items()}

    def at(self, values):
        r"""
        The verdict at numerical values of the parameters: that of the
        case whose region holds there; ``None`` on a boundary (no region
        holds).

        INPUT:

        - ``values`` -- dict ``{parameter: number}`` for every parameter of
          the regions (a float is the exact decimal it prints as)

        EXAMPLES::

            sage: from sage_dynsym.analysis.kelvin_chetaev import kelvin_chetaev
            sage: k = var('k')
            sage: v = kelvin_chetaev(matrix([[1]]), matrix([[0]]), matrix([[0]]), matrix([[k]]))
            sage: v.at({k: 2}), v.at({k: -2}), v.at({k: 0}), v.at({k: 0.0})
            ('stable', 'unstable', None, None)
        """
        values = exact_decimals(values)
        for case in self.cases():
            region = case.region()
            if region is None:
                if case is self:
                    return self._verdict
                continue
            try:
                inside = region_holds(region, values)
            except (TypeError, ValueError) as err:
                raise AnalysisError(f"cannot evaluate the region {region} at {values} "
                                    f"({err}): give a value to every parameter",
                                    entry="StabilityVerdict.at") from err
            if inside:
                return case.verdict()
        return None

    def critical_values(self, parameter, values=None, samples=3):
        r"""
        The critical values of ``parameter``: the roots in it of the
        boundaries (:meth:`boundaries`) at which the parameter leaves or
        enters the stable set.

        Each candidate root is an exact expression in the other parameters;
        it is kept if the stable set changes across it, tested at
        ``samples`` sample points of the other parameters (those declared
        positive are sampled positive; any other must be given in
        ``values``), which must all agree.

        INPUT:

        - ``parameter`` -- a symbol of the regions
        - ``values`` -- (optional) dict giving the other parameters numerical
          values (then one sample)
        - ``samples`` -- (default: 3) the number of sample points

        OUTPUT: a list of expressions, by increasing value

        EXAMPLES: Ziegler's column (see
        :mod:`~sage_dynsym.analysis.kelvin_chetaev`), stable up to the
        flutter load `P = (7/2 - \sqrt 2)\,k/l`::

            sage: from sage_dynsym.analysis.kelvin_chetaev import kelvin_chetaev
            sage: P, k, l, m = var('P k l m')
            sage: M = m*l^2*matrix([[3, 1], [1, 1]])
            sage: W = matrix([[2*k - P*l, P*l - k], [-k, k]])
            sage: v = kelvin_chetaev(M, zero_matrix(2), zero_matrix(2), (W + W.T)/2,
            ....:                    (W - W.T)/2, positive=[k, l, m])
            sage: v.critical_values(P)
            [-sqrt(2)*k/l + 7/2*k/l]
            sage: v.critical_values(P, values={k: 1, l: 2})
            [-1/2*sqrt(2) + 7/4]

        TESTS::

            sage: w = kelvin_chetaev(M, zero_matrix(2), zero_matrix(2), (W + W.T)/2,
            ....:                    (W - W.T)/2, positive=[m])
            sage: w.critical_values(P)
            Traceback (most recent call last):
            ...
            AnalysisError: critical_values: give a value to k and l in values= (not declared positive)
        """
        from .critical import critical_values
        return critical_values(self.region(), self.boundaries(), parameter,
                               positive=self._positive, values=exact_decimals(values),
                               samples=samples)

    def report_lines(self, indent="  "):
        r"""
        The verdict as report lines: the verdict, the method and the
        reason; with several cases, each with its region.

        EXAMPLES::

            sage: from sage_dynsym.analysis.linear import LinearSystem
            sage: m, c, k = var('m c k')
            sage: v = LinearSystem([var('x')], M=[[m]], S=[[c]], W=[[k]]).stability(positive=[m, k])
            sage: print("\n".join(v.report_lines()))
              stability depends on the parameters:
                asymptotically stable (first approximation) where [c > 0]: every root ...
                unstable (first approximation) where [c < 0]: a root ...
        """
        def where(case):
            region = case.region()
            if not region or region == [[]]:
                return ""
            return " where " + " or ".join("[" + ", ".join(map(str, alt)) + "]"
                                           for alt in region)

        def method(case):
            return f" ({case.method()})" if case.method() else ""
        if len(self.cases()) == 1:
            case = self.cases()[0]
            return [f"{indent}stability: {case.verdict()}{method(case)}{where(case)}: "
                    f"{case.reason()}"]
        return [f"{indent}stability depends on the parameters:"] + \
            [f"{indent}  {case.verdict()}{method(case)}{where(case)}: {case.reason()}"
             for case in self.cases()]

    def _test_cases(self, **options):
        r"""The cases partition the parameter space: each is one verdict,
        and at sample points (random rationals, off the boundaries almost
        surely; the symbols declared positive sampled positive) exactly one
        region holds.

        EXAMPLES: run by ``TestSuite`` (see the class).
        """
        import random
        from sage.rings.rational_field import QQ
        from sage.symbolic.ring import SR
        tester = self._tester(**options)
        cases = self.cases()
        for case in cases:
            tester.assertEqual(case.cases(), [case])
        regions = [case.region() for case in cases]
        if len(cases) < 2 or None in regions:
            return
        symbols = {v for region in regions for alt in region for rel in alt
                   for v in SR(rel).variables()}
        positive = set(map(SR, self._positive))
        rng = random.Random(0)
        for _ in range(20):
            point = {v: QQ((rng.choice([1] if v in positive else [1, -1]) * rng.randint(1, 999),
                            rng.randint(1, 97))) for v in symbols}
            holding = [case.verdict() for case, region in zip(cases, regions)
                       if region_holds(region, point)]
            tester.assertEqual(len(holding), 1, f"at {point} the cases {holding} hold")

    def _repr_(self):
        cond = f" if {self._conditions}" if self._conditions else ""
        if self._region is not None and self._region != [[]]:
            cond = " where " + " or ".join(
                "[" + ", ".join(map(str, alt)) + "]" for alt in self._region)
        return f"{self._verdict}{cond}: {self._reason}"


def verdict_from_parts(parts, reasons, boundaries, positive=(), domain=((),),
                       method='first approximation', methods=None, rest='unstable'):
    r"""
    The verdict whose cases partition ``domain``: the regions of ``parts``
    made disjoint by precedence, and ``'unstable'`` for the rest (the
    boundaries, where a strict condition is zero, belong to no case).

    INPUT:

    - ``parts`` -- list of pairs ``(verdict, region or None)``, by
      precedence (e.g. asymptotically stable, stable, stable in first
      approximation, undecided)
    - ``reasons`` -- dict ``{verdict: reason}``, ``'unstable'`` included
    - ``boundaries`` -- dict of the boundaries (see
      :meth:`StabilityVerdict.boundaries`)
    - ``positive`` -- symbols declared positive
    - ``domain`` -- (default: everywhere) the region where the parts are
      taken (e.g. where the kinetic matrix is positive definite)
    - ``method`` -- the method recorded in each case, unless
      ``methods`` (a dict ``{verdict: method}``) names another
    - ``rest`` -- (default: ``'unstable'``) the verdict of the rest of
      ``domain``

    OUTPUT: a :class:`StabilityVerdict`: the single case, or ``'depends on
    the parameters'`` with the cases

    EXAMPLES::

        sage: from sage_dynsym.analysis.verdict import verdict_from_parts
        sage: a = var('a')
        sage: v = verdict_from_parts([('stable', [[a > 0]])],
        ....:                        {'stable': 'a minimum', 'unstable': 'a maximum'}, {})
        sage: [(c.verdict(), c.region()) for c in v.cases()]
        [('stable', [[a > 0]]), ('unstable', [[a < 0]])]
        sage: verdict_from_parts([('stable', [[a^2 + 1 > 0]])], {'stable': 'always'}, {})
        stable: always
    """
    positive = list(positive)
    # redundant relations would hide the boundary (the sleeping top's
    # stable set is M3^2 > 4 A m g l alone)
    found = [(name, drop_redundant(prune_empty(region, positive), positive)
              if region is not None else None)
             for name, region in partition(parts, rest=rest, domain=domain,
                                           positive=positive)]
    cases = []
    for name, region in found:
        if region == []:
            continue
        strict = region is not None and len(region) == 1 and \
            all(r.operator().__name__ in ('gt', 'lt') for r in region[0])
        conditions = [(r.lhs() - r.rhs()) if r.operator().__name__ == 'gt' else
                      (r.rhs() - r.lhs()) for r in region[0]] if strict else []
        cases.append(StabilityVerdict(name, reasons[name], conditions=conditions,
                                      method=(methods or {}).get(name, method),
                                      region=region, boundaries=boundaries,
                                      positive=positive))
    if len(cases) == 1:
        return cases[0]
    return depends_on_parameters(cases, boundaries, positive)


def depends_on_parameters(cases, boundaries=None, positive=()):
    r"""
    The verdict ``'depends on the parameters'`` made of ``cases``.

    INPUT:

    - ``cases`` -- a list of :class:`StabilityVerdict`, each with its region
    - ``boundaries`` -- (optional) dict of the boundaries (see
      :meth:`StabilityVerdict.boundaries`)
    - ``positive`` -- symbols declared positive

    OUTPUT: a :class:`StabilityVerdict` whose reason names the verdicts of
    the cases

    EXAMPLES::

        sage: from sage_dynsym.analysis.verdict import StabilityVerdict, depends_on_parameters
        sage: a = var('a')
        sage: v = depends_on_parameters([StabilityVerdict('stable', 'a minimum', region=[[a > 0]]),
        ....:                            StabilityVerdict('unstable', 'a maximum', region=[[a < 0]])],
        ....:                           {'a = 0': [a == 0]}); v
        depends on the parameters: see cases(): stable, unstable
        sage: v.at({a: 1}), v.boundaries()
        ('stable', {'a = 0': [a == 0]})
    """
    return StabilityVerdict('depends on the parameters', "see cases(): " +
                            ", ".join(c.verdict() for c in cases), cases=cases,
                            boundaries=boundaries, positive=positive)

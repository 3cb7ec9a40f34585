r"""
The machinery shared by the censuses of equilibria (private to the package)

:mod:`~sage_dynsym.analysis.census` (the equilibria of a Lagrangian or Routh
function) and :mod:`~sage_dynsym.analysis.leaf_census` (the relative
equilibria of a Lie--Poisson system on its leaves) differ in their
bifurcation sets and in what they solve at a sample point; they share what
is here: the stationary ideal an elimination onto the parameters starts
from and the zero sets of its results, the cells of the parameter space
(intervals between real roots, or the cylinders of a decomposition of the
plane, each with a rational sample), and the checks and counts of the
tasks that solve a sample point. The census itself is
:class:`~sage_dynsym.analysis.census.Census`.

EXAMPLES: the cells of the positive half-line cut at `c = 1`::

    sage: from sage_dynsym.analysis._census import cell_shapes
    sage: c = var('c')
    sage: cell_shapes([c - 1], [c], [True])
    [('0 < c < 1', {c: 1/2}, (0, 1)), ('1 < c', {c: 2}, (1, None))]

REFERENCES:

- G. E. Collins, *Quantifier elimination for real closed fields by
  cylindrical algebraic decomposition*, LNCS 33 (1975) 134--183.
"""
import threading

from sage.arith.misc import gcd
from sage.misc.verbose import verbose
from sage.rings.polynomial.polynomial_ring_constructor import PolynomialRing
from sage.rings.qqbar import AA
from sage.rings.rational_field import QQ
from sage.symbolic.ring import SR

from ..errors import AnalysisError
from ..arguments import symbol_arguments
from ..algebra.translation import Translation
from .verdict import STABLE_VERDICTS


def log(message, level=1):
    r"""
    Report the progress of a census through Sage's ``verbose``.

    EXAMPLES::

        sage: from sage_dynsym.analysis._census import log
        sage: log("solving at {a: 1}")
    """
    verbose(f"equilibrium_census: {message}", level=level)


# -- the arguments ------------------------------------------------------------------

def census_arguments(parameters, positive, values):
    r"""
    The ``parameters`` (one or two) and the ``positive`` symbols of a
    census as lists of symbols, and its ``values`` as a dict over symbols
    (keys given as names or symbols), checked.

    EXAMPLES::

        sage: from sage_dynsym.analysis._census import census_arguments
        sage: census_arguments(['a'], [], {'b': 1})
        ([a], [], {b: 1})
        sage: census_arguments(['a', 'b', 'c'], [], None)
        Traceback (most recent call last):
        ...
        AnalysisError: parameters: a census is over one or two parameters, got 3 (a, b, c)
    """
    parameters = symbol_arguments(parameters, 'parameters', error=AnalysisError)
    positive = symbol_arguments(positive, 'positive', error=AnalysisError)
    if len(parameters) not in (1, 2):
        raise AnalysisError(f"a census is over one or two parameters, got {len(parameters)} "
                            f"({', '.join(map(str, parameters))})", entry="parameters")
    values = {SR.var(k) if isinstance(k, str) else SR(k): v for k, v in (values or {}).items()}
    return parameters, positive, values


def check_values(symbols, parameters, values):
    r"""
    Refuse a census where one of the ``symbols`` of the system is neither
    one of its ``parameters`` nor given one of the ``values``.

    EXAMPLES::

        sage: from sage_dynsym.analysis._census import check_values
        sage: a, b, c = var('a b c')
        sage: check_values([a, b], [a], {b: 1})
        sage: check_values([a, b, c], [a], {})
        Traceback (most recent call last):
        ...
        AnalysisError: values: give a value to b, c (the census is over a), e.g. values={b: 1, c: 1}
    """
    chosen = {str(p) for p in parameters} | {str(k) for k in values}
    missing = sorted({str(s) for s in symbols} - chosen)
    if missing:
        raise AnalysisError(f"give a value to {', '.join(missing)} (the census is over "
                            f"{', '.join(map(str, parameters))}), e.g. values="
                            f"{{{', '.join(f'{s}: 1' for s in missing)}}}", entry="values")


# -- eliminations onto the parameters -----------------------------------------------

def stationary_ideal(equations, unknowns, parameters, extra=()):
    r"""
    The ideal of ``equations`` in the polynomial ring of the unknowns and
    the parameters (angles in their cosines and sines, denominators
    saturated away), with the ring variables to eliminate to reach the
    parameters and the numerators of the ``extra`` expressions in that
    ring: what an elimination onto the parameters starts from.

    OUTPUT: a tuple ``(translation, ideal, state, extra)``

    EXAMPLES::

        sage: from sage_dynsym.analysis._census import stationary_ideal
        sage: x, a = var('x a')
        sage: T, I, state, extra = stationary_ideal([x^2 - a], [x], [a], [2*x])
        sage: I.gens(), state, extra
        ([x1^2 - x0], [x1], [2*x1])
    """
    T = Translation(list(equations), list(unknowns) + list(parameters), extra=list(extra))
    P = T.ring()
    keep = {str(g) for p in parameters for g in T.generators_of(p)}
    state = [g for g in P.gens() if str(g) not in keep]
    ideal = P.ideal(T.equations())
    for d in T.denominators():
        ideal = ideal.saturation(P.ideal(d))[0]
    return T, ideal, state, [T.numerator(e)[0] for e in extra]


def add_zero_set_factors(gens, factors):
    r"""
    Append to ``factors`` the irreducible factors (not there yet, up to
    sign) of a polynomial vanishing on the zero set of the nonzero
    polynomials ``gens`` in the parameters: the factors of their gcd for
    one parameter; for two, of a curve through it (a finite set of points
    lies on it).

    EXAMPLES::

        sage: from sage_dynsym.analysis._census import add_zero_set_factors
        sage: R.<a, b> = QQ[]
        sage: found = [a - 1]
        sage: add_zero_set_factors([(a - 1)*(a + 2)*b, (a + 2)*(b + 1)], found); found
        [a - 1, a + 2]
    """
    g = gcd(gens) if len(gens) > 1 else gens[0]
    if g.is_constant():
        g = gens[0]
    factors += [f for f, _ in g.factor() if not f.is_constant() and f not in factors
                and -f not in factors]


# -- the tasks solving a sample point ----------------------------------------------

def verdict_counts(verdicts):
    r"""
    The counts of a cell from the verdicts of its equilibria: ``(count,
    stable, stable with those in first approximation, undecided)``.

    EXAMPLES::

        sage: from sage_dynsym.analysis._census import verdict_counts
        sage: verdict_counts(['stable', 'unstable', 'stable in first approximation', 'undecided'])
        (4, 1, 2, 1)
    """
    stable = sum(1 for v in verdicts if v == 'stable')
    linear = sum(1 for v in verdicts if v in STABLE_VERDICTS)
    undecided = sum(1 for v in verdicts if v == 'undecided')
    return len(verdicts), stable, linear, undecided


def check_main_thread(values):
    r"""
    Refuse a sample point sent to a thread other than the main one, before
    PARI runs there (its stack belongs to the main thread).

    EXAMPLES::

        sage: from sage_dynsym.analysis._census import check_main_thread
        sage: check_main_thread({var('a'): 1})
    """
    if threading.current_thread() is not threading.main_thread():
        # PARI's stack belongs to the main thread: in another one it faults
        raise AnalysisError(f"the sample point {values} was sent to a thread "
                            f"({threading.current_thread().name}), where Sage's PARI cannot "
                            "run; solve the samples in the main thread of processes: "
                            "sage_dynsym.scale.equilibrium_census(..., client=...) (Dask's "
                            "process pool with client='local'; with a dask.distributed Client, "
                            "in child processes of its workers) or "
                            "executor=concurrent.futures.ProcessPoolExecutor()",
                            entry="executor")


# -- cells -------------------------------------------------------------------------

def polynomials_inside(polys, parameters, signs):
    r"""
    For one parameter, the factors with a zero inside the declared signs
    (only those bound cells; ``signs`` says for each parameter whether it
    is declared positive); for two, all.

    EXAMPLES::

        sage: from sage_dynsym.analysis._census import polynomials_inside
        sage: c = var('c')
        sage: polynomials_inside([c + 1, c - 2, c^2 + 1], [c], [True])
        [c - 2]
    """
    if len(parameters) != 1:
        return polys
    return [f for f in polys if any(r > 0 or not signs[0] for r in
                                    real_roots([f], parameters[0], False))]


def _between(a, b):
    r"""A rational strictly between ``a < b`` (``None`` for no bound), of the
    smallest denominator, the closest to ``a`` among those."""
    if a is None and b is None:
        return QQ(0)
    if a is None:
        return QQ((b - 1).ceil())
    if b is None:
        return QQ(a.floor() + 1)
    den = 1
    while True:
        n = (a * den).floor() + 1
        if QQ(n) / den < b:
            return QQ(n) / den
        den += 1


def real_roots(polys, x, positive):
    r"""
    The distinct real roots in ``x`` of the univariate ``polys`` (real
    algebraic numbers), sorted; with ``positive``, those `> 0` and `0`
    itself as a bound.

    EXAMPLES::

        sage: from sage_dynsym.analysis._census import real_roots
        sage: c = var('c')
        sage: real_roots([c^2 - 2, c + 1], c, False), real_roots([c^2 - 2, c + 1], c, True)
        ([-1.414213562373095?, -1, 1.414213562373095?], [0, 1.414213562373095?])
    """
    ring = PolynomialRing(QQ, 'z')
    roots = set()
    for f in polys:
        if SR(f).has(x):
            f = ring(SR(f).coefficients(x, sparse=False))
            roots.update(r for r, _ in f.roots(AA))
    if positive:
        roots = {r for r in roots if r > 0} | {AA(0)}
    return sorted(roots)


def _intervals(roots, positive):
    bounds = ([] if positive else [None]) + list(roots) + [None]
    return list(zip(bounds[:-1], bounds[1:]))


def _shown(value):
    r"""A bound as radicals when they are real ones, else as a real algebraic number."""
    try:
        text = str(value.radical_expression())
    except (AttributeError, ValueError, NotImplementedError, TypeError):
        return str(value)
    return str(value) if 'I' in text else text


def cell_shapes(polys, parameters, signs):
    r"""
    The open cells of the parameter space adapted to ``polys`` (one or two
    ``parameters``; ``signs`` says for each whether it is declared
    positive), each as ``(description, sample, bounds)``: for one
    parameter, the intervals between the real roots, ``bounds`` their ends
    (real algebraic numbers, ``None`` for an infinite end); for two, the
    cells of a cylindrical decomposition of the plane (Collins), ``bounds``
    the interval of the first parameter, the index of the section and
    their number.

    EXAMPLES: see the module documentation; the cusp `4a^3 = 27b^2`::

        sage: from sage_dynsym.analysis._census import cell_shapes
        sage: a, b = var('a b')
        sage: [text for text, _, _ in cell_shapes([4*a^3 - 27*b^2], [a, b], [False, False])]
        ['a < 0', '0 < a, b in section 1 of 3', '0 < a, b in section 2 of 3',
         '0 < a, b in section 3 of 3']
    """
    if len(parameters) == 2:
        return _cylinders(polys, parameters[0], parameters[1], signs[0], signs[1])
    p, positive = parameters[0], signs[0]
    return [(_interval_text(lo, p, hi), {p: _between(lo, hi)}, (lo, hi))
            for lo, hi in _intervals(real_roots(polys, p, positive), positive)]


def _interval_text(lo, p, hi):
    return (f"{_shown(lo)} < " if lo is not None else "") + str(p) + \
        (f" < {_shown(hi)}" if hi is not None else "")


def _cylinders(polys, p1, p2, positive1, positive2):
    r"""Sample points of the open cells of a cylindrical decomposition of
    the plane adapted to ``polys``: the intervals of ``p1`` between the
    critical values of the projection, and in each the intervals of ``p2``
    between the sections."""
    ring = PolynomialRing(QQ, [str(p1), str(p2)])
    F = ring(1)
    for f in polys:
        F *= ring(SR(f).polynomial(QQ))
    F = F.radical() if hasattr(F, 'radical') else F
    y = ring.gen(1)
    critical = [F.polynomial(y).leading_coefficient()]
    if F.degree(y) > 0:
        # in the bivariate ring (Singular's resultant): the univariate
        # discriminant over QQ[p1] goes through PARI, which refuses the
        # variable order ("incorrect priority in gtopoly") by an abort()
        # that cysignals recovers from but faulthandler reports
        critical.append(F.discriminant(y))
    if positive2:
        # a section crossing the boundary p2 = 0 changes the count of sections
        critical.append(F.subs({y: 0}))
    critical = [SR(c) for c in critical if not c.is_constant()]
    out = []
    for lo, hi in _intervals(real_roots(critical, p1, positive1), positive1):
        s1 = _between(lo, hi)
        over = SR(F.subs({ring.gen(0): s1}))
        sections = real_roots([over], p2, positive2) if over.has(p2) else \
            ([AA(0)] if positive2 else [])
        for k, (a, b) in enumerate(_intervals(sections, positive2)):
            text = (_interval_text(lo, p1, hi) +
                    (f", {p2} in section {k + 1} of {len(sections) + (0 if positive2 else 1)}"
                     if len(sections) > (1 if positive2 else 0) else ""))
            out.append((text, {p1: s1, p2: _between(a, b)}, (lo, hi, k, len(sections))))
    return out

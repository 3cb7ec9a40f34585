r"""
Plots of a census of equilibria (:mod:`~sage_dynsym.analysis.census`)

Over two parameters, each open cell of the cylindrical decomposition is
filled between its lower and upper sections (computed numerically for the
picture only: the counts are exact), coloured by the number of
equilibria; the bifurcation curves are drawn on top, and the legend names
each colour with the count and the stable count.

EXAMPLES::

    sage: from sage_dynsym import Lagrangian
    sage: from sage_dynsym.analysis.census import equilibrium_census
    sage: x, dx, a, b = var('x dx a b')
    sage: L = Lagrangian(dx^2/2 - x^4/4 + a*x^2/2 - b*x, [x])
    sage: G = equilibrium_census(L, [a, b]).plot(xmin=-1, xmax=3)
    sage: sorted(set(p.options().get('legend_label') for p in G if p.options().get('legend_label')))
    ['1 equilibrium, 1 stable', '3 equilibria, 2 stable']
"""
from sage.plot.colors import rainbow
from sage.plot.contour_plot import implicit_plot
from sage.plot.graphics import Graphics
from sage.plot.line import line
from sage.plot.polygon import polygon
from sage.rings.real_double import RDF
from sage.symbolic.ring import SR

from ..errors import AnalysisError

__all__ = ['POINTS', 'census_plot']

POINTS = 60


def _label(n, stable, first_approximation=False):
    return f"{n} equilibri{'um' if n == 1 else 'a'}, {stable} stable" + \
        (" (with first approximation)" if first_approximation else "")


def _sections(polys, p1, p2, t):
    r"""The real roots in ``p2`` at ``p1 = t`` (numerical), sorted."""
    roots = []
    for f in polys:
        g = SR(f).subs({p1: t})
        if g.has(p2):
            roots += g.polynomial(RDF).roots(multiplicities=False)
    return sorted(roots)


def census_plot(census, signs, xmin=None, xmax=None, ymin=None, ymax=None,
                first_approximation=False, **options):
    r"""
    The picture of a census: see :meth:`~sage_dynsym.analysis.census.Census.plot`.

    INPUT:

    - ``census`` -- a :class:`~sage_dynsym.analysis.census.Census`
    - ``signs`` -- for each parameter whether it is declared positive
    - ``xmin``, ``xmax``, ``ymin``, ``ymax`` -- (optional) the window
    - ``first_approximation`` -- (default: ``False``) if ``True``, the cells
      and curves of ``bifurcation_set(first_approximation=True)``, coloured
      by the count and ``stable_count(first_approximation=True)``
    - further options are passed to ``Graphics.show`` defaults

    EXAMPLES: see the module documentation.
    """
    cells = census.cells(first_approximation)
    params = census.parameters()

    def key_of(c):
        return c.count(), c.stable_count(first_approximation)
    counts = sorted({key_of(c) for c in cells})
    colours = dict(zip(counts, rainbow(max(len(counts), 2))))
    G = Graphics()
    if len(params) == 1:
        for c in cells:
            lo, hi = c.bounds()
            a = float(lo) if lo is not None else float(c.sample()[params[0]]) - 1
            b = float(hi) if hi is not None else float(c.sample()[params[0]]) + 1
            key = key_of(c)
            G += line([(a, c.count()), (b, c.count())], color=colours[key], thickness=3,
                      legend_label=_label(*key, first_approximation))
        G.axes_labels([str(params[0]), 'equilibria'])
        return G
    p1, p2 = params
    samples = [c.sample() for c in cells]
    xs = [float(s[p1]) for s in samples]
    ys = [float(s[p2]) for s in samples]
    xmin = min(xs) - 1 if xmin is None else float(xmin)
    xmax = max(xs) + 1 if xmax is None else float(xmax)
    ymin = min(ys) - 1 if ymin is None else float(ymin)
    ymax = max(ys) + 1 if ymax is None else float(ymax)
    if signs[0]:
        xmin = max(xmin, 0.0)
    if signs[1]:
        ymin = max(ymin, 0.0)
    if not xmin < xmax or not ymin < ymax:
        raise AnalysisError(f"the window {xmin} < {p1} < {xmax}, {ymin} < {p2} < {ymax} is "
                            "empty", entry="plot")
    polys = census.bifurcation_set(first_approximation)
    labelled = set()
    for c in cells:
        lo, hi, k, n = c.bounds()
        a = xmin if lo is None else max(xmin, float(lo))
        b = xmax if hi is None else min(xmax, float(hi))
        if a >= b:
            continue
        lower, upper = [], []
        for i in range(POINTS + 1):
            t = a + (b - a) * i / POINTS
            roots = [r for r in _sections(polys, p1, p2, t) if not (signs[1] and r <= 0)]
            roots = [r for j, r in enumerate(roots) if j == 0 or r - roots[j - 1] > 1e-9]
            if len(roots) != n - (1 if signs[1] else 0):
                continue    # the numerical roots miss one here (the picture only)
            bounds = ([0.0] if signs[1] else [ymin]) + roots + [ymax]
            lower.append((t, min(max(bounds[k], ymin), ymax)))
            upper.append((t, min(max(bounds[k + 1], ymin), ymax)))
        if not lower:
            continue
        key = key_of(c)
        label = _label(*key, first_approximation) if key not in labelled else None
        labelled.add(key)
        G += polygon(lower + upper[::-1], color=colours[key], alpha=0.7, thickness=0,
                     **({'legend_label': label} if label else {}))
    edges = [p for p, positive in zip(params, signs) if positive]
    for f in polys:
        if any(bool(SR(f) == p) for p in edges):
            continue    # the edge p = 0 of the window (an implicit plot there is degenerate)
        G += implicit_plot(SR(f), (p1, xmin, xmax), (p2, ymin, ymax), color='black')
    G.axes_labels([str(p1), str(p2)])
    G.set_axes_range(xmin, xmax, ymin, ymax)
    G.set_legend_options(loc=(1.02, 0.4))     # beside the plane, not over it
    return G

r"""
Reports of models: sections, their budget, and the one runner

A model describes its report as a list of :class:`ReportSection` (see
:meth:`~sage_dynsym.dynamics.model.Model.report_sections`); :func:`run_sections`
runs any such list, the same way for every kind of model:

- a section is printed when one of its keys is wanted (and, for an
  analysis section, when the analysis is); it is also computed, silently,
  when a printed section needs or uses its result;
- before a section is computed, its estimate (a number of polynomial
  terms, found without creating them) is compared with the budget; a
  section can check further estimates while it runs
  (:meth:`ReportContext.check`). Over the budget, the section is one line
  saying so;
- a section that fails is one line too: ``not available (...)`` for the
  package's own errors (a model that does not have what the section
  shows), ``section failed: ...`` for any other error (its name is added
  to ``failed``). A ``KeyboardInterrupt`` is not caught;
- a section whose needed results are missing (an earlier section was
  skipped or failed, and said so) is left out.

Formulas are shown as text with their LaTeX (:func:`formula_lines`).

EXAMPLES::

    sage: from sage_dynsym.dynamics.reporting import ReportSection, run_sections, formula_lines
    sage: x = var('x')
    sage: def potential(context):
    ....:     context.results['potential'] = x^4/4 - x^2/2
    ....:     return ["Potential:"] + formula_lines("V = ", context.results['potential'])
    sage: def equilibria(context):
    ....:     V = context.results['potential']
    ....:     return ["Equilibria:"] + [f"  x = {s.rhs()}" for s in solve(V.diff(x), x)]
    sage: sections = [ReportSection('potential', "Potential", potential, estimate=lambda c: 2,
    ....:                           what="the potential"),
    ....:             ReportSection('stationary', "Equilibria", equilibria, needs=['potential'],
    ....:                           analysis=True)]
    sage: print(run_sections("== a double well ==", sections))
    == a double well ==
    Potential:
      V = 1/4*x^4 - 1/2*x^2
        LaTeX: \frac{1}{4} \, x^{4} - \frac{1}{2} \, x^{2}
    Equilibria:
      x = -1
      x = 1
      x = 0
    sage: print(run_sections("== a double well ==", sections, wanted=['stationary'], budget=1))
    == a double well ==
    Potential: skipped, the potential: about 2 polynomial terms, over the budget of 1 (raise it with --budget)
"""
from sage.misc.latex import latex
from sage.structure.sage_object import SageObject

from ..errors import BudgetError, DynSymError


class ReportSection(SageObject):
    r"""
    One section of a model's report.

    INPUT:

    - ``key`` -- the name under which a report selects it (the command
      line's ``--sections``, see :data:`sage_dynsym.report.sections.SECTIONS`),
      or a tuple of such names (printed when any of them is wanted), or
      ``None`` (always printed); several sections may share a key, and a
      section's result is stored in ``context.results`` under the key it
      chooses (usually its own)
    - ``name`` -- the section's name in the one line that replaces it when
      it is skipped or fails (``Lagrangian: skipped, ...``); a string, or a
      function of the results so far
    - ``compute`` -- a function of a :class:`ReportContext` returning the
      section's lines (its heading included), or ``None`` when the section
      does not apply to the model
    - ``estimate`` -- (optional) a function of the context returning the
      number of polynomial terms the section would create, without
      creating them
    - ``what`` -- (default: the name) what the estimate counts, for the
      line of a skipped section
    - ``analysis`` -- (default: ``False``) whether the section is analysis
      (left out of a report without analysis)
    - ``needs`` -- (default: none) results the section cannot do without: a
      printed section makes the runner compute the sections that provide
      them, and is left out when they could not
    - ``uses`` -- (default: none) results the section takes when they are
      there (the runner computes their providers too)

    EXAMPLES::

        sage: from sage_dynsym.dynamics.reporting import ReportSection
        sage: ReportSection('equations', "Lagrange equations", lambda c: [])
        Report section 'equations' (Lagrange equations)
    """

    def __init__(self, key, name, compute, estimate=None, what=None, analysis=False,
                 needs=(), uses=()):
        self.key, self.name, self.compute = key, name, compute
        self.estimate, self.what, self.analysis = estimate, what, analysis
        self.needs, self.uses = tuple(needs), tuple(uses)

    def _repr_(self):
        return f"Report section {self.key!r} ({self.name})"

    def keys(self):
        r"""The keys that select the section (empty: always printed).

        EXAMPLES::

            sage: from sage_dynsym.dynamics.reporting import ReportSection
            sage: ReportSection(('routh', 'stationary'), "Not cyclic", lambda c: []).keys()
            ('routh', 'stationary')
        """
        if self.key is None:
            return ()
        return self.key if isinstance(self.key, tuple) else (self.key,)

    def title(self, results):
        r"""The section's name, given the results so far.

        EXAMPLES::

            sage: from sage_dynsym.dynamics.reporting import ReportSection
            sage: s = ReportSection('stationary', lambda r: 'Equilibria' if r else 'Motions',
            ....:                   lambda c: [])
            sage: s.title({}), s.title({'routh': None})
            ('Motions', 'Equilibria')
        """
        return self.name(results) if callable(self.name) else self.name


class ReportContext:
    r"""
    What a section sees while it is computed: the ``results`` of the
    sections before it (by key; it may add its own), the ``budget``,
    whether the section is ``shown`` (a section computed only for its
    result may leave out work that serves its lines only), and
    :meth:`check`.

    EXAMPLES::

        sage: from sage_dynsym.dynamics.reporting import ReportContext
        sage: c = ReportContext({}, 100)
        sage: c.check("the equations", 10)
        sage: c.check("the equations", 1000)
        Traceback (most recent call last):
        ...
        BudgetError: the equations: about 1e+03 polynomial terms, over the budget of 100
    """

    def __init__(self, results, budget, shown=True):
        self.results, self.budget, self.shown = results, budget, shown

    def check(self, what, estimate):
        r"""Raise a :class:`~sage_dynsym.errors.BudgetError` when
        ``estimate`` (polynomial terms of ``what``) exceeds the budget.

        EXAMPLES: see the class.
        """
        if self.budget is not None and estimate > self.budget:
            raise BudgetError(what, estimate=estimate, budget=self.budget)


def formula_lines(label, expr, indent="  "):
    r"""
    The two report lines of a formula: ``label`` followed by its text, and
    its LaTeX, indented.

    EXAMPLES::

        sage: from sage_dynsym.dynamics.reporting import formula_lines
        sage: formula_lines("H = ", var('p')^2/2)
        ['  H = 1/2*p^2', '    LaTeX: \\frac{1}{2} \\, p^{2}']
    """
    return [f"{indent}{label}{expr}", f"{indent}  LaTeX: {latex(expr)}"]


def conditions_lines(model):
    r"""
    What the declared signs leave open for ``model`` to be physical (the
    rest of the report holds where these hold); ``None`` when nothing is.

    EXAMPLES::

        sage: from sage_dynsym import load
        sage: from sage_dynsym.description import example_path
        sage: from sage_dynsym.dynamics.reporting import conditions_lines
        sage: conditions_lines(load(example_path('spherical_pendulum.yaml'))) is None
        True
    """
    conditions = model.conditions()
    if not conditions:
        return None
    return ["Conditions for the model to be physical (not decided by the declared signs): "
            + ", ".join(map(str, conditions))]


def clip(text, limit=300):
    r"""
    ``text`` on one line, cut at ``limit`` characters (an error message in
    a report line).

    EXAMPLES::

        sage: from sage_dynsym.dynamics.reporting import clip
        sage: clip("a\n  b"), clip("x" * 10, limit=6)
        ('a b', 'xxx...')
    """
    text = " ".join(text.split())
    return text if len(text) <= limit else text[:limit - 3] + "..."


def run_sections(title, sections, wanted=None, budget=None, analysis=True, failed=None):
    r"""
    The report of a list of sections (see the module documentation), as a
    string: ``title`` on the first line, then the sections.

    INPUT:

    - ``title`` -- the first line
    - ``sections`` -- a list of :class:`ReportSection`, in the order they
      are printed
    - ``wanted`` -- (default: all) the keys of the sections to print
    - ``budget`` -- (default: none) the size budget of each section, in
      polynomial terms
    - ``analysis`` -- (default: ``True``) whether to print analysis
      sections
    - ``failed`` -- (optional) a list to which the names of the sections
      that failed on an error that is not the package's own are appended

    EXAMPLES: see the module documentation.
    """
    failed = [] if failed is None else failed
    sections = list(sections)

    def shown(section):
        keys = section.keys()
        return (not keys or wanted is None or any(k in wanted for k in keys)) and \
            (analysis or not section.analysis)

    # a section is computed when it is shown, or when a later computed
    # section needs or uses a result it provides (under one of its keys)
    computed = [shown(s) for s in sections]
    for i in reversed(range(len(sections))):
        if computed[i]:
            wants = set(sections[i].needs) | set(sections[i].uses)
            for j in range(i):
                if wants & set(sections[j].keys()):
                    computed[j] = True
    lines, results = [title], {}
    for section, compute, show in zip(sections, computed, map(shown, sections)):
        # a missing result: its section said why, or does not apply
        if not compute or any(k not in results for k in section.needs):
            continue
        context = ReportContext(results, budget, shown=show)
        name = section.title(results)
        try:
            if section.estimate is not None:
                context.check(section.what or name, section.estimate(context))
            body = section.compute(context)
        except BudgetError as err:
            lines.append(f"{name}: skipped, {err.message} (raise it with --budget)")
            continue
        except DynSymError as err:
            lines.append(f"{name}: not available ({clip(str(err))})")
            continue
        except Exception as err:    # Sage, Maxima, memory, recursion: one line, no traceback
            lines.append(f"{name}: section failed: {type(err).__name__}: {clip(str(err))}")
            failed.append(name)
            continue
        if show and body:
            lines.extend(body)
    return "\n".join(lines)

r"""
Reports of models: sections, their budget, and the one runner

A model describes its report as a list of :class:`ReportSection` (see
:meth:`~sage_dynsym.dynamics.model.Model.report_sections`); :func:`report_blocks`
runs any such list, the same way for every kind of model, and yields each
section's lines as soon as the section ends (the command line prints them
at once); :func:`run_sections` joins them into one text:

- a section is printed when one of its keys is wanted (and, for an
  analysis section, when the analysis is); it is also computed, silently,
  when a printed section needs or uses its result;
- before a section is computed, its estimate (a number of polynomial
  terms, found without creating them) is compared with the budget; a
  section can check further estimates while it runs
  (:meth:`ReportContext.check`). Over the budget, the section is one line
  saying so, and how to raise the budget;
- a section that fails is one line too: ``not available (...)`` for the
  package's own errors (a model that does not have what the section
  shows), ``section failed: ...`` for any other error (its name is added
  to ``failed``). A ``KeyboardInterrupt`` is not caught;
- a printed section whose needed results are missing (an earlier section
  was skipped or failed) is one line naming what it needs and why that is
  missing; and every section asked for that printed nothing (one the model
  does not have, or that does not apply to it) is one line saying so, so
  that every section asked for is accounted for.

Formulas are :class:`Formula` lines: :func:`render` writes them in full
(text and LaTeX), or, in a readable report, summarises those longer than
a few lines (:func:`summary`) and leaves out the LaTeX.

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
    sage: print(run_sections("== a double well ==", sections, latex=False))
    == a double well ==
    Potential:
      V = 1/4*x^4 - 1/2*x^2
    ...
    sage: print(run_sections("== a double well ==", sections, wanted=['stationary'], budget=1))
    == a double well ==
    Potential: skipped, the potential: about 2 polynomial terms, over the budget of 1 (raise it with --budget)
    Equilibria: skipped, it needs: Potential (skipped above; --budget raises the limit)
    sage: print(run_sections("== a double well ==", sections, wanted=['stationary'],
    ....:                    analysis=False))
    == a double well ==
    Equilibria: left out (an analysis section; the analysis is off: --no-analysis)
"""
from sage.misc.latex import latex as latex_form
from sage.structure.sage_object import SageObject
from sage.symbolic.operators import add_vararg, mul_vararg
from sage.symbolic.ring import SR

from ..errors import BudgetError, DynSymError

__all__ = ['SUMMARY_LENGTH', 'LINE_LENGTH', 'FULL_FORM', 'LEADING_TERMS', 'TERM_LENGTH',
           'ReportSection', 'ReportContext', 'Formula', 'summary', 'formula_lines', 'render',
           'conditions_lines', 'clip', 'report_blocks', 'run_sections']

#: A formula whose text is longer than this many characters (about five
#: lines of a terminal) is summarised in a readable report.
SUMMARY_LENGTH = 500

#: A line of a readable report that is not a formula is cut at this many
#: characters.
LINE_LENGTH = 1000

#: Where the full form of what a readable report summarises is.
FULL_FORM = "in full with --full or in the -o file"

#: How many leading terms a summary shows, and at most how many characters of each.
LEADING_TERMS, TERM_LENGTH = 3, 120


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
      section's lines (its heading included; strings and :class:`Formula`),
      or ``None`` when the section does not apply to the model
    - ``estimate`` -- (optional) a function of the context returning the
      number of polynomial terms the section would create, without
      creating them
    - ``what`` -- (default: the name) what the estimate counts, for the
      line of a skipped section
    - ``analysis`` -- (default: ``False``) whether the section is analysis
      (left out of a report without analysis)
    - ``needs`` -- (default: none) results the section cannot do without: a
      printed section makes the runner compute the sections that provide
      them, and is one line saying what is missing when they could not
    - ``uses`` -- (default: none) results the section takes when they are
      there (the runner computes their providers too)
    - ``absent`` -- (optional) why the model does not have the section,
      for the line of a section asked for when ``compute`` returns
      ``None``
    - ``auxiliary`` -- (default: ``False``) a section printed only where
      it applies (the constraints of a constrained system, ...): no line
      when its needs are missing

    EXAMPLES::

        sage: from sage_dynsym.dynamics.reporting import ReportSection
        sage: ReportSection('equations', "Lagrange equations", lambda c: [])
        Report section 'equations' (Lagrange equations)
    """

    def __init__(self, key, name, compute, estimate=None, what=None, analysis=False,
                 needs=(), uses=(), absent=None, auxiliary=False):
        self.key, self.name, self.compute = key, name, compute
        self.estimate, self.what, self.analysis = estimate, what, analysis
        self.needs, self.uses = tuple(needs), tuple(uses)
        self.absent, self.auxiliary = absent, auxiliary

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



class Formula(SageObject):
    r"""
    A formula of a report: ``label`` followed by the expression ``expr``,
    written in full (its text and, on a second line, its LaTeX) or, when
    its text is longer than :data:`SUMMARY_LENGTH`, summarised
    (:func:`summary`).

    INPUT:

    - ``label`` -- the text before the expression (``"H = "``, ``"[x] "``)
    - ``expr`` -- a symbolic expression (or a list of them, or a list of
      rows)
    - ``indent`` -- (default: two spaces) the indentation of the line
    - ``variables`` -- (optional) the variables that matter for the
      formula (the accelerations of an equation, the variable of a
      characteristic polynomial): a summary gives its degree in them and
      its terms of highest degree first
    - ``named`` -- (optional) a name for ``variables`` in the summary
      (``"the accelerations"``)

    EXAMPLES::

        sage: from sage_dynsym.dynamics.reporting import Formula
        sage: x, lam = var('x lam')
        sage: F = Formula("H = ", x^2/2); F
        Formula H = 1/2*x^2
        sage: F.lines()
        ['  H = 1/2*x^2', '    LaTeX: \\frac{1}{2} \\, x^{2}']
        sage: F.lines(latex=False)
        ['  H = 1/2*x^2']
        sage: P = Formula("characteristic polynomial: ", sum((x + k)*lam^k for k in range(60)),
        ....:             variables=[lam])
        sage: len(P.lines()[0]) > 500, len(P.lines(full=False))
        (True, 1)
        sage: print(P.lines(full=False)[0])
          characteristic polynomial: <a sum of 60 terms of degree 59 in lam, 1043 characters; leading terms: lam^59*(x + 59) + lam^58*(x + 58) + lam^57*(x + 57) + ...; in full with --full or in the -o file>
    """

    def __init__(self, label, expr, indent="  ", variables=(), named=None):
        self.label, self.expr, self.indent = label, expr, indent
        self.variables, self.named = list(variables), named

    def _repr_(self):
        return f"Formula {self.label}{self.expr}"

    def lines(self, full=True, latex=True):
        r"""
        The lines of the formula: its text, then its LaTeX when ``latex``;
        unless ``full``, a formula longer than :data:`SUMMARY_LENGTH`
        characters is one line, its summary (without LaTeX).

        EXAMPLES: see the class.
        """
        text = f"{self.indent}{self.label}{self.expr}"
        if not full and len(text) > SUMMARY_LENGTH:
            size = len(text) - len(self.indent) - len(self.label)
            return [f"{self.indent}{self.label}"
                    f"<{summary(self.expr, self.variables, self.named, size)}; {FULL_FORM}>"]
        if not latex:
            return [text]
        return [text, f"{self.indent}  LaTeX: {latex_form(self.expr)}"]


def summary(expr, variables=(), named=None, characters=None):
    r"""
    A summary of a long expression: what it is (a sum of how many terms, a
    product of how many factors, a matrix of what shape), its degree in
    ``variables`` (named ``named``), its length in characters, and its
    leading terms (of highest degree in ``variables`` first), each cut at
    :data:`TERM_LENGTH` characters.

    INPUT:

    - ``expr`` -- a symbolic expression, a list of them or a list of rows
    - ``variables`` -- (optional) the variables that matter
    - ``named`` -- (optional) their name (default: the variables listed)
    - ``characters`` -- (optional) the length of the text of ``expr``, if
      known

    OUTPUT: a string

    EXAMPLES::

        sage: from sage_dynsym.dynamics.reporting import summary
        sage: x, y, ddx, ddy = var('x y ddx ddy')
        sage: summary(sum(x^k for k in range(10)) + ddx*y + ddy^2*x, [ddx, ddy], 'the accelerations')
        'a sum of 12 terms of degree 2 in the accelerations, 71 characters; leading terms: ddy^2*x + ddx*y + x^9 + ...'
        sage: summary((x + y)^3*sin(x)*cos(y))
        'a product of 3 factors, 23 characters; leading terms: (x + y)^3 * cos(y) * sin(x)'
        sage: summary([[x, y], [y, x]])
        'a 2x2 matrix, 16 characters; leading terms: x, y, ...'
    """
    text_length = len(str(expr)) if characters is None else characters
    if isinstance(expr, (list, tuple)):
        rows = [list(row) if isinstance(row, (list, tuple)) else [row] for row in expr]
        shape = (f"a {len(rows)}x{len(rows[0])} matrix" if rows and
                 all(isinstance(row, (list, tuple)) for row in expr)
                 else f"a list of {len(rows)} entries")
        entries = [e for row in rows for e in row]
        shown = ", ".join(clip(str(e), TERM_LENGTH) for e in entries[:2])
        more = ", ..." if len(entries) > 2 else ""
        return f"{shape}, {text_length} characters; leading terms: {shown}{more}"
    try:
        e = SR(expr)
    except (TypeError, ValueError):     # not symbolic: its text, cut
        return f"{text_length} characters: {clip(str(expr), TERM_LENGTH)}"
    operator, parts = e.operator(), [e]
    if operator is add_vararg or operator is mul_vararg:
        parts = e.operands()
    described = {add_vararg: f"a sum of {len(parts)} terms",
                 mul_vararg: f"a product of {len(parts)} factors"}.get(operator, "an expression")
    present = [v for v in variables if e.has(v)]
    degree = _degree(e, present) if present else None
    if degree is not None and operator is add_vararg:
        degrees = [_degree(t, present) for t in parts]
        if None not in degrees:
            parts = [t for _, t in sorted(zip(degrees, parts), key=lambda p: -p[0])]
    if degree is not None:
        described += f" of degree {degree} in {named or ', '.join(map(str, present))}"
    shown = ""
    for k, t in enumerate(parts[:LEADING_TERMS]):
        term = clip(str(t), TERM_LENGTH)
        if k and operator is add_vararg:
            term = f" - {term[1:]}" if term.startswith("-") else f" + {term}"
        elif k:
            term = f" * {term}"
        shown += term
    if len(parts) > LEADING_TERMS:
        shown += " + ..." if operator is add_vararg else " * ..."
    return f"{described}, {text_length} characters; leading terms: {shown}"


def _degree(expr, variables):
    r"""The total degree of ``expr`` in ``variables`` (structural: nothing
    is expanded), or ``None`` where it is not defined (``x^y``).

    EXAMPLES::

        sage: from sage_dynsym.dynamics.reporting import _degree
        sage: x, y = var('x y')
        sage: _degree(x^2*y + sqrt(x), [x, y]), _degree(x^y + x, [x])
        (3, None)
    """
    try:
        if len(variables) == 1:
            return expr.degree(variables[0])
        s = SR.symbol()
        return expr.subs({v: s * v for v in variables}).degree(s)
    except (RuntimeError, TypeError, ValueError):
        return None


def formula_lines(label, expr, indent="  ", variables=(), named=None):
    r"""
    The lines of a formula in a report: one :class:`Formula`, written in
    full (``label`` followed by the text of ``expr``, and its LaTeX,
    indented) or summarised by :func:`render`.

    EXAMPLES::

        sage: from sage_dynsym.dynamics.reporting import formula_lines, render
        sage: formula_lines("H = ", var('p')^2/2)
        [Formula H = 1/2*p^2]
        sage: render(formula_lines("H = ", var('p')^2/2))
        ['  H = 1/2*p^2', '    LaTeX: \\frac{1}{2} \\, p^{2}']
    """
    return [Formula(label, expr, indent=indent, variables=variables, named=named)]


def render(lines, full=True, latex=True):
    r"""
    The text lines of report ``lines`` (strings and :class:`Formula`): in
    full (``full``, the default) or readable -- formulas longer than
    :data:`SUMMARY_LENGTH` characters summarised, other lines cut at
    :data:`LINE_LENGTH` characters --, with the LaTeX of the formulas when
    ``latex``.

    EXAMPLES::

        sage: from sage_dynsym.dynamics.reporting import render, formula_lines
        sage: x = var('x')
        sage: lines = ["Energy:"] + formula_lines("E = ", x^2) + ["note: " + "n" * 2000]
        sage: render(lines)[:3]
        ['Energy:', '  E = x^2', '    LaTeX: x^{2}']
        sage: short = render(lines, full=False, latex=False)
        sage: short[:2], len(short[2]) < 500
        (['Energy:', '  E = x^2'], True)
        sage: short[2][-75:]
        'nn... <the line has 2006 characters; in full with --full or in the -o file>'
    """
    out = []
    for line in lines:
        if isinstance(line, Formula):
            out += line.lines(full=full, latex=latex)
        elif full or len(line) <= LINE_LENGTH:
            out.append(line)
        else:
            out.append(f"{line[:SUMMARY_LENGTH - 100]}... <the line has {len(line)} "
                       f"characters; {FULL_FORM}>")
    return out


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


def report_blocks(title, sections, wanted=None, budget=None, analysis=True, failed=None,
                  progress=None, labels=None):
    r"""
    The report of a list of sections (see the module documentation), one
    block of lines (strings and :class:`Formula`) at a time, each as soon
    as it is computed: ``[title]``, then the lines of each section, then a
    line for each section asked for that printed nothing.

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
    - ``progress`` -- (optional) a function called with the name of each
      section before it is computed
    - ``labels`` -- (optional) a dict from keys to the names of the
      sections they select, for the line of a section asked for that the
      model does not have (default: the key)

    EXAMPLES::

        sage: from sage_dynsym.dynamics.reporting import ReportSection, report_blocks
        sage: sections = [ReportSection('energy', "Energy", lambda c: ["Energy: 1"]),
        ....:             ReportSection('routh', "Routh", lambda c: None,
        ....:                           absent="no cyclic coordinates")]
        sage: for block in report_blocks("== toy ==", sections, wanted=['energy', 'routh', 'x'],
        ....:                            progress=lambda s: print("...", s)):
        ....:     print(block)
        ['== toy ==']
        ... Energy
        ['Energy: 1']
        ... Routh
        ['Routh: not available (no cyclic coordinates)']
        ['x: not available for this model']
    """
    failed = [] if failed is None else failed
    labels = labels or {}
    sections = list(sections)

    def selected(section):
        keys = section.keys()
        return not keys or wanted is None or any(k in wanted for k in keys)

    def shown(section):
        return selected(section) and (analysis or not section.analysis)

    # a section is computed when it is shown, or when a later computed
    # section needs or uses a result it provides (under one of its keys)
    computed = [shown(s) for s in sections]
    for i in reversed(range(len(sections))):
        if computed[i]:
            wants = set(sections[i].needs) | set(sections[i].uses)
            for j in range(i):
                if wants & set(sections[j].keys()):
                    computed[j] = True
    # the keys asked for: those wanted, or all those the model offers (its
    # analysis sections only with the analysis)
    asked = list(wanted) if wanted is not None else list(dict.fromkeys(
        k for s in sections if shown(s) for k in s.keys()
        if k in labels and (analysis or not _analysed(sections, k))))
    accounted, missing, absent, results = set(), {}, {}, {}
    yield [title]
    for section, compute, show in zip(sections, computed, map(shown, sections)):
        if not compute:
            continue
        name = section.title(results)
        lacking = [k for k in section.needs if k not in results]
        if lacking:
            # an earlier section said why (skipped, failed), or does not apply
            why = missing.get(lacking[0])
            if why is None:
                continue
            for key in section.keys():
                missing.setdefault(key, why)
            if show and not section.auxiliary:
                accounted.update(section.keys())
                yield [f"{name}: skipped, it needs: {why}"]
            continue
        if progress is not None:
            progress(name)
        context = ReportContext(results, budget, shown=show)
        try:
            if section.estimate is not None:
                context.check(section.what or name, section.estimate(context))
            body = section.compute(context)
        except BudgetError as err:
            line = f"{name}: skipped, {err.message} (raise it with --budget)"
            why = "skipped above; --budget raises the limit"
        except DynSymError as err:
            line, why = f"{name}: not available ({clip(str(err))})", "not available, above"
        except Exception as err:    # Sage, Maxima, memory, recursion: one line, no traceback
            line = f"{name}: section failed: {type(err).__name__}: {clip(str(err))}"
            why = "failed above"
            failed.append(name)
        else:
            if body is None:
                for key in section.keys():
                    absent[key] = absent.get(key) or section.absent
            elif show and body:
                accounted.update(section.keys())
                yield list(body)
            continue
        for key in section.keys():
            missing.setdefault(key, f"{name} ({why})")
        accounted.update(section.keys())
        yield [line]
    for key in asked:
        if key not in accounted:
            yield [_unaccounted_line(key, sections, labels, absent.get(key), analysis, results)]


def _analysed(sections, key):
    r"""Whether a section of ``key`` is analysis."""
    return any(s.analysis for s in sections if key in s.keys())


def _unaccounted_line(key, sections, labels, reason, analysis, results):
    r"""The line of a section asked for (``key``) that printed nothing:
    left out with the analysis, or not available (for ``reason``)."""
    offered = [s for s in sections if key in s.keys()]
    name = labels.get(key) or (offered[0].title(results) if offered else key)
    if not analysis and _analysed(sections, key):
        return f"{name}: left out (an analysis section; the analysis is off: --no-analysis)"
    if reason:
        return f"{name}: not available ({reason})"
    return f"{name}: not available for this model"


def run_sections(title, sections, wanted=None, budget=None, analysis=True, failed=None,
                 full=True, latex=True, labels=None):
    r"""
    The report of a list of sections (see the module documentation and
    :func:`report_blocks`), as a string: ``title`` on the first line, then
    the sections, in full (``full``, the default) or readable, with the
    LaTeX of the formulas when ``latex`` (see :func:`render`).

    EXAMPLES: see the module documentation.
    """
    blocks = report_blocks(title, sections, wanted=wanted, budget=budget, analysis=analysis,
                           failed=failed, labels=labels)
    return "\n".join(line for block in blocks for line in render(block, full, latex))

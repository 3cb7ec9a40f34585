r"""
The report of a Lie--Poisson system

The sections (see :mod:`sage_dynsym.dynamics.reporting`) of the report of
a :class:`~sage_dynsym.lie.system.LiePoissonSystem`: the Hamiltonian, the
equations (text and LaTeX), the Casimirs, the polynomial first integrals
of degree `\le 2` besides `H` and the Casimirs, and the stationary motions
over `H`, the Casimirs and those integrals, with their stability -- each
estimated from the data (:func:`lie_estimates`) before it is computed.

EXAMPLES::

    sage: from sage_dynsym.lie.system import LiePoissonSystem
    sage: from sage_dynsym.lie.report import lie_report
    sage: M1 = var('M1')
    sage: print(lie_report(LiePoissonSystem('so3', M1^2/2), sections=['integrals']))
    == Lie-Poisson system on so3: variables M1, M2, M3 ==
    Polynomial first integrals of degree <= 2 besides H and the Casimirs:
      M1
        LaTeX: M_{1}

The budget bounds every section::

    sage: M2, M3 = var('M2 M3')
    sage: print(lie_report(LiePoissonSystem('so3', (M1 + 2*M2 + 3*M3)^200), budget=10^5))
    == Lie-Poisson system on so3: variables M1, M2, M3 ==
    Hamiltonian:
    ...
    Lie-Poisson equations dx/dt = {x, H}: skipped, the Lie-Poisson equations (terms of J_ij times those of dH/dx_j): about 1.21e+05 polynomial terms, over the budget of 100000 (raise it with --budget)
    Casimirs (polynomial, degree <= 4):
      M1^2 + M2^2 + M3^2
        LaTeX: M_{1}^{2} + M_{2}^{2} + M_{3}^{2}
    Polynomial first integrals of degree <= 2 besides H and the Casimirs: skipped, ...
    Stationary motions (Routh-Lyapunov over H, the Casimirs): skipped, ...
"""
from ..algebra.size import polynomial_terms
from ..dynamics.reporting import ReportSection, formula_lines, run_sections

__all__ = ['LIE_SECTIONS', 'report_title', 'report_sections', 'lie_report', 'lie_estimates']

#: What each estimate of :func:`lie_estimates` counts, by section.
_WHAT = {
    'equations': "the Lie-Poisson equations (terms of J_ij times those of dH/dx_j)",
    'casimirs': "the Casimirs of degree <= 4 (monomials times the terms of J)",
    'integrals': "the integrals of degree <= 2 (monomials times the terms of the equations)",
    'stationary': "the stationary motions (terms of H, the Casimirs and the integrals times "
                  "2^(n + k) for n variables and k multipliers, and the Casimirs' search)",
}

#: Sections of :func:`lie_report`.
LIE_SECTIONS = {
    'hamiltonian': "the Hamiltonian",
    'equations': "the Lie-Poisson equations",
    'casimirs': "the polynomial Casimirs of the algebra",
    'integrals': "the polynomial first integrals of degree <= 2",
    'stationary': "stationary motions (Routh-Lyapunov) with their stability",
}


def report_title(system):
    r"""
    The heading of the report of ``system``.

    EXAMPLES::

        sage: from sage_dynsym.lie.system import LiePoissonSystem
        sage: from sage_dynsym.lie.report import report_title
        sage: report_title(LiePoissonSystem('so3', var('M1')^2/2, name='a top'))
        '== a top (Lie-Poisson system on so3: variables M1, M2, M3) =='
    """
    what = system.structure().name() or "a Poisson structure"
    head = f"Lie-Poisson system on {what}: variables {', '.join(map(str, system.variables()))}"
    return f"== {system.name()} ({head}) ==" if system.name() else f"== {head} =="


def report_sections(system):
    r"""
    The sections of the report of ``system`` (see the module
    documentation), in order.

    EXAMPLES::

        sage: from sage_dynsym.lie.system import LiePoissonSystem
        sage: from sage_dynsym.lie.report import report_sections
        sage: [s.key for s in report_sections(LiePoissonSystem('so3', var('M1')^2/2))]
        ['hamiltonian', 'equations', 'casimirs', 'integrals', 'stationary']
    """
    estimates = {}

    def estimate(key):
        def size(context):
            if not estimates:       # computed once, and only with a budget
                estimates.update(lie_estimates(system))
            return estimates[key][1]
        return size

    def what(key):
        return _WHAT[key]

    def equations(context):
        lines = ["Lie-Poisson equations dx/dt = {x, H}:"]
        for x, e in zip(system.variables(), system.equations()):
            lines += formula_lines(f"d{x}/dt = ", e)
        return lines

    def casimirs(context):
        lines = ["Casimirs (polynomial, degree <= 4):"]
        for C in system.casimirs():
            lines += formula_lines("", C)
        return lines if system.casimirs() else lines + ["  none"]

    def integrals(context):
        found = context.results['integrals'] = system.polynomial_integrals(2, new_only=True)
        lines = ["Polynomial first integrals of degree <= 2 besides H and the Casimirs:"]
        for F in found:
            lines += formula_lines("", F)
        return lines if found else lines + ["  none (for generic parameter values)"]

    def stationary(context):
        found = context.results.get('integrals', [])
        return ([stationary_title(context.results) + ":"]
                + system.stationary_solutions(found).report_lines())

    def stationary_size(context):
        # the data alone first (the Casimirs' search included), then the
        # integrals found: each adds a multiplier, an unknown of the solver
        size = estimate('stationary')(context)
        if context.budget is not None and size > context.budget:
            return size
        found = [system.hamiltonian()] + system.casimirs() + context.results.get('integrals', [])
        n = len(system.variables()) + len(found) - 1
        return size + sum(polynomial_terms(f) for f in found) * 2 ** n

    def stationary_title(results):
        return ("Stationary motions (Routh-Lyapunov over H, the Casimirs"
                + (" and the integrals above)" if results.get('integrals') else ")"))

    return [
        ReportSection('hamiltonian', "Hamiltonian",
                      lambda context: ["Hamiltonian:"] + formula_lines("H = ",
                                                                       system.hamiltonian())),
        ReportSection('equations', "Lie-Poisson equations dx/dt = {x, H}", equations,
                      estimate=estimate('equations'), what=what('equations')),
        ReportSection('casimirs', "Casimirs (polynomial, degree <= 4)", casimirs,
                      estimate=estimate('casimirs'), what=what('casimirs')),
        ReportSection('integrals', "Polynomial first integrals of degree <= 2 besides H and "
                      "the Casimirs", integrals, estimate=estimate('integrals'),
                      what=what('integrals'), analysis=True),
        ReportSection('stationary', stationary_title, stationary,
                      estimate=stationary_size, what=what('stationary'), analysis=True),
    ]


def lie_report(system, sections=None, analysis=True, budget=None, failed=None):
    r"""
    A text report of a Lie--Poisson system (see the module documentation).

    INPUT:

    - ``system`` -- a :class:`~sage_dynsym.lie.system.LiePoissonSystem`
    - ``sections`` -- (default: all) keys of :data:`LIE_SECTIONS` (others
      are ignored)
    - ``analysis`` -- (default: ``True``) whether to include the polynomial
      integrals and the stationary motions
    - ``budget`` -- (optional) the size budget of each section, in
      polynomial terms (see :func:`lie_estimates`): a section whose estimate
      is larger is one line saying so
    - ``failed`` -- (optional) a list: the names of the sections that
      failed on an error that is not the package's own are appended to it

    A section that fails is one line saying why; the others are still
    printed. The same as :func:`~sage_dynsym.report.writer.report` of the
    system.

    EXAMPLES: see the module documentation.
    """
    return run_sections(report_title(system), report_sections(system), wanted=sections,
                        budget=budget, analysis=analysis, failed=failed)


def lie_estimates(system):
    r"""
    The size estimates of the sections of :func:`lie_report`, in polynomial
    terms (see :func:`~sage_dynsym.algebra.size.polynomial_terms`),
    computed from the data alone, before the sections: a dict from the
    section keys to pairs ``(what, estimate)``.

    - ``equations`` -- `\sum_{ij}` (terms of `J_{ij}`) (terms of
      `\partial H/\partial x_j`): the expanded right-hand sides;
    - ``casimirs`` -- the monomials of degree `\le 4` in the `n` variables
      times the terms of `J`: the coefficient matrix of the search;
    - ``integrals`` -- the monomials of degree `\le 2` times the terms of the
      equations, and the Casimirs of degree `\le 2`;
    - ``stationary`` -- the terms of `H` times `2^n` (the exact solver
      splits the system into cases), and the Casimirs' search; the report
      adds, once the Casimirs and the integrals are found, their terms and
      those of `H` times `2^{n + k}` for their `k` multipliers.

    EXAMPLES::

        sage: from sage_dynsym.lie.system import LiePoissonSystem
        sage: from sage_dynsym.lie.report import lie_estimates
        sage: M1, M2, M3 = var('M1 M2 M3')
        sage: E = lie_estimates(LiePoissonSystem('so3', (M1^2 + M2^2 + M3^2)/2))
        sage: {key: estimate for key, (_, estimate) in E.items()}
        {'casimirs': 204, 'equations': 6, 'integrals': 108, 'stationary': 228}
    """
    from .integrals import basis_size
    x, J = system.variables(), system.poisson_matrix()
    n = len(x)
    H = system.hamiltonian()
    structure = sum(polynomial_terms(e) for e in J.list())
    equations = sum(polynomial_terms(J[i, j]) * polynomial_terms(H.diff(x[j]))
                    for i in range(n) for j in range(n) if not J[i, j].is_zero())
    # at least one term per variable: an abelian algebra (J = 0) still builds
    # the whole basis
    casimirs = basis_size(n, 4) * max(structure, n)
    sizes = {'equations': equations, 'casimirs': casimirs,
             'integrals': basis_size(n, 2) * max(equations + structure, n),
             'stationary': polynomial_terms(H) * 2 ** n + casimirs}
    return {key: (_WHAT[key], size) for key, size in sizes.items()}

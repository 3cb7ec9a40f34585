r"""
Plain-text and LaTeX reports of a model

:func:`report` derives what a description file's model has to offer
(Lagrangian, Lagrange equations, Routh function for the cyclic coordinates,
Hamiltonian; for circuits the mixed potential and state equations, and the
loop Lagrangian of a linear circuit) and renders it as readable text with the
LaTeX form of every formula. The command line ``python -m sage_dynsym`` (or
``sage-dynsym``) prints it for each file given.

Every kind of model says what its report holds
(:meth:`~sage_dynsym.dynamics.model.Model.report_sections`); the sections
are run here, for every kind alike, by
:func:`~sage_dynsym.dynamics.reporting.report_blocks` within one budget,
each section yielded as soon as it is computed (the command line prints it
at once), its formulas written in full or summarised by
:func:`~sage_dynsym.dynamics.reporting.render`.

EXAMPLES::

    sage: from sage_dynsym import load
    sage: from sage_dynsym.description import example_path
    sage: from sage_dynsym.report import report
    sage: print(report(load(example_path('spherical_pendulum.yaml'))))
    == spherical pendulum (mechanical system: 1 body, coordinates psi, theta) ==
    Lagrangian L = T + U:
      1/2*dpsi^2*l^2*m*sin(theta)^2 + 1/2*dtheta^2*l^2*m - g*l*m*cos(theta)
      LaTeX: ...
    Lagrange equations (E_i = 0):
      [psi] 2*dpsi*dtheta*l^2*m*cos(theta)*sin(theta) + ddpsi*l^2*m*sin(theta)^2
      ...
    Routh function for the cyclic coordinates psi (momenta p_psi):
      ...
    Stationary motions (Routh function at rest, cyclic momenta constant):
      0 = -(g*l^3*m^2*sin(theta)^4 + p_psi^2*cos(theta))/(l^2*m*sin(theta)^3)
      ...
    Hamiltonian:
      ...
"""
# Sage's symbolic functions, Maxima and coercions need the whole library initialised
# first (the package's face loads it lazily, only when a name is used)
import sage.all
del sage  # imported for its effect alone: no name of this module

from ..arguments import count
from ..dynamics.model import Model
from ..dynamics.reporting import report_blocks as section_blocks, render
from ..errors import DynSymError

from .sections import DEFAULT_BUDGET, SECTIONS, ANALYSIS_SECTIONS, TITLES

__all__ = ['report', 'report_blocks', 'ANALYSIS_SECTIONS']


def report(model, sections=None, budget=DEFAULT_BUDGET, analysis=True, failed=None,
           full=True, latex=True):
    r"""
    A text report of ``model`` (see the module documentation).

    INPUT:

    - ``model`` -- a model of any kind (a
      :class:`~sage_dynsym.dynamics.model.Model`)
    - ``sections`` -- (default: all the model has) the keys of
      :data:`SECTIONS` to print; a section asked for that the model does
      not have is one line saying so
    - ``budget`` -- (default: :data:`DEFAULT_BUDGET`) the size budget of
      each section, in polynomial terms
    - ``analysis`` -- (default: ``True``) whether to include the analysis
      sections (:data:`ANALYSIS_SECTIONS`)
    - ``failed`` -- (optional) a list: the titles of the sections that
      failed on an error that is not the package's own (``section failed:
      ...``) are appended to it (the command line's exit status 3)
    - ``full`` -- (default: ``True``) whether to write every formula in
      full; ``False``: a formula longer than a few lines is summarised (its
      kind, degree, number of terms and leading terms; see
      :func:`~sage_dynsym.dynamics.reporting.summary`), as the command line
      prints it without ``--full``
    - ``latex`` -- (default: ``True``) whether to add the LaTeX of each
      formula written in full

    OUTPUT: a string (:func:`report_blocks` gives it section by section)

    Each section estimates the number of polynomial terms it would create
    *before* its expensive step (expanding a determinant, deriving the
    Lagrangian of a long chain, ...): over the budget it is replaced by one
    line saying so, and the rest of the report is still printed. A section
    that fails for another reason is also one line (the error's class and
    message), never a traceback. Every section asked for is accounted for:
    its lines, or one line saying why it is not there.

    EXAMPLES::

        sage: from sage_dynsym import load
        sage: from sage_dynsym.description import example_path
        sage: from sage_dynsym.report import report
        sage: text = report(load(example_path('nonlinear_circuit.yaml')))
        sage: print(text.splitlines()[0])
        == nonlinear circuit of Example 2 (circuit: 13 branches on 5 nodes) ==
        sage: 'State equations' in text
        True

    Sections and budget::

        sage: from sage_dynsym.circuits import Circuit
        sage: C = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1'],
        ....:              [3, 4, 'R2'], [4, 0, 'L2']], name='RLC')
        sage: print(report(C, sections=['lagrangian']))
        == RLC (circuit: 6 branches on 5 nodes) ==
        Lagrangian (loop-current method):
          L = 1/2*L1*dq1^2 + 1/2*L2*dq2^2 - 1/2*(q1 - q2)^2/C1
            LaTeX: ...
        sage: print(report(C, sections=['equations', 'stability'], budget=9))
        == RLC (circuit: 6 branches on 5 nodes) ==
        Lagrange equations: skipped, the Lagrange equations (terms of dL/d(dq_i) times 2n + 1, and of dL/dq_i): about 17 polynomial terms, over the budget of 9 (raise it with --budget)
        Stability of the free circuit: skipped, the characteristic polynomial (permanent bound of the determinant): about 10 polynomial terms, over the budget of 9 (raise it with --budget)
        sage: pendulum = load(example_path('spherical_pendulum.yaml'))
        sage: print(report(pendulum, budget=10))
        == spherical pendulum (mechanical system: 1 body, coordinates psi, theta) ==
        Lagrangian: skipped, the Lagrangian (n^2 2^r T^2: coordinates, varying angles along a chain, terms of the data): about 16 polynomial terms, over the budget of 10 (raise it with --budget)
        Lagrange equations: skipped, it needs: Lagrangian (skipped above; --budget raises the limit)
        Routh function: skipped, it needs: Lagrangian (skipped above; --budget raises the limit)
        Equilibria: skipped, it needs: Lagrangian (skipped above; --budget raises the limit)
        Hamiltonian: skipped, it needs: Lagrangian (skipped above; --budget raises the limit)
        sage: print(report(pendulum, sections=['hamiltonian', 'stationary', 'casimirs'],
        ....:              analysis=False, latex=False))
        == spherical pendulum (mechanical system: 1 body, coordinates psi, theta) ==
        Hamiltonian:
          H = g*l*m*cos(theta) + 1/2*p_theta^2/(l^2*m) + 1/2*p_psi^2/(l^2*m*sin(theta)^2)
        Stationary motions: left out (an analysis section; the analysis is off: --no-analysis)
        Casimirs: not available for this model

    TESTS::

        sage: report(42)
        Traceback (most recent call last):
        ...
        DynSymError: cannot report on Integer: expected a model (a mechanical system, a circuit, a Lie-Poisson system, ...)
        sage: report(C, sections=['colour'])
        Traceback (most recent call last):
        ...
        DynSymError: unknown report section 'colour'; the sections are: lagrangian, equations, routh, stationary, hamiltonian, mixed_potential, state_equations, lyapunov, stability, casimirs, integrals
    """
    blocks = report_blocks(model, sections=sections, budget=budget, analysis=analysis,
                           failed=failed)
    return "\n".join(line for block in blocks for line in render(block, full, latex))


def report_blocks(model, sections=None, budget=DEFAULT_BUDGET, analysis=True, failed=None,
                  progress=None):
    r"""
    The report of ``model`` (see :func:`report`), one block of lines at a
    time, each as soon as its section is computed: the title, then each
    section. The lines are strings and formulas
    (:class:`~sage_dynsym.dynamics.reporting.Formula`), written by
    :func:`~sage_dynsym.dynamics.reporting.render`.

    INPUT: as for :func:`report`, and

    - ``progress`` -- (optional) a function called with the name of each
      section before it is computed

    The arguments are checked at once, before any section is computed.

    EXAMPLES::

        sage: from sage_dynsym import load
        sage: from sage_dynsym.description import example_path
        sage: from sage_dynsym.report.writer import report_blocks
        sage: blocks = report_blocks(load(example_path('spherical_pendulum.yaml')))
        sage: next(blocks)
        ['== spherical pendulum (mechanical system: 1 body, coordinates psi, theta) ==']
        sage: next(blocks)
        ['Lagrangian L = T + U:', Formula 1/2*dpsi^2*l^2*m*sin(theta)^2 + 1/2*dtheta^2*l^2*m - g*l*m*cos(theta)]
    """
    wanted = None if sections is None else list(sections)
    for key in wanted or ():
        if key not in SECTIONS:
            raise DynSymError(f"unknown report section {key!r}; the sections are: "
                              f"{', '.join(SECTIONS)}")
    budget = count(budget, 'budget', error=DynSymError)
    if failed is not None and not isinstance(failed, list):
        raise DynSymError(f"failed must be a list, got {failed!r}")
    if not isinstance(model, Model):
        raise DynSymError(f"cannot report on {type(model).__name__}: expected a model "
                          "(a mechanical system, a circuit, a Lie-Poisson system, ...)")
    return section_blocks(model.report_title(), model.report_sections(), wanted=wanted,
                          budget=budget, analysis=analysis, failed=failed, progress=progress,
                          labels=TITLES)

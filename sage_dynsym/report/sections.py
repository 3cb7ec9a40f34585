r"""
The sections of a report and its default budget

What the command line offers (``--sections``, ``--budget``) is defined
here, apart from :mod:`sage_dynsym.report.writer` which computes them:
this module does not load Sage, so ``sage-dynsym --help`` and argument
errors answer at once.

EXAMPLES::

    sage: from sage_dynsym.report.sections import SECTIONS, DEFAULT_BUDGET
    sage: list(SECTIONS)[:3], DEFAULT_BUDGET
    (['lagrangian', 'equations', 'routh'], 100000)
"""

__all__ = ['DEFAULT_BUDGET', 'SECTIONS', 'TITLES', 'ANALYSIS_SECTIONS']

#: Default size budget of one report section: the largest number of
#: polynomial terms a section may create (estimated before it does).
DEFAULT_BUDGET = 100_000

#: The sections of a report, in the order they are printed.
SECTIONS = {
    'lagrangian': "the Lagrangian (mechanical systems; linear circuits, loop method)",
    'equations': "the Lagrange equations",
    'routh': "the Routh function and equations for the cyclic coordinates",
    'stationary': "stationary motions or equilibria with their stability",
    'hamiltonian': "the Hamiltonian (Dirac's scheme for a singular Lagrangian)",
    'mixed_potential': "the Brayton-Moser mixed potential of a circuit",
    'state_equations': "the state equations of a circuit",
    'lyapunov': "dP/dt along the state equations of a circuit",
    'stability': "stability of the free linear circuit (characteristic polynomial, "
                 "Lienard-Chipart conditions)",
    'casimirs': "the Casimir functions of a Lie-Poisson system",
    'integrals': "polynomial first integrals of degree <= 2 of a Lie-Poisson system",
}

#: The name of each section in the line of a section asked for that a
#: model does not have.
TITLES = {
    'lagrangian': "Lagrangian", 'equations': "Equations", 'routh': "Routh function",
    'stationary': "Stationary motions", 'hamiltonian': "Hamiltonian",
    'mixed_potential': "Mixed potential", 'state_equations': "State equations",
    'lyapunov': "dP/dt", 'stability': "Stability", 'casimirs': "Casimirs",
    'integrals': "Polynomial first integrals",
}

#: The sections that are analysis (left out by ``analysis=False``, the
#: command line's ``--no-analysis``).
ANALYSIS_SECTIONS = ('stationary', 'lyapunov', 'stability', 'integrals')

r"""
Reports of models: the characteristic functions, equations and analysis of
a model as plain text with LaTeX

- :mod:`~sage_dynsym.report.sections` -- the sections a report offers and
  its default size budget (what the command line shows; no Sage);
- :mod:`~sage_dynsym.report.writer` -- :func:`report`: the sections each
  kind of model names (:meth:`~sage_dynsym.dynamics.model.Model.report_sections`),
  each estimated against the budget before it is computed;
  :func:`~sage_dynsym.report.writer.report_blocks` gives them one by one,
  as each is computed.

The names are imported on first use, so that the command line answers
``--help`` without loading Sage.

EXAMPLES::

    sage: from sage_dynsym.report import report, SECTIONS
    sage: 'stationary' in SECTIONS
    True
"""
from ..errors import lazy_face

from .sections import DEFAULT_BUDGET, SECTIONS, ANALYSIS_SECTIONS

_SOURCE = {
    'report': '.writer', 'report_blocks': '.writer',
    # the size estimates live with what they estimate; importable from here
    # as in earlier versions
    'polynomial_terms': '..algebra.size', 'determinant_terms': '..algebra.size',
    'lagrangian_estimate': '..mechanics.report', 'circuit_estimate': '..circuits.report',
    'equations_estimate': '..dynamics.lagrangian_report',
    'characteristic_estimate': '..dynamics.lagrangian_report',
}

__all__ = ['DEFAULT_BUDGET', 'SECTIONS', 'ANALYSIS_SECTIONS']
__all__ += list(_SOURCE)

__getattr__, __dir__ = lazy_face(__name__, _SOURCE)
del lazy_face

r"""
Reports of models: the characteristic functions, equations and analysis of
a model as plain text with LaTeX

- :mod:`~sage_dynsym.report.sections` -- the sections a report offers and
  its default size budget (what the command line shows; no Sage);
- :mod:`~sage_dynsym.report.writer` -- :func:`report`, each section
  estimated against the budget before it is computed.

The names are imported on first use, so that the command line answers
``--help`` without loading Sage.

EXAMPLES::

    sage: from sage_dynsym.report import report, SECTIONS
    sage: 'stationary' in SECTIONS
    True
"""
import importlib

from .sections import DEFAULT_BUDGET, SECTIONS, ANALYSIS_SECTIONS

_SOURCE = {name: '.writer' for name in (
    'report', 'polynomial_terms', 'determinant_terms', 'lagrangian_estimate',
    'circuit_estimate', 'equations_estimate', 'characteristic_estimate')}

__all__ = ['DEFAULT_BUDGET', 'SECTIONS', 'ANALYSIS_SECTIONS'] + list(_SOURCE)


def __getattr__(name):
    if name not in _SOURCE:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = getattr(importlib.import_module(_SOURCE[name], __name__), name)
    globals()[name] = value
    return value


def __dir__():
    return sorted(set(globals()) | set(__all__))

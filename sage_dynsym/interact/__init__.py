r"""
Interactive pages for Jupyter worksheets (SageMath kernel)

System builder, equations explorer and stability explorer; see
:mod:`sage_dynsym.interact.pages`, :mod:`sage_dynsym.interact.builder`,
:mod:`sage_dynsym.interact.forms` and :mod:`sage_dynsym.interact.stability`.
"""
# Sage's symbolic functions, Maxima and coercions need the whole library initialised
# (the package's face loads it lazily, only when a name is used)
import sage.all
del sage  # imported for its effect alone: no name of this module
from .forms import available_forms, derive, derivation_latex
from .builder import SystemBuilder
from .stability import StabilityStudy
from .pages import equations_explorer, system_builder

__all__ = ['available_forms', 'derive', 'derivation_latex', 'SystemBuilder', 'StabilityStudy',
           'equations_explorer', 'system_builder']

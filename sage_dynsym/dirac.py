r"""
Deprecated alias of :mod:`sage_dynsym.dynamics.dirac`: the module's earlier name,
which warns and gives that module itself.
"""
import importlib
import sys
import warnings

NEW = "sage_dynsym.dynamics.dirac"
warnings.warn(f"{__name__} is deprecated: import {NEW} instead",
              DeprecationWarning, stacklevel=2)
sys.modules[__name__] = importlib.import_module(NEW)

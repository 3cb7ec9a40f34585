r"""
Deprecated alias of :mod:`sage_dynsym.dynamics.dirac`: the module's earlier name,
which warns and gives that module itself.
"""
from sage_dynsym.errors import moved_module

moved_module(__name__, "sage_dynsym.dynamics.dirac")

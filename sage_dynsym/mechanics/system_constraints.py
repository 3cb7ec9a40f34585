r"""
Deprecated alias of :mod:`sage_dynsym.mechanics.constraint_set`: the module's earlier name,
which warns and gives that module itself.
"""
from sage_dynsym.errors import moved_module

moved_module(__name__, "sage_dynsym.mechanics.constraint_set")

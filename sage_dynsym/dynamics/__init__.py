r"""
Characteristic functions and equations: the Lagrangian and the Routh
function, the natural form and the structured Lagrange equations, the
Hamiltonian and Dirac's scheme, Poisson brackets, and the common interface
of models.
"""
# Sage's symbolic functions, Maxima and coercions need the whole library initialised
# (the package's face loads it lazily, only when a name is used)
import sage.all
del sage  # imported for its effect alone: no name of this module

__all__ = []

r"""
Characteristic functions and equations: the Lagrangian and the Routh
function, the natural form and the structured Lagrange equations, the
Hamiltonian and Dirac's scheme, Poisson brackets, and the common interface
of models.
"""

r"""
Momenta, energy and the Legendre transform of a Lagrangian

Functions of a :class:`~sage_dynsym.dynamics.lagrangian.Lagrangian`: the
generalized momenta `p_i = \partial L/\partial \dot q_i`
(:func:`generalized_momenta`), the generalized energy or Jacobi integral
(:func:`energy`) and the Legendre transform (:func:`legendre`), which gives
the :class:`~sage_dynsym.dynamics.hamiltonian.Hamiltonian` (with Dirac's
scheme for a singular Lagrangian). The Lagrangian's methods of the same
names call them.

EXAMPLES::

    sage: from sage_dynsym import Lagrangian
    sage: from sage_dynsym.dynamics.legendre import generalized_momenta, energy, legendre
    sage: x, dx, m, k = var('x dx m k')
    sage: L = Lagrangian(m*dx^2/2 - k*x^2/2, [x])
    sage: generalized_momenta(L), energy(L), legendre(L).expr()
    ([dx*m], 1/2*dx^2*m + 1/2*k*x^2, 1/2*k*x^2 + 1/2*p_x^2/m)
"""
from ..errors import ModelError
from .hamiltonian import Hamiltonian

__all__ = ['generalized_momenta', 'energy', 'legendre']


def generalized_momenta(lagrangian):
    r"""
    The expressions `p_i = \partial L / \partial \dot q_i` of ``lagrangian``.

    EXAMPLES::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.dynamics.legendre import generalized_momenta
        sage: x, dx, m, e, A = var('x dx m e A')
        sage: generalized_momenta(Lagrangian(m*dx^2/2 + e*A*x*dx, [x]))
        [A*e*x + dx*m]
    """
    expr = lagrangian.expr()
    return [expr.diff(v) for v in lagrangian.velocities()]


def energy(lagrangian):
    r"""
    The generalized energy (Jacobi integral)
    `h = \sum \dot q_i \partial L/\partial \dot q_i - L` of ``lagrangian``;
    for a natural Lagrangian `h = T_2 - T_0 - U` (expanded).

    EXAMPLES::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.dynamics.legendre import energy
        sage: x, dx, m, k = var('x dx m k')
        sage: energy(Lagrangian(m*dx^2/2 - k*x^2/2, [x]))
        1/2*dx^2*m + 1/2*k*x^2
    """
    expr = lagrangian.expr()
    h = sum(v * p for v, p in zip(lagrangian.velocities(), generalized_momenta(lagrangian)))
    return (h - expr).expand() if lagrangian.is_natural() else h - expr


def legendre(lagrangian):
    r"""
    The Hamiltonian of ``lagrangian`` by the Legendre transform; for a
    singular Lagrangian the result carries Dirac's constraint analysis (see
    :class:`~sage_dynsym.dynamics.hamiltonian.Hamiltonian`).

    Constraints are refused: holonomic ones are first eliminated by
    :meth:`~sage_dynsym.dynamics.lagrangian.Lagrangian.reduce`, and with
    velocity constraints the equations in independent speeds apply
    (:mod:`~sage_dynsym.dynamics.reduced`).

    EXAMPLES::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.dynamics.legendre import legendre
        sage: x, dx, m, k = var('x dx m k')
        sage: legendre(Lagrangian(m*dx^2/2 - k*x^2/2, [x])).expr()
        1/2*k*x^2 + 1/2*p_x^2/m

    TESTS::

        sage: legendre(Lagrangian(m*dx^2/2, [x], constraints=[x - var('t')]))
        Traceback (most recent call last):
        ...
        ModelError: constraints: the Legendre transform of a constrained Lagrangian is not supported: reduce it to independent coordinates first (reduce)
    """
    if lagrangian.nonholonomic_constraints():
        raise ModelError("the Legendre transform of a Lagrangian with velocity constraints is "
                         "not supported: use reduced_equations() (Kane's equations in "
                         "independent speeds)", entry="nonholonomic")
    if lagrangian.constraints():
        raise ModelError("the Legendre transform of a constrained Lagrangian is not "
                         "supported: reduce it to independent coordinates first "
                         "(reduce)", entry="constraints")
    return Hamiltonian(lagrangian)

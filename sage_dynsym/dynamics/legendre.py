r"""
Momenta, energy and the Legendre transform of a Lagrangian

:class:`LegendreTransform` is a base class of
:class:`~sage_dynsym.dynamics.lagrangian.Lagrangian`: the generalized
momenta `p_i = \partial L/\partial \dot q_i`, the generalized energy
(Jacobi integral) and when it is conserved, whether the Legendre transform
is invertible, and the Hamiltonian
(:class:`~sage_dynsym.dynamics.hamiltonian.Hamiltonian`, with Dirac's
scheme for a singular Lagrangian).

EXAMPLES::

    sage: from sage_dynsym import Lagrangian
    sage: x, dx, m, k = var('x dx m k')
    sage: L = Lagrangian(m*dx^2/2 - k*x^2/2, [x])
    sage: L.generalized_momenta(), L.energy(), L.hamiltonian().expr()
    ([dx*m], 1/2*dx^2*m + 1/2*k*x^2, 1/2*k*x^2 + 1/2*p_x^2/m)
"""
from sage.symbolic.ring import SR

from ..errors import ModelError
from ..symbols import t
from ..numerics.expressions import symbols_and_functions
from .hamiltonian import Hamiltonian
from .natural_form import natural_form, is_singular

__all__ = ['LegendreTransform']


class LegendreTransform:
    r"""
    The momenta, energy and Hamiltonian of a
    :class:`~sage_dynsym.dynamics.lagrangian.Lagrangian` (a base class of
    it, see the module documentation).

    EXAMPLES: see :class:`~sage_dynsym.dynamics.lagrangian.Lagrangian`.
    """

    def generalized_momenta(self):
        r"""
        The expressions `p_i = \partial L / \partial \dot q_i`.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, dx, m, e, A = var('x dx m e A')
            sage: Lagrangian(m*dx^2/2 + e*A*x*dx, [x]).generalized_momenta()
            [A*e*x + dx*m]
        """
        return [self._expr.diff(v) for v in self._velocities]

    def energy(self):
        r"""
        The generalized energy (Jacobi integral)
        `h = \sum \dot q_i \partial L/\partial \dot q_i - L`;
        conserved when `L` does not depend on `t` and there are no
        non-potential forces. For a natural Lagrangian `h = T_2 - T_0 - U`.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, dx, m, k = var('x dx m k')
            sage: Lagrangian(m*dx^2/2 - k*x^2/2, [x]).energy()
            1/2*dx^2*m + 1/2*k*x^2
        """
        h = sum(v * p for v, p in zip(self._velocities, self.generalized_momenta()))
        return (h - self._expr).expand() if self.is_natural() else h - self._expr

    def is_singular(self):
        r"""
        Whether `\det(\partial^2 L/\partial \dot q^2) = 0` identically: then
        the Legendre transform is not invertible and
        :meth:`hamiltonian` applies Dirac's scheme.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, y, dx, dy = var('x y dx dy')
            sage: Lagrangian(x*dy - y*dx - x^2 - y^2, [x, y]).is_singular()
            True
            sage: Lagrangian(dx^2 + dy^2, [x, y]).is_singular()
            False
        """
        return is_singular(self.mass_matrix())

    def _conserved_energy(self):
        r"""
        The generalized energy (:meth:`energy`) when it is an integral of
        the motion -- no explicit time in `L` or the constraints, no
        dissipation, no generalized forces --, else ``None``; what
        ``simulate(...).energy_drift()`` measures.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, dx, c = var('x dx c')
            sage: Lagrangian(dx^2/2 - x^2/2, [x])._conserved_energy()
            1/2*dx^2 + 1/2*x^2
            sage: Lagrangian(dx^2/2 - x^2/2, [x], dissipation=c*dx^2/2)._conserved_energy() is None
            True

        From the decomposition of a mechanical system, `T_2 - T_0 - U`::

            sage: from sage_dynsym import load
            sage: from sage_dynsym.description import example_path
            sage: load(example_path('spherical_pendulum.yaml')).lagrangian()._conserved_energy()
            1/2*dpsi^2*l^2*m*sin(theta)^2 + 1/2*dtheta^2*l^2*m + g*l*m*cos(theta)
        """
        if self._structure is not None:
            # h = T_2 - T_0 - U from the decomposition: nothing expanded (a
            # memoized walk looks for t: large models share subexpressions)
            A, A1, A0 = self._structure
            if str(t) in symbols_and_functions(list(A.list()) + list(A1) + [A0])[0]:
                return None
            energy = natural_form(A, [0] * len(self._velocities), -A0, self._velocities)
        elif self._expr.has(t):
            return None
        else:
            energy = None
        if (not self._dissipation.is_zero() or any(not f.is_zero() for f in self._forces)
                or any(SR(f).has(t) for f in self._constraints)):
            return None
        return self.energy() if energy is None else energy

    def hamiltonian(self):
        r"""
        The Hamiltonian by the Legendre transform; for a singular Lagrangian
        the result carries Dirac's constraint analysis.

        See :class:`~sage_dynsym.dynamics.hamiltonian.Hamiltonian`.

        EXAMPLES::

            sage: from sage_dynsym import Lagrangian
            sage: x, dx, m, k = var('x dx m k')
            sage: Lagrangian(m*dx^2/2 - k*x^2/2, [x]).hamiltonian().expr()
            1/2*k*x^2 + 1/2*p_x^2/m

        TESTS::

            sage: Lagrangian(m*dx^2/2, [x], constraints=[x - var('t')]).hamiltonian()
            Traceback (most recent call last):
            ...
            ModelError: constraints: the Legendre transform of a constrained Lagrangian is not supported: reduce it to independent coordinates first (reduce)
        """
        if self._constraints:
            raise ModelError("the Legendre transform of a constrained Lagrangian is not "
                             "supported: reduce it to independent coordinates first "
                             "(reduce)", entry="constraints")
        return Hamiltonian(self)

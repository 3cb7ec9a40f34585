"""
Identities of the equations of motion.

1. Hamilton's equations are equivalent to Lagrange's: at random states
   ``(q, dq)`` with ``p = dL/d(dq)``, Hamilton's ``dq/dt = dH/dp`` returns
   ``dq`` and ``dp/dt = -dH/dq`` equals the time derivative of ``dL/d(dq)``
   along the motion whose accelerations solve the Lagrange equations; the
   Hamiltonian equals the Jacobi integral ``sum dq dL/d(dq) - L``.
2. A conservative system integrated numerically (``solve_ivp``, DOP853,
   rtol = atol = 1e-12) from its Lagrange equations keeps the Jacobi integral
   to 1e-9 relative; for these time-independent systems the integral is
   also ``T - U`` (kinetic energy minus force function).

The accelerations are obtained here from the equations ``E_i`` themselves
(``E`` is linear in ``ddq``: ``E = M ddq + b``), not from the package's
solved forms.
"""
import math
import sys
from pathlib import Path

import numpy as np
import pytest
from scipy.integrate import solve_ivp

sys.path.insert(0, str(Path(__file__).resolve().parent))
from test_mechanics_crosscheck import CASES, sage_system  # noqa: E402

from sage.all import SR, fast_callable, RDF  # noqa: E402

# Regular systems with at most 3 coordinates (the Legendre transform of
# bigger random chains is slow); the energy test takes bodies with at most
# two rotations about different axes (no gimbal lock on the way).
HAMILTON_CASES = ['spherical_pendulum', 'random17-seed1040-2bodies',
                  'random10-seed1024-3bodies', 'random03-seed1011-4bodies']
ENERGY_CASES = ['spherical_pendulum', 'random17-seed1040-2bodies',
                'random11-seed1031-4bodies', 'two_roots_and_slider']


class NumericLagrangian:
    """Fast numerical functions of one sage_dynsym Lagrangian."""

    def __init__(self, name):
        desc = CASES[name]
        self.system = sage_system(desc)
        self.L = self.system.lagrangian()
        self.q, self.dq, self.ddq = self.L.coordinates(), self.L.velocities(), self.L.accelerations()
        self.n = len(self.q)
        self.values = desc['values']
        self.params = [SR.var(p) for p in desc['parameters']]
        state = self.q + self.dq
        L = self.L.expr()
        E = self.L.lagrange_equations()
        zero = {a: 0 for a in self.ddq}
        p = [L.diff(v) for v in self.dq]
        self._M = self._compile([[e.diff(a) for a in self.ddq] for e in E], state)
        self._b = self._compile([e.subs(zero) for e in E], state)
        self._p = self._compile(p, state)
        self._dp_dq = self._compile([[pi.diff(x) for x in self.q] for pi in p], state)
        self._h = self._compile([sum(v * pi for v, pi in zip(self.dq, p)) - L], state)
        self._T_minus_U = self._compile(
            [self.system.kinetic_energy() - self.system.force_function()], state)

    def _compile(self, exprs, variables):
        variables = list(variables) + self.params
        def compile_one(e):
            return fast_callable(SR(e), vars=variables, domain=RDF)
        if isinstance(exprs[0], list):
            fs = [[compile_one(e) for e in row] for row in exprs]
            return lambda *x: np.array([[f(*x) for f in row] for row in fs])
        fs = [compile_one(e) for e in exprs]
        return lambda *x: np.array([f(*x) for f in fs])

    def _args(self, q, dq):
        return list(q) + list(dq) + [self.values[str(p)] for p in self.params]

    def mass_matrix(self, q, dq):
        return self._M(*self._args(q, dq))

    def accelerations(self, q, dq):
        args = self._args(q, dq)
        return np.linalg.solve(self._M(*args), -self._b(*args))

    def momenta(self, q, dq):
        return self._p(*self._args(q, dq))

    def momenta_rate(self, q, dq):
        """d/dt dL/d(dq) along the Lagrangian motion through (q, dq)."""
        args = self._args(q, dq)
        return self._dp_dq(*args) @ dq + self._M(*args) @ self.accelerations(q, dq)

    def jacobi_integral(self, q, dq):
        return float(self._h(*self._args(q, dq))[0])

    def T_minus_U(self, q, dq):
        return float(self._T_minus_U(*self._args(q, dq))[0])


def _random_state(rng, n):
    return rng.uniform(-math.pi, math.pi, n), rng.uniform(-2, 2, n)


@pytest.mark.parametrize('name', HAMILTON_CASES)
def test_hamilton_equations_equal_lagrange_equations(name):
    N = NumericLagrangian(name)
    H = N.L.hamiltonian()
    assert [str(x) for x in H.coordinates()] == [str(x) for x in N.q]
    assert [str(x) for x in H.momenta()] == ['p_' + str(x) for x in N.q]
    variables = list(H.coordinates()) + list(H.momenta()) + N.params
    rhs = [(fast_callable(SR(a), vars=variables, domain=RDF),
            fast_callable(SR(b), vars=variables, domain=RDF)) for a, b in H.equations()]
    H_num = fast_callable(SR(H.expr()), vars=variables, domain=RDF)
    rng = np.random.default_rng(7)
    checked = 0
    while checked < 4:
        q, dq = _random_state(rng, N.n)
        if abs(np.linalg.det(N.mass_matrix(q, dq))) < 1e-6:
            continue   # too close to a singular configuration
        p = N.momenta(q, dq)
        args = list(q) + list(p) + [N.values[str(x)] for x in N.params]
        dq_H = np.array([f(*args) for f, _ in rhs])
        dp_H = np.array([g(*args) for _, g in rhs])
        dp_L = N.momenta_rate(q, dq)
        scale = 1 + np.max(np.abs(dp_L))
        assert np.allclose(dq_H, dq, rtol=1e-9, atol=1e-9), f"{name}: dH/dp {dq_H} != dq {dq}"
        assert np.allclose(dp_H, dp_L, rtol=1e-8, atol=1e-8 * scale), (
            f"{name}: -dH/dq {dp_H} != d/dt dL/d(dq) {dp_L} at q = {q}, dq = {dq}")
        h = N.jacobi_integral(q, dq)
        assert math.isclose(H_num(*args), h, rel_tol=1e-9, abs_tol=1e-9), (
            f"{name}: H = {H_num(*args)} != sum dq dL/d(dq) - L = {h}")
        checked += 1


@pytest.mark.parametrize('name', ENERGY_CASES)
def test_energy_integral_is_conserved(name):
    N = NumericLagrangian(name)
    n = N.n

    def rhs(_, x):
        return np.concatenate([x[n:], N.accelerations(x[:n], x[n:])])

    rng = np.random.default_rng(11)
    q0, dq0 = _random_state(rng, n)
    if name == 'spherical_pendulum':   # away from theta = 0, with a real swing
        q0, dq0 = np.array([0.2, 1.1]), np.array([1.5, -0.4])
    eigenvalues = np.linalg.eigvalsh(N.mass_matrix(q0, dq0))
    assert eigenvalues[0] > 1e-2 * eigenvalues[-1], (
        f"{name}: kinetic energy not positive definite at the start: {eigenvalues}")
    h0 = N.jacobi_integral(q0, dq0)
    assert math.isclose(N.T_minus_U(q0, dq0), h0, rel_tol=1e-12, abs_tol=1e-12)
    sol = solve_ivp(rhs, (0.0, 4.0), np.concatenate([q0, dq0]), method='DOP853',
                    rtol=1e-12, atol=1e-12, dense_output=False)
    assert sol.success, sol.message
    drift = max(abs(N.jacobi_integral(x[:n], x[n:]) - h0) for x in sol.y.T) / abs(h0)
    moved = np.max(np.abs(sol.y[:n, -1] - q0))
    assert moved > 0.1, "the test motion should not stay near its start"
    assert drift < 1e-9, f"{name}: relative drift of the energy integral {drift}"

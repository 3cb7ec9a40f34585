"""The modified Routh-Lyapunov method in two positional coordinates: a
particle in an axisymmetric field V1(r) + V2(z) in cylindrical coordinates
(the angle cyclic). Each family of invariant manifolds is checked
independently: it is a common level of the energy and of the energy of the
vertical motion (integrals written here from mechanics), and a numerically
integrated motion started on it stays on it."""
import numpy as np
import pytest
from scipy.integrate import solve_ivp
from sage.all import SR, var, function, sqrt

from sage_dynsym import Lagrangian
from sage_dynsym.analysis.modified_routh import ModifiedRouthLyapunov
from sage_dynsym.errors import AnalysisError

r, z, phi, dr, dz, dphi = var('r z phi dr dz dphi')
E, C1, p = var('_E _C1 p_phi')


def families(V1, V2):
    L = Lagrangian((dr**2 + r**2 * dphi**2 + dz**2) / 2 - V1 - V2, [r, z, phi])
    return ModifiedRouthLyapunov(L.routh([phi])).invariant_manifolds()


def test_families_are_levels_of_the_energies():
    V1, V2 = function('V1')(r), function('V2')(z)
    fams = families(V1, V2)
    assert len(fams) == 4                       # the signs of dr and dz
    signs = set()
    for fam in fams:
        assert [eq.lhs() for eq in fam] == [dr, dz]
        vr, vz = (eq.rhs() for eq in fam)
        # the energy of the Routh system (p_phi = r^2 dphi) and that of z
        energy = (vr**2 + vz**2) / 2 + p**2 / (2 * r**2) + V1 + V2
        vertical = vz**2 / 2 + V2
        assert (energy - E).simplify_full() == 0
        assert (vertical - C1).simplify_full() == 0
        at = {E: 10, C1: 5, p: 1, r: 1}
        signs.add(tuple(bool(v.subs({V1: 0, V2: 0}).subs(at) > 0) for v in (vr, vz)))
    assert len(signs) == 4


def test_a_motion_started_on_a_family_stays_on_it():
    # V = r^2/2 + z^2 (a harmonic trap), p_phi = 1/2
    fams = families(r**2 / 2, z**2)
    values = {E: 3, C1: 1, p: SR(1) / 2}
    for fam in fams:
        vr, vz = (eq.rhs().subs(values) for eq in fam)
        phi_r = lambda a, b: float(vr.subs({r: a, z: b}))
        phi_z = lambda a, b: float(vz.subs({r: a, z: b}))
        r0, z0 = 1.0, 0.3
        x0 = [r0, z0, phi_r(r0, z0), phi_z(r0, z0)]

        def rhs(t, x):
            # Lagrange's equations, written here: r'' = p^2/r^3 - r, z'' = -2 z
            return [x[2], x[3], 0.25 / x[0]**3 - x[0], -2 * x[1]]

        sol = solve_ivp(rhs, (0, 0.15), x0, rtol=1e-11, atol=1e-12, dense_output=True)
        for t in np.linspace(0, 0.15, 7):
            a, b, va, vb = sol.sol(t)
            assert abs(va - phi_r(a, b)) < 1e-7
            assert abs(vb - phi_z(a, b)) < 1e-7


def test_degeneracy_conditions_are_the_gradient_of_the_energy_equation():
    V1, V2 = function('V1')(r), function('V2')(z)
    L = Lagrangian((dr**2 + r**2 * dphi**2 + dz**2) / 2 - V1 - V2, [r, z, phi])
    MR = ModifiedRouthLyapunov(L.routh([phi]))
    H = MR.energy_equation().lhs()
    conds = MR.degeneracy_conditions()
    for q, c in zip([r, z], conds):
        assert (c.lhs() + H.diff(q)).simplify_full() == 0
    # the gradient condition of f = grad s
    assert len(conds) == 3


def test_not_separable_is_said():
    k = var('k')
    L = Lagrangian((dr**2 + r**2 * dphi**2 + dz**2) / 2 + k / sqrt(r**2 + z**2), [r, z, phi])
    with pytest.raises(AnalysisError, match="do not separate"):
        ModifiedRouthLyapunov(L.routh([phi])).invariant_manifolds()


def test_old_import_path():
    from sage_dynsym.analysis.stationary import ModifiedRouthLyapunov as old
    assert old is ModifiedRouthLyapunov

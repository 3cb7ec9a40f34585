"""Integrals on an invariant level: the Goryachev-Chaplygin top (A = B = 4C,
centre of mass on the first principal axis) has a cubic integral on the
level (M, gamma) = 0 of the area integral (Goryachev 1900, Chaplygin 1901;
Borisov & Mamaev, Rigid Body Dynamics, ch. 2). The time derivative of the
integral found is checked here with the Euler-Poisson equations written out
by hand: it is a polynomial multiple of (M, gamma)."""
import pytest
from sage.all import QQ, PolynomialRing, SR, var

from sage_dynsym import LiePoissonSystem
from sage_dynsym.errors import AnalysisError

M1, M2, M3, g1, g2, g3 = var('M1 M2 M3 gamma1 gamma2 gamma3')
eps = var('eps')
AREA = M1 * g1 + M2 * g2 + M3 * g3


def euler_poisson_derivative(F):
    """dF/dt for H = (M1^2 + M2^2 + 4 M3^2)/2 + eps gamma1:
    M' = M x omega + gamma x (eps, 0, 0), gamma' = gamma x omega,
    omega = (M1, M2, 4 M3)."""
    w = (M1, M2, 4 * M3)
    M, g, r = (M1, M2, M3), (g1, g2, g3), (eps, 0, 0)
    cross = lambda a, b: (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                          a[0] * b[1] - a[1] * b[0])
    dM = [x + y for x, y in zip(cross(M, w), cross(g, r))]
    dg = list(cross(g, w))
    return sum(F.diff(v) * d for v, d in zip(M + g, dM + dg)).expand()


def test_goryachev_chaplygin_cubic_integral_on_the_zero_area_level():
    S = LiePoissonSystem('e3', (M1**2 + M2**2 + 4 * M3**2) / 2 + eps * g1)
    assert S.polynomial_integrals(3, new_only=True) == []      # none off the level
    (F,) = S.polynomial_integrals(3, new_only=True, levels={AREA: 0})
    R = PolynomialRing(QQ, 'eps, M1, M2, M3, gamma1, gamma2, gamma3')
    dF = R(euler_poisson_derivative(F))
    quotient, remainder = dF.quo_rem(R(AREA))
    assert remainder == 0 and quotient != 0        # conserved on the level only
    # the classical form: M3 (M1^2 + M2^2) - eps M1 gamma3, up to a factor
    classical = M3 * (M1**2 + M2**2) - eps * M1 * g3
    assert R(euler_poisson_derivative(classical)).quo_rem(R(AREA))[1] == 0
    ratio = (F / classical).simplify_full()
    assert ratio.is_constant() and ratio != 0


def test_level_of_a_casimir_and_bad_arguments():
    S = LiePoissonSystem('e3', (M1**2 + M2**2 + 4 * M3**2) / 2 + eps * g1)
    # modulo gamma^2 = 1 the Casimir is a constant: not in the basis
    basis = S.polynomial_integrals(2, levels={g1**2 + g2**2 + g3**2: 1})
    assert all((b - (g1**2 + g2**2 + g3**2)).expand() != 0 for b in basis)
    for bad in ([M1 == 0], None, 'yes', 1):
        with pytest.raises(AnalysisError, match="conditions must be True or False"):
            S.polynomial_integrals(2, conditions=bad)
    with pytest.raises(AnalysisError, match="not invariant"):
        S.polynomial_integrals(2, levels={M3: 0})
    with pytest.raises(AnalysisError, match="levels must be a dict"):
        S.polynomial_integrals(2, levels=[AREA])

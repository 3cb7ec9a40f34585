"""
The census of the relative equilibria of the asymmetric heavy top (the
Euler--Poisson equations on e(3)*, sage_dynsym.analysis.leaf_census) against
the classical parametrization of its permanent rotations.

H = 1/2 sum M_i^2 / I_i + (gamma, r) with I = (1, 2, 3) and r = (1, 1, 1) (and with
I = (2, 3, 4), r = (1, -1, 2)), on the levels (M, gamma) = c, (gamma, gamma) = 1:
M' = M x w + gamma x r, gamma' = gamma x w
with w = I^-1 M. A relative equilibrium with c != 0 is a permanent rotation about
the vertical, w = nu gamma (nu != 0), and then gamma x (r - nu^2 I gamma) = 0, so
r = (nu^2 I + mu) gamma: the axes of the permanent rotations lie on Staude's cone
(O. Staude, Ueber permanente Rotationsaxen bei der Bewegung eines schweren Koerpers
um einen festen Punkt, J. reine angew. Math. 113 (1894) 318-334; E. Leimanis, The
General Problem of the Motion of Coupled Rigid Bodies about a Fixed Point,
Springer, 1965, on the permanent rotations). With t = mu / nu^2:

    gamma = (I + t)^-1 r / nu^2,  nu^2 = N(t) = |(I + t)^-1 r|  (|gamma| = 1),
    c = nu (I gamma, gamma) = sign(nu) f(t),  f(t) = sum I_i r_i^2 / (I_i + t)^2 / N(t)^(3/2),

one relative equilibrium for each real t != -I_i with f(t) = |c| (f > 0: nu has the
sign of c). f tends to 0 at t = +-oo and to +oo at the poles t = -I_i, so for every
c != 0 there are two on the outer intervals, and two more on a middle interval
where |c| exceeds its least value there: the bifurcation values are the local
minima of f on the two bounded intervals between the poles. Here they are found
by a scan of t with SciPy (brentq, minimize_scalar), independently of the
elimination of the census, and the
stability of each rotation is decided with NumPy: the energy-Casimir condition by
the inertia of the bordered Hessian of H - l1 (M, gamma) - l2 (gamma, gamma) (the
second variation is definite on the tangent space of the leaf iff the bordered
matrix [[B, G^T], [G, 0]] has n eigenvalues of the sign and k of the other: Gould,
"On practical conditions for the existence and uniqueness of solutions to the
general equality quadratic programming problem", Math. Programming 32 (1985) 90-99),
and the first approximation by the eigenvalues of the linearization on the leaf. The
count stable in first approximation also changes where two of those eigenvalues
collide: those levels are located along the parametrization (the discriminant of
q, p(z) = q(z^2) the characteristic polynomial on the leaf, changes sign) and
compared with the refined cells (cells(first_approximation=True)).
"""
import numpy as np
import pytest
from scipy.optimize import brentq, minimize_scalar

from sage.all import var, QQ
from sage_dynsym.lie import LiePoissonSystem

from test_leaf_census import e3_leaf, simple_and_imaginary

#: (moments of inertia, centre of mass): the body of the module documentation, and
#: another one with the centre of mass off the diagonal
TOP = (np.array([1.0, 2.0, 3.0]), np.array([1.0, 1.0, 1.0]))
BODIES = [TOP, (np.array([2.0, 3.0, 4.0]), np.array([1.0, -1.0, 2.0]))]


def staude_f(t, body=TOP):
    """|c| on the permanent rotation of parameter t (see the module documentation)."""
    inertia, centre = body
    n = np.sqrt(np.sum(centre**2 / (inertia + t)**2))
    return np.sum(inertia * centre**2 / (inertia + t)**2) / n**1.5


def staude_rotation(t, sign, body=TOP):
    """The point (M, gamma) of the permanent rotation of parameter t, nu of the given sign."""
    inertia, centre = body
    nu = sign * np.sqrt(np.sqrt(np.sum(centre**2 / (inertia + t)**2)))
    gamma = centre / (inertia + t) / nu**2
    return np.concatenate([inertia * nu * gamma, gamma])


def _scans(body, samples=4000):
    """Values of t on each interval between the poles t = -I_i and to infinity, dense
    near the poles (where f grows like |t + I_i|^(-1/2)) and far out (where f decays
    like |t|^(-1/2))."""
    poles = sorted(-body[0])
    near = np.geomspace(1e-10, 1, samples)
    scans = [poles[0] - np.geomspace(1e-10, 1e12, samples)[::-1]]
    for a, b in zip(poles, poles[1:]):
        scans.append(np.unique(np.concatenate([a + near * (b - a) / 2, b - near * (b - a) / 2])))
    scans.append(poles[-1] + np.geomspace(1e-10, 1e12, samples))
    return scans


def staude_minima(body=TOP):
    """The local minima of f on the bounded intervals between its poles."""
    poles = sorted(-body[0])
    return sorted(minimize_scalar(staude_f, bounds=(a + 1e-9, b - 1e-9), args=(body,),
                                  method='bounded', options={'xatol': 1e-13}).fun
                  for a, b in zip(poles, poles[1:]))


def staude_points(level, body=TOP):
    """The relative equilibria on the level (M, gamma) = level != 0, (gamma, gamma) = 1:
    the roots t of f(t) = |level|, bracketed by sign changes on the scans."""
    found = []
    for ts in _scans(body):
        values = np.array([staude_f(t, body) for t in ts]) - abs(level)
        for i in np.nonzero(np.sign(values[:-1]) != np.sign(values[1:]))[0]:
            t = brentq(lambda s: staude_f(s, body) - abs(level), ts[i], ts[i + 1], xtol=1e-15)
            found.append(staude_rotation(t, np.sign(level), body))
    return found


def leaf_spectrum(x, body):
    """NumPy's eigenvalues of the linearization on the leaf at the point x."""
    inertia, centre = body
    return e3_leaf(x, np.diag(1 / inertia), lambda g: centre, np.zeros((3, 3)))[0]


def leaf_discriminant(t, body=TOP):
    """On the rotation of parameter t: the discriminant of q, p(z) = q(z^2) the
    characteristic polynomial of the linearization on the leaf (NumPy's eigenvalues),
    relative to the square of the middle coefficient: zero where two roots collide."""
    p = np.real(np.poly(leaf_spectrum(staude_rotation(t, 1, body), body)))
    return (p[2]**2 - 4 * p[4]) / p[2]**2


def staude_collisions(body=TOP, top=20):
    """The levels |c| < top where two roots of the linearization on the leaf of a
    permanent rotation collide (where the stability in first approximation may
    change), by sign changes of leaf_discriminant on the scans."""
    found = []
    for ts in _scans(body, 2000):
        ts = ts[[staude_f(t, body) < top for t in ts]]     # (also away from the poles)
        d = np.array([leaf_discriminant(t, body) for t in ts])
        for i in np.nonzero(np.sign(d[:-1]) != np.sign(d[1:]))[0]:
            if ts[i + 1] - ts[i] < 1:           # not across a gap left by the filter
                t = brentq(leaf_discriminant, ts[i], ts[i + 1], args=(body,), xtol=1e-15)
                found.append(staude_f(t, body))
    return sorted(found)


def bordered_definite(x, body=TOP):
    """Whether the second variation of H - l1 (M, gamma) - l2 (gamma, gamma) is definite on
    the tangent space of the leaf at x: the inertia of the bordered Hessian."""
    inertia, centre = body
    m, g = np.split(x, 2)
    gradients = np.array([np.concatenate([g, m]), np.concatenate([np.zeros(3), 2 * g])])
    l1, l2 = np.linalg.lstsq(gradients.T, np.concatenate([m / inertia, centre]), rcond=None)[0]
    second = np.block([[np.diag(1 / inertia), -l1 * np.eye(3)],
                       [-l1 * np.eye(3), -2 * l2 * np.eye(3)]])
    bordered = np.block([[second, gradients.T], [gradients, np.zeros((2, 2))]])
    eig = np.linalg.eigvalsh(bordered)
    assert np.min(np.abs(eig)) > 1e-9           # regular: the verdict is not at a boundary
    positive = int(np.sum(eig > 0))
    return positive in (6, 2)       # definite: 6 + 2 or 2 + 6 eigenvalues of the two signs


def verdicts(level, body=TOP):
    """(count, stable, stable or stable in first approximation) on the level, by NumPy."""
    points = staude_points(level, body)
    stable = [bordered_definite(x, body) for x in points]
    linear = [simple_and_imaginary(leaf_spectrum(x, body)) for x in points]
    return len(points), sum(stable), sum(s or a for s, a in zip(stable, linear))


def test_staude_parametrization_is_on_the_leaf():
    """The parametrized rotations are relative equilibria on their levels."""
    for inertia, centre in BODIES:
        for t in (-5.0, -2.6, -1.5, 0.3):
            for sign in (1, -1):
                x = staude_rotation(t, sign, (inertia, centre))
                m, g = np.split(x, 2)
                w = m / inertia
                assert np.allclose(np.cross(m, w) + np.cross(g, centre), 0, atol=1e-12)
                assert np.allclose(np.cross(g, w), 0) and abs(g @ g - 1) < 1e-12
                assert abs(m @ g - sign * staude_f(t, (inertia, centre))) < 1e-12


@pytest.mark.slow       # the census and its refinement take about two minutes per body
@pytest.mark.parametrize("body", BODIES, ids=["I=123,r=111", "I=234,r=1-12"])
def test_asymmetric_heavy_top_census(body):
    M1, M2, M3, g1, g2, g3, c = var('M1 M2 M3 gamma1 gamma2 gamma3 c')
    inertia, centre = [[QQ(int(a)) for a in v] for v in body]
    H = sum(m**2 / i for m, i in zip([M1, M2, M3], inertia)) / 2 + \
        sum(r * g for r, g in zip(centre, [g1, g2, g3]))
    census = LiePoissonSystem('e3', H).equilibrium_census([c], levels=[c, 1])
    minima = staude_minima(body)
    values = [float(v) for v in census.bifurcation_values()]
    assert values == pytest.approx(sorted([-v for v in minima] + minima), rel=1e-9)
    cells = census.cells()
    assert len(cells) == 5
    rng = np.random.default_rng(3)
    for cell in cells:
        level = float(cell.sample()[c])
        count, stable, either = verdicts(level, body)
        assert (cell.count(), cell.stable_count(), cell.families()) == (count, stable, [])
        assert cell.stable_count(first_approximation=True) == either
        # the count and the energy-Casimir count are constant on the cell
        lo, hi = [None if b is None else float(b) for b in cell.bounds()]
        lo, hi = (hi - 3 if lo is None else lo), (lo + 3 if hi is None else hi)
        for other in rng.uniform(lo, hi, size=2):
            other += 0.5 if abs(other) < 0.1 else 0     # (c = 0: the rotations stop)
            assert verdicts(other, body)[:2] == (count, stable)
    # 2 rotations near c = 0, 4 beyond the first minimum, 6 beyond the second
    assert [x.count() for x in cells] == [6, 4, 2, 4, 6]
    # the first approximation: its boundaries are the degenerate rotations and the
    # collisions of roots on the leaf; its count at random levels inside each cell
    collisions = staude_collisions(body)
    assert len(collisions) == 2
    values = [float(v) for v in census.bifurcation_values(first_approximation=True)]
    assert values == pytest.approx(sorted(v * s for v in minima + collisions for s in (1, -1)),
                                   rel=1e-9)
    for cell in census.cells(first_approximation=True):
        lo, hi = [None if b is None else float(b) for b in cell.bounds()]
        lo, hi = (hi - 3 if lo is None else lo), (lo + 3 if hi is None else hi)
        for other in rng.uniform(lo + (hi - lo) / 50, hi - (hi - lo) / 50, size=2):
            other += 0.5 if abs(other) < 0.1 else 0
            assert verdicts(other, body) == (cell.count(), cell.stable_count(),
                                       cell.stable_count(first_approximation=True))

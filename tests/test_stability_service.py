"""The one stability service, LinearSystem.stability: its cases partition
the parameter space (checked at random points, exactly one case holds
off the boundaries), and each case agrees with numpy eigenvalues of the
first-order matrix written here by hand; literature values for the
sleeping top (Maxwell / Klein-Sommerfeld: M3^2 > 4 A m g l), gyroscopic
stabilization and first-order circuits."""
import random

import numpy as np
import pytest
from sage.all import SR, QQ, matrix, identity_matrix, diagonal_matrix, var

from sage_dynsym.analysis.linear import LinearSystem, linearize
from sage_dynsym.errors import AnalysisError

CLASS = {'asymptotically stable': 'asymptotic', 'stable': 'marginal',
         'stable in first approximation': 'marginal', 'unstable': 'unstable'}


def top_real_part(A, point):
    A = np.array([[complex(SR(x).subs(point)) for x in row] for row in A.rows()])
    return max(np.linalg.eigvals(A).real)


def numeric_class(A, point):
    top = top_real_part(A, point)
    if top < -1e-6:
        return 'asymptotic'
    if top > 1e-6:
        return 'unstable'
    return 'marginal' if abs(top) < 1e-9 else None


def holding_cases(v, point):
    from sage_dynsym.algebra.conditions import region_holds
    return [c.verdict() for c in v.cases() if region_holds(c.region(), point)]


def check_partition(v, A, sample, n=40, seed=0):
    rng = random.Random(seed)
    seen = set()
    for _ in range(n):
        point = sample(rng)
        if any(SR(r.lhs() - r.rhs()).subs(point).is_zero()
               for rs in v.boundaries().values() for r in rs):
            continue            # on a boundary: no case, by definition
        cases = holding_cases(v, point)
        expected = numeric_class(A, point)
        if expected is None:
            continue
        assert len(cases) == 1, (point, cases)
        assert CLASS[cases[0]] == expected, (point, cases, expected)
        seen.add(cases[0])
    return seen


# the heavy symmetric top, Euler-Poisson equations on e(3)
M1, M2, M3, g1, g2, g3 = var('M1 M2 M3 gamma1 gamma2 gamma3')
A_, C_, m, g, l = var('A C m g l')
EULER_POISSON = [g * l * m * g2 + (A_ - C_) * M2 * M3 / (A_ * C_),
                 -g * l * m * g1 - (A_ - C_) * M1 * M3 / (A_ * C_),
                 M3 * g2 / C_ - M2 * g3 / A_, -M3 * g1 / C_ + M1 * g3 / A_]


def sleeping_top():
    return linearize(EULER_POISSON, {M1: 0, M2: 0, g1: 0, g2: 0}, [M1, M2, g1, g2])


def test_sleeping_top_band_is_unstable():
    # the band 2 A m g l gamma3 (..) < M3^2 < 4 A m g l gamma3 was no case;
    # at A = 1, C = 3/2, m g l = 1, M3^2 = 3.8 a root has real part +0.22
    Ls = sleeping_top()
    v = Ls.stability(positive=[A_, C_, m, g, l])
    point = {A_: 1, C_: QQ(3) / 2, m: 1, g: 1, l: 1, g3: 1, M3: SR(QQ(38) / 10).sqrt()}
    top = top_real_part(Ls.jacobian(), point)
    assert top == pytest.approx(0.2236, abs=1e-3)
    assert v.at(point) == 'unstable'
    # the exact boundary M3^2 = 4 A m g l gamma3: just above it, stable
    above = {**point, M3: SR(QQ(41) / 10).sqrt()}
    assert abs(top_real_part(Ls.jacobian(), above)) < 1e-9
    assert v.at(above) == 'stable in first approximation'
    boundary = 4 * A_ * m * g * l * g3 - M3 ** 2
    for case in v.cases():
        for alt in case.region():
            for r in alt:
                assert bool(((r.lhs() - r.rhs()) / boundary).simplify_full().is_constant()), r


def test_sleeping_top_partition_against_numpy():
    Ls = sleeping_top()
    v = Ls.stability(positive=[A_, C_, m, g, l])

    def sample(rng):
        return {A_: QQ(rng.randint(5, 30)) / 10, C_: QQ(rng.randint(5, 30)) / 10,
                m: 1, g: QQ(rng.randint(5, 20)) / 10, l: 1,
                g3: QQ(rng.choice([-1, 1]) * rng.randint(1, 10)) / 10,
                M3: QQ(rng.randint(-40, 40)) / 10}
    assert check_partition(v, Ls.jacobian(), sample) == {'stable in first approximation',
                                                         'unstable'}


def test_from_equations_does_not_double_the_gyroscopic_matrix():
    # x'' - g y' - a x = 0, y'' + g x' - b y = 0: stable iff g^2 > (sqrt a + sqrt b)^2
    x, y, a, b, gg = var('x y a b g')
    Ls = LinearSystem.from_equations(identity_matrix(2), [[0, -gg], [gg, 0]],
                                     diagonal_matrix([-a, -b]), variables=[x, y])
    v = Ls.stability(positive=[a, b, gg])
    assert v.at({a: 1, b: 4, gg: QQ(31) / 10}) == 'stable in first approximation'
    assert v.at({a: 1, b: 4, gg: QQ(29) / 10}) == 'unstable'

    def sample(rng):
        return {a: QQ(rng.randint(1, 40)) / 10, b: QQ(rng.randint(1, 40)) / 10,
                gg: QQ(rng.randint(1, 60)) / 10}
    seen = check_partition(v, Ls.jacobian(), sample, n=60)
    assert seen == {'stable in first approximation', 'unstable'}


def test_first_order_circuit():
    # a series RLC circuit L i' = -R i - u, C u' = i: asymptotically stable iff R > 0
    i, u, L, R, C = var('i u L R C')
    Ls = LinearSystem([i, u], J=[[-R, -1], [1, 0]], B=diagonal_matrix([L, C]))
    v = Ls.stability(positive=[L, C])

    def sample(rng):
        return {L: QQ(rng.randint(1, 30)) / 10, C: QQ(rng.randint(1, 30)) / 10,
                R: QQ(rng.randint(-30, 30)) / 10}
    assert check_partition(v, Ls.jacobian(), sample) == {'asymptotically stable', 'unstable'}


def test_ignorable_coordinate_and_with_respect_to():
    # a free body with a damper and a spring on a second coordinate: its
    # position is ignorable, its velocity decays
    x, y, c, k = var('x y c k')
    Ls = LinearSystem([x, y], M=identity_matrix(2), S=diagonal_matrix([c, c]),
                      W=diagonal_matrix([0, k]))
    v = Ls.stability(positive=[c, k])
    assert v.verdict() == 'asymptotically stable'
    assert 'rates of x' in v.reason()
    # all the variables: a zero root for all parameters
    w = Ls.stability(positive=[c, k], with_respect_to=[x, y])
    assert w.verdict() == 'stable in first approximation'
    with pytest.raises(AnalysisError, match="y enters the linear equations"):
        Ls.stability(with_respect_to=[x])


def bisect_threshold(stable, lo, hi, steps=60):
    # the change of numerical stability between lo and hi
    assert stable(lo) != stable(hi)
    for _ in range(steps):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if stable(mid) == stable(lo) else (lo, mid)
    return (lo + hi) / 2


def test_gyroscopic_threshold_is_the_denested_biquadratic_root():
    x, y, a, b, gg = var('x y a b g')
    Ls = LinearSystem.from_equations(identity_matrix(2), [[0, -gg], [gg, 0]],
                                     diagonal_matrix([-a, -b]), variables=[x, y])
    v = Ls.stability(positive=[a, b, gg])
    (crit,) = v.critical_values(gg)
    assert bool((crit - a.sqrt() - b.sqrt()).simplify_full() == 0)
    # numerically, at a = 2, b = 3: the eigenvalues leave the imaginary axis
    A = Ls.jacobian()
    point = {a: 2, b: 3}
    found = bisect_threshold(lambda s: top_real_part(A, {**point, gg: s}) < 1e-9, 0.5, 10)
    assert found == pytest.approx(float(crit.subs(point)), rel=1e-9)


def test_jeffcott_whirl_speed_positive_only():
    # Jeffcott rotor with external damping c_e and rotating (internal)
    # damping c_i: unstable above Omega = omega_n (1 + c_e/c_i)
    # (Crandall 1983; Genta, Dynamics of Rotating Systems, 2005, sec. 8.3)
    x, y, mm, ce, ci, k, Om = var('x y m c_e c_i k Omega')
    Ls = LinearSystem.from_equations(mm * identity_matrix(2), (ce + ci) * identity_matrix(2),
                                     [[k, ci * Om], [-ci * Om, k]], variables=[x, y])
    v = Ls.stability(positive=[mm, ce, ci, k, Om])
    (crit,) = v.critical_values(Om)
    assert bool((crit**2 - k / mm * (1 + ce / ci)**2).simplify_full() == 0)
    assert crit.subs({k: 2, mm: 3, ce: 1, ci: 5}) > 0
    # not declared positive: the mirror value -omega_n (1 + c_e/c_i) is critical too
    w = Ls.stability(positive=[mm, ce, ci, k])
    assert len(w.critical_values(Om)) == 2


def test_sleeping_top_critical_spin():
    Ls = sleeping_top()
    v = Ls.stability(positive=[A_, C_, m, g, l])
    values = {A_: 1, C_: QQ(3) / 2, m: 1, g: 1, l: 1, g3: 1}
    # M3^2 = 4 A m g l gamma3 = 4
    assert v.critical_values(M3, values=values) == [-2, 2]


def test_heavy_top_report_has_no_gap():
    # the Lie-Poisson heavy top (examples/heavy_top_e3.yaml): its stationary
    # family M1 = M2 = gamma1 = gamma2 = 0 is stable (Routh-Lyapunov) where
    # M3^2 > 4 A m g l gamma3 and unstable (first approximation) in all the
    # rest, the former unreported band included (numpy: +0.22 at M3^2 = 3.8)
    from sage_dynsym import load
    from sage_dynsym.description import example_path
    top = load(example_path('heavy_top_e3.yaml'))
    M3s = var('M3')
    family = next(s for s in top.stationary_solutions([M3s])
                  if s.dimension() == 2 and set(s.point()) >= {M1, M2, g1, g2}
                  and all(s.point()[x] == 0 for x in (M1, M2, g1, g2)))
    v = family.stability()
    point = {A_: 1, C_: QQ(3) / 2, m: 1, g: 1, l: 1, g3: 1}
    assert v.at({**point, M3: SR(QQ(38) / 10).sqrt()}) == 'unstable'
    assert v.at({**point, M3: SR(QQ(41) / 10).sqrt()}) == 'stable'
    assert top_real_part(sleeping_top().jacobian(),
                         {**point, M3: SR(QQ(38) / 10).sqrt()}) > 0.2


def test_gyroscopic_threshold_with_symbolic_stiffnesses():
    # x'' - g y' + k1 x = 0, y'' + g x' + k2 y = 0: the flutter boundary
    # g^4 + 2 (k1 + k2) g^2 + (k1 - k2)^2 = 0 has the denested root
    # sqrt(-k1) + sqrt(-k2) (Thomson-Tait; Merkin, sec. 6.5); with values
    # k1 = -1, k2 = -4 the critical rate is 1 + 2 = 3
    from sage_dynsym.algebra.radicals import roots_in_radicals
    x, y, k1, k2, gg = var('x y k1 k2 g')
    Ls = LinearSystem.from_equations(identity_matrix(2), [[0, -gg], [gg, 0]],
                                     diagonal_matrix([k1, k2]), variables=[x, y])
    flutter = Ls.stability(positive=[gg]).boundaries()['flutter']
    (f,) = [r.lhs() - r.rhs() for r in flutter if (r.lhs() - r.rhs()).has(gg)]
    roots = roots_in_radicals(f, gg)
    assert any(str(r) in ('sqrt(-k1) + sqrt(-k2)', 'sqrt(-k2) + sqrt(-k1)') for r in roots)
    v = Ls.stability(positive=[gg])
    assert v.critical_values(gg, values={k1: -1, k2: -4}) == [3]


def test_partition_covers_a_mass_of_unknown_sign():
    # m x'' + c x' + k x = 0 with no declared sign: every point off the
    # boundaries is in exactly one case, m < 0 included (there the first
    # approximation: all of m, c, k of one sign), against numpy
    x, mm, c, k = var('x m c k')
    Ls = LinearSystem([x], M=[[mm]], S=[[c]], W=[[k]])
    v = Ls.stability()

    def sample(rng):
        return {s: QQ(rng.choice([-1, 1]) * rng.randint(1, 30)) / 10 for s in (mm, c, k)}
    seen = check_partition(v, Ls.jacobian(), sample, n=60)
    assert seen == {'asymptotically stable', 'unstable'}
    assert v.at({mm: -1, c: -2, k: -3}) == 'asymptotically stable'

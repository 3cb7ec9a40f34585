"""The Whipple bicycle with the benchmark's steer axis tilt lam = pi/10
exactly (cos(pi/10) = sqrt(2 sqrt 5 + 10)/4 in its number field): the
weave and capsize speeds from LinearSystem.stability().critical_values(v),
to 20 digits, against an independent computation in 200-bit arithmetic
from the closed form of Meijaard, Papadopoulos, Ruina and Schwab, Proc. R.
Soc. A 463 (2007), Appendix A (written out in test_whipple_bicycle.py):
the weave speed is where the Hurwitz determinant a3 a2 a1 - a4 a1^2 -
a3^2 a0 of the quartic det(M s^2 + v C1 s + g K0 + v^2 K2) vanishes, the
capsize speed where a0 = det(g K0 + v^2 K2) does (Table 2 (a): 4.2924,
6.0243 m/s)."""
import pytest
from sage.all import SR, RealField, pi

from sage_dynsym import load, linearize, LinearSystem
from sage_dynsym.description import example_path
from test_whipple_bicycle import BENCHMARK, closed_form, WEAVE_SPEED, CAPSIZE_SPEED

RF = RealField(200)


def hand_coefficients(speed):
    # the closed form in 200-bit arithmetic, the 2x2 determinant by hand
    p = {k: RF(x) for k, x in BENCHMARK.items() if k != 'lam'}
    p['lam'] = RF(pi) / 10
    X = closed_form(p)
    M, C1, K0, K2 = ([[RF(X[key][i, j]) for j in range(2)] for i in range(2)]
                     for key in ('M', 'C1', 'K0', 'K2'))
    g = p['g']
    # entries a + b s + c s^2 of M s^2 + v C1 s + g K0 + v^2 K2
    e = [[(g * K0[i][j] + speed ** 2 * K2[i][j], speed * C1[i][j], M[i][j])
          for j in range(2)] for i in range(2)]

    def mul(u, w):
        out = [RF(0)] * 5
        for k, x in enumerate(u):
            for l, y in enumerate(w):
                out[k + l] += x * y
        return out
    d = [x - y for x, y in zip(mul(e[0][0], e[1][1]), mul(e[0][1], e[1][0]))]
    return d                                    # a0, a1, a2, a3, a4


def hurwitz3(speed):
    a0, a1, a2, a3, a4 = hand_coefficients(speed)
    return a3 * a2 * a1 - a4 * a1 ** 2 - a3 ** 2 * a0


def capsize(speed):
    return hand_coefficients(speed)[0]


def bisect(f, lo, hi):
    lo, hi = RF(lo), RF(hi)
    assert (f(lo) > 0) != (f(hi) > 0)
    for _ in range(190):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if (f(mid) > 0) == (f(lo) > 0) else (lo, mid)
    return (lo + hi) / 2


@pytest.mark.slow
def test_weave_and_capsize_speeds_with_lam_pi_over_10_exactly():
    S = load(example_path('whipple_bicycle.yaml'))
    lean, steer, v = SR.var('lean'), SR.var('steer'), SR.var('v')
    linear = linearize(S, S.operating_point('upright'), coordinates=[lean, steer])
    values = {SR.var(k): x for k, x in BENCHMARK.items()}
    assert values[SR.var('lam')] == pi / 10
    exact = LinearSystem([lean, steer], *(X.subs(values) for X in
                                         (linear.M(), linear.S(), linear.W())))
    verdict = exact.stability(positive=[v])
    weave, capsize_speed = verdict.critical_values(v)
    expected_weave, expected_capsize = bisect(hurwitz3, 4, 5), bisect(capsize, 5.5, 6.5)
    assert abs(RF(weave) - expected_weave) < RF(10) ** -20
    assert abs(RF(capsize_speed) - expected_capsize) < RF(10) ** -20
    # and the paper's 14 digits
    assert abs(float(weave) - WEAVE_SPEED) < 1e-13
    assert abs(float(capsize_speed) - CAPSIZE_SPEED) < 1e-13
    assert verdict.at({v: 5}) == 'asymptotically stable'
    assert verdict.at({v: 4}) == 'unstable' and verdict.at({v: 7}) == 'unstable'

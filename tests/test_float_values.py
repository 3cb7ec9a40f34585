"""Float parameter values are the exact decimals they print as: the
Whipple bicycle with the values of Table 1 of Meijaard et al. (2007) typed
as floats (lam = 0.3141592653589793) substitutes and linearizes about the
upright operating point (the constraint cos^2 + sin^2 = 1 holds exactly),
giving exactly the matrices of the symbolic linearization with the same
decimals substituted afterwards (the other order of the two steps)."""
from fractions import Fraction

import pytest

from sage.all import SR, QQ

from sage_dynsym import load, linearize
from sage_dynsym.description import example_path
from test_whipple_bicycle import BENCHMARK


@pytest.mark.slow
def test_bicycle_with_float_values_linearizes_like_the_exact_path():
    S = load(example_path('whipple_bicycle.yaml'))
    floats = {k: float(v) for k, v in BENCHMARK.items() if k != 'lam'}
    floats['lam'] = 0.3141592653589793
    coordinates = [SR.var('lean'), SR.var('steer')]
    linear = linearize(S.subs(floats), S.subs(floats).operating_point('upright'),
                       coordinates=coordinates)
    # the decimals as printed, by Python's fractions (not the package)
    decimals = {SR.var(k): QQ(Fraction(repr(v))) for k, v in floats.items()}
    assert decimals[SR.var('lam')] == QQ(3141592653589793) / 10 ** 16
    symbolic = linearize(S, S.operating_point('upright'), coordinates=coordinates)
    for name in ('M', 'S', 'W'):
        got = getattr(linear, name)()
        want = getattr(symbolic, name)().subs(decimals)
        for a, b in zip(got.list(), want.list()):
            assert (SR(a) - SR(b)).simplify_trig().is_zero(), (name, a, b)

"""Roots in radicals (sage_dynsym.algebra.radicals) of random linear and
quadratic polynomials with symbolic coefficients, against NumPy's roots of
the same polynomial at random values of the parameters."""
import random
import sys
from pathlib import Path

import numpy as np
import pytest
from sage.all import SR, var

from sage_dynsym.algebra.radicals import roots_in_radicals

sys.path.insert(0, str(Path(__file__).resolve().parent))
from reference.numerics import same_multiset  # noqa: E402

p, k, l = var('p k l')


def random_coefficient(rng):
    # a small polynomial in k and l, sometimes over a square denominator
    c = sum(rng.randint(-3, 3) * m for m in (1, k, l, k * l, k**2, l**2))
    return c / l**2 if rng.random() < 0.2 else c


@pytest.mark.parametrize("seed", range(6))
def test_roots_agree_with_numpy(seed):
    rng = random.Random(seed)
    checked = 0
    while checked < 10:
        degree = rng.choice([1, 2])
        a = [random_coefficient(rng) for _ in range(degree + 1)]
        if SR(a[-1]).is_zero():
            continue
        f = sum(c * p**i for i, c in enumerate(a))
        roots = roots_in_radicals(f, p)
        assert len(roots) == degree and all(not r.has(p) for r in roots)
        for _ in range(3):
            at = {k: rng.uniform(0.5, 2), l: rng.uniform(0.5, 2)}
            top = complex(SR(a[-1]).subs(at))
            if abs(top) < 1e-6:
                continue
            expected = np.roots([complex(SR(c).subs(at)) for c in reversed(a)])
            got = [complex(SR(r).subs(at)) for r in roots]
            scale = max(1.0, float(np.max(np.abs(expected))))
            assert same_multiset(expected, got, rel=1e-9, scale=scale), (f, at, roots)
        checked += 1


@pytest.mark.parametrize("seed", range(4))
def test_cubic_and_quartic_roots_agree_with_numpy(seed):
    # Cardano and Ferrari (and biquadratics, denested), against np.roots
    rng = random.Random(100 + seed)
    checked = 0
    while checked < 6:
        degree = rng.choice([3, 4])
        a = [random_coefficient(rng) for _ in range(degree + 1)]
        if degree == 4 and rng.random() < 0.4:
            a[1] = a[3] = 0                      # biquadratic
        if SR(a[-1]).is_zero():
            continue
        f = sum(c * p**i for i, c in enumerate(a))
        roots = roots_in_radicals(f, p)
        assert len(roots) == degree and all(not r.has(p) for r in roots)
        at = {k: rng.uniform(0.5, 2), l: rng.uniform(0.5, 2)}
        if abs(complex(SR(a[-1]).subs(at))) < 1e-3:
            continue
        expected = list(np.roots([complex(SR(c).subs(at)) for c in reversed(a)]))
        got = [complex(SR(r).subs(at)) for r in roots]
        scale = max(1.0, float(np.max(np.abs(expected))))
        assert same_multiset(got, expected, rel=1e-6, scale=scale), (f, at, roots)
        checked += 1


def test_denested_biquadratic_threshold():
    # g^4 - 2(a + b) g^2 + (a - b)^2 = 0 at g = sqrt(a) + sqrt(b), by hand
    a, b, g = var('a b g')
    roots = roots_in_radicals(g**4 - 2 * (a + b) * g**2 + (a - b)**2, g)
    assert any(bool((r - (a.sqrt() + b.sqrt())).simplify_full() == 0) for r in roots)
    assert all('sqrt(' not in str(r).replace('sqrt(a)', '').replace('sqrt(b)', '')
               for r in roots)

"""The algebra of trigonometric polynomials against outside references.

- the representatives of TrigAlgebra are Singular's normal forms modulo the
  ideal (c_i^2 + s_i^2 - 1) (a Groebner basis), computed by Singular itself;
- an element and its symbolic form agree with the original expression
  evaluated in floating point by Python's ``math`` at random points;
- two fractions are equal in TrigFractions exactly when the expressions
  agree numerically at random points;
- the Sage category checks (TestSuite) hold on algebras with sums of angles,
  functions of time and atoms.
"""
import math
import random

import pytest
from sage.all import SR, QQ, cos, sin, sqrt, var
from sage.misc import sage_unittest

from sage_dynsym.algebra.trig_algebra import TrigAlgebra
from sage_dynsym.algebra.trigonometric import NotPolynomial

a, b, m, w, t = var("a b m w t")


def _random_expression(rng, angles, symbols, terms=6):
    factors = [cos(x) for x in angles] + [sin(x) for x in angles] + list(symbols)
    total = SR(0)
    for _ in range(terms):
        term = SR(QQ((rng.randint(-9, 9), rng.randint(1, 4))))
        for _ in range(rng.randint(0, 4)):
            term *= rng.choice(factors)
        total += term
    return total


def _numeric(expr, point):
    # an independent evaluation: the expression's tree with Python floats
    return float(SR(expr).subs(point).n(100))


@pytest.mark.parametrize("seed", range(8))
def test_representatives_are_singular_normal_forms(seed):
    rng = random.Random(seed)
    A = TrigAlgebra([a, b], [m])
    R = A.cover_ring()
    circle = R.ideal([c.lift() ** 2 + s.lift() ** 2 - 1 for c, s in map(A.trig, [a, b])])
    e = _random_expression(rng, [a, b], [m], terms=8)
    x = A(e)
    # the same polynomial, converted by Sage's own conversion of the cover ring
    names = {cos(a): SR.var("dynsymcos0"), cos(b): SR.var("dynsymcos1"),
             sin(a): SR.var("dynsymsin0"), sin(b): SR.var("dynsymsin1")}
    assert x.lift() == circle.reduce(R(e.subs(names)))


@pytest.mark.parametrize("seed", range(8))
def test_elements_agree_with_the_expression_numerically(seed):
    rng = random.Random(100 + seed)
    angles = [a, a - b, w * t]
    A = TrigAlgebra(angles, [m, w, t])
    e = _random_expression(rng, angles, [m], terms=7)
    x = A(e)
    for _ in range(3):
        point = {v: rng.uniform(-3, 3) for v in (a, b, m, w, t)}
        value = _numeric(e, point)
        assert math.isclose(_numeric(SR(x), point), value, rel_tol=1e-9, abs_tol=1e-9)


@pytest.mark.parametrize("seed", range(4))
def test_multiples_and_sums_of_angles_are_expanded(seed):
    rng = random.Random(200 + seed)
    A = TrigAlgebra([a, b], [m])
    K = A.fraction_field()
    e = m * sin(2 * a - b) * cos(3 * a) + cos(a + b) ** 2
    f = m * (sin(a - 2 * b) / cos(-a - b) + 1 / sin(3 * b))
    x, y = A(e), K(f)
    for _ in range(3):
        point = {a: rng.uniform(0.1, 1.0), b: rng.uniform(0.1, 1.0), m: rng.uniform(0.5, 2)}
        assert math.isclose(_numeric(SR(x), point), _numeric(e, point), rel_tol=1e-9)
        assert math.isclose(_numeric(SR(y), point), _numeric(f, point), rel_tol=1e-9)


def test_zero_modulo_the_circle_is_recognised():
    A = TrigAlgebra([a, b], [m])
    e = (cos(a) ** 2 + sin(a) ** 2 - 1) * (m * sin(b) ** 3 + cos(a) * cos(b) + 7)
    assert not A(e.expand())
    assert A(cos(a) ** 4 - sin(a) ** 4) == A(cos(a) ** 2 - sin(a) ** 2)
    # sin(-a) and cos(-a) share the pair of a
    assert A(cos(-a) * cos(a) - sin(-a) * sin(a)) == 1


def test_fractions_are_equal_exactly_when_the_functions_are():
    K = TrigAlgebra([a], [m]).fraction_field()
    pairs = [(sin(a) ** 2 / (1 - cos(a)), 1 + cos(a), True),
             (m / sin(a) + cos(a) / (m * sin(a)), (m ** 2 + cos(a)) / (m * sin(a)), True),
             (sin(a) / cos(a), cos(a) / sin(a), False)]
    rng = random.Random(7)
    for left, right, equal in pairs:
        point = {a: rng.uniform(0.1, 1.4), m: rng.uniform(0.5, 2)}
        numerically = math.isclose(_numeric(left, point), _numeric(right, point), rel_tol=1e-12)
        assert numerically == equal
        assert (K(left) == K(right)) == equal


def test_what_is_not_polynomial_is_refused():
    A = TrigAlgebra([a], [m])
    for e in (1 / m, sqrt(m), cos(a / 2), cos(m * a), sin(b)):
        with pytest.raises(NotPolynomial):
            A(e)


@pytest.mark.parametrize("angles, symbols, atoms", [
    ([a], [], []),
    ([a, a - b], [m], []),
    ([w * t], [w, t, m], [sqrt(2)]),
])
def test_category_checks(angles, symbols, atoms):
    A = TrigAlgebra(angles, symbols, atoms)
    sage_unittest.TestSuite(A).run(raise_on_failure=True)
    sage_unittest.TestSuite(A.fraction_field()).run(raise_on_failure=True)

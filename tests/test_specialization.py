"""
Decisions taken at random values of the parameters, checked against the
exact computation over the field of the parameters.

Over `QQ(a, b)` the package decides primality (``prime_by_specialization``),
membership in a prime (``membership_by_specialization``,
``AlgebraicSolution.contains``) and whether an ideal is the whole ring
(``is_unit_ideal``) without Groebner bases over that field, which take
minutes on the large systems. Here the ideals are small, so the same
questions are answered exactly by Singular over the field -- normal forms,
``minAssGTZ`` and the reduced basis -- and the answers must agree.
"""
import random

import pytest
from sage.all import QQ, SR, Frac, PolynomialRing, TermOrder, var
from sage.libs.singular.function import singular_function, lib as singular_lib

from sage_dynsym.algebra.decomposition import (is_unit_ideal, membership_by_specialization,
                                               prime_by_specialization)
from sage_dynsym.algebra.solving import solve_exactly

singular_lib('primdec.lib')
minimal_associated_char = singular_function('minAssChar')

K = Frac(PolynomialRing(QQ, 'a, b'))
a, b = K.gens()
R = PolynomialRing(K, 'x, y, z')
x, y, z = R.gens()


def _random_polynomial(rng, terms=3, degree=2):
    monomials = [x**i * y**j * z**k for i in range(degree + 1) for j in range(degree + 1)
                 for k in range(degree + 1) if 0 < i + j + k <= degree]
    coefficients = [1, -1, 2, a, b, a - b, a * b + 1, 1 / (a + 2)]
    return sum(rng.choice(coefficients) * m for m in rng.sample(monomials, terms)) + \
        rng.choice([0, 1, a, -b])


@pytest.mark.parametrize("seed", range(8))
def test_membership_agrees_with_the_normal_form_over_the_field(seed):
    rng = random.Random(seed)
    # a prime: the graph of a map (x, y) -> z, with a curve in the plane
    f, g = _random_polynomial(rng), _random_polynomial(rng)
    Q = R.ideal([z - f.subs(z=0), x**2 - a * y - g.subs(x=0, z=0)])
    member = membership_by_specialization(Q)
    inside = [Q.gens()[0] * _random_polynomial(rng), Q.gens()[1] * z + Q.gens()[0]]
    outside = [x - y, z + 1, Q.gens()[1] + 1]
    for h in inside + outside:
        assert member(h) == (Q.reduce(h) == 0), h


def test_membership_of_a_rational_multiple():
    Q = R.ideal([x**2 - a * y**3, z - b])
    member = membership_by_specialization(Q)
    assert member((x**2 - a * y**3) * (x + 1 / (a - b)))
    assert member((z - b) / (a**2 + 1))
    assert not member(x * y)
    assert not member(z - a)


@pytest.mark.parametrize("seed", range(8))
def test_primality_agrees_with_the_decomposition_over_the_field(seed):
    rng = random.Random(100 + seed)
    f, g = _random_polynomial(rng).subs(z=0), _random_polynomial(rng)
    # z given linearly (eliminated over QQ at the values drawn) over a curve
    # that is prime, or over its union with a line, which is not
    curve = x**2 - a * y - g.subs(x=0, z=0)
    for J in (R.ideal([z - f, curve]), R.ideal([z - f, curve * (y - b * x)])):
        # over the field: one minimal prime (characteristic sets), equal to J
        primes = [R.ideal(list(P)) for P in minimal_associated_char(J)]
        exact = len(primes) == 1 and all(J.reduce(h) == 0 for h in primes[0].gens())
        # a prime over the field may split at special values, never the other way
        assert not prime_by_specialization(J) or exact
        if not exact:
            assert not prime_by_specialization(J)


def test_a_prime_found_prime_in_most_draws():
    J = R.ideal([z - a * x * y, x**2 - (a - b) * y**3])
    assert sum(prime_by_specialization(J) for _ in range(20)) >= 18


def test_unit_ideal_from_the_basis_in_the_rings_order():
    for order in ('lex', 'degrevlex', TermOrder('degrevlex', 2) + TermOrder('lex', 1)):
        S = PolynomialRing(K, 'x, y, z', order=order)
        u, v, w = S.gens()
        assert is_unit_ideal(S.ideal([u * v - a, u, w]))
        assert not is_unit_ideal(S.ideal([u * v - a, w - b]))
        assert is_unit_ideal(S.ideal([S(1) / a]))
        assert not is_unit_ideal(S.ideal([S(0)]))
        # Sage's own comparison with the unit ideal, the reference
        for I in (S.ideal([u * v - a, u, w]), S.ideal([u * v - a, w - b])):
            assert is_unit_ideal(I) == I.is_one()


def test_contains_on_a_family_with_parameters_agrees_with_substitution():
    # x^2 - c y^3 = 0: an implicit curve over QQ(c); an expression vanishes
    # on it iff it does at the points (t^2 c, t^3 c) for every t
    xs, ys, c, t = var('x y c t')
    s = solve_exactly([xs**2 - c * ys**3], [xs, ys])[0]
    on_curve = {xs: c**2 * t**3, ys: c * t**2}
    for e in [(xs**2 - c * ys**3) * (xs + c), xs - c * ys, xs**2 * ys - c * ys**4,
              (xs**2 - c * ys**3) / (ys - c)]:
        expected = bool((SR(e).numerator().subs(on_curve)).expand().is_zero())
        assert s.contains(e) == expected, e

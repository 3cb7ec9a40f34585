"""One trigonometric algebra: the translation into polynomial systems, the
kinematics, the linear algebra and the spectrum read sines and cosines in the
same Sage parent, and the translation is right as a map of functions.

- the parent is ``TrigAlgebra`` keyed by its generators (UniqueRepresentation):
  the translation of equations, the kinematics computed in its ring, the
  fractions of the linear algebra and the atoms of the spectrum get the very
  object ``TrigAlgebra(angles, symbols, atoms)``, whatever the order in which
  the angles are met;
- random trigonometric expressions (multiple angles, sums of angles with a
  parameter, tangents, fractions, atoms such as sqrt(2), pi, cos(alpha)) go to
  the translation's fraction field, or the algebra, and back, and agree with
  the original evaluated numerically at random points;
- a random equation set with a known solution whose cosine and sine are
  rational (3/5, 4/5) is translated; the real solutions of the polynomial
  system (Singular's variety over the real algebraic numbers) map back, by
  q = atan2(s, c), to solutions of the original equations evaluated
  numerically, and the known solution is among them. Its equations vanish at
  that solution by construction with SymPy's own trigonometric expansion.
"""
import math
import random

import pytest
import sympy
from sage.all import AA, SR, QQ, cos, sin, tan, sqrt, pi, var

from sage_dynsym import load
from sage_dynsym.algebra.translation import Translation, ParameterAtoms
from sage_dynsym.algebra.trig_algebra import TrigAlgebra
from sage_dynsym.algebra.trig_linear import TrigFractionField
from sage_dynsym.analysis.spectrum import spectrum_regions
from sage_dynsym.description import example_path
from sage_dynsym.mechanics.kinematics import Kinematics

q, r, x, m, k, alpha, lam = var("q r x m k alpha lam")
psi, theta, l, g, dpsi, dtheta = var("psi theta l g dpsi dtheta")


def test_translation_kinematics_spectrum_and_linear_algebra_share_the_parent():
    S = load(example_path("spherical_pendulum.yaml"))
    L = S.lagrangian().expr()
    position = S.kinematics().mass_center_position(1).components(0)
    T = Translation([L.diff(theta)], [psi, theta], extra=[L] + list(position))
    A = TrigAlgebra([psi, theta], [dpsi, dtheta, g, l, m])
    assert T.algebra() is A
    # the kinematics computed in the translation's ring: its elements are the
    # algebra's, and the mass matrix is the textbook l^2 m diag(sin^2, 1)
    K = Kinematics(S, A.polynomial_ring())
    M, _, _ = K.body_decomposition(1)
    assert A(M[0][0]) == A(l ** 2 * m * sin(theta) ** 2)
    assert A(M[1][1]) == A(l ** 2 * m) and A(M[0][1]) == 0
    assert [A(c) for c in K.mass_center_position(1).components(0)] == [A(c) for c in position]
    # the spectrum's atoms and the translation of the same polynomial
    poly = lam ** 2 + k * cos(alpha) * lam + m
    B = TrigAlgebra([], [k, lam, m], [cos(alpha)])
    assert spectrum_regions(poly, lam).parameter_atoms().algebra() is B
    assert ParameterAtoms([poly], [lam]).algebra() is B
    assert Translation([poly], [lam]).algebra() is B
    # the linear algebra over trigonometric fractions, whatever the order in
    # which the angles are met
    for e in (m * cos(psi) / sin(theta), m * sin(theta) / cos(psi)):
        F = TrigFractionField([e]).fractions()
        assert F.algebra() is TrigAlgebra([theta, psi], [m, psi, theta])
        assert F is F.algebra().fraction_field()
    assert TrigAlgebra.for_expressions([m * cos(psi) * sin(theta)]) is \
        TrigAlgebra([psi, theta], [m, psi, theta])


def _random_expression(rng, fractions):
    angles = [cos(q), sin(q), cos(2 * q), sin(q - r), cos(q + r), sin(q - alpha),
              cos(3 * r + alpha)]
    others = [x, m, k, sqrt(2), pi, cos(alpha)]
    if fractions:
        angles += [tan(q), 1 / (2 + cos(r))]
        others += [1 / x, 1 / (m + x ** 2)]
    total = SR(0)
    for _ in range(rng.randint(2, 5)):
        term = SR(QQ((rng.randint(-9, 9), rng.randint(1, 5))))
        for _ in range(rng.randint(1, 3)):
            term *= rng.choice(angles + others)
        total += term
    return total


def _at(expr, point):
    return complex(SR(expr).subs(point).n(80))


def _random_point(rng):
    return {q: rng.uniform(-3, 3), r: rng.uniform(-3, 3), alpha: rng.uniform(-3, 3),
            x: rng.uniform(0.5, 2), m: rng.uniform(0.5, 2), k: rng.uniform(-2, 2)}


@pytest.mark.parametrize("seed", range(12))
def test_to_the_translation_and_back_is_the_same_function(seed):
    rng = random.Random(seed)
    e = _random_expression(rng, fractions=True)
    T = Translation([], [q, r, x], extra=[e])
    back = T.symbolic(T.fraction(e))
    for _ in range(3):
        point = _random_point(rng)
        assert abs(_at(back, point) - _at(e, point)) <= 1e-9 * (1 + abs(_at(e, point))), (e, back)


@pytest.mark.parametrize("seed", range(12))
def test_to_the_algebra_and_back_is_the_same_function(seed):
    rng = random.Random(1000 + seed)
    e = _random_expression(rng, fractions=False)
    A = Translation([e], [q, r]).algebra()
    back = SR(A(e))
    # the translation and the algebra give the same polynomial
    T = Translation([e], [q, r])
    assert A(T.symbolic(T.fraction(e))) == A(e)
    for _ in range(3):
        point = _random_point(rng)
        assert abs(_at(back, point) - _at(e, point)) <= 1e-9 * (1 + abs(_at(e, point))), (e, back)


def _sympy_value(expr, c0, s0, x0):
    # an independent evaluation: SymPy expands the multiple angles and sums,
    # then cos q, sin q are replaced by their exact values
    Q, X = sympy.symbols("q x")
    e = sympy.expand_trig(sympy.sympify(str(expr), locals={"q": Q, "x": X}))
    return sympy.nsimplify(sympy.simplify(e.subs({sympy.cos(Q): c0, sympy.sin(Q): s0, X: x0})))


def _random_equation(rng):
    parts = [cos(q), sin(q), sin(2 * q), cos(2 * q), x, x ** 2, x * sin(q)]
    total = SR(0)
    for _ in range(rng.randint(2, 3)):
        term = SR(QQ((rng.randint(-5, 5) or 1, rng.randint(1, 3))))
        for _ in range(rng.randint(1, 2)):
            term *= rng.choice(parts)
        total += term
    return total


@pytest.mark.parametrize("seed", range(6))
def test_real_solutions_of_the_polynomial_system_solve_the_equations(seed):
    rng = random.Random(2000 + seed)
    c0, s0 = sympy.Rational(3, 5), sympy.Rational(4, 5)
    x0 = sympy.Rational(rng.randint(-4, 4), rng.randint(1, 3))
    equations = []
    while len(equations) < 2:
        f = _random_equation(rng)
        if f.has(x) and f.has(q):
            value = _sympy_value(f, c0, s0, x0)
            equations.append(f - SR(QQ(str(value))))
    T = Translation(equations, [q, x])
    ideal = T.ring().ideal(T.equations())
    if ideal.dimension() != 0:
        pytest.skip("a random system with a curve of solutions")
    c, s = T.generators_of(q)
    (X,) = T.generators_of(x)
    solutions = []
    for point in ideal.variety(AA):
        angle = math.atan2(float(point[s]), float(point[c]))
        assert abs(float(point[c]) ** 2 + float(point[s]) ** 2 - 1) < 1e-12
        values = {q: angle, x: float(point[X])}
        for e in equations:
            assert abs(_at(e, values)) < 1e-8, (e, values)
        solutions.append((angle, float(point[X])))
    known = (math.atan2(4, 3), float(x0))
    assert any(abs(a - known[0]) < 1e-9 and abs(v - known[1]) < 1e-9 for a, v in solutions)

"""Families of equilibria by elimination: every solution annuls the
right-hand sides (checked at random points), Example 4 from the circuits
part, and clear errors for non-polynomial input."""
import random

import pytest
from sage.all import SR, QQ, var, function, sin

from sage_dynsym import load
from sage_dynsym.analysis import equilibrium_family
from sage_dynsym.errors import AnalysisError


def cubic_rhs():
    i1, i2, u3, u4, u5, u6, I0, I01, I02 = var('i1 i2 u3 u4 u5 u6 I0 I01 I02')
    g = var('g1 g2 g3 g4')
    s = var('s1 s2 s3 s4')
    f = [lambda u, j=j: g[j] * u * (u - 3 * s[j])**2 for j in range(4)]
    rhs = [u4 + u6 - u3, u5 - u4, I01 + i1 + f[2](u3), i2 - i1 + f[1](u4) - I0,
           I02 - i2 + f[3](u5), -i1 - I0 + f[0](u6)]
    return rhs, [i1, i2, u3, u4, u5, u6], f


def test_example4_family_annuls_rhs_at_random_points():
    rhs, x, f = cubic_rhs()
    i1, i2, u3, u4, u5, u6 = x
    fam = equilibrium_family(rhs, x, eliminate=[u3, u5, i1, i2])
    assert not fam.used_groebner()
    u40, u60 = var('u40 u60')
    I01, I02 = var('I01 I02')
    sol = fam.parameters_for({u4: u40, u6: u60}, [I01, I02])
    point = fam.point({u4: u40, u6: u60}, parameters=sol)
    symbols = set().union(*(set(SR(e).variables()) for e in rhs)) | {u40, u60}
    rng = random.Random(11)
    for _ in range(20):
        vals = {v: QQ(rng.uniform(-3, 3)) for v in symbols}
        full = {k: SR(v).subs(vals) for k, v in point.items()}
        params = {k: SR(v).subs(vals) for k, v in sol.items()}
        for e in rhs:
            assert SR(e).subs(full).subs(params).subs(vals) == 0
    # the source currents of Example 4 (doc/method.rst): I01 = I0 - f1(u6) - f3(u4 + u6), ...
    assert (sol[I01] - (var('I0') - f[0](u60) - f[2](u40 + u60))).expand() == 0
    assert (sol[I02] - (f[0](u60) - f[1](u40) - f[3](u40))).expand() == 0


def test_example4_from_the_circuits_part():
    circuit = load('examples/nonlinear_circuit.yaml')
    x = [v for v, _ in circuit.state_variables()]
    rhs = circuit.state_equations()
    i1, i2, u3, u4, u5, u6 = x
    fam = equilibrium_family(rhs, x, eliminate=[u3, u5, i1, i2])
    assert len(fam.equations()) == 2
    assert all(not e.has(v) for e in fam.equations() for v in (u3, u5, i1, i2))


def test_groebner_part_against_solutions():
    # circle and parabola; the eliminated x appears quadratically
    x, y, z = var('x y z')
    fam = equilibrium_family([x**2 + y**2 - 1, x**2 - y, z - x * y], [x, y, z],
                             eliminate=[x, z])
    assert fam.used_groebner()
    (eq,) = fam.equations()
    for yv in SR(eq).solve(y):
        yv = yv.rhs()
        xv = yv.sqrt()
        zv = fam.substitutions()[z].subs({x: xv, y: yv})
        for e in [x**2 + y**2 - 1, x**2 - y, z - x * y]:
            assert (e.subs({x: xv, y: yv, z: zv})).simplify_full() == 0


def test_nonconstant_coefficients_are_reported():
    x, y, a = var('x y a')
    fam = equilibrium_family([a * x - y, y**2 - 1], [x, y], eliminate=[x])
    assert fam.nonzero_conditions() == [a]
    assert fam.substitutions() == {x: y / a}


def test_non_polynomial_input_is_an_error():
    x, y = var('x y')
    with pytest.raises(AnalysisError, match="polynomial"):
        equilibrium_family([sin(x) - y, x**2 - y], [x, y], eliminate=[x])
    f = function('f')
    with pytest.raises(AnalysisError, match="polynomial"):
        equilibrium_family([f(x) * y**2 - 1, y**2 - x], [x, y], eliminate=[y])


def test_parameters_not_determined_is_an_error():
    x, a, b = var('x a b')
    fam = equilibrium_family([x - a * b], [x], eliminate=[])
    with pytest.raises(AnalysisError, match="uniquely"):
        fam.parameters_for({x: 1}, [a, b])

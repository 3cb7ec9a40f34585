"""
``minAssGTZ`` over its budget is abandoned in a forked process, not
interrupted by an alarm in this one: the characteristic sets give the
components, and Singular still answers correctly afterwards in the same
process (an interrupted Singular library call used to leave it broken: a
later call segfaulted).
"""
from sage.all import QQ, PolynomialRing, set_verbose

from sage_dynsym.algebra.decomposition import positive_dimensional_primes


def test_gtz_over_budget_falls_back_and_singular_still_works(capsys):
    R = PolynomialRing(QQ, 'x,y,z,w,v', order='degrevlex')
    x, y, z, w, v = R.gens()
    g1, g3 = x*y*z - w**2 + x - 1, v*x - y*z + w**3
    fa, fb = x**2 + y**2 - z**2, w - y**2 + 2*x
    # minAssGTZ runs for minutes on this ideal, minAssChar takes 0.1 s
    J = R.ideal([g1, fa*fb, g3])
    set_verbose(1)
    try:
        primes = positive_dimensional_primes(J, budget=1)
    finally:
        set_verbose(0)
    assert ("minAssGTZ: over 1 s of processor time: characteristic sets instead"
            in capsys.readouterr().out)
    # the zero set splits along the factored generator into two surfaces
    expected = [R.ideal([g1, fa, g3]), R.ideal([g1, fb, g3])]
    assert len(primes) == 2
    assert all(any(Q == E for Q in primes) for E in expected)
    # Singular afterwards: a Groebner basis known by hand (x = y on the circle
    # x^2 + y^2 = 1 gives 2 y^2 = 1), and a decomposition with GTZ
    S = PolynomialRing(QQ, 'a,b', order='lex')
    a, b = S.gens()
    assert S.ideal([a**2 + b**2 - 1, a - b]).groebner_basis() == [a - b, b**2 - QQ((1, 2))]
    T = PolynomialRing(QQ, 'p,q,r')
    p, q, r = T.gens()
    found = positive_dimensional_primes(T.ideal([p*q, p*r]))
    assert {frozenset(Q.gens()) for Q in found} == {frozenset([p]), frozenset([q, r])}

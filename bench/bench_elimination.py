"""Elimination on Example 4's system (circuit state equations (11) with cubic
resistor characteristics f_j(u) = g_j u (u - 3 s_j)^2): eliminate
u3, u5, i1, i2 from the equilibrium equations.

sage_dynsym: equilibrium_family (linear substitution first, Gröbner only on
what is left) and the source currents I01, I02 for a given point.
References in the same run, each in a subprocess killed after --timeout
seconds: sympy.groebner (lex, eliminated unknowns first) and, with
--plain, Sage's plain elimination_ideal of the whole system.

Usage: python bench/bench_elimination.py [--quick] [--timeout S] [--plain]
"""
import argparse
import time

from isolated import in_subprocess

NAMES = "i1 i2 u3 u4 u5 u6 I0 I01 I02 g1 g2 g3 g4 s1 s2 s3 s4"


def system_strings():
    # the right-hand sides (11) with the cubic characteristics, as text for
    # both SymPy and Sage (the benchmark's own fixed input)
    f = lambda j, u: f"g{j}*({u})*(({u}) - 3*s{j})**2"
    return ["u4 + u6 - u3", "u5 - u4", f"I01 + i1 + {f(3, 'u3')}",
            f"i2 - i1 + {f(2, 'u4')} - I0", f"I02 - i2 + {f(4, 'u5')}",
            f"-i1 - I0 + {f(1, 'u6')}"]


def sympy_job(queue):
    import sympy
    syms = sympy.symbols(NAMES)
    loc = {str(s): s for s in syms}
    eqs = [sympy.sympify(e, locals=loc) for e in system_strings()]
    elim = [loc[n] for n in ("u3", "u5", "i1", "i2")]
    rest = [s for s in syms if s not in elim]
    t0 = time.time()
    G = sympy.groebner(eqs, *elim, *rest, order='lex')
    kept = [g for g in G.exprs if not any(g.has(v) for v in elim)]
    queue.put((time.time() - t0, len(kept)))


def plain_job(queue):
    from sage.all import PolynomialRing, QQ
    R = PolynomialRing(QQ, NAMES.split())
    polys = [R(e.replace('**', '^')) for e in system_strings()]
    t0 = time.time()
    J = R.ideal(polys).elimination_ideal([R(n) for n in ("u3", "u5", "i1", "i2")])
    queue.put((time.time() - t0, len(J.gens())))


def run_sage():
    from sage.all import SR
    from sage_dynsym.io.expressions import ExpressionParser
    from sage_dynsym.analysis.elimination import equilibrium_family
    P = ExpressionParser(NAMES.split())
    rhs = [P.parse(e.replace('**', '^')) for e in system_strings()]
    x = [SR.var(n) for n in "i1 i2 u3 u4 u5 u6".split()]
    i1, i2, u3, u4, u5, u6 = x
    t0 = time.time()
    fam = equilibrium_family(rhs, x, eliminate=[u3, u5, i1, i2])
    t1 = time.time()
    u40, u60 = SR.var('u40 u60')
    sol = fam.parameters_for({u4: u40, u6: u60}, [SR.var('I01'), SR.var('I02')])
    t2 = time.time()
    return t1 - t0, t2 - t1, fam, sol


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--quick', action='store_true', help='short timeouts')
    parser.add_argument('--timeout', type=float, default=60.0)
    parser.add_argument('--plain', action='store_true',
                        help="also run Sage's plain elimination_ideal (minutes)")
    args = parser.parse_args()
    timeout = min(args.timeout, 10.0) if args.quick else args.timeout
    te, tp, fam, sol = run_sage()
    n_terms = [len(e.expand().operands()) for e in fam.equations()]
    print(f"sage_dynsym equilibrium_family: {te:.4f} s (Gröbner needed: "
          f"{fam.used_groebner()}), {len(fam.equations())} equations in u4, u6 "
          f"({n_terms} terms); parameters_for(I01, I02): {tp:.4f} s")
    for name, job in [("sympy.groebner (lex)", sympy_job)] + \
            ([("Sage plain elimination_ideal", plain_job)] if args.plain else []):
        res = in_subprocess(job, (), timeout)
        if res is None:
            print(f"{name}: timeout after {timeout:.0f} s; ratio > {timeout / te:.0f}x")
        else:
            print(f"{name}: {res[0]:.3f} s, {res[1]} equations without the "
                  f"eliminated unknowns; ratio {res[0] / te:.0f}x")


if __name__ == '__main__':
    main()

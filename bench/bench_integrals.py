"""Benchmark: polynomial first integrals on e(3) by undetermined coefficients,
sage_dynsym against a direct SymPy solve in the same run.

For each system and degree d, the space of polynomial integrals of degree
<= d (modulo constants) is computed by ``LiePoissonSystem.polynomial_integrals``
(blocks of the coefficient matrix, Singular syzygies over Q[parameters]) and
by SymPy: F = sum c_k m_k over the same monomials, {F, H} with the e(3)
bracket written out here, its coefficients collected (Poly.coeffs), the
linear system turned into a matrix (linear_eq_to_matrix) and its null space
computed by SymPy's DomainMatrix over the fraction field of the parameters
(the fastest exact path SymPy offers). SymPy runs in a child process with a
time limit. Both dimensions are printed; they must agree.

Systems (all with symbolic parameters):
- heavy body, generic: A1, A2, A3, mu, x0, y0, z0 (7 parameters);
- Kovalevskaya: A = B = 2C, centre of mass (x0, 0, 0): C, mu, x0;
- Kirchhoff: H = (sum a_i M_i^2 + b_i p_i^2)/2: a1..a3, b1..b3.

Usage: python bench/bench_integrals.py [--quick] [--timeout SECONDS]
"""
import argparse
import time

from sage.all import var

from sage_dynsym.io.expressions import ExpressionParser
from sage_dynsym.lie import LiePoissonSystem

from isolated import in_subprocess

NAMES = ['M1', 'M2', 'M3', 'g1', 'g2', 'g3']
PARAMETERS = ['A1', 'A2', 'A3', 'mu', 'x0', 'y0', 'z0', 'C', 'a1', 'a2', 'a3', 'b1', 'b2', 'b3']
SYSTEMS = {
    'heavy body (generic)': "M1**2/(2*A1) + M2**2/(2*A2) + M3**2/(2*A3) + mu*(x0*g1 + y0*g2 + z0*g3)",
    'Kovalevskaya': "(M1**2 + M2**2)/(4*C) + M3**2/(2*C) + mu*x0*g1",
    'Kirchhoff': "(a1*M1**2 + a2*M2**2 + a3*M3**2 + b1*g1**2 + b2*g2**2 + b3*g3**2)/2",
}


def ours(text, degree):
    x = var(' '.join(NAMES))
    H = ExpressionParser(NAMES + PARAMETERS).parse(text.replace('**', '^'))
    S = LiePoissonSystem('e3', H, variables=list(x))
    start = time.time()
    basis = S.polynomial_integrals(degree)
    return time.time() - start, len(basis)


def sympy_dimension(text, degree, queue):
    import itertools
    import sympy
    from sympy.polys.matrices import DomainMatrix
    start = time.time()
    x = sympy.symbols(NAMES)
    M, g = x[:3], x[3:]
    H = sympy.sympify(text.replace('**', '^'), convert_xor=True)
    monomials = [sympy.Mul(*c) for d in range(1, degree + 1)
                 for c in itertools.combinations_with_replacement(x, d)]
    cs = sympy.symbols(f'c0:{len(monomials)}')
    F = sum(c * mono for c, mono in zip(cs, monomials))

    def eps(i, j, k):
        return (i - j) * (j - k) * (k - i) // 2
    J = sympy.zeros(6, 6)      # {M_i, M_j} = -eps M_k, {M_i, g_j} = -eps g_k
    for i, j, k in itertools.product(range(3), repeat=3):
        J[i, j] -= eps(i, j, k) * M[k]
        J[i, 3 + j] -= eps(i, j, k) * g[k]
        J[3 + j, i] += eps(i, j, k) * g[k]
    dF = [sympy.diff(F, v) for v in x]
    dH = [sympy.diff(H, v) for v in x]
    bracket = sympy.expand(sum(dF[i] * J[i, j] * dH[j] for i in range(6) for j in range(6)))
    num, _ = sympy.fraction(sympy.together(bracket))
    equations = sympy.Poly(sympy.expand(num), *x).coeffs()
    A, _ = sympy.linear_eq_to_matrix(equations, cs)
    dM = DomainMatrix.from_Matrix(A).to_field()
    dimension = len(cs) - dM.rank()
    queue.put((time.time() - start, dimension, len(cs)))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--quick', action='store_true', help='degrees 1 and 2 only')
    parser.add_argument('--timeout', type=float, default=None,
                        help='time limit of each SymPy solve in seconds (default 120, quick 30)')
    args = parser.parse_args()
    degrees = [1, 2] if args.quick else [1, 2, 3, 4]
    timeout = args.timeout or (30 if args.quick else 120)
    print(f"{'system':22} {'d':>2} {'unknowns':>8} {'dim':>4} {'sage_dynsym':>12} "
          f"{'SymPy':>10} {'dim':>4} {'ratio':>8}")
    for name, text in SYSTEMS.items():
        for d in degrees:
            t_ours, dim = ours(text, d)
            ref = in_subprocess(sympy_dimension, (text, d), timeout)
            if ref is None:
                print(f"{name:22} {d:>2} {'':>8} {dim:>4} {t_ours:>11.3f}s "
                      f"{'> ' + format(timeout, 'g') + 's':>10} {'':>4} {'> ' + format(timeout / t_ours, '.0f'):>8}")
                continue
            t_ref, dim_ref, unknowns = ref
            assert dim == dim_ref, (name, d, dim, dim_ref)
            print(f"{name:22} {d:>2} {unknowns:>8} {dim:>4} {t_ours:>11.3f}s "
                  f"{t_ref:>9.3f}s {dim_ref:>4} {t_ref / t_ours:>8.1f}")


if __name__ == '__main__':
    main()

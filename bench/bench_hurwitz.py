"""Characteristic polynomial and Hurwitz / Liénard-Chipart conditions of an
n-mass chain with symbolic masses, springs and dampers, against SymPy.

The chain: masses m1..mn in a row, fixed to walls at both ends by springs
k1..k(n+1) and dampers c1..c(n+1) (3n+2 parameters; 14 at n = 4). Its
characteristic polynomial det(M lam^2 + C lam + K) has degree 2n.

sage_dynsym: LinearSystem(...).characteristic_polynomial (fraction-free over
a polynomial ring) and the fraction-free Routh scheme for the Hurwitz
determinants; expanded while a product costs less than the budget of term
multiplications, unexpanded (polynomials in the coefficients) beyond.
SymPy (reference, in a subprocess killed after --timeout seconds):
Matrix.det (berkowitz) of the characteristic matrix, then the leading
principal minors of the Hurwitz matrix, expanded.

Usage: python bench/bench_hurwitz.py [--quick] [--timeout S] [--nmax N (default 8, the issue's range)]
"""
import argparse
import multiprocessing as mp
import time


def sympy_job(n, queue):
    import sympy
    lam = sympy.Symbol('lam')
    m = sympy.symbols('m1:%d' % (n + 1))
    k = sympy.symbols('k1:%d' % (n + 2))
    c = sympy.symbols('c1:%d' % (n + 2))
    t0 = time.time()
    A = sympy.zeros(n, n)
    for i in range(n):
        A[i, i] = m[i] * lam**2 + (c[i] + c[i + 1]) * lam + k[i] + k[i + 1]
        if i + 1 < n:
            A[i, i + 1] = A[i + 1, i] = -(c[i + 1] * lam + k[i + 1])
    p = sympy.Poly(sympy.expand(A.det(method='berkowitz')), lam)
    t1 = time.time()
    queue.put(('charpoly', t1 - t0))
    a = p.all_coeffs()
    N = len(a) - 1
    H = sympy.Matrix(N, N, lambda i, j: a[2 * j - i + 1] if 0 <= 2 * j - i + 1 <= N else 0)
    sizes = []
    for r in range(1, N):
        d = sympy.expand(H[:r, :r].det(method='berkowitz'))
        sizes.append(len(sympy.Add.make_args(d)))
    queue.put(('hurwitz', time.time() - t1, sizes))


def run_sympy(n, timeout):
    queue = mp.Queue()
    proc = mp.Process(target=sympy_job, args=(n, queue))
    proc.start()
    t0 = time.time()
    results = {}
    while time.time() - t0 < timeout and (proc.is_alive() or not queue.empty()):
        try:
            item = queue.get(timeout=0.2)
            results[item[0]] = item[1:]
            if item[0] == 'hurwitz':
                break
        except Exception:
            pass
    if proc.is_alive():
        proc.kill()
    proc.join()
    return results


def chain(n):
    from sage.all import matrix, SR
    from sage_dynsym.analysis.linear import LinearSystem
    m = [SR.var('m%d' % i) for i in range(1, n + 1)]
    k = [SR.var('k%d' % i) for i in range(1, n + 2)]
    c = [SR.var('c%d' % i) for i in range(1, n + 2)]

    def tri(d):
        A = matrix(SR, n, n)
        for i in range(n):
            A[i, i] = d[i] + d[i + 1]
            if i + 1 < n:
                A[i, i + 1] = A[i + 1, i] = -d[i + 1]
        return A
    return LinearSystem(m, M=matrix.diagonal(SR, m), S=tri(c), W=tri(k)), m + k + c


def run_sage(n, budget):
    from sage.all import SR
    from sage_dynsym.analysis.hurwitz import (_determinants, _Unexpanded,
                                              lienard_chipart_conditions)
    lam = SR.var('lam')
    system, params = chain(n)
    t0 = time.time()
    p = system.characteristic_polynomial(lam, as_polynomial=True)
    t1 = time.time()
    from sage_dynsym.analysis.hurwitz import _normalized_coefficients
    a = _normalized_coefficients(p, 'lam')
    deltas = _determinants(a, len(a) - 2, budget)
    t2 = time.time()
    sizes = [('unexpanded' if isinstance(d, _Unexpanded) else len(d.dict()))
             for d in deltas[1:]]
    conds = lienard_chipart_conditions(p, 'lam', positive=params, budget=budget)
    t3 = time.time()
    return t1 - t0, t2 - t1, t3 - t2, sizes, len(conds)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--quick', action='store_true', help='n = 2, 3 only, short timeout')
    parser.add_argument('--timeout', type=float, default=60.0)
    # n = 7, 8 work but the generic (unexpanded) Hurwitz determinants of
    # degree 14, 16 take minutes; see the report
    parser.add_argument('--nmax', type=int, default=8)
    args = parser.parse_args()
    nmax = 3 if args.quick else args.nmax
    timeout = min(args.timeout, 20.0) if args.quick else args.timeout
    from sage_dynsym.analysis.hurwitz import DEFAULT_BUDGET
    print(f"n-mass chain, SymPy timeout {timeout:.0f} s, expansion budget "
          f"{DEFAULT_BUDGET:.0e} term products")
    print(f"{'n':>2} {'deg':>3} {'params':>6} | {'charpoly':>9} {'Hurwitz':>9} {'L-C':>8}"
          f" | {'SymPy charpoly':>14} {'SymPy Hurwitz':>14} | {'ratio':>10} | sizes of Delta_1..Delta_(n-1)")
    sympy_dead = False
    for n in range(2, nmax + 1):
        tc, th, tl, sizes, ncond = run_sage(n, DEFAULT_BUDGET)
        if sympy_dead:
            sres = None
        else:
            sres = run_sympy(n, timeout)
        if sres is None:
            sc = sh = 'skipped'
            ratio = '-'
        else:
            sc = f"{sres['charpoly'][0]:.3f}s" if 'charpoly' in sres else 'timeout'
            if 'hurwitz' in sres:
                sh = f"{sres['hurwitz'][0]:.3f}s"
                ratio = f"{(sres['charpoly'][0] + sres['hurwitz'][0]) / (tc + th):.0f}x"
            else:
                sh = 'timeout'
                ratio = f">{timeout / (tc + th):.0f}x"
                sympy_dead = True
        print(f"{n:>2} {2 * n:>3} {3 * n + 2:>6} | {tc:>8.3f}s {th:>8.3f}s {tl:>7.3f}s"
              f" | {sc:>14} {sh:>14} | {ratio:>10} | {sizes}", flush=True)
    # fully expanded determinants at n = 3 (no budget), for the record
    tc, th, tl, sizes, _ = run_sage(3, None)
    print(f"n = 3 fully expanded: charpoly {tc:.3f}s, all Hurwitz determinants "
          f"{th:.3f}s, Liénard-Chipart {tl:.3f}s, sizes {sizes}")


if __name__ == '__main__':
    main()

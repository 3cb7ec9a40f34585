"""
Benchmark: Lagrange equations of an N-link spatial chain, sage_dynsym vs
SymPy's KanesMethod and LagrangesMethod.

Link k turns about z by psi<k>, then about the new x by theta<k> (as in
Example 1); its joint is at the end of the previous link, (0, 0, l<k-1>) in
the parent's axes; mass centre (0, 0, c<k>); inertia diag(A<k>, A<k>, C<k>)
about the joint; symbolic masses m<k>; gravity (0, 0, -g). The model is the
plain-data ``spatial_chain(N)`` of ``tests/reference/chains.py``, built by
sage_dynsym and by ``sympy.physics.mechanics`` (``tests/reference/
sympy_chain.py``: ``KanesMethod`` with the speeds u = q' and the weights as
loads, ``fr + frstar``; ``LagrangesMethod``).

Each (tool, N) runs in a fresh subprocess with a timeout; the time covers
building the model and deriving the equations (not importing the library).
Output size: total length of the equations' text without spaces, in plain
symbols (psi1, dpsi1, ddpsi1, ...) with ``^`` for powers; for sage_dynsym
also the size of the opt-in compact form ``equations_cse`` (the
definitions ``x1_=...`` of the common subexpressions and the equations
written with them; its time is not included). All three evaluate their equations at the same random point
(Kane's with the sign of the Lagrange equations, fr + frstar = -E) and the
largest relative difference to sage_dynsym is printed (a correctness guard).

sage_dynsym runs ``MechanicalSystem.lagrangian()`` with its default
``christoffel='auto'``: Christoffel coefficients cancelled in the
polynomial ring (most compact for small systems) while the bodies are at
most 8 rotations deep and the mass matrix has at most 10,000 terms (here
N <= 4), the recursive (Newton-Euler) assembly beyond: mass matrix times
accelerations plus nested velocity terms; ``--christoffel polynomial``,
``recursive`` or ``symbolic`` forces one of them.

Usage: ``python bench/bench_chain.py [--quick] [--max-n N] [--timeout S]
[--christoffel auto|polynomial|recursive|symbolic] [--no-rhs]`` (``--quick``:
N = 1..3, 60 s timeout). Once a SymPy method times out at some N it is not
run for larger N (its cost only grows). The timeout covers the whole
worker; the derivation time is reported even when only the untimed size or
evaluation step overran it. At the end, unless ``--no-rhs``, the speed of
the compiled right-hand side of the 4-link chain against SymPy's
``lambdify(cse=True)`` is printed by ``bench/rhs_speed.py`` (if present).
"""
import argparse
import json
import os
import random
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, os.pardir, 'tests'))

from reference.chains import random_point, spatial_chain  # noqa: E402


def _size(exprs):
    return sum(len(str(e).replace(' ', '').replace('**', '^')) for e in exprs)


def _report(result=None, **new):
    """Print the results so far (one JSON line each time, the last is the
    most complete) so that a timeout in the untimed size / evaluation steps
    still leaves the derivation time."""
    result = dict(result or {}, **new)
    print(json.dumps(result), flush=True)
    return result


def worker_sage(n, christoffel='auto'):
    from sage.all import SR, fast_callable, RDF
    from sage_dynsym.dynamics.compact import equations_cse
    from sage_chains import sage_chain_parts, assemble
    desc = spatial_chain(n)
    parts = sage_chain_parts(desc)
    start = time.perf_counter()
    S = assemble(*parts)
    E = S.lagrangian(christoffel).lagrange_equations()
    result = _report(time=time.perf_counter() - start)
    result = _report(result, size=_size(E))
    C = equations_cse(E)
    result = _report(result, cse_size=_size([f'{s}={e}' for s, e in C.subexpressions()]
                                            + C.equations()))
    point = random_point(desc, random.Random(1))
    order = sorted(point)
    values = [float(fast_callable(SR(e), vars=[SR.var(s) for s in order], domain=RDF)(
        *[point[s] for s in order])) for e in E]
    _report(result, values=values)


def worker_sympy(n, method):
    import sympy
    from reference.sympy_chain import SympyChain
    desc = spatial_chain(n)
    start = time.perf_counter()
    chain = SympyChain(desc['bodies'], desc['coordinates'], desc['gravity'], desc['parameters'])
    if method == 'kane':
        eom = chain.kane_equations(plain=False)
    else:
        eom = chain.lagrange_equations(plain=False)
    result = _report(time=time.perf_counter() - start)
    E = [chain.to_plain(e) for e in eom]
    result = _report(result, size=_size(E))
    point = random_point(desc, random.Random(1))
    order = sorted(point)
    f = sympy.lambdify([sympy.Symbol(s) for s in order], E, modules='math', cse=True)
    sign = -1 if method == 'kane' else 1    # fr + frstar = -E
    _report(result, values=[sign * float(v) for v in f(*[point[s] for s in order])])


def run(tool, n, timeout, christoffel='auto'):
    """
    Run one worker in a fresh interpreter. Return its result dict (it may lack
    ``size`` / ``values`` if the timeout came after the derivation),
    ``'timeout'`` if the derivation itself did not finish, or ``'error: ...'``.
    """
    cmd = [sys.executable, os.path.abspath(__file__), '--worker', tool, str(n),
           '--christoffel', christoffel]
    try:
        out = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
        stdout, failed = out.stdout, out.returncode != 0
    except subprocess.TimeoutExpired as timeout_error:
        stdout, failed = timeout_error.stdout or '', False
        if isinstance(stdout, bytes):
            stdout = stdout.decode()
    lines = [line for line in stdout.splitlines() if line.startswith('{')]
    if lines:
        return json.loads(lines[-1])
    if failed:
        return 'error: ' + (out.stderr.strip().splitlines() or ['?'])[-1]
    return 'timeout'


def _relative_difference(a, b):
    scale = max(1.0, max(abs(x) for x in b))
    return max(abs(x - y) for x, y in zip(a, b)) / scale


TOOLS = ('sage', 'kane', 'lagrange')


def _cell(r, width, key='time', fmt='.2f'):
    if isinstance(r, dict) and r.get(key) is not None:
        return f"{r[key]:>{width}{fmt}}"
    text = 'n/a' if isinstance(r, dict) else str(r)
    return f"{text:>{width}.{width}}"


def _ratio(a, b, width):
    if isinstance(a, dict) and isinstance(b, dict) and a.get('time') and b.get('time'):
        return f"{b['time'] / a['time']:>{width - 1}.1f}x"
    return f"{'-':>{width}}"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--quick', action='store_true', help='N = 1..3, 60 s timeout')
    parser.add_argument('--max-n', type=int, default=None)
    parser.add_argument('--timeout', type=float, default=None)
    parser.add_argument('--christoffel', choices=['auto', 'polynomial', 'recursive', 'symbolic'],
                        default='auto')
    parser.add_argument('--no-rhs', action='store_true',
                        help='skip the right-hand side comparison of bench/rhs_speed.py')
    parser.add_argument('--worker', nargs=2, help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.worker:
        tool, n = args.worker
        if tool == 'sage':
            worker_sage(int(n), args.christoffel)
        else:
            worker_sympy(int(n), tool)
        return
    max_n = args.max_n or (3 if args.quick else 6)
    timeout = args.timeout or (60 if args.quick else 300)
    print(f"N-link spatial chain, Lagrange equations; timeout {timeout:g} s per run; "
          f"sage_dynsym with christoffel={args.christoffel!r}")
    print("times in s (build + derivation); sizes in characters; 'xKane', 'xLagr': "
          "SymPy's time over sage_dynsym's; 'size/Kane': sage_dynsym's size over Kane's")
    print(f"{'N':>2} {'sage_dynsym':>11} {'Kane':>8} {'Lagrange':>8} {'xKane':>7} {'xLagr':>7} "
          f"{'sage size':>10} {'cse size':>9} {'Kane size':>10} {'Lagr size':>10} "
          f"{'size/Kane':>9} {'max rel diff':>12}")
    gave_up = {}
    for n in range(1, max_n + 1):
        res = {}
        for tool in TOOLS:
            res[tool] = 'skipped' if tool in gave_up else run(tool, n, timeout, args.christoffel)
            if res[tool] == 'timeout':
                gave_up.setdefault(tool, n)
        sage, kane, lagr = (res[t] for t in TOOLS)
        cells = [f"{n:>2}", _cell(sage, 11), _cell(kane, 8), _cell(lagr, 8),
                 _ratio(sage, kane, 7), _ratio(sage, lagr, 7),
                 _cell(sage, 10, 'size', 'd'), _cell(sage, 9, 'cse_size', 'd'),
                 _cell(kane, 10, 'size', 'd'), _cell(lagr, 10, 'size', 'd')]
        sizes = [r.get('size') if isinstance(r, dict) else None for r in (sage, kane)]
        cells.append(f"{sizes[0] / sizes[1]:>9.3f}" if all(sizes) else f"{'-':>9}")
        values = [r.get('values') if isinstance(r, dict) else None for r in (sage, kane, lagr)]
        diffs = [_relative_difference(values[0], v) for v in values[1:] if values[0] and v]
        cells.append(f"{max(diffs):>12.1e}" if diffs else f"{'-':>12}")
        print(" ".join(cells), flush=True)
        for tool, r in zip(('sage_dynsym', 'SymPy Kane', 'SymPy Lagrange'), (sage, kane, lagr)):
            if isinstance(r, str) and r.startswith('error'):
                print(f"   {tool} failed at N = {n}: {r}", flush=True)
            if isinstance(r, dict) and 'values' not in r:
                print(f"   {tool} at N = {n}: derived in {r['time']:.1f} s; output size / "
                      "numerical evaluation did not finish within the timeout", flush=True)
    for tool, n in gave_up.items():
        print(f"{tool} timed out at N = {n}; 'skipped' = not run for larger N "
              "(its cost only grows).")
    if not args.no_rhs:
        _compare_rhs()


def _compare_rhs():
    try:
        from rhs_speed import compare_rhs
    except ImportError:
        return      # bench/rhs_speed.py is optional
    print()
    compare_rhs(4)


if __name__ == '__main__':
    main()

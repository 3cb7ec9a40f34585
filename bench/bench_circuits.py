"""
Benchmark: state equations of an RLC ladder with n sections, symbolic values.

sage_dynsym (Brayton-Moser state equations from the mixed potential) against
Lcapy's state-space analysis (``Circuit(netlist).ss``: matrices A and B) of
the same ladder, in the same run. Lcapy runs in a subprocess with a time
limit. Prints times, ratios and output sizes; at the smallest n both results
are compared (eigenvalues of the state matrix at random element values).

Ladder: voltage source from ground 0 to node 1; section k: series resistor
R_k (node 2k-1 -> 2k) and inductor L_k (2k -> 2k+1), shunt capacitor C_k
(2k+1 -> 0); load resistor R_{n+1} across the last capacitor.

Usage: python bench/bench_circuits.py [--quick] [--timeout SECONDS] [--sizes 5,10,20,40]
"""
import argparse
import json
import subprocess
import sys
import time

import numpy as np


def ladder_branches(n):
    branches = [[0, 1, 'E1']]
    for k in range(1, n + 1):
        branches += [[2 * k - 1, 2 * k, f'R{k}'], [2 * k, 2 * k + 1, f'L{k}'],
                     [2 * k + 1, 0, f'C{k}']]
    branches.append([2 * n + 1, 0, f'R{n + 1}'])
    return branches


def lcapy_netlist(n):
    lines = ['V1 1 0']      # a symbolic source; the state matrix does not depend on it
    for k in range(1, n + 1):
        lines += [f'R{k} {2 * k - 1} {2 * k}', f'L{k} {2 * k} {2 * k + 1}',
                  f'C{k} {2 * k + 1} 0']
    lines.append(f'R{n + 1} {2 * n + 1} 0')
    return '\n'.join(lines)


LCAPY_SCRIPT = r"""
import json, sys, time
n = int(sys.argv[1]); netlist = sys.stdin.read()
t0 = time.perf_counter()
from lcapy import Circuit
t1 = time.perf_counter()
ss = Circuit(netlist).ss
A, B = ss.A, ss.B
t2 = time.perf_counter()
out = {"import": t1 - t0, "time": t2 - t1, "size": len(str(A)) + len(str(B)),
       "states": [str(x) for x in ss.x], "A": [[str(a) for a in row] for row in A.tolist()]}
print(json.dumps(out))
"""


def run_lcapy(n, timeout):
    try:
        proc = subprocess.run([sys.executable, '-c', LCAPY_SCRIPT, str(n)],
                              input=lcapy_netlist(n), capture_output=True, text=True,
                              timeout=timeout)
    except subprocess.TimeoutExpired:
        return None
    if proc.returncode != 0 and "No module named 'lcapy'" in proc.stderr:
        return "missing"
    if proc.returncode != 0:
        raise RuntimeError(f"Lcapy failed at n={n}:\n{proc.stderr[-2000:]}")
    return json.loads(proc.stdout.strip().splitlines()[-1])


def run_ours(n):
    from sage_dynsym.circuits import Circuit
    t0 = time.perf_counter()
    C = Circuit(ladder_branches(n))
    eqs = C.state_equations()
    states = C.state_variables()
    elapsed = time.perf_counter() - t0
    return elapsed, C, states, eqs


def compare_at_random_values(n, C, states, eqs, lcapy_result):
    """Eigenvalues of the state matrix from both tools at random element values."""
    import sympy
    from sage.all import SR
    rng = np.random.default_rng(5)
    values = {f'{p}{k}': float(rng.uniform(0.5, 2)) for p in 'RLC' for k in range(1, n + 2)}
    xs = [x for x, _ in states]
    coeff = {name: values[name] for _, name in states}
    ours = np.array([[float(SR(e).diff(x).subs({SR.var(k): v for k, v in values.items()}))
                      for x in xs] for e in eqs])
    ours = ours / np.array([[coeff[name]] for _, name in states])
    subs = {sympy.Symbol(k, positive=True): v for k, v in values.items()}
    subs.update({sympy.Symbol(k): v for k, v in values.items()})
    A = np.array([[float(sympy.sympify(a).subs(subs)) for a in row]
                  for row in lcapy_result["A"]])
    ev1 = np.sort_complex(np.linalg.eigvals(ours))
    ev2 = np.sort_complex(np.linalg.eigvals(A))
    return float(np.max(np.abs(ev1 - ev2)))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[1])
    parser.add_argument('--quick', action='store_true', help='small smoke run (n = 3, 5)')
    parser.add_argument('--timeout', type=float, default=300.0,
                        help='time limit for Lcapy per size, seconds (default 300)')
    parser.add_argument('--sizes', default=None, help='comma-separated n values')
    args = parser.parse_args()
    sizes = [3, 5] if args.quick else [5, 10, 20, 40]
    if args.sizes:
        sizes = [int(x) for x in args.sizes.split(',')]
    import sage.all  # noqa: F401  (load Sage before timing)
    print(f"RLC ladder, symbolic values; Lcapy time limit {args.timeout:.0f} s")
    print(f"{'n':>4} {'states':>6} {'sage_dynsym [s]':>16} {'Lcapy [s]':>10} "
          f"{'ratio':>8} {'our size':>9} {'Lcapy size':>10}")
    for i, n in enumerate(sizes):
        ours, C, states, eqs = run_ours(n)
        size = sum(len(str(e)) for e in eqs)
        lc = run_lcapy(n, args.timeout)
        if lc == "missing":
            print(f"{n:>4} {len(states):>6} {ours:>16.3f}  (Lcapy not installed: pip install lcapy)")
            continue
        if lc is None:
            lc_time, ratio, lc_size = f"> {args.timeout:.0f}", f"> {args.timeout / ours:.0f}", "-"
        else:
            lc_time, ratio, lc_size = f"{lc['time']:.2f}", f"{lc['time'] / ours:.0f}", lc['size']
        print(f"{n:>4} {len(states):>6} {ours:>16.3f} {lc_time:>10} {ratio:>8} "
              f"{size:>9} {lc_size:>10}", flush=True)
        if i == 0 and lc is not None:
            err = compare_at_random_values(n, C, states, eqs, lc)
            print(f"     check at n={n}: max |eigenvalue difference| = {err:.2e}")
            assert err < 1e-8, "the two tools disagree"


if __name__ == '__main__':
    main()

"""
Benchmark: simulating the N-link spatial chain, sage_dynsym vs SymPy + SciPy.

The chain is ``spatial_chain(N)`` of ``tests/reference/chains.py`` (see
``bench/bench_chain.py``). sage_dynsym: Lagrange equations, compiled
right-hand side (``numerical_rhs``) and ``simulate`` (DOP853, rtol 1e-10,
atol 1e-12). Reference: SymPy's ``KanesMethod`` on the same chain
(``tests/reference/sympy_chain.py``), ``lambdify(cse=True)`` of its mass
matrix and forcing with a ``numpy.linalg.solve`` per call, integrated by
SciPy's ``solve_ivp`` with the same method, tolerances and samples.

Printed per N: the time to build the right-hand side (equations and
compilation; SymPy: KanesMethod and lambdify), the integration time, their
ratio (best of 3 runs each), the largest difference between the two trajectories at the samples
and sage_dynsym's relative energy drift.

Usage: ``python bench/bench_simulate.py [--quick] [--max-n N] [--t-end T]``
(``--quick``: N = 2..3, t_end = 1).
"""
import argparse
import os
import random
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, os.pardir, 'tests'))

from reference.chains import physical_values, spatial_chain  # noqa: E402
from rhs_speed import sage_chain, kane_chain, sympy_rhs  # noqa: E402

TOLERANCES = dict(method='DOP853', rtol=1e-10, atol=1e-12)


def best_time(f, repeat=3):
    """The shortest of ``repeat`` runs (the machine may be shared)."""
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        f()
        times.append(time.perf_counter() - start)
    return min(times)


def run(n, t_end, points=101, seed=3):
    from scipy.integrate import solve_ivp
    from sage_dynsym.numerics import numerical_rhs, simulate
    desc = spatial_chain(n)
    rng = random.Random(seed)
    values = physical_values(desc, rng)
    state = {c: rng.uniform(0.3, 1.2) for c in desc['coordinates']}
    state.update({'d' + c: rng.uniform(-0.5, 0.5) for c in desc['coordinates']})

    start = time.perf_counter()
    L = sage_chain(desc).lagrangian()
    rhs = numerical_rhs(L.to_linearizer(), values)
    sage_build = time.perf_counter() - start
    sage_run = best_time(lambda: simulate(rhs, values, state, t_end, points=points,
                                          energy=L.energy(), **TOLERANCES))
    T = simulate(rhs, values, state, t_end, points=points, energy=L.energy(), **TOLERANCES)

    start = time.perf_counter()
    kane = kane_chain(desc)
    small, _ = sympy_rhs(kane, values)
    sympy_build = time.perf_counter() - start
    order = [str(s) for s in kane['q'] + kane['u']]
    def reference():
        return solve_ivp(small, (0, t_end), [state[k] for k in order],
                         t_eval=np.linspace(0, t_end, points), **TOLERANCES)
    sympy_run = best_time(reference)
    sol = reference()
    ours = np.array([T.values(k) for k in order])
    diff = float(np.max(np.abs(ours - sol.y)))
    return dict(n=n, sage_build=sage_build, sage_run=sage_run, sympy_build=sympy_build,
                sympy_run=sympy_run, diff=diff, drift=T.energy_drift())


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--quick', action='store_true', help='N = 2..3, t_end = 1')
    parser.add_argument('--max-n', type=int, default=None)
    parser.add_argument('--t-end', type=float, default=None)
    args = parser.parse_args()
    max_n = args.max_n or (3 if args.quick else 4)
    t_end = args.t_end or (1.0 if args.quick else 5.0)
    print(f"N-link spatial chain: simulate to t = {t_end:g} (101 samples, DOP853, rtol 1e-10); "
          "sage_dynsym numerical_rhs + simulate vs SymPy KanesMethod + lambdify(cse=True) + "
          "solve_ivp")
    print(f"{'N':>2} {'build s':>8} {'SymPy build s':>14} {'run s':>7} {'SymPy run s':>12} "
          f"{'run ratio':>10} {'max diff':>9} {'energy drift':>13}")
    for n in range(2, max_n + 1):
        r = run(n, t_end)
        print(f"{n:>2} {r['sage_build']:>8.2f} {r['sympy_build']:>14.2f} {r['sage_run']:>7.2f} "
              f"{r['sympy_run']:>12.2f} {r['sympy_run'] / r['sage_run']:>9.1f}x "
              f"{r['diff']:>9.1e} {r['drift']:>13.1e}", flush=True)


if __name__ == '__main__':
    main()

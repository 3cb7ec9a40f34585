"""Stability maps of a sixth-order system: points per second per core of
sage_dynsym.scale.stability_map against a plain Python loop over
numpy.linalg.eigvals, and the scaling from one to two Dask workers.

The system: the RLC ladder of examples/rlc_ladder.yaml (three inductors,
three capacitors: B x' = J x of order 6), free (source off), in the plane of
the resistances R1, R2 in [-1, 2] (negative: active elements), the other
elements fixed.

References, in the same run, on the first --loop points of the grid:
- "loop": what one writes without this package: for each point, the 36
  entries of A = B^-1 J from Sage's fast_callable (compiled once), then
  numpy.linalg.eigvals(A);
- "loop, eigvals only": the same loop over matrices evaluated beforehand
  (the cost of numpy.linalg.eigvals called once per point).
sage_dynsym: stability_map with client=False (plain NumPy in this process,
one core; 'polynomial' method: compiled characteristic polynomial and a
vectorised Laguerre iteration; 'eigvals' method: compiled matrices and
numpy.linalg.eigvals on stacks), then, on a larger grid (--dask-n, so that
the chunks are many and the overheads small), on local Dask clusters of 1
and 2 worker processes (started before the timing; a warm-up map first),
compared with the NumPy map of that grid.

Usage: python bench/bench_map.py [--quick] [--n N (grid N x N, default 400)]
       [--dask-n N (default 1000)] [--loop P (default 5000)]
"""
import argparse
import os
import tempfile
import time

import numpy as np


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="small smoke run")
    parser.add_argument("--n", type=int, default=400, help="grid of N x N points")
    parser.add_argument("--dask-n", type=int, default=1000, help="grid of the Dask runs")
    parser.add_argument("--loop", type=int, default=5000, help="points of the loop references")
    args = parser.parse_args()
    if args.quick:
        args.n, args.dask_n, args.loop = 60, 100, 500

    from sage.all import SR, RDF, fast_callable
    from distributed import Client, LocalCluster
    from sage_dynsym import load
    from sage_dynsym.scale import stability_map, model_linear_system

    fixed = {'R3': 1, 'R4': 2, 'L1': 1, 'L2': 0.5, 'L3': 1, 'C1': 1, 'C2': 2, 'C3': 1}
    grid = {'R1': (-1, 2, args.n), 'R2': (-1, 2, args.n)}
    total = args.n ** 2
    print(f"stability map of the RLC ladder (order 6) on {args.n} x {args.n} = {total} points; "
          f"load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")

    t0 = time.perf_counter()
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "examples",
                        "rlc_ladder.yaml")
    system = model_linear_system(load(path))
    print(f"  linear system from the description: {time.perf_counter() - t0:.2f} s")

    # --- references: plain Python loops --------------------------------------
    R1, R2 = SR.var('R1'), SR.var('R2')
    A = system.jacobian().subs({SR.var(k): v for k, v in fixed.items()})
    entries = [fast_callable(e, vars=[R1, R2], domain=RDF) for e in A.list()]
    axis = np.linspace(-1, 2, args.n)
    points = [(axis[i // args.n], axis[i % args.n]) for i in range(min(args.loop, total))]
    t0 = time.perf_counter()
    loop_alpha = []
    for a, b in points:
        M = np.array([f(a, b) for f in entries]).reshape(6, 6)
        loop_alpha.append(np.linalg.eigvals(M).real.max())
    t_loop = (time.perf_counter() - t0) / len(points)
    mats = np.array([np.array([f(a, b) for f in entries]).reshape(6, 6) for a, b in points])
    t0 = time.perf_counter()
    for M in mats:
        np.linalg.eigvals(M).real.max()
    t_eig = (time.perf_counter() - t0) / len(points)

    rows = [("loop: fast_callable + eigvals", 1 / t_loop, None),
            ("loop: eigvals only", 1 / t_eig, None)]

    # --- sage_dynsym without Dask ---------------------------------------------
    maps = {}
    for method in ("polynomial", "eigvals"):
        t0 = time.perf_counter()
        S = stability_map(system, grid, fixed=fixed, client=False, method=method)
        dt = time.perf_counter() - t0
        maps[method] = S
        rows.append((f"stability_map, NumPy, {method}", total / dt, dt))
    S = maps["polynomial"]
    check = S.max_real_part().ravel()[:len(points)]
    scale = max(1.0, float(np.max(np.abs(loop_alpha))))
    print(f"  largest real part vs the loop ({len(points)} points): max difference "
          f"{np.max(np.abs(check - loop_alpha)):.1e} (scale {scale:.2g}); verdicts equal: "
          f"{(maps['eigvals'].stable() == S.stable()).mean() * 100:.2f}% of the grid")

    # --- sage_dynsym on Dask ----------------------------------------------------
    big = {'R1': (-1, 2, args.dask_n), 'R2': (-1, 2, args.dask_n)}
    t0 = time.perf_counter()
    S = stability_map(system, big, fixed=fixed, client=False)
    dt = time.perf_counter() - t0
    total = args.dask_n ** 2
    rows.append((f"  the same on {args.dask_n} x {args.dask_n}", total / dt, dt))
    times = {}
    for workers in (1, 2):
        http = dict(dashboard=False, dashboard_address='127.0.0.1:0')
        with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                          host='127.0.0.1', dashboard_address=None, scheduler_kwargs=http) as cl, \
                Client(cl, set_as_default=False) as client:
            stability_map(system, {'R1': (-1, 2, 50), 'R2': (-1, 2, 50)}, fixed=fixed,
                          client=client)                        # warm-up
            t0 = time.perf_counter()
            T = stability_map(system, big, fixed=fixed, client=client)
            times[workers] = dt = time.perf_counter() - t0
        assert np.array_equal(T.max_real_part(), S.max_real_part(), equal_nan=True)
        rows.append((f"  Dask, {workers} worker{'s' if workers > 1 else ''}",
                     total / dt / workers, dt))

    print(f"  {'':42s} {'points/s/core':>14s} {'vs loop':>8s} {'vs eigvals loop':>16s} {'time':>8s}")
    for name, rate, dt in rows:
        print(f"  {name:42s} {rate:14.0f} {rate * t_loop:7.1f}x {rate * t_eig:15.1f}x "
              f"{'' if dt is None else f'{dt:7.2f}s'}")
    print(f"  scaling 1 -> 2 workers on {args.dask_n} x {args.dask_n}: {times[1] / times[2]:.2f}x "
          f"(ideal 2; load average now {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores)")
    print("  maps on 1 and 2 workers identical to the NumPy map: yes")
    with tempfile.TemporaryDirectory() as tmp:
        S.save(os.path.join(tmp, "map.npz"))
        size = os.path.getsize(os.path.join(tmp, "map.npz"))
    print(f"  map saved as .npz: {size / 1e6:.2f} MB ({S.stable().mean() * 100:.1f}% stable)")


if __name__ == "__main__":
    main()

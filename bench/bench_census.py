"""Benchmark: the census of equilibria of the gyrostat satellite.

The gyrostat satellite on a circular orbit (principal moments 1, 2, 5/2,
a rotor of axial moment 1 along the third axis, orbital rate 1) in the
Euler angles z, x, y, with the angles z, y, x as the regular chart on
their singular set. ``equilibrium_census`` over the gyrostatic moment h > 0
is timed stage by stage (the discriminant by elimination, the exact solve
at each sample point), and compared in the same run with the reference
route: a direct numerical search of the critical points of the amended
potential on SO(3) (SciPy, rotation vectors, 300 random starts) at the
same sample points. The table gives, per cell, both counts and both times.

Target: the whole census within minutes on 2 cores.

``--heavy-top``: the census of the relative equilibria of the asymmetric heavy
top (I = (1, 2, 3), centre of mass r = (1, 1, 1), levels (M, gamma) = c,
(gamma, gamma) = 1) over c, its cells against Staude's parametrization of the
permanent rotations (SciPy/NumPy, tests/test_heavy_top_census.py), and the time
of one exact stability verdict at the sample c = -4 (points of degree 18) in the
number field of the point; with ``--compare`` also by algebraic numbers (QQbar),
the route before (minutes per point).

Usage: python bench/bench_census.py [--quick] [--executor process] [--heavy-top [--compare]]
"""
import argparse
import os
import sys
import time

from sage.all import SR, QQ
from sage_dynsym.analysis.census import equilibrium_census, discriminant_polynomials, \
    equilibria_at, _amended_potential

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, 'tests'))
from gyrostat import VALUES, INERTIA, critical_orientations, gyrostat, gyrostat_torque  # noqa: E402


def direct(h, starts=300):
    """Critical points and minima of W on SO(3), numerically (the reference)."""
    found, minima = critical_orientations(gyrostat_torque(*INERTIA, h), starts=starts, seed=5)
    return len(found), minima


def cell_table(census, symbol, reference, exact, name):
    """Each cell's sample, the census's numbers there (``exact(cell)``) and the
    reference's (``reference(sample)``, timed), and how many cells agree."""
    print(f"{'sample ' + str(symbol):>10} {'exact':>10} {name:>10} {name + ' s':>10}")
    agree = 0
    for cell in census.cells():
        value = cell.sample()[symbol]
        start = time.time()
        ref, mine = tuple(reference(float(value))), tuple(exact(cell))
        agree += ref == mine
        print(f"{str(value):>10} {'/'.join(map(str, mine)):>10} {'/'.join(map(str, ref)):>10} "
              f"{time.time() - start:10.2f}")
    print(f"agreement: {agree} of {len(census.cells())} cells")


def heavy_top(quick, compare):
    """The asymmetric heavy top's verdicts and census (see the module documentation)."""
    from sage.all import var
    from sage_dynsym.lie import LiePoissonSystem
    from sage_dynsym.analysis.leaf_census import relative_equilibria_at
    from sage_dynsym.analysis.point_stability import relative_equilibrium_verdict, \
        _algebraic_leaf_verdict
    from test_heavy_top_census import verdicts
    M1, M2, M3, g1, g2, g3, c = var('M1 M2 M3 gamma1 gamma2 gamma3 c')
    H = (M1**2 + M2**2 / 2 + M3**2 / 3) / 2 + g1 + g2 + g3
    S = LiePoissonSystem('e3', H)
    x, C, J = S.variables(), S.casimirs(), S.poisson_matrix()
    start = time.process_time()
    points, _ = relative_equilibria_at(H, C, J, x, [-4, 1])
    print(f"c = -4: {len(points)} relative equilibria solved and decided in "
          f"{time.process_time() - start:.2f} s CPU")
    values = [points[0][0].value(v) for v in x]
    start = time.process_time()
    verdict = relative_equilibrium_verdict(H, C, J, x, values)
    print(f"one verdict in the number field of the point: {verdict} in "
          f"{time.process_time() - start:.2f} s CPU")
    if compare:
        start = time.process_time()
        verdict = _algebraic_leaf_verdict(H, C, J, x, values)
        print(f"the same by algebraic numbers (QQbar): {verdict} in "
              f"{time.process_time() - start:.1f} s CPU")
    if quick:
        return
    start, cpu = time.time(), time.process_time()
    census = S.equilibrium_census([c], levels=[c, 1])
    print(census)
    print(f"census: {time.time() - start:.1f} s wall, {time.process_time() - cpu:.1f} s CPU "
          f"for {len(census.cells())} cells")
    print("count/stable/stable with those in first approximation:")
    cell_table(census, c, verdicts, lambda cell: (cell.count(), cell.stable_count(),
                                                  cell.stable_count(first_approximation=True)),
               'Staude')


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--quick', action='store_true', help='one sample point only')
    parser.add_argument('--executor', choices=['none', 'process'], default='none',
                        help='solve the sample points in 2 worker processes')
    parser.add_argument('--heavy-top', action='store_true',
                        help='the census of the asymmetric heavy top instead')
    parser.add_argument('--compare', action='store_true',
                        help='with --heavy-top: also one verdict by algebraic numbers')
    args = parser.parse_args()
    if args.heavy_top:
        heavy_top(args.quick, args.compare)
        return
    first, second = gyrostat([(3, 'alpha'), (1, 'beta'), (2, 'gamma')]), \
        gyrostat([(3, 'alpha'), (2, 'beta'), (1, 'gamma')])
    h = first[0].momenta()[0]
    start = time.time()
    q, W = _amended_potential(first[0])
    polys = discriminant_polynomials(SR(W).subs(VALUES), q, [h])
    print(f"discriminant (elimination, Singular): {time.time() - start:.2f} s, "
          f"{len(polys)} factors: {polys}")
    if args.quick:
        for value in (0, QQ(1) / 3):
            start = time.time()
            found = equilibria_at(first[0], {**VALUES, h: value}, first[1],
                                  (second[0].subs(VALUES), second[1]))
            exact_time = time.time() - start
            start = time.time()
            ref = direct(float(value))
            print(f"h = {value}: exact {len(found)} equilibria, "
                  f"{sum(v == 'stable' for _, v in found)} stable in {exact_time:.2f} s; "
                  f"direct numerical {ref[0]}, {ref[1]} in {time.time() - start:.2f} s")
        return
    executor = None
    if args.executor == 'process':
        from concurrent.futures import ProcessPoolExecutor
        executor = ProcessPoolExecutor(max_workers=2)
    start = time.time()
    census = equilibrium_census(first[0], [h], positive=[h], values=VALUES, chart=first[1],
                                regular=second, executor=executor)
    total = time.time() - start
    print(census)
    print(f"census: {total:.1f} s for {len(census.cells())} cells")
    cell_table(census, h, direct, lambda cell: (cell.count(), cell.stable_count()), 'direct')
    if executor is not None:
        executor.shutdown()


if __name__ == '__main__':
    main()

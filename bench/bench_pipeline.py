"""
Benchmark: from the description of an N-link chain to a compiled right-hand
side x' = f(t, x), sage_dynsym against Pinocchio and PyDy in the same run.

Two chains of ``tests/reference/chains.py`` (2 coordinates per link):

- ``spatial``: ``spatial_chain(N)`` of ``bench/bench_chain.py``, link k
  turned about z then x, joints on the previous link's axis, diagonal
  inertias, symbolic masses, lengths and inertias (given values per run);
- ``offset``: ``offset_chain(N)``, link k turned about y then z, joints
  offset from the previous link's axis, full inertia tensors, numbers.

For each chain and N = 2, 4, 6, 8, 12, 20 (``--quick``: 2, 4), every tool
runs in a fresh interpreter with a timeout, one after the other:

- sage_dynsym: the description (a dict of strings, as read from a YAML
  file) -> ``model_from_dict`` -> ``numerical_rhs(values)`` (the recursive
  path), with an empty cache of compiled code: ``build`` is the whole time,
  ``cc`` the part spent in the C compiler; ``derive``: the symbolic Lagrange
  equations in recursive form (``lagrangian('recursive').lagrange_equations()``),
  timed in a process of its own;
- Pinocchio (``pin``): the model built programmatically to match the chain
  (``tests/reference/pinocchio_chain.py``: each rotation a revolute joint,
  the joint offsets as placements); per call ``pinocchio.aba`` alone and a
  full right-hand side from Python (``aba`` on the slices of x, then
  ``numpy.concatenate``), timed in sage_dynsym's process in turn with its
  right-hand side (the best of 15 rounds each), so that a loaded machine
  treats both alike; ``build`` and the accelerations in a process of its own;
- PyDy: ``KanesMethod`` of ``sympy.physics.mechanics`` (the model of
  ``tests/reference/sympy_chain.py``) and ``pydy``'s
  ``generate_ode_function`` with the Cython generator; ``build`` covers both.
  Once it times out at some N it is not run for larger N.

Per call: the best of several repetitions. ``vs pin``: the largest relative
difference of the accelerations to Pinocchio's at 3 random states (``vs
pin`` of PyDy likewise). The growth exponents are least-squares slopes of
log(time) against log(N) over N >= 4. The targets of the pipeline are
checked at the end.

Usage: ``python bench/bench_pipeline.py [--quick] [--n N ...] [--chain
spatial|offset] [--tools sage|derive|pin|pydy ...] [--timeout S]``
"""
import argparse
import json
import math
import os
import random
import subprocess
import sys
import tempfile
import time
import timeit

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, os.pardir, 'tests'))

from reference.chains import spatial_chain, offset_chain, physical_values  # noqa: E402

CHAINS = {'spatial': spatial_chain, 'offset': offset_chain}
SIZES = (2, 4, 6, 8, 12, 20)


def chain_values(name, desc):
    """The parameter values of a run (fixed seeds): physically possible."""
    if name == 'offset':
        return {'g': 9.81}
    return physical_values(desc, random.Random(1))


def states(desc, count=3):
    """Random states, as dicts name -> value over the coordinates and velocities."""
    rng = random.Random(7)
    out = []
    for _ in range(count):
        state = {c: rng.uniform(-1.5, 1.5) for c in desc['coordinates']}
        state.update({'d' + c: rng.uniform(-1, 1) for c in desc['coordinates']})
        out.append(state)
    return out


def _calls(function, args, seconds):
    """How many calls of ``function`` take about ``seconds``."""
    function(*args)
    number, elapsed = 1, 0.0
    while elapsed < seconds / 4:
        number *= 4
        elapsed = timeit.timeit(lambda: function(*args), number=number)
    return max(1, int(number * seconds / elapsed))


def best(function, *args):
    """Seconds per call: the best of 7 repetitions of about 0.05 s each."""
    number = _calls(function, args, 0.05)
    return min(timeit.repeat(lambda: function(*args), number=number, repeat=7)) / number


def best_interleaved(calls, rounds=15):
    """
    Seconds per call of each ``(function, args)`` of ``calls``, timed in turn
    (one repetition of each per round, the best of ``rounds``): on a loaded
    machine the functions see the same conditions.
    """
    numbers = [_calls(f, args, 0.02) for f, args in calls]
    times = [[] for _ in calls]
    for _ in range(rounds):
        for (f, args), number, out in zip(calls, numbers, times):
            out.append(timeit.timeit(lambda: f(*args), number=number) / number)
    return [min(t) for t in times]


def _text(value):
    from fractions import Fraction
    if isinstance(value, Fraction):
        return f"{value.numerator}/{value.denominator}" if value.denominator != 1 \
            else str(value.numerator)
    return str(value).replace('**', '^')


def description(desc):
    """The chain as the mapping of a description file (all strings)."""
    bodies = [dict(name=f'link{k}', parent=b['parent'],
                   rotations=[[axis, angle] for axis, angle in b['rotations']],
                   joint=[_text(c) for c in b['joint']],
                   mass_center=[_text(c) for c in b['mass_center']], mass=_text(b['mass']),
                   inertia=[[_text(c) for c in row] for row in b['inertia']])
              for k, b in enumerate(desc['bodies'], 1)]
    return dict(kind='mechanical', name='chain', parameters=list(desc['parameters']),
                coordinates=list(desc['coordinates']),
                force_function={'uniform_gravity': [_text(g) for g in desc['gravity']]},
                bodies=bodies)


def _order(names, desc):
    return [names.index(c) for c in desc['coordinates']]


def worker_sage(desc, values):
    import numpy as np
    os.environ['SAGE_DYNSYM_CACHE'] = tempfile.mkdtemp(prefix='bench_pipeline_')
    from sage.all import SR  # noqa: F401  (Sage fully initialised before timing)
    import sage_dynsym.numerics.compiler as compiler
    from sage_dynsym.description import model_from_dict
    spent = [0.0]
    compile_c = compiler.compile_c

    def timed(*args, **kwds):
        start = time.perf_counter()
        try:
            return compile_c(*args, **kwds)
        finally:
            spent[0] += time.perf_counter() - start
    compiler.compile_c = timed
    data = description(desc)
    start = time.perf_counter()
    f = model_from_dict(data).numerical_rhs(values)
    build = time.perf_counter() - start
    names = [str(v) for v in f.variables()]
    n = len(names) // 2
    order = _order(names[:n], desc)
    accelerations = []
    for state in states(desc):
        x = np.array([state[k] for k in names])
        accelerations.append(f(0.0, x)[n:][order].tolist())
    result = dict(build=build, cc=spent[0], accelerations=accelerations,
                  solver=f.form().solver())
    try:
        pin_calls = pinocchio_calls(desc, values, x, names)
    except ImportError:
        result['call'] = best(f, 0.0, x)
    else:
        # Pinocchio timed in this process, in turn with ours
        result['call'], result['aba'], result['pin_call'] = best_interleaved(
            [(f, (0.0, x))] + pin_calls)
    return result


def worker_derive(desc, values):
    from sage.all import SR  # noqa: F401  (Sage fully initialised before timing)
    from sage_dynsym.description import model_from_dict
    data = description(desc)
    start = time.perf_counter()
    model_from_dict(data).lagrangian('recursive').lagrange_equations()
    return dict(derive=time.perf_counter() - start)


def pinocchio_calls(desc, values, x, names):
    """
    Pinocchio's ``aba`` and its full right-hand side of the chain at the
    state ``x`` over ``names``, as ``[(function, args), ...]``.
    """
    import numpy as np
    import pinocchio as pin
    from reference.pinocchio_chain import pinocchio_model
    model, order = pinocchio_model(desc, values)
    data = model.createData()
    n = model.nv
    tau = np.zeros(n)
    xp = np.array([x[names.index(c)] for c in order] + [x[names.index('d' + c)] for c in order])

    def rhs(t, x):
        v = x[n:]
        return np.concatenate((v, pin.aba(model, data, x[:n], v, tau)))
    return [(pin.aba, (model, data, xp[:n].copy(), xp[n:].copy(), tau)), (rhs, (0.0, xp))]


def worker_pin(desc, values):
    import numpy as np
    import pinocchio as pin
    from reference.pinocchio_chain import pinocchio_model
    start = time.perf_counter()
    model, order = pinocchio_model(desc, values)
    data = model.createData()
    build = time.perf_counter() - start
    n = model.nv
    tau = np.zeros(n)
    accelerations = []
    position = [order.index(c) for c in desc['coordinates']]
    for state in states(desc):
        q = np.array([state[c] for c in order])
        v = np.array([state['d' + c] for c in order])
        accelerations.append(pin.aba(model, data, q, v, tau)[position].tolist())
    return dict(build=build, accelerations=accelerations)


def worker_pydy(desc, values):
    import numpy as np
    import sympy
    from sympy.physics import mechanics as me
    from pydy.codegen.ode_function_generators import generate_ode_function
    from reference.sympy_chain import SympyChain
    start = time.perf_counter()
    chain = SympyChain(desc['bodies'], desc['coordinates'], desc['gravity'], desc['parameters'])
    q = chain.coordinates
    u = chain.speeds()
    KM = me.KanesMethod(chain.inertial_frame, q_ind=q, u_ind=u,
                        kd_eqs=[a.diff(me.dynamicsymbols._t) - b for a, b in zip(q, u)])
    loads = [(C, b.mass * chain.gravity) for b, C in zip(chain.bodies, chain.mass_centers)]
    KM.kanes_equations(chain.bodies, loads)
    constants = [sympy.Symbol(p) for p in desc['parameters']]
    rhs = generate_ode_function(KM.forcing, q, u, constants, mass_matrix=KM.mass_matrix,
                                coordinate_derivatives=sympy.Matrix(u), generator='cython')
    build = time.perf_counter() - start
    p = np.array([values[str(c)] for c in constants])
    n = len(q)
    accelerations = []
    for state in states(desc):
        x = np.array([state[c] for c in desc['coordinates']]
                     + [state['d' + c] for c in desc['coordinates']])
        accelerations.append(np.asarray(rhs(x, 0.0, p))[n:].tolist())
    return dict(build=build, call=best(rhs, x, 0.0, p), accelerations=accelerations)


WORKERS = {'sage': worker_sage, 'derive': worker_derive, 'pin': worker_pin,
           'pydy': worker_pydy}


def run(tool, chain, n, timeout):
    """One worker in a fresh interpreter: its result dict, 'timeout' or 'error: ...'."""
    cmd = [sys.executable, os.path.abspath(__file__), '--worker', tool, chain, str(n)]
    try:
        out = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return 'timeout'
    lines = [line for line in out.stdout.splitlines() if line.startswith('{')]
    if out.returncode or not lines:
        message = (out.stderr.strip().splitlines() or ['?'])[-1]
        if 'No module named' in message:
            return 'not installed'
        return 'error: ' + message
    return json.loads(lines[-1])


def relative_difference(a, b):
    worst = 0.0
    for x, y in zip(a, b):
        scale = max(1.0, max(abs(v) for v in y))
        worst = max(worst, max(abs(s - r) for s, r in zip(x, y)) / scale)
    return worst


def exponent(points):
    """Least-squares slope of log(y) against log(N) over N >= 4."""
    pts = [(math.log(n), math.log(y)) for n, y in points if n >= 4 and y and y > 0]
    if len(pts) < 2:
        return None
    mx = sum(x for x, _ in pts) / len(pts)
    my = sum(y for _, y in pts) / len(pts)
    sxx = sum((x - mx) ** 2 for x, _ in pts)
    return sum((x - mx) * (y - my) for x, y in pts) / sxx if sxx else None


def _cell(result, key, width, scale=1.0, fmt='.2f'):
    if isinstance(result, dict) and result.get(key) is not None:
        return f"{result[key] * scale:>{width}{fmt}}"
    text = '-' if isinstance(result, dict) or result is None else str(result)
    return f"{text:>{width}.{width}}"


def bench_chain(name, sizes, timeout, tools):
    print(f"\nchain '{name}' ({CHAINS[name].__doc__.strip().splitlines()[0].strip()})")
    print("times: build, derive, cc in s; per call in us; 'vs pin': largest relative "
          "difference of the accelerations to Pinocchio's")
    header = (f"{'N':>3} {'derive':>7} {'build':>7} {'cc':>6} {'call':>7} {'pin aba':>8} "
              f"{'pin RHS':>8} {'PyDy bld':>9} {'PyDy':>7} {'vs pin':>8} {'PyDy vs':>8}")
    print(header, flush=True)
    rows, gave_up = [], set()
    for n in sizes:
        desc = CHAINS[name](n)
        res = {}
        for tool in WORKERS:
            if tool not in tools:
                res[tool] = None
                continue
            res[tool] = 'skipped' if tool in gave_up else run(tool, name, n, timeout)
            if res[tool] in ('timeout', 'not installed'):
                gave_up.add(tool)
        sage, derive, pin, pydy = res['sage'], res['derive'], res['pin'], res['pydy']
        diffs = [relative_difference(r['accelerations'], pin['accelerations'])
                 if isinstance(r, dict) and isinstance(pin, dict) else None for r in (sage, pydy)]
        cells = [f"{n:>3}", _cell(derive, 'derive', 7), _cell(sage, 'build', 7),
                 _cell(sage, 'cc', 6), _cell(sage, 'call', 7, 1e6), _cell(sage, 'aba', 8, 1e6),
                 _cell(sage, 'pin_call', 8, 1e6), _cell(pydy, 'build', 9),
                 _cell(pydy, 'call', 7, 1e6)]
        cells += [f"{d:>8.1e}" if d is not None else f"{'-':>8}" for d in diffs]
        print(" ".join(cells), flush=True)
        for tool, r in res.items():
            if isinstance(r, str) and r != 'skipped':
                print(f"    {tool} at N = {n}: {r}", flush=True)
        rows.append((n, sage, pin, pydy, diffs, derive))
    growth = {}
    for label, tool, key in (('sage_dynsym build', 1, 'build'), ('sage_dynsym derive', 5, 'derive'),
                             ('sage_dynsym per call', 1, 'call'), ('Pinocchio aba', 1, 'aba'),
                             ('Pinocchio RHS', 1, 'pin_call'), ('PyDy build', 3, 'build')):
        points = [(row[0], row[tool][key]) for row in rows if isinstance(row[tool], dict)]
        growth[label] = exponent(points)
    print("growth exponents (N >= 4): " + ", ".join(
        f"{k} {v:.2f}" for k, v in growth.items() if v is not None))
    return rows, growth


def targets(rows, growth):
    """The pipeline's targets, checked on the rows of one chain."""
    by_n = {row[0]: row for row in rows}
    lines = []

    def check(label, ok):
        lines.append(f"  [{'met' if ok else 'NOT met'}] {label}")
    for n, limit in ((8, 10), (12, 30), (20, 60)):
        if n in by_n and isinstance(by_n[n][1], dict):
            check(f"N = {n}: description -> compiled RHS {by_n[n][1]['build']:.1f} s "
                  f"< {limit} s", by_n[n][1]['build'] < limit)
    if growth.get('sage_dynsym build') is not None:
        check(f"growth exponent of the build {growth['sage_dynsym build']:.2f} <= 2",
              growth['sage_dynsym build'] <= 2)
    for n in (8, 12, 20):
        if n in by_n and isinstance(by_n[n][1], dict) and 'pin_call' in by_n[n][1]:
            ours, theirs = by_n[n][1]['call'], by_n[n][1]['pin_call']
            check(f"N = {n}: per call {1e6 * ours:.2f} us <= Pinocchio's full RHS "
                  f"{1e6 * theirs:.2f} us", ours <= theirs)
    worst = [row[4][0] for row in rows if row[4][0] is not None]
    if worst:
        check(f"accelerations equal to Pinocchio's: largest relative difference "
              f"{max(worst):.1e} <= 1e-10", max(worst) <= 1e-10)
    if 20 in by_n and isinstance(by_n[20][5], dict):
        check(f"N = 20: recursive symbolic derivation {by_n[20][5]['derive']:.1f} s < 10 s",
              by_n[20][5]['derive'] < 10)
    elif 20 in by_n and by_n[20][5] is not None:
        check(f"N = 20: recursive symbolic derivation: {by_n[20][5]}", False)
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--quick', action='store_true', help='N = 2, 4 only')
    parser.add_argument('--n', type=int, nargs='*', default=None)
    parser.add_argument('--chain', choices=list(CHAINS), nargs='*', default=None)
    parser.add_argument('--timeout', type=float, default=None)
    parser.add_argument('--tools', choices=list(WORKERS), nargs='*', default=None,
                        help='run only these tools (default: all)')
    parser.add_argument('--worker', nargs=3, help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.worker:
        tool, name, n = args.worker
        desc = CHAINS[name](int(n))
        print(json.dumps(WORKERS[tool](desc, chain_values(name, desc))), flush=True)
        return
    sizes = args.n or ((2, 4) if args.quick else SIZES)
    timeout = args.timeout or (120 if args.quick else 300)
    print("From a chain's description to a compiled right-hand side: sage_dynsym "
          f"vs Pinocchio and PyDy; one tool at a time, timeout {timeout:g} s per run")
    summary = []
    for name in args.chain or list(CHAINS):
        rows, growth = bench_chain(name, sizes, timeout, args.tools or list(WORKERS))
        summary.append((name, targets(rows, growth)))
    print("\ntargets:")
    for name, lines in summary:
        print(f" chain '{name}':")
        print("\n".join(lines) if lines else "  (no sizes measured for the targets)")


if __name__ == '__main__':
    main()

"""
Benchmark: models of robot size and their Jacobians, sage_dynsym against
Pinocchio in the same run.

Models (plain data of ``tests/reference/chains.py``):

- ``offset_chain(N)``: N links, 2 coordinates each (rotations about y then
  z), joints offset from the previous link's axis, full inertia tensors;
- ``humanoid_tree()``: 46 coordinates on a free-floating base (three
  translations, three rotations), a torso with a head, two arms with hands of
  three fingers, two legs: several children per body.

For each model every tool runs in a fresh interpreter with a timeout:

- sage_dynsym: the description (a dict of strings, as read from a YAML file)
  -> ``model_from_dict`` -> ``numerical_rhs(values)`` with an empty cache of
  compiled code (``build``), then ``numerical_rhs(values, jacobian=True)``
  (``jac build``: the differentiation and compilation of the Jacobian);
  per call the right-hand side and the Jacobian (the best of several
  repetitions);
- Pinocchio (``pin``, in the interpreter given by ``--pin-python`` or
  ``$PIN_PYTHON``, default this one): the model built programmatically
  (``tests/reference/pinocchio_chain.py``: elementary revolute and prismatic
  joints); per call ``aba``, a full right-hand side from Python (``aba`` on
  the slices of x, ``numpy.concatenate``) and the state Jacobian
  (``computeABADerivatives`` and the assembly of ``[[0, I], [ddq_dq,
  ddq_dv]]``). With ``--pin-site`` (a site directory holding Pinocchio,
  e.g. ``<venv>/lib/python3.11/site-packages`` of a venv with the same
  NumPy) Pinocchio is also loaded in sage_dynsym's process and the times
  per call are taken in turn there (short measurements, the best of each,
  see :func:`in_turn`), so that a loaded machine treats both alike.

Accuracy: the largest relative difference of the accelerations to
Pinocchio's ``aba`` at 3 random states (target 1e-10), of the Jacobian to
Pinocchio's derivatives and to central differences of the compiled
right-hand side (targets 1e-7). The growth exponents are least-squares slopes
of log(time) against log(N). The full run adds the build time of the
right-hand side of a 500-link chain (1,000 coordinates; no Jacobian;
``--no-large`` leaves it out, ``--large`` adds it to ``--quick``).

Usage: ``python bench/bench_robot.py [--quick] [--n N ...] [--no-humanoid]
[--large | --no-large] [--pin-python PATH] [--pin-site DIR] [--timeout S]`` (``--quick``: N =
4, 8, no humanoid, no 500 links). Pinocchio's interpreter needs ``pin``, ``numpy`` and
``sympy`` (e.g. ``python3.11 -m venv /tmp/pin && /tmp/pin/bin/pip install pin numpy sympy``,
then ``--pin-python /tmp/pin/bin/python --pin-site
/tmp/pin/lib/python3.11/site-packages``).
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, os.pardir, 'tests'))

from bench_pipeline import (description, states, best, exponent,  # noqa: E402
                            relative_difference)
from reference.chains import offset_chain, humanoid_tree  # noqa: E402
from reference.numerics import central_differences  # noqa: E402

SIZES = (20, 50, 100)


def model(name, n):
    """The plain-data description and the parameter values of a model."""
    return (humanoid_tree() if name == 'humanoid' else offset_chain(n)), {'g': 9.81}


def worker_sage(name, n, jacobian=True):
    import numpy as np
    import site
    if os.environ.get('PIN_SITE'):
        site.addsitedir(os.environ['PIN_SITE'])     # after this interpreter's own packages
    os.environ['SAGE_DYNSYM_CACHE'] = tempfile.mkdtemp(prefix='bench_robot_')
    from sage.all import SR  # noqa: F401  (Sage fully initialised before timing)
    from sage_dynsym.description import model_from_dict
    desc, values = model(name, n)
    data = description(desc)
    start = time.perf_counter()
    S = model_from_dict(data)
    f = S.numerical_rhs(values)
    result = dict(build=time.perf_counter() - start)
    names = [str(v) for v in f.variables()]
    k = len(names) // 2
    order = [names.index(c) for c in desc['coordinates']]
    points = [np.array([state[c] for c in names]) for state in states(desc)]
    result['accelerations'] = [f(0.0, x)[k:][order].tolist() for x in points]
    result['call'] = best(f, 0.0, points[0])
    if jacobian:
        start = time.perf_counter()
        _, jac = S.numerical_rhs(values, jacobian=True)
        result['jac_build'] = time.perf_counter() - start
        J = jac(0.0, points[0])
        result['jac_call'] = best(jac, 0.0, points[0])
        try:
            pin_rhs, pin_jacobian, pin = pinocchio_functions(name, n)
        except ImportError:
            pass
        else:
            # Pinocchio in this process, timed in turn with sage_dynsym: on a
            # loaded machine both see the same conditions
            # each pair alone: the large code of the Jacobians would evict the
            # right-hand sides' from the caches between their measurements
            result['call'], result['pin_rhs'] = in_turn([(f, (0.0, points[0])),
                                                         (pin_rhs, (0.0, pin['x']))])
            result['jac_call'], result['pin_jac'] = in_turn([(jac, (0.0, points[0])),
                                                             (pin_jacobian, (0.0, pin['x']))])
        reference = central_differences(f, points[0])
        result['jac_vs_cd'] = float(np.max(np.abs(J - reference))
                                    / max(1.0, np.max(np.abs(reference))))
        # in the order of desc['coordinates'] then their velocities
        full = order + [k + i for i in order]
        result['jacobian'] = J[np.ix_(full, full)].tolist()
    return result


def in_turn(calls, seconds=3.0):
    """
    Seconds per call of each ``(function, args)`` of ``calls``: short
    measurements (about 0.5 ms) taken in turn for about ``seconds`` in all,
    the best of each. On a machine shared by many processes a short
    measurement is often not interrupted, so the best is the uncontended
    time (longer ones are always interrupted), and taken in turn the
    functions see the same conditions.
    """
    import timeit
    numbers = []
    for function, args in calls:
        function(*args)
        elapsed = timeit.timeit(lambda: function(*args), number=10) / 10
        numbers.append(max(1, int(5e-4 / max(elapsed, 1e-9))))
    best_times = [math.inf] * len(calls)
    end = time.perf_counter() + seconds
    while time.perf_counter() < end:
        for k, ((function, args), number) in enumerate(zip(calls, numbers)):
            elapsed = timeit.timeit(lambda: function(*args), number=number) / number
            best_times[k] = min(best_times[k], elapsed)
    return best_times


def pinocchio_functions(name, n):
    """
    Pinocchio's model of a model, and ``(rhs, jacobian, result)``: its full
    right-hand side and state Jacobian as functions of ``(t, x)`` (x over
    the model's own order of the coordinates) and the build time,
    accelerations at the states and Jacobian at the first one (in the order
    of the description's coordinates).
    """
    import numpy as np
    import pinocchio as pin
    from reference.pinocchio_chain import pinocchio_model
    desc, values = model(name, n)
    start = time.perf_counter()
    pmodel, order = pinocchio_model(desc, values)
    data = pmodel.createData()
    result = dict(build=time.perf_counter() - start)
    nv = pmodel.nv
    tau = np.zeros(nv)
    position = [order.index(c) for c in desc['coordinates']]
    points = [(np.array([state[c] for c in order]), np.array([state['d' + c] for c in order]))
              for state in states(desc)]
    result['accelerations'] = [pin.aba(pmodel, data, q, v, tau)[position].tolist()
                               for q, v in points]

    def rhs(t, x):
        v = x[nv:]
        return np.concatenate((v, pin.aba(pmodel, data, x[:nv], v, tau)))

    def jacobian(t, x):
        pin.computeABADerivatives(pmodel, data, x[:nv], x[nv:], tau)
        J = np.zeros((2 * nv, 2 * nv))
        J[:nv, nv:] = np.eye(nv)
        J[nv:, :nv] = data.ddq_dq
        J[nv:, nv:] = data.ddq_dv
        return J
    x = np.concatenate(points[0])
    full = position + [nv + i for i in position]
    result['jacobian'] = jacobian(0.0, x)[np.ix_(full, full)].tolist()
    result['x'] = x
    return rhs, jacobian, result


def worker_pin(name, n):
    rhs, jacobian, result = pinocchio_functions(name, n)
    x = result.pop('x')
    result['rhs'] = best(rhs, 0.0, x)
    result['jac_call'] = best(jacobian, 0.0, x)
    return result


def run(tool, name, n, timeout, python=None, jacobian=True):
    """One worker in a fresh interpreter: its result dict, 'timeout' or 'error: ...'."""
    cmd = [python or sys.executable, os.path.abspath(__file__), '--worker', tool, name, str(n)]
    if not jacobian:
        cmd.append('--no-jacobian')
    env = dict(os.environ)
    if tool == 'pin':
        env.pop('PYTHONPATH', None)     # the other interpreter's own packages only
    try:
        out = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout, env=env)
    except subprocess.TimeoutExpired:
        return 'timeout'
    lines = [line for line in out.stdout.splitlines() if line.startswith('{')]
    if out.returncode or not lines:
        message = (out.stderr.strip().splitlines() or ['?'])[-1]
        return 'not installed' if 'No module named' in message else 'error: ' + message
    return json.loads(lines[-1])


def matrix_difference(a, b):
    import numpy as np
    a, b = np.array(a), np.array(b)
    return float(np.max(np.abs(a - b)) / max(1.0, np.max(np.abs(b))))


def _cell(result, key, width, scale=1.0, fmt='.2f'):
    if isinstance(result, dict) and result.get(key) is not None:
        return f"{result[key] * scale:>{width}{fmt}}"
    return f"{'-':>{width}}"


def _ratio(a, b, key_a, key_b, width):
    if isinstance(a, dict) and isinstance(b, dict) and a.get(key_a) and b.get(key_b):
        return f"{a[key_a] / b[key_b]:>{width}.2f}"
    return f"{'-':>{width}}"


def timings(sage, pin):
    """Pinocchio's times per call: those measured in turn with sage_dynsym
    when there are, else those of its own process."""
    if isinstance(sage, dict) and 'pin_rhs' in sage:
        return dict(rhs=sage['pin_rhs'], jac_call=sage['pin_jac'])
    return pin if isinstance(pin, dict) else None


def table(rows):
    print(f"{'model':>9} {'n':>4} {'build':>6} {'jac bld':>7} {'call':>7} {'pin RHS':>8} "
          f"{'ratio':>6} {'jac':>8} {'pin jac':>8} {'ratio':>6} {'acc vs pin':>10} "
          f"{'J vs pin':>9} {'J vs cd':>8}")
    for label, n, sage, pin in rows:
        times = timings(sage, pin)
        acc = (relative_difference(sage['accelerations'], pin['accelerations'])
               if isinstance(sage, dict) and isinstance(pin, dict) else None)
        jd = (matrix_difference(sage['jacobian'], pin['jacobian'])
              if isinstance(sage, dict) and isinstance(pin, dict) and 'jacobian' in sage
              else None)
        print(" ".join([f"{label:>9}", f"{n:>4}", _cell(sage, 'build', 6, fmt='.1f'),
                        _cell(sage, 'jac_build', 7, fmt='.1f'), _cell(sage, 'call', 7, 1e6),
                        _cell(times, 'rhs', 8, 1e6), _ratio(sage, times, 'call', 'rhs', 6),
                        _cell(sage, 'jac_call', 8, 1e6, '.1f'),
                        _cell(times, 'jac_call', 8, 1e6, '.1f'),
                        _ratio(sage, times, 'jac_call', 'jac_call', 6),
                        f"{acc:>10.1e}" if acc is not None else f"{'-':>10}",
                        f"{jd:>9.1e}" if jd is not None else f"{'-':>9}",
                        _cell(sage, 'jac_vs_cd', 8, fmt='.1e')]), flush=True)
        for tool, r in (('sage_dynsym', sage), ('pin', pin)):
            if isinstance(r, str):
                print(f"    {tool}: {r}")


def targets(rows, large):
    lines = []

    def check(label, ok):
        lines.append(f"  [{'met' if ok else 'NOT met'}] {label}")
    chain = {n: (sage, pin) for label, n, sage, pin in rows if label == 'chain'}
    for n, limit in ((50, 10), (100, 30)):
        if n in chain and isinstance(chain[n][0], dict):
            check(f"{n} links: description -> compiled RHS {chain[n][0]['build']:.1f} s "
                  f"< {limit} s", chain[n][0]['build'] < limit)
    if isinstance(large, dict):
        check(f"500 links: description -> compiled RHS {large['build']:.1f} s < 180 s",
              large['build'] < 180)
    for label, n, sage, pin in rows:
        if isinstance(sage, dict) and isinstance(pin, dict):
            limit = 0.5 if label == 'humanoid' else 0.4
            times = timings(sage, pin)
            ratio = sage['call'] / times['rhs']
            check(f"{label} {n}: per call {ratio:.2f}x Pinocchio's full RHS <= {limit}",
                  ratio <= limit)
            if 'jac_call' in sage:
                ratio = sage['jac_call'] / times['jac_call']
                check(f"{label} {n}: Jacobian per call {ratio:.2f}x Pinocchio's "
                      "computeABADerivatives + assembly <= 1", ratio <= 1)
            acc = relative_difference(sage['accelerations'], pin['accelerations'])
            check(f"{label} {n}: accelerations vs aba {acc:.1e} <= 1e-10", acc <= 1e-10)
            if 'jacobian' in sage:
                jd = matrix_difference(sage['jacobian'], pin['jacobian'])
                check(f"{label} {n}: Jacobian vs Pinocchio's derivatives {jd:.1e} <= 1e-7",
                      jd <= 1e-7)
        if isinstance(sage, dict) and 'jac_vs_cd' in sage:
            check(f"{label} {n}: Jacobian vs central differences {sage['jac_vs_cd']:.1e} "
                  "<= 1e-7", sage['jac_vs_cd'] <= 1e-7)
    return lines


def growth(rows, large):
    points = {key: [(n, sage[key]) for label, n, sage, _ in rows
                    if label == 'chain' and isinstance(sage, dict) and key in sage]
              for key in ('build', 'jac_build', 'call', 'jac_call')}
    if isinstance(large, dict):
        points['build'].append((500, large['build']))
    pin_points = {key: [(n, timings(sage, pin)[key]) for label, n, sage, pin in rows
                        if label == 'chain' and isinstance(pin, dict)]
                  for key in ('rhs', 'jac_call')}
    out = []
    for label, pts in (('build', points['build']), ('jac build', points['jac_build']),
                       ('per call', points['call']), ('jac per call', points['jac_call']),
                       ('Pinocchio RHS', pin_points['rhs']),
                       ('Pinocchio jac', pin_points['jac_call'])):
        slope = exponent(pts)
        if slope is not None:
            out.append(f"{label} {slope:.2f}")
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--quick', action='store_true', help='N = 4, 8 only, no humanoid')
    parser.add_argument('--n', type=int, nargs='*', default=None)
    parser.add_argument('--no-humanoid', action='store_true')
    parser.add_argument('--large', action='store_true',
                        help='the build time of a 500-link chain also with --quick')
    parser.add_argument('--no-large', action='store_true',
                        help='without the build time of a 500-link chain')
    parser.add_argument('--pin-python', default=os.environ.get('PIN_PYTHON'),
                        help="the interpreter with Pinocchio (default: this one)")
    parser.add_argument('--pin-site', default=os.environ.get('PIN_SITE'),
                        help="a site directory with Pinocchio, for timing it in turn with "
                        "sage_dynsym in one process (NumPy must be the same version)")
    parser.add_argument('--timeout', type=float, default=None)
    parser.add_argument('--worker', nargs=3, help=argparse.SUPPRESS)
    parser.add_argument('--no-jacobian', action='store_true', help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.worker:
        tool, name, n = args.worker
        if tool == 'sage':
            result = worker_sage(name, int(n), jacobian=not args.no_jacobian)
        else:
            result = worker_pin(name, int(n))
        print(json.dumps(result), flush=True)
        return
    if args.pin_site:
        os.environ['PIN_SITE'] = args.pin_site
    sizes = args.n or ((4, 8) if args.quick else SIZES)
    timeout = args.timeout or (300 if args.quick else 1200)
    print("Robot-size models: sage_dynsym vs Pinocchio, each tool in a fresh interpreter, "
          f"timeout {timeout:g} s per run")
    print("times: build in s; per call in us; ratio: sage_dynsym / Pinocchio; accuracy: "
          "largest relative differences")
    models = [('chain', n) for n in sizes]
    if not (args.quick or args.no_humanoid):
        models.append(('humanoid', 46))
    rows = []
    for label, n in models:
        name = 'humanoid' if label == 'humanoid' else 'offset'
        sage = run('sage', name, n, timeout)
        pin = run('pin', name, n, timeout, python=args.pin_python)
        rows.append((label, n, sage, pin))
    table(rows)
    with_large = (args.large or not args.quick) and not args.no_large
    large = run('sage', 'offset', 500, max(timeout, 900), jacobian=False) if with_large \
        else None
    if large is not None:
        print(f"500 links (1,000 coordinates): description -> compiled RHS "
              f"{large['build'] if isinstance(large, dict) else large}"
              f"{' s' if isinstance(large, dict) else ''}")
    print("growth exponents in N (chains): " + ", ".join(growth(rows, large)))
    print("\ntargets:")
    print("\n".join(targets(rows, large)))


if __name__ == '__main__':
    main()

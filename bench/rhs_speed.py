"""
Evaluation speed of the right-hand side x' = f(t, x) of the N-link spatial chain:
sage_dynsym's compiled ``numerical_rhs`` against SymPy.

The chain is the plain-data ``spatial_chain(N)`` of ``tests/reference/chains.py``
(see ``bench/bench_chain.py``), built by sage_dynsym (``MechanicalSystem``,
Lagrange equations, ``numerical_rhs``: mass matrix and forcing evaluated by
generated C with common subexpressions, solved per call) and by
``sympy.physics.mechanics`` (``tests/reference/sympy_chain.py``) with
``KanesMethod`` (generalized speeds u = q'), whose ``mass_matrix`` and
``forcing`` -- and ``mass_matrix_full`` / ``forcing_full`` -- are compiled with
``lambdify(cse=True)`` and solved with ``numpy.linalg.solve`` per call.

Both right-hand sides are evaluated at the same random state (they must
agree) and timed per call; the ratio is SymPy's faster variant over
sage_dynsym. ``compare_rhs(n)`` is also called by ``bench/bench_chain.py``.

Usage: ``python bench/rhs_speed.py [--quick] [--n N ...] [--calls K]``
"""
import argparse
import os
import random
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, os.pardir, 'tests'))

from reference.chains import physical_values, spatial_chain  # noqa: E402
from sage_chains import sage_chain  # noqa: E402


def kane_chain(desc):
    """
    SymPy's ``KanesMethod`` on the reference chain: returns ``(KM, q, u,
    parameters)`` with plain symbols (q, u, parameter symbols) substituted
    for the dynamic symbols in ``mass_matrix``, ``forcing`` and the full forms
    (attributes ``M``, ``F``, ``M_full``, ``F_full`` of the returned dict).
    """
    import sympy
    from sympy.physics import mechanics as me
    from reference.sympy_chain import SympyChain
    chain = SympyChain(desc['bodies'], desc['coordinates'], desc['gravity'], desc['parameters'])
    q = chain.coordinates
    u = me.dynamicsymbols(' '.join(f"u_{c}" for c in desc['coordinates']))
    u = list(u) if isinstance(u, (list, tuple)) else [u]
    kd = [qi.diff(me.dynamicsymbols._t) - ui for qi, ui in zip(q, u)]
    names = {p: sympy.Symbol(p) for p in desc['parameters']}
    N = chain.inertial_frame
    gravity = sum((sympy.parse_expr(str(c), local_dict=dict(names)) * e
                   for c, e in zip(desc['gravity'], (N.x, N.y, N.z))), me.Vector(0))
    loads = [(C, body.mass * gravity) for C, body in zip(chain.mass_centers, chain.bodies)]
    KM = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    KM.kanes_equations(chain.bodies, loads)
    plain_q = [sympy.Symbol(c) for c in desc['coordinates']]
    plain_u = [sympy.Symbol('d' + c) for c in desc['coordinates']]
    rule = dict(zip(q, plain_q)) | dict(zip(u, plain_u))
    return dict(M=KM.mass_matrix.xreplace(rule), F=KM.forcing.xreplace(rule),
                M_full=KM.mass_matrix_full.xreplace(rule), F_full=KM.forcing_full.xreplace(rule),
                q=plain_q, u=plain_u, parameters=[names[p] for p in desc['parameters']])


def sympy_rhs(kane, values):
    """The two SymPy right-hand sides (n x n and full 2n x 2n solves)."""
    import sympy
    args = kane['q'] + kane['u'] + kane['parameters']
    p = [values[str(s)] for s in kane['parameters']]
    n = len(kane['q'])
    M = sympy.lambdify(args, kane['M'], cse=True)
    F = sympy.lambdify(args, kane['F'], cse=True)
    M_full = sympy.lambdify(args, kane['M_full'], cse=True)
    F_full = sympy.lambdify(args, kane['F_full'], cse=True)

    def small(t, x):
        a = (*x, *p)
        return np.concatenate([x[n:], np.linalg.solve(M(*a), F(*a)).ravel()])

    def full(t, x):
        a = (*x, *p)
        return np.linalg.solve(M_full(*a), F_full(*a)).ravel()
    return small, full


def per_call(f, x, calls):
    f(0.0, x)
    start = time.perf_counter()
    for _ in range(calls):
        f(0.0, x)
    return (time.perf_counter() - start) / calls


def compare_rhs(n, calls=2000, seed=1, verbose=True):
    """
    Build the N-link chain both ways, check that the right-hand sides
    agree at a random state, and time one call of each.

    OUTPUT: dict with ``sage_rhs_us`` (compiled numerical_rhs), ``sage_python_us``
    (its Python fallback), ``sympy_rhs_us`` / ``sympy_full_us`` (lambdify(cse=True)
    of Kane's mass_matrix/forcing, resp. the full forms, + numpy solve),
    ``ratio`` (the faster SymPy variant / sage_dynsym), ``max_rel_diff``,
    and the build times ``sage_build_s`` (equations + compilation) and
    ``sympy_build_s`` (KanesMethod + lambdify).
    """
    from sage_dynsym.numerics import numerical_rhs
    desc = spatial_chain(n)
    rng = random.Random(seed)
    values = physical_values(desc, rng)
    start = time.perf_counter()
    record = sage_chain(desc).lagrangian().to_linearizer()
    sage = numerical_rhs(record, values)
    sage_build = time.perf_counter() - start
    python = numerical_rhs(record, values, backend='python')
    start = time.perf_counter()
    kane = kane_chain(desc)
    small, full = sympy_rhs(kane, values)
    sympy_build = time.perf_counter() - start
    # the same state for both: (q, dq) by name
    names = [str(v) for v in sage.variables()]
    state = {c: rng.uniform(-1.5, 1.5) for c in desc['coordinates']}
    state.update({'d' + c: rng.uniform(-1, 1) for c in desc['coordinates']})
    x_sage = np.array([state[k] for k in names])
    x_sympy = np.array([state[str(s)] for s in kane['q'] + kane['u']])
    order = [names.index(str(s)) for s in kane['q'] + kane['u']]
    reference = small(0.0, x_sympy)
    got = sage(0.0, x_sage)[order]
    scale = max(1.0, float(np.max(np.abs(reference))))
    diff = max(float(np.max(np.abs(got - reference))),
               float(np.max(np.abs(full(0.0, x_sympy) - reference)))) / scale
    result = dict(n=n, sage_rhs_us=1e6 * per_call(sage, x_sage, calls),
                  sage_python_us=1e6 * per_call(python, x_sage, max(1, calls // 10)),
                  sympy_rhs_us=1e6 * per_call(small, x_sympy, max(1, calls // 4)),
                  sympy_full_us=1e6 * per_call(full, x_sympy, max(1, calls // 4)),
                  max_rel_diff=diff, sage_build_s=sage_build, sympy_build_s=sympy_build,
                  backend=sage.backend())
    result['ratio'] = min(result['sympy_rhs_us'], result['sympy_full_us']) / result['sage_rhs_us']
    if verbose:
        print(f"N={n}: right-hand side per call: sage_dynsym {result['sage_rhs_us']:.1f} us "
              f"({result['backend']}; Python fallback {result['sage_python_us']:.1f} us), "
              f"SymPy Kane lambdify(cse=True) + solve {result['sympy_rhs_us']:.1f} us "
              f"(full forms {result['sympy_full_us']:.1f} us); ratio {result['ratio']:.1f}x; "
              f"max rel diff {diff:.1e}; build {sage_build:.2f} s vs {sympy_build:.2f} s",
              flush=True)
    return result


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--quick', action='store_true', help='N = 2 only, fewer calls')
    parser.add_argument('--n', type=int, nargs='*', default=None)
    parser.add_argument('--calls', type=int, default=None)
    args = parser.parse_args()
    sizes = args.n or ([2] if args.quick else [2, 3, 4])
    calls = args.calls or (200 if args.quick else 2000)
    print("Right-hand side of the N-link spatial chain: compiled numerical_rhs vs SymPy "
          "KanesMethod + lambdify(cse=True) + numpy.linalg.solve")
    for n in sizes:
        compare_rhs(n, calls=calls)


if __name__ == '__main__':
    main()

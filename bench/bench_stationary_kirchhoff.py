"""Benchmark: stationary sets of Kirchhoff's equations with symbolic parameters.

Kirchhoff's equations of a rigid body in an ideal fluid on e(3)*,
dM/dt = M x dH/dM + p x dH/dp, dp/dt = p x dH/dM, with the Hamiltonian

    H = 1/2 (M, A M) + (M, B p) + 1/2 (p, C p),  A, C diagonal,

and the Casimirs p.p and M.p: ``stationary_solutions([H, p.p, M.p], ...)``
(the Routh-Lyapunov stationary set, multipliers lambda1, lambda2) is timed
for

- Clebsch's case, B = 0 and c_i = theta a_j a_k (one parameter besides A);
- B diagonal (three more parameters);
- B symmetric with the parameters given rational values (``GENERIC``);
- B symmetric (the generic Hamiltonian with A diagonal: six more).

Each run has a budget (``--budget`` seconds, Sage's ``alarm``); a run over
budget is reported as such, not waited for. With ``-v`` the solver's
progress (Sage's ``verbose``: translation, factorizing Groebner basis,
components) is printed.

Target (issue 33): each under a minute.

Usage: python bench/bench_stationary_kirchhoff.py [--budget 120] [-v]
"""
import argparse
import time

from sage.all import SR, var, vector, matrix, alarm, cancel_alarm, set_verbose
from cysignals.signals import AlarmInterrupt

from sage_dynsym.analysis.stationary import stationary_solutions

M = list(var('M1 M2 M3'))
P = list(var('p1 p2 p3'))
A = list(var('a1 a2 a3'))
C = list(var('c1 c2 c3'))
theta = var('theta')


def kirchhoff(B, C):
    Mv, pv = vector(SR, M), vector(SR, P)
    H = (sum(A[i] * M[i]**2 + C[i] * P[i]**2 for i in range(3)) / 2 + Mv * B * pv)
    w = vector(SR, [H.diff(x) for x in M])
    u = vector(SR, [H.diff(x) for x in P])
    X = list(Mv.cross_product(w) + pv.cross_product(u)) + list(pv.cross_product(w))
    return [H, pv * pv, Mv * pv], X


#: Rational values of a_i, b_ij, c_i for the generic case (no symmetry).
GENERIC = {'a1': 3, 'a2': 5, 'a3': 7, 'b11': 1, 'b12': 2, 'b13': -1, 'b22': 3,
           'b23': 1, 'b33': 2, 'c1': 11, 'c2': 13, 'c3': 17}


def cases():
    zero = matrix(SR, 3, 3)
    diagonal = matrix.diagonal(SR, list(var('b1 b2 b3')))
    symmetric = matrix(SR, 3, 3, lambda i, j: SR.var(f"b{min(i, j) + 1}{max(i, j) + 1}"))
    clebsch = [theta * A[1] * A[2], theta * A[0] * A[2], theta * A[0] * A[1]]
    return [("Clebsch (B = 0, c_i = theta a_j a_k)", zero, clebsch),
            ("B diagonal", diagonal, C),
            # before the symbolic case: a Singular library call stopped by
            # the alarm leaves Singular's interpreter without a basering
            ("B symmetric, values given", symmetric, C, GENERIC),
            ("B symmetric (generic)", symmetric, C)]


def run(name, B, Cs, budget, values=None):
    integrals, X = kirchhoff(B, Cs)
    if values:
        values = {SR.var(k): v for k, v in values.items()}
        integrals = [f.subs(values) for f in integrals]
        X = [e.subs(values) for e in X]
    t0 = time.time()
    try:
        alarm(budget)
        sols = stationary_solutions(integrals, M + P, equations=X)
        cancel_alarm()
    except AlarmInterrupt:
        return f"{name:40s} over the budget of {budget} s"
    seconds = time.time() - t0
    dims = sorted(s.dimension() for s in sols)
    implicit = sum(1 for s in sols if not s.is_explicit())
    return (f"{name:40s} {seconds:7.1f} s: {len(sols)} solutions, dimensions {dims}, "
            f"{implicit} implicit")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--budget', type=int, default=120, help="seconds per case")
    parser.add_argument('-v', action='store_true', help="the solver's progress")
    args = parser.parse_args()
    if args.v:
        set_verbose(1)
    for case in cases():
        print(run(*case[:3], args.budget, *case[3:]), flush=True)


if __name__ == '__main__':
    main()

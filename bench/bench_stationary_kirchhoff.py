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
- B symmetric (the generic Hamiltonian with A diagonal: six more);
- Brun's problem, a rigid body with a fixed point in a quadratic potential
  on e(3)* (gamma the unit vertical in the body),

      H = 1/2 (M, A M) + epsilon/2 (gamma, A^{-1} gamma),

  with its extra integral F = 1/2 (M, M) - epsilon/(2 a1 a2 a3) (gamma, A gamma)
  (the Clebsch case of Kirchhoff's equations with c_i = epsilon/a_i;
  A. V. Borisov, I. S. Mamaev, *Rigid Body Dynamics*, De Gruyter 2018,
  Brun's problem): ``stationary_solutions([H, F, gamma.gamma, M.gamma],
  levels=[None, 1, c])`` on both Casimir levels, c = 0 and c symbolic.

Each run has a budget (``--budget`` seconds, ``stationary_solutions(...,
budget=)``: the solving runs in a forked process, stopped at the budget);
a run over budget is reported as such, not waited for. The CPU time is
that of this process and its children. With ``-v`` the solver's
progress (Sage's ``verbose``: translation, factorizing Groebner basis,
components) is printed.

Target (issue 33): each under a minute. Measured 2026-12-05 on 2 cores
loaded by other jobs (wall / CPU of this process and its children):
Clebsch 1.8 / 1.1 s, B diagonal 6.2 / 4.1 s, B symmetric with values
13.0 / 8.9 s, Brun on M.gamma = 0 6.7 / 4.4 s, Brun on M.gamma = c
62 / 44 s (45 to 53 s wall in runs without the budget's fork; 20 to 36 s
of it one Groebner basis, in the block order of the 1-parameter family,
over the field of the 5 parameters, and about 15 s the characteristic
sets at the random values that decide that its parts are prime). The
generic case with symbolic parameters is still over the budget. Its first
Groebner basis (degrevlex over the field of the 12 parameters) takes 1.5 s
with M first and the multipliers last, over 100 s with p before M (the
translation's order puts the multipliers first, then p, then M); but then
its two components (M = p = 0, and the family where p is a kernel vector)
are split in half a second at rational values and not within minutes over
the field: saturation by p1 over 300 s, the quotient by p1, minAssChar
and minAssGTZ each over 200 s, and after M is substituted (it enters
linearly) one Groebner basis of the 5 remaining unknowns 130 s. Putting
the unknowns in their own order (M first, multipliers last) for every
problem made Brun's problem on M.gamma = c take over 300 s.

Measured 2026-12-05 (fourth session) on the generic case: in the block
order (M, p | lambda), degrevlex in each block, the Groebner basis of the
Lagrange system takes 0.04 s with lambda1 (the multiplier of p.p) before
lambda2 and 21 s with them swapped (plain degrevlex: 7 to over 15 s in
every order tried). The system is homogeneous in (M, p) (the multipliers
of degree 0), so its saturation by p1 is that basis with each element
divided by its largest power of p1 (Bayer's criterion, p1 last in its
block): the two components (M = p = 0, and the family) in 0.45 s. What
then stalls is the rest of the solver on the family: its dimension is
computed again in the translation's degrevlex order (over 10 minutes,
4.7 GB). A route needs the whole component pipeline (dimension, free
unknowns, block basis of the multipliers) to work in an order chosen by
trying, not only the decomposition. In Brun's problem on M.gamma = c the
block basis of the family (24 s in the solver) did not finish in 30 s in
any of 18 orders of its blocks tried from the prime's own generators.

Usage: python bench/bench_stationary_kirchhoff.py [--budget 120] [-v] [--only NAME]
"""
import argparse
import os
import time

from sage.all import SR, var, vector, matrix, set_verbose

from sage_dynsym.errors import AnalysisError

from sage_dynsym.analysis.stationary import stationary_solutions

M = list(var('M1 M2 M3'))
P = list(var('p1 p2 p3'))
A = list(var('a1 a2 a3'))
C = list(var('c1 c2 c3'))
theta = var('theta')


def lie_poisson(H):
    """The equations of motion on e(3)*: M' = M x H_M + p x H_p, p' = p x H_M."""
    Mv, pv = vector(SR, M), vector(SR, P)
    w = vector(SR, [H.diff(x) for x in M])
    u = vector(SR, [H.diff(x) for x in P])
    return list(Mv.cross_product(w) + pv.cross_product(u)) + list(pv.cross_product(w))


def brun():
    """Brun's Hamiltonian, its integrals (p is gamma) and equations."""
    epsilon = var('epsilon')
    H = sum(A[i] * M[i]**2 + epsilon * P[i]**2 / A[i] for i in range(3)) / 2
    F = (sum(x**2 for x in M) - epsilon * sum(A[i] * P[i]**2 for i in range(3))
         / (A[0] * A[1] * A[2])) / 2
    pv = vector(SR, P)
    return [H, F, pv * pv, vector(SR, M) * pv], lie_poisson(H)


def kirchhoff(B, C):
    Mv, pv = vector(SR, M), vector(SR, P)
    H = (sum(A[i] * M[i]**2 + C[i] * P[i]**2 for i in range(3)) / 2 + Mv * B * pv)
    return [H, pv * pv, Mv * pv], lie_poisson(H)


#: Rational values of a_i, b_ij, c_i for the generic case (no symmetry).
GENERIC = {'a1': 3, 'a2': 5, 'a3': 7, 'b11': 1, 'b12': 2, 'b13': -1, 'b22': 3,
           'b23': 1, 'b33': 2, 'c1': 11, 'c2': 13, 'c3': 17}


def cases():
    """``(name, integrals, equations, levels, values)`` of each case."""
    zero = matrix(SR, 3, 3)
    diagonal = matrix.diagonal(SR, list(var('b1 b2 b3')))
    symmetric = matrix(SR, 3, 3, lambda i, j: SR.var(f"b{min(i, j) + 1}{max(i, j) + 1}"))
    clebsch = [theta * A[1] * A[2], theta * A[0] * A[2], theta * A[0] * A[1]]
    integrals, X = brun()
    return [("Clebsch (B = 0, c_i = theta a_j a_k)", *kirchhoff(zero, clebsch), None, None),
            ("B diagonal", *kirchhoff(diagonal, C), None, None),
            ("B symmetric, values given", *kirchhoff(symmetric, C), None, GENERIC),
            ("Brun, M.gamma = 0", integrals, X, [None, 1, 0], None),
            ("Brun, M.gamma = c", integrals, X, [None, 1, var('c')], None),
            ("B symmetric (generic)", *kirchhoff(symmetric, C), None, None)]


def _cpu():
    # the solving runs in a child process (the budget): its CPU time counts
    t = os.times()
    return t.user + t.system + t.children_user + t.children_system


def run(name, integrals, X, levels, values, budget):
    if values:
        values = {SR.var(k): v for k, v in values.items()}
        integrals = [f.subs(values) for f in integrals]
        X = [e.subs(values) for e in X]
    t0, c0 = time.time(), _cpu()
    try:
        sols = stationary_solutions(integrals, M + P, equations=X, levels=levels, budget=budget)
    except AnalysisError as err:
        return f"{name:40s} {err}"
    seconds, cpu = time.time() - t0, _cpu() - c0
    dims = sorted(s.dimension() for s in sols)
    implicit = sum(1 for s in sols if not s.is_explicit())
    return (f"{name:40s} {seconds:7.1f} s (CPU {cpu:6.1f} s): {len(sols)} solutions, "
            f"dimensions {dims}, {implicit} implicit")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--budget', type=int, default=120, help="seconds per case")
    parser.add_argument('-v', action='store_true', help="the solver's progress")
    parser.add_argument('--only', default=None, help="run the cases whose name contains this")
    args = parser.parse_args()
    if args.v:
        set_verbose(1)
    for case in cases():
        if args.only is None or args.only in case[0]:
            print(run(*case, args.budget), flush=True)


if __name__ == '__main__':
    main()

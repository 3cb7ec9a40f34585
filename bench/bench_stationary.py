"""Benchmark: exact decomposition of stationary sets against Maxima's solve.

For growing problems -- n coupled pendulums, n free rigid rotors, a heavy
rigid body in Euler--Poisson variables (9 unknowns: 6 variables and 3
multipliers) -- the stationary set of K = V0 + sum lambda_j V_j is computed
by ``stationary_solutions`` (Singular: prime components over Q(parameters))
and, in the same run, by Maxima's ``solve`` on the same equations (in a
child process with a time limit). For Maxima the table also counts its
answers that are not solutions (an echoed equation, a value that does not
annul the equations) -- the failure that made the package move away from it.

Target: 9-unknown problems in under 1 s.

Usage: python bench/bench_stationary.py [--quick] [--timeout SECONDS]
"""
import argparse
import time

from sage.all import SR, QQ, var, cos, sin, solve

from sage_dynsym.analysis import stationary_solutions

from isolated import in_subprocess


def pendulums(n, numeric):
    r"""n pendulums coupled by springs between the bobs (the spring acting on
    the horizontal offsets): V = -a sum cos th_i + k/2 sum (sin th_i - sin th_{i+1})^2."""
    th = [SR.var(f'th{i}') for i in range(n)]
    a, k = (2, QQ(3) / 2) if numeric else var('a k')
    V = -a * sum(cos(x) for x in th) + k / 2 * sum((sin(th[i]) - sin(th[i + 1])) ** 2
                                                   for i in range(n - 1))
    return f"{n} coupled pendulums" + (" (numeric)" if numeric else ""), [V], th


def rotors(n):
    r"""n free rigid rotors, each with its energy and squared angular momentum:
    K = sum H_i + sum lambda_i |M_i|^2."""
    integrals, variables, H = [], [], 0
    for i in range(n):
        M = [SR.var(f'M{i}{j}') for j in range(3)]
        A = [SR.var(f'A{i}{j}') for j in range(3)]
        H += sum(m ** 2 / (2 * a) for m, a in zip(M, A))
        integrals.append(sum(m ** 2 for m in M))
        variables += M
    return f"{n} free rotors", [H] + integrals, variables


def heavy_body():
    r"""A heavy rigid body with a fixed point, centre of mass on its third
    axis, in Euler--Poisson variables (M, gamma): K = H + l1 |gamma|^2 +
    l2 M.gamma + l3 |M|^2 -- 6 variables and 3 multipliers."""
    M = var('M1 M2 M3')
    G = var('g1 g2 g3')
    A, B, C, P = var('A B C P')
    H = M[0] ** 2 / (2 * A) + M[1] ** 2 / (2 * B) + M[2] ** 2 / (2 * C) + P * G[2]
    V = [sum(g ** 2 for g in G), sum(m * g for m, g in zip(M, G)), sum(m ** 2 for m in M)]
    return "heavy rigid body (Euler-Poisson)", [H] + V, list(M) + list(G)


def _equations(integrals, variables):
    multipliers = [SR.var(f'lambda{j}') for j in range(1, len(integrals))]
    K = integrals[0] + sum(l * V for l, V in zip(multipliers, integrals[1:]))
    return [K.diff(x) for x in variables], variables + multipliers


def _maxima(integrals, variables, queue):
    equations, unknowns = _equations(integrals, variables)
    start = time.time()
    try:
        found = solve([e == 0 for e in equations], *unknowns, solution_dict=True)
    except Exception as err:      # report whatever Maxima does
        queue.put(("error", time.time() - start, str(err)[:60]))
        return
    elapsed = time.time() - start
    bogus = 0
    names = {str(u) for u in unknowns}
    for sol in found:
        values = {u: sol.get(u, u) for u in unknowns}
        echoed = any(str(v) in names for val in values.values() for v in SR(val).variables()
                     if str(v) not in {str(u) for u in sol})
        try:
            wrong = any(not SR(e).subs(values).simplify_full().is_zero() for e in equations)
        except Exception:
            wrong = True
        bogus += bool(echoed or wrong)
    queue.put(("ok", elapsed, (len(found), bogus)))


def run(problem, timeout):
    name, integrals, variables = problem
    n_unknowns = len(variables) + len(integrals) - 1
    start = time.time()
    sols = stationary_solutions(integrals, variables)
    ours = time.time() - start
    dims = sorted(s.dimension() for s in sols)
    m = in_subprocess(_maxima, (integrals, variables), timeout,
                      default=("error", None, "no answer"))
    if m is None:
        maxima, note = f"> {timeout} s", "timed out"
        ratio = f"> {timeout / ours:.0f}x"
    elif m[0] == "error":
        maxima, note, ratio = "-", f"error: {m[2]}", "-"
    else:
        maxima = f"{m[1]:.2f} s"
        count, bogus = m[2]
        note = f"{count} answers, {bogus} not solutions"
        ratio = f"{m[1] / ours:.1f}x"
    print(f"| {name} | {n_unknowns} | {ours:.2f} s | {len(sols)} (dims {dims}) | "
          f"{maxima} | {note} | {ratio} |", flush=True)
    return ours


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="small problems only")
    parser.add_argument("--timeout", type=float, default=120, help="Maxima time limit (s)")
    args = parser.parse_args()
    problems = [pendulums(1, False), pendulums(2, False), pendulums(2, True), rotors(1),
                heavy_body()]
    if not args.quick:
        problems += [pendulums(3, True), rotors(2)]
    print("| problem | unknowns | sage_dynsym | components | Maxima solve | "
          "Maxima's answers | speed-up |")
    print("|---|---|---|---|---|---|---|")
    worst_nine = 0
    for problem in problems:
        t = run(problem, args.timeout)
        if len(problem[2]) + len(problem[1]) - 1 == 9:
            worst_nine = max(worst_nine, t)
    print(f"\n9-unknown problems: {worst_nine:.2f} s (target: under 1 s) -> "
          f"{'PASS' if worst_nine < 1 else 'FAIL'}")


if __name__ == "__main__":
    main()

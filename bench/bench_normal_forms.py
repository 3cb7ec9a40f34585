"""Birkhoff normal forms of L4 in the restricted three-body problem (two
degrees of freedom), against the closed forms of Deprit & Deprit-Bartholome
(1967) evaluated in the same run.

Measured, for the mass ratio as a parameter:

- the numeric normal form of order 4 and 6 at a sample mu (256 bits);
- the exceptional values over mu (Routh's mu1, the resonances mu2, mu3
  exactly from resultants, the zero mu_c of Arnold's determinant by
  bisection on the order-4 normal form): the answer over the parameter;
- the exact normal form (formal coefficients) of the pendulum to order 6,
  of a pendulum of free stiffness, and of L4 with the mass ratio left
  free to order 4 (two degrees of freedom, in the field
  QQ(mu)[sqrt 3, lambda1, lambda2]/P; target: under a minute), with
  Arnold's determinant exactly and the polynomial of mu_c, compared with
  Deprit's 644 x^2 - 541 x + 36 (x = 27 mu (1 - mu)/4).

Printed: times, the largest error against the closed forms, the sizes.

Usage: python bench/bench_normal_forms.py [--quick]
"""
import argparse
import time


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--quick', action='store_true', help='a small smoke run')
    args = parser.parse_args()
    from sage.all import QQ, var, sqrt, cos, RealField
    from sage_dynsym import (Lagrangian, birkhoff_normal_form, exceptional_values,
                             nonlinear_stability)
    x, y, dx, dy, mu = var('x y dx dy mu')
    r1, r2 = sqrt((x + mu) ** 2 + y ** 2), sqrt((x - 1 + mu) ** 2 + y ** 2)
    L = Lagrangian(((dx - y) ** 2 + (dy + x) ** 2) / 2 + (1 - mu) / r1 + mu / r2, [x, y])
    L4 = {x: QQ(1) / 2 - mu, y: sqrt(3) / 2}
    samples = [QQ(1) / 100] if args.quick else [QQ(1) / 200, QQ(1) / 100, QQ(2) / 100,
                                                 QQ(3) / 100]
    print(f"{'task':44s} {'time/s':>8s}  result")
    worst = 0
    for m in samples:
        t0 = time.time()
        nf = birkhoff_normal_form(L, {**L4, mu: m}, order=4, prec=256)
        t = time.time() - t0
        X = (27 * m * (1 - m) / 4).n(300)
        D = (36 - 541 * X + 644 * X ** 2) / (16 * (1 - 4 * X) * (4 - 25 * X))
        err = abs(nf.arnold_determinant() - D)
        worst = max(worst, err)
        print(f"{'order 4, mu = ' + str(m):44s} {t:8.2f}  D = {RealField(50)(nf.arnold_determinant())}"
              f" (closed form: error {RealField(20)(err)})")
    if not args.quick:
        t0 = time.time()
        nf6 = birkhoff_normal_form(L, {**L4, mu: QQ(1) / 100}, order=6, prec=256)
        print(f"{'order 6, mu = 1/100':44s} {time.time() - t0:8.2f}  "
              f"{len(nf6.coefficients())} coefficients in the actions")
    t0 = time.time()
    found = exceptional_values(L, L4, mu, (0, QQ(1) / 2), samples=10 if args.quick else 40)
    print(f"{'exceptional values over mu (order 4)':44s} {time.time() - t0:8.2f}  "
          + ", ".join(f"{k}: {RealField(50)(v[0]):.12f}" for k, v in found.items()))
    t0 = time.time()
    v = nonlinear_stability(L, {**L4, mu: QQ(1) / 100})
    print(f"{'nonlinear_stability, mu = 1/100':44s} {time.time() - t0:8.2f}  {v.verdict()}")
    q, dq, k = var('q dq k')
    t0 = time.time()
    pendulum = birkhoff_normal_form(Lagrangian(dq ** 2 / 2 + cos(q), [q]), {q: 0}, order=6,
                                    exact=True)
    print(f"{'pendulum, exact, order 6':44s} {time.time() - t0:8.2f}  "
          f"{ {m: QQ(c) for m, c in pendulum.coefficients(exact=True).items()} }")
    t0 = time.time()
    free = birkhoff_normal_form(Lagrangian(dq ** 2 / 2 + k * cos(q), [q]), {q: 0}, order=4,
                                sample={k: 1})
    print(f"{'pendulum of stiffness k (free), order 4':44s} {time.time() - t0:8.2f}  "
          f"{free.coefficients()}")
    from sage.all import PolynomialRing
    from sage_dynsym.analysis.parametric_normal_forms import arnold_polynomial
    t0 = time.time()
    symbolic = birkhoff_normal_form(L, L4, order=4, sample={mu: QQ(1) / 100})
    t_nf = time.time() - t0
    D, N = arnold_polynomial(symbolic)
    t_all = time.time() - t0
    m = PolynomialRing(QQ, 'mu').gen()
    X = 27 * m * (1 - m) / 4
    deprit = (644 * X ** 2 - 541 * X + 36).monic()
    print(f"{'L4, mu free, exact, order 4':44s} {t_nf:8.2f}  {len(symbolic.coefficients())} "
          f"coefficients; with D and its norm {t_all:.2f} s (target < 60 s)")
    print(f"{'  norm of D = (Deprit polynomial)^k':44s} {'':8s}  "
          f"{N.radical() == deprit.change_ring(N.parent().base_ring())}: {N.factor()}")
    print(f"largest error of Arnold's determinant against Deprit's closed form: "
          f"{RealField(20)(worst)}")


if __name__ == '__main__':
    main()

"""
The report's size budget: every section estimates, before its expensive
step, how many polynomial terms it would create; over the budget it is one
line and the rest of the report still prints. The estimates are upper
bounds, checked here against term counts of the expanded results (computed
independently, by expanding) and against brute-force permanents.
"""
import itertools
import random
import subprocess
import sys
from pathlib import Path

import pytest

from sage.all import SR, matrix, prod, var
from sage.symbolic.operators import add_vararg
from sage_dynsym import load
from sage_dynsym.circuits import Circuit
from sage_dynsym.description import example_path
from sage_dynsym.report import (report, determinant_terms, polynomial_terms,
                                characteristic_estimate, equations_estimate, lagrangian_estimate,
                                DEFAULT_BUDGET)

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
from hostile.corpus import ladder  # noqa: E402


def expanded_terms(expr):
    e = SR(expr).expand()
    if e.is_zero():
        return 0
    return len(e.operands()) if e.operator() is add_vararg else 1


@pytest.fixture(scope="module")
def big_ladder(tmp_path_factory):
    path = tmp_path_factory.mktemp("ladder") / "ladder40.yaml"
    path.write_text(ladder("ladder of 40 sections", 40, inductive_load=True))
    return str(path)


def test_budget_skips_the_stability_of_a_large_ladder_and_the_rest_prints(big_ladder):
    text = report(load(big_ladder))
    lines = text.splitlines()
    skipped = [line for line in lines if "skipped" in line]
    assert len(skipped) == 1
    assert skipped[0].startswith("Stability of the free circuit: skipped, the characteristic "
                                 "polynomial")
    assert f"over the budget of {DEFAULT_BUDGET}" in skipped[0]
    for section in ("Mixed potential P(i, u):", "State equations (", "Time derivative of P",
                    "Lagrangian (loop-current method):", "Lagrange equations (E_i = 0):"):
        assert any(line.startswith(section) for line in lines), section
    # 40 state equations and 41 Lagrange equations are printed
    assert sum(line.startswith("  [L") or line.startswith("  [C") for line in lines) == 81
    assert sum(line.startswith("  [q") for line in lines) == 41


@pytest.mark.slow
def test_cli_on_a_large_ladder(big_ladder):
    run = subprocess.run([sys.executable, "-m", "sage_dynsym", big_ladder], capture_output=True,
                         text=True, timeout=300)
    assert run.returncode == 0 and run.stderr == ""
    assert "Stability of the free circuit: skipped" in run.stdout
    assert "Lagrange equations (E_i = 0):" in run.stdout
    chosen = subprocess.run([sys.executable, "-m", "sage_dynsym", big_ladder, "--sections",
                             "lagrangian,stability", "--budget", "1000"],
                            capture_output=True, text=True, timeout=300)
    assert chosen.returncode == 0
    assert "State equations" not in chosen.stdout
    assert "Lagrangian (loop-current method):" in chosen.stdout
    assert "Stability of the free circuit: skipped" in chosen.stdout
    assert "over the budget of 1000 " in chosen.stdout
    quiet = subprocess.run([sys.executable, "-m", "sage_dynsym", big_ladder, "--no-analysis"],
                           capture_output=True, text=True, timeout=300)
    assert "Stability" not in quiet.stdout and "dP/dt" not in quiet.stdout
    bad = subprocess.run([sys.executable, "-m", "sage_dynsym", big_ladder, "--sections", "x"],
                         capture_output=True, text=True, timeout=300)
    assert bad.returncode == 2 and "unknown section 'x'" in bad.stderr
    assert "Traceback" not in bad.stderr


def test_a_raised_budget_computes_the_section():
    C = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1'], [3, 4, 'R2'],
                 [4, 0, 'L2']], name='RLC')
    small = report(C, sections=['stability'], budget=5)
    assert "skipped" in small and "characteristic polynomial:" not in small
    large = report(C, sections=['stability'], budget=100)
    assert "skipped" not in large and "characteristic polynomial:" in large


def test_a_failing_section_is_one_line_and_the_rest_prints(monkeypatch):
    import sage_dynsym.circuits.report as R

    def broken(*args):
        raise RuntimeError("Singular error: no more memory")

    monkeypatch.setattr(R, "equations_lines", broken)
    text = report(load(example_path("rlc_ladder.yaml")))
    assert "Lagrange equations: section failed: RuntimeError: Singular error: no more memory" \
        in text
    assert "Lagrangian (loop-current method):" in text and "Stability" in text


def test_keyboard_interrupt_is_not_swallowed(monkeypatch):
    import sage_dynsym.circuits.report as R

    def interrupted(*args):
        raise KeyboardInterrupt

    monkeypatch.setattr(R, "equations_lines", interrupted)
    with pytest.raises(KeyboardInterrupt):
        report(load(example_path("rlc_ladder.yaml")))


# -- the estimates are upper bounds ------------------------------------------

def brute_force_permanent(counts):
    n = len(counts)
    return sum(prod(counts[i][p[i]] for i in range(n)) for p in itertools.permutations(range(n)))


def test_determinant_terms_is_the_permanent_on_random_sparse_matrices():
    rng = random.Random(10)
    for _ in range(60):
        n = rng.randint(1, 7)
        counts = [[rng.choice([0, 0, 1, 2, 3]) for _ in range(n)] for _ in range(n)]
        assert determinant_terms(counts) == brute_force_permanent(counts)


def test_determinant_terms_bounds_expanded_determinants():
    rng = random.Random(11)
    symbols = var('a b c d e f g h')
    for _ in range(20):
        n = rng.randint(2, 4)
        M = matrix(SR, n, n, lambda i, j: sum(rng.choice([0, 1, -2]) * rng.choice(symbols)
                                                 for _ in range(rng.randint(0, 3))))
        counts = [[polynomial_terms(e) for e in row] for row in M.rows()]
        assert determinant_terms(counts) >= expanded_terms(M.det())


def test_polynomial_terms_bounds_expansions():
    x, y, z, w = var('x y z w')
    rng = random.Random(12)
    atoms = [x, y, z, w, SR(2), SR(-3)]
    for _ in range(100):
        e = SR(0)
        for _ in range(rng.randint(1, 4)):
            factor = sum(rng.choice(atoms) for _ in range(rng.randint(1, 3)))
            e += factor ** rng.randint(1, 3) * rng.choice(atoms)
        assert polynomial_terms(e) >= expanded_terms(e)


@pytest.mark.parametrize("sections", [2, 3, 4])
def test_circuit_estimates_bound_the_results(sections):
    C = Circuit([[0, 1, 'E1']] + [b for k in range(1, sections + 1) for b in (
        [2 * k - 1, 2 * k, f'R{k}'], [2 * k, 2 * k + 1, f'L{k}'], [2 * k + 1, 0, f'C{k}'])]
        + [[2 * sections + 1, 2 * sections + 2, f'R{sections + 1}'],
           [2 * sections + 2, 0, f'L{sections + 1}']])
    L = C.lagrangian()
    assert equations_estimate(L) >= sum(expanded_terms(e) for e in L.lagrange_equations())
    from sage_dynsym.analysis import linearize
    free = L.subs({SR.var('E1'): 0})
    poly = linearize(free, {q: 0 for q in free.coordinates()}).characteristic_polynomial(
        SR.var('lambda_'))
    assert characteristic_estimate(free) >= expanded_terms(poly)


def test_mechanical_estimates_bound_the_results():
    S = load(example_path("spherical_pendulum.yaml"))
    L = S.lagrangian()
    A = L.mass_matrix()
    assert lagrangian_estimate(S) >= sum(expanded_terms(e) for e in A.list())
    assert equations_estimate(L) >= sum(expanded_terms(e) for e in L.lagrange_equations())

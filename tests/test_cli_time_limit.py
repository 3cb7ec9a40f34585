"""
``--time-limit``: a file over the limit is given up (one error line, the
sections it had printed kept), the next file is reported, and the process
is sound afterwards: the report is computed in a forked process that is
killed, never interrupted by an alarm in this one (an interrupted Singular
call left Singular broken: a segfault later).
"""
import os
import time

import pytest

from conftest import run_cli as run

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PENDULUM = os.path.join(ROOT, "examples", "spherical_pendulum.yaml")
LIMIT = 15      # seconds; the pendulum's report takes about 2


@pytest.mark.slow
def test_a_file_over_the_time_limit_is_given_up_and_the_next_reported(monkeypatch, tmp_path):
    import sage_dynsym.mechanics.report as R
    original, flag = R.hamiltonian_lines, tmp_path / "hung"

    def hamiltonian_lines(*args):
        # the first report hangs in its Hamiltonian section (forever, for
        # the limit to stop), the second one goes through
        if not flag.exists():
            flag.write_text("once")
            time.sleep(3600)
        return original(*args)

    monkeypatch.setattr(R, "hamiltonian_lines", hamiltonian_lines)
    out = tmp_path / "out.txt"
    result = run("--time-limit", str(LIMIT), PENDULUM, PENDULUM, "-o", str(out))
    assert result.returncode == 1
    assert result.stderr == (f"sage-dynsym: error: {PENDULUM}: gave up after {LIMIT} s "
                             "(--time-limit)\n")
    first, second = result.stdout.split("\n\n== ")
    assert "Lagrange equations (E_i = 0):" in first and "Hamiltonian:" not in first
    assert "Lagrange equations (E_i = 0):" in second and "Hamiltonian:" in second
    assert out.read_text().count("Lagrange equations (E_i = 0):") == 2
    # Singular in this process afterwards: x = y on the circle gives 2 y^2 = 1
    from sage.all import QQ, PolynomialRing
    S = PolynomialRing(QQ, 'a,b', order='lex')
    a, b = S.gens()
    assert S.ideal([a**2 + b**2 - 1, a - b]).groebner_basis() == [a - b, b**2 - QQ((1, 2))]

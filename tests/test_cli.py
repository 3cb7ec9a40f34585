"""The command line produces a report for every bundled description file,
with the equations and the analysis sections, and a clean error otherwise."""
import glob
import os
import pytest
from conftest import run_cli as run, slow_except

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXAMPLES = sorted(glob.glob(os.path.join(ROOT, "examples", "*.yaml")))


# one example in `make test`; every example in `make test-slow` (CI)
FAST_EXAMPLES = [p for p in EXAMPLES if os.path.basename(p) == 'spherical_pendulum.yaml']


@pytest.mark.parametrize("path", slow_except(EXAMPLES, FAST_EXAMPLES, ids=os.path.basename))
def test_report_for_every_example(path):
    result = run(path, "--latex")
    assert result.returncode == 0, result.stderr
    assert "Traceback" not in result.stderr
    text = result.stdout
    assert text.startswith("== ")
    assert "LaTeX: " in text
    # every report carries equations and an analysis section
    assert "equations" in text
    assert any(section in text for section in (
        "Stationary motions", "Equilibria", "Stability of the free circuit", "dP/dt"))


def test_report_file_and_bad_file(tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text("kind: mechanical\ncoordinates: [x]\nbodies: 3\n")
    out = tmp_path / "report.txt"
    result = run(EXAMPLES[0], str(bad), "-o", str(out))
    assert result.returncode == 1
    assert "Traceback" not in result.stderr
    assert "bad.yaml: bodies: expected a list of bodies" in result.stderr
    assert out.read_text().startswith("== ")

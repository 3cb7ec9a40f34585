"""The README's Python block runs unchanged, as a plain script with the
project's Python and in the SageMath Jupyter kernel, and shows what its
comments promise (Example 1 of doc/method.rst: the spherical pendulum)."""
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from deprecated_aliases import is_deprecated_alias

ROOT = Path(__file__).resolve().parent.parent


def readme_block():
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    blocks = re.findall(r"```python\n(.*?)```", text, re.S)
    assert blocks, "the README has no Python block"
    return blocks[0]


def checkout_copy(tmp_path):
    # the block reads examples/ and writes its pictures in output/
    shutil.copytree(ROOT / "examples", tmp_path / "examples")
    return tmp_path


def check_output(out, folder):
    # Example 1: 2L = m l^2 (sin^2 theta dpsi^2 + dtheta^2) - 2 m g l cos theta
    assert "1/2*dpsi^2*l^2*m*sin(theta)^2 + 1/2*dtheta^2*l^2*m - g*l*m*cos(theta)" in out
    # Example 1: 2R = m l^2 dtheta^2 - p^2/(m l^2 sin^2 theta) - 2 m g l cos theta
    assert "1/2*dtheta^2*l^2*m - g*l*m*cos(theta) - 1/2*p_psi^2/(l^2*m*sin(theta)^2)" in out
    # the two conical motions below the pivot, both stable
    conical = [line for line in out.splitlines() if "sqrt(-g*l/cos(theta))" in line]
    assert len(conical) == 2 and all(line.endswith("stable") for line in conical), out
    assert all("cos(theta) < 0" in line for line in conical)
    drift = [float(x) for x in re.findall(r"^([0-9.e-]+)$", out, re.M)]
    assert drift and drift[0] < 1e-8
    assert "void mass_matrix_and_forcing" in out
    for picture in ("pendulum_theta.png", "pendulum_phase.png"):
        assert (folder / "output" / picture).stat().st_size > 1000


def test_readme_block_as_a_script(tmp_path):
    folder = checkout_copy(tmp_path)
    (folder / "readme.py").write_text(readme_block())
    run = subprocess.run([sys.executable, "readme.py"], cwd=folder, capture_output=True,
                         text=True, timeout=600)
    assert run.returncode == 0, run.stderr[-3000:]
    check_output(run.stdout, folder)


@pytest.mark.slow       # a Jupyter kernel of its own; `make test-slow` (CI)
def test_readme_block_in_the_sage_kernel(tmp_path):
    nbformat = pytest.importorskip("nbformat")
    pytest.importorskip("nbclient")
    from notebook_runner import run_notebook
    folder = checkout_copy(tmp_path)
    notebook = nbformat.v4.new_notebook()
    notebook.cells.append(nbformat.v4.new_code_cell(readme_block()))
    done = run_notebook(notebook, folder)
    out = "".join(o.get("text", "") for o in done.cells[0].outputs if o.get("name") == "stdout")
    check_output(out, folder)


def test_readme_lists_every_worksheet():
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    listed = set(re.findall(r"^\| `(\d\d_\w+)` \|", text, re.M))
    shipped = {p.stem for p in (ROOT / "worksheets").glob("*.ipynb")}
    assert listed == shipped


def test_readme_layout_names_every_part_of_the_package():
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    layout = text[text.index("## Layout"):text.index("Earlier module names")]
    named = set(re.findall(r"`(\w+)(?:/|\.py)`", layout))
    package = ROOT / "sage_dynsym"
    # the deprecated aliases of earlier module names are no part of the layout
    parts = {p.stem for p in package.glob("*.py")
             if p.stem != "__init__" and not is_deprecated_alias(p)}
    parts |= {p.name for p in package.iterdir() if (p / "__init__.py").exists()}
    assert named == parts

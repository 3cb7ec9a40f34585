"""
Every worksheet in worksheets/ runs without error in the SageMath Jupyter
kernel (nbclient; a cell that raises fails the test with its traceback).
The worksheets check their own results with ``assert`` against the
reference formulas of the method (Examples 1-4) and textbook results.
"""
from pathlib import Path

import pytest

WORKSHEETS = sorted((Path(__file__).resolve().parent.parent / "worksheets").glob("*.ipynb"))


def test_there_are_worksheets():
    assert len(WORKSHEETS) >= 8


@pytest.mark.parametrize("path", WORKSHEETS, ids=lambda p: p.stem)
def test_worksheet_is_a_valid_notebook(path):
    # nbformat's own schema: Jupyter and nbconvert refuse (or warn on) any
    # other shape, e.g. "outputs" on a markdown cell
    import nbformat
    with open(path, encoding="utf-8") as handle:
        nbformat.validate(nbformat.read(handle, as_version=nbformat.NO_CONVERT))


# a Jupyter kernel each (10 s): all of them in `make test-slow` (CI) and `make worksheets`
@pytest.mark.slow
@pytest.mark.parametrize("path", WORKSHEETS, ids=lambda p: p.stem)
def test_worksheet_runs(path, tmp_path):
    nbformat = pytest.importorskip("nbformat")
    pytest.importorskip("nbclient")
    from notebook_runner import run_notebook
    run_notebook(nbformat.read(path, as_version=4), tmp_path)

"""
Every worksheet in worksheets/ runs without error in the SageMath Jupyter
kernel (nbclient; a cell that raises fails the test with its traceback).
The worksheets check their own results with ``assert`` against the
reference formulas of the method (Examples 1-4) and textbook results.
"""
from pathlib import Path

import pytest

nbformat = pytest.importorskip("nbformat")
nbclient = pytest.importorskip("nbclient")
from jupyter_client.kernelspec import KernelSpecManager, NoSuchKernel  # noqa: E402

WORKSHEETS = sorted((Path(__file__).resolve().parent.parent / "worksheets").glob("*.ipynb"))
KERNEL = "sagemath"


def test_there_are_worksheets():
    assert len(WORKSHEETS) >= 8


@pytest.mark.parametrize("path", WORKSHEETS, ids=[p.stem for p in WORKSHEETS])
def test_worksheet_runs(path, tmp_path):
    try:
        KernelSpecManager().get_kernel_spec(KERNEL)
    except NoSuchKernel:
        pytest.fail("the SageMath kernel spec is not installed (make kernel)")
    nb = nbformat.read(path, as_version=4)
    client = nbclient.NotebookClient(nb, kernel_name=KERNEL, timeout=600,
                                     resources={"metadata": {"path": str(tmp_path)}})
    client.execute()
    errors = [out for cell in nb.cells if cell.cell_type == "code"
              for out in cell.get("outputs", []) if out.get("output_type") == "error"]
    assert not errors

"""
Every worksheet in worksheets/ runs without error in the SageMath Jupyter
kernel (nbclient; a cell that raises fails the test with its traceback).
The worksheets check their own results with ``assert`` against the
reference formulas of the method (Examples 1-4) and textbook results.
"""
from pathlib import Path
from queue import Empty
from time import monotonic

import pytest

nbformat = pytest.importorskip("nbformat")
nbclient = pytest.importorskip("nbclient")
from jupyter_client.kernelspec import KernelSpecManager, NoSuchKernel  # noqa: E402
from conftest import slow_except  # noqa: E402

WORKSHEETS = sorted((Path(__file__).resolve().parent.parent / "worksheets").glob("*.ipynb"))
KERNEL = "sagemath"


def test_there_are_worksheets():
    assert len(WORKSHEETS) >= 8


def _patient(get_msg, step=1.0):
    """
    ``get_msg`` that waits in short polls. A ZMQ socket signals readiness
    through an edge-triggered file descriptor, and the asyncio poller can
    miss a wake-up: then a single ``poll(600 s)`` sleeps through a reply
    that is already queued (seen as a worksheet whose kernel sat idle while
    nbclient waited). Every new poll first checks the socket's events, so
    short polls pick such a message up within ``step`` seconds.
    """
    async def get(timeout=None):
        deadline = None if timeout is None else monotonic() + timeout
        while True:
            wait = step if deadline is None else max(0.0, min(step, deadline - monotonic()))
            try:
                return await get_msg(timeout=wait)
            except Empty:
                if deadline is not None and monotonic() >= deadline:
                    raise
    return get


class PatientNotebookClient(nbclient.NotebookClient):
    """A ``NotebookClient`` whose shell and IOPub channels use :func:`_patient`."""

    async def async_start_new_kernel_client(self):
        result = await super().async_start_new_kernel_client()
        for channel in (self.kc.shell_channel, self.kc.iopub_channel):
            channel.get_msg = _patient(channel.get_msg)
        return result


def run_notebook(nb, folder):
    """Execute the notebook ``nb`` in the SageMath kernel, in ``folder``;
    a cell that raises fails the calling test. Returns the notebook with
    its outputs."""
    try:
        KernelSpecManager().get_kernel_spec(KERNEL)
    except NoSuchKernel:
        pytest.fail("the SageMath kernel spec is not installed (make kernel)")
    client = PatientNotebookClient(nb, kernel_name=KERNEL, timeout=600,
                                   resources={"metadata": {"path": str(folder)}})
    client.execute()
    errors = [out for cell in nb.cells if cell.cell_type == "code"
              for out in cell.get("outputs", []) if out.get("output_type") == "error"]
    assert not errors
    return nb


# one worksheet in `make test`; all of them in `make test-slow` (CI) and `make worksheets`
@pytest.mark.parametrize("path", slow_except(WORKSHEETS, WORKSHEETS[:1], ids=lambda p: p.stem))
def test_worksheet_runs(path, tmp_path):
    run_notebook(nbformat.read(path, as_version=4), tmp_path)

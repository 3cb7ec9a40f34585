"""
Running a notebook in the SageMath Jupyter kernel (nbclient), for the
worksheet and README tests. A module of its own so that collecting the tests
does not import the Jupyter client (3 s for each pytest process).
"""
from queue import Empty
from time import monotonic

import nbclient
from jupyter_client.kernelspec import KernelSpecManager, NoSuchKernel
import pytest

KERNEL = "sagemath"


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

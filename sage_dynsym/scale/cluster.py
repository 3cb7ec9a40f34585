r"""
Running chunks of work on Dask, or in this process

:func:`run_chunks` applies a kernel function to the chunks ``[start,
stop)`` of a computation and hands each result to a collector, in chunk
order or as they complete. Where it runs is given by ``client``:

- ``None`` -- a :class:`dask.distributed.LocalCluster` of worker processes
  (one thread each, on 127.0.0.1, without dashboard), one per core unless
  ``workers=`` says otherwise, started for this computation and closed
  after it;
- a :class:`dask.distributed.Client` -- used as given (e.g. connected to a
  scheduler of a cluster), left open;
- a string -- the address of a scheduler (``'tcp://host:8786'``), connected
  to for this computation;
- ``False`` -- no Dask at all: the chunks run one after the other in this
  process (plain NumPy).

The chunks are the same whatever runs them, so the results are identical
with any number of workers. A chunk lost with its worker is computed again
by Dask on another one. ``progress=True`` shows Dask's progress bar (a
widget in a notebook). An interrupt (Ctrl-C) cancels the pending chunks.

The kernel functions travel *by value* (cloudpickle), so the workers only
need NumPy, SciPy and Dask -- not Sage nor this package.

EXAMPLES::

    sage: from sage_dynsym.scale.cluster import run_chunks, chunks
    sage: out = {}
    sage: run_chunks(lambda task, a, b: task * (b - a), 10, chunks(7, 3),
    ....:            lambda i, r: out.__setitem__(i, r), client=False)
    sage: out
    {0: 30, 1: 30, 2: 10}
"""
import contextlib
import os
import uuid

from ..errors import AnalysisError
from ..io.arguments import count, finite_real, is_integer

DEFAULT_TIMEOUT = 10        # seconds to reach a scheduler or to get a worker
#: Most worker processes of a local cluster (``workers=``): each is a
#: Python process; far more than the cores only costs memory.
MAX_WORKERS = 256


def chunks(total, size):
    r"""
    The chunks ``(start, stop)`` of ``range(total)`` of ``size`` points
    (the last one shorter).

    EXAMPLES::

        sage: from sage_dynsym.scale.cluster import chunks
        sage: chunks(7, 3), chunks(0, 3)
        ([(0, 3), (3, 6), (6, 7)], [])
        sage: chunks(7, 0)
        Traceback (most recent call last):
        ...
        AnalysisError: scale: chunk_size must be a positive integer, got 0
        sage: chunks(7, 2.5)
        Traceback (most recent call last):
        ...
        AnalysisError: scale: chunk_size must be a positive integer, got 2.50000000000000
    """
    if not (is_integer(size) and size >= 1):
        raise AnalysisError(f"chunk_size must be a positive integer, got {size!r}", entry="scale")
    size = int(size)
    return [(a, min(total, a + size)) for a in range(0, total, size)]


def machine_cores():
    r"""The number of cores this process may use.

    EXAMPLES::

        sage: from sage_dynsym.scale.cluster import machine_cores
        sage: machine_cores() >= 1
        True
    """
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:      # not on Linux
        return os.cpu_count() or 1


class _Shipped:
    r"""
    A kernel function that pickles *by value*: unpickling it on a worker
    gives the function itself without importing this package (which would
    load Sage). Called locally it is the function.
    """

    def __init__(self, function):
        import cloudpickle
        from . import kernel
        cloudpickle.register_pickle_by_value(kernel)
        try:
            self._payload = cloudpickle.dumps(function)
        finally:
            cloudpickle.unregister_pickle_by_value(kernel)
        self._function = function
        self.__name__ = getattr(function, '__name__', 'chunk')

    def __call__(self, *args):
        return self._function(*args)

    def __reduce__(self):
        import cloudpickle
        return cloudpickle.loads, (self._payload,)


def _dask():
    try:
        import distributed
    except ImportError:
        raise AnalysisError("Dask is not installed: install it with "
                            "pip install 'dask[distributed]', or pass client=False "
                            "to compute in this process", entry="scale") from None
    return distributed


@contextlib.contextmanager
def connected(client=None, workers=None, timeout=DEFAULT_TIMEOUT):
    r"""
    A Dask client for ``client`` (see the module documentation), closed on
    exit if it was opened here.

    TESTS:

    A scheduler that does not answer is an error after ``timeout`` seconds::

        sage: from sage_dynsym.scale.cluster import connected
        sage: with connected('tcp://127.0.0.1:9', timeout=1): pass
        Traceback (most recent call last):
        ...
        AnalysisError: scale: no Dask scheduler answers at tcp://127.0.0.1:9 within 1 s ...
        sage: with connected(42): pass
        Traceback (most recent call last):
        ...
        AnalysisError: scale: client must be None (a local cluster), False (no Dask), a Dask Client or a scheduler address, got 42
        sage: with connected(workers=10^5): pass
        Traceback (most recent call last):
        ...
        AnalysisError: workers: 100000 is more than the limit of 256
    """
    finite_real(timeout, 'timeout', error=AnalysisError, minimum=0, strict=True)
    if client is None:
        n = machine_cores() if workers is None else count(workers, 'workers',
                                                          maximum=MAX_WORKERS,
                                                          error=AnalysisError)
    distributed = _dask()
    if isinstance(client, distributed.Client):
        if client.status not in ('running', 'connecting', 'newly-created'):
            raise AnalysisError(f"the Dask client is {client.status}", entry="scale")
        _wait_for_workers(client, timeout, "the scheduler of the given client")
        yield client
        return
    if isinstance(client, str):
        try:
            c = distributed.Client(client, timeout=timeout, set_as_default=False)
        except (OSError, TimeoutError, ValueError) as err:
            raise AnalysisError(f"no Dask scheduler answers at {client} within {timeout} s "
                                f"({type(err).__name__}: {err})", entry="scale") from None
        with c:
            _wait_for_workers(c, timeout, f"the scheduler at {client}")
            yield c
        return
    if client is not None:
        raise AnalysisError("client must be None (a local cluster), False (no Dask), a Dask "
                            f"Client or a scheduler address, got {client!r}", entry="scale")
    # no dashboard; the scheduler's HTTP endpoints on a free port of 127.0.0.1
    http = dict(dashboard=False, dashboard_address='127.0.0.1:0')
    with distributed.LocalCluster(n_workers=n, threads_per_worker=1, processes=True,
                                  host='127.0.0.1', dashboard_address=None,
                                  scheduler_kwargs=http) as cluster, \
            distributed.Client(cluster, set_as_default=False) as c:
        yield c


def _wait_for_workers(client, timeout, what):
    try:
        client.wait_for_workers(1, timeout=timeout)
    except (TimeoutError, OSError) as err:
        raise AnalysisError(f"{what} has no worker after {timeout} s ({err})",
                            entry="scale") from None


def run_chunks(function, task, ranges, collect, client=None, workers=None,
               timeout=DEFAULT_TIMEOUT, progress=False, label='chunk'):
    r"""
    Compute ``function(task, start, stop)`` for each ``(start, stop)`` of
    ``ranges`` and call ``collect(i, result)`` for the ``i``-th one.

    INPUT:

    - ``function`` -- a kernel function (of :mod:`sage_dynsym.scale.kernel`,
      shipped by value) or any picklable function
    - ``task`` -- the data shared by all chunks (sent once)
    - ``ranges`` -- list of ``(start, stop)``
    - ``collect`` -- called in this process with each result, in order of
      completion (chunk order without Dask)
    - ``client``, ``workers``, ``timeout`` -- where to run (see the module
      documentation)
    - ``progress`` -- show Dask's progress bar
    - ``label`` -- the prefix of the Dask task names

    Errors of a chunk are raised here; a chunk whose workers keep dying is
    an :class:`~sage_dynsym.errors.AnalysisError`.

    EXAMPLES: see the module documentation, and
    :func:`~sage_dynsym.scale.maps.stability_map`.
    """
    if client is False:
        for i, (a, b) in enumerate(ranges):
            collect(i, function(task, a, b))
        return
    distributed = _dask()
    from . import kernel
    shipped = _Shipped(function) if getattr(function, '__module__', None) == kernel.__name__ \
        else function
    token = uuid.uuid4().hex[:10]
    with connected(client, workers, timeout) as c:
        data = c.submit(_Shipped(kernel.identity), task, key=f"{label}-data-{token}", pure=False)
        futures = [c.submit(shipped, data, a, b, key=f"{label}-{token}-{i}", pure=False)
                   for i, (a, b) in enumerate(ranges)]
        index = {f.key: i for i, f in enumerate(futures)}
        try:
            if progress:
                _show_progress(c, futures)
            for future in distributed.as_completed(futures, loop=c.loop):
                try:
                    result = future.result()
                except distributed.KilledWorker as err:
                    raise AnalysisError(f"the workers computing {future.key} kept dying "
                                        f"({err})", entry="scale") from None
                collect(index[future.key], result)
                future.release()
        except BaseException:
            c.cancel(futures + [data], force=True)
            raise
        finally:
            del futures, data


def _show_progress(client, futures):
    from distributed.diagnostics.progressbar import progress
    from distributed.utils import is_kernel
    scheduler = client.scheduler.address    # the client need not be the default one
    if is_kernel():             # a widget; the computation goes on meanwhile
        bar = progress(futures, notebook=True, multi=False, scheduler=scheduler)
        from IPython.display import display
        display(bar)
    else:                       # a text bar on the terminal, until all are done
        progress(futures, notebook=False, multi=False, scheduler=scheduler)

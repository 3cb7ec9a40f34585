r"""
Running chunks of work on Dask, or in this process

:func:`run_chunks` applies a kernel function to the chunks ``[start,
stop)`` of a computation and hands each result to a collector, in chunk
order or as they complete. Where it runs is given by ``client``:

- ``None`` (the default) -- chosen by the cost: the first chunk runs in
  this process and is timed; when the estimated time of the others, at
  that pace, exceeds :data:`CLUSTER_THRESHOLD` seconds and the machine has
  more than one core, a local Dask cluster is started for them (as for
  ``'local'``), otherwise they run here too. Starting a cluster costs a
  few seconds, and on a small machine it can at best divide the time by
  the number of cores, so small computations never pay for it. A note is
  logged (``logging``, logger ``sage_dynsym.scale``) when a cluster is
  started;
- ``'local'`` -- a local Dask cluster, started for this computation and
  closed after it: a scheduler in this process and worker processes (one
  thread each, on 127.0.0.1, without dashboard), one per core unless
  ``workers=`` says otherwise (giving ``workers=`` with ``client=None``
  also asks for one). The workers are started as fresh Python processes
  (``python -m dask``), not by :mod:`multiprocessing`: they never
  import the user's script, so a plain script without an
  ``if __name__ == '__main__':`` guard works;
- a :class:`dask.distributed.Client` -- used as given (e.g. connected to a
  scheduler of a cluster), left open;
- a string other than ``'local'`` -- the address of a scheduler
  (``'tcp://host:8786'``), connected to for this computation;
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
    'this process'
    sage: out
    {0: 30, 1: 30, 2: 10}
"""
import contextlib
import logging
import os
import time
import uuid

from ..errors import AnalysisError, DynSymError
from ..arguments import count, finite_real, is_integer

__all__ = ['DEFAULT_TIMEOUT', 'MAX_WORKERS', 'CLUSTER_THRESHOLD', 'LOCAL_START_TIMEOUT', 'chunks',
           'machine_cores', 'connected', 'SHUTDOWN_LOGGERS', 'closed_quietly', 'local_cluster',
           'run_chunks', 'run_in_processes', 'CHILD_CODE', 'serve_child']

DEFAULT_TIMEOUT = 10        # seconds to reach a scheduler or to get a worker
#: Most worker processes of a local cluster (``workers=``): each is a
#: Python process; far more than the cores only costs memory.
MAX_WORKERS = 256

#: Seconds of estimated work (at the pace of the first chunk, in this
#: process) above which ``client=None`` starts a local cluster for the rest.
CLUSTER_THRESHOLD = 30

#: Seconds to wait for the workers of a local cluster to start.
LOCAL_START_TIMEOUT = 120

_log = logging.getLogger('sage_dynsym.scale')


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
    except ImportError as err:
        raise AnalysisError("Dask is not installed: install it with "
                            "pip install 'dask[distributed]', or pass client=False "
                            "to compute in this process", entry="scale") from err
    return distributed


@contextlib.contextmanager
def connected(client='local', workers=None, timeout=DEFAULT_TIMEOUT):
    r"""
    A Dask client for ``client`` (``'local'``, a ``Client`` or a scheduler
    address; see the module documentation), closed on exit if it was
    opened here.

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
        AnalysisError: scale: client must be None (chosen by the cost), 'local' (a local cluster), False (no Dask), a Dask Client or a scheduler address, got 42
        sage: with connected(workers=10^5): pass
        Traceback (most recent call last):
        ...
        AnalysisError: workers: 100000 is more than the limit of 256
    """
    finite_real(timeout, 'timeout', error=AnalysisError, minimum=0, strict=True)
    if workers is not None:
        count(workers, 'workers', maximum=MAX_WORKERS, error=AnalysisError)
    distributed = _dask()
    if isinstance(client, distributed.Client):
        if client.status not in ('running', 'connecting', 'newly-created'):
            raise AnalysisError(f"the Dask client is {client.status}", entry="scale")
        _wait_for_workers(client, timeout, "the scheduler of the given client")
        yield client
        return
    if isinstance(client, str) and client != 'local':
        try:
            c = distributed.Client(client, timeout=timeout, set_as_default=False)
        except (OSError, TimeoutError, ValueError) as err:
            raise AnalysisError(f"no Dask scheduler answers at {client} within {timeout} s "
                                f"({type(err).__name__}: {err})", entry="scale") from err
        with closed_quietly(c):
            _wait_for_workers(c, timeout, f"the scheduler at {client}")
            yield c
        return
    if client != 'local':
        raise AnalysisError("client must be None (chosen by the cost), 'local' (a local "
                            "cluster), False (no Dask), a Dask Client or a scheduler "
                            f"address, got {client!r}", entry="scale")
    n = machine_cores() if workers is None else int(workers)
    # the client is closed before its cluster, both quietly
    with closed_quietly(local_cluster(n)) as cluster, \
            closed_quietly(distributed.Client(cluster, set_as_default=False)) as c:
        _wait_for_workers(c, LOCAL_START_TIMEOUT, "the local cluster", n)
        yield c


#: The loggers silenced while a client or a cluster closes.
SHUTDOWN_LOGGERS = ('distributed', 'tornado')


@contextlib.contextmanager
def closed_quietly(resource):
    r"""
    ``resource`` (a Dask client or cluster), closed on exit with the
    loggers of :data:`SHUTDOWN_LOGGERS` silenced (below ``CRITICAL``)
    during the close only.

    Closing a cluster cuts the connections of its scheduler to the
    workers; a message the scheduler was still sending then fails, and
    ``distributed.batched`` logs the ``CommClosedError`` with its traceback
    -- after the cluster's own ``silence_logs`` has been lifted, in about
    one run out of five. The results are complete by then: such messages
    are noise, and the levels are restored as soon as the close returns.

    EXAMPLES::

        sage: import logging
        sage: from sage_dynsym.scale.cluster import closed_quietly
        sage: class Resource:
        ....:     def close(self):
        ....:         print(logging.getLogger('distributed.batched').getEffectiveLevel())
        sage: with closed_quietly(Resource()) as r:
        ....:     print(logging.getLogger('distributed.batched').getEffectiveLevel() < 50)
        True
        50
    """
    try:
        yield resource
    finally:
        loggers = [logging.getLogger(name) for name in SHUTDOWN_LOGGERS]
        levels = [logger.level for logger in loggers]
        for logger in loggers:
            logger.setLevel(logging.CRITICAL)
        try:
            resource.close()
        finally:
            for logger, level in zip(loggers, levels):
                logger.setLevel(level)


def local_cluster(workers):
    r"""
    A local Dask cluster of ``workers`` worker processes (one thread each,
    on 127.0.0.1, no dashboard), its scheduler in this process.

    The workers are fresh interpreters (``python -m dask``, one process
    each, without a nanny: a chunk lost with a worker is computed again by
    another one), not children made by
    :mod:`multiprocessing`: the ``spawn`` and ``forkserver`` start methods
    import the main script again in every child, which runs an unguarded
    script once per worker and fails; ``fork`` is unsafe in a process with
    threads, which a Sage session has.

    EXAMPLES::

        sage: from distributed import Client
        sage: from sage_dynsym.scale.cluster import local_cluster
        sage: with local_cluster(1) as cluster, Client(cluster) as c:
        ....:     c.submit(lambda x: x + 1, 1).result()
        2
    """
    from distributed import Scheduler, SpecCluster
    from distributed.deploy.subprocess import SubprocessWorker
    quiet = logging.ERROR
    worker = {'cls': SubprocessWorker,
              'options': {'worker_class': 'distributed.Worker',
                          'worker_kwargs': {'nthreads': 1, 'host': '127.0.0.1',
                                            'silence_logs': quiet}}}
    # no dashboard; the scheduler's other HTTP endpoints on a free port of
    # 127.0.0.1 (a fixed port may be taken by another cluster)
    scheduler = {'cls': Scheduler,
                 'options': {'host': '127.0.0.1', 'dashboard': False,
                             'dashboard_address': '127.0.0.1:0'}}
    return SpecCluster(scheduler=scheduler, workers={i: worker for i in range(workers)},
                       worker=worker, silence_logs=quiet, name='sage_dynsym')


def _wait_for_workers(client, timeout, what, n=1):
    try:
        client.wait_for_workers(n, timeout=timeout)
    except (TimeoutError, OSError) as err:
        raise AnalysisError(f"{what} has no worker after {timeout} s ({err})",
                            entry="scale") from err


def run_chunks(function, task, ranges, collect, client=None, workers=None,
               timeout=DEFAULT_TIMEOUT, progress=False, label='chunk',
               threshold=CLUSTER_THRESHOLD):
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
    - ``threshold`` -- (default: :data:`CLUSTER_THRESHOLD`) with
      ``client=None``: the estimated seconds of work above which a local
      cluster is started

    OUTPUT: where the chunks ran: ``'this process'``, ``'local cluster'``
    or ``'dask'`` (a given client or scheduler)

    Errors of a chunk are raised here; a chunk whose workers keep dying is
    an :class:`~sage_dynsym.errors.AnalysisError`.

    EXAMPLES:

    Small work stays in this process when the choice is left to the cost::

        sage: from sage_dynsym.scale.cluster import run_chunks, chunks
        sage: out = {}
        sage: run_chunks(lambda task, a, b: task * (b - a), 10, chunks(7, 3),
        ....:            lambda i, r: out.__setitem__(i, r))
        'this process'
        sage: out
        {0: 30, 1: 30, 2: 10}

    See also :func:`~sage_dynsym.scale.maps.stability_map`.
    """
    # the arguments checked before any chunk runs
    finite_real(timeout, 'timeout', error=AnalysisError, minimum=0, strict=True)
    if workers is not None:
        count(workers, 'workers', maximum=MAX_WORKERS, error=AnalysisError)
    first = 0
    if client is None and workers is None:
        if not ranges:
            return 'this process'
        begin = time.perf_counter()
        collect(0, function(task, *ranges[0]))
        elapsed = time.perf_counter() - begin
        first = 1
        size = max(1, ranges[0][1] - ranges[0][0])
        estimate = elapsed * sum(b - a for a, b in ranges[1:]) / size
        if estimate <= threshold or machine_cores() < 2:
            client = False
        else:
            _log.info("about %.0f s of work left at the pace of the first chunk: "
                      "starting a local Dask cluster of %d workers", estimate,
                      machine_cores() if workers is None else workers)
            client = 'local'
    elif client is None:
        client = 'local'
    if client is False:
        for i in range(first, len(ranges)):
            collect(i, function(task, *ranges[i]))
        return 'this process'
    distributed = _dask()
    from . import kernel
    shipped = _Shipped(function) if getattr(function, '__module__', None) == kernel.__name__ \
        else function
    token = uuid.uuid4().hex[:10]
    with connected(client, workers, timeout) as c:
        data = c.submit(_Shipped(kernel.identity), task, key=f"{label}-data-{token}", pure=False)
        futures = [c.submit(shipped, data, a, b, key=f"{label}-{token}-{i}", pure=False)
                   for i, (a, b) in enumerate(ranges) if i >= first]
        index = {f.key: first + i for i, f in enumerate(futures)}
        try:
            if progress:
                _show_progress(c, futures)
            for future in distributed.as_completed(futures, loop=c.loop):
                try:
                    result = future.result()
                except distributed.KilledWorker as err:
                    raise AnalysisError(f"the workers computing {future.key} kept dying "
                                        f"({err})", entry="scale") from err
                collect(index[future.key], result)
                future.release()
        except BaseException:
            c.cancel(futures + [data], force=True)
            raise
        finally:
            del futures, data
    return 'local cluster' if client == 'local' else 'dask'


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


def run_in_processes(function, arguments, client=None, workers=None, timeout=DEFAULT_TIMEOUT,
                     threshold=CLUSTER_THRESHOLD):
    r"""
    ``[function(*a) for a in arguments]``, each call in the main thread of
    a process: for work that uses Sage's PARI, which cannot run in another
    thread.

    Where the calls run, by ``client``:

    - ``None`` (the default) -- chosen by the cost, as in
      :func:`run_chunks`: the first call runs in this process and is
      timed; the others go to Dask's process pool when their estimated
      time exceeds ``threshold`` seconds on a machine of several cores,
      otherwise they run here too;
    - ``'local'`` -- Dask's process pool
      (``dask.compute(..., scheduler='processes')``, whose tasks run in the
      main thread of its worker processes), ``workers`` processes (default:
      one per core), started for this computation and closed after it.
      Its workers are spawned and import the main module again: a script
      needs the ``if __name__ == '__main__':`` guard;
    - a :class:`dask.distributed.Client` or a scheduler address -- its
      workers, as given. A ``dask.distributed`` worker runs its tasks in
      threads of its process, even with one thread (its event loop holds
      the main thread): the task sent to a worker hands the call to a child
      process of the worker (:func:`~sage_dynsym.scale.kernel.in_child_process`,
      :func:`serve_child`), which runs it in its main thread. The children
      are kept by the worker and reused, one per task running at the same
      time (at most its number of threads), so Sage is imported once per
      child; they end with their worker. The workers need Sage and this
      package (the workers of maps and sweeps do not);
    - ``False`` -- in this process, one after the other.

    ``function`` and ``arguments`` travel by cloudpickle (a function of the
    main script too). An error of a call on a worker is raised here: an
    error of this package as it is, another one as an
    :class:`~sage_dynsym.errors.AnalysisError`; the cause of either holds
    the traceback in the child.

    OUTPUT: the list of the results, in the order of ``arguments``

    EXAMPLES::

        sage: from operator import add
        sage: from sage_dynsym.scale.cluster import run_in_processes
        sage: run_in_processes(add, [(1, 2), (3, 4)])
        [3, 7]
        sage: run_in_processes(add, [(1, 2), (3, 4)], client='local', workers=1)  # long time
        [3, 7]

    On the workers of a ``dask.distributed`` cluster, in the main thread of
    their children; an error there is raised here with its cause::

        sage: import os, operator
        sage: from distributed import Client, LocalCluster
        sage: def where(x):
        ....:     import os, threading
        ....:     return x, os.getpid(), threading.current_thread() is threading.main_thread()
        sage: with LocalCluster(n_workers=1, threads_per_worker=1, processes=True,  # long time
        ....:                   dashboard_address=None) as cluster, Client(cluster) as c:
        ....:     out = run_in_processes(where, [(1,), (2,)], client=c)
        ....:     workers = c.run(os.getpid)
        ....:     run_in_processes(operator.truediv, [(int(1), int(0))], client=c)
        Traceback (most recent call last):
        ...
        AnalysisError: scale: truediv failed in a child process of a Dask worker: ZeroDivisionError: division by zero
        sage: [x for x, _, _ in out], all(main for _, _, main in out)  # long time
        ([1, 2], True)
        sage: len({p for _, p, _ in out}), {p for _, p, _ in out} & set(workers.values())  # long time
        (1, set())
    """
    finite_real(timeout, 'timeout', error=AnalysisError, minimum=0, strict=True)
    if workers is not None:
        count(workers, 'workers', maximum=MAX_WORKERS, error=AnalysisError)
    arguments = list(arguments)
    done = []
    if client is None and workers is None and arguments:
        begin = time.perf_counter()
        done.append(function(*arguments[0]))
        estimate = (time.perf_counter() - begin) * (len(arguments) - 1)
        if estimate <= threshold or machine_cores() < 2:
            client = False
        else:
            _log.info("about %.0f s of work left at the pace of the first task: "
                      "starting Dask's process pool of %d workers", estimate, machine_cores())
    rest = arguments[len(done):]
    if client is False or not rest:
        return done + [function(*a) for a in rest]
    if client is None or client == 'local':
        import dask
        tasks = [dask.delayed(function, pure=False)(*a) for a in rest]
        # one task at a time per process: each is a whole solve
        return done + list(dask.compute(*tasks, scheduler='processes', chunksize=1,
                                        num_workers=workers or machine_cores()))
    with connected(client, workers, timeout) as c:
        return done + _in_worker_children(c, function, rest)


#: The code run by a child process of a Dask worker (:func:`serve_child`).
CHILD_CODE = "from sage_dynsym.scale.cluster import serve_child; serve_child()"


def _in_worker_children(client, function, arguments):
    r"""``[function(*a) for a in arguments]`` in the children of the workers of ``client``."""
    import cloudpickle
    from . import kernel
    distributed = _dask()
    run = _Shipped(kernel.in_child_process)
    futures = [client.submit(run, cloudpickle.dumps((function, a)), CHILD_CODE, pure=False)
               for a in arguments]
    try:
        replies = client.gather(futures)
    except distributed.KilledWorker as err:
        raise AnalysisError(f"the workers computing {function.__name__} kept dying ({err})",
                            entry="scale") from err
    except BaseException:
        client.cancel(futures, force=True)
        raise
    return [_outcome(reply, getattr(function, '__name__', 'a task')) for reply in replies]


class _RemoteTraceback(Exception):
    r"""The traceback of an error in another process (the cause of its error here)."""

    def __str__(self):
        return self.args[0]


def _outcome(reply, name):
    r"""The result of the reply of :func:`~sage_dynsym.scale.kernel.in_child_process`,
    or its error raised."""
    import pickle
    kind, data = reply
    if kind == 'lost':
        raise AnalysisError(f"{name}: {data}", entry="scale")
    kind, *rest = pickle.loads(data)
    if kind == 'done':
        return rest[0]
    dumped, text, summary = rest
    remote = _RemoteTraceback(f"\n\"\"\"\n{text}\"\"\"")
    try:
        error = pickle.loads(dumped) if dumped is not None else None
    except (pickle.UnpicklingError, AttributeError, ImportError, TypeError, ValueError,
            EOFError):          # a class this process cannot rebuild: its text is enough
        error = None
    if isinstance(error, DynSymError):
        raise error from remote
    if error is not None:
        error.__cause__ = remote
    raise AnalysisError(f"{name} failed in a child process of a Dask worker: {summary}",
                        entry="scale") from (remote if error is None else error)


def serve_child(requests=None, replies=None):
    r"""
    The loop of a child process of a Dask worker: each message of
    ``requests`` (see :func:`~sage_dynsym.scale.kernel.send_message`) is a
    call ``(function, arguments)`` (cloudpickle), run in this thread, its
    reply written to ``replies``: ``('done', result)``, or ``('error',
    error, traceback, summary)`` (``error`` pickled, ``None`` if it cannot
    be). Ends when ``requests`` ends.

    INPUT:

    - ``requests``, ``replies`` -- binary streams (default: the standard
      input, and the standard output, which is then pointed to the
      standard error so that what the work prints does not mix with the
      replies)

    EXAMPLES::

        sage: import io, operator, pickle, cloudpickle
        sage: from sage_dynsym.scale.cluster import serve_child
        sage: from sage_dynsym.scale.kernel import send_message, receive_message
        sage: requests, replies = io.BytesIO(), io.BytesIO()
        sage: for call in [(operator.add, (1, 2)), (operator.truediv, (int(1), int(0)))]:
        ....:     send_message(requests, cloudpickle.dumps(call))
        sage: _ = requests.seek(0); serve_child(requests, replies); _ = replies.seek(0)
        sage: pickle.loads(receive_message(replies))
        ('done', 3)
        sage: kind, error, text, summary = pickle.loads(receive_message(replies))
        sage: kind, pickle.loads(error), summary, 'Traceback' in text
        ('error', ZeroDivisionError('division by zero'), 'ZeroDivisionError: division by zero', True)
    """
    import sys
    if requests is None:
        requests = sys.stdin.buffer
        replies = os.fdopen(os.dup(1), 'wb')
        os.dup2(2, 1)
    from .kernel import receive_message, send_message
    for call in iter(lambda: receive_message(requests), None):
        send_message(replies, _reply(call))


def _reply(call):
    r"""The reply to one call of :func:`serve_child` (bytes)."""
    import pickle
    import traceback
    import cloudpickle
    try:
        function, arguments = pickle.loads(call)
        return cloudpickle.dumps(('done', function(*arguments)))
    except Exception as err:    # sent back, raised in the caller's process
        try:
            dumped = cloudpickle.dumps(err)
        except (pickle.PicklingError, TypeError, AttributeError):   # its text goes
            dumped = None
        return cloudpickle.dumps(('error', dumped, traceback.format_exc(),
                                  f"{type(err).__name__}: {err}"))

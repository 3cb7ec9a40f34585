r"""
A computation in a forked process, abandoned safely after a time

A Singular (or PARI, Maxima) library call interrupted by an alarm can leave
the library's state broken in the process that goes on (a later call
segfaulted in CI); a forked child that is killed leaves nothing behind.
:func:`forked` runs ``compute(send)`` in a child, passes back what the
child sends along the way and its result (pickled through a pipe), and
kills it after ``seconds``. It uses no signal: the wait is a ``select`` on
the pipe, so it works in any thread (Sage's ``fork`` decorator waits under
an alarm, which only the main thread receives).

A budget that decides *which way* a computation goes (the term order
tried first, a decomposition that falls back on another) must not depend
on the machine's load: ``cpu_seconds`` stops the child after that much
processor time of its own (the kernel's limit ``RLIMIT_CPU``), which a
busy machine does not shorten, where wall-clock ``seconds`` would.

EXAMPLES::

    sage: from sage_dynsym.algebra.forked import forked
    sage: forked(lambda send: factor(2^64 + 1), 60)
    ([], ('value', 274177 * 67280421310721))
    sage: forked(lambda send: [send(k) for k in range(3)] and sleep(10), 1, receive=print)
    0
    1
    2
    ([0, 1, 2], ('timeout', 1))
"""
import math
import os
import pickle
import resource
import select
import signal
import struct
import sys
import time

__all__ = ['forked', 'within_processor_time']

_LENGTH = struct.Struct('>Q')


def forked(compute, seconds=None, receive=None, cpu_seconds=None):
    r"""
    Run ``compute(send)`` in a forked process stopped after ``seconds``.

    INPUT:

    - ``compute`` -- a function of one argument ``send``: ``send(x)``
      passes the picklable object ``x`` to this process at once (what was
      sent before the child was stopped is kept)
    - ``seconds`` -- (default: ``None``, no limit) wall-clock seconds after
      which the child is killed
    - ``receive`` -- (optional) a function called here on each object sent,
      as soon as it arrives (e.g. to print what the child computed)
    - ``cpu_seconds`` -- (default: ``None``, no limit) seconds of processor
      time of the child after which it is stopped (rounded up to a whole
      second, the kernel's unit)

    OUTPUT: a pair ``(sent, outcome)``: the list of the objects sent, and
    ``('value', v)`` (``compute`` returned ``v``), ``('error', e)`` (it
    raised the exception ``e``: an exception that cannot be pickled comes
    back as a ``RuntimeError`` naming it), ``('timeout', seconds)``,
    ``('cpu', cpu_seconds)`` (over its processor time) or ``('died',
    why)`` (the child ended without a result, e.g. a crash)

    The standard output and error of the child are this process's own
    (flushed before the fork).

    EXAMPLES::

        sage: from sage_dynsym.algebra.forked import forked
        sage: R.<x, y> = QQ[]
        sage: forked(lambda send: R.ideal([x*y, x^2]).groebner_basis(), 60)
        ([], ('value', [x^2, x*y]))
        sage: forked(lambda send: 1/0)
        ([], ('error', ZeroDivisionError('rational division by zero')))

    A child that computes for longer than one second of processor time is
    stopped, however long it waited before; sleeping costs none::

        sage: forked(lambda send: sleep(2) or factor(2^64 + 1), cpu_seconds=1)
        ([], ('value', 274177 * 67280421310721))
        sage: forked(lambda send: len([k for k in range(10^10)]), cpu_seconds=1)
        ([], ('cpu', 1))

    TESTS::

        sage: import signal
        sage: forked(lambda send: os.kill(os.getpid(), signal.SIGKILL))
        ([], ('died', 'killed by signal 9'))
        sage: class Unpicklable(Exception):
        ....:     __reduce__ = None
        sage: def f(send): raise Unpicklable("no")
        sage: forked(f)
        ([], ('error', RuntimeError('Unpicklable: no (the exception of the forked process could not be passed back)')))
    """
    sys.stdout.flush()
    sys.stderr.flush()
    read_end, write_end = os.pipe()
    pid = os.fork()
    if pid == 0:
        os.close(read_end)
        if cpu_seconds is not None:
            _limit_processor_time(cpu_seconds)
        _child(compute, write_end)
    os.close(write_end)
    sent, outcome = [], None
    try:
        outcome = _collect(read_end, seconds, sent, receive)
    finally:
        os.close(read_end)
        if outcome is None or outcome[0] == 'timeout':
            os.kill(pid, signal.SIGKILL)
        _, status, usage = os.wait4(pid, 0)
    if outcome[0] == 'died':
        if cpu_seconds is not None and _over_processor_time(status, usage, cpu_seconds):
            return sent, ('cpu', cpu_seconds)
        outcome = ('died', f"killed by signal {os.WTERMSIG(status)}" if os.WIFSIGNALED(status)
                   else f"exit status {os.WEXITSTATUS(status)}")
    return sent, outcome


def within_processor_time(compute, seconds):
    r"""
    ``compute()`` in a forked process (:func:`forked`) within ``seconds``
    of its processor time, for a computation that has another way to go
    when it is stopped.

    OUTPUT: ``(True, value)``; or ``(False, why)`` when the child was
    stopped at its processor time (``why`` is ``'cpu'``) or ended without a
    result (``why`` says how). An exception of ``compute`` is raised here.

    EXAMPLES::

        sage: from sage_dynsym.algebra.forked import within_processor_time
        sage: within_processor_time(lambda: 2 + 2, 5)
        (True, 4)
        sage: within_processor_time(lambda: len([k for k in range(10^10)]), 1)
        (False, 'cpu')
        sage: within_processor_time(lambda: 1/0, 5)
        Traceback (most recent call last):
        ...
        ZeroDivisionError: rational division by zero
    """
    _, (how, value) = forked(lambda send: compute(), cpu_seconds=seconds)
    if how == 'value':
        return True, value
    if how == 'error':
        raise value
    return False, how if how == 'cpu' else f"{how}: {value}"


def _over_processor_time(status, usage, seconds):
    # stopped by the kernel at the limit: SIGXCPU at the soft limit, or
    # SIGKILL at the hard one (a second later) if SIGXCPU was caught; the
    # kernel's count and the one reported can differ by a tick, so the
    # processor time reported is compared with a margin
    if not os.WIFSIGNALED(status):
        return False
    if os.WTERMSIG(status) == signal.SIGXCPU:
        return True
    return (os.WTERMSIG(status) == signal.SIGKILL
            and usage.ru_utime + usage.ru_stime >= 0.9 * max(1, math.ceil(seconds)))


def _limit_processor_time(seconds):
    # in the child, whose processor time starts at 0 at the fork: the kernel
    # sends SIGXCPU at the soft limit and SIGKILL a second later (if SIGXCPU
    # was caught); no core file is written for either
    whole = max(1, math.ceil(seconds))
    resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
    _, hard = resource.getrlimit(resource.RLIMIT_CPU)
    if hard != resource.RLIM_INFINITY and hard <= whole:
        whole = max(1, hard - 1)
    resource.setrlimit(resource.RLIMIT_CPU, (whole, whole + 1))


def _child(compute, write_end):
    # never returns: the child must not go on with the parent's program
    # (its callers' finally blocks, atexit handlers): it kills itself at the
    # end, its outcome written (or the parent sees it died)
    try:
        try:
            from sage.interfaces.quit import invalidate_all
            invalidate_all()        # the parent's pexpect interfaces are not the child's
        except ImportError:
            pass

        def send(obj):
            _write(write_end, ('sent', obj))
        try:
            value = compute(send)
        except Exception as err:
            # passed back to be raised there; raised here too, where the
            # finally below ends the child before anything is printed
            _passed_back(write_end, ('error', err),
                         f"{type(err).__name__}: {err} (the exception")
            raise
        _passed_back(write_end, ('value', value), "(the value")
    finally:
        try:
            sys.stdout.flush()
            sys.stderr.flush()
        finally:
            os.kill(os.getpid(), signal.SIGKILL)


def _passed_back(fd, outcome, what):
    # an object that cannot be pickled comes back as a RuntimeError naming it
    try:
        _write(fd, outcome)
    except (pickle.PicklingError, TypeError, AttributeError):
        _write(fd, ('error', RuntimeError(f"{what} of the forked process could not be "
                                          "passed back)")))


def _write(fd, message):
    data = pickle.dumps(message)
    data = _LENGTH.pack(len(data)) + data
    while data:
        data = data[os.write(fd, data):]


def _collect(read_end, seconds, sent, receive):
    # the outcome read from the pipe; what is sent before it appended to
    # sent and passed to receive
    deadline = None if seconds is None else time.monotonic() + seconds
    buffer = b''
    while True:
        wait = None if deadline is None else max(deadline - time.monotonic(), 0)
        ready, _, _ = select.select([read_end], [], [], wait)
        if not ready:
            return ('timeout', seconds)
        chunk = os.read(read_end, 1 << 16)
        if not chunk:
            return ('died', None)
        buffer += chunk
        while len(buffer) >= _LENGTH.size:
            size = _LENGTH.unpack_from(buffer)[0]
            if len(buffer) < _LENGTH.size + size:
                break
            kind, obj = pickle.loads(buffer[_LENGTH.size:_LENGTH.size + size])
            buffer = buffer[_LENGTH.size + size:]
            if kind != 'sent':
                return (kind, obj)
            sent.append(obj)
            if receive is not None:
                receive(obj)

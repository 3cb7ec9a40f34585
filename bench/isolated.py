"""
A computation of a benchmark in a process of its own, with a time limit.

The reference tools (SymPy, Maxima, a plain Singular call) may run for hours
or leave a library in a bad state when interrupted: each runs in a child
process that is killed when its time is up.
"""
import multiprocessing


def in_subprocess(job, args, timeout, default=None):
    """
    ``job(*args, queue)`` in a child process: what it put on ``queue``;
    ``default`` if it ended without putting anything; ``None`` if it was
    still running after ``timeout`` seconds (it is killed).
    """
    queue = multiprocessing.Queue()
    child = multiprocessing.Process(target=job, args=(*args, queue))
    child.start()
    child.join(timeout)
    if child.is_alive():
        child.kill()
        child.join()
        return None
    return queue.get() if not queue.empty() else default

"""
Run ``sage_dynsym.load`` on many files in one process, each file in a
forked child with a time limit (``signal.alarm``, and a kill from the
parent) and a memory limit (``RLIMIT_DATA``), so that a crash, a hang or a
memory explosion of one file is seen as such and does not stop the others.

Usage: ``python tests/hostile/run_load.py SECONDS MEGABYTES FILE...``;
prints one JSON line per file: ``{"path", "status", "class", "message",
"seconds"}`` with ``status`` one of ``ok`` (loaded), ``error`` (the
package's own error), ``exception`` (any other exception: a bug),
``crash`` (the child died), ``hang`` (over the time limit).
"""
import json
import os
import resource
import select
import signal
import sys
import time
import traceback


def run_one(path, seconds, megabytes, load, DynSymError):
    read_end, write_end = os.pipe()
    pid = os.fork()
    if pid == 0:                                    # the child
        os.close(read_end)
        result = {}
        try:
            limit = megabytes * 2**20
            resource.setrlimit(resource.RLIMIT_DATA, (limit, limit))
            signal.signal(signal.SIGALRM, signal.SIG_DFL)     # a hang ends the child
            signal.alarm(seconds)
            try:
                model = load(path)
                result = {"status": "ok", "class": type(model).__name__, "message": str(model)}
            except DynSymError as err:
                result = {"status": "error", "class": type(err).__name__, "message": str(err)}
            except BaseException as err:                      # noqa: B902 -- report everything
                result = {"status": "exception", "class": type(err).__name__,
                          "message": str(err)[:2000], "traceback": traceback.format_exc()[-4000:]}
            data = json.dumps(result).encode()
            while data:
                data = data[os.write(write_end, data):]
        finally:
            os._exit(0)
    os.close(write_end)
    start, chunks, deadline = time.time(), [], time.time() + seconds + 5
    while True:
        remaining = deadline - time.time()
        ready, _, _ = select.select([read_end], [], [], max(remaining, 0))
        if not ready:
            os.kill(pid, signal.SIGKILL)
            break
        chunk = os.read(read_end, 65536)
        if not chunk:
            break
        chunks.append(chunk)
    os.close(read_end)
    _, status = os.waitpid(pid, 0)
    elapsed = time.time() - start
    if chunks:
        result = json.loads(b"".join(chunks))
    elif os.WIFSIGNALED(status) and os.WTERMSIG(status) in (signal.SIGALRM, signal.SIGKILL):
        result = {"status": "hang", "class": None,
                  "message": f"over {seconds} s (signal {os.WTERMSIG(status)})"}
    else:
        how = (f"signal {os.WTERMSIG(status)}" if os.WIFSIGNALED(status)
               else f"exit status {os.WEXITSTATUS(status)}")
        result = {"status": "crash", "class": None, "message": f"the child died ({how})"}
    result.update(path=path, seconds=round(elapsed, 3))
    return result


def main(argv):
    seconds, megabytes, files = int(argv[0]), int(argv[1]), argv[2:]
    from sage_dynsym import load, DynSymError
    for path in files:
        print(json.dumps(run_one(path, seconds, megabytes, load, DynSymError)), flush=True)


if __name__ == "__main__":
    main(sys.argv[1:])

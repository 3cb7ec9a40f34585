"""
Benchmark: the command line on RLC ladders, with the report's size budget.

An N-section ladder (series R_k, L_k, shunt C_k, driven by E1) is loaded by
a resistor (as ``examples/rlc_ladder.yaml``) or by a resistor and an
inductor (then the free-circuit stability section is reachable). Each run
is ``python -m sage_dynsym FILE`` in a fresh child process; the wall time
and the peak resident memory of the child (``ru_maxrss`` from
``os.wait4``, i.e. ``resource.getrusage`` of that child) are printed with
the size of the report and the sections skipped for the budget.

The reference in the same run is the report without a budget (``--budget
10**40``: every section computed, as before the budget existed) on the
small ladders; it is not run on large ones, where it took 24 GB at 40
sections. The target of the reliability issue is checked on the 40-section
ladders: under 30 s and 2 GB peak memory.

Usage: ``python bench/bench_cli_ladder.py [--quick] [--sizes 3,5,10,40]
[--timeout S]`` (``--quick``: sizes 3 and 40, no reference run beyond 3).
"""
import argparse
import os
import resource
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "tests"))
from hostile.corpus import ladder  # noqa: E402

TARGET_SECONDS, TARGET_MB = 30, 2048
#: the reference (no budget) is run up to this many sections
REFERENCE_UP_TO = 5
#: memory limit of every child (RLIMIT_DATA), protecting the machine
LIMIT_MB = 6144


def _limit():
    limit = LIMIT_MB * 2**20
    resource.setrlimit(resource.RLIMIT_DATA, (limit, limit))


def run(path, extra, timeout):
    """Wall seconds, peak MB, report characters, skipped lines, status."""
    start = time.time()
    with tempfile.TemporaryFile("w+") as out, tempfile.TemporaryFile("w+") as err:
        child = subprocess.Popen([sys.executable, "-m", "sage_dynsym", path, *extra],
                                 stdout=out, stderr=err, preexec_fn=_limit)
        deadline = start + timeout
        while True:
            pid, status, usage = os.wait4(child.pid, os.WNOHANG)
            if pid:
                break
            if time.time() > deadline:
                child.kill()
                pid, status, usage = os.wait4(child.pid, 0)
                break
            time.sleep(0.05)
        seconds = time.time() - start
        out.seek(0)
        text = out.read()
        err.seek(0)
        errors = err.read()
    status = ("timeout" if seconds > timeout else "ok" if os.WIFEXITED(status) and
              os.WEXITSTATUS(status) == 0 else f"failed ({errors.strip()[-200:]})")
    skipped = [line.split(":")[0] for line in text.splitlines() if ": skipped," in line]
    return seconds, usage.ru_maxrss / 1024, len(text), skipped, status


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true", help="sizes 3 and 40 only")
    parser.add_argument("--sizes", default="3,5,10,40", help="comma-separated section counts")
    parser.add_argument("--timeout", type=float, default=300, help="seconds per run")
    args = parser.parse_args(argv)
    sizes = [3, 40] if args.quick else [int(n) for n in args.sizes.split(",")]
    with tempfile.TemporaryDirectory(prefix="bench_cli_ladder_") as folder:
        return _bench(sizes, args, folder)


def _bench(sizes, args, folder):
    print(f"{'load':9} {'N':>4} {'run':10} {'seconds':>8} {'peak MB':>8} {'report chars':>13}"
          "  skipped for the budget / status")
    verdicts = []
    for load_kind in ("R", "R+L"):
        for n in sizes:
            path = os.path.join(folder, f"ladder_{load_kind.replace('+', '')}_{n}.yaml")
            with open(path, "w") as stream:
                stream.write(ladder(f"ladder of {n} sections, {load_kind} load", n,
                                    inductive_load=(load_kind == "R+L")))
            runs = [("budget", [])]
            if n <= (3 if args.quick else REFERENCE_UP_TO):
                runs.append(("no budget", ["--budget", str(10**40)]))
            figures = {}
            for label, extra in runs:
                seconds, mb, chars, skipped, status = run(path, extra, args.timeout)
                figures[label] = seconds
                print(f"{load_kind:9} {n:>4} {label:10} {seconds:8.1f} {mb:8.0f} {chars:13d}  "
                      f"{', '.join(skipped) or '-'} / {status}")
                if n == 40 and label == "budget":
                    verdicts.append((load_kind, seconds, mb, status))
            if len(figures) == 2:
                print(f"{'':9} {n:>4} {'ratio':10} {figures['budget'] / figures['no budget']:8.2f}"
                      "  (with budget / without)")
    for load_kind, seconds, mb, status in verdicts:
        ok = status == "ok" and seconds < TARGET_SECONDS and mb < TARGET_MB
        print(f"40 sections, {load_kind} load: {seconds:.1f} s, {mb:.0f} MB peak -> "
              f"{'PASS' if ok else 'FAIL'} (target < {TARGET_SECONDS} s and < {TARGET_MB} MB)")
    return 0 if all(status == "ok" and s < TARGET_SECONDS and mb < TARGET_MB
                    for _, s, mb, status in verdicts) else 1


if __name__ == "__main__":
    sys.exit(main())

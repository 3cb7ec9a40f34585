"""
Refresh the two timing files that order ``make test`` slowest first:
``tests/doctest_timings.json`` from the times ``sage -t`` recorded in its
last run of ``make doctest`` (``.venv/doctest-timings.json``), and
``tests/pytest_timings.json`` from a run of the fast pytest set with
``--durations=0`` (seconds per file, files under half a second left out).
Run by ``make timings``; the files are data, a stale one only costs time.
"""
import json
import re
import subprocess
import sys
from collections import defaultdict
from pathlib import Path

TESTS = Path(__file__).resolve().parent
ROOT = TESTS.parent


def write(path, entries):
    lines = [f" {json.dumps(key)}: {value}" for key, value in entries]
    path.write_text("{\n" + ",\n".join(lines) + "\n}\n")


def doctest_timings():
    recorded = json.loads((ROOT / ".venv" / "doctest-timings.json").read_text())
    write(TESTS / "doctest_timings.json",
          [(name, json.dumps({"walltime": round(stats["walltime"], 2)}))
           for name, stats in sorted(recorded.items())
           if name.startswith("sage_dynsym") or "." not in name])


def pytest_timings():
    run = subprocess.run([sys.executable, "-m", "pytest", "-q", "-n", "2", "--dist", "loadfile",
                          "--durations=0", "-p", "no:warnings", "-m", "not slow", "tests",
                          "--ignore=tests/browser"], cwd=ROOT, capture_output=True, text=True)
    if run.returncode:
        sys.exit(run.stdout[-3000:] + run.stderr[-3000:])
    seconds = defaultdict(float)
    for found in re.finditer(r"^([0-9.]+)s (?:call|setup|teardown)\s+tests/([^:\s]+)::",
                             run.stdout, re.MULTILINE):
        seconds[found.group(2)] += float(found.group(1))
    write(TESTS / "pytest_timings.json",
          sorted(((name, round(s, 1)) for name, s in seconds.items() if s >= 0.5),
                 key=lambda entry: (-entry[1], entry[0])))


if __name__ == "__main__":
    doctest_timings()
    pytest_timings()

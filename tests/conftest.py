"""pytest set-up: Sage must be fully initialised before sage_dynsym is used."""
import os

import sage.all  # noqa: F401


def slow_except(values, fast, ids=None):
    r"""The parameters ``values`` for ``pytest.mark.parametrize``, all but
    those in ``fast`` marked slow: ``make test`` runs the ``fast`` ones,
    ``make test-slow`` (CI) the others. ``ids`` names a value."""
    import pytest
    return [pytest.param(v, marks=() if v in fast else pytest.mark.slow,
                         id=ids(v) if ids else None) for v in values]


def run_cli(*args):
    r"""``sage-dynsym ARGS`` run by the command line's ``main`` in this
    process: a ``CompletedProcess`` with the exit status and the text written
    to standard output and error. The tests that need a process of their own
    (signals, limits, imports) start one; the others save the interpreter's
    start-up (Sage's import, 3 s) this way."""
    import contextlib
    import io
    import subprocess
    from sage_dynsym.__main__ import main
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            status = main([str(arg) for arg in args])
        except SystemExit as exit:          # argparse: a malformed command line
            status = exit.code
    return subprocess.CompletedProcess(["sage-dynsym", *args], status, out.getvalue(),
                                       err.getvalue())


#: ``make test`` runs each property-based test (marked ``fuzz``) on a fifth of
#: its examples; ``make test-slow`` (CI) sets SAGE_DYNSYM_FUZZ=full and runs
#: them again on all of them.
FULL_FUZZ = os.environ.get("SAGE_DYNSYM_FUZZ") == "full"


def fuzz_settings(n):
    r"""Hypothesis settings for ``n`` examples (a fifth of them, at least 10,
    unless SAGE_DYNSYM_FUZZ=full): deterministic, no deadline, no example
    database -- the property is about the arguments, not about timing."""
    from hypothesis import HealthCheck, settings
    return settings(max_examples=n if FULL_FUZZ else max(10, n // 5), deadline=None,
                    derandomize=True, database=None, suppress_health_check=list(HealthCheck))


def pytest_collection_modifyitems(config, items):
    r"""The test files slowest first (their seconds in ``make test``, from
    ``tests/pytest_timings.json``; a file not listed counts as fast), so that
    the two processes of ``make test`` (``--dist loadfile
    --no-loadscope-reorder``) do not end with one long file on one process
    while the other waits. Within a file the order is unchanged."""
    import json
    from pathlib import Path
    seconds = json.loads((Path(__file__).parent / "pytest_timings.json").read_text())
    items.sort(key=lambda item: -seconds.get(item.path.name, 0.0))   # a stable sort

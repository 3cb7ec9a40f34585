"""
Hostile and malformed description files (``tests/hostile/corpus.py``: more
than 120 of them, from every class of the reliability issue) go through
``load`` and through the command line, in subprocesses with a time and a
memory limit: no traceback, no crash, no hang; each file is refused with
the package's own error naming the file (and the expected fragment), or --
for the valid ones -- loaded and reported.

``load`` runs for all files in one process that forks a child per file
(``tests/hostile/run_load.py``); the command line runs once over all files
(``--time-limit``), and alone on the files that used to hang, crash or eat
memory.
"""
import json
import os
import resource
import subprocess
import sys
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
from hostile.corpus import cases, write  # noqa: E402

# the whole hostile corpus, each file in a process of its own: `make test-slow` (CI) runs it
pytestmark = pytest.mark.slow

SECONDS = 60                # per file: a hang detector, far above the usual seconds
MEGABYTES = 2048            # RLIMIT_DATA of each process
CASES = cases()
NAMES = [c[0] for c in CASES]
#: files that crashed, hung or exhausted memory before, run alone through the CLI
ALONE = ["ok_ladder_300", "ok_ladder_40", "ok_coordinates_50", "coordinates_5000",
         "parentheses_100000",
         "nested_sin_3000", "polynomial_1e6_chars", "billion_laughs", "nested_50000_flow_lists",
         "three_to_ten_to_ten", "integer_1e6_digits", "resistor_zero", "log0_mass",
         "ok_huge_mass_expansion", "ok_huge_capacitance_expansion"]
#: report sections whose failures are another module's (the exact stationary
#: solver); any other "section failed" line is a bug
OTHERS = ("Equilibria", "Stationary motions")


def _limits():
    limit = MEGABYTES * 2**20
    resource.setrlimit(resource.RLIMIT_DATA, (limit, limit))


def _cli(*args, timeout):
    return subprocess.run([sys.executable, "-m", "sage_dynsym", *args], capture_output=True,
                          text=True, timeout=timeout, preexec_fn=_limits)


@pytest.fixture(scope="module")
def corpus(tmp_path_factory):
    return write(str(tmp_path_factory.mktemp("hostile")))


@pytest.fixture(scope="module")
def load_results(corpus):
    paths = [path for path, _, _ in corpus.values()]
    run = subprocess.run([sys.executable, str(HERE / "hostile" / "run_load.py"), str(SECONDS),
                          str(MEGABYTES), *paths], capture_output=True, text=True,
                         timeout=SECONDS * len(paths))
    assert run.returncode == 0, run.stderr[-3000:]
    results = {}
    for line in run.stdout.splitlines():
        result = json.loads(line)
        results[Path(result["path"]).stem] = result
    return results


@pytest.fixture(scope="module")
def cli_all(corpus):
    paths = sorted(path for path, _, _ in corpus.values())
    return _cli("--time-limit", str(SECONDS), *paths, timeout=SECONDS * len(paths))


def test_corpus_is_large_and_covers_both_outcomes():
    assert len(CASES) >= 120
    assert len(set(NAMES)) == len(NAMES)
    assert sum(expect == "ok" for _, _, expect, _ in CASES) >= 10


@pytest.mark.parametrize("name", NAMES)
def test_load(name, corpus, load_results):
    path, expect, fragment = corpus[name]
    result = load_results[name]
    assert result["status"] in ("ok", "error"), result     # no exception, crash or hang
    assert result["status"] == expect, result
    if expect == "error":
        assert result["class"].endswith("Error")
        assert result["message"].startswith(path + ": "), result
        assert fragment is None or fragment in result["message"], result


def test_cli_on_the_whole_corpus(corpus, cli_all):
    assert cli_all.returncode == 1, cli_all.stderr[-3000:]
    assert "Traceback" not in cli_all.stderr + cli_all.stdout
    errors = cli_all.stderr.splitlines()
    assert all(line.startswith("sage-dynsym: error: ") for line in errors), errors
    for name, (path, expect, fragment) in corpus.items():
        mine = [line for line in errors if line.startswith(f"sage-dynsym: error: {path}: ")]
        if expect == "error":
            assert len(mine) == 1, (name, mine)
            assert fragment is None or fragment in mine[0], (name, mine[0])
        else:
            assert mine == [], (name, mine)
            assert f"\n== {name} (" in "\n" + cli_all.stdout, name
    failed = [line for line in cli_all.stdout.splitlines()
              if "section failed" in line and not line.startswith(OTHERS)]
    assert failed == []


@pytest.mark.parametrize("name", ALONE)
def test_cli_alone_on_former_crashes_and_hangs(name, corpus):
    path, expect, fragment = corpus[name]
    run = _cli(path, timeout=120)
    assert run.returncode == (0 if expect == "ok" else 1), run.stderr[-2000:]
    assert "Traceback" not in run.stderr + run.stdout
    if expect == "ok":
        assert run.stdout.startswith(f"== {name} (")
        # the sections after a skipped one are still printed
        assert "Lagrangian" in run.stdout or "Mixed potential" in run.stdout
    else:
        assert run.stderr.count("\n") == 1 and fragment in run.stderr


def test_no_file_was_created_by_a_hostile_expression():
    assert not os.path.exists("HACKED")

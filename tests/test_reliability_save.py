"""
``save`` never loses a file: it writes a temporary file in the same folder,
syncs it and renames it over the old one. Interrupted by SIGKILL or SIGINT
while writing a large model over its own description, the old file is
left byte for byte; a failed save leaves no temporary file behind.
"""
import glob
import os
import signal
import stat
import subprocess
import sys
import textwrap
import time

import pytest

from sage_dynsym import load, save, DescriptionError
from sage_dynsym.description import example_path
from conftest import slow_except  # noqa: E402

WRITER = textwrap.dedent("""
    import sys
    from sage_dynsym import save
    from sage_dynsym.circuits import Circuit
    path, n = sys.argv[1], int(sys.argv[2])
    branches = [[0, 1, 'E1']]
    for k in range(1, n + 1):
        branches += [[2*k - 1, 2*k, f'R{k}'], [2*k, 2*k + 1, f'L{k}'], [2*k + 1, 0, f'C{k}']]
    model = Circuit(branches, name='a large ladder written over its own file')
    print('ready', flush=True)
    save(model, path, results=False)
    print('done', flush=True)
""")


def _interrupt(path, signum, sections):
    """Start a save of a large model over ``path``; send ``signum`` while the
    temporary file is being written. Return (signalled, returncode)."""
    child = subprocess.Popen([sys.executable, "-c", WRITER, str(path), str(sections)],
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    assert child.stdout.readline().strip() == "ready"
    pattern = os.path.join(os.path.dirname(path), f".{os.path.basename(path)}.*.tmp")
    signalled = False
    while child.poll() is None:
        partial = glob.glob(pattern)
        if partial and os.path.getsize(partial[0]) > 0:
            child.send_signal(signum)
            signalled = True
            break
        time.sleep(0.001)
    child.communicate(timeout=300)
    return signalled, child.returncode


@pytest.mark.parametrize("signum", slow_except([signal.SIGKILL, signal.SIGINT], [signal.SIGINT],
                                                ids=lambda s: s.name))
def test_interrupted_save_keeps_the_old_file(tmp_path, signum):
    path = tmp_path / "model.yaml"
    save(load(example_path("nonlinear_circuit.yaml")), str(path))
    before = path.read_bytes()
    for sections in (5000, 20000, 60000):       # large enough to be caught while writing
        signalled, returncode = _interrupt(str(path), signum, sections)
        if signalled:
            break
    assert signalled, "the save finished before it could be interrupted"
    assert returncode != 0
    assert path.read_bytes() == before
    assert load(str(path)).name() == "nonlinear circuit of Example 2"
    leftovers = glob.glob(str(tmp_path / ".model.yaml.*.tmp"))
    if signum == signal.SIGINT:           # the interrupted save cleans up after itself
        assert leftovers == []


def test_save_replaces_a_file_and_keeps_its_permissions(tmp_path):
    path = tmp_path / "model.yaml"
    path.write_text("old content\n")
    os.chmod(path, 0o640)
    save(load(example_path("rlc_ladder.yaml")), str(path))
    assert stat.S_IMODE(os.stat(path).st_mode) == 0o640
    assert load(str(path)).name() == "RLC ladder with three sections"
    assert os.listdir(tmp_path) == ["model.yaml"]


def test_save_through_a_symbolic_link_replaces_its_target(tmp_path):
    target = tmp_path / "real.yaml"
    target.write_text("old\n")
    link = tmp_path / "link.yaml"
    os.symlink(target, link)
    save(load(example_path("rlc_ladder.yaml")), str(link))
    assert os.path.islink(link)
    assert load(str(target)).name() == "RLC ladder with three sections"


def test_a_failing_save_leaves_the_old_file_and_no_temporary_file(tmp_path, monkeypatch):
    import yaml
    path = tmp_path / "model.yaml"
    path.write_text("old content\n")

    def half_then_interrupted(data, stream, **options):
        stream.write("kind: circuit\nbranch")
        raise KeyboardInterrupt

    monkeypatch.setattr(yaml, "safe_dump", half_then_interrupted)
    with pytest.raises(KeyboardInterrupt):
        save(load(example_path("rlc_ladder.yaml")), str(path), results=False)
    assert path.read_text() == "old content\n"
    assert os.listdir(tmp_path) == ["model.yaml"]


def test_save_into_a_missing_folder_is_the_package_error(tmp_path):
    with pytest.raises(DescriptionError, match="cannot write the file"):
        save(load(example_path("rlc_ladder.yaml")), str(tmp_path / "no" / "such.yaml"))

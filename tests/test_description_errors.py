"""Bad description files get a clear error from the package's own classes,
naming the entry; never a traceback from inside Sage, never code execution."""
import os
import sys
import textwrap
from pathlib import Path

import pytest

from sage_dynsym import load, DescriptionError, ModelError, ExpressionError

sys.path.insert(0, str(Path(__file__).resolve().parent))
from hostile.corpus import pendulum  # noqa: E402

GOOD = pendulum("probe")


def write(tmp_path, text, name="model.yaml"):
    path = tmp_path / name
    path.write_text(textwrap.dedent(text))
    return str(path)


def test_good_file_loads(tmp_path):
    system = load(write(tmp_path, GOOD))
    assert [str(q) for q in system.coordinates()] == ["psi", "theta"]


@pytest.mark.parametrize("old, new, error, fragments", [
    ("parent: 0", "parent: nowhere", ModelError, ["bodies[0].parent", "unknown parent body 'nowhere'"]),
    ("[[3, psi], [1, theta]]", "[[3, psi], [7, theta]]", ModelError,
     ["bodies[0].rotations[1]", "must be 1, 2 or 3"]),
    ("mass: m\n", "mass: m*k\n", ExpressionError, ["bodies[0].mass", "undeclared symbol 'k'"]),
    ("[[m*l^2, 0, 0], [0, m*l^2, 0], [0, 0, 0]]", "[[m*l^2, 1, 0], [0, m*l^2, 0], [0, 0, 0]]",
     ModelError, ["bodies[0].inertia", "symmetric"]),
    ("joint: [0, 0, 0]", "joint: [0, 0]", DescriptionError, ["bodies[0].joint", "3 expressions"]),
    ("mass_center: [0, 0, l]", "mass_center: [0, 0, l +* 2]", ExpressionError,
     ["bodies[0].mass_center[2]", "malformed expression"]),
    ("mass: m\n", "mass: m\n    colour: red\n", DescriptionError, ["bodies[0]", "unknown key 'colour'"]),
    ("name: probe", "name: probe\nauthor: me", DescriptionError, ["unknown key 'author'"]),
    ("coordinates: [psi, theta]\n", "", DescriptionError, ["coordinates", "missing key"]),
    ("mass: m\n", "mass: -2\n", ModelError, ["bodies[0].mass", "non-negative"]),
    ("mass: m\n", "mass: \"__import__('os').system('touch HACKED')\"\n", ExpressionError,
     ["bodies[0].mass", "unknown function '__import__'"]),
    ("uniform_gravity: [0, 0, -g]", "uniform_gravity: [0, -g]", DescriptionError,
     ["force_function.uniform_gravity", "3 expressions"]),
])
def test_bad_entries(tmp_path, old, new, error, fragments):
    assert old in GOOD
    path = write(tmp_path, GOOD.replace(old, new))
    with pytest.raises(error) as info:
        load(path)
    message = str(info.value)
    assert message.startswith(path)
    for fragment in fragments:
        assert fragment in message
    assert not os.path.exists("HACKED")


def test_cycle_in_parents(tmp_path):
    text = GOOD.replace("parent: 0", "parent: arm") + textwrap.indent(textwrap.dedent("""
        - name: arm
          parent: pendulum
          mass: m
        """), "  ")
    with pytest.raises(ModelError, match="the parents form a cycle: "):
        load(write(tmp_path, text))


def test_python_object_tag_is_refused(tmp_path):
    marker = tmp_path / "executed"
    path = write(tmp_path, f"kind: !!python/object/apply:os.system ['touch {marker}']\n")
    with pytest.raises(DescriptionError, match="construct a Python object"):
        load(path)
    assert not marker.exists()


def test_yaml_syntax_error(tmp_path):
    with pytest.raises(DescriptionError, match="not valid YAML"):
        load(write(tmp_path, "kind: [mechanical\n"))


def test_cli_bad_file_exit_status(tmp_path):
    from conftest import run_cli
    path = write(tmp_path, GOOD.replace("parent: 0", "parent: nowhere"))
    run = run_cli(path)
    assert run.returncode == 1
    assert "Traceback" not in run.stderr
    assert "unknown parent body 'nowhere'" in run.stderr

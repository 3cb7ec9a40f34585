"""The ``map`` command checks everything before it computes, reads exact
constants in ``--value`` and ``--at``, names the coordinate of a point that
is not a regular equilibrium and suggests one that works, and prints
decimals in the subtitles of its pictures.

Expected verdicts come from the potential energy of the models (Lagrange-
Dirichlet, and the sign of det W: with det M > 0, det(M l^2 + D l + W) has
a positive real root when det W < 0), not from the code under test."""
import os
import re

import numpy as np
import pytest

import sage_dynsym.description
import sage_dynsym.scale.maps
from sage_dynsym.__main__ import main
from sage_dynsym.description import example_path

CART = example_path('cart_pendulum_spring_damper.yaml')
CART_VALUES = ['--value', 'M=1', '--value', 'm=1/2', '--value', 'l=1', '--value', 'g=9.81']
LADDER = example_path('rlc_ladder.yaml')
LADDER_VALUES = ['--value', 'R3=1', '--value', 'R4=2', '--value', 'L1=1', '--value', 'L2=1',
                 '--value', 'L3=1', '--value', 'C1=1', '--value', 'C2=1', '--value', 'C3=1']

# A pendulum swinging about the x axis (its bob at (0, l sin(theta), -l cos(theta)))
# with gravity along -y: V = m g l sin(theta), minimal at theta = -pi/2 and
# maximal at theta = pi/2; theta = 0 is not an equilibrium.
SIDEWAYS = """\
kind: mechanical
name: sideways pendulum
parameters: [m, l, g]
positive: [m, l, g]
coordinates: [theta]
force_function:
  uniform_gravity: [0, -g, 0]
bodies:
  - name: bob
    parent: 0
    rotations: [[1, theta]]
    mass_center: [0, 0, -l]
    mass: m
    inertia: [[m*l^2, 0, 0], [0, m*l^2, 0], [0, 0, 0]]   # about the pivot
"""


def error_line(capsys):
    err = capsys.readouterr().err
    lines = err.splitlines()
    assert len(lines) == 1 and lines[0].startswith("sage-dynsym: error: "), err
    assert "unexpected" not in err and "Traceback" not in err, err
    return lines[0]


@pytest.fixture
def nothing_computed(monkeypatch):
    r"""The model must not be loaded nor the map computed."""
    def refuse(*args, **kwargs):
        raise AssertionError("computed although the command line was refused")
    monkeypatch.setattr(sage_dynsym.description, 'load', refuse)
    monkeypatch.setattr(sage_dynsym.scale.maps, 'stability_map', refuse)


# -- output files: decided before anything is computed -----------------------------------

def test_existing_outputs_are_refused_before_any_computation(tmp_path, capsys,
                                                            nothing_computed):
    prefix = tmp_path / "ladder"
    for ext in (".png", ".npz"):
        (tmp_path / f"ladder{ext}").write_text("keep me")
    status = main(['map', LADDER, '--param', 'R1=-1:2:3000', '--param', 'R2=-1:2:3000',
                   *LADDER_VALUES, '--numpy', '-o', str(prefix)])
    line = error_line(capsys)
    assert status == 1
    assert (f"-o: {prefix}.png, {prefix}.npz exist already: give --force to replace them, "
            "or another -o PREFIX") in line
    assert all((tmp_path / f"ladder{ext}").read_text() == "keep me" for ext in (".png", ".npz"))


def test_one_existing_output_is_named_in_the_singular(tmp_path, capsys, nothing_computed):
    (tmp_path / "ladder.npz").write_text("keep me")
    status = main(['map', LADDER, '--param', 'R1=-1:2:30', '--param', 'R2=-1:2:30',
                   *LADDER_VALUES, '--numpy', '-o', str(tmp_path / "ladder")])
    assert status == 1
    assert f"{tmp_path / 'ladder'}.npz exists already: give --force to replace it" in \
        error_line(capsys)


@pytest.mark.parametrize("arguments, fragment", [
    # random samples in three parameters are not drawn: only the arrays are written, and
    # only they are checked
    (['--param', 'R1=0:1', '--param', 'R2=0:1', '--param', 'R3=0:1', '--samples', '5'],
     "out.npz exists already"),
    (['--param', 'R1=0:1:3', '--value', 'R2=1/0'], "--value: R2=1/0: expected a real number"),
    (['--param', 'R1=0:1:3', '--at', 'i1=x'], "--at: i1=x: expected a real number"),
    (['--param', 'R1=0:1:3', '--at', 'i1=I'], "--at: i1=I: expected a real number"),
    (['--param', 'R1=0:1:3', '--value', 'R2=-exp(800)'],
     "--value: R2=-exp(800): the value is beyond floating point"),
])
def test_other_refusals_before_any_computation(tmp_path, capsys, nothing_computed, arguments,
                                               fragment):
    (tmp_path / "out.npz").write_text("keep me")
    (tmp_path / "out.png").write_text("keep me")
    force = [] if 'exists' in fragment else ['--force']
    status = main(['map', LADDER, *arguments, '--numpy', '-o', str(tmp_path / "out"), *force])
    assert status == 1 and fragment in error_line(capsys)


def test_a_folder_as_prefix_is_refused(tmp_path, capsys, nothing_computed):
    status = main(['map', LADDER, '--param', 'R1=0:1:3', '--numpy', '-o', str(tmp_path) + "/"])
    assert status == 1 and "names a folder: expected PREFIX" in error_line(capsys)


def test_force_replaces_the_files(tmp_path, capsys):
    prefix = tmp_path / "ladder"
    for ext in (".png", ".npz"):
        (tmp_path / f"ladder{ext}").write_text("old")
    status = main(['map', LADDER, '--param', 'R1=-1:2:5', '--param', 'R2=-1:2:5',
                   *LADDER_VALUES, '--numpy', '-o', str(prefix), '--force'])
    assert status == 0, capsys.readouterr().err
    assert (tmp_path / "ladder.png").read_bytes()[:4] == b"\x89PNG"
    assert np.load(str(prefix) + ".npz")['stable'].shape == (5, 5)
    assert sorted(os.listdir(tmp_path)) == ["ladder.npz", "ladder.png"]    # no temporary left


# -- exact constants in --value and --at -------------------------------------------------

def test_inverted_pendulum_at_exact_pi_is_unstable(tmp_path, capsys):
    # theta = 0 is the hanging pendulum (mass_center [0, 0, -l]), theta = pi the inverted
    # one: V = k y^2/2 - m g l cos(theta), so W = diag(k, -m g l) there, det W < 0
    prefix = str(tmp_path / "inverted")
    status = main(['map', CART, '--param', 'k=0.5:5:9', '--param', 'c=0.1:2:9',
                   *CART_VALUES, '--at', 'theta=pi', '--numpy', '-o', prefix])
    out = capsys.readouterr()
    assert status == 0, out.err
    data = np.load(prefix + ".npz")
    K = data['axis_0'][:, None] * np.ones((1, 9))
    assert (K * (-0.5 * 9.81 * 1) < 0).all()           # det W < 0 at every point
    assert (data['classes'] == 0).all() and (data['max_real_part'] > 0).all()
    assert dict(zip(data['fixed_names'], data['fixed_values']))['g'] == 9.81


def test_a_decimal_near_pi_is_refused_with_the_exact_value_suggested(tmp_path, capsys):
    status = main(['map', CART, '--param', 'k=0.5:5:3', '--param', 'c=0.1:2:3',
                   *CART_VALUES, '--at', 'theta=3.141592653589793', '--numpy',
                   '-o', str(tmp_path / "near")])
    line = error_line(capsys)
    assert status == 1 and not os.listdir(tmp_path)
    assert "the equation of theta does not vanish there" in line
    assert "did you mean theta = pi?" in line and "(--at theta=pi on the command line)" in line


@pytest.mark.parametrize("at, kind", [('-pi/2', 1), ('pi/2', 0), ('-sqrt(2)*sqrt(2)*pi/4', 1)])
def test_exact_points_of_a_sideways_pendulum(tmp_path, capsys, at, kind):
    # V = m g l sin(theta): a minimum at -pi/2 (stable, undamped: class 1), a maximum at
    # pi/2 (unstable: class 0)
    path = tmp_path / "sideways.yaml"
    path.write_text(SIDEWAYS)
    prefix = str(tmp_path / "sideways")
    status = main(['map', str(path), '--param', 'l=0.5:2:4', '--param', 'g=1:10:4',
                   '--value', 'm=1', '--at', f'theta={at}', '--numpy', '-o', prefix])
    assert status == 0, capsys.readouterr().err
    assert (np.load(prefix + ".npz")['classes'] == kind).all()


def test_default_point_that_is_not_an_equilibrium(tmp_path, capsys):
    path = tmp_path / "sideways.yaml"
    path.write_text(SIDEWAYS)
    status = main(['map', str(path), '--param', 'l=0.5:2:4', '--param', 'g=1:10:4',
                   '--value', 'm=1', '--numpy', '-o', str(tmp_path / "s")])
    line = error_line(capsys)
    assert status == 1
    assert ("at: the point {theta: 0} (the default: every coordinate 0) is not an "
            "equilibrium: the equation of theta does not vanish there") in line
    # the suggestion is an equilibrium: cos(pi/2) = 0
    assert "at={'theta': pi/2} (--at theta=pi/2 on the command line)" in line


def test_singular_default_point_names_the_coordinate_and_at(capsys, tmp_path):
    # the spherical pendulum in the angles (psi, theta) of its file: the kinetic matrix
    # diag(m l^2 sin(theta)^2, m l^2) is singular at theta = 0 and pi, its equilibria
    status = main(['map', example_path('spherical_pendulum.yaml'), '--param', 'l=0.5:2:3',
                   '--param', 'g=1:10:3', '--value', 'm=1', '--numpy', '-o',
                   str(tmp_path / "sp")])
    line = error_line(capsys)
    assert status == 1
    assert ("at: the point {psi: 0, theta: 0} (the default: every coordinate 0) is a "
            "singularity of the coordinates at theta = 0") in line
    assert "--at theta=VALUE" in line and "pi" in line


# -- subtitles ----------------------------------------------------------------------------

def test_subtitles_print_decimals():
    from sage.all import QQ, pi
    from sage_dynsym import load
    S = sage_dynsym.scale.maps.stability_map(
        load(CART), {'k': (0.5, 5, 3), 'c': (0.1, 2, 3)},
        fixed={'M': 1, 'm': QQ(1) / 2, 'l': 1.25, 'g': QQ(981) / 100}, client=False)
    G = S.plot()
    title = G.matplotlib(**G._extra_kwds).axes[0].get_title()
    assert "$g = 9.81$" in title and "$m = 0.5$" in title and "$l = 1.25$" in title, title
    assert "$M = 1$" in title and "981" not in title and "frac" not in title, title
    # the point of linearization, where it is not 0, is in the title too
    S = sage_dynsym.scale.maps.stability_map(
        load(CART), {'k': (0.5, 5, 3), 'c': (0.1, 2, 3)}, at={'theta': pi},
        fixed={'M': 1, 'm': QQ(1) / 2, 'l': 1, 'g': QQ(981) / 100}, client=False)
    G = S.plot()
    title = G.matplotlib(**G._extra_kwds).axes[0].get_title()
    assert "stability map at $\\theta = \\pi$" in title, title


# -- the example of the README ------------------------------------------------------------

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def map_commands(text):
    r"""The ``sage-dynsym map`` commands of a Markdown text (inline code, or
    one command of a code block, continuation lines joined), as lists of
    arguments."""
    found = re.findall(r"sage-dynsym map ([^`]*)", text.replace("\\\n", " "))
    return [command.split() for command in found]


def test_map_commands_are_found_inline_and_in_code_blocks():
    text = ("writes a map: `sage-dynsym map examples/a.yaml --param\nR=0:5:400`.\n\n```sh\n"
            "sage-dynsym map examples/b.yaml --param a=0:1:3 \\\n    --value b=1 -o /tmp/b\n```\n")
    assert map_commands(text) == [['examples/a.yaml', '--param', 'R=0:5:400'],
                                  ['examples/b.yaml', '--param', 'a=0:1:3', '--value', 'b=1',
                                   '-o', '/tmp/b']]


def test_readme_map_examples_run_on_shipped_files(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(ROOT)
    with open("README.md", encoding="utf-8") as stream:
        commands = map_commands(stream.read())
    assert commands, "the README shows no sage-dynsym map command"
    for i, arguments in enumerate(commands):
        assert arguments[0].startswith("examples/") and os.path.exists(arguments[0]), \
            f"the README's map example names {arguments[0]}, not a shipped example file"
        if '-o' in arguments:                   # written here instead
            del arguments[arguments.index('-o'):arguments.index('-o') + 2]
        # the same command on a coarser grid
        smaller = [re.sub(r"^(\w+=[^:]+:[^:]+):\d+$", r"\1:11", a) for a in arguments]
        status = main(['map', *smaller, '--numpy', '-o', str(tmp_path / f"readme{i}")])
        out = capsys.readouterr()
        assert status == 0, out.err
        assert "stability map of 11" in out.out

"""
The command lines ``sage-dynsym FILE ...`` and ``sage-dynsym map ...`` on
hostile input: every failure is one line naming the file and the entry or
the option, never "unexpected ...", with the documented exit status (0
reported, 1 refused, 2 malformed command line, 3 a section failed on a
foreign error); the size limits and ``--budget`` hold before anything
large is computed, for the Lie-Poisson sections too.

Most runs call ``main`` in this process (the limits are checked before any
allocation, so nothing here can exhaust the memory of the test process);
two runs go through the interpreter with a time and a memory limit, as a
user would.
"""
import os
import resource
import subprocess
import sys

import pytest

from sage_dynsym.__main__ import main
from sage_dynsym.description import example_path

LADDER = example_path('rlc_ladder.yaml')
VALUES = ['--value', 'R3=1', '--value', 'R4=2', '--value', 'L1=1', '--value', 'L2=1',
          '--value', 'L3=1', '--value', 'C1=1', '--value', 'C2=1', '--value', 'C3=1']
MEGABYTES = 3072

ABELIAN = ("kind: lie_poisson\nname: abelian 30\nvariables: [{names}]\n"
           "algebra: {{poisson_matrix: [{rows}]}}\nhamiltonian: \"{h}\"\n")
POWER = ("kind: lie_poisson\nname: power 200\nalgebra: so3\n"
         "hamiltonian: \"(M1 + 2*M2 + 3*M3)^200\"\n")
PERFECT = """\
kind: circuit
name: perfect coupling
branches:
  - [0, 1, E1]
  - [1, 2, R1]
  - [2, 3, L1]
  - [3, 0, C1]
  - [4, 5, L2]
  - [5, 6, C2]
  - [6, 4, R2]
  - {kind: mutual, between: [L1, L2], value: "sqrt(L1*L2)"}
"""


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    folder = tmp_path_factory.mktemp("cli")
    names = [f"x{k}" for k in range(1, 31)]
    zero = "[" + ", ".join(["0"] * 30) + "]"
    texts = {'abelian': ABELIAN.format(names=", ".join(names), rows=", ".join([zero] * 30),
                                       h=" + ".join(f"{x}^2" for x in names)),
             'power': POWER, 'perfect': PERFECT}
    paths = {}
    for name, text in texts.items():
        paths[name] = str(folder / f"{name}.yaml")
        with open(paths[name], "w") as out:
            out.write(text)
    return paths


def one_line_error(capsys, status, expected, fragment, path=None):
    out = capsys.readouterr()
    assert status == expected, out.err
    lines = out.err.splitlines()
    assert len(lines) == 1 and lines[0].startswith("sage-dynsym: error: "), out.err
    assert "unexpected" not in out.err and "Traceback" not in out.err
    if path is not None:
        assert lines[0].startswith(f"sage-dynsym: error: {path}: "), lines[0]
    assert fragment in lines[0], lines[0]


# -- map --------------------------------------------------------------------------------

MAP_ERRORS = [
    ("output folder", ['--param', 'R1=0:1:3', '--param', 'R2=0:1:3', '-o', 'no_such_dir/out'],
     "-o: the folder no_such_dir does not exist"),
    ("10^5 x 10^5", ['--param', 'R1=0:1:100000', '--param', 'R2=0:1:100000'],
     "--param: 10000000000 points are more than the limit of 10000000; raise it with --max-points"),
    ("huge n", ['--param', 'R1=0:1:10000000000000000000000', '--param', 'R2=0:1:3'],
     "--param: 30000000000000000000000 points are more than the limit of 10000000"),
    ("10^10 samples", ['--param', 'R1=0:1', '--param', 'R2=0:1', '--samples', '10000000000'],
     "--samples: 10000000000 points are more than the limit of 10000000; raise it with --max-points"),
    ("overflowing bounds", ['--param', 'R1=-1e308:1e308:5', '--param', 'R2=0:1:3'],
     "--param[R1]: the range (-1e+308, 1e+308, 5) is too wide for floating point"),
    ("infinite bound", ['--param', 'R1=0:inf:5', '--param', 'R2=0:1:3'],
     "--param[R1]: the bounds must be finite"),
    ("--at names no state", ['--param', 'R1=0:1:3', '--param', 'R2=0:1:3', '--at', 'zz=1'],
     "at: zz is not a state variable of the model; the state variables are i1, i2, i3, u4, u5"),
    ("--value twice", ['--param', 'R1=0:1:3', '--param', 'R2=0:1:3', '--value', 'R3=5'],
     "--value: a value is given twice: R3"),
    ("--at twice", ['--param', 'R1=0:1:3', '--param', 'R2=0:1:3', '--at', 'i1=0', '--at', 'i1=1'],
     "--at: a point is given twice: i1"),
    ("unknown parameter", ['--param', 'X=0:1:3'], "unknown parameter X"),
]


@pytest.mark.parametrize("name, arguments, fragment", MAP_ERRORS, ids=[c[0] for c in MAP_ERRORS])
def test_map_errors_name_the_file_and_the_option(name, arguments, fragment, capsys, tmp_path,
                                                 monkeypatch):
    monkeypatch.chdir(tmp_path)
    status = main(['map', LADDER, *arguments, *VALUES, '--numpy'])
    one_line_error(capsys, status, 1, fragment, LADDER)
    assert os.listdir(tmp_path) == []           # nothing written


@pytest.mark.parametrize("arguments, fragment", [
    (['--seed', '-5'], "argument --seed: expected a non-negative integer, got '-5'"),
    (['--workers', '100000'], "argument --workers: expected an integer from 1 to 256"),
    (['--samples', '2.5'], "argument --samples: expected a positive integer, got '2.5'"),
    (['--max-points', '0'], "argument --max-points: expected a positive integer"),
    (['--param', 'R1=0:1:3.5'], "expected an integer number of points"),
])
def test_map_malformed_command_line(arguments, fragment, capsys):
    with pytest.raises(SystemExit) as stop:
        main(['map', LADDER, '--param', 'R2=0:1:3', *arguments, '--numpy'])
    assert stop.value.code == 2
    err = capsys.readouterr().err
    assert fragment in err and "Traceback" not in err


def test_map_with_raised_limit_and_huge_but_finite_bounds(capsys, tmp_path):
    prefix = str(tmp_path / "m")
    status = main(['map', LADDER, '--param', 'R1=-1e200:1e200:5', '--param', 'R2=0:1:3',
                   *VALUES, '--numpy', '--max-points', '15', '-o', prefix])
    out = capsys.readouterr()
    assert status == 0 and out.err == "", out.err
    assert "stability map of 5 x 3 points" in out.out
    assert os.path.exists(prefix + ".npz") and os.path.exists(prefix + ".png")


# -- reports ---------------------------------------------------------------------------

def test_budget_bounds_the_lie_poisson_sections(files, capsys):
    status = main([files['abelian'], files['power']])
    out = capsys.readouterr()
    assert status == 0, out.err
    text = out.out
    assert ("Casimirs (polynomial, degree <= 4): skipped, the Casimirs of degree <= 4 "
            "(monomials times the terms of J): about 1.39e+06 polynomial terms, over the budget "
            "of 100000 (raise it with --budget)") in text
    assert "Stationary motions (Routh-Lyapunov over H, the Casimirs): skipped" in text
    # (M1 + 2 M2 + 3 M3)^199 has C(201, 2) = 20100 monomials: 6 brackets of them
    assert ("Lie-Poisson equations dx/dt = {x, H}: skipped, the Lie-Poisson equations (terms of "
            "J_ij times those of dH/dx_j): about 1.21e+05 polynomial terms") in text
    assert "section failed" not in text


def test_a_section_that_is_not_available_says_why(files, capsys):
    status = main([files['perfect'], '--sections', 'lyapunov'])
    out = capsys.readouterr()
    assert status == 0, out.err
    assert ("dP/dt: not available (dP/dt needs the inverse of the inductance matrix, which is "
            "singular: some windings are perfectly coupled") in out.out


def test_a_failed_section_gives_exit_status_3(files, capsys, monkeypatch):
    import sage_dynsym.mechanics.report as R

    def broken(*args):
        raise ZeroDivisionError("division by zero")
    monkeypatch.setattr(R, "hamiltonian_lines", broken)
    status = main([example_path('spherical_pendulum.yaml'), '--sections', 'hamiltonian'])
    out = capsys.readouterr()
    assert status == 3
    assert "Hamiltonian: section failed: ZeroDivisionError: division by zero" in out.out


def test_report_output_errors_before_any_report(capsys, tmp_path):
    status = main([example_path('spherical_pendulum.yaml'), '-o', '/no/such/dir/out.txt'])
    one_line_error(capsys, status, 1, "-o: the folder /no/such/dir does not exist")
    status = main([example_path('spherical_pendulum.yaml'), '-o', str(tmp_path)])
    one_line_error(capsys, status, 1, f"-o: {tmp_path} is a folder, not a file")


# -- through the interpreter, with limits -----------------------------------------------

def _limits():
    limit = MEGABYTES * 2**20
    resource.setrlimit(resource.RLIMIT_AS, (limit, limit))


def _run(*args):
    return subprocess.run([sys.executable, "-m", "sage_dynsym", *args], capture_output=True,
                          text=True, timeout=240, preexec_fn=_limits)


@pytest.mark.slow
def test_report_processes_with_limits(files):
    run = _run("--time-limit", "60", files['abelian'], files['power'], files['perfect'],
               "/no/such/file.yaml")
    assert run.returncode == 1, run.stderr
    assert run.stderr == ("sage-dynsym: error: /no/such/file.yaml: cannot read the file: No such "
                          "file or directory\n")
    assert "Traceback" not in run.stdout and "section failed" not in run.stdout
    assert run.stdout.count("\n== ") + run.stdout.startswith("== ") == 3


def test_map_process_with_limits(tmp_path):
    run = _run("map", LADDER, "--param", "R1=0:1:100000", "--param", "R2=0:1:100000", *VALUES,
               "--numpy", "-o", str(tmp_path / "out"))
    assert run.returncode == 1 and run.stdout == ""
    assert run.stderr == (f"sage-dynsym: error: {LADDER}: --param: 10000000000 points are more "
                          "than the limit of 10000000; raise it with --max-points if that is "
                          "what you want\n")

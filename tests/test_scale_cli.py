"""The command line `sage-dynsym map FILE --param NAME=LOW:HIGH:N ...`: the
written map against hand-derived conditions, errors as one line, and the
report command line `sage-dynsym FILE ...` unchanged."""
import os
import subprocess
import sys

import numpy as np
import pytest

from sage_dynsym.__main__ import main
from scale_helpers import example_path

LADDER = example_path('rlc_ladder.yaml')
LADDER_VALUES = ['--value', 'R3=1', '--value', 'R4=2', '--value', 'L1=1', '--value', 'L2=0.5',
                 '--value', 'L3=1', '--value', 'C1=1', '--value', 'C2=2', '--value', 'C3=1']

OSCILLATOR = """\
kind: mechanical
name: damped oscillator
parameters: [m, k, c]
coordinates: [x]
force_function:
  expression: -k*x^2/2
dissipation: c*dx^2/2
bodies:
  - name: slider
    joint: [x, 0, 0]
    mass: m
"""


def test_mechanical_model_against_hand_conditions(tmp_path, capsys):
    path = tmp_path / "oscillator.yaml"
    path.write_text(OSCILLATOR)
    prefix = str(tmp_path / "osc")
    status = main(['map', str(path), '--param', 'c=-1:2:31', '--param', 'k=-1:2:31',
                   '--value', 'm=2', '--at', 'x=0', '--numpy', '-o', prefix])
    out = capsys.readouterr().out
    assert status == 0
    assert "damped oscillator: stability map of 31 x 31 points in (c, k)" in out
    assert "Lienard-Chipart conditions: agree at 100.0% of the points" in out
    assert os.path.getsize(prefix + ".png") > 1000
    data = np.load(prefix + ".npz")
    C, K = np.meshgrid(data['axis_0'], data['axis_1'], indexing='ij')
    # m x'' + c x' + k x = 0, m > 0: stable iff c > 0 and k > 0; away from the
    # lines c = 0 and k = 0 (one grid step) the map must say so
    exact = (C > 0) & (K > 0)
    away = np.minimum(np.abs(C), np.abs(K)) > 0.1 + 1e-12
    assert (data['stable'] == exact)[away].all()
    assert list(data['parameters']) == ['c', 'k'] and list(data['fixed_names']) == ['m']


def test_circuit_map_matches_the_api(tmp_path, capsys):
    from sage_dynsym import load
    from sage_dynsym.scale import stability_map
    prefix = str(tmp_path / "ladder")
    status = main(['map', LADDER, '--param', 'R1=-1:2:21', '--param', 'R2=-1:2:21',
                   *LADDER_VALUES, '--numpy', '-o', prefix])
    out = capsys.readouterr().out
    assert status == 0 and "RLC ladder with three sections: stability map" in out
    assert f"wrote {prefix}.png, {prefix}.npz" in out
    values = dict(v.split('=') for v in LADDER_VALUES[1::2])
    S = stability_map(load(LADDER), {'R1': (-1, 2, 21), 'R2': (-1, 2, 21)},
                      fixed={k: float(v) for k, v in values.items()}, client=False)
    data = np.load(prefix + ".npz")
    assert np.array_equal(data['max_real_part'], S.max_real_part())
    assert np.array_equal(data['stable'], S.stable())


def test_random_samples_and_one_parameter(tmp_path, capsys):
    prefix = str(tmp_path / "samples")
    assert main(['map', LADDER, '--param', 'R1=-1:2', '--param', 'R2=-1:2', *LADDER_VALUES,
                 '--samples', '500', '--seed', '3', '--numpy', '-o', prefix]) == 0
    assert "500 random points" in capsys.readouterr().out
    assert np.load(prefix + ".npz")['stable'].shape == (500,)
    prefix = str(tmp_path / "line")
    assert main(['map', LADDER, '--param', 'R1=-1:2:50', '--value', 'R2=1', *LADDER_VALUES,
                 '--numpy', '--method', 'eigvals', '-o', prefix]) == 0
    assert "(method: eigvals)" in capsys.readouterr().out
    assert os.path.exists(prefix + ".png")


@pytest.mark.parametrize("arguments, message", [
    (['--param', 'X=0:1:3'], "unknown parameter X: the symbols of the system are C1, C2"),
    (['--param', 'R1=0:1:3'], "no value for C1, C2, C3, L1, L2, L3, R2, R3, R4: give them"),
    (['--param', 'R1=0:1:0'], r"--param\[R1\]: empty range"),
    (['--param', 'R1=1:0:3'], r"--param\[R1\]: empty range"),
    (['--param', 'R1=0:1'], r"--param\[R1\]: expected \(low, high, n\)"),
    (['--param', 'R1=0:1:3', '--param', 'R1=0:2:3'], "--param: a parameter is given twice"),
])
def test_errors_are_one_line(arguments, message, capsys):
    assert main(['map', LADDER, *arguments, '--numpy']) == 1
    err = capsys.readouterr().err
    assert err.startswith("sage-dynsym: error: ") and err.count("\n") == 1
    import re
    assert re.search(message, err)


@pytest.mark.parametrize("arguments", [['--param', 'R1'], ['--param', 'R1=a:1:3'],
                                       ['--numpy', '--scheduler', 'tcp://127.0.0.1:1']])
def test_usage_errors(arguments):
    with pytest.raises(SystemExit) as exit:
        main(['map', LADDER, *arguments])
    assert exit.value.code == 2


def test_scheduler_that_does_not_answer(capsys):
    import socket
    with socket.socket() as s:
        s.bind(('127.0.0.1', 0))
        port = s.getsockname()[1]
    status = main(['map', LADDER, '--param', 'R1=0:1:3', '--param', 'R2=0:1:3',
                   *LADDER_VALUES, '--scheduler', f'tcp://127.0.0.1:{port}', '--timeout', '1'])
    assert status == 1
    assert f"no Dask scheduler answers at tcp://127.0.0.1:{port} within 1 s" in \
        capsys.readouterr().err


def test_report_command_line_unchanged(capsys):
    assert main([LADDER, '--sections', 'lagrangian']) == 0
    assert "Lagrangian (loop-current method):" in capsys.readouterr().out


@pytest.mark.slow       # starts a local cluster; `make test-slow` (CI)
def test_console_with_a_local_cluster(tmp_path):
    prefix = str(tmp_path / "cluster")
    run = subprocess.run([sys.executable, '-m', 'sage_dynsym', 'map', LADDER,
                          '--param', 'R1=-1:2:30', '--param', 'R2=-1:2:30', *LADDER_VALUES,
                          '--workers', '1', '-o', prefix],
                         capture_output=True, text=True, timeout=300, cwd=str(tmp_path))
    assert run.returncode == 0, run.stderr
    assert "stability map of 30 x 30 points" in run.stdout
    assert np.load(prefix + ".npz")['stable'].shape == (30, 30)

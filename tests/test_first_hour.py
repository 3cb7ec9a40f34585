"""What a new user meets in the first hour: the command line answers
``--help`` and argument errors without loading Sage, pictures say what they
show, the map command does not overwrite files, labels are not cut, the
report does not repeat itself. Expected values come from closed forms
(the harmonic oscillator, the Liénard-Chipart conditions of
lambda^2 + c lambda + k) or from the definitions of the labels."""
import json
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from sage.all import var

ROOT = Path(__file__).resolve().parent.parent


def python(code):
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          timeout=300, cwd=ROOT)


@pytest.mark.parametrize("argv", [["--help"], ["map", "--help"], ["map"],
                                  ["--budget", "zero", "x.yaml"]])
def test_cli_answers_without_loading_sage(argv):
    run = python("import sys\nfrom sage_dynsym.__main__ import main\n"
                 f"try:\n    main({argv!r})\nexcept SystemExit:\n    pass\n"
                 "print('LOADED', 'sage.all' in sys.modules)")
    assert run.stdout.strip().endswith("LOADED False"), run.stdout + run.stderr


def test_map_help_has_an_example_on_a_bundled_file():
    from sage_dynsym.scale.cli import parser, EXAMPLE
    assert EXAMPLE in parser().format_help()
    bundled = EXAMPLE.split("sage-dynsym map ")[1].split()[0]
    assert (ROOT / bundled).exists()
    assert "roots of the compiled characteristic polynomial" in parser().format_help()


def ladder_arguments(prefix):
    return ["examples/rlc_ladder.yaml", "--param", "R1=-1:2:11", "--param", "R2=-1:2:11",
            "--value", "R3=1", "--value", "R4=2", "--value", "L1=1", "--value", "L2=1",
            "--value", "L3=1", "--value", "C1=1", "--value", "C2=1", "--value", "C3=1",
            "--numpy", "-o", str(prefix)]


def test_map_refuses_to_overwrite_without_force(tmp_path, capsys, monkeypatch):
    from sage_dynsym.scale.cli import main
    monkeypatch.chdir(ROOT)
    prefix = tmp_path / "ladder"
    (tmp_path / "ladder.png").write_text("keep me")
    assert main(ladder_arguments(prefix)) == 1
    err = capsys.readouterr().err
    assert "exists already" in err and "--force" in err
    assert (tmp_path / "ladder.png").read_text() == "keep me"
    assert main(ladder_arguments(prefix) + ["--force"]) == 0
    assert (tmp_path / "ladder.png").read_bytes()[:4] == b"\x89PNG"


def test_map_names_the_option_of_a_missing_value(capsys, monkeypatch, tmp_path):
    from sage_dynsym.scale.cli import main
    monkeypatch.chdir(ROOT)
    arguments = ladder_arguments(tmp_path / "x")
    del arguments[arguments.index("C3=1") - 1:arguments.index("C3=1") + 1]
    assert main(arguments) == 1
    assert "--value" in capsys.readouterr().err


def oscillator():
    from sage_dynsym import Lagrangian
    x, dx = var('x dx')
    return Lagrangian(dx ** 2 / 2 - x ** 2 / 2, [x]), x, dx


def test_trajectory_pictures_say_what_they_show():
    L, x, dx = oscillator()
    T = L.simulate({}, {x: 1, dx: 0}, 10, points=11)
    G = T.plot(x)
    assert G.axes_labels() == ('$t$', '$x$') and 'trajectory' in G._extra_kwds['title']
    P = T.phase_portrait(x, dx)
    assert P.axes_labels() == ('$x$', r'${\dot{x}}$') and P._extra_kwds['title']
    assert isinstance(T.values(x), np.ndarray) and isinstance(T.times(), np.ndarray)


def test_phase_portrait_is_smooth_between_samples():
    # 11 samples of a period-2 pi circle: straight chords would cut it by up to
    # 1 - cos(pi/10) ~ 5%; the curve drawn follows x = cos t, dx = -sin t
    L, x, dx = oscillator()
    T = L.simulate({}, {x: 1, dx: 0}, 2 * math.pi, points=11)
    curve = T.phase_portrait(x, dx)[0]
    xs, ys = np.array(curve.xdata), np.array(curve.ydata)
    assert len(xs) >= 200
    assert np.max(np.abs(np.hypot(xs, ys) - 1)) < 1e-8


def test_stability_map_picture_has_legend_and_title():
    from sage_dynsym import linearize, stability_map
    x, y, m, c, k = var('x y m c k')
    osc = linearize([y, -(c * y + k * x) / m], {x: 0, y: 0}, [x, y])
    S = stability_map(osc, {c: (-1, 2, 31), k: (-1, 2, 31)}, fixed={m: 1}, client=False)
    G = S.plot([c > 0, k > 0])
    labels = {p.options().get('legend_label') for p in G} - {None}
    assert {'asymptotically stable', 'unstable', 'exact boundary'} <= labels
    assert '$m = 1$' in G._extra_kwds['title']
    # conditions that hold in the whole box have no boundary to draw
    H = S.plot([c > -5])
    assert 'exact boundary' not in {p.options().get('legend_label') for p in H}


def test_report_names_its_method_once_and_families_as_families():
    from sage_dynsym import load
    from sage_dynsym.report import report
    text = report(load(ROOT / "examples/spherical_pendulum.yaml"))
    stability = [line for line in text.splitlines() if "stability:" in line]
    assert stability and all(line.count("Routh-Lyapunov") <= 1 for line in stability)
    # p_psi as a function of theta: a family of conical motions, not isolated
    conical = [line for line in text.splitlines() if "p_psi =" in line]
    assert conical and all("family over theta" in line for line in conical)


def test_stability_explorer_labels_are_not_cut():
    pytest.importorskip("ipywidgets")
    from sage_dynsym.interact.stability import StabilityStudy
    x, y, k, c = var('x y k c')
    St = StabilityStudy([y, -k * x - c * y], [x, y], {x: 0, y: 0})
    w = St.explorer({'k': (-1, 2, 1), 'c': (-1, 2, 0.5)})
    assert all(c.style.description_width == 'initial' for c in w.kwargs_widgets)


def test_worksheets_print_lam_as_lambda():
    for path in sorted((ROOT / "worksheets").glob("*.ipynb")):
        for cell in json.loads(path.read_text())["cells"]:
            source = "".join(cell["source"])
            if "var('lam'" in source:
                assert "latex_name=r'\\lambda'" in source, path.name

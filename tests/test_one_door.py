"""One public door per room: stationary solutions and linear systems.

- ``stationary_solutions`` is the one way to ask for stationary solutions:
  of first integrals, of a Routh function or Lagrangian (what the
  contract's ``stationary_motions`` delegates to), of a written-out
  ``StationaryProblem`` (what the deprecated ``solve_stationary`` did);
- ``linearize`` is the one way to build a linear system from a model:
  ``linearize(model, at, sources=False)`` is the model's free linear system
  (the deprecated ``model_linear_system`` delegates to it).

Expected values come from the textbook formulas written here: a particle on
a smooth cone (circular orbits, `p^2 = m^2 g r^3 \\cot\\alpha`, from the
balance of the centrifugal term `p^2/(m r^3)` and gravity along the cone)
and the series RLC circuit (`L C \\lambda^2 + R C \\lambda + 1`, Kirchhoff's
voltage law).
"""
import warnings

import pytest
from sage.all import SR, cot, sin, var

from sage_dynsym import Circuit, Lagrangian, linearize, stationary_motions, stationary_solutions


def _cone():
    r, phi, dr, dphi, m, g, al = var('r phi dr dphi m g alpha')
    # z = r cot(alpha) on the cone: v^2 = dr^2/sin(alpha)^2 + r^2 dphi^2
    L = Lagrangian(m / 2 * (dr**2 / sin(al)**2 + r**2 * dphi**2) - m * g * r * cot(al),
                   [r, phi])
    return L, (r, m, g, al)


def test_stationary_motions_delegate_to_the_door():
    L, (r, m, g, al) = _cone()
    R = L.routh([L.coordinates()[1]])
    p = R.momenta()[0]
    by_door = stationary_solutions(R, solve_for=[p], positive=[m, g, r])
    by_name = stationary_motions(R, solve_for=[p], positive=[m, g, r])
    expected = m**2 * g * r**3 * cot(al)
    for sols in (by_door, by_name):
        values = [s.point()[p] for s in sols]
        assert len(values) == 2
        assert all(bool((v**2 - expected).simplify_full() == 0) for v in values)
    assert [s.point() for s in by_door] == [s.point() for s in by_name]
    assert by_door.equations() == by_name.equations()


def test_the_door_refuses_integral_arguments_with_a_routh_function():
    L, (r, m, g, al) = _cone()
    from sage_dynsym.errors import AnalysisError
    with pytest.raises(AnalysisError, match="solve_for= and positive= only"):
        stationary_solutions(L.routh([L.coordinates()[1]]), [r])
    with pytest.raises(AnalysisError, match="phase variables are needed"):
        stationary_solutions([r**2])


def test_solve_stationary_is_deprecated_and_delegates():
    from sage_dynsym.analysis.stationary import StationaryProblem, solve_stationary
    x, a = var('x a')
    problem = StationaryProblem(x**3 / 3 - a * x, [x], [x], [], [x**2 - a], positive=[a])
    with pytest.warns(DeprecationWarning, match="stationary_solutions"):
        old = solve_stationary(problem)
    new = stationary_solutions(problem)
    # the critical points of x^3/3 - a x: x^2 = a
    assert sorted(str(s.point()[x]) for s in new) == ["-sqrt(a)", "sqrt(a)"]
    assert [s.point() for s in old] == [s.point() for s in new]


def _rlc():
    return Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1']])


def test_linearize_switches_the_sources_off():
    lam = SR.var('lam')
    R1, L1, C1 = var('R1 L1 C1')
    S = linearize(_rlc(), sources=False)
    p = S.characteristic_polynomial(lam)
    expected = L1 * C1 * lam**2 + R1 * C1 * lam + 1
    assert bool((p / p.coefficient(lam, 0) - expected).expand() == 0)
    # the contract's model method is the same system
    F = _rlc().free_linear_system()
    assert (S.jacobian(), S.lhs_matrix()) == (F.jacobian(), F.lhs_matrix())


def test_model_linear_system_is_deprecated_and_delegates():
    from sage_dynsym.scale.maps import model_linear_system
    with pytest.warns(DeprecationWarning, match=r"linearize\(model, at, sources=False\)"):
        old = model_linear_system(_rlc())
    new = linearize(_rlc(), sources=False)
    assert (old.jacobian(), old.lhs_matrix()) == (new.jacobian(), new.lhs_matrix())


def test_the_doors_themselves_do_not_warn():
    L, (r, m, g, al) = _cone()
    with warnings.catch_warnings():
        warnings.simplefilter("error", DeprecationWarning)
        linearize(_rlc(), sources=False)
        stationary_motions(L.routh([L.coordinates()[1]]), solve_for=None, positive=[m, g])


def _counting_parse_points(monkeypatch):
    # every call of parse_points, wherever it is imported from
    import sage_dynsym.scale.maps as maps
    import sage_dynsym.scale.points as points
    calls, real = [], points.parse_points

    def counting(*args, **kwargs):
        calls.append(args)
        return real(*args, **kwargs)
    monkeypatch.setattr(maps, "parse_points", counting)
    monkeypatch.setattr(points, "parse_points", counting)
    return calls


def test_a_map_parses_its_points_once(monkeypatch):
    from sage_dynsym.scale import stability_map
    calls = _counting_parse_points(monkeypatch)
    C = Circuit([[0, 1, 'E1'], [1, 2, 'R1'], [2, 3, 'L1'], [3, 0, 'C1']],
                positive=['R1', 'L1', 'C1'])
    S = stability_map(C, {'R1': (1, 2, 3)}, fixed={'L1': 1, 'C1': 1}, client=False)
    assert len(calls) == 1
    # L C lam^2 + R C lam + 1 with positive coefficients: Hurwitz, every point stable
    assert S.stable().all() and S.stable().shape == (3,)


def test_the_command_line_parses_the_points_once(monkeypatch, tmp_path, capsys):
    from sage_dynsym.__main__ import main
    calls = _counting_parse_points(monkeypatch)
    path = tmp_path / "rlc.yaml"
    path.write_text("kind: circuit\nname: RLC\nbranches:\n  - [0, 1, E1]\n  - [1, 2, R1]\n"
                    "  - [2, 3, L1]\n  - [3, 0, C1]\n", encoding="utf-8")
    status = main(['map', str(path), '--param', 'R1=1:2:3', '--value', 'L1=1', '--value',
                   'C1=1', '--numpy', '-o', str(tmp_path / "m")])
    assert status == 0, capsys.readouterr().err
    assert len(calls) == 1

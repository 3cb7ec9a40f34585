"""Ignorable coordinates in the stability service: the upright rolling
disk is stable in first approximation exactly where W^2 > g/(3 r) (uniform
disk; Routh, Advanced Rigid Dynamics, art. 244; K. T. McDonald, The
rolling motion of a disk on a horizontal plane, 2000), unstable below,
with its heading left out; the RLC ladder's free circuit is
asymptotically stable for positive element values, checked against numpy
eigenvalues of its state matrix."""
import random

import numpy as np
import pytest
from sage.all import SR, QQ, var

from sage_dynsym import load
from sage_dynsym.analysis.linear import linearize
from sage_dynsym.description import example_path
from test_nonholonomic import DISK, system


def eigenvalues(A, point):
    return np.linalg.eigvals(np.array([[complex(SR(x).subs(point)) for x in row]
                                       for row in A.rows()]))


@pytest.fixture(scope='module')
def uniform_disk():
    m, r, A, C = var('m r A C')
    S = system(DISK).subs({A: m * r ** 2 / 4, C: m * r ** 2 / 2})
    return linearize(S, S.operating_point('upright'))


def test_rolling_disk_threshold(uniform_disk):
    m, r, g, W = var('m r g W')
    v = uniform_disk.stability(positive=[m, r, g])
    assert [str(x) for x in uniform_disk.variables()] == ['theta', 'psi']
    assert 'psi' in v.reason() or all('rates of psi' in c.reason() for c in v.cases())
    rng = random.Random(1)
    for _ in range(12):
        point = {m: QQ(rng.randint(1, 30)) / 10, r: QQ(rng.randint(1, 30)) / 10,
                 g: QQ(981) / 100}
        critical = float((point[g] / (3 * point[r])) ** 0.5)
        for factor, expected in ((QQ(11) / 10, 'stable in first approximation'),
                                 (QQ(9) / 10, 'unstable')):
            spin = QQ(round(critical * 1000)) / 1000 * factor
            assert v.at({**point, W: spin}) == expected
            # numpy: the tilt's roots on the imaginary axis, or one to the right
            roots = eigenvalues(uniform_disk.jacobian(), {**point, W: spin})
            assert (max(roots.real) > 1e-6) == (expected == 'unstable')
    # the critical spins, positive and negative (W has no declared sign)
    crit = v.critical_values(W, values={m: 1, r: QQ(1) / 2, g: QQ(981) / 100})
    assert [float(c) for c in crit] == pytest.approx([-(9.81 / 1.5) ** 0.5, (9.81 / 1.5) ** 0.5])


def test_rolling_disk_with_the_heading_is_undecided_only_when_asked(uniform_disk):
    m, r, g, W, psi, theta = var('m r g W psi theta')
    v = uniform_disk.stability(positive=[m, r, g], with_respect_to=[theta, psi])
    # the heading drifts: a double zero root with one eigenvector
    assert 'undecided' in [c.verdict() for c in v.cases()]


def test_rlc_ladder_free_circuit_is_asymptotically_stable():
    C = load(example_path('rlc_ladder.yaml'))
    linear = C.free_linear_system()
    values = sorted({s for x in linear.jacobian().list() for s in SR(x).variables()}, key=str)
    v = linear.stability(positive=values)
    assert v.verdict() == 'asymptotically stable'
    rng = random.Random(2)
    for _ in range(10):
        point = {s: QQ(rng.randint(1, 50)) / 10 for s in values}
        assert max(eigenvalues(linear.jacobian(), point).real) < 0


def test_rlc_ladder_report_and_map_agree():
    # the report's verdict (the service) and the map's numerical classes
    # (eigenvalues of the same free state equations) over a grid of R1
    import numpy as np
    from sage_dynsym import stability_map
    from sage_dynsym.report import report
    C = load(example_path('rlc_ladder.yaml'))
    text = report(C)
    section = text[text.index("Stability of the free circuit"):]
    assert "stability: asymptotically stable" in section.splitlines()[-1] or \
        any(line.startswith("  stability: asymptotically stable") for line in section.splitlines())
    fixed = {var(n): 1 for n in ('C1', 'C2', 'C3', 'L1', 'L2', 'L3', 'R2', 'R3', 'R4')}
    smap = stability_map(C, {var('R1'): (QQ(1) / 10, 5, 11)}, fixed=fixed)
    assert np.all(smap.stable())


def test_rolling_hoop_threshold():
    # a thin hoop (A = m r^2/2, C = m r^2) rolls upright stably iff
    # C (C + m r^2) W^2 > m g r A, i.e. W^2 > g/(4 r) (Routh, art. 244;
    # the uniform disk's g/(3 r) with the hoop's moments of inertia)
    m, r, A, C, g, W = var('m r A C g W')
    S = system(DISK).subs({A: m * r ** 2 / 2, C: m * r ** 2})
    hoop = linearize(S, S.operating_point('upright'))
    v = hoop.stability(positive=[m, r, g])
    for case in v.cases():
        for alt in case.region():
            for rel in alt:
                assert bool(((rel.lhs() - rel.rhs()) / (4 * r * W ** 2 - g))
                            .simplify_full().is_constant()), rel
    assert v.at({m: 1, r: 1, g: 4, W: QQ(11) / 10}) == 'stable in first approximation'
    assert v.at({m: 1, r: 1, g: 4, W: QQ(9) / 10}) == 'unstable'


def test_rolling_disk_report_asks_the_service():
    # the report's verdict of the operating point: the heading left out,
    # the threshold C (C + m r^2) W^2 > m g r A (Routh, art. 244)
    from sage_dynsym.report import report
    text = report(system(dict(DISK, positive=['m', 'r', 'A', 'C', 'g'])),
                  sections=['stationary'])
    lines = [line for line in text.splitlines() if 'first approximation) where' in line]
    assert len(lines) == 2
    stable = next(line for line in lines if 'stable in first approximation (' in line)
    m, r, A, C, g, W = var('m r A C g W')
    region = SR(stable.split('where [')[1].split(' > 0]')[0])
    assert bool((region / (C * (C + m * r ** 2) * W ** 2 - m * g * r * A)).simplify_full()
                .is_constant())
    assert 'rates of psi' in stable

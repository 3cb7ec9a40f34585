"""
The census of equilibria (sage_dynsym.analysis.census, .charts) against
independent computations.

- Charts: the critical points of a function on SO(3) counted as
  orientations, against a direct numerical search on the rotation group
  (SciPy root finding on the torque, from many random starts, in rotation
  vectors: no Euler angles).
- The gyrostat satellite on a circular orbit (gravity-gradient torque,
  rotor along the third principal axis with gyrostatic moment h). Its
  amended potential is written here from the physics, in direction
  cosines: with gamma and n the radial and orbit-normal unit vectors in
  body axes, I_s the carrier's inertia and I = I_s + diag(0, 0, J),

      W = 3/2 w0^2 gamma.I gamma - 1/2 w0^2 n.I_s n - h w0 n_3,

  whose torque for a body rotation eps is
  3 w0^2 (I gamma) x gamma - w0^2 (I_s n) x n - h w0 e_3 x n.
  At h = 0: 24 equilibrium orientations, 4 stable (Beletsky; Sarychev);
  for h along a principal axis: between 8 and 24 equilibria, the stable
  ones from 4 to 2 (Gutnik and Sarychev).
"""
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import brentq

from sage.all import SR, QQ, var, cos, sin
from sage_dynsym import Lagrangian
from sage_dynsym.analysis.charts import configuration_points
from sage_dynsym.analysis.census import equilibria_at, equilibrium_census
from sage_dynsym.analysis.stationary import stationary_solutions, stationary_motions
from sage_dynsym.mechanics.charts import euler_angles

sys.path.insert(0, str(Path(__file__).resolve().parent))
from gyrostat import VALUES, INERTIA, critical_orientations, gyrostat, gyrostat_torque  # noqa: E402


@pytest.fixture(scope='module')
def models():
    first = gyrostat([(3, 'alpha'), (1, 'beta'), (2, 'gamma')])
    second = gyrostat([(3, 'alpha'), (2, 'beta'), (1, 'gamma')])
    return first, second


# -- charts ---------------------------------------------------------------------------

def linear_torque(M):
    """The torque of W(R) = tr(M^T R) on the body turned to ``R``: dW along
    R exp(eps^) is tr(M^T R eps^), so the torque is vee(R^T M - M^T R)."""
    def torque(R):
        S = R.T @ M - M.T @ R
        return np.array([S[2, 1], S[0, 2], S[1, 0]])
    return torque


def test_linear_function_on_so3_has_four_critical_orientations():
    a, b, c = var('a b c')
    chart = euler_angles([(3, a), (1, b), (2, c)])
    exact = [[1, 0, 0], [0, 2, 0], [0, QQ(1) / 3, 3]]
    M = np.array(exact, dtype=float)
    R = chart.rotation_matrix()
    W = sum(exact[i][j] * R[i, j] for i in range(3) for j in range(3))
    points = configuration_points(stationary_solutions([W], [a, b, c]), chart)
    found, _ = critical_orientations(linear_torque(M), starts=100)
    assert len(points) == len(found) == 4
    numeric = sorted(tuple(np.round(np.array([float(x) for x in p.embedding()]), 8)) for p in points)
    direct = sorted(tuple(np.round(Rn.flatten(), 8)) for Rn in found)
    assert np.allclose(numeric, direct, atol=1e-7)


@pytest.mark.slow
@pytest.mark.parametrize('h', [0, QQ(1) / 10])
def test_gyrostat_equilibria_are_orientations(models, h):
    (R1, chart1), (R2, chart2) = models
    p = R1.momenta()[0]
    values = {**VALUES, p: h}
    found = equilibria_at(R1, values, chart1, regular=(R2, chart2))
    verdicts = [v for _, v in found]
    n, stable, undecided = len(verdicts), verdicts.count('stable'), verdicts.count('undecided')
    direct, minima = critical_orientations(gyrostat_torque(*INERTIA, float(h)))
    assert (n, stable, undecided) == (len(direct), minima, 0)
    if h == 0:
        assert (n, stable) == (24, 4)      # Beletsky; Sarychev


# -- listings of stationary solutions in a chart -------------------------------------

def rotation(chart, point, values=None):
    point = {q: SR(v).subs(values or {}) for q, v in point.items()}
    # the embedding of Euler angles is the rotation matrix, row by row
    return np.array([float(SR(x).subs(point)) for x in chart.embedding()[:9]]).reshape(3, 3)


def test_listing_in_a_chart_with_a_symbolic_parameter():
    # W = tr(M^T R), M depending on k: the listing compares the images
    # symbolically; at k = 1/3 its points are the numerical critical points
    a, b, c, k = var('a b c k')
    chart = euler_angles([(3, a), (1, b), (2, c)])
    R = chart.rotation_matrix()
    W = R[0, 0] + 2 * R[1, 1] + 3 * R[2, 2] + k * R[2, 1]
    sols = stationary_solutions([W], [a, b, c], chart=chart)
    M = np.array([[1, 0, 0], [0, 2, 0], [0, 1 / 3, 3]])
    torque = linear_torque(M)
    found, _ = critical_orientations(torque, starts=100)
    listed = [rotation(chart, s.point(), {k: QQ(1) / 3}) for s in sols]
    assert len(sols.chart_solutions()) == 16 and len(listed) == len(found) == 4
    assert all(sum(np.allclose(L, F, atol=1e-8) for F in found) == 1 for L in listed)
    # the solutions left out are on the singular set (cos b = 0) and not critical
    for s in sols.chart_artifacts():
        Rn = rotation(chart, s.point(), {k: QQ(1) / 3})
        assert abs(Rn[2, 1]) == pytest.approx(1) and np.linalg.norm(torque(Rn)) > 1e-3


@pytest.mark.slow
@pytest.mark.parametrize('h', [0, QQ(1) / 10])
def test_gyrostat_listing_is_orientations(models, h):
    (R1, chart1), (R2, chart2) = models
    values = {**VALUES, R1.momenta()[0]: h}
    sols = stationary_motions(R1.subs(values), chart=chart1,
                              regular=stationary_motions(R2.subs(values), chart=chart2))
    torque = gyrostat_torque(*INERTIA, float(h))
    direct, minima = critical_orientations(torque)
    listed = [rotation(chart1, s.point()) for s in sols]
    # each orientation once, every one an equilibrium, none missing
    assert len(listed) == len(direct) == 24                   # Beletsky; Sarychev
    assert all(sum(np.allclose(L, D, atol=1e-7) for D in direct) == 1 for L in listed)
    # what the chart adds at beta = +-pi/2 (h != 0) is not an equilibrium
    for s in sols.chart_artifacts():
        Rn = rotation(chart1, s.point())
        assert abs(Rn[2, 1]) == pytest.approx(1) and np.linalg.norm(torque(Rn)) > 1e-3
    assert len(sols.chart_artifacts()) == (16 if h else 0)
    # Routh: the minima of the amended potential on SO(3) are the stable ones
    assert sum(1 for s in sols if s.stability().verdict() == 'stable') == minima == 4


# -- census ---------------------------------------------------------------------------

def cusp_counts(a, b):
    """Real roots of W'(x) = x^3 - a x + b, and the minima among them (NumPy)."""
    roots = [z.real for z in np.roots([1, 0, -a, b]) if abs(z.imag) < 1e-9]
    return len(roots), sum(1 for x in roots if 3 * x**2 - a > 0)


def test_cusp_census_against_numpy():
    x, dx, a, b = var('x dx a b')
    census = equilibrium_census(Lagrangian(dx**2 / 2 - x**4 / 4 + a * x**2 / 2 - b * x, [x]), [a, b])
    # the discriminant of x^3 - a x + b (Arnold, Catastrophe Theory, ch. 1)
    assert [SR(f) for f in census.bifurcation_set()] == [4 * a**3 - 27 * b**2]
    for cell in census.cells():
        s = cell.sample()
        assert (cell.count(), cell.stable_count()) == cusp_counts(float(s[a]), float(s[b]))
    rng = np.random.default_rng(3)
    for a0, b0 in rng.integers(-6, 7, size=(4, 2)):
        if 4 * a0**3 != 27 * b0**2:
            assert census.count_at({a: int(a0), b: int(b0)}) == cusp_counts(a0, b0)


CUSP_WITH_FAULTHANDLER = """
from sage.all import var
import faulthandler
faulthandler.enable()           # as pytest does: it reports every SIGABRT
from sage_dynsym import Lagrangian
from sage_dynsym.analysis.census import equilibrium_census
x, dx, a, b = var('x dx a b')
census = equilibrium_census(Lagrangian(dx**2 / 2 - x**4 / 4 + a * x**2 / 2 - b * x, [x]), [a, b])
print(len(census.cells()))
"""


@pytest.mark.slow
def test_cusp_census_raises_no_abort():
    # a PARI error (a univariate discriminant over QQ[a] in the variable
    # order PARI refuses) is signalled by cysignals through SIGABRT, which
    # faulthandler printed as "Fatal Python error: Aborted"
    import os
    import subprocess
    import sys
    done = subprocess.run([sys.executable, "-c", CUSP_WITH_FAULTHANDLER], capture_output=True,
                          text=True, timeout=600, env=dict(os.environ))
    assert done.returncode == 0, done.stderr[-2000:]
    assert "Aborted" not in done.stderr and "Fatal Python error" not in done.stderr
    assert int(done.stdout.split()[-1]) > 1


def test_hoop_census_bifurcation_value():
    th, dth, w, g = var('theta dtheta w g')
    # bead on a hoop (R = 1) turning at w: tilted equilibria for w^2 > g
    L = Lagrangian(dth**2 / 2 + w**2 * sin(th)**2 / 2 + g * cos(th), [th])
    census = equilibrium_census(L, [w], positive=[w], values={g: 2})
    assert [v**2 for v in census.bifurcation_values()] == [2]
    assert [(c.count(), c.stable_count()) for c in census.cells()] == [(2, 1), (4, 2)]


@pytest.mark.slow
def test_gyrostat_census_against_direct_solve(models):
    (R1, chart1), (R2, chart2) = models
    h = R1.momenta()[0]
    census = equilibrium_census(R1, [h], positive=[h], values=VALUES, chart=chart1,
                                regular=(R2, chart2))
    counts = []
    for cell in census.cells():
        direct, minima = critical_orientations(gyrostat_torque(*INERTIA, float(cell.sample()[h])))
        assert (cell.count(), cell.stable_count()) == (len(direct), minima), cell
        counts.append((cell.count(), cell.stable_count()))
    # Gutnik and Sarychev: no fewer than 8, no more than 24; stable from 4 to 2
    assert counts[0] == (24, 4) and counts[-1] == (8, 2)
    assert all(8 <= n <= 24 and 2 <= s <= 4 for n, s in counts)
    assert census.count_at({h: 0}) == (24, 4)


def test_census_samples_in_worker_processes():
    # Sage's PARI is not thread-safe: the samples go to processes (a Dask
    # worker runs its tasks in a thread, where PARI crashes)
    from concurrent.futures import ProcessPoolExecutor
    th, dth, w, g = var('theta dtheta w g')
    L = Lagrangian(dth**2 / 2 + w**2 * sin(th)**2 / 2 + g * cos(th), [th])
    here = equilibrium_census(L, [w], positive=[w], values={g: 2})
    with ProcessPoolExecutor(max_workers=2) as executor:
        there = equilibrium_census(L, [w], positive=[w], values={g: 2}, executor=executor)
    # a bead on a hoop of radius 1: tilted equilibria for w^2 > g
    assert [(c.sample(), c.count(), c.stable_count()) for c in there.cells()] == \
        [(c.sample(), c.count(), c.stable_count()) for c in here.cells()] == \
        [({w: 1}, 2, 1), ({w: 2}, 4, 2)]


# -- the census on Dask ---------------------------------------------------------------

@pytest.mark.slow
def test_gyrostat_census_identical_in_dask_process_pool(models):
    from sage_dynsym.scale import equilibrium_census as census_on_dask
    (R1, chart1), (R2, chart2) = models
    h = R1.momenta()[0]
    options = dict(positive=[h], values=VALUES, chart=chart1, regular=(R2, chart2))
    here = equilibrium_census(R1, [h], **options)
    there = census_on_dask(R1, [h], client='local', workers=2, **options)
    table = [(c.sample(), c.count(), c.stable_count(), c.undecided_count()) for c in here.cells()]
    assert [(c.sample(), c.count(), c.stable_count(), c.undecided_count())
            for c in there.cells()] == table
    assert there.bifurcation_set() == here.bifurcation_set()
    # Gutnik and Sarychev: 24 equilibria, 4 stable, at small h; 8 and 2 at large h
    assert table[0][1:3] == (24, 4) and table[-1][1:3] == (8, 2)


def where_it_runs(x):
    import os
    import threading
    return x, os.getpid(), threading.current_thread() is threading.main_thread()


@pytest.mark.slow       # a dask.distributed cluster whose worker's children import Sage
def test_census_on_a_distributed_client_in_child_processes_of_its_worker():
    # in a pytest process of its own: the cluster's event-loop threads stay
    # in the process that started it, and Sage's Singular must not be
    # reached from another thread (a garbage collection there) while later
    # tests compute in the main one
    import os
    import subprocess
    import sys
    if os.environ.get('SAGE_DYNSYM_CLUSTER_TEST') == 'inside':
        return _census_on_a_distributed_client()
    name = 'test_census_on_a_distributed_client_in_child_processes_of_its_worker'
    run = subprocess.run([sys.executable, '-m', 'pytest', '-q', '-p', 'no:cacheprovider',
                          '-m', 'slow', f'{__file__}::{name}'],
                         env=dict(os.environ, SAGE_DYNSYM_CLUSTER_TEST='inside'),
                         capture_output=True, text=True, timeout=900)
    assert run.returncode == 0, run.stdout[-3000:] + run.stderr[-3000:]


def _census_on_a_distributed_client():
    import psutil
    from distributed import Client, LocalCluster
    from sage_dynsym.errors import AnalysisError
    from sage_dynsym.scale import equilibrium_census as census_on_dask
    from sage_dynsym.scale.cluster import chunks, run_in_processes
    x, dx, a, b = var('x dx a b')
    L = Lagrangian(dx**2 / 2 - x**4 / 4 + a * x**2 / 2 - b * x, [x])
    here = equilibrium_census(L, [a, b])
    table = [(c.description(), c.sample(), c.count(), c.stable_count()) for c in here.cells()]
    with LocalCluster(n_workers=1, processes=True, threads_per_worker=2, host='127.0.0.1',
                      dashboard_address=None) as cluster, \
            Client(cluster, set_as_default=False) as client:
        there = census_on_dask(L, [a, b], client=client)
        assert [(c.description(), c.sample(), c.count(), c.stable_count())
                for c in there.cells()] == table
        assert there.bifurcation_set() == here.bifurcation_set()
        # every call in the main thread of a child of the worker, at most one
        # child per thread of the worker, kept across tasks
        worker_pid, = client.run(lambda: __import__('os').getpid()).values()
        out = run_in_processes(where_it_runs, [(i,) for i in range(6)], client=client)
        assert [i for i, _, _ in out] == list(range(6)) and all(m for _, _, m in out)
        pids = {p for _, p, _ in out}
        children = {c.pid for c in psutil.Process(worker_pid).children()}
        assert len(pids) <= 2 and pids <= children
        kept = [psutil.Process(p) for p in pids]
        # a package error in a child is raised here as it is, with the remote traceback as cause
        with pytest.raises(AnalysisError, match='chunk_size must be a positive integer') as err:
            run_in_processes(chunks, [(7, 0)], client=client)
        assert 'Traceback' in str(err.value.__cause__)
    # the children end with their worker (their input closes)
    _, alive = psutil.wait_procs(kept, timeout=60)
    assert alive == []
    # the cusp: 3 equilibria, 2 stable, inside 4 a^3 > 27 b^2; 1 outside
    # (Arnold, Catastrophe Theory, ch. 1), against NumPy at each sample
    for description, s, n, stable in table:
        assert (n, stable) == cusp_counts(float(s[a]), float(s[b]))
        assert (n, stable) == ((3, 2) if 4 * s[a]**3 > 27 * s[b]**2 else (1, 1))
    assert {(n, stable) for _, _, n, stable in table} == {(3, 2), (1, 1)}


#: A plain Python script (distributed logs to its stderr, which pytest's
#: capture would hide): the hoop's census in this process, in Dask's
#: process pool, and on a dask.distributed client (in child processes of its
#: worker). The pool's processes are spawned and import the script again: the guard.
ROUTES = """
import os, threading
from sage.all import var, sin, cos
from distributed import Client
from sage_dynsym import Lagrangian
from sage_dynsym.errors import AnalysisError
from sage_dynsym.scale import equilibrium_census
from sage_dynsym.scale.cluster import local_cluster, closed_quietly, run_in_processes

def where_it_runs():        # defined in __main__: shipped by value (cloudpickle)
    return os.getpid(), threading.current_thread() is threading.main_thread()

def table(census):
    return [(c.sample(), c.count(), c.stable_count()) for c in census.cells()]

if __name__ == '__main__':
    th, dth, w, g = var('theta dtheta w g')
    L = Lagrangian(dth**2 / 2 + w**2 * sin(th)**2 / 2 + g * cos(th), [th])
    print('here', table(equilibrium_census(L, [w], positive=[w], values={g: 2})))
    print('pool', table(equilibrium_census(L, [w], positive=[w], values={g: 2},
                                           client='local', workers=2)))
    print('pool runs in main threads of other processes',
          all(pid != os.getpid() and main for pid, main in
              run_in_processes(where_it_runs, [()] * 3, client='local', workers=2)))
    with closed_quietly(local_cluster(1)) as cluster, \\
            closed_quietly(Client(cluster, set_as_default=False)) as client:
        print('one-thread worker runs in main thread', client.submit(where_it_runs).result()[1])
        print('client', table(equilibrium_census(L, [w], positive=[w], values={g: 2},
                                                 client=client)))
"""


@pytest.mark.slow       # two process pools and a cluster, each importing Sage
def test_census_routes_agree_and_close_quietly(tmp_path):
    import subprocess
    import sys
    script = tmp_path / 'routes.py'
    script.write_text(ROUTES)
    run = subprocess.run([sys.executable, str(script)], capture_output=True, text=True,
                         timeout=600)
    # a bead on a hoop of radius 1: tilted equilibria for w^2 > g
    hoop = "[({w: 1}, 2, 1), ({w: 2}, 4, 2)]"
    assert run.stdout.splitlines() == [
        f"here {hoop}", f"pool {hoop}", "pool runs in main threads of other processes True",
        # a dask.distributed worker of one thread still runs its tasks in a thread
        "one-thread worker runs in main thread False", f"client {hoop}"], \
        run.stdout + run.stderr
    assert run.returncode == 0, run.stderr
    # no traceback, no fault, no message of a cut connection at the close
    assert 'Traceback (most recent call last)' not in run.stderr, run.stderr
    assert 'Segmentation' not in run.stderr and 'CommClosedError' not in run.stderr, run.stderr


# -- first approximation: gyroscopic stabilization -----------------------------------
#
# M x'' + G x' + K x = 0 with M = 1, G = g [[0, -1], [1, 0]], K = diag(k1, k2):
# for k1, k2 < 0 the linearization is stable (all roots simple, on the
# imaginary axis) iff g^2 + k1 + k2 > 2 sqrt(k1 k2), i.e. |g| > sqrt(-k1) +
# sqrt(-k2) (Thomson and Tait; Merkin, Introduction to the Theory of
# Stability, ch. 6). Neither boundary below is a degenerate equilibrium.

def first_approximation_stable(k1, k2, g, tol=1e-9):
    """NumPy: the eigenvalues of the first-order form, all simple and on the imaginary axis."""
    A = np.array([[0, 0, 1, 0], [0, 0, 0, 1], [-k1, 0, 0, g], [0, -k2, -g, 0]], dtype=float)
    ev = np.linalg.eigvals(A)
    distinct = min(abs(a - b) for i, a in enumerate(ev) for b in ev[i + 1:]) > 1e-7
    return bool(np.all(np.abs(ev.real) < tol) and distinct)


def check_first_approximation_cells(census, p, stiffness, critical):
    """Each cell of census.cells(first_approximation=True): its count in first
    approximation against NumPy at its sample; and on both sides of the
    critical value, the cells containing them against NumPy there."""
    with warnings.catch_warnings():
        # every stability region decided with the parameters symbolic: the set is complete
        warnings.simplefilter('error')
        cells = census.cells(first_approximation=True)
    for cell in cells:
        s = float(cell.sample()[p])
        assert cell.count() == 1
        expected = first_approximation_stable(*stiffness(s))
        assert cell.stable_count(first_approximation=True) == expected
    values = census.bifurcation_values(first_approximation=True)
    assert min(abs(float(v) - critical) for v in values) < 1e-12
    for s in (critical - 1e-3, critical + 1e-3):
        cell, = [c for c in cells if (c.bounds()[0] is None or c.bounds()[0] < s)
                 and (c.bounds()[1] is None or s < c.bounds()[1])]
        expected = first_approximation_stable(*stiffness(s))
        assert cell.stable_count(first_approximation=True) == expected
    return cells


def test_first_approximation_census_of_a_gyroscopically_stabilized_maximum():
    # a potential maximum -(x^2 + 2 y^2)/2 coupled to a rotor (cyclic angle
    # phi, momentum p) through x dy - y dx: the Routh function has the
    # gyroscopic term p (x dy - y dx), g = 2 p, K = diag(-1, -2)
    x, y, phi, dx, dy, dphi = var('x y phi dx dy dphi')
    L = Lagrangian((dx**2 + dy**2) / 2 + (dphi + x * dy - y * dx)**2 / 2 + (x**2 + 2 * y**2) / 2,
                   [x, y, phi])
    R = L.routh([phi])
    p = R.momenta()[0]
    census = equilibrium_census(R, [p], positive=[p])
    # the equilibrium x = y = 0 is never degenerate: no discriminant
    assert census.bifurcation_set() == [] and len(census.cells()) == 1
    critical = (1 + np.sqrt(2)) / 2            # 2 p = sqrt(1) + sqrt(2)
    cells = check_first_approximation_cells(census, p, lambda s: (-1.0, -2.0, 2 * s), critical)
    assert [c.stable_count(first_approximation=True) for c in cells][-1] == 1
    assert all(c.stable_count() == 0 for c in cells)        # W has a maximum: never Routh-stable


def test_first_approximation_census_of_a_turning_saddle():
    # a particle on the saddle (x^2 - 2 y^2)/2 turning at the rate w, in the
    # turning frame: K = diag(1 - w^2, -2 - w^2), g = 2 w; stable in first
    # approximation in a window above w = 1 (where K is degenerate)
    x, y, dx, dy, w = var('x y dx dy w')
    L = Lagrangian((dx**2 + dy**2) / 2 + w * (x * dy - y * dx) + w**2 * (x**2 + y**2) / 2
                   - (x**2 - 2 * y**2) / 2, [x, y])
    census = equilibrium_census(L, [w], positive=[w])
    assert [float(v) for v in census.bifurcation_values()] == [1.0]

    def stiffness(s):
        return 1 - s**2, -2 - s**2, 2 * s
    # the upper end of the window: 2 w = sqrt(w^2 - 1) + sqrt(w^2 + 2)
    critical = brentq(lambda s: 2 * s - np.sqrt(s**2 - 1) - np.sqrt(s**2 + 2), 1 + 1e-9, 2)
    cells = check_first_approximation_cells(census, w, stiffness, critical)
    assert [c.stable_count(first_approximation=True) for c in cells] == [0, 1, 0]
    # the coarse cell 1 < w mixes both: the refined census is needed
    assert [c.stable_count(first_approximation=True) for c in census.cells()] == [0, 0]

"""Stability maps and sweeps on Dask (small local clusters of processes on
127.0.0.1, always closed): the same arrays as plain NumPy whatever the
number of workers, a worker killed in the middle, an interrupt, schedulers
that do not answer or have no worker."""
import os
import signal
import threading

import numpy as np
import psutil
import pytest
from distributed import Client, LocalCluster

import scale_helpers
from conftest import slow_except
from sage.all import var

from sage_dynsym import load
from scale_helpers import example_path
from sage_dynsym.errors import AnalysisError
from sage_dynsym import linearize
from sage_dynsym.scale import stability_map, sweep

LADDER_FIXED = {'R3': 1, 'R4': 2, 'L1': 1, 'L2': 0.5, 'L3': 1, 'C1': 1, 'C2': 2, 'C3': 1}
LADDER_GRID = {'R1': (-1, 2, 60), 'R2': (-1, 2, 50)}


def cluster(n):
    return LocalCluster(n_workers=n, threads_per_worker=1, processes=True, host='127.0.0.1',
                        dashboard_address=None,
                        scheduler_kwargs=dict(dashboard=False, dashboard_address='127.0.0.1:0'))


@pytest.fixture(scope="module")
def ladder():
    return linearize(load(example_path("rlc_ladder.yaml")), sources=False)


@pytest.fixture(scope="module")
def clients():
    with cluster(1) as one, Client(one, set_as_default=False) as c1, \
            cluster(2) as two, Client(two, set_as_default=False) as c2:
        yield {1: c1, 2: c2}


def same(S, T):
    return np.array_equal(S.max_real_part(), T.max_real_part(), equal_nan=True) and \
        np.array_equal(S.stable(), T.stable())


# the polynomial method in `make test`; both, and the other comparisons of one
# and two workers with NumPy, the interrupt and the progress bar in `make test-slow` (CI)
@pytest.mark.parametrize("method", slow_except(["polynomial", "eigvals"], ["polynomial"]))
def test_map_identical_with_one_two_workers_and_numpy(clients, ladder, method):
    args = dict(fixed=LADDER_FIXED, method=method, chunk_size=500)     # 6 chunks
    plain = stability_map(ladder, LADDER_GRID, client=False, **args)
    one = stability_map(ladder, LADDER_GRID, client=clients[1], **args)
    two = stability_map(ladder, LADDER_GRID, client=clients[2], **args)
    assert same(plain, one) and same(plain, two)
    assert 0.1 < plain.stable().mean() < 0.9


@pytest.mark.slow
def test_random_samples_identical_with_one_two_workers_and_numpy(clients, ladder):
    args = dict(fixed=LADDER_FIXED, samples=5000, seed=11, chunk_size=700)
    plain = stability_map(ladder, LADDER_GRID, client=False, **args)
    for n in (1, 2):
        S = stability_map(ladder, LADDER_GRID, client=clients[n], **args)
        assert same(plain, S)
        assert all(np.array_equal(S.axes()[k], plain.axes()[k]) for k in plain.axes())


def test_workers_do_not_load_sage(clients, ladder):
    stability_map(ladder, LADDER_GRID, fixed=LADDER_FIXED, client=clients[2], chunk_size=500)
    loaded = clients[2].run(lambda: [m for m in ('sage', 'sage_dynsym') if m in __import__('sys').modules])
    assert all(v == [] for v in loaded.values())


@pytest.mark.slow
def test_sweep_identical_with_one_two_workers_and_numpy(clients):
    grid = {'a': (0, 1, 7), 'b': (-1, 1, 5)}
    plain = sweep(scale_helpers.product, grid, fixed={'c': 3.0}, client=False)
    expected = 3.0 * np.outer(np.linspace(0, 1, 7), np.linspace(-1, 1, 5))
    np.testing.assert_array_equal(plain.values(), expected)
    for n in (1, 2):
        W = sweep(scale_helpers.product, grid, fixed={'c': 3.0}, client=clients[n], chunk_size=4)
        assert np.array_equal(W.values(), plain.values())
    # a function of the session (shipped by value), vectorized, on random points
    V = sweep(lambda a, b: np.hypot(a, b), grid, samples=2000, vectorized=True,
              client=clients[2], chunk_size=300)
    P = sweep(lambda a, b: np.hypot(a, b), grid, samples=2000, vectorized=True, client=False)
    assert np.array_equal(V.values(), P.values())


def test_model_sweep_on_dask(clients):
    model = scale_helpers.OscillatorModel()
    c, k = var('c k')
    W = sweep(model, {c: (0, 1, 3), k: (1, 2, 2)}, simulate=dict(initial=1.0, t_end=2.0),
              reduce=scale_helpers.last_value, client=clients[2], chunk_size=2)
    expected = [[scale_helpers.damped_response(cv, kv, t=2.0) for kv in (1, 2)]
                for cv in (0, 0.5, 1)]
    np.testing.assert_allclose(W.values(), expected, rtol=1e-12)


@pytest.mark.parametrize("label, run", [
    ("stability-map-", lambda ladder, c: stability_map(ladder, LADDER_GRID, fixed=LADDER_FIXED,
                                                       client=c, chunk_size=200)),
    ("sweep-", lambda ladder, c: sweep(scale_helpers.slow_product, {'a': (0, 1, 4), 'b': (0, 1, 4)},
                                       fixed={'delay': 0.05}, client=c, chunk_size=1)),
])
@pytest.mark.slow       # real worker processes killed and restarted; `make test-slow` (CI)
def test_worker_killed_in_the_middle(tmp_path, ladder, label, run):
    marker = tmp_path / "killed"
    with cluster(2) as two, Client(two, set_as_default=False) as c:
        c.register_plugin(scale_helpers.KillOnce(label, 3, str(marker)))
        result = run(ladder, c)
        assert marker.exists()          # chunk 3 started on a worker, which died then
        pids = set(c.run(os.getpid).values())
    assert int(marker.read_text()) not in pids     # its replacement did the rest
    reference = run(ladder, False)
    if label == "sweep-":
        assert np.array_equal(result.values(), reference.values())
    else:
        assert same(result, reference)


def children():
    return {p.pid for p in psutil.Process().children(recursive=True)}


def test_own_cluster_is_closed(ladder):
    before = children()
    S = stability_map(ladder, LADDER_GRID, fixed=LADDER_FIXED, workers=1)
    assert same(S, stability_map(ladder, LADDER_GRID, fixed=LADDER_FIXED, client=False))
    psutil.wait_procs([psutil.Process(p) for p in children() - before], timeout=30)
    assert children() <= before


@pytest.mark.slow
def test_interrupt_cancels_and_closes(ladder):
    before = children()
    started = threading.Event()

    def interrupt():
        # SIGINT once the cluster runs (its workers exist), as Ctrl-C would
        while not (children() - before):
            if started.wait(0.05):
                break
        threading.Event().wait(2)
        os.kill(os.getpid(), signal.SIGINT)

    timer = threading.Thread(target=interrupt, daemon=True)
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        # 40 chunks of 0.5 s on one worker: far longer than the 2 s before the interrupt
        sweep(scale_helpers.slow_product, {'a': (0, 1, 40), 'b': (0, 1, 1)},
              fixed={'delay': 0.5}, workers=1, chunk_size=1)
    started.set()
    timer.join()
    psutil.wait_procs([psutil.Process(p) for p in children() - before], timeout=30)
    assert children() <= before


def free_port():
    import socket
    with socket.socket() as s:
        s.bind(('127.0.0.1', 0))
        return s.getsockname()[1]


def test_scheduler_that_does_not_answer(ladder):
    errors = []

    def attempt():
        try:
            stability_map(ladder, LADDER_GRID, fixed=LADDER_FIXED,
                          client=f"tcp://127.0.0.1:{free_port()}", timeout=2)
        except AnalysisError as err:
            errors.append(err)

    worker = threading.Thread(target=attempt, daemon=True)
    worker.start()
    worker.join(60)                     # a hang detector, not a timing
    assert not worker.is_alive()
    assert errors and "no Dask scheduler answers at tcp://127.0.0.1:" in str(errors[0])


def test_scheduler_without_workers(ladder):
    with cluster(0) as empty, Client(empty, set_as_default=False) as c:
        with pytest.raises(AnalysisError, match="has no worker after 1 s"):
            stability_map(ladder, LADDER_GRID, fixed=LADDER_FIXED, client=c, timeout=1)
        address = empty.scheduler_address
        with pytest.raises(AnalysisError, match=f"the scheduler at {address} has no worker"):
            sweep(scale_helpers.product, {'a': (0, 1, 3), 'b': (0, 1, 3)}, client=address,
                  timeout=1)


@pytest.mark.slow
def test_progress_bar(clients, ladder, capsys):
    S = stability_map(ladder, LADDER_GRID, fixed=LADDER_FIXED, client=clients[2], chunk_size=500,
                      progress=True)
    assert "% Completed" in capsys.readouterr().out
    assert same(S, stability_map(ladder, LADDER_GRID, fixed=LADDER_FIXED, client=False))

"""Helpers of the tests of sage_dynsym.scale that run on Dask workers.

Plain NumPy/Dask on purpose: the workers import this module (the tests'
folder is on their path), and it must not load Sage there.
"""
import os
import signal
import time

import numpy as np
from distributed.diagnostics.plugin import WorkerPlugin


class KillOnce(WorkerPlugin):
    """Kill the worker process (SIGKILL) when the task whose name starts with
    ``prefix`` and ends with ``-<chunk>`` starts executing -- once for the
    whole cluster: the first worker to do it creates ``marker``."""

    name = "kill-once"

    def __init__(self, prefix, chunk, marker):
        self.prefix, self.chunk, self.marker = prefix, chunk, marker

    def transition(self, key, start, finish, **kwargs):
        key = str(key)
        if finish != "executing" or not key.startswith(self.prefix) \
                or not key.endswith(f"-{self.chunk}"):
            return
        try:
            fd = os.open(self.marker, os.O_CREAT | os.O_EXCL | os.O_WRONLY)
        except FileExistsError:
            return
        os.write(fd, str(os.getpid()).encode())
        os.close(fd)
        os.kill(os.getpid(), signal.SIGKILL)


def example_path(name):
    """A description file of the examples/ folder (by path: the package is
    being reorganised)."""
    return os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "examples", name)


def damped_response(c, k, m=1.0, t=1.0):
    """x(t) of m x'' + c x' + k x = 0, x(0) = 1, x'(0) = 0 (closed form)."""
    mu, disc = -c / (2 * m), c * c - 4 * m * k
    if disc < 0:
        w = np.sqrt(-disc) / (2 * m)
        return float(np.exp(mu * t) * (np.cos(w * t) - mu / w * np.sin(w * t)))
    if disc == 0:
        return float(np.exp(mu * t) * (1 - mu * t))
    r1, r2 = mu + np.sqrt(disc) / (2 * m), mu - np.sqrt(disc) / (2 * m)
    return float((r2 * np.exp(r1 * t) - r1 * np.exp(r2 * t)) / (r2 - r1))


class OscillatorModel:
    """A stand-in for a model with ``simulate(values, initial, t_end, points)``
    (the calling convention of the package's simulations): the exact
    trajectory of m x'' + c x' + k x = 0 from x(0) = initial, x'(0) = 0."""

    def simulate(self, values, initial, t_end, points=3):
        values = {str(key): value for key, value in values.items()}    # symbols or names
        times = np.linspace(0, t_end, points)
        xs = [initial * damped_response(values['c'], values['k'], values.get('m', 1.0), t)
              for t in times]
        return Trajectory(times, xs)


class Trajectory:
    def __init__(self, times, xs):
        self._times, self._xs = list(times), list(xs)

    def times(self):
        return self._times

    def values(self, name):
        return self._xs


def last_value(trajectory):
    return trajectory.values('x')[-1]


def slow_product(a, b, delay=0.2):
    time.sleep(delay)
    return a * b


def product(a, b, c=1.0):
    return a * b * c

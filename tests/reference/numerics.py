"""
Numerical yardsticks shared by the tests and the benchmarks (NumPy only).
"""
import numpy as np


def central_differences(f, x, h=1e-6):
    """
    The Jacobian of the right-hand side ``f(t, x)`` at ``t = 0`` by central
    differences, with the step ``h`` relative to each ``|x_j|`` (at least
    ``h``).
    """
    x = np.asarray(x, dtype=float)
    columns = []
    for j in range(len(x)):
        step = h * max(1.0, abs(x[j]))
        e = np.zeros_like(x)
        e[j] = step
        columns.append((f(0.0, x + e) - f(0.0, x - e)) / (2 * step))
    return np.array(columns).T


def same_multiset(a, b, rel=1e-8, scale=None):
    """
    Whether the numbers ``a`` and ``b`` are the same with their
    multiplicities, each number ``x`` to ``rel`` relative to ``scale`` (by
    default ``max(1, |x|)``): each number of ``a`` takes the nearest of the
    numbers of ``b`` not taken yet.
    """
    a, b = list(a), list(b)
    if len(a) != len(b):
        return False
    for x in a:
        k = min(range(len(b)), key=lambda j: abs(b[j] - x))
        if abs(b[k] - x) > rel * (max(1.0, abs(x)) if scale is None else scale):
            return False
        b.pop(k)
    return True

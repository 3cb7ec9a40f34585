r"""
Numerical kernels of the scale-out computations (NumPy only)

These functions run on the Dask workers. They import nothing from Sage nor
from the rest of the package, and :mod:`sage_dynsym.scale.cluster` ships
them *by value*: a worker needs NumPy (and SciPy for singular left-hand
matrices), not Sage. One of them, :func:`in_child_process`, runs a task
that does need Sage in a child process of the worker.

A *program* is the compiled form of a list of symbolic expressions (see
:mod:`sage_dynsym.scale.compile`): plain tuples, evaluated here on NumPy
arrays, one instruction at a time over a whole chunk of points.

A *point specification* describes the points of a map or sweep so that any
chunk ``[start, stop)`` of them can be generated on its own, identically
wherever and in whatever order the chunks run:

- ``('grid', axes)`` -- the Cartesian grid of the 1-D arrays ``axes``,
  flattened in C order (the last axis varies fastest);
- ``('samples', lows, highs, seed)`` -- uniform random points in the box;
  point ``i`` comes from block ``i // BLOCK``, whose generator is seeded
  with ``[seed, block]``, so it does not depend on the chunking.

EXAMPLES::

    sage: from sage_dynsym.scale.kernel import chunk_points, polynomial_abscissa
    sage: chunk_points(('grid', [[0., 1.], [10., 20., 30.]]), 2, 5)
    [array([0., 1., 1.]), array([30., 10., 20.])]
    sage: import numpy as np
    sage: alpha, rho = polynomial_abscissa(np.array([[1., 3., 2.], [1., 0., 1.]]))
    sage: alpha, rho       # (lam + 1)(lam + 2), and lam^2 + 1
    (array([-1.,  0.]), array([2., 1.]))
"""
import operator

import numpy as np

__all__ = ['BLOCK', 'BATCH', 'FUNCTIONS', 'COMPARISONS', 'run_program', 'chunk_points',
           'polynomial_abscissa', 'pencil_abscissa', 'classify', 'stability_class', 'map_chunk',
           'sweep_chunk', 'identity', 'CHILDREN', 'send_message', 'receive_message',
           'in_child_process']

BLOCK = 4096            # random points are drawn in blocks of this size
BATCH = 4096            # points evaluated at once inside a chunk
_EPS = np.finfo(float).eps

FUNCTIONS = {
    'sin': np.sin, 'cos': np.cos, 'tan': np.tan, 'exp': np.exp, 'log': np.log,
    'sinh': np.sinh, 'cosh': np.cosh, 'tanh': np.tanh, 'abs': np.abs,
    'arcsin': np.arcsin, 'arccos': np.arccos, 'arctan': np.arctan, 'arctan2': np.arctan2,
    'arcsinh': np.arcsinh, 'arccosh': np.arccosh, 'arctanh': np.arctanh,
    'sgn': np.sign, 'sec': lambda x: 1 / np.cos(x), 'csc': lambda x: 1 / np.sin(x),
    'cot': lambda x: 1 / np.tan(x),
}
COMPARISONS = {'gt': operator.gt, 'ge': operator.ge, 'lt': operator.lt,
               'le': operator.le, 'eq': operator.eq, 'ne': operator.ne}


# ---------------------------------------------------------------------------
# programs
# ---------------------------------------------------------------------------

def run_program(program, inputs, size):
    r"""
    Evaluate a compiled program.

    INPUT:

    - ``program`` -- ``(instructions, outputs, releases)``: instruction ``k``
      is ``('input', i)``, ``('const', c)``, ``('add', r, ...)``,
      ``('mul', r, ...)``, ``('ipow', r, n)``, ``('pow', r, s)``,
      ``('call', name, r, ...)`` or ``('cmp', name, r, s)``, where ``r, s``
      are indices of earlier instructions; ``releases[k]`` lists the
      results no longer needed after instruction ``k``
    - ``inputs`` -- list of 1-D arrays (the values of the input symbols)
    - ``size`` -- the number of points

    OUTPUT: a list of arrays of length ``size``, one per output

    EXAMPLES: `x y + 2` and `x^2 > y`::

        sage: from sage_dynsym.scale.kernel import run_program
        sage: import numpy as np
        sage: prog = ([('input', 0), ('input', 1), ('mul', 0, 1), ('const', 2.0),
        ....:          ('add', 2, 3), ('ipow', 0, 2), ('cmp', 'gt', 5, 1)], [4, 6],
        ....:         [[], [], [], [], [], [0], [1, 5]])
        sage: run_program(prog, [np.array([1., 2.]), np.array([3., 3.])], 2)
        [array([5., 8.]), array([False,  True])]
    """
    instructions, outputs, releases = program
    regs = [None] * len(instructions)
    with np.errstate(all='ignore'):
        for k, ins in enumerate(instructions):
            op = ins[0]
            if op == 'input':
                value = inputs[ins[1]]
            elif op == 'const':
                value = ins[1]
            elif op == 'add':
                value = regs[ins[1]]
                for r in ins[2:]:
                    value = value + regs[r]
            elif op == 'mul':
                value = regs[ins[1]]
                for r in ins[2:]:
                    value = value * regs[r]
            elif op == 'ipow':
                value = _integer_power(regs[ins[1]], ins[2])
            elif op == 'pow':
                value = np.power(regs[ins[1]], regs[ins[2]])
            elif op == 'call':
                value = FUNCTIONS[ins[1]](*(regs[r] for r in ins[2:]))
            elif op == 'cmp':
                value = COMPARISONS[ins[1]](regs[ins[2]], regs[ins[3]])
            else:
                raise ValueError(f"unknown instruction {op!r}")
            regs[k] = value
            for r in releases[k]:
                regs[r] = None
    return [np.broadcast_to(np.asarray(regs[k]), (size,)) for k in outputs]


def _integer_power(x, n):
    if n == 1:
        return x
    if n == -1:
        return 1.0 / x
    if n < 0:
        return 1.0 / _integer_power(x, -n)
    if n == 2:
        return x * x
    return np.power(x, float(n)) if isinstance(x, np.ndarray) else x ** n


# ---------------------------------------------------------------------------
# points
# ---------------------------------------------------------------------------

def chunk_points(layout, start, stop):
    r"""
    The coordinates of the points ``start, ..., stop - 1`` of a point
    specification (see the module documentation).

    OUTPUT: a list of 1-D arrays, one per parameter

    EXAMPLES: random points do not depend on how they are chunked::

        sage: from sage_dynsym.scale.kernel import chunk_points
        sage: import numpy as np
        sage: layout = ('samples', [0., -1.], [1., 1.], 7)
        sage: whole = chunk_points(layout, 0, 5000)
        sage: parts = [chunk_points(layout, a, b) for a, b in ((0, 4095), (4095, 4097), (4097, 5000))]
        sage: all((np.concatenate([p[k] for p in parts]) == whole[k]).all() for k in (0, 1))
        True
    """
    kind = layout[0]
    if kind == 'grid':
        axes = [np.asarray(a, dtype=float) for a in layout[1]]
        index = np.unravel_index(np.arange(start, stop), tuple(len(a) for a in axes))
        return [a[i] for a, i in zip(axes, index)]
    if kind == 'samples':
        lows, highs, seed = (np.asarray(layout[1], float), np.asarray(layout[2], float),
                             int(layout[3]))
        start, stop = int(start), int(stop)
        first, last = start // BLOCK, max(start, stop - 1) // BLOCK
        blocks = [np.random.default_rng([seed, int(b)]).random((BLOCK, len(lows)))
                  for b in range(first, last + 1)]
        u = np.concatenate(blocks)[start - first * BLOCK: stop - first * BLOCK]
        return [lows[k] + (highs[k] - lows[k]) * u[:, k] for k in range(len(lows))]
    raise ValueError(f"unknown point specification {kind!r}")


# ---------------------------------------------------------------------------
# spectral abscissa
# ---------------------------------------------------------------------------

def polynomial_abscissa(coefficients):
    r"""
    The largest real part ``alpha`` and the largest modulus ``rho`` of the
    roots of many real polynomials at once.

    Laguerre's method, vectorised over the polynomials: one root at a
    time from 0 (so roughly in increasing modulus, which keeps deflation
    stable), then deflation by `z - r` for a real root or by the real
    quadratic `z^2 - 2\,\mathrm{Re}(r) z + |r|^2` for a complex one.
    Polynomials whose leading coefficient vanishes, and the rare ones where
    the iteration does not converge, are solved one by one with
    ``numpy.roots``. A polynomial that is a nonzero constant has no roots:
    ``alpha = -inf``, ``rho = 0``; non-finite or all-zero coefficients give
    ``nan``.

    INPUT: ``coefficients`` -- array ``(m, n + 1)``, highest degree first

    OUTPUT: two arrays of length ``m``

    EXAMPLES::

        sage: from sage_dynsym.scale.kernel import polynomial_abscissa
        sage: import numpy as np
        sage: c = np.array([np.poly([-1, -2 + 3j, -2 - 3j, 0.5]).real, [0, 0, 1, 2, 1.]])
        sage: polynomial_abscissa(c)      # roots -1, -2 +- 3i, 1/2; then -1 (double)
        (array([ 0.5, -1. ]), array([3.60555128, 1.        ]))
    """
    c = np.asarray(coefficients, dtype=float)
    m, n1 = c.shape
    alpha, rho = np.full(m, -np.inf), np.zeros(m)
    finite = np.isfinite(c).all(axis=1)
    alpha[~finite] = rho[~finite] = np.nan
    regular = finite & (c[:, 0] != 0)
    singular = np.flatnonzero(finite & ~regular)
    idx = np.flatnonzero(regular)
    groups = [(idx, (c[idx, 1:] / c[idx, :1]).T.copy())] if n1 > 1 else []
    while groups:
        idx, a = groups.pop()               # a: monic, rows = coefficients 1..n
        n = a.shape[0]
        if n == 0 or len(idx) == 0:
            continue
        if n <= 2:
            re, mod = _small_roots(a)
        else:
            x, ok = _laguerre(a)
            if not ok.all():
                singular = np.concatenate([singular, idx[~ok]])
                idx, a, x = idx[ok], a[:, ok], x[ok]
            re, mod = x.real, np.abs(x)
            pair = np.abs(x.imag) > 1e-7 * mod
            for sel, quadratic in ((~pair, False), (pair, True)):
                if sel.any():
                    groups.append((idx[sel], _deflate(a[:, sel], x[sel], quadratic)))
        alpha[idx] = np.maximum(alpha[idx], re)
        rho[idx] = np.maximum(rho[idx], mod)
    for i in singular:
        roots = np.roots(c[i])
        if not np.isfinite(roots).all():
            alpha[i] = rho[i] = np.nan
        elif len(roots):
            alpha[i], rho[i] = roots.real.max(), np.abs(roots).max()
        elif not c[i].any():
            alpha[i] = rho[i] = np.nan
    return alpha + 0.0, rho         # + 0.0: no negative zeros


def _small_roots(a):
    # degree 1 or 2, monic: largest real part and largest modulus
    if a.shape[0] == 1:
        return -a[0], np.abs(a[0])
    h, q = -a[0] / 2, a[1]
    disc = h * h - q
    s = np.sqrt(np.abs(disc))
    real = disc >= 0
    # the real roots h +- s, computed as r1 = h + sign(h) s and q / r1
    r1 = h + np.copysign(s, h)
    with np.errstate(all='ignore'):
        r2 = np.where(r1 != 0, q / r1, 0.0)
    re = np.where(real, np.maximum(r1, r2), h)
    mod = np.where(real, np.maximum(np.abs(r1), np.abs(r2)), np.sqrt(np.abs(q)))
    return re, mod


def _laguerre(a, maxit=60):
    r"""One root of each monic polynomial (columns of ``a``, coefficients
    1..n), and whether the iteration converged."""
    n, m = a.shape
    x = np.zeros(m, dtype=complex)
    ok = np.zeros(m, dtype=bool)
    act = np.arange(m)
    xa, aa, absa = x.copy(), a, np.abs(a)
    with np.errstate(all='ignore'):
        for _ in range(maxit):
            p = xa + aa[0]
            dp = np.ones_like(p)
            ddp = np.zeros_like(p)
            ax = np.abs(xa)
            bound = ax + absa[0]
            for j in range(1, n):       # Horner for p, p', p''/2
                # the complex products out of place: NumPy's in-place complex
                # multiplication rounds differently on very short arrays, and
                # the results must not depend on the chunking
                ddp = ddp * xa
                ddp += dp
                dp = dp * xa
                dp += p
                p = p * xa
                p += aa[j]
                bound *= ax
                bound += absa[j]
            # |p| at the rounding level of Horner's scheme: x is a root
            done = np.abs(p) <= 8 * _EPS * bound
            g = dp / p
            h = g * g - 2 * ddp / p
            sq = np.sqrt((n - 1) * (n * h - g * g))
            d1, d2 = g + sq, g - sq
            step = n / np.where(np.abs(d1) >= np.abs(d2), d1, d2)
            step[~np.isfinite(step)] = 0.6 + 0.8j      # p' = p'' = 0: move off
            step[done] = 0
            xa = xa - step
            done |= np.abs(step) <= 1e-14 * np.abs(xa)
            if done.any():
                x[act[done]] = xa[done]
                ok[act[done]] = True
                keep = ~done
                if not keep.any():
                    break
                act, xa, aa, absa = act[keep], xa[keep], aa[:, keep], absa[:, keep]
    return x, ok


def _deflate(a, x, quadratic):
    # synthetic division of the monic polynomials by z - r or by the real
    # quadratic factor of the pair r, conj(r); the quotient is monic
    n, m = a.shape
    if quadratic:
        p, q = -2 * x.real, np.abs(x) ** 2
        d = np.empty((n - 2, m))
        prev2, prev = np.zeros(m), np.ones(m)
        for j in range(n - 2):
            cur = a[j] - p * prev - q * prev2
            d[j] = cur
            prev2, prev = prev, cur
        return d
    r = x.real
    d = np.empty((n - 1, m))
    prev = np.ones(m)
    for j in range(n - 1):
        prev = a[j] + r * prev
        d[j] = prev
    return d


def pencil_abscissa(J, B=None):
    r"""
    The largest real part and the largest modulus of the finite
    eigenvalues of the pencils `B\lambda - J` (``numpy.linalg.eigvals`` on
    a stack of matrices).

    Where `B` is well conditioned the eigenvalues are those of `B^{-1}J`;
    where it is singular (condition number above `10^{12}`), those of the
    generalized problem (``scipy.linalg.eigvals(J, B)``, one point at a
    time), infinite eigenvalues left out (no finite eigenvalue: ``-inf``).
    Non-finite entries and singular pencils (`\det(B\lambda - J) \equiv 0`)
    give ``nan``.

    INPUT: ``J``, ``B`` -- arrays ``(m, k, k)``; ``B=None`` is the identity

    EXAMPLES::

        sage: from sage_dynsym.scale.kernel import pencil_abscissa
        sage: import numpy as np
        sage: J = np.array([[[0., 1.], [-2., -3.]], [[0., 1.], [-1., 0.]]])
        sage: pencil_abscissa(J)
        (array([-1.,  0.]), array([2., 1.]))
        sage: B = np.array([[[1., 0.], [0., 0.]]] * 2)
        sage: pencil_abscissa(J, B)[0]     # x' = y, 0 = -2x - 3y: x' = -2/3 x; x' = y, 0 = -x
        array([-0.66666667,        -inf])
        sage: pencil_abscissa(np.array([[[0., 1.], [0., 0.]]]), B[:1])[0]   # det(B lam - J) = 0
        array([nan])
    """
    m = J.shape[0]
    alpha, rho = np.full(m, np.nan), np.full(m, np.nan)
    good = np.isfinite(J).all(axis=(1, 2))
    if B is not None:
        good &= np.isfinite(B).all(axis=(1, 2))
    idx = np.flatnonzero(good)
    if B is None:
        easy, hard = idx, idx[:0]
    else:
        with np.errstate(all='ignore'):
            cond = np.linalg.cond(B[idx]) if len(idx) else np.zeros(0)
        easy, hard = idx[cond < 1e12], idx[~(cond < 1e12)]
    if len(easy):
        A = J[easy] if B is None else np.linalg.solve(B[easy], J[easy])
        w = np.linalg.eigvals(A)
        alpha[easy], rho[easy] = w.real.max(axis=1), np.abs(w).max(axis=1)
    if len(hard):
        from scipy.linalg import eigvals
        for i in hard:
            if _singular_pencil(J[i], B[i]):
                continue
            w = eigvals(J[i], B[i])
            w = w[np.isfinite(w)]
            alpha[i], rho[i] = (w.real.max(), np.abs(w).max()) if len(w) else (-np.inf, 0.0)
    return alpha + 0.0, rho


def _singular_pencil(J, B):
    # det(B lam - J) vanishes identically: test at an arbitrary complex lam
    lam = 0.6180339887 + 0.7548776662j
    scale = (np.abs(J).max() + np.abs(B).max() * abs(lam)) ** len(J)
    return abs(np.linalg.det(B * lam - J)) <= 1e-12 * scale


# ---------------------------------------------------------------------------
# chunk functions (the Dask tasks)
# ---------------------------------------------------------------------------

def classify(alpha, rho, tol, marginal_tol):
    r"""
    The stability class of each point from the largest real part
    ``alpha`` and the largest modulus ``rho`` of its characteristic roots:
    ``2`` asymptotically stable (`\alpha < -\mathrm{tol}\,\rho`), ``1``
    stable in first approximation (`|\alpha|` within the tolerances: the
    roots of largest real part on the imaginary axis), ``0`` unstable
    (`\alpha > \mathrm{marginal\_tol}\,\rho`), ``-1`` where the system is
    not defined (``nan``).

    EXAMPLES::

        sage: from sage_dynsym.scale.kernel import classify
        sage: import numpy as np
        sage: classify(np.array([-1., 0., 1e-12, 0.5, np.nan]), np.ones(5), 1e-9, 1e-7)
        array([ 2,  1,  1,  0, -1], dtype=int8)
    """
    classes = np.full(np.shape(alpha), -1, dtype=np.int8)
    with np.errstate(invalid='ignore'):
        classes[alpha > marginal_tol * rho] = 0
        classes[(alpha >= -tol * rho) & (alpha <= marginal_tol * rho)] = 1
        classes[alpha < -tol * rho] = 2
    return classes


def stability_class(roots, tol=1e-9, marginal_tol=1e-7):
    r"""
    The stability class of one set of characteristic roots (or of the
    eigenvalues of a square matrix): ``2`` asymptotically stable, ``1``
    stable in first approximation, ``0`` unstable (see :func:`classify`);
    for the functions of a :func:`~sage_dynsym.scale.sweeps.sweep`.

    INPUT:

    - ``roots`` -- a 1-D array of complex numbers, or a square matrix
      (2-D array) whose eigenvalues are taken
    - ``tol``, ``marginal_tol`` -- the tolerances, relative to the largest
      modulus

    EXAMPLES::

        sage: from sage_dynsym.scale.kernel import stability_class
        sage: import numpy as np
        sage: stability_class([-1, -2 + 1j, -2 - 1j]), stability_class(np.array([[0, 1], [-1, 0]]))
        (2, 1)
        sage: stability_class([0.1, -3])
        0

    TESTS::

        sage: stability_class("roots")
        Traceback (most recent call last):
        ...
        AnalysisError: stability_class: expected characteristic roots (a 1-D array of numbers) or a square matrix
    """
    try:
        roots = np.asarray(roots)
        if roots.ndim == 2 and roots.shape[0] == roots.shape[1]:
            roots = np.linalg.eigvals(roots.astype(float))
        roots = roots.astype(complex)
    except (TypeError, ValueError) as error:
        roots = error
    if isinstance(roots, Exception) or roots.ndim != 1:
        # imported here: the kernels run on workers that may lack the package
        from sage_dynsym.errors import AnalysisError
        raise AnalysisError("stability_class: expected characteristic roots (a 1-D array of "
                            "numbers) or a square matrix") from (
                                roots if isinstance(roots, Exception) else None)
    if not len(roots):
        return 2
    alpha, rho = roots.real.max(), np.abs(roots).max()
    return int(classify(np.array([alpha]), np.array([rho]), tol, marginal_tol)[0])


def map_chunk(task, start, stop):
    r"""
    The largest real part of the characteristic roots, the verdict and the
    stability class at the points ``start .. stop - 1`` of a stability map.

    ``task`` is a dict: ``points`` (a point specification), ``method``
    (``'polynomial'`` or ``'eigvals'``), ``program`` (the coefficients of
    the characteristic polynomial, highest degree first; or the entries of
    `J` then of `B`, row by row), ``size`` (the order `k` of the pencil),
    ``lhs`` (whether `B` is given), ``tol`` and ``marginal_tol`` (default
    `10^{-7}`). A point is asymptotically stable when ``alpha < -tol *
    rho``; its class is that of :func:`classify`.

    OUTPUT: ``(alpha, stable, classes)``, arrays of length ``stop - start``

    EXAMPLES: `\lambda^2 + c\lambda + 1` for `c = -1, 0, 1`::

        sage: from sage_dynsym.scale.kernel import map_chunk
        sage: task = dict(points=('grid', [[-1., 0., 1.]]), method='polynomial', tol=1e-9,
        ....:             program=([('input', 0), ('const', 1.0)], [1, 0, 1], [[], []]))
        sage: map_chunk(task, 0, 3)
        (array([ 0.5,  0. , -0.5]), array([False, False,  True]), array([0, 1, 2], dtype=int8))
    """
    alpha = np.empty(stop - start)
    rho = np.empty(stop - start)
    stable = np.empty(stop - start, dtype=bool)
    for a in range(start, stop, BATCH):
        b = min(stop, a + BATCH)
        values = run_program(task['program'], chunk_points(task['points'], a, b), b - a)
        if task['method'] == 'polynomial':
            al, rh = polynomial_abscissa(np.stack(values, axis=1))
        else:
            k = task['size']
            J = np.stack(values[:k * k], axis=1).reshape(b - a, k, k)
            B = np.stack(values[k * k:], axis=1).reshape(b - a, k, k) if task['lhs'] else None
            al, rh = pencil_abscissa(J, B)
        alpha[a - start:b - start], rho[a - start:b - start] = al, rh
        with np.errstate(invalid='ignore'):
            stable[a - start:b - start] = al < -task['tol'] * rh
    return alpha, stable, classify(alpha, rho, task['tol'], task.get('marginal_tol', 1e-7))


def sweep_chunk(task, start, stop):
    r"""
    The user's function at the points ``start .. stop - 1`` of a sweep.

    ``task`` is a dict: ``points``, ``names`` (the keyword of each
    parameter), ``fixed`` (other keyword arguments), ``function`` and
    ``vectorized`` (call once with arrays instead of once per point).

    OUTPUT: a list of results (one per point), or the function's result on
    the arrays; a failure at a point is returned as
    ``('__sweep_failure__', point, error class name, message)``

    EXAMPLES::

        sage: from sage_dynsym.scale.kernel import sweep_chunk
        sage: task = dict(points=('grid', [[1., 2.], [10., 20.]]), names=['a', 'b'],
        ....:             fixed={'c': 100}, function=lambda a, b, c: a + b + c, vectorized=False)
        sage: sweep_chunk(task, 1, 4)
        [121.0, 112.0, 122.0]
        sage: task['function'] = lambda a, b, c: a / (b - 20)
        sage: sweep_chunk(task, 0, 4)[1]
        ('__sweep_failure__', {'a': 1.0, 'b': 20.0}, 'ZeroDivisionError', 'float division by zero')
    """
    columns = chunk_points(task['points'], start, stop)
    names, fixed, function = task['names'], task['fixed'], task['function']
    if task['vectorized']:
        return function(**dict(zip(names, columns)), **fixed)
    results = []
    for values in zip(*columns):
        point = {name: float(v) for name, v in zip(names, values)}
        try:
            results.append(function(**point, **fixed))
        except Exception as err:       # reported with the point by the caller
            results.append(('__sweep_failure__', point, type(err).__name__, str(err)))
    return results


def identity(value):
    r"""``value`` itself (a Dask task holding the data shared by the chunks).

    EXAMPLES::

        sage: from sage_dynsym.scale.kernel import identity
        sage: identity({'a': 1})
        {'a': 1}
    """
    return value


# ---------------------------------------------------------------------------
# Sage work on a dask.distributed worker: in a child process of the worker
# ---------------------------------------------------------------------------

#: The name in ``sys.modules`` of the record of a worker's child processes:
#: the functions here arrive by value, with fresh globals at every task, so
#: what a worker keeps across tasks is kept there.
CHILDREN = '_sage_dynsym_children'


def send_message(stream, data):
    r"""
    Write the bytes ``data`` to the binary ``stream``, preceded by their
    length (8 bytes, big-endian), and flush it.

    EXAMPLES::

        sage: import io
        sage: from sage_dynsym.scale.kernel import send_message, receive_message
        sage: s = io.BytesIO(); send_message(s, b'abc'); send_message(s, b'')
        sage: s.seek(0); receive_message(s), receive_message(s), receive_message(s)
        0
        (b'abc', b'', None)
    """
    stream.write(len(data).to_bytes(8, 'big') + data)
    stream.flush()


def receive_message(stream):
    r"""
    The bytes of the next message of :func:`send_message` on ``stream``;
    ``None`` when the stream ends before a message starts.

    A message cut in the middle is an ``EOFError`` (its writer died).

    EXAMPLES: see :func:`send_message`. TESTS::

        sage: import io
        sage: from sage_dynsym.scale.kernel import receive_message
        sage: receive_message(io.BytesIO(int(5).to_bytes(int(8), 'big') + b'ab'))
        Traceback (most recent call last):
        ...
        EOFError: a message of 5 bytes ends after 2
    """
    head = stream.read(8)
    if not head:
        return None
    if len(head) < 8:
        raise EOFError(f"the length of a message ends after {len(head)} of its 8 bytes")
    size = int.from_bytes(head, 'big')
    data = stream.read(size)
    if len(data) != size:
        raise EOFError(f"a message of {size} bytes ends after {len(data)}")
    return data


def in_child_process(call, code):
    r"""
    The reply of a child process of this one to the message ``call``: a
    task of a ``dask.distributed`` worker whose work must run in the main
    thread of a process (Sage's PARI), which a worker's task thread is not.

    The children are Python processes started by this function
    (``python -c code``, with this process's ``sys.path``), kept in this
    process across tasks -- one per task running at the same time, so each
    imports Sage once -- and reused. A child reads its messages on its
    standard input and writes its replies on its standard output; it ends
    when its input closes, i.e. when this process ends. They are not made
    by :mod:`multiprocessing`, whose children a worker (a daemonic process)
    may not have, and which would import the worker's main module again.

    INPUT:

    - ``call`` -- bytes, sent to the child as they are
    - ``code`` -- the Python code a child runs (its loop of messages)

    OUTPUT: ``('reply', bytes)``, or ``('lost', text)`` when the child
    died before replying (a fresh one serves the next task)

    EXAMPLES: a child that echoes its messages reversed::

        sage: from sage_dynsym.scale.kernel import in_child_process
        sage: echo = ("import sys; from sage_dynsym.scale.kernel import send_message, receive_message\n"
        ....:         "for m in iter(lambda: receive_message(sys.stdin.buffer), None):\n"
        ....:         "    send_message(sys.stdout.buffer, m[::-1])")
        sage: in_child_process(b'abc', echo), in_child_process(b'de', echo)
        (('reply', b'cba'), ('reply', b'ed'))
        sage: in_child_process(b'abc', 'import os; os._exit(3)')
        ('lost', 'the child process ... of this worker ended (exit code 3) before replying')
    """
    import os
    import subprocess
    import sys
    import threading
    import types
    kept = sys.modules.get(CHILDREN)
    if kept is None:
        kept = types.ModuleType(CHILDREN)
        kept.lock, kept.idle = threading.Lock(), {}
        kept = sys.modules.setdefault(CHILDREN, kept)
    with kept.lock:
        idle = kept.idle.setdefault(code, [])
        child = idle.pop() if idle else None
    if child is None:
        path = os.pathsep.join(p for p in sys.path if p)
        child = subprocess.Popen([sys.executable, '-c', code], stdin=subprocess.PIPE,
                                 stdout=subprocess.PIPE, env=dict(os.environ, PYTHONPATH=path))
    try:
        send_message(child.stdin, call)
        reply = receive_message(child.stdout)
    except (OSError, EOFError):
        reply = None
    if reply is None:
        child.kill()
        child.wait()
        return ('lost', f"the child process {child.pid} of this worker ended (exit code "
                        f"{child.returncode}) before replying")
    with kept.lock:
        kept.idle[code].append(child)
    return ('reply', reply)

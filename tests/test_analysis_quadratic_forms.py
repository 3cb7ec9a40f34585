"""Sylvester's criterion, restriction to a subspace and simultaneous
reduction, against numerical eigenvalues; non-symmetric input rejected."""
import random

import numpy as np
import pytest
from sage.all import SR, QQ, RDF, var, matrix, identity_matrix

from sage_dynsym.analysis import (sylvester_conditions, restrict_to_subspace,
                                  simultaneous_reduction)
from sage_dynsym.errors import AnalysisError


def holds(conds, pt):
    return all(float(SR(c).subs(pt)) > 0 for c in conds)


@pytest.mark.parametrize("n", [2, 3])
def test_sylvester_against_eigenvalues(n):
    a = [[SR.var('a%d%d' % (min(i, j), max(i, j))) for j in range(n)] for i in range(n)]
    A = matrix(SR, a)
    pos = sylvester_conditions(A)
    neg = sylvester_conditions(A, sign='negative')
    rng = random.Random(n)
    seen = set()
    for _ in range(100):
        vals = {}
        for i in range(n):
            for j in range(i, n):
                vals[a[i][j]] = QQ(rng.uniform(-1, 1) if i != j else rng.uniform(-2, 2))
        ev = np.linalg.eigvalsh(A.subs(vals).change_ring(RDF).numpy())
        assert holds(pos, vals) == bool(np.all(ev > 0))
        assert holds(neg, vals) == bool(np.all(ev < 0))
        seen.add((bool(np.all(ev > 0)), bool(np.all(ev < 0))))
    assert len(seen) == 3


def test_form_given_as_expression():
    x, y, a, b = var('x y a b')
    assert sylvester_conditions(a * x**2 + 2 * x * y + b * y**2, [x, y]) == [a, a * b - 1]


def test_non_symmetric_matrix_is_an_error():
    with pytest.raises(AnalysisError, match="symmetric"):
        sylvester_conditions(matrix([[1, 2], [0, 1]]))
    x, y = var('x y')
    with pytest.raises(AnalysisError, match="not a quadratic form"):
        sylvester_conditions(x**2 + y, [x, y])


def test_restriction_is_definite_on_subspace():
    x, y, z = var('x y z')
    form, free = restrict_to_subspace(x**2 - y**2 + z**2 + 4 * x * y, [x - y], [x, y, z])
    # on x = y the form is 4 y^2 + z^2
    assert (form - (4 * y**2 + z**2)).expand() == 0 and free == [y, z]


def test_simultaneous_reduction():
    rng = random.Random(9)
    for _ in range(5):
        C = matrix(QQ, 2, 2, [QQ(rng.randint(-3, 3)) for _ in range(4)])
        B = C.transpose() * C + identity_matrix(QQ, 2)
        A = matrix(QQ, 2, 2, [QQ(rng.randint(-3, 3)) for _ in range(4)])
        A = A + A.transpose()
        mu, T = simultaneous_reduction(A, B)
        assert (T.transpose() * B * T - identity_matrix(2)).simplify_full().is_zero()
        D = (T.transpose() * A * T).simplify_full()
        assert D.is_diagonal()
        num = sorted(np.linalg.eigvals(np.linalg.solve(B.change_ring(RDF).numpy(),
                                                       A.change_ring(RDF).numpy())).real)
        assert np.allclose(sorted(float(m) for m in mu), num)

"""Sylvester's criterion with denominators of unknown sign, cross-checked
against numpy eigenvalues at random points (issue 9).

Random symmetric 2x2 and 3x3 matrices whose entries are rational functions
of a, b (, c) with denominators such as (a - b) and (a*b - 1), whose sign is
not known. At random rational points (away from the zero sets of the
denominators and from singular matrices) the conditions returned by
``definiteness_conditions`` / ``sylvester_conditions`` must hold exactly
when numpy says all eigenvalues are > 0 (resp. < 0 for sign='negative').
The reference is numpy's ``eigvalsh`` on the matrix evaluated by plain
substitution: nothing computed by the code under test.
"""
import random

import numpy as np
import pytest
from sage.all import SR, QQ, var, matrix

from sage_dynsym.algebra.conditions import holds
from sage_dynsym.analysis.quadratic_forms import definiteness_conditions, sylvester_conditions

a, b, c = var('a b c')
SYMBOLS = [a, b, c]
# denominators whose sign changes inside the sampled box
DENOMINATORS = [a - b, a * b - 1, a + c - 2, b - c, a**2 - 2 * c]
# (size, symbols in the numerators, denominators, probability of a denominator)
KINDS = {2: ([a, b, c, a * b], DENOMINATORS, 0.5),
         3: ([a, b], [a - b, a * b - 1], 0.4)}


def random_entry(rng, n, diagonal):
    """A random rational function: an integer-coefficient numerator (a
    positive constant shift on the diagonal makes definite matrices
    frequent enough), over a denominator of unknown sign with the
    probability of KINDS[n]."""
    monomials, denominators, p = KINDS[n]
    num = rng.randint(-2, 2) + sum(rng.randint(-2, 2) * m for m in monomials)
    if diagonal:
        num += rng.randint(1, 4) if n == 2 else rng.randint(3, 7)
    if rng.random() < p:
        num = num / rng.choice(denominators)
    return SR(num)


def random_matrix(rng, n):
    A = matrix(SR, n, n)
    for i in range(n):
        for j in range(i, n):
            A[i, j] = A[j, i] = random_entry(rng, n, i == j)
    return A


def random_point(rng, positive_a=False):
    """A random rational point with every denominator safely nonzero."""
    while True:
        vals = {s: QQ(rng.randint(-24, 24)) / 8 for s in SYMBOLS}
        if positive_a:
            vals[a] = QQ(rng.randint(1, 24)) / 8
        if all(abs(float(d.subs(vals))) > 0.1 for d in DENOMINATORS):
            return vals


def numeric_definiteness(A, vals):
    """(positive definite, negative definite) by numpy, or None when the
    matrix is too close to singular to decide numerically."""
    M = np.array([[float(SR(e).subs(vals)) for e in row] for row in A.rows()])
    ev = np.linalg.eigvalsh(M)
    if np.min(np.abs(ev)) < 1e-6 * max(1.0, np.max(np.abs(ev))):
        return None
    return bool(np.all(ev > 0)), bool(np.all(ev < 0))


def conditions_hold(conds, vals):
    return conds is not None and all(holds(cnd, vals) for cnd in conds)


def expressions_positive(exprs, vals):
    return all(float(SR(e).subs(vals)) > 0 for e in exprs)


def cross_check(seed, sizes, n_matrices, points, function, positive_a=False):
    """Mismatches between ``function`` (definiteness_conditions with
    relationals, or sylvester_conditions with expressions > 0) and numpy,
    and how many definite / not definite cases were seen."""
    rng = random.Random(seed)
    positive = [a] if positive_a else []
    check = conditions_hold if function is definiteness_conditions else expressions_positive
    mismatches, seen = [], {True: 0, False: 0}
    for k in range(n_matrices):
        A = random_matrix(rng, sizes[k % len(sizes)])
        conds = {s: function(A, sign=s, positive=positive) for s in ('positive', 'negative')}
        for _ in range(points):
            vals = random_point(rng, positive_a)
            ref = numeric_definiteness(A, vals)
            if ref is None:
                continue
            for sign, expected in zip(('positive', 'negative'), ref):
                seen[expected] += 1
                if check(conds[sign], vals) != expected:
                    mismatches.append((sign, A, vals, expected, conds[sign]))
    return mismatches, seen


# random matrices against NumPy's eigenvalues: `make test-slow` (CI); in
# `make test` the two tests below (a declared sign, Sylvester's conditions)
@pytest.mark.slow
@pytest.mark.parametrize("seed,sizes,n", [(901, (2,), 80), (902, (3,), 80), (903, (2, 3), 40)])
def test_definiteness_conditions_agree_with_eigenvalues(seed, sizes, n):
    mismatches, seen = cross_check(seed, sizes, n, 6, definiteness_conditions)
    # the sample must contain both definite and indefinite cases
    assert seen[True] >= 40 and seen[False] >= 40, seen
    assert not mismatches, mismatches[:3]


def test_definiteness_with_a_declared_positive():
    # declarations may simplify the conditions, never change their truth
    # where the declarations hold
    mismatches, seen = cross_check(904, (2, 3), 30, 5, definiteness_conditions,
                                   positive_a=True)
    assert seen[True] >= 10 and seen[False] >= 10, seen
    assert not mismatches, mismatches[:3]


def test_sylvester_conditions_agree_with_eigenvalues():
    # diag(1, a/b^2) is positive definite iff a > 0 and b != 0: at a = b = 1
    # every expression returned must be positive
    A = matrix(SR, [[1, 0], [0, a / b**2]])
    assert expressions_positive(sylvester_conditions(A), {a: 1, b: 1})
    mismatches, seen = cross_check(905, (2,), 40, 5, sylvester_conditions)
    assert seen[True] >= 20 and seen[False] >= 20, seen
    assert not mismatches, mismatches[:3]


def test_hand_checked_denominators():
    # [[1, b], [b, b^2 + a/g]] has the leading minors 1 and a/g: positive
    # definite iff a*g > 0 (Gantmacher, The Theory of Matrices, ch. X,
    # Sylvester's criterion); -A is then negative definite
    g = var('g')
    A = matrix(SR, [[1, b], [b, b**2 + a / g]])
    pos = definiteness_conditions(A)
    neg = definiteness_conditions(-A, sign='negative')
    for av, gv in [(1, 2), (1, -2), (-1, 2), (-1, -2)]:
        vals = {a: QQ(av), b: QQ(3), g: QQ(gv)}
        assert conditions_hold(pos, vals) == (av * gv > 0)
        assert conditions_hold(neg, vals) == (av * gv > 0)
    # the identity is always definite, diag(1, -1) never
    assert definiteness_conditions(matrix(SR, [[1, 0], [0, 1]])) == []
    assert definiteness_conditions(matrix(SR, [[1, 0], [0, -1]])) is None
    assert definiteness_conditions(matrix(SR, [[1, 0], [0, -1]]), sign='negative') is None

"""Three-class stability maps: 2 asymptotically stable, 1 stable in first
approximation, 0 unstable. The classes are checked against numpy
eigenvalues of the state matrix computed here, against the classical
gyroscopic stabilization condition 2g > sqrt(a) + sqrt(b) (Merkin, ch. 6),
and per class against the exact verdict regions, off a boundary band."""
import numpy as np
from sage.all import SR, var, matrix, identity_matrix, zero_matrix, diagonal_matrix

from sage_dynsym.analysis import kelvin_chetaev
from sage_dynsym.analysis.linear import LinearSystem
from sage_dynsym.scale import stability_map, sweep, stability_class
from sage_dynsym.scale.maps import CLASS_NAMES

x, y = var('x y')
I2, Z = identity_matrix(SR, 2), zero_matrix(SR, 2)
J = matrix([[0, 1], [-1, 0]])


def numpy_classes(M, S, W, keys, axes):
    """The class of each grid point from numpy eigenvalues (None near the
    imaginary axis but not on it)."""
    out = np.empty((len(axes[0]), len(axes[1])), dtype=object)
    for i, u in enumerate(axes[0]):
        for j, v in enumerate(axes[1]):
            pt = {keys[0]: float(u), keys[1]: float(v)}
            Mn, Sn, Wn = (X.subs(pt).numpy(dtype=float) for X in (M, S, W))
            Mi = np.linalg.inv(Mn)
            A = np.block([[np.zeros((2, 2)), np.eye(2)], [-Mi @ Wn, -Mi @ Sn]])
            ev = np.linalg.eigvals(A)
            top, rho = ev.real.max(), np.abs(ev).max()
            out[i, j] = 2 if top < -1e-6 * rho else 0 if top > 1e-6 * rho else \
                (1 if abs(top) < 1e-12 * rho else None)
    return out


def test_circulatory_map_in_three_classes():
    d, p = var('d p')
    K, P, D = diagonal_matrix([1, 2]), p * J, d * I2
    lin = LinearSystem([x, y], M=I2, S=D, W=K + P)
    S = stability_map(lin, {d: (-0.5, 1, 31), p: (-2, 2, 31)}, client=False)
    assert set(np.unique(S.classes())) == {0, 1, 2}
    assert np.array_equal(S.classes() == 2, S.stable())
    truth = numpy_classes(I2, D, K + P, [d, p], [S.axes()[d], S.axes()[p]])
    known = np.vectorize(lambda c: c is not None)(truth)
    assert (S.classes()[known] == truth[known].astype(int)).all()
    # the same with the eigenvalues of the matrices
    T = stability_map(lin, {d: (-0.5, 1, 31), p: (-2, 2, 31)}, client=False, method='eigvals')
    assert (T.classes()[known] == truth[known].astype(int)).all()
    # per class against the exact verdict, off a band of one step
    v = kelvin_chetaev(I2, D, Z, K, P)
    agree = S.agreement(v, by_class=True, band=1)
    assert agree[0] == 1.0 and agree[2] == 1.0
    assert np.isnan(agree[1])                # class 1 exactly only on the line d = 0
    # there: below the flutter load |p| < 1/2 (the discriminant 1 - 4 p^2 of
    # mu^2 + 3 mu + 2 + p^2), stable in first approximation
    i = int(np.argmin(np.abs(S.axes()[d])))
    assert S.axes()[d][i] == 0
    for j, pv in enumerate(S.axes()[p]):
        if abs(abs(pv) - 0.5) > 1e-9:
            assert S.classes()[i, j] == (1 if abs(pv) < 0.5 else 0)


def test_gyroscopic_stabilization_map():
    a, g = var('a g')
    G, K = g * J, diagonal_matrix([-a, -1])
    lin = LinearSystem([x, y], M=I2, S=2 * G, W=K)
    S = stability_map(lin, {a: (0.05, 3, 30), g: (0, 2, 30)}, client=False, classes='spectrum')
    A, Gv = np.meshgrid(S.axes()[a], S.axes()[g], indexing='ij')
    classical = 2 * Gv > np.sqrt(A) + 1           # Merkin: 2g > sqrt(a) + sqrt(b)
    margin = np.abs(2 * Gv - np.sqrt(A) - 1) > 0.05
    assert np.array_equal((S.classes() == 1)[margin], classical[margin])
    assert (S.classes()[~classical & margin] == 0).all()
    assert S.agreement(by_class=True, band=1)[1] == 1.0
    labels = {prim.options().get('legend_label') for prim in S.plot()}
    assert {CLASS_NAMES[2], CLASS_NAMES[1], CLASS_NAMES[0]} & labels == \
        {CLASS_NAMES[1], CLASS_NAMES[0]}


def test_classes_are_saved(tmp_path):
    c = var('c')
    S = stability_map(LinearSystem([x, y], J=[[0, 1], [-1, -c]]), {c: (-1, 1, 5)},
                      client=False)
    S.save(tmp_path / 'm.npz')
    data = np.load(tmp_path / 'm.npz')
    assert data['classes'].tolist() == [0, 0, 1, 2, 2]


def test_sweep_of_stability_classes():
    def spring(c, k):
        return stability_class(np.array([[0, 1], [-k, -c]]))
    W = sweep(spring, {'c': (-1, 1, 9), 'k': (-1, 1, 9)}, client=False)
    C, K = np.meshgrid(np.linspace(-1, 1, 9), np.linspace(-1, 1, 9), indexing='ij')
    # x'' + c x' + k x: 2 iff c, k > 0; 1 on c = 0 < k and on k = 0 <= c; 0 else
    expected = np.where((C > 0) & (K > 0), 2, np.where(((C == 0) & (K > 0)) |
                                                        ((K == 0) & (C >= 0)), 1, 0))
    assert np.array_equal(W.values(), expected)
    assert len(W.plot()) == 4

"""The Whipple bicycle of examples/whipple_bicycle.yaml, linearized about
upright straight running, against the benchmark of Meijaard, Papadopoulos,
Ruina and Schwab, Proc. R. Soc. A 463 (2007) 1955-1982:

- the closed-form entries of M, C1, K0, K2 of their Appendix A, written out
  here, for symbolic parameters (an identity) and for a random set of exact
  parameters;
- the published matrices of their section 5 (14 digits), eigenvalues of
  their Table 2 and the weave and capsize speeds (14 digits), with their
  benchmark parameters of Table 1, exact rationals and lam = pi/10.
"""
import random

import pytest

from sage.all import QQ, SR, RealField, ComplexField, PolynomialRing, cos, sin, pi, matrix

from sage_dynsym import load, linearize, hurwitz_conditions, LinearSystem
from sage_dynsym.description import example_path
from sage_dynsym.algebra.trigonometric import trig_rational_simplify

def _q(text):
    # a decimal of Table 1, exactly
    return QQ(Rational_from_decimal(text))


def Rational_from_decimal(text):
    sign = -1 if text.startswith('-') else 1
    whole, _, fraction = text.lstrip('-').partition('.')
    return sign * QQ(int(whole + fraction)) / 10 ** len(fraction)


PARAMETERS = "w c lam g rR mR IRxx IRyy xB zB mB IBxx IByy IBzz IBxz xH zH mH IHxx IHyy IHzz " \
             "IHxz rF mF IFxx IFyy v".split()

#: Table 1 of Meijaard et al. (2007), exact (lam = pi/10)
BENCHMARK = dict(w=_q('1.02'), c=_q('0.08'), lam=pi / 10, g=_q('9.81'), rR=_q('0.3'), mR=2,
                 IRxx=_q('0.0603'), IRyy=_q('0.12'), xB=_q('0.3'), zB=_q('-0.9'), mB=85,
                 IBxx=_q('9.2'), IByy=11, IBzz=_q('2.8'), IBxz=_q('2.4'), xH=_q('0.9'),
                 zH=_q('-0.7'), mH=4, IHxx=_q('0.05892'), IHyy=_q('0.06'), IHzz=_q('0.00708'),
                 IHxz=_q('-0.00756'), rF=_q('0.35'), mF=3, IFxx=_q('0.1405'), IFyy=_q('0.28'))

#: Section 5 of the paper (after eq. (5.3)): the published matrices
PUBLISHED = {
    'M': [[80.81722, 2.31941332208709], [2.31941332208709, 0.29784188199686]],
    'C1': [[0, 33.86641391492494], [-0.85035641456978, 1.68540397397560]],
    'K0': [[-80.95, -2.59951685249872], [-2.59951685249872, -0.80329488458618]],
    'K2': [[0, 76.59734589573222], [0, 2.65431523794604]],
}

#: Table 2 of the paper: eigenvalues at the forward speeds 0, 1, ..., 10 m/s
#: (the capsize mode, the weave pair, the castering mode); the same numbers
#: as the tests of the bicycle models of SymPy's and D. L. Peterson's suites
TABLE2 = {
    0: [-3.13164324790656, 3.13164324790656, -5.53094371765393, 5.53094371765393],
    1: [-3.13423125066578, (3.52696170990070, 0.8077402751993), -7.11008014637442],
    2: [-3.07158645641514, (2.68234517512745, 1.68066296590675), -8.67387984831735],
    3: [-2.63366137253667, (1.70675605663975, 2.31582447384325), -10.35101467245920],
    4: [-1.42944427361326, (0.41325331521125, 3.07910818603206), -12.15861426576450],
    5: [-0.32286642900409, (-0.77534188219585, 4.46486771378823), -14.07838969279820],
    6: [-0.00406690076970, (-1.52644486584142, 5.87673060598709), -16.08537123098030],
    7: [0.10268170574766, (-2.13875644258362, 7.19525913329805), -18.15788466125262],
    8: [0.14327879765713, (-2.69348683581097, 8.46037971396931), -20.27940894394569],
    9: [0.15790184030917, (-3.21675402252485, 9.69377351531791), -22.43788559040858],
    10: [0.16105338653172, (-3.72016840437287, 10.90681139476287), -24.62459635017404],
}

#: Table 2 (a): the weave and capsize speeds
WEAVE_SPEED, CAPSIZE_SPEED = 4.29238253634111, 6.02426201538837


def closed_form(p):
    r"""M, C1, K0, K2 from Appendix A of Meijaard et al. (2007), eqs. (A1)-(A27),
    for a dict ``p`` of the parameters of Table 1 (symbols or values)."""
    lam = p['lam']
    mT = p['mR'] + p['mB'] + p['mH'] + p['mF']
    xT = (p['xB'] * p['mB'] + p['xH'] * p['mH'] + p['w'] * p['mF']) / mT
    zT = (-p['rR'] * p['mR'] + p['zB'] * p['mB'] + p['zH'] * p['mH'] - p['rF'] * p['mF']) / mT
    ITxx = (p['IRxx'] + p['IBxx'] + p['IHxx'] + p['IFxx'] + p['mR'] * p['rR'] ** 2
            + p['mB'] * p['zB'] ** 2 + p['mH'] * p['zH'] ** 2 + p['mF'] * p['rF'] ** 2)
    ITxz = (p['IBxz'] + p['IHxz'] - p['mB'] * p['xB'] * p['zB'] - p['mH'] * p['xH'] * p['zH']
            + p['mF'] * p['w'] * p['rF'])
    IRzz, IFzz = p['IRxx'], p['IFxx']
    ITzz = (IRzz + p['IBzz'] + p['IHzz'] + IFzz + p['mB'] * p['xB'] ** 2
            + p['mH'] * p['xH'] ** 2 + p['mF'] * p['w'] ** 2)
    mA = p['mH'] + p['mF']
    xA = (p['xH'] * p['mH'] + p['w'] * p['mF']) / mA
    zA = (p['zH'] * p['mH'] - p['rF'] * p['mF']) / mA
    IAxx = (p['IHxx'] + p['IFxx'] + p['mH'] * (p['zH'] - zA) ** 2
            + p['mF'] * (p['rF'] + zA) ** 2)
    IAxz = (p['IHxz'] - p['mH'] * (p['xH'] - xA) * (p['zH'] - zA)
            + p['mF'] * (p['w'] - xA) * (p['rF'] + zA))
    IAzz = p['IHzz'] + IFzz + p['mH'] * (p['xH'] - xA) ** 2 + p['mF'] * (p['w'] - xA) ** 2
    uA = (xA - p['w'] - p['c']) * cos(lam) - zA * sin(lam)
    IAll = (mA * uA ** 2 + IAxx * sin(lam) ** 2 + 2 * IAxz * sin(lam) * cos(lam)
            + IAzz * cos(lam) ** 2)
    IAlx = -mA * uA * zA + IAxx * sin(lam) + IAxz * cos(lam)
    IAlz = mA * uA * xA + IAxz * sin(lam) + IAzz * cos(lam)
    mu = p['c'] / p['w'] * cos(lam)
    SR_, SF = p['IRyy'] / p['rR'], p['IFyy'] / p['rF']
    ST = SR_ + SF
    SA = mA * uA + mu * mT * xT
    M = [[ITxx, IAlx + mu * ITxz], [IAlx + mu * ITxz, IAll + 2 * mu * IAlz + mu ** 2 * ITzz]]
    K0 = [[mT * zT, -SA], [-SA, -SA * sin(lam)]]
    K2 = [[0, (ST - mT * zT) / p['w'] * cos(lam)], [0, (SA + SF * sin(lam)) / p['w'] * cos(lam)]]
    C1 = [[0, mu * ST + SF * cos(lam) + ITxz / p['w'] * cos(lam) - mu * mT * zT],
          [-(mu * ST + SF * cos(lam)), IAlz / p['w'] * cos(lam)
           + mu * (SA + ITzz / p['w'] * cos(lam))]]
    return {'M': matrix(SR, M), 'C1': matrix(SR, C1), 'K0': matrix(SR, K0),
            'K2': matrix(SR, K2)}


@pytest.fixture(scope="module")
def bicycle():
    S = load(example_path('whipple_bicycle.yaml'))
    lean, steer = SR.var('lean'), SR.var('steer')
    linear = linearize(S, S.operating_point('upright'), coordinates=[lean, steer])
    v, g = SR.var('v'), SR.var('g')
    # M q'' + v C1 q' + (g K0 + v^2 K2) q = 0
    W = linear.W()
    return {'system': S, 'linear': linear, 'M': linear.M(),
            'C1': linear.S().apply_map(lambda e: e.diff(v)),
            'K0': W.apply_map(lambda e: e.diff(g)),
            'K2': W.apply_map(lambda e: e.diff(v, 2) / 2),
            'S': linear.S(), 'W': W}


def test_the_description_follows_the_paper(bicycle):
    S = bicycle['system']
    assert [str(p) for p in S.parameters()] == PARAMETERS
    assert {'lean', 'steer'} <= {str(q) for q in S.coordinates()}
    contacts = S.constraint_set().contacts()
    # the rear contact is held by the coordinates; the front one is holonomic
    assert contacts[0].imposed_by_coordinates()
    assert not contacts[1].imposed_by_coordinates()
    assert len(S.nonholonomic_constraints()) == 4 and len(S.constraints()) == 1


def test_the_structure_of_the_linearized_equations(bicycle):
    linear, v, g = bicycle['linear'], SR.var('v'), SR.var('g')
    assert [str(x) for x in linear.variables()] == ['lean', 'steer']
    # S is v C1 and W is g K0 + v^2 K2: nothing else
    assert all(trig_rational_simplify(e - v * c).is_zero()
               for e, c in zip(bicycle['S'].list(), bicycle['C1'].list()))
    assert all(trig_rational_simplify(e - g * k0 - v ** 2 * k2).is_zero()
               for e, k0, k2 in zip(bicycle['W'].list(), bicycle['K0'].list(),
                                    bicycle['K2'].list()))
    motion = linear.steady_motion()
    assert [str(q) for q in motion.dropped()] == ['x', 'y', 'yaw', 'thetaR', 'thetaF']
    assert motion.dependent_coordinates() == {SR.var('pitch'): 0}
    assert [str(u) for u in motion.decoupled_speeds()] == ['dthetaR']


def test_the_matrices_are_the_closed_forms_of_appendix_a(bicycle):
    # an identity in the 26 symbolic parameters
    expected = closed_form({name: SR.var(name) for name in PARAMETERS})
    for key in ('M', 'C1', 'K0', 'K2'):
        for got, want in zip(bicycle[key].list(), expected[key].list()):
            assert trig_rational_simplify(got - want).is_zero(), (key, got, want)


def test_a_random_parameter_set_gives_the_closed_forms(bicycle):
    rng = random.Random(24)
    values = {name: QQ((rng.randint(1, 400), rng.randint(1, 97))) for name in PARAMETERS}
    values['zB'], values['zH'], values['IHxz'] = -values['zB'], -values['zH'], -values['IHxz']
    values['lam'] = QQ((rng.randint(1, 9), 13))
    expected = closed_form(values)
    substitution = {SR.var(k): x for k, x in values.items()}
    for key in ('M', 'C1', 'K0', 'K2'):
        for got, want in zip(bicycle[key].list(), expected[key].list()):
            assert trig_rational_simplify(SR(got).subs(substitution) - want).is_zero(), (key, got)


def _benchmark(X):
    return X.subs({SR.var(k): x for k, x in BENCHMARK.items()})


def test_the_published_matrices_to_14_digits(bicycle):
    RF = RealField(200)
    for key, rows in PUBLISHED.items():
        got = _benchmark(bicycle[key])
        for i in range(2):
            for j in range(2):
                assert abs(RF(got[i, j]) - RF(rows[i][j])) < 1e-14, (key, i, j, got[i, j])


def _characteristic(bicycle):
    r"""The characteristic polynomial with the benchmark values, cos(lam)
    and sin(lam) kept as the symbols cl, sl (the Hurwitz conditions want
    coefficients rational in the parameters), and their values."""
    cl, sl, lam = SR.var('cl'), SR.var('sl'), SR.var('lam')
    trig = {cos(lam): cl, sin(lam): sl}
    exact = {SR.var(k): x for k, x in BENCHMARK.items() if k != 'lam'}
    M, S, W = (X.subs(exact).subs(trig) for X in (bicycle['M'], bicycle['S'], bicycle['W']))
    x = SR.var('x')
    poly = LinearSystem([SR.var('lean'), SR.var('steer')], M=M, S=S, W=W) \
        .characteristic_polynomial(x)
    RF = RealField(300)
    return poly, x, {cl: RF(pi / 10).cos(), sl: RF(pi / 10).sin()}


def test_the_eigenvalues_of_table_2(bicycle):
    poly, x, trig = _characteristic(bicycle)
    CF = ComplexField(300)
    R = PolynomialRing(CF, 'z')
    # the table has 14 decimals, computed in double precision: the entries
    # of modulus above 10 carry errors of some 1e-13 (up to 6e-13 at v = 7,
    # where the exact value is -18.157884661252021); relative to the
    # modulus, all agree to better than 4e-14
    for speed, expected in TABLE2.items():
        P = R(poly.subs(trig).subs({SR.var('v'): speed}).subs({x: R.gen()}))
        roots = P.roots(multiplicities=False)
        assert len(roots) == 4
        for value in expected:
            target = CF(*value) if isinstance(value, tuple) else CF(value)
            error = min(abs(r - target) for r in roots)
            assert error < 1e-13 * max(1, abs(target)), (speed, value, roots)


def test_the_weave_and_capsize_speeds_are_roots_of_the_hurwitz_conditions(bicycle):
    poly, x, trig = _characteristic(bicycle)
    v = SR.var('v')
    conditions = hurwitz_conditions(poly, x)
    RF = RealField(300)
    R = PolynomialRing(RF, 'u')
    roots = []
    for c in conditions:
        e = c.subs(trig)
        if e.has(v):
            roots += [r for r in R(e.subs({v: R.gen()})).roots(multiplicities=False)
                      if 0 < r < 10]
    # the stable speeds: every condition positive between two of these roots
    def stable(speed):
        return all(c.subs(trig).subs({v: speed}) > 0 for c in conditions)
    roots.sort()
    bounds = [(a, b) for a, b in zip(roots, roots[1:]) if stable((a + b) / 2)]
    assert len(bounds) == 1
    weave, capsize = bounds[0]
    # the paper's last (15th) digit comes from double precision: 14 agree
    assert abs(weave - WEAVE_SPEED) < 2e-14 and abs(capsize - CAPSIZE_SPEED) < 2e-14
    assert not stable(RF(4)) and stable(RF(5)) and not stable(RF(7))


def test_the_state_matrix_of_sympys_bicycle_test(bicycle):
    # sympy/physics/mechanics/tests/test_kane3.py (test_bicycle) compares its
    # linearized bicycle with this state matrix in (lean, steer, their rates),
    # for v = 0, ..., 5 and to 1e-12
    v = SR.var('v')
    rows = [[9.48977444677355, -0.891197738059089 * v ** 2 - 0.571523173729245,
             -0.105522449805691 * v, -0.330515398992311 * v],
            [11.7194768719633, -1.97171508499972 * v ** 2 + 30.9087533932407,
             3.67680523332152 * v, -3.08486552743311 * v]]
    M, S, W = (_benchmark(bicycle[k]) for k in ('M', 'S', 'W'))
    inverse = M.inverse()
    bottom = (-inverse * W).augment(-inverse * S)
    for speed in range(6):
        for i in range(2):
            for j in range(4):
                got = RealField(200)(bottom[i, j].subs({v: speed}))
                assert abs(got - SR(rows[i][j]).subs({v: speed})) < 1e-12, (speed, i, j)


def test_a_stability_map_in_the_speed(bicycle):
    # the linear system of the package's maps: stable on the grid points
    # between the weave and capsize speeds, and only there
    import numpy as np
    from sage_dynsym import stability_map
    v = SR.var('v')
    linear = LinearSystem([SR.var('lean'), SR.var('steer')],
                          *(_benchmark(bicycle[k]) for k in ('M', 'S', 'W')))
    speeds_map = stability_map(linear, {v: (0, 10, 201)})
    speeds, stable = speeds_map.axes()[v], speeds_map.stable()
    assert np.array_equal(stable, (speeds > WEAVE_SPEED) & (speeds < CAPSIZE_SPEED))

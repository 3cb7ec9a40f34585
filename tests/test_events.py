"""Events on trajectories: zero crossings located by the integrator, checked
against closed forms -- the period of a pendulum, 4 sqrt(l/g) K(m) with
m = sin^2(theta0/2) (scipy.special.ellipk takes the parameter m), and
points of a Poincare section on the level of an exact integral."""
import numpy as np
import pytest
from scipy.special import ellipk
from sage.all import var, sin, cos

from sage_dynsym import Lagrangian
from sage_dynsym.analysis.motion import SecondOrderEquations
from sage_dynsym.errors import ModelError
from sage_dynsym.numerics.events import Event
from sage_dynsym.numerics.simulate import simulate

th, dth, m, l, g = var('theta dtheta m l g')
PENDULUM = Lagrangian(m * l**2 * dth**2 / 2 + m * g * l * cos(th), [th])
VALUES = {m: 1.5, l: 2.0, g: 9.81}


@pytest.mark.parametrize("theta0", [0.3, 1.0, 2.5])
def test_pendulum_period_against_the_elliptic_integral(theta0):
    T = PENDULUM.simulate(VALUES, {th: theta0, dth: 0}, 12, points=5,
                          events=[Event(th, direction=-1)])
    exact = 4 * np.sqrt(2.0 / 9.81) * ellipk(np.sin(theta0 / 2)**2)
    assert abs(T.period() - exact) < 1e-8 * exact
    # the first crossing is a quarter period after the release
    assert abs(T.event_times()[0] - exact / 4) < 1e-8 * exact
    # at each crossing theta is zero to the integrator's tolerance
    assert all(abs(state[th]) < 1e-9 for _, _, state in T.events())


def test_terminal_event_ends_the_trajectory():
    T = PENDULUM.simulate(VALUES, {th: 1.0, dth: 0}, 12, points=101,
                          events=[Event(dth, direction=1, terminal=True)])
    exact = 4 * np.sqrt(2.0 / 9.81) * ellipk(np.sin(0.5)**2)
    # dtheta first increases through zero at the far turning point: half a period
    assert abs(T.times()[-1] - exact / 2) < 1e-8
    assert abs(T.final_state()[th] + 1.0) < 1e-8
    assert np.all(np.diff(T.times()) > 0)


def test_event_states_are_read_by_name_as_values_are():
    T = PENDULUM.simulate(VALUES, {th: 1.0, dth: 0}, 12, points=101,
                          events=[Event(dth, direction=1, terminal=True)])
    (_, _, state), = T.events()
    # the far turning point of a pendulum released at rest at theta = 1
    assert abs(state['theta'] + 1.0) < 1e-8 and abs(state['dtheta']) < 1e-9
    assert state['theta'] == state[th] and 'dtheta' in state and state.get('zz') is None
    assert T.final_state()['theta'] == T.values('theta')[-1]
    with pytest.raises(KeyError, match="'zz' is not a state variable"):
        state['zz']


def test_poincare_section_lies_on_an_integral():
    x, y, dx, dy, ddx, ddy = var('x y dx dy ddx ddy')
    E = SecondOrderEquations([ddx + x, ddy + 3 * y], [x, y], [dx, dy], [ddx, ddy])
    T = simulate(E, {}, {x: 1, y: 0.5, dx: 0, dy: 0.2}, 100, events=[Event(x, direction=1)])
    P = T.section([y, dy])
    # x = cos t increases through zero at t = 3 pi/2 + 2 pi k
    expected = 3 * np.pi / 2 + 2 * np.pi * np.arange(int((100 - 3 * np.pi / 2) // (2 * np.pi)) + 1)
    assert np.max(np.abs(T.event_times() - expected)) < 1e-8
    energy_y = 3 * 0.5**2 + 0.2**2
    assert np.max(np.abs(3 * P[:, 0]**2 + P[:, 1]**2 - energy_y)) < 1e-9


def test_events_with_constraints():
    # a Cartesian pendulum kept on its circle: the crossings of x = 0
    x, y, dx, dy, ddx, ddy, mu = var('x y dx dy ddx ddy mu')
    E = SecondOrderEquations([ddx - 2 * mu * x, ddy + 1 - 2 * mu * y], [x, y], [dx, dy],
                             [ddx, ddy], constraints=[x**2 + y**2 - 1], multipliers=[mu])
    x0 = np.sin(0.5)
    T = simulate(E, {}, {x: x0, y: -np.cos(0.5), dx: 0, dy: 0}, 15, points=61,
                 events=[Event(x, direction=-1)])
    exact = 4 * ellipk(np.sin(0.25)**2)
    assert abs(T.period() - exact) < 1e-7


def test_bad_events():
    with pytest.raises(ModelError, match="not a state variable"):
        PENDULUM.simulate(VALUES, {th: 1, dth: 0}, 1, events=[th - var('b')])
    with pytest.raises(ModelError, match="direction"):
        Event(th, direction='up')
    T = PENDULUM.simulate(VALUES, {th: 1, dth: 0}, 0.1, events=[th])
    with pytest.raises(ModelError, match="at least 2 crossings"):
        T.period()

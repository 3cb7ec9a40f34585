"""
Singular attitudes of a rotation chart (numerics/recursive.py): a free body
described by three translations and the (3, 2, 1) sequence of rotations
(psi about z, theta about y, phi about x). Its body angular velocity, by
hand,

    omega = (phi' - psi' sin theta,
             theta' cos phi + psi' sin phi cos theta,
             -theta' sin phi + psi' cos phi cos theta),

has the matrix of determinant cos(theta) in (psi', theta', phi'): the chart
is singular exactly where cos(theta) = 0. There the right-hand side and its
Jacobian must refuse the state naming the chart, the angle and its value
(both backends, for the articulated-body algorithm and for the mass
matrix); just away from it, the motion integrates and keeps the kinetic
energy computed from the formula above.
"""
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from sage.all import var, diagonal_matrix

from sage_dynsym.errors import AnalysisError
from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
from sage_dynsym.numerics.recursive import RecursiveForm
from sage_dynsym.numerics.rhs import numerical_rhs, StateJacobian

MASS, INERTIA = 2.0, (1.0, 2.0, 3.0)


def _form(solver):
    x, y, z, psi, theta, phi = var('x y z psi theta phi')
    base = TreeBody(0, joint=[x, y, z], rotations=[(3, psi), (2, theta), (1, phi)],
                    mass=MASS, inertia=diagonal_matrix(list(INERTIA)), name='base')
    return RecursiveForm(BodyTree([base], [x, y, z, psi, theta, phi]), solver=solver)


def _energy(state):
    _, _, _, _, theta, phi, vx, vy, vz, dpsi, dtheta, dphi = state
    omega = np.array([dphi - dpsi * math.sin(theta),
                      dtheta * math.cos(phi) + dpsi * math.sin(phi) * math.cos(theta),
                      -dtheta * math.sin(phi) + dpsi * math.cos(phi) * math.cos(theta)])
    return 0.5 * MASS * (vx**2 + vy**2 + vz**2) + 0.5 * omega @ (np.array(INERTIA) * omega)


def _state(theta, dtheta=0.2):
    return [0.1, -0.2, 0.3, 0.4, theta, -0.5, 0.1, 0.2, -0.1, 0.3, dtheta, -0.4]


SINGULAR = [(math.pi / 2, 'pi/2'), (-math.pi / 2, '-pi/2'), (3 * math.pi / 2, '3/2*pi')]


@pytest.mark.parametrize('solver', ['articulated', 'ltdl'])
@pytest.mark.parametrize('backend', ['c', 'python'])
def test_singular_attitude_refused(solver, backend):
    F = _form(solver)
    f = numerical_rhs(F, {}, backend=backend)
    jac = StateJacobian(F, {}, backend=backend)
    for theta, text in SINGULAR:
        for offset in (0.0, 1e-9 * theta):     # at and within rounding of the set
            for function in (f, jac):
                with pytest.raises(AnalysisError) as error:
                    function(0.0, _state(theta + offset))
                message = str(error.value)
                assert f"rotation chart of body 'base' is singular at theta = {text}" in message
                assert 'gimbal lock' in message


@pytest.mark.parametrize('solver', ['articulated', 'ltdl'])
def test_near_singular_attitude_integrates(solver):
    f = numerical_rhs(_form(solver), {})
    # theta moving away from pi/2 (towards it, the rates of psi and phi grow
    # without bound and the integration reaches the refused set)
    x0 = _state(math.pi / 2 - 1e-3, dtheta=-0.2)
    solution = solve_ivp(f, (0.0, 0.2), x0, rtol=1e-11, atol=1e-12, method='DOP853')
    assert solution.success
    assert np.all(np.isfinite(solution.y))
    energies = [_energy(solution.y[:, i]) for i in range(solution.y.shape[1])]
    assert max(abs(e - energies[0]) for e in energies) < 1e-7 * energies[0]


@pytest.mark.parametrize('method', ['DOP853', 'Radau'])
def test_simulate_from_a_singular_attitude_refused(method):
    from sage_dynsym import MechanicalSystem, RigidBody
    x, y, z, psi, theta, phi = var('x y z psi theta phi')
    base = RigidBody('base', joint=[x, y, z], rotations=[(3, psi), (2, theta), (1, phi)],
                     mass=MASS, inertia=diagonal_matrix(list(INERTIA)))
    S = MechanicalSystem([base], [x, y, z, psi, theta, phi])
    variables = S.numerical_rhs({}).variables()
    initial = dict(zip(variables, _state(-math.pi / 2)))
    with pytest.raises(AnalysisError, match=r"body 'base' is singular at theta = -pi/2"):
        S.simulate({}, initial, 1, method=method)

"""The command line reports a damped system: a cart with a damper carrying a
pendulum. The cart's position is absent from the Lagrangian but its momentum
is not conserved (the damper acts on it), so it is not offered as cyclic and
the report goes on to the equilibria of the full system (issue: the CLI used
to stop because ``cyclic_coordinates()`` offered ``x`` and ``routh([x])``
refused it)."""
import pytest
from conftest import run_cli as run
from descriptions import cartesian_pendulum

CART = """\
kind: mechanical
name: damped cart pendulum
parameters: [M, m, l, g, c]
positive: [M, m, l, g, c]
coordinates: [x, theta]
force_function:
  uniform_gravity: [0, 0, -g]
dissipation: "c*dx^2/2"
bodies:
  - name: cart
    parent: 0
    joint: [x, 0, 0]
    mass: M
  - name: bob
    parent: cart
    rotations: [[2, theta]]
    mass_center: [0, 0, -l]
    mass: m
    inertia: [[m*l^2, 0, 0], [0, m*l^2, 0], [0, 0, 0]]
"""


def test_damped_cart_is_reported(tmp_path):
    path = tmp_path / "cart.yaml"
    path.write_text(CART)
    result = run(str(path))
    assert result.returncode == 0, result.stderr
    assert "Traceback" not in result.stderr
    text = result.stdout
    assert "section failed" not in text and "not available" not in text
    # the damping term c*dx is in the cart's equation
    assert "c*dx" in text
    assert "Not cyclic" in text and ": x\n" in text
    assert "Routh function" not in text
    # equilibria of the pendulum: hanging down and upside down (a
    # one-parameter family in x); upside down is unstable
    assert "Equilibria" in text
    assert "theta = 0" in text and "theta = pi" in text
    upside_down = text.split("theta = pi")[1].split("\n")[1]
    assert "unstable" in upside_down
    assert "Hamiltonian" in text


@pytest.mark.slow       # one more whole report; `make test-slow` (CI)
def test_undamped_cart_still_reduced(tmp_path):
    path = tmp_path / "cart.yaml"
    path.write_text(CART.replace('dissipation: "c*dx^2/2"\n', ""))
    result = run(str(path))
    assert result.returncode == 0, result.stderr
    text = result.stdout
    assert "Routh function for the cyclic coordinates x" in text
    assert "Not cyclic" not in text


@pytest.mark.slow       # one more whole report; `make test-slow` (CI)
def test_constrained_pendulum_is_reported(tmp_path):
    """The multiplier's equations and the solved multiplier are printed; the
    analysis that needs independent coordinates says so instead of stopping.
    (Tension T = -2 mu1 l = m (v^2 - g z)/l on the circle, Goldstein et al.,
    Classical Mechanics, 3rd ed., section 2.4.)"""
    path = tmp_path / "pendulum.yaml"
    path.write_text(cartesian_pendulum())
    result = run(str(path))
    assert result.returncode == 0, result.stderr
    text = result.stdout
    assert "[x] ddx*m - 2*mu1*x" in text
    assert "[z] ddz*m + g*m - 2*mu1*z" in text
    assert "mu1 = 1/2*(g*m*z - (dx^2 + dz^2)*m)/(x^2 + z^2)" in text
    assert "Equilibria (equations at rest): not available (constraints:" in text
    assert "section failed" not in text

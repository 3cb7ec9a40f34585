"""The system builder's new fields (potential term, loads, constraints,
long-form circuit entries) give the models of the textbook equations.

Expected values are written by hand from the textbook forms:

- cart of mass M on a spring k and a damper c, carrying a pendulum (point
  mass m at the distance l), pushed at the bob by a horizontal force F
  (Meirovitch, *Methods of Analytical Dynamics*, 1970, the cart-pendulum
  example of chapter 2; the force enters by virtual work with the
  bob's horizontal position y + l sin(theta)):

      (M + m) y'' + m l cos(theta) theta'' - m l sin(theta) theta'^2 + c y' + k y = F
      m l^2 theta'' + m l cos(theta) y'' + m g l sin(theta) = F l cos(theta)

- a point mass on a rod of length l in Cartesian coordinates: the tension
  T = m (l theta'^2 + g cos(theta)) (any mechanics text, e.g. Goldstein,
  *Classical Mechanics*, section 2.4), here the multiplier of the
  constraint x^2 + y^2 - l^2 = 0 with the force J^T mu = 2 mu (x, y), so
  mu = -T / (2 l);
- two inductors coupled only by a mutual inductance M, each closed by a
  resistor: the natural frequencies solve det(s [[L1, M], [M, L2]] +
  diag(R1, R2)) = 0.
"""
import random

from sage.all import QQ, SR, cos, matrix, sin, var

from sage_dynsym.interact.builder import SystemBuilder


def builder(bodies, **fields):
    """A builder whose text fields hold ``fields`` (by the field's name) and
    whose bodies are ``bodies`` (the fields of each, as typed)."""
    B = SystemBuilder()
    for key, value in fields.items():
        getattr(B, key).value = value
    B.remove_body()             # the spherical pendulum's body a new builder shows
    for body in bodies:
        B.add_body(body)
    return B


def test_cart_pendulum_with_spring_damper_and_push():
    # inertia about the pivot O_k (the package's convention): a point mass
    B = builder([dict(name='cart', parent='0', joint='0, y, 0', mass='M'),
                 dict(name='bob', parent='cart', rotations='1 theta', mass_center='0, 0, -l',
                      mass='m', inertia='m*l^2, m*l^2, 0')],
                name='cart', parameters='M, m, l, g, k, c, F', coordinates='y, theta',
                gravity='0, 0, -g', potential='-k*y^2/2', dissipation='c*dy^2/2')
    B.add_load(dict(body='bob', point='0, 0, -l', force='0, F, 0', axes='0'))
    E = B.model().lagrangian().lagrange_equations()
    M, m, l, g, k, c, F, y, th, dy, dth, ddy, ddth = var(
        'M m l g k c F y theta dy dtheta ddy ddtheta')
    expected = [(M + m) * ddy + m * l * cos(th) * ddth - m * l * sin(th) * dth**2
                + c * dy + k * y - F,
                m * l**2 * ddth + m * l * cos(th) * ddy + m * g * l * sin(th)
                - F * l * cos(th)]
    for e, x in zip(E, expected):
        assert (e - x).simplify_full() == 0


def test_cartesian_pendulum_constraint_force():
    B = builder([dict(name='bob', parent='0', joint='x, y, 0', mass='m')], name='rod',
                parameters='m, l, g', coordinates='x, y', gravity='0, -g, 0',
                constraints='x^2 + y^2 - l^2')
    L = B.model().lagrangian()
    assert len(L.multipliers()) == 1
    mu = L.multipliers()[0]
    rng = random.Random(3)
    m, l, g = (QQ(rng.randint(1, 9)) for _ in range(3))
    th, w = QQ(rng.randint(-30, 30)) / 20, QQ(rng.randint(-30, 30)) / 10
    x, y, dx, dy = var('x y dx dy')
    state = {x: l * sin(th), y: -l * cos(th), dx: l * cos(th) * w, dy: l * sin(th) * w,
             SR.var('m'): m, SR.var('l'): l, SR.var('g'): g}
    solved = L.accelerations_and_multipliers()
    tension = m * (l * w**2 + g * cos(th))
    assert (SR(solved[mu]).subs(state) + tension / (2 * l)).simplify_full() == 0


def test_isolated_windings_coupled_by_mutual_inductance():
    B = builder([], kind='circuit', circuit_parameters='Mu',
                branches="1 2 L1\n2 1 R1\n3 4 L2\n4 3 R2\nmutual L1 L2 = Mu")
    C = B.model()
    values = {SR.var(n): v for n, v in
              dict(L1=QQ(2), L2=QQ(3), R1=QQ(5), R2=QQ(7), Mu=QQ(1)).items()}
    x = [v for v, _ in C.state_variables()]
    Bm = C.lhs_matrix().subs(values)
    A = matrix([[SR(e).diff(v) for v in x] for e in C.state_equations()]).subs(values)
    s = var('s')
    ours = (s * Bm - A).det().expand()
    theirs = (s * matrix([[2, 1], [1, 3]]) + matrix([[5, 0], [0, 7]])).det().expand()
    assert (ours / ours.coefficient(s, 2) - theirs / theirs.coefficient(s, 2)).expand() == 0


def test_a_failure_is_shown_on_the_status_line(tmp_path, monkeypatch):
    # a page boundary: the package's errors by their message, an unforeseen
    # one with its class, a file that cannot be written with the system's
    # message; never a traceback, and nothing derived or saved after them
    B = SystemBuilder()

    def broken():
        raise ZeroDivisionError("no model")
    monkeypatch.setattr(B, "model", broken)
    B.derive()
    assert B.status.value == "<b>error:</b> ZeroDivisionError: no model"
    assert B.output.value == ""
    monkeypatch.undo()
    B.path.value = str(tmp_path / "missing" / "system.yaml")
    B.save()
    assert B.status.value.startswith("<b>error:</b> ") and "saved" not in B.status.value
    assert "ZeroDivisionError" not in B.status.value
    B.path.value = str(tmp_path / "system.yaml")
    B.save()
    assert B.status.value == f"saved to {tmp_path / 'system.yaml'}"

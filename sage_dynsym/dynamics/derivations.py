r"""
Forms of the equations: the characteristic function with its equations

A :class:`Derivation` is one classical form of a model's equations: the
characteristic function it comes from and the list of equations, as data a
page or a worksheet can display. Every kind of model lists the forms it has
(:meth:`~sage_dynsym.dynamics.model.Model.equation_forms`); the forms that
come from a Lagrangian -- Lagrange equations of the second kind, Routh
equations for chosen cyclic coordinates, Hamilton equations (Dirac's scheme
for a singular Lagrangian) -- are built here, by
:func:`lagrangian_forms`, for any kind that has a Lagrangian.

EXAMPLES::

    sage: from sage_dynsym import Lagrangian
    sage: from sage_dynsym.dynamics.derivations import lagrangian_forms
    sage: from sage_dynsym.symbols import velocity
    sage: x, m, k = var('x m k'); dx = velocity(x)
    sage: forms = lagrangian_forms(lambda: Lagrangian(m*dx^2/2 - k*x^2/2, [x]))
    sage: list(forms)
    ['Lagrange', 'Routh', 'Hamilton']
    sage: forms['Hamilton']().equations
    [('\\dot{x}', p_x/m), ('\\dot{{p_{x}}}', -k*x)]

REFERENCES:

- A. I. Lurie, *Analytical Mechanics*, Springer, 2002, chapters 7
  (Lagrange and Routh equations) and 8 (Hamilton equations).
"""
from collections import namedtuple

from sage.misc.latex import latex

from ..errors import ModelError

__all__ = ['Derivation', 'lagrangian_forms', 'lagrange_derivation', 'routh_derivation',
           'hamilton_derivation']

#: ``function`` is a pair (name, expression); ``equations`` a list of pairs
#: ``(lhs, rhs)`` meaning ``lhs = rhs`` (``lhs`` a LaTeX string).
Derivation = namedtuple("Derivation", ["form", "function", "equations", "note"])
Derivation.__doc__ = r"""
One form of the equations of a model: ``form`` its name, ``function`` the
pair ``(name, expression)`` of its characteristic function, ``equations`` a
list of pairs ``(lhs, rhs)`` meaning `lhs = rhs` (``lhs`` a LaTeX string),
``note`` a remark (e.g. the Dirac constraints of a singular Lagrangian) or
``None``.

EXAMPLES::

    sage: from sage_dynsym import load
    sage: from sage_dynsym.description import example_path
    sage: d = load(example_path('spherical_pendulum.yaml')).equation_forms()['Lagrange']()
    sage: d.form, d.function, d.note
    ('Lagrange', ('L', 1/2*dpsi^2*l^2*m*sin(theta)^2 + 1/2*dtheta^2*l^2*m - g*l*m*cos(theta)), None)
    sage: d.equations[1]
    ('0', -dpsi^2*l^2*m*cos(theta)*sin(theta) + ddtheta*l^2*m - g*l*m*sin(theta))
"""


def lagrangian_forms(lagrangian, names=('Lagrange', 'Routh', 'Hamilton')):
    r"""
    The forms of the equations that come from a Lagrangian: a dict from
    the names ``names`` (for Lagrange, Routh and Hamilton, in this order) to
    functions building the :class:`Derivation`; the Routh form takes the
    keyword ``cyclic`` (names or symbols of cyclic coordinates; empty: all
    cyclic coordinates).

    INPUT:

    - ``lagrangian`` -- a function of no argument returning the
      :class:`~sage_dynsym.dynamics.lagrangian.Lagrangian` (built only when
      a form is asked for)
    - ``names`` -- (default: ``('Lagrange', 'Routh', 'Hamilton')``) the
      names of the three forms; ``None`` leaves a form out

    EXAMPLES: the Routh form of the spherical pendulum, `\psi` cyclic::

        sage: from sage_dynsym import load
        sage: from sage_dynsym.description import example_path
        sage: from sage_dynsym.dynamics.derivations import lagrangian_forms
        sage: S = load(example_path('spherical_pendulum.yaml'))
        sage: d = lagrangian_forms(S.lagrangian)['Routh'](cyclic=['psi'])
        sage: d.function
        ('R', 1/2*dtheta^2*l^2*m - g*l*m*cos(theta) - 1/2*p_psi^2/(l^2*m*sin(theta)^2))

    TESTS::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.symbols import velocity
        sage: x = var('x')
        sage: lagrangian_forms(lambda: Lagrangian(velocity(x)^2 - x^2, [x]))['Routh']()
        Traceback (most recent call last):
        ...
        ModelError: the Routh form needs at least one cyclic coordinate; this Lagrangian has none among [x]
        sage: list(lagrangian_forms(None, names=('Lagrange (loop)', None, 'Hamilton (loop)')))
        ['Lagrange (loop)', 'Hamilton (loop)']
    """
    lagrange, routh, hamilton = names
    forms = {}
    if lagrange is not None:
        forms[lagrange] = lambda cyclic=(): lagrange_derivation(lagrangian(), lagrange)
    if routh is not None:
        forms[routh] = lambda cyclic=(): routh_derivation(lagrangian(), cyclic, routh)
    if hamilton is not None:
        forms[hamilton] = lambda cyclic=(): hamilton_derivation(lagrangian(), hamilton)
    return forms


def lagrange_derivation(L, form='Lagrange'):
    r"""
    The Lagrange equations of the second kind of ``L``, each `0 = E_i`.

    EXAMPLES::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.dynamics.derivations import lagrange_derivation
        sage: from sage_dynsym.symbols import velocity
        sage: x, m, k = var('x m k')
        sage: lagrange_derivation(Lagrangian(m*velocity(x)^2/2 - k*x^2/2, [x])).equations
        [('0', ddx*m + k*x)]
    """
    return Derivation(form, ('L', L.expr()), [("0", e) for e in L.lagrange_equations()], None)


def routh_derivation(L, cyclic=(), form='Routh'):
    r"""
    The Routh equations of ``L`` for the cyclic coordinates named in
    ``cyclic`` (empty: all cyclic coordinates of ``L``).

    EXAMPLES: see :func:`lagrangian_forms`.

    TESTS::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.dynamics.derivations import routh_derivation
        sage: from sage_dynsym.symbols import velocity
        sage: x, y = var('x y')
        sage: L = Lagrangian((velocity(x)^2 + velocity(y)^2)/2 - x^2/2, [x, y])
        sage: routh_derivation(L).function
        ('R', 1/2*dx^2 - 1/2*p_y^2 - 1/2*x^2)
    """
    names = {str(c) for c in cyclic}
    chosen = [q for q in L.coordinates() if str(q) in names] if names \
        else L.cyclic_coordinates()
    if not chosen:
        raise ModelError("the Routh form needs at least one cyclic coordinate; "
                         f"this Lagrangian has none among {L.coordinates()}")
    R = L.routh(chosen)
    return Derivation(form, ('R', R.expr()), [("0", e) for e in R.equations()], None)


def hamilton_derivation(L, form='Hamilton'):
    r"""
    The Hamilton equations of the Legendre transform of ``L``; for a
    singular Lagrangian, Dirac's constraints (each `0 = \varphi_j`) with a
    note.

    EXAMPLES: a Lagrangian linear in the velocity is singular::

        sage: from sage_dynsym import Lagrangian
        sage: from sage_dynsym.dynamics.derivations import hamilton_derivation
        sage: from sage_dynsym.symbols import velocity
        sage: x, y = var('x y')
        sage: d = hamilton_derivation(Lagrangian(y*velocity(x) - x^2/2 - y^2/2, [x, y]))
        sage: d.note.startswith("singular Lagrangian, Dirac's scheme")
        True
    """
    H = L.hamiltonian()
    if H.is_singular():
        D = H.constraints()
        return Derivation(form, ('H', H.expr()), [("0", c) for c in D.constraints()],
                          f"singular Lagrangian, Dirac's scheme: {D}")
    rows = []
    for q, p, (dq, dp) in zip(H.coordinates(), H.momenta(), H.equations()):
        rows.append((f"\\dot{{{latex(q)}}}", dq))
        rows.append((f"\\dot{{{latex(p)}}}", dp))
    return Derivation(form, ('H', H.expr()), rows, None)

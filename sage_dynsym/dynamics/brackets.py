r"""
Poisson brackets

The canonical bracket of functions of coordinates `q` and momenta `p`, the
bracket of Hamilton's equations `\dot f = \{f, H\}` and of Dirac's
constraint analysis.

EXAMPLES::

    sage: from sage_dynsym.dynamics.brackets import poisson_bracket
    sage: q, p = var('q p')
    sage: poisson_bracket(p, q, [q], [p])
    -1
"""

from ..arguments import expression_argument

__all__ = ['poisson_bracket']


def poisson_bracket(f, g, coordinates, momenta):
    r"""
    The canonical Poisson bracket
    `\{f, g\} = \sum_i \partial_{q_i} f\, \partial_{p_i} g - \partial_{p_i} f\, \partial_{q_i} g`.

    EXAMPLES::

        sage: from sage_dynsym.dynamics.brackets import poisson_bracket
        sage: q, p = var('q p')
        sage: poisson_bracket(q, p, [q], [p]), poisson_bracket(q^2, p^2, [q], [p])
        (1, 4*p*q)
    """
    f, g = expression_argument(f, "f"), expression_argument(g, "g")
    return sum(f.diff(q) * g.diff(p) - f.diff(p) * g.diff(q)
               for q, p in zip(coordinates, momenta))

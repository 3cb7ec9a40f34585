r"""
Derivatives of expression graphs: forward-mode differentiation

:func:`tangent` adds to an :class:`~sage_dynsym.numerics.graph.ExpressionGraph`
the directional derivatives of some of its nodes: every operation node
`v = \phi(a, b)` gets the node `\dot v = \phi_a \dot a + \phi_b \dot b`,
the inputs the given seeds (nodes, normally inputs of their own), constants
zero. The rules are those of the operations and of the functions of
:data:`~sage_dynsym.numerics.expressions.FUNCTIONS` (forward-mode automatic
differentiation, [GW2008]_, Chapter 3); the graph folds the zeros, so the
derivative of a node that does not depend on the seeded inputs costs
nothing, and the values of the nodes themselves are shared with the
derivatives.

With a unit seed on one state variable the derivative nodes give one column
of the Jacobian; :func:`~sage_dynsym.numerics.compiler.jacobian_c_source`
writes C that computes the values once and the derivatives once per column
(see :meth:`~sage_dynsym.numerics.recursive.RecursiveForm.jacobian_kernel`).

EXAMPLES: `d/dx (x\sin x) = \sin x + x\cos x`::

    sage: from sage_dynsym.numerics.graph import ExpressionGraph
    sage: from sage_dynsym.numerics.derivatives import tangent
    sage: G = ExpressionGraph(); x, s = G.input('x', 0), G.input('x', 1)
    sage: [d] = tangent(G, [G.mul(x, G.call('sin', x))], {x: s})
    sage: G.show(d)
    '(x[1]*sin(x[0])) + (x[0]*(x[1]*cos(x[0])))'

REFERENCES:

.. [GW2008] A. Griewank and A. Walther, *Evaluating Derivatives: Principles
   and Techniques of Algorithmic Differentiation*, 2nd ed., SIAM 2008.
"""
from ..errors import AnalysisError

__all__ = ['tangent']


def _derivative_of_function(G, name, args, node):
    """The partial derivatives of the function ``name`` at ``args`` (one
    node per argument); ``node`` is the value of the function."""
    a = args[0]
    one = G.one
    if name == 'sin':
        return [G.call('cos', a)]
    if name == 'cos':
        return [G.neg(G.call('sin', a))]
    if name == 'tan':
        return [G.add(one, G.mul(node, node))]
    if name == 'exp':
        return [node]
    if name == 'log':
        return [G.div(one, a)]
    if name == 'abs':
        return [G.div(node, a)]
    if name == 'sqrt':
        return [G.div(G.constant(0.5), node)]
    if name == 'sinh':
        return [G.call('cosh', a)]
    if name == 'cosh':
        return [G.call('sinh', a)]
    if name == 'tanh':
        return [G.sub(one, G.mul(node, node))]
    if name in ('arcsin', 'arccos'):
        d = G.div(one, G.call('sqrt', G.sub(one, G.mul(a, a))))
        return [d if name == 'arcsin' else G.neg(d)]
    if name == 'arctan':
        return [G.div(one, G.add(one, G.mul(a, a)))]
    if name == 'arcsinh':
        return [G.div(one, G.call('sqrt', G.add(G.mul(a, a), one)))]
    if name == 'arccosh':
        return [G.div(one, G.call('sqrt', G.sub(G.mul(a, a), one)))]
    if name == 'arctanh':
        return [G.div(one, G.sub(one, G.mul(a, a)))]
    if name == 'arctan2':
        y, x = args
        r2 = G.add(G.mul(x, x), G.mul(y, y))
        return [G.div(x, r2), G.neg(G.div(y, r2))]
    raise AnalysisError(f"the function {name} has no derivative here", entry="jacobian")


def _operations(G, outputs, seeds):
    # the operation nodes between the seeds and the outputs, arguments first
    # (creation order): the graph below a seeded node is not traversed
    needed, stack = set(), list(outputs)
    while stack:
        node = stack.pop()
        if node in needed or node in seeds:
            continue
        kind, args = G.operation(node)
        if kind in ('input', 'constant'):
            continue
        needed.add(node)
        stack.extend(a for a in args if not isinstance(a, str))
    return sorted(needed)


def tangent(G, outputs, seeds):
    r"""
    The directional derivatives of the nodes ``outputs`` of the graph
    ``G`` (a list of nodes of ``G``, added to it).

    INPUT:

    - ``G`` -- an :class:`~sage_dynsym.numerics.graph.ExpressionGraph`
    - ``outputs`` -- a list of its nodes
    - ``seeds`` -- dict: node -> the node of its derivative (inputs not in
      it have derivative zero); a seeded node that is no input cuts the
      graph: its derivative is the seed, what it is computed from is not
      differentiated (as the accelerations held fixed in
      :mod:`~sage_dynsym.numerics.rnea_derivatives`)

    OUTPUT: the list of the nodes of the derivatives of ``outputs``

    EXAMPLES: see the module documentation; quotients, powers and
    functions of two arguments::

        sage: from sage_dynsym.numerics.graph import ExpressionGraph
        sage: from sage_dynsym.numerics.derivatives import tangent
        sage: from sage_dynsym.numerics.compiler import run_python
        sage: G = ExpressionGraph(); x, y = G.input('x', 0), G.input('x', 1)
        sage: f = [G.div(x, y), G.power(x, 3), G.call('arctan2', y, x), G.power(x, 0.5)]
        sage: d = tangent(G, f, {x: G.one})          # d/dx
        sage: run_python(G.python_source(d), '_graph')(0, [float(2), float(3)], [])
        [0.3333333333333333, 12.0, -0.23076923076923078, 0.35355339059327373]

    A cut: `u = x^2` held fixed, `d(u y)/dy = u`::

        sage: u = G.mul(x, x)
        sage: [G.show(d) for d in tangent(G, [G.mul(u, y)], {y: G.one, u: G.zero})]
        ['x[0]*x[0]']

    TESTS::

        sage: tangent(G, [G.call('sin', y)], {x: G.one}) == [G.zero]
        True
    """
    d = dict(seeds)

    def of(node):
        if node in d:
            return d[node]
        kind, args = G.operation(node)
        return G.zero if kind in ('input', 'constant') else d[node]

    for node in _operations(G, outputs, seeds):
        kind, args = G.operation(node)
        da = [of(a) for a in args]
        if all(G.is_zero(x) for x in da):
            d[node] = G.zero
            continue
        if kind == '+':
            d[node] = G.add(*da)
        elif kind == '-':
            d[node] = G.sub(*da)
        elif kind == 'neg':
            d[node] = G.neg(da[0])
        elif kind == '*':
            a, b = args
            d[node] = G.add(G.mul(da[0], b), G.mul(a, da[1]))
        elif kind == '/':
            a, b = args        # (da - (a/b) db) / b
            d[node] = G.div(G.sub(da[0], G.mul(node, da[1])), b)
        elif kind == 'pow':
            a, b = args        # b a^(b-1) da + a^b log(a) db
            e = G.value(b)
            lower = G.power(a, e - 1) if e is not None else G.div(node, a)
            d[node] = G.add(G.mul(G.mul(b, lower), da[0]),
                            G.mul(G.mul(node, G.call('log', a)), da[1]))
        else:
            partials = _derivative_of_function(G, kind, args, node)
            d[node] = G.sum([G.mul(p, x) for p, x in zip(partials, da)])
    return [of(a) for a in outputs]

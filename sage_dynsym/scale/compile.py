r"""
Compilation of symbolic expressions into vectorised NumPy programs

:func:`compile_expressions` walks the expression trees of Sage's symbolic
ring once and writes a *program* (plain tuples, see
:func:`sage_dynsym.scale.kernel.run_program`) that evaluates all the
expressions on arrays of parameter values. Common subexpressions are
computed once; intermediate arrays are released after their last use. No
text is evaluated: the expressions come from the package's own symbolic
computations, and only the functions of
:data:`sage_dynsym.scale.kernel.FUNCTIONS` are allowed.

EXAMPLES::

    sage: from sage_dynsym.scale.compile import compile_expressions
    sage: from sage_dynsym.scale.kernel import run_program
    sage: import numpy as np
    sage: a, b = var('a b')
    sage: prog = compile_expressions([a^2 - b/2, sin(a)*sqrt(b), a > b], [a, b])
    sage: run_program(prog, [np.array([1., 2.]), np.array([4., 4.])], 2)
    [array([-1.,  2.]), array([1.68294197, 1.81859485]), array([False, False])]
"""
# Sage's symbolic functions, Maxima and coercions need the whole library initialised
# first (this subpackage's face stays Sage-free for the command line)
import sage.all
del sage  # imported for its effect alone: no name of this module
import operator

from sage.symbolic.operators import add_vararg, mul_vararg
from sage.symbolic.ring import SR

from ..errors import AnalysisError
from ..numerics.expressions import real_constant, function_name
from .kernel import FUNCTIONS

__all__ = ['compile_expressions']

#: what a user can do about a symbol or function without a value
_HINT = "; give it a value in fixed= (--value NAME=VALUE on the command line)"

_COMPARISONS = {operator.gt: 'gt', operator.ge: 'ge', operator.lt: 'lt',
                operator.le: 'le', operator.eq: 'eq', operator.ne: 'ne'}


def compile_expressions(expressions, inputs, entry="stability_map"):
    r"""
    Compile symbolic expressions (or relationals) in the symbols ``inputs``
    into a program for :func:`~sage_dynsym.scale.kernel.run_program`.

    INPUT:

    - ``expressions`` -- list of symbolic expressions or relationals
    - ``inputs`` -- list of symbols; the program's inputs, in this order
    - ``entry`` -- the name used in error messages

    OUTPUT: ``(instructions, outputs, releases)``

    Raises :class:`~sage_dynsym.errors.AnalysisError` for a symbol not in
    ``inputs``, a function without a numerical counterpart (an unspecified
    function such as a diode characteristic ``f1(u)``, or its derivative)
    and a complex constant.

    EXAMPLES::

        sage: from sage_dynsym.scale.compile import compile_expressions
        sage: x, y = var('x y')
        sage: compile_expressions([x*y + sin(x*y)], [x, y])[0]     # x*y computed once
        [('input', 0), ('input', 1), ('mul', 0, 1), ('call', 'sin', 2), ('add', 2, 3)]

    TESTS::

        sage: compile_expressions([x + y], [x])
        Traceback (most recent call last):
        ...
        AnalysisError: stability_map: no value for y (give it as a parameter or in fixed=; --param or --value on the command line)
        sage: f = function('f')
        sage: compile_expressions([diff(f(x), x).subs(x=0) * y], [y])
        Traceback (most recent call last):
        ...
        AnalysisError: stability_map: D[0](f)(0) has no numerical value; give it a value in fixed= (--value NAME=VALUE on the command line)
        sage: compile_expressions([I*x], [x])
        Traceback (most recent call last):
        ...
        AnalysisError: stability_map: the constant I is not real
    """
    inputs = [SR(v) for v in inputs]
    position = {v: i for i, v in enumerate(inputs)}
    instructions, memo = [], {}

    def emit(ins):
        instructions.append(ins)
        return len(instructions) - 1

    def walk(e):
        if e in memo:
            return memo[e]
        if e in position:
            r = emit(('input', position[e]))
        elif e.is_symbol():
            raise AnalysisError(f"no value for {e} (give it as a parameter or in fixed=; "
                                "--param or --value on the command line)", entry=entry)
        else:
            op = e.operator()
            if op is None:
                r = emit(('const', real_constant(e, entry, _HINT)))
            elif op is add_vararg or op is mul_vararg:
                r = emit(('add' if op is add_vararg else 'mul',) + tuple(walk(o) for o in e.operands()))
            elif op is operator.pow:
                base, exponent = e.operands()
                if exponent.is_integer():
                    r = emit(('ipow', walk(base), int(exponent)))
                else:
                    r = emit(('pow', walk(base), walk(exponent)))
            elif op in _COMPARISONS:
                left, right = e.operands()
                r = emit(('cmp', _COMPARISONS[op], walk(left), walk(right)))
            elif not e.variables():
                r = emit(('const', real_constant(e, entry, _HINT)))
            elif function_name(op) in FUNCTIONS:
                r = emit(('call', function_name(op)) + tuple(walk(o) for o in e.operands()))
            else:
                raise AnalysisError(f"{e} has no numerical value{_HINT}", entry=entry)
        memo[e] = r
        return r

    outputs = [walk(SR(e)) for e in expressions]
    last = {}
    for k, ins in enumerate(instructions):
        for r in _arguments(ins):
            last[r] = k
    for r in outputs:
        last[r] = len(instructions)
    releases = [[] for _ in instructions]
    for r, k in last.items():
        if k < len(instructions):
            releases[k].append(r)
    return instructions, outputs, releases


def _arguments(ins):
    op = ins[0]
    if op in ('input', 'const'):
        return ()
    if op == 'ipow':
        return (ins[1],)
    if op in ('call', 'cmp'):
        return ins[2:]
    return ins[1:]

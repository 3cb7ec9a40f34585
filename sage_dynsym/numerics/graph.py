r"""
Expression graphs: straight-line numerical code with shared subexpressions

An :class:`ExpressionGraph` records a scalar computation as a graph of
nodes -- inputs (time, state, parameters), floating-point constants and
operations -- built by the package's code generators (see
:mod:`~sage_dynsym.numerics.recursive`). Each node is created once
(hash-consing): building the same operation on the same arguments again
returns the existing node, so every common subexpression is computed once
over the whole graph. Constants are folded while the graph is built
(`x\cdot 0 = 0`, `x \cdot 1 = x`, `x + 0 = x`, `2 \cdot 3 = 6`, signs pulled
out of products), so the structure of a model -- zero and constant
entries, rotation axes, parameter values when they are known -- costs
nothing at run time.

:meth:`ExpressionGraph.c_functions` writes the nodes needed by a list of
outputs as C functions of bounded size (values passed between them
through a work array), so that even large graphs compile quickly with the
optimizer switched on; :meth:`ExpressionGraph.python_source` writes one
Python function.

EXAMPLES::

    sage: from sage_dynsym.numerics.graph import ExpressionGraph
    sage: G = ExpressionGraph()
    sage: x, y = G.input('x', 0), G.input('x', 1)
    sage: s = G.call('sin', x)
    sage: e = G.add(G.mul(s, y), G.mul(y, s))      # y*sin(x) built once
    sage: G.size(), G.show(e)
    (7, '(x[1]*sin(x[0])) + (x[1]*sin(x[0]))')
    sage: G.show(G.mul(G.add(x, G.zero), G.one)) == G.show(x)
    True
    sage: from sage_dynsym.numerics.compiler import run_python
    sage: f = run_python(G.python_source([e, G.neg(x)]), '_graph')
    sage: f(0, [float(1), float(2)], [])
    [3.365883939231586, -1.0]
"""
import math

from ..errors import AnalysisError
from .expressions import FUNCTIONS

__all__ = ['ExpressionGraph', 'SymbolicConverter']

#: Node kinds. An input's argument is (array, index); a constant's its value.
_INPUT, _CONST, _ADD, _SUB, _MUL, _DIV, _NEG, _CALL, _POW = range(9)
_SYMBOL = {_ADD: '+', _SUB: '-', _MUL: '*', _DIV: '/'}
_KIND_NAMES = {**_SYMBOL, _INPUT: 'input', _CONST: 'constant', _NEG: 'neg', _POW: 'pow'}
#: Python's math functions for the names of :data:`FUNCTIONS`.
_PYTHON = {name: getattr(math, python.split('.')[-1]) if python.startswith('math.') else abs
           for name, (python, _) in FUNCTIONS.items()}
_PYTHON['sqrt'] = math.sqrt


def _arithmetic(kind, operands):
    # an operation of _SYMBOL or a negation, with the texts of its operands
    if kind == _NEG:
        return f'-{operands[0]}'
    spacing = ' ' if kind in (_ADD, _SUB) else ''
    return f'{operands[0]}{spacing}{_SYMBOL[kind]}{spacing}{operands[1]}'


class ExpressionGraph:
    r"""
    A graph of scalar operations with shared subexpressions and folded
    constants (see the module documentation). Nodes are integers.

    EXAMPLES::

        sage: from sage_dynsym.numerics.graph import ExpressionGraph
        sage: G = ExpressionGraph()
        sage: a = G.input('p', 0)
        sage: G.add(a, G.constant(0)) == a, G.mul(a, G.zero) == G.zero
        (True, True)
        sage: G.value(G.add(G.constant(2), G.constant(3)))
        5.0
        sage: G.power(a, -2) == G.div(G.one, G.mul(a, a))
        True
    """

    def __init__(self):
        self._kind, self._args, self._index = [], [], {}
        self.zero = self.constant(0.0)
        self.one = self.constant(1.0)

    def _node(self, kind, args):
        key = (kind, args)
        node = self._index.get(key)
        if node is None:
            node = self._index[key] = len(self._kind)
            self._kind.append(kind)
            self._args.append(args)
        return node

    def size(self):
        r"""The number of nodes (inputs and constants included).

        EXAMPLES: see the module documentation.
        """
        return len(self._kind)

    def constant(self, value):
        r"""The node of the float ``value``.

        EXAMPLES::

            sage: from sage_dynsym.numerics.graph import ExpressionGraph
            sage: G = ExpressionGraph(); G.constant(1) == G.one
            True
            sage: G.constant(float('inf'))
            Traceback (most recent call last):
            ...
            AnalysisError: numerical_rhs: the constant inf is not a finite number
        """
        value = float(value)
        if not math.isfinite(value):
            raise AnalysisError(f"the constant {value} is not a finite number",
                                entry="numerical_rhs")
        return self._node(_CONST, value + 0.0)      # -0.0 is 0.0

    def input(self, array, index=None):
        r"""
        The node of an input: ``array`` is the name of the C/Python
        argument (``'x'``, ``'p'``, or ``'t'`` with ``index=None``).

        EXAMPLES::

            sage: from sage_dynsym.numerics.graph import ExpressionGraph
            sage: G = ExpressionGraph(); G.show(G.input('t')), G.show(G.input('x', 2))
            ('t', 'x[2]')
        """
        return self._node(_INPUT, (array, index))

    def value(self, node):
        r"""The float of a constant node, ``None`` for any other node.

        EXAMPLES: see the class documentation.
        """
        return self._args[node] if self._kind[node] == _CONST else None

    def is_zero(self, node):
        r"""Whether ``node`` is the constant 0.

        EXAMPLES::

            sage: from sage_dynsym.numerics.graph import ExpressionGraph
            sage: G = ExpressionGraph(); G.is_zero(G.sub(G.one, G.one))
            True
        """
        return node == self.zero

    def _negated(self, node):
        # the node whose negative ``node`` is, or None
        return self._args[node][0] if self._kind[node] == _NEG else None

    def neg(self, a):
        r"""`-a`.

        EXAMPLES: see the module documentation.
        """
        if self._kind[a] == _CONST:
            return self.constant(-self._args[a])
        inner = self._negated(a)
        if inner is not None:
            return inner
        if self._kind[a] == _SUB:
            x, y = self._args[a]
            return self._node(_SUB, (y, x))
        return self._node(_NEG, (a,))

    def add(self, a, b):
        r"""`a + b`.

        EXAMPLES: see the class documentation.
        """
        if a == self.zero:
            return b
        if b == self.zero:
            return a
        va, vb = self.value(a), self.value(b)
        if va is not None and vb is not None:
            return self.constant(va + vb)
        na, nb = self._negated(a), self._negated(b)
        if nb is not None:
            return self.sub(a, nb)
        if na is not None:
            return self.sub(b, na)
        return self._node(_ADD, (a, b) if a <= b else (b, a))

    def sub(self, a, b):
        r"""`a - b`.

        EXAMPLES: see the class documentation.
        """
        if b == self.zero:
            return a
        if a == self.zero:
            return self.neg(b)
        if a == b:
            return self.zero
        va, vb = self.value(a), self.value(b)
        if va is not None and vb is not None:
            return self.constant(va - vb)
        nb = self._negated(b)
        if nb is not None:
            return self.add(a, nb)
        na = self._negated(a)
        if na is not None:
            return self.neg(self.add(na, b))
        return self._node(_SUB, (a, b))

    def mul(self, a, b):
        r"""`a b`.

        EXAMPLES: see the class documentation.
        """
        if a == self.zero or b == self.zero:
            return self.zero
        if a == self.one:
            return b
        if b == self.one:
            return a
        va, vb = self.value(a), self.value(b)
        if va is not None and vb is not None:
            return self.constant(va * vb)
        if va == -1.0:
            return self.neg(b)
        if vb == -1.0:
            return self.neg(a)
        if va is not None and va < 0:
            return self.neg(self.mul(self.constant(-va), b))
        if vb is not None and vb < 0:
            return self.neg(self.mul(a, self.constant(-vb)))
        na, nb = self._negated(a), self._negated(b)
        if na is not None or nb is not None:
            product = self.mul(a if na is None else na, b if nb is None else nb)
            return product if (na is None) == (nb is None) else self.neg(product)
        return self._node(_MUL, (a, b) if a <= b else (b, a))

    def div(self, a, b):
        r"""`a / b` (by a constant: a product with its reciprocal).

        EXAMPLES::

            sage: from sage_dynsym.numerics.graph import ExpressionGraph
            sage: G = ExpressionGraph(); x = G.input('x', 0)
            sage: G.show(G.div(x, G.constant(4))), G.show(G.div(G.zero, x))
            ('x[0]*0.25', '0.0')
        """
        if a == self.zero:
            return self.zero
        if b == self.one:
            return a
        vb = self.value(b)
        if vb is not None:
            if vb == 0:
                raise AnalysisError("division by the constant 0", entry="numerical_rhs")
            return self.mul(a, self.constant(1.0 / vb))
        if a == b:
            return self.one
        na, nb = self._negated(a), self._negated(b)
        if na is not None or nb is not None:
            quotient = self.div(a if na is None else na, b if nb is None else nb)
            return quotient if (na is None) == (nb is None) else self.neg(quotient)
        return self._node(_DIV, (a, b))

    def call(self, name, *args):
        r"""
        The function ``name`` (a name of
        :data:`~sage_dynsym.numerics.expressions.FUNCTIONS`, or ``'sqrt'``)
        of the nodes ``args``.

        EXAMPLES::

            sage: from sage_dynsym.numerics.graph import ExpressionGraph
            sage: G = ExpressionGraph(); G.value(G.call('cos', G.zero))
            1.0
            sage: G.call('gamma', G.one)
            Traceback (most recent call last):
            ...
            AnalysisError: numerical_rhs: the function gamma has no numerical counterpart
        """
        if name not in _PYTHON:
            raise AnalysisError(f"the function {name} has no numerical counterpart",
                                entry="numerical_rhs")
        values = [self.value(a) for a in args]
        if all(v is not None for v in values):
            try:
                return self.constant(_PYTHON[name](*values))
            except (ValueError, OverflowError) as err:
                raise AnalysisError(f"{name}{tuple(values)} has no real value",
                                    entry="numerical_rhs") from err
        return self._node(_CALL, (name,) + tuple(args))

    def power(self, a, exponent):
        r"""
        `a^e` for a number ``exponent``: integers as products (negative
        ones as quotients), `1/2` as a square root.

        EXAMPLES::

            sage: from sage_dynsym.numerics.graph import ExpressionGraph
            sage: G = ExpressionGraph(); x = G.input('x', 0)
            sage: G.show(G.power(x, 3)), G.show(G.power(x, 0.5)), G.show(G.power(x, 1.5))
            ('x[0]*(x[0]*x[0])', 'sqrt(x[0])', 'pow(x[0], 1.5)')
        """
        e = float(exponent)
        if e == int(e) and abs(e) <= 64:
            n = int(e)
            if n < 0:
                return self.div(self.one, self.power(a, -n))
            result, square = self.one, a
            while n:
                if n & 1:
                    result = self.mul(result, square)
                n >>= 1
                if n:
                    square = self.mul(square, square)
            return result
        if e == 0.5:
            return self.call('sqrt', a)
        va = self.value(a)
        if va is not None:
            if va < 0:
                raise AnalysisError(f"{va}^{e} has no real value", entry="numerical_rhs")
            return self.constant(va ** e)
        return self._node(_POW, (a, self.constant(e)))

    def dot(self, u, w):
        r"""`\sum_i u_i w_i` of two sequences of nodes.

        EXAMPLES::

            sage: from sage_dynsym.numerics.graph import ExpressionGraph
            sage: G = ExpressionGraph(); x = G.input('x', 0)
            sage: G.show(G.dot([x, G.zero, G.one], [G.one, x, x]))
            'x[0] + x[0]'
        """
        total = self.zero
        for a, b in zip(u, w):
            total = self.add(total, self.mul(a, b))
        return total

    def sum(self, nodes):
        r"""The sum of ``nodes``, as a balanced tree (short dependency chains).

        EXAMPLES::

            sage: from sage_dynsym.numerics.graph import ExpressionGraph
            sage: G = ExpressionGraph(); x = [G.input('x', i) for i in range(3)]
            sage: G.show(G.sum(x))
            'x[1] + (x[0] + x[2])'
        """
        nodes = [a for a in nodes if a != self.zero]
        if not nodes:
            return self.zero
        while len(nodes) > 1:
            half = (len(nodes) + 1) // 2
            nodes = [self.add(nodes[i], nodes[half + i]) if half + i < len(nodes) else nodes[i]
                     for i in range(half)]
        return nodes[0]

    # ------------------------------------------------------------------
    # writing code

    def _operand(self, node, names, language):
        kind, args = self._kind[node], self._args[node]
        if kind == _CONST:
            return repr(args) if args >= 0 else f'({args!r})'
        if kind == _INPUT:
            array, index = args
            return array if index is None else f'{array}[{index}]'
        return names[node]

    def _text(self, node, names, language):
        kind, args = self._kind[node], self._args[node]
        if kind in (_CONST, _INPUT):
            return self._operand(node, names, language)
        operands = [self._operand(a, names, language) for a in args
                    if not isinstance(a, str)]
        if kind == _POW:
            return (f'{operands[0]}**{operands[1]}' if language == 'python' else
                    f'pow({operands[0]}, {operands[1]})')
        if kind != _CALL:
            return _arithmetic(kind, operands)
        name = args[0]
        if name == 'sqrt':
            function = 'math.sqrt' if language == 'python' else 'sqrt'
        else:
            function = FUNCTIONS[name][0 if language == 'python' else 1]
        return f"{function}({', '.join(operands)})"

    def show(self, node):
        r"""
        The expression of ``node`` written out (C syntax), for
        documentation and tests only (the text grows with sharing).

        EXAMPLES: see the module documentation.
        """
        kind, args = self._kind[node], self._args[node]
        if kind in (_CONST, _INPUT):
            return self._operand(node, {}, 'c')

        def inner(a):
            text = self.show(a)
            return text if self._kind[a] in (_CONST, _INPUT, _CALL, _POW) else f'({text})'
        if kind == _POW:
            return f'pow({self.show(args[0])}, {self.show(args[1])})'
        if kind == _CALL:
            return f"{args[0]}({', '.join(self.show(a) for a in args[1:])})"
        return _arithmetic(kind, [inner(a) for a in args])

    def operations(self, outputs):
        r"""
        The operation nodes the nodes ``outputs`` depend on, in an order
        where each comes after its arguments.

        EXAMPLES::

            sage: from sage_dynsym.numerics.graph import ExpressionGraph
            sage: G = ExpressionGraph(); x = G.input('x', 0)
            sage: s = G.call('sin', x); G.operations([G.mul(s, s)]) == [s, s + 1]
            True
        """
        return self._needed(outputs)

    def _needed(self, outputs):
        # the operation nodes the outputs depend on, in creation order (a
        # node is always created after its arguments)
        needed, stack = set(), [a for a in outputs]
        while stack:
            node = stack.pop()
            if node in needed or self._kind[node] in (_CONST, _INPUT):
                continue
            needed.add(node)
            stack.extend(a for a in self._args[node] if not isinstance(a, str))
        return sorted(needed)

    def python_source(self, outputs, name='_graph'):
        r"""
        The source of a Python function ``name(t, x, p)`` returning the list
        of the values of ``outputs`` (functions of the module ``math``; see
        :func:`~sage_dynsym.numerics.compiler.run_python`). A quotient by
        zero raises :class:`ZeroDivisionError`.

        EXAMPLES::

            sage: from sage_dynsym.numerics.graph import ExpressionGraph
            sage: G = ExpressionGraph(); x = G.input('x', 0)
            sage: print(G.python_source([G.div(G.one, G.call('cos', x))]))
            def _graph(t, x, p):
                v3 = math.cos(x[0])
                v4 = 1.0/v3
                return [v4]
        """
        names = {}
        lines = [f'def {name}(t, x, p):']
        for node in self._needed(outputs):
            names[node] = f'v{node}'
            lines.append(f'    v{node} = {self._text(node, names, "python")}')
        lines.append(f"    return [{', '.join(self._operand(a, names, 'python') for a in outputs)}]")
        return '\n'.join(lines)

    def c_functions(self, outputs, prefix='dynsym_part', chunk=300, groups=None):
        r"""
        C functions computing ``outputs``: ``(source, count, slots)`` where
        ``source`` defines ``count`` functions
        ``static void <prefix><i>(double t, const double *x, const double *p, double *w)``
        to be called in order, each of at most ``chunk`` statements, and
        ``slots[k]`` is the index in the work array ``w`` of the value of
        ``outputs[k]`` (``w`` must have room for ``max(slots) + 1`` values;
        ``-1`` slots do not occur: constants and inputs are stored too).

        With ``groups``, a function of the nodes that returns the index of
        the group that computes them (the arguments of a node in the same or
        an earlier group), each group has functions of its own and ``count``
        is the list of their numbers: a group can be run again alone (as the
        derivatives in one direction after another, see
        :mod:`~sage_dynsym.numerics.derivatives`), reading the values of the
        earlier ones from ``w``.

        EXAMPLES::

            sage: from sage_dynsym.numerics.graph import ExpressionGraph
            sage: G = ExpressionGraph(); x = G.input('x', 0)
            sage: s = G.call('sin', x); y = G.mul(s, s)
            sage: source, count, slots = G.c_functions([y, G.add(y, x), G.one], chunk=2)
            sage: print(source)
            static void dynsym_part0(double t, const double *x, const double *p, double *w)
            {
                const double v3 = sin(x[0]);
                const double v4 = v3*v3;
                w[0] = v4;
            }
            static void dynsym_part1(double t, const double *x, const double *p, double *w)
            {
                const double v4 = w[0];
                const double v5 = x[0] + v4;
                w[1] = v5;
                w[2] = 1.0;
            }
            sage: count, slots
            (2, [0, 1, 2])
        """
        nodes = self._needed(outputs)
        if groups is None:
            part = {node: i // chunk for i, node in enumerate(nodes)}
            counts = [max(1, (len(nodes) + chunk - 1) // chunk)]
        else:
            members = {}
            for node in nodes:
                members.setdefault(groups(node), []).append(node)
            part, counts = {}, []
            for g in range(max(members, default=0) + 1):
                first = sum(counts)
                part.update((node, first + i // chunk) for i, node in enumerate(members.get(g, [])))
                counts.append(max(1, (len(members.get(g, [])) + chunk - 1) // chunk))
            nodes = sorted(nodes, key=part.__getitem__)
        count = sum(counts)
        # values used by a later function are passed in the work array
        slot, loads = {}, [{} for _ in range(count)]
        for node in nodes:
            for a in self._args[node]:
                if isinstance(a, str) or a not in part or part[a] == part[node]:
                    continue
                if a not in slot:
                    slot[a] = len(slot)
                loads[part[node]][a] = None         # an ordered set
        output_slots = []
        for a in outputs:
            if a not in slot:
                slot[a] = len(slot)
            output_slots.append(slot[a])
        bodies = [[] for _ in range(count)]
        names = {node: f'v{node}' for node in nodes}
        for k in range(count):
            bodies[k] += [f'    const double v{a} = w[{slot[a]}];' for a in loads[k]]
        stored = set()
        for node in nodes:
            k = part[node]
            bodies[k].append(f'    const double v{node} = {self._text(node, names, "c")};')
        # store what later functions or the caller read, at the end of the
        # function that computed it
        for a, index in slot.items():
            if a in stored:
                continue
            stored.add(a)
            k = part.get(a, count - 1)
            bodies[k].append(f'    w[{index}] = {self._operand(a, names, "c")};')
        lines = []
        for k in range(count):
            lines.append(f'static void {prefix}{k}(double t, const double *x, const double *p, '
                         'double *w)')
            lines += ['{'] + bodies[k] + ['}']
        return '\n'.join(lines), count if groups is None else counts, output_slots

    def operation(self, node):
        r"""
        ``(kind, args)`` of ``node``: ``kind`` one of ``'input'``,
        ``'constant'``, ``'+'``, ``'-'``, ``'*'``, ``'/'``, ``'neg'``,
        ``'pow'`` (args: base and exponent nodes) or the name of a function
        (args: its argument nodes).

        EXAMPLES::

            sage: from sage_dynsym.numerics.graph import ExpressionGraph
            sage: G = ExpressionGraph(); x = G.input('x', 0)
            sage: G.operation(G.call('sin', x)) == ('sin', (x,)), G.operation(x)
            (True, ('input', ('x', 0)))
        """
        kind, args = self._kind[node], self._args[node]
        if kind == _CALL:
            return args[0], args[1:]
        return _KIND_NAMES[kind], args


class SymbolicConverter:
    r"""
    Symbolic expressions of Sage as nodes of an :class:`ExpressionGraph`:
    every symbol is an input node or a folded value, shared subexpressions
    are converted once.

    INPUT:

    - ``graph`` -- an :class:`ExpressionGraph`
    - ``inputs`` -- dict: symbol -> its node (an input of the graph)
    - ``values`` -- (optional) dict: symbol -> a number, folded into the
      code
    - ``entry`` -- the name used in error messages

    EXAMPLES::

        sage: from sage_dynsym.numerics.graph import ExpressionGraph, SymbolicConverter
        sage: G = ExpressionGraph(); x, k = var('x k')
        sage: C = SymbolicConverter(G, {x: G.input('x', 0)}, {k: 2})
        sage: G.show(C(k*sin(x)^2/(1 + x)))
        '(2.0*(sin(x[0])*sin(x[0])))/(1.0 + x[0])'
        sage: C(x*var('y'))
        Traceback (most recent call last):
        ...
        AnalysisError: numerical_rhs: no value for the symbol y
        sage: C(function('f')(x))
        Traceback (most recent call last):
        ...
        AnalysisError: numerical_rhs: f(x) has no numerical value
    """

    def __init__(self, graph, inputs, values=None, entry="numerical_rhs"):
        from sage.symbolic.ring import SR
        from .expressions import StructuralKey
        self._graph, self._entry, self._key = graph, entry, StructuralKey
        self._done = {StructuralKey(SR(symbol)): node for symbol, node in inputs.items()}
        for symbol, value in (values or {}).items():
            self._done[StructuralKey(SR(symbol))] = graph.constant(value)

    def __call__(self, expr):
        from sage.symbolic.ring import SR
        return self._convert(SR(expr))

    def _convert(self, e):
        import operator
        from sage.symbolic.operators import add_vararg, mul_vararg
        from .expressions import real_constant, function_name
        key = self._key(e)
        node = self._done.get(key)
        if node is not None:
            return node
        G, op = self._graph, e.operator()
        if op is None or not e.variables():
            if e.is_symbol():
                raise AnalysisError(f"no value for the symbol {e}", entry=self._entry)
            node = G.constant(real_constant(e, self._entry))
        elif op is add_vararg:
            node = G.sum([self._convert(a) for a in e.operands()])
        elif op is mul_vararg:
            above, below = [], []
            for a in e.operands():
                if a.operator() is operator.pow and a.operands()[1].is_numeric() \
                        and a.operands()[1] < 0:
                    below.append(self._convert(a.operands()[0] ** -a.operands()[1]))
                else:
                    above.append(self._convert(a))
            node = _product(G, above)
            if below:
                node = G.div(node, _product(G, below))
        elif op is operator.pow:
            base, exponent = e.operands()
            if exponent.is_numeric() and exponent.is_real():
                node = G.power(self._convert(base), float(exponent))
            else:
                node = G._node(_POW, (self._convert(base), self._convert(exponent)))
        elif function_name(op) in FUNCTIONS:
            node = G.call(function_name(op), *[self._convert(a) for a in e.operands()])
        else:
            raise AnalysisError(f"{e} has no numerical value", entry=self._entry)
        self._done[key] = node
        return node


def _product(graph, nodes):
    result = graph.one
    for a in nodes:
        result = graph.mul(result, a)
    return result

r"""
Equations written with common subexpressions

The equations of a large system repeat the same kinematic pieces (sines
and cosines, rotated angular velocities, accelerations of joints) many
times. :func:`equations_cse` names every subexpression that occurs more
than once by a new symbol ``x1_``, ``x2_``, ... (names ending with an
underscore are kept for internal symbols, see :mod:`sage_dynsym.symbols`,
so no declared name can clash) and writes the equations with them: a
compact form for reading or for generating code, exactly equal to the
original after :meth:`CompactEquations.expand`.

EXAMPLES: the spherical pendulum, equations (9) of Example 1 of
:doc:`the method </method>`::

    sage: from sage_dynsym import load
    sage: from sage_dynsym.description import example_path
    sage: from sage_dynsym.dynamics.compact import equations_cse
    sage: E = load(example_path('spherical_pendulum.yaml')).lagrangian().lagrange_equations()
    sage: C = equations_cse(E); C
    Equations written with 2 common subexpressions:
      x1_ = cos(theta)
      x2_ = sin(theta)
      0 = 2*dpsi*dtheta*l^2*m*x1_*x2_ + ddpsi*l^2*m*x2_^2
      0 = -dpsi^2*l^2*m*x1_*x2_ + ddtheta*l^2*m - g*l*m*x2_
    sage: C.expand() == E
    True
"""
from sage.structure.sage_object import SageObject
from sage.symbolic.ring import SR

from ..arguments import expression_argument, expression_list
from ..errors import ModelError, brief

__all__ = ['CompactEquations', 'equations_cse']

# above this many characters the representation is a summary
_SHOWN_CHARACTERS = 10000


class CompactEquations(SageObject):
    r"""
    Equations written with common subexpressions: a list of pairs
    ``(symbol, expression)``, each expression using only the symbols
    defined before it, and the equations using them (see
    :func:`equations_cse`).

    EXAMPLES::

        sage: from sage_dynsym.dynamics.compact import equations_cse
        sage: x, y = var('x y')
        sage: C = equations_cse([sin(x + y)^2 + x, sin(x + y)*y])
        sage: C.subexpressions(), C.equations()
        ([(x1_, sin(x + y))], [x1_^2 + x, x1_*y])

    TESTS: its symbols are defined in order. It has no value equality (two
    of them are equal only if they are the same object), so the pickling
    test, which compares the copy with the original, is skipped::

        sage: TestSuite(C).run(skip=['_test_pickling'])
    """

    def __init__(self, subexpressions, equations):
        pairs = subexpressions if isinstance(subexpressions, (list, tuple)) else None
        if pairs is None or not all(isinstance(p, (list, tuple)) and len(p) == 2 for p in pairs):
            raise ModelError(f"expected a list of pairs (symbol, expression), got "
                             f"{brief(subexpressions)}; equations_cse(equations) makes them",
                             entry="subexpressions")
        self._subexpressions = [(expression_argument(s, "subexpressions"),
                                 expression_argument(e, "subexpressions"))
                                for s, e in pairs]
        self._equations = expression_list(equations, "equations")

    def _test_definitions(self, **options):
        r"""Each name of :meth:`subexpressions` is a new symbol, and each
        expression uses only the names defined before it.

        EXAMPLES: run by ``TestSuite`` (see the class); a name used before
        its definition::

            sage: from sage_dynsym.dynamics.compact import CompactEquations
            sage: a, b, x = var('a b x')
            sage: CompactEquations([(a, b + 1), (b, x^2)], [a])._test_definitions()
            Traceback (most recent call last):
            ...
            AssertionError: b + 1 uses b before its definition
        """
        tester = self._tester(**options)
        names = [s for s, _ in self._subexpressions]
        tester.assertTrue(all(s.is_symbol() for s in names))
        tester.assertEqual(len(set(names)), len(names))
        for k, (symbol, expr) in enumerate(self._subexpressions):
            later = set(expr.variables()) & set(names[k:])
            tester.assertFalse(later, f"{expr} uses {', '.join(map(str, later))} before its "
                                      "definition")

    def subexpressions(self):
        r"""
        The list of pairs ``(symbol, expression)``, in the order of
        definition.

        EXAMPLES::

            sage: from sage_dynsym.dynamics.compact import equations_cse
            sage: x = var('x')
            sage: equations_cse([cos(x)^2, cos(x)]).subexpressions()
            [(x1_, cos(x))]
        """
        return list(self._subexpressions)

    def equations(self):
        r"""
        The equations (expressions meaning ``== 0``) written with the
        symbols of :meth:`subexpressions`.

        EXAMPLES::

            sage: from sage_dynsym.dynamics.compact import equations_cse
            sage: x = var('x')
            sage: equations_cse([cos(x)^2, cos(x)]).equations()
            [x1_^2, x1_]
        """
        return list(self._equations)

    def expand(self):
        r"""
        The equations with every symbol replaced by its expression: the
        equations given to :func:`equations_cse`.

        EXAMPLES::

            sage: from sage_dynsym.dynamics.compact import equations_cse
            sage: x, y = var('x y')
            sage: E = [sin(x + y)^2 + x, sin(x + y)*y]
            sage: equations_cse(E).expand() == E
            True
        """
        values = {}
        for symbol, expr in self._subexpressions:
            # earlier values are expanded already: one substitution each
            values[symbol] = expr.subs(values) if values else expr
        return [e.subs(values) if values else e for e in self._equations]

    def _repr_(self):
        r"""
        EXAMPLES::

            sage: from sage_dynsym.dynamics.compact import equations_cse
            sage: x = var('x')
            sage: equations_cse([x^2])
            Equations written with 0 common subexpressions:
              0 = x^2
        """
        lines = [f"  {s} = {e}" for s, e in self._subexpressions]
        lines += [f"  0 = {e}" for e in self._equations]
        head = f"Equations written with {len(self._subexpressions)} common subexpressions"
        if sum(map(len, lines)) > _SHOWN_CHARACTERS:
            return (f"{head} ({len(self._equations)} equations, "
                    f"{sum(map(len, lines))} characters; see subexpressions() and equations())")
        return "\n".join([head + ":"] + lines)


def _atomic(expr):
    # a symbol, a number, or such one times a number or to a number's power:
    # not worth a name
    if expr.operator() is None:
        return True
    operands = expr.operands()
    return len(operands) == 2 and all(x.operator() is None for x in operands) and (
        any(x.is_numeric() for x in operands))


def equations_cse(equations, reserved_names=()):
    r"""
    The equations written with their common subexpressions.

    Every subexpression that occurs at least twice in the equations (and
    is more than a symbol, a number, or a symbol times or to the power of
    a number) gets a symbol ``x<k>_``; names in ``reserved_names`` or
    among the equations' variables are skipped.

    INPUT:

    - ``equations`` -- a list of symbolic expressions
    - ``reserved_names`` -- (default: none) names (strings or symbols) the
      new symbols must not take

    OUTPUT: a :class:`CompactEquations`

    EXAMPLES::

        sage: from sage_dynsym.dynamics.compact import equations_cse
        sage: x, x1_, y = var('x x1_ y')
        sage: C = equations_cse([(x + y)*cos(x + y) + x1_, cos(x + y)^2], reserved_names=['x2_'])
        sage: C.subexpressions()
        [(x3_, x + y), (x4_, cos(x3_))]
        sage: C.equations()
        [x3_*x4_ + x1_, x4_^2]

    TESTS::

        sage: equations_cse([]).equations(), equations_cse([SR(0), x]).equations()
        ([], [0, x])
    """
    equations = expression_list(equations, "equations")
    taken = {str(name) for name in reserved_names}
    for e in equations:
        taken.update(str(v) for v in e.variables())
    # nodes by hash (pynac caches it); equal nodes are found among the few
    # sharing a hash with is_trivially_equal (structural comparison)
    buckets = {}

    def node(expr):
        bucket = buckets.setdefault(hash(expr), [])
        for entry in bucket:
            if entry[0].is_trivially_equal(expr):
                return entry, False
        entry = [expr, 0, None]    # expression, occurrences, rewritten form
        bucket.append(entry)
        return entry, True

    def count(expr):
        # occurrences of each node; a repeated node's inside is counted once
        stack = [expr]
        while stack:
            e = stack.pop()
            if _atomic(e):
                continue
            entry, new = node(e)
            entry[1] += 1
            if new:
                stack.extend(e.operands())

    for e in equations:
        count(e)
    subexpressions = []
    names = (f"x{k}_" for k in range(1, 10 ** 9) if f"x{k}_" not in taken)

    def rewrite(expr):
        if _atomic(expr):
            return expr
        entry = node(expr)[0]
        if entry[2] is None:
            operands = [rewrite(x) for x in expr.operands()]
            written = expr.operator()(*operands)
            if entry[1] > 1:
                symbol = SR.var(next(names))
                subexpressions.append((symbol, written))
                written = symbol
            entry[2] = written
        return entry[2]

    return CompactEquations(subexpressions, [rewrite(e) for e in equations])

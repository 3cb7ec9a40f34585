r"""
The description format of Lie--Poisson systems (read)

A description with ``kind: lie_poisson``::

    kind: lie_poisson
    name: heavy symmetric top
    algebra: e3                        # so3, e3, so4, so31, e4, or a mapping:
                                       #   {poisson_matrix: [[...], ...]} or
                                       #   {structure_constants: [[x, y, {z: 1}], ...]}
    variables: [M1, M2, M3, gamma1, gamma2, gamma3]   # or prefixes [M, gamma];
                                       # optional for a named algebra
    parameters: [A, C, m, g, l]
    positive: [A, C, m, g, l]          # optional: parameters known to be positive
    hamiltonian: "(M1^2 + M2^2)/(2*A) + M3^2/(2*C) + m*g*l*gamma3"

Structure constants are a list of brackets ``[a, b, {c: coefficient,
...}]``, `[e_a, e_b] = \sum c\, e_c` (named by the variables); the other
brackets are zero or follow by skew-symmetry. Expressions are parsed by
:class:`~sage_dynsym.io.expressions.ExpressionParser` with the declared
variables and parameters only.

:func:`read_lie_poisson_system` builds the system from the parsed YAML
mapping; :func:`~sage_dynsym.lie.report.lie_report` is its text report
(equations, Casimirs, polynomial integrals up to degree 2, stationary
solutions).

EXAMPLES::

    sage: from sage_dynsym.lie.description import lie_poisson_from_dict, lie_report
    sage: d = {'kind': 'lie_poisson', 'name': 'free rigid body', 'algebra': 'so3',
    ....:      'parameters': ['A1', 'A2', 'A3'], 'positive': ['A1', 'A2', 'A3'],
    ....:      'hamiltonian': 'M1^2/(2*A1) + M2^2/(2*A2) + M3^2/(2*A3)'}
    sage: S = lie_poisson_from_dict(d); S
    Lie-Poisson system 'free rigid body' on so3 (M1, M2, M3) with H = 1/2*M1^2/A1 + 1/2*M2^2/A2 + 1/2*M3^2/A3
    sage: print(lie_report(S))
    == free rigid body (Lie-Poisson system on so3: variables M1, M2, M3) ==
    Hamiltonian:
      H = 1/2*M1^2/A1 + 1/2*M2^2/A2 + 1/2*M3^2/A3
      LaTeX: ...
    Lie-Poisson equations dx/dt = {x, H}:
      dM1/dt = (A2 - A3)*M2*M3/(A2*A3)
      ...
    Casimirs (polynomial, degree <= 4):
      M1^2 + M2^2 + M3^2
      ...
    Polynomial first integrals of degree <= 2 besides H and the Casimirs:
      none (for generic parameter values)
    Stationary motions (Routh-Lyapunov over H, the Casimirs):
      solution 1 (isolated): M1 = 0, M2 = 0, M3 = 0
        stability: ...
      solution 2 (1-parameter family): M2 = 0, M3 = 0
        stability depends on the parameters:
          stable (Routh-Lyapunov) where [A1 - A2 > 0, A1 - A3 > 0, M1 != 0] or [A1 - A2 < 0, A1 - A3 < 0, M1 != 0]
          unstable (first approximation) where [A1 - A3 > 0, A1 - A2 < 0] or [A1 - A2 > 0, A1 - A3 < 0]
      ...
"""
from ..errors import DescriptionError, brief, in_source
from ..io.expressions import ExpressionParser
from ..symbols import check_names
from .algebras import NAMED, lie_algebra

__all__ = ['LIE_POISSON_KEYS', 'MAX_VARIABLES', 'MAX_PARAMETERS', 'read_lie_poisson_system',
           'LiePoissonFormat']

#: The keys of a ``kind: lie_poisson`` description.
LIE_POISSON_KEYS = {'kind', 'name', 'algebra', 'variables', 'parameters', 'positive',
                    'hamiltonian', 'results'}
#: Most variables of a description (e(4) has 10).
MAX_VARIABLES = 30
#: Most parameters of a description.
MAX_PARAMETERS = 500

def _names(data, key, source, required=False, limit=None):
    value = data.get(key)
    if value is None:
        if required:
            raise DescriptionError(f"missing key {key!r} (a list of symbol names)", entry=key,
                                   source=source)
        return None
    if not isinstance(value, list) or not all(isinstance(v, str) for v in value):
        raise DescriptionError(f"expected a list of symbol names, got {brief(value)}",
                               entry=key, source=source)
    if limit is not None and len(value) > limit:
        raise DescriptionError(f"{len(value)} names; a description has at most {limit}",
                               entry=key, source=source)
    return list(value)


def read_lie_poisson_system(cls, data, source=None):
    r"""
    Build a :class:`~sage_dynsym.lie.system.LiePoissonSystem` (the class
    ``cls``, whose ``from_dict`` calls this function) from a
    ``kind: lie_poisson`` description mapping (see the module
    documentation).

    INPUT:

    - ``cls`` -- the class built
    - ``data`` -- the mapping
    - ``source`` -- (optional) the file name, for error messages

    EXAMPLES (through the earlier name, see :mod:`sage_dynsym.lie.description`):
    a user's algebra, `\mathfrak{sl}(2)` (`[h, x] = 2x`, `[h, y] =
    -2y`, `[x, y] = h`)::

        sage: from sage_dynsym.lie.description import lie_poisson_from_dict
        sage: d = {'kind': 'lie_poisson', 'variables': ['h', 'x', 'y'],
        ....:      'algebra': {'structure_constants': [['h', 'x', {'x': 2}],
        ....:                                          ['h', 'y', {'y': -2}], ['x', 'y', {'h': 1}]]},
        ....:      'hamiltonian': 'h^2/2 + x*y'}
        sage: S = lie_poisson_from_dict(d); S.casimirs()
        [h^2 + 4*x*y]

    TESTS::

        sage: lie_poisson_from_dict({'kind': 'lie_poisson', 'algebra': 'so5', 'hamiltonian': 'M1'},
        ....:                       'top.yaml')
        Traceback (most recent call last):
        ...
        ModelError: top.yaml: algebra: unknown Lie algebra 'so5'; the named algebras are so3, e3, so4, so31, e4 (or give a Poisson matrix or structure constants)
        sage: lie_poisson_from_dict({'kind': 'lie_poisson', 'algebra': 'so3',
        ....:                        'hamiltonian': 'M1^2 + gamma1'}, 'top.yaml')
        Traceback (most recent call last):
        ...
        ExpressionError: top.yaml: hamiltonian: undeclared symbol 'gamma1' in 'M1^2 + gamma1'; declared symbols are: M1, M2, M3, t
        sage: lie_poisson_from_dict({'kind': 'lie_poisson', 'algebra': 'e3',
        ....:                        'variables': ['a', 'b', 'c'], 'hamiltonian': 'a'}, 'top.yaml')
        Traceback (most recent call last):
        ...
        ModelError: top.yaml: variables: e3 has 6 coordinates (M1, M2, M3, gamma1, gamma2, gamma3) or 2 prefixes (e.g. ['M', 'gamma']), got 3 variables: ['a', 'b', 'c']
        sage: lie_poisson_from_dict({'kind': 'lie_poisson', 'variables': ['x', 'y', 'z'],
        ....:     'algebra': {'poisson_matrix': [[0, 'x', 0], ['-x', 0, 'y'], [0, '-y', 0]]},
        ....:     'hamiltonian': 'x'}, 'bad.yaml')
        Traceback (most recent call last):
        ...
        ModelError: bad.yaml: algebra: the matrix breaks the Jacobi identity: {x, {y, z}} + {y, {z, x}} + {z, {x, y}} = x, not 0
        sage: lie_poisson_from_dict({'kind': 'lie_poisson', 'variables': ['x', 'y'],
        ....:     'algebra': {'structure_constants': [['x', 'y', {'y': 1}], ['y', 'x', {'y': -1}]]},
        ....:     'hamiltonian': 'x*y'}, 'b.yaml')
        Traceback (most recent call last):
        ...
        DescriptionError: b.yaml: algebra.structure_constants[1]: the bracket of y and x is already given in structure_constants[0]: give each pair once (the other order follows by skew-symmetry)
        sage: lie_poisson_from_dict({'kind': 'lie_poisson', 'algebra': 'so3', 'hamiltonian': 'M1',
        ....:                        'colour': 'red'}, 'top.yaml')
        Traceback (most recent call last):
        ...
        DescriptionError: top.yaml: unknown key 'colour'; a lie_poisson description has the keys algebra, hamiltonian, kind, name, parameters, positive, results, variables
        sage: lie_poisson_from_dict({'kind': 'lie_poisson', 'algebra': 'so3'}, 'top.yaml')
        Traceback (most recent call last):
        ...
        DescriptionError: top.yaml: hamiltonian: missing key 'hamiltonian' (an expression in the variables and parameters)
    """
    with in_source(source):
        return _from_dict(cls, data, source)


def _from_dict(cls, data, source):
    if not isinstance(data, dict):
        raise DescriptionError(f"expected a mapping, got {brief(data)}", source=source)
    for key in data:
        if key not in LIE_POISSON_KEYS:
            raise DescriptionError(f"unknown key {brief(key)}; a lie_poisson description has "
                                   f"the keys {', '.join(sorted(LIE_POISSON_KEYS))}",
                                   source=source)
    for key, what in (('algebra', "a named algebra or a mapping"),
                      ('hamiltonian', "an expression in the variables and parameters")):
        if key not in data:
            raise DescriptionError(f"missing key {key!r} ({what})", entry=key, source=source)
    name = data.get('name')
    if name is not None and not isinstance(name, (str, int, float)):
        raise DescriptionError(f"expected a text, got {brief(name)}", entry='name',
                               source=source)
    parameters = _names(data, 'parameters', source, limit=MAX_PARAMETERS) or []
    variables = _names(data, 'variables', source, limit=MAX_VARIABLES)
    algebra = data['algebra']
    named = isinstance(algebra, str)
    if named:
        # the structure first: an unknown name or a wrong number of variables
        # is reported before the expressions that use them
        algebra = lie_algebra(algebra, variables)
        variables = [str(x) for x in algebra.variables()]
    elif variables is None:
        raise DescriptionError("a Poisson matrix or structure constants need the list of "
                               "variables", entry='variables', source=source)
    declared = [(v, 'variable', f'variables[{i}]') for i, v in enumerate(variables)]
    declared += [(a, 'parameter', f'parameters[{i}]') for i, a in enumerate(parameters)]
    check_names(declared, 'mechanical', DescriptionError, source)
    parser = ExpressionParser(variables + parameters)
    H = parser.parse(data['hamiltonian'], entry='hamiltonian')
    if not named:
        algebra = _algebra(algebra, variables, parser, source)
    positive = _names(data, 'positive', source, limit=MAX_PARAMETERS) or []
    for i, a in enumerate(positive):
        if a not in parameters:
            raise DescriptionError(f"{a!r} is not a declared parameter", entry=f'positive[{i}]',
                                   source=source)
    return cls(algebra, H, variables=[parser.parse(v) for v in variables],
               parameters=[parser.parse(a) for a in parameters],
               positive=[parser.parse(a) for a in positive],
               name=None if name is None else str(name))


def _algebra(algebra_data, variables, parser, source):
    if not isinstance(algebra_data, dict) or len(algebra_data) != 1:
        raise DescriptionError(f"expected a named algebra ({', '.join(NAMED)}) or a mapping "
                               "with one key, poisson_matrix or structure_constants, got "
                               f"{brief(algebra_data)}", entry='algebra', source=source)
    (kind, value), = algebra_data.items()
    n = len(variables)
    if kind == 'poisson_matrix':
        if not isinstance(value, list) or len(value) != n or any(
                not isinstance(row, list) or len(row) != n for row in value):
            raise DescriptionError(f"expected a {n}x{n} matrix (a list of {n} rows), got "
                                   f"{brief(value)}", entry='algebra.poisson_matrix',
                                   source=source)
        return [[parser.parse(c, entry=f'algebra.poisson_matrix[{i}][{j}]')
                 for j, c in enumerate(row)] for i, row in enumerate(value)]
    if kind == 'structure_constants':
        if not isinstance(value, list):
            raise DescriptionError(f"expected a list of brackets [a, b, {{c: coefficient}}], "
                                   f"got {brief(value)}", entry='algebra.structure_constants',
                                   source=source)
        constants, given = {}, {}
        for i, item in enumerate(value):
            entry = f'algebra.structure_constants[{i}]'
            if not (isinstance(item, list) and len(item) == 3 and isinstance(item[2], dict)
                    and all(isinstance(v, str) and v in variables for v in item[:2])
                    and all(isinstance(k, str) and k in variables for k in item[2])):
                raise DescriptionError(f"expected a bracket [a, b, {{c: coefficient}}] of the "
                                       f"variables {', '.join(variables)}, got {brief(item)}",
                                       entry=entry, source=source)
            pair = frozenset(item[:2])
            if pair in given:
                raise DescriptionError(f"the bracket of {item[0]} and {item[1]} is already given "
                                       f"in structure_constants[{given[pair]}]: give each pair "
                                       "once (the other order follows by skew-symmetry)",
                                       entry=entry, source=source)
            given[pair] = i
            constants[item[0], item[1]] = {k: parser.parse(c, entry=f'{entry}.{k}')
                                           for k, c in item[2].items()}
        return constants
    raise DescriptionError(f"unknown key {brief(kind)}: expected poisson_matrix or "
                           "structure_constants", entry='algebra', source=source)


class LiePoissonFormat:
    r"""
    The description format of :class:`~sage_dynsym.lie.system.LiePoissonSystem`,
    both ways: the class inherits it (the model interface's ``from_dict``,
    ``to_dict``, ``results`` and ``result_symbols``).

    EXAMPLES::

        sage: from sage_dynsym.lie.format import LiePoissonFormat
        sage: from sage_dynsym.lie.system import LiePoissonSystem
        sage: issubclass(LiePoissonSystem, LiePoissonFormat)
        True
    """

    @classmethod
    def from_dict(cls, data, source=None):
        r"""
        The Lie--Poisson system of a description mapping (``kind: lie_poisson``); ``source``
        names the file in errors. The format is read by
        :func:`~sage_dynsym.lie.format.read_lie_poisson_system`.

        EXAMPLES::

            sage: from sage_dynsym.lie.system import LiePoissonSystem
            sage: LiePoissonSystem.from_dict({'kind': 'lie_poisson', 'algebra': 'so3',
            ....:                             'hamiltonian': 'M3^2/2'}).equations()
            [M2*M3, -M1*M3, 0]
        """
        return read_lie_poisson_system(cls, data, source)

    def to_dict(self):
        r"""
        The description mapping of the system (``kind: lie_poisson``;
        expressions as text), the inverse of
        :func:`~sage_dynsym.lie.description.lie_poisson_from_dict`.

        EXAMPLES::

            sage: from sage_dynsym.lie.system import LiePoissonSystem
            sage: M1, A = var('M1 A')
            sage: LiePoissonSystem('so3', M1^2/A, positive=[A], name='top').to_dict()
            {'algebra': 'so3',
             'hamiltonian': 'M1^2/A',
             'kind': 'lie_poisson',
             'name': 'top',
             'parameters': ['A'],
             'positive': ['A'],
             'variables': ['M1', 'M2', 'M3']}
        """
        structure = self.structure()
        algebra = structure.name() or {'poisson_matrix': [[str(c) for c in row]
                                                          for row in structure.matrix().rows()]}
        data = {'kind': 'lie_poisson'}
        if self.name():
            data['name'] = self.name()
        data.update({'algebra': algebra, 'variables': [str(x) for x in self.variables()],
                     'parameters': [str(a) for a in self.parameters()]})
        if self.positive_parameters():
            data['positive'] = [str(a) for a in self.positive_parameters()]
        data['hamiltonian'] = str(self.hamiltonian())
        return data

    def results(self):
        r"""
        The ``results:`` section of a saved description: the equations and
        the Casimirs (of degree at most 2), as text and LaTeX.

        EXAMPLES::

            sage: from sage_dynsym.lie.system import LiePoissonSystem
            sage: M1, A = var('M1 A')
            sage: R = LiePoissonSystem('so3', M1^2/A).results(); R['casimirs']
            ['M1^2 + M2^2 + M3^2']
        """
        from sage.misc.latex import latex
        equations = self.equations()
        casimirs = self.casimirs(degree=2)
        return {'equations': [str(e) for e in equations],
                'equations_latex': [str(latex(e)) for e in equations],
                'casimirs': [str(c) for c in casimirs],
                'casimirs_latex': [str(latex(c)) for c in casimirs]}

    def result_symbols(self, results):
        r"""
        The names a ``results:`` section of this system may use: its
        variables and parameters; no functions.

        EXAMPLES::

            sage: from sage_dynsym.lie.system import LiePoissonSystem
            sage: M1, A = var('M1 A')
            sage: LiePoissonSystem('so3', M1^2/A).result_symbols({})
            (['M1', 'M2', 'M3', 'A'], ())
        """
        return [str(x) for x in self.variables()] + [str(a) for a in self.parameters()], ()

r"""
Reading YAML description files safely

PyYAML's *safe* loader (tags that would construct Python objects are
refused), with limits checked while the document is read: the file's size,
the nesting depth, the number of aliases and the size once they are
expanded (the "billion laughs" bomb), the digits of integers; duplicate
keys and merge keys are errors. Every problem is a
:class:`~sage_dynsym.errors.DescriptionError` naming the file.

EXAMPLES::

    sage: import tempfile
    sage: from sage_dynsym.io.yaml import read_yaml
    sage: f = tempfile.NamedTemporaryFile('w', suffix='.yaml', delete=False)
    sage: _ = f.write("kind: circuit\nbranches: [[1, 2, R1]]\n"); f.close()
    sage: read_yaml(f.name)
    {'branches': [[1, 2, 'R1']], 'kind': 'circuit'}
"""
import os
import stat

import yaml

from ..errors import DescriptionError, brief
from .expressions import MAX_INTEGER_DIGITS

__all__ = ['MAX_FILE_BYTES', 'MAX_YAML_DEPTH', 'MAX_YAML_ALIASES', 'MAX_YAML_VALUES', 'read_yaml']

#: Largest description file read (bytes).
MAX_FILE_BYTES = 32 * 2**20
#: Deepest nesting of YAML lists and mappings.
MAX_YAML_DEPTH = 50
#: Most YAML aliases (``*name``) in one file.
MAX_YAML_ALIASES = 100
#: Most YAML values once aliases are expanded (the "billion laughs" bomb
#: expands 81 aliases into 10^9 values).
MAX_YAML_VALUES = 100_000


class _Refused(yaml.YAMLError):
    # a limit of the reader, with the place in the file
    def __init__(self, message, mark=None):
        where = f" (line {mark.line + 1}, column {mark.column + 1})" if mark else ""
        super().__init__(message + where)


class _Loader(yaml.SafeLoader):
    r"""
    PyYAML's safe loader with limits: nesting depth, number of aliases,
    size once aliases are expanded, digits of integers; duplicate keys and
    merge keys (``<<``) are errors. The composer of PyYAML recurses once per
    nesting level: the depth is checked before each level.
    """

    def __init__(self, stream):
        super().__init__(stream)
        self._depth = 0
        self._aliases = 0

    def compose_node(self, parent, index):
        if self.check_event(yaml.AliasEvent):
            self._aliases += 1
            if self._aliases > MAX_YAML_ALIASES:
                raise _Refused(f"more than {MAX_YAML_ALIASES} YAML aliases (MAX_YAML_ALIASES)",
                               self.peek_event().start_mark)
            return super().compose_node(parent, index)
        self._depth += 1
        if self._depth > MAX_YAML_DEPTH:
            raise _Refused(f"lists and mappings nested deeper than {MAX_YAML_DEPTH} levels "
                           "(MAX_YAML_DEPTH)", self.peek_event().start_mark)
        try:
            return super().compose_node(parent, index)
        finally:
            self._depth -= 1

    def construct_document(self, node):
        _check_expanded_size(node)
        return super().construct_document(node)

    def construct_mapping(self, node, deep=False):
        if isinstance(node, yaml.MappingNode):
            seen = {}
            for key_node, _ in node.value:
                if key_node.tag == 'tag:yaml.org,2002:merge':
                    raise _Refused("YAML merge keys (<<) are not supported in description "
                                   "files", key_node.start_mark)
                key = self.construct_object(key_node, deep=True)
                try:
                    first = seen.setdefault(key, key_node)
                except TypeError:
                    continue            # unhashable: the base class says so
                if first is not key_node:
                    raise _Refused(f"duplicate key {brief(key)} (first at line "
                                   f"{first.start_mark.line + 1})", key_node.start_mark)
        return super().construct_mapping(node, deep=deep)

    def construct_yaml_int(self, node):
        text = str(node.value).replace('_', '').lstrip('+-')
        if len(text) > MAX_INTEGER_DIGITS:
            raise _Refused(f"an integer with {len(text)} digits (at most {MAX_INTEGER_DIGITS}; "
                           "MAX_INTEGER_DIGITS)", node.start_mark)
        return super().construct_yaml_int(node)


_Loader.add_constructor('tag:yaml.org,2002:int', _Loader.construct_yaml_int)


def _check_expanded_size(root):
    # values counted with aliases expanded (memoized: shared nodes are
    # counted once per use, in linear time), and no recursive alias
    size, state, stack = {}, {}, [(root, False)]
    while stack:
        node, done = stack.pop()
        key = id(node)
        if done:
            children = _children(node)
            size[key] = 1 + sum(size[id(c)] for c in children)
            if size[key] > MAX_YAML_VALUES:
                raise _Refused(f"more than {MAX_YAML_VALUES} values once YAML aliases are "
                               "expanded (MAX_YAML_VALUES)", node.start_mark)
            state[key] = 2
            continue
        if state.get(key) == 2:
            continue
        if state.get(key) == 1:
            raise _Refused("a YAML alias refers to a list or mapping that contains it",
                           node.start_mark)
        state[key] = 1
        stack.append((node, True))
        for child in _children(node):
            if state.get(id(child)) == 1:
                raise _Refused("a YAML alias refers to a list or mapping that contains it",
                               child.start_mark)
            stack.append((child, False))


def _children(node):
    if isinstance(node, yaml.SequenceNode):
        return node.value
    if isinstance(node, yaml.MappingNode):
        return [x for pair in node.value for x in pair]
    return []


def read_yaml(path):
    r"""
    Read a description file: UTF-8 text of at most :data:`MAX_FILE_BYTES`
    bytes, parsed by PyYAML's safe loader with limits (nesting depth
    :data:`MAX_YAML_DEPTH`, :data:`MAX_YAML_ALIASES` aliases,
    :data:`MAX_YAML_VALUES` values once aliases are expanded, integers of
    at most :data:`~sage_dynsym.io.expressions.MAX_INTEGER_DIGITS` digits);
    duplicate keys are errors. Any problem becomes a
    :class:`~sage_dynsym.errors.DescriptionError` naming the file.

    EXAMPLES::

        sage: from sage_dynsym.io.yaml import read_yaml
        sage: import tempfile
        sage: def write(text, mode='w'):
        ....:     f = tempfile.NamedTemporaryFile(mode, suffix='.yaml', delete=False)
        ....:     _ = f.write(text); f.close(); return f.name
        sage: read_yaml(write("kind: !!python/object/apply:os.system ['echo hacked']\n"))
        Traceback (most recent call last):
        ...
        DescriptionError: ...: the file contains a YAML tag that would construct a Python object (...); description files may only hold plain data
        sage: read_yaml('/nonexistent.yaml')
        Traceback (most recent call last):
        ...
        DescriptionError: /nonexistent.yaml: cannot read the file: No such file or directory

    TESTS::

        sage: read_yaml(write("kind: circuit\nname: a\nkind: mechanical\n"))
        Traceback (most recent call last):
        ...
        DescriptionError: ...: not valid YAML: duplicate key 'kind' (first at line 1) (line 3, column 1)
        sage: read_yaml(write("[" * 100 + "]" * 100))
        Traceback (most recent call last):
        ...
        DescriptionError: ...: not valid YAML: lists and mappings nested deeper than 50 levels (MAX_YAML_DEPTH) (line 1, column 51)
        sage: read_yaml(write(b"kind: \xff\xfe\n", 'wb'))
        Traceback (most recent call last):
        ...
        DescriptionError: ...: the file is not UTF-8 text (invalid byte 0xff at byte 6)
        sage: bomb = "a: &a [x, x, x, x, x, x, x, x, x, x]\n" + "".join(
        ....:     f"{c}: &{c} [{', '.join(['*' + p] * 10)}]\n" for p, c in zip('abcdefg', 'bcdefgh'))
        sage: read_yaml(write(bomb))
        Traceback (most recent call last):
        ...
        DescriptionError: ...: not valid YAML: more than 100000 values once YAML aliases are expanded (MAX_YAML_VALUES) (line 5, column 4)
        sage: read_yaml(write("a: &a [*a]\n"))
        Traceback (most recent call last):
        ...
        DescriptionError: ...: not valid YAML: a YAML alias refers to a list or mapping that contains it (line 1, column 4)
        sage: read_yaml(write("mass: " + "9" * 5000 + "\n"))
        Traceback (most recent call last):
        ...
        DescriptionError: ...: not valid YAML: an integer with 5000 digits (at most 1000; MAX_INTEGER_DIGITS) (line 1, column 7)
        sage: read_yaml(tempfile.gettempdir())
        Traceback (most recent call last):
        ...
        DescriptionError: ...: cannot read the file: not a regular file
        sage: read_yaml(0)
        Traceback (most recent call last):
        ...
        DescriptionError: 0: expected a file name, got 0
    """
    source = str(path)
    if not isinstance(path, (str, bytes, os.PathLike)):
        raise DescriptionError(f"expected a file name, got {brief(path)}", source=brief(path))
    try:
        if not stat.S_ISREG(os.stat(path).st_mode):
            raise DescriptionError("cannot read the file: not a regular file", source=source)
        with open(path, 'rb') as stream:
            raw = stream.read(MAX_FILE_BYTES + 1)
    except OSError as err:
        raise DescriptionError(f"cannot read the file: {err.strerror or err}",
                               source=source) from err
    except (TypeError, ValueError) as err:
        raise DescriptionError(f"cannot read the file: {err}", source=source) from err
    if len(raw) > MAX_FILE_BYTES:
        raise DescriptionError(f"the file is larger than {MAX_FILE_BYTES} bytes "
                               "(MAX_FILE_BYTES)", source=source)
    try:
        text = raw.decode('utf-8')
    except UnicodeDecodeError as err:
        raise DescriptionError(f"the file is not UTF-8 text (invalid byte "
                               f"0x{raw[err.start]:02x} at byte {err.start})",
                               source=source) from err
    loader = None
    try:
        loader = _Loader(text)
        return loader.get_single_data()
    except yaml.constructor.ConstructorError as err:
        if err.problem and 'python/' in err.problem:
            raise DescriptionError("the file contains a YAML tag that would construct a Python "
                                   f"object ({err.problem}); description files may only hold "
                                   "plain data", source=source) from err
        raise DescriptionError(f"not valid YAML: {_yaml_problem(err)}", source=source) from err
    except yaml.YAMLError as err:
        raise DescriptionError(f"not valid YAML: {_yaml_problem(err)}", source=source) from err
    finally:
        if loader is not None:
            loader.dispose()


def _yaml_problem(err):
    # one line: what is wrong and where (PyYAML's text quotes the line)
    problem = getattr(err, 'problem', None)
    if problem is None:
        return " ".join(str(err).replace('"<unicode string>", ', '').split())
    context = getattr(err, 'context', None)
    mark = getattr(err, 'problem_mark', None)
    where = f" (line {mark.line + 1}, column {mark.column + 1})" if mark else ""
    return f"{context + ': ' if context else ''}{problem}{where}"

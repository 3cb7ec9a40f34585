r"""
The system builder: a model entered in form fields

The counterpart of the original packages' dialog panels. The user types
the parameters, coordinates, the force function (gravity and/or a
potential term), the dissipation, holonomic constraints and, body by body,
the parent, rotation sequence, vectors, mass and inertia, and loads on the
bodies -- or, for a circuit, one branch per line (short or long form). :func:`mechanical_description` and
:func:`circuit_description` turn those texts into the same dictionary a
description file holds, so the model is built and checked by the loader of
:mod:`sage_dynsym.description` (safe parser, errors naming the entry), and
:func:`~sage_dynsym.description.save` writes it to a file.
:class:`SystemBuilder` is the widget page around them.

Field syntax: lists are comma-separated (``m, l, g``); a rotation sequence
is ``axis angle`` pairs (``3 psi, 1 theta``); an inertia tensor is three
diagonal entries or nine entries row by row (rows may be separated by
``;``); constraints are one per line; a load is the fields ``body``,
``point`` (in the body's axes), ``force``, ``torque`` (three components
each, optional) and ``axes`` (``0``: inertial, or a body name). A branch is
``from to element`` (``1 2 L1``), or in long form ``from to kind name``
with an optional ``= value`` (``1 2 capacitor C1 = C0*(1 + u^2)``); two
coupled windings are ``mutual L1 L2 = M``.

EXAMPLES::

    sage: from sage_dynsym.interact.builder import mechanical_description, model_from_description
    sage: body = dict(name='pendulum', parent='0', rotations='3 psi, 1 theta',
    ....:             joint='0, 0, 0', mass_center='0, 0, l', mass='m',
    ....:             inertia='m*l^2, m*l^2, 0')
    sage: data = mechanical_description('spherical pendulum', 'm, l, g', 'psi, theta',
    ....:                               '0, 0, -g', [body])
    sage: data['bodies'][0]['rotations'], data['bodies'][0]['inertia']
    ([[3, 'psi'], [1, 'theta']], [['m*l^2', '0', '0'], ['0', 'm*l^2', '0'], ['0', '0', '0']])
    sage: S = model_from_description(data); S.lagrangian().expr()
    1/2*dpsi^2*l^2*m*sin(theta)^2 + 1/2*dtheta^2*l^2*m - g*l*m*cos(theta)
"""
import re
from collections import namedtuple

import ipywidgets as widgets

from ..description import kinds
from ..errors import DescriptionError, DynSymError

__all__ = ['split_list', 'mechanical_description', 'circuit_description', 'model_from_description',
           'SystemBuilder']


def split_list(text, separators=","):
    r"""
    Split ``text`` at the separators that are outside parentheses and
    brackets, stripping blanks; an empty text gives ``[]``.

    EXAMPLES::

        sage: from sage_dynsym.interact.builder import split_list
        sage: split_list(' m, atan2(y, x) ;l', ',;')
        ['m', 'atan2(y, x)', 'l']
        sage: split_list('  ')
        []
    """
    items, depth, current = [], 0, []
    for ch in text:
        if ch in "([":
            depth += 1
        elif ch in ")]":
            depth -= 1
        if ch in separators and depth == 0:
            items.append("".join(current).strip())
            current = []
        else:
            current.append(ch)
    items.append("".join(current).strip())
    return [item for item in items if item]


def _rotations(text, entry):
    pairs = []
    for item in split_list(text):
        parts = item.split()
        if len(parts) != 2 or parts[0] not in ("1", "2", "3"):
            raise DescriptionError(f"expected 'axis angle' pairs such as '3 psi, 1 theta', "
                                   f"got {item!r}", entry=entry)
        pairs.append([int(parts[0]), parts[1]])
    return pairs


def _vector(text, entry):
    items = split_list(text)
    if len(items) != 3:
        raise DescriptionError(f"expected three comma-separated components, got {text!r}",
                               entry=entry)
    return items


def _inertia(text, entry):
    items = split_list(text, ",;")
    if len(items) == 3:
        return [[items[i] if i == j else "0" for j in range(3)] for i in range(3)]
    if len(items) == 9:
        return [items[3 * i:3 * i + 3] for i in range(3)]
    raise DescriptionError("expected the 3 diagonal entries or the 9 entries of the "
                           f"inertia tensor, got {len(items)}", entry=entry)


def mechanical_description(name, parameters, coordinates, gravity, bodies,
                           dissipation="", potential="", constraints="", loads=()):
    r"""
    The description-file dictionary of a mechanical system entered as text
    fields.

    INPUT:

    - ``name``, ``parameters``, ``coordinates`` -- strings (lists
      comma-separated)
    - ``gravity`` -- the gravity vector in the inertial axes (three
      components), or an empty string for none
    - ``bodies`` -- a list of dictionaries with the string fields ``name``,
      ``parent``, ``rotations``, ``joint``, ``mass_center``, ``mass``,
      ``inertia`` and optionally ``velocity`` (empty: the default)
    - ``dissipation`` -- (optional) the Rayleigh function
    - ``potential`` -- (optional) a force function `U(q, t)` added to the
      gravity term (e.g. ``-k*x^2/2`` for a spring)
    - ``constraints`` -- (optional) holonomic constraints `f(q, t)`, one
      per line, each meaning ``f == 0``
    - ``loads`` -- (optional) a list of dictionaries with the string fields
      ``body``, ``point``, ``force``, ``torque`` and ``axes``

    OUTPUT: a dictionary as read from a description file

    EXAMPLES: a pendulum on a cart held by a spring, pushed at its bob::

        sage: from sage_dynsym.interact.builder import mechanical_description
        sage: cart = dict(name='cart', joint='x, 0, 0', mass='M')
        sage: bob = dict(name='bob', parent='cart', rotations='2 phi', mass_center='0, 0, -l',
        ....:            mass='m')
        sage: push = dict(body='bob', point='0, 0, -l', force='F, 0, 0', axes='0')
        sage: data = mechanical_description('cart', 'M, m, l, g, k, F', 'x, phi', '0, 0, -g',
        ....:                               [cart, bob], potential='-k*x^2/2', loads=[push])
        sage: data['force_function']
        [{'uniform_gravity': ['0', '0', '-g']}, {'expression': '-k*x^2/2'}]
        sage: data['loads']
        [{'axes': 0, 'body': 'bob', 'force': ['F', '0', '0'], 'point': ['0', '0', '-l']}]
        sage: mechanical_description('ring', 'm', 'x, y', '', [], constraints='x^2 + y^2 - 1')['constraints']
        ['x^2 + y^2 - 1']

    TESTS::

        sage: mechanical_description('x', 'm', 'q', '', [dict(rotations='4 q')])
        Traceback (most recent call last):
        ...
        DescriptionError: bodies[0].rotations: expected 'axis angle' pairs such as '3 psi, 1 theta', got '4 q'
        sage: mechanical_description('x', 'm', 'q', '0, 0', [])
        Traceback (most recent call last):
        ...
        DescriptionError: force_function.uniform_gravity: expected three comma-separated components, got '0, 0'
        sage: mechanical_description('x', 'm', 'q', '', [], loads=[dict(body='b', force='1, 2')])
        Traceback (most recent call last):
        ...
        DescriptionError: loads[0].force: expected three comma-separated components, got '1, 2'
    """
    data = {'kind': 'mechanical', 'name': name.strip() or 'mechanical system',
            'parameters': split_list(parameters), 'coordinates': split_list(coordinates)}
    terms = []
    if gravity.strip():
        terms.append({'uniform_gravity': _vector(gravity, 'force_function.uniform_gravity')})
    if potential.strip():
        terms.append({'expression': potential.strip()})
    if terms:
        # one term keeps the single-mapping form of older files
        data['force_function'] = terms[0] if len(terms) == 1 else terms
    if dissipation.strip():
        data['dissipation'] = dissipation.strip()
    lines = [line.strip() for line in constraints.splitlines() if line.strip()]
    if lines:
        data['constraints'] = lines
    data['bodies'] = []
    for k, fields in enumerate(bodies):
        entry = f"bodies[{k}]"
        body = {'name': fields.get('name', '').strip() or f"body {k + 1}",
                'parent': _parent(fields.get('parent', '0'))}
        body['rotations'] = _rotations(fields.get('rotations', ''), f"{entry}.rotations")
        for key in ('joint', 'velocity', 'mass_center'):
            if fields.get(key, '').strip():
                body[key] = _vector(fields[key], f"{entry}.{key}")
        body['mass'] = fields.get('mass', '0').strip() or '0'
        if fields.get('inertia', '').strip():
            body['inertia'] = _inertia(fields['inertia'], f"{entry}.inertia")
        data['bodies'].append(body)
    if loads:
        data['loads'] = [_load(fields, f"loads[{k}]") for k, fields in enumerate(loads)]
    return data


def _load(fields, entry):
    load = {'body': _parent(fields.get('body', ''))}
    for key in ('point', 'force', 'torque'):
        if fields.get(key, '').strip():
            load[key] = _vector(fields[key], f"{entry}.{key}")
    load['axes'] = _parent(fields.get('axes', '0'))
    return load


def _parent(text):
    text = str(text).strip() or "0"
    return int(text) if text.isdigit() else text


def circuit_description(name, branches, parameters=""):
    r"""
    The description-file dictionary of a circuit entered as text: one
    branch per line, ``from to element`` (short form), ``from to kind
    name`` with an optional ``= value`` (long form, for the kinds of
    :data:`~sage_dynsym.circuits.elements.BRANCH_KINDS`), or ``mutual L1 L2
    = M`` for a mutual inductance.

    EXAMPLES::

        sage: from sage_dynsym.interact.builder import circuit_description, model_from_description
        sage: data = circuit_description('RLC', '1 2 E1\n2 3 R1\n3 4 L1\n4 1 C1')
        sage: data['branches']
        [[1, 2, 'E1'], [2, 3, 'R1'], [3, 4, 'L1'], [4, 1, 'C1']]
        sage: model_from_description(data).state_equations()
        [-R1*i1 + E1 + u2, -i1]

    Long-form entries and a mutual inductance, with a parameter used in a
    value::

        sage: data = circuit_description('coupled', '1 2 L1\n2 1 capacitor C1 = C0\n'
        ....:                            '1 2 L2\nmutual L1 L2 = M', parameters='C0, M')
        sage: data['branches'][1], data['branches'][3]
        ({'from': 2, 'kind': 'capacitor', 'name': 'C1', 'to': 1, 'value': 'C0'},
         {'between': ['L1', 'L2'], 'kind': 'mutual', 'value': 'M'})

    TESTS::

        sage: circuit_description('x', '1 2')
        Traceback (most recent call last):
        ...
        DescriptionError: branches[0]: expected 'from_node to_node element' such as '1 2 L1', 'from_node to_node kind name [= value]' or 'mutual L1 L2 = M', got '1 2'
        sage: circuit_description('x', 'mutual L1 = M')
        Traceback (most recent call last):
        ...
        DescriptionError: branches[0]: expected 'from_node to_node element' such as '1 2 L1', 'from_node to_node kind name [= value]' or 'mutual L1 L2 = M', got 'mutual L1 = M'
    """
    rows = []
    for k, line in enumerate(l for l in branches.splitlines() if l.strip()):
        rows.append(_branch(line.strip(), f"branches[{k}]"))
    data = {'kind': 'circuit', 'name': name.strip() or 'circuit', 'branches': rows}
    if parameters.strip():
        data['parameters'] = split_list(parameters)
    return data


def _branch(line, entry):
    head, _, value = line.partition("=")
    parts, value = head.replace(",", " ").split(), value.strip()
    if parts and parts[0] == 'mutual' and len(parts) == 3 and value:
        return {'kind': 'mutual', 'between': parts[1:], 'value': value}
    if len(parts) >= 3 and parts[0].isdigit() and parts[1].isdigit():
        ends = [int(parts[0]), int(parts[1])]
        if len(parts) == 3 and not value:
            return ends + [parts[2]]
        if len(parts) == 4:
            branch = {'from': ends[0], 'to': ends[1], 'kind': parts[2], 'name': parts[3]}
            if value:
                branch['value'] = value
            return branch
    raise DescriptionError("expected 'from_node to_node element' such as '1 2 L1', "
                           "'from_node to_node kind name [= value]' or 'mutual L1 L2 = M', "
                           f"got {line!r}", entry=entry)


def model_from_description(data, source="system builder"):
    r"""
    Build the model of a description dictionary with the description-file
    loader (same checks, same error messages).

    EXAMPLES::

        sage: from sage_dynsym.interact.builder import model_from_description
        sage: model_from_description({'kind': 'circuit', 'branches': [[1, 2, 'L1'], [2, 1, 'C1']]})
        Circuit with 2 branches on 2 nodes
    """
    from ..description import model_from_dict
    return model_from_dict(dict(data, kind=data.get('kind', 'mechanical')), source=source)


_BODY_FIELDS = [('name', 'name'), ('parent', 'parent'), ('rotations', 'rotations'),
                ('joint', 'joint r0'), ('velocity', 'velocity v0'),
                ('mass_center', 'mass centre rc'), ('mass', 'mass'),
                ('inertia', 'inertia')]

_LOAD_FIELDS = [('body', 'body'), ('point', 'point rP'), ('force', 'force F'),
                ('torque', 'torque M'), ('axes', 'axes')]

_PENDULUM = dict(name='pendulum', parent='0', rotations='3 psi, 1 theta', joint='0, 0, 0',
                 velocity='', mass_center='0, 0, l', mass='m', inertia='m*l^2, m*l^2, 0')

_EXAMPLE2 = "\n".join(["1 2 L1", "2 3 f1", "2 3 C1", "3 4 L2", "4 5 I02", "4 5 C4", "4 5 f4",
                       "3 5 C2", "3 5 f2", "5 2 I0", "1 5 C3", "1 5 f3", "1 5 I01"])


#: The fields of one kind of model on the builder's page: their ``box``,
#: the function that turns them into a description, and the function that
#: names a loader's entry as the page shows it (``None``: as the loader does).
_Panel = namedtuple('_Panel', 'box description as_seen')


class SystemBuilder:
    r"""
    The system-builder page: form fields for a mechanical system (bodies
    added one by one) or a circuit (branches), a button that derives the
    Lagrangian / mixed potential and the equations (shown as LaTeX), and a
    button that saves the description file.

    ``SystemBuilder().widget`` is the ipywidgets box to display. The
    fields start with Example 1 (spherical pendulum) and Example 2.

    EXAMPLES::

        sage: from sage_dynsym.interact.builder import SystemBuilder
        sage: B = SystemBuilder()
        sage: B.model()
        Mechanical system 'spherical pendulum': 1 body, coordinates (psi, theta)
        sage: B.kind.value = 'circuit'; B.model()
        Circuit 'nonlinear circuit of Example 2' with 13 branches on 5 nodes
        sage: import os, tempfile
        sage: B.path.value = os.path.join(tempfile.mkdtemp(), 'built.yaml')
        sage: B.save(); os.path.exists(B.path.value)
        True
        sage: B.save(); B.status.value          # an existing file: ask first
        '<b>...built.yaml exists.</b> Click <i>overwrite</i> to replace it.'
        sage: B.confirm.layout.display is None
        True
        sage: B.save(overwrite=True); B.status.value
        'saved to ...built.yaml'
        sage: B.derive(); B.output.value
        '$$\\begin{aligned}\nP &amp;= ...'
        sage: B.branches.value = '1 2 Q1'; B.derive()   # the error is shown, not raised
        sage: B.status.value
        '<b>error:</b> ...'
    """

    def __init__(self):
        W = widgets
        wide = W.Layout(width='95%')
        self.name = W.Text(value='spherical pendulum', description='name', layout=wide)
        self.parameters = W.Text(value='m, l, g', description='parameters', layout=wide)
        self.coordinates = W.Text(value='psi, theta', description='coordinates', layout=wide)
        self.gravity = W.Text(value='0, 0, -g', description='gravity g', layout=wide)
        self.potential = W.Text(value='', description='potential U', layout=wide)
        self.dissipation = W.Text(value='', description='dissipation', layout=wide)
        self.constraints = W.Textarea(value='', description='constraints',
                                      placeholder='f(q, t), one per line (f = 0)', layout=wide)
        self.bodies, self._body_fields = W.VBox(), []
        self.loads, self._load_fields = W.VBox(), []
        self.add_body(_PENDULUM)
        buttons = []
        for label, action in [('add body', lambda _: self.add_body()),
                              ('remove last body', lambda _: self.remove_body()),
                              ('add load', lambda _: self.add_load()),
                              ('remove last load', lambda _: self.remove_load())]:
            buttons.append(W.Button(description=label))
            buttons[-1].on_click(action)
        self.mechanical = W.VBox([self.name, self.parameters, self.coordinates, self.gravity,
                                  self.potential, self.dissipation, self.constraints,
                                  self.bodies, W.HBox(buttons[:2]), self.loads,
                                  W.HBox(buttons[2:])])
        self.circuit_name = W.Text(value='nonlinear circuit of Example 2',
                                   description='name', layout=wide)
        self.circuit_parameters = W.Text(value='', description='parameters', layout=wide)
        self.branches = W.Textarea(value=_EXAMPLE2, description='branches',
                                   layout=W.Layout(width='95%', height='14em'))
        self.circuit = W.VBox([self.circuit_name, self.circuit_parameters, self.branches])
        # what differs per kind on this page: its fields, how they become a
        # description, how the loader's entries are shown; the kinds offered
        # are those of the registry that have fields here
        self._panels = {'mechanical': _Panel(self.mechanical, self._mechanical_description,
                                             self._bodies_as_seen),
                        'circuit': _Panel(self.circuit, self._circuit_description, None)}
        self.kind = W.ToggleButtons(options=[kind for kind in kinds() if kind in self._panels],
                                    description='kind')
        self.kind.observe(self._switch, names='value')
        self._switch({'new': self.kind.value})
        derive = W.Button(description='derive equations', button_style='primary')
        derive.on_click(lambda _: self.derive())
        self.path = W.Text(value='built_system.yaml', description='file')
        save = W.Button(description='save description')
        save.on_click(lambda _: self.save())
        # shown only while an existing file waits for the user's consent
        self.confirm = W.Button(description='overwrite', button_style='warning')
        self.confirm.on_click(lambda _: self.save(overwrite=True))
        self.confirm.layout.display = 'none'
        self.path.observe(lambda _: self._hide_confirm(), names='value')
        self.status = W.HTML()
        self.output = W.HTMLMath()
        self.widget = W.VBox([self.kind, self.mechanical, self.circuit,
                              W.HBox([derive, self.path, save, self.confirm]), self.status,
                              self.output])

    def _hide_confirm(self):
        self.confirm.layout.display = 'none'

    def _switch(self, change):
        for kind, panel in self._panels.items():
            panel.box.layout.display = None if kind == change['new'] else 'none'

    def add_body(self, values=None):
        r"""
        Add the fields of one more body (empty, or filled from ``values``).

        EXAMPLES::

            sage: from sage_dynsym.interact.builder import SystemBuilder
            sage: B = SystemBuilder()      # the fields hold the spherical pendulum
            sage: B.add_body(dict(name='bob', parent='1', mass='m2'))
            sage: len(B.bodies.children), B.description()['bodies'][1]
            (2, {'mass': 'm2', 'name': 'bob', 'parent': 1, 'rotations': []})
        """
        values = values or {'parent': str(len(self._body_fields))}
        self._body_fields.append(_text_fields(_BODY_FIELDS, values))
        self._refresh()

    def remove_body(self):
        r"""
        Remove the fields of the last body.

        EXAMPLES::

            sage: from sage_dynsym.interact.builder import SystemBuilder
            sage: B = SystemBuilder()      # the fields hold the spherical pendulum
            sage: B.add_body(); len(B.bodies.children)
            2
            sage: B.remove_body(); len(B.bodies.children)
            1
        """
        if self._body_fields:
            self._body_fields.pop()
            self._refresh()

    def add_load(self, values=None):
        r"""
        Add the fields of one more load on a body (empty, or filled from
        ``values``): the body, the point of application in the body's axes,
        the force and the torque, and the axes their components are given
        in (``0`` for the inertial axes, or a body name).

        EXAMPLES::

            sage: from sage_dynsym.interact.builder import SystemBuilder
            sage: B = SystemBuilder()      # the fields hold the spherical pendulum
            sage: B.add_load(dict(body='pendulum', point='0, 0, l', torque='0, 0, M0'))
            sage: B.description()['loads']
            [{'axes': 0, 'body': 'pendulum', 'point': ['0', '0', 'l'], 'torque': ['0', '0', 'M0']}]
        """
        self._load_fields.append(_text_fields(_LOAD_FIELDS, values or {'axes': '0'}))
        self._refresh()

    def remove_load(self):
        r"""
        Remove the fields of the last load.

        EXAMPLES::

            sage: from sage_dynsym.interact.builder import SystemBuilder
            sage: B = SystemBuilder()
            sage: B.add_load(); B.remove_load(); len(B.loads.children)
            0
        """
        if self._load_fields:
            self._load_fields.pop()
            self._refresh()

    def _refresh(self):
        self.bodies.children = _boxes("body", self._body_fields)
        self.loads.children = _boxes("load", self._load_fields)

    def description(self):
        r"""
        The description dictionary of what the fields hold.

        EXAMPLES::

            sage: from sage_dynsym.interact.builder import SystemBuilder
            sage: B = SystemBuilder()      # the fields hold the spherical pendulum
            sage: d = B.description(); d['coordinates'], d['bodies'][0]['rotations']
            (['psi', 'theta'], [[3, 'psi'], [1, 'theta']])
            sage: B.kind.value = 'circuit'; B.description()['branches'][:2]
            [[1, 2, 'L1'], [2, 3, 'f1']]
        """
        try:
            return self._panels[self.kind.value].description()
        except DynSymError as err:
            raise self._as_seen(err) from err

    def _mechanical_description(self):
        values = [{k: w.value for k, w in fields.items()} for fields in self._body_fields]
        loads = [{k: w.value for k, w in fields.items()} for fields in self._load_fields]
        return mechanical_description(self.name.value, self.parameters.value,
                                      self.coordinates.value, self.gravity.value, values,
                                      self.dissipation.value, self.potential.value,
                                      self.constraints.value, loads)

    def _circuit_description(self):
        return circuit_description(self.circuit_name.value, self.branches.value,
                                   self.circuit_parameters.value)

    def model(self):
        r"""
        The model the fields describe (raises the loader's errors).

        EXAMPLES::

            sage: from sage_dynsym.interact.builder import SystemBuilder
            sage: B = SystemBuilder()      # the fields hold the spherical pendulum
            sage: B.model().lagrangian().expr()
            1/2*dpsi^2*l^2*m*sin(theta)^2 + 1/2*dtheta^2*l^2*m - g*l*m*cos(theta)
            sage: B.parameters.value = 'm, l'; B.model()
            Traceback (most recent call last):
            ...
            ExpressionError: system builder: force_function.uniform_gravity[2]: undeclared symbol 'g' in '-g'; declared symbols are: l, m, psi, t, theta

        Errors name a body as the page shows it::

            sage: B.parameters.value = 'm, l, g'
            sage: B._body_fields[0]['mass'].value = 'm*k'; B.model()
            Traceback (most recent call last):
            ...
            ExpressionError: system builder: body 1 (pendulum).mass: undeclared symbol 'k' in 'm*k'; ...
            sage: B._body_fields[0]['rotations'].value = '4 psi'; B.model()
            Traceback (most recent call last):
            ...
            DescriptionError: body 1 (pendulum).rotations: expected 'axis angle' pairs such as '3 psi, 1 theta', got '4 psi'
        """
        try:
            return model_from_description(self.description())
        except DynSymError as err:
            raise self._as_seen(err) from err

    def _as_seen(self, err):
        # the loader's entry as the page shows it, where the kind's fields
        # name it otherwise
        as_seen = self._panels[self.kind.value].as_seen
        return err if not err.entry or as_seen is None else as_seen(err)

    def _bodies_as_seen(self, err):
        # the loader names list positions (bodies[1].mass); the page shows
        # "body 2 (bob)" with its fields
        def body(match):
            k = int(match.group(1))
            name = (self._body_fields[k]['name'].value.strip()
                    if k < len(self._body_fields) else '')
            return f"body {k + 1}" + (f" ({name})" if name else "")

        entry = re.sub(r"^bodies\[(\d+)\]", body, err.entry)
        entry = re.sub(r"^loads\[(\d+)\]", lambda m: f"load {int(m.group(1)) + 1}", entry)
        return err if entry == err.entry else type(err)(err.message, entry=entry,
                                                        source=err.source)

    def derive(self):
        r"""
        Show the characteristic function and the equations as LaTeX (or the
        error, naming the field).

        EXAMPLES::

            sage: from sage_dynsym.interact.builder import SystemBuilder
            sage: B = SystemBuilder()      # the fields hold the spherical pendulum
            sage: B.derive(); print(B.output.value)
            $$\begin{aligned}
            L &amp;= \frac{1}{2} \, {\dot{\psi}}^{2} l^{2} m \sin\left(\theta\right)^{2} + ...\\
            0 &amp;= 2 \, {\dot{\psi}} {\dot{\theta}} l^{2} m ...\\
            0 &amp;= -{\dot{\psi}}^{2} l^{2} m ...
            \end{aligned}$$
            sage: B.parameters.value = 'm, l'; B.derive(); B.status.value
            '<b>error:</b> system builder: force_function.uniform_gravity[2]: undeclared symbol ...'
        """
        from .forms import derive, derivation_latex
        self.output.value = ""

        def derivation():
            model = self.model()
            # the kind's first form (Lagrange for a mechanical system,
            # Brayton-Moser for a circuit), from the model's class
            return model, derivation_latex(derive(model, next(iter(model.equation_forms()))))
        done, found = self._attempt(derivation)
        if not done:
            return
        model, block = found
        self.status.value = f"{_escape(model)}"
        self.output.value = f"$${_escape(block)}$$"

    def save(self, overwrite=False):
        r"""
        Write the description file named in the ``file`` field, with the
        results section. An existing file is replaced only with
        ``overwrite=True`` (the *overwrite* button, shown after the first
        attempt); the file is written atomically.
        """
        import os
        from ..description import save
        path = self.path.value
        if os.path.exists(path) and not overwrite:
            self.status.value = (f"<b>{_escape(path)} exists.</b> Click <i>overwrite</i> to "
                                 "replace it.")
            self.confirm.layout.display = None
            return
        self._hide_confirm()
        if self._attempt(lambda: save(self.model(), path), expected=(DynSymError, OSError))[0]:
            self.status.value = f"saved to {_escape(path)}"

    def _attempt(self, action, expected=DynSymError):
        # ``(True, action())``, or ``(False, None)`` with the failure shown
        # on the status line: the expected errors by their message, any
        # other by its class too
        try:
            return True, action()
        except expected as err:
            self.status.value = f"<b>error:</b> {_escape(err)}"
        except Exception as err:        # a page: the status line, never a traceback
            self.status.value = f"<b>error:</b> {_escape(type(err).__name__)}: {_escape(err)}"
        return False, None


def _text_fields(keys, values):
    return {key: widgets.Text(value=values.get(key, ''), description=label,
                              layout=widgets.Layout(width='48%'))
            for key, label in keys}


def _boxes(title, items):
    boxes = []
    for k, fields in enumerate(items):
        cells = list(fields.values())
        rows = [widgets.HBox(cells[i:i + 2]) for i in range(0, len(cells), 2)]
        boxes.append(widgets.VBox([widgets.HTML(f"<b>{title} {k + 1}</b>")] + rows))
    return boxes


def _escape(obj):
    import html
    return html.escape(str(obj))

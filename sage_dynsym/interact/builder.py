r"""
The system builder: a model entered in form fields

The counterpart of the original packages' dialog panels. The user types
the parameters, coordinates, force field and, body by body, the parent,
rotation sequence, vectors, mass and inertia -- or, for a circuit, one
branch per line. :func:`mechanical_description` and
:func:`circuit_description` turn those texts into the same dictionary a
description file holds, so the model is built and checked by the loader of
:mod:`sage_dynsym.description` (safe parser, errors naming the entry), and
:func:`~sage_dynsym.description.save` writes it to a file.
:class:`SystemBuilder` is the widget page around them.

Field syntax: lists are comma-separated (``m, l, g``); a rotation sequence
is ``axis angle`` pairs (``3 psi, 1 theta``); an inertia tensor is three
diagonal entries or nine entries row by row (rows may be separated by
``;``); a branch is ``from to element`` (``1 2 L1``).

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
import ipywidgets as widgets

from ..errors import DescriptionError, DynSymError


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
                           dissipation=""):
    r"""
    The description-file dictionary of a mechanical system entered as text
    fields.

    INPUT:

    - ``name``, ``parameters``, ``coordinates`` -- strings (lists
      comma-separated)
    - ``gravity`` -- the gravity vector in the inertial axes (three
      components), or an empty string for no force function
    - ``bodies`` -- a list of dictionaries with the string fields ``name``,
      ``parent``, ``rotations``, ``joint``, ``mass_center``, ``mass``,
      ``inertia`` and optionally ``velocity`` (empty: the default)
    - ``dissipation`` -- (optional) the Rayleigh function

    OUTPUT: a dictionary as read from a description file

    TESTS::

        sage: from sage_dynsym.interact.builder import mechanical_description
        sage: mechanical_description('x', 'm', 'q', '', [dict(rotations='4 q')])
        Traceback (most recent call last):
        ...
        DescriptionError: bodies[0].rotations: expected 'axis angle' pairs such as '3 psi, 1 theta', got '4 q'
        sage: mechanical_description('x', 'm', 'q', '0, 0', [])
        Traceback (most recent call last):
        ...
        DescriptionError: force_function.uniform_gravity: expected three comma-separated components, got '0, 0'
    """
    data = {'kind': 'mechanical', 'name': name.strip() or 'mechanical system',
            'parameters': split_list(parameters), 'coordinates': split_list(coordinates)}
    if gravity.strip():
        data['force_function'] = {
            'uniform_gravity': _vector(gravity, 'force_function.uniform_gravity')}
    if dissipation.strip():
        data['dissipation'] = dissipation.strip()
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
    return data


def _parent(text):
    text = str(text).strip() or "0"
    return int(text) if text.isdigit() else text


def circuit_description(name, branches, parameters=""):
    r"""
    The description-file dictionary of a circuit entered as text: one
    branch ``from to element`` per line.

    EXAMPLES::

        sage: from sage_dynsym.interact.builder import circuit_description, model_from_description
        sage: data = circuit_description('RLC', '1 2 E1\n2 3 R1\n3 4 L1\n4 1 C1')
        sage: data['branches']
        [[1, 2, 'E1'], [2, 3, 'R1'], [3, 4, 'L1'], [4, 1, 'C1']]
        sage: model_from_description(data).state_equations()
        [-R1*i1 + E1 + u2, -i1]

    TESTS::

        sage: circuit_description('x', '1 2')
        Traceback (most recent call last):
        ...
        DescriptionError: branches[0]: expected 'from_node to_node element' such as '1 2 L1', got '1 2'
    """
    rows = []
    for k, line in enumerate(l for l in branches.splitlines() if l.strip()):
        parts = line.replace(",", " ").split()
        if len(parts) != 3 or not (parts[0].isdigit() and parts[1].isdigit()):
            raise DescriptionError("expected 'from_node to_node element' such as '1 2 L1', "
                                   f"got {line.strip()!r}", entry=f"branches[{k}]")
        rows.append([int(parts[0]), int(parts[1]), parts[2]])
    data = {'kind': 'circuit', 'name': name.strip() or 'circuit', 'branches': rows}
    if parameters.strip():
        data['parameters'] = split_list(parameters)
    return data


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

_PENDULUM = dict(name='pendulum', parent='0', rotations='3 psi, 1 theta', joint='0, 0, 0',
                 velocity='', mass_center='0, 0, l', mass='m', inertia='m*l^2, m*l^2, 0')

_EXAMPLE2 = "\n".join(["1 2 L1", "2 3 f1", "2 3 C1", "3 4 L2", "4 5 I02", "4 5 C4", "4 5 f4",
                       "3 5 C2", "3 5 f2", "5 2 I0", "1 5 C3", "1 5 f3", "1 5 I01"])


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
        self.kind = W.ToggleButtons(options=['mechanical', 'circuit'], description='kind')
        self.name = W.Text(value='spherical pendulum', description='name', layout=wide)
        self.parameters = W.Text(value='m, l, g', description='parameters', layout=wide)
        self.coordinates = W.Text(value='psi, theta', description='coordinates', layout=wide)
        self.gravity = W.Text(value='0, 0, -g', description='gravity g', layout=wide)
        self.dissipation = W.Text(value='', description='dissipation', layout=wide)
        self.bodies = W.VBox()
        self._body_fields = []
        self.add_body(_PENDULUM)
        add = W.Button(description='add body')
        add.on_click(lambda _: self.add_body())
        remove = W.Button(description='remove last body')
        remove.on_click(lambda _: self.remove_body())
        self.mechanical = W.VBox([self.name, self.parameters, self.coordinates, self.gravity,
                                  self.dissipation, self.bodies, W.HBox([add, remove])])
        self.circuit_name = W.Text(value='nonlinear circuit of Example 2',
                                   description='name', layout=wide)
        self.branches = W.Textarea(value=_EXAMPLE2, description='branches',
                                   layout=W.Layout(width='95%', height='14em'))
        self.circuit = W.VBox([self.circuit_name, self.branches])
        self.circuit.layout.display = 'none'
        self.kind.observe(self._switch, names='value')
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
        mech = change['new'] == 'mechanical'
        self.mechanical.layout.display = None if mech else 'none'
        self.circuit.layout.display = 'none' if mech else None

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
        fields = {key: widgets.Text(value=values.get(key, ''), description=label,
                                    layout=widgets.Layout(width='48%'))
                  for key, label in _BODY_FIELDS}
        self._body_fields.append(fields)
        self._refresh_bodies()

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
            self._refresh_bodies()

    def _refresh_bodies(self):
        boxes = []
        for k, fields in enumerate(self._body_fields):
            title = widgets.HTML(f"<b>body {k + 1}</b>")
            items = list(fields.values())
            rows = [widgets.HBox(items[i:i + 2]) for i in range(0, len(items), 2)]
            boxes.append(widgets.VBox([title] + rows))
        self.bodies.children = boxes

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
        if self.kind.value == 'circuit':
            return circuit_description(self.circuit_name.value, self.branches.value)
        bodies = [{k: w.value for k, w in fields.items()} for fields in self._body_fields]
        return mechanical_description(self.name.value, self.parameters.value,
                                      self.coordinates.value, self.gravity.value, bodies,
                                      self.dissipation.value)

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
        """
        return model_from_description(self.description())

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
        try:
            model = self.model()
            form = 'Brayton-Moser' if self.kind.value == 'circuit' else 'Lagrange'
            block = derivation_latex(derive(model, form))
        except DynSymError as err:
            self.status.value = f"<b>error:</b> {_escape(err)}"
            return
        except Exception as err:        # never a traceback in the page
            self.status.value = f"<b>error:</b> {_escape(type(err).__name__)}: {_escape(err)}"
            return
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
        try:
            save(self.model(), path)
        except (DynSymError, OSError) as err:
            self.status.value = f"<b>error:</b> {_escape(err)}"
            return
        except Exception as err:        # never a traceback in the page
            self.status.value = f"<b>error:</b> {_escape(type(err).__name__)}: {_escape(err)}"
            return
        self.status.value = f"saved to {_escape(path)}"


def _escape(obj):
    import html
    return html.escape(str(obj))

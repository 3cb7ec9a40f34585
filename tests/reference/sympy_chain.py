"""
Reference model of a chain of rigid bodies built with ``sympy.physics.mechanics``.

Independent of sage_dynsym (it must not be imported here). The input is plain
data, the same fields as the rigid-body description of doc/method.rst:

``bodies`` -- list of dicts (body ``k`` is ``bodies[k-1]``) with keys

- ``parent``       -- 0 (inertial frame) or the 1-based index of an earlier body
- ``rotations``    -- list of ``(axis, angle)``, axis in {1, 2, 3}; each rotation
  is about the *new* axis of the frame produced by the previous one
- ``joint``        -- r^j_{0k}: position of O_k in the parent's axes (3 entries);
  may depend on coordinates (sliding joint), its time derivative is then the
  relative velocity
- ``velocity``     -- (optional) v^j_{0k}: the relative velocity of O_k in the
  parent's axes, prescribed instead of the derivative of ``joint``; may also
  be written with the velocities ``d<q>``
- ``mass_center``  -- r^k_{ck}: position of C_k in the body's axes
- ``mass``         -- m_k
- ``inertia``      -- inertia tensor about O_k in the body's axes (3x3, symmetric)

Entries are numbers (int, Fraction, SymPy numbers) or SymPy-parsable strings
written with ``**`` over the names in ``coordinates`` and ``parameters``
(and ``t``). ``gravity`` is the uniform acceleration vector in the inertial axes.

Convention of the equations: ``E_i = d/dt dL/d(dq_i) - dL/dq_i`` with
``L = T - V`` and ``V = -sum m_k g . r_{C_k}`` (SymPy's ``LagrangesMethod``
returns exactly this ``eom`` when there are no forces or constraints;
``KanesMethod``, with the generalized speeds ``u_i = dq_i``, returns
``fr + frstar = -E_i``).
"""
from fractions import Fraction

import sympy
from sympy.physics import mechanics as me

T = me.dynamicsymbols._t


class _Parser:
    """Turn plain-data entries into SymPy expressions (coordinates -> q(t))."""

    def __init__(self, coordinates, parameters):
        self.coords = [me.dynamicsymbols(str(c)) for c in coordinates]
        self.names = {str(c): q for c, q in zip(coordinates, self.coords)}
        self.names.update({'d' + str(c): q.diff(T) for c, q in zip(coordinates, self.coords)})
        for p in parameters:
            self.names.setdefault(str(p), sympy.Symbol(str(p)))
        self.names['t'] = T

    def __call__(self, value):
        if isinstance(value, Fraction):
            return sympy.Rational(value.numerator, value.denominator)
        if isinstance(value, str):
            # Only test-authored strings reach this point.
            return sympy.parse_expr(value, local_dict=dict(self.names))
        return sympy.sympify(value)


def _depends_on_time(expr):
    return expr.has(T)


def _vector(frame, components):
    return sum((c * e for c, e in zip(components, (frame.x, frame.y, frame.z))),
               me.Vector(0))


class SympyChain:
    """
    The chain of rigid bodies built with ``sympy.physics.mechanics``.

    Attributes: ``coordinates`` (dynamic symbols), ``frames``, ``joints``,
    ``mass_centers``, ``bodies`` (``RigidBody``), ``inertial_frame``,
    ``kinetic_energy``, ``potential_energy``, ``lagrangian`` (all in q(t)).
    """

    def __init__(self, bodies, coordinates, gravity=(0, 0, 0), parameters=()):
        parse = _Parser(coordinates, parameters)
        self.coordinates = parse.coords
        N = me.ReferenceFrame('N')
        O = me.Point('O')
        O.set_vel(N, 0)
        self.inertial_frame, self.origin = N, O
        frames, joints, centers, rigid = [N], [O], [], []
        for k, body in enumerate(bodies, start=1):
            parent = int(body['parent'])
            if not 0 <= parent < k:
                raise ValueError(f"body {k}: parent must be in 0..{k - 1}")
            frame = frames[parent]
            for i, (axis, angle) in enumerate(body.get('rotations', ())):
                new = me.ReferenceFrame(f'B{k}_{i + 1}')
                new.orient_axis(frame, (frame.x, frame.y, frame.z)[int(axis) - 1],
                                parse(angle))
                frame = new
            # Joint point O_k, given in the parent's axes.
            r0 = [parse(c) for c in body['joint']]
            Ok = joints[parent].locatenew(f'O{k}', _vector(frames[parent], r0))
            if body.get('velocity') is not None:
                # the prescribed relative velocity, carried by the parent's motion
                Ok.set_vel(N, joints[parent].vel(N)
                           + frames[parent].ang_vel_in(N).cross(_vector(frames[parent], r0))
                           + _vector(frames[parent], [parse(c) for c in body['velocity']]))
            elif any(_depends_on_time(c) for c in r0):
                # the rate of r0 in the parent's axes, carried by the parent's
                # motion (not pos_from(O).dt(N): a prescribed velocity above
                # is not the rate of a position)
                r = _vector(frames[parent], r0)
                Ok.set_vel(N, joints[parent].vel(N) + r.dt(frames[parent])
                           + frames[parent].ang_vel_in(N).cross(r))
            else:
                Ok.v2pt_theory(joints[parent], N, frames[parent])
            # Mass centre C_k, given in the body's own axes.
            c = sympy.Matrix([parse(x) for x in body['mass_center']])
            Ck = Ok.locatenew(f'C{k}', _vector(frame, c))
            if any(_depends_on_time(x) for x in c):
                r = _vector(frame, c)
                Ck.set_vel(N, Ok.vel(N) + r.dt(frame) + frame.ang_vel_in(N).cross(r))
            else:
                Ck.v2pt_theory(Ok, N, frame)
            # Velocities expressed in the body's own axes: SymPy then dots
            # single-frame vectors (a dot product of vectors spread over many
            # frames grows quadratically and makes LagrangesMethod very slow).
            frame.set_ang_vel(N, frame.ang_vel_in(N).express(frame))
            Ok.set_vel(N, Ok.vel(N).express(frame))
            Ck.set_vel(N, Ck.vel(N).express(frame))
            m = parse(body['mass'])
            I_O = sympy.Matrix(3, 3, [parse(x) for row in body['inertia'] for x in row])
            if I_O != I_O.T:
                raise ValueError(f"body {k}: inertia tensor is not symmetric")
            # Parallel-axis theorem: central inertia from the one about O_k.
            I_C = I_O - m * ((c.T * c)[0, 0] * sympy.eye(3) - c * c.T)
            dyadic = sum((I_C[i, j] * (e_i | e_j)
                          for i, e_i in enumerate((frame.x, frame.y, frame.z))
                          for j, e_j in enumerate((frame.x, frame.y, frame.z))),
                         me.Dyadic(0))
            rigid.append(me.RigidBody(f'body{k}', Ck, frame, m, (dyadic, Ck)))
            frames.append(frame)
            joints.append(Ok)
            centers.append(Ck)
        self.frames, self.joints, self.mass_centers, self.bodies = frames, joints, centers, rigid
        g = _vector(N, [parse(x) for x in gravity])
        self.gravity = g
        self.kinetic_energy = sum((b.kinetic_energy(N) for b in rigid), sympy.S.Zero)
        self.potential_energy = -sum((b.mass * g.dot(C.pos_from(O))
                                      for b, C in zip(rigid, centers)), sympy.S.Zero)
        self.lagrangian = self.kinetic_energy - self.potential_energy

    def plain_symbols(self):
        """
        Map q''(t), q'(t), q(t) to plain symbols ``ddq``, ``dq``, ``q``
        (the naming used by sage_dynsym), as a dict for ``xreplace``.
        """
        rule = {}
        for q in self.coordinates:
            name = q.func.__name__
            rule[q.diff(T, 2)] = sympy.Symbol('dd' + name)
            rule[q.diff(T)] = sympy.Symbol('d' + name)
            rule[q] = sympy.Symbol(name)
        return rule

    def to_plain(self, expr):
        """``expr`` with q(t) and its derivatives replaced by plain symbols
        (and the generalized speeds of :meth:`kane_equations` by ``dq``,
        their derivatives by ``ddq``)."""
        # xreplace matches whole subtrees first, so q''(t) is replaced before q(t).
        rule = self.plain_symbols()
        for q, u in zip(self.coordinates, self.speeds()):
            rule[u.diff(T)] = rule[q.diff(T, 2)]
            rule[u] = rule[q.diff(T)]
        return sympy.sympify(expr).xreplace(rule)

    def speeds(self):
        """The generalized speeds ``u_q(t)`` of :meth:`kane_equations`, ``u_q = q'``."""
        return [me.dynamicsymbols('u_' + q.func.__name__) for q in self.coordinates]

    def kane_equations(self, plain=True):
        """
        ``fr + frstar`` of ``KanesMethod`` with the generalized speeds
        ``u_q = q'`` and the weights ``m_k g`` at the mass centres: minus the
        Lagrange equations; in plain symbols unless ``plain=False``.
        """
        u = self.speeds()
        KM = me.KanesMethod(self.inertial_frame, q_ind=self.coordinates, u_ind=u,
                            kd_eqs=[q.diff(T) - s for q, s in zip(self.coordinates, u)])
        loads = [(C, b.mass * self.gravity) for b, C in zip(self.bodies, self.mass_centers)]
        fr, frstar = KM.kanes_equations(self.bodies, loads)
        eom = list(fr + frstar)
        return [self.to_plain(e) for e in eom] if plain else eom

    def lagrange_equations(self, plain=True):
        """
        The Lagrange equations ``E_i = d/dt dL/d(dq_i) - dL/dq_i`` from
        ``LagrangesMethod``, in plain symbols unless ``plain=False``.
        """
        LM = me.LagrangesMethod(self.lagrangian, self.coordinates,
                                frame=self.inertial_frame)
        eom = list(LM.form_lagranges_equations())
        return [self.to_plain(e) for e in eom] if plain else eom


def lagrange_equations(bodies, coordinates, gravity=(0, 0, 0), parameters=()):
    """Shortcut: the plain-symbol Lagrange equations of the described chain."""
    return SympyChain(bodies, coordinates, gravity, parameters).lagrange_equations()

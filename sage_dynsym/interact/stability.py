r"""
Stability of an equilibrium, numerically explorable

A :class:`StabilityStudy` takes a nonlinear first-order system
`B\dot x = F(x)` (circuit state equations, a Lagrangian system in its
first-order form, ...) and an equilibrium that may depend on parameters. It
does the symbolic work once -- first approximation
(:func:`~sage_dynsym.analysis.linear.linearize`), characteristic polynomial,
the conditions of asymptotic stability from the stability service
(:meth:`~sage_dynsym.analysis.linear.LinearSystem.stability`) -- and
then answers numerical questions for given parameter values: the
characteristic roots, whether the conditions hold, the stability region in
a plane of two parameters, a simulated trajectory of the *nonlinear*
equations (see :mod:`sage_dynsym.numerics`). :meth:`StabilityStudy.explorer` is the
interactive page with a slider per parameter.

Where the symbolic conditions are not available (too large, or the
analysis part cannot produce them) the region is computed from the roots
themselves (spectral abscissa `< 0`) -- a stability map
(:func:`~sage_dynsym.scale.maps.stability_map`, in this process) -- and
:meth:`StabilityStudy.note` says so.

EXAMPLES:

A series RLC circuit driven by a constant source, with a tunnel diode
`i = g u (u - 3s)^2` across the capacitor (two extrema, at `u = s` and
`u = 3s`). Around the equilibrium `u = 2s` on the falling branch the diode
is a negative resistance::

    sage: from sage_dynsym.interact.stability import StabilityStudy
    sage: i, u, E, R, L, C, g, s = var('i u E R L C g s')
    sage: f = g*u*(u - 3*s)^2
    sage: rhs = [E - R*i - u, i - f]
    sage: from sage_dynsym.analysis import solve_exactly
    sage: (eq,) = solve_exactly(rhs + [u - 2*s], [i, u, E]); eq.values()
    {i: 2*g*s^3, u: 2*s, E: 2*R*g*s^3 + 2*s}
    sage: St = StabilityStudy(rhs, [i, u], eq, lhs_matrix=[L, C], positive=[L, C, R, g, s])
    sage: St.parameters()
    [C, L, R, g, s]
    sage: St.characteristic_polynomial()
    -3*L*g*lam*s^2 + C*L*lam^2 - 3*R*g*s^2 + C*R*lam + 1
    sage: St.conditions()
    [-3*R*g*s^2 + 1, -3*L*g*s^2 + C*R]

Both conditions hold for a small diode gain and a resistive enough
circuit, and then every root has a negative real part::

    sage: values = dict(C=1, L=1, R=2, g=0.05, s=1)
    sage: St.conditions_hold(values), St.spectral_abscissa(values) < 0
    (True, True)
    sage: values['g'] = 0.5
    sage: St.conditions_hold(values), St.spectral_abscissa(values) < 0
    (False, False)

The nonlinear trajectory from a perturbed equilibrium::

    sage: t, X = St.simulate(dict(C=1, L=1, R=2, g=0.05, s=1), t_end=40)
    sage: bool(abs(X[-1][1] - 2) < 1e-3)    # back to u = 2s
    True
"""
import numpy

from sage.misc.functional import N
from sage.plot.graphics import Graphics
from sage.structure.sage_object import SageObject
from sage.symbolic.ring import SR

from ..algebra.solving import AlgebraicSolution
from ..analysis.stationary import StationarySolution
from ..errors import AnalysisError

__all__ = ['StabilityStudy']


class StabilityStudy(SageObject):
    r"""
    The stability study of one equilibrium of `B\dot x = F(x)`.

    INPUT:

    - ``rhs`` -- the right-hand sides `F`
    - ``variables`` -- the state `x`, in order
    - ``at`` -- the equilibrium, ``{variable: value}``; it may also give
      parameters as functions of others (e.g. a source fixed by the
      equilibrium), which are then eliminated; or a solution of
      :func:`~sage_dynsym.algebra.solving.solve_exactly` (an equilibrium
      found exactly) or a stationary solution
    - ``lhs_matrix`` -- (optional) `B`, or the list of its diagonal
    - ``positive`` -- parameters known to be positive (simplifies the
      conditions)

    See the module documentation for a circuit with a tunnel diode.

    EXAMPLES: the nonlinear oscillator `\ddot x = -kx(x - a) - c\dot x`
    around its equilibrium `x = a`, which depends on a parameter; with `k,
    c > 0` it is stable for `a > 0`::

        sage: from sage_dynsym.interact.stability import StabilityStudy
        sage: x, y, k, c, a = var('x y k c a')
        sage: St = StabilityStudy([y, -k*(x - a)*x - c*y], [x, y], {x: a, y: 0},
        ....:                     positive=[k, c]); St
        Stability study of an equilibrium of a system in (x, y)
        sage: St.characteristic_polynomial(), St.conditions()
        (a*k + c*lam + lam^2, [a])
        sage: St.conditions_hold(dict(a=1, k=1, c=1)), St.conditions_hold(dict(a=-1, k=1, c=1))
        (True, False)
    """

    def __init__(self, rhs, variables, at, lhs_matrix=None, positive=()):
        from sage.matrix.constructor import matrix
        self._variables = [SR(v) for v in variables]
        if isinstance(at, AlgebraicSolution):
            at = at.values()        # a solution of the exact core (solve_exactly)
        elif isinstance(at, StationarySolution):
            at = at.point()
        at = {SR(k): SR(v) for k, v in at.items()}
        fixed = {k: v for k, v in at.items() if k not in self._variables}
        self._rhs = [SR(f).subs(fixed) for f in rhs]
        self._point = [at[v].subs(fixed) if v in at else SR(0) for v in self._variables]
        n = len(self._variables)
        if lhs_matrix is None:
            B = matrix.identity(SR, n)
        elif hasattr(lhs_matrix, 'nrows') or isinstance(lhs_matrix[0], (list, tuple)):
            B = matrix(SR, lhs_matrix)
        else:
            B = matrix.diagonal(SR, list(lhs_matrix))
        self._B = B.subs(fixed)
        symbols = set()
        for e in self._rhs + self._point + list(self._B.list()):
            symbols |= set(e.variables())
        self._parameters = sorted(symbols - set(self._variables), key=str)
        self._lam = SR.var('lam')
        point = dict(zip(self._variables, self._point))
        self._note = None
        try:
            from ..analysis import linearize
        except ImportError:     # analysis part not there: numeric criterion only
            self._linear = None
            J = matrix(SR, [[f.diff(v).subs(point) for v in self._variables] for f in self._rhs])
            self._poly = (self._B * self._lam - J).det().expand()
            self._conditions = None
            self._note = "symbolic conditions not available: stability from the roots"
            return
        self._linear = linearize(self._rhs, point, self._variables, lhs_matrix=self._B)
        self._poly = self._linear.characteristic_polynomial(self._lam)
        try:
            # the one stability service decides; the page shows the
            # conditions of its asymptotically stable case
            self._conditions = _asymptotic_conditions(self._linear.stability(positive=positive))
            if self._conditions is None:
                self._note = ("no conjunction of conditions for asymptotic stability "
                              "(see linear_system().stability()): stability from the roots")
        except AnalysisError as err:
            self._conditions = None
            self._note = (f"no symbolic conditions ({err}): stability from the roots; the "
                          "region plot is a stability map of the characteristic roots "
                          "(sage_dynsym.scale.stability_map)")

    def _repr_(self):
        vs = ', '.join(map(str, self._variables))
        return f"Stability study of an equilibrium of a system in ({vs})"

    def parameters(self):
        r"""The parameters the study depends on, sorted by name.

        EXAMPLES: a damped oscillator `\ddot x + c\dot x + kx = 0` as a
        first-order system::

            sage: from sage_dynsym.interact.stability import StabilityStudy
            sage: x, y, k, c = var('x y k c')
            sage: St = StabilityStudy([y, -k*x - c*y], [x, y], {x: 0, y: 0})
            sage: St.parameters()
            [c, k]
        """
        return list(self._parameters)

    def variables(self):
        r"""The state variables.

        EXAMPLES: a damped oscillator `\ddot x + c\dot x + kx = 0` as a
        first-order system::

            sage: from sage_dynsym.interact.stability import StabilityStudy
            sage: x, y, k, c = var('x y k c')
            sage: St = StabilityStudy([y, -k*x - c*y], [x, y], {x: 0, y: 0})
            sage: St.variables()
            [x, y]
        """
        return list(self._variables)

    def equilibrium(self):
        r"""The equilibrium point, a list in the order of the variables.

        EXAMPLES: a damped oscillator `\ddot x + c\dot x + kx = 0` as a
        first-order system::

            sage: from sage_dynsym.interact.stability import StabilityStudy
            sage: x, y, k, c = var('x y k c')
            sage: St = StabilityStudy([y, -k*x - c*y], [x, y], {x: 0, y: 0})
            sage: St.equilibrium()
            [0, 0]
        """
        return list(self._point)

    def linear_system(self):
        r"""The first-approximation system (``None`` without the analysis part).

        EXAMPLES: a damped oscillator `\ddot x + c\dot x + kx = 0` as a
        first-order system::

            sage: from sage_dynsym.interact.stability import StabilityStudy
            sage: x, y, k, c = var('x y k c')
            sage: St = StabilityStudy([y, -k*x - c*y], [x, y], {x: 0, y: 0})
            sage: St.linear_system()
            Linear system B x' = J x in (x, y)
        """
        return self._linear

    def characteristic_polynomial(self):
        r"""The characteristic polynomial in ``lam`` (fraction-free).

        EXAMPLES: a damped oscillator `\ddot x + c\dot x + kx = 0` as a
        first-order system::

            sage: from sage_dynsym.interact.stability import StabilityStudy
            sage: x, y, k, c = var('x y k c')
            sage: St = StabilityStudy([y, -k*x - c*y], [x, y], {x: 0, y: 0})
            sage: St.characteristic_polynomial()
            c*lam + lam^2 + k
        """
        return self._poly

    def conditions(self):
        r"""
        The Liénard--Chipart conditions (all ``> 0``), or ``None`` (see
        :meth:`note`).

        EXAMPLES: a damped oscillator `\ddot x + c\dot x + kx = 0` as a
        first-order system::

            sage: from sage_dynsym.interact.stability import StabilityStudy
            sage: x, y, k, c = var('x y k c')
            sage: St = StabilityStudy([y, -k*x - c*y], [x, y], {x: 0, y: 0})
            sage: St.conditions()
            [k, c]
        """
        return None if self._conditions is None else list(self._conditions)

    def note(self):
        r"""A remark on how stability is decided here, or ``None``.

        EXAMPLES: a damped oscillator `\ddot x + c\dot x + kx = 0` as a
        first-order system::

            sage: from sage_dynsym.interact.stability import StabilityStudy
            sage: x, y, k, c = var('x y k c')
            sage: St = StabilityStudy([y, -k*x - c*y], [x, y], {x: 0, y: 0})
            sage: St.note() is None
            True

        A stiffness `\sin k` is an atom of the conditions; an undamped
        oscillator is never asymptotically stable: no conditions, the
        region from the roots::

            sage: StabilityStudy([y, -sin(k)*x - c*y], [x, y], {x: 0, y: 0}).conditions()
            [sin(k), c]
            sage: St = StabilityStudy([y, -k*x], [x, y], {x: 0, y: 0})
            sage: print(St.note())
            no conjunction of conditions for asymptotic stability (see linear_system().stability()): stability from the roots
            sage: St.conditions() is None
            True
        """
        return self._note

    def _values(self, values):
        subs = {}
        for p in self._parameters:
            if str(p) not in values:
                raise AnalysisError(f"no value given for the parameter {p}",
                                    entry="stability study")
            subs[p] = values[str(p)]
        return subs

    def roots(self, values):
        r"""
        The characteristic roots (complex numbers) for the parameter values
        ``values`` (a dict ``{name: number}``).

        EXAMPLES::

            sage: from sage_dynsym.interact.stability import StabilityStudy
            sage: x, y, k = var('x y k')
            sage: St = StabilityStudy([y, -k*x - y], [x, y], {x: 0, y: 0})
            sage: sorted(St.roots({'k': 2}), key=lambda z: z.imag)   # lam^2 + lam + 2
            [(-0.5-1.3228...j), (-0.5+1.3228...j)]
        """
        p = self._poly.subs(self._values(values))
        coefficients = [complex(N(c)) for c in reversed(p.coefficients(self._lam, sparse=False))]
        while coefficients and coefficients[0] == 0:
            coefficients.pop(0)
        return [complex(z) for z in numpy.roots(coefficients)] if len(coefficients) > 1 else []

    def spectral_abscissa(self, values):
        r"""The largest real part of the characteristic roots.

        EXAMPLES: a damped oscillator `\ddot x + c\dot x + kx = 0` as a
        first-order system::

            sage: from sage_dynsym.interact.stability import StabilityStudy
            sage: x, y, k, c = var('x y k c')
            sage: St = StabilityStudy([y, -k*x - c*y], [x, y], {x: 0, y: 0})
            sage: St.spectral_abscissa({'k': 2, 'c': 1}), St.spectral_abscissa({'k': 2, 'c': -1})
            (-0.5, 0.5)
        """
        return float(max(z.real for z in self.roots(values)))

    def conditions_hold(self, values):
        r"""
        Whether all the conditions are positive at ``values`` (``None``
        without symbolic conditions).

        EXAMPLES: a damped oscillator `\ddot x + c\dot x + kx = 0` as a
        first-order system::

            sage: from sage_dynsym.interact.stability import StabilityStudy
            sage: x, y, k, c = var('x y k c')
            sage: St = StabilityStudy([y, -k*x - c*y], [x, y], {x: 0, y: 0})
            sage: St.conditions_hold({'k': 2, 'c': 1}), St.conditions_hold({'k': 2, 'c': -1})
            (True, False)
        """
        if self._conditions is None:
            return None
        subs = self._values(values)
        return all(N(SR(c).subs(subs)) > 0 for c in self._conditions)

    def region_plot(self, x, y, values, xrange, yrange, plot_points=60):
        r"""
        The stability region in the plane of the parameters ``x`` and ``y``
        (names), the others fixed at ``values``; the current point is
        marked.

        EXAMPLES::

            sage: from sage_dynsym.interact.stability import StabilityStudy
            sage: x, y, k, c = var('x y k c')
            sage: St = StabilityStudy([y, -k*x - c*y], [x, y], {x: 0, y: 0})
            sage: St.region_plot('k', 'c', {'k': 1, 'c': 1}, (-1, 2), (-1, 2))
            Graphics object consisting of 3 graphics primitives

        Without symbolic conditions (an undamped oscillator is never
        asymptotically stable), the region is the stability map of the
        roots::

            sage: St = StabilityStudy([y, -k*x], [x, y], {x: 0, y: 0})
            sage: St.region_plot('k', 'c', {'k': 1, 'c': 1}, (-1, 4), (-1, 2))
            Graphics object consisting of 3 graphics primitives

        TESTS:

        Conditions free of the plane's parameters (here: none at all)::

            sage: St = StabilityStudy([y, -k*x - c*y], [x, y], {x: 0, y: 0}, positive=[k, c])
            sage: St.conditions()
            []
            sage: St.region_plot('k', 'c', {'k': 1, 'c': 1}, (0, 2), (0, 2))
            Graphics object consisting of 2 graphics primitives
        """
        from sage.plot.contour_plot import region_plot
        from sage.plot.point import point
        from sage.plot.polygon import polygon
        from ..scale.maps import linear_symbols
        X, Y = SR.var(x), SR.var(y)
        others = {p: v for p, v in self._values(values).items() if p not in (X, Y)}
        if self._conditions is not None:
            conds = [SR(c).subs(others) for c in self._conditions]
            constant = [c for c in conds if not (set(c.variables()) & {X, Y})]
            conds = [c > 0 for c in conds if c not in constant]
            if any(N(c) <= 0 for c in constant):      # unstable whatever x and y
                G = Graphics()
            elif not conds:                           # stable whatever x and y
                (x0, x1), (y0, y1) = xrange, yrange
                G = polygon([(x0, y0), (x1, y0), (x1, y1), (x0, y1)], color='lightgreen')
            else:
                G = region_plot(conds, (X, *xrange), (Y, *yrange), plot_points=plot_points,
                                incol='lightgreen', bordercol='darkgreen')
        elif self._linear is not None and {X, Y} <= set(linear_symbols(self._linear)):
            G = self._map(X, Y, others, xrange, yrange, plot_points).plot()
        else:                           # a plane parameter left out of the linear system
            def stable(a, b):
                return self.spectral_abscissa(dict(values, **{x: a, y: b})) < 0
            G = region_plot(stable, xrange, yrange, plot_points=plot_points // 2,
                            incol='lightgreen', bordercol='darkgreen')
        G += point((values[x], values[y]), color='red', size=40, zorder=5)
        G.axes_labels([f"${x}$", f"${y}$"])
        G.set_aspect_ratio('automatic')
        return G

    def _map(self, X, Y, others, xrange, yrange, n):
        r"""The stability map of the first approximation in the plane of
        ``X`` and ``Y`` (``n`` x ``n`` points, in this process)."""
        from ..scale.maps import stability_map, linear_symbols
        symbols = set(linear_symbols(self._linear))
        fixed = {p: v for p, v in others.items() if p in symbols}
        return stability_map(self._linear, {X: (*xrange, n), Y: (*yrange, n)}, fixed=fixed,
                             client=False)

    def roots_plot(self, values):
        r"""The characteristic roots in the complex plane.

        EXAMPLES: a damped oscillator `\ddot x + c\dot x + kx = 0` as a
        first-order system::

            sage: from sage_dynsym.interact.stability import StabilityStudy
            sage: x, y, k, c = var('x y k c')
            sage: St = StabilityStudy([y, -k*x - c*y], [x, y], {x: 0, y: 0})
            sage: St.roots_plot({'k': 2, 'c': 1})     # the imaginary axis and the roots
            Graphics object consisting of 2 graphics primitives
        """
        from sage.plot.point import point
        from sage.plot.line import line
        zs = self.roots(values)
        h = max([abs(z.imag) for z in zs] + [abs(z.real) for z in zs] + [1]) * 1.1
        G = line([(0, -h), (0, h)], color='gray', linestyle='--')
        G += point([(z.real, z.imag) for z in zs], size=40,
                   color='green' if max(z.real for z in zs) < 0 else 'red')
        G.axes_labels(["Re", "Im"])
        return G

    def simulate(self, values, perturbation=0.05, t_end=20, points=400):
        r"""
        Integrate the nonlinear equations from the equilibrium with every
        variable shifted by ``perturbation`` (the compiled right-hand side of
        :mod:`sage_dynsym.numerics`, SciPy's LSODA).

        OUTPUT: ``(t, X)``: the times and the states (NumPy arrays; ``X[k]``
        is the state at ``t[k]``)

        EXAMPLES: a damped oscillator `\ddot x + c\dot x + kx = 0` as a
        first-order system::

            sage: from sage_dynsym.interact.stability import StabilityStudy
            sage: x, y, k, c = var('x y k c')
            sage: St = StabilityStudy([y, -k*x - c*y], [x, y], {x: 0, y: 0})
            sage: t, X = St.simulate({'k': 2, 'c': 1}, t_end=30)
            sage: t.shape, X.shape, X[0]
            ((400,), (400, 2), array([0.05, 0.05]))
            sage: bool(abs(X[-1]).max() < 1e-5)      # back to the equilibrium
            True
        """
        from ..analysis.motion import FirstOrderEquations
        from ..numerics.simulate import simulate
        subs = self._values(values)
        record = FirstOrderEquations([f.subs(subs) for f in self._rhs], self._variables,
                                     lhs_matrix=self._B.subs(subs))
        x0 = {v: float(N(p.subs(subs))) + perturbation
              for v, p in zip(self._variables, self._point)}
        trajectory = simulate(record, {}, x0, t_end, points=points, method='LSODA',
                              rtol=1e-8, atol=1e-10)
        return trajectory.times(), trajectory.states()

    def trajectory_plot(self, values, perturbation=0.05, t_end=20):
        r"""
        The simulated trajectory: every variable against time, and the phase
        portrait in the first two variables.

        EXAMPLES: a damped oscillator `\ddot x + c\dot x + kx = 0` as a
        first-order system::

            sage: from sage_dynsym.interact.stability import StabilityStudy
            sage: x, y, k, c = var('x y k c')
            sage: St = StabilityStudy([y, -k*x - c*y], [x, y], {x: 0, y: 0})
            sage: St.trajectory_plot({'k': 2, 'c': 1})
            Graphics Array of size 1 x 2
        """
        from sage.plot.line import line
        from sage.plot.plot import graphics_array
        from sage.plot.colors import rainbow
        t, X = self.simulate(values, perturbation, t_end)
        colors = rainbow(len(self._variables))
        G = Graphics()
        for k, v in enumerate(self._variables):
            G += line(zip(t, X[:, k]), color=colors[k], legend_label=f"${v}$")
        G.axes_labels(["$t$", ""])
        if len(self._variables) < 2:
            return G
        P = line(zip(X[:, 0], X[:, 1]), color='blue')
        P.axes_labels([f"${self._variables[0]}$", f"${self._variables[1]}$"])
        return graphics_array([G, P])

    def explorer(self, ranges, plane=None, t_end=20):
        r"""
        The stability-explorer page: a slider per parameter, the plane of
        the region plot, the perturbation and the simulated time; shows the
        verdict, the conditions, the region, the roots and the trajectory.

        INPUT:

        - ``ranges`` -- ``{name: (min, max, default)}`` for every parameter
        - ``plane`` -- (default: the first two parameters) the pair of
          parameter names of the region plot

        OUTPUT: the interactive widget (display it)

        EXAMPLES::

            sage: from sage_dynsym.interact.stability import StabilityStudy
            sage: x, y, k, c = var('x y k c')
            sage: St = StabilityStudy([y, -k*x - c*y], [x, y], {x: 0, y: 0})
            sage: w = St.explorer({'k': (-1, 2, 1), 'c': (-1, 2, 0.5)})  # drawn once
            ...first approximation: asymptotically stable (max Re lambda = -0.25)
            ...
            sage: [c.description for c in w.kwargs_widgets]
            ['c', 'k', 'x axis', 'y axis', 'perturbation', 'time']
        """
        import ipywidgets as W
        from IPython.display import display, Math
        from sage.misc.latex import latex
        from sage.plot.plot import graphics_array
        from sage.repl.ipython_kernel.interact import sage_interactive
        names = [str(p) for p in self._parameters]
        missing = [p for p in names if p not in ranges]
        if missing:
            raise AnalysisError(f"no slider range for {', '.join(missing)}",
                                entry="stability explorer")
        plane = plane or (names + names)[:2]
        controls = {}
        # labels as wide as their text (the default width cuts "perturbation")
        label = dict(style={'description_width': 'initial'})
        for p in names:
            lo, hi, default = ranges[p]
            controls[p] = W.FloatSlider(value=default, min=lo, max=hi, step=(hi - lo) / 100,
                                        description=p, continuous_update=False, **label)
        controls['plane_x'] = W.Dropdown(options=names, value=plane[0], description='x axis',
                                         **label)
        controls['plane_y'] = W.Dropdown(options=names, value=plane[1], description='y axis',
                                         **label)
        controls['perturbation'] = W.FloatSlider(value=0.05, min=0, max=1, step=0.01,
                                                 description='perturbation',
                                                 continuous_update=False, **label)
        controls['t_end'] = W.FloatSlider(value=t_end, min=1, max=5 * t_end, step=1,
                                          description='time', continuous_update=False, **label)

        def page(**values):
            plane_x, plane_y = values.pop('plane_x'), values.pop('plane_y')
            perturbation, t_end = values.pop('perturbation'), values.pop('t_end')
            abscissa = self.spectral_abscissa(values)
            verdict = ("asymptotically stable" if abscissa < -1e-12 else
                       "unstable" if abscissa > 1e-12 else "critical case")
            print(f"first approximation: {verdict} (max Re lambda = {abscissa:.4g})")
            if self._note:
                print(self._note)
            if self._conditions is not None:
                held = self.conditions_hold(values)
                print(f"Lienard-Chipart conditions {'hold' if held else 'fail'}:")
                display(Math(",\\quad ".join(f"{latex(c)} > 0" for c in self._conditions)
                             or "\\text{(none: stable for all positive parameters)}"))
            x, y = plane_x, plane_y
            if x == y:
                y = next(p for p in names if p != x) if len(names) > 1 else x
            regions = self.region_plot(x, y, values, ranges[x][:2], ranges[y][:2])
            graphics_array([regions, self.roots_plot(values)]).show(figsize=[10, 4])
            self.trajectory_plot(values, perturbation, t_end).show(figsize=[10, 3.5])

        return sage_interactive(page, **controls)


def _asymptotic_conditions(verdict):
    r"""The conditions (each ``> 0``) of the asymptotically stable case of
    ``verdict``: ``[]`` where it holds everywhere, ``None`` where there is
    no such case or it is not one conjunction of strict inequalities."""
    for case in verdict.cases():
        if case.verdict() == 'asymptotically stable':
            if case.region() == [[]]:
                return []
            return case.conditions() or None
    return None

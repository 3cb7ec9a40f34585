r"""
Numerical right-hand sides `\dot x = f(t, x)` of equations of motion

:func:`numerical_rhs` turns a record of :mod:`sage_dynsym.analysis.motion`
(second order `E(q, \dot q, \ddot q) = 0`, or first order
`B \dot x = F(x)`) and parameter values into a callable ``f(t, x)`` on
NumPy arrays: at each call the mass matrix and the forcing (or `B` and
`F`) are evaluated by compiled code with common subexpressions shared, and
the linear system is solved numerically -- no symbolic inverse (see
:mod:`~sage_dynsym.numerics.form` and :mod:`~sage_dynsym.numerics.compiler`).
For second-order equations the state is `x = (q, \dot q)`.

EXAMPLES: a pendulum::

    sage: from sage_dynsym.analysis.motion import SecondOrderEquations
    sage: from sage_dynsym.numerics.rhs import numerical_rhs
    sage: x, dx, ddx, g, l = var('x dx ddx g l')
    sage: E = SecondOrderEquations([l*ddx + g*sin(x)], [x], [dx], [ddx])
    sage: f = numerical_rhs(E, {g: 9.81, 'l': 2}); f
    Numerical right-hand side x' = f(t, x) in (x, dx)
    sage: f(0, [pi.n()/2, 0.5])
    array([ 0.5  , -4.905])
"""
import math

import numpy as np

from sage.structure.sage_object import SageObject

from ..errors import AnalysisError, ModelError, brief
from ..arguments import finite_real
from .form import as_form
from .rnea_derivatives import jacobian_graph

__all__ = ['parameter_values', 'real_number', 'state_vector', 'RightHandSide', 'StateJacobian',
           'numerical_rhs']


def parameter_values(form, values):
    r"""
    The values of the parameters of ``form`` (in its order) as a NumPy
    array, from the dict ``values`` (keys: symbols or their names; values:
    Python or Sage numbers). Other keys are ignored.

    EXAMPLES::

        sage: from sage_dynsym.analysis.motion import FirstOrderEquations
        sage: from sage_dynsym.numerics.form import NumericalForm
        sage: from sage_dynsym.numerics.rhs import parameter_values
        sage: x, a, b = var('x a b')
        sage: N = NumericalForm(FirstOrderEquations([a*x + b], [x]))
        sage: parameter_values(N, {'a': 1/2, b: sqrt(2)})
        array([0.5       , 1.41421356])

    TESTS::

        sage: parameter_values(N, {a: 1})
        Traceback (most recent call last):
        ...
        ModelError: values: missing values of the parameters b
        sage: parameter_values(N, {a: 1, b: x})
        Traceback (most recent call last):
        ...
        ModelError: values: the value of b must be a real number, got x
    """
    if not isinstance(values, dict):
        raise ModelError(f"values must be a dict of parameter values, got {type(values).__name__}",
                         entry="values")
    by_name = {str(k): v for k, v in values.items()}
    missing = [a for a in form.parameters() if str(a) not in by_name]
    if missing:
        raise ModelError(f"missing values of the parameters {', '.join(map(str, missing))}",
                         entry="values")
    return np.array([real_number(by_name[str(a)], str(a)) for a in form.parameters()],
                    dtype=float)


def real_number(value, name, entry="values"):
    r"""
    ``value`` (a Python or Sage number, or a constant expression) as a
    finite float (see :func:`~sage_dynsym.arguments.finite_real`).

    EXAMPLES::

        sage: from sage_dynsym.numerics.rhs import real_number
        sage: real_number(pi, 'a'), real_number(3/4, 'b')
        (3.141592653589793, 0.75)

    TESTS::

        sage: real_number(float('nan'), 'x', entry='initial')
        Traceback (most recent call last):
        ...
        ModelError: initial: the value of x must be a finite real number, got nan
        sage: real_number(oo, 'k')
        Traceback (most recent call last):
        ...
        ModelError: values: the value of k must be a finite real number, got +Infinity
        sage: real_number('7', 'k')
        Traceback (most recent call last):
        ...
        ModelError: values: the value of k must be a real number, got '7' (str)
    """
    return finite_real(value, name, entry=entry)


def state_vector(x, size, entry="numerical_rhs"):
    r"""
    The state ``x`` (a sequence of ``size`` finite real numbers) as a NumPy
    array of floats; a :class:`~sage_dynsym.errors.ModelError` for anything
    else (strings, booleans, complex numbers, ``nan``, a wrong length).

    EXAMPLES::

        sage: from sage_dynsym.numerics.rhs import state_vector
        sage: state_vector([1, 1/2], 2)
        array([1. , 0.5])

    TESTS::

        sage: state_vector(['a', 'b'], 2)
        Traceback (most recent call last):
        ...
        ModelError: numerical_rhs: the state must be 2 real numbers, got ['a', 'b']
        sage: state_vector([1.0, float('nan')], 2)
        Traceback (most recent call last):
        ...
        ModelError: numerical_rhs: the state must be 2 finite real numbers, got [1.0, nan]
        sage: state_vector([1.0], 2)
        Traceback (most recent call last):
        ...
        ModelError: numerical_rhs: the state must have 2 entries, got 1
        sage: state_vector(None, 2)
        Traceback (most recent call last):
        ...
        ModelError: numerical_rhs: the state must be 2 real numbers, got None
    """
    array = None
    if not isinstance(x, (str, bytes, dict)) and hasattr(x, '__len__'):
        array = np.asarray(x) if not isinstance(x, np.ndarray) else x
        if array.dtype.kind == 'O':     # Sage numbers, one by one
            try:
                array = np.array([finite_real(v, 'x') for v in array.ravel()], dtype=float) \
                    if array.ndim == 1 else None
            except ModelError:
                array = None
        elif array.dtype.kind not in 'iuf':
            array = None
    if array is None:
        raise ModelError(f"the state must be {size} real numbers, got {brief(x)}", entry=entry)
    if array.shape != (size,):
        got = len(array) if array.ndim == 1 else f"shape {array.shape}"
        raise ModelError(f"the state must have {size} entries, got {got}", entry=entry)
    array = np.ascontiguousarray(array, dtype=float)
    if not np.isfinite(array).all():
        raise ModelError(f"the state must be {size} finite real numbers, got "
                         f"{brief(list(map(float, array)))}", entry=entry)
    return array


class RightHandSide(SageObject):
    r"""
    A numerical right-hand side ``f(t, x)`` (see :func:`numerical_rhs`).

    EXAMPLES::

        sage: from sage_dynsym.analysis.motion import FirstOrderEquations
        sage: from sage_dynsym.numerics.rhs import numerical_rhs
        sage: x, y, w = var('x y w')
        sage: f = numerical_rhs(FirstOrderEquations([w*y, -w*x], [x, y]), {w: 2})
        sage: f(0.0, [1.0, 0.0]), f.variables(), f.parameters()
        (array([ 0., -2.]), [x, y], {w: 2.0})
    """

    def __init__(self, form, values, backend='auto'):
        if not isinstance(values, dict):
            raise ModelError("values must be a dict of parameter values, got "
                             f"{type(values).__name__}", entry="values")
        form = form.with_functions(values)
        self._form = form
        self._p = parameter_values(form, values)
        self._kernel = form.kernel(backend)
        self._call = self._kernel.bind(self._p)
        self._shape = (len(form.state()),)

    def _repr_(self):
        return (f"Numerical right-hand side x' = f(t, x) in "
                f"({', '.join(map(str, self._form.state()))})")

    def __call__(self, t, x):
        # the integrators' calls, a float and a NumPy array of floats of the
        # right length, go straight to the compiled code; anything else is
        # checked first
        if (type(x) is np.ndarray and x.dtype == np.float64 and x.shape == self._shape
                and isinstance(t, float) and math.isfinite(t)):
            return self._call(t, x)
        t = finite_real(t, 't', entry="numerical_rhs")
        return self._call(t, state_vector(x, self._shape[0]))

    def variables(self):
        r"""The state variables, in the order of ``x``.

        EXAMPLES: see the class documentation.
        """
        return self._form.state()

    def parameters(self):
        r"""The parameter values used, as a dict.

        EXAMPLES: see the class documentation.
        """
        return dict(zip(self._form.parameters(), map(float, self._p)))

    def backend(self):
        r"""``'c'`` (compiled) or ``'python'``.

        EXAMPLES::

            sage: from sage_dynsym.analysis.motion import FirstOrderEquations
            sage: from sage_dynsym.numerics.rhs import numerical_rhs
            sage: x = var('x')
            sage: numerical_rhs(FirstOrderEquations([-x], [x]), {}, backend='python').backend()
            'python'
        """
        return self._kernel.backend()

    def form(self):
        r"""The :class:`~sage_dynsym.numerics.form.NumericalForm` evaluated.

        EXAMPLES::

            sage: from sage_dynsym.analysis.motion import FirstOrderEquations
            sage: from sage_dynsym.numerics.rhs import numerical_rhs
            sage: x = var('x')
            sage: numerical_rhs(FirstOrderEquations([-x], [x]), {}).form()
            Numerical form x' = F in (x), parameters ()
        """
        return self._form


class StateJacobian(SageObject):
    r"""
    The compiled Jacobian ``jac(t, x)`` of a right-hand side ``f(t, x)``
    with respect to the state: the dense square matrix
    `\partial f_i/\partial x_j`, generated from the recursive algorithms
    differentiated (by the coordinates through inverse dynamics, see
    :mod:`~sage_dynsym.numerics.rnea_derivatives`; forward mode, see
    :mod:`~sage_dynsym.numerics.derivatives`) and compiled like ``f`` --
    not finite differences; the columns are computed several at a time in
    the lanes of C vectors. For second-order systems, `x = (q, \dot q)`
    and the Jacobian is `\begin{pmatrix} 0 & E \\ \partial\ddot q/\partial q
    & \partial\ddot q/\partial\dot q\end{pmatrix}`.

    INPUT:

    - ``form`` -- a :class:`~sage_dynsym.numerics.recursive.RecursiveForm`
      (the form of the equations has no compiled Jacobian: an
      :class:`~sage_dynsym.errors.AnalysisError` says so)
    - ``values`` -- dict of the parameter values
    - ``backend`` -- ``'auto'``, ``'c'`` or ``'python'``

    EXAMPLES: a pendulum, `\ddot\varphi = -(g/l)\sin\varphi`::

        sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
        sage: from sage_dynsym.numerics.recursive import RecursiveForm
        sage: from sage_dynsym.numerics.rhs import StateJacobian
        sage: phi, m, l, g = var('phi m l g')
        sage: rod = TreeBody(0, rotations=[(1, phi)], mass=m, mass_center=[0, 0, -l],
        ....:                inertia=diagonal_matrix([m*l^2, m*l^2, 0]))
        sage: jac = StateJacobian(RecursiveForm(BodyTree([rod], [phi], gravity=[0, 0, -g])),
        ....:                     {g: 9.81, l: 2, m: 1})
        sage: jac(0, [0, 0.5])
        array([[ 0.   ,  1.   ],
               [-4.905,  0.   ]])

    TESTS::

        sage: jac(0, [0])
        Traceback (most recent call last):
        ...
        ModelError: numerical_rhs: the state must have 2 entries, got 1
        sage: from sage_dynsym.analysis.motion import FirstOrderEquations
        sage: from sage_dynsym.numerics.form import NumericalForm
        sage: StateJacobian(NumericalForm(FirstOrderEquations([-phi], [phi])), {})
        Traceback (most recent call last):
        ...
        AnalysisError: jacobian: the compiled Jacobian is generated from the recursive algorithms of a tree of rigid bodies (a mechanical system with algorithm='recursive'); this model's right-hand side comes from its equations
        sage: F = RecursiveForm(BodyTree([TreeBody(0, joint=[phi, 0, 0], mass=m)], [phi]))
        sage: StateJacobian(F, {m: 0})(0, [0.0, 0.0])
        Traceback (most recent call last):
        ...
        AnalysisError: jacobian: the system is singular at t = 0.0, state [0.0, 0.0]
    """

    def __init__(self, form, values, backend='auto'):
        if not hasattr(form, 'jacobian_kernel'):
            raise AnalysisError("the compiled Jacobian is generated from the recursive "
                                "algorithms of a tree of rigid bodies (a mechanical system with "
                                "algorithm='recursive'); this model's right-hand side comes from "
                                "its equations", entry="jacobian")
        form = form.with_functions(values)
        self._form = form
        self._p = parameter_values(form, values)
        self._function = form.jacobian_kernel(backend, derivatives=jacobian_graph)
        self._size = len(form.state())

    def _repr_(self):
        return (f"Jacobian of the numerical right-hand side by the state "
                f"({', '.join(map(str, self._form.state()))})")

    def __call__(self, t, x):
        if not (type(x) is np.ndarray and x.dtype == np.float64 and x.shape == (self._size,)
                and isinstance(t, float) and math.isfinite(t)):
            t = finite_real(t, 't', entry="numerical_rhs")
            x = state_vector(x, self._size)
        try:
            return self._function(t, x, self._p)
        except ZeroDivisionError as err:
            chart = getattr(self._form, 'singular_chart', lambda x: None)(x)
            if chart is not None:
                raise AnalysisError(chart, entry="jacobian") from err
            raise AnalysisError(f"the system is singular at t = {float(t)}, state "
                                f"{list(map(float, x))}", entry="jacobian") from err

    def variables(self):
        r"""The state variables, in the order of the rows and columns.

        EXAMPLES::

            sage: from sage_dynsym.numerics.body_tree import BodyTree, TreeBody
            sage: from sage_dynsym.numerics.recursive import RecursiveForm
            sage: from sage_dynsym.numerics.rhs import StateJacobian
            sage: x = var('x')
            sage: F = RecursiveForm(BodyTree([TreeBody(0, joint=[x, 0, 0], mass=1)], [x]))
            sage: StateJacobian(F, {}).variables()
            [x, dx]
        """
        return self._form.state()


def numerical_rhs(equations, values, backend='auto'):
    r"""
    The numerical right-hand side ``f(t, x)`` of ``equations``.

    INPUT:

    - ``equations`` -- a record of :mod:`sage_dynsym.analysis.motion`, a
      :class:`~sage_dynsym.numerics.form.NumericalForm` or a
      :class:`~sage_dynsym.numerics.recursive.RecursiveForm`
    - ``values`` -- dict of the parameter values (symbols or names as
      keys) and of the definitions of unspecified functions (see
      :meth:`~sage_dynsym.numerics.form.NumericalForm.with_functions`)
    - ``backend`` -- ``'auto'`` (compiled C when a compiler works, else
      Python), ``'c'`` or ``'python'``

    OUTPUT: a :class:`RightHandSide`: ``f(t, x)`` takes a sequence ``x``
    over :meth:`RightHandSide.variables` and returns a NumPy array

    EXAMPLES: see the module documentation; holonomic constraints are
    honoured through their multipliers (a Cartesian pendulum,
    `x^2 + y^2 = l^2`)::

        sage: from sage_dynsym.analysis.motion import SecondOrderEquations
        sage: from sage_dynsym.numerics.rhs import numerical_rhs
        sage: x, y, dx, dy, ddx, ddy, mu, g = var('x y dx dy ddx ddy mu g')
        sage: E = SecondOrderEquations([ddx - 2*mu*x, ddy + g - 2*mu*y], [x, y], [dx, dy], [ddx, ddy],
        ....:                          constraints=[x^2 + y^2 - 1], multipliers=[mu])
        sage: numerical_rhs(E, {g: 1})(0, [1.0, 0.0, 0.0, 1.0])    # centripetal
        array([ 0.,  1., -1., -1.])

    A nonlinear resistor `i = f(u)` in parallel with a capacitor `C`::

        sage: from sage_dynsym.analysis.motion import FirstOrderEquations
        sage: u, C = var('u C'); f = function('f')
        sage: E1 = FirstOrderEquations([-f(u)], [u], lhs_matrix=[C])
        sage: numerical_rhs(E1, {C: 2, 'f': lambda v: v^3 - v})(0, [2.0])
        array([-3.])

    TESTS::

        sage: numerical_rhs(E, {})
        Traceback (most recent call last):
        ...
        ModelError: values: missing values of the parameters g
    """
    return RightHandSide(as_form(equations), values, backend)

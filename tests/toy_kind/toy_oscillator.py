"""
A kind of model defined outside sage_dynsym: a damped oscillator
``m x'' + c x' + k x = 0`` described by ``kind: oscillator`` files.

It implements the model interface (sage_dynsym.dynamics.model.Model) and
nothing else; tests/test_model_interface.py registers it through an entry
point of a temporary distribution and runs it through load, the report, the
command line, a stability map and save -- none of which knows this class.
"""
import sage.all  # noqa: F401
from sage.symbolic.ring import SR

from sage_dynsym.analysis import linearize
from sage_dynsym.analysis.motion import FirstOrderEquations
from sage_dynsym.dynamics.derivations import Derivation
from sage_dynsym.dynamics.model import Model, linearization_point
from sage_dynsym.dynamics.reporting import ReportSection, formula_lines
from sage_dynsym.errors import DescriptionError
from sage_dynsym.io.expressions import ExpressionParser

FIELDS = ('mass', 'stiffness', 'damping')


class Oscillator(Model):
    kind = 'oscillator'

    def __init__(self, mass, stiffness, damping, parameters=(), positive=(), name=None):
        self._values = [SR(mass), SR(stiffness), SR(damping)]
        self._parameters = list(parameters)
        self._positive = list(positive)
        self._name = name
        self._x, self._v = SR.var('x'), SR.var('v')

    def _repr_(self):
        return f"Oscillator {self._name!r}"

    def name(self):
        return self._name

    def parameters(self):
        return self._parameters

    def positive_parameters(self):
        return self._positive

    @classmethod
    def from_dict(cls, data, source=None):
        names = data.get('parameters', [])
        parser = ExpressionParser(names)
        missing = [f for f in FIELDS if f not in data]
        if missing:
            raise DescriptionError(f"missing key {missing[0]!r}", source=source)
        values = [parser.parse(str(data[f]), entry=f) for f in FIELDS]
        parameters = [SR.var(n) for n in names]
        positive = [SR.var(n) for n in data.get('positive', [])]
        return cls(*values, parameters=parameters, positive=positive, name=data.get('name'))

    def to_dict(self):
        data = {'kind': self.kind}
        if self._name:
            data['name'] = self._name
        data['parameters'] = [str(p) for p in self._parameters]
        data['positive'] = [str(p) for p in self._positive]
        data.update({f: str(v) for f, v in zip(FIELDS, self._values)})
        return data

    def results(self):
        return {'equations': [str(e) for e in self.equations()]}

    def result_symbols(self, results):
        return ['x', 'v'] + [str(p) for p in self._parameters], ()

    def equations(self):
        m, k, c = self._values
        return [self._v, -(k * self._x + c * self._v) / m]

    def equations_record(self):
        return FirstOrderEquations(self.equations(), [self._x, self._v])

    def characteristic_functions(self):
        m, k, _ = self._values
        return {'energy': lambda: m * self._v**2 / 2 + k * self._x**2 / 2}

    def equation_forms(self):
        def state(cyclic=()):
            rows = [("\\dot{x}", self.equations()[0]), ("\\dot{v}", self.equations()[1])]
            return Derivation('state', ('E', self.characteristic_functions()['energy']()),
                              rows, None)
        return {'state': state}

    def free_linear_system(self, at=None):
        point = linearization_point(at, [self._x, self._v])
        return linearize(self.equations(), point, [self._x, self._v])

    def report_title(self):
        return f"== {self._name} (oscillator) =="

    def report_sections(self):
        def equations(context):
            lines = ["State equations:"]
            for x, f in zip(('x', 'v'), self.equations()):
                lines += formula_lines(f"d{x}/dt = ", f)
            return lines

        def stability(context):
            poly = self.free_linear_system().characteristic_polynomial(SR.var('lambda_'))
            return ["Stability:"] + formula_lines("characteristic polynomial: ", poly)
        return [ReportSection('equations', "State equations", equations),
                ReportSection('stability', "Stability", stability, analysis=True)]

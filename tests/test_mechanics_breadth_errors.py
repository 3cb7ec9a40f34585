"""
Bad input for the modelling-breadth entries of mechanical systems: force
functions as lists of terms, loads, constraints, parameter values. Every
error is a DynSymError naming the file (where there is one) and the entry.
"""
import pytest
import yaml

from sage.all import SR
from sage_dynsym import MechanicalSystem, RigidBody, UniformGravity, load
from sage_dynsym.errors import DescriptionError, DynSymError, ExpressionError, ModelError
from sage_dynsym.mechanics.loads import Load

BASE = {
    'kind': 'mechanical', 'name': 'slider', 'parameters': ['m', 'k', 'g', 'l', 'F'],
    'coordinates': ['x', 'z'],
    'bodies': [{'name': 'b', 'joint': ['x', 0, 'z'], 'mass': 'm'}],
}


def load_dict(tmp_path, **changes):
    data = dict(BASE, **changes)
    path = tmp_path / "model.yaml"
    path.write_text(yaml.safe_dump(data))
    return load(str(path))


def refused(tmp_path, error, entry, **changes):
    with pytest.raises(error) as info:
        load_dict(tmp_path, **changes)
    message = str(info.value)
    assert "model.yaml" in message and f"{entry}:" in message, message
    return message


# -- force functions ---------------------------------------------------------

def test_force_function_terms(tmp_path):
    refused(tmp_path, ExpressionError, "force_function[1].expression",
            force_function=[{'uniform_gravity': [0, 0, '-g']}, {'expression': '-k*dx^2'}])
    refused(tmp_path, DescriptionError, "force_function[0]",
            force_function=[{'uniform_gravity': [0, 0, '-g'], 'expression': 'x'}])
    refused(tmp_path, DescriptionError, "force_function[1]",
            force_function=[{'expression': 'x'}, {'gravity': [0, 0, 1]}])
    refused(tmp_path, DescriptionError, "force_function[0].uniform_gravity",
            force_function=[{'uniform_gravity': [0, 0]}])
    refused(tmp_path, DescriptionError, "force_function", force_function=[])
    refused(tmp_path, ExpressionError, "force_function[1].expression",
            force_function=[{'expression': 'x'}, {'expression': 'q^2'}])


def test_force_function_terms_python():
    x, k = SR.var('x k')
    with pytest.raises(ModelError, match=r"force_function\[1\]: .*velocity dx"):
        MechanicalSystem([], [x], force_function=[-k * x ** 2, SR.var('dx')])
    with pytest.raises(ModelError, match=r"force_function\[0\]: undeclared symbol q"):
        MechanicalSystem([], [x], parameters=[k], force_function=[SR.var('q'), UniformGravity([0, 0, -1])])


# -- loads -----------------------------------------------------------------

def test_load_errors(tmp_path):
    message = refused(tmp_path, ModelError, "loads[0].body",
                      loads=[{'body': 'wheel', 'force': [1, 0, 0]}])
    assert "unknown body 'wheel'" in message and "known bodies are: b" in message
    refused(tmp_path, ModelError, "loads[1].body",
            loads=[{'body': 'b', 'force': [1, 0, 0]}, {'body': 3, 'force': [1, 0, 0]}])
    refused(tmp_path, ModelError, "loads[0].axes",
            loads=[{'body': 'b', 'force': [1, 0, 0], 'axes': 'frame'}])
    refused(tmp_path, DescriptionError, "loads[0].point",
            loads=[{'body': 'b', 'point': [0, 1], 'force': [1, 0, 0]}])
    refused(tmp_path, ExpressionError, "loads[0].point[2]",
            loads=[{'body': 'b', 'point': [0, 0, 'dz'], 'force': [1, 0, 0]}])
    refused(tmp_path, ExpressionError, "loads[0].force[0]",
            loads=[{'body': 'b', 'force': ['q', 0, 0]}])
    refused(tmp_path, DescriptionError, "loads[0]", loads=[{'body': 'b'}])
    refused(tmp_path, DescriptionError, "loads[0]", loads=[{'force': [1, 0, 0]}])
    refused(tmp_path, DescriptionError, "loads[0]",
            loads=[{'body': 'b', 'force': [1, 0, 0], 'colour': 'red'}])
    refused(tmp_path, DescriptionError, "loads[0].body", loads=[{'body': [1], 'force': [1, 0, 0]}])
    refused(tmp_path, DescriptionError, "loads", loads={'body': 'b'})


def test_load_errors_python():
    x = SR.var('x')
    body = RigidBody('b', joint=[x, 0, 0], mass=1)
    with pytest.raises(ModelError, match=r"loads\[2\]\.body: unknown body 'c'"):
        MechanicalSystem([body], [x], loads=[Load('b', force=[1, 0, 0])] * 2
                         + [{'body': 'c', 'force': [1, 0, 0]}])
    with pytest.raises(ModelError, match=r"loads\[0\]\.point: expected a list of 3"):
        MechanicalSystem([body], [x], loads=[{'body': 'b', 'point': [1], 'force': [1, 0, 0]}])
    with pytest.raises(ModelError, match=r"loads\[0\]\.point: the point of application cannot depend on dx"):
        MechanicalSystem([body], [x], loads=[{'body': 'b', 'point': [SR.var('dx'), 0, 0],
                                              'force': [1, 0, 0]}])
    with pytest.raises(ModelError, match=r"loads\[0\]\.force: the force cannot depend on ddx"):
        MechanicalSystem([body], [x], loads=[{'body': 'b', 'force': [SR.var('ddx'), 0, 0]}])
    with pytest.raises(ModelError, match=r"loads\[0\]: expected a Load"):
        MechanicalSystem([body], [x], loads=[3])


# -- constraints -------------------------------------------------------------

def test_constraint_errors(tmp_path):
    message = refused(tmp_path, ModelError, "constraints[0]", constraints=['l - 1'])
    assert "does not depend on the coordinates" in message
    message = refused(tmp_path, ModelError, "constraints",
                      constraints=['x^2 + z^2 - l^2', '2*x^2 + 2*z^2 - 2*l^2'])
    assert "not independent" in message
    refused(tmp_path, ModelError, "constraints", constraints=['x', 'z', 'x + z - l'])
    refused(tmp_path, ExpressionError, "constraints[1]", constraints=['x - l', 'z - dx'])
    refused(tmp_path, ExpressionError, "constraints[0]", constraints=['x - q'])
    refused(tmp_path, DescriptionError, "constraints", constraints='x - l')


def test_constraint_errors_python():
    x, y, l = SR.var('x y l')
    with pytest.raises(ModelError, match=r"constraints\[0\]: the constraint l - 1 == 0 does not depend"):
        MechanicalSystem([], [x, y], constraints=[l - 1])
    with pytest.raises(ModelError, match=r"constraints: the 2 constraints are not independent"):
        MechanicalSystem([], [x, y], constraints=[x - y, 2 * y - 2 * x])
    with pytest.raises(ModelError, match=r"constraints\[0\]: a holonomic constraint f\(q, t\) "
                                         r"cannot depend on the velocity dx"):
        MechanicalSystem([], [x, y], constraints=[SR.var('dx') - y])
    with pytest.raises(ModelError, match=r"constraints\[0\]: undeclared symbol q"):
        MechanicalSystem([], [x, y], parameters=[l], constraints=[x - SR.var('q')])


# -- parameter values --------------------------------------------------------

def test_subs_errors(tmp_path):
    S = load_dict(tmp_path)
    with pytest.raises(ModelError, match="subs: cannot substitute for x"):
        S.subs({SR.var('x'): 1})
    with pytest.raises(ModelError, match="subs: cannot substitute for dz"):
        S.subs({'dz': 1})
    with pytest.raises(ModelError, match="subs: w is not a parameter"):
        S.subs({'w': 1})
    # m is not declared positive: its sign is a condition of the model
    with pytest.raises(ModelError, match=r"subs: the values break the condition m >= 0"):
        S.subs({'m': -1})
    with pytest.raises(DynSymError):
        S.subs([1, 2])

"""
A plain-data chain of rigid bodies (``reference/chains.py``) as a Pinocchio model.

Independent of sage_dynsym. Each elementary rotation whose angle is a
coordinate becomes a revolute joint about that axis (``JointModelRX``,
``RY``, ``RZ``), each component of a joint point that is a coordinate a
prismatic joint along that axis (``JointModelPX``, ...; a free base); the first one of a body is placed at the body's joint point
in the parent's frame, the following ones at the frame of the previous one
(a body turned by two angles is two revolute joints with a massless
intermediate body); the body's inertia (given about its joint point) is
moved to its mass centre for ``pinocchio.Inertia``. Offsets, masses and
inertias are numbers or strings over the parameters, evaluated with
``values``.
"""
from fractions import Fraction


def _number(value, values):
    import sympy
    if isinstance(value, Fraction):
        return float(value)
    if isinstance(value, str):
        names = {k: sympy.Symbol(k) for k in values}
        return float(sympy.sympify(value, locals=names).subs(
            {names[k]: v for k, v in values.items()}))
    return float(value)


def pinocchio_model(desc, values):
    """
    ``(model, coordinates)``: the ``pinocchio.Model`` of the plain-data chain
    ``desc`` with the parameter values ``values`` (dict name -> float) and the
    coordinate names in the order of the model's configuration vector.
    """
    import numpy as np
    import pinocchio as pin
    model = pin.Model()
    model.gravity = pin.Motion(np.array([_number(g, values) for g in desc['gravity']] + [0, 0, 0]))
    joint_of, frame_of, order = {0: 0}, {0: pin.SE3.Identity()}, []
    for k, body in enumerate(desc['bodies'], 1):
        parent = joint_of[body['parent']]
        # a joint component that is a coordinate: a prismatic joint along
        # that axis of the parent (a free base: x, y, z)
        sliding = [(i, c) for i, c in enumerate(body['joint']) if c in desc['coordinates']]
        offset = frame_of[body['parent']] * pin.SE3(
            np.eye(3), np.array([0.0 if c in desc['coordinates'] else _number(c, values)
                                 for c in body['joint']]))
        placement = offset
        for i, c in sliding:
            joint = (pin.JointModelPX, pin.JointModelPY, pin.JointModelPZ)[i]()
            parent = model.addJoint(parent, joint, placement, str(c))
            order.append(c)
            placement = pin.SE3.Identity()
        for axis, angle in body['rotations']:
            if angle not in desc['coordinates']:
                raise ValueError(f"body {k}: the angle {angle} is not a coordinate")
            joint = (pin.JointModelRX, pin.JointModelRY, pin.JointModelRZ)[int(axis) - 1]()
            parent = model.addJoint(parent, joint, placement, str(angle))
            order.append(angle)
            placement = pin.SE3.Identity()
        joint_of[k], frame_of[k] = parent, placement
        m = _number(body['mass'], values)
        c = np.array([_number(x, values) for x in body['mass_center']])
        inertia = np.array([[_number(x, values) for x in row] for row in body['inertia']])
        central = inertia - m * (c @ c * np.eye(3) - np.outer(c, c))
        model.appendBodyToJoint(parent, pin.Inertia(m, c, central), placement)
    return model, order

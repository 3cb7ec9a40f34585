"""
Plain-data descriptions of rigid-body chains (no Sage, no SymPy objects).

The dicts use the fields read by :mod:`reference.sympy_chain`; every entry is
an int, a :class:`fractions.Fraction` or a string over the declared names, so
the same description can be handed to any implementation.
"""
import random
from fractions import Fraction


def _rational(rng, low, high, den=4):
    return Fraction(rng.randint(low * den, high * den), den)


def random_spd(rng, den=4):
    """A random symmetric positive definite 3x3 matrix of rationals (A A^T + I/2)."""
    A = [[rng.randint(-3, 3) for _ in range(3)] for _ in range(3)]
    return [[Fraction(sum(A[i][s] * A[j][s] for s in range(3)), den)
             + (Fraction(1, 2) if i == j else 0) for j in range(3)] for i in range(3)]


def physical_inertia(rng, mass, center):
    """
    A random inertia tensor about O_k that a real body can have: the central
    tensor ``tr(J) E - J`` of a random positive definite second-moment matrix
    ``J`` (so its principal moments obey the triangle inequalities), moved to
    O_k by the parallel-axis theorem.
    """
    J = random_spd(rng)
    trace = J[0][0] + J[1][1] + J[2][2]
    c2 = sum(x * x for x in center)
    return [[(trace if i == j else 0) - J[i][j]
             + mass * ((c2 if i == j else 0) - center[i] * center[j])
             for j in range(3)] for i in range(3)]


def random_chain(seed, n_bodies=None, max_rotations=3, symbolic=False, massless_carrier=False):
    """
    A random chain of 1-4 rigid bodies in uniform gravity.

    Each body gets a random earlier parent (body 1: the inertial frame), 0..3
    elementary rotations about random axes (each angle is its own coordinate
    ``q<k>_<i>``), random joint and mass-centre vectors, a random mass and a
    random, physically possible (hence positive definite) inertia tensor
    about its joint point.

    With ``symbolic=True`` the masses, one mass-centre component and the
    diagonal inertias are symbols (``m<k>``, ``c<k>``, ``A<k>``) whose random
    values are returned in ``values``; with ``massless_carrier=True`` body 1 has
    mass 0 and zero inertia.

    OUTPUT: dict with keys ``bodies``, ``coordinates``, ``parameters``,
    ``gravity``, ``values`` (numbers for the parameters).
    """
    rng = random.Random(seed)
    n = n_bodies or rng.randint(1, 4)
    bodies, coords, params, values = [], [], [], {}
    for k in range(1, n + 1):
        rotations = []
        for i in range(1, rng.randint(0, max_rotations) + 1):
            name = f"q{k}_{i}"
            rotations.append((rng.randint(1, 3), name))
            coords.append(name)
        body = dict(parent=0 if k == 1 else rng.randint(1, k - 1),
                    rotations=rotations,
                    joint=[_rational(rng, -2, 2) for _ in range(3)],
                    mass_center=[_rational(rng, -2, 2) for _ in range(3)],
                    mass=_rational(rng, 1, 3))
        body['inertia'] = physical_inertia(rng, body['mass'], body['mass_center'])
        if symbolic:
            m, c, A = f"m{k}", f"c{k}", f"A{k}"
            params += [m, c, A]
            values.update({m: float(body['mass']), c: float(body['mass_center'][2]),
                           A: float(body['inertia'][0][0])})
            body['mass'] = m
            body['mass_center'][2] = c
            body['inertia'][0][0] = A
        bodies.append(body)
    if massless_carrier:
        bodies[0]['mass'] = 0
        bodies[0]['inertia'] = [[0] * 3 for _ in range(3)]
    gravity = [_rational(rng, -3, 3) for _ in range(3)]
    return dict(bodies=bodies, coordinates=coords, parameters=params,
                gravity=gravity, values=values)


def spatial_chain(n):
    """
    The N-link spatial chain of the benchmark: link k turns about z by
    ``psi<k>`` then about the new x by ``theta<k>``; its joint is at the end of
    the previous link, ``(0, 0, l<k-1>)`` in the parent's axes; mass centre
    ``(0, 0, c<k>)``; inertia ``diag(A<k>, A<k>, C<k>)`` about the joint; mass
    ``m<k>``; gravity ``(0, 0, -g)``.
    """
    bodies, coords, params = [], [], ['g']
    for k in range(1, n + 1):
        coords += [f"psi{k}", f"theta{k}"]
        params += [f"m{k}", f"l{k}", f"c{k}", f"A{k}", f"C{k}"]
        bodies.append(dict(parent=k - 1, rotations=[(3, f"psi{k}"), (1, f"theta{k}")],
                           joint=[0, 0, f"l{k - 1}" if k > 1 else 0],
                           mass_center=[0, 0, f"c{k}"], mass=f"m{k}",
                           inertia=[[f"A{k}", 0, 0], [0, f"A{k}", 0], [0, 0, f"C{k}"]]))
    return dict(bodies=bodies, coordinates=coords, parameters=params,
                gravity=[0, 0, "-g"], values={})


def physical_values(desc, rng):
    """
    Random parameter values of :func:`spatial_chain` that a real chain can
    have: the central inertia diag(A - m c^2, A - m c^2, C) is positive and
    obeys the triangle inequalities (else the mass matrix may be singular).
    """
    values = {'g': 9.81}
    for k in range(1, len(desc['bodies']) + 1):
        m, c = rng.uniform(0.5, 2), rng.uniform(0.3, 1)
        values.update({f'm{k}': m, f'c{k}': c, f'l{k}': rng.uniform(0.5, 2),
                       f'A{k}': m * c * c + m * rng.uniform(0.2, 0.5),
                       f'C{k}': m * rng.uniform(0.05, 0.2)})
    return {p: values[p] for p in desc['parameters']}


def random_point(desc, rng, values=None):
    """
    A random numerical point for every symbol of the equations of ``desc``:
    each coordinate ``q`` and its ``dq``, ``ddq``, then each parameter (taken
    from ``values`` where it has one; a value is drawn for every parameter
    all the same, so that the draws that follow do not depend on ``values``).
    """
    values = values or {}
    point = {}
    for q in desc['coordinates']:
        point[q] = rng.uniform(-3, 3)
        point['d' + q] = rng.uniform(-2, 2)
        point['dd' + q] = rng.uniform(-2, 2)
    for p in desc['parameters']:
        drawn = rng.uniform(0.5, 2)
        point[p] = values.get(p, drawn)
    return point


def offset_chain(n):
    """
    A second N-link chain, unlike :func:`spatial_chain`: link k turns about
    y by ``a<k>`` then about the new z by ``b<k>``; its joint is offset from
    the previous link's axis, ``(1/5, -1/10, 3/4)`` in the parent's axes;
    mass centre ``(1/10, 1/20, 2/5)``; a full inertia tensor about the joint
    (products of inertia included, physically possible); numbers for every
    datum but gravity ``(0, 0, -g)``.
    """
    bodies, coords = [], []
    for k in range(1, n + 1):
        coords += [f"a{k}", f"b{k}"]
        rng = random.Random(1000 + k)
        mass = Fraction(2 + k % 3, 2)
        center = [Fraction(1, 10), Fraction(1, 20), Fraction(2, 5)]
        joint = [Fraction(1, 5), Fraction(-1, 10), Fraction(3, 4)] if k > 1 else [0, 0, 0]
        bodies.append(dict(parent=k - 1, rotations=[(2, f"a{k}"), (3, f"b{k}")], joint=joint,
                           mass_center=center, mass=mass,
                           inertia=physical_inertia(rng, mass, center)))
    return dict(bodies=bodies, coordinates=coords, parameters=['g'], gravity=[0, 0, "-g"],
                values={})


def humanoid_tree():
    """
    A humanoid-like tree of 46 coordinates on a free-floating base: the
    pelvis moves by three translations ``x, y, z`` (its joint point) and
    three rotations (z, y, x: ``yaw, pitch, roll``); it carries a torso (2
    rotations) with a head (2), two arms (shoulder 3, elbow 1, wrist 2) each
    with a hand of three fingers (2 joints each), and two legs (hip 3, knee
    1, ankle 2). Several children per body; joint offsets, mass centres,
    masses and full inertia tensors are numbers (fixed seed); gravity
    ``(0, 0, -g)``.
    """
    rng = random.Random(46)
    bodies, coords = [], []

    def add(parent, name, axes, joint, mass, length):
        rotations = []
        for i, axis in enumerate(axes, 1):
            coords.append(f"{name}_{i}")
            rotations.append((axis, f"{name}_{i}"))
        center = [_rational(rng, -1, 1, 20), _rational(rng, -1, 1, 20), Fraction(-length, 2)]
        bodies.append(dict(parent=parent, rotations=rotations, joint=joint, mass_center=center,
                           mass=Fraction(mass), inertia=physical_inertia(rng, mass, center),
                           name=name))
        return len(bodies)

    coords += ['x', 'y', 'z']
    pelvis = add(0, 'pelvis', (3, 2, 1), ['x', 'y', 'z'], 8, Fraction(1, 5))
    torso = add(pelvis, 'torso', (3, 2), [0, 0, Fraction(1, 5)], 12, Fraction(-2, 5))
    add(torso, 'head', (3, 2), [0, 0, Fraction(1, 2)], 4, Fraction(-1, 5))
    # bodies numbered depth first (each subtree contiguous), as Pinocchio's
    # derivative algorithms assume of its joints
    for side, sign in (('l', 1), ('r', -1)):
        upper = add(torso, f'{side}shoulder', (2, 1, 3), [0, sign * Fraction(1, 5), Fraction(2, 5)],
                    2, Fraction(3, 10))
        fore = add(upper, f'{side}elbow', (2,), [0, 0, Fraction(-3, 10)], Fraction(3, 2),
                   Fraction(1, 4))
        hand = add(fore, f'{side}wrist', (1, 2), [0, 0, Fraction(-1, 4)], Fraction(1, 2),
                   Fraction(1, 10))
        for finger in range(3):
            add(hand, f'{side}finger{finger}', (2, 1), [Fraction(finger - 1, 40), 0,
                                                        Fraction(-1, 10)], Fraction(1, 20),
                Fraction(1, 20))
    for side, sign in (('l', 1), ('r', -1)):
        thigh = add(pelvis, f'{side}hip', (3, 1, 2), [0, sign * Fraction(1, 10), 0], 6,
                    Fraction(2, 5))
        shin = add(thigh, f'{side}knee', (2,), [0, 0, Fraction(-2, 5)], 3, Fraction(2, 5))
        add(shin, f'{side}ankle', (2, 1), [0, 0, Fraction(-2, 5)], 1, Fraction(1, 10))
    return dict(bodies=bodies, coordinates=coords, parameters=['g'], gravity=[0, 0, "-g"],
                values={})

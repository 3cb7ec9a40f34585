"""
Models of robot size from description files: 1,000 coordinates and the
parameters they need load; one coordinate, body or parameter more is
refused with an error naming the limit.

The files are written here, as text, from a 500-link chain whose every link
has its own mass, length, mass centre and six moments of inertia (9 parameters
a link, 4,501 in all) and two rotations (1,000 coordinates).
"""
import pytest

from sage_dynsym import load
from sage_dynsym.errors import DescriptionError


def chain_text(links, extra_coordinates=0, extra_parameters=0, extra_bodies=0):
    """The YAML text of the chain (one more body per extra coordinate, a
    slider; extra parameters unused; extra bodies without coordinates)."""
    parameters = ['g']
    coordinates = []
    bodies = []
    for k in range(1, links + 1):
        p = [f'{s}{k}' for s in ('m', 'l', 'c', 'Ixx', 'Iyy', 'Izz', 'Ixy', 'Ixz', 'Iyz')]
        parameters += p
        coordinates += [f'a{k}', f'b{k}']
        joint = f'[0, 0, l{k - 1}]' if k > 1 else '[0, 0, 0]'
        bodies.append(f"  - {{name: link{k}, parent: {k - 1}, rotations: [[2, a{k}], [3, b{k}]], "
                      f"joint: {joint}, mass_center: [0, 0, c{k}], mass: m{k}, inertia: "
                      f"[[Ixx{k}, Ixy{k}, Ixz{k}], [Ixy{k}, Iyy{k}, Iyz{k}], "
                      f"[Ixz{k}, Iyz{k}, Izz{k}]]}}")
    for j in range(extra_coordinates):
        coordinates.append(f's{j}')
        bodies.append(f"  - {{name: slider{j}, joint: [s{j}, 0, 0], mass: 1}}")
    parameters += [f'u{j}' for j in range(extra_parameters)]
    bodies += [f"  - {{name: extra{j}, parent: 0, mass: 1}}" for j in range(extra_bodies)]
    return "\n".join(["kind: mechanical", "name: long chain",
                      f"parameters: [{', '.join(parameters)}]",
                      f"coordinates: [{', '.join(coordinates)}]",
                      "force_function:", "  uniform_gravity: [0, 0, -g]", "bodies:"]
                     + bodies) + "\n"


def _write(tmp_path, text):
    path = tmp_path / 'chain.yaml'
    path.write_text(text)
    return str(path)


@pytest.mark.slow       # half a minute: the physical conditions of 500 bodies
def test_a_500_link_chain_of_1000_coordinates_loads(tmp_path):
    S = load(_write(tmp_path, chain_text(500)))
    assert len(S.coordinates()) == 1000
    assert len(S.bodies()) == 500
    assert len(S.parameters()) == 1 + 9 * 500
    # the last link hangs from the one before it, through the whole chain
    assert S.parent_index(500) == 499 and S.parent_index(1) == 0


@pytest.mark.parametrize('links, extra, limit', [
    (500, dict(extra_coordinates=1), 'MAX_COORDINATES'),
    (0, dict(extra_bodies=1001), 'MAX_BODIES'),
    (0, dict(extra_parameters=10_000), 'MAX_PARAMETERS'),     # with g: 10,001
])
def test_one_more_is_refused_by_name(tmp_path, links, extra, limit):
    with pytest.raises(DescriptionError, match=limit) as error:
        load(_write(tmp_path, chain_text(links, **extra)))
    assert 'at most' in str(error.value)

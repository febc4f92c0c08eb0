"""beamsolid.boundaries on small models: tributary areas, the dashpot tensor
and its orientation (free decay of a node on an inclined face against the
trapezoidal rule's closed form), the Joyner-Chen force, ties, and bad input.
The wave problems are in test_shear_column.py."""
import math

import numpy as np
import pytest

import beamsolid
from beamsolid import boundaries as bd

RHO, E, NU = 2.0, 52000.0, 0.3


def test_wave_speeds():
    vp, vs = bd.wave_speeds(E, NU, RHO)
    assert vs == pytest.approx(100.0, rel=1e-14)  # G = 20000, rho = 2
    assert vp / vs == pytest.approx(math.sqrt(2 * (1 - NU) / (1 - 2 * NU)), rel=1e-14)
    with pytest.raises(ValueError, match="nu"):
        bd.wave_speeds(E, 0.5, RHO)


def skewed_face(m):
    """A planar quadrilateral (no parallelogram) in the plane x + y + z = 1."""
    m.model("basic", "-ndm", 3, "-ndf", 3)
    e1 = np.array([1.0, -1.0, 0.0]) / math.sqrt(2)
    e2 = np.array([1.0, 1.0, -2.0]) / math.sqrt(6)
    origin = np.array([1.0, 1.0, 1.0]) / 3
    corners = [(0.0, 0.0), (2.0, 0.0), (1.5, 1.0), (0.2, 1.4)]
    for tag, (a, b) in enumerate(corners, start=1):
        m.node(tag, *(origin + a * e1 + b * e2))
    area = 0.5 * abs(sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(corners, corners[1:] + corners[:1])))
    return [1, 2, 3, 4], area, np.cross(e1, e2)


def test_face_areas_sum_to_the_face_and_follow_the_shape_functions(model):
    face, area, normal = skewed_face(model)
    areas = bd.face_areas(model, [face])
    total = sum(areas.values())
    assert np.allclose(total, area * normal, rtol=0, atol=1e-13 * area)
    # For a rectangle every node gets a quarter.
    model.wipe()
    model.model("basic", "-ndm", 3, "-ndf", 3)
    for tag, (x, y) in enumerate([(0, 0), (3, 0), (3, 2), (0, 2)], start=1):
        model.node(tag, float(x), float(y), 0.0)
    areas = bd.face_areas(model, [[1, 2, 3, 4]])
    for a in areas.values():
        assert np.allclose(a, [0.0, 0.0, 1.5], atol=1e-14)


def test_dashpots_on_an_inclined_face_damp_normal_and_tangential_velocity_at_their_rates(model):
    """Four free nodes of mass m, held only by the face's dashpots, start with
    velocity (1, 0.3, -0.2) and the matching acceleration. Newmark average acceleration is the trapezoidal
    rule: v_{n+1} = (m + C dt/2)^-1 (m - C dt/2) v_n with the node's tensor
    C = rho A_a (Vp n n^T + Vs (I - n n^T)), A_a its tributary area. Checked
    to 1e-12 over 20 steps: the normal part decays at rho Vp A_a / m and
    the tangential at rho Vs A_a / m."""
    face, _, normal = skewed_face(model)
    vp, vs = bd.wave_speeds(E, NU, RHO)
    m, dt, v0 = 20.0, 0.002, np.array([1.0, 0.3, -0.2])
    for n in face:
        model.mass(n, m, m, m)
    made = bd.viscous_boundary(model, bd.Tags(node=10, element=10, material=10), RHO, vp, vs, faces=[face])
    assert len(made["nodes"]) == 4 and len(made["elements"]) == 4
    assert set(made["dashpots"]) == set(face)
    areas = bd.face_areas(model, [face])
    model.constraints("Plain")
    model.numberer("Plain")
    model.system("FullGeneral")
    model.test("NormDispIncr", 1e-14, 10)
    model.algorithm("Linear")
    model.integrator("Newmark", 0.5, 0.25)
    model.analysis("Transient")
    # Newmark takes the acceleration it is given (OpenSees does no initial
    # solve): start in equilibrium, a0 = -C v0 / m.
    for n in face:
        a0 = -made["tensors"][n] @ v0 / m
        for dof in (1, 2, 3):
            model.setNodeVel(n, dof, v0[dof - 1], "-commit")
            model.setNodeAccel(n, dof, a0[dof - 1], "-commit")
    assert model.analyze(20, dt) == 0
    for n in face:
        a = float(np.linalg.norm(areas[n]))
        C = RHO * a * (vp * np.outer(normal, normal) + vs * (np.eye(3) - np.outer(normal, normal)))
        assert np.allclose(made["tensors"][n], C, rtol=1e-13, atol=1e-13 * np.max(C))
        step = np.linalg.solve(m * np.eye(3) + 0.5 * dt * C, m * np.eye(3) - 0.5 * dt * C)
        expected = np.linalg.matrix_power(step, 20) @ v0
        v = np.array(model.nodeVel(n))
        assert np.allclose(v, expected, rtol=0, atol=1e-12), (v, expected)
        # the normal part decayed more than the tangential one
        assert abs(v @ normal) / abs(v0 @ normal) < np.linalg.norm(v - (v @ normal) * normal) / np.linalg.norm(
            v0 - (v0 @ normal) * normal)


def test_area_vectors_and_faces_give_the_same_dashpots(model):
    face, _, _ = skewed_face(model)
    areas = bd.face_areas(model, [face])
    by_face = bd._dashpot_tensors(model, [face], None, RHO, 2.0, 1.0)
    by_node = bd._dashpot_tensors(model, None, areas, RHO, 2.0, 1.0)
    for n in face:
        assert np.allclose(by_face[n], by_node[n], rtol=1e-14)
    # A node on two perpendicular faces gets the sum of both tensors.
    both = bd._dashpot_tensors(model, None, {1: [0.0, 0.0, 2.0], 2: [0.0, 0.0, 2.0]}, 1.0, 3.0, 1.0)
    corner = bd._dashpot_tensors(model, None, {1: [0.0, 0.0, 2.0]}, 1.0, 3.0, 1.0)
    assert np.allclose(both[1], np.diag([2.0, 2.0, 6.0]))
    assert np.allclose(corner[1], both[1])


def base_reactions(model, record, **kw):
    """Four base nodes on a 2 x 2 face under compliant_base (rock rho 2.4,
    Vp 800, Vs 400, dt 0.1), fixed so that the input load comes back as the
    reaction at t = 0.25 (a spring on a node of its own keeps the static
    system from being empty). Returns (what compliant_base made, reactions)."""
    model.model("basic", "-ndm", 3, "-ndf", 3)
    for tag, (x, y) in enumerate([(0, 0), (2, 0), (2, 2), (0, 2)], start=1):
        model.node(tag, float(x), float(y), 0.0)
    made = bd.compliant_base(model, bd.Tags(node=10, element=10, material=10, series=3, pattern=4),
                             2.4, 800.0, 400.0, record, 0.1, faces=[[1, 2, 3, 4]], **kw)
    for n in (1, 2, 3, 4):
        model.fix(n, 1, 1, 1)
    model.node(98, 5.0, 5.0, 0.0)
    model.node(99, 5.0, 5.0, 0.0)
    model.fix(98, 1, 1, 1)
    model.uniaxialMaterial("Elastic", 1, 1.0)
    model.element("zeroLength", 1, 98, 99, "-mat", 1, 1, 1, "-dir", 1, 2, 3)
    model.setTime(0.25)
    model.constraints("Plain")
    model.numberer("Plain")
    model.system("FullGeneral")
    model.test("NormDispIncr", 1e-12, 10)
    model.algorithm("Linear")
    model.integrator("LoadControl", 0.0)
    model.analysis("Static")
    assert model.analyze(1) == 0
    model.reactions()
    return made, [np.array(model.nodeReaction(n)) for n in (1, 2, 3, 4)]


def test_compliant_base_force_is_the_rock_dashpot_times_the_outcrop_velocity(model):
    """The input load on a base node of area A_a = 1 is rho_r Vs_r A_a v_out(t)
    along a horizontal direction; an acceleration record is integrated by the
    trapezoidal rule: at t = 0.25, between the samples 0.25 and 0.5, v_out = 0.375."""
    acc = np.array([0.0, 1.0, 3.0, 2.0, 0.0])
    made, reactions = base_reactions(model, acc, direction=2, kind="accel")
    assert np.allclose(made["velocity"][2], [0.0, 0.05, 0.25, 0.5, 0.6])
    assert made["series"] == {2: 3} and made["pattern"] == {2: 4}
    for r in reactions:
        assert np.allclose(r, [0.0, -2.4 * 400.0 * 0.375, 0.0], rtol=1e-12)


def test_compliant_base_with_two_components_and_the_incident_wave(model):
    """record={1: vx, 3: vz} with incident=True: 2 rho_r Vs_r A_a vx along x and,
    the vertical being normal to the base (a P wave), 2 rho_r Vp_r A_a vz."""
    vx, vz = [0.0, 1.0, 2.0, 2.0], [0.0, -1.0, 0.0, 4.0]
    made, reactions = base_reactions(model, {1: vx, 3: vz}, incident=True)
    assert made["series"] == {1: 3, 3: 4} and made["pattern"] == {1: 4, 3: 5}
    for r in reactions:  # at t = 0.25: vx = 2, vz = 2
        assert np.allclose(r, [-2 * 2.4 * 400.0 * 2.0, 0.0, -2 * 2.4 * 800.0 * 2.0], rtol=1e-12)


def test_brick_faces_find_the_faces_of_a_side(model):
    """A 2 x 2 x 1 block of bricks 1.5 x 2 x 3: two faces on x = 0 and on y = 4,
    four on z = 0; their areas add up to the side's."""
    model.model("basic", "-ndm", 3, "-ndf", 3)
    model.nDMaterial("ElasticIsotropic", 1, E, NU, RHO)

    def tag(i, j, k):
        return 1 + i + 3 * j + 9 * k

    for k in range(2):
        for j in range(3):
            for i in range(3):
                model.node(tag(i, j, k), 1.5 * i, 2.0 * j, 3.0 * k)
    elements = []
    for j in range(2):
        for i in range(2):
            e = 1 + i + 2 * j
            model.element("stdBrick", e, tag(i, j, 0), tag(i + 1, j, 0), tag(i + 1, j + 1, 0), tag(i, j + 1, 0),
                          tag(i, j, 1), tag(i + 1, j, 1), tag(i + 1, j + 1, 1), tag(i, j + 1, 1), 1)
            elements.append(e)
    for axis, value, count, area in ((1, 0.0, 2, 4.0 * 3.0), (2, 4.0, 2, 3.0 * 3.0), (3, 0.0, 4, 3.0 * 4.0)):
        faces = bd.brick_faces(model, elements, axis, value)
        assert len(faces) == count
        total = sum(bd.face_areas(model, faces).values())
        assert abs(abs(total[axis - 1]) - area) < 1e-12 and np.linalg.norm(total) == pytest.approx(area)
    assert bd.brick_faces(model, elements, 1, 0.7) == []


def test_ties(model):
    model.model("basic", "-ndm", 3, "-ndf", 3)
    for tag, (x, y, z) in enumerate([(0, 0, 0), (1, 0, 0), (0, 0, 1), (1, 0, 1), (1, 0, 1.0000001)], start=1):
        model.node(tag, float(x), float(y), z)
    levels = bd.tie_levels(model, [1, 2, 3, 4], dofs=(1, 2))
    assert levels == {0.0: 1, 1.0: 3}
    model.wipe()
    model.model("basic", "-ndm", 3, "-ndf", 3)
    for tag, (x, z) in enumerate([(0, 0), (0, 1), (5, 0), (5, 1)], start=1):
        model.node(tag, float(x), 0.0, float(z))
    assert bd.tie_periodic(model, [1, 2], [4, 3]) == [(1, 3), (2, 4)]
    with pytest.raises(ValueError, match="both sides"):
        bd.tie_periodic(model, [], [3])


def test_bad_input(model):
    model.model("basic", "-ndm", 3, "-ndf", 3)
    model.node(1, 0.0, 0.0, 0.0)
    tags = bd.Tags()
    with pytest.raises(ValueError, match="4 nodes"):
        bd.viscous_boundary(model, tags, 1.0, 2.0, 1.0, faces=[[1, 1, 1]])
    with pytest.raises(ValueError, match="no faces"):
        bd.viscous_boundary(model, tags, 1.0, 2.0, 1.0)
    with pytest.raises(beamsolid.OpenSeesError, match="nodeCoord"):
        bd.viscous_boundary(model, tags, 1.0, 2.0, 1.0, faces=[[1, 2, 3, 4]])
    with pytest.raises(ValueError, match="kind"):
        bd.compliant_base(model, tags, 1.0, 2.0, 1.0, [0.0], 0.1, kind="disp", nodes={1: [0, 0, 1]})
    with pytest.raises(ValueError, match="viscous_boundary: need rho"):
        bd.viscous_boundary(model, tags, 1.0, 0.0, 0.0, nodes={1: [0, 0, 1]})
    with pytest.raises(ValueError, match="compliant_base: need dt"):
        bd.compliant_base(model, tags, 1.0, 2.0, 1.0, [0.0], 0.1, nodes={1: [0, 0, 1]})
    with pytest.raises(ValueError, match="width"):
        bd.free_field_column(model, tags, [0.0, 1.0], [1], 0.0, 0.0, 0.0)
    with pytest.raises(ValueError, match="heights"):
        bd.free_field_column(model, tags, [1.0, 0.0], [1], 0.0, 0.0, 10.0)
    with pytest.raises(ValueError, match="no free-field node"):
        bd.attach_free_field(model, {5.0: 1}, [1])

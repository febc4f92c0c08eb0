"""zeroLengthContact3D in a model: a ring of 16 elements (dir 0, radial) between
an inner node ring (constrained, tied to a centre node by equalDOF: a rigid
pile section) and an outer ring (retained, fixed soil) of radius R - delta0, so
that every contact starts with the penetration delta0 (a confinement). The
centre is pushed along x by u in one step (DisplacementControl): the front
contacts press harder, the flanks slide, the back ones open.

Closed form for node k at angle theta (e_r, e_theta; n = -e_r):
    N = Kn max(delta0 + u cos theta, 0),  slip s1 = -u sin theta,
    F_t = min(Kt u |sin theta|, mu N + c) (zero when open),
    push P = sum_k N cos theta + F_t |sin theta|   (one step: no path dependence).
Tolerances: P and the statuses against the closed form (1e-10 relative), the
outer ring's reactions balance the push (1e-10 of P; y and z to 1e-10 of P),
the elements' forces on the inner ring add up to P (1e-10). The PVD recorder
draws the 16 contacts as vertices at the retained nodes with their status,
gap, normal and friction forces (to the written precision).
"""
import math
import os

import meshio
import numpy as np
import pytest

R, DELTA0 = 0.5, 1e-3
KN, KT, MU, C = 1e5, 2e4, 0.4, 1.0
N_RING = 16
U = 2e-3
CENTRE, INNER, OUTER = 1, 100, 200


def angles():
    return [(k + 0.5) * 2.0 * math.pi / N_RING for k in range(N_RING)]


def build_ring(m):
    m.model("basic", "-ndm", 3, "-ndf", 3)
    m.node(CENTRE, 0.0, 0.0, 0.0)
    for k, th in enumerate(angles()):
        c, s = math.cos(th), math.sin(th)
        m.node(INNER + k, R * c, R * s, 0.0)
        m.node(OUTER + k, (R - DELTA0) * c, (R - DELTA0) * s, 0.0)
        m.fix(OUTER + k, 1, 1, 1)
        m.equalDOF(CENTRE, INNER + k, 1, 2, 3)
        m.element("zeroLengthContact3D", 1 + k, INNER + k, OUTER + k, KN, KT, MU, C, 0)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.load(CENTRE, 1.0, 0.0, 0.0)
    m.constraints("Transformation")
    m.numberer("Plain")
    m.system("UmfPack")
    m.test("NormDispIncr", 1e-14, 30)
    m.algorithm("Newton")
    m.integrator("DisplacementControl", CENTRE, 1, U)
    m.analysis("Static")


def closed_form():
    push, status = 0.0, []
    for th in angles():
        N = KN * max(DELTA0 + U * math.cos(th), 0.0)
        if N == 0.0:
            status.append(0)
            continue
        demand, limit = KT * U * abs(math.sin(th)), MU * N + C
        status.append(1 if demand <= limit else 2)
        push += N * math.cos(th) + min(demand, limit) * abs(math.sin(th))
    return push, status


def test_ring_of_contacts_transmits_a_lateral_push(model):
    build_ring(model)
    assert model.analyze(1) == 0
    P = model.getLoadFactor(1)
    expected, expected_status = closed_form()
    assert set(expected_status) == {0, 1, 2}  # the case has open, sticking and sliding contacts
    assert P == pytest.approx(expected, rel=1e-10)
    assert [model.eleResponse(1 + k, "status")[0] for k in range(N_RING)] == expected_status
    assert model.nodeDisp(CENTRE, 1) == pytest.approx(U, rel=1e-14)
    assert abs(model.nodeDisp(CENTRE, 2)) < 1e-12 * U and abs(model.nodeDisp(CENTRE, 3)) < 1e-12 * U
    model.reactions()
    reaction = np.sum([model.nodeReaction(OUTER + k) for k in range(N_RING)], axis=0)
    assert reaction[0] == pytest.approx(-P, rel=1e-10)
    assert np.all(np.abs(reaction[1:]) < 1e-10 * P)
    on_inner = np.sum([model.eleResponse(1 + k, "force")[:3] for k in range(N_RING)], axis=0)
    assert on_inner[0] == pytest.approx(P, rel=1e-10)
    assert np.all(np.abs(on_inner[1:]) < 1e-10 * P)
    # Each element: the force on the retained node is the normal plus the friction part.
    for k, th in enumerate(angles()):
        N = model.eleResponse(1 + k, "normalForce")[0]
        assert N == pytest.approx(KN * max(DELTA0 + U * math.cos(th), 0.0), rel=1e-10, abs=1e-9)
        normal = np.array(model.eleResponse(1 + k, "normal"))
        assert normal == pytest.approx([-math.cos(th), -math.sin(th), 0.0], abs=1e-15)
        whole = np.array(model.eleResponse(1 + k, "contactForce"))
        friction = np.array(model.eleResponse(1 + k, "frictionForce"))
        assert whole == pytest.approx(-N * normal + friction, abs=1e-9 * P)


def test_pvd_recorder_draws_the_contacts_as_vertices(model, tmp_path):
    build_ring(model)
    name = str(tmp_path / "ring")
    model.recorder("PVD", name, "-precision", 12)
    assert model.analyze(1) == 0
    grid = meshio.read(os.path.join(name, "ring_000000.vtu"))
    assert [(b.type, len(b.data)) for b in grid.cells] == [("vertex", N_RING)]
    tags = grid.point_data["nodeTag"].ravel().tolist()
    assert tags == [OUTER + k for k in range(N_RING)]  # the retained nodes only
    assert [tags[c[0]] for c in grid.cells[0].data] == [OUTER + k for k in range(N_RING)]
    data = {key: np.concatenate(blocks) for key, blocks in grid.cell_data.items()}
    assert data["elementKind"].ravel().tolist() == [4] * N_RING
    elements = [1 + k for k in range(N_RING)]
    assert data["contactStatus"].ravel().tolist() == [model.eleResponse(t, "status")[0] for t in elements]
    rtol = 1e-11
    for array, response in (("contactGap", "gap"), ("contactNormalForce", "normalForce"),
                            ("contactFrictionForce", "frictionForce"), ("contactNormal", "normal")):
        expected = np.array([model.eleResponse(t, response) for t in elements]).reshape(data[array].shape)
        np.testing.assert_allclose(data[array], expected, rtol=rtol, atol=rtol * np.max(np.abs(expected)))

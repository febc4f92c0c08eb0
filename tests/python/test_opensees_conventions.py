"""Conventions BeamSolid shares with OpenSeesPy that are easy to get wrong:
eleType names and element response layouts. The expected values were read
from OpenSeesPy 3.7.1 (tests/python/oracle_scripts has the scripts) and are
checked here against statics so that they hold without the oracle too.
"""
import math

import pytest


def _frame_and_solids(ops):
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    ops.node(1, 0.0, 0.0, 0.0)
    ops.node(2, 0.0, 0.0, 3.0)
    ops.geomTransf("Linear", 1, 1.0, 0.0, 0.0)
    ops.element("elasticBeamColumn", 1, 1, 2, 0.5, 30e6, 12e6, 0.04, 0.02, 0.02, 1)
    ops.uniaxialMaterial("Elastic", 1, 100.0)
    ops.element("truss", 2, 1, 2, 1.0, 1)
    ops.element("corotTruss", 3, 1, 2, 1.0, 1)
    ops.element("zeroLength", 4, 1, 2, "-mat", 1, "-dir", 1)
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    corners = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
    for i, x in enumerate(corners, start=10):
        ops.node(i, *x)
    ops.nDMaterial("ElasticIsotropic", 1, 1000.0, 0.25, 1.5)
    ops.element("stdBrick", 5, *range(10, 18), 1)


def test_ele_type_answers_opensees_class_names(ops):
    _frame_and_solids(ops)
    names = [ops.eleType(t) for t in range(1, 6)]
    assert names == ["ElasticBeam3d", "Truss", "CorotTruss", "ZeroLength", "Brick"]


def _static(ops):
    ops.system("UmfPack")
    ops.constraints("Transformation")
    ops.numberer("Plain")
    ops.test("NormDispIncr", 1e-12, 10)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", 1.0)
    ops.analysis("Static")
    assert ops.analyze(1) == 0


@pytest.mark.parametrize("ndf", [3, 6])
def test_truss_local_force_has_ndf_values_per_node(ops, ndf):
    # A bar from (0,0,0) to (2,1,0.5) pulled along x at node 2, y and z held.
    # OpenSees' truss localForce: [-N, 0.., N, 0..] (ndf per node);
    # corotTruss: [N]; basicStiffness A E / L. Tolerance 1e-12.
    P, A, E = 1.5, 2.0, 1000.0
    L = math.sqrt(2.0 ** 2 + 1.0 + 0.25)
    ops.model("basic", "-ndm", 3, "-ndf", ndf)
    ops.node(1, 0.0, 0.0, 0.0)
    ops.node(2, 2.0, 1.0, 0.5)
    ops.node(3, 0.0, 0.0, 0.0)
    ops.fix(1, *([1] * ndf))
    ops.fix(3, *([1] * ndf))
    ops.fix(2, *([0, 1, 1] + [1] * (ndf - 3)))
    ops.uniaxialMaterial("Elastic", 1, E)
    ops.element("truss", 1, 1, 2, A, 1)
    ops.element("corotTruss", 2, 3, 2, A, 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, P, *([0.0] * (ndf - 1)))
    _static(ops)
    n = ops.eleResponse(1, "axialForce")[0]
    assert n > 0.0
    local = ops.eleResponse(1, "localForce")
    expected = [0.0] * (2 * ndf)
    expected[0], expected[ndf] = -n, n
    assert local == pytest.approx(expected, abs=1e-12 * n)
    assert ops.eleResponse(1, "localForces") == local
    assert ops.eleResponse(1, "basicStiffness") == pytest.approx([A * E / L], rel=1e-12)
    # The corotational bar (beside it, sharing the load) reports N alone.
    corot = ops.eleResponse(2, "axialForce")
    assert corot[0] > 0.0
    assert ops.eleResponse(2, "localForces") == corot


def test_beam_basic_stiffness_and_local_axes(ops):
    # Basic stiffness (row by row): EA/L, 4EI/L and 2EI/L per bending plane,
    # GJ/L. Local axes: x along the member, y = vecxz x x, z = x x y.
    A, E, G, J, Iy, Iz = 0.5, 30e6, 12e6, 0.04, 0.02, 0.03
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    ops.node(1, 0.0, 0.0, 0.0)
    ops.node(2, 1.0, 0.5, 3.0)
    ops.geomTransf("Linear", 1, 1.0, 0.0, 0.0)
    ops.element("elasticBeamColumn", 1, 1, 2, A, E, G, J, Iy, Iz, 1)
    L = math.sqrt(1.0 + 0.25 + 9.0)
    k = [[0.0] * 6 for _ in range(6)]
    k[0][0] = E * A / L
    k[1][1] = k[2][2] = 4 * E * Iz / L
    k[1][2] = k[2][1] = 2 * E * Iz / L
    k[3][3] = k[4][4] = 4 * E * Iy / L
    k[3][4] = k[4][3] = 2 * E * Iy / L
    k[5][5] = G * J / L
    assert ops.eleResponse(1, "basicStiffness") == pytest.approx([v for row in k for v in row], rel=1e-12)
    x = [1.0 / L, 0.5 / L, 3.0 / L]
    y = [0.0, -x[2], x[1]]  # (1, 0, 0) x x
    ny = math.hypot(y[1], y[2])
    y = [v / ny for v in y]
    z = [x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]]
    for name, axis in (("xaxis", x), ("yaxis", y), ("zaxis", z)):
        assert ops.eleResponse(1, name) == pytest.approx(axis, abs=1e-14)


def test_zero_length_basic_stiffness_and_axes(ops):
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    ops.node(1, 0.0, 0.0, 0.0)
    ops.node(2, 0.0, 0.0, 0.0)
    ops.uniaxialMaterial("Elastic", 1, 100.0)
    ops.uniaxialMaterial("Elastic", 2, 50.0)
    ops.element("zeroLength", 1, 1, 2, "-mat", 1, 2, "-dir", 1, 3, "-orient", 0.0, 2.0, 0.0, -1.0, 0.0, 0.0)
    assert ops.eleResponse(1, "basicStiffness") == [100.0, 0.0, 0.0, 50.0]
    # x = (0, 1, 0), yp = (-1, 0, 0): z = x cross yp = (0, 0, 1), y = z cross x = (-1, 0, 0).
    assert ops.eleResponse(1, "xaxis") == pytest.approx([0.0, 1.0, 0.0], abs=1e-15)
    assert ops.eleResponse(1, "yaxis") == pytest.approx([-1.0, 0.0, 0.0], abs=1e-15)
    assert ops.eleResponse(1, "zaxis") == pytest.approx([0.0, 0.0, 1.0], abs=1e-15)


def test_response_component_names_are_opensees(ops, tmp_path):
    # The <ResponseType> names OpenSees writes in XML recorder headers.
    import re

    ops.model("basic", "-ndm", 3, "-ndf", 6)
    ops.node(1, 0.0, 0.0, 0.0)
    ops.node(2, 0.0, 0.0, 3.0)
    ops.geomTransf("Linear", 1, 1.0, 0.0, 0.0)
    ops.element("elasticBeamColumn", 1, 1, 2, 0.5, 30e6, 12e6, 0.04, 0.02, 0.02, 1)
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    ops.node(3, 0.0, 0.0, 0.0)
    ops.node(4, 1.0, 0.0, 0.0)
    ops.uniaxialMaterial("Elastic", 1, 100.0)
    ops.element("truss", 2, 3, 4, 1.0, 1)
    ops.element("zeroLength", 3, 3, 4, "-mat", 1, 1, "-dir", 1, 3)
    cases = {
        (1, "basicDeformations"): ["eps", "theta11", "theta12", "theta21", "theta22", "phi"],
        (2, "force"): ["P1_1", "P1_2", "P1_3", "P2_1", "P2_2", "P2_3"],
        (2, "material 1 stressStrain"): ["sig11", "eps11"],
        (3, "basicForce"): ["P1", "P2"],
        (3, "material 2 tangent"): ["C11"],
    }
    files = {}
    for (tag, response), names in cases.items():
        files[(tag, response)] = str(tmp_path / f"{tag}_{response.replace(' ', '_')}.xml")
        ops.recorder("Element", "-xml", files[(tag, response)], "-ele", tag, *response.split())
    ops.record()
    ops.wipe()
    for key, names in cases.items():
        with open(files[key]) as f:
            assert re.findall(r"<ResponseType>(.*?)</ResponseType>", f.read()) == names, key

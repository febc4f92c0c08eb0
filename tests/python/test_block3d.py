"""block3D: the corner form meshes a box into a regular grid (coordinates
exact), the 27-point form reproduces a quadratic geometry exactly (a top
face bulged as a parabola), tags run x, then y, then z from startNode and
startEle, and bad input names block3D and the argument."""
import pytest

from beamsolid.model import Model

CORNERS = [1, 0, 0, 0, 2, 4, 0, 0, 3, 4, 3, 0, 4, 0, 3, 0, 5, 0, 0, 2, 6, 4, 0, 2, 7, 4, 3, 2, 8, 0, 3, 2]


def _model():
    ops = Model()
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    ops.nDMaterial("ElasticIsotropic", 1, 1000.0, 0.25)
    return ops


def test_corner_form_is_a_regular_grid():
    ops = _model()
    ops.block3D(4, 3, 2, 10, 100, "stdBrick", 1, *[float(v) for v in CORNERS])
    tags = ops.getNodeTags()
    assert tags == list(range(10, 10 + 5 * 4 * 3))
    for k in range(3):
        for j in range(4):
            for i in range(5):
                tag = 10 + i + 5 * j + 20 * k
                assert ops.nodeCoord(tag) == pytest.approx([1.0 * i, 1.0 * j, 1.0 * k], abs=1e-14)
    assert ops.getEleTags() == list(range(100, 100 + 24))
    # Element (i, j, k) = (1, 2, 1): bottom face counterclockwise from node (1, 2, 1), then the top face.
    n1 = 10 + 1 + 5 * 2 + 20 * 1
    assert ops.eleNodes(100 + 1 + 4 * 2 + 12 * 1) == [n1, n1 + 1, n1 + 6, n1 + 5, n1 + 20, n1 + 21, n1 + 26, n1 + 25]


def test_27_point_form_reproduces_a_quadratic_top():
    # Top face z = 2 + 0.5 (1 - ((x - 2)/2)^2): its edge midpoints and centre
    # lie on the bulge, the vertical edges and faces halfway.
    def top(x):
        return 2.0 + 0.5 * (1.0 - ((x - 2.0) / 2.0) ** 2)

    pts = [float(v) for v in CORNERS]
    pts += [18, 2.0, 0.0, top(2.0), 20, 2.0, 3.0, top(2.0), 22, 2.0, 1.5, top(2.0),
            23, 2.0, 0.0, top(2.0) / 2, 25, 2.0, 3.0, top(2.0) / 2, 27, 2.0, 1.5, top(2.0) / 2]
    ops = _model()
    ops.block3D(4, 2, 2, 1, 1, "stdBrick", 1, *pts)
    for k in range(3):
        for j in range(3):
            for i in range(5):
                x, y = float(i), 1.5 * j
                expected = [x, y, top(x) * k / 2.0]
                assert ops.nodeCoord(1 + i + 5 * j + 15 * k) == pytest.approx(expected, rel=1e-14, abs=1e-14)


@pytest.mark.parametrize("args, message", [
    ((2, 2, 2, 1, 1, "stdBrick", 1, *CORNERS[:28]), "block3D.*block point 8 is missing"),
    ((0, 2, 2, 1, 1, "stdBrick", 1, *CORNERS), "block3D.*numX"),
    ((2, 2, 2, 1, 1, "quad", 1, *CORNERS), "block3D.*'quad' is not an eight-node brick"),
    ((2, 2, 2, 1, 1, "stdBrick", 1, *CORNERS, 1, 0.0, 0.0, 0.0), "block3D.*at most once"),
    ((2, 2, 2, 1, 1, "stdBrick", 1, *CORNERS, 28, 0.0, 0.0, 0.0), "block3D.*1 to 27"),
    ((2, 2, 2, 1, 1, "stdBrick", 9, *CORNERS), "block3D.*9"),
])
def test_bad_input_names_block3d(args, message):
    ops = _model()
    with pytest.raises(RuntimeError, match=message):
        ops.block3D(*args)


def test_block3d_needs_a_3d_model():
    ops = Model()
    ops.model("basic", "-ndm", 2, "-ndf", 2)
    with pytest.raises(RuntimeError, match="block3D.*ndm 3"):
        ops.block3D(1, 1, 1, 1, 1, "stdBrick", 1, *CORNERS)

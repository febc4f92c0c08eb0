"""block2D: structured quad meshes over a block of corner (and optional edge
and centre) points, as OpenSees' block2D.

Closed forms: a straight block's nodes are the bilinear map of the corners;
a block with an edge point has that edge's nodes on the parabola through its
three points; tags run in local x first. A plane-stress patch under uniform
tension gives the exact uniform stress and displacement (1e-12).
"""
import numpy as np
import pytest

import beamsolid


def quad_block(ops, nx, ny, points, start_node=1, start_ele=1):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 2)
    ops.nDMaterial("ElasticIsotropic", 1, 1000.0, 0.25)
    ops.block2D(nx, ny, start_node, start_ele, "quad", 2.0, "PlaneStress", 1, *points)


def test_straight_block_is_the_bilinear_map_numbered_in_x_first(ops):
    corners = np.array([[1.0, 0.5], [9.0, 1.5], [8.0, 7.0], [0.0, 6.0]])
    nx, ny = 4, 3
    quad_block(ops, nx, ny, [v for k, c in enumerate(corners, 1) for v in (k, *c)], start_node=10, start_ele=100)
    assert sorted(ops.getNodeTags()) == list(range(10, 10 + (nx + 1) * (ny + 1)))
    assert sorted(ops.getEleTags()) == list(range(100, 100 + nx * ny))
    for j in range(ny + 1):
        for i in range(nx + 1):
            s, t = i / nx, j / ny
            expected = (1 - s) * (1 - t) * corners[0] + s * (1 - t) * corners[1] + s * t * corners[2] + (1 - s) * t * corners[3]
            assert ops.nodeCoord(10 + j * (nx + 1) + i) == pytest.approx(expected, abs=1e-13)
    for j in range(ny):
        for i in range(nx):
            n1 = 10 + j * (nx + 1) + i
            assert ops.eleNodes(100 + j * nx + i) == [n1, n1 + 1, n1 + 1 + nx + 1, n1 + nx + 1]


def test_edge_point_curves_its_edge_along_the_parabola(ops):
    # Edge 1-2 from (0, 0) to (8, 0) through point 5 at (4, -2): y = -2 (1 - s^2), s in [-1, 1].
    quad_block(ops, 4, 2, [1, 0.0, 0.0, 2, 8.0, 0.0, 3, 8.0, 4.0, 4, 0.0, 4.0, 5, 4.0, -2.0])
    for i in range(5):
        s = -1.0 + 2.0 * i / 4
        assert ops.nodeCoord(1 + i) == pytest.approx([4.0 + 4.0 * s, -2.0 * (1.0 - s * s)], abs=1e-13)
    # The opposite edge stays straight.
    for i in range(5):
        assert ops.nodeCoord(11 + i) == pytest.approx([2.0 * i, 4.0], abs=1e-13)


def test_uniform_tension_patch_is_exact(ops):
    E, nu, t, sigma = 1000.0, 0.25, 2.0, 3.0
    L, H = 10.0, 4.0
    quad_block(ops, 5, 3, [1, 0.0, 0.0, 2, L, 0.0, 3, L, H, 4, 0.0, H, 9, 4.0, 2.5])
    nx = 5
    for j in range(4):
        left = 1 + j * (nx + 1)
        ops.fix(left, 1, 1 if j == 0 else 0)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    # Consistent nodal forces of sigma on the right edge (straight, 3 equal segments).
    for j in range(4):
        share = 0.5 if j in (0, 3) else 1.0
        ops.load((j + 1) * (nx + 1), share * sigma * t * H / 3, 0.0)
    ops.analysis("Static")
    assert ops.analyze(1) == 0
    for n in ops.getNodeTags():
        x, y = ops.nodeCoord(n)
        assert ops.nodeDisp(n) == pytest.approx([sigma / E * x, -nu * sigma / E * y], abs=1e-12)
    for e in ops.getEleTags():
        s = np.reshape(ops.eleResponse(e, "stresses"), (-1, 3))
        assert s == pytest.approx(np.tile([sigma, 0.0, 0.0], (4, 1)), abs=1e-11)


@pytest.mark.parametrize(
    "args, fragment",
    [
        ((2, 2, 1, 1, "quad", 1.0, "PlaneStress", 1, 1, 0, 0, 2, 1, 0, 3, 1, 1), "block point 4 is missing"),
        ((2, 2, 1, 1, "truss", 1.0, 1, 1, 0, 0), "not a quadrilateral"),
        ((2, 2, 1, 1, "quad", 1.0, "PlaneStress", 1, 12, 0, 0), "block point"),
        ((0, 2, 1, 1, "quad", 1.0, "PlaneStress", 1, 1, 0, 0), "numX"),
        ((2, 2, 1, 1, "quad", 1.0, "PlaneStress", 7, 1, 0, 0, 2, 1, 0, 3, 1, 1, 4, 0, 1), "block2D"),
    ],
)
def test_bad_block2d_input_names_the_command(ops, args, fragment):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 2)
    ops.nDMaterial("ElasticIsotropic", 1, 1000.0, 0.25)
    with pytest.raises(beamsolid.OpenSeesError, match=fragment):
        ops.block2D(*args)


@pytest.mark.parametrize("name", ["shell", "Shell", "shellMITC4", "ShellMITC4"])
def test_shell_block_under_membrane_tension_is_exact(ops, name):
    # OpenSees' other names of ShellMITC4 ('shell' in OpenSeesPy's
    # PlanarShearWall test) mesh the same element: a membrane patch in the
    # x-y plane pulled by sigma gives u = sigma x / E, v = -nu sigma y / E.
    E, nu, t, sigma, L, H, nx, ny = 3000.0, 0.2, 12.0, 2.0, 120.0, 60.0, 4, 2
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    ops.section("ElasticMembranePlateSection", 1, E, nu, t, 0.0)
    ops.block2D(nx, ny, 1, 1, name, 1, 1, 0.0, 0.0, 0.0, 2, L, 0.0, 0.0, 3, L, H, 0.0, 4, 0.0, H, 0.0)
    for n in ops.getNodeTags():
        x = ops.nodeCoord(n, 1)
        ops.fix(n, 1 if x == 0.0 else 0, 1 if n == 1 else 0, 1, 1, 1, 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    for j in range(ny + 1):
        share = 0.5 if j in (0, ny) else 1.0
        ops.load((j + 1) * (nx + 1), share * sigma * t * H / ny, 0.0, 0.0, 0.0, 0.0, 0.0)
    ops.analysis("Static")
    assert ops.analyze(1) == 0
    assert ops.eleType(1) == "ShellMITC4"
    for n in ops.getNodeTags():
        x, y, _ = ops.nodeCoord(n)
        assert ops.nodeDisp(n)[:2] == pytest.approx([sigma / E * x, -nu * sigma / E * y], abs=1e-12)

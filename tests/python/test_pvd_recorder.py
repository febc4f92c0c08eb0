"""The PVD (ParaView) recorder: every value read back from the .vtu files with
meshio is compared with what nodeDisp, nodeReaction and eleResponse give at
that step, to the written precision; the .pvd must list every step with its
time and be a complete XML document after every step.
"""
import math
import os
import xml.etree.ElementTree as ET

import meshio
import numpy as np
import pytest

import beamsolid
from beamsolid import mesh

R = 0.3  # pile radius
N_THETA, N_RADIAL, N_Z = 8, 2, 2
PILE_Z = [0.5, -0.5, -1.5, -2.5]  # beam nodes between the soil levels 0, -1, -2
PILE_NODES = [1, 2, 3, 4]
PILE_ELEMENTS = [1, 2, 3]


def build_pile_in_soil(ops):
    """A pile (three elasticBeamColumns on the axis) in a donut of stdBricks
    with one BeamContact3D per pile-surface soil node, as in
    tests/cpp/test_BeamContactAnalysis.cpp."""
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    for tag, z in zip(PILE_NODES, PILE_Z):
        ops.node(tag, 0.0, 0.0, z)
        ops.fix(tag, 0, 0, 0, 0, 0, 1)  # no twist
    ops.fix(PILE_NODES[0], 0, 0, 1, 0, 0, 0)  # head held in z while confining
    ops.geomTransf("Linear", 1, 1.0, 0.0, 0.0)
    area, inertia = math.pi * R**2, math.pi * R**4 / 4.0
    for k in PILE_ELEMENTS:
        ops.element("elasticBeamColumn", k, k, k + 1, area, 3e7, 1.2e7, 2 * inertia, inertia, inertia, 1)

    ops.model("basic", "-ndm", 3, "-ndf", 3)
    ops.nDMaterial("ElasticIsotropic", 2, 1e4, 0.3)
    ops.nDMaterial("ContactMaterial3D", 1, 0.4, 2e4, 0.0, 0.0)
    soil = mesh.donut(ops, inner_radius=R, outer_radius=1.0, z_top=0.0, z_bottom=-2.0, n_theta=N_THETA,
                      n_radial=N_RADIAL, n_z=N_Z, radial_ratio=1.0, material_tag=2, first_node=100,
                      first_element=100)
    contacts, multipliers = [], []
    for s_node in soil.inner_nodes:
        z = ops.nodeCoord(s_node, 3)
        segment = next(k for k in PILE_ELEMENTS if PILE_Z[k - 1] > z > PILE_Z[k])
        ops.node(1000 + s_node, 0.0, 0.0, z)
        ops.element("BeamContact3D", 1000 + s_node, segment, segment + 1, s_node, 1000 + s_node, R, 1, 1,
                    1e-8, 1e-8)
        contacts.append(1000 + s_node)
        multipliers.append(1000 + s_node)
    return soil, contacts, multipliers


def run_stages(ops, soil, on_step):
    """Stage 1 (frictionless): the outer ring squeezed inwards in 2 steps.
    Stage 2 (friction on, time goes on from 1): the pile head pulled up a
    little and pushed sideways in 4 steps, hard enough that contacts stick,
    slide and open. on_step() is called after every step."""
    ops.updateMaterialStage("-material", 1, "-stage", 0)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    squeeze = 2e-3
    for tag in soil.outer_nodes:
        x, y, _ = ops.nodeCoord(tag)
        r = math.hypot(x, y)
        ops.sp(tag, 1, -squeeze * x / r)
        ops.sp(tag, 2, -squeeze * y / r)
        ops.sp(tag, 3, 0.0)
    ops.constraints("Transformation")
    ops.numberer("RCM")
    ops.system("UmfPack")
    ops.test("NormUnbalance", 1e-9, 25)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", 0.5)
    ops.analysis("Static")
    for _ in range(2):
        assert ops.analyze(1) == 0
        on_step()
    ops.loadConst()
    ops.updateMaterialStage("-material", 1, "-stage", 1)
    ops.remove("sp", PILE_NODES[0], 3)
    ops.timeSeries("Path", 2, "-time", 1.0, 2.0, "-values", 0.0, 1.0)
    ops.pattern("Plain", 2, 2)
    ops.sp(PILE_NODES[0], 3, 0.002)
    ops.load(PILE_NODES[0], 300.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    ops.integrator("LoadControl", 0.05)
    for _ in range(4):
        assert ops.analyze(1) == 0
        on_step()


def read_collection(path):
    """(time, file) of every DataSet of a .pvd, which must parse as XML."""
    root = ET.parse(path).getroot()
    assert root.tag == "VTKFile" and root.attrib["type"] == "Collection"
    datasets = root.find("Collection").findall("DataSet")
    return [(float(d.attrib["timestep"]), d.attrib["file"]) for d in datasets]


def cell_arrays(grid):
    """Cell data as one array per name over all cells, in file order."""
    return {name: np.concatenate(blocks) for name, blocks in grid.cell_data.items()}


def close(actual, expected, rtol):
    """Equal to rtol of each value, and to 1e-3 rtol of the largest value
    (for components that are round-off in a sum)."""
    actual, expected = np.asarray(actual, float), np.asarray(expected, float)
    scale = np.max(np.abs(expected)) if expected.size else 0.0
    np.testing.assert_allclose(actual, expected, rtol=rtol, atol=1e-3 * rtol * scale)


# VTK_HEXAHEDRON's corners in its parametric space (r, s, t) in [0, 1]^3:
# the bottom face 0-3 counterclockwise about +t, the top face 4-7 above it.
VTK_HEX_CORNERS = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0],
                            [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]], float)


def vtk_hex_jacobians(x):
    """det(dx/d(r,s,t)) at the 2x2x2 Gauss points of VTK's trilinear hexahedron
    with corner coordinates x (8 x 3), and the weights (summing to 1)."""
    g = 0.5 + np.array([-1.0, 1.0]) / (2.0 * math.sqrt(3.0))
    dets = []
    for r in g:
        for s in g:
            for t in g:
                p = np.array([r, s, t])
                grads = np.empty((8, 3))
                for a, c in enumerate(VTK_HEX_CORNERS):
                    f = np.where(c == 1, p, 1.0 - p)  # the linear factor in each direction
                    df = np.where(c == 1, 1.0, -1.0)
                    grads[a] = [df[0] * f[1] * f[2], f[0] * df[1] * f[2], f[0] * f[1] * df[2]]
                dets.append(np.linalg.det(x.T @ grads))
    return np.array(dets), np.full(8, 1.0 / 8.0)


def test_pvd_recorder_writes_what_the_model_holds(ops, tmp_path):
    soil, contacts, multipliers = build_pile_in_soil(ops)
    name = str(tmp_path / "pile")
    precision = 12
    rtol = 10.0 ** (1 - precision)  # %.12g rounds to 5e-12 relative
    ops.recorder("PVD", name, "-precision", precision, "-time", "disp", "reaction", "incrDisp")
    # The OpenSees name 'vtk' with -dT: records only once the time has moved on by 0.45.
    thinned = str(tmp_path / "thin" / "pile_dt")
    ops.recorder("vtk", thinned, "-dT", 0.12)

    bricks = list(soil.elements)
    expected_cells = bricks + PILE_ELEMENTS + contacts
    # Every node a cell uses (soil, pile); the contacts' multiplier nodes are used by no cell.
    expected_points = sorted(set(PILE_NODES) | set(soil.nodes.values()))
    all_nodes = ops.getNodeTags()
    assert set(multipliers) <= set(all_nodes) and not set(multipliers) & set(expected_points)

    times = []
    previous = {tag: np.zeros(len(ops.nodeDisp(tag))) for tag in all_nodes}
    statuses = set()
    rotations = []  # largest pile rotation of each step
    history = []  # displacements of every node at each step

    def check_step():
        times.append(ops.getTime())
        listed = read_collection(name + ".pvd")  # complete XML after every step
        assert [t for t, _ in listed] == pytest.approx(times, rel=1e-14)
        assert [f for _, f in listed] == [f"pile/pile_{k:06d}.vtu" for k in range(len(times))]
        grid = meshio.read(os.path.join(os.path.dirname(name), listed[-1][1]))
        assert grid.field_data["TimeValue"] == pytest.approx(times[-1], rel=1e-14)

        # Points: the used nodes by tag, at their reference coordinates.
        point_tags = grid.point_data["nodeTag"].ravel().tolist()
        assert point_tags == expected_points
        close(grid.points, [ops.nodeCoord(t) for t in point_tags], rtol)
        ops.reactions()
        disp = {t: np.array(ops.nodeDisp(t)) for t in point_tags}
        reaction = {t: np.array(ops.nodeReaction(t)) for t in point_tags}
        six = lambda v: np.concatenate([v, np.zeros(6 - len(v))]) if len(v) < 6 else v  # noqa: E731
        close(grid.point_data["displacement"], [disp[t][:3] for t in point_tags], rtol)
        close(grid.point_data["rotation"], [six(disp[t])[3:6] for t in point_tags], rtol)
        close(grid.point_data["reaction"], [reaction[t][:3] for t in point_tags], rtol)
        close(grid.point_data["reactionMoment"], [six(reaction[t])[3:6] for t in point_tags], rtol)
        close(grid.point_data["incrDisp"], [(disp[t] - previous[t])[:3] for t in point_tags], rtol)
        close(grid.point_data["incrRotation"], [six(disp[t] - previous[t])[3:6] for t in point_tags], rtol)
        for t in all_nodes:
            previous[t] = np.array(ops.nodeDisp(t))
        history.append({t: ops.nodeDisp(t) for t in all_nodes})
        rotations.append(max(np.linalg.norm(disp[t][3:6]) for t in PILE_NODES))

        # Cells: hexahedra, then lines, then vertices, each by element tag.
        assert [(b.type, len(b.data)) for b in grid.cells] == [
            ("hexahedron", len(bricks)), ("line", len(PILE_ELEMENTS)), ("vertex", len(contacts))]
        data = cell_arrays(grid)
        assert data["elementTag"].ravel().tolist() == expected_cells
        assert data["elementKind"].ravel().tolist() == [1] * len(bricks) + [2] * 3 + [4] * len(contacts)
        index = {tag: i for i, tag in enumerate(point_tags)}
        for tag, conn in zip(bricks, grid.cells[0].data):
            assert [point_tags[i] for i in conn] == ops.eleNodes(tag)
        for tag, conn in zip(PILE_ELEMENTS, grid.cells[1].data):
            assert [point_tags[i] for i in conn] == ops.eleNodes(tag)
        for tag, conn in zip(contacts, grid.cells[2].data):
            assert conn.tolist() == [index[ops.eleNodes(tag)[2]]]  # the soil node

        nb, nl = len(bricks), len(PILE_ELEMENTS)
        for what, array in (("stresses", "stress"), ("strains", "strain")):
            mean = [np.mean(np.reshape(ops.eleResponse(t, what), (8, 6)), axis=0) for t in bricks]
            close(data[array][:nb], mean, rtol)
            assert not data[array][nb:].any()
        close(data["localForce"][nb:nb + nl], [ops.eleResponse(t, "localForce") for t in PILE_ELEMENTS], rtol)
        assert not data["localForce"][:nb].any() and not data["localForce"][nb + nl:].any()
        c = slice(nb + nl, None)
        status = [ops.eleResponse(t, "status")[0] for t in contacts]
        statuses.update(status)
        assert data["contactStatus"][c].ravel().tolist() == status
        close(data["contactGap"][c].ravel(), [ops.eleResponse(t, "gap")[0] for t in contacts], rtol)
        close(data["contactNormalForce"][c].ravel(), [ops.eleResponse(t, "forcescalar")[0] for t in contacts],
              rtol)
        close(data["contactFrictionForce"][c], [ops.eleResponse(t, "soilFrictionForce") for t in contacts], rtol)
        close(data["contactNormal"][c], [ops.eleResponse(t, "normal") for t in contacts], rtol)
        for array in ("contactStatus", "contactGap", "contactNormalForce", "contactFrictionForce", "contactNormal"):
            assert not data[array][:nb + nl].any()

    run_stages(ops, soil, check_step)
    assert len(times) == 6
    assert statuses == {0.0, 1.0, 2.0}  # separated, sticking and sliding contacts were written
    assert rotations[-1] > 1e-4  # the pile bends: rotations are not trivially zero

    # The hexahedra are right-handed in VTK's own corner convention, and
    # their volumes add up to the faceted annulus (ri = R, ro = 1, h = 2).
    grid = meshio.read(str(tmp_path / "pile" / "pile_000000.vtu"))
    volume = 0.0
    for conn in grid.cells[0].data:
        dets, weights = vtk_hex_jacobians(grid.points[conn])
        assert (dets > 0).all()
        volume += weights @ dets
    n = N_THETA
    assert volume == pytest.approx(0.5 * n * math.sin(2 * math.pi / n) * (1.0 - R**2) * 2.0, rel=1e-12)

    # -dT 0.12: a record once the time reached the last recorded + 0.12
    # (times 0.5, 1, 1.05, 1.1, 1.15, 1.2: records at 0.5, 1, 1.15).
    recorded, last = [], None
    for k, t in enumerate(times):
        if last is None or t - (last + 0.12) >= -1e-5 * 0.12:
            recorded.append(k)
            last = t
    assert len(recorded) == 3
    listed = read_collection(thinned + ".pvd")
    assert [t for t, _ in listed] == pytest.approx([times[k] for k in recorded], rel=1e-14)
    for (_, file), k in zip(listed, recorded):
        grid = meshio.read(os.path.join(os.path.dirname(thinned), file))
        tags = grid.point_data["nodeTag"].ravel().tolist()
        # Default precision 10: %.10g rounds to 5e-10 relative.
        close(grid.point_data["displacement"], [history[k][t][:3] for t in tags], 1e-9)
        assert "reaction" not in grid.point_data and "incrDisp" not in grid.point_data


def test_trusses_are_lines_and_zero_length_is_left_out(ops, tmp_path):
    """truss (localForce ndf values per end) and corotTruss (N alone) map to the
    12 end forces; a zeroLength and the node only it uses are not written."""
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    ops.node(1, 0.0, 0.0, 0.0)
    ops.node(2, 2.0, 0.0, 0.0)
    ops.node(3, 2.0, 1.5, 0.0)
    ops.node(4, 2.0, 1.5, 0.0)  # spring to ground, used by the zeroLength only
    ops.fix(1, 1, 1, 1)
    ops.fix(4, 1, 1, 1)
    ops.fix(2, 0, 0, 1)
    ops.fix(3, 0, 0, 1)
    ops.uniaxialMaterial("Elastic", 1, 2e5)
    ops.element("truss", 1, 1, 2, 1.0, 1)
    ops.element("corotTruss", 2, 2, 3, 1.0, 1)
    ops.element("truss", 3, 1, 3, 1.0, 1)
    ops.element("zeroLength", 4, 3, 4, "-mat", 1, "-dir", 1)
    ops.recorder("PVD", str(tmp_path / "trusses"))
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, 10.0, -5.0, 0.0)
    ops.integrator("LoadControl", 0.5)
    ops.analysis("Static")
    assert ops.analyze(2) == 0

    listed = read_collection(str(tmp_path / "trusses.pvd"))
    assert [t for t, _ in listed] == pytest.approx([0.5, 1.0], rel=1e-14)
    grid = meshio.read(str(tmp_path / listed[-1][1]))
    assert grid.point_data["nodeTag"].ravel().tolist() == [1, 2, 3]
    assert [(b.type, len(b.data)) for b in grid.cells] == [("line", 3)]
    data = cell_arrays(grid)
    assert data["elementTag"].ravel().tolist() == [1, 2, 3]
    assert data["elementKind"].ravel().tolist() == [3, 3, 3]
    assert "stress" not in data and "contactGap" not in data
    rtol = 1e-9  # default precision 10
    for row, tag in zip(data["localForce"], [1, 2, 3]):
        axial = ops.eleResponse(tag, "basicForce")[0]
        assert abs(axial) > 1.0
        expected = np.zeros(12)
        expected[0], expected[6] = -axial, axial
        close(row, expected, rtol)
    # The truss' own localForce (ndf 3 per end) lands in components 0-2 and 6-8.
    close(data["localForce"][0][[0, 1, 2, 6, 7, 8]], ops.eleResponse(1, "localForce"), rtol)
    close(grid.point_data["rotation"], np.zeros((3, 3)), rtol)


def test_pvd_is_complete_after_wipe_and_record_writes_the_current_state(ops, tmp_path):
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    ops.nDMaterial("ElasticIsotropic", 1, 1000.0, 0.25)
    corners = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
    for k, xyz in enumerate(corners, start=1):
        ops.node(k, *map(float, xyz))
    ops.element("stdBrick", 1, *range(1, 9), 1)
    name = str(tmp_path / "cube.pvd")  # a name ending in .pvd is the collection itself
    ops.recorder("PVD", name, "eigen", 1, "vel")
    ops.record()  # the initial state at time 0
    listed = read_collection(name)
    assert listed == [(0.0, "cube/cube_000000.vtu")]
    grid = meshio.read(str(tmp_path / "cube" / "cube_000000.vtu"))
    assert [(b.type, len(b.data)) for b in grid.cells] == [("hexahedron", 1)]
    assert not grid.point_data["displacement"].any()
    assert {"eigen_1", "eigenRotation_1", "velocity", "angularVelocity"} <= set(grid.point_data)
    ops.wipe()
    assert read_collection(name) == listed


@pytest.mark.parametrize("args, message", [
    ((), "name"),
    (("out", "-precision", 0), "precision"),
    (("out", "-dT", -1.0), "dT"),
    (("out", "stresses"), "response"),
    (("out", "eigen", 0), "mode"),
    (("out", "-nodes", 1), "option"),
    ((".",), "name"),
])
def test_bad_pvd_recorder_arguments_name_the_argument(ops, tmp_path, args, message):
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    cwd = os.getcwd()
    os.chdir(tmp_path)
    try:
        with pytest.raises(beamsolid.OpenSeesError, match=f"recorder PVD.*{message}"):
            ops.recorder("PVD", *args)
    finally:
        os.chdir(cwd)


def test_quads_are_vtk_quads_next_to_lines(ops, tmp_path):
    """A 2D block2D mesh of quads with a truss and a beam: quads are VTK_QUAD
    cells (elementKind 5) before the lines; their stress and strain are the
    means of eleResponse 'stresses'/'strains' over the 4 Gauss points in
    the xx, yy, xy slots; the quad's node order is kept."""
    ops.model("basic", "-ndm", 2, "-ndf", 2)
    ops.nDMaterial("ElasticIsotropic", 1, 1000.0, 0.25)
    ops.block2D(2, 1, 1, 1, "quad", 1.0, "PlaneStress", 1, 1, 0.0, 0.0, 2, 2.0, 0.0, 3, 2.0, 1.0, 4, 0.0, 1.0)
    ops.node(7, 3.0, 0.5)
    ops.uniaxialMaterial("Elastic", 2, 500.0)
    ops.element("truss", 10, 3, 7, 0.5, 2)
    ops.element("truss", 11, 6, 7, 0.5, 2)
    ops.fix(1, 1, 1)
    ops.fix(4, 1, 1)
    ops.recorder("PVD", str(tmp_path / "quads"))
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(7, 3.0, -2.0)
    ops.integrator("LoadControl", 1.0)
    ops.analysis("Static")
    assert ops.analyze(1) == 0
    listed = read_collection(str(tmp_path / "quads.pvd"))
    grid = meshio.read(str(tmp_path / listed[-1][1]))
    assert [(b.type, len(b.data)) for b in grid.cells] == [("quad", 2), ("line", 2)]
    tags = grid.point_data["nodeTag"].ravel().tolist()
    assert tags == [1, 2, 3, 4, 5, 6, 7]
    for cell, ele in zip(grid.cells[0].data, (1, 2)):
        assert [tags[i] for i in cell] == ops.eleNodes(ele)
    data = cell_arrays(grid)
    assert data["elementKind"].ravel().tolist() == [5, 5, 3, 3]
    rtol = 1e-9
    for row, ele in zip(data["stress"][:2], (1, 2)):
        s = np.array(ops.eleResponse(ele, "stresses")).reshape(4, 3).mean(axis=0)
        assert np.abs(s).max() > 0.1
        close(row, [s[0], s[1], 0.0, s[2], 0.0, 0.0], rtol)
    for row, ele in zip(data["strain"][:2], (1, 2)):
        e = np.array(ops.eleResponse(ele, "strains")).reshape(4, 3).mean(axis=0)
        close(row, [e[0], e[1], 0.0, e[2], 0.0, 0.0], rtol)
    close(data["stress"][2:], np.zeros((2, 6)), rtol)


def test_shells_are_vtk_quads_with_their_section_forces(ops, tmp_path):
    """ShellMITC4 elements are VTK_QUAD cells (elementKind 6) ahead of the
    beams; 'shellForce' is the mean over the 4 Gauss points of eleResponse
    'stresses' (p11 p22 p12 m11 m22 m12 q1 q2), 0 on other cells."""
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    for k, (x, z) in enumerate([(0, 0), (2, 0), (4, 0), (0, 3), (2, 3.2), (4, 3)]):
        ops.node(k + 1, float(x), 0.0, float(z))
    for n in (1, 2, 3):
        ops.fix(n, 1, 1, 1, 1, 1, 1)
    ops.section("ElasticMembranePlateSection", 1, 3.0e4, 0.2, 0.2)
    ops.element("ShellMITC4", 1, 1, 2, 5, 4, 1)
    ops.element("ShellMITC4", 2, 2, 3, 6, 5, 1)
    ops.geomTransf("Linear", 1, 0.0, 0.0, 1.0)
    ops.element("elasticBeamColumn", 3, 4, 5, 0.1, 3.0e4, 1.25e4, 1e-3, 2e-3, 3e-3, 1)
    ops.recorder("PVD", str(tmp_path / "shells"))
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(5, 10.0, 3.0, -4.0, 0.0, 0.0, 1.0)
    ops.integrator("LoadControl", 1.0)
    ops.analysis("Static")
    assert ops.analyze(1) == 0
    listed = read_collection(str(tmp_path / "shells.pvd"))
    grid = meshio.read(str(tmp_path / listed[-1][1]))
    assert [(b.type, len(b.data)) for b in grid.cells] == [("quad", 2), ("line", 1)]
    tags = grid.point_data["nodeTag"].ravel().tolist()
    for cell, ele in zip(grid.cells[0].data, (1, 2)):
        assert [tags[i] for i in cell] == ops.eleNodes(ele)
    data = cell_arrays(grid)
    assert data["elementKind"].ravel().tolist() == [6, 6, 2]
    for row, ele in zip(data["shellForce"][:2], (1, 2)):
        s = np.array(ops.eleResponse(ele, "stresses")).reshape(4, 8).mean(axis=0)
        assert np.abs(s).max() > 0.1
        close(row, s, 1e-9)
    close(data["shellForce"][2], np.zeros(8), 1e-9)


def test_triangles_and_tetrahedra_are_vtk_triangles_and_tetras(ops, tmp_path):
    """tri31 cells are VTK_TRIANGLE (elementKind 5) and FourNodeTetrahedron
    cells VTK_TETRA (elementKind 1), with their node order and the one
    point's stress in the xx, yy, (zz,) xy slots."""
    ops.model("basic", "-ndm", 2, "-ndf", 2)
    for tag, (x, y) in enumerate([(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)], start=1):
        ops.node(tag, x, y)
    ops.nDMaterial("ElasticIsotropic", 1, 1000.0, 0.25)
    ops.element("tri31", 1, 1, 2, 3, 1.0, "PlaneStress", 1)
    ops.element("tri31", 2, 1, 3, 4, 1.0, "PlaneStress", 1)
    ops.fix(1, 1, 1)
    ops.fix(4, 1, 0)
    ops.recorder("PVD", str(tmp_path / "tris"))
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(3, 3.0, -2.0)
    ops.integrator("LoadControl", 1.0)
    ops.analysis("Static")
    assert ops.analyze(1) == 0
    listed = read_collection(str(tmp_path / "tris.pvd"))
    grid = meshio.read(str(tmp_path / listed[-1][1]))
    assert [(b.type, len(b.data)) for b in grid.cells] == [("triangle", 2)]
    tags = grid.point_data["nodeTag"].ravel().tolist()
    for cell, ele in zip(grid.cells[0].data, (1, 2)):
        assert [tags[i] for i in cell] == ops.eleNodes(ele)
    data = cell_arrays(grid)
    assert data["elementKind"].ravel().tolist() == [5, 5]
    for row, ele in zip(data["stress"], (1, 2)):
        s = ops.eleResponse(ele, "stresses")
        assert np.abs(s).max() > 0.1
        close(row, [s[0], s[1], 0.0, s[2], 0.0, 0.0], 1e-9)
    ops.wipe()

    ops.model("basic", "-ndm", 3, "-ndf", 3)
    for tag, x in enumerate([(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)], start=1):
        ops.node(tag, *x)
    ops.nDMaterial("ElasticIsotropic", 1, 1000.0, 0.25)
    ops.element("FourNodeTetrahedron", 1, 1, 2, 3, 4, 1)
    ops.fix(1, 1, 1, 1)
    ops.fix(2, 0, 1, 1)
    ops.fix(3, 0, 0, 1)
    ops.recorder("PVD", str(tmp_path / "tet"))
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(4, 1.0, 2.0, 3.0)
    ops.integrator("LoadControl", 1.0)
    ops.analysis("Static")
    assert ops.analyze(1) == 0
    listed = read_collection(str(tmp_path / "tet.pvd"))
    grid = meshio.read(str(tmp_path / listed[-1][1]))
    assert [(b.type, len(b.data)) for b in grid.cells] == [("tetra", 1)]
    tags = grid.point_data["nodeTag"].ravel().tolist()
    assert [tags[i] for i in grid.cells[0].data[0]] == [1, 2, 3, 4]
    data = cell_arrays(grid)
    assert data["elementKind"].ravel().tolist() == [1]
    close(data["stress"][0], ops.eleResponse(1, "stresses"), 1e-9)

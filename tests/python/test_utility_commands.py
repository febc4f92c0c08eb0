"""The small commands of OpenSeesPy scripts, and the rigid diaphragm and 2D rigid links.

Answers are checked against closed forms (a rigid floor on cantilever columns under a
force and a torque; a 2D cantilever with a rigid arm; a bar whose node is moved) or
against the full responses they are shortcuts of.
"""
import pytest

import beamsolid


@pytest.fixture
def m():
    model = beamsolid.Model()
    yield model
    model.wipe()


def static(m, constraints="Transformation", steps=1):
    m.constraints(constraints)
    m.numberer("RCM")
    m.system("UmfPack")
    m.test("NormDispIncr", 1e-12, 10)
    m.algorithm("Newton")
    m.integrator("LoadControl", 1.0 / steps)
    m.analysis("Static")
    return m.analyze(steps)


def test_version_and_the_single_process_stand_ins(m):
    assert m.version() == beamsolid.__version__
    assert m.getNP() == 1 and m.getPID() == 0
    assert m.barrier() is None


def test_node_bounds_pad_to_3d(m):
    m.model("basic", "-ndm", 2, "-ndf", 3)
    for tag, (x, y) in enumerate([(0.0, -1.0), (4.0, 3.0), (-2.0, 0.5)], start=1):
        m.node(tag, x, y)
    assert m.nodeBounds() == [-2.0, -1.0, 0.0, 4.0, 3.0, 0.0]


def frame_3d(m, integration=True):
    """A 3D cantilever of one forceBeamColumn (Lobatto, 3 points) on an elastic section."""
    m.model("basic", "-ndm", 3, "-ndf", 6)
    m.node(1, 0.0, 0.0, 0.0)
    m.node(2, 0.0, 0.0, 2.0)
    m.fix(1, 1, 1, 1, 1, 1, 1)
    m.geomTransf("Linear", 1, 1.0, 0.0, 0.0)
    m.section("Elastic", 1, 200e6, 0.01, 8e-5, 6e-5, 80e6, 1e-4)
    m.beamIntegration("Lobatto", 1, 1, 3)
    m.element("forceBeamColumn", 1, 1, 2, 1, 1)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.load(2, 3.0, 0.0, -10.0, 0.0, 0.0, 0.0)


def test_basic_and_section_shortcuts_equal_the_element_responses(m):
    frame_3d(m)
    assert static(m) == 0
    for name in ("basicForce", "basicDeformation", "basicStiffness"):
        assert getattr(m, name)(1) == m.eleResponse(1, name)
    # Lobatto with 3 points on L = 2: sections at 0, 1, 2 with weights L/6, 4L/6, L/6.
    assert m.sectionLocation(1) == pytest.approx([0.0, 1.0, 2.0], abs=1e-14)
    assert m.sectionLocation(1, 2) == pytest.approx(1.0, abs=1e-14)
    assert m.sectionWeight(1) == pytest.approx([1 / 3, 4 / 3, 1 / 3], rel=1e-14)
    for k in (1, 2, 3):
        assert m.sectionForce(1, k) == m.eleResponse(1, "section", k, "force")
        assert m.sectionDeformation(1, k) == m.eleResponse(1, "section", k, "deformation")
        # Axial force -10 in every section (compression), P of the section's resultants first.
        assert m.sectionForce(1, k, 1) == pytest.approx(-10.0, rel=1e-12)
    # The base moment of the 3 kN tip load: M = 3 * 2 = 6 (one of the bending resultants).
    base = m.sectionForce(1, 1)
    assert max(abs(v) for v in base[1:3]) == pytest.approx(6.0, rel=1e-10)
    with pytest.raises(beamsolid.OpenSeesError, match=r"sectionForce 1: .*dof 9 is out of range 1..4"):
        m.sectionForce(1, 1, 9)
    with pytest.raises(beamsolid.OpenSeesError, match=r"sectionLocation 1: secNum 4 is out of range 1..3"):
        m.sectionLocation(1, 4)


def test_constraint_queries(m):
    m.model("basic", "-ndm", 2, "-ndf", 3)
    for tag in range(1, 6):
        m.node(tag, float(tag), 0.0)
    m.fix(1, 1, 1, 1)
    m.fix(4, 0, 1, 0)
    m.equalDOF(2, 3, 1)
    m.rigidLink("beam", 2, 5)
    assert m.getFixedNodes() == [1, 4]
    assert m.getFixedDOFs(1) == [1, 2, 3] and m.getFixedDOFs(4) == [2] and m.getFixedDOFs(2) == []
    assert m.getConstrainedNodes() == [3, 5] and m.getConstrainedNodes(2) == [3, 5]
    assert m.getRetainedNodes() == [2] and m.getRetainedNodes(5) == [2]
    with pytest.raises(beamsolid.OpenSeesError, match="getFixedDOFs 9: node 9 does not exist"):
        m.getFixedDOFs(9)


def bar(m, length=2.0):
    m.model("basic", "-ndm", 2, "-ndf", 2)
    m.node(1, 0.0, 0.0)
    m.node(2, length, 0.0)
    m.fix(1, 1, 1)
    m.fix(2, 0, 1)
    m.uniaxialMaterial("Elastic", 1, 1000.0)
    m.element("Truss", 1, 1, 2, 0.5, 1)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.load(2, 10.0, 0.0)


def test_node_response_codes(m):
    bar(m)
    assert static(m) == 0
    m.reactions()
    assert m.nodeResponse(2, 1, 1) == m.nodeDisp(2, 1) == pytest.approx(10.0 * 2.0 / (1000.0 * 0.5))
    assert m.nodeResponse(1, 1, 6) == m.nodeReaction(1, 1) == pytest.approx(-10.0)
    assert m.nodeResponse(2, 1, 7) == m.nodeUnbalance(2, 1)
    with pytest.raises(beamsolid.OpenSeesError, match="responseID 5 is not one of"):
        m.nodeResponse(2, 1, 5)


def test_set_node_coord_moves_the_node_and_its_elements_follow(m):
    """u = F L / (E A): moving node 2 from x = 2 to x = 3 makes the bar 1.5 times softer."""
    bar(m)
    m.setNodeCoord(2, 1, 3.0)
    assert m.nodeCoord(2) == [3.0, 0.0]
    assert static(m) == 0
    assert m.nodeDisp(2, 1) == pytest.approx(10.0 * 3.0 / (1000.0 * 0.5), rel=1e-12)
    with pytest.raises(beamsolid.OpenSeesError, match="setNodeCoord 2: dim 3 is out of range 1..2"):
        m.setNodeCoord(2, 3, 1.0)
    with pytest.raises(beamsolid.OpenSeesError, match="setNodeCoord 2: element 1 cannot take the new position"):
        m.setNodeCoord(2, 1, 0.0)  # a zero-length truss
    assert m.nodeCoord(2) == [3.0, 0.0]  # refused: the node stays where it was


def test_set_node_disp_with_and_without_commit(m):
    bar(m)
    m.setNodeDisp(2, 1, 0.25)
    assert m.nodeDisp(2) == [0.25, 0.0]
    m.setNodeDisp(2, 1, 0.5, "-commit")
    m.setNodeVel(2, 2, -1.0)
    assert m.nodeVel(2) == [0.0, -1.0]
    assert m.nodeDisp(2, 1) == 0.5


def test_log_file_keeps_the_warnings(m, tmp_path, capfd):
    log = tmp_path / "log.txt"
    m.logFile(str(log), "-noEcho")
    try:
        m.model("basic", "-ndm", 1, "-ndf", 1)
        m.node(1, 0.0)
        m.node(2, 1.0)
        m.uniaxialMaterial("Elastic", 1, 100.0)
        m.element("Truss", 1, 1, 2, 1.0, 1)  # no support: singular
        m.timeSeries("Linear", 1)
        m.pattern("Plain", 1, 1)
        m.load(2, 1.0)
        assert static(m) == -3
    finally:
        beamsolid._beamsolid.close_log_file()
    assert "WARNING analyze:" in log.read_text()
    assert "WARNING analyze:" not in capfd.readouterr().err
    with pytest.raises(beamsolid.OpenSeesError, match="logFile: cannot open"):
        m.logFile(str(tmp_path / "no" / "such" / "dir.txt"))


def test_timer(m, capfd):
    with pytest.raises(beamsolid.OpenSeesError, match="stop: no timer running"):
        m.stop()
    m.start()
    m.stop()
    assert "TIME(sec) Real:" in capfd.readouterr().err


# --- rigidDiaphragm ------------------------------------------------------------------------
H, E, G = 3.0, 200e6, 80e6
A, IY, IZ, J = 0.01, 5e-5, 5e-5, 2e-5
COLUMNS = [(-2.0, -1.5), (2.0, -1.5), (2.0, 1.5), (-2.0, 1.5), (0.5, 0.0)]


def diaphragm_floor(m, perp=3):
    """Cantilever columns (fixed base) at COLUMNS, their tops joined by a rigid floor in
    the plane normal to axis `perp` (the columns run along it), retained node at the
    origin of the floor; the retained node's out-of-plane dofs are fixed."""
    m.model("basic", "-ndm", 3, "-ndf", 6)

    def xyz(a, b, h):  # in-plane coordinates (a, b) on the axes after perp, height h along it
        p = perp - 1
        c = [0.0, 0.0, 0.0]
        c[(p + 1) % 3], c[(p + 2) % 3], c[p] = a, b, h
        return c

    m.node(100, *xyz(0.0, 0.0, H))
    fixity = [0] * 6
    fixity[perp - 1] = 1                        # out-of-plane translation
    fixity[3 + (perp % 3)] = 1                  # and the two in-plane-axis rotations
    fixity[3 + ((perp + 1) % 3)] = 1
    m.fix(100, *fixity)
    vecxz = [0.0, 0.0, 0.0]
    vecxz[perp % 3] = 1.0
    m.geomTransf("Linear", 1, *vecxz)
    tops = []
    for k, (a, b) in enumerate(COLUMNS):
        base, top = 2 * k + 1, 2 * k + 2
        m.node(base, *xyz(a, b, 0.0))
        m.node(top, *xyz(a, b, H))
        m.fix(base, 1, 1, 1, 1, 1, 1)
        m.element("elasticBeamColumn", k + 1, base, top, A, E, G, J, IY, IZ, 1)
        tops.append(top)
    m.rigidDiaphragm(perp, 100, *tops)
    return tops


@pytest.mark.parametrize("perp", [1, 2, 3])
def test_a_rigid_floor_on_cantilever_columns(m, perp):
    """Each column top moves with the floor: (u - theta b_i, v + theta a_i) in the plane,
    its own rotations about the in-plane axes free, so it is a cantilever of lateral
    stiffness k = 3EI/H^3 and torsional stiffness GJ/H. A floor force F gives
    u = F / (n k); a floor torque T gives theta = T / (k sum r_i^2 + n GJ/H), the column
    layout's centroid being off the origin (0.1, 0) coupling a little: solved here by hand
    as a 3x3 system."""
    import numpy as np

    tops = diaphragm_floor(m, perp)
    k = 3.0 * E * IY / H**3
    kt = G * J / H
    a = np.array([c[0] for c in COLUMNS])
    b = np.array([c[1] for c in COLUMNS])
    n = len(COLUMNS)
    # Floor stiffness on (u, v, theta): sum of k [1, 0, -b; 0, 1, a; -b, a, a^2 + b^2] + kt on theta.
    K = k * np.array([[n, 0.0, -b.sum()], [0.0, n, a.sum()], [-b.sum(), a.sum(), (a * a + b * b).sum()]])
    K[2, 2] += n * kt
    F, T = 12.0, 30.0
    expected = np.linalg.solve(K, [F, 0.0, T])
    load = [0.0] * 6
    load[perp % 3] = F
    load[3 + perp - 1] = T
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.load(100, *load)
    assert static(m) == 0
    floor = m.nodeDisp(100)
    i, j, p = perp % 3, (perp + 1) % 3, perp - 1
    got = [floor[i], floor[j], floor[3 + p]]
    assert got == pytest.approx(list(expected), rel=1e-9)
    for top, (ai, bi) in zip(tops, COLUMNS):
        u = m.nodeDisp(top)
        assert u[i] == pytest.approx(got[0] - got[2] * bi, rel=1e-9, abs=1e-15)
        assert u[j] == pytest.approx(got[1] + got[2] * ai, rel=1e-9, abs=1e-15)
        assert u[3 + p] == pytest.approx(got[2], rel=1e-9)


def test_rigid_diaphragm_bad_input(m):
    m.model("basic", "-ndm", 3, "-ndf", 6)
    m.node(1, 0.0, 0.0, 3.0)
    m.node(2, 1.0, 0.0, 3.0)
    m.node(3, 1.0, 0.0, 3.5)
    with pytest.raises(beamsolid.OpenSeesError, match="rigidDiaphragm 4 1: perpDirn must be 1, 2 or 3"):
        m.rigidDiaphragm(4, 1, 2)
    with pytest.raises(beamsolid.OpenSeesError, match="node 3 is not in the diaphragm's plane"):
        m.rigidDiaphragm(3, 1, 2, 3)
    with pytest.raises(beamsolid.OpenSeesError, match="node 7 does not exist"):
        m.rigidDiaphragm(3, 1, 7)
    with pytest.raises(beamsolid.OpenSeesError, match="missing the constrained node tags"):
        m.rigidDiaphragm(3, 1)


def test_rigid_link_beam_in_2d(m):
    """A 2D cantilever (L, EI, EA) with a rigid arm of length d at its tip, pulled down by P
    at the arm's end: the tip carries P and the moment P d, so
    v = P L^3/3EI + P d L^2/2EI, theta = P L^2/2EI + P d L/EI; the arm end moves
    v + theta d downward. Then the bar form: the arm end follows the tip's translations."""
    L, d, P, EI = 3.0, 0.8, 5.0, 200e6 * 1e-4
    for kind in ("beam", "bar"):
        m.wipe()
        m.model("basic", "-ndm", 2, "-ndf", 3)
        m.node(1, 0.0, 0.0)
        m.node(2, L, 0.0)
        m.node(3, L + d, 0.0)
        m.fix(1, 1, 1, 1)
        m.geomTransf("Linear", 1)
        m.element("elasticBeamColumn", 1, 1, 2, 0.01, 200e6, 1e-4, 1)
        m.rigidLink(kind, 2, 3)
        if kind == "bar":
            m.fix(3, 0, 0, 1)  # its rotation is its own
        m.timeSeries("Linear", 1)
        m.pattern("Plain", 1, 1)
        m.load(3, 0.0, -P, 0.0)
        assert static(m) == 0
        moment = P * d if kind == "beam" else 0.0
        v = P * L**3 / (3 * EI) + moment * L**2 / (2 * EI)
        theta = P * L**2 / (2 * EI) + moment * L / EI
        tip, arm = m.nodeDisp(2), m.nodeDisp(3)
        assert tip[1] == pytest.approx(-v, rel=1e-12)
        assert tip[2] == pytest.approx(-theta, rel=1e-12)
        if kind == "beam":
            assert arm[1] == pytest.approx(-(v + theta * d), rel=1e-12)
            assert arm[2] == pytest.approx(-theta, rel=1e-12)
        else:
            assert arm[:2] == pytest.approx(tip[:2], rel=1e-12)
    with pytest.raises(beamsolid.OpenSeesError, match="a rigid beam link needs a 2D or 3D model"):
        m.wipe()
        m.model("basic", "-ndm", 1, "-ndf", 1)
        m.node(1, 0.0)
        m.node(2, 1.0)
        m.rigidLink("beam", 1, 2)


def test_default_units_checks_names_and_scales_nothing(m):
    # OpenSeesPy's defaultUnits returns None and leaves every number as typed:
    # a cantilever bar's tip displacement stays P L / (E A) in the script's units.
    m.model("basic", "-ndm", 2, "-ndf", 2)
    assert m.defaultUnits("-force", "kip", "-length", "in", "-time", "sec", "-temp", "F") is None
    assert m.defaultUnits("-Length", "m", "-Force", "kN", "-Time", "sec") is None
    m.node(1, 0.0, 0.0)
    m.node(2, 120.0, 0.0)
    assert m.nodeCoord(2) == [120.0, 0.0]
    m.fix(1, 1, 1)
    m.fix(2, 0, 1)
    m.uniaxialMaterial("Elastic", 1, 29000.0)
    m.element("truss", 1, 1, 2, 2.5, 1)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.load(2, 10.0, 0.0)
    assert static(m, "Plain") == 0
    assert m.nodeDisp(2, 1) == pytest.approx(10.0 * 120.0 / (29000.0 * 2.5), rel=1e-13)
    for bad, match in [(("-force", "kip", "-length", "in"), "missing a unit type"),
                       (("-force", "lbf", "-length", "in", "-time", "sec"), "force unit 'lbf'"),
                       (("-force", "kip", "-length", "km", "-time", "sec"), "length unit 'km'"),
                       (("-force", "kip", "-length", "in", "-time", "min"), "time unit 'min'"),
                       (("-force", "kip", "-length", "in", "-time", "sec", "-extra", 1), "unrecognized unit flag"),
                       (("-force", 1.0, "-length", "in", "-time", "sec"), "force unit")]:
        with pytest.raises(beamsolid.OpenSeesError, match="defaultUnits.*" + match):
            m.defaultUnits(*bad)


def test_mass_values_beyond_the_node_dofs_are_dropped_and_missing_ones_zero(m, capfd):
    # OpenSees (and its dev_test_Brick script) gives 3-dof nodes six masses:
    # the first ndf are the node's, the rest are dropped. A bar k = EA/L with
    # the tip's x mass 2: omega^2 = k / 2.
    m.model("basic", "-ndm", 3, "-ndf", 3)
    m.node(1, 0.0, 0.0, 0.0)
    m.node(2, 4.0, 0.0, 0.0, "-mass", 2.0, 5.0, 5.0, 1e-5, 1e-5, 1e-5)
    m.node(3, 8.0, 0.0, 0.0)
    m.mass(3, 0.49, 0.49, 0.49, 0.00001, 0.00001, 0.00001)
    assert m.nodeMass(2) == [2.0, 5.0, 5.0]
    assert m.nodeMass(3) == [0.49, 0.49, 0.49]
    err = capfd.readouterr().err
    # Said once until wipe: a meshing loop would repeat it for every node.
    assert "WARNING node 2 - 6 mass values for 3 dofs" in err
    assert "WARNING mass 3" not in err
    m.fix(1, 1, 1, 1)
    m.fix(2, 0, 1, 1)
    m.fix(3, 1, 1, 1)
    m.uniaxialMaterial("Elastic", 1, 100.0)
    m.element("truss", 1, 1, 2, 1.0, 1)
    lam = m.eigen("-fullGenLapack", 1)
    assert lam[0] == pytest.approx((100.0 / 4.0) / 2.0, rel=1e-12)
    # Fewer values than dofs: `mass` leaves the rest zero, as OpenSeesPy does (a 2D frame script's
    # mass(n, m) on a 3-dof node), with the warning; node's '-mass' refuses them, as OpenSeesPy does.
    m.wipe()
    m.model("basic", "-ndm", 2, "-ndf", 3)
    m.node(1, 0.0, 0.0)
    m.mass(1, 5.0)
    assert m.nodeMass(1) == [5.0, 0.0, 0.0]
    assert "WARNING mass 1 - 1 mass values for 3 dofs: the missing ones are zero" in capfd.readouterr().err
    with pytest.raises(beamsolid.OpenSeesError, match="node 2: the node has 3 dofs but 2 mass values"):
        m.node(2, 1.0, 0.0, "-mass", 7.0, 8.0)

"""rigidDiaphragm, 2D rigidLink and the query shortcuts of OpenSeesPy scripts.

A two-storey 3D frame whose floors are rigid diaphragms (retained nodes at the
floor centres, out-of-plane dofs fixed), pushed and twisted; a 2D cantilever
with rigid beam and bar links; a force-based 3D column with the section
shortcuts; a truss whose node is moved with setNodeCoord before the analysis.
Returns the displacements and the queries (getFixedNodes, getFixedDOFs,
getConstrainedNodes, getRetainedNodes, nodeBounds, nodeResponse, basicForce,
basicDeformation, basicStiffness, sectionForce, sectionDeformation,
sectionLocation, sectionWeight, numIter, getNP, getPID).
"""


def _analysis(ops, constraints="Transformation"):
    ops.constraints(constraints)
    ops.numberer("RCM")
    ops.system("UmfPack")
    ops.test("NormDispIncr", 1.0e-12, 10)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", 1.0)
    ops.analysis("Static")
    return ops.analyze(1)


def _diaphragm_frame(ops, out):
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    columns = [(0.0, 0.0), (6.0, 0.0), (6.0, 4.0), (0.0, 4.0)]
    h = 3.2
    tag = 1
    ops.geomTransf("Linear", 1, 1.0, 0.0, 0.0)
    ops.geomTransf("Linear", 2, 0.0, 0.0, 1.0)
    for level in range(3):
        for x, y in columns:
            ops.node(10 * level + columns.index((x, y)) + 1, x, y, level * h)
    for k in range(1, 5):
        ops.fix(k, 1, 1, 1, 1, 1, 1)
    for level in (1, 2):
        master = 100 + level
        ops.node(master, 3.0, 2.0, level * h)
        ops.fix(master, 0, 0, 1, 1, 1, 0)
        ops.rigidDiaphragm(3, master, *[10 * level + k for k in range(1, 5)])
        for k in range(1, 5):
            ops.element("elasticBeamColumn", tag, 10 * (level - 1) + k, 10 * level + k, 0.02, 25.0e6, 10.0e6,
                        3.0e-4, 1.6e-4, 2.1e-4, 1)
            tag += 1
        for i, j in ((1, 2), (2, 3), (3, 4), (4, 1)):
            ops.element("elasticBeamColumn", tag, 10 * level + i, 10 * level + j, 0.03, 25.0e6, 10.0e6, 4.0e-4,
                        2.0e-4, 6.0e-4, 2)
            tag += 1
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(101, 40.0, 10.0, 0.0, 0.0, 0.0, 15.0)
    ops.load(102, 80.0, -5.0, 0.0, 0.0, 0.0, 30.0)
    ops.load(13, 0.0, 0.0, -50.0, 0.0, 0.0, 0.0)
    out["diaphragm.code"] = _analysis(ops)
    out["diaphragm.masters"] = [ops.nodeDisp(n) for n in (101, 102)]
    out["diaphragm.corners"] = [ops.nodeDisp(10 * lv + k) for lv in (1, 2) for k in range(1, 5)]
    ops.reactions()
    out["diaphragm.reactions"] = [ops.nodeReaction(k) for k in range(1, 5)]
    out["diaphragm.fixed"] = ops.getFixedNodes()
    out["diaphragm.fixedDOFs"] = [ops.getFixedDOFs(n) for n in (1, 101)]
    out["diaphragm.constrained"] = ops.getConstrainedNodes()
    out["diaphragm.constrained of 102"] = ops.getConstrainedNodes(102)
    out["diaphragm.retained"] = ops.getRetainedNodes()
    out["diaphragm.retained of 23"] = ops.getRetainedNodes(23)
    out["diaphragm.bounds"] = ops.nodeBounds()
    out["diaphragm.nodeResponse"] = [ops.nodeResponse(102, d, 1) for d in (1, 2, 6)]
    out["diaphragm.reaction response"] = ops.nodeResponse(1, 1, 6)
    out["diaphragm.basicForce"] = [ops.basicForce(e) for e in (1, 5, 9)]
    out["diaphragm.basicDeformation"] = ops.basicDeformation(1)
    out["diaphragm.basicStiffness"] = ops.basicStiffness(1)
    out["diaphragm.numIter"] = ops.numIter()
    out["processes"] = [ops.getNP(), ops.getPID()]


def _rigid_links_2d(ops, out):
    for kind in ("beam", "bar"):
        ops.wipe()
        ops.model("basic", "-ndm", 2, "-ndf", 3)
        ops.node(1, 0.0, 0.0)
        ops.node(2, 3.0, 1.0)
        ops.node(3, 3.8, 0.4)
        ops.fix(1, 1, 1, 1)
        ops.geomTransf("Linear", 1)
        ops.element("elasticBeamColumn", 1, 1, 2, 0.01, 200.0e6, 1.0e-4, 1)
        ops.rigidLink(kind, 2, 3)
        if kind == "bar":
            ops.fix(3, 0, 0, 1)
        ops.timeSeries("Linear", 1)
        ops.pattern("Plain", 1, 1)
        ops.load(3, 2.0, -5.0, 0.0)
        out["link2d." + kind + ".code"] = _analysis(ops)
        out["link2d." + kind + ".disp"] = [ops.nodeDisp(n) for n in (2, 3)]
        out["link2d." + kind + ".retained"] = ops.getRetainedNodes(3)


def _sections(ops, out):
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    ops.node(1, 0.0, 0.0, 0.0)
    ops.node(2, 0.0, 0.0, 2.5)
    ops.fix(1, 1, 1, 1, 1, 1, 1)
    ops.geomTransf("Linear", 1, 1.0, 0.0, 0.0)
    ops.section("Elastic", 1, 30.0e6, 0.09, 6.75e-4, 6.75e-4, 12.5e6, 1.1e-3)
    ops.beamIntegration("Lobatto", 1, 1, 4)
    ops.element("forceBeamColumn", 1, 1, 2, 1, 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, 4.0, -3.0, -20.0, 0.0, 0.0, 1.5)
    out["sections.code"] = _analysis(ops)
    out["sections.force"] = [ops.sectionForce(1, k) for k in (1, 2, 3, 4)]
    out["sections.force dof"] = ops.sectionForce(1, 1, 2)
    out["sections.deformation"] = [ops.sectionDeformation(1, k) for k in (1, 4)]
    out["sections.location"] = ops.sectionLocation(1)
    out["sections.weight"] = ops.sectionWeight(1)


def _t_section(ops, out):
    """A 3D fiber T-section (flange off the fiber origin): the reference axis is its area
    centroid, so the axial load alone gives no bending; then bending about both axes."""
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    ops.node(1, 0.0, 0.0, 0.0)
    ops.node(2, 3.0, 0.0, 0.0)
    ops.fix(1, 1, 1, 1, 1, 1, 1)
    ops.uniaxialMaterial("Steel01", 1, 350.0e3, 200.0e6, 0.01)
    ops.section("Fiber", 1, "-GJ", 1.0e4)
    ops.patch("rect", 1, 10, 2, 0.30, -0.15, 0.35, 0.15)
    ops.patch("rect", 1, 12, 2, 0.0, -0.02, 0.30, 0.02)
    ops.layer("straight", 1, 3, 2.0e-4, 0.05, -0.1, 0.05, 0.1)
    ops.geomTransf("Linear", 1, 0.0, 0.0, 1.0)
    ops.beamIntegration("Lobatto", 1, 1, 4)
    ops.element("forceBeamColumn", 1, 1, 2, 1, 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, 500.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    out["tsection.axial.code"] = _analysis(ops)
    out["tsection.axial.disp"] = ops.nodeDisp(2)
    out["tsection.axial.section"] = ops.eleResponse(1, "section", 1, "force")
    ops.loadConst("-time", 0.0)
    ops.pattern("Plain", 2, 1)
    ops.load(2, 0.0, 40.0, 15.0, 0.0, 0.0, 0.0)
    ops.integrator("LoadControl", 0.25)
    codes = [ops.analyze(1) for _ in range(4)]
    out["tsection.bent.codes"] = codes
    out["tsection.bent.disp"] = ops.nodeDisp(2)
    out["tsection.bent.base"] = ops.eleResponse(1, "section", 1, "deformation")
    out["tsection.bent.fiber"] = ops.eleResponse(1, "section", 1, "fiber", 0.326, 0.1, "stressStrain")


def _moved_node(ops, out):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 2)
    ops.node(1, 0.0, 0.0)
    ops.node(2, 2.0, 0.0)
    ops.node(3, 1.0, 1.0)
    ops.fix(1, 1, 1)
    ops.fix(2, 0, 1)
    ops.setNodeCoord(3, 2, 1.5)
    out["moved.coord"] = ops.nodeCoord(3)
    ops.uniaxialMaterial("Elastic", 1, 1000.0)
    for k, (i, j) in enumerate(((1, 2), (1, 3), (2, 3)), start=1):
        ops.element("Truss", k, i, j, 1.0, 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(3, 1.0, -2.0)
    out["moved.code"] = _analysis(ops, "Plain")
    out["moved.disp"] = [ops.nodeDisp(n) for n in (2, 3)]
    out["moved.axial"] = [ops.eleResponse(e, "axialForce") for e in (1, 2, 3)]


def run(ops):
    out = {}
    _diaphragm_frame(ops, out)
    _rigid_links_2d(ops, out)
    _sections(ops, out)
    _t_section(ops, out)
    _moved_node(ops, out)
    ops.wipe()
    return out

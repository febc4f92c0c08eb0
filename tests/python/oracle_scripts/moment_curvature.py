"""Moment-curvature of fiber sections with zeroLengthSection.

In the style of the OpenSees example MomentCurvature.py: a zeroLengthSection
between two coincident nodes, an axial load held constant, then
DisplacementControl on the rotation of node 2 (the curvature, the element
having unit length). Sections: the example's RC column (Concrete01 core and
cover, Steel01 bars, patch rect and layer straight), a similar column as
an RCSection2d (Steel02 bars), a steel WFSection2d (Steel02), a circular section (patch circ, layer circ) and a 3D fiber
section bent about y and z. Curvature, moment, iteration counts, section
and fiber responses at every step.
"""


def _analysis(ops):
    ops.system("BandGeneral")
    ops.numberer("Plain")
    ops.constraints("Plain")
    ops.test("NormUnbalance", 1e-9, 20)
    ops.algorithm("Newton")


def _moment_curvature_2d(ops, out, key, build_section, axial, max_k, steps, fiber=None):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    build_section(ops)
    ops.node(1, 0.0, 0.0)
    ops.node(2, 0.0, 0.0)
    ops.fix(1, 1, 1, 1)
    ops.fix(2, 0, 1, 0)
    ops.element("zeroLengthSection", 1, 1, 2, 1)
    ops.timeSeries("Constant", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, axial, 0.0, 0.0)
    _analysis(ops)
    ops.integrator("LoadControl", 0.0)
    ops.analysis("Static")
    out[key + "axial code"] = ops.analyze(1)
    out[key + "axial iter"] = ops.testIter()
    ops.timeSeries("Linear", 2)
    ops.pattern("Plain", 2, 2)
    ops.load(2, 0.0, 0.0, 1.0)
    dk = max_k / steps
    ops.integrator("DisplacementControl", 2, 3, dk, 1, dk, dk)
    curvature, moment, iters, codes, fibers = [], [], [], [], []
    for _ in range(steps):
        codes.append(ops.analyze(1))
        iters.append(ops.testIter())
        curvature.append(ops.nodeDisp(2, 3))
        moment.append(ops.getLoadFactor(2))
        if fiber is not None:
            fibers.append(ops.eleResponse(1, "section", "fiber", *fiber, "stressStrain"))
    out[key + "codes"] = codes
    out[key + "iters"] = iters
    out[key + "curvature"] = curvature
    out[key + "moment"] = moment
    if fiber is not None:
        out[key + "fiber stressStrain"] = fibers
    for what in ("force", "deformation", "stiffness"):
        out[key + "section " + what] = ops.eleResponse(1, "section", what)
    for what in ("force", "forces", "deformation", "basicForce", "basicDeformation", "localForce"):
        out[key + "element " + what] = ops.eleResponse(1, what)
    out[key + "axial strain"] = ops.nodeDisp(2, 1)
    ops.reactions()
    out[key + "reaction"] = ops.nodeReaction(1)


def _rc_column(ops):
    # MomentCurvature.py: 15 x 24 column, 1.5 cover, 3 + 2 + 3 bars of 0.60.
    ops.uniaxialMaterial("Concrete01", 1, -6.0, -0.004, -5.0, -0.014)
    ops.uniaxialMaterial("Concrete01", 2, -5.0, -0.002, 0.0, -0.006)
    ops.uniaxialMaterial("Steel01", 3, 60.0, 30000.0, 0.01)
    width, depth, cover, bar = 15.0, 24.0, 1.5, 0.60
    y1, z1 = depth / 2.0, width / 2.0
    ops.section("Fiber", 1)
    ops.patch("rect", 1, 10, 1, cover - y1, cover - z1, y1 - cover, z1 - cover)
    ops.patch("rect", 2, 10, 1, -y1, z1 - cover, y1, z1)
    ops.patch("rect", 2, 10, 1, -y1, -z1, y1, cover - z1)
    ops.patch("rect", 2, 2, 1, -y1, cover - z1, cover - y1, z1 - cover)
    ops.patch("rect", 2, 2, 1, y1 - cover, cover - z1, y1, z1 - cover)
    ops.layer("straight", 3, 3, bar, y1 - cover, z1 - cover, y1 - cover, cover - z1)
    ops.layer("straight", 3, 2, bar, 0.0, z1 - cover, 0.0, cover - z1)
    ops.layer("straight", 3, 3, bar, cover - y1, z1 - cover, cover - y1, cover - z1)


def _unsymmetric(ops):
    # A T-shaped steel section: the centroid is not at y = 0.
    ops.uniaxialMaterial("Steel01", 1, 50.0, 29000.0, 0.02)
    ops.uniaxialMaterial("Elastic", 2, 29000.0)
    ops.section("Fiber", 1, "-GJ", 1.0e6)
    ops.patch("quad", 1, 2, 8, 10.0, -4.0, 12.0, -4.0, 12.0, 4.0, 10.0, 4.0)
    ops.patch("rect", 1, 10, 1, 0.0, -0.5, 10.0, 0.5)
    ops.fiber(1.0, 0.0, 0.5, 2)


def _wide_flange(ops):
    ops.uniaxialMaterial("Steel02", 1, 50.0, 29000.0, 0.003, 20.0, 0.925, 0.15)
    ops.section("WFSection2d", 1, 1, 20.99, 0.4, 8.24, 0.615, 10, 3)


def _rc_section_2d(ops):
    ops.uniaxialMaterial("Concrete01", 1, -6.0, -0.004, -5.0, -0.014)
    ops.uniaxialMaterial("Concrete01", 2, -5.0, -0.002, 0.0, -0.006)
    ops.uniaxialMaterial("Steel02", 3, 60.0, 29000.0, 0.01, 18.0, 0.925, 0.15)
    ops.section("RCSection2d", 1, 1, 2, 3, 24.0, 15.0, 1.5, 0.79 * 3, 0.6 * 3, 0.44, 12, 2, 4)


def _circular(ops):
    ops.uniaxialMaterial("Concrete01", 1, -5.0, -0.002, -4.0, -0.008)
    ops.uniaxialMaterial("Steel01", 2, 60.0, 29000.0, 0.005)
    ops.section("Fiber", 1)
    ops.patch("circ", 1, 16, 4, 0.0, 0.0, 0.0, 12.0, 0.0, 360.0)
    ops.layer("circ", 2, 10, 0.79, 0.0, 0.0, 10.0, 0.0, 324.0)


def _section_3d(ops, out):
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    ops.uniaxialMaterial("Steel01", 1, 50.0, 29000.0, 0.01)
    ops.section("Fiber", 1, "-GJ", 5.0e5)
    ops.patch("rect", 1, 8, 6, -6.0, -4.0, 6.0, 4.0)
    ops.node(1, 0.0, 0.0, 0.0)
    ops.node(2, 0.0, 0.0, 0.0)
    ops.fix(1, 1, 1, 1, 1, 1, 1)
    ops.fix(2, 0, 1, 1, 0, 0, 0)
    ops.element("zeroLengthSection", 1, 1, 2, 1, "-orient", 1.0, 0.0, 0.0, 0.0, 1.0, 0.0)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, 0.0, 0.0, 0.0, 1.0, 1.0, 2.0)
    _analysis(ops)
    ops.integrator("DisplacementControl", 2, 6, 2.0e-4)
    ops.analysis("Static")
    disp, iters = [], []
    for _ in range(15):
        ops.analyze(1)
        iters.append(ops.testIter())
        disp.append(ops.nodeDisp(2))
    out["3d.disp"] = disp
    out["3d.iters"] = iters
    for what in ("force", "deformation", "stiffness"):
        out["3d.section " + what] = ops.eleResponse(1, "section", what)
    out["3d.force"] = ops.eleResponse(1, "force")
    out["3d.fiber"] = ops.eleResponse(1, "section", "fiber", 5.0, 3.0, "stressStrain")


def run(ops):
    out = {}
    _moment_curvature_2d(ops, out, "rc.", _rc_column, -180.0, 0.001, 40, fiber=(10.5, 0.0, 3))
    _moment_curvature_2d(ops, out, "rc tension.", _rc_column, 50.0, 0.0008, 20)
    _moment_curvature_2d(ops, out, "tee.", _unsymmetric, 0.0, 0.0012, 15, fiber=(11.0, 0.0))
    _moment_curvature_2d(ops, out, "wf.", _wide_flange, -100.0, 0.0006, 30, fiber=(10.0, 0.0))
    _moment_curvature_2d(ops, out, "circ.", _circular, -300.0, 0.0008, 30)
    _moment_curvature_2d(ops, out, "rcsection2d.", _rc_section_2d, -150.0, 0.001, 30)
    _section_3d(ops, out)
    ops.wipe()
    return out

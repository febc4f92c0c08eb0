"""betaKcomm damping given after a static analysis.

A steel truss bar (Steel01, '-doRayleigh' 1) and a fiber-section
forceBeamColumn cantilever are pushed statically past yield; only then
rayleigh(0, 0, 0, betaKcomm) (or a region / setElementRayleighDampingFactors
with the same factor) is given and a short transient follows under a
constant load. OpenSees damps already in the first dynamic step with the
tangent of the last converged (yielded) state, not the initial stiffness.
Displacements, velocities and iteration counts at every step.
"""


def _truss(ops, damping):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 2)
    ops.node(1, 0.0, 0.0)
    ops.node(2, 2.0, 0.0)
    ops.fix(1, 1, 1)
    ops.fix(2, 0, 1)
    ops.mass(2, 3.0, 3.0)
    ops.uniaxialMaterial("Steel01", 1, 250.0, 2.0e5, 0.05)
    ops.element("Truss", 1, 1, 2, 1.0e-3, 1, "-doRayleigh", 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, 1.0, 0.0)
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.system("FullGeneral")
    ops.test("NormDispIncr", 1e-12, 20)
    ops.algorithm("Newton")
    ops.integrator("DisplacementControl", 2, 1, 1.0e-3)
    ops.analysis("Static")
    ops.analyze(6)
    ops.loadConst("-time", 0.0)
    damping(ops, 1)
    ops.wipeAnalysis()
    ops.timeSeries("Constant", 2)
    ops.pattern("Plain", 2, 2)
    ops.load(2, 20.0, 0.0)
    return _transient(ops, 2, 1)


def _column(ops, damping):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    ops.node(1, 0.0, 0.0)
    ops.node(2, 0.0, 3.0)
    ops.fix(1, 1, 1, 1)
    ops.mass(2, 50.0, 1.0e-6, 0.0)
    ops.uniaxialMaterial("Steel02", 1, 400.0, 2.0e5, 0.02, 18.0, 0.925, 0.15)
    ops.uniaxialMaterial("Concrete01", 2, -30.0, -0.002, -6.0, -0.006)
    ops.section("Fiber", 1)
    ops.patch("rect", 2, 10, 1, -0.2, -0.15, 0.2, 0.15)
    ops.layer("straight", 1, 3, 5.0e-4, -0.16, 0.1, -0.16, -0.1)
    ops.layer("straight", 1, 3, 5.0e-4, 0.16, 0.1, 0.16, -0.1)
    ops.geomTransf("Linear", 1)
    ops.beamIntegration("Lobatto", 1, 1, 5)
    ops.element("forceBeamColumn", 1, 1, 2, 1, 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, 0.0, -500.0, 0.0)
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.system("BandGeneral")
    ops.test("NormDispIncr", 1e-10, 20)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", 0.25)
    ops.analysis("Static")
    ops.analyze(4)
    ops.loadConst("-time", 0.0)
    ops.timeSeries("Linear", 2)
    ops.pattern("Plain", 2, 2)
    ops.load(2, 1.0, 0.0, 0.0)
    ops.integrator("DisplacementControl", 2, 1, 0.004)
    ops.analyze(5)
    ops.loadConst("-time", 0.0)
    damping(ops, 1)
    ops.wipeAnalysis()
    ops.timeSeries("Constant", 3)
    ops.pattern("Plain", 3, 3)
    ops.load(2, 20.0, 0.0, 0.0)
    return _transient(ops, 2, 1)


def _transient(ops, node, dof):
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.system("BandGeneral")
    ops.test("NormDispIncr", 1e-10, 20)
    ops.algorithm("Newton")
    ops.integrator("Newmark", 0.5, 0.25)
    ops.analysis("Transient")
    rows = []
    for _ in range(8):
        code = ops.analyze(1, 0.005)
        rows.append([code, ops.testIter(), ops.nodeDisp(node, dof), ops.nodeVel(node, dof)])
    return rows


def _global(ops, ele):
    ops.rayleigh(0.0, 0.0, 0.0, 0.004)


def _region(ops, ele):
    ops.region(1, "-ele", ele, "-rayleigh", 0.0, 0.0, 0.0, 0.004)


def _element(ops, ele):
    ops.setElementRayleighDampingFactors(ele, 0.0, 0.0, 0.0, 0.004)


def _current(ops, ele):
    ops.rayleigh(0.0, 0.004, 0.0, 0.0)


def run(ops):
    out = {}
    for name, damping in (("global", _global), ("region", _region), ("element", _element), ("current", _current)):
        out["truss." + name] = _truss(ops, damping)
        out["column." + name] = _column(ops, damping)
    return out

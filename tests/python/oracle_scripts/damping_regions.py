"""Damping by region, and viscous (rate-dependent) bars.

A two-storey 2D cantilever column (elasticBeamColumn with element mass and
nodal masses) in free vibration after a load pulse, damped through
region(..., '-rayleigh', ...) in the documented forms: '-ele' (the elements
and their nodes), '-eleOnly', '-eleRange', '-node' (the nodes and the
elements wholly inside), '-nodeOnly', '-nodeRange', two regions, and a
later rayleigh() that replaces the regions' factors. Then a truss and a
corotTruss whose material is Viscous (alpha 1 and 0.5) in parallel with an
elastic spring, with and without '-doRayleigh', under a load history.
Displacements, velocities, accelerations, -rayleigh reactions and iteration
counts are returned at every step.
"""


def _column(ops, out, tag, damping):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    ops.node(1, 0.0, 0.0)
    ops.node(2, 0.0, 3.0)
    ops.node(3, 0.0, 6.0)
    ops.fix(1, 1, 1, 1)
    ops.mass(2, 10.0, 10.0, 0.1)
    ops.mass(3, 8.0, 8.0, 0.1)
    ops.geomTransf("Linear", 1)
    ops.element("elasticBeamColumn", 1, 1, 2, 0.01, 2.0e8, 1.0e-4, 1, "-mass", 5.0)
    ops.element("elasticBeamColumn", 2, 2, 3, 0.01, 2.0e8, 1.0e-4, 1, "-mass", 4.0)
    damping(ops)
    ops.timeSeries("Path", 1, "-dt", 0.01, "-values", 0.0, 1.0, 0.5, 0.0)
    ops.pattern("Plain", 1, 1)
    ops.load(3, 100.0, -50.0, 0.0)
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.system("UmfPack")
    ops.test("NormDispIncr", 1e-12, 10)
    ops.algorithm("Newton")
    ops.integrator("Newmark", 0.5, 0.25)
    ops.analysis("Transient")
    rows = []
    for _ in range(25):
        code = ops.analyze(1, 0.01)
        ops.reactions("-rayleigh")
        rows.append([code, ops.testIter(), *ops.nodeDisp(3), *ops.nodeVel(3), *ops.nodeAccel(2),
                     *ops.nodeReaction(1), *ops.nodeReaction(2)])
    out["column." + tag] = rows


def _regions():
    def both_kinds(ops):
        ops.region(1, "-ele", 2, "-rayleigh", 0.0, 0.002, 0.0, 0.0)
        ops.region(2, "-nodeOnly", 3, "-rayleigh", 0.8, 0.0, 0.0, 0.0)

    def replaced(ops):
        ops.region(1, "-ele", 1, 2, "-rayleigh", 0.5, 0.001, 0.0, 0.0)
        ops.rayleigh(0.2, 0.0, 0.0005, 0.0)

    def after_global(ops):
        ops.rayleigh(0.2, 0.0, 0.0, 0.0)
        ops.region(1, "-eleRange", 2, 9, "-rayleigh", 0.0, 0.0, 0.001, 0.0005)

    return {
        "ele": lambda ops: ops.region(1, "-ele", 2, "-rayleigh", 0.5, 0.001, 0.0, 0.0),
        "eleOnly": lambda ops: ops.region(1, "-eleOnly", 2, "-rayleigh", 0.5, 0.001, 0.0, 0.0),
        "eleRange": lambda ops: ops.region(3, "-eleRange", 1, 1, "-rayleigh", 0.3, 0.0, 0.002, 0.0),
        "node": lambda ops: ops.region(1, "-node", 2, 3, "-rayleigh", 0.5, 0.0, 0.0, 0.001),
        "nodeOnly": lambda ops: ops.region(1, "-nodeOnly", 2, 3, "-rayleigh", 0.5, 0.001, 0.0, 0.0),
        "nodeRange": lambda ops: ops.region(1, "-nodeRange", 1, 2, "-rayleigh", 0.4, 0.001, 0.0, 0.0),
        "two": both_kinds,
        "replaced": replaced,
        "after_global": after_global,
    }


def _bar(ops, out, element, alpha, rayleigh):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 2)
    ops.node(1, 0.0, 0.0)
    ops.node(2, 3.0, 4.0)
    ops.fix(1, 1, 1)
    ops.mass(2, 2.0, 2.0)
    ops.uniaxialMaterial("Elastic", 1, 500.0)
    ops.uniaxialMaterial("Viscous", 2, 40.0, alpha)
    ops.element(element, 1, 1, 2, 1.0, 2, "-doRayleigh", rayleigh)
    ops.element(element, 2, 1, 2, 1.0, 1, "-rho", 0.5)
    ops.node(3, 6.0, 0.0)
    ops.fix(3, 1, 1)
    ops.element(element, 3, 3, 2, 1.0, 1)
    ops.rayleigh(0.1, 0.002, 0.0, 0.0)
    ops.timeSeries("Path", 1, "-dt", 0.02, "-values", 0.0, 30.0, 60.0, 20.0, -40.0, 0.0)
    ops.pattern("Plain", 1, 1)
    ops.load(2, 1.0, -2.0)
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.system("FullGeneral")
    ops.test("NormDispIncr", 1e-10, 25)
    ops.algorithm("Newton")
    ops.integrator("Newmark", 0.5, 0.25)
    ops.analysis("Transient")
    rows = []
    for _ in range(15):
        code = ops.analyze(1, 0.02)
        ops.reactions("-dynamic")
        rows.append([code, ops.testIter(), *ops.nodeDisp(2), *ops.nodeVel(2), *ops.nodeAccel(2),
                     *ops.nodeReaction(1), *ops.eleResponse(1, "axialForce")])
    out["bar.%s.%g.%d" % (element, alpha, rayleigh)] = rows


def run(ops):
    out = {}
    _column(ops, out, "none", lambda ops: None)
    for tag, damping in _regions().items():
        _column(ops, out, tag, damping)
    for element in ("Truss", "corotTruss"):
        for alpha in (1.0, 0.5):
            for rayleigh in (0, 1):
                _bar(ops, out, element, alpha, rayleigh)
    ops.wipe()
    return out

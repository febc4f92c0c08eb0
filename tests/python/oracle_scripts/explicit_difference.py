"""integrator('ExplicitDifference') (Linear algorithm, every free dof with mass).

A spring-mass under a load history, undamped, with mass-proportional Rayleigh
damping and with a Viscous dashpot; then a 2D portal frame (elasticBeamColumn,
nodal masses on every dof) with Rayleigh damping (alphaM and betaK) under a
Trig series load. Displacements, velocities and accelerations at every step.
"""


def _spring(ops, out, tag, damping):
    ops.wipe()
    ops.model("basic", "-ndm", 1, "-ndf", 1)
    ops.node(1, 0.0)
    ops.node(2, 0.0)
    ops.fix(1, 1)
    ops.mass(2, 2.0)
    ops.uniaxialMaterial("Elastic", 1, 100.0)
    if damping == "viscous":
        ops.uniaxialMaterial("Viscous", 2, 3.0, 1.0)
        ops.element("zeroLength", 1, 1, 2, "-mat", 1, 2, "-dir", 1, 1)
    else:
        ops.element("zeroLength", 1, 1, 2, "-mat", 1, "-dir", 1)
    if damping == "rayleigh":
        ops.rayleigh(0.5, 0.0, 0.0, 0.0)
    ops.timeSeries("Path", 1, "-dt", 0.05, "-values", 0.0, 10.0, 10.0, -5.0, 0.0, 0.0, 3.0)
    ops.pattern("Plain", 1, 1)
    ops.load(2, 1.0)
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.system("FullGeneral")
    ops.algorithm("Linear")
    ops.integrator("ExplicitDifference")
    ops.analysis("Transient")
    rows = []
    for _ in range(30):
        code = ops.analyze(1, 0.05)
        rows.append([code, ops.getTime(), ops.nodeDisp(2, 1), ops.nodeVel(2, 1), ops.nodeAccel(2, 1)])
    out["spring." + tag] = rows


def _frame(ops, out):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    for t, xy in {1: (0.0, 0.0), 2: (5.0, 0.0), 3: (0.0, 3.0), 4: (5.0, 3.0)}.items():
        ops.node(t, *xy)
    ops.fix(1, 1, 1, 1)
    ops.fix(2, 1, 1, 1)
    for t in (3, 4):
        ops.mass(t, 20.0, 20.0, 0.5)
    ops.geomTransf("Linear", 1)
    ops.element("elasticBeamColumn", 1, 1, 3, 0.02, 2.0e8, 2.0e-4, 1)
    ops.element("elasticBeamColumn", 2, 2, 4, 0.02, 2.0e8, 2.0e-4, 1)
    ops.element("elasticBeamColumn", 3, 3, 4, 0.03, 2.0e8, 4.0e-4, 1)
    ops.rayleigh(0.3, 1.0e-5, 0.0, 0.0)
    ops.timeSeries("Trig", 1, 0.0, 0.5, 0.25)
    ops.pattern("Plain", 1, 1)
    ops.load(3, 100.0, 0.0, 0.0)
    ops.constraints("Plain")
    ops.numberer("RCM")
    ops.system("UmfPack")
    ops.algorithm("Linear")
    ops.integrator("ExplicitDifference")
    ops.analysis("Transient")
    rows = []
    for _ in range(60):
        code = ops.analyze(1, 0.001)
        rows.append([code, *ops.nodeDisp(3), *ops.nodeVel(4), *ops.nodeAccel(3)])
    out["frame"] = rows


def run(ops):
    out = {}
    for tag in ("undamped", "rayleigh", "viscous"):
        _spring(ops, out, tag, tag)
    _frame(ops, out)
    ops.wipe()
    return out

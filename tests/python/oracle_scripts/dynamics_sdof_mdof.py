"""Transient analysis: an SDOF spring and a 2D portal frame in time.

A spring-mass (truss with -doRayleigh) under a ramp, with every Newmark
-form, HHT and TRBDF2; a spring with a Viscous dashpot (alpha 1, 0.5, 0.3); then a fixed-base portal frame (elasticBeamColumn, nodal
masses on every dof, top floor tied by equalDOF) with Rayleigh damping set from its first two
eigenvalues (eigen before the analysis), loaded by a nodal load history
(Path series with -dt/-values) under Newmark, HHT, TRBDF2, CentralDifference
(Linear algorithm) and VariableTransient. Node displacements, velocities,
accelerations, static/-dynamic/-rayleigh reactions, times and iteration
counts are returned at every step, and Node recorder files of disp, vel, accel.
"""
import math


def _spring(ops, out, integrator, tag):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 2)
    ops.node(1, 0.0, 0.0)
    ops.node(2, 1.0, 0.0)
    ops.fix(1, 1, 1)
    ops.fix(2, 0, 1)
    ops.mass(2, 2.0, 0.0)
    ops.uniaxialMaterial("Elastic", 1, 100.0)
    ops.element("Truss", 1, 1, 2, 1.0, 1, "-doRayleigh", 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, 10.0, 0.0)
    ops.rayleigh(0.3, 0.01, 0.002, 0.001)
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.system("BandGeneral")
    ops.test("NormDispIncr", 1e-12, 10)
    ops.algorithm("Newton")
    ops.integrator(*integrator)
    ops.analysis("Transient")
    rows = []
    for _ in range(8):
        code = ops.analyze(1, 0.05)
        row = [code, ops.getTime(), ops.nodeDisp(2, 1), ops.nodeVel(2, 1), ops.nodeAccel(2, 1), ops.testIter()]
        for flag in ((), ("-dynamic",), ("-rayleigh",)):
            ops.reactions(*flag)
            row += [ops.nodeReaction(1, 1), ops.nodeReaction(2, 1)]
        rows.append(row)
    out["spring." + tag] = rows


def _dashpot(ops, out, alpha):
    ops.wipe()
    ops.model("basic", "-ndm", 1, "-ndf", 1)
    ops.node(1, 0.0)
    ops.node(2, 0.0)
    ops.fix(1, 1)
    ops.mass(2, 2.0)
    ops.uniaxialMaterial("Elastic", 1, 100.0)
    ops.uniaxialMaterial("Viscous", 2, 3.0, alpha)
    ops.element("zeroLength", 1, 1, 2, "-mat", 1, 2, "-dir", 1, 1)
    ops.timeSeries("Path", 1, "-dt", 0.05, "-values", 0.0, 10.0, 10.0, -5.0, 0.0, 0.0, 3.0)
    ops.pattern("Plain", 1, 1)
    ops.load(2, 1.0)
    ops.test("NormDispIncr", 1e-12, 20)
    ops.algorithm("Newton")
    ops.integrator("Newmark", 0.5, 0.25)
    ops.system("FullGeneral")
    ops.analysis("Transient")
    rows = []
    for _ in range(10):
        code = ops.analyze(1, 0.05)
        rows.append([code, ops.nodeDisp(2, 1), ops.nodeVel(2, 1), ops.nodeAccel(2, 1), ops.testIter(),
                     ops.eleResponse(1, "material", 2, "stress")])
    out["dashpot.%g" % alpha] = rows


def _frame(ops, out, integrator, tag, algorithm="Newton", variable=False):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    h, b = 3.0, 5.0
    for t, xy in {1: (0.0, 0.0), 2: (b, 0.0), 3: (0.0, h), 4: (b, h), 5: (0.0, 2 * h), 6: (b, 2 * h)}.items():
        ops.node(t, *xy)
    ops.fix(1, 1, 1, 1)
    ops.fix(2, 1, 1, 1)
    for t in (3, 4, 5, 6):
        ops.mass(t, 2.0, 2.0, 0.05)
    ops.equalDOF(5, 6, 1)  # a rigid top floor: constrained dofs move with their masters
    ops.geomTransf("Linear", 1)
    E, A, I = 2.0e4, 0.04, 2.0e-4
    for e, (i, j) in enumerate([(1, 3), (2, 4), (3, 5), (4, 6), (3, 4), (5, 6)], start=1):
        ops.element("elasticBeamColumn", e, i, j, A, E, 2 * I if e > 4 else I, 1)
    lam = ops.eigen("-fullGenLapack", 2)
    out["frame." + tag + ".eigen"] = lam
    w1, w2 = math.sqrt(lam[0]), math.sqrt(lam[1])
    zeta = 0.05
    ops.rayleigh(2 * zeta * w1 * w2 / (w1 + w2), 0.0, 2 * zeta / (w1 + w2), 0.0)
    values = [0.0, 1.0, 3.0, 2.0, -1.5, -2.5, 0.5, 1.0, 0.0, 0.0]
    ops.timeSeries("Path", 1, "-dt", 0.02, "-values", *values)
    ops.pattern("Plain", 1, 1)
    ops.load(5, 1.0, 0.0, 0.0)
    ops.load(3, 0.5, -0.2, 0.0)
    ops.constraints("Transformation")
    ops.numberer("RCM")
    ops.system("UmfPack")
    ops.test("NormDispIncr", 1e-12, 10)
    ops.algorithm(algorithm)
    ops.integrator(*integrator)
    ops.analysis("VariableTransient" if variable else "Transient")
    files = []
    if tag == "newmark":
        for what in ("disp", "vel", "accel"):
            files.append("frame_%s.out" % what)
            ops.recorder("Node", "-file", files[-1], "-time", "-node", 5, 6, "-dof", 1, 2, 3, what)
    rows = []
    for _ in range(12):
        code = ops.analyze(1, 0.01, 0.0025, 0.04, 4) if variable else ops.analyze(1, 0.01)
        row = [code, ops.getTime(), ops.testIter()]
        for n in (3, 4, 5, 6):
            row += ops.nodeDisp(n) + ops.nodeVel(n) + ops.nodeAccel(n)
        ops.reactions("-dynamic")
        row += ops.nodeReaction(1) + ops.nodeReaction(2)
        rows.append(row)
    out["frame." + tag] = rows
    if files:
        ops.remove("recorders")
        for name in files:
            with open(name) as f:
                out["file:" + name] = f.read()
    if variable:
        out["frame." + tag + ".multi"] = [ops.analyze(5, 0.01, 0.0025, 0.04, 4), ops.getTime()]
    ops.wipe()


def run(ops):
    out = {}
    for integrator, tag in [
        (("Newmark", 0.5, 0.25), "newmark"),
        (("Newmark", 0.5, 0.25, "-form", "V"), "newmarkV"),
        (("Newmark", 0.6, 0.3025, "-form", "A"), "newmarkA"),
        (("HHT", 0.8), "hht"),
        (("TRBDF2",), "trbdf2"),
        (("CentralDifference",), "central"),
    ]:
        _spring(ops, out, integrator, tag) if tag != "central" else None
    for alpha in (1.0, 0.5, 0.3):
        _dashpot(ops, out, alpha)
    _frame(ops, out, ("Newmark", 0.5, 0.25), "newmark")
    _frame(ops, out, ("HHT", 0.7, 0.8, 0.4225), "hht")
    _frame(ops, out, ("CentralDifference",), "central", algorithm="Linear")
    _frame(ops, out, ("TRBDF2",), "trbdf2")
    _frame(ops, out, ("Newmark", 0.5, 0.25), "variable", variable=True)
    ops.wipe()
    return out

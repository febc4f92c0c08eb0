"""The analysis idioms of public OpenSeesPy examples, on a braced 2D frame.

A one-bay, two-storey frame of elasticBeamColumn members (PDelta columns) with
Steel01 truss braces: eigen periods before gravity and the mode shapes
(nodeEigenvector); gravity in 10 steps held by loadConst('-time', 0.0); a
DisplacementControl pushover of the roof that yields the braces, driven by the
examples' loop "if analyze fails, try ModifiedNewton -initial, then
NewtonLineSearch, then a smaller step"; every system name of the examples in turn
on the same model (wipeAnalysis between them) until one step passes; and the
queries scripts read along the way (getTime, getLoadFactor, testIter, testNorm,
reactions, nodeReaction, nodeUnbalance, eleResponse, systemSize).
"""

SYSTEMS = ("BandGen", "BandGEN", "BandGeneral", "BandSPD", "ProfileSPD", "SparseGeneral", "FullGeneral", "UmfPack",
           "Umfpack", "Mumps", "SuperLU")


def _frame(ops):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    b, h = 6.0, 3.5
    for i, (x, y) in enumerate([(0, 0), (b, 0), (0, h), (b, h), (0, 2 * h), (b, 2 * h)], start=1):
        ops.node(i, float(x), float(y))
    ops.fix(1, 1, 1, 1)
    ops.fix(2, 1, 1, 0)  # a pinned base on the right
    for n in (3, 4, 5, 6):
        ops.mass(n, 20.0, 20.0, 0.0)
    ops.geomTransf("PDelta", 1)
    ops.geomTransf("Linear", 2)
    E = 200.0e6
    ops.element("elasticBeamColumn", 1, 1, 3, 0.012, E, 2.2e-4, 1)
    ops.element("elasticBeamColumn", 2, 2, 4, 0.012, E, 2.2e-4, 1)
    ops.element("elasticBeamColumn", 3, 3, 5, 0.010, E, 1.6e-4, 1)
    ops.element("elasticBeamColumn", 4, 4, 6, 0.010, E, 1.6e-4, 1)
    ops.element("elasticBeamColumn", 5, 3, 4, 0.008, E, 3.0e-4, 2)
    ops.element("elasticBeamColumn", 6, 5, 6, 0.008, E, 3.0e-4, 2)
    ops.uniaxialMaterial("Steel01", 1, 350.0e3, E, 0.02)
    ops.element("Truss", 7, 1, 4, 6.0e-4, 1)
    ops.element("Truss", 8, 3, 6, 5.0e-4, 1)


def _gravity(ops):
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    for n in (3, 4, 5, 6):
        ops.load(n, 0.0, -150.0, 0.0)
    ops.eleLoad("-ele", 5, 6, "-type", "-beamUniform", -12.0)
    ops.constraints("Plain")
    ops.numberer("RCM")
    ops.system("BandGeneral")
    ops.test("NormDispIncr", 1.0e-10, 10)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", 0.1)
    ops.analysis("Static")
    return ops.analyze(10)


def _signed(shape):
    """A mode shape with its largest component positive: a mode's sign is arbitrary
    (OpenSees leaves ARPACK's), so scripts that compare shapes fix it first."""
    flat = [c for node in shape for c in node]
    big = max(flat, key=abs)
    return [[c if big > 0 else -c for c in node] for node in shape]


def _eigen(ops, out):
    _frame(ops)
    out["eigen.values"] = ops.eigen(3)
    out["eigen.shapes"] = [_signed([ops.nodeEigenvector(n, mode) for n in (3, 4, 5, 6)]) for mode in (1, 2, 3)]
    roof = ops.nodeEigenvector(5, 1, 1)
    out["eigen.|dof|"] = abs(roof)
    out["eigen.dof agrees with the shape"] = roof == ops.nodeEigenvector(5, 1)[0]
    out["eigen.full"] = ops.eigen("-fullGenLapack", 3)
    out["eigen.full shapes"] = [_signed([ops.nodeEigenvector(n, mode) for n in (3, 4, 5, 6)]) for mode in (1, 2, 3)]


def _pushover(ops, out):
    _frame(ops)
    out["gravity.code"] = _gravity(ops)
    out["gravity.disp"] = [ops.nodeDisp(n) for n in (3, 4, 5, 6)]
    out["gravity.time"] = ops.getTime()
    ops.loadConst("-time", 0.0)
    out["gravity.time after loadConst"] = ops.getTime()
    out["gravity.factor after loadConst"] = ops.getLoadFactor(1)

    ops.recorder("Node", "-file", "roof.out", "-time", "-node", 5, "-dof", 1, "disp")
    ops.recorder("Element", "-file", "braces.out", "-time", "-ele", 7, 8, "axialForce")
    ops.timeSeries("Linear", 2)
    ops.pattern("Plain", 2, 2)
    ops.load(3, 1.0, 0.0, 0.0)
    ops.load(5, 2.0, 0.0, 0.0)
    ops.wipeAnalysis()
    ops.constraints("Plain")
    ops.numberer("RCM")
    ops.system("UmfPack")
    ops.test("NormDispIncr", 1.0e-10, 3)
    ops.algorithm("Newton")
    target, du = 0.12, 0.004
    ops.integrator("DisplacementControl", 5, 1, du)
    ops.analysis("Static")
    out["push.systemSize"] = ops.systemSize()

    # The examples' loop: on failure try other algorithms, then halve the step.
    history, tries = [], []
    ok = 0
    while ok == 0 and ops.nodeDisp(5, 1) < target - 1e-12:
        ok = ops.analyze(1)
        tries.append(("Newton", ok))
        if ok != 0:
            ops.algorithm("ModifiedNewton", "-initial")
            ok = ops.analyze(1)
            tries.append(("ModifiedNewton", ok))
            ops.algorithm("Newton")
        if ok != 0:
            ops.algorithm("NewtonLineSearch", 0.8)
            ok = ops.analyze(1)
            tries.append(("NewtonLineSearch", ok))
            ops.algorithm("Newton")
        if ok != 0:
            ops.test("NormDispIncr", 1.0e-10, 50)
            ops.integrator("DisplacementControl", 5, 1, du / 4.0)
            ok = ops.analyze(4)
            tries.append(("quarter step, more iterations", ok))
            ops.integrator("DisplacementControl", 5, 1, du)
            ops.test("NormDispIncr", 1.0e-10, 3)
        history.append([ops.getTime(), ops.nodeDisp(5, 1), ops.testIter()])
    out["push.ok"] = ok
    out["push.tries"] = tries
    out["push.history"] = history
    out["push.testNorm"] = ops.testNorm()
    out["push.factor"] = ops.getLoadFactor(2)
    out["push.disp"] = [ops.nodeDisp(n) for n in (3, 4, 5, 6)]
    out["push.brace axialForce"] = [ops.eleResponse(e, "axialForce") for e in (7, 8)]
    out["push.brace strain"] = [ops.eleResponse(e, "material", 1, "strain") for e in (7, 8)]
    out["push.column force"] = [ops.eleResponse(e, "localForce") for e in (1, 2, 3, 4)]
    ops.reactions()
    out["push.reactions"] = [ops.nodeReaction(n) for n in (1, 2)]
    out["push.reaction dof"] = ops.nodeReaction(1, 1)
    out["push.unbalance"] = ops.nodeUnbalance(5)
    ops.wipe()


def _system_loop(ops, out):
    """Each system in turn: a fresh analysis of the same gravity step."""
    for name in SYSTEMS:
        _frame(ops)
        ops.timeSeries("Linear", 1)
        ops.pattern("Plain", 1, 1)
        ops.load(5, 40.0, -150.0, 0.0)
        ops.wipeAnalysis()
        ops.system(name)
        ops.constraints("Transformation")
        ops.numberer("Plain")
        ops.test("NormUnbalance", 1.0e-8, 10)
        ops.algorithm("Newton")
        ops.integrator("LoadControl", 1.0)
        ops.analysis("Static")
        out["system." + name + ".code"] = ops.analyze(1)
        out["system." + name + ".iter"] = ops.testIter()
        out["system." + name + ".disp"] = ops.nodeDisp(5)
    ops.wipe()


def _set_time(ops, out):
    _frame(ops)
    out["gravity2.code"] = _gravity(ops)
    ops.setTime(3.5)
    out["setTime"] = ops.getTime()
    ops.loadConst("-time", 1.25)
    out["loadConst time"] = ops.getTime()
    ops.loadConst()
    out["loadConst plain"] = ops.getTime()
    ops.wipe()


def run(ops):
    out = {}
    _eigen(ops, out)
    _pushover(ops, out)
    _system_loop(ops, out)
    _set_time(ops, out)
    return out

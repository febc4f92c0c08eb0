"""geomTransf('Corotational') in 2D with elasticBeamColumn, large
displacements under load control: a cantilever of 10 elements rolled up by
an end moment into a half circle, the same cantilever bent by a tip load,
and a shallow two-bar frame loaded at the crown; then the same frame with
joint offsets on one bar, where BeamSolid and OpenSeesPy differ on purpose
(compare.KNOWN_DIFFERENCES: OpenSees does not turn the offsets with
their node, so a rigid rotation strains the member).
"""
import math

L, N = 10.0, 10
E, A, I = 1.0e4, 1.0, 1.0 / 12.0


def _cantilever(ops):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    for i in range(N + 1):
        ops.node(i + 1, L * i / N, 0.0)
    ops.fix(1, 1, 1, 1)
    ops.geomTransf("Corotational", 1)
    for i in range(N):
        ops.element("elasticBeamColumn", i + 1, i + 1, i + 2, A, E, I, 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)


def _analysis(ops, dlambda, maxiter=30):
    ops.system("UmfPack")
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.test("NormDispIncr", 1e-10, maxiter)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", dlambda)
    ops.analysis("Static")


def _steps(ops, out, prefix, steps, node, ele):
    codes, iters, tips = [], [], []
    for _ in range(steps):
        codes.append(ops.analyze(1))
        iters.append(ops.testIter())
        tips.append(ops.nodeDisp(node))
    out[prefix + "codes"] = codes
    out[prefix + "testIter"] = iters
    out[prefix + "tip"] = tips
    out[prefix + "force"] = ops.eleResponse(ele, "force")
    out[prefix + "basicForce"] = ops.eleResponse(ele, "basicForce")
    out[prefix + "localForce"] = ops.eleResponse(ele, "localForce")
    out[prefix + "basicDeformation"] = ops.eleResponse(ele, "basicDeformation")
    ops.reactions()
    out[prefix + "reaction"] = ops.nodeReaction(1)


def run(ops):
    out = {}
    # 1. End moment pi EI / L rolls the cantilever into a half circle
    #    (OpenSeesPy 3.7.1 fails once a chord turns past pi; BeamSolid does
    #    not: see test_verification_corotational_2d.py for the full circle).
    _cantilever(ops)
    ops.load(N + 1, 0.0, 0.0, math.pi * E * I / L)
    _analysis(ops, 0.25)
    _steps(ops, out, "moment.", 4, N + 1, N)
    out["moment.mid"] = ops.nodeDisp(N // 2 + 1)

    # 2. Transverse tip load PL^2/EI = 5 (the elastica).
    _cantilever(ops)
    ops.load(N + 1, 0.0, -5.0 * E * I / L**2, 0.0)
    _analysis(ops, 0.2)
    _steps(ops, out, "tipload.", 5, N + 1, 1)

    # 3. Uniform transverse element load, which turns with the chord.
    _cantilever(ops)
    ops.eleLoad("-ele", *range(1, N + 1), "-type", "-beamUniform", -2.0 * E * I / L**3)
    _analysis(ops, 0.25)
    _steps(ops, out, "uniform.", 4, N + 1, 1)

    # 4. A shallow two-bar frame, crown load; 5. the same with rigid arms.
    for label, offsets in (("arch.", ()), ("offsets.", ("-jntOffset", 0.1, 0.05, -0.2, 0.02))):
        ops.wipe()
        ops.model("basic", "-ndm", 2, "-ndf", 3)
        ops.node(1, 0.0, 0.0)
        ops.node(2, 5.0, 0.4)
        ops.node(3, 10.0, 0.0)
        ops.fix(1, 1, 1, 0)
        ops.fix(3, 1, 1, 0)
        ops.geomTransf("Corotational", 1)
        ops.geomTransf("Corotational", 2, *offsets)
        ops.element("elasticBeamColumn", 1, 1, 2, 5.0, 2.0e4, 0.3, 1)
        ops.element("elasticBeamColumn", 2, 2, 3, 5.0, 2.0e4, 0.3, 2)
        ops.timeSeries("Linear", 1)
        ops.pattern("Plain", 1, 1)
        ops.load(2, 0.0, -60.0, 0.0)
        _analysis(ops, 0.25)
        _steps(ops, out, label, 4, 2, 2)
        out[label + "ele1.force"] = ops.eleResponse(1, "force")
    return out

"""3D truss of ElasticPP bars loaded by LoadControl beyond first yield.

Five bars meet at one free node (3 dofs, statically indeterminate twice), so
bars yield one after the other while the structure stays stable. The same
load history runs under several convergence tests and algorithms; the
iteration count and norms of every step are returned, plus the adaptive
LoadControl (numIter, minIncr, maxIncr) increments.
"""

E = 200.0e3
EPSY = 0.002
SUPPORTS = [(-1.5, -1.2, 0.0), (1.6, -1.1, 0.0), (1.4, 1.5, 0.0), (-1.3, 1.4, 0.0), (0.1, -1.8, 0.4)]
AREAS = [1.0, 1.3, 0.8, 1.1, 0.6]
APEX = (0.2, 0.1, 2.0)
LOAD = (120.0, 60.0, -900.0)


def _build(ops, element="truss", ndf=3):
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", ndf)
    ops.uniaxialMaterial("ElasticPP", 1, E, EPSY)
    ops.node(100, *APEX)
    for i, x in enumerate(SUPPORTS, start=1):
        ops.node(i, *x)
        ops.fix(i, *([1] * ndf))
        ops.element(element, i, i, 100, AREAS[i - 1], 1)
    if ndf == 6:
        ops.fix(100, 0, 0, 0, 1, 1, 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(100, *LOAD, *([0.0] * (ndf - 3)))
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.system("UmfPack")


def _history(ops, out, prefix, steps):
    iters, norms, times, disps, codes = [], [], [], [], []
    for _ in range(steps):
        codes.append(ops.analyze(1))
        iters.append(ops.testIter())
        norms.append(list(ops.testNorm()))
        times.append(ops.getTime())
        disps.append(ops.nodeDisp(100)[:3])
    out[prefix + "codes"] = codes
    out[prefix + "testIter"] = iters
    out[prefix + "testNorm"] = norms
    out[prefix + "time"] = times
    out[prefix + "disp"] = disps
    out[prefix + "axialForce"] = [ops.eleResponse(e, "axialForce") for e in range(1, 6)]
    out[prefix + "stress"] = [ops.eleResponse(e, "material", 1, "stress") for e in range(1, 6)]
    out[prefix + "strain"] = [ops.eleResponse(e, "material", 1, "strain") for e in range(1, 6)]
    ops.reactions()
    out[prefix + "reactions"] = [ops.nodeReaction(i)[:3] for i in range(1, 6)]


def run(ops):
    out = {}
    tests = [("NormUnbalance", 1e-8), ("NormDispIncr", 1e-12), ("EnergyIncr", 1e-16)]
    for test, tol in tests:
        for algorithm in ("Newton", "ModifiedNewton"):
            _build(ops)
            ops.test(test, tol, 50)
            ops.algorithm(algorithm)
            ops.integrator("LoadControl", 0.1)
            ops.analysis("Static")
            _history(ops, out, f"{test}.{algorithm}.", 11)
    # Large displacement bars on ndf 6 nodes.
    _build(ops, "corotTruss", 6)
    ops.test("NormUnbalance", 1e-8, 50)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", 0.1)
    ops.analysis("Static")
    _history(ops, out, "corotTruss.", 11)
    # Adaptive LoadControl: dLambda *= numIter / iterations of the last step.
    _build(ops)
    ops.test("NormDispIncr", 1e-12, 50)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", 0.1, 2, 0.02, 0.15)
    ops.analysis("Static")
    _history(ops, out, "adaptive.", 12)
    _build(ops)
    ops.test("NormDispIncr", 1e-12, 50)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", 0.05, 3, 0.01, 0.15)
    ops.analysis("Static")
    _history(ops, out, "adaptive-grow.", 8)
    # Past the collapse load (two more bars yield, three elastic bars are
    # needed): the step fails and the model stays at its last converged state.
    _build(ops)
    ops.test("NormUnbalance", 1e-8, 10)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", 1.1)
    ops.analysis("Static")
    out["failure.first"] = ops.analyze(1)
    ops.integrator("LoadControl", 0.2)
    out["failure.code"] = ops.analyze(1)
    out["failure.time"] = ops.getTime()
    out["failure.disp"] = ops.nodeDisp(100)
    out["failure.axialForce"] = [ops.eleResponse(e, "axialForce") for e in range(1, 6)]
    ops.wipe()
    return out

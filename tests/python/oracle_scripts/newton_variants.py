"""The Newton variants public examples fall back on, and testIter after a failure.

A Steel02 bar loaded past yield in one step: each algorithm's iteration count,
its norms and the converged displacement; RaphsonNewton with its -iterate and
-increment tangents, PeriodicNewton with its default and given -maxDim; a
failed step (ModifiedNewton from the elastic tangent cannot reach 1e-12 in 30
iterations), after which OpenSees' testIter reads one more than the
iterations numIter counts.
"""

ALGORITHMS = (
    ("Newton",),
    ("ModifiedNewton",),
    ("RaphsonNewton",),
    ("RaphsonNewton", "-initial"),
    ("RaphsonNewton", "-iterate", "initial"),
    ("RaphsonNewton", "-increment", "initial"),
    ("RaphsonNewton", "-iterate", "noTangent"),
    ("PeriodicNewton",),
    ("PeriodicNewton", "-maxDim", 2),
    ("PeriodicNewton", "-maxDim", 5),
    ("PeriodicNewton", "-initial"),
)


def _bar(ops, algorithm, load):
    ops.wipe()
    ops.model("basic", "-ndm", 1, "-ndf", 1)
    ops.node(1, 0.0)
    ops.node(2, 1.0)
    ops.fix(1, 1)
    ops.uniaxialMaterial("Steel02", 1, 1.0, 100.0, 0.05, 18.0, 0.925, 0.15)
    ops.element("Truss", 1, 1, 2, 1.0, 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, load)
    ops.system("UmfPack")
    ops.numberer("Plain")
    ops.constraints("Plain")
    ops.test("NormUnbalance", 1.0e-12, 30)
    ops.algorithm(*algorithm)
    ops.integrator("LoadControl", 1.0)
    ops.analysis("Static")


def run(ops):
    out = {}
    for algorithm in ALGORITHMS:
        key = " ".join(str(a) for a in algorithm)
        _bar(ops, algorithm, 1.3)
        code = ops.analyze(1)
        out[key + ".code"] = code
        out[key + ".testIter"] = ops.testIter()
        out[key + ".numIter"] = ops.numIter()
        out[key + ".norms"] = ops.testNorm()[: ops.numIter()]
        out[key + ".u"] = ops.nodeDisp(2, 1)
        # a second step from the yielded state: unloading then reloading
        ops.integrator("LoadControl", -1.5)
        out[key + ".unload code"] = ops.analyze(1)
        out[key + ".unload testIter"] = ops.testIter()
        out[key + ".unload u"] = ops.nodeDisp(2, 1)
    ops.wipe()
    return out

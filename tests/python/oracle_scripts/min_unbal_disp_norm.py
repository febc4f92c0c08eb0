"""integrator MinUnbalDispNorm past limit points: a softening spring in series
with an elastic one (1D; the default increment and the Jd/min/max adaptation)
and the von Mises two-bar truss of corotTrusses snapping through (2D; Newton
and ModifiedNewton): load factor, displacement and iterations at every step.
"""


def _softening_chain(ops, args):
    ops.wipe()
    ops.model("basic", "-ndm", 1, "-ndf", 1)
    for tag in (1, 2, 3):
        ops.node(tag, 0.0)
    ops.fix(1, 1)
    ops.uniaxialMaterial("Steel01", 1, 10.0, 100.0, -0.05)
    ops.uniaxialMaterial("Elastic", 2, 50.0)
    ops.element("zeroLength", 1, 1, 2, "-mat", 1, "-dir", 1)
    ops.element("zeroLength", 2, 2, 3, "-mat", 2, "-dir", 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(3, 1.0)
    ops.system("UmfPack")
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.test("NormDispIncr", 1e-10, 30)
    ops.algorithm("Newton")
    ops.integrator("MinUnbalDispNorm", *args)
    ops.analysis("Static")


def _von_mises_truss(ops, algorithm):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 2)
    ops.node(1, 0.0, 0.0)
    ops.node(2, 10.0, 1.0)
    ops.node(3, 20.0, 0.0)
    ops.fix(1, 1, 1)
    ops.fix(3, 1, 1)
    ops.fix(2, 1, 0)
    ops.uniaxialMaterial("Elastic", 1, 1000.0)
    ops.element("corotTruss", 1, 1, 2, 1.0, 1)
    ops.element("corotTruss", 2, 2, 3, 1.0, 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, 0.0, -1.0)
    ops.system("BandGeneral")
    ops.constraints("Plain")
    ops.numberer("RCM")
    ops.test("NormDispIncr", 1e-10, 50)
    ops.algorithm(algorithm)
    ops.integrator("MinUnbalDispNorm", 0.05)
    ops.analysis("Static")


def run(ops):
    out = {}
    for name, args in (("default", (2.0,)), ("adaptive", (2.0, 3, 0.5, 4.0))):
        _softening_chain(ops, args)
        for step in range(25):
            out[f"{name}.{step}"] = [ops.analyze(1), ops.testIter(), ops.getTime(), ops.nodeDisp(3, 1)]
    for algorithm in ("Newton", "ModifiedNewton"):
        _von_mises_truss(ops, algorithm)
        for step in range(60):
            out[f"truss.{algorithm}.{step}"] = [ops.analyze(1), ops.testIter(), ops.getTime(), ops.nodeDisp(2, 2)]
    return out

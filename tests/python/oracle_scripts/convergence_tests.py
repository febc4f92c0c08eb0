"""The convergence tests NormDispAndUnbalance, NormDispOrUnbalance,
RelativeEnergyIncr and RelativeTotalNormDispIncr on a two-bar Steel02 truss
chain pulled past yield: every step's return code, testIter, testNorm and
displacement, with Newton (a few iterations a step), ModifiedNewton (many,
linear convergence) and a maxIter too small (the failed step's testIter and
norms). The And/Or tests are given pFlag (and nType): OpenSeesPy 3.7.1 reads
test('NormDispAndUnbalance', tolIncr, tolR, iter) with 25 iterations and
only the unbalance norms, and with maxIncr given it takes nType as iter;
BeamSolid follows the documented arguments in every form (docs/commands.md).
"""

TESTS = (
    ("and", ("NormDispAndUnbalance", 1e-9, 1e-7, 30, 0)),
    ("and.max", ("NormDispAndUnbalance", 1e-9, 1e-7, 30, 0, 0)),
    ("and.1norm", ("NormDispAndUnbalance", 1e-9, 1e-7, 30, 0, 1)),
    ("or", ("NormDispOrUnbalance", 1e-9, 1e-7, 30, 0)),
    ("or.loose", ("NormDispOrUnbalance", 1e-3, 1e-12, 30, 0, 2)),
    ("relEnergy", ("RelativeEnergyIncr", 1e-12, 30)),
    ("relEnergy.max", ("RelativeEnergyIncr", 1e-12, 30, 0, 0)),
    ("relTotal", ("RelativeTotalNormDispIncr", 1e-9, 30)),
    ("relTotal.1norm", ("RelativeTotalNormDispIncr", 1e-9, 30, 0, 1)),
    ("and.short", ("NormDispAndUnbalance", 1e-12, 1e-10, 3, 0)),
    ("relTotal.short", ("RelativeTotalNormDispIncr", 1e-12, 2)),
)


def _model(ops):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 2)
    ops.node(1, 0.0, 0.0)
    ops.node(2, 1.0, 0.0)
    ops.node(3, 2.0, 0.5)
    ops.fix(1, 1, 1)
    ops.fix(2, 0, 1)
    ops.fix(3, 0, 1)
    ops.uniaxialMaterial("Steel02", 1, 10.0, 1000.0, 0.05, 18.0, 0.925, 0.15)
    ops.uniaxialMaterial("Steel02", 2, 14.0, 800.0, 0.02, 15.0, 0.9, 0.1)
    ops.element("Truss", 1, 1, 2, 1.0, 1)
    ops.element("Truss", 2, 2, 3, 1.2, 2)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(3, 1.0, 0.0)
    ops.system("UmfPack")
    ops.constraints("Plain")
    ops.numberer("Plain")


def run(ops):
    out = {}
    for algorithm in ("Newton", "ModifiedNewton"):
        for name, test in TESTS:
            _model(ops)
            ops.test(*test)
            ops.algorithm(algorithm)
            ops.integrator("LoadControl", 3.0)
            ops.analysis("Static")
            steps = []
            for _ in range(5):
                code = ops.analyze(1)
                steps.append({"code": code, "testIter": ops.testIter(), "testNorm": ops.testNorm(),
                              "disp": ops.nodeDisp(3, 1)})
            key = f"{algorithm}.{name}"
            out[key + ".codes"] = [s["code"] for s in steps]
            out[key + ".testIter"] = [s["testIter"] for s in steps]
            out[key + ".disp"] = [s["disp"] for s in steps]
            for k, s in enumerate(steps):
                out[f"{key}.testNorm{k}"] = s["testNorm"]
    ops.wipe()
    return out

"""printA and printB after an analysis: the system matrix (FullGeneral, the
one system OpenSees returns it for) and the right-hand side left after the
last iteration, returned ('-ret') and written ('-file'), for a 2D truss
(Plain constraints) and a 2D portal frame whose beam ends share the sway by
equalDOF (Transformation), both numbered Plain. The right-hand side of a
converged step is round-off: only its size and smallness are compared.
"""


def _truss(ops):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 2)
    ops.node(1, 0.0, 0.0)
    ops.node(2, 4.0, 0.0)
    ops.node(3, 2.0, 3.0)
    ops.node(4, 6.0, 3.0)
    ops.fix(1, 1, 1)
    ops.fix(2, 0, 1)
    ops.uniaxialMaterial("Steel01", 1, 30.0, 100.0, 0.1)
    for e, (i, j) in enumerate(((1, 2), (1, 3), (2, 3), (3, 4), (2, 4)), start=1):
        ops.element("Truss", e, i, j, 1.0, 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(3, 1.0, -2.0)
    ops.load(4, 0.5, -1.0)
    ops.constraints("Plain")


def _frame(ops):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    for tag, (x, y) in enumerate(((0.0, 0.0), (5.0, 0.0), (0.0, 3.0), (5.0, 3.0)), start=1):
        ops.node(tag, x, y)
    ops.fix(1, 1, 1, 1)
    ops.fix(2, 1, 1, 0)
    ops.geomTransf("Linear", 1)
    ops.element("elasticBeamColumn", 1, 1, 3, 0.02, 2e5, 1e-4, 1)
    ops.element("elasticBeamColumn", 2, 2, 4, 0.02, 2e5, 1e-4, 1)
    ops.element("elasticBeamColumn", 3, 3, 4, 0.03, 2e5, 3e-4, 1)
    ops.equalDOF(3, 4, 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(3, 10.0, -5.0, 0.0)
    ops.load(4, 0.0, -5.0, 2.0)
    ops.constraints("Transformation")


def run(ops):
    out = {}
    for name, build in (("truss", _truss), ("frame", _frame)):
        build(ops)
        ops.numberer("Plain")
        ops.system("FullGeneral")
        ops.test("NormDispIncr", 1e-12, 30)
        ops.algorithm("Newton")
        ops.integrator("LoadControl", 5.0)
        ops.analysis("Static")
        for step in range(3):
            out[f"{name}.code {step}"] = ops.analyze(1)
            out[f"{name}.A {step}"] = ops.printA("-ret")
            b = ops.printB("-ret")
            out[f"{name}.B size {step}"] = len(b)
            out[f"{name}.B is round-off {step}"] = max(abs(v) for v in b) < 1e-9
        ops.printA("-file", f"A_{name}.txt")
        with open(f"A_{name}.txt") as f:
            out[f"file:A_{name}.txt"] = f.read()
    return out

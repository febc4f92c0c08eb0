"""SecantNewton, BFGS and Broyden against Newton on two nonlinear models.

A 2D truss whose bars harden (Steel01, Hardening) and soften
(ElasticMultiLinear with a falling branch) under proportional load steps, and
an RC column of displacement-based fiber elements (Concrete01 core and cover,
Steel01 bars) under axial load held by loadConst, then pushed sideways by
DisplacementControl past the peak. Every algorithm option the manuals list
(-count, -initial; -iterate, -increment, -maxDim, -cutOut) reaches the same
converged states; return codes and iteration counts are compared as well
(for BFGS and Broyden OpenSees' testIter counts tangent cycles, and so does
BeamSolid's).
"""


def _truss(ops):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 2)
    for tag, (x, y) in enumerate(((0, 0), (3, 0), (6, 0), (1.5, 2), (4.5, 2.5)), start=1):
        ops.node(tag, float(x), float(y))
    ops.fix(1, 1, 1)
    ops.fix(3, 1, 1)
    ops.uniaxialMaterial("Steel01", 1, 50.0, 1000.0, 0.05)
    ops.uniaxialMaterial("ElasticMultiLinear", 2, 0.0, "-strain", -1.0, -0.04, 0.0, 0.03, 1.0,
                         "-stress", -50.0, -40.0, 0.0, 45.0, 30.0)
    ops.uniaxialMaterial("Hardening", 3, 800.0, 40.0, 0.0, 100.0)
    bars = ((1, 4, 1), (4, 2, 2), (2, 5, 3), (5, 3, 1), (4, 5, 2), (1, 2, 3), (2, 3, 1))
    for e, (i, j, m) in enumerate(bars, start=1):
        ops.element("Truss", e, i, j, 1.0, m)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(4, 1.0, -2.0)
    ops.load(5, 0.5, -3.0)
    ops.load(2, 0.0, -1.0)
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.system("UmfPack")
    ops.test("NormDispIncr", 1e-10, 100)


TRUSS_ALGORITHMS = (
    ("Newton",),
    ("SecantNewton",),
    ("SecantNewton", "-increment", "initial"),
    ("SecantNewton", "-maxDim", 5),
    ("SecantNewton", "-cutOut", 3.5, 0.3),
    ("BFGS",),
    ("BFGS", "-count", 3),
    ("Broyden",),
    ("Broyden", "-count", 4),
    ("Broyden", "-initial"),
)


def _column(ops):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    height = 120.0
    for i in range(4):
        ops.node(i + 1, 0.0, height * i / 3)
    ops.fix(1, 1, 1, 1)
    ops.uniaxialMaterial("Concrete01", 1, -6.0, -0.004, -5.0, -0.014)
    ops.uniaxialMaterial("Concrete01", 2, -5.0, -0.002, 0.0, -0.006)
    ops.uniaxialMaterial("Steel01", 3, 60.0, 30000.0, 0.01)
    b, h, cover, bar = 15.0, 20.0, 1.5, 0.6
    y1, z1 = h / 2.0, b / 2.0
    ops.section("Fiber", 1)
    ops.patch("rect", 1, 8, 1, cover - y1, cover - z1, y1 - cover, z1 - cover)
    ops.patch("rect", 2, 8, 1, -y1, z1 - cover, y1, z1)
    ops.patch("rect", 2, 8, 1, -y1, -z1, y1, cover - z1)
    ops.layer("straight", 3, 3, bar, y1 - cover, z1 - cover, y1 - cover, cover - z1)
    ops.layer("straight", 3, 3, bar, cover - y1, z1 - cover, cover - y1, cover - z1)
    ops.geomTransf("PDelta", 1)
    ops.beamIntegration("Lobatto", 1, 1, 4)
    for e in range(3):
        ops.element("dispBeamColumn", e + 1, e + 1, e + 2, 1, 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(4, 0.0, -150.0, 0.0)
    ops.constraints("Plain")
    ops.numberer("RCM")
    ops.system("BandGeneral")
    ops.test("NormDispIncr", 1e-12, 60)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", 0.25)
    ops.analysis("Static")
    ops.analyze(4)
    ops.loadConst("-time", 0.0)
    ops.timeSeries("Linear", 2)
    ops.pattern("Plain", 2, 2)
    ops.load(4, 1.0, 0.0, 0.0)


# OpenSees' BFGS and Broyden diverge under DisplacementControl (their updates
# ignore the load factor the integrator solves for), so they push the column
# by LoadControl up to 90% of its capacity; the Newton-type algorithms past the
# peak by DisplacementControl.
COLUMN_ALGORITHMS = (
    (("Newton",), "DisplacementControl"),
    (("SecantNewton",), "DisplacementControl"),
    (("SecantNewton", "-iterate", "initial", "-maxDim", 6), "DisplacementControl"),
    (("Newton",), "LoadControl"),
    (("BFGS",), "LoadControl"),
    (("BFGS", "-count", 4), "LoadControl"),
    (("Broyden",), "LoadControl"),
    (("Broyden", "-count", 5), "LoadControl"),
)


LOAD_STEP = 1.2


def run(ops):
    out = {}
    for alg in TRUSS_ALGORITHMS:
        key = "truss " + " ".join(str(a) for a in alg) + "."
        _truss(ops)
        ops.algorithm(*alg)
        ops.integrator("LoadControl", 2.0)
        ops.analysis("Static")
        codes, iters, disp = [], [], []
        for _ in range(8):
            codes.append(ops.analyze(1))
            iters.append(ops.testIter())
            disp.append([ops.nodeDisp(n, d) for n in (2, 4, 5) for d in (1, 2)])
        out[key + "codes"] = codes
        out[key + "testIter"] = iters
        out[key + "disp"] = disp
        out[key + "basicForce"] = [ops.eleResponse(e, "basicForce")[0] for e in range(1, 8)]
    for alg, control in COLUMN_ALGORITHMS:
        key = f"column {control} " + " ".join(str(a) for a in alg) + "."
        _column(ops)
        ops.algorithm(*alg)
        if control == "DisplacementControl":
            ops.integrator("DisplacementControl", 4, 1, 0.15)
        else:
            # 1e-10, not 1e-12: near 1e-12 the last quasi-Newton iterates differ by
            # round-off and a step can take one more cycle on one side.
            ops.test("NormDispIncr", 1e-10, 60)
            ops.integrator("LoadControl", LOAD_STEP)
        codes, iters, disp, lam = [], [], [], []
        # Plain SecantNewton's 19th step wanders for ~55 iterations near the peak before it meets
        # 1e-12, and which iterate meets it depends on round-off (the norms of both programs part
        # at the 1e-9 level after 20 iterations; BeamSolid takes 56, 58 or 59 by the BLAS kernel):
        # that case stops after 18 steps.
        steps = 18 if alg == ("SecantNewton",) and control == "DisplacementControl" else 20
        for _ in range(steps):
            codes.append(ops.analyze(1))
            iters.append(ops.testIter())
            lam.append(ops.getLoadFactor(2))
            disp.append([ops.nodeDisp(n, d) for n in (2, 3, 4) for d in (1, 2, 3)])
        out[key + "codes"] = codes
        out[key + "testIter"] = iters
        out[key + "loadFactor"] = lam
        out[key + "disp"] = disp
        out[key + "section force"] = ops.eleResponse(1, "section", 1, "force")
    return out

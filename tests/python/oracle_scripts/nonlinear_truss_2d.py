"""2D truss (ndm 2, ndf 2) of four bars meeting at one free node, with
Hardening, Parallel (Steel01 + Elastic), Series (Elastic + Hardening) and
MinMax (Steel01 failing at a strain limit) materials, under LoadControl to
first yield and beyond, until the MinMax bar fails and the others carry the
load. Iteration counts, displacements, bar forces and material responses
at every step; then a 2D zeroLength with -orient and a rotational spring
(ndf 3) loaded past yield.
"""

SUPPORTS = [(-1.0, 0.0), (-0.4, 0.0), (0.5, 0.0), (1.2, 0.0)]
APEX = (0.1, 1.5)


def _truss(ops, out):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 2)
    ops.uniaxialMaterial("Hardening", 1, 200.0e3, 250.0, 1000.0, 2000.0)
    ops.uniaxialMaterial("Steel01", 2, 300.0, 200.0e3, 0.02)
    ops.uniaxialMaterial("Elastic", 3, 5.0e3)
    ops.uniaxialMaterial("Parallel", 4, 2, 3)
    ops.uniaxialMaterial("Elastic", 5, 400.0e3)
    ops.uniaxialMaterial("Hardening", 6, 200.0e3, 200.0, 0.0, 4000.0)
    ops.uniaxialMaterial("Series", 7, 5, 6)
    ops.uniaxialMaterial("MinMax", 8, 2, "-max", 0.0007)
    ops.node(100, *APEX)
    for i, (x, mat, area) in enumerate(zip(SUPPORTS, (1, 4, 7, 8), (1.0, 0.8, 1.2, 0.9)), start=1):
        ops.node(i, *x)
        ops.fix(i, 1, 1)
        ops.element("truss", i, i, 100, area, mat)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(100, 100.0, 800.0)
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.system("UmfPack")
    ops.test("NormDispIncr", 1e-10, 50)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", 0.05)
    ops.analysis("Static")
    codes, iters, disps, forces, stresses = [], [], [], [], []
    for _ in range(26):
        codes.append(ops.analyze(1))
        iters.append(ops.testIter())
        disps.append(ops.nodeDisp(100))
        forces.append([ops.eleResponse(e, "axialForce")[0] for e in range(1, 5)])
        stresses.append([ops.eleResponse(e, "material", 1, "stress")[0] for e in range(1, 5)])
    out["truss.codes"] = codes
    out["truss.testIter"] = iters
    out["truss.disp"] = disps
    out["truss.axialForce"] = forces
    out["truss.stress"] = stresses
    out["truss.strain"] = [ops.eleResponse(e, "material", 1, "strain") for e in range(1, 5)]
    ops.reactions()
    out["truss.reactions"] = [ops.nodeReaction(i) for i in range(1, 5)]


def _zero_length_2d(ops, out):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    ops.node(1, 0.0, 0.0)
    ops.node(2, 0.0, 0.0)
    ops.fix(1, 1, 1, 1)
    ops.uniaxialMaterial("Hardening", 1, 100.0, 1.5, 2.0, 3.0)
    ops.uniaxialMaterial("Elastic", 2, 40.0)
    ops.uniaxialMaterial("MultiLinear", 3, 0.01, 0.2, 0.05, 0.5)
    # yp is ignored in 2D (OpenSees takes (-x2, x1, 0)).
    ops.element("zeroLength", 1, 1, 2, "-mat", 1, 2, 3, "-dir", 1, 2, 3, "-orient", 2.0, 1.0, 0.0, 0.3, -0.2, 1.0)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, 2.0, -0.5, 0.6)
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.system("UmfPack")
    ops.test("NormDispIncr", 1e-12, 30)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", 0.1)
    ops.analysis("Static")
    codes, iters, disps = [], [], []
    for _ in range(10):
        codes.append(ops.analyze(1))
        iters.append(ops.testIter())
        disps.append(ops.nodeDisp(2))
    out["zl2d.codes"] = codes
    out["zl2d.testIter"] = iters
    out["zl2d.disp"] = disps
    for r in ("force", "localForce", "basicForce", "deformation", "basicDeformation", "xaxis",
              "yaxis", "zaxis"):
        out["zl2d." + r] = ops.eleResponse(1, r)
    out["zl2d.material3.stress"] = ops.eleResponse(1, "material", 3, "stress")
    ops.reactions()
    out["zl2d.reaction"] = ops.nodeReaction(1)


def run(ops):
    out = {}
    _truss(ops, out)
    _zero_length_2d(ops, out)
    return out

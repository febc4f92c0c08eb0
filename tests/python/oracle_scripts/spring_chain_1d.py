"""1D chain of zeroLength springs (ndm 1, ndf 1) under cyclic
DisplacementControl of the free end: a Hardening spring, a MultiLinear
spring, a Parallel (Elastic + Hardening) spring and a Hysteretic spring
(pinching, damage, degraded unloading) in series, then an -orient case
whose local x points backwards. The springs yield one after
the other and unload with their own rules; iteration counts, the node
displacements, spring forces and deformations are returned at every step.
"""


def _spring_chain(ops, out, prefix, orient):
    ops.wipe()
    ops.model("basic", "-ndm", 1, "-ndf", 1)
    for i, x in enumerate((0.0, 0.0, 0.0, 0.0, 0.0), start=1):
        ops.node(i, x)
    ops.fix(1, 1)
    ops.uniaxialMaterial("Hardening", 1, 100.0, 2.0, 5.0, 10.0)
    ops.uniaxialMaterial("MultiLinear", 2, 0.01, 1.5, 0.03, 2.5, 0.06, 3.0)
    ops.uniaxialMaterial("Elastic", 3, 60.0)
    ops.uniaxialMaterial("Hardening", 4, 80.0, 1.0, 0.0, 2.0)
    ops.uniaxialMaterial("Parallel", 5, 3, 4)
    ops.uniaxialMaterial("Hysteretic", 6, 1.2, 0.01, 1.8, 0.03, 2.0, 0.08, -1.0, -0.008, -1.6, -0.03, -1.9, -0.09,
                         0.6, 0.3, 0.02, 0.02, 0.2)
    extra = ["-orient", -1.0, 0.0, 0.0, 0.0, 1.0, 0.0] if orient else []
    for e, mat in enumerate((1, 2, 5, 6), start=1):
        ops.element("zeroLength", e, e, e + 1, "-mat", mat, "-dir", 1, *extra)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(5, 1.0)
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.system("UmfPack")
    ops.test("NormDispIncr", 1e-12, 30)
    ops.algorithm("Newton")
    codes, iters, disps, forces, defs, lam = [], [], [], [], [], []
    sign = -1.0 if orient else 1.0
    for increment, steps in ((0.012, 10), (-0.014, 16), (0.016, 14), (-0.015, 14), (0.012, 8)):
        ops.integrator("DisplacementControl", 5, 1, sign * increment)
        if not codes:
            ops.analysis("Static")
        for _ in range(steps):
            codes.append(ops.analyze(1))
            iters.append(ops.testIter())
            lam.append(ops.getLoadFactor(1))
            disps.append([ops.nodeDisp(n, 1) for n in (2, 3, 4, 5)])
            forces.append([ops.eleResponse(e, "basicForce")[0] for e in (1, 2, 3, 4)])
            defs.append([ops.eleResponse(e, "deformation")[0] for e in (1, 2, 3, 4)])
    out[prefix + "codes"] = codes
    out[prefix + "testIter"] = iters
    out[prefix + "loadFactor"] = lam
    out[prefix + "disp"] = disps
    out[prefix + "basicForce"] = forces
    out[prefix + "deformation"] = defs
    out[prefix + "force"] = [ops.eleResponse(e, "force") for e in (1, 2, 3, 4)]
    out[prefix + "material.stress"] = [ops.eleResponse(e, "material", 1, "stress") for e in (1, 2, 3, 4)]
    out[prefix + "material.tangent"] = [ops.eleResponse(e, "material", 1, "tangent") for e in (1, 2, 3, 4)]
    ops.reactions()
    out[prefix + "reaction"] = ops.nodeReaction(1)


def run(ops):
    out = {}
    _spring_chain(ops, out, "global.", orient=False)
    _spring_chain(ops, out, "reversed.", orient=True)
    return out

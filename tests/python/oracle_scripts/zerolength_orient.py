"""zeroLength springs with -orient local axes: translational springs on
ndf 3 nodes, translational and rotational springs on ndf 6 nodes, and an
ElasticPP spring loaded past yield. The two nodes are coincident except in
the last case (a zeroLength does not need coincident nodes).
"""

X_AXIS = (1.0, 1.0, 0.3)
YP = (-0.4, 1.0, 0.8)


def _analyse(ops, steps=1, dlambda=1.0, handler="Plain"):
    ops.system("UmfPack")
    ops.constraints(handler)
    ops.numberer("Plain")
    ops.test("NormDispIncr", 1e-12, 20)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", dlambda)
    ops.analysis("Static")
    return [ops.analyze(1) for _ in range(steps)]


def _responses(ops, out, prefix, tag, nmat):
    for r in ("force", "localForce", "basicForce", "deformation", "basicDeformation", "basicStiffness",
              "xaxis", "yaxis", "zaxis"):
        out[f"{prefix}{r}"] = ops.eleResponse(tag, r)
    out[prefix + "eleForce"] = ops.eleForce(tag)
    for k in range(1, nmat + 1):
        out[f"{prefix}material{k}.stress"] = ops.eleResponse(tag, "material", k, "stress")
        out[f"{prefix}material{k}.strain"] = ops.eleResponse(tag, "material", k, "strain")


def run(ops):
    out = {}
    # ndf 3: three translational springs along the oriented local axes.
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    ops.node(1, 1.0, 2.0, 3.0)
    ops.node(2, 1.0, 2.0, 3.0)
    ops.fix(1, 1, 1, 1)
    ops.uniaxialMaterial("Elastic", 1, 100.0)
    ops.uniaxialMaterial("Elastic", 2, 250.0)
    ops.uniaxialMaterial("Elastic", 3, 40.0)
    ops.element("zeroLength", 1, 1, 2, "-mat", 1, 2, 3, "-dir", 1, 2, 3, "-orient", *X_AXIS, *YP)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, 3.0, -2.0, 5.0)
    out["ndf3.codes"] = _analyse(ops)
    out["ndf3.disp"] = ops.nodeDisp(2)
    ops.reactions()
    out["ndf3.reaction"] = ops.nodeReaction(1)
    _responses(ops, out, "ndf3.", 1, 3)

    # ndf 6: all six directions, springs listed out of order.
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    ops.node(1, 0.0, 0.0, 0.0)
    ops.node(2, 0.0, 0.0, 0.0)
    ops.fix(1, 1, 1, 1, 1, 1, 1)
    for k, stiffness in enumerate((100.0, 250.0, 40.0, 7.0, 11.0, 5.0), start=1):
        ops.uniaxialMaterial("Elastic", k, stiffness)
    ops.element("zeroLength", 1, 1, 2, "-mat", 4, 1, 6, 2, 5, 3, "-dir", 4, 1, 6, 2, 5, 3, "-orient", *X_AXIS, *YP)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, 3.0, -2.0, 5.0, 0.4, -0.7, 0.2)
    out["ndf6.codes"] = _analyse(ops)
    out["ndf6.disp"] = ops.nodeDisp(2)
    ops.reactions()
    out["ndf6.reaction"] = ops.nodeReaction(1)
    _responses(ops, out, "ndf6.", 1, 6)

    # ElasticPP spring in local x past yield, elastic springs in y and z;
    # nodes 0.5 apart.
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    ops.node(1, 0.0, 0.0, 0.0)
    ops.node(2, 0.3, 0.4, 0.0)
    ops.fix(1, 1, 1, 1)
    ops.uniaxialMaterial("ElasticPP", 1, 100.0, 0.02)
    ops.uniaxialMaterial("Elastic", 2, 300.0)
    ops.element("zeroLength", 1, 1, 2, "-mat", 1, 2, 2, "-dir", 1, 2, 3, "-orient", *X_AXIS, *YP)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.sp(2, 1, 0.05)
    ops.load(2, 0.0, 1.0, 0.0)
    out["yield.codes"] = _analyse(ops, 4, 0.25, "Transformation")
    out["yield.disp"] = ops.nodeDisp(2)
    ops.reactions()
    out["yield.reaction"] = ops.nodeReaction(1)
    out["yield.reaction2"] = ops.nodeReaction(2)
    _responses(ops, out, "yield.", 1, 3)
    ops.wipe()
    return out

"""3D elastic cantilever frame: elasticBeamColumn with Linear and PDelta
transforms, joint offsets, -beamUniform and -beamPoint element loads and
reactions.

Two inclined members (not along a global axis, vecxz not orthogonal to the
axis) so that every local/global rotation is exercised; the second takes its
properties from an Elastic section (the section form).
"""

E, G = 200e6, 80e6
A, J, IY, IZ = 0.01, 2.0e-5, 1.2e-5, 3.0e-5

RESPONSES = ("force", "localForce", "basicForce", "basicDeformations")


def _build(ops, transf, offsets, point_loads=False):
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    ops.node(1, 0.0, 0.0, 0.0)
    ops.node(2, 0.4, 0.3, 2.0)
    ops.node(3, 0.9, 0.5, 4.1)
    ops.fix(1, 1, 1, 1, 1, 1, 1)
    vecxz = (1.0, -0.2, 0.1)
    if offsets:
        ops.geomTransf(transf, 1, *vecxz, "-jntOffset", 0.02, 0.01, 0.10, -0.01, 0.0, -0.05)
    else:
        ops.geomTransf(transf, 1, *vecxz)
    ops.geomTransf(transf, 2, 0.0, 1.0, 0.3)
    ops.element("elasticBeamColumn", 1, 1, 2, A, E, G, J, IY, IZ, 1)
    ops.section("Elastic", 7, E, A, IZ, IY, G, J)
    ops.element("elasticBeamColumn", 2, 2, 3, 7, 2)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(3, 3.0, -2.0, -40.0, 0.5, -0.3, 0.7)
    if point_loads:
        ops.eleLoad("-ele", 1, "-type", "-beamPoint", 2.5, -1.2, 0.3, 0.8)
        ops.eleLoad("-ele", 2, "-type", "-beamPoint", -0.7, 1.9, 0.65)
        ops.eleLoad("-ele", 1, 2, "-type", "-beamUniform", 0.2, 0.3)
    else:
        ops.eleLoad("-ele", 1, "-type", "-beamUniform", 1.5, -0.8, 0.6)
        ops.eleLoad("-ele", 2, "-type", "-beamUniform", -0.4, 1.1)
    ops.system("UmfPack")
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.test("NormDispIncr", 1e-12, 20)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", 0.5)
    ops.analysis("Static")


def _case(ops, transf, offsets, out, prefix, point_loads=False):
    _build(ops, transf, offsets, point_loads)
    codes = [ops.analyze(1) for _ in range(2)]
    out[prefix + "codes"] = codes
    out[prefix + "testIter"] = ops.testIter()
    out[prefix + "time"] = ops.getTime()
    for n in (2, 3):
        out[f"{prefix}disp{n}"] = ops.nodeDisp(n)
    ops.reactions()
    out[prefix + "reaction1"] = ops.nodeReaction(1)
    for e in (1, 2):
        for r in RESPONSES:
            out[f"{prefix}ele{e}.{r}"] = ops.eleResponse(e, r)
        out[f"{prefix}eleForce{e}"] = ops.eleForce(e)
    ops.wipe()


def run(ops):
    out = {}
    for transf in ("Linear", "PDelta"):
        for offsets in (False, True):
            _case(ops, transf, offsets, out, f"{transf}{'-offset' if offsets else ''}.")
        _case(ops, transf, True, out, f"{transf}-points.", point_loads=True)
    return out

"""beamIntegration HingeMidpoint and HingeEndpoint (and HingeRadau,
HingeRadauTwo for reference) on forceBeamColumn cantilevers: section
locations and weights, and a pushover with a Steel01 fiber hinge section and
an elastic interior: head displacement, base moment and iterations per step,
and the hinge section's deformation.
"""


def _cantilever(ops, rule, lp_i, lp_j):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    ops.node(1, 0.0, 0.0)
    ops.node(2, 0.0, 3.0)
    ops.fix(1, 1, 1, 1)
    ops.uniaxialMaterial("Steel01", 1, 300.0, 200000.0, 0.02)
    ops.section("Fiber", 1)
    ops.patch("rect", 1, 1, 10, -0.2, -0.1, 0.2, 0.1)
    ops.section("Elastic", 2, 200000.0, 0.08, 0.08 * 0.4**2 / 12)
    ops.geomTransf("Linear", 1)
    ops.beamIntegration(rule, 1, 1, lp_i, 1, lp_j, 2)
    ops.element("forceBeamColumn", 1, 1, 2, 1, 1)


def run(ops):
    out = {}
    for rule in ("HingeMidpoint", "HingeEndpoint", "HingeRadau", "HingeRadauTwo"):
        for lp_i, lp_j in ((0.3, 0.3), (0.45, 0.2)):
            key = f"{rule}.{lp_i}.{lp_j}"
            _cantilever(ops, rule, lp_i, lp_j)
            out[key + ".locations"] = ops.sectionLocation(1)
            out[key + ".weights"] = ops.sectionWeight(1)
        _cantilever(ops, rule, 0.3, 0.3)
        ops.timeSeries("Linear", 1)
        ops.pattern("Plain", 1, 1)
        ops.load(2, 1.0, 0.0, 0.0)
        ops.system("BandGeneral")
        ops.constraints("Plain")
        ops.numberer("Plain")
        ops.test("NormDispIncr", 1e-10, 30)
        ops.algorithm("Newton")
        ops.integrator("DisplacementControl", 2, 1, 0.004)
        ops.analysis("Static")
        for step in range(12):
            code = ops.analyze(1)
            ops.reactions()
            out[f"{rule}.push{step}"] = [code, ops.testIter(), ops.getTime(), ops.nodeReaction(1, 3)]
        out[f"{rule}.hinge"] = ops.eleResponse(1, "section", 1, "deformation")
    return out

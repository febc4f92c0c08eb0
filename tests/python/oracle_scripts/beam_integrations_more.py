"""beamIntegration rules with given or equally spaced points: UserDefined,
FixedLocation, MidDistance, LowOrder (no, some and all weights given, locations
out of order), Trapezoidal, CompositeSimpson (both argument forms). For each, a forceBeamColumn and a dispBeamColumn cantilever of a
Steel01 fiber section (a second elastic section at some points) pushed past
yield: sectionLocation, sectionWeight, every step's code, iteration count and
tip displacement, and the end section's forces.
"""

RULES = (
    ("UserDefined", (5, 1, 2, 2, 2, 1, 0.1, 0.3, 0.5, 0.7, 0.9, 0.2, 0.15, 0.3, 0.15, 0.2)),
    ("FixedLocation", (5, 1, 2, 2, 2, 1, 0.0, 0.2, 0.5, 0.8, 1.0)),
    ("FixedLocation", (4, 1, 1, 2, 2, 0.05, 0.3, 0.65, 0.9)),
    ("MidDistance", (5, 1, 2, 2, 2, 1, 0.0, 0.2, 0.5, 0.8, 1.0)),
    ("MidDistance", (3, 1, 1, 1, 0.1, 0.4, 0.85)),
    ("LowOrder", (5, 1, 2, 2, 2, 1, 0.0, 0.2, 0.5, 0.8, 1.0, 0.2, 0.2)),
    ("LowOrder", (4, 1, 1, 2, 2, 0.05, 0.3, 0.65, 0.9)),
    ("LowOrder", (3, 1, 2, 1, 0.0, 0.5, 1.0, 0.1, 0.8, 0.1)),
    ("LowOrder", (3, 1, 2, 1, 0.9, 0.5, 0.1, 0.3)),
    ("Trapezoidal", (1, 5)),
    ("Trapezoidal", (4, 1, 2, 2, 1)),
    ("CompositeSimpson", (1, 5)),
    ("CompositeSimpson", (3, 1, 2, 1)),
)


def _model(ops, rule, args, element):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    ops.node(1, 0.0, 0.0)
    ops.node(2, 0.0, 3.0)
    ops.fix(1, 1, 1, 1)
    ops.uniaxialMaterial("Steel01", 1, 350.0, 2.0e5, 0.02)
    ops.section("Fiber", 1)
    ops.patch("rect", 1, 8, 1, -0.15, -0.1, 0.15, 0.1)
    ops.section("Elastic", 2, 2.0e5, 0.06, 6.0e-4)
    ops.geomTransf("Linear", 1)
    ops.beamIntegration(rule, 1, *args)
    ops.element(element, 1, 1, 2, 1, 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, 1.0, 0.0, 0.0)
    ops.system("UmfPack")
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.test("NormDispIncr", 1e-12, 30)
    ops.algorithm("Newton")
    ops.integrator("DisplacementControl", 2, 1, 0.006)
    ops.analysis("Static")


def run(ops):
    out = {}
    for k, (rule, args) in enumerate(RULES):
        for element in ("forceBeamColumn", "dispBeamColumn"):
            _model(ops, rule, args, element)
            key = f"{rule}{k}.{element}"
            n = args[0] if len(args) != 2 else args[1]
            out[key + ".locations"] = [ops.sectionLocation(1, i) for i in range(1, n + 1)]
            out[key + ".weights"] = [ops.sectionWeight(1, i) for i in range(1, n + 1)]
            steps = []
            for _ in range(4):
                steps.append([ops.analyze(1), ops.testIter(), ops.getLoadFactor(1)])
            out[key + ".steps"] = steps
            out[key + ".tip"] = ops.nodeDisp(2)
            out[key + ".section1"] = ops.eleResponse(1, "section", 1, "force")
    ops.wipe()
    return out

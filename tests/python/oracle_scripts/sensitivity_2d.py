"""Sensitivity analysis (the direct differentiation method) in the style of the OpenSeesPy
"Cantilever 2D sensitivity" example: a steel cantilever of dispBeamColumn elements with a web-only
WFSection2d of Hardening steel under a tip load that yields it, load control, and the tip
displacement's sensitivity to the steel's E, Fy and H_kin (all elements), the section depth d and
the tip node's x coordinate (the length), at every step; with the Linear and the Corotational
transformations (the corotational one to a tip rotation of about 0.15 rad) and a Trig load that
loads, unloads and reverses; with Steel01 (E, Fy, b) to a 0.4 rad tip; then with an Elastic
material and E only.
"""

STEPS = 500


def _cantilever(ops, transf, mat, P):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    L, n = 5.0, 5
    ops.node(1, 0.0, 0.0)
    ops.node(2, L, 0.0)
    ops.fix(1, 1, 1, 1)
    E, Fy, b = 200e6, 410e3, 0.02
    if mat == "Hardening":
        ops.uniaxialMaterial("Hardening", 1, E, Fy, 0.0, b / (1 - b) * E)
    elif mat == "Steel01":
        ops.uniaxialMaterial("Steel01", 1, Fy, E, b)
    else:
        ops.uniaxialMaterial("Elastic", 1, E)
    ops.section("WFSection2d", 1, 1, 0.5, 0.1, 0.1, 0.0, 20, 0)
    ops.geomTransf(transf, 1)
    ops.beamIntegration("Legendre", 1, 1, 5)
    for i in range(1, n):
        ops.node(9 + i, i * L / n, 0.0)
    nodes = [1] + [9 + i for i in range(1, n)] + [2]
    for i in range(n):
        ops.element("dispBeamColumn", i + 1, nodes[i], nodes[i + 1], 1, 1)
    ops.timeSeries("Trig", 1, 0.0, 1.0, 1.0)
    ops.pattern("Plain", 1, 1)
    names = {"Hardening": ("E", "Fy", "Hkin", "d"), "Steel01": ("E", "Fy", "b", "d")}.get(mat, ("E", "d"))
    for k, name in enumerate(names, start=1):
        ops.parameter(k)
        for e in range(1, n + 1):
            ops.addToParameter(k, "element", e, name)
    ops.parameter(len(names) + 1, "node", 2, "coord", 1)
    ops.load(2, 0.0, P, 0.0)
    ops.system("BandGeneral")
    ops.numberer("RCM")
    ops.constraints("Transformation")
    ops.test("NormDispIncr", 1e-12, 10, 0)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", 1.0 / STEPS)
    ops.analysis("Static")
    ops.sensitivityAlgorithm("-computeAtEachStep")
    return names + ("L",)


def run(ops):
    out = {}
    for key, transf, mat, P in (("linear", "Linear", "Hardening", 1000.0), ("corot", "Corotational", "Hardening", 700.0),
                                ("steel01", "Corotational", "Steel01", 1000.0),
                                ("elastic", "Corotational", "Elastic", 3000.0)):
        names = _cantilever(ops, transf, mat, P)
        tags = ops.getParamTags()
        out[f"sens.{key}.paramTags"] = list(tags)
        for step in range(STEPS):
            out.setdefault(f"{key}.ok", []).append(ops.analyze(1))
            out.setdefault(f"{key}.disp", []).append(ops.nodeDisp(2, 2))
            for tag, name in zip(tags, names):
                out.setdefault(f"sens.{key}.{name}", []).append(ops.sensNodeDisp(2, 2, tag))
                out.setdefault(f"sens.{key}.{name}.rotation", []).append(ops.sensNodeDisp(2, 3, tag))
        out[f"sens.{key}.lambda"] = [ops.sensLambda(1, tag) for tag in tags]
    return out

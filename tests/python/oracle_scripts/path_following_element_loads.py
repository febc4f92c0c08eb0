"""Element loads in the pattern that DisplacementControl (or ArcLength) pushes.

A two-element column (elasticBeamColumn, forceBeamColumn, dispBeamColumn with an
Elastic section) with a tip load and a uniform load on both elements in the same
Linear pattern. OpenSees' reference load holds the element loads' nodal
equivalents, so the elastic and displacement-based columns converge in one
iteration per step and the force-based one in its element-load iterations.
Load factors, tip displacements and iteration counts.
"""


def _column(ops, element, integrator):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    ops.node(1, 0.0, 0.0)
    ops.node(2, 0.0, 3.0)
    ops.node(3, 0.0, 6.0)
    ops.fix(1, 1, 1, 1)
    ops.section("Elastic", 1, 2.0e5, 0.08, 0.001)
    ops.geomTransf("Linear", 1)
    ops.beamIntegration("Lobatto", 1, 1, 5)
    for tag, (i, j) in enumerate(((1, 2), (2, 3)), 1):
        if element == "elasticBeamColumn":
            ops.element(element, tag, i, j, 0.08, 2.0e5, 0.001, 1)
        else:
            ops.element(element, tag, i, j, 1, 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(3, 1.0, -100.0, 0.0)
    ops.eleLoad("-ele", 1, 2, "-type", "-beamUniform", 0.3)
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.system("BandGeneral")
    ops.test("NormDispIncr", 1.0e-12, 50)
    ops.algorithm("Newton")
    if integrator == "DisplacementControl":
        ops.integrator("DisplacementControl", 3, 1, 0.002)
    else:
        ops.integrator("ArcLength", 0.01, 1.0)
    ops.analysis("Static")
    rows = []
    for _ in range(5):
        ok = ops.analyze(1)
        rows.append([ok, ops.testIter(), ops.getLoadFactor(1), ops.nodeDisp(3, 1), ops.nodeDisp(3, 2)])
    return rows


def run(ops):
    out = {}
    for element in ("elasticBeamColumn", "dispBeamColumn", "forceBeamColumn"):
        for integrator in ("DisplacementControl", "ArcLength"):
            out[f"{element}.{integrator}"] = _column(ops, element, integrator)
    return out

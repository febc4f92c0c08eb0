"""mixedBeamColumn as OpenSees documents it: (transfTag, integrationTag), '-mass'.

A two-element fiber cantilever (Steel01, yielding) pushed sideways by
DisplacementControl with an axial load that grows with it, 2D Linear and
Corotational, 3D Linear; and its lumped-mass periods. OpenSeesPy's
mixedBeamColumn equals its forceBeamColumn here step by step (without
'-geomNonlinear'), which is what BeamSolid builds.
Load factors, displacements, local forces and Newton iterations at every step.
"""


def _cantilever(ops, ndm, geom):
    ops.wipe()
    if ndm == 2:
        ops.model("basic", "-ndm", 2, "-ndf", 3)
        for tag, y in ((1, 0.0), (2, 3.0), (3, 6.0)):
            ops.node(tag, 0.0, y)
        ops.fix(1, 1, 1, 1)
        ops.section("Fiber", 1)
        ops.geomTransf(geom, 1)
    else:
        ops.model("basic", "-ndm", 3, "-ndf", 6)
        for tag, z in ((1, 0.0), (2, 3.0), (3, 6.0)):
            ops.node(tag, 0.0, 0.0, z)
        ops.fix(1, 1, 1, 1, 1, 1, 1)
        ops.section("Fiber", 1, "-GJ", 1.0e4)
        ops.geomTransf(geom, 1, 1.0, 0.0, 0.0)
    ops.uniaxialMaterial("Steel01", 1, 350.0, 2.0e5, 0.02)
    ops.patch("rect", 1, 10, 4, -0.2, -0.1, 0.2, 0.1)
    ops.beamIntegration("Lobatto", 1, 1, 5)
    for tag, (i, j) in enumerate(((1, 2), (2, 3)), 1):
        ops.element("mixedBeamColumn", tag, i, j, 1, 1, "-mass", 2.0)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(3, *((1.0, -100.0, 0.0) if ndm == 2 else (1.0, 0.5, -100.0, 0.0, 0.0, 0.0)))
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.system("BandGeneral")
    ops.test("NormDispIncr", 1.0e-10, 50)
    ops.algorithm("Newton")
    ops.integrator("DisplacementControl", 3, 1, 0.004)
    ops.analysis("Static")
    rows = []
    for _ in range(25):
        ok = ops.analyze(1)
        rows.append([ok, ops.testIter(), ops.getLoadFactor(1), ops.nodeDisp(2, 1), ops.nodeDisp(3, 1)]
                    + list(ops.eleResponse(1, "localForce")))
    return rows


def _periods(ops):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    for tag, y in ((1, 0.0), (2, 3.0), (3, 6.0)):
        ops.node(tag, 0.0, y)
    ops.fix(1, 1, 1, 1)
    ops.section("Elastic", 1, 2.0e5, 0.08, 0.001)
    ops.geomTransf("Linear", 1)
    ops.beamIntegration("Lobatto", 1, 1, 5)
    for tag, (i, j) in enumerate(((1, 2), (2, 3)), 1):
        ops.element("mixedBeamColumn", tag, i, j, 1, 1, "-mass", 2.0)
    return ops.eigen("-fullGenLapack", 3)


def run(ops):
    out = {}
    for ndm, geom in ((2, "Linear"), (2, "Corotational"), (3, "Linear")):
        out[f"{ndm}d.{geom}"] = _cantilever(ops, ndm, geom)
    out["periods"] = _periods(ops)
    return out

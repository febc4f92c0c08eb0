"""3D elasticBeamColumn with '-releasez'/'-releasey' (every code in both
planes) in a portal of inclined members under nodal loads and a uniform
element load on the released member: displacements, local and basic forces.
(A -beamPoint load on a released 3D member is left out: OpenSeesPy 3.7.1
keeps the fully fixed end moments there, see docs/commands.md.)
"""

CODES = ((0, 0), (1, 0), (2, 3), (3, 1), (0, 2), (3, 3))


def run(ops):
    out = {}
    for rz, ry in CODES:
        ops.wipe()
        ops.model("basic", "-ndm", 3, "-ndf", 6)
        ops.node(1, 0.0, 0.0, 0.0)
        ops.node(2, 3.0, 0.0, 0.5)
        ops.node(3, 3.0, 4.0, 0.5)
        ops.node(4, 0.0, 4.0, 0.0)
        for n in (1, 4):
            ops.fix(n, 1, 1, 1, 1, 1, 1)
        ops.geomTransf("Linear", 1, 0.0, 0.0, 1.0)
        ops.geomTransf("PDelta", 2, 1.0, 0.0, 0.2)
        ops.element("elasticBeamColumn", 1, 1, 2, 0.01, 2e8, 8e7, 2e-5, 1.2e-5, 3e-5, 1)
        ops.element("elasticBeamColumn", 2, 2, 3, 0.01, 2e8, 8e7, 2e-5, 1.2e-5, 3e-5, 2,
                    "-releasez", rz, "-releasey", ry)
        ops.element("elasticBeamColumn", 3, 3, 4, 0.01, 2e8, 8e7, 2e-5, 1.2e-5, 3e-5, 1, "-releasey", 1)
        ops.timeSeries("Linear", 1)
        ops.pattern("Plain", 1, 1)
        ops.load(2, 10.0, -5.0, 3.0, 1.0, 2.0, -1.0)
        ops.load(3, -4.0, 2.0, -6.0, 0.0, 0.0, 0.5)
        ops.eleLoad("-ele", 2, "-type", "-beamUniform", -3.0, 2.0, 0.5)
        ops.system("UmfPack")
        ops.numberer("Plain")
        ops.constraints("Plain")
        ops.test("NormDispIncr", 1e-12, 10)
        ops.algorithm("Newton")
        ops.integrator("LoadControl", 0.5)
        ops.analysis("Static")
        key = f"rz{rz}ry{ry}"
        out[key + ".steps"] = [[ops.analyze(1), ops.testIter()] for _ in range(2)]
        out[key + ".disp"] = ops.nodeDisp(2) + ops.nodeDisp(3)
        for e in (2, 3):
            out[f"{key}.ele{e}.local"] = ops.eleResponse(e, "localForce")
            out[f"{key}.ele{e}.basic"] = ops.eleResponse(e, "basicForce")
    ops.wipe()
    return out

"""ShellMITC4 on the through-thickness plate sections: section('PlateFiber',
...) and section('LayeredShell', ...) of nDMaterial('PlateFiber', ...)
wrappers. A tilted plate strip of distorted elements, clamped at one end:
elastic (an unsymmetric three-layer shell of two materials, whose membrane
and bending couple, and a PlateFiber section) under a tip force and moment,
with responses and eigenvalues; then J2 plasticity on a flat strip pushed past first yield
(8 load steps with iteration counts; OpenSeesPy's J2 stops converging soon
after, and sooner on the tilted strip, where BeamSolid's goes on).
"""

NX, NY = 4, 2


def _strip(ops, section_cmds, materials, tilt):
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 6)

    def tag(i, j):
        return 1 + i + (NX + 1) * j

    for j in range(NY + 1):
        for i in range(NX + 1):
            ops.node(tag(i, j), float(i), 0.5 * j + 0.05 * i * j, tilt * i)
    for j in range(NY + 1):
        ops.fix(tag(0, j), 1, 1, 1, 1, 1, 1)
    for m in materials:
        ops.nDMaterial(*m)
    for s in section_cmds:
        ops.section(*s)
    e = 0
    for j in range(NY):
        for i in range(NX):
            e += 1
            ops.element("ShellMITC4", e, tag(i, j), tag(i + 1, j), tag(i + 1, j + 1), tag(i, j + 1), 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    return tag


def _static(ops, step):
    ops.system("UmfPack")
    ops.numberer("RCM")
    ops.constraints("Plain")
    ops.test("NormDispIncr", 1e-10, 30)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", step)
    ops.analysis("Static")


def run(ops):
    out = {}
    elastic = [("ElasticIsotropic", 1, 1000.0, 0.25, 2.0), ("ElasticIsotropic", 3, 3000.0, 0.3, 1.0),
               ("PlateFiber", 2, 1), ("PlateFiber", 4, 3)]
    for name, section in (("layered", ("LayeredShell", 1, 3, 2, 0.02, 4, 0.05, 2, 0.01)),
                          ("platefiber", ("PlateFiber", 1, 4, 0.08))):
        tag = _strip(ops, [section], elastic, 0.1)
        ops.load(tag(NX, NY), 0.3, 0.0, -0.02, 0.0, 0.01, 0.0)
        ops.load(tag(NX, 0), 0.3, 0.1, -0.01, 0.0, 0.0, 0.0)
        _static(ops, 1.0)
        out[name + ".code"] = ops.analyze(1)
        out[name + ".tip"] = ops.nodeDisp(tag(NX, NY)) + ops.nodeDisp(tag(NX, 0))
        out[name + ".stresses"] = ops.eleResponse(1, "stresses")
        out[name + ".forces"] = ops.eleResponse(2, "forces")
        ops.wipeAnalysis()
        out[name + ".eigen"] = ops.eigen("-fullGenLapack", 3)
    j2 = [("J2Plasticity", 1, 1000.0, 500.0, 1.0, 1.5, 3.0, 10.0), ("PlateFiber", 2, 1)]
    for name, section in (("j2 platefiber", ("PlateFiber", 1, 2, 0.1)),
                          ("j2 layered", ("LayeredShell", 1, 5, 2, 0.02, 2, 0.02, 2, 0.02, 2, 0.02, 2, 0.02))):
        tag = _strip(ops, [section], j2, 0.0)
        for j in range(NY + 1):
            ops.load(tag(NX, j), 0.002, 0.0, -0.00025, 0.0, 0.0, 0.0)
        _static(ops, 0.1)
        steps = []
        for _ in range(8):
            steps.append([ops.analyze(1), ops.testIter(), ops.nodeDisp(tag(NX, NY), 3), ops.nodeDisp(tag(NX, NY), 1)])
        out[name + ".steps"] = steps
    ops.wipe()
    return out

"""ElasticTimoshenkoBeam in 2D and 3D: a portal of shear-flexible members
(one inclined) under nodal and -beamUniform loads with Linear and PDelta
transformations (OpenSees' element stays linear with either), its lumped and
consistent mass eigenvalues, a few Newmark steps, and a 3D two-member frame
(static and consistent-mass eigenvalues).
"""

E, G = 200.0, 80.0


def _static(ops):
    ops.system("UmfPack")
    ops.constraints("Transformation")
    ops.numberer("RCM")
    ops.test("NormDispIncr", 1e-12, 10)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", 1.0)
    ops.analysis("Static")
    return ops.analyze(1)


def _portal(ops, transf, cmass):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    for tag, x, y in ((1, 0.0, 0.0), (2, 6.0, 0.0), (3, 0.0, 4.0), (4, 6.5, 4.2)):
        ops.node(tag, x, y)
    ops.fix(1, 1, 1, 1)
    ops.fix(2, 1, 1, 0)
    ops.geomTransf(transf, 1)
    mass = ("-mass", 1.5) + (("-cMass",) if cmass else ())
    ops.element("ElasticTimoshenkoBeam", 1, 1, 3, E, G, 10.0, 30.0, 8.0, 1, *mass)
    ops.element("ElasticTimoshenkoBeam", 2, 2, 4, E, G, 12.0, 40.0, 9.0, 1, *mass)
    ops.element("ElasticTimoshenkoBeam", 3, 3, 4, E, G, 8.0, 20.0, 6.0, 1, *mass)


def run(ops):
    out = {}
    for transf in ("Linear", "PDelta"):
        _portal(ops, transf, False)
        ops.timeSeries("Linear", 1)
        ops.pattern("Plain", 1, 1)
        ops.load(3, 2.0, -5.0, 0.5)
        ops.eleLoad("-ele", 3, "-type", "-beamUniform", -1.2, 0.2)
        out[transf + ".code"] = _static(ops)
        for n in (3, 4):
            out[f"{transf}.disp{n}"] = ops.nodeDisp(n)
        ops.reactions()
        for n in (1, 2):
            out[f"{transf}.reaction{n}"] = ops.nodeReaction(n)
        for e in (1, 2, 3):
            for r in ("force", "localForce", "globalForce"):
                out[f"{transf}.ele{e}.{r}"] = ops.eleResponse(e, r)
    for cmass in (False, True):
        _portal(ops, "Linear", cmass)
        out[f"eigen.cmass{cmass}"] = ops.eigen("-fullGenLapack", 6 if cmass else 4)
    # A few Newmark steps of the consistent-mass portal under a sudden load.
    _portal(ops, "Linear", True)
    ops.timeSeries("Constant", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(4, 3.0, 0.0, 0.0)
    ops.system("UmfPack")
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.test("NormDispIncr", 1e-12, 10)
    ops.algorithm("Newton")
    ops.integrator("Newmark", 0.5, 0.25)
    ops.analysis("Transient")
    for step in range(5):
        out[f"dyn{step}.code"] = ops.analyze(1, 0.05)
        out[f"dyn{step}.disp4"] = ops.nodeDisp(4)
        out[f"dyn{step}.accel3"] = ops.nodeAccel(3)

    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    ops.node(1, 0.0, 0.0, 0.0)
    ops.node(2, 3.0, 4.0, 0.0)
    ops.node(3, 3.0, 4.0, 5.0)
    ops.fix(1, 1, 1, 1, 1, 1, 1)
    ops.geomTransf("PDelta", 1, 0.0, 0.0, 1.0)
    ops.geomTransf("Linear", 2, 1.0, 0.0, 0.0)
    section = (E, G, 10.0, 20.0, 25.0, 30.0, 8.0, 7.0)
    ops.element("ElasticTimoshenkoBeam", 1, 1, 2, *section, 1, "-mass", 2.0, "-cMass")
    ops.element("ElasticTimoshenkoBeam", 2, 2, 3, *section, 2, "-mass", 2.0, "-cMass")
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(3, -0.4, 0.3, 1.0, 0.2, -0.1, 0.3)
    ops.eleLoad("-ele", 1, "-type", "-beamUniform", 0.5, -0.3, 0.1)
    out["3d.code"] = _static(ops)
    for n in (2, 3):
        out[f"3d.disp{n}"] = ops.nodeDisp(n)
    for e in (1, 2):
        out[f"3d.ele{e}.localForce"] = ops.eleResponse(e, "localForce")
        out[f"3d.ele{e}.force"] = ops.eleResponse(e, "force")
    ops.wipeAnalysis()
    out["3d.eigen"] = ops.eigen("-fullGenLapack", 12)
    return out

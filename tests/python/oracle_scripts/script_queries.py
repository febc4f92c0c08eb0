"""Queries and small commands that scripts and post-processors (opsvis, vfo)
call, with OpenSeesPy's return values and types: getNDM, getNumElements,
getCrdTransfTags, getPatterns, node and element loads per pattern (tags, data,
class tags) in 2D and 3D, getEleClassTags, classType, MP constraint dofs,
setPrecision, setStartNodeTag, set/getNumThreads, the algorithm counters
(types only: times differ), reset, parameter/addToParameter/updateParameter/
getParamTags/getParamValue (the response-spectrum-by-parameter idiom of
public examples: one SDF model, reset and a new stiffness per period),
setElementRayleighDampingFactors in a transient run, and imposedSupportMotion.
"""

import math


def _typed(value):
    return [type(value).__name__, value]


def _frame_2d(ops, out):
    # (getNDM right after wipe is left out: OpenSees' wipe keeps the last model
    # builder, so it answers that builder's ndm, 0 only in a fresh process.)
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    for tag, x, y in ((1, 0, 0), (2, 5, 0), (3, 0, 3), (4, 5, 3)):
        ops.node(tag, float(x), float(y))
    ops.fix(1, 1, 1, 1)
    ops.fix(2, 1, 1, 0)
    ops.equalDOF(3, 4, 1)
    ops.geomTransf("Linear", 1)
    ops.geomTransf("PDelta", 7)
    ops.element("elasticBeamColumn", 1, 1, 3, 0.1, 2e8, 1e-3, 7)
    ops.element("elasticBeamColumn", 2, 2, 4, 0.1, 2e8, 1e-3, 7)
    ops.element("elasticBeamColumn", 3, 3, 4, 0.1, 2e8, 2e-3, 1)
    ops.uniaxialMaterial("Elastic", 5, 1e5)
    ops.uniaxialMaterial("Steel01", 6, 350e3, 2e8, 0.01)
    ops.uniaxialMaterial("ElasticPPGap", 8, 1e5, 20.0, 0.001)
    ops.element("Truss", 4, 1, 4, 0.01, 5)
    ops.section("Elastic", 9, 2e8, 0.1, 1e-3)
    ops.section("Fiber", 10)
    ops.fiber(0.0, 0.0, 0.01, 6)
    ops.section("Aggregator", 11, 5, "Vy", "-section", 10)
    ops.beamIntegration("Lobatto", 3, 9, 4)
    ops.element("forceBeamColumn", 5, 1, 4, 1, 3)
    ops.element("dispBeamColumn", 6, 2, 3, 1, 3)
    ops.element("zeroLength", 7, 1, 3, "-mat", 5, "-dir", 2)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 10, 1)
    ops.load(3, 10.0, 0.0, 0.0)
    ops.load(4, 1.0, -2.0, 3.0)
    ops.eleLoad("-ele", 3, "-type", "-beamUniform", -5.0, 0.5)
    ops.eleLoad("-ele", 1, 2, "-type", "-beamPoint", -3.0, 0.4, 2.0)
    ops.timeSeries("Constant", 2)
    ops.pattern("Plain", 20, 2)
    ops.load(4, 0.0, -7.0, 0.0)
    ops.eleLoad("-ele", 3, "-type", "-beamUniform", -1.0)

    out["getNDM"] = ops.getNDM()
    out["getNDM node"] = ops.getNDM(3)
    out["getNumElements"] = ops.getNumElements()
    out["getCrdTransfTags"] = ops.getCrdTransfTags()
    out["getPatterns"] = ops.getPatterns()
    for q in ("getNodeLoadTags", "getNodeLoadData", "getEleLoadTags", "getEleLoadData", "getEleLoadClassTags"):
        out["2d " + q] = getattr(ops, q)()
        out["2d " + q + " 20"] = getattr(ops, q)(20)
    out["getEleClassTags"] = ops.getEleClassTags()
    out["getEleClassTags 4"] = ops.getEleClassTags(4)
    for tag in (5, 6, 8):
        out[f"classType uniaxialMaterial {tag}"] = ops.classType("uniaxialMaterial", tag)
    for tag in (9, 10, 11):
        out[f"classType section {tag}"] = ops.classType("section", tag)
    out["classType element (None)"] = ops.classType("element", 1)
    out["getConstrainedDOFs"] = [ops.getConstrainedDOFs(4), ops.getConstrainedDOFs(4, 3), ops.getConstrainedDOFs(4, 3, 1)]
    out["getRetainedDOFs"] = [ops.getRetainedDOFs(3), ops.getRetainedDOFs(3, 4), ops.getRetainedDOFs(3, 4, 1)]
    out["setPrecision"] = _typed(ops.setPrecision(10))
    out["setStartNodeTag"] = _typed(ops.setStartNodeTag(100))
    out["setNumThreads"] = _typed(ops.setNumThreads(1))
    out["getNumThreads"] = _typed(ops.getNumThreads())

    ops.constraints("Transformation")
    ops.system("UmfPack")
    ops.numberer("RCM")
    ops.test("NormDispIncr", 1e-10, 10)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", 0.5)
    ops.analysis("Static")
    out["analyze"] = ops.analyze(2)
    out["disp 4"] = ops.nodeDisp(4)
    # Counters: the types agree; the values are times and counts of each program's own.
    out["counter types"] = [type(getattr(ops, c)()).__name__ for c in ("numFact", "totalCPU", "solveCPU", "accelCPU")]
    out["reset"] = _typed(ops.reset())
    out["after reset"] = [ops.getTime()] + ops.nodeDisp(4) + ops.eleForce(3)
    out["analyze after reset"] = [ops.analyze(1), ops.getTime()] + ops.nodeDisp(4)


def _loads_3d(ops, out):
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    ops.node(1, 0.0, 0.0, 0.0)
    ops.node(2, 4.0, 0.0, 0.0)
    ops.geomTransf("Linear", 1, 0.0, 0.0, 1.0)
    ops.element("elasticBeamColumn", 1, 1, 2, 0.1, 2e8, 8e7, 1e-3, 2e-3, 3e-3, 1)
    ops.section("Elastic", 2, 2e8, 0.1, 2e-3, 3e-3, 8e7, 1e-3)
    out["3d classType section"] = ops.classType("section", 2)
    ops.beamIntegration("Legendre", 1, 2, 3)
    ops.element("forceBeamColumn", 2, 1, 2, 1, 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.eleLoad("-ele", 1, "-type", "-beamUniform", -5.0, 2.0, 3.0)
    ops.eleLoad("-ele", 2, "-type", "-beamPoint", -3.0, 4.0, 0.4, 7.0)
    ops.load(2, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0)
    for q in ("getNodeLoadTags", "getNodeLoadData", "getEleLoadTags", "getEleLoadData", "getEleLoadClassTags"):
        out["3d " + q] = getattr(ops, q)()
    out["3d getEleClassTags"] = ops.getEleClassTags()
    out["3d getNDM"] = ops.getNDM()


def _spectrum_by_parameter(ops, out):
    # One SDF oscillator; for each period: reset, a new stiffness through the
    # parameter, and the peak displacement under a short ground motion.
    ops.wipe()
    ops.model("basic", "-ndm", 1, "-ndf", 1)
    ops.node(1, 0.0)
    ops.fix(1, 1)
    ops.node(2, 0.0)
    ops.mass(2, 1.0)
    ops.uniaxialMaterial("Elastic", 1, 1.0)
    ops.element("zeroLength", 1, 1, 2, "-mat", 1, "-dir", 1)
    dt = 0.02
    accel = [math.sin(2.0 * math.pi * 1.3 * i * dt) * math.exp(-0.4 * i * dt) * 3.0 for i in range(120)]
    ops.timeSeries("Path", 1, "-dt", dt, "-values", *accel)
    ops.pattern("UniformExcitation", 1, 1, "-accel", 1)
    ops.rayleigh(0.2, 0.0, 0.0, 0.0)
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.system("FullGeneral")
    ops.test("NormDispIncr", 1e-12, 10)
    ops.algorithm("Linear")
    ops.integrator("Newmark", 0.5, 0.25)
    ops.analysis("Transient")
    out["parameter"] = ops.parameter(1, "element", 1, "E")
    out["getParamTags"] = ops.getParamTags()
    peaks = []
    for Tn in (0.2, 0.5, 1.0, 2.0):
        ops.reset()
        k = (2.0 * math.pi / Tn) ** 2
        out[f"updateParameter T={Tn}"] = ops.updateParameter(1, k)
        out[f"getParamValue T={Tn}"] = ops.getParamValue(1)
        peak = 0.0
        for _ in range(100):
            ops.analyze(1, dt)
            peak = max(peak, abs(ops.nodeDisp(2, 1)))
        peaks.append(peak)
    out["spectrum"] = peaks
    # Two parameters on the same argument: the last update wins.
    out["parameter 2"] = ops.parameter(2)
    out["addToParameter"] = ops.addToParameter(2, "element", 1, "E")
    out["updateParameter 2"] = ops.updateParameter(2, 50.0)
    out["getParamTags 2"] = ops.getParamTags()
    ops.reset()
    for _ in range(20):
        ops.analyze(1, dt)
    out["E from parameter 2"] = [ops.nodeDisp(2, 1), ops.eleForce(1)]
    out["parameter node coord"] = [ops.parameter(3, "node", 2, "coord", 1), ops.getParamValue(3)]


def _element_damping(ops, out):
    # Two equal oscillators, one damped through its own element factors.
    ops.wipe()
    ops.model("basic", "-ndm", 1, "-ndf", 1)
    for n in (1, 2, 3):
        ops.node(n, 0.0)
    ops.fix(1, 1)
    ops.mass(2, 1.0)
    ops.mass(3, 1.0)
    ops.uniaxialMaterial("Elastic", 1, 40.0)
    ops.element("zeroLength", 1, 1, 2, "-mat", 1, "-dir", 1, "-doRayleigh", 1)
    ops.element("zeroLength", 2, 1, 3, "-mat", 1, "-dir", 1, "-doRayleigh", 1)
    out["setElementRayleighDampingFactors"] = _typed(ops.setElementRayleighDampingFactors(2, 0.0, 0.02, 0.0, 0.0))
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, 1.0)
    ops.load(3, 1.0)
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.system("FullGeneral")
    ops.test("NormDispIncr", 1e-12, 10)
    ops.algorithm("Newton")
    ops.integrator("Newmark", 0.5, 0.25)
    ops.analysis("Transient")
    ops.analyze(60, 0.05)
    out["damped vs undamped"] = [ops.nodeDisp(2, 1), ops.nodeDisp(3, 1), ops.nodeVel(2, 1), ops.nodeVel(3, 1)]


def _support_motion(ops, out):
    ops.wipe()
    ops.model("basic", "-ndm", 1, "-ndf", 1)
    for n in (1, 2, 3):
        ops.node(n, 0.0)
    ops.fix(1, 1)
    ops.mass(2, 2.0)
    ops.uniaxialMaterial("Elastic", 1, 50.0)
    ops.element("zeroLength", 1, 1, 2, "-mat", 1, "-dir", 1)
    ops.element("zeroLength", 2, 2, 3, "-mat", 1, "-dir", 1)
    ops.timeSeries("Path", 1, "-time", 0.0, 1.0, 2.0, "-values", 0.0, 0.2, -0.1)
    ops.pattern("MultipleSupport", 1)
    ops.groundMotion(7, "Plain", "-disp", 1)
    ops.imposedSupportMotion(3, 1, 7)
    ops.constraints("Transformation")
    ops.numberer("Plain")
    ops.system("FullGeneral")
    ops.test("NormDispIncr", 1e-12, 10)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", 0.25)
    ops.analysis("Static")
    ops.analyze(6)
    out["imposedSupportMotion"] = [ops.nodeDisp(2, 1), ops.nodeDisp(3, 1)]


def _class_tags_more(ops, out):
    # Class tags of the shell, 3D Timoshenko beam and the stabilized solids.
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    for i, c in enumerate([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]):
        ops.node(i + 1, *map(float, c))
    ops.section("ElasticMembranePlateSection", 1, 1000.0, 0.25, 0.1)
    ops.element("ShellMITC4", 1, 1, 2, 3, 4, 1)
    ops.geomTransf("Linear", 1, 0.0, 0.0, 1.0)
    ops.element("ElasticTimoshenkoBeam", 2, 1, 2, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1)
    out["3d shell and Timoshenko class tags"] = ops.getEleClassTags()
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 2)
    for i, c in enumerate([(0, 0), (1, 0), (1, 1), (0, 1)]):
        ops.node(i + 1, *map(float, c))
    ops.nDMaterial("ElasticIsotropic", 1, 100.0, 0.2)
    ops.element("SSPquad", 1, 1, 2, 3, 4, 1, "PlaneStrain", 1.0)
    ops.element("bbarQuad", 2, 1, 2, 3, 4, 1.0, 1)
    out["2d SSPquad bbarQuad class tags"] = ops.getEleClassTags()
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    for i, c in enumerate([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]):
        ops.node(i + 1, *map(float, c))
    ops.nDMaterial("ElasticIsotropic", 1, 100.0, 0.2)
    ops.element("SSPbrick", 1, *range(1, 9), 1)
    out["SSPbrick class tag"] = ops.getEleClassTags()


def run(ops):
    out = {}
    _class_tags_more(ops, out)
    _frame_2d(ops, out)
    _loads_3d(ops, out)
    _spectrum_by_parameter(ops, out)
    _element_damping(ops, out)
    _support_motion(ops, out)
    return out

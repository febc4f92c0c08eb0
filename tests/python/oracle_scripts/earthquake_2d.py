"""Earthquake scripts in the style of the public OpenSeesPy examples, over a whole record.

The ground motion is the shipped synthetic record (examples/records/
synthetic_kt_seed16.acc, 2001 accelerations at 0.01 s in g), read with
timeSeries('Path', '-dt', dt, '-filePath', file, '-factor', g).

1. An elastic 2D cantilever column with a lumped top mass: eigen, Rayleigh
   damping (2 %) on its first mode, UniformExcitation, Newmark average
   acceleration, 800 steps of 0.01 s; top displacement, velocity,
   acceleration and base reaction at every 20th step, plus a Node recorder.
2. An RC portal frame (fiber sections: Concrete01, Steel01; forceBeamColumn
   columns, elastic girder): gravity in 10 steps, loadConst('-time', 0.0),
   eigen, Rayleigh damping (5 %) on the first two modes, then the record
   scaled to 0.4 g peak for 600 steps of 0.01 s with Newton, falling back to
   ModifiedNewton -initial when a step fails (the examples' idiom); roof
   displacement and base shear at every 20th step, iteration counts of every step.
   The columns crack and their bars yield (roof drift 0.8 %); both programs
   agree to 2e-9 with the same iteration counts. At 0.6 g they agree with
   equal iteration counts to 5.45 s (545 steps; it parted at 2.34 s before
   the element followed OpenSees' iterations); then they part by 7e-7 in
   displacements, one iteration more in OpenSees at step 546. Not traced
   yet; the likely cause is the element fall-back beyond the tangent and
   initial-flexibility attempts, which BeamSolid does not reproduce
   (docs/commands.md).
"""
import math
import os

G = 386.4  # in/s^2
RECORD = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "examples", "records",
                      "synthetic_kt_seed16.acc")


def _cantilever(ops, out):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    ops.node(1, 0.0, 0.0)
    ops.node(2, 0.0, 360.0)
    ops.fix(1, 1, 1, 1)
    ops.mass(2, 5.18, 1e-9, 0.0)
    ops.geomTransf("Linear", 1)
    ops.element("elasticBeamColumn", 1, 1, 2, 3600.0, 3225.0, 1080000.0, 1)
    w1 = math.sqrt(ops.eigen("-fullGenLapack", 1)[0])
    out["cantilever.w1"] = w1
    ops.rayleigh(0.0, 0.0, 0.0, 2.0 * 0.02 / w1)
    ops.timeSeries("Path", 1, "-dt", 0.01, "-filePath", RECORD, "-factor", G)
    ops.pattern("UniformExcitation", 1, 1, "-accel", 1)
    ops.recorder("Node", "-file", "cantilever_top.out", "-time", "-node", 2, "-dof", 1, "disp")
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.system("BandGeneral")
    ops.test("NormDispIncr", 1e-12, 10)
    ops.algorithm("Newton")
    ops.integrator("Newmark", 0.5, 0.25)
    ops.analysis("Transient")
    for step in range(800):
        out.setdefault("cantilever.codes", []).append(ops.analyze(1, 0.01))
        if step % 20 == 19:
            ops.reactions()
            out[f"cantilever.{step + 1}"] = [ops.getTime(), ops.nodeDisp(2, 1), ops.nodeVel(2, 1),
                                              ops.nodeAccel(2, 1), ops.nodeReaction(1, 1), ops.nodeReaction(1, 3)]
    ops.remove("recorders")


def _frame(ops):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    width, height = 288.0, 144.0
    for tag, x, y in ((1, 0.0, 0.0), (2, width, 0.0), (3, 0.0, height), (4, width, height)):
        ops.node(tag, x, y)
    ops.fix(1, 1, 1, 1)
    ops.fix(2, 1, 1, 1)
    ops.uniaxialMaterial("Concrete01", 1, -6.0, -0.004, -5.0, -0.014)
    ops.uniaxialMaterial("Concrete01", 2, -5.0, -0.002, 0.0, -0.006)
    ops.uniaxialMaterial("Steel01", 3, 60.0, 30000.0, 0.01)
    b, d, cover, bar = 15.0, 20.0, 1.5, 0.79
    y1, z1 = d / 2.0, b / 2.0
    ops.section("Fiber", 1)
    ops.patch("rect", 1, 8, 1, cover - y1, cover - z1, y1 - cover, z1 - cover)
    ops.patch("rect", 2, 8, 1, -y1, z1 - cover, y1, z1)
    ops.patch("rect", 2, 8, 1, -y1, -z1, y1, cover - z1)
    ops.patch("rect", 2, 2, 1, -y1, cover - z1, cover - y1, z1 - cover)
    ops.patch("rect", 2, 2, 1, y1 - cover, cover - z1, y1, z1 - cover)
    ops.layer("straight", 3, 3, bar, y1 - cover, z1 - cover, y1 - cover, cover - z1)
    ops.layer("straight", 3, 3, bar, cover - y1, z1 - cover, cover - y1, cover - z1)
    ops.geomTransf("PDelta", 1)
    ops.geomTransf("Linear", 2)
    ops.beamIntegration("Lobatto", 1, 1, 5)
    ops.element("forceBeamColumn", 1, 1, 3, 1, 1)
    ops.element("forceBeamColumn", 2, 2, 4, 1, 1)
    ops.element("elasticBeamColumn", 3, 3, 4, 360.0, 4030.0, 8640.0, 2)
    for n in (3, 4):
        ops.mass(n, 0.25, 0.25, 0.0)


def _frame_earthquake(ops, out):
    _frame(ops)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(3, 0.0, -90.0, 0.0)
    ops.load(4, 0.0, -90.0, 0.0)
    ops.constraints("Transformation")
    ops.numberer("RCM")
    ops.system("BandGeneral")
    ops.test("NormDispIncr", 1e-12, 20)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", 0.1)
    ops.analysis("Static")
    out["frame.gravity"] = ops.analyze(10)
    ops.loadConst("-time", 0.0)
    ops.wipeAnalysis()
    lam = ops.eigen("-fullGenLapack", 2)
    w1, w2 = math.sqrt(lam[0]), math.sqrt(lam[1])
    out["frame.w"] = [w1, w2]
    zeta = 0.05
    ops.rayleigh(2.0 * zeta * w1 * w2 / (w1 + w2), 0.0, 0.0, 2.0 * zeta / (w1 + w2))
    peak = 0.4 / 0.35  # the record's peak is about 0.35 g
    ops.timeSeries("Path", 2, "-dt", 0.01, "-filePath", RECORD, "-factor", peak * G)
    ops.pattern("UniformExcitation", 2, 1, "-accel", 2)
    ops.constraints("Transformation")
    ops.numberer("RCM")
    ops.system("UmfPack")
    ops.test("NormDispIncr", 1e-10, 20)
    ops.algorithm("Newton")
    ops.integrator("Newmark", 0.5, 0.25)
    ops.analysis("Transient")
    for step in range(600):
        ok = ops.analyze(1, 0.01)
        if ok != 0:
            ops.algorithm("ModifiedNewton", "-initial")
            ok = ops.analyze(1, 0.01)
            ops.algorithm("Newton")
        out.setdefault("frame.codes", []).append(ok)
        out.setdefault("frame.iterations", []).append(ops.testIter())
        if step % 20 == 19:
            ops.reactions()
            out[f"frame.{step + 1}"] = [ops.getTime(), ops.nodeDisp(3, 1), ops.nodeDisp(4, 1), ops.nodeVel(3, 1),
                                        ops.nodeAccel(3, 1), ops.nodeReaction(1, 1) + ops.nodeReaction(2, 1)]
    out["frame.ele1 basicForce"] = ops.eleResponse(1, "basicForce")
    out["frame.ele1 section 1 deformation"] = ops.eleResponse(1, "section", 1, "deformation")


def run(ops):
    out = {}
    _cantilever(ops, out)
    _frame_earthquake(ops, out)
    ops.wipe()
    return out

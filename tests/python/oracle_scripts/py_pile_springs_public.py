"""The layout of the public OpenSeesPy p-y pile example (a beam pile on
p-y and t-z springs, springs built in an ndf 3 model and the pile in an
ndf 6 one): spring nodes fixed in dofs 2 and 3 and tied to the pile in dofs
1 and 3 by equalDOF (a fix OpenSees' Transformation handler overrides), an
Aggregator section adding torsion to an Elastic section, dispBeamColumn with
Legendre integration, a Path series with -time after setTime, RCM and
SparseGeneral, NormDispIncr with print flag, recorders with -nodeRange,
-eleRange and -dT, and the head pushed until the springs yield.
"""
import math


def run(ops):
    out = {}
    ops.wipe()
    n_ele, length, embedded = 24, 12.0, 10.0
    size = length / n_ele
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    embedded_nodes = 0
    for i in range(n_ele + 1):
        z = size * i
        if z <= embedded + 1e-9:
            ops.node(i + 1, 0.0, 0.0, z)
            ops.node(i + 101, 0.0, 0.0, z)
            embedded_nodes += 1
    for i in range(embedded_nodes):
        ops.fix(i + 1, 1, 1, 1)
        ops.fix(i + 101, 0, 1, 1)
    for i in range(1, embedded_nodes + 1):
        depth = embedded - size * (i - 1)
        pult = max(0.5, 3.0 * 17.0 * depth * math.tan(math.radians(36.0)) ** 2) * size
        ops.uniaxialMaterial("PySimple1", i, 2, pult, 0.002 + 0.0004 * depth, 0.0)
        ops.uniaxialMaterial("TzSimple1", i + 100, 2, 0.4 * pult, 0.001, 0.0)
    for i in range(1, embedded_nodes + 1):
        ops.element("zeroLength", 1000 + i, i, 100 + i, "-mat", i, 100 + i, "-dir", 1, 3)
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    for i in range(1, n_ele + 2):
        ops.node(i + 200, 0.0, 0.0, size * (i - 1))
    ops.geomTransf("Linear", 1, 0.0, -1.0, 0.0)
    for i in range(201, 202 + n_ele):
        ops.fix(i, 0, 1, 0, 1, 0, 1)
    for i in range(1, embedded_nodes + 1):
        ops.equalDOF(200 + i, 100 + i, 1, 3)
    ops.section("Elastic", 1, 25e6, 0.785, 0.049, 0.049, 9.6e6, 0.098)
    ops.uniaxialMaterial("Elastic", 3000, 1e10)
    ops.section("Aggregator", 3, 3000, "T", "-section", 1)
    ops.beamIntegration("Legendre", 1, 3, 3)
    for i in range(201, 201 + n_ele):
        ops.element("dispBeamColumn", i, i, i + 1, 1, 1)
    head = 201 + n_ele
    ops.recorder("Node", "-file", "pileDisp.out", "-time", "-dT", 0.5, "-nodeRange", 201, head, "-dof", 1, 2, 3, "disp")
    ops.recorder("Node", "-file", "reaction.out", "-time", "-dT", 0.5, "-nodeRange", 1, embedded_nodes, "-dof", 1,
                 "reaction")
    ops.recorder("Element", "-file", "pileForce.out", "-time", "-dT", 0.5, "-eleRange", 201, 200 + n_ele,
                 "globalForce")
    ops.setTime(10.0)
    ops.timeSeries("Path", 1, "-values", 0.0, 0.0, 1.0, 1.0, "-time", 0.0, 10.0, 20.0, 10000.0, "-factor", 1.0)
    ops.pattern("Plain", 10, 1)
    ops.load(head, 150.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    ops.integrator("LoadControl", 0.25)
    ops.numberer("RCM")
    ops.system("SparseGeneral")
    ops.constraints("Transformation")
    ops.test("NormDispIncr", 1e-10, 30, 0)
    ops.algorithm("Newton")
    ops.analysis("Static")
    for step in range(40):
        out[f"step{step}.code"] = ops.analyze(1)
        out[f"step{step}.iterations"] = ops.testIter()
        out[f"step{step}.head"] = ops.nodeDisp(head)
    ops.reactions()
    for i in (1, 5, embedded_nodes):
        out[f"reaction{i}"] = ops.nodeReaction(i)
        out[f"springForce{i}"] = ops.eleResponse(1000 + i, "force")
    out["time"] = ops.getTime()
    ops.wipe()
    for name in ("pileDisp.out", "reaction.out", "pileForce.out"):
        with open(name) as f:
            out["file:" + name] = f.read()
    return out

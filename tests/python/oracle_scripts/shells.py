"""ShellMITC4 with ElasticMembranePlateSection: a plate mesh whose interior
nodes are moved (no element is a parallelogram) and whose mid-plane is
tilted in space, clamped along one edge and simply supported along another,
under transverse and in-plane nodal loads and its own weight (eleLoad is not
used: shells take none here); every response of a few elements; the lowest
eigenvalues of the consistent mass; three Newmark steps; and a vertical wall
(x-z plane) of two shells on a beam, loaded in its plane and out of it.
"""
import math

NX, NY = 4, 3
LX, LY = 4.0, 3.0
E, NU, H, RHO = 3.0e4, 0.2, 0.15, 2.4


def _tilted(x, y):
    # The mid-plane turned 30 degrees about the x axis, then 20 about z.
    a, b = math.radians(30.0), math.radians(20.0)
    p = (x, y * math.cos(a), y * math.sin(a))
    return (p[0] * math.cos(b) - p[1] * math.sin(b), p[0] * math.sin(b) + p[1] * math.cos(b), p[2])


def _tag(i, j):
    return 1 + i + (NX + 1) * j


def _plate(ops):
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    moved = {(1, 1): (0.12, -0.07), (2, 1): (-0.09, 0.1), (3, 2): (0.06, 0.08), (2, 2): (-0.05, -0.11)}
    for j in range(NY + 1):
        for i in range(NX + 1):
            dx, dy = moved.get((i, j), (0.0, 0.0))
            ops.node(_tag(i, j), *_tilted(LX * i / NX + dx, LY * j / NY + dy))
    for j in range(NY + 1):
        ops.fix(_tag(0, j), 1, 1, 1, 1, 1, 1)  # clamped edge x = 0
    for i in range(1, NX + 1):
        ops.fix(_tag(i, 0), 0, 0, 1, 0, 0, 0)  # simply supported edge y = 0 (global z)
    ops.section("ElasticMembranePlateSection", 1, E, NU, H, RHO)
    tag = 0
    for j in range(NY):
        for i in range(NX):
            tag += 1
            ops.element("ShellMITC4", tag, _tag(i, j), _tag(i + 1, j), _tag(i + 1, j + 1), _tag(i, j + 1), 1)


def _static(ops):
    ops.system("UmfPack")
    ops.numberer("RCM")
    ops.constraints("Plain")
    ops.test("NormDispIncr", 1e-12, 10)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", 0.5)
    ops.analysis("Static")


def run(ops):
    out = {}
    _plate(ops)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(_tag(NX, NY), 0.0, 0.0, -2.0, 0.3, 0.0, 0.0)
    ops.load(_tag(NX, 1), 1.5, -0.5, 0.8, 0.0, 0.2, 0.05)
    ops.load(_tag(2, 3), 0.0, 0.7, -1.0, 0.0, 0.0, 0.0)
    _static(ops)
    out["steps"] = [[ops.analyze(1), ops.testIter()] for _ in range(2)]
    for n in (_tag(NX, NY), _tag(NX, 1), _tag(2, 2), _tag(3, 2)):
        out[f"disp{n}"] = ops.nodeDisp(n)
    ops.reactions()
    out["reaction1"] = ops.nodeReaction(_tag(0, 0))
    out["reaction_ss"] = ops.nodeReaction(_tag(2, 0))
    for e in (1, 6, 12):
        for name in ("forces", "globalForce", "stresses", "strains"):
            out[f"ele{e}.{name}"] = ops.eleResponse(e, name)
    out["ele6.section2"] = ops.eleResponse(6, "section", 2, "force")
    out["ele6.material3"] = ops.eleResponse(6, "material", 3, "deformation")
    out["eleType"] = ops.eleType(1)

    ops.wipeAnalysis()
    ops.loadConst("-time", 0.0)
    out["eigen"] = ops.eigen("-fullGenLapack", 4)
    ops.wipeAnalysis()
    ops.system("UmfPack")
    ops.numberer("RCM")
    ops.constraints("Plain")
    ops.test("NormDispIncr", 1e-12, 10)
    ops.algorithm("Newton")
    ops.integrator("Newmark", 0.5, 0.25)
    ops.analysis("Transient")
    ops.timeSeries("Constant", 2)
    ops.pattern("Plain", 2, 2)
    ops.load(_tag(NX, NY), 0.0, 0.0, 1.0, 0.0, 0.0, 0.0)
    out["transient"] = []
    for _ in range(3):
        ops.analyze(1, 0.01)
        out["transient"].append(ops.nodeDisp(_tag(NX, NY)) + ops.nodeVel(_tag(NX, 2)))

    # A wall in the x-z plane on a beam (node order clockwise seen from +y).
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    for k, (x, z) in enumerate([(0, 0), (2, 0), (4, 0), (0, 3), (2, 3.2), (4, 3)]):
        ops.node(k + 1, float(x), 0.0, float(z))
    for n in (1, 2, 3):
        ops.fix(n, 1, 1, 1, 1, 1, 1)
    ops.section("ElasticMembranePlateSection", 1, E, NU, 0.2, RHO)
    ops.element("ShellMITC4", 1, 1, 2, 5, 4, 1)
    ops.element("ShellMITC4", 2, 2, 3, 6, 5, 1)
    ops.geomTransf("Linear", 1, 0.0, 0.0, 1.0)
    ops.element("elasticBeamColumn", 3, 4, 5, 0.1, E, E / 2.4, 1e-3, 2e-3, 3e-3, 1)
    ops.element("elasticBeamColumn", 4, 5, 6, 0.1, E, E / 2.4, 1e-3, 2e-3, 3e-3, 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(5, 10.0, 3.0, -4.0, 0.0, 0.0, 1.0)
    ops.load(6, 0.0, -2.0, 0.0, 0.5, 0.0, 0.0)
    _static(ops)
    out["wall.steps"] = [ops.analyze(1) for _ in range(2)]
    for n in (4, 5, 6):
        out[f"wall.disp{n}"] = ops.nodeDisp(n)
    out["wall.ele1.stresses"] = ops.eleResponse(1, "stresses")
    out["wall.ele2.forces"] = ops.eleResponse(2, "forces")
    ops.wipe()
    return out

"""tri31: a cantilever plate of constant-strain triangles (each cell of a
4 x 2 grid cut along alternating diagonals, interior nodes moved) in
PlaneStress and PlaneStrain with pressure, element rho and body forces on
the element command: a tip load, displacements, reactions, element forces,
stresses, material responses; then eleLoad '-selfWeight' in a Linear
pattern; the lowest eigenvalues (element rho, and the material's rho when
the element's is 0); a few Newmark steps of free vibration; and a patch test
(a linear field imposed on the boundary reproduced inside).
"""
import solid_elements  # the shared static analysis set-up


NX, NY = 4, 2
LX, LY = 4.0, 1.0
E, NU, RHO_MAT = 3.0e4, 0.3, 2.5
THICK = 0.25
MOVED = {(1, 1): (0.11, -0.07), (2, 1): (-0.08, 0.09), (3, 1): (0.05, 0.04)}
PATCH = ((1.0e-3, 0.4e-3), (-0.6e-3, 0.7e-3))


def _tag(i, j):
    return 1 + i + (NX + 1) * j


def _mesh(ops, kind, pressure, rho, body):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 2)
    for j in range(NY + 1):
        for i in range(NX + 1):
            dx, dy = MOVED.get((i, j), (0.0, 0.0))
            ops.node(_tag(i, j), LX * i / NX + dx, LY * j / NY + dy)
    ops.nDMaterial("ElasticIsotropic", 1, E, NU, RHO_MAT)
    tag = 0
    for j in range(NY):
        for i in range(NX):
            a, b, c, d = _tag(i, j), _tag(i + 1, j), _tag(i + 1, j + 1), _tag(i, j + 1)
            tris = ((a, b, c), (a, c, d)) if (i + j) % 2 == 0 else ((a, b, d), (b, c, d))
            for t in tris:
                tag += 1
                # OpenSees reads the optional numbers only when all four are given.
                ops.element("tri31", tag, *t, THICK, kind, 1, pressure, rho, *body)
    return tag


def run(ops):
    out = {}
    nodes = [_tag(i, j) for j in range(NY + 1) for i in range(NX + 1)]
    base = [_tag(0, j) for j in range(NY + 1)]
    for kind in ("PlaneStress", "PlaneStrain"):
        p = f"{kind}."
        count = _mesh(ops, kind, 3.0, 1.7, (0.4, -6.0))
        for n in base:
            ops.fix(n, 1, 1)
        ops.timeSeries("Linear", 1)
        ops.pattern("Plain", 1, 1)
        ops.load(_tag(NX, NY), 5.0, -40.0)
        out[p + "codes"] = solid_elements._analyse(ops)
        out[p + "disp"] = [ops.nodeDisp(n) for n in nodes]
        ops.reactions()
        out[p + "reactions"] = [ops.nodeReaction(n) for n in base]
        for e in (1, 4, count):
            out[f"{p}ele{e}.forces"] = ops.eleResponse(e, "forces")
            out[f"{p}ele{e}.stresses"] = ops.eleResponse(e, "stresses")
            out[f"{p}ele{e}.material1.stress"] = ops.eleResponse(e, "material", 1, "stress")
            out[f"{p}ele{e}.material1.strain"] = ops.eleResponse(e, "material", 1, "strain")
            out[f"{p}ele{e}.integrPoint1.stress"] = ops.eleResponse(e, "integrPoint", 1, "stress")
            out[f"{p}ele{e}.material1.tangent"] = ops.eleResponse(e, "material", 1, "tangent")
        out[p + "classTags"] = ops.getEleClassTags(1)
        # Self weight: factor * (fx b1, fy b2) replaces b while active.
        ops.loadConst("-time", 0.0)
        ops.timeSeries("Linear", 2)
        ops.pattern("Plain", 2, 2)
        ops.eleLoad("-ele", *range(1, count + 1), "-type", "-selfWeight", 0.5, 2.0)
        out[p + "sw.codes"] = solid_elements._analyse(ops, 2, 0.5)
        out[p + "sw.disp"] = [ops.nodeDisp(n) for n in nodes]
        # Modes: lumped mass with the element's rho, then the material's.
        for rho in (1.7, 0.0):
            _mesh(ops, kind, 0.0, rho, (0.0, 0.0))
            for n in base:
                ops.fix(n, 1, 1)
            out[f"{p}eigen.rho{rho}"] = ops.eigen("-fullGenLapack", 4)
        # Free vibration from a tip push (Newmark, average acceleration).
        _mesh(ops, kind, 0.0, 1.7, (0.0, 0.0))
        for n in base:
            ops.fix(n, 1, 1)
        ops.timeSeries("Constant", 3)
        ops.pattern("Plain", 3, 3)
        ops.load(_tag(NX, NY), 0.0, -20.0)
        ops.system("UmfPack")
        ops.constraints("Plain")
        ops.numberer("Plain")
        ops.test("NormDispIncr", 1e-12, 10)
        ops.algorithm("Newton")
        ops.integrator("Newmark", 0.5, 0.25)
        ops.analysis("Transient")
        history = []
        for _ in range(6):
            ops.analyze(1, 0.004)
            history.append(ops.nodeDisp(_tag(NX, NY)))
        out[p + "newmark.tip"] = history
        out[p + "newmark.vel"] = ops.nodeVel(_tag(NX, NY))
        out[p + "newmark.accel"] = ops.nodeAccel(_tag(NX, NY))
        # Patch test: boundary nodes on the linear field, interior nodes free.
        _mesh(ops, kind, 0.0, 0.0, (0.0, 0.0))
        ops.timeSeries("Constant", 4)
        ops.pattern("Plain", 4, 4)
        boundary = [n for n in nodes if n not in {_tag(i, 1) for i in range(1, NX)}]
        for n in boundary:
            x = ops.nodeCoord(n)
            for d in range(2):
                ops.sp(n, d + 1, PATCH[d][0] * x[0] + PATCH[d][1] * x[1])
        out[p + "patch.codes"] = solid_elements._analyse(ops, handler="Transformation")
        out[p + "patch.disp"] = [ops.nodeDisp(_tag(i, 1)) for i in range(1, NX)]
        out[p + "patch.stresses"] = [ops.eleResponse(e, "stresses") for e in (1, 5)]
    return out

"""FourNodeTetrahedron: a block of 3 x 2 x 2 cells, each cut into six
tetrahedra around its main diagonal (Kuhn's split, conforming), interior
nodes moved: body forces on the element command and a corner load,
displacements, reactions, element forces, stresses, strains and material
responses; then eleLoad '-selfWeight' in a Linear pattern; a few Newmark
steps (the element's one-point mass); the lowest eigenvalues; and a patch
test (a linear field imposed on the boundary reproduced inside).
"""
import itertools

import solid_elements  # the static analysis set-up, shared

NX, NY, NZ = 3, 2, 2
LX, LY, LZ = 3.0, 2.0, 1.6
E, NU, RHO = 2.0e4, 0.3, 1.8
MOVED = {(1, 1, 1): (0.12, -0.07, 0.05), (2, 1, 1): (-0.09, 0.1, -0.06)}
PATCH = ((1.0e-3, 0.4e-3, -0.3e-3), (0.2e-3, -0.5e-3, 0.6e-3), (0.7e-3, 0.1e-3, 0.8e-3))


def _tag(i, j, k):
    return 1 + i + (NX + 1) * (j + (NY + 1) * k)


def _coords(i, j, k):
    d = MOVED.get((i, j, k), (0.0, 0.0, 0.0))
    return (LX * i / NX + d[0], LY * j / NY + d[1], LZ * k / NZ + d[2])


def _volume6(x):
    a = [x[1][c] - x[0][c] for c in range(3)]
    b = [x[2][c] - x[0][c] for c in range(3)]
    d = [x[3][c] - x[0][c] for c in range(3)]
    return (a[0] * (b[1] * d[2] - b[2] * d[1]) - a[1] * (b[0] * d[2] - b[2] * d[0])
            + a[2] * (b[0] * d[1] - b[1] * d[0]))


def _tets():
    """Node tags of every tetrahedron, ordered to a positive volume."""
    out = []
    for k in range(NZ):
        for j in range(NY):
            for i in range(NX):
                for perm in itertools.permutations(range(3)):
                    corner = [0, 0, 0]
                    path = [tuple(corner)]
                    for axis in perm:
                        corner[axis] = 1
                        path.append(tuple(corner))
                    ijk = [(i + a, j + b, k + c) for a, b, c in path]
                    if _volume6([_coords(*p) for p in ijk]) < 0.0:
                        ijk[1], ijk[2] = ijk[2], ijk[1]
                    out.append([_tag(*p) for p in ijk])
    return out


def _mesh(ops, body):
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    for k in range(NZ + 1):
        for j in range(NY + 1):
            for i in range(NX + 1):
                ops.node(_tag(i, j, k), *_coords(i, j, k))
    ops.nDMaterial("ElasticIsotropic", 1, E, NU, RHO)
    tets = _tets()
    for e, nodes in enumerate(tets, start=1):
        ops.element("FourNodeTetrahedron", e, *nodes, 1, *body)
    return len(tets)


def run(ops):
    out = {}
    nodes = [_tag(i, j, k) for k in range(NZ + 1) for j in range(NY + 1) for i in range(NX + 1)]
    base = [_tag(i, j, 0) for j in range(NY + 1) for i in range(NX + 1)]
    count = _mesh(ops, (0.5, -1.0, -18.0))
    for n in base:
        ops.fix(n, 1, 1, 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(_tag(NX, NY, NZ), 30.0, -12.0, 8.0)
    out["codes"] = solid_elements._analyse(ops)
    out["disp"] = [ops.nodeDisp(n) for n in nodes]
    ops.reactions()
    out["reactions"] = [ops.nodeReaction(n) for n in base]
    for e in (1, 7, 40, count):
        out[f"ele{e}.forces"] = ops.eleResponse(e, "forces")
        out[f"ele{e}.stresses"] = ops.eleResponse(e, "stresses")
        out[f"ele{e}.strains"] = ops.eleResponse(e, "strains")
        out[f"ele{e}.material1.stress"] = ops.eleResponse(e, "material", 1, "stress")
        out[f"ele{e}.material1.strain"] = ops.eleResponse(e, "material", 1, "strain")
        out[f"ele{e}.integrPoint1.stress"] = ops.eleResponse(e, "integrPoint", 1, "stress")
        out[f"ele{e}.material1.tangent"] = ops.eleResponse(e, "material", 1, "tangent")
    out["classTags"] = ops.getEleClassTags(1)
    # Self weight: factor * (fx b1, fy b2, fz b3) replaces b while active.
    ops.loadConst("-time", 0.0)
    ops.timeSeries("Linear", 2)
    ops.pattern("Plain", 2, 2)
    ops.eleLoad("-ele", *range(1, count + 1), "-type", "-selfWeight", 0.5, 2.0, 1.5)
    out["sw.codes"] = solid_elements._analyse(ops, 2, 0.5)
    out["sw.disp"] = [ops.nodeDisp(n) for n in nodes]
    # Free vibration from a corner push (Newmark, average acceleration).
    _mesh(ops, ())
    for n in base:
        ops.fix(n, 1, 1, 1)
    ops.timeSeries("Constant", 3)
    ops.pattern("Plain", 3, 3)
    ops.load(_tag(NX, NY, NZ), 0.0, 0.0, -20.0)
    ops.system("UmfPack")
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.test("NormDispIncr", 1e-12, 10)
    ops.algorithm("Newton")
    ops.integrator("Newmark", 0.5, 0.25)
    ops.analysis("Transient")
    history = []
    for _ in range(6):
        ops.analyze(1, 0.003)
        history.append(ops.nodeDisp(_tag(NX, NY, NZ)))
    out["newmark.corner"] = history
    out["newmark.vel"] = ops.nodeVel(_tag(NX, NY, NZ))
    out["newmark.accel"] = ops.nodeAccel(_tag(NX, NY, NZ))
    ops.wipeAnalysis()
    out["eigen"] = ops.eigen("-fullGenLapack", 3)
    # Patch test.
    _mesh(ops, ())
    ops.timeSeries("Constant", 4)
    ops.pattern("Plain", 4, 4)
    interior = {_tag(i, j, k) for i in range(1, NX) for j in range(1, NY) for k in range(1, NZ)}
    for n in nodes:
        if n not in interior:
            x = ops.nodeCoord(n)
            for d in range(3):
                ops.sp(n, d + 1, sum(PATCH[d][c] * x[c] for c in range(3)))
    out["patch.codes"] = solid_elements._analyse(ops, handler="Transformation")
    out["patch.disp"] = [ops.nodeDisp(n) for n in sorted(interior)]
    out["patch.stresses"] = [ops.eleResponse(e, "stresses") for e in (1, 30, count)]
    return out

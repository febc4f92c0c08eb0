"""The locking-free solids bbarQuad, SSPquad (PlaneStrain and PlaneStress),
bbarBrick and SSPbrick on small elastic meshes, regular (axis-aligned
rectangles and boxes) and distorted (moved interior nodes): a corner load,
body forces of the element command, then an eleLoad '-selfWeight' in a
Linear pattern; displacements, reactions, element forces, stresses and
strains; and the lowest eigenvalues with the elements' mass. Also a patch
test on the distorted meshes (a linear field imposed on the boundary),
which every formulation must reproduce whatever its stabilization.
"""

NX, NY, NZ = 3, 2, 2
LX, LY, LZ = 3.0, 2.0, 1.6
E, NU, RHO = 2.0e4, 0.45, 1.8
THICK = 0.4
MOVED2 = {(1, 1): (0.13, -0.08), (2, 1): (-0.1, 0.11)}
MOVED3 = {(1, 1, 1): (0.12, -0.07, 0.05), (2, 1, 1): (-0.09, 0.1, -0.06)}
PATCH = ((1.0e-3, 0.4e-3, -0.3e-3), (0.2e-3, -0.5e-3, 0.6e-3), (0.7e-3, 0.1e-3, 0.8e-3))


def _tag2(i, j):
    return 1 + i + (NX + 1) * j


def _tag3(i, j, k):
    return 1 + i + (NX + 1) * (j + (NY + 1) * k)


def _analyse(ops, steps=1, dlambda=1.0, handler="Plain"):
    ops.wipeAnalysis()
    ops.system("UmfPack")
    ops.constraints(handler)
    ops.numberer("Plain")
    ops.test("NormDispIncr", 1e-12, 10)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", dlambda)
    ops.analysis("Static")
    return [ops.analyze(1) for _ in range(steps)]


def _quads(ops, etype, kind, distorted, body):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 2)
    for j in range(NY + 1):
        for i in range(NX + 1):
            dx, dy = MOVED2.get((i, j), (0.0, 0.0)) if distorted else (0.0, 0.0)
            ops.node(_tag2(i, j), LX * i / NX + dx, LY * j / NY + dy)
    ops.nDMaterial("ElasticIsotropic", 1, E, NU, RHO)
    tag = 0
    for j in range(NY):
        for i in range(NX):
            tag += 1
            nodes = (_tag2(i, j), _tag2(i + 1, j), _tag2(i + 1, j + 1), _tag2(i, j + 1))
            if etype == "bbarQuad":
                ops.element("bbarQuad", tag, *nodes, THICK, 1)
            else:
                ops.element("SSPquad", tag, *nodes, 1, kind, THICK, *body)


def _bricks(ops, etype, distorted, body):
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    for k in range(NZ + 1):
        for j in range(NY + 1):
            for i in range(NX + 1):
                d = MOVED3.get((i, j, k), (0.0, 0.0, 0.0)) if distorted else (0.0, 0.0, 0.0)
                ops.node(_tag3(i, j, k), LX * i / NX + d[0], LY * j / NY + d[1], LZ * k / NZ + d[2])
    ops.nDMaterial("ElasticIsotropic", 1, E, NU, RHO)
    tag = 0
    for k in range(NZ):
        for j in range(NY):
            for i in range(NX):
                tag += 1
                b = (_tag3(i, j, k), _tag3(i + 1, j, k), _tag3(i + 1, j + 1, k), _tag3(i, j + 1, k))
                t = tuple(n + (NX + 1) * (NY + 1) for n in b)
                ops.element(etype, tag, *b, *t, 1, *body)


def _static(ops, out, prefix, dim, nodes, base, elements, corner, load):
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(corner, *load)
    out[prefix + "codes"] = _analyse(ops)
    out[prefix + "disp"] = [ops.nodeDisp(n) for n in nodes]
    ops.reactions()
    out[prefix + "reactionSum"] = [sum(ops.nodeReaction(n, d) for n in base) for d in range(1, dim + 1)]
    for e in elements:
        out[f"{prefix}ele{e}.forces"] = ops.eleResponse(e, "forces")
        out[f"{prefix}ele{e}.stresses"] = ops.eleResponse(e, "stresses")
        out[f"{prefix}ele{e}.strains"] = ops.eleResponse(e, "strains")
        if prefix.startswith("bbar"):
            for k in (1, 2):
                out[f"{prefix}ele{e}.material{k}.stress"] = ops.eleResponse(e, "material", k, "stress")
                out[f"{prefix}ele{e}.material{k}.strain"] = ops.eleResponse(e, "material", k, "strain")


def _self_weight(ops, out, prefix, elements, factors):
    ops.loadConst("-time", 0.0)
    ops.timeSeries("Linear", 2)
    ops.pattern("Plain", 2, 2)
    ops.eleLoad("-ele", *elements, "-type", "-selfWeight", *factors)
    out[prefix + "sw.codes"] = _analyse(ops, 2, 0.5)
    out[prefix + "sw.disp"] = [ops.nodeDisp(n) for n in (elements[-1],)]


def _patch(ops, out, prefix, dim, nodes, boundary):
    ops.timeSeries("Constant", 3)
    ops.pattern("Plain", 3, 3)
    for n in boundary:
        x = ops.nodeCoord(n)
        for d in range(dim):
            ops.sp(n, d + 1, sum(PATCH[d][c] * x[c] for c in range(dim)))
    out[prefix + "patch.codes"] = _analyse(ops, handler="Transformation")
    out[prefix + "patch.disp"] = [ops.nodeDisp(n) for n in nodes if n not in boundary]


def run(ops):
    out = {}
    # --- quads -------------------------------------------------------------------
    nodes2 = [_tag2(i, j) for j in range(NY + 1) for i in range(NX + 1)]
    base2 = [_tag2(i, 0) for i in range(NX + 1)]
    for etype, kind in (("bbarQuad", "PlaneStrain"), ("SSPquad", "PlaneStrain"), ("SSPquad", "PlaneStress")):
        for distorted in (False, True):
            prefix = f"{etype}.{kind}.{'distorted' if distorted else 'regular'}."
            body = () if etype == "bbarQuad" else (1.5, -20.0)
            _quads(ops, etype, kind, distorted, body)
            for n in base2:
                ops.fix(n, 1, 1)
            _static(ops, out, prefix, 2, nodes2, base2, (1, 5), _tag2(NX, NY), (40.0, -15.0))
            if body:
                _self_weight(ops, out, prefix, list(range(1, NX * NY + 1)), (1.0, 0.5))
            # Modes with the element mass (fixed base).
            ops.wipeAnalysis()
            out[prefix + "eigen"] = ops.eigen("-fullGenLapack", 3)
            if distorted:
                _quads(ops, etype, kind, True, ())
                boundary = [_tag2(i, j) for j in range(NY + 1) for i in range(NX + 1)
                            if i in (0, NX) or j in (0, NY)]
                _patch(ops, out, prefix, 2, nodes2, boundary)
    # --- bricks ------------------------------------------------------------------
    nodes3 = [_tag3(i, j, k) for k in range(NZ + 1) for j in range(NY + 1) for i in range(NX + 1)]
    base3 = [_tag3(i, j, 0) for j in range(NY + 1) for i in range(NX + 1)]
    for etype in ("bbarBrick", "SSPbrick"):
        for distorted in (False, True):
            prefix = f"{etype}.{'distorted' if distorted else 'regular'}."
            _bricks(ops, etype, distorted, (0.5, -1.0, -18.0))
            for n in base3:
                ops.fix(n, 1, 1, 1)
            _static(ops, out, prefix, 3, nodes3, base3, (1, 6, 10), _tag3(NX, NY, NZ), (30.0, -12.0, 8.0))
            _self_weight(ops, out, prefix, list(range(1, NX * NY * NZ + 1)), (1.0, 1.0, 0.5))
            ops.wipeAnalysis()
            out[prefix + "eigen"] = ops.eigen("-fullGenLapack", 3)
            if distorted:
                _bricks(ops, etype, True, ())
                boundary = [_tag3(i, j, k) for k in range(NZ + 1) for j in range(NY + 1) for i in range(NX + 1)
                            if i in (0, NX) or j in (0, NY) or k in (0, NZ)]
                _patch(ops, out, prefix, 3, nodes3, boundary)
    return out

"""A block of 2 x 2 x 2 stdBrick elements (one interior node moved so that no
element is a parallelepiped) on a fixed base: under the element's body-force
arguments (b1, b2, b3), under an eleLoad '-selfWeight', and under a pressure
on the top face applied as consistent nodal loads. Node and element
recorders write files that are returned as text.
"""

NX, NY, NZ = 2, 2, 2
LX, LY, LZ = 2.0, 1.5, 3.0
E, NU, RHO = 30.0e3, 0.3, 2.0
BODY = (0.4, -0.3, -18.0)
PRESSURE = 25.0


def _tag(i, j, k):
    return 1 + i + (NX + 1) * (j + (NY + 1) * k)


def _build(ops, body):
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    for k in range(NZ + 1):
        for j in range(NY + 1):
            for i in range(NX + 1):
                x, y, z = LX * i / NX, LY * j / NY, LZ * k / NZ
                if (i, j, k) == (1, 1, 1):
                    x, y, z = x + 0.07, y - 0.05, z + 0.11
                ops.node(_tag(i, j, k), x, y, z)
    ops.fixZ(0.0, 1, 1, 1)
    ops.nDMaterial("ElasticIsotropic", 1, E, NU, RHO)
    tag = 0
    for k in range(NZ):
        for j in range(NY):
            for i in range(NX):
                tag += 1
                nodes = [_tag(i, j, k), _tag(i + 1, j, k), _tag(i + 1, j + 1, k), _tag(i, j + 1, k),
                         _tag(i, j, k + 1), _tag(i + 1, j, k + 1), _tag(i + 1, j + 1, k + 1), _tag(i, j + 1, k + 1)]
                ops.element("stdBrick", tag, *nodes, 1, *body)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)


def _analyse(ops, dlambda, steps):
    ops.system("UmfPack")
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.test("NormDispIncr", 1e-12, 10)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", dlambda)
    ops.analysis("Static")
    return [ops.analyze(1) for _ in range(steps)]


def _results(ops, out, prefix):
    top = [_tag(i, j, NZ) for j in range(NY + 1) for i in range(NX + 1)]
    out[prefix + "topDisp"] = [ops.nodeDisp(n) for n in top]
    out[prefix + "midDisp"] = ops.nodeDisp(_tag(1, 1, 1))
    ops.reactions()
    base = [_tag(i, j, 0) for j in range(NY + 1) for i in range(NX + 1)]
    out[prefix + "baseReactions"] = [ops.nodeReaction(n) for n in base]
    out[prefix + "reactionSum"] = [sum(ops.nodeReaction(n, d) for n in base) for d in (1, 2, 3)]
    for e in (1, 8):
        for r in ("stresses", "strains", "force"):
            out[f"{prefix}ele{e}.{r}"] = ops.eleResponse(e, r)
        out[f"{prefix}ele{e}.material2.stress"] = ops.eleResponse(e, "material", 2, "stress")
        out[f"{prefix}ele{e}.material2.strain"] = ops.eleResponse(e, "material", 2, "strain")


def _read(path):
    with open(path) as f:
        return f.read()


def run(ops):
    out = {}
    # 1. Body forces of the element command: per unit volume, constant.
    _build(ops, BODY)
    ops.recorder("Node", "-file", "brick_disp.out", "-time", "-node", _tag(NX, NY, NZ), _tag(1, 1, 1), "-dof", 1, 2, 3, "disp")
    ops.recorder("Element", "-file", "brick_stress.out", "-time", "-ele", 1, "stresses")
    ops.recorder("Element", "-file", "brick_force.out", "-ele", 8, "force")
    out["body.codes"] = _analyse(ops, 0.5, 2)
    out["body.time"] = ops.getTime()
    _results(ops, out, "body.")
    ops.wipe()
    out["body.recorder.disp"] = _read("brick_disp.out")
    out["body.recorder.stress"] = _read("brick_stress.out")
    out["body.recorder.force"] = _read("brick_force.out")

    # 2. eleLoad -selfWeight on the same elements, factored by the pattern.
    _build(ops, BODY)
    ops.eleLoad("-ele", *range(1, 9), "-type", "-selfWeight", 0.5, 1.0, 2.0)
    out["selfWeight.codes"] = _analyse(ops, 0.5, 1)
    _results(ops, out, "selfWeight.")
    ops.wipe()

    # 3. Pressure on the top face as consistent nodal loads (a quarter of each
    #    face's force to each of its corners), no body force.
    _build(ops, ())
    for j in range(NY + 1):
        for i in range(NX + 1):
            share = (1 if i in (0, NX) else 2) * (1 if j in (0, NY) else 2)
            ops.load(_tag(i, j, NZ), 0.0, 0.0, -PRESSURE * share * (LX / NX) * (LY / NY) / 4.0)
    ops.recorder("Node", "-file", "brick_top.out", "-time", "-precision", 10, "-nodeRange", _tag(0, 0, NZ), _tag(NX, NY, NZ), "-dof", 3, "disp")
    out["pressure.codes"] = _analyse(ops, 0.25, 4)
    _results(ops, out, "pressure.")
    ops.wipe()
    out["pressure.recorder.top"] = _read("brick_top.out")
    return out

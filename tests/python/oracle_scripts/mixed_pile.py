"""A pile in soil the way OpenSees scripts build one with the elements at
hand: stdBrick soil on ndf 3 nodes, an elasticBeamColumn pile on ndf 6
nodes re-created after model('basic', '-ndm', 3, '-ndf', 6), tied to the
soil nodes it shares a position with by equalDOF 1 2 3, the base fixed for
both kinds of node by one fixZ with six flags, soil self weight from the
element body forces, then a lateral head load in a second pattern after
loadConst. Element and node recorders run through both stages.
"""

NX, NY, NZ = 2, 2, 3
H = (2.0, 2.0, 1.5)  # element sizes in x, y, z


def _soil_tag(i, j, k):
    return 1 + i + (NX + 1) * (j + (NY + 1) * k)


def run(ops):
    out = {}
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    for k in range(NZ + 1):
        for j in range(NY + 1):
            for i in range(NX + 1):
                ops.node(_soil_tag(i, j, k), H[0] * (i - 1), H[1] * (j - 1), H[2] * k)
    ops.nDMaterial("ElasticIsotropic", 1, 2.0e4, 0.3, 1.8)
    tag = 0
    for k in range(NZ):
        for j in range(NY):
            for i in range(NX):
                tag += 1
                n = [_soil_tag(i, j, k), _soil_tag(i + 1, j, k), _soil_tag(i + 1, j + 1, k), _soil_tag(i, j + 1, k),
                     _soil_tag(i, j, k + 1), _soil_tag(i + 1, j, k + 1), _soil_tag(i + 1, j + 1, k + 1),
                     _soil_tag(i, j + 1, k + 1)]
                ops.element("stdBrick", tag, *n, 1, 0.0, 0.0, -18.0)
    # Lateral boundaries: x faces fixed in x, y faces in y.
    for k in range(1, NZ + 1):
        for j in range(NY + 1):
            for i in range(NX + 1):
                flags = [1 if i in (0, NX) else 0, 1 if j in (0, NY) else 0, 0]
                if any(flags):
                    ops.fix(_soil_tag(i, j, k), *flags)

    ops.model("basic", "-ndm", 3, "-ndf", 6)
    pile = [1000 + k for k in range(NZ + 1)]
    for k, p in enumerate(pile):
        ops.node(p, 0.0, 0.0, H[2] * k)
    ops.node(2000, 0.0, 0.0, H[2] * NZ + 1.0)  # pile head above ground
    ops.geomTransf("Linear", 1, 1.0, 0.0, 0.0)
    for k in range(NZ):
        ops.element("elasticBeamColumn", 100 + k, pile[k], pile[k + 1], 0.2, 3.0e7, 1.2e7, 6e-3, 3e-3, 3e-3, 1)
    ops.element("elasticBeamColumn", 100 + NZ, pile[NZ], 2000, 0.2, 3.0e7, 1.2e7, 6e-3, 3e-3, 3e-3, 1)
    for k in range(1, NZ + 1):
        ops.equalDOF(_soil_tag(1, 1, k), pile[k], 1, 2, 3)
    ops.fixZ(0.0, 1, 1, 1, 1, 1, 1)

    ops.recorder("Node", "-file", "head.out", "-time", "-node", 2000, "-dof", 1, 2, 3, "disp")
    ops.recorder("Element", "-file", "pile.out", "-time", "-ele", 100, 101, "localForce")
    ops.recorder("Element", "-file", "soil.out", "-time", "-ele", 5, "stresses")

    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2000, 0.0, 0.0, -50.0, 0.0, 0.0, 0.0)
    ops.constraints("Transformation")
    ops.numberer("RCM")
    ops.system("UmfPack")
    ops.test("NormDispIncr", 1e-12, 10)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", 0.5)
    ops.analysis("Static")
    out["gravity"] = [ops.analyze(1) for _ in range(2)]
    out["gravity.head"] = ops.nodeDisp(2000)
    out["gravity.surface"] = [ops.nodeDisp(_soil_tag(i, 1, NZ)) for i in range(NX + 1)]
    ops.loadConst("-time", 0.0)
    ops.timeSeries("Linear", 2)
    ops.pattern("Plain", 2, 2)
    ops.load(2000, 20.0, 5.0, 0.0, 0.0, 0.0, 0.0)
    ops.integrator("LoadControl", 0.25)
    out["lateral"] = [ops.analyze(1) for _ in range(4)]
    out["head"] = ops.nodeDisp(2000)
    out["pile"] = [ops.nodeDisp(p) for p in pile]
    out["pile forces"] = [ops.eleResponse(100 + k, "localForce") for k in range(NZ + 1)]
    out["soil 5 stresses"] = ops.eleResponse(5, "stresses")
    ops.reactions()
    out["base reactions"] = [ops.nodeReaction(_soil_tag(i, j, 0)) for j in range(NY + 1) for i in range(NX + 1)]
    out["pile base reaction"] = ops.nodeReaction(pile[0])
    ops.wipe()
    for name in ("head.out", "pile.out", "soil.out"):
        with open(name) as f:
            out["file:" + name] = f.read()
    return out

"""block3D (corners only, and with edge, face and centre points 9-27 in the
20- and 27-point forms) meshing stdBrick elements, and block2D with four and
nine points meshing quads: node tags, coordinates and element connectivity
as getNodeTags, nodeCoord and eleNodes report them; then the distorted brick
block, fixed at its base, under a load on its top corner. With nine block2D
points OpenSees creates only (numX/2)(numY/2) of the quads (BeamSolid meshes
every cell, see docs/commands.md): there only the nodes are compared.
"""

CORNERS = ((0.0, 0.0, 0.0), (4.0, 0.0, 0.0), (4.0, 3.0, 0.0), (0.0, 3.0, 0.0),
           (0.0, 0.0, 2.0), (4.0, 0.0, 2.0), (4.0, 3.0, 2.0), (0.0, 3.0, 2.0))


def _points(n):
    pts = []
    for i, p in enumerate(CORNERS, start=1):
        pts += [i, *p]
    # Points 9-n moved off the trilinear block so that each one shows.
    grid = {9: (0, 0, 1), 10: (2, 0, 1), 11: (2, 2, 1), 12: (0, 2, 1), 13: (1, 0, 0), 14: (2, 1, 0),
            15: (1, 2, 0), 16: (0, 1, 0), 17: (1, 1, 0), 18: (1, 0, 2), 19: (2, 1, 2), 20: (1, 2, 2),
            21: (0, 1, 2), 22: (1, 1, 2), 23: (1, 0, 1), 24: (2, 1, 1), 25: (1, 2, 1), 26: (0, 1, 1),
            27: (1, 1, 1)}
    for k in range(9, n + 1):
        i, j, l = grid[k]
        pts += [k, 2.0 * i + 0.05 * (k % 3) - 0.05, 1.5 * j + 0.04 * (k % 4) - 0.06, 1.0 * l + 0.03 * (k % 5) - 0.06]
    return pts


def _mesh(ops, out, key):
    tags = ops.getNodeTags()
    out[key + "nodeTags"] = tags
    out[key + "coords"] = [ops.nodeCoord(t) for t in tags]
    eles = ops.getEleTags()
    out[key + "eleTags"] = eles
    out[key + "eleNodes"] = [ops.eleNodes(e) for e in eles]


def run(ops):
    out = {}
    for n, divisions, start in ((8, (2, 2, 1), (1, 1)), (20, (3, 2, 2), (101, 11)), (27, (4, 3, 2), (1, 1)),
                                (12, (2, 2, 2), (5, 7))):
        ops.wipe()
        ops.model("basic", "-ndm", 3, "-ndf", 3)
        ops.nDMaterial("ElasticIsotropic", 1, 1000.0, 0.25)
        ops.block3D(*divisions, *start, "stdBrick", 1, *_points(n))
        _mesh(ops, out, f"block3D {n} points ")
    # The 27-point block under load: fixed base, a corner pulled sideways.
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    ops.nDMaterial("ElasticIsotropic", 1, 1000.0, 0.25)
    ops.block3D(4, 3, 2, 1, 1, "stdBrick", 1, *_points(27))
    for t in ops.getNodeTags():
        if abs(ops.nodeCoord(t, 3)) < 1e-9:
            ops.fix(t, 1, 1, 1)
    top = max(ops.getNodeTags())
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(top, 1.0, 2.0, -3.0)
    ops.system("UmfPack")
    ops.numberer("Plain")
    ops.constraints("Plain")
    ops.algorithm("Linear")
    ops.integrator("LoadControl", 1.0)
    ops.analysis("Static")
    out["block3D loaded.code"] = ops.analyze(1)
    out["block3D loaded.disp"] = [ops.nodeDisp(t) for t in ops.getNodeTags()]

    for points, key in ((4, "block2D 4 points "), (9, "block2D 9 points ")):
        ops.wipe()
        ops.model("basic", "-ndm", 2, "-ndf", 2)
        ops.nDMaterial("ElasticIsotropic", 1, 1000.0, 0.25)
        pts = [1, 0.0, 0.0, 2, 4.0, 0.0, 3, 4.0, 3.0, 4, 0.0, 3.0]
        if points == 9:
            pts += [5, 2.0, -0.2, 6, 4.2, 1.5, 7, 2.0, 3.3, 8, -0.1, 1.5, 9, 2.1, 1.6]
        ops.block2D(4, 2, 1, 1, "quad", 1.0, "PlaneStrain", 1, *pts)
        _mesh(ops, out, key)
        if points == 9:
            del out[key + "eleTags"], out[key + "eleNodes"]
    return out

"""nDMaterial('ElasticOrthotropic', ...): a distorted brick under normal and
shear tractions (every compliance term: the Poisson's ratio convention and
each shear modulus), eleResponse stresses/strains, and a quad mesh in plane
strain and plane stress through the PlaneStrain/PlaneStress wrappers (the
condensed 3D law; OpenSees' quad takes no plane form of the orthotropic
material directly) with mass from rho.
"""

MAT = (100.0, 200.0, 300.0, 0.2, 0.25, 0.3, 40.0, 50.0, 60.0, 1.5)
CRD = [(0, 0, 0), (1, 0, 0), (1.1, 1, 0), (0, 1, 0.1), (0, 0, 1), (1, 0.1, 1), (1, 1, 1.05), (0, 1, 1)]


def run(ops):
    out = {}
    for case, force in enumerate([(1, 0, 0), (0, 1, 0), (0, 0, 1), (0.3, -0.2, 0.1)]):
        ops.wipe()
        ops.model("basic", "-ndm", 3, "-ndf", 3)
        for i, c in enumerate(CRD):
            ops.node(i + 1, *map(float, c))
        for n in (1, 2, 3, 4):
            ops.fix(n, 1, 1, 1)
        ops.nDMaterial("ElasticOrthotropic", 1, *MAT)
        ops.element("stdBrick", 1, *range(1, 9), 1)
        ops.timeSeries("Linear", 1)
        ops.pattern("Plain", 1, 1)
        for n in (5, 6, 7, 8):
            ops.load(n, *[0.25 * f for f in force])
        ops.analysis("Static")
        ops.analyze(1)
        out[f"brick{case}.disp"] = [ops.nodeDisp(n) for n in (5, 6, 7, 8)]
        out[f"brick{case}.stresses"] = ops.eleResponse(1, "stresses")
        out[f"brick{case}.strains"] = ops.eleResponse(1, "strains")
    for kind in ("PlaneStrain", "PlaneStress"):
        ops.wipe()
        ops.model("basic", "-ndm", 2, "-ndf", 2)
        tag = 0
        for j in range(3):
            for i in range(3):
                tag += 1
                ops.node(tag, i + 0.1 * j * (i == 1), j + 0.05 * i)
        for n in (1, 2, 3):
            ops.fix(n, 1, 1)
        ops.nDMaterial("ElasticOrthotropic", 1, *MAT)
        ops.nDMaterial(kind, 2, 1)
        e = 0
        for j in range(2):
            for i in range(2):
                e += 1
                a = 1 + i + 3 * j
                ops.element("quad", e, a, a + 1, a + 4, a + 3, 0.5, kind, 2)
        ops.timeSeries("Linear", 1)
        ops.pattern("Plain", 1, 1)
        ops.load(9, 1.0, -0.5)
        ops.load(7, -0.3, 0.2)
        ops.analysis("Static")
        ops.analyze(1)
        out[kind + ".disp"] = [ops.nodeDisp(n) for n in (7, 8, 9)]
        out[kind + ".stresses"] = ops.eleResponse(4, "stresses")
        ops.wipeAnalysis()
        out[kind + ".eigen"] = ops.eigen("-fullGenLapack", 3)
    ops.wipe()
    return out

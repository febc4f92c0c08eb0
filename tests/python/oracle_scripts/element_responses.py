"""eleResponse names, sizes and values for every element type, after one
loaded step, including the material responses reached through the element.
A name an implementation does not know is recorded as "[]" (OpenSeesPy
returns an empty list) or "error" (the call raised).
"""

NAMES = (
    "force", "forces", "globalForce", "globalForces", "localForce", "localForces",
    "basicForce", "basicForces", "deformation", "deformations", "basicDeformation",
    "basicDeformations", "axialForce", "stress", "stresses", "strain", "strains",
    "basicStiffness", "xaxis", "yaxis", "zaxis",
)
MATERIAL_NAMES = ("stress", "strain", "tangent", "stressStrain")


def _query(ops, tag, *args):
    try:
        value = ops.eleResponse(tag, *args)
    except Exception:  # noqa: BLE001 - the error behaviour is what is compared
        return "error"
    if isinstance(value, (list, tuple)):
        return list(value) if value else "[]"
    return repr(value)


def _analyse(ops):
    ops.system("UmfPack")
    ops.constraints("Transformation")
    ops.numberer("Plain")
    ops.test("NormDispIncr", 1e-12, 20)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", 1.0)
    ops.analysis("Static")
    return ops.analyze(1)


def _collect(ops, out, label, tag, material_paths):
    out[label + ".eleType"] = ops.eleType(tag) if hasattr(ops, "eleType") else "n/a"
    for name in NAMES:
        out[f"{label}.{name}"] = _query(ops, tag, name)
    for path in material_paths:
        for name in MATERIAL_NAMES:
            out[f"{label}.{' '.join(map(str, path))} {name}"] = _query(ops, tag, *path, name)


def run(ops):
    out = {}
    # elasticBeamColumn on ndf 6 nodes.
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    ops.node(1, 0.0, 0.0, 0.0)
    ops.node(2, 1.0, 0.5, 3.0)
    ops.fix(1, 1, 1, 1, 1, 1, 1)
    ops.geomTransf("Linear", 1, 1.0, 0.0, 0.0)
    ops.element("elasticBeamColumn", 1, 1, 2, 0.5, 30e6, 12e6, 0.04, 0.02, 0.03, 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, 10.0, 5.0, -300.0, 1.0, 2.0, 3.0)
    out["beam.code"] = _analyse(ops)
    _collect(ops, out, "beam", 1, [("material", 1), ("section", 1)])

    # truss and corotTruss on ndf 3 and ndf 6 nodes.
    for element in ("truss", "corotTruss"):
        for ndf in (3, 6):
            ops.wipe()
            ops.model("basic", "-ndm", 3, "-ndf", ndf)
            ops.node(1, 0.0, 0.0, 0.0)
            ops.node(2, 2.0, 1.0, 0.5)
            ops.fix(1, *([1] * ndf))
            ops.fix(2, *([0, 1, 1] + [1] * (ndf - 3)))
            ops.uniaxialMaterial("ElasticPP", 1, 1000.0, 0.001)
            ops.element(element, 1, 1, 2, 2.0, 1)
            ops.timeSeries("Linear", 1)
            ops.pattern("Plain", 1, 1)
            ops.load(2, 1.5, *([0.0] * (ndf - 1)))
            out[f"{element}{ndf}.code"] = _analyse(ops)
            _collect(ops, out, f"{element}{ndf}", 1, [("material",), ("material", 1), ("section",)])

    # zeroLength with two springs.
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    ops.node(1, 0.0, 0.0, 0.0)
    ops.node(2, 0.0, 0.0, 0.0)
    ops.fix(1, 1, 1, 1)
    ops.fix(2, 0, 0, 1)
    ops.uniaxialMaterial("Elastic", 1, 100.0)
    ops.uniaxialMaterial("Elastic", 2, 50.0)
    ops.element("zeroLength", 1, 1, 2, "-mat", 1, 2, "-dir", 1, 2)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, 3.0, -1.0, 0.0)
    out["zeroLength.code"] = _analyse(ops)
    _collect(ops, out, "zeroLength", 1, [("material", 1), ("material", 2), ("material", 3)])

    # stdBrick, one element under a corner load.
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    corners = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
    for i, x in enumerate(corners, start=1):
        ops.node(i, *x)
        if i <= 4:
            ops.fix(i, 1, 1, 1)
    ops.nDMaterial("ElasticIsotropic", 1, 1000.0, 0.25, 1.5)
    ops.element("stdBrick", 1, *range(1, 9), 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(7, 1.0, 2.0, -3.0)
    out["stdBrick.code"] = _analyse(ops)
    _collect(ops, out, "stdBrick", 1, [("material", 1), ("material", 8), ("integrPoint", 3), ("material", 9)])
    ops.wipe()
    return out

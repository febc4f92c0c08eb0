"""The component names every element response carries: written by XML
element recorders as <ResponseType> entries (what tools reading OpenSees
XML see), one recorder per element type and response.
"""
import re

CASES = {
    "beam": ("elasticBeamColumn", 1, ("force", "localForce", "basicForce", "basicDeformations")),
    "truss3": ("truss", 2, ("force", "localForce", "axialForce", "basicDeformation", "material 1 stress")),
    "corotTruss3": ("corotTruss", 3, ("force", "axialForce", "basicDeformation")),
    "zeroLength": ("zeroLength", 4, ("force", "basicForce", "deformation", "material 1 stress")),
    "stdBrick": ("stdBrick", 5, ("force", "stresses", "strains", "material 1 stress")),
}


def run(ops):
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    ops.node(1, 0.0, 0.0, 0.0)
    ops.node(2, 0.0, 0.0, 3.0)
    ops.fix(1, 1, 1, 1, 1, 1, 1)
    ops.geomTransf("Linear", 1, 1.0, 0.0, 0.0)
    ops.element("elasticBeamColumn", 1, 1, 2, 0.5, 30e6, 12e6, 0.04, 0.02, 0.02, 1)
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    corners = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
    for i, x in enumerate(corners, start=10):
        ops.node(i, *x)
    ops.uniaxialMaterial("Elastic", 1, 100.0)
    ops.element("truss", 2, 10, 16, 1.0, 1)
    ops.element("corotTruss", 3, 10, 16, 1.0, 1)
    ops.element("zeroLength", 4, 10, 11, "-mat", 1, 1, "-dir", 1, 3)
    ops.nDMaterial("ElasticIsotropic", 1, 1000.0, 0.25, 1.5)
    ops.element("stdBrick", 5, *range(10, 18), 1)
    files = {}
    for label, (_, tag, responses) in CASES.items():
        for response in responses:
            name = f"{label}_{response.replace(' ', '_')}.xml"
            try:
                ops.recorder("Element", "-xml", name, "-ele", tag, *response.split())
                files[f"{label} {response}"] = name
            except Exception:  # noqa: BLE001
                files[f"{label} {response}"] = None
    ops.record()
    ops.wipe()
    out = {}
    for key, name in files.items():
        if name is None:
            out[key] = "recorder raised"
            continue
        with open(name) as f:
            text = f.read()
        out[key] = re.findall(r"<ResponseType>(.*?)</ResponseType>", text)
    return out

"""recorder('Drift') on a two-storey column, in the only form OpenSeesPy
3.7.1 accepts (one node pair, '-time' last): the file, and the drift computed
from nodeDisp for the same pair. OpenSeesPy 3.7.1 misparses this recorder
(its file holds another pair's drift; see KNOWN_DIFFERENCES); the
nodeDisp-based drift is the check both sides must pass, and BeamSolid's file
equals it (test_drift_recorder checks the closed form).
"""


def run(ops):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    for n, y in ((1, 0.0), (2, 3.0), (3, 7.0)):
        ops.node(n, 0.0, y)
    ops.fix(1, 1, 1, 1)
    ops.geomTransf("Linear", 1)
    ops.element("elasticBeamColumn", 1, 1, 2, 0.01, 2.0e8, 2.0e-4, 1)
    ops.element("elasticBeamColumn", 2, 2, 3, 0.01, 2.0e8, 2.0e-4, 1)
    ops.recorder("Drift", "-file", "drift23.out", "-iNode", 2, "-jNode", 3, "-dof", 1, "-perpDirn", 2, "-time")
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(3, 10.0, 0.0, 0.0)
    ops.system("UmfPack")
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.test("NormDispIncr", 1e-12, 10)
    ops.algorithm("Linear")
    ops.integrator("LoadControl", 0.5)
    ops.analysis("Static")
    drift = []
    for _ in range(3):
        ops.analyze(1)
        drift.append((ops.nodeDisp(3, 1) - ops.nodeDisp(2, 1)) / 4.0)
    ops.wipe()
    with open("drift23.out") as f:
        rows = [[float(v) for v in line.split()] for line in f if line.strip()]
    return {"drift.fromNodeDisp": drift, "drift.file": rows}

"""modalDamping after eigen.

A two-storey 2D cantilever column (nodal masses; then with element mass too)
and a two-storey shear frame on equalDOF floors, given an initial push and
left to vibrate, damped by modalDamping(z) (all modes found), modalDamping(z1,
z2) (one ratio per mode) and more ratios than modes (extra ignored), under
Newmark and HHT. Displacements, velocities and iteration counts (the damping
force is in the residual only, so steps iterate) at every step.
"""


def _column(ops, out, tag, modes, factors, element_mass=0.0, integrator=("Newmark", 0.5, 0.25)):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    ops.node(1, 0.0, 0.0)
    ops.node(2, 0.0, 3.0)
    ops.node(3, 0.0, 6.0)
    ops.fix(1, 1, 1, 1)
    ops.mass(2, 10.0, 10.0, 0.2)
    ops.mass(3, 8.0, 8.0, 0.1)
    ops.geomTransf("Linear", 1)
    ops.element("elasticBeamColumn", 1, 1, 2, 0.01, 2.0e8, 1.0e-4, 1, "-mass", element_mass)
    ops.element("elasticBeamColumn", 2, 2, 3, 0.01, 2.0e8, 1.0e-4, 1, "-mass", element_mass)
    ops.timeSeries("Path", 1, "-dt", 0.01, "-values", 0.0, 1.0, 0.0)
    ops.pattern("Plain", 1, 1)
    ops.load(3, 100.0, -50.0, 5.0)
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.system("UmfPack")
    ops.test("NormDispIncr", 1e-12, 20)
    ops.algorithm("Newton")
    ops.integrator(*integrator)
    ops.analysis("Transient")
    out["column.%s.eigen" % tag] = ops.eigen(modes)
    ops.modalDamping(*factors)
    rows = []
    for _ in range(30):
        code = ops.analyze(1, 0.01)
        rows.append([code, ops.testIter(), *ops.nodeDisp(3), *ops.nodeVel(2)])
    out["column." + tag] = rows


def _shear_frame(ops, out, factors):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    for t, xy in {1: (0.0, 0.0), 2: (4.0, 0.0), 3: (0.0, 3.0), 4: (4.0, 3.0), 5: (0.0, 6.0), 6: (4.0, 6.0)}.items():
        ops.node(t, *xy)
    ops.fix(1, 1, 1, 1)
    ops.fix(2, 1, 1, 1)
    for t in (3, 5):
        ops.mass(t, 5.0, 1.0e-3, 0.0)
        ops.equalDOF(t, t + 1, 1)
    ops.geomTransf("Linear", 1)
    for e, (i, j) in enumerate(((1, 3), (2, 4), (3, 5), (4, 6)), start=1):
        ops.element("elasticBeamColumn", e, i, j, 0.02, 2.0e8, 2.0e-4, 1)
    ops.element("elasticBeamColumn", 5, 3, 4, 0.05, 2.0e8, 1.0e-2, 1)
    ops.element("elasticBeamColumn", 6, 5, 6, 0.05, 2.0e8, 1.0e-2, 1)
    ops.timeSeries("Trig", 1, 0.0, 0.2, 0.2)
    ops.pattern("Plain", 1, 1)
    ops.load(5, 50.0, 0.0, 0.0)
    ops.constraints("Transformation")
    ops.numberer("Plain")
    ops.system("UmfPack")
    ops.test("NormDispIncr", 1e-12, 20)
    ops.algorithm("Newton")
    ops.integrator("Newmark", 0.5, 0.25)
    ops.analysis("Transient")
    out["frame.%d.eigen" % len(factors)] = ops.eigen(2)
    ops.modalDamping(*factors)
    rows = []
    for _ in range(30):
        code = ops.analyze(1, 0.01)
        rows.append([code, ops.testIter(), ops.nodeDisp(3, 1), ops.nodeDisp(5, 1), ops.nodeVel(6, 1)])
    out["frame.%d" % len(factors)] = rows


def run(ops):
    out = {}
    _column(ops, out, "one", 2, (0.05,))
    _column(ops, out, "each", 2, (0.05, 0.02))
    _column(ops, out, "extra", 2, (0.05, 0.02, 0.01))
    _column(ops, out, "mode1", 1, (0.1,))
    _column(ops, out, "elementMass", 3, (0.05,), element_mass=3.0)
    _column(ops, out, "hht", 2, (0.05, 0.03), integrator=("HHT", 0.9))
    _shear_frame(ops, out, (0.05,))
    _shear_frame(ops, out, (0.02, 0.1))
    ops.wipe()
    return out

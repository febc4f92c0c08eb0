"""BeamContact3D between a beam segment and one soil node pressed onto it, then the pile pulled
up (DisplacementControl) so that the node sticks and then slides: every response OpenSees names
for the element (force, frictionforce, forcescalar, masterforce, mastermoment, masterreaction, slip,
gap, status) after each step, the soil node's displacement and the pull's load factor.

frictionforce is the friction acting on the pile: a pile pulled up reads a negative z. The same
pull-out runs again with BeamContact3Dp (penalty 1e6 instead of the multiplier). Then a soil node
under the pile tip against BeamEndContact3D and BeamEndContact3Dp, pressed and released.

Nodes: beam 1 (0, 0, 0) and 2 (0, 0, 2), ndf 6, free only along z (a 1 kN/m spring under 1); soil node 3 at (R, 0, 1) on a
zeroLength spring (k = 1000 in x, y, z) to fixed node 8, pushed onto the pile by N = 10 kN;
Lagrange multiplier node 4. Friction mu = 0.3 and stick stiffness G = 1000 from the start (stage
1), so the pile is held vertically by the stick: sliding starts at mu N = 3 kN, a pull of
3/G + 3/k = 6 mm (steps 1-5 stick, 6-10 slide).
"""
R = 0.3
RESPONSES = ("force", "frictionforce", "forcescalar", "masterforce", "mastermoment", "masterreaction", "slip")


def run(ops):
    out = {}
    _pull(ops, out, "")
    _pull(ops, out, "penalty.")
    _end(ops, out, "")
    _end(ops, out, "penalty.")
    ops.wipe()
    return out


def _pull(ops, out, prefix):
    """The pull-out; prefix 'penalty.' runs it with BeamContact3Dp (penalty 1e6, no multiplier)."""
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    ops.node(1, 0.0, 0.0, 0.0)
    ops.node(2, 0.0, 0.0, 2.0)
    for n in (1, 2):
        ops.fix(n, 1, 1, 0, 1, 1, 1)
    # A soft vertical spring (1 kN/m) under the pile: before the first iteration has a normal
    # force the contact has no friction capacity, and the pile no vertical stiffness. (OpenSees
    # solves that singular first iteration regardless; BeamSolid refuses a singular matrix.)
    ops.node(9, 0.0, 0.0, 0.0)
    ops.fix(9, 1, 1, 1, 1, 1, 1)
    ops.uniaxialMaterial("Elastic", 9, 1.0)
    ops.element("zeroLength", 31, 9, 1, "-mat", 9, "-dir", 3)
    ops.geomTransf("Linear", 1, 1.0, 0.0, 0.0)
    ops.element("elasticBeamColumn", 10, 1, 2, 0.28, 3e7, 1.2e7, 0.0127, 0.0064, 0.0064, 1)
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    ops.node(3, R, 0.0, 1.0)
    if not prefix:
        ops.node(4, R, 0.0, 1.0)  # the multiplier node (none with the penalty)
    ops.node(8, R, 0.0, 1.0)
    ops.fix(8, 1, 1, 1)
    ops.uniaxialMaterial("Elastic", 3, 1000.0)
    ops.element("zeroLength", 30, 8, 3, "-mat", 3, 3, 3, "-dir", 1, 2, 3)
    ops.nDMaterial("ContactMaterial3D", 1, 0.3, 1000.0, 0.0, 0.0)
    if prefix:
        ops.element("BeamContact3Dp", 20, 1, 2, 3, R, 1, 1, 1.0e6, 0)
    else:
        ops.element("BeamContact3D", 20, 1, 2, 3, 4, R, 1, 1, 1e-10, 1e-10)

    ops.updateMaterialStage("-material", 1, "-stage", 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(3, -10.0, 0.0, 0.0)
    ops.constraints("Transformation")
    ops.numberer("Plain")
    ops.system("UmfPack")
    ops.test("NormDispIncr", 1e-12, 30)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", 1.0)
    ops.analysis("Static")
    out[prefix + "press.code"] = ops.analyze(1)
    _read(ops, out, prefix + "press")

    ops.loadConst("-time", 0.0)
    ops.timeSeries("Linear", 2)
    ops.pattern("Plain", 2, 2)
    ops.load(2, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0)
    ops.integrator("DisplacementControl", 2, 3, 0.001)
    for step in range(10):
        out[f"{prefix}pull{step}.code"] = ops.analyze(1)
        out[f"{prefix}pull{step}.iter"] = ops.testIter()
        out[f"{prefix}pull{step}.lambda"] = ops.getLoadFactor(2)
        _read(ops, out, f"{prefix}pull{step}")


def _end(ops, out, prefix):
    """BeamEndContact3D (BeamEndContact3Dp with prefix 'penalty.'): the pile's tip is node 2 at
    z = 0 (iNode; jNode 1 above it), a soil node 3 under the tip on springs is pushed up against
    the face and then pulled away (the Path factor turns negative), so the contact closes and
    opens."""
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    ops.node(1, 0.0, 0.0, 2.0)
    ops.node(2, 0.0, 0.0, 0.0)
    ops.fix(1, 1, 1, 1, 1, 1, 1)
    ops.fix(2, 1, 1, 0, 1, 1, 1)
    ops.geomTransf("Linear", 1, 1.0, 0.0, 0.0)
    ops.element("elasticBeamColumn", 10, 1, 2, 0.28, 3e7, 1.2e7, 0.0127, 0.0064, 0.0064, 1)
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    ops.node(3, 0.1, 0.05, -0.001)
    if not prefix:
        ops.node(4, 0.1, 0.05, -0.001)
    ops.node(8, 0.1, 0.05, -0.001)
    ops.fix(8, 1, 1, 1)
    ops.uniaxialMaterial("Elastic", 3, 1000.0)
    ops.element("zeroLength", 30, 8, 3, "-mat", 3, 3, 3, "-dir", 1, 2, 3)
    if prefix:
        ops.element("BeamEndContact3Dp", 20, 2, 1, 3, R, 1.0e6)
    else:
        ops.element("BeamEndContact3D", 20, 2, 1, 3, 4, R, 1e-10, 1e-10)
    ops.timeSeries("Path", 1, "-time", 0.0, 1.0, 2.0, 3.0, "-values", 0.0, 1.0, 0.4, -0.5)
    ops.pattern("Plain", 1, 1)
    ops.load(3, 0.0, 0.0, 20.0)
    ops.constraints("Transformation")
    ops.numberer("Plain")
    ops.system("UmfPack")
    ops.test("NormDispIncr", 1e-12, 30)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", 0.5)
    ops.analysis("Static")
    for step in range(6):
        key = f"{prefix}end{step}"
        out[key + ".code"] = ops.analyze(1)
        out[key + ".iter"] = ops.testIter()
        for r in ("force", "masterforce"):
            out[f"{key}.{r}"] = ops.eleResponse(20, r)
        out[key + ".soil"] = ops.nodeDisp(3)
        out[key + ".tip"] = ops.nodeDisp(2, 3)


def _read(ops, out, key):
    for r in RESPONSES:
        out[f"{key}.{r}"] = ops.eleResponse(20, r)
    out[f"{key}.soil"] = ops.nodeDisp(3)

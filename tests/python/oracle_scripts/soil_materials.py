"""J2Plasticity and DruckerPrager in one stdBrick and one quad, loaded past yield.

Run by tests/python/test_soil_materials_oracle.py with both BeamSolid and
OpenSeesPy (not part of the SCRIPTS set). Every element holds a homogeneous
state (symmetry planes, a face pushed or pulled), so the Gauss point
stresses are the material's answer on the path.
- j2.brick: uniaxial stress, cyclic to +-5 yield strains, saturation and
  linear hardening.
- j2.quad.PlaneStrain / j2.quad.PlaneStress: the same in a 2D quad.
- dp.brick: confining pressure 10 (loads), then the top pushed down past
  the cone; associative, non-associative, and with saturation and linear
  isotropic hardening (theta 1); then non-associative with the confining
  stage elastic (setParameter 'materialState' 0, the route OpenSeesPy
  3.7.1 honours) and plastic after (2). 'state' is compared too.
- dp.quad: the same three in plane-strain biaxial compression.
"""

CUBE = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]


def _analysis(ops, dt):
    ops.constraints("Transformation")
    ops.numberer("Plain")
    ops.system("FullGeneral")
    ops.test("NormDispIncr", 1e-10, 25)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", dt)
    ops.analysis("Static")


def _brick(ops, material):
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    for i, x in enumerate(CUBE, start=1):
        ops.node(i, *[float(c) for c in x])
        ops.fix(i, int(x[0] == 0), int(x[1] == 0), int(x[2] == 0))
    ops.nDMaterial(*material)
    ops.element("stdBrick", 1, *range(1, 9), material[1])


def _quad(ops, material, kind):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 2)
    for i, x in enumerate([(0, 0), (1, 0), (1, 1), (0, 1)], start=1):
        ops.node(i, float(x[0]), float(x[1]))
        ops.fix(i, int(x[0] == 0), int(x[1] == 0))
    ops.nDMaterial(*material)
    ops.element("quad", 1, 1, 2, 3, 4, 1.0, kind, material[1])


def _record(ops, out, key, top_nodes, dof):
    """Per step: material 1 stress and strain, the top face reaction."""
    ops.reactions()
    out.setdefault(key + ".stress", []).append(ops.eleResponse(1, "material", "1", "stress"))
    out.setdefault(key + ".strain", []).append(ops.eleResponse(1, "material", "1", "strain"))
    out.setdefault(key + ".reaction", []).append(sum(ops.nodeReaction(n, dof) for n in top_nodes))
    if key.startswith("dp"):
        # I1, ||s - beta||, tr(eps_p), ||dev(eps_p)||, ||eps_p||
        out.setdefault(key + ".state", []).append(ops.eleResponse(1, "material", "1", "state"))


def _cyclic_top(ops, out, key, top_nodes, dof, amplitude, steps_per_leg=12):
    """Top face displaced through 0 -> a -> -a -> a/2 by sp in a Path series."""
    # (a last point past the end of the run: the analysis time accumulates
    # round-off, and a path is 0 just past its end in OpenSees)
    ops.timeSeries("Path", 1, "-time", 0.0, 1.0, 2.0, 3.0, 4.0, "-values", 0.0, amplitude, -amplitude, 0.5 * amplitude,
                   0.5 * amplitude)
    ops.pattern("Plain", 1, 1)
    for n in top_nodes:
        ops.sp(n, dof, 1.0)
    _analysis(ops, 1.0 / steps_per_leg)
    codes = []
    for _ in range(3 * steps_per_leg):
        codes.append(ops.analyze(1))
        _record(ops, out, key, top_nodes, dof)
    out[key + ".codes"] = codes


def run(ops):
    out = {}
    # ---- J2: K, G, sig0, sigInf, delta, H
    K, G = 160e3, 80e3
    E = 9 * K * G / (3 * K + G)
    j2 = ("J2Plasticity", 1, K, G, 250.0, 320.0, 40.0, 900.0)
    _brick(ops, j2)
    _cyclic_top(ops, out, "j2.brick", [5, 6, 7, 8], 3, 5 * 250.0 / E)
    for kind in ("PlaneStrain", "PlaneStress"):
        _quad(ops, j2, kind)
        _cyclic_top(ops, out, "j2.quad." + kind, [3, 4], 2, 5 * 250.0 / E)

    # ---- Drucker-Prager (the manual's triaxial example constants), confining 10
    for name, rho_bar, hardening in (("assoc", 0.398, (0.0, 0.0, 0.0, 0.0, 0.0, 1.0)),
                                      ("nonassoc", 0.1, (0.0, 0.0, 0.0, 0.0, 0.0, 1.0)),
                                      ("hardening", 0.2, (30.0, 5.0, 40.0, 0.0, 150.0, 1.0))):
        kinf, ko, d1, d2, h, theta = hardening
        dp = ("DruckerPrager", 1, 27777.78, 9259.26, 5.0, 0.398, rho_bar, kinf, ko, d1, d2, h, theta, 1.7)
        _brick(ops, dp)
        # Faces x = 1 (nodes 2, 3, 6, 7) and y = 1 (3, 4, 7, 8): 10 over the unit face, 2.5 a node.
        loads = [(n, 1, -2.5) for n in (2, 3, 6, 7)] + [(n, 2, -2.5) for n in (3, 4, 7, 8)]
        _brick_confined(ops, out, "dp.brick." + name, loads, 0.004)
        _quad(ops, dp, "PlaneStrain")
        _quad_confined(ops, out, "dp.quad." + name, 0.004)
    # Gravity-stage practice: elastic while confined, plastic for the shearing.
    dp = ("DruckerPrager", 1, 27777.78, 9259.26, 5.0, 0.398, 0.1, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 1.7)
    _brick(ops, dp)
    loads = [(n, 1, -2.5) for n in (2, 3, 6, 7)] + [(n, 2, -2.5) for n in (3, 4, 7, 8)]
    _brick_confined(ops, out, "dp.brick.staged", loads, 0.004, stage=(0, 2))
    return out


def _brick_confined(ops, out, key, loads, amplitude, stage=None):
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    for node, dof, value in loads:
        f = [0.0, 0.0, 0.0]
        f[dof - 1] = value
        ops.load(node, *f)
    _shear_after_confinement(ops, out, key, [5, 6, 7, 8], 3, amplitude, stage)


def _quad_confined(ops, out, key, amplitude, stage=None):
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    for node in (2, 3):
        ops.load(node, -5.0, 0.0)
    _shear_after_confinement(ops, out, key, [3, 4], 2, amplitude, stage)


def _shear_after_confinement(ops, out, key, top_nodes, dof, amplitude, stage):
    # The confining load on the top face too, as a reaction-free start: the
    # top is held by the sp of pattern 2 only after the confinement.
    ndf = 3 if dof == 3 else 2
    for n in top_nodes:
        f = [0.0] * ndf
        f[dof - 1] = -10.0 / len(top_nodes)
        ops.load(n, *f)
    if stage is not None:
        ops.setParameter("-val", stage[0], "-ele", 1, "materialState")
    _analysis(ops, 0.25)
    codes = [ops.analyze(4)]
    # (no reaction: the top face is free under its load in this stage)
    out[key + ".confine.stress"] = [ops.eleResponse(1, "material", "1", "stress")]
    out[key + ".confine.strain"] = [ops.eleResponse(1, "material", "1", "strain")]
    ops.loadConst("-time", 0.0)
    if stage is not None:
        ops.setParameter("-val", stage[1], "-ele", 1, "materialState")
    # Axial compression: the top face moved on from where the confinement left it.
    start = ops.nodeDisp(top_nodes[0], dof)
    ops.timeSeries("Path", 2, "-time", 0.0, 20.0, "-values", start, start - amplitude)
    ops.pattern("Plain", 2, 2)
    for n in top_nodes:
        ops.sp(n, dof, 1.0)
    ops.integrator("LoadControl", 1.0)
    for _ in range(20):
        codes.append(ops.analyze(1))
        _record(ops, out, key, top_nodes, dof)
    out[key + ".codes"] = codes

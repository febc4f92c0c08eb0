"""Section Aggregator in 2D (and 3D) and shear-flexible force-based beams.

A 2D fiber section aggregated with an elastic-plastic shear spring (Vy) in a
zeroLengthSection driven in shear and in bending; forceBeamColumn
cantilevers whose sections are an Aggregator of a fiber section and a Vy
material, an Aggregator of P and Mz materials alone, and an Elastic section
with G and alphaY (Timoshenko; a dispBeamColumn leaves its Vy unstrained),
pushed at the tip; a consistent-mass
force-based cantilever's eigenvalues with -cMass (OpenSees keeps its mass lumped); and a 3D zeroLengthSection of
an Aggregator of P, Mz, My and T materials.
"""


def _analysis(ops, test=("NormDispIncr", 1e-10, 20)):
    ops.system("BandGeneral")
    ops.numberer("Plain")
    ops.constraints("Plain")
    ops.test(*test)
    ops.algorithm("Newton")


def _fiber_section(ops, tag):
    ops.uniaxialMaterial("Steel01", 1, 50.0, 29000.0, 0.01)
    ops.section("Fiber", tag)
    ops.patch("rect", 1, 12, 1, -6.0, -3.0, 6.0, 3.0)


def _zero_length(ops, out):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    _fiber_section(ops, 1)
    ops.uniaxialMaterial("Steel01", 2, 8.0, 4000.0, 0.05)
    ops.section("Aggregator", 2, 2, "Vy", "-section", 1)
    ops.node(1, 0.0, 0.0)
    ops.node(2, 0.0, 0.0)
    ops.fix(1, 1, 1, 1)
    ops.fix(2, 1, 0, 0)
    ops.element("zeroLengthSection", 1, 1, 2, 2)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, 0.0, 1.0, 100.0)
    _analysis(ops)
    ops.integrator("DisplacementControl", 2, 2, 0.0005)
    ops.analysis("Static")
    path, iters = [], []
    for _ in range(10):
        ops.analyze(1)
        iters.append(ops.testIter())
        path.append(ops.nodeDisp(2))
    out["zl.path"] = path
    out["zl.iters"] = iters
    for what in ("force", "deformation", "stiffness"):
        out["zl.section " + what] = ops.eleResponse(1, "section", what)
    out["zl.fiber"] = ops.eleResponse(1, "section", "fiber", 5.5, 0.0, "stressStrain")
    out["zl.force"] = ops.eleResponse(1, "force")
    out["zl.basicForce"] = ops.eleResponse(1, "basicForce")


def _cantilever(ops, out, key, build_section, steps, dU, responses=("force", "localForce", "basicForce",
                                                                     "basicDeformation", "plasticDeformation",
                                                                     "basicStiffness"), element="forceBeamColumn"):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    build_section(ops)
    length = 100.0
    ops.node(1, 0.0, 0.0)
    ops.node(2, 0.0, length)
    ops.fix(1, 1, 1, 1)
    ops.geomTransf("Linear", 1)
    ops.beamIntegration("Lobatto", 1, 3, 4)
    ops.element(element, 1, 1, 2, 1, 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, 1.0, 0.0, 0.0)
    _analysis(ops)
    ops.integrator("DisplacementControl", 2, 1, dU)
    ops.analysis("Static")
    path, factor, iters = [], [], []
    for _ in range(steps):
        ops.analyze(1)
        iters.append(ops.testIter())
        path.append(ops.nodeDisp(2))
        factor.append(ops.getLoadFactor(1))
    out[key + "path"] = path
    out[key + "factor"] = factor
    out[key + "iters"] = iters
    for what in responses:
        out[key + what] = ops.eleResponse(1, what)
    for n in (1, 2):
        for what in ("force", "deformation", "stiffness"):
            out[f"{key}section {n} {what}"] = ops.eleResponse(1, "section", n, what)


def _fiber_with_shear(ops):
    _fiber_section(ops, 1)
    ops.uniaxialMaterial("Steel01", 2, 30.0, 11200.0 * 72.0 * 5.0 / 6.0, 0.02)
    ops.section("Aggregator", 3, 2, "Vy", "-section", 1)


def _materials_only(ops):
    ops.uniaxialMaterial("Elastic", 1, 29000.0 * 72.0)
    ops.uniaxialMaterial("Steel01", 2, 3000.0, 29000.0 * 864.0, 0.02)
    ops.section("Aggregator", 3, 1, "P", 2, "Mz")


def _timoshenko(ops):
    ops.section("Elastic", 3, 29000.0, 72.0, 864.0, 11200.0, 5.0 / 6.0)


def _mass(ops, out):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    ops.section("Elastic", 1, 29000.0, 20.0, 800.0)
    ops.node(1, 0.0, 0.0)
    for k in range(1, 4):
        ops.node(k + 1, 0.0, 40.0 * k)
    ops.fix(1, 1, 1, 1)
    ops.geomTransf("Linear", 1)
    ops.beamIntegration("Lobatto", 1, 1, 5)
    ops.element("forceBeamColumn", 1, 1, 2, 1, 1, "-mass", 0.01, "-cMass")
    ops.element("forceBeamColumn", 2, 2, 3, 1, 1, "-mass", 0.01, "-cMass")
    ops.element("forceBeamColumn", 3, 3, 4, 1, 1, "-mass", 0.01)
    out["mass.eigen"] = ops.eigen("-fullGenLapack", 4)


def _aggregator_3d(ops, out):
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    ops.uniaxialMaterial("Elastic", 1, 5000.0)
    ops.uniaxialMaterial("Steel01", 2, 200.0, 40000.0, 0.05)
    ops.uniaxialMaterial("Steel01", 3, 100.0, 30000.0, 0.05)
    ops.uniaxialMaterial("ElasticPP", 4, 20000.0, 0.004)
    ops.section("Aggregator", 1, 1, "P", 2, "Mz", 3, "My", 4, "T")
    ops.node(1, 0.0, 0.0, 0.0)
    ops.node(2, 0.0, 0.0, 0.0)
    ops.fix(1, 1, 1, 1, 1, 1, 1)
    ops.fix(2, 1, 0, 1, 0, 0, 0)
    ops.element("zeroLengthSection", 1, 1, 2, 1, "-orient", 0.0, 1.0, 0.0, -1.0, 0.0, 0.0)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, 1.0, 0.0, 0.0, 20.0, 10.0, 30.0)
    _analysis(ops)
    ops.integrator("DisplacementControl", 2, 6, 0.001)
    ops.analysis("Static")
    path = []
    for _ in range(8):
        ops.analyze(1)
        path.append(ops.nodeDisp(2))
    out["3d.path"] = path
    for what in ("force", "deformation", "stiffness"):
        out["3d.section " + what] = ops.eleResponse(1, "section", what)
    out["3d.force"] = ops.eleResponse(1, "force")


def run(ops):
    out = {}
    _zero_length(ops, out)
    _cantilever(ops, out, "shear.", _fiber_with_shear, 25, 0.05)
    _cantilever(ops, out, "pm.", _materials_only, 12, 0.1)
    # Elastic: no plastic deformation to compare (only round-off about zero).
    _cantilever(ops, out, "timoshenko.", _timoshenko, 2, 0.05,
                responses=("force", "localForce", "basicForce", "basicDeformation", "basicStiffness"))
    _cantilever(ops, out, "timoshenko disp.", _timoshenko, 2, 0.05,
                responses=("force", "localForce", "basicForce", "basicDeformation", "basicStiffness"),
                element="dispBeamColumn")
    _mass(ops, out)
    _aggregator_3d(ops, out)
    ops.wipe()
    return out

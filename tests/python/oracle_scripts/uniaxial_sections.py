"""section('Uniaxial', tag, matTag, quantity) in the uses of public scripts.

2D: a Steel01 moment-rotation spring (zeroLengthSection of a Uniaxial 'Mz'
section) at the base of an elastic cantilever pushed past yield by
DisplacementControl; 'P' and 'Vy' springs pulled in turn; an Aggregator of
a Uniaxial 'Mz' section plus an axial material ('-section') in
forceBeamColumn and dispBeamColumn. 3D: torsion and axial springs
(zeroLengthSection of Uniaxial 'T' and 'P') and an Aggregator of a Uniaxial
'Mz' section with P, My and T materials in forceBeamColumn and
dispBeamColumn. Every step's displacements, iteration counts and the
section responses ('force', 'deformation', 'stiffness') are compared.
"""


def _analysis(ops, node, dof, du, steps):
    ops.system("UmfPack")
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.test("NormDispIncr", 1e-12, 25)
    ops.algorithm("Newton")
    ops.integrator("DisplacementControl", node, dof, du)
    ops.analysis("Static")
    out = []
    for _ in range(steps):
        code = ops.analyze(1)
        out.append([code, ops.testIter(), ops.getLoadFactor(1)])
    return out


def _section_state(ops, ele, prefix=("section",)):
    return {
        "force": ops.eleResponse(ele, *prefix, "force"),
        "deformation": ops.eleResponse(ele, *prefix, "deformation"),
        "stiffness": ops.eleResponse(ele, *prefix, "stiffness"),
    }


def _spring_2d(ops, out):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    ops.node(1, 0.0, 0.0)
    ops.node(2, 0.0, 0.0)
    ops.node(3, 0.0, 3.0)
    ops.fix(1, 1, 1, 1)
    ops.equalDOF(1, 2, 1, 2)
    ops.uniaxialMaterial("Steel01", 1, 150.0, 2.0e4, 0.05)
    ops.section("Uniaxial", 1, 1, "Mz")
    out["classType"] = ops.classType("section", 1)
    ops.element("zeroLengthSection", 1, 1, 2, 1)
    ops.geomTransf("Linear", 1)
    ops.element("elasticBeamColumn", 2, 2, 3, 0.02, 2.0e8, 1.0e-4, 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(3, 1.0, 0.0, 0.0)
    steps = _analysis(ops, 3, 1, 0.01, 6)
    out["spring2d.steps"] = steps
    out["spring2d.disp"] = [ops.nodeDisp(n) for n in (2, 3)]
    out["spring2d.section"] = _section_state(ops, 1)
    out["spring2d.force"] = ops.eleResponse(1, "force")
    out["spring2d.basicForce"] = ops.eleResponse(1, "basicForce")


def _axial_shear_2d(ops, out):
    for code, dof in (("P", 1), ("Vy", 2)):
        ops.wipe()
        ops.model("basic", "-ndm", 2, "-ndf", 3)
        ops.node(1, 0.0, 0.0)
        ops.node(2, 0.0, 0.0)
        ops.fix(1, 1, 1, 1)
        ops.fix(2, *[0 if d == dof else 1 for d in (1, 2, 3)])
        ops.uniaxialMaterial("Steel01", 1, 30.0, 1.0e4, 0.1)
        ops.section("Uniaxial", 1, 1, code)
        ops.element("zeroLengthSection", 1, 1, 2, 1, "-orient", 1.0, 1.0, 0.0, -1.0, 1.0, 0.0)
        ops.timeSeries("Linear", 1)
        ops.pattern("Plain", 1, 1)
        ops.load(2, *[1.0 if d == dof else 0.0 for d in (1, 2, 3)])
        key = "spring2d." + code
        out[key + ".steps"] = _analysis(ops, 2, dof, 0.002, 4)
        out[key + ".disp"] = ops.nodeDisp(2)
        out[key + ".section"] = _section_state(ops, 1)


def _aggregated_beams_2d(ops, out):
    for element in ("forceBeamColumn", "dispBeamColumn"):
        ops.wipe()
        ops.model("basic", "-ndm", 2, "-ndf", 3)
        ops.node(1, 0.0, 0.0)
        ops.node(2, 0.0, 2.5)
        ops.fix(1, 1, 1, 1)
        ops.uniaxialMaterial("Steel01", 1, 40.0, 5.0e3, 0.03)  # moment-curvature
        ops.uniaxialMaterial("Elastic", 2, 4.0e6)  # EA
        ops.section("Uniaxial", 1, 1, "Mz")
        ops.section("Aggregator", 2, 2, "P", "-section", 1)
        ops.geomTransf("Linear", 1)
        ops.beamIntegration("Lobatto", 1, 2, 4)
        ops.element(element, 1, 1, 2, 1, 1)
        ops.timeSeries("Linear", 1)
        ops.pattern("Plain", 1, 1)
        ops.load(2, 1.0, -0.5, 0.0)
        key = "beam2d." + element
        out[key + ".steps"] = _analysis(ops, 2, 1, 0.004, 5)
        out[key + ".disp"] = ops.nodeDisp(2)
        out[key + ".basicForce"] = ops.eleResponse(1, "basicForce")
        out[key + ".section1"] = _section_state(ops, 1, ("section", 1))


def _springs_3d(ops, out):
    for code, dof in (("T", 4), ("P", 1)):
        ops.wipe()
        ops.model("basic", "-ndm", 3, "-ndf", 6)
        ops.node(1, 0.0, 0.0, 0.0)
        ops.node(2, 0.0, 0.0, 0.0)
        ops.fix(1, 1, 1, 1, 1, 1, 1)
        ops.fix(2, *[0 if d == dof else 1 for d in range(1, 7)])
        ops.uniaxialMaterial("Steel01", 1, 80.0, 1.0e4, 0.02)
        ops.section("Uniaxial", 1, 1, code)
        ops.element("zeroLengthSection", 1, 1, 2, 1)
        ops.timeSeries("Linear", 1)
        ops.pattern("Plain", 1, 1)
        ops.load(2, *[1.0 if d == dof else 0.0 for d in range(1, 7)])
        key = "spring3d." + code
        out[key + ".steps"] = _analysis(ops, 2, dof, 0.004, 5)
        out[key + ".disp"] = ops.nodeDisp(2)
        out[key + ".section"] = _section_state(ops, 1)
        out[key + ".force"] = ops.eleResponse(1, "force")


def _aggregated_beams_3d(ops, out):
    for element in ("forceBeamColumn", "dispBeamColumn"):
        ops.wipe()
        ops.model("basic", "-ndm", 3, "-ndf", 6)
        ops.node(1, 0.0, 0.0, 0.0)
        ops.node(2, 2.0, 0.0, 0.0)
        ops.fix(1, 1, 1, 1, 1, 1, 1)
        ops.uniaxialMaterial("Steel01", 1, 40.0, 5.0e3, 0.03)  # Mz-kappaZ
        ops.uniaxialMaterial("Elastic", 2, 4.0e6)  # EA
        ops.uniaxialMaterial("Elastic", 3, 8.0e3)  # EIy
        ops.uniaxialMaterial("Elastic", 4, 3.0e3)  # GJ
        ops.section("Uniaxial", 1, 1, "Mz")
        ops.section("Aggregator", 2, 2, "P", 3, "My", 4, "T", "-section", 1)
        ops.geomTransf("Linear", 1, 0.0, 0.0, 1.0)
        ops.beamIntegration("Legendre", 1, 2, 3)
        ops.element(element, 1, 1, 2, 1, 1)
        ops.timeSeries("Linear", 1)
        ops.pattern("Plain", 1, 1)
        ops.load(2, 0.0, 1.0, 0.3, 0.1, 0.0, 0.0)
        key = "beam3d." + element
        out[key + ".steps"] = _analysis(ops, 2, 2, 0.004, 5)
        out[key + ".disp"] = ops.nodeDisp(2)
        out[key + ".basicForce"] = ops.eleResponse(1, "basicForce")


def run(ops):
    out = {}
    _spring_2d(ops, out)
    _axial_shear_2d(ops, out)
    _aggregated_beams_2d(ops, out)
    _springs_3d(ops, out)
    _aggregated_beams_3d(ops, out)
    ops.wipe()
    return out

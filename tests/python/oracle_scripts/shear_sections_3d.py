"""Shear-deformable 3D sections in forceBeamColumn: section('Aggregator', tag,
matTag, 'Vy', matTag, 'Vz', '-section', secTag) and the 8-number
section('Elastic', tag, E, A, Iz, Iy, G, J, alphaY, alphaZ).

- frame: the model of OpenSeesPy's response spectrum example (a 4 m x 3 m
  one-bay, two-storey 3D frame of 16 forceBeamColumns, 5 Lobatto points, an
  elastic section with Vy and Vz shear springs aggregated, masses at the
  floor nodes, rigid-diaphragm floors with unmassed masters), built here in
  its own code: eigen('-genBandArpack', 7), modalProperties (the sign-free
  entries: mode shapes have no sign), responseSpectrumAnalysis with -Tn/-Sa
  lists (all modes, an Element recorder of 'section', '1', 'force'), with a
  Path series, and mode by mode with eleResponse, combined by CQC.
- loads: a cantilever of the 8-number Elastic section under tip loads and
  beamUniform/beamPoint element loads (the shear of the simply supported
  basic system), section force, deformation and stiffness responses (order
  [P, Mz, Vy, My, Vz, T]); the Aggregator with Vz given before Vy. A
  beamPoint load along z differs on purpose (see compare.KNOWN_DIFFERENCES).
- dispBeamColumn: both sections; the shear stays unstrained, as OpenSees'.
- zeroLengthSection: both sections, oriented, Steel01 in Vz past yield.
- pushover: a cantilever whose shear springs are Steel01 (Vy) and Steel01
  (Vz), pushed diagonally past the shear yield and back, so that the element
  iterates its sections to compatibility.
"""

import math

TN = [0.0, 0.06, 0.1, 0.12, 0.18, 0.24, 0.3, 0.36, 0.4, 0.42, 0.48, 0.54, 0.6, 0.9, 1.2, 1.5, 2.0, 3.0]
SA = [1.9612, 3.72628, 4.903, 4.903, 4.903, 4.903, 4.903, 4.903, 4.903, 4.6696172, 4.0861602, 3.6321424,
      3.2683398, 2.1788932, 1.6346602, 1.3071398, 0.990406, 0.66]


def _cqc(values, lambdas, zeta=0.05):
    total = 0.0
    for i, li in enumerate(lambdas):
        for j, lj in enumerate(lambdas):
            r = math.sqrt(lj / li)
            rho = (8.0 * zeta ** 2 * (1.0 + r) * r ** 1.5) / ((1.0 - r ** 2) ** 2 + 4.0 * zeta ** 2 * r * (1.0 + r) ** 2)
            total += values[i] * rho * values[j]
    return math.sqrt(total)


def _frame(ops):
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    ops.uniaxialMaterial("Elastic", 2, 938000000.0)
    E, G, b = 30.0e9, 12.5e9, 0.3
    A, I = b * b, b ** 4 / 12.0
    ops.section("Elastic", 1, E, A, I, I, G, 0.1406 * b ** 4)
    ops.section("Aggregator", 3, 2, "Vy", 2, "Vz", "-section", 1)
    ops.beamIntegration("Lobatto", 1, 3, 5)
    # Column lines at the bay's corners; levels 0, 3, 6 m. Node 100 k + level.
    corners = ((0.0, 0.0), (4.0, 0.0), (4.0, 3.0), (0.0, 3.0))
    for k, (x, y) in enumerate(corners):
        for level in range(3):
            tag = 100 * (k + 1) + level
            ops.node(tag, x, y, 3.0 * level)
            if level == 0:
                ops.fix(tag, 1, 1, 1, 1, 1, 1)
            else:
                ops.mass(tag, 200.0, 200.0, 200.0, 0.0, 0.0, 0.0)
    ops.geomTransf("Linear", 1, 1.0, 0.0, 0.0)   # columns
    ops.geomTransf("Linear", 2, 0.0, 0.0, 1.0)   # beams
    e = 1
    for k in range(4):
        for level in (1, 2):
            ops.element("forceBeamColumn", e, 100 * (k + 1) + level - 1, 100 * (k + 1) + level, 1, 1)
            e += 1
    for level in (1, 2):
        for k in range(4):
            ops.element("forceBeamColumn", e, 100 * (k + 1) + level, 100 * ((k + 1) % 4 + 1) + level, 2, 1)
            e += 1
    for level in (1, 2):
        master = 10 + level
        ops.node(master, 2.0, 1.5, 3.0 * level)
        ops.fix(master, 0, 0, 1, 1, 1, 0)
        ops.rigidDiaphragm(3, master, *[100 * (k + 1) + level for k in range(4)])
    ops.constraints("Transformation")
    ops.numberer("RCM")
    ops.system("UmfPack")
    ops.test("NormUnbalance", 0.0001, 10)
    ops.algorithm("Linear")
    ops.integrator("LoadControl", 0.0)
    ops.analysis("Static")


def _read_column(name, column):
    with open(name) as f:
        return [float(line.split()[column]) for line in f if line.strip()]


def _frame_results(ops, out):
    _frame(ops)
    lam = ops.eigen("-genBandArpack", 7)
    out["frame.lambda"] = lam
    props = ops.modalProperties("-unorm", "-return")
    for key in ("totalMass", "centerOfMass", "partiMassMX", "partiMassMY", "partiMassRMZ", "partiMassRatiosMX",
                "partiMassRatiosMY", "partiMassRatiosRMZ"):
        out["frame.modal." + key] = props[key]
    ops.timeSeries("Path", 1, "-time", *TN, "-values", *SA)
    ops.recorder("Element", "-file", "sec1.out", "-closeOnWrite", "-precision", 16, "-ele", 1, "section", "1",
                 "force")
    ops.responseSpectrumAnalysis(1, "-Tn", *TN, "-Sa", *SA)
    my = _read_column("sec1.out", 2)
    out["frame.lists.My per mode"] = my
    out["frame.lists.My cqc"] = _cqc(my, lam)
    for m in (1, 4):
        ops.responseSpectrumAnalysis(1, 1, "-mode", m)
        out[f"frame.series.mode {m}.section 1 force"] = ops.eleResponse(1, "section", "1", "force")
    ops.remove("recorders")
    for direction in (1, 2):
        modal = []
        for m in range(1, len(lam) + 1):
            ops.responseSpectrumAnalysis(direction, "-Tn", *TN, "-Sa", *SA, "-mode", m)
            row = ops.eleResponse(1, "section", "1", "force") + ops.eleResponse(1, "section", "3", "force")
            row += ops.eleResponse(9, "section", "2", "force") + ops.eleResponse(9, "section", "5", "deformation")
            row += ops.eleResponse(4, "basicForce")
            modal.append(row)
        out[f"frame.dir{direction}.cqc"] = [_cqc([r[k] for r in modal], lam) for k in range(len(modal[0]))]
    out["frame.section 1 stiffness"] = ops.eleResponse(1, "section", "1", "stiffness")


def _cantilever(ops, section, L=2.5, points=5):
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    ops.node(1, 0.0, 0.0, 0.0)
    ops.node(2, L, 0.0, 0.0)
    ops.fix(1, 1, 1, 1, 1, 1, 1)
    section(ops)
    ops.geomTransf("Linear", 1, 0.0, 0.0, 1.0)
    ops.beamIntegration("Lobatto", 1, 10, points)
    ops.element("forceBeamColumn", 1, 1, 2, 1, 1)
    ops.system("FullGeneral")
    ops.numberer("Plain")
    ops.constraints("Plain")


def _elastic8(ops):
    ops.section("Elastic", 10, 200.0, 10.0, 3.0, 2.0, 80.0, 5.0, 0.5, 0.7)


def _aggregator_zy(ops):
    ops.uniaxialMaterial("Elastic", 2, 50.0)
    ops.uniaxialMaterial("Elastic", 3, 70.0)
    ops.section("Elastic", 1, 200.0, 10.0, 3.0, 2.0, 80.0, 5.0)
    ops.section("Aggregator", 10, 3, "Vz", 2, "Vy", "-section", 1)


def _static(ops, tip, uniform=None, point=None):
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, *tip)
    if uniform:
        ops.eleLoad("-ele", 1, "-type", "-beamUniform", *uniform)
    if point:
        ops.eleLoad("-ele", 1, "-type", "-beamPoint", *point)
    ops.test("NormDispIncr", 1.0e-12, 20)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", 1.0)
    ops.analysis("Static")
    return ops.analyze(1)


def _loads_results(ops, out):
    cases = {
        "tip": dict(tip=[0.3, 1.0, 2.0, 0.4, 0.0, 0.0]),
        "uniform": dict(tip=[0.0] * 6, uniform=[0.8, -0.6, 0.2]),
        "point y": dict(tip=[0.0] * 6, point=[1.5, 0.0, 0.35, 0.4]),
        # Known difference: OpenSeesPy 3.7.1 gives Vz of a beamPoint load the sign opposite to dMy/dx.
        "point z": dict(tip=[0.0] * 6, point=[0.0, -0.7, 0.35, 0.4]),
    }
    for name, section in (("elastic8", _elastic8), ("aggregator Vz Vy", _aggregator_zy)):
        for case, loads in cases.items():
            _cantilever(ops, section)
            key = f"{name}.{case}."
            out[key + "ok"] = _static(ops, **loads)
            out[key + "disp"] = ops.nodeDisp(2)
            ops.reactions()
            out[key + "reactions"] = ops.nodeReaction(1)
            out[key + "basicForce"] = ops.eleResponse(1, "basicForce")
            out[key + "localForce"] = ops.eleResponse(1, "localForce")
            for s in ("1", "2") if case.startswith("point") else ("1", "2", "3"):
                out[key + "section " + s + " force"] = ops.eleResponse(1, "section", s, "force")
                out[key + "section " + s + " deformation"] = ops.eleResponse(1, "section", s, "deformation")
            out[key + "section 2 stiffness"] = ops.eleResponse(1, "section", "2", "stiffness")
            if case == "tip":
                out[key + "sectionForce"] = ops.sectionForce(1, 1)
                out[key + "sectionForce dof 5"] = ops.sectionForce(1, 2, 5)
                out[key + "sectionDeformation dof 6"] = ops.sectionDeformation(1, 1, 6)
                out[key + "sectionStiffness"] = ops.sectionStiffness(1, 1)


def _steel_shear(ops):
    ops.uniaxialMaterial("Steel01", 2, 0.6, 40.0, 0.05)
    ops.uniaxialMaterial("Steel01", 3, 0.9, 60.0, 0.02)
    ops.section("Elastic", 1, 200.0, 10.0, 3.0, 2.0, 80.0, 5.0)
    ops.section("Aggregator", 10, 2, "Vy", 3, "Vz", "-section", 1)


def _pushover_results(ops, out):
    _cantilever(ops, _steel_shear, L=2.0, points=4)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, -1.0, 1.0, 0.6, 0.05, 0.0, 0.0)
    ops.test("NormDispIncr", 1.0e-12, 30)
    ops.algorithm("Newton")
    history = []
    for target, steps in ((0.25, 10), (-0.1, 14), (0.35, 16)):
        du = (target - ops.nodeDisp(2, 2)) / steps
        ops.integrator("DisplacementControl", 2, 2, du)
        ops.analysis("Static")
        for _ in range(steps):
            ok = ops.analyze(1)
            row = [ok, ops.getLoadFactor(1)] + ops.nodeDisp(2)
            row += ops.eleResponse(1, "section", "1", "force") + ops.eleResponse(1, "section", "3", "deformation")
            row += ops.eleResponse(1, "basicForce")
            history.append(row)
    out["pushover.history"] = history
    out["pushover.section 2 stiffness"] = ops.eleResponse(1, "section", "2", "stiffness")
    out["pushover.basicStiffness"] = ops.eleResponse(1, "basicStiffness")


def _disp_beam_results(ops, out):
    # dispBeamColumn leaves the shear unstrained (Euler-Bernoulli answer), as OpenSees.
    for name, section in (("elastic8", _elastic8), ("aggregator Vz Vy", _aggregator_zy)):
        ops.wipe()
        ops.model("basic", "-ndm", 3, "-ndf", 6)
        ops.node(1, 0.0, 0.0, 0.0)
        ops.node(2, 2.5, 0.0, 0.0)
        ops.fix(1, 1, 1, 1, 1, 1, 1)
        section(ops)
        ops.geomTransf("Linear", 1, 0.0, 0.0, 1.0)
        ops.beamIntegration("Legendre", 1, 10, 3)
        ops.element("dispBeamColumn", 1, 1, 2, 1, 1)
        key = f"dispBeamColumn.{name}."
        out[key + "ok"] = _static(ops, [0.3, 1.0, 2.0, 0.4, 0.0, 0.0])
        out[key + "disp"] = ops.nodeDisp(2)
        out[key + "section 1 force"] = ops.eleResponse(1, "section", "1", "force")
        out[key + "section 1 deformation"] = ops.eleResponse(1, "section", "1", "deformation")


def _zero_length_results(ops, out):
    for name in ("aggregator", "elastic8"):
        ops.wipe()
        ops.model("basic", "-ndm", 3, "-ndf", 6)
        ops.node(1, 0.0, 0.0, 0.0)
        ops.node(2, 0.0, 0.0, 0.0)
        ops.fix(1, 1, 1, 1, 1, 1, 1)
        ops.uniaxialMaterial("Elastic", 2, 50.0)
        ops.uniaxialMaterial("Steel01", 3, 0.5, 70.0, 0.1)
        ops.section("Elastic", 1, 200.0, 10.0, 3.0, 2.0, 80.0, 5.0)
        if name == "aggregator":
            ops.section("Aggregator", 10, 3, "Vz", 2, "Vy", "-section", 1)
        else:
            ops.section("Elastic", 10, 200.0, 10.0, 3.0, 2.0, 80.0, 5.0, 0.5, 0.7)
        ops.element("zeroLengthSection", 1, 1, 2, 10, "-orient", 1.0, 1.0, 0.0, -1.0, 1.0, 0.0)
        ops.timeSeries("Linear", 1)
        ops.pattern("Plain", 1, 1)
        ops.load(2, 1.0, 2.0, 3.0, 0.5, 0.6, 0.7)
        ops.system("FullGeneral")
        ops.numberer("Plain")
        ops.constraints("Plain")
        ops.test("NormDispIncr", 1.0e-12, 30)
        ops.algorithm("Newton")
        ops.integrator("LoadControl", 0.1)
        ops.analysis("Static")
        key = f"zeroLengthSection.{name}."
        out[key + "ok"] = ops.analyze(10)
        out[key + "disp"] = ops.nodeDisp(2)
        for response in ("basicForce", "deformation", "force"):
            out[key + response] = ops.eleResponse(1, response)
        out[key + "section force"] = ops.eleResponse(1, "section", "force")


def run(ops):
    out = {}
    _frame_results(ops, out)
    _loads_results(ops, out)
    _pushover_results(ops, out)
    _zero_length_results(ops, out)
    _disp_beam_results(ops, out)
    ops.wipe()
    return out

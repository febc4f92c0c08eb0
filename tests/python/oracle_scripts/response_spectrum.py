"""Modal response spectrum analysis as the newer OpenSeesPy examples run it: a
3D two-storey one-bay frame with rigid-diaphragm floors (masses on the master
nodes and some at the column tops), eigen, modalProperties, then responseSpectrumAnalysis one mode at a
time with the spectrum in a Path timeSeries (-time/-values), reading each
mode's displacements and element forces and combining them in Python by SRSS
and CQC (5% damping). Also: all modes at once with a Node recorder, the
-Tn/-Sa list form (clamped past its ends), a Linear series as the spectrum,
-scale (accepted, unused), a 2D frame in direction 1, and a static analysis
afterwards (the modal displacements replace its state).
"""

import math

# A design spectrum (T in s, Sa in m/s^2) of the shape public examples use.
TN = [0.0, 0.06, 0.1, 0.12, 0.18, 0.24, 0.3, 0.36, 0.4, 0.42, 0.48, 0.54, 0.6, 0.66, 0.72, 0.78, 0.84,
      0.9, 0.96, 1.02, 1.2, 1.5, 2.0, 3.0]
SA = [1.9612, 3.72628, 4.903, 4.903, 4.903, 4.903, 4.903, 4.903, 4.903, 4.6696172, 4.0861602, 3.6321424,
      3.2683398, 2.971218, 2.7241068, 2.5142584, 2.3348086, 2.1788932, 2.0425898, 1.9229566, 1.6346602,
      1.3071398, 0.990406, 0.66]


def _frame(ops):
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    Lx, Ly, H = 6.0, 4.5, 3.2
    corners = ((0.0, 0.0), (Lx, 0.0), (Lx, Ly), (0.0, Ly))
    for level in range(3):
        for i, (x, y) in enumerate(corners):
            ops.node(10 * level + i + 1, x, y, H * level)
    for i in range(4):
        ops.fix(i + 1, 1, 1, 1, 1, 1, 1)
    for level in (1, 2):
        master = 100 + level
        # The floor's centre of mass is off the geometric centre (torsion couples the modes).
        ops.node(master, 0.55 * Lx, 0.45 * Ly, H * level)
        ops.fix(master, 0, 0, 1, 1, 1, 0)
        m = 18.0 if level == 1 else 14.0
        ops.mass(master, m, m, 0.0, 0.0, 0.0, m * (Lx ** 2 + Ly ** 2) / 12.0)
        ops.rigidDiaphragm(3, master, *[10 * level + i + 1 for i in range(4)])
        # Some mass at the column tops too (half a column each), vertical and rotational included.
        for i in range(4):
            ops.mass(10 * level + i + 1, 0.6, 0.6, 0.6, 0.01, 0.01, 0.0)
    ops.geomTransf("Linear", 1, 1.0, 0.0, 0.0)  # columns
    ops.geomTransf("Linear", 2, 0.0, 0.0, 1.0)  # beams
    E, G = 30e6, 12.5e6
    e = 1
    for level in (1, 2):
        for i in range(4):
            Iy, Iz = (3.2e-3, 2.1e-3) if i % 2 == 0 else (2.4e-3, 2.9e-3)
            ops.element("elasticBeamColumn", e, 10 * (level - 1) + i + 1, 10 * level + i + 1,
                        0.16, E, G, 4.5e-3, Iy, Iz, 1)
            e += 1
        for i in range(4):
            ops.element("elasticBeamColumn", e, 10 * level + i + 1, 10 * level + (i + 1) % 4 + 1,
                        0.12, E, G, 2.0e-3, 1.6e-3, 3.6e-3, 2)
            e += 1
    ops.constraints("Transformation")


def _cqc(values, omegas, zeta=0.05):
    total = 0.0
    for i, wi in enumerate(omegas):
        for j, wj in enumerate(omegas):
            r = wj / wi
            rho = (8.0 * zeta ** 2 * (1.0 + r) * r ** 1.5) / ((1.0 - r ** 2) ** 2 + 4.0 * zeta ** 2 * r * (1.0 + r) ** 2)
            total += values[i] * rho * values[j]
    return math.sqrt(total)


def run(ops):
    out = {}
    _frame(ops)
    ops.timeSeries("Path", 1, "-time", *TN, "-values", *SA)
    lam = ops.eigen(6)
    omegas = [math.sqrt(v) for v in lam]
    out["periods"] = [2.0 * math.pi / w for w in omegas]
    ops.modalProperties("-unorm")
    for direction in (1, 2):
        modal_disp, modal_force = [], []
        for m in range(1, len(lam) + 1):
            ops.responseSpectrumAnalysis(1, direction, "-mode", m)
            modal_disp.append(ops.nodeDisp(22) + ops.nodeDisp(102))
            modal_force.append(ops.eleForce(1) + ops.eleResponse(9, "localForce"))
            out[f"dir{direction}.mode{m}.disp 102"] = ops.nodeDisp(102)
            out[f"dir{direction}.mode{m}.time"] = ops.getTime()
        for k in range(len(modal_disp[0])):
            column = [row[k] for row in modal_disp]
            out.setdefault(f"dir{direction}.disp srss", []).append(math.sqrt(sum(v * v for v in column)))
            out.setdefault(f"dir{direction}.disp cqc", []).append(_cqc(column, omegas))
        for k in range(len(modal_force[0])):
            column = [row[k] for row in modal_force]
            out.setdefault(f"dir{direction}.force cqc", []).append(_cqc(column, omegas))

    # All modes in one call: the recorder records each mode; the domain keeps the last.
    ops.recorder("Node", "-file", "rsa_modes.out", "-time", "-node", 102, 22, "-dof", 1, 2, 6, "disp")
    ops.responseSpectrumAnalysis(1, 1)
    ops.remove("recorders")
    with open("rsa_modes.out") as f:
        out["recorded modes"] = [[float(x) for x in line.split()] for line in f if line.strip()]
    out["all modes: last"] = ops.nodeDisp(102)

    # The list form, clamped at both ends; a Linear series; -scale is accepted and unused.
    for m in (1, 6):
        ops.responseSpectrumAnalysis(2, "-Tn", 0.05, 0.1, "-Sa", 3.0, 2.0, "-mode", m)
        out[f"lists clamped mode {m}"] = ops.nodeDisp(102)
        ops.responseSpectrumAnalysis(1, "-Tn", *TN, "-Sa", *SA, "-scale", 2.0, "-mode", m)
        out[f"lists mode {m}"] = ops.nodeDisp(102)
    ops.timeSeries("Linear", 2, "-factor", 9.81)
    ops.responseSpectrumAnalysis(2, 6, "-mode", 3)
    out["Linear series, rotation dir 6"] = ops.nodeDisp(101)

    # A static analysis afterwards starts from the last modal state and, being
    # linear, lands on the static answer.
    ops.pattern("Plain", 1, 2)
    ops.load(102, 10.0, 5.0, 0.0, 0.0, 0.0, 3.0)
    ops.system("UmfPack")
    ops.numberer("RCM")
    ops.integrator("LoadControl", 0.1)
    ops.algorithm("Linear")
    ops.analysis("Static")
    out["static after"] = [ops.analyze(1), ops.getTime()] + ops.nodeDisp(102)

    # 2D: a two-storey frame with lumped masses, direction 1 (X).
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    for tag, x, y in ((1, 0, 0), (2, 6, 0), (3, 0, 3), (4, 6, 3), (5, 0, 6), (6, 6, 6)):
        ops.node(tag, float(x), float(y))
    ops.fix(1, 1, 1, 1)
    ops.fix(2, 1, 1, 1)
    for n, m in ((3, 10.0), (4, 12.0), (5, 8.0), (6, 7.0)):
        ops.mass(n, m, m, 0.0)
    ops.geomTransf("Linear", 1)
    for e, (i, j, iz) in enumerate(((1, 3, 1e-3), (2, 4, 1e-3), (3, 5, 1e-3), (4, 6, 1e-3), (3, 4, 2e-3),
                                    (5, 6, 2e-3)), start=1):
        ops.element("elasticBeamColumn", e, i, j, 0.1, 2e8, iz, 1)
    ops.timeSeries("Path", 5, "-time", *TN, "-values", *SA)
    lam = ops.eigen(3)
    ops.modalProperties()
    for m in (1, 2, 3):
        ops.responseSpectrumAnalysis(5, 1, "-mode", m)
        out[f"2d mode {m}"] = ops.nodeDisp(5) + ops.nodeDisp(6) + ops.eleForce(1)
    return out

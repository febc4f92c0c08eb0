"""A two-story, one-bay moment frame in the style of the OpenSeesPy "Pushover Analysis of
2-Story Moment Frame" example: elastic columns and beams with stiffness (n+1)/n times the
member's, rotational Bilin springs (K = (n+1) 6EI/L, as from Mc/My = 1.05 and the n
modification, theta_p 0.025, theta_pc 0.3, Res 0.4, theta_u 0.4) in zeroLength elements with
equalDOF on the translations. A displacement-controlled pushover of the roof past the capping
point, then (on a fresh model with Lamda = 10 on every mode) a cyclic roof history of growing
amplitude that deteriorates the springs.
"""


def frame(ops, spring_material):
    """The frame, its springs made by spring_material(tag, K, b, My, theta_p) with b from
    Mc/My = 1.05 and the n modification; also used by imk_peak_frame_2d."""
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    H, L, E, Ic, Ib, A, n = 144.0, 288.0, 29000.0, 2000.0, 1500.0, 50.0, 10.0
    for tag, x, y in ((1, 0, 0), (2, L, 0), (11, 0, H), (12, L, H), (21, 0, 2 * H), (22, L, 2 * H),
                      (101, 0, 0), (102, L, 0), (111, 0, H), (112, L, H), (121, 0, 2 * H), (122, L, 2 * H)):
        ops.node(tag, float(x), float(y))
    ops.fix(1, 1, 1, 1)
    ops.fix(2, 1, 1, 1)
    ops.geomTransf("Linear", 1)
    mc_my, th_p = 1.05, 0.025
    for tag, K, My in ((1, (n + 1) * 6 * E * Ic / H, 20000.0), (2, (n + 1) * 6 * E * Ib / L, 10000.0)):
        a = (n + 1.0) * (My * (mc_my - 1.0)) / (K * th_p)
        spring_material(tag, K, a / (1.0 + n * (1.0 - a)), My, th_p)
    Icm, Ibm = Ic * (n + 1) / n, Ib * (n + 1) / n
    for tag, i, j, I in ((1, 101, 11, Icm), (2, 102, 12, Icm), (3, 11, 21, Icm), (4, 12, 22, Icm),
                         (5, 111, 112, Ibm), (6, 121, 122, Ibm)):
        ops.element("elasticBeamColumn", tag, i, j, A, E, I, 1)
    for tag, i, j, m in ((201, 1, 101, 1), (202, 2, 102, 1), (211, 11, 111, 2), (212, 12, 112, 2),
                         (221, 21, 121, 2), (222, 22, 122, 2)):
        ops.element("zeroLength", tag, i, j, "-mat", m, "-dir", 6)
        ops.equalDOF(i, j, 1, 2)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(11, 1.0, 0.0, 0.0)
    ops.load(21, 2.0, 0.0, 0.0)
    ops.constraints("Transformation")
    ops.numberer("RCM")
    ops.system("BandGeneral")
    ops.test("NormDispIncr", 1e-12, 50)
    ops.algorithm("Newton")


def _frame(ops, lam):
    def bilin(tag, K, b, My, th_p):
        ops.uniaxialMaterial("Bilin", tag, K, b, b, My, -My, lam, lam, lam, lam, 1.0, 1.0, 1.0, 1.0, th_p, th_p,
                             0.3, 0.3, 0.4, 0.4, 0.4, 0.4, 1.0, 1.0)

    frame(ops, bilin)


def _record(ops, out, key):
    for name, value in (("roof", ops.nodeDisp(21, 1)), ("floor", ops.nodeDisp(11, 1)), ("lambda", ops.getTime()),
                        ("baseMoment", ops.eleResponse(201, "force")[2]),
                        ("beamRotation", ops.eleResponse(221, "deformation")[0])):
        out.setdefault(f"{key}.{name}", []).append(value)


def run(ops):
    out = {}
    _frame(ops, 0.0)
    ops.integrator("DisplacementControl", 21, 1, 0.1)
    ops.analysis("Static")
    out["push.ok"] = [ops.analyze(1) for _ in range(3)]
    for step in range(180):
        out["push.ok"].append(ops.analyze(1))
        _record(ops, out, "push")

    _frame(ops, 10.0)
    ops.analysis("Static")
    out["cyclic.ok"] = []
    roof = 0.0
    for target in (2.0, -2.0, 3.5, -3.5, 5.0, -5.0):
        while abs(target - roof) > 1e-12:
            d = max(-0.2, min(0.2, target - roof))
            ops.integrator("DisplacementControl", 21, 1, d)
            out["cyclic.ok"].append(ops.analyze(1))
            roof += d
            _record(ops, out, "cyclic")
    return out

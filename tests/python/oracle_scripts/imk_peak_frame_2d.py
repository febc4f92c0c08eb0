"""The two-story, one-bay moment frame of bilin_frame_2d with rotational ModIMKPeakOriented
springs in the zeroLength hinges (Mc/My = 1.05 with the member's n-modification applied to the
hardening ratio by hand, as the OpenSeesPy examples do for this material: it has no nFactor;
theta_p 0.025, theta_pc 0.3, Res 0.4, theta_u 0.4). A displacement-controlled pushover of the
roof past the capping point, then (on a fresh model with Lamda_S = Lamda_C = Lamda_K = 10) a
cyclic roof history of growing amplitude that deteriorates the springs and reloads them
towards their previous peaks; the same cyclic run with ModIMKPinching springs (FprPos = FprNeg
= 0.3, A_pinch = 0.5).

Lamda_C is 1000 in the pushover rather than 0: OpenSeesPy 3.7.1 drops a ModIMKPeakOriented
spring's strength to ~1e-10 of its value at the first zero crossing when Lamda_C = 0
(docs/commands.md); Lamda_A is 0 (docs/commands.md lists its small differences).
"""
import bilin_frame_2d


def _frame(ops, lam_s, lam_c, lam_k, pinching=None):
    def imk(tag, K, b, My, th_p):
        name, extra = ("ModIMKPeakOriented", ()) if pinching is None else ("ModIMKPinching", pinching)
        ops.uniaxialMaterial(name, tag, K, b, b, My, -My, *extra, lam_s, lam_c, 0.0, lam_k, 1.0, 1.0, 1.0, 1.0, th_p,
                             th_p, 0.3, 0.3, 0.4, 0.4, 0.4, 0.4, 1.0, 1.0)

    bilin_frame_2d.frame(ops, imk)


def _record(ops, out, key):
    for name, value in (("roof", ops.nodeDisp(21, 1)), ("floor", ops.nodeDisp(11, 1)), ("lambda", ops.getTime()),
                        ("baseMoment", ops.eleResponse(201, "force")[2]),
                        ("beamRotation", ops.eleResponse(221, "deformation")[0]),
                        ("beamMoment", ops.eleResponse(221, "force")[2])):
        out.setdefault(f"{key}.{name}", []).append(value)


def run(ops):
    out = {}
    _frame(ops, 0.0, 1000.0, 0.0)
    ops.integrator("DisplacementControl", 21, 1, 0.1)
    ops.analysis("Static")
    out["push.ok"] = [ops.analyze(1) for _ in range(3)]
    for step in range(180):
        out["push.ok"].append(ops.analyze(1))
        _record(ops, out, "push")

    for key, pinching in (("cyclic", None), ("pinching", (0.3, 0.3, 0.5))):
        _frame(ops, 10.0, 10.0, 10.0, pinching)
        ops.analysis("Static")
        out[f"{key}.ok"] = []
        roof = 0.0
        for target in (2.0, -2.0, 3.5, -1.0, 5.0, -5.0, 0.5):
            while abs(target - roof) > 1e-12:
                d = max(-0.2, min(0.2, target - roof))
                ops.integrator("DisplacementControl", 21, 1, d)
                out[f"{key}.ok"].append(ops.analyze(1))
                roof += d
                _record(ops, out, key)
    return out

"""zeroLengthContact3D node to node: both nodes' displacements imposed step by
step (sp in a Constant pattern per step, Penalty handler alpha 1e14, so the
forces carry ~1e-11 of the penalty's round-off), the element's 'force' read
after each step.

* dir 1, 2, 3: closing and opening along the normal by either node, stick
  under tangential motion, an initial gap and an initial penetration from
  non-coincident nodes;
* dir 0 about (1, -0.5): coincident nodes at several angles, radial motions
  only (OpenSees re-evaluates the radii at the current positions, BeamSolid
  keeps the initial normal: both are the same for radial motion);
* a stick-slip history along t1 under a constant normal force (dir 3): the
  steps in stick agree.

Two differences are on purpose (compare.KNOWN_DIFFERENCES): in slide
OpenSeesPy's tangential force drops below mu N + c (a sawtooth: each step that
would pass the limit restarts from zero force), and a contact that closes again
keeps OpenSeesPy's old stick point, where BeamSolid restarts friction from the
position of the opening.

Element nodes: (constrained, retained) = (1, 2).
"""
import math

KN, KT, MU, C = 1000.0, 100.0, 0.5, 2.0


def _model(ops, dir_args, X1=(0.0, 0.0, 0.0), X2=(0.0, 0.0, 0.0)):
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    ops.node(1, *X1)
    ops.node(2, *X2)
    ops.element("zeroLengthContact3D", 1, 1, 2, KN, KT, MU, C, *dir_args)
    ops.system("FullGeneral")
    ops.numberer("Plain")
    ops.constraints("Penalty", 1e14, 1e14)
    ops.test("NormDispIncr", 1e-12, 50)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", 1.0)
    ops.analysis("Static")


def _history(ops, out, key, path):
    """path: [(u1, u2)] imposed displacements of the constrained and retained nodes."""
    for step, (u1, u2) in enumerate(path):
        tag = 10 + len(out)  # unique over the whole run
        ops.timeSeries("Constant", tag)
        ops.pattern("Plain", tag, tag)
        for node, u in ((1, u1), (2, u2)):
            for dof in range(3):
                ops.sp(node, dof + 1, u[dof])
        out[f"{key}.step{step}.code"] = ops.analyze(1)
        out[f"{key}.step{step}.force"] = ops.eleResponse(1, "force")
        ops.remove("loadPattern", tag)


def run(ops):
    out = {}
    zero = (0.0, 0.0, 0.0)
    for d in (1, 2, 3):
        n = [0.0, 0.0, 0.0]
        n[d - 1] = 1.0
        t = [0.0, 0.0, 0.0]
        t[d % 3] = 1.0
        s = [0.0, 0.0, 0.0]
        s[(d + 1) % 3] = 1.0

        def combo(a, b, c):
            return tuple(a * n[i] + b * t[i] + c * s[i] for i in range(3))

        _model(ops, (d,))
        _history(ops, out, f"dir{d}", [
            (zero, combo(0.002, 0.0, 0.0)),          # retained moves along +n: closes
            (combo(-0.003, 0.0, 0.0), zero),         # constrained moves along -n: closes
            (combo(-0.003, 0.01, -0.004), zero),     # stick in two tangential directions
            (combo(0.001, 0.01, -0.004), zero),      # opens
        ])
        # Closes again, away from where it opened: the friction memory differs.
        _history(ops, out, f"dir{d}.recontact", [(combo(-0.002, 0.012, 0.0), combo(0.0, 0.0, 0.001))])
        # Initial gap 0.01 (constrained node on the +n side), then penetration from the start.
        _model(ops, (d,), X1=combo(0.01, 0.0, 0.0))
        _history(ops, out, f"dir{d}.gap", [(zero, combo(0.004, 0.0, 0.0)), (zero, combo(0.013, 0.0, 0.0))])
        _model(ops, (d,), X1=combo(-0.004, 0.0, 0.0))
        _history(ops, out, f"dir{d}.overlap", [(zero, zero)])

    ox, oy = 1.0, -0.5
    for deg in (0.0, 30.0, 135.0, 250.0):
        th = math.radians(deg)
        er = (math.cos(th), math.sin(th), 0.0)
        X = (ox + 2.0 * er[0], oy + 2.0 * er[1], 0.3)
        _model(ops, (0, ox, oy), X1=X, X2=X)
        _history(ops, out, f"dir0.{int(deg)}", [
            (zero, tuple(-0.002 * e for e in er)),   # retained (outer) moves inwards: closes
            (tuple(0.003 * e for e in er), zero),    # constrained (inner) moves outwards: closes
            (tuple(-0.001 * e for e in er), zero),   # constrained inwards: opens
        ])

    # Stick-slip along x (t1 of dir 3) under N = 4 (Fy = mu N + c = 4: slides past s = 0.04).
    _model(ops, (3,))
    _history(ops, out, "stickslip", [((0.01 * k, 0.0, -0.004), zero) for k in range(4)])
    _history(ops, out, "stickslip.slide", [((s, 0.0, -0.004), zero) for s in (0.04 + 1e-3, 0.06, 0.08)])
    return out

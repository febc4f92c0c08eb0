"""integrator('GeneralizedAlpha', alphaM, alphaF, <gamma, beta>) on a
two-storey shear building of zeroLength springs (one elastic, one Steel01
that yields) with Rayleigh damping, under a sine load and then free
vibration: every step's displacements, velocities, accelerations,
iteration count; with the default gamma/beta (several alphaM, alphaF
pairs, including alphaM = 1: HHT) and with given gamma and beta; and the
same method under OpenSees' other name, integrator('HHTGeneralized', alphaI,
alphaF, beta, gamma) (with beta and gamma given: OpenSeesPy 3.7.1 ignores
the two-argument form, docs/commands.md).
"""

CASES = (
    ("a", (1.0, 0.8)),
    ("b", (1.2, 0.9)),
    ("c", (0.95, 0.75)),
    ("d", (1.1, 0.85, 0.7, 0.4)),
    ("e", ("HHTGeneralized", 0.9, 0.8, 0.3025, 0.6)),
    ("f", ("HHTGeneralized", 1.0, 0.75, 0.39, 0.75)),
)


def run(ops):
    out = {}
    for name, args in CASES:
        ops.wipe()
        ops.model("basic", "-ndm", 1, "-ndf", 1)
        for n in (1, 2, 3):
            ops.node(n, 0.0)
        ops.fix(1, 1)
        ops.mass(2, 2.0)
        ops.mass(3, 1.5)
        ops.uniaxialMaterial("Elastic", 1, 800.0)
        ops.uniaxialMaterial("Steel01", 2, 6.0, 500.0, 0.05)
        ops.element("zeroLength", 1, 1, 2, "-mat", 1, "-dir", 1)
        ops.element("zeroLength", 2, 2, 3, "-mat", 2, "-dir", 1)
        ops.rayleigh(0.2, 0.002, 0.0, 0.0)
        ops.timeSeries("Trig", 1, 0.0, 0.6, 0.4)
        ops.pattern("Plain", 1, 1)
        ops.load(3, 20.0)
        ops.system("UmfPack")
        ops.constraints("Plain")
        ops.numberer("Plain")
        ops.test("NormDispIncr", 1e-12, 20)
        ops.algorithm("Newton")
        ops.integrator(*(args if isinstance(args[0], str) else ("GeneralizedAlpha",) + args))
        ops.analysis("Transient")
        steps = []
        for _ in range(40):
            code = ops.analyze(1, 0.02)
            steps.append([code, ops.testIter(), ops.nodeDisp(2, 1), ops.nodeDisp(3, 1), ops.nodeVel(3, 1),
                          ops.nodeAccel(3, 1)])
        out[name + ".steps"] = steps
        out[name + ".force"] = ops.eleResponse(2, "force")
    ops.wipe()
    return out

"""Earthquake load patterns under static LoadControl (which OpenSees
allows), so that they can be compared before any transient analysis.

UniformExcitation: a 2D truss with nodal masses (one on a fixed node) and
lumped or consistent truss masses under a ground acceleration path; the
effective load -M r a_g shows in the displacements, the applied nodal load
(nodeUnbalance) and the reactions; '-fact', dir 2, '-vel0' (node velocities)
and a pattern given only '-vel' / '-disp' (OpenSees applies nothing).

MultipleSupport: a chain of springs whose far end follows imposedMotion of
a groundMotion given by its displacement, velocity (integrated once) or
acceleration (integrated twice by the trapezoidal rule at OpenSees' step
0.01), with '-fact'; the imposed node's displacement, velocity and
acceleration, the spring between and the reaction. Times stay inside the
records (the ends of integrated records are not compared).
"""


def _truss(ops, rho, cmass, fixed_mass):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 2)
    ops.node(1, 0.0, 0.0)
    ops.node(2, 2.0, 0.0)
    ops.node(3, 2.0, 1.5)
    ops.fix(1, 1, 1)
    ops.fix(3, 0, 1)
    ops.mass(2, 3.0, 5.0)
    ops.mass(3, 7.0, 11.0)
    if fixed_mass:
        ops.mass(1, fixed_mass, fixed_mass)
    ops.uniaxialMaterial("Elastic", 1, 100.0)
    extra = ["-rho", rho] + (["-cMass", 1] if cmass else [])
    ops.element("Truss", 1, 1, 2, 1.0, 1, *extra)
    ops.element("Truss", 2, 2, 3, 1.0, 1, *extra)
    ops.element("Truss", 3, 1, 3, 1.0, 1, *extra)
    ops.timeSeries("Path", 1, "-time", 0.0, 1.0, 2.0, 3.0, "-values", 0.0, 2.0, 8.0, -1.0)


def _static(ops, out, key, steps=5, dt=0.5):
    ops.constraints("Transformation")
    ops.numberer("Plain")
    ops.system("FullGeneral")
    ops.test("NormUnbalance", 1e-12, 10)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", dt)
    ops.analysis("Static")
    rows, unbalance = [], []
    for _ in range(steps):
        ok = ops.analyze(1)
        ops.reactions()
        rows.append([ok, ops.getTime()] + [v for n in ops.getNodeTags() for v in ops.nodeDisp(n)]
                    + [v for n in ops.getNodeTags() for v in ops.nodeReaction(n)])
        unbalance.append([v for n in ops.getNodeTags() for v in ops.nodeUnbalance(n)])
    out[key] = rows
    out[key + ".nodeUnbalance"] = unbalance


def _uniform(ops, out):
    cases = {
        "accel": ((1, "-accel", 1), 0.0, False, 0.0),
        "accel.fixedMass": ((1, "-accel", 1), 0.0, False, 13.0),
        "accel.dir2.fact": ((2, "-accel", 1, "-fact", 3.0), 0.0, False, 0.0),
        "accel.lumpedRho": ((1, "-accel", 1), 0.5, False, 0.0),
        "accel.consistentRho": ((1, "-accel", 1, "-fact", -0.5), 0.5, True, 0.0),
        "velOnly": ((1, "-vel", 1), 0.0, False, 0.0),
        "dispOnly": ((2, "-disp", 1), 0.0, False, 0.0),
    }
    for name, (args, rho, cmass, fixed_mass) in cases.items():
        _truss(ops, rho, cmass, fixed_mass)
        ops.pattern("UniformExcitation", 1, *args)
        _static(ops, out, "uniform." + name)
    _truss(ops, 0.0, False, 0.0)
    ops.pattern("UniformExcitation", 1, 1, "-accel", 1, "-vel0", 0.7)
    out["uniform.vel0.before"] = [ops.nodeVel(n) for n in (1, 2, 3)]
    _static(ops, out, "uniform.vel0", steps=2)
    out["uniform.vel0.after"] = [ops.nodeVel(n) for n in (1, 2, 3)]


def _multiple(ops, out):
    cases = {
        "disp": ("-disp", 1),
        "disp.fact": ("-disp", 1, "-fact", 2.0),
        "vel": ("-vel", 1),
        "accel": ("-accel", 1),
        "accel.uniformPath": ("-accel", 2, "-fact", 0.5),
        "disp.accel": ("-disp", 1, "-accel", 1),
    }
    for name, gm in cases.items():
        ops.wipe()
        ops.model("basic", "-ndm", 1, "-ndf", 1)
        for n in (1, 2, 3):
            ops.node(n, 0.0)
        ops.fix(1, 1)
        ops.mass(2, 2.0)
        ops.uniaxialMaterial("Elastic", 1, 50.0)
        ops.uniaxialMaterial("Elastic", 2, 30.0)
        ops.element("zeroLength", 1, 1, 2, "-mat", 1, "-dir", 1)
        ops.element("zeroLength", 2, 2, 3, "-mat", 2, "-dir", 1)
        ops.timeSeries("Path", 1, "-time", 0.0, 1.0, 2.0, 4.0, "-values", 0.0, 2.0, 8.0, -3.0)
        ops.timeSeries("Path", 2, "-dt", 0.5, "-values", 0.0, 2.0, 8.0, 3.0, -1.0, 0.5, 1.0)
        ops.pattern("MultipleSupport", 1)
        ops.groundMotion(7, "Plain", *gm)
        ops.imposedMotion(3, 1, 7)
        _static(ops, out, "multiple." + name, steps=10, dt=0.25)
        out["multiple." + name + ".motion"] = [ops.nodeDisp(3, 1), ops.nodeVel(3, 1), ops.nodeAccel(3, 1)]


def run(ops):
    out = {}
    _uniform(ops, out)
    _multiple(ops, out)
    return out

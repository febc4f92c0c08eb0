"""Every time series and option evaluated through a unit spring: a
zeroLength of stiffness 1 under a unit load, stepped by static LoadControl
to chosen times (before, at, between and past the data points and the
start/end of the periodic series; all exactly representable in binary so
both programs land on the same times). The spring displacement and
getLoadFactor are the series value. Compared with OpenSeesPy to 1e-12.
"""

TIMES = (0.0, 0.25, 0.5, 1.0, 1.125, 1.25, 1.5, 1.75, 2.0, 2.25, 2.5, 3.0, 3.125, 3.5, 3.75, 4.0, 4.5, 5.0, 6.0)

SERIES = {
    "Constant": ("Constant", "-factor", 2.5),
    "Linear": ("Linear", "-factor", -1.5),
    "Path.dt": ("Path", "-dt", 0.5, "-values", 0.0, 1.0, 3.0, -2.0, 0.5, "-factor", 1.5),
    "Path.dt.useLast": ("Path", "-dt", 0.5, "-values", 1.0, 3.0, -2.0, 0.5, "-useLast"),
    "Path.dt.prependZero": ("Path", "-dt", 0.75, "-values", 1.0, 3.0, -2.0, "-prependZero"),
    "Path.dt.startTime": ("Path", "-dt", 0.5, "-values", 1.0, 3.0, -2.0, 0.5, "-startTime", 1.25),
    "Path.time": ("Path", "-time", 0.0, 0.25, 1.25, 2.0, 3.5, "-values", 0.0, 2.0, -1.0, 0.5, 4.0),
    "Path.time.useLast": ("Path", "-time", 0.5, 1.25, 2.0, 3.5, "-values", 2.0, -1.0, 0.5, 4.0, "-useLast", "-factor", 2.0),
    "Path.filePath": ("Path", "-dt", 0.25, "-filePath", "ts_values.txt", "-factor", 0.5),
    "Path.fileTime": ("Path", "-fileTime", "ts_times.txt", "-filePath", "ts_values.txt"),
    "Trig": ("Trig", 1.0, 3.0, 2.0),
    "Trig.all": ("Trig", 1.0, 4.0, 1.5, "-factor", 2.0, "-shift", 0.3, "-zeroShift", 0.5),
    "Sine.shift": ("Sine", 0.5, 5.0, 2.5, "-shift", -0.7),
    "Rectangular": ("Rectangular", 1.0, 3.0),
    "Rectangular.factor": ("Rectangular", 0.5, 3.5, "-factor", -2.5),
    "Pulse": ("Pulse", 1.0, 4.0, 1.0),
    "Pulse.all": ("Pulse", 1.0, 5.0, 1.5, "-width", 0.3, "-shift", 0.2, "-factor", 2.0, "-zeroShift", 0.1),
    "Triangle": ("Triangle", 1.0, 4.0, 2.0),
    "Triangle.all": ("Triangle", 0.5, 5.0, 2.5, "-factor", 1.5, "-shift", 0.4, "-zeroShift", 0.3),
}


def _evaluate(ops, spec):
    ops.wipe()
    ops.model("basic", "-ndm", 1, "-ndf", 1)
    ops.node(1, 0.0)
    ops.node(2, 0.0)
    ops.fix(1, 1)
    ops.uniaxialMaterial("Elastic", 1, 1.0)
    ops.element("zeroLength", 1, 1, 2, "-mat", 1, "-dir", 1)
    ops.timeSeries(spec[0], 7, *spec[1:])
    ops.pattern("Plain", 3, 7)
    ops.load(2, 1.0)
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.system("FullGeneral")
    ops.test("NormUnbalance", 1e-12, 5)
    ops.algorithm("Linear")
    disp, lam, times = [], [], []
    previous = 0.0
    for i, t in enumerate(TIMES):
        ops.integrator("LoadControl", t - previous)
        if i == 0:
            ops.analysis("Static")
        previous = t
        ops.analyze(1)
        times.append(ops.getTime())
        disp.append(ops.nodeDisp(2, 1))
        lam.append(ops.getLoadFactor(3))
    return times, disp, lam


def run(ops):
    with open("ts_values.txt", "w") as f:
        f.write("0.0 1.5\n-2.0\n4.0 0.5 3.0\n1.0\n")
    with open("ts_times.txt", "w") as f:
        f.write("0.5\n1.0\n1.25 2.0\n2.5 3.0 4.25\n")
    out = {}
    for name, spec in SERIES.items():
        times, disp, lam = _evaluate(ops, spec)
        out["ts." + name + ".time"] = times
        out["ts." + name + ".disp"] = disp
        out["ts." + name + ".loadFactor"] = lam
    return out

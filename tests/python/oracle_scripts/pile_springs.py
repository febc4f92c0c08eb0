"""A beam pile on the p-y, t-z and q-z springs of beamsolid.springs (loaded from its
file, so that the same helper builds the model under OpenSeesPy): a 2D pile of
elasticBeamColumn elements in Matlock soft clay, then in API sand, under an axial
load at the head, then pushed laterally at the head by DisplacementControl and
cycled (+-2 D/10 and on to 3 D/10): every pile node's displacements, the spring
forces of every depth and the iteration counts at every step.
"""
import importlib.util
import math
import os

_HERE = os.path.dirname(os.path.abspath(__file__))
_BEAMSOLID = os.path.join(_HERE, "..", "..", "..", "python", "beamsolid")


def _load(name):
    spec = importlib.util.spec_from_file_location("beamsolid_" + name, os.path.join(_BEAMSOLID, name + ".py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


bd = _load("boundaries")
sp = _load("springs")

L, D, N = 16.0, 1.0, 32  # pile length and diameter (m), elements
E = 3.0e7  # kPa
A, I = math.pi * D**2 / 4.0, math.pi * D**4 / 64.0

PROFILES = {
    "clay": [sp.SoftClay(0.0, 6.0, su=15.0, su_gradient=2.0, gamma=6.0, eps50=0.02, Cd=0.3),
             sp.SoftClay(6.0, 20.0, su=30.0, su_gradient=1.5, gamma=7.0, eps50=0.01, Cd=0.3, suction=0.1)],
    "sand": [sp.Sand(0.0, 4.0, phi=32.0, gamma=9.0, k=16300.0, Cd=1.0),
             sp.Sand(4.0, 20.0, phi=36.0, gamma=10.0, k=33900.0, Cd=1.0)],
}


# Head pushes (m) and displacement step: the clay springs reach ~4 y50 near the head,
# the sand's ~20 y50 (y50 ~ 3 mm there), in steps of 0.2 y50 (OpenSees' own iteration
# leaves ~1e-9 of p_ult unconverged when a step goes far past 0.98 p_ult in one go).
RUNS = {"clay": ((0.2 * D, -0.2 * D, 0.3 * D), 0.01 * D), "sand": ((0.05, -0.05, 0.08), 0.0005)}


def _pile(ops, layers, pushes, step):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    for i in range(N + 1):
        ops.node(i + 1, 0.0, -L * i / N)  # head at the ground surface
    ops.geomTransf("Linear", 1)
    for i in range(N):
        ops.element("elasticBeamColumn", i + 1, i + 1, i + 2, A, E, I, 1)
    tags = bd.Tags(node=1000, element=1000, material=1)
    springs = sp.pile_springs(ops, tags, list(range(1, N + 2)), D, layers, ground=0.0)
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.system("UmfPack")
    ops.test("NormDispIncr", 1e-11, 50)
    ops.algorithm("Newton")
    # Axial load first, in ten steps: 30 % of the tip and shaft capacity.
    capacity = sum(r["tz"]["tult"] for r in springs.rows if r["tz"]) + sum(
        r["qz"]["qult"] for r in springs.rows if r["qz"])
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(1, 0.0, -0.3 * capacity, 0.0)
    ops.integrator("LoadControl", 0.1)
    ops.analysis("Static")
    codes, iters, disps, forces = [], [], [], []

    def record():
        iters.append(ops.testIter())
        disps.append([ops.nodeDisp(n)[:2] for n in range(1, N + 2)])
        forces.append([ops.eleResponse(r["element"], "force")[3:5] for r in springs.rows])

    for _ in range(10):
        codes.append(ops.analyze(1))
        record()
    ops.loadConst("-time", 0.0)
    ops.timeSeries("Linear", 2)
    ops.pattern("Plain", 2, 2)
    ops.load(1, 1.0, 0.0, 0.0)
    for target in pushes:
        now = ops.nodeDisp(1, 1)
        n = max(1, int(round(abs(target - now) / step)))
        ops.integrator("DisplacementControl", 1, 1, (target - now) / n)
        for _ in range(n):
            codes.append(ops.analyze(1))
            record()
    return {"codes": codes, "testIter": iters, "disp": disps, "springForce": forces,
            "pult": [r["py"][1]["pult"] for r in springs.rows], "y50": [r["py"][1]["y50"] for r in springs.rows]}


def run(ops):
    out = {}
    for name, layers in PROFILES.items():
        pushes, step = RUNS[name]
        for key, value in _pile(ops, layers, pushes, step).items():
            out[name + "." + key] = value
    return out

"""Lateral pile in elastic soil (BeamContact3D): an OpenSeesPy script.

Runs unchanged under OpenSeesPy and BeamSolid; only the import differs:

    python lateral_pile.py [opensees|beamsolid] [SYSTEM] [n_theta n_radial n_z] [steps]

A beam pile (elasticBeamColumn, Linear transformation) on the axis of an O-grid of
stdBrick soil (ElasticIsotropic, self weight as body force), one BeamContact3D (Lagrange
multiplier node) per soil node on the pile surface (ContactMaterial3D, mu = 0.5); the beam
nodes lie half a soil layer off the soil levels (the head half the top layer above ground),
so that every contact node projects inside its segment. Stage 1: gravity with the pile
held and frictionless contacts; stage 2: friction on, the pile released (tip pinned), the
head pushed 20 mm along x by an sp in `steps` LoadControl steps. After every
step the script reads the head's displacement and reaction and every contact's status,
as scripts do. Prints one JSON line: timings, iterations, head force per step.
Units kN, m, kPa. Same problem as beamsolid.scenes.lateral_pile.
"""
import json
import math
import sys
import time

program = sys.argv[1] if len(sys.argv) > 1 else "beamsolid"
if program == "opensees":
    import openseespy.opensees as ops
else:
    import beamsolid.opensees as ops

SYSTEM = sys.argv[2] if len(sys.argv) > 2 else "UmfPack"
N_THETA, N_RADIAL, N_Z = (int(a) for a in sys.argv[3:6]) if len(sys.argv) > 5 else (16, 7, 16)
STEPS = int(sys.argv[6]) if len(sys.argv) > 6 else 21

R, L, R_OUT = 0.5, 20.0, 12.0
PILE_E, PILE_NU = 30e6, 0.2
SOIL_E, SOIL_NU, GAMMA = 20e3, 0.3, 20.0
MU, CONTACT_G = 0.5, 1e3
HEAD_DISP, TOL, MAX_ITER = 0.02, 1e-6, 25


def graded(start, stop, count, ratio):
    first = (stop - start) * (ratio - 1.0) / (ratio**count - 1.0)
    points, x, step = [start], start, first
    for _ in range(count):
        x += step
        points.append(x)
        step *= ratio
    points[-1] = stop
    return points


wall0, cpu0 = time.perf_counter(), time.process_time()
ops.wipe()
ops.model("basic", "-ndm", 3, "-ndf", 6)
levels = graded(0.0, -L, N_Z, 6.0 ** (1.0 / (N_Z - 1)))
# Beam nodes half a soil layer off the soil levels (the head half the top layer above ground, the
# tip on the fixed base), so that every pile-surface soil node projects inside its segment.
pile_z = [0.5 * (levels[0] - levels[1])] + [0.5 * (a + b) for a, b in zip(levels, levels[1:])] + [-L]
pile = list(range(1, len(pile_z) + 1))
for tag, z in zip(pile, pile_z):
    ops.node(tag, 0.0, 0.0, z)
ops.geomTransf("Linear", 1, 1.0, 0.0, 0.0)
A, I = math.pi * R**2, math.pi * R**4 / 4.0
for e in range(1, len(pile)):
    ops.element("elasticBeamColumn", e, e, e + 1, A, PILE_E, PILE_E / (2 * (1 + PILE_NU)), 2 * I, I, I, 1)
for tag in pile:
    ops.fix(tag, 1, 1, 1, 1, 1, 1)

ops.model("basic", "-ndm", 3, "-ndf", 3)
ops.nDMaterial("ElasticIsotropic", 1, SOIL_E, SOIL_NU)
radii = graded(R, R_OUT, N_RADIAL, (R_OUT / R) ** (1.0 / N_RADIAL))
per_level = (N_RADIAL + 1) * N_THETA


def soil(i, j, k):
    return 1001 + k * per_level + j * N_THETA + (i % N_THETA)


for k, z in enumerate(levels):
    for j, r in enumerate(radii):
        for i in range(N_THETA):
            t = 2.0 * math.pi * i / N_THETA
            ops.node(soil(i, j, k), r * math.cos(t), r * math.sin(t), z)
bricks = []
for k in range(N_Z):
    for j in range(N_RADIAL):
        for i in range(N_THETA):
            quad = [(i, j), (i, j + 1), (i + 1, j + 1), (i + 1, j)]
            e = 1001 + len(bricks)
            ops.element("stdBrick", e, *[soil(a, b, k + 1) for a, b in quad], *[soil(a, b, k) for a, b in quad],
                        1, 0.0, 0.0, -GAMMA)
            bricks.append(e)
for k in range(N_Z + 1):
    for j in range(N_RADIAL + 1):
        for i in range(N_THETA):
            if k == N_Z:
                ops.fix(soil(i, j, k), 1, 1, 1)
            elif j == N_RADIAL:
                ops.fix(soil(i, j, k), 1, 1, 0)

ops.nDMaterial("ContactMaterial3D", 2, MU, CONTACT_G, 0.0, 0.0)
contacts = []
for k in range(N_Z):  # soil level k lies inside pile segment (k, k+1); the base ring is fixed
    for i in range(N_THETA):
        s, tag = soil(i, 0, k), 200001 + len(contacts)
        ops.node(tag, *ops.nodeCoord(s), "-ndf", 3)
        ops.element("BeamContact3D", tag, pile[k], pile[k + 1], s, tag, R, 1, 2, 1e-8, 1e-8, 0)
        contacts.append(tag)
build_wall, build_cpu = time.perf_counter() - wall0, time.process_time() - cpu0


def analysis(dt):
    ops.constraints("Transformation")
    ops.numberer("RCM")
    ops.system(SYSTEM)
    ops.test("NormUnbalance", TOL, MAX_ITER)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", dt)
    ops.analysis("Static")


wall1, cpu1 = time.perf_counter(), time.process_time()
iterations = []
# Stage 1: gravity, pile held, contacts frictionless.
# (friction on from the start: the frictionless stage 0 is not the same in both programs)
analysis(1.0)
ok = ops.analyze(1)
iterations.append(ops.testIter())
ops.loadConst("-time", 0.0)
ops.wipeAnalysis()
ops.updateMaterialStage("-material", 2, "-stage", 1)

# Stage 2: the push.
head, tip = pile[0], pile[-1]
for tag in pile:
    for dof in range(1, 7):
        if not ((tag == tip and dof <= 3) or (tag == head and dof == 6)):
            ops.remove("sp", tag, dof)
ops.timeSeries("Path", 2, "-time", 0.0, 1.0, "-values", 0.0, HEAD_DISP)
ops.pattern("Plain", 2, 2)
ops.sp(head, 1, 1.0)
analysis(1.0 / STEPS)
head_disp, head_force, normal = [], [], []
for step in range(STEPS):
    ok = ops.analyze(1)
    if ok != 0:
        break
    iterations.append(ops.testIter())
    ops.reactions()
    head_disp.append(ops.nodeDisp(head, 1))
    head_force.append(ops.nodeReaction(head, 1))
    normal.append(sum(ops.eleResponse(e, "forcescalar")[0] for e in contacts))
equations = ops.systemSize()
analysis_wall, analysis_cpu = time.perf_counter() - wall1, time.process_time() - cpu1
print(json.dumps(dict(program=program, system=SYSTEM, mesh=[N_THETA, N_RADIAL, N_Z], steps=STEPS, ok=ok,
                      equations=equations, bricks=len(bricks), contacts=len(contacts),
                      build_wall=build_wall, build_cpu=build_cpu, analysis_wall=analysis_wall,
                      analysis_cpu=analysis_cpu, iterations=iterations, head_disp=head_disp,
                      head_force=head_force, normal=normal)))
ops.wipe()

"""Donut pullout (Arduino, Petek & Mackenzie-Helnwein 2007, Table 1): an OpenSeesPy script.

Runs unchanged under OpenSeesPy and BeamSolid; only the import differs:

    python donut_pullout.py [opensees|beamsolid] [SYSTEM] [n_theta n_radial n_z] [mu ...]

A beam pile pulled up through an elastic O-grid ring of stdBrick soil that confines it by
its own weight; one BeamContact3D (Lagrange multiplier node) per pile-surface soil node,
ContactMaterial3D with G = 1000. For each friction coefficient: gravity (pile held,
contacts frictionless), then friction on, the pile released along its axis and the head
pulled up in 12 LoadControl steps past full sliding. After each step the script reads the
head's reaction and displacement and every contact's forcescalar. Q is the largest head
force. Prints one JSON line. Units kN, m, kPa. Same problem as
beamsolid.scenes.donut_pullout.
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
N_THETA, N_RADIAL, N_Z = (int(a) for a in sys.argv[3:6]) if len(sys.argv) > 5 else (16, 6, 20)
MUS = [float(a) for a in sys.argv[6:]] or [0.1, 0.25, 0.5, 1.0]

R, R_OUT, DEPTH, GAMMA = 0.5, 5.0, 10.0, 20.0
SOIL_E, SOIL_NU, PILE_E, PILE_G = 20e3, 0.3, 30e6, 12.5e6
G, RADIAL_RATIO, STEPS, TOL, MAX_ITER = 1000.0, 1.5, 12, 1e-8, 25
K0 = SOIL_NU / (1.0 - SOIL_NU)


def graded(start, stop, count, ratio):
    first = (stop - start) * (ratio - 1.0) / (ratio**count - 1.0)
    points, x, step = [start], start, first
    for _ in range(count):
        x += step
        points.append(x)
        step *= ratio
    points[-1] = stop
    return points


def pull_distance(mu):
    """Past full sliding: 0.04 mu + 0.004 on the paper's 16 x 4 x 10 ring, scaled by the deepest
    ring's slip at sliding, sigma_h(D) R sin(2 pi / n) h / G."""
    def slip(n_theta, n_z):
        return K0 * GAMMA * DEPTH * R * math.sin(2 * math.pi / n_theta) * (DEPTH / n_z) / G
    return (0.04 * mu + 0.004) * max(1.0, slip(N_THETA, N_Z) / slip(16, 10))


def build(mu):
    ops.wipe()
    h = DEPTH / N_Z
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    pile = list(range(1, N_Z + 3))
    for k, tag in enumerate(pile):
        ops.node(tag, 0.0, 0.0, 0.5 * h - k * h)
        ops.fix(tag, 1, 1, 1, 1, 1, 1)
    ops.geomTransf("Linear", 1, 1.0, 0.0, 0.0)
    A, I = math.pi * R**2, math.pi * R**4 / 4.0
    for k in range(N_Z + 1):
        ops.element("elasticBeamColumn", 1 + k, 1 + k, 2 + k, A, PILE_E, PILE_G, 2 * I, I, I, 1)
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    ops.nDMaterial("ElasticIsotropic", 1, SOIL_E, SOIL_NU)
    radii = graded(R, R_OUT, N_RADIAL, RADIAL_RATIO)
    per_level = (N_RADIAL + 1) * N_THETA

    def soil(i, j, k):
        return 1001 + k * per_level + j * N_THETA + (i % N_THETA)

    for k in range(N_Z + 1):
        for j, r in enumerate(radii):
            for i in range(N_THETA):
                t = 2.0 * math.pi * i / N_THETA
                ops.node(soil(i, j, k), r * math.cos(t), r * math.sin(t), -k * h)
    e = 1001
    for k in range(N_Z):
        for j in range(N_RADIAL):
            for i in range(N_THETA):
                quad = [(i, j), (i, j + 1), (i + 1, j + 1), (i + 1, j)]
                ops.element("stdBrick", e, *[soil(a, b, k + 1) for a, b in quad], *[soil(a, b, k) for a, b in quad],
                            1, 0.0, 0.0, -GAMMA)
                e += 1
    for k in range(N_Z + 1):
        for j in range(N_RADIAL + 1):
            for i in range(N_THETA):
                x = 1 if j == N_RADIAL else 0
                if x or k == N_Z:
                    ops.fix(soil(i, j, k), x, x, 1 if k == N_Z else 0)
    ops.nDMaterial("ContactMaterial3D", 2, mu, G, 0.0, 0.0)
    contacts = []
    for k in range(N_Z + 1):  # level k (z = -k h) lies in segment (pile node k+1, k+2)
        for i in range(N_THETA):
            s, tag = soil(i, 0, k), 200001 + len(contacts)
            ops.node(tag, *ops.nodeCoord(s), "-ndf", 3)
            ops.element("BeamContact3D", tag, 1 + k, 2 + k, s, tag, R, 1, 2, 1e-8, 1e-8)
            contacts.append(tag)
    return pile, contacts, e - 1001


def analysis(dt):
    ops.constraints("Transformation")
    ops.numberer("RCM")
    ops.system(SYSTEM)
    ops.test("NormUnbalance", TOL, MAX_ITER)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", dt)
    ops.analysis("Static")


runs = []
for mu in MUS:
    wall0, cpu0 = time.perf_counter(), time.process_time()
    pile, contacts, bricks = build(mu)
    build_wall, build_cpu = time.perf_counter() - wall0, time.process_time() - cpu0
    wall1, cpu1 = time.perf_counter(), time.process_time()
    # (friction on from the start: the frictionless stage 0 is not the same in both programs)
    analysis(1.0)
    ok = ops.analyze(1)
    iterations = [ops.testIter()]
    ops.loadConst("-time", 0.0)
    ops.wipeAnalysis()
    ops.updateMaterialStage("-material", 2, "-stage", 1)
    head = pile[0]
    for tag in pile:
        ops.remove("sp", tag, 3)
    ops.timeSeries("Linear", 2)
    ops.pattern("Plain", 2, 2)
    ops.sp(head, 3, pull_distance(mu))
    analysis(1.0 / STEPS)
    head_force, head_disp, normal = [], [], []
    for step in range(STEPS):
        ok = ops.analyze(1)
        if ok != 0:
            break
        iterations.append(ops.testIter())
        ops.reactions()
        head_force.append(ops.nodeReaction(head, 3))
        head_disp.append(ops.nodeDisp(head, 3))
        normal.append(sum(ops.eleResponse(e, "forcescalar")[0] for e in contacts))
    runs.append(dict(mu=mu, ok=ok, equations=ops.systemSize(), bricks=bricks, contacts=len(contacts),
                     build_wall=build_wall, build_cpu=build_cpu,
                     analysis_wall=time.perf_counter() - wall1, analysis_cpu=time.process_time() - cpu1,
                     iterations=iterations, head_force=head_force, head_disp=head_disp, normal=normal,
                     Q=max(head_force) if head_force else None))
    ops.wipe()
print(json.dumps(dict(program=program, system=SYSTEM, mesh=[N_THETA, N_RADIAL, N_Z], runs=runs)))

"""Wave boundaries of beamsolid.boundaries (loaded from its file, so that the
same helpers build the model under OpenSeesPy): a tied column of stdBricks on
an elastic bedrock (dashpots and the Joyner-Chen force from an acceleration
record) with stiffness-proportional Rayleigh damping; the same column on
Lysmer dashpots hit by S and P force pulses at the surface; a small box whose
far faces follow a free-field column, under UniformExcitation; the same box
with gravity on a fixed base, then the horizontal fixes removed and shaken
on the elastic bedrock. Newmark
average acceleration, Newton: displacements, velocities, accelerations,
iteration counts and the dashpot forces at every step.

OpenSees' stdBrick forms the consistent mass of its material's density;
BeamSolid's the lumped one (row sums), so the soil here has no density and
its lumped mass is given as nodal masses. 'brick_mass' keeps the difference
in view (KNOWN_DIFFERENCES): the eigenvalues of one unit brick with one or two
free nodes on unit springs (lumped 8; consistent 27, and 18 and 54).
"""
import importlib.util
import math
import os

_PATH = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "python", "beamsolid",
                     "boundaries.py")
_spec = importlib.util.spec_from_file_location("beamsolid_boundaries", _PATH)
bd = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(bd)

RHO, E, NU, H, NZ = 2.0, 52000.0, 0.3, 8.0, 8


def _ricker(n, dt, fp, t0):
    out = []
    for i in range(n):
        a = (math.pi * fp * (i * dt - t0)) ** 2
        out.append((1.0 - 2.0 * a) * math.exp(-a))
    return out


def _lump(ops, elements):
    """Nodal masses rho V / 8 per brick (rectangular bricks)."""
    for e in elements:
        nodes = ops.eleNodes(e)
        x = [ops.nodeCoord(n) for n in nodes]
        volume = abs((x[1][0] - x[0][0]) * (x[3][1] - x[0][1]) * (x[4][2] - x[0][2]))
        m = RHO * volume / 8.0
        for n in nodes:
            ops.mass(n, m, m, m)


def _brick_mass(ops, free):
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    ops.nDMaterial("ElasticIsotropic", 1, 1e-9, 0.3, 1.0)
    corners = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
    for i, x in enumerate(corners):
        ops.node(i + 1, *map(float, x))
        if i + 1 not in free:
            ops.fix(i + 1, 1, 1, 1)
    ops.element("stdBrick", 1, *range(1, 9), 1)
    ops.uniaxialMaterial("Elastic", 2, 1.0)
    for j, n in enumerate(free):
        ops.node(100 + j, *ops.nodeCoord(n))
        ops.fix(100 + j, 1, 1, 1)
        ops.element("zeroLength", 100 + j, 100 + j, n, "-mat", 2, 2, 2, "-dir", 1, 2, 3)
    for cmd in _transient():
        getattr(ops, cmd[0])(*cmd[1:])
    return ops.eigen("-fullGenLapack", 3 * len(free) - 1)


def _column(ops, tags):
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    ops.nDMaterial("ElasticIsotropic", 1, E, NU, 0.0)
    rings = []
    for k in range(NZ + 1):
        ring = [1 + 4 * k + j for j in range(4)]
        for n, (x, y) in zip(ring, [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]):
            ops.node(n, x, y, H * k / NZ)
        rings.append(ring)
    for k in range(NZ):
        ops.element("stdBrick", k + 1, *rings[k], *rings[k + 1], 1)
    _lump(ops, range(1, NZ + 1))
    return rings


def _transient():
    return [("constraints", "Transformation"), ("numberer", "RCM"), ("system", "UmfPack"),
            ("test", "NormDispIncr", 1e-10, 10), ("algorithm", "Newton"), ("integrator", "Newmark", 0.5, 0.25),
            ("analysis", "Transient")]


def _run(ops, steps, dt, nodes, elements, out, key):
    for cmd in _transient():
        getattr(ops, cmd[0])(*cmd[1:])
    rows = []
    for _ in range(steps):
        ok = ops.analyze(1, dt)
        row = [ok, ops.testIter(), ops.getTime()]
        for n in nodes:
            row += ops.nodeDisp(n) + ops.nodeVel(n) + ops.nodeAccel(n)
        for e in elements:
            row += ops.eleResponse(e, "force")
        rows.append(row)
    out[key] = rows


def run(ops):
    out = {"brick_mass.one": _brick_mass(ops, [7]), "brick_mass.two": _brick_mass(ops, [7, 8])}
    # 1. Elastic bedrock, acceleration record, Rayleigh damping.
    tags = bd.Tags(node=1000, element=1000, material=10, series=1, pattern=1)
    rings = _column(ops, tags)
    bd.tie_levels(ops, [n for r in rings for n in r])
    dt = 0.004
    made = bd.compliant_base(ops, tags, 2.4, 750.0, 400.0, _ricker(150, dt, 6.0, 0.2), dt, kind="accel",
                             faces=[rings[0]])
    ops.rayleigh(0.0, 0.002, 0.0, 0.0)
    _run(ops, 300, dt, [rings[0][0], rings[NZ // 2][1], rings[-1][2]], made["elements"][:2], out, "elastic_base")
    # 2. Lysmer dashpots under S and P pulses at the surface.
    tags = bd.Tags(node=1000, element=1000, material=10, series=1, pattern=1)
    rings = _column(ops, tags)
    bd.tie_levels(ops, [n for r in rings for n in r])
    vp, vs = bd.wave_speeds(E, NU, RHO)
    made = bd.viscous_boundary(ops, tags, RHO, vp, vs, faces=[rings[0]])
    dt = 0.002
    ops.timeSeries("Path", 1, "-dt", dt, "-values", *_ricker(100, dt, 12.5, 0.1))
    ops.pattern("Plain", 1, 1)
    ops.load(rings[-1][0], 1.0, 0.0, 0.5)
    _run(ops, 200, dt, [rings[0][0], rings[NZ // 2][3], rings[-1][0]], made["elements"], out, "viscous_base")
    # 3. A box 2 x 1 x 4 on a rigid base, far faces on a free-field column.
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    ops.nDMaterial("ElasticIsotropic", 1, E, NU, 0.0)
    nx, nz = 2, 4

    def tag(i, j, k):
        return 1 + i + (nx + 1) * (j + 2 * k)

    for k in range(nz + 1):
        for j in range(2):
            for i in range(nx + 1):
                ops.node(tag(i, j, k), 3.0 * i, 2.0 * j, 2.0 * k)
                if k == 0:
                    ops.fix(tag(i, j, k), 1, 1, 1)
    for k in range(nz):
        for i in range(nx):
            ops.element("stdBrick", 1 + i + nx * k, tag(i, 0, k), tag(i + 1, 0, k), tag(i + 1, 1, k),
                        tag(i, 1, k), tag(i, 0, k + 1), tag(i + 1, 0, k + 1), tag(i + 1, 1, k + 1),
                        tag(i, 1, k + 1), 1)
    tags = bd.Tags(node=1000, element=1000)
    ff = bd.free_field_column(ops, tags, [2.0 * k for k in range(nz + 1)], [1] * nz, 20.0, 0.0, 30.0)
    bd.attach_free_field(ops, ff["levels"], [tag(i, j, k) for k in range(1, nz + 1) for j in range(2)
                                             for i in (0, nx)], dofs=(1, 2))
    _lump(ops, list(range(1, nx * nz + 1)) + ff["elements"])
    dt = 0.005
    ops.timeSeries("Path", 1, "-dt", dt, "-values", *_ricker(100, dt, 5.0, 0.25))
    ops.pattern("UniformExcitation", 1, 1, "-accel", 1)
    ops.rayleigh(0.0, 0.002, 0.0, 0.0)
    _run(ops, 150, dt, [tag(1, 0, nz), tag(0, 1, nz), tag(1, 1, 2), ff["levels"][8.0]], [], out, "free_field")
    # 4. Gravity, then the bedrock (docs/dynamics.md's staging).
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    ops.nDMaterial("ElasticIsotropic", 1, E, NU, 0.0)
    body = (0.0, 0.0, -RHO * 9.81)
    for k in range(nz + 1):
        for j in range(2):
            for i in range(nx + 1):
                ops.node(tag(i, j, k), 3.0 * i, 2.0 * j, 2.0 * k)
    held = []
    for j in range(2):
        for i in range(nx + 1):
            if i in (0, nx):
                ops.fix(tag(i, j, 0), 0, 0, 1)
            else:
                ops.fix(tag(i, j, 0), 1, 1, 1)
                held.append(tag(i, j, 0))
    for k in range(nz):
        for i in range(nx):
            ops.element("stdBrick", 1 + i + nx * k, tag(i, 0, k), tag(i + 1, 0, k), tag(i + 1, 1, k),
                        tag(i, 1, k), tag(i, 0, k + 1), tag(i + 1, 0, k + 1), tag(i + 1, 1, k + 1),
                        tag(i, 1, k + 1), 1, *body)
    tags = bd.Tags(node=1000, element=1000, material=10, series=1, pattern=1)
    ff = bd.free_field_column(ops, tags, [2.0 * k for k in range(nz + 1)], [1] * nz, 20.0, 0.0, 30.0,
                              base="rollers", body=body)
    ops.fix(ff["levels"][0.0], 1, 1, 0)
    held.append(ff["levels"][0.0])
    bd.attach_free_field(ops, ff["levels"], [tag(i, j, 0) for j in range(2) for i in (0, nx)], dofs=(1, 2))
    bd.attach_free_field(ops, ff["levels"], [tag(i, j, k) for k in range(1, nz + 1) for j in range(2)
                                             for i in (0, nx)])
    _lump(ops, list(range(1, nx * nz + 1)) + ff["elements"])
    ops.constraints("Transformation")
    ops.numberer("RCM")
    ops.system("UmfPack")
    ops.test("NormDispIncr", 1e-10, 10)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", 1.0)
    ops.analysis("Static")
    out["gravity"] = [ops.analyze(1), ops.testIter()] + [v for n in ops.getNodeTags() for v in ops.nodeDisp(n)]
    ops.loadConst("-time", 0.0)
    ops.wipeAnalysis()
    for n in held:
        ops.remove("sp", n, 1)
        ops.remove("sp", n, 2)
    dt = 0.005
    faces = [ff["base_face"]] + [[tag(i, 0, 0), tag(i + 1, 0, 0), tag(i + 1, 1, 0), tag(i, 1, 0)] for i in range(nx)]
    bd.compliant_base(ops, tags, 2.4, 0.0, 400.0, _ricker(100, dt, 5.0, 0.25), dt, faces=faces)
    _run(ops, 120, dt, [tag(1, 0, nz), tag(1, 1, 0), tag(0, 0, 0), ff["levels"][8.0]], [], out, "gravity_then_shaking")
    return out

"""A rigid cylinder moved laterally through weightless von Mises clay: the plane-strain slice.

Randolph and Houlsby (1984), "The limiting pressure on a circular pile loaded laterally in
cohesive soil", Geotechnique 34(4), 613-623: a rigid circular pile moved through rigid-plastic
Tresca (in plane strain: von Mises) soil of undrained strength s_u reaches the limiting
pressure P / (s_u D) = 9.14 for a smooth interface and 11.94 for a fully rough one (interface
shear strength s_u), with the soil in contact all around the pile (no gap behind it). Martin
and Randolph (2006, Geotechnique 56(2)) confirmed both as exact (equal lower and upper
bounds): 9.142 and 11.940.

The slice: one layer of bricks (bbarBrick or SSPbrick: J2 flow is isochoric and standard
bricks lock) of thickness t around a hole of radius R, every soil node's z fixed (plane
strain), the outer circle at R_out fixed; the pile a two-node beam on the axis joined to the
soil by BeamContact3D (one per surface node, Lagrange multipliers); the pile's head and tip
nodes are moved together along x. Soil: J2Plasticity with sig0 = sqrt(3) s_u (pure shear
yields at s_u), no hardening. Interface: ContactMaterial3D with mu = 0 and cohesion c = 0
(smooth) or c = s_u times the node's share of the pile surface (rough).

The solution assumes no gap behind the pile. Weightless soil starts unstressed, so the back of
the pile would pull away at once. Two ways to keep it closed (no_gap):

* "tension" (the default): the contacts carry tension -- BeamContact3D's forceTol and
  ContactMaterial3D's tensile strength t far above any contact force -- so no contact can
  open; the run records the smallest normal force (the tension a gap would have relieved).
* "confine": a pressure p0 on the outer circle first, with the pile held (soil elastic,
  contacts frictionless, inside InitialStateAnalysis so that the geometry returns to the
  reference with the stress kept); then the outer circle is fixed. In perfect plasticity the
  limit load does not depend on the initial stress, but here the contact forces p0 A turn
  with the contact normals (finite sliding) while the soil's stress stays in its reference
  configuration (small strain): the pile feels a spurious force of order p0 D u / R that
  grows with the displacement u (measured: -0.11 p0 D per 1 % of D of displacement). With a
  stiff soil (G = 5e4 s_u) the limit is reached at u ~ 1e-4 D and the two ways agree.

interface="bonded" replaces the contact by the pile's motion imposed on every hole node (no
slip, no gap): the fully rough limit again, 11.94, without the contact.

Units: kN, m, kPa.
"""
import math
import time
from dataclasses import dataclass, field

from ..contact import pile_interface
from ..mesh import ogrid
from ..model import Model
from ..stepping import adaptive_analyze

# n_theta of each level. The rings are graded geometrically from R to R_out = 20 R with
# n_radial = n_theta / 2 (cells = "square": about as deep radially as they are wide) or
# n_radial = n_theta (cells = "flat": half as deep). The radial size near the pile is what
# matters most (benchmarks/results/lateral_capacity_slice.md).
LEVELS = {"coarse": 16, "medium": 24, "fine": 32, "xfine": 48, "xxfine": 64}
CELLS = {"square": 2, "flat": 1}  # n_theta / n_radial

# P / (s_u D): 6 + pi and 2 pi + 4 sqrt(2), Randolph and Houlsby's N_p = pi + 2 asin(a)
# + 2 cos(asin(a)) + 4 (cos(asin(a) / 2) + sin(asin(a) / 2)) at adhesion a = 0 and 1.
RANDOLPH_HOULSBY = {"smooth": 6.0 + math.pi, "rough": 2.0 * math.pi + 4.0 * math.sqrt(2.0)}
RANDOLPH_HOULSBY["bonded"] = RANDOLPH_HOULSBY["rough"]

PILE_HEAD, PILE_TIP = 1, 2
TRANSF, SOIL, CONTACT, SOIL_J2 = 1, 1, 2, 3
FIRST_SOIL = 101
TS_CONFINE, PAT_CONFINE, TS_PUSH, PAT_PUSH = 1, 1, 2, 2


@dataclass(frozen=True)
class Slice:
    """The problem (kN, m, kPa) and the numerical choices of one slice run."""

    su: float = 40.0
    radius: float = 0.5
    outer_radius: float = 10.0  # 20 R: the mechanism reaches about 2 D from the axis
    thickness: float = 0.1
    # Soil shear modulus / s_u. The limit load does not depend on it; a stiff soil reaches it
    # at a small displacement, where the contact's finite kinematics (normals turning by u / R)
    # against the soil's small strains change nothing measurable.
    G_over_su: float = 5000.0
    nu: float = 0.49  # undrained: nearly incompressible elastic part
    p0_over_su: float = 10.0  # confining pressure / s_u
    # "confine": p0 keeps the contacts closed; "tension": no confinement, the contacts carry
    # tension (BeamContact3D's forceTol and ContactMaterial3D's t large): they cannot open.
    no_gap: str = "tension"
    interface: str = "smooth"  # "smooth" (mu = 0, c = 0) | "rough" (mu = 0, c = s_u) | "bonded"
    level: str = "medium"
    cells: str = "square"
    element: str = "bbarBrick"
    push: float = 0.003  # pile displacement / D (the plateau starts near 0.002 for G = 5000 s_u)
    steps: int = 10
    tol: float = 1e-8  # NormDispIncr (m; the multiplier rows in kN)
    max_iter: int = 30

    def __post_init__(self):
        if self.interface not in RANDOLPH_HOULSBY:
            raise ValueError(f"capacity_slice: interface must be 'smooth', 'rough' or 'bonded', got "
                             f"{self.interface!r}")
        if self.no_gap not in ("confine", "tension"):
            raise ValueError(f"capacity_slice: no_gap must be 'confine' or 'tension', got {self.no_gap!r}")
        if self.level not in LEVELS:
            raise ValueError(f"capacity_slice: level must be one of {sorted(LEVELS)}, got {self.level!r}")
        if self.cells not in CELLS:
            raise ValueError(f"capacity_slice: cells must be one of {sorted(CELLS)}, got {self.cells!r}")

    @property
    def mesh(self):
        """(n_theta, n_radial)."""
        n_theta = LEVELS[self.level]
        return n_theta, n_theta // CELLS[self.cells]

    @property
    def diameter(self):
        return 2.0 * self.radius

    @property
    def G(self):
        return self.G_over_su * self.su

    @property
    def K(self):
        return 2.0 * self.G * (1.0 + self.nu) / (3.0 * (1.0 - 2.0 * self.nu))

    @property
    def closed_form(self):
        return RANDOLPH_HOULSBY[self.interface]


@dataclass
class SliceResult:
    problem: Slice
    disp: list = field(default_factory=list)  # pile displacement / D, per converged step (0 first)
    pressure: list = field(default_factory=list)  # P / (s_u D) = F_x / (t s_u D)
    iterations: list = field(default_factory=list)
    norms: list = field(default_factory=list)  # testNorm of each step's iterations
    min_normal: list = field(default_factory=list)  # smallest contact normal force (kN; > 0 compression)
    n_open: list = field(default_factory=list)  # contacts out of contact (status 0)
    n_sliding: list = field(default_factory=list)
    converged: bool = False
    cuts: int = 0  # steps halved after a failed Newton
    n_equations: int = 0
    n_elements: int = 0
    n_contacts: int = 0
    wall: float = 0.0

    @property
    def limit(self):
        """The largest pressure reached (the curve rises monotonically to its plateau)."""
        return max(self.pressure)

    @property
    def error(self):
        return self.limit / self.problem.closed_form - 1.0


def _outer_pressure_loads(m, mesh, p0, thickness):
    """Nodal forces of a pressure p0 on the outer circle's faces (each face a chord x t
    rectangle; a quarter of its force on each of its nodes, along its inward normal)."""
    n_theta = mesh.n_theta
    loads = {}
    for i in range(n_theta):
        a = mesh.plan.groups["outer"][i]
        b = mesh.plan.groups["outer"][(i + 1) % n_theta]
        (xa, ya), (xb, yb) = mesh.plan.points[a], mesh.plan.points[b]
        chord = math.hypot(xb - xa, yb - ya)
        nx, ny = (yb - ya) / chord, -(xb - xa) / chord  # outward for counterclockwise points
        f = p0 * chord * thickness / 4.0
        for p in (a, b):
            for k in (0, 1):
                tag = mesh.node_at[(p, k)]
                fx, fy = loads.get(tag, (0.0, 0.0))
                loads[tag] = (fx - f * nx, fy - f * ny)
    for tag, (fx, fy) in loads.items():
        m.load(tag, fx, fy, 0.0)


def build(problem, m):
    """The slice in `m`; returns (mesh, interface (None if bonded), the outer nodes on the x axis)."""
    p = problem
    n_theta, n_radial = p.mesh
    t, R = p.thickness, p.radius
    m.wipe()
    m.model("basic", "-ndm", 3, "-ndf", 6)
    m.node(PILE_HEAD, 0.0, 0.0, 0.0)
    m.node(PILE_TIP, 0.0, 0.0, -t)
    m.geomTransf("Linear", TRANSF, 1.0, 0.0, 0.0)
    A, I = math.pi * R**2, math.pi * R**4 / 4.0
    m.element("elasticBeamColumn", 1, PILE_HEAD, PILE_TIP, A, 1e9, 4e8, 2.0 * I, I, I, TRANSF)
    for tag in (PILE_HEAD, PILE_TIP):
        m.fix(tag, 1, 1, 1, 1, 1, 1)

    m.model("basic", "-ndm", 3, "-ndf", 3)
    sig0 = math.sqrt(3.0) * p.su
    m.nDMaterial("J2Plasticity", SOIL_J2, p.K, p.G, sig0, sig0, 0.0, 0.0)
    m.nDMaterial("InitialStateAnalysisWrapper", SOIL, SOIL_J2, 3)
    ratio = (p.outer_radius / R) ** (1.0 / n_radial)
    mesh = ogrid(m, pile_radius=R, outer_size=p.outer_radius, outer="circle", n_theta=n_theta, n_radial=n_radial,
                 radial_ratio=ratio, levels=[0.0, -t], material_tag=SOIL, first_node=FIRST_SOIL,
                 first_element=FIRST_SOIL, element=p.element)
    on_axis = []
    for tag in mesh.nodes:
        m.fix(tag, 0, 0, 1)  # plane strain
    # Symmetric supports for the confinement stage (no rigid rotation with a smooth interface):
    # the outer nodes on the x axis keep y = 0, as the symmetric solution does.
    for tag in mesh.groups["outer"]:
        if abs(m.nodeCoord(tag, 2)) < 1e-9 * p.outer_radius:
            m.fix(tag, 0, 1, 0)
            on_axis.append(tag)
    if p.interface == "bonded":
        return mesh, None, on_axis
    # Each surface node stands for an arc 2 pi R / n_theta of half the layer.
    c = p.su * (2.0 * math.pi * R / n_theta) * (t / 2.0) if p.interface == "rough" else 0.0
    stick = 100.0 * p.G * t  # stick stiffness per node (kN/m), stiff against the soil's G h
    tension = p.no_gap == "tension"
    strength = 1e3 * p.su * R * t if tension else 0.0  # far above any contact force
    m.nDMaterial("ContactMaterial3D", CONTACT, 0.0, stick, c, strength)
    iface = pile_interface(m, [PILE_HEAD, PILE_TIP], mesh.surface_nodes(), R, TRANSF, CONTACT,
                           force_tol=strength if tension else 1e-8, first_element=10001, first_node=10001)
    return mesh, iface, on_axis


def contact_state(m, iface):
    """(smallest normal force, open count, sliding count) over the interface."""
    if iface is None:
        return math.nan, 0, 0
    normals, n_open, n_slide = [], 0, 0
    for e in iface.elements:
        status = int(m.eleResponse(e, "status")[0])
        n_open += status == 0
        n_slide += status == 2
        normals.append(m.eleResponse(e, "forcescalar")[0])
    return min(normals), n_open, n_slide


def confine(p, m, mesh):
    """The confinement stage: p0 on the outer circle with the soil elastic, the contacts
    frictionless and the pile held; the displacements are zeroed after, the stress kept."""
    m.InitialStateAnalysis("on")
    m.updateMaterialStage("-material", SOIL, "-stage", 0)
    m.updateMaterialStage("-material", CONTACT, "-stage", 0)
    m.timeSeries("Linear", TS_CONFINE)
    m.pattern("Plain", PAT_CONFINE, TS_CONFINE)
    _outer_pressure_loads(m, mesh, p.p0_over_su * p.su, p.thickness)
    m.constraints("Transformation")
    m.numberer("RCM")
    m.system("UmfPack")
    m.test("NormDispIncr", p.tol, p.max_iter)
    m.algorithm("Newton")
    m.integrator("LoadControl", 1.0)
    m.analysis("Static")
    if m.analyze(1) != 0:
        raise RuntimeError(f"capacity_slice: the confinement stage did not converge ({m.last_error()})")
    m.InitialStateAnalysis("off")
    m.loadConst("-time", 0.0)
    m.wipeAnalysis()
    m.updateMaterialStage("-material", SOIL, "-stage", 1)
    m.updateMaterialStage("-material", CONTACT, "-stage", 1)


def run(problem=Slice(), m=None):
    """(Confine,) then push the pile by problem.push * D in problem.steps steps (halved on a
    failed Newton, down to 1/32)."""
    p = problem
    t0 = time.perf_counter()
    m = m if m is not None else Model()
    mesh, iface, on_axis = build(p, m)

    if p.no_gap == "confine" and iface is not None:
        confine(p, m, mesh)

    for tag in mesh.groups["outer"]:
        m.fix(tag, 1, 0 if tag in on_axis else 1, 0)

    # The push: head and tip moved together along x (bonded: every hole node, y held).
    bonded = p.interface == "bonded"
    pushed = mesh.surface_nodes() if bonded else [PILE_HEAD, PILE_TIP]
    if bonded:
        for tag in pushed:
            m.fix(tag, 0, 1, 0)
    else:
        for tag in pushed:
            m.remove("sp", tag, 1)
    m.timeSeries("Linear", TS_PUSH)
    m.pattern("Plain", PAT_PUSH, TS_PUSH)
    for tag in pushed:
        m.sp(tag, 1, p.push * p.diameter)
    m.constraints("Transformation")
    m.numberer("RCM")
    m.system("UmfPack")
    m.test("NormDispIncr", p.tol, p.max_iter)
    m.algorithm("Newton")
    m.integrator("LoadControl", 1.0 / p.steps)
    m.analysis("Static")

    r = SliceResult(problem=p, n_elements=len(mesh.elements), n_contacts=len(iface.elements) if iface else 0)
    scale = p.thickness * p.su * p.diameter

    def record(iterations, norms):
        m.reactions()
        r.disp.append(m.nodeDisp(pushed[0], 1) / p.diameter)
        r.pressure.append(sum(m.nodeReaction(tag, 1) for tag in pushed) / scale)
        r.iterations.append(iterations)
        r.norms.append(norms)
        normal, n_open, n_slide = contact_state(m, iface)
        r.min_normal.append(normal)
        r.n_open.append(n_open)
        r.n_sliding.append(n_slide)

    record(0, [])
    # Newton may overshoot by far near the limit load (perfect plasticity): halve such a step.
    stepper = adaptive_analyze(m, 1.0, p.steps, min_fraction=1.0 / 32,
                               on_step=lambda t, n: record(n, list(m.testNorm()[:n])))
    r.converged = stepper.converged
    r.cuts = stepper.cuts
    r.n_equations = int(m.systemSize())
    r.wall = time.perf_counter() - t0
    m.wipe()
    return r

"""A single pile in elastic soil pushed laterally at its head (issue 5).

This module holds the physical problem shared by the scene, the accuracy-versus-cost
benchmark and the stability map: the parameters, the mesh levels and the closed forms.
Units: kN, m, kPa.

Problem: a solid circular concrete pile of radius R and length L, head at the ground
surface (z = 0), tip at z = -L on the base of a cylindrical soil domain of radius
R_out. The soil is elastic (E, nu) and confined by its own weight (unit weight gamma):
sigma_v = gamma d, sigma_h = K0 sigma_v at depth d with K0 = nu / (1 - nu) (the elastic
geostatic stage under uniaxial strain). The head is pushed along +x.

Randolph (1981), "The response of flexible piles to lateral loading", Geotechnique
31(2), 247-259 (also Fleming et al., Piling Engineering, 3rd ed., section 6.3), for a
flexible pile (L > lc) in homogeneous elastic soil (rho_c = 1), load H at ground level:
    G*  = G (1 + 3 nu / 4),         Ep = E_pile I_pile / (pi R^4 / 4)
    lc  = 2 R (Ep / G*)^(2/7)       (critical length)
    u   = (Ep / G*)^(1/7) / G* * (0.27 H / (lc / 2) + 0.3 M / (lc / 2)^2)
    theta = (Ep / G*)^(1/7) / G* * (0.3 H / (lc / 2)^2 + 0.8 M / (lc / 2)^3)
"""
import math
from dataclasses import dataclass

from .circular_pile import CircularPile

# Mesh levels: (n_theta, n_radial, n_z) of the soil O-grid; every level keeps the
# same geometry and grading so that the levels converge to one answer.
LEVELS = {
    "coarse": (12, 6, 12),
    "medium": (16, 9, 18),
    "fine": (24, 12, 27),
}


@dataclass(frozen=True)
class LateralPile(CircularPile):
    """The physical problem (kN, m, kPa). Numerical choices live with the models that use it."""

    pile_radius: float = 0.5
    length: float = 20.0  # pile length = soil depth (the pile is flexible: L = 2 lc)
    outer_radius: float = 12.0  # soil domain radius (24 pile diameters)
    pile_E: float = 30e6
    pile_nu: float = 0.2
    soil_E: float = 20e3
    soil_nu: float = 0.3
    gamma: float = 20.0  # soil unit weight (kN/m^3)
    mu: float = 0.5  # pile-soil friction coefficient
    head_disp: float = 0.02  # largest head displacement (m), 2% of the diameter

    @property
    def soil_G(self):
        return self.soil_E / (2.0 * (1.0 + self.soil_nu))

    @property
    def K0(self):
        """At-rest earth pressure coefficient of the elastic geostatic stage (uniaxial strain)."""
        return self.soil_nu / (1.0 - self.soil_nu)

    @property
    def stiffness_scale(self):
        """Soil stiffness scale per contact node, E_soil R (kN/m): penalties are quoted as multiples."""
        return self.soil_E * self.pile_radius

    # --- Randolph (1981) --------------------------------------------------------
    @property
    def G_star(self):
        return self.soil_G * (1.0 + 0.75 * self.soil_nu)

    @property
    def Ep(self):
        """Equivalent modulus of a solid pile of radius R with the pile's bending stiffness."""
        return self.pile_E * self.inertia / (math.pi * self.pile_radius**4 / 4.0)

    @property
    def critical_length(self):
        return 2.0 * self.pile_radius * (self.Ep / self.G_star) ** (2.0 / 7.0)

    def randolph_head(self, H, M=0.0):
        """(u, theta) at ground level of a flexible pile in homogeneous elastic soil."""
        half = 0.5 * self.critical_length
        scale = (self.Ep / self.G_star) ** (1.0 / 7.0) / self.G_star
        u = scale * (0.27 * H / half + 0.3 * M / half**2)
        theta = scale * (0.3 * H / half**2 + 0.8 * M / half**3)
        return u, theta

    @property
    def randolph_compliance(self):
        """u / H at ground level for a lateral load alone (m/kN)."""
        return self.randolph_head(1.0)[0]


# =====================================================================================
# The model: numerical choices, the run, its result.
# =====================================================================================
import time
from dataclasses import field

from ..contact import interface_forces, pile_interface
from ..geostatic import geostatic_stage
from ..mesh import fix_soil_boundary, graded, ogrid
from ..model import Model
from ..stepping import adaptive_analyze

# Grading shared by every level (only the number of intervals changes with the level):
# radii in geometric progression R .. R_out (equal aspect ratio of the soil cells in plan),
# vertical intervals growing geometrically with depth, the deepest VERTICAL_GROWTH times the
# shallowest (the pile bends within the top lc ~ 10 m; the surface is where the gap opens).
VERTICAL_GROWTH = 6.0

SOIL, CONTACT, SOIL_ELASTIC = 1, 2, 3  # material tags (SOIL wraps SOIL_ELASTIC)
TRANSF = 1
TS_PUSH, PAT_PUSH = 2, 2
FIRST_SOIL_NODE = 1001
FIRST_CONTACT = 200001  # element tags; multiplier node tags alike


@dataclass(frozen=True)
class Numerics:
    """Numerical choices of one lateral pile run."""

    level: str = "coarse"  # key of LEVELS
    interface: str = "contact"  # "contact" (BeamContact3D) | "penalty" (BeamContact3Dp) | "tied" (rigidLink)
    penalty_factor: float = 1e3  # penalty = penalty_factor * problem.stiffness_scale ("penalty")
    # Stick stiffness of ContactMaterial3D (kN per m of elastic slip, per contact node). Stiff
    # relative to the soil (E_soil h ~ 1e4 kN/m per surface node) so that a sticking node does
    # not slip: the interface is then rigid-plastic Coulomb friction, whose answer no longer
    # depends on G (head force at 20 mm, coarse, 10 steps: 896.7 kN for G = 1e5, 897.5 for 1e6;
    # the paper's G = 1e3 gives 819.6, 9 % soft). Any G converges (ContactMaterial3D::setIterate);
    # stiff G takes 5-7 Newton iterations a step, G = 1e3 3-4.
    contact_G: float = 1e5
    algorithm: str = "Newton"  # "Newton" | "NewtonLineSearch" | "KrylovNewton"
    steps: int = 20  # steps to reach head_disp (monotonic), or per quarter cycle (cyclic)
    protocol: str = "monotonic"  # "monotonic" | "cyclic"
    cycles: int = 2  # cyclic: full cycles 0 -> +d -> 0 -> -d -> 0 (peaks +d, -d, +d, ...)
    # "disp": the head displacement follows the protocol to +-head_disp (the head force is its
    # reaction); "force": a head load follows the same protocol to +-head_load kN (LoadControl).
    control: str = "disp"
    head_load: float = 700.0
    adaptive: bool = False  # cut the step on failure (halve), grow it back (double) after easy steps
    min_fraction: float = 1.0 / 64  # adaptive: smallest step, as a fraction of the nominal one
    tol: float = 1e-6  # NormUnbalance (kN; the multiplier rows in m)
    max_iter: int = 25
    # Zero the displacements after the gravity stage (InitialStateAnalysis), keeping its stresses.
    # Without it the soil settles by gamma H^2 / (2 M) = 0.15 m at the surface while the pile is
    # held, and slides that far down the beam pile before the push (docs/lateral_pile.md).
    initial_state: bool = True

    def __post_init__(self):
        if self.level not in LEVELS:
            raise ValueError(f"lateral_pile: level must be one of {sorted(LEVELS)}, got {self.level!r}")
        if self.interface not in ("contact", "penalty", "tied"):
            raise ValueError(f"lateral_pile: interface must be 'contact', 'penalty' or 'tied', got {self.interface!r}")
        if self.algorithm not in ("Newton", "NewtonLineSearch", "KrylovNewton"):
            raise ValueError(f"lateral_pile: unknown algorithm {self.algorithm!r}")
        if self.protocol not in ("monotonic", "cyclic"):
            raise ValueError(f"lateral_pile: protocol must be 'monotonic' or 'cyclic', got {self.protocol!r}")
        if self.control not in ("disp", "force"):
            raise ValueError(f"lateral_pile: control must be 'disp' or 'force', got {self.control!r}")
        if self.steps < 1 or self.cycles < 1:
            raise ValueError("lateral_pile: steps and cycles must be at least 1")


@dataclass
class LateralResult:
    """Curves (one entry per converged push step, the first entry the state after release)
    and final profiles of one run."""

    problem: LateralPile
    numerics: Numerics
    time: list = field(default_factory=list)  # pseudo time of the protocol (quarter cycles)
    head_disp: list = field(default_factory=list)  # m, +x
    head_force: list = field(default_factory=list)  # kN, the imposed displacement's reaction, +x
    iterations: list = field(default_factory=list)  # Newton iterations (0 for the initial state)
    gap_depth: list = field(default_factory=list)  # trailing side (behind the motion): deepest open node, m
    gap_depth_back: list = field(default_factory=list)  # x < 0 side
    gap_depth_front: list = field(default_factory=list)  # x > 0 side
    max_penetration: list = field(default_factory=list)  # largest -gap of a node in contact, m
    # Largest -gap of an open node (m): a released node overlapping the pile. The status lags by a
    # step (C20), so an opening that should close shows here until the next commit.
    max_open_overlap: list = field(default_factory=list)
    # Open contacts on each side (a depth of 0 is also the ground surface, so count them too).
    n_open_back: list = field(default_factory=list)  # x < 0
    n_open_front: list = field(default_factory=list)  # x > 0
    n_open: list = field(default_factory=list)  # contacts open (status 0)
    n_sliding: list = field(default_factory=list)
    converged: bool = False
    failed_at: float = None  # protocol time of the last converged state when the run stopped
    returncode: int = 0  # the failed analyze's code when the run stopped, and why
    error: str = ""
    steps_cut: int = 0
    steps_grown: int = 0
    # Final state.
    z: list = field(default_factory=list)  # pile node elevations, head first
    deflection: list = field(default_factory=list)  # u_x at the pile nodes
    moment: list = field(default_factory=list)  # M_y at the pile nodes (see bending_moments)
    head_moment: float = 0.0  # beam end moment at the head (free head: only the contacts' moment on the head node)
    head_contact_moment: float = 0.0  # M_y the contacts apply to the head node (friction at radius R)
    tip_reaction: tuple = (0.0, 0.0, 0.0)  # pinned tip, global
    pile_contact_force: tuple = None  # summed contact forces acting on the pile (global); None if tied
    interface: object = None  # beamsolid.contact.InterfaceForces (None if tied)
    n_equations: int = 0
    n_contacts: int = 0
    timings: dict = field(default_factory=dict)  # build, geostatic, push, total (s, wall)

    @property
    def compliance(self):
        """Secant head compliance u/H of the last state (m/kN)."""
        return self.head_disp[-1] / self.head_force[-1]

    @property
    def randolph_ratio(self):
        return self.compliance / self.problem.randolph_compliance


def soil_levels(problem, n_z):
    """Node elevations of the soil (and of the pile), ground surface first."""
    ratio = VERTICAL_GROWTH ** (1.0 / (n_z - 1)) if n_z > 1 else 1.0
    return graded(0.0, -problem.length, n_z, ratio)


def radial_ratio(problem, n_radial):
    """Geometric radial grading: each ring's width grows by (R_out / R)^(1 / n_radial)."""
    return (problem.outer_radius / problem.pile_radius) ** (1.0 / n_radial)


def soil_radii(problem, n_radial):
    return graded(problem.pile_radius, problem.outer_radius, n_radial, radial_ratio(problem, n_radial))


def protocol_path(problem, numerics):
    """(times, head displacements) of the loading protocol; one time unit per quarter cycle."""
    d = problem.head_disp
    if numerics.protocol == "monotonic":
        return [0.0, 1.0], [0.0, d]
    times, values = [0.0], [0.0]
    for _ in range(numerics.cycles):
        times += [times[-1] + 1.0, times[-1] + 3.0, times[-1] + 4.0]
        values += [d, -d, 0.0]
    return times, values


class LateralPileModel:
    """Builds the lateral pile model in `m` (a beamsolid.Model) and runs its stages."""

    def __init__(self, problem=LateralPile(), numerics=Numerics(), m=None):
        self.p, self.n = problem, numerics
        self.m = m if m is not None else Model()
        self.pile_nodes, self.beams, self.iface, self.mesh = [], [], None, None
        self.contact_soil = []  # soil nodes on the pile surface (all levels but the base)
        self._x = {}  # soil node -> reference x (trailing side test)

    # --- build ----------------------------------------------------------------
    def build(self):
        p, n, m = self.p, self.n, self.m
        n_theta, n_radial, n_z = LEVELS[n.level]
        levels = soil_levels(p, n_z)
        m.wipe()
        m.model("basic", "-ndm", 3, "-ndf", 6)
        self.pile_nodes = list(range(1, n_z + 2))
        for tag, z in zip(self.pile_nodes, levels):
            m.node(tag, 0.0, 0.0, z)
        # Local z = global x: the push bends the pile about local y = global y.
        m.geomTransf("Linear", TRANSF, 1.0, 0.0, 0.0)
        I = p.inertia
        self.beams = list(range(1, n_z + 1))
        for e in self.beams:
            m.element("elasticBeamColumn", e, e, e + 1, p.area, p.pile_E, p.pile_G, 2.0 * I, I, I, TRANSF)
        for tag in self.pile_nodes:
            m.fix(tag, 1, 1, 1, 1, 1, 1)  # geostatic stage: the pile is held

        m.model("basic", "-ndm", 3, "-ndf", 3)
        # Wrapped so that the gravity stage's stresses survive InitialStateAnalysis('off').
        m.nDMaterial("ElasticIsotropic", SOIL_ELASTIC, p.soil_E, p.soil_nu)
        m.nDMaterial("InitialStateAnalysisWrapper", SOIL, SOIL_ELASTIC, 3)
        self.mesh = mesh = ogrid(m, pile_radius=p.pile_radius, outer_size=p.outer_radius, outer="circle",
                                 n_theta=n_theta, n_radial=n_radial, radial_ratio=radial_ratio(p, n_radial),
                                 levels=levels, material_tag=SOIL, first_node=FIRST_SOIL_NODE,
                                 first_element=FIRST_SOIL_NODE, body_force=(0.0, 0.0, -p.gamma))
        self.fixed_soil = list(fix_soil_boundary(m, mesh))  # outer nodes fixed in x and y, base fixed

        # The base ring is fixed and the tip pinned: no interface there (a multiplier on fixed
        # dofs only would make the system singular).
        self.contact_soil = [t for k in range(n_z) for t in mesh.surfaces[0][k]]
        self._x = {t: m.nodeCoord(t, 1) for t in self.contact_soil}
        if n.interface == "tied":
            for k in range(n_z):
                for i in range(n_theta):
                    m.rigidLink("beam", self.pile_nodes[k], mesh.surfaces[0][k][i])
        else:
            m.nDMaterial("ContactMaterial3D", CONTACT, p.mu, n.contact_G, 0.0, 0.0)
            penalty = n.penalty_factor * p.stiffness_scale if n.interface == "penalty" else None
            self.iface = pile_interface(m, self.pile_nodes, self.contact_soil, p.pile_radius, TRANSF, CONTACT,
                                        penalty=penalty, first_element=FIRST_CONTACT, first_node=FIRST_CONTACT)
        return self

    def _analysis(self, dt, algorithm):
        n, m = self.n, self.m
        m.constraints("Transformation")
        m.numberer("RCM")
        m.system("UmfPack")
        m.test("NormUnbalance", n.tol, n.max_iter)
        m.algorithm(algorithm)
        m.integrator("LoadControl", dt)
        m.analysis("Static")

    # --- stages -----------------------------------------------------------------
    def geostatic(self):
        """Self weight with the pile held and frictionless contacts (uniaxial strain), checked
        against sigma_v = gamma d, sigma_h = K0 sigma_v; then loadConst and friction on."""
        p, m = self.p, self.m
        self.geostatic_state = geostatic_stage(m, soil_elements=self.mesh.elements, gamma=p.gamma, K0=p.K0,
                                               contact_materials=[CONTACT] if self.iface is not None else [],
                                               tol=self.n.tol, max_iter=self.n.max_iter,
                                               # Exact only with Lagrange multipliers: a penalty interface
                                               # yields by sigma_h A / penalty, and tied to the held pile the
                                               # soil cannot settle (irrelevant to the linear tied push).
                                               check_tol=1e-8 if self.n.interface == "contact" else None,
                                               initial_state=self.n.initial_state)

    def release(self):
        """Friction on; the pile free but for its pinned tip and the torsion at its head; the
        head displacement along x imposed by the protocol's Path series. (geostatic_stage has
        already frozen the weight with loadConst and switched the friction on.)"""
        m = self.m
        head, tip = self.pile_nodes[0], self.pile_nodes[-1]
        for tag in self.pile_nodes:
            for dof in range(1, 7):
                keep = (tag == tip and dof <= 3) or (tag == head and dof == 6)
                if not keep:
                    m.remove("sp", tag, dof)
        times, values = protocol_path(self.p, self.n)
        if self.n.control == "force":  # the series gives the head load in kN
            values = [v / self.p.head_disp * self.n.head_load for v in values]
        m.timeSeries("Path", TS_PUSH, "-time", *times, "-values", *values)
        m.pattern("Plain", PAT_PUSH, TS_PUSH)
        if self.n.control == "force":
            m.load(head, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0)
        else:
            m.sp(head, 1, 1.0)
        self._analysis(1.0 / self.n.steps, self.n.algorithm)

    def add_recorders(self, out):
        """Node, Element (OpenSees text format) and PVD recorders of the push into `out`."""
        import pathlib

        out = pathlib.Path(out)
        out.mkdir(parents=True, exist_ok=True)
        m, head = self.m, self.pile_nodes[0]
        m.recorder("Node", "-file", str(out / "head_reaction.out"), "-time", "-node", head, "-dof", 1, "reaction")
        m.recorder("Node", "-file", str(out / "pile_disp.out"), "-time", "-node", *self.pile_nodes, "-dof", 1,
                   "disp")
        m.recorder("Element", "-file", str(out / "pile_forces.out"), "-time", "-ele", *self.beams, "localForce")
        m.recorder("PVD", str(out / "lateral_pile"))

    # --- queries ----------------------------------------------------------------
    def contact_state(self):
        """Gap depth (deepest open node) and open count on the x<0 and x>0 sides, open and
        sliding counts, the largest penetration of a closed contact and the largest overlap of
        an open one, as a dict."""
        state = dict(back=0.0, front=0.0, n_back=0, n_front=0, n_open=0, n_slide=0, penetration=0.0,
                     open_overlap=0.0)
        if self.iface is None:
            return state
        m, tol = self.m, 1e-9 * self.p.pile_radius
        for s in self.contact_soil:
            e = self.iface.element_of[s]
            status = m.eleResponse(e, "status")[0]
            gap = m.eleResponse(e, "gap")[0]
            if status == 0.0:
                state["n_open"] += 1
                state["open_overlap"] = max(state["open_overlap"], -gap)
                depth, x = -m.nodeCoord(s, 3), self._x[s]
                if x < -tol:
                    state["back"] = max(state["back"], depth)
                    state["n_back"] += 1
                elif x > tol:
                    state["front"] = max(state["front"], depth)
                    state["n_front"] += 1
            else:
                state["n_slide"] += status == 2.0
                state["penetration"] = max(state["penetration"], -gap)
        return state

    def bending_moments(self):
        """M_y at the pile nodes: the moment about +y of the forces acting on the pile above the
        section, M = sum (z_F - z) F_x (positive below a head pushed along +x). From the beams'
        localForce (local y = global y): My at end 1 of the element below the node, end 2 for the tip."""
        forces = [self.m.eleResponse(e, "localForce") for e in self.beams]
        return [f[4] for f in forces] + [-forces[-1][10]]

    def record(self, r, t, iterations):
        m, head = self.m, self.pile_nodes[0]
        m.reactions()
        r.time.append(t)
        r.head_disp.append(m.nodeDisp(head, 1))
        if self.n.control == "force":
            r.head_force.append(m.getLoadFactor(PAT_PUSH))
        elif self.iface is None:
            # Tied: the ring at the head level is rigid-linked to the head node, and a retained
            # node's reaction leaves out what its constrained nodes carry; global equilibrium
            # does not (the weight is vertical): H = -(soil supports + pile tip), along x.
            tip = self.pile_nodes[-1]
            r.head_force.append(-(sum(m.nodeReaction(t, 1) for t in self.fixed_soil) + m.nodeReaction(tip, 1)))
        else:
            r.head_force.append(m.nodeReaction(head, 1))
        r.iterations.append(iterations)
        c = self.contact_state()
        r.gap_depth_back.append(c["back"])
        r.gap_depth_front.append(c["front"])
        r.gap_depth.append(c["back"] if r.head_disp[-1] >= 0.0 else c["front"])
        r.n_open_back.append(c["n_back"])
        r.n_open_front.append(c["n_front"])
        r.n_open.append(c["n_open"])
        r.n_sliding.append(c["n_slide"])
        r.max_penetration.append(c["penetration"])
        r.max_open_overlap.append(c["open_overlap"])

    def finish(self, r):
        m = self.m
        m.reactions()
        r.z = [m.nodeCoord(t, 3) for t in self.pile_nodes]
        r.deflection = [m.nodeDisp(t, 1) for t in self.pile_nodes]
        r.moment = self.bending_moments()
        r.head_moment = r.moment[0]
        r.tip_reaction = tuple(m.nodeReaction(self.pile_nodes[-1], d) for d in (1, 2, 3))
        if self.iface is not None:
            total = [0.0, 0.0, 0.0]
            for e in self.iface.elements:
                f = m.eleResponse(e, "masterforce")
                for i in range(3):
                    total[i] += f[i] + f[3 + i]
            r.pile_contact_force = tuple(total)
            head = self.pile_nodes[0]
            for e in self.iface.elements:
                i, j = (int(t) for t in m.eleResponse(e, "segment"))
                if head in (i, j):
                    r.head_contact_moment += m.eleResponse(e, "mastermoment")[1 if i == head else 4]
            r.interface = interface_forces(m, self.iface)


def run(problem=LateralPile(), numerics=Numerics(), m=None, out=None, record=False):
    """Geostatic stage, release and the lateral push (monotonic or cyclic) of one pile.

    With record=True (and an `out` directory) the push is recorded: head_reaction.out, pile_disp.out,
    pile_forces.out (OpenSees text, with JSON sidecars) and lateral_pile.pvd."""
    t0 = time.perf_counter()
    model = LateralPileModel(problem, numerics, m).build()
    r = LateralResult(problem=problem, numerics=numerics,
                      n_contacts=len(model.iface.elements) if model.iface else 0)
    t1 = time.perf_counter()
    model.geostatic()
    t2 = time.perf_counter()
    model.release()
    if record:
        if out is None:
            raise ValueError("lateral_pile.run: record=True needs an out directory")
        model.add_recorders(out)
    model.record(r, 0.0, 0)
    times, _ = protocol_path(problem, numerics)
    stepper = adaptive_analyze(model.m, times[-1], numerics.steps * int(round(times[-1])),
                               adaptive=numerics.adaptive, min_fraction=numerics.min_fraction,
                               breakpoints=times[1:-1], on_step=lambda t, it: model.record(r, t, it))
    t3 = time.perf_counter()
    r.n_equations = int(model.m.systemSize())  # the system the push solved
    r.converged = stepper.converged
    r.failed_at = None if stepper.converged else stepper.failed_at
    r.returncode, r.error = stepper.returncode, stepper.error
    r.steps_cut, r.steps_grown = stepper.cuts, stepper.grows
    model.finish(r)
    model.m.wipe()  # closes the recorders
    r.timings = dict(build=t1 - t0, geostatic=t2 - t1, push=t3 - t2, total=time.perf_counter() - t0)
    return r


# =====================================================================================
# The scene: python -m beamsolid.scenes lateral_pile --level coarse|medium|fine
# =====================================================================================
def _plots(out, main, tied, problem):
    """PNG plots of the curves; returns the files written."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    files = []
    label = f"{main.numerics.interface} (mu = {problem.mu:g})"
    fig, ax = plt.subplots(figsize=(6.0, 4.4))
    ax.plot([1e3 * u for u in main.head_disp], main.head_force, "o-", ms=3, label=label)
    ax.plot([1e3 * u for u in tied.head_disp], tied.head_force, "s--", ms=3, label="tied (bonded)")
    span = (min(main.head_disp), max(main.head_disp))
    ax.plot([1e3 * u for u in span], [u / problem.randolph_compliance for u in span], "k:", lw=1,
            label="Randolph (1981), bonded")
    ax.set_xlabel("head displacement (mm)")
    ax.set_ylabel("head force H (kN)")
    ax.set_title("Lateral pile: head load-displacement")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    files.append(out / "head_load_displacement.png")
    fig.savefig(files[-1], dpi=120)
    plt.close(fig)

    fig, (a1, a2) = plt.subplots(1, 2, figsize=(7.2, 5.0), sharey=True)
    for r, style, name in ((main, "o-", label), (tied, "s--", "tied")):
        a1.plot([1e3 * u for u in r.deflection], r.z, style, ms=3, label=name)
        a2.plot(r.moment, r.z, style, ms=3, label=name)
    a1.set_xlabel("deflection u_x (mm)")
    a1.set_ylabel("z (m)")
    a2.set_xlabel("bending moment M_y (kNm)")
    for a in (a1, a2):
        a.grid(alpha=0.3)
        a.axvline(0.0, color="k", lw=0.5)
    a1.legend(fontsize=8)
    fig.suptitle(f"Pile profiles at the last state (head displacement {1e3 * main.head_disp[-1]:.1f} mm)")
    fig.tight_layout()
    files.append(out / "profiles.png")
    fig.savefig(files[-1], dpi=120)
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(6.0, 4.4))
    ax.plot([1e3 * u for u in main.head_disp], main.gap_depth_back, "o-", ms=3, label="x < 0 side (behind a +x push)")
    if any(main.gap_depth_front):
        ax.plot([1e3 * u for u in main.head_disp], main.gap_depth_front, "s-", ms=3, label="x > 0 side")
    ax.set_xlabel("head displacement (mm)")
    ax.set_ylabel("gap depth (m)")
    ax.invert_yaxis()
    ax.set_title("Depth of the gap behind the pile")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    files.append(out / "gap_depth.png")
    fig.savefig(files[-1], dpi=120)
    plt.close(fig)
    return files


def _rows(r, count=5):
    """Indices of about `count` states spread over the run (always the last)."""
    n = len(r.head_disp)
    picks = sorted({round(k * (n - 1) / (count - 1)) for k in range(count)}) if n > 1 else [0]
    return picks


def scene(level="coarse", out="lateral_pile_output", adaptive=False, steps=None, interface="contact",
          protocol="monotonic", cycles=2, algorithm="Newton", problem=LateralPile()):
    """Run the scene: the bonded (tied) reference, then the chosen interface with recorders;
    print the table, save the plots. Returns (result, tied result, files written)."""
    import pathlib

    out = pathlib.Path(out)
    out.mkdir(parents=True, exist_ok=True)
    t0 = time.perf_counter()
    numerics = Numerics(level=level, interface=interface, protocol=protocol, cycles=cycles, algorithm=algorithm,
                        adaptive=adaptive, **({} if steps is None else {"steps": steps}))
    # The tied model is linear: two steps give its compliance (and a curve to plot).
    tied = run(problem, Numerics(level=level, interface="tied", steps=2))
    main = run(problem, numerics, out=out, record=True)

    n_theta, n_radial, n_z = LEVELS[level]
    print(f"lateral_pile ({level}: soil O-grid {n_theta} x {n_radial} x {n_z} stdBricks, {n_z} pile elements, "
          f"{main.n_contacts} contacts, {main.n_equations} equations); units kN, m")
    print(f"  pile R = {problem.pile_radius:g}, L = {problem.length:g}, E = {problem.pile_E:.3g}; soil E = "
          f"{problem.soil_E:.3g}, nu = {problem.soil_nu:g}, gamma = {problem.gamma:g}, R_out = "
          f"{problem.outer_radius:g}; mu = {problem.mu:g}; interface {interface}, {numerics.algorithm}, "
          f"{protocol}, {numerics.steps} steps{' per quarter cycle' if protocol == 'cyclic' else ''}"
          f"{', adaptive' if adaptive else ''}")
    print(f"\n{'time':>6s}{'u_head mm':>11s}{'H kN':>10s}{'iters':>7s}{'gap m':>8s}{'open':>6s}{'penetr. m':>11s}")
    for k in _rows(main, 6 if protocol == "monotonic" else 9):
        print(f"{main.time[k]:6.2f}{1e3 * main.head_disp[k]:11.3f}{main.head_force[k]:10.2f}{main.iterations[k]:7d}"
              f"{main.gap_depth[k]:8.2f}{main.n_open[k]:6d}{main.max_penetration[k]:11.1e}")
    status = "reached the end" if main.converged else f"STOPPED at time {main.failed_at}"
    print(f"  {status}; {len(main.iterations) - 1} steps, {sum(main.iterations)} iterations, "
          f"{main.steps_cut} cuts; push {main.timings['push']:.1f} s")
    print(f"\nbonded head compliance u/H: tied {tied.compliance:.4e} m/kN, Randolph (1981) "
          f"{problem.randolph_compliance:.4e} m/kN, ratio {tied.randolph_ratio:.3f}")
    if main.converged and main.head_disp[-1] != 0.0:
        print(f"secant compliance of the {interface} model at the last state: {main.compliance:.4e} m/kN "
              f"({main.compliance / tied.compliance:.3f} x tied)")
    print(f"gap depth behind the pile at the last state: {main.gap_depth[-1]:.2f} m "
          f"(lc = {problem.critical_length:.2f} m)")
    files = [out / "head_reaction.out", out / "pile_disp.out", out / "pile_forces.out", out / "lateral_pile.pvd"]
    try:
        files += _plots(out, main, tied, problem)
    except ImportError:
        print("matplotlib not installed: no plots")
    print(f"\nwrote {', '.join(f.name for f in files)} in {out}; wall time {time.perf_counter() - t0:.1f} s")
    return main, tied, files

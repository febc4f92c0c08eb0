"""A free-head pile in undrained clay pushed laterally to failure, four ways (issue 18).

The problem (units kN, m, kPa): a solid concrete pile of diameter D = 0.8 m and embedded length
L = 6 m (L / D = 7.5), head at the ground surface, in a uniform clay layer of undrained strength
s_u = 40 kPa (von Mises: J2Plasticity, sig0 = sqrt(3) s_u, no hardening; E = 400 s_u, nu = 0.49),
unit weight gamma = 18 kN/m^3, 9 m deep (1.5 L) and 8 m (10 D) in radius. The pile stays
elastic (E = 30 GPa): its largest moment at failure is about 0.8 MNm here, which a 0.8 m RC
pile with 2 % steel carries (My ~ 1.2 MNm), so Broms' short-pile mechanism applies (a rigid pile
rotating in the soil). The head is pushed along +x to 0.25 D; free head (rotation free, no
moment), no eccentricity.

Four models of it:

(a) "smooth", "rough": the pile as elasticBeamColumn elements on its axis, the soil an O-grid of
    bbarBricks (mesh.ogrid, the hole filled below the tip), joined by BeamContact3D (one per
    pile-surface soil node, Lagrange multipliers, the '-pile' chain). Interface: ContactMaterial3D
    with mu = 0 and adhesion c = 0 (smooth) or c = s_u times the node's share of the pile surface
    (rough). A gap opens behind the pile where the soil's horizontal stress (K0 gamma z) is used up.
(b) "brick": the pile as elastic bricks (mesh.solid_cylinder) in the same soil, joined to it by
    one zeroLengthContact3D per pair of coincident surface nodes (normal towards the pile axis,
    adhesion c as (a) rough; node-to-node, so for small sliding); "brick_tied": the pairs tied
    (equalDOF, also under the base): no gap, no slip.
(c) "py": the beam pile on Matlock (1970) soft-clay p-y springs from the same s_u and gamma
    (beamsolid.springs.pile_springs, PySimple1 soilType 1, eps50 = 0.005, J = 0.5), a 2D model.
(d) "broms": Broms (1964) ultimate lateral load of a short free-head pile in cohesive soil
    (`broms_short`): no resistance over 1.5 D, 9 s_u D below.

The solid models run OpenSees users' stages: the elastic gravity stage (geostatic.geostatic_stage:
soil stage 0, pile held, contacts frictionless, inside InitialStateAnalysis), then the soil
plastic (updateMaterialStage 1), the friction back, the pile released and pushed (displacement
control of the head node, steps halved on a failed Newton).
"""
import math
import time
from dataclasses import dataclass, field

from .circular_pile import CircularPile

# =====================================================================================
# The problem and the closed form
# =====================================================================================


@dataclass(frozen=True)
class ClayPile(CircularPile):
    """The physical problem (kN, m, kPa)."""

    su: float = 40.0
    E_over_su: float = 500.0
    nu: float = 0.49  # undrained
    gamma: float = 18.0  # total unit weight (clay above the water table)
    pile_radius: float = 0.4
    length: float = 6.0  # embedded length; the head is at the ground surface
    soil_depth: float = 9.0
    outer_radius: float = 8.0
    pile_E: float = 30e6
    pile_nu: float = 0.2
    head_disp: float = 0.16  # 0.2 D
    eps50: float = 0.005  # Matlock's strain at half the peak deviator (s_u / E = 0.002 for this soil)
    J: float = 0.5  # Matlock's J

    @property
    def diameter(self):
        return 2.0 * self.pile_radius

    @property
    def soil_E(self):
        return self.E_over_su * self.su

    @property
    def soil_G(self):
        return self.soil_E / (2.0 * (1.0 + self.nu))

    @property
    def soil_K(self):
        return self.soil_E / (3.0 * (1.0 - 2.0 * self.nu))

    @property
    def K0(self):
        return self.nu / (1.0 - self.nu)


@dataclass(frozen=True)
class Broms:
    """Broms (1964), "Lateral resistance of piles in cohesive soils", J. Soil Mech. Found. Div.
    ASCE 90(SM2), 27-63: free-head pile, load H at height e above the ground, soil resistance
    zero from the surface to 1.5 D and 9 s_u D below it."""

    H_short: float  # ultimate load of the short (rigid) pile: the soil fails along the whole pile
    M_short: float  # the largest moment in the short pile at that load
    f: float  # depth of the largest moment below 1.5 D
    H_long: float  # ultimate load of the long pile (a plastic hinge at My); inf if My is None
    My: float
    mode: str  # "short" when M_short < My, else "long"

    @property
    def H(self):
        return self.H_short if self.mode == "short" else self.H_long


def broms(problem, My=None, e=0.0):
    """Broms' ultimate lateral load.

    Short pile: with f = H / (9 s_u D) and g = L - 1.5 D - f, moment equilibrium of the pile
    below the largest moment gives M_max = H (e + 1.5 D + f / 2) = 2.25 D s_u g^2; solved for H.
    Long pile: a plastic hinge at My, H (e + 1.5 D + f / 2) = My. My = None: the pile stays
    elastic (short pile)."""
    p = problem
    D, su, L = p.diameter, p.su, p.length
    q = 9.0 * su * D  # kN/m below 1.5 D
    a = e + 1.5 * D
    # q f (a + f / 2) = 2.25 D su (L - 1.5 D - f)^2, a quadratic in f.
    c2 = 0.5 * q - 2.25 * D * su
    c1 = q * a + 2.0 * 2.25 * D * su * (L - 1.5 * D)
    c0 = -2.25 * D * su * (L - 1.5 * D) ** 2
    f = (-c1 + math.sqrt(c1 * c1 - 4.0 * c2 * c0)) / (2.0 * c2) if c2 != 0.0 else -c0 / c1
    H_short = q * f
    M_short = H_short * (a + 0.5 * f)
    if My is None:
        H_long = math.inf
    else:  # q f (a + f / 2) = My with f = H / q
        f_long = -a + math.sqrt(a * a + 2.0 * My / q)
        H_long = q * f_long
    mode = "short" if My is None or M_short <= My else "long"
    return Broms(H_short=H_short, M_short=M_short, f=f, H_long=H_long, My=math.inf if My is None else My,
                 mode=mode)


# =====================================================================================
# The models
# =====================================================================================
from ..contact import pile_interface  # noqa: E402
from ..geostatic import geostatic_stage  # noqa: E402
from ..mesh import fix_soil_boundary, graded, ogrid, solid_cylinder  # noqa: E402
from ..model import Model  # noqa: E402
from ..stepping import adaptive_analyze  # noqa: E402

MODELS = {
    "rough": "beam + BeamContact3D, rough (c = s_u)",
    "smooth": "beam + BeamContact3D, smooth",
    "brick": "brick pile + zeroLengthContact3D, rough",
    "brick_tied": "brick pile tied to the soil",
    "py": "beam on Matlock p-y springs",
}

# (n_theta, n_radial, layers along the pile, layers below the tip). The rings are graded
# geometrically to R_out (cells about as deep as wide near the pile), the layers along the
# pile finer at the top (the deepest 3 times the shallowest), those below growing downwards.
LEVELS = {
    "coarse": (12, 6, 8, 2),
    "medium": (16, 8, 12, 3),
    "fine": (24, 12, 18, 4),
}
PY_ELEMENTS = {"coarse": 24, "medium": 48, "fine": 96}  # beam elements of the p-y model
TOP_GROWTH = 3.0
BELOW_GROWTH = 2.0

SOIL, SOIL_J2, PILE, PILE_ELASTIC = 1, 2, 3, 4  # nDMaterial tags (SOIL and PILE wrap for InitialStateAnalysis)
FIRST_CONTACT_MAT = 100
TRANSF = 1
TS_PUSH, PAT_PUSH = 2, 2
FIRST_SOIL = 1001
HEAD_BRICK = 900001  # the brick pile's head node (rigidLink 'beam' to its top face)


@dataclass(frozen=True)
class Numerics:
    level: str = "coarse"
    steps: int = 16  # nominal steps to head_disp (halved on a failed Newton, down to 1/32)
    tol: float = 1e-8  # NormDispIncr (m; multiplier rows in kN)
    max_iter: int = 15  # converged steps take 6-10; a diverging one is cut sooner
    contact_G: float = 1e5  # stick stiffness of the rough contact (kN/m per node)
    # The rough contact material's tensile strength t (kN per node). With mu = 0 and c > 0 the
    # adhesion drops from c to 0 where the normal force crosses -t: with t = 0 a node at the edge
    # of the gap, its normal force near zero, flipped between adhering and free from one Newton
    # iteration to the next, and the medium push stalled at 0.058 D (iterations cycling). Above
    # any contact force, the gap opens only through the element's status (forceTol, decided at
    # the commit as the paper's C20 does) and the adhesion is continuous within a step: the
    # medium push reaches 0.2 D without a step cut (133 iterations).
    contact_tension: float = 1e9
    # The solid models: a full Newton step from the elastic predictor can throw the perfectly
    # plastic soil far off (the first step diverged at every level); the line search (its
    # defaults: interpolated, ratio 0.8) damps such steps and takes full steps near the solution,
    # so Newton's rate stays quadratic. Coarse scene, CPU: 73 s against 114 s with plain Newton
    # and its step cuts (the smooth push: 17 s, 0 cuts against 52 s, 10 cuts).
    algorithm: str = "NewtonLineSearch"
    # Taken from the last converged state when `algorithm` stops (None: stop there).
    fallback: str = "Newton"

    def __post_init__(self):
        if self.level not in LEVELS:
            raise ValueError(f"lateral_capacity: level must be one of {sorted(LEVELS)}, got {self.level!r}")
        if self.algorithm not in ("Newton", "NewtonLineSearch"):
            raise ValueError(f"lateral_capacity: algorithm must be 'Newton' or 'NewtonLineSearch', "
                             f"got {self.algorithm!r}")
        if self.fallback not in (None, "Newton", "NewtonLineSearch"):
            raise ValueError(f"lateral_capacity: fallback must be None, 'Newton' or 'NewtonLineSearch', "
                             f"got {self.fallback!r}")


@dataclass
class CapacityResult:
    """Curves (one entry per converged step, the first the state after release) and the final
    profiles of one model."""

    model: str
    level: str
    head_disp: list = field(default_factory=list)  # m, +x
    head_force: list = field(default_factory=list)  # kN
    iterations: list = field(default_factory=list)
    norms: list = field(default_factory=list)  # testNorm of each step's iterations
    n_open: list = field(default_factory=list)  # contacts open (status 0)
    gap_depth: list = field(default_factory=list)  # deepest open contact behind the pile (m)
    converged: bool = False
    cuts: int = 0
    fallback_at: float = None  # push fraction where the fallback algorithm took over (None: not needed)
    error: str = ""
    z: list = field(default_factory=list)  # profile elevations, head first
    deflection: list = field(default_factory=list)
    moment: list = field(default_factory=list)  # M_y (kNm), positive for a head pushed along +x
    soil_reaction: float = 0.0  # sum of the soil's x forces on the pile at the last state (kN, along -x)
    # Soil bricks at the last state: (x, y, z of the centroid, mean equivalent plastic strain).
    plastic: list = field(default_factory=list)
    # Beam + contact: M_y the contacts apply to the head and tip nodes (the adhesion's vertical
    # forces at radius R), which the beam's end moments balance: a free end's moment is not 0.
    end_moments: tuple = (0.0, 0.0)
    n_equations: int = 0
    n_elements: int = 0
    n_contacts: int = 0
    geostatic: object = None
    timings: dict = field(default_factory=dict)

    @property
    def capacity(self):
        """The head force at the last state (the end of the push)."""
        return self.head_force[-1]

    def force_at(self, u):
        """Head force at head displacement u (linear between the recorded states)."""
        d, h = self.head_disp, self.head_force
        for k in range(1, len(d)):
            if d[k] >= u:
                return h[k - 1] + (h[k] - h[k - 1]) * (u - d[k - 1]) / (d[k] - d[k - 1])
        return math.nan

    @property
    def max_moment(self):
        return max(self.moment, key=abs) if self.moment else math.nan

    @property
    def wall(self):
        return self.timings.get("total", math.nan)

    @property
    def cpu(self):
        """CPU time of the process (all its threads): the cost measure on a shared machine."""
        return self.timings.get("cpu", math.nan)


def pile_levels(problem, n_pile):
    """Elevations from the ground to the tip: n_pile layers, the deepest TOP_GROWTH times the top one."""
    ratio = TOP_GROWTH ** (1.0 / (n_pile - 1)) if n_pile > 1 else 1.0
    return graded(0.0, -problem.length, n_pile, ratio)


def soil_levels(problem, n_pile, n_below):
    below = graded(-problem.length, -problem.soil_depth, n_below,
                   BELOW_GROWTH ** (1.0 / (n_below - 1)) if n_below > 1 else 1.0)
    return pile_levels(problem, n_pile) + below[1:]


class _SolidModel:
    """What the contact and brick models share: the soil mesh, the stages, the push."""

    def __init__(self, problem, numerics, kind, m=None):
        self.p, self.n, self.kind = problem, numerics, kind
        self.m = m if m is not None else Model()
        n_theta, n_radial, n_pile, n_below = LEVELS[numerics.level]
        self.n_theta, self.n_radial, self.n_pile = n_theta, n_radial, n_pile
        self.levels = soil_levels(problem, n_pile, n_below)
        self.iface = []
        self.contacts = []

    def soil(self):
        p, m = self.p, self.m
        m.model("basic", "-ndm", 3, "-ndf", 3)
        sig0 = math.sqrt(3.0) * p.su
        m.nDMaterial("J2Plasticity", SOIL_J2, p.soil_K, p.soil_G, sig0, sig0, 0.0, 0.0)
        m.nDMaterial("InitialStateAnalysisWrapper", SOIL, SOIL_J2, 3)
        self.mesh = ogrid(m, pile_radius=p.pile_radius, outer_size=p.outer_radius, outer="circle",
                          n_theta=self.n_theta, n_radial=self.n_radial,
                          radial_ratio=(p.outer_radius / p.pile_radius) ** (1.0 / self.n_radial),
                          levels=self.levels, material_tag=SOIL, first_node=FIRST_SOIL, first_element=FIRST_SOIL,
                          body_force=(0.0, 0.0, -p.gamma), core_below=-p.length, element="bbarBrick")
        self.fixed_soil = list(fix_soil_boundary(m, self.mesh))

    def tip_surcharge(self):
        """The weight of the soil the pile replaces, gamma L, as a pressure on the soil under its
        tip (consistent nodal loads on the filled core's top face). The beam pile weighs nothing
        and does not bear on that soil, which would otherwise carry only its own weight (its
        stress 40 % off the free field's, and 7 % off beside the tip)."""
        p, m, mesh = self.p, self.m, self.mesh
        q = p.gamma * p.length
        g = 1.0 / math.sqrt(3.0)
        loads = {}
        for quad_index in mesh.plan.core_quads:
            quad = mesh.plan.quads[quad_index]
            xy = [mesh.plan.points[i] for i in quad]
            for xi, eta in ((-g, -g), (g, -g), (g, g), (-g, g)):
                N = [(1 - xi) * (1 - eta) / 4, (1 + xi) * (1 - eta) / 4, (1 + xi) * (1 + eta) / 4,
                     (1 - xi) * (1 + eta) / 4]
                dxi = [-(1 - eta) / 4, (1 - eta) / 4, (1 + eta) / 4, -(1 + eta) / 4]
                deta = [-(1 - xi) / 4, -(1 + xi) / 4, (1 + xi) / 4, (1 - xi) / 4]
                jxx = sum(d * c[0] for d, c in zip(dxi, xy))
                jxy = sum(d * c[1] for d, c in zip(dxi, xy))
                jyx = sum(d * c[0] for d, c in zip(deta, xy))
                jyy = sum(d * c[1] for d, c in zip(deta, xy))
                w = abs(jxx * jyy - jxy * jyx)
                for a, point in enumerate(quad):
                    tag = mesh.node_at[(point, self.n_pile)]
                    loads[tag] = loads.get(tag, 0.0) + q * N[a] * w
        m.timeSeries("Linear", 1)
        m.pattern("Plain", 1, 1)
        for tag, f in loads.items():
            m.load(tag, 0.0, 0.0, -f)
        return sum(loads.values())

    def analysis(self):
        m, n = self.m, self.n
        m.constraints("Transformation")
        m.numberer("RCM")
        m.system("UmfPack")
        m.test("NormDispIncr", n.tol, n.max_iter)
        m.algorithm(n.algorithm)
        m.integrator("LoadControl", 1.0 / n.steps)
        m.analysis("Static")

    def push(self, r, on_step=None):
        m, p = self.m, self.p
        m.timeSeries("Linear", TS_PUSH)
        m.pattern("Plain", PAT_PUSH, TS_PUSH)
        m.sp(self.head, 1, p.head_disp)
        self.analysis()
        self.record(r, 0)

        def step(t, iterations):
            self.record(r, iterations)
            if on_step is not None:
                on_step(self, r)

        stepper = adaptive_analyze(m, 1.0, self.n.steps, min_fraction=1.0 / 32, on_step=step)
        r.cuts, r.error = stepper.cuts, stepper.error
        if not stepper.converged and self.n.fallback and self.n.fallback != self.n.algorithm:
            # What OpenSees users do when a step fails: another algorithm from the last
            # converged state (the medium rough push stalled at 0.058 D under the line search,
            # its Newton iterations cycling; plain Newton carries it further).
            r.fallback_at = stepper.progress
            m.algorithm(self.n.fallback)
            remaining = 1.0 - stepper.progress
            stepper = adaptive_analyze(m, remaining, max(1, round(remaining * self.n.steps)),
                                       min_fraction=1.0 / 32, on_step=step)
            r.cuts += stepper.cuts
            r.error = stepper.error
        r.converged = stepper.converged
        r.n_equations = int(m.systemSize())

    def record(self, r, iterations):
        m = self.m
        r.head_disp.append(m.nodeDisp(self.head, 1))
        r.head_force.append(self.head_force())
        r.iterations.append(iterations)
        r.norms.append(list(m.testNorm()[:iterations]) if iterations else [])
        n_open, depth = 0, 0.0
        for s, e in self.contacts:
            if m.eleResponse(e, "status")[0] == 0.0:
                n_open += 1
                if m.nodeCoord(s, 1) < 0.0:
                    depth = max(depth, -m.nodeCoord(s, 3))
        r.n_open.append(n_open)
        r.gap_depth.append(depth)

    def plastic_state(self):
        """[(x, y, z, mean equivalent plastic strain, the 8 corners)] of every soil brick."""
        m, out = self.m, []
        for e in self.mesh.elements:
            xyz = [self.mesh.coords[t] for t in m.eleNodes(e)]
            xi = m.eleResponse(e, "equivalentPlasticStrains")
            out.append((*(sum(c[i] for c in xyz) / len(xyz) for i in range(3)), sum(xi) / len(xi), xyz))
        return out

    def add_pvd(self, out, name):
        import pathlib

        out = pathlib.Path(out)
        out.mkdir(parents=True, exist_ok=True)
        self.m.recorder("PVD", str(out / name))


class ContactModel(_SolidModel):
    """(a): the beam pile with BeamContact3D in the J2 soil, smooth or rough."""

    def build(self):
        p, m, n = self.p, self.m, self.n
        m.wipe()
        m.model("basic", "-ndm", 3, "-ndf", 6)
        z_pile = self.levels[:self.n_pile + 1]
        # Beam nodes at the head, the tip and half way between the soil levels, so that every
        # interior ring of contacts sits inside a segment. A soil node level with a beam node is
        # handed from segment to segment whenever it moves vertically relative to the pile (the
        # head tilts); each hand-over re-numbers the system, and the hand-over's redistribution
        # leaves an unbalance at the beam nodes that only the next step removes.
        z_beam = [z_pile[0]] + [0.5 * (a + b) for a, b in zip(z_pile, z_pile[1:])] + [z_pile[-1]]
        self.pile_nodes = list(range(1, len(z_beam) + 1))
        for tag, z in zip(self.pile_nodes, z_beam):
            m.node(tag, 0.0, 0.0, z)
        m.geomTransf("Linear", TRANSF, 1.0, 0.0, 0.0)  # local z = global x: bending about global y
        I = p.inertia
        self.beams = list(range(1, len(z_beam)))
        for e in self.beams:
            m.element("elasticBeamColumn", e, e, e + 1, p.area, p.pile_E, p.pile_G, 2.0 * I, I, I, TRANSF)
        for tag in self.pile_nodes:
            m.fix(tag, 1, 1, 1, 1, 1, 1)  # held for the gravity stage
        self.head = self.pile_nodes[0]
        self.soil()
        arc = 2.0 * math.pi * p.pile_radius / self.n_theta
        self.materials = []
        for k in range(self.n_pile + 1):
            # A node stands for its arc over half of the layers above and below it along the pile.
            h = (0.5 * (z_pile[k - 1] - z_pile[k]) if k > 0 else 0.0) + \
                (0.5 * (z_pile[k] - z_pile[k + 1]) if k < self.n_pile else 0.0)
            c = p.su * arc * h if self.kind == "rough" else 0.0
            mat = FIRST_CONTACT_MAT + k
            m.nDMaterial("ContactMaterial3D", mat, 0.0, n.contact_G, c, n.contact_tension if c > 0.0 else 0.0)
            self.materials.append(mat)
            ring = self.mesh.surfaces[0][k]
            iface = pile_interface(m, self.pile_nodes, ring, p.pile_radius, TRANSF, mat)
            self.iface.append(iface)
            self.contacts += [(s, iface.element_of[s]) for s in ring]
        return self

    def geostatic(self):
        p, m = self.p, self.m
        m.updateMaterialStage("-material", SOIL, "-stage", 0)
        self.tip_surcharge()
        state = geostatic_stage(m, soil_elements=self.mesh.elements, gamma=p.gamma, K0=p.K0,
                                contact_materials=self.materials, tol=self.n.tol, check_tol=1e-6,
                                initial_state=True)
        m.updateMaterialStage("-material", SOIL, "-stage", 1)
        # Free head: pushed along x; its vertical translation and the torsion held (nothing else
        # holds them with a smooth interface); everything else free.
        for tag in self.pile_nodes:
            for dof in range(1, 7):
                if not (tag == self.head and dof in (3, 6)):
                    m.remove("sp", tag, dof)
        return state

    def head_force(self):
        self.m.reactions()
        return self.m.nodeReaction(self.head, 1)

    def finish(self, r):
        m = self.m
        forces = [m.eleResponse(e, "localForce") for e in self.beams]
        r.z = [m.nodeCoord(t, 3) for t in self.pile_nodes]
        r.deflection = [m.nodeDisp(t, 1) for t in self.pile_nodes]
        r.moment = [f[4] for f in forces] + [-forces[-1][10]]
        total = 0.0
        ends = {self.pile_nodes[0]: 0.0, self.pile_nodes[-1]: 0.0}
        for _, e in self.contacts:
            f = m.eleResponse(e, "masterforce")
            total += f[0] + f[3]
            i, j = (int(t) for t in m.eleResponse(e, "segment"))
            for end in ends:
                if end in (i, j):  # M_y the contacts apply to an end node (adhesion at radius R)
                    ends[end] += m.eleResponse(e, "mastermoment")[1 if i == end else 4]
        r.soil_reaction = total
        r.end_moments = (ends[self.pile_nodes[0]], ends[self.pile_nodes[-1]])


class BrickModel(_SolidModel):
    """(b): the pile as elastic bricks (SSPbrick: no shear locking in bending) in the J2 soil,
    its head rigid (rigidLink 'beam' to a 6-dof head node). kind "brick": one zeroLengthContact3D
    per pair of coincident pile and soil surface nodes (dir 0: normal towards the pile axis;
    penalty Kn, adhesion c = s_u times the node's share of the surface, mu = 0), the base free;
    kind "brick_tied": every coincident pair tied (equalDOF), also under the base."""

    def build(self):
        p, m, n = self.p, self.m, self.n
        m.wipe()
        self.soil()
        m.nDMaterial("ElasticIsotropic", PILE_ELASTIC, p.pile_E, p.pile_nu)
        m.nDMaterial("InitialStateAnalysisWrapper", PILE, PILE_ELASTIC, 3)
        z_pile = self.levels[:self.n_pile + 1]
        tied = self.kind == "brick_tied"
        # Tied, the pile weighs as much as the soil it replaces (it carries the column below it);
        # in contact it is held through the gravity stage, weightless, as the beam pile.
        self.pile = solid_cylinder(m, radius=p.pile_radius, levels=z_pile, n_theta=self.n_theta, material_tag=PILE,
                                   body_force=(0.0, 0.0, -p.gamma if tied else 0.0), element="SSPbrick")
        soil_at = {tuple(round(c, 9) for c in xyz): t for t, xyz in self.mesh.coords.items()}
        self.pairs = []  # (pile node, soil node, zeroLengthContact3D tag or None)
        base = set(self.pile.groups["base"])
        ring = set(self.pile.groups["outer"])
        arc = 2.0 * math.pi * p.pile_radius / self.n_theta
        Kn = 1e3 * p.soil_E * p.pile_radius  # normal penalty per node pair (as scenes.lateral_pile_solid)
        tag = max(m.getEleTags()) + 1
        for t in self.pile.nodes:
            s = soil_at.get(tuple(round(c, 9) for c in self.pile.coords[t]))
            if s is None:
                continue
            if tied:
                m.equalDOF(t, s, 1, 2, 3)
                self.pairs.append((t, s, None))
            elif t in ring:
                k = min(range(len(z_pile)), key=lambda i: abs(z_pile[i] - self.pile.coords[t][2]))
                h = (0.5 * (z_pile[k - 1] - z_pile[k]) if k > 0 else 0.0) + \
                    (0.5 * (z_pile[k] - z_pile[k + 1]) if k < self.n_pile else 0.0)
                m.element("zeroLengthContact3D", tag, t, s, Kn, n.contact_G, 0.0, p.su * arc * h, 0)
                self.pairs.append((t, s, tag))
                self.contacts.append((s, tag))
                tag += 1
        expected = self.n_theta * self.n_pile + (len(base) if tied else self.n_theta)
        if len(self.pairs) != expected:
            raise RuntimeError(f"lateral_capacity: joined {len(self.pairs)} pile nodes to the soil, expected {expected}")
        m.model("basic", "-ndm", 3, "-ndf", 6)
        m.node(HEAD_BRICK, 0.0, 0.0, 0.0)
        for t in self.pile.groups["top"]:
            m.rigidLink("beam", HEAD_BRICK, t)
        self.head = HEAD_BRICK
        return self

    def geostatic(self):
        p, m = self.p, self.m
        m.updateMaterialStage("-material", SOIL, "-stage", 0)
        if self.kind == "brick_tied":
            # Tied, the soil hangs on the stiffer pile: the stress is reported, not checked.
            state = geostatic_stage(m, soil_elements=self.mesh.elements, gamma=p.gamma, K0=p.K0, tol=self.n.tol,
                                    initial_state=True)
            m.updateMaterialStage("-material", SOIL, "-stage", 1)
            return state
        # Contact: the pile held (its head and every pile node below it), the contacts frictionless,
        # the soil under the tip loaded by the weight of the column the pile replaces.
        elements = [e for _, _, e in self.pairs]
        held = [t for t in self.pile.nodes if t not in set(self.pile.groups["top"])]
        m.fix(self.head, 1, 1, 1, 1, 1, 1)
        for t in held:
            m.fix(t, 1, 1, 1)
        m.setParameter("-val", 0.0, "-ele", *elements, "friction")
        self.tip_surcharge()
        # Not inside InitialStateAnalysis: zeroing the displacements would zero the penalty
        # contacts' penetration, hence their force, and the soil would start off balance by its
        # horizontal stress. The soil settles by gamma H^2 / (2 M) ~ 2 mm past the held pile instead.
        # The penalty contacts yield by sigma_h A / Kn: not exactly uniaxial strain, so reported.
        state = geostatic_stage(m, soil_elements=self.mesh.elements, gamma=p.gamma, K0=p.K0, tol=self.n.tol)
        m.setParameter("-val", 1.0, "-ele", *elements, "friction")
        m.updateMaterialStage("-material", SOIL, "-stage", 1)
        for t in held:
            for d in (1, 2, 3):
                m.remove("sp", t, d)
        for d in range(1, 7):
            m.remove("sp", self.head, d)
        m.fix(self.head, 0, 0, 0, 0, 0, 1)  # the torsion held, as the beam pile's
        return state

    def head_force(self):
        """From global equilibrium along x (the weight is vertical): minus the soil supports'
        reactions (a retained node's reaction leaves out its constrained nodes)."""
        m = self.m
        m.reactions()
        return -sum(m.nodeReaction(t, 1) for t in self.fixed_soil)

    def interface_forces(self):
        """[(x, z, Fx, Fz)]: the soil's action on the pile at each joined node. Contact: minus the
        element's force on the pile (its first) node. Tied: minus the soil bricks' resisting forces
        there (at a tied pair the two sides' resisting forces balance)."""
        m = self.m
        if self.kind == "brick":
            out = []
            for t, s, e in self.pairs:
                f = m.eleResponse(e, "force")
                out.append((m.nodeCoord(t, 1), m.nodeCoord(t, 3), -f[0], -f[2]))
            return out
        tied = {s for _, s, _ in self.pairs}
        acc = {}
        for e in self.mesh.elements:
            nodes = m.eleNodes(e)
            if not tied & set(nodes):
                continue
            f = m.eleResponse(e, "forces")
            for a, t in enumerate(nodes):
                if t in tied:
                    v = acc.setdefault(t, [0.0, 0.0])
                    v[0] += f[3 * a]
                    v[1] += f[3 * a + 2]
        return [(m.nodeCoord(s, 1), m.nodeCoord(s, 3), -fx, -fz) for s, (fx, fz) in acc.items()]

    def finish(self, r):
        m = self.m
        forces = self.interface_forces()
        H = r.head_force[-1]
        z_pile = self.levels[:self.n_pile + 1]
        r.z = list(z_pile)
        r.moment = []
        for z in z_pile:
            M = H * (z_pile[0] - z)
            for x, zi, fx, fz in forces:
                if zi > z + 1e-9:
                    M += (zi - z) * fx - x * fz
            r.moment.append(M)
        r.deflection = [sum(m.nodeDisp(t, 1) for t in ring) / len(ring) for ring in self.pile.surfaces[0]]
        r.soil_reaction = sum(f[2] for f in forces)


def _run_solid(cls, kind, problem, numerics, m=None, out=None, on_step=None):
    t0, c0 = time.perf_counter(), time.process_time()
    model = cls(problem, numerics, kind, m).build()
    r = CapacityResult(model=kind, level=numerics.level, n_contacts=len(model.contacts),
                       n_elements=len(model.mesh.elements) + (len(model.pile.elements) if kind.startswith("brick")
                                                                else 0))
    t1 = time.perf_counter()
    r.geostatic = model.geostatic()
    t2 = time.perf_counter()
    if out is not None:
        model.add_pvd(out, f"lateral_capacity_{kind}")
    model.push(r, on_step)
    t3 = time.perf_counter()
    model.finish(r)
    r.plastic = model.plastic_state()
    model.m.wipe()
    r.timings = dict(build=t1 - t0, geostatic=t2 - t1, push=t3 - t2, total=time.perf_counter() - t0,
                     cpu=time.process_time() - c0)
    return r


def run_contact(problem=ClayPile(), numerics=Numerics(), interface="rough", m=None, out=None, on_step=None):
    """(a) beam + BeamContact3D, interface 'smooth' or 'rough'. `on_step(model, result)` after every step."""
    if interface not in ("smooth", "rough"):
        raise ValueError(f"lateral_capacity: interface must be 'smooth' or 'rough', got {interface!r}")
    return _run_solid(ContactModel, interface, problem, numerics, m, out, on_step)


def run_brick(problem=ClayPile(), numerics=Numerics(), interface="contact", m=None, out=None):
    """(b) the brick pile, with zeroLengthContact3D ('contact') or tied to the soil ('tied')."""
    if interface not in ("contact", "tied"):
        raise ValueError(f"lateral_capacity: brick interface must be 'contact' or 'tied', got {interface!r}")
    return _run_solid(BrickModel, "brick" if interface == "contact" else "brick_tied", problem, numerics, m, out)


def run_py(problem=ClayPile(), numerics=Numerics(), m=None):
    """(c) the beam pile on Matlock soft-clay p-y springs (2D: x horizontal, y up)."""
    from ..boundaries import Tags
    from ..springs import SoftClay, pile_springs

    p = problem
    t0, c0 = time.perf_counter(), time.process_time()
    m = m if m is not None else Model()
    n_el = PY_ELEMENTS[numerics.level]
    m.wipe()
    m.model("basic", "-ndm", 2, "-ndf", 3)
    nodes = list(range(1, n_el + 2))
    for k, tag in enumerate(nodes):
        m.node(tag, 0.0, -p.length * k / n_el)
    m.geomTransf("Linear", TRANSF)
    for e in range(1, n_el + 1):
        m.element("elasticBeamColumn", e, e, e + 1, p.area, p.pile_E, p.inertia, TRANSF)
    layer = SoftClay(0.0, p.length, su=p.su, gamma=p.gamma, eps50=p.eps50, J=p.J)
    made = pile_springs(m, Tags(node=10001, element=10001, material=10001), nodes, p.diameter, [layer],
                        axial=False, tip=False)
    head = nodes[0]
    m.fix(head, 0, 1, 0)  # the vertical dof (no t-z springs)
    m.timeSeries("Linear", TS_PUSH)
    m.pattern("Plain", PAT_PUSH, TS_PUSH)
    m.sp(head, 1, p.head_disp)
    m.constraints("Transformation")
    m.numberer("RCM")
    m.system("UmfPack")
    m.test("NormDispIncr", numerics.tol, numerics.max_iter)
    m.algorithm("Newton")
    m.integrator("LoadControl", 1.0 / numerics.steps)
    m.analysis("Static")
    r = CapacityResult(model="py", level=numerics.level, n_elements=n_el)

    def record(iterations):
        m.reactions()
        r.head_disp.append(m.nodeDisp(head, 1))
        r.head_force.append(m.nodeReaction(head, 1))
        r.iterations.append(iterations)
        r.norms.append(list(m.testNorm()[:iterations]) if iterations else [])

    record(0)
    stepper = adaptive_analyze(m, 1.0, numerics.steps, min_fraction=1.0 / 32, on_step=lambda t, it: record(it))
    r.converged, r.cuts, r.error = stepper.converged, stepper.cuts, stepper.error
    r.n_equations = int(m.systemSize())
    forces = [m.eleResponse(e, "localForce") for e in range(1, n_el + 1)]
    r.z = [m.nodeCoord(t, 2) for t in nodes]
    r.deflection = [m.nodeDisp(t, 1) for t in nodes]
    # 2D localForce: N1 V1 M1 N2 V2 M2 (local x down the pile); M at a section from the end forces,
    # signed as the 3D models' (positive below a head pushed along +x).
    r.moment = [-f[2] for f in forces] + [forces[-1][5]]
    r.soil_reaction = sum(m.eleResponse(row["element"], "force")[0] for row in made.rows)
    m.wipe()
    r.timings = dict(total=time.perf_counter() - t0, cpu=time.process_time() - c0)
    return r


def run(model, problem=ClayPile(), numerics=Numerics(), out=None):
    """One model by name: 'rough', 'smooth', 'brick' or 'py'."""
    if model in ("rough", "smooth"):
        return run_contact(problem, numerics, model, out=out)
    if model in ("brick", "brick_tied"):
        return run_brick(problem, numerics, "contact" if model == "brick" else "tied", out=out)
    if model == "py":
        return run_py(problem, numerics)
    raise ValueError(f"lateral_capacity: model must be one of {sorted(MODELS)}, got {model!r}")


# =====================================================================================
# The scene: python -m beamsolid.scenes lateral_capacity --level coarse|medium|fine
# =====================================================================================
def _plots(out, results, problem, closed):
    """PNG plots: head load-displacement and bending-moment profiles; returns the files."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    files = []
    D = problem.diameter
    styles = {"rough": "o-", "smooth": "s-", "brick": "^-", "brick_tied": "v--", "py": "D-"}
    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    for key, r in results.items():
        ax.plot([u / D for u in r.head_disp], r.head_force, styles[key], ms=3, label=MODELS[key])
    ax.axhline(closed.H, color="k", ls="--", lw=1, label=f"Broms (1964), short pile: {closed.H:.0f} kN")
    ax.set_xlabel("head displacement / D")
    ax.set_ylabel("head load H (kN)")
    ax.set_title(f"Free-head pile in clay (s_u = {problem.su:g} kPa): load-displacement")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    files.append(out / "load_displacement.png")
    fig.savefig(files[-1], dpi=120)
    plt.close(fig)

    fig, (a1, a2) = plt.subplots(1, 2, figsize=(7.6, 5.2), sharey=True)
    for key, r in results.items():
        a1.plot([1e3 * u for u in r.deflection], r.z, styles[key], ms=3, label=MODELS[key])
        a2.plot(r.moment, r.z, styles[key], ms=3, label=key)
    a2.axvline(closed.M_short, color="k", ls="--", lw=1, label=f"Broms M_max {closed.M_short:.0f} kNm")
    a1.set_xlabel("deflection u_x (mm)")
    a1.set_ylabel("z (m)")
    a2.set_xlabel("bending moment M_y (kNm)")
    for a in (a1, a2):
        a.grid(alpha=0.3)
        a.axvline(0.0, color="k", lw=0.5)
    a1.legend(fontsize=7)
    a2.legend(fontsize=7)
    fig.suptitle(f"Pile profiles at head displacement {problem.head_disp / D:.2f} D")
    fig.tight_layout()
    files.append(out / "profiles.png")
    fig.savefig(files[-1], dpi=120)
    plt.close(fig)

    solid = [k for k in ("rough", "brick_tied") if k in results and results[k].plastic]
    if solid:
        from matplotlib.collections import PolyCollection

        fig, axes = plt.subplots(2, len(solid), figsize=(5.4 * len(solid), 7.6), squeeze=False)
        for col, key in enumerate(solid):
            cells = results[key].plastic
            vmax = max(c[3] for c in cells) or 1.0
            top = max(c[2] for c in cells)
            # The vertical section through the axis along the push: the bricks astride y = 0 (drawn
            # over their x-z extent); and the top layer (each brick's top face in plan).
            section = [c for c in cells if min(p[1] for p in c[4]) < 0.0 < max(p[1] for p in c[4])]
            polys_s = [[(min(p[0] for p in c[4]), min(p[2] for p in c[4])), (max(p[0] for p in c[4]),
                        min(p[2] for p in c[4])), (max(p[0] for p in c[4]), max(p[2] for p in c[4])),
                        (min(p[0] for p in c[4]), max(p[2] for p in c[4]))] for c in section]
            surface = [c for c in cells if abs(c[2] - top) < 1e-9]
            polys_t = [[(p[0], p[1]) for p in c[4][4:]] for c in surface]  # the top face: nodes 5-8
            for ax, polys, pts, ylabel, title in ((axes[0][col], polys_s, section, "z (m)", "section y = 0"),
                                                  (axes[1][col], polys_t, surface, "y (m)", "top layer, plan")):
                coll = PolyCollection(polys, array=[c[3] for c in pts], cmap="magma_r", edgecolors="0.7",
                                      linewidths=0.2)
                coll.set_clim(0.0, vmax)
                ax.add_collection(coll)
                ax.autoscale_view()
                ax.set_aspect("equal")
                ax.set_title(f"{MODELS[key]}: {title}", fontsize=8)
                ax.set_xlabel("x (m)")
                ax.set_ylabel(ylabel)
                fig.colorbar(coll, ax=ax, shrink=0.8, label="equivalent plastic strain")
        fig.suptitle(f"Plastic zone at head displacement {problem.head_disp / D:.2f} D (brick means)", fontsize=10)
        fig.tight_layout()
        files.append(out / "plastic_zone.png")
        fig.savefig(files[-1], dpi=110)
        plt.close(fig)
    return files


def summary_rows(results, problem, closed):
    """(name, H at 0.1 D, H at the end, H / Broms, M_max, steps, iterations, equations, wall) per model."""
    rows = []
    for key, r in results.items():
        rows.append(dict(model=key, name=MODELS[key], H_01D=r.force_at(0.1 * problem.diameter), H_end=r.capacity,
                         ratio=r.capacity / closed.H, M_max=r.max_moment, steps=len(r.iterations) - 1,
                         iterations=sum(r.iterations), equations=r.n_equations, wall=r.wall,
                         gap_depth=r.gap_depth[-1] if r.gap_depth else 0.0, converged=r.converged,
                         equilibrium=abs(r.capacity + r.soil_reaction) / abs(r.capacity)))
    return rows


def scene(level="coarse", out="lateral_capacity_output", steps=None, problem=ClayPile()):
    """Run the four models at `level`; print the summary table, write the PVD series of the two
    contact models and the brick model (plastic strain on the soil), plot the curves and the
    profiles. Returns (results by model, Broms, files written)."""
    import pathlib

    out = pathlib.Path(out)
    out.mkdir(parents=True, exist_ok=True)
    t0 = time.perf_counter()
    numerics = Numerics(level=level, **({} if steps is None else {"steps": steps}))
    closed = broms(problem)
    results = {}
    for key in MODELS:
        results[key] = run(key, problem, numerics, out=None if key == "py" else out)
        r = results[key]
        print(f"  {MODELS[key]:40s} {'ok' if r.converged else 'STOPPED'}: H = {r.capacity:7.1f} kN at "
              f"{r.head_disp[-1] / problem.diameter:.3f} D, {r.wall:6.1f} s", flush=True)

    n_theta, n_radial, n_pile, n_below = LEVELS[level]
    print(f"\nlateral_capacity ({level}: soil O-grid {n_theta} x {n_radial} x {n_pile}+{n_below} bbarBricks, "
          f"p-y beam of {PY_ELEMENTS[level]} elements); units kN, m, kPa")
    print(f"  pile D = {problem.diameter:g}, L = {problem.length:g}, E = {problem.pile_E:.3g} (elastic); clay s_u = "
          f"{problem.su:g}, E = {problem.soil_E:.3g}, nu = {problem.nu:g}, gamma = {problem.gamma:g}; Matlock eps50 = "
          f"{problem.eps50:g}, J = {problem.J:g}")
    print(f"  Broms (1964), short free-head pile: H_u = {closed.H_short:.1f} kN, M_max = {closed.M_short:.1f} kNm "
          f"(the pile stays elastic: short-pile mode)")
    print(f"\n{'model':42s}{'H(0.1D)':>9s}{'H(end)':>9s}{'/Broms':>8s}{'M_max':>9s}{'gap m':>7s}{'steps':>7s}"
          f"{'iters':>7s}{'eqs':>8s}{'wall s':>8s}")
    rows = summary_rows(results, problem, closed)
    for row in rows:
        print(f"{row['name']:42s}{row['H_01D']:9.1f}{row['H_end']:9.1f}{row['ratio']:8.3f}{row['M_max']:9.1f}"
              f"{row['gap_depth']:7.2f}{row['steps']:7d}{row['iterations']:7d}{row['equations']:8d}{row['wall']:8.1f}")
    print(f"{'Broms (1964)':42s}{'':9s}{closed.H:9.1f}{1.0:8.3f}{closed.M_short:9.1f}")
    files = [out / f"lateral_capacity_{k}.pvd" for k in MODELS if k != "py"]
    try:
        files += _plots(out, results, problem, closed)
    except ImportError:
        print("matplotlib not installed: no plots")
    print(f"\nwrote {', '.join(f.name for f in files)} in {out}; wall time {time.perf_counter() - t0:.1f} s")
    return results, closed, files

"""The donut pullout test of Arduino, Petek & Mackenzie-Helnwein (2007), Table 1.

A pile of elastic beam elements is pulled up through a ring ("donut") of
elastic stdBrick soil that confines it by its own weight. Units: kN, m, kPa.

Geometry (defaults): pile radius R = 0.5 m (B = 1 m); soil annulus from R to
R_out = 5 m, ground surface z = 0, base z = -D = -10 m; an O-grid of
n_theta x n_radial x n_z bricks (radial spacing graded towards the pile) whose
inner nodes lie on the pile circle. The pile's beam nodes sit half a soil layer
off the soil node levels (z = h/2, -h/2, ..., -D - h/2 with h = D/n_z), so that
every pile-surface soil node projects onto the middle of a segment and stays
inside it while the pile moves by less than h/2. One BeamContact3D (or
BeamContact3Dp) per pile-surface soil node.

Stage 1, geostatic (uniaxial strain): soil self weight as stdBrick body forces
b3 = -gamma (force per unit volume); outer nodes fixed in x and y, base nodes
fixed in z, the pile fixed, the contacts frictionless (updateMaterialStage
stage 0). The exact state is sigma_v = gamma d, sigma_h = K0 sigma_v with
K0 = nu / (1 - nu) at depth d; the pile is confined by sigma_h(z).

Stage 2, pullout: loadConst('-time', 0), friction on (stage 1), the pile
released vertically (x, y and its rotations stay fixed: the problem is
axisymmetric), and the head pulled up by an imposed displacement until no
contact sticks: every contact slides, except those near the ground surface that
the drag of the pull has opened (their normal force went tensile). The head
force Q then equals the summed friction mu sum(N_i).

Reference values:
    beta method       Qs = pi B integral_0^D mu sigma_h dz = pi B mu K0 gamma D^2 / 2
    faceted ring      sum N_i = n R sin(2 pi / n) integral_0^D sigma_h dz  (geostatic, exact)
    facet factor      n sin(2 pi / n) / (2 pi)   (0.9745 for n = 16)
"""
import math
import time
from dataclasses import dataclass, field

from ..geostatic import geostatic_stage
from ..mesh import donut
from ..model import Model

# Table 1 of the paper: (mu, G, Q_contact, Q_s beta method).
PAPER_TABLE1 = [(0.1, 1000.0, 141.0, 135.0), (0.25, 1000.0, 344.0, 335.0), (0.5, 1000.0, 666.0, 670.0),
                (1.0, 1000.0, 1240.0, 1320.0)]

SOIL, CONTACT = 1, 2  # material tags
TRANSF = 1
FIRST_SOIL_NODE = 1001
FIRST_CONTACT = 200001  # element tags; multiplier node tags alike


@dataclass(frozen=True)
class DonutPullout:
    """Parameters of one donut pullout run (kN, m)."""

    mu: float = 0.5
    G: float = 1000.0  # contact stick stiffness: kN per m of slip, per contact node
    pile_radius: float = 0.5
    outer_radius: float = 5.0
    depth: float = 10.0
    gamma: float = 20.0  # soil unit weight, kN/m^3
    soil_E: float = 20e3
    soil_nu: float = 0.3
    pile_E: float = 30e6
    pile_G: float = 12.5e6
    n_theta: int = 16
    n_radial: int = 4
    n_z: int = 10
    radial_ratio: float = 1.5
    pull: float = None  # final head displacement (up); None: past full sliding (head_pull)
    twist: float = 0.0  # final head rotation about the pile axis (rad)
    steps: int = 12
    contact: str = "BeamContact3D"  # or "BeamContact3Dp"
    penalty: float = 1e6  # BeamContact3Dp only, kN/m
    tol: float = 1e-8  # NormUnbalance tolerance, kN
    max_iter: int = 25

    # --- closed forms -------------------------------------------------------
    @property
    def K0(self):
        """Earth pressure coefficient at rest of a laterally restrained elastic soil."""
        return self.soil_nu / (1.0 - self.soil_nu)

    @property
    def head_pull(self):
        """The pull, by default 0.04 mu + 0.004 on the paper's ring (past full sliding there). A node
        slides once its slip reaches mu N / G, so a ring whose deepest node carries more normal
        force per unit G (fewer facets, thicker layers) is pulled proportionally further."""
        if self.pull is not None:
            return self.pull
        return (0.04 * self.mu + 0.004) * max(1.0, self.deepest_slip_scale / PAPER_SLIP_SCALE)

    @property
    def deepest_slip_scale(self):
        """N / G of the deepest ring's contacts at geostatic rest (m): sigma_h(D) R sin(2 pi/n) h / G."""
        return self.sigma_h(self.depth) * self.pile_radius * math.sin(2.0 * math.pi / self.n_theta) * self.layer / self.G

    @property
    def layer(self):
        return self.depth / self.n_z

    def sigma_h(self, depth):
        return self.K0 * self.gamma * depth

    @property
    def sigma_h_integral(self):
        """integral_0^D sigma_h dz (kN/m)."""
        return 0.5 * self.K0 * self.gamma * self.depth**2

    @property
    def beta_method(self):
        """Qs = pi B integral(mu sigma_h dz): the paper's beta-method column."""
        return math.pi * 2.0 * self.pile_radius * self.mu * self.sigma_h_integral

    @property
    def facet_factor(self):
        """Perimeter share of the inscribed n-gon's consistent normal forces: n sin(2 pi/n) / (2 pi)."""
        n = self.n_theta
        return n * math.sin(2.0 * math.pi / n) / (2.0 * math.pi)

    @property
    def faceted_normal_sum(self):
        """Exact geostatic sum of the contact normal forces for the faceted ring."""
        n = self.n_theta
        return n * self.pile_radius * math.sin(2.0 * math.pi / n) * self.sigma_h_integral


@dataclass
class PulloutResult:
    setup: DonutPullout
    geostatic_normal_sum: float = 0.0
    head_disp: list = field(default_factory=list)  # per step (0 at the start)
    head_rotation: list = field(default_factory=list)
    head_force: list = field(default_factory=list)  # support reaction at the head, up +
    head_moment: list = field(default_factory=list)  # about the pile axis
    friction_sum: list = field(default_factory=list)  # summed vertical friction on the soil nodes, up +
    normal_sum: list = field(default_factory=list)  # summed contact normal forces N_i
    sticking: list = field(default_factory=list)  # number of sticking contacts
    sliding: list = field(default_factory=list)  # number of sliding contacts
    iterations: list = field(default_factory=list)  # Newton iterations per pullout step
    step_time: list = field(default_factory=list)  # seconds per pullout step (analyze only), wall
    step_cpu: list = field(default_factory=list)  # the same, CPU time of the process
    n_contacts: int = 0
    geostatic_time: float = 0.0
    pullout_time: float = 0.0
    failed_step: int = 0  # 0 when every step converged

    @property
    def full_sliding(self):
        """Index of the first state in which no contact sticks and some slide (None if never):
        every contact slides or has opened."""
        for k, (stick, slide) in enumerate(zip(self.sticking, self.sliding)):
            if stick == 0 and slide > 0:
                return k
        return None

    @property
    def open(self):
        """Number of open (separated) contacts at the end."""
        return self.n_contacts - self.sticking[-1] - self.sliding[-1]

    @property
    def q_contact(self):
        """Maximum frictional resistance: the largest head force."""
        return max(self.head_force)

    @property
    def unloading(self):
        """sum N at the end (full sliding) / geostatic sum N."""
        return self.normal_sum[-1] / self.geostatic_normal_sum

    @property
    def sliding_resistance(self):
        """What Q must be once every contact slides, gate (c): Qs x facet factor x unloading."""
        return self.setup.beta_method * self.setup.facet_factor * self.unloading


# The paper's ring (the defaults), for which the default pull was chosen.
PAPER_SLIP_SCALE = DonutPullout().deepest_slip_scale


def _static(m, s, dt):
    m.constraints("Transformation")
    m.numberer("RCM")
    m.system("UmfPack")
    m.test("NormUnbalance", s.tol, s.max_iter)
    m.algorithm("Newton")
    m.integrator("LoadControl", dt)
    m.analysis("Static")


class DonutModel:
    """Builds the donut pullout model in `m` (a beamsolid.Model) and runs its stages."""

    def __init__(self, setup, m=None):
        self.s = setup
        self.m = m if m is not None else Model()
        self.pile_nodes = []
        self.contacts = []
        self.mesh = None

    def build(self):
        s, m = self.s, self.m
        m.wipe()
        self.pile_nodes, self.contacts = [], []
        h = s.layer
        R = s.pile_radius
        m.model("basic", "-ndm", 3, "-ndf", 6)
        for k in range(s.n_z + 2):
            m.node(1 + k, 0.0, 0.0, 0.5 * h - k * h)
            m.fix(1 + k, 1, 1, 1, 1, 1, 1)
            self.pile_nodes.append(1 + k)
        m.geomTransf("Linear", TRANSF, 1.0, 0.0, 0.0)
        A, I = math.pi * R**2, math.pi * R**4 / 4.0
        for k in range(s.n_z + 1):
            m.element("elasticBeamColumn", 1 + k, 1 + k, 2 + k, A, s.pile_E, s.pile_G, 2.0 * I, I, I, TRANSF)

        m.model("basic", "-ndm", 3, "-ndf", 3)
        m.nDMaterial("ElasticIsotropic", SOIL, s.soil_E, s.soil_nu)
        self.mesh = mesh = donut(m, inner_radius=R, outer_radius=s.outer_radius, z_top=0.0, z_bottom=-s.depth,
                                 n_theta=s.n_theta, n_radial=s.n_radial, n_z=s.n_z, radial_ratio=s.radial_ratio,
                                 material_tag=SOIL, first_node=FIRST_SOIL_NODE, first_element=FIRST_SOIL_NODE,
                                 body_force=(0.0, 0.0, -s.gamma))
        flags = {}
        for n in mesh.outer_nodes:
            flags.setdefault(n, [0, 0, 0])[:2] = [1, 1]
        for n in mesh.base_nodes:
            flags.setdefault(n, [0, 0, 0])[2] = 1
        for n, f in flags.items():
            m.fix(n, *f)

        m.nDMaterial("ContactMaterial3D", CONTACT, s.mu, s.G, 0.0, 0.0)
        tag = FIRST_CONTACT
        for k in range(s.n_z + 1):  # level k (z = -k h) lies in segment (pile node k+1, k+2)
            for i in range(s.n_theta):
                soil = mesh.nodes[(i, 0, k)]
                if s.contact == "BeamContact3D":
                    m.node(tag, *m.nodeCoord(soil))
                    m.element("BeamContact3D", tag, 1 + k, 2 + k, soil, tag, R, TRANSF, CONTACT, 1e-8, 1e-8)
                else:
                    m.element("BeamContact3Dp", tag, 1 + k, 2 + k, soil, R, TRANSF, CONTACT, s.penalty)
                self.contacts.append(tag)
                tag += 1
        return self

    # --- queries --------------------------------------------------------------
    def contact_scalars(self):
        """[(N, T_axial, T_circumferential)] of every contact (forces on the soil nodes)."""
        return [self.m.eleResponse(t, "physicalForceScalar") for t in self.contacts]

    def normal_sum(self):
        return sum(f[0] for f in self.contact_scalars())

    def status_counts(self):
        """(sticking, sliding) contacts of the last update."""
        status = [self.m.eleResponse(t, "status")[0] for t in self.contacts]
        return status.count(1.0), status.count(2.0)

    # --- stages ---------------------------------------------------------------
    def geostatic(self):
        """Stage 1: self weight with frictionless contacts and a fixed pile; returns sum N.

        geostatic_stage checks sigma_v = gamma d and sigma_h = K0 sigma_v in every brick,
        then loadConst('-time', 0) and the contacts get their friction back."""
        s, m = self.s, self.m
        self.geostatic_state = geostatic_stage(m, soil_elements=self.mesh.elements, gamma=s.gamma, K0=s.K0,
                                               contact_materials=[CONTACT], tol=s.tol, max_iter=s.max_iter,
                                               # Exact only with multipliers: a penalty interface lets the
                                               # soil into the pile by sigma_h A / penalty.
                                               check_tol=1e-8 if s.contact == "BeamContact3D" else None)
        return self.normal_sum()

    def release(self):
        """Stage 2 set-up: pile free along (and about) its axis, head motion imposed."""
        s, m = self.s, self.m
        head = self.pile_nodes[0]
        for n in self.pile_nodes:
            m.remove("sp", n, 3)
            if s.twist != 0.0:
                m.remove("sp", n, 6)
        m.timeSeries("Linear", 2)
        m.pattern("Plain", 2, 2)
        m.sp(head, 3, s.head_pull)
        if s.twist != 0.0:
            m.sp(head, 6, s.twist)
        # Symmetry keeps the pile on its axis; x, y, rx, ry stay fixed.
        _static(m, s, 1.0 / s.steps)

    def record(self, r):
        m, head = self.m, self.pile_nodes[0]
        m.reactions()
        scalars = self.contact_scalars()
        r.head_disp.append(m.nodeDisp(head, 3))
        r.head_rotation.append(m.nodeDisp(head, 6))
        r.head_force.append(m.nodeReaction(head, 3))
        r.head_moment.append(m.nodeReaction(head, 6))
        r.friction_sum.append(sum(m.eleResponse(t, "soilFrictionForce")[2] for t in self.contacts))
        r.normal_sum.append(sum(f[0] for f in scalars))
        stick, slide = self.status_counts()
        r.sticking.append(stick)
        r.sliding.append(slide)

    def pull(self, r, extra_after_full_sliding=None):
        """Pull for setup.steps steps; with extra_after_full_sliding = k, stop k steps
        after the first step at full sliding."""
        full = None
        for step in range(self.s.steps):
            t0, c0 = time.perf_counter(), time.process_time()
            ok = self.m.analyze(1)
            r.step_time.append(time.perf_counter() - t0)
            r.step_cpu.append(time.process_time() - c0)
            if ok != 0:
                r.failed_step = step + 1
                break
            r.iterations.append(self.m.testIter())
            self.record(r)
            if full is None:
                full = r.full_sliding
            if extra_after_full_sliding is not None and full is not None and \
                    len(r.head_force) - 1 - full >= extra_after_full_sliding:
                break
        return r


def run(setup, extra_after_full_sliding=None, m=None):
    """Both stages of one donut pullout; the result holds the curves and sums.

    With extra_after_full_sliding = k the pull stops k steps after full sliding."""
    model = DonutModel(setup, m).build()
    r = PulloutResult(setup=setup, n_contacts=len(model.contacts))
    t0 = time.perf_counter()
    r.geostatic_normal_sum = model.geostatic()
    t1 = time.perf_counter()
    model.release()
    model.record(r)
    model.pull(r, extra_after_full_sliding)
    r.geostatic_time, r.pullout_time = t1 - t0, time.perf_counter() - t1
    model.m.wipe()
    return r


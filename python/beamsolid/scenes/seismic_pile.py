"""A pile in an elastic soil layer on rigid bedrock, shaken at the base (issue 16).

This module holds the physical problem shared by the scene, the accuracy-versus-cost benchmark
and the tests: the parameters, the mesh levels, the model and its run. Units: kN, m, s, t.

Problem: a solid circular concrete pile of radius R through a soil layer of depth H, head at
the ground surface (z = 0), tip pinned on rigid bedrock (z = -H). The soil is a square box of
half-width W, elastic (E, nu, unit weight gamma, density gamma / g). The box's lateral sides are
tied periodically (a node on x = +W moves with its image on x = -W at the same y and z, likewise
in y), so the box is one cell of an infinite row of piles and, without a pile, every soil
column moves like the free field (the 1D shear column). The base is fixed: the record shakes it
along x through pattern('UniformExcitation'), so displacements, velocities and accelerations
are relative to the bedrock.

Stages: gravity (geostatic stress under uniaxial strain, pile held, contacts frictionless, then
InitialStateAnalysis off and loadConst), release of the pile (tip pinned, head torsion held),
then Transient with Newmark average acceleration (gamma = 1/2, beta = 1/4) and Rayleigh damping
of ratio zeta at the first two natural frequencies of the soil column,
    omega_n = (2 n - 1) pi Vs / (2 H),   Vs = sqrt(G / rho)   (n = 1, 2),
    alphaM = 2 zeta omega_1 omega_2 / (omega_1 + omega_2),  betaK = 2 zeta / (omega_1 + omega_2).
Interfaces: 'contact' (BeamContact3D with Lagrange multipliers, Coulomb friction mu: gapping and
sliding), 'tied' (every pile-surface soil node rigidLink'ed to its pile node), 'py' (no soil box:
the beam pile on p-y springs, PySimple1 after Matlock's soft clay from the undrained strength
su, whose far ends move with the free field: the 1D shear column's relative displacement at each
pile node's depth, imposed by sp in a Plain pattern under the same UniformExcitation), or 'none'
(no pile: the free-field box).
"""
import math
import pathlib
import time
from dataclasses import dataclass, field

import numpy as np

from ..contact import pile_interface
from ..geostatic import geostatic_stage
from ..groundmotion import read_record
from ..mesh import graded, ogrid
from ..model import Model
from ..springs import SoftClay, pile_springs
from ..boundaries import Tags
from .circular_pile import CircularPile

RECORD = str(pathlib.Path(__file__).resolve().parents[3] / "examples" / "records" / "synthetic_kt_seed16.acc")

# Mesh levels: (n_theta, n_radial, n_z) of the square soil O-grid; uniform layers so that
# every level resolves the same wavelengths alike (coarse: 1.25 m, 8 per wavelength at 10 Hz).
LEVELS = {
    "coarse": (8, 2, 8),
    "medium": (12, 3, 12),
    "fine": (16, 4, 16),
}
# The scene's time step per level: the contact's impacts must be resolved, the finer the mesh the
# smaller the step (benchmarks/results/seismic_pile_accuracy.md: at the default motion the contact
# run stops at medium with 0.01 s and at fine with 0.005 s, and reaches the end with these).
SCENE_DT = {"coarse": 0.01, "medium": 0.005, "fine": 0.0025}

SOIL, CONTACT, SOIL_ELASTIC = 1, 2, 3  # material tags (SOIL wraps SOIL_ELASTIC)
TRANSF = 1
TS_MOTION, PAT_MOTION = 10, 10
FIRST_SOIL_NODE = 1001
FIRST_CONTACT = 200001  # element tags; multiplier node tags alike
PY_FIRST = 300001  # p-y spring nodes, elements and materials


@dataclass(frozen=True)
class SeismicPile(CircularPile):
    """The physical problem (kN, m, s, t)."""

    pile_radius: float = 0.4
    depth: float = 10.0  # soil layer depth H = pile length
    half_width: float = 6.0  # soil box half-width W (15 pile radii)
    pile_E: float = 30e6
    pile_nu: float = 0.2
    pile_density: float = 2.5  # t/m^3
    head_mass: float = 0.0  # t, a lumped mass at the pile head (a superstructure), none by default
    soil_E: float = 50e3
    soil_nu: float = 0.3
    gamma: float = 19.0  # kN/m^3
    g: float = 9.81
    mu: float = 0.5
    damping: float = 0.03  # Rayleigh damping ratio at the soil column's first two modes
    record: str = RECORD  # one value per line, in g; its dt in record + '.json'
    # Factor on the record (its PGA is 0.3 g) and the seconds of it run. PGA 0.015 g for 3 s opens
    # the first gaps near the surface and ends before the contact chatters (coarse stops at 3.16 s,
    # PGA 0.3 g at about 1.3 s: Numerics.overlap_limit).
    scale: float = 0.05
    duration: float = 3.0
    # The p-y model only (interface 'py'): Matlock (1970) soft-clay curves from the undrained
    # strength su (E / su = 500 for the soil above) and eps50, with PySimple1's drag Cd. The
    # soil box stays elastic: at the default motion its free-field shear stress stays far below su.
    su: float = 100.0
    eps50: float = 0.005
    py_drag: float = 0.3

    @property
    def soil_rho(self):
        return self.gamma / self.g

    @property
    def soil_G(self):
        return self.soil_E / (2.0 * (1.0 + self.soil_nu))

    @property
    def Vs(self):
        return math.sqrt(self.soil_G / self.soil_rho)

    @property
    def K0(self):
        return self.soil_nu / (1.0 - self.soil_nu)

    def column_omega(self, n):
        """Circular frequency of the n-th shear mode of the soil layer on rigid bedrock (rad/s)."""
        return (2 * n - 1) * math.pi * self.Vs / (2.0 * self.depth)

    @property
    def rayleigh(self):
        """(alphaM, betaK) giving the damping ratio at the column's first two modes."""
        w1, w2 = self.column_omega(1), self.column_omega(2)
        return 2.0 * self.damping * w1 * w2 / (w1 + w2), 2.0 * self.damping / (w1 + w2)


@dataclass(frozen=True)
class Numerics:
    level: str = "coarse"
    interface: str = "contact"  # "contact" | "penalty" (BeamContact3Dp) | "tied" | "py" | "none" (the soil box alone)
    gap_tol: float = 1e-8  # BeamContact3D gapTol (m): a released node closes again below it
    force_tol: float = 1e-8  # BeamContact3D forceTol (kN): a node is released when lambda <= -forceTol
    penalty_factor: float = 1e3  # "penalty": penalty = penalty_factor * E_soil * R (kN/m per contact node)
    dt: float = 0.01  # time step (s)
    contact_G: float = 1e5  # stick stiffness of ContactMaterial3D (kN/m per contact node)
    tol: float = 1e-6  # NormUnbalance (kN)
    max_iter: int = 25
    pvd_dt: float = 0.05  # PVD frames every pvd_dt seconds (when recording)
    # Stop when a released (open) soil node lies this far inside the pile (fraction of R): the
    # status lags a step (C20), so under shaking an open node can sink into the pile, and its
    # re-closure kicks it out again; past this the contact chatters without bound (docs).
    overlap_limit: float = 0.01

    def __post_init__(self):
        if self.level not in LEVELS:
            raise ValueError(f"seismic_pile: level must be one of {sorted(LEVELS)}, got {self.level!r}")
        if self.interface not in ("contact", "penalty", "tied", "py", "none"):
            raise ValueError("seismic_pile: interface must be 'contact', 'penalty', 'tied', 'py' or 'none', "
                             f"got {self.interface!r}")
        if not self.dt > 0:
            raise ValueError(f"seismic_pile: dt must be positive, got {self.dt}")


@dataclass
class SeismicResult:
    """Histories (one entry per converged step, the first the state after gravity) and envelopes."""

    problem: SeismicPile
    numerics: Numerics
    time: list = field(default_factory=list)
    ground_accel: list = field(default_factory=list)  # m/s^2 along x
    head_disp: list = field(default_factory=list)  # relative to the bedrock, m
    head_accel: list = field(default_factory=list)  # absolute, m/s^2
    surface_accel: list = field(default_factory=list)  # absolute, at the surface node nearest the box centre
    surface_disp: list = field(default_factory=list)
    max_gap: list = field(default_factory=list)  # largest gap of an open contact (m), 0 when all closed
    n_open: list = field(default_factory=list)
    n_sliding: list = field(default_factory=list)
    max_overlap: list = field(default_factory=list)  # deepest open node inside the pile (m)
    iterations: list = field(default_factory=list)
    z: list = field(default_factory=list)  # pile node elevations, head first
    moment_envelope: list = field(default_factory=list)  # max over time of |M_y| at the pile nodes (kNm)
    converged: bool = False
    failed_at: float = None
    stop_reason: str = None
    n_equations: int = 0
    n_contacts: int = 0
    n_springs: int = 0  # p-y spring elements (interface 'py')
    timings: dict = field(default_factory=dict)

    @property
    def peak_head_disp(self):
        return max(abs(u) for u in self.head_disp)

    @property
    def peak_gap(self):
        return max(self.max_gap) if self.max_gap else 0.0


def periodic_ties(m, mesh_coords, half_width, z_base, centre=(0.0, 0.0)):
    """equalDOF (1, 2, 3) of every node on x = cx + W to its image on x = cx - W, and on y = cy + W
    to y = cy - W, at the same height; the corner lines go to the (-W, -W) corner, so no retained
    node is itself constrained. Nodes at the fixed base are left alone. Returns the pairs."""
    tol = 1e-9 * half_width
    by_position = {}
    for tag, (x, y, z) in mesh_coords.items():
        by_position[(round((x - centre[0]) / tol), round((y - centre[1]) / tol), round(z / tol))] = tag
    pairs = []
    for tag, (x, y, z) in sorted(mesh_coords.items()):
        if abs(z - z_base) <= tol:
            continue
        ix = -half_width if abs(x - centre[0] - half_width) <= tol else x - centre[0]
        iy = -half_width if abs(y - centre[1] - half_width) <= tol else y - centre[1]
        if (ix, iy) == (x - centre[0], y - centre[1]):
            continue
        image = by_position.get((round(ix / tol), round(iy / tol), round(z / tol)))
        if image is None:
            raise ValueError(f"periodic_ties: node {tag} at ({x}, {y}, {z}) has no image on the opposite side")
        m.equalDOF(image, tag, 1, 2, 3)
        pairs.append((image, tag))
    return pairs


def layer_levels(problem, n_z):
    return graded(0.0, -problem.depth, n_z)


class SeismicPileModel:
    """Builds the model in `m` (a beamsolid.Model) and runs its stages."""

    def __init__(self, problem=SeismicPile(), numerics=Numerics(), m=None):
        self.p, self.n = problem, numerics
        self.m = m if m is not None else Model()
        self.pile_nodes, self.beams, self.iface, self.mesh = [], [], None, None
        self.contact_soil, self.base_nodes, self.ties = [], [], []
        self.springs, self.free_field = None, None

    @property
    def soil_box(self):
        return self.n.interface != "py"

    def build(self):
        p, n, m = self.p, self.n, self.m
        n_theta, n_radial, n_z = LEVELS[n.level]
        levels = layer_levels(p, n_z)
        m.wipe()
        with_pile = n.interface != "none"
        if with_pile:
            m.model("basic", "-ndm", 3, "-ndf", 6)
            self.pile_nodes = list(range(1, n_z + 2))
            for tag, z in zip(self.pile_nodes, levels):
                m.node(tag, 0.0, 0.0, z)
            if p.head_mass > 0.0:
                m.mass(self.pile_nodes[0], p.head_mass, p.head_mass, p.head_mass, 0.0, 0.0, 0.0)
            m.geomTransf("Linear", TRANSF, 1.0, 0.0, 0.0)  # local z = global x: shaking bends about y
            I = p.inertia
            self.beams = list(range(1, n_z + 1))
            for e in self.beams:
                m.element("elasticBeamColumn", e, e, e + 1, p.area, p.pile_E, p.pile_G, 2.0 * I, I, I, TRANSF,
                          "-mass", p.pile_density * p.area)
            for tag in self.pile_nodes:
                m.fix(tag, 1, 1, 1, 1, 1, 1)  # gravity stage: the pile is held
        if not self.soil_box:
            self.springs = pile_springs(m, Tags(node=PY_FIRST, element=PY_FIRST, material=PY_FIRST),
                                        self.pile_nodes, 2.0 * p.pile_radius,
                                        [SoftClay(0.0, p.depth, p.su, p.gamma, eps50=p.eps50, Cd=p.py_drag)],
                                        lateral_dofs=(1, 2), axial=False, tip=False)
            return self
        m.model("basic", "-ndm", 3, "-ndf", 3)
        m.nDMaterial("ElasticIsotropic", SOIL_ELASTIC, p.soil_E, p.soil_nu, p.soil_rho)
        m.nDMaterial("InitialStateAnalysisWrapper", SOIL, SOIL_ELASTIC, 3)
        ratio = (p.half_width / p.pile_radius) ** (1.0 / n_radial) if n_radial > 1 else 1.0
        self.mesh = mesh = ogrid(m, pile_radius=p.pile_radius, outer_size=p.half_width, outer="square",
                                 n_theta=n_theta, n_radial=n_radial, radial_ratio=ratio, levels=levels,
                                 material_tag=SOIL, first_node=FIRST_SOIL_NODE, first_element=FIRST_SOIL_NODE,
                                 body_force=(0.0, 0.0, -p.gamma),
                                 core_below=None if with_pile else levels[0])
        self.base_nodes = list(mesh.groups["base"])
        for t in self.base_nodes:
            m.fix(t, 1, 1, 1)
        self.ties = periodic_ties(m, mesh.coords, p.half_width, levels[-1])
        top = mesh.groups["top"]
        self.surface_node = min(top, key=lambda t: math.hypot(*mesh.coords[t][:2]))
        if with_pile:
            # The base ring is fixed and the tip pinned: no interface there.
            self.contact_soil = [t for k in range(n_z) for t in mesh.surfaces[0][k]]
            if n.interface == "tied":
                for k in range(n_z):
                    for t in mesh.surfaces[0][k]:
                        m.rigidLink("beam", self.pile_nodes[k], t)
            else:
                m.nDMaterial("ContactMaterial3D", CONTACT, p.mu, n.contact_G, 0.0, 0.0)
                penalty = n.penalty_factor * p.soil_E * p.pile_radius if n.interface == "penalty" else None
                self.iface = pile_interface(m, self.pile_nodes, self.contact_soil, p.pile_radius, TRANSF, CONTACT,
                                            penalty=penalty, gap_tol=n.gap_tol, force_tol=n.force_tol,
                                            first_element=FIRST_CONTACT, first_node=FIRST_CONTACT)
        return self

    def gravity(self):
        p, m = self.p, self.m
        if not self.soil_box:
            # No soil: nothing to bring to its geostatic state (the pile has no self weight). The
            # free field the springs follow is the 1D column, run with the same gravity stage.
            times, disp, accel = run_column(p, Numerics(level=self.n.level, interface="none", dt=self.n.dt),
                                            all_levels=True)
            self.free_field = (times, disp, accel)
            return
        self.geostatic_state = geostatic_stage(
            m, soil_elements=self.mesh.elements, gamma=p.gamma, K0=p.K0,
            contact_materials=[CONTACT] if self.iface is not None else [], tol=self.n.tol, max_iter=self.n.max_iter,
            # Exact with frictionless Lagrange contacts or no pile; the tied soil hangs on the held pile.
            check_tol=1e-8 if self.n.interface in ("contact", "none") else None, initial_state=True)

    def shake(self):
        """Release the pile, apply the record at the base, set up the transient analysis."""
        p, n, m = self.p, self.n, self.m
        if self.pile_nodes:
            head, tip = self.pile_nodes[0], self.pile_nodes[-1]
            for tag in self.pile_nodes:
                for dof in range(1, 7):
                    if not ((tag == tip and dof <= 3) or (tag == head and dof == 6)):
                        m.remove("sp", tag, dof)
        dt_record, self.record = read_record(p.record)
        self.record_times = np.arange(len(self.record)) * dt_record
        m.timeSeries("Path", TS_MOTION, "-dt", dt_record, "-filePath", p.record, "-factor", p.g * p.scale)
        m.pattern("UniformExcitation", PAT_MOTION, 1, "-accel", TS_MOTION)
        if self.springs is not None:
            self._drive_springs()
        alpha_m, beta_k = p.rayleigh
        m.rayleigh(alpha_m, beta_k, 0.0, 0.0)
        m.constraints("Transformation")
        m.numberer("RCM")
        m.system("UmfPack")
        m.test("NormUnbalance", n.tol, n.max_iter)
        m.algorithm("Newton")
        m.integrator("Newmark", 0.5, 0.25)
        m.analysis("Transient")

    def _drive_springs(self):
        """Each p-y spring's far end follows the free field along x at its pile node's level: its x
        fix becomes an sp of a Plain pattern whose Path series is the column's relative displacement
        there (the same relative frame as the UniformExcitation that shakes the pile)."""
        m = self.m
        times, disp, _ = self.free_field
        for k, row in enumerate(self.springs.rows):
            level = self.pile_nodes.index(row["pile_node"])
            ts = PY_FIRST + k
            m.remove("sp", row["fixed_node"], 1)
            # A uniform path ends before its last point (as OpenSees): one more sample keeps the
            # last step's value.
            m.timeSeries("Path", ts, "-dt", self.n.dt, "-values", *disp[level], disp[level][-1])
            m.pattern("Plain", ts, ts)
            m.sp(row["fixed_node"], 1, 1.0)

    def ground_accel(self, t):
        """The base acceleration the Path series gives at time t (linear between samples), m/s^2."""
        return float(np.interp(t, self.record_times, self.record, right=0.0)) * self.p.g * self.p.scale

    def add_recorders(self, out):
        out = pathlib.Path(out)
        out.mkdir(parents=True, exist_ok=True)
        m = self.m
        if self.pile_nodes:
            head = self.pile_nodes[0]
            m.recorder("Node", "-file", str(out / "head_accel_abs.out"), "-time", "-timeSeries", TS_MOTION,
                       "-node", head, "-dof", 1, "accel")
            m.recorder("Node", "-file", str(out / "pile_disp.out"), "-time", "-node", *self.pile_nodes, "-dof", 1,
                       "disp")
            m.recorder("Element", "-file", str(out / "pile_forces.out"), "-time", "-ele", *self.beams, "localForce")
        m.recorder("PVD", str(out / "seismic_pile"), "-dT", self.n.pvd_dt, "disp", "vel", "accel")

    def bending_moments(self):
        """M_y at the pile nodes (end 1 of the element below, end 2 for the tip), as lateral_pile."""
        forces = [self.m.eleResponse(e, "localForce") for e in self.beams]
        return [f[4] for f in forces] + [-forces[-1][10]]

    def record_state(self, r, t, iterations, envelope):
        m = self.m
        ag = self.ground_accel(t)
        r.time.append(t)
        r.ground_accel.append(ag)
        r.iterations.append(iterations)
        if self.soil_box:
            r.surface_disp.append(m.nodeDisp(self.surface_node, 1))
            r.surface_accel.append(m.nodeAccel(self.surface_node, 1) + ag)
        else:  # the free field's surface (the 1D column at the same step)
            k = len(r.time) - 1
            r.surface_disp.append(self.free_field[1][0][k])
            r.surface_accel.append(self.free_field[2][0][k] + ag)
        if self.pile_nodes:
            head = self.pile_nodes[0]
            r.head_disp.append(m.nodeDisp(head, 1))
            r.head_accel.append(m.nodeAccel(head, 1) + ag)
            for k, v in enumerate(self.bending_moments()):
                envelope[k] = max(envelope[k], abs(v))
        gap, overlap, n_open, n_slide = 0.0, 0.0, 0, 0
        if self.iface is not None:
            for e in self.iface.elements:
                status = m.eleResponse(e, "status")[0]
                if status == 0.0:
                    n_open += 1
                    g = m.eleResponse(e, "gap")[0]
                    gap, overlap = max(gap, g), max(overlap, -g)
                n_slide += status == 2.0
        r.max_gap.append(gap)
        r.max_overlap.append(overlap)
        r.n_open.append(n_open)
        r.n_sliding.append(n_slide)

    def step(self, dt, t):
        """One step of dt; on failure, the same interval in 4 then 16 substeps. Returns iterations or None."""
        m = self.m
        if m.analyze(1, dt) == 0:
            return int(m.testIter())
        for parts in (4, 16):
            m.setTime(t)
            ok, its = True, 0
            for _ in range(parts):
                if m.analyze(1, dt / parts) != 0:
                    ok = False
                    break
                its += int(m.testIter())
            if ok:
                return its
        return None


def run(problem=SeismicPile(), numerics=Numerics(), m=None, out=None, record=False, on_step=None):
    """Gravity, release and the shaking of one model; returns a SeismicResult.

    With record=True and `out`: head_accel_abs.out (absolute, via -timeSeries), pile_disp.out,
    pile_forces.out and seismic_pile.pvd (disp, vel, accel) in `out`."""
    t0, c0 = time.perf_counter(), time.process_time()
    model = SeismicPileModel(problem, numerics, m).build()
    r = SeismicResult(problem=problem, numerics=numerics, n_contacts=len(model.iface.elements) if model.iface else 0,
                      n_springs=len(model.springs.elements) if model.springs else 0)
    t1 = time.perf_counter()
    model.gravity()
    t2, c2 = time.perf_counter(), time.process_time()
    model.shake()
    if record:
        if out is None:
            raise ValueError("seismic_pile.run: record=True needs an out directory")
        model.add_recorders(out)
    envelope = [0.0] * len(model.pile_nodes)
    model.record_state(r, 0.0, 0, envelope)
    steps = int(round(problem.duration / numerics.dt))
    r.converged = True
    for k in range(1, steps + 1):
        t = k * numerics.dt
        its = model.step(numerics.dt, (k - 1) * numerics.dt)
        if its is None:
            r.converged, r.failed_at = False, (k - 1) * numerics.dt
            r.stop_reason = "a step and its 4 and 16 substeps failed"
            break
        model.record_state(r, t, its, envelope)
        if r.max_overlap[-1] > numerics.overlap_limit * problem.pile_radius:
            r.converged, r.failed_at = False, t
            r.stop_reason = (f"an open contact node lies {1e3 * r.max_overlap[-1]:.1f} mm inside the pile "
                             "(contact chatter)")
            break
        if on_step is not None:
            on_step(model, t)
    t3, c3 = time.perf_counter(), time.process_time()
    r.n_equations = int(model.m.systemSize())
    r.z = [model.m.nodeCoord(t, 3) for t in model.pile_nodes]
    r.moment_envelope = envelope
    # the shaking stage's factorizations and solves (BeamSolid only; OpenSeesPy does not say)
    solver = model.m.solver_info()["solver_seconds"] if hasattr(model.m, "solver_info") else None
    model.m.wipe()
    # cpu_*: this process's CPU time (all its threads), steadier than wall time on a shared machine
    r.timings = dict(build=t1 - t0, gravity=t2 - t1, shaking=t3 - t2, total=time.perf_counter() - t0, solver=solver,
                     cpu_shaking=c3 - c2, cpu_total=time.process_time() - c0)
    return r


def run_column(problem=SeismicPile(), numerics=Numerics(interface="none"), width=1.0, all_levels=False):
    """The 1D shear column the periodic box reduces to without a pile: one stdBrick per layer
    (width x width in plan, the box's levels), its four vertical edges tied like the box's sides,
    run alike (gravity, record, Rayleigh, Newmark). Returns (times, top displacement along x), or
    with all_levels (times, displacements, accelerations), each a list over the levels (top
    first) of the history along x, relative to the bedrock."""
    n_z = LEVELS[numerics.level][2]
    levels = layer_levels(problem, n_z)
    m = Model()
    m.model("basic", "-ndm", 3, "-ndf", 3)
    m.nDMaterial("ElasticIsotropic", SOIL_ELASTIC, problem.soil_E, problem.soil_nu, problem.soil_rho)
    m.nDMaterial("InitialStateAnalysisWrapper", SOIL, SOIL_ELASTIC, 3)
    h = 0.5 * width
    corners = [(-h, -h), (h, -h), (h, h), (-h, h)]  # counterclockwise seen from above
    coords = {}
    for k, z in enumerate(levels):
        for c, (x, y) in enumerate(corners):
            tag = 1 + 4 * k + c
            m.node(tag, x, y, z)
            coords[tag] = (x, y, z)
    elements = []
    for k in range(n_z):
        top, bottom = [1 + 4 * k + c for c in range(4)], [1 + 4 * (k + 1) + c for c in range(4)]
        m.element("stdBrick", k + 1, *bottom, *top, SOIL, 0.0, 0.0, -problem.gamma)
        elements.append(k + 1)
    for c in range(4):
        m.fix(1 + 4 * n_z + c, 1, 1, 1)
    periodic_ties(m, coords, h, levels[-1])
    geostatic_stage(m, soil_elements=elements, gamma=problem.gamma, K0=problem.K0, tol=numerics.tol,
                    max_iter=numerics.max_iter, check_tol=1e-8, initial_state=True)
    dt_record, _ = read_record(problem.record)
    m.timeSeries("Path", TS_MOTION, "-dt", dt_record, "-filePath", problem.record, "-factor", problem.g * problem.scale)
    m.pattern("UniformExcitation", PAT_MOTION, 1, "-accel", TS_MOTION)
    m.rayleigh(*problem.rayleigh, 0.0, 0.0)
    m.constraints("Transformation")
    m.numberer("RCM")
    m.system("UmfPack")
    m.test("NormUnbalance", numerics.tol, numerics.max_iter)
    m.algorithm("Newton")
    m.integrator("Newmark", 0.5, 0.25)
    m.analysis("Transient")
    level_nodes = [1 + 4 * k for k in range(len(levels))]
    times = [0.0]
    disp = [[m.nodeDisp(n, 1)] for n in level_nodes]
    accel = [[m.nodeAccel(n, 1)] for n in level_nodes]
    for k in range(1, int(round(problem.duration / numerics.dt)) + 1):
        if m.analyze(1, numerics.dt) != 0:
            raise RuntimeError(f"run_column: step {k} failed")
        times.append(k * numerics.dt)
        for i, n in enumerate(level_nodes):
            disp[i].append(m.nodeDisp(n, 1))
            accel[i].append(m.nodeAccel(n, 1))
    m.wipe()
    return (times, disp, accel) if all_levels else (times, disp[0])


def lumped_masses(m, elements, rho):
    """{node: rho * integral of N_a over the element} summed over 8-node bricks, by 2 x 2 x 2 Gauss
    quadrature (exact for the trilinear shape functions times the Jacobian of a brick)."""
    g = 1.0 / math.sqrt(3.0)
    signs = [(-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1), (-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1)]
    masses = {}
    for e in elements:
        nodes = m.eleNodes(e)
        X = np.array([m.nodeCoord(t) for t in nodes])
        for gp in signs:
            xi = np.array(gp, dtype=float) * g
            N = np.array([(1 + s[0] * xi[0]) * (1 + s[1] * xi[1]) * (1 + s[2] * xi[2]) / 8.0 for s in signs])
            dN = np.array([[s[0] * (1 + s[1] * xi[1]) * (1 + s[2] * xi[2]) / 8.0,
                            s[1] * (1 + s[0] * xi[0]) * (1 + s[2] * xi[2]) / 8.0,
                            s[2] * (1 + s[0] * xi[0]) * (1 + s[1] * xi[1]) / 8.0] for s in signs])
            detJ = abs(np.linalg.det(dN.T @ X))
            for a, t in enumerate(nodes):
                masses[t] = masses.get(t, 0.0) + rho * N[a] * detJ
    return masses


# =====================================================================================
# The scene: python -m beamsolid.scenes seismic_pile --level coarse|medium|fine
# =====================================================================================
def _plots(out, main, tied, others=()):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    files = []
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(7.0, 6.0), sharex=True)
    a1.plot(main.time, main.ground_accel, color="0.6", lw=0.8, label="bedrock")
    runs = [(main, "-", main.numerics.interface), (tied, "--", "tied")] + [(r, ":", r.numerics.interface) for r in others]
    for r, style, name in runs:
        a1.plot(r.time, r.head_accel, style, lw=1.0, label=f"pile head, {name}")
        a2.plot(r.time, [1e3 * u for u in r.head_disp], style, lw=1.0, label=name)
    a1.set_ylabel("absolute acceleration (m/s^2)")
    a2.set_ylabel("head displacement (mm)")
    a2.set_xlabel("time (s)")
    for a in (a1, a2):
        a.grid(alpha=0.3)
        a.legend(fontsize=8)
    fig.suptitle("Seismic pile: head response")
    fig.tight_layout()
    files.append(out / "head_response.png")
    fig.savefig(files[-1], dpi=120)
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(4.5, 5.5))
    for r, style, name in runs:
        ax.plot(r.moment_envelope, r.z, style + ("o" if style == "-" else "s" if style == "--" else "^"), ms=3,
                label=name)
    ax.set_xlabel("max |M_y| over time (kNm)")
    ax.set_ylabel("z (m)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_title("Bending-moment envelope")
    fig.tight_layout()
    files.append(out / "moment_envelope.png")
    fig.savefig(files[-1], dpi=120)
    plt.close(fig)

    if main.n_contacts:
        fig, ax = plt.subplots(figsize=(7.0, 3.2))
        ax.plot(main.time, [1e3 * g for g in main.max_gap], lw=1.0)
        ax.set_xlabel("time (s)")
        ax.set_ylabel("largest gap (mm)")
        ax2 = ax.twinx()
        ax2.plot(main.time, main.n_open, color="C3", lw=0.8)
        ax2.set_ylabel("open contacts", color="C3")
        ax.grid(alpha=0.3)
        ax.set_title("Gap opening at the pile-soil interface")
        fig.tight_layout()
        files.append(out / "gap_opening.png")
        fig.savefig(files[-1], dpi=120)
        plt.close(fig)
    return files


def scene(level="coarse", out="seismic_pile_output", interface="contact", steps=None, head_mass=0.0, scale=None,
          problem=None, py=True):
    """The chosen interface with recorders, the tied reference and (py=True) the beam on p-y
    springs; print the table, save plots. steps: time steps over the window (default: dt from
    SCENE_DT, 0.01, 0.005 and 0.0025 s at coarse, medium and fine).
    Returns (result, tied result, files); the p-y result is `scene.py_result`."""
    out = pathlib.Path(out)
    out.mkdir(parents=True, exist_ok=True)
    t0 = time.perf_counter()
    if problem is None:
        problem = SeismicPile(head_mass=head_mass, **({} if scale is None else {"scale": scale}))
    dt = SCENE_DT[level] if steps is None else problem.duration / steps
    main = run(problem, Numerics(level=level, interface=interface, dt=dt), out=out, record=True)
    tied = main if interface == "tied" else run(problem, Numerics(level=level, interface="tied", dt=dt))
    others = [run(problem, Numerics(level=level, interface="py", dt=dt))] if py and interface != "py" else []
    scene.py_result = others[0] if others else (main if interface == "py" else None)
    n_theta, n_radial, n_z = LEVELS[level]
    a_m, b_k = problem.rayleigh
    print(f"seismic_pile ({level}: soil box {n_theta} x {n_radial} x {n_z} stdBricks around the pile, {n_z} pile "
          f"elements, {main.n_contacts} contacts, {main.n_equations} equations); units kN, m, s, t")
    print(f"  pile R = {problem.pile_radius:g}, L = H = {problem.depth:g}; soil E = {problem.soil_E:.3g}, nu = "
          f"{problem.soil_nu:g}, Vs = {problem.Vs:.1f} m/s, f1 = {problem.column_omega(1) / (2 * math.pi):.2f} Hz; "
          f"box half-width {problem.half_width:g} (periodic sides); head mass {problem.head_mass:g} t")
    print(f"  record {pathlib.Path(problem.record).name} x {problem.scale:g}, first {problem.duration:g} s, dt = "
          f"{dt:g}; Newmark (1/2, 1/4); rayleigh {a_m:.4g} {b_k:.4g} ({100 * problem.damping:g} % at modes 1, 2)")
    print(f"\n{'model':>8s}{'peak u_head mm':>16s}{'peak a_head':>13s}{'max |M| kNm':>13s}{'at z':>7s}"
          f"{'peak gap mm':>13s}{'max open':>10s}{'iters':>7s}{'wall s':>8s}")
    results = ((tied, main) if main is not tied else (main,)) + tuple(others)
    for r in results:
        k = max(range(len(r.moment_envelope)), key=lambda i: r.moment_envelope[i])
        print(f"{r.numerics.interface:>8s}{1e3 * r.peak_head_disp:16.3f}{max(abs(a) for a in r.head_accel):13.3f}"
              f"{r.moment_envelope[k]:13.1f}{r.z[k]:7.2f}{1e3 * r.peak_gap:13.4f}{max(r.n_open):10d}"
              f"{sum(r.iterations):7d}{r.timings['total']:8.1f}")
    if others or interface == "py":
        print(f"  py: the beam on {scene.py_result.n_springs} zeroLength elements of x and y PySimple1 springs (Matlock soft clay, "
              f"su = {problem.su:g}, eps50 = {problem.eps50:g}, Cd = {problem.py_drag:g}) whose ends follow the "
              "free-field column")
    for r in results:
        if not r.converged:
            print(f"  {r.numerics.interface}: STOPPED at t = {r.failed_at:.3f} s: {r.stop_reason}")
    files = [out / "head_accel_abs.out", out / "pile_disp.out", out / "pile_forces.out", out / "seismic_pile.pvd"]
    try:
        files += _plots(out, main, tied, others)
    except ImportError:
        print("matplotlib not installed: no plots")
    print(f"\nwrote {', '.join(f.name for f in files)} in {out}; wall time {time.perf_counter() - t0:.1f} s")
    return main, tied, files

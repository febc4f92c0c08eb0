"""The lateral pile with the pile itself meshed in bricks: the expensive reference (issue 5).

The same physical problem as scenes.lateral_pile (class LateralPile), modelled the
classical way: the pile is a cylinder of stdBrick elements (butterfly cross-section,
mesh.solid_cylinder) in the hole of the soil O-grid, its surface nodes coincident with
the soil's. The interface is either

    "tied"     equalDOF of every pile-surface node to its soil node (no gap, no slip), or
    "contact"  one zeroLengthContact3D per node pair (penalty Kn normal to the pile axis,
               Kt tangential, Coulomb friction mu), which opens behind the pushed pile.

The head cross-section is made rigid by rigidLink('beam', head, node) to a 6-dof head
node on the axis, which carries the load (y, rx and the torsion held, as the beam pile's
head); the base cross-section is rigid and pinned, like the beam pile's tip.
The geostatic stage runs with the pile held and the interface frictionless, then the
friction comes back, the pile is released and the head is pushed along +x.

The bending moment at a level z is found from the free body of the pile above the cut:
M_y(z) = sum over the interface forces on the pile above z of (z_i - z) F_x - (x_i - x_c) F_z
plus the head load's moment; exact statics, the same formula as for the beam pile.
"""
import math
import time
from dataclasses import dataclass, field

from ..geostatic import geostatic_stage
from ..mesh import fix_soil_boundary, ogrid, solid_cylinder
from ..model import Model
from .lateral_pile import LEVELS, LateralPile, radial_ratio, soil_levels

SOIL, PILE, SOIL_ELASTIC = 1, 2, 3  # SOIL wraps SOIL_ELASTIC (InitialStateAnalysis)
HEAD = 900001  # the rigid head's node
BASE = 900002  # the rigid base's node


@dataclass(frozen=True)
class SolidNumerics:
    level: object = "coarse"  # a key of LEVELS or (n_theta, n_radial, n_z)
    interface: str = "contact"  # "contact" | "tied"
    penalty_factor: float = 1e3  # Kn = factor x E_soil R (per node pair)
    stick_G: float = 1e6  # Kt (kN/m per node pair): a stiff stick
    control: str = "force"  # "force": head load H in `steps`; "disp": head displacement problem.head_disp
    head_load: float = 500.0  # kN (control "force")
    steps: int = 10
    tol: float = 1e-6
    max_iter: int = 40


@dataclass
class SolidResult:
    head_disp: list = field(default_factory=list)
    head_force: list = field(default_factory=list)
    iterations: list = field(default_factory=list)
    z: list = field(default_factory=list)  # levels, top to bottom
    moment: list = field(default_factory=list)  # M_y at each level, final state
    deflection: list = field(default_factory=list)  # mean u_x of the pile section at each level
    n_open: int = 0
    converged: bool = False
    n_equations: int = 0
    n_elements: int = 0
    build_time: float = 0.0
    geostatic_time: float = 0.0
    push_time: float = 0.0

    @property
    def max_moment(self):
        return max((abs(v) for v in self.moment), default=0.0)

    @property
    def wall(self):
        return self.build_time + self.geostatic_time + self.push_time


class SolidPileModel:
    def __init__(self, problem=LateralPile(), numerics=SolidNumerics(), m=None):
        self.p, self.n = problem, numerics
        self.m = m if m is not None else Model()
        self.pairs = []  # (level, soil node, pile node, element or None)

    def build(self):
        p, n, m = self.p, self.n, self.m
        # A level name, or (n_theta, n_radial, n_z) for a level beyond the scene's three.
        n_theta, n_radial, n_z = LEVELS[n.level] if isinstance(n.level, str) else n.level
        levels = soil_levels(p, n_z)  # the same soil mesh as the beam-pile models
        m.wipe()
        m.model("basic", "-ndm", 3, "-ndf", 3)
        m.nDMaterial("ElasticIsotropic", SOIL_ELASTIC, p.soil_E, p.soil_nu)
        m.nDMaterial("InitialStateAnalysisWrapper", SOIL, SOIL_ELASTIC, 3)
        m.nDMaterial("ElasticIsotropic", PILE, p.pile_E, p.pile_nu)
        self.soil = ogrid(m, pile_radius=p.pile_radius, outer_size=p.outer_radius, outer="circle", n_theta=n_theta,
                          n_radial=n_radial, radial_ratio=radial_ratio(p, n_radial), levels=levels, material_tag=SOIL,
                          body_force=(0.0, 0.0, -p.gamma) if n.interface == "contact" else (0.0, 0.0, 0.0))
        self.fixed_soil = list(fix_soil_boundary(m, self.soil))
        self.pile = solid_cylinder(m, radius=p.pile_radius, levels=levels, n_theta=n_theta, material_tag=PILE)
        base = set(self.pile.groups["base"])
        self.levels = levels
        k_normal = n.penalty_factor * p.stiffness_scale
        tag = max(m.getEleTags()) + 1
        for k in range(len(levels)):
            for soil, pile in zip(self.soil.surfaces[0][k], self.pile.surfaces[0][k]):
                if pile in base:
                    self.pairs.append((k, soil, pile, None))
                    continue
                if n.interface == "tied":
                    m.equalDOF(pile, soil, 1, 2, 3)
                    self.pairs.append((k, soil, pile, None))
                else:
                    # dir 0: the retained node (soil, outer) has the normal towards the axis, the
                    # constrained node is the pile's.
                    m.element("zeroLengthContact3D", tag, pile, soil, k_normal, n.stick_G, p.mu, 0.0, 0, 0.0, 0.0)
                    self.pairs.append((k, soil, pile, tag))
                    tag += 1
        m.model("basic", "-ndm", 3, "-ndf", 6)
        m.node(HEAD, 0.0, 0.0, levels[0])
        for t in self.pile.groups["top"]:
            m.rigidLink("beam", HEAD, t)
        # The base section is rigid and pinned (translations fixed, rotations free), as the beam
        # pile's tip: a clamped base of stiff (locking) bricks would carry a shear of its own.
        m.node(BASE, 0.0, 0.0, levels[-1])
        for t in self.pile.groups["base"]:
            m.rigidLink("beam", BASE, t)
        m.fix(BASE, 1, 1, 1, 0, 0, 0)
        self.contacts = [e for (_, _, _, e) in self.pairs if e is not None]
        return self

    # --- stages ------------------------------------------------------------------------------
    def geostatic(self):
        """Gravity with the pile held and the interface frictionless (contact only: the tied
        problem is linear, so the weight does not change its lateral response)."""
        p, m = self.p, self.m
        if not self.contacts:
            m.fix(HEAD, 0, 1, 0, 1, 0, 1)
            return None
        held = [t for t in self.pile.nodes if t not in set(self.pile.groups["base"])]
        m.fix(HEAD, 1, 1, 1, 1, 1, 1)  # holds the head face through the rigid links
        below_head = [t for t in held if t not in set(self.pile.groups["top"])]
        for t in below_head:
            m.fix(t, 1, 1, 1)
        if self.contacts:
            m.setParameter("-val", 0.0, "-ele", *self.contacts, "friction")
        # The penalty interface yields a little (the soil presses into the pile by sigma_h A / Kn):
        # not exactly uniaxial strain, so the stress error is reported, not enforced.
        state = geostatic_stage(m, soil_elements=self.soil.elements, gamma=p.gamma, K0=p.K0, tol=1e-6,
                                initial_state=True)
        if self.contacts:
            m.setParameter("-val", 1.0, "-ele", *self.contacts, "friction")
        for t in below_head:
            for d in (1, 2, 3):
                m.remove("sp", t, d)
        for d in (1, 2, 3, 4, 5, 6):
            m.remove("sp", HEAD, d)
        m.fix(HEAD, 0, 1, 0, 1, 0, 1)  # pushed along x: y and rx (symmetry) and torsion held, as the beam pile
        return state

    def push(self, r):
        p, n, m = self.p, self.n, self.m
        m.timeSeries("Linear", 2)
        m.pattern("Plain", 2, 2)
        if n.control == "force":
            m.load(HEAD, n.head_load, 0.0, 0.0, 0.0, 0.0, 0.0)
        m.constraints("Transformation")
        m.numberer("RCM")
        m.system("UmfPack")
        m.test("NormDispIncr", n.tol * p.head_disp, n.max_iter)
        m.algorithm("Newton")
        if n.control == "force":
            m.integrator("LoadControl", 1.0 / n.steps)
        else:
            m.integrator("DisplacementControl", HEAD, 1, p.head_disp / n.steps)
        m.analysis("Static")
        for _ in range(n.steps):
            if m.analyze(1) != 0:
                return r
            r.n_equations = m.systemSize() if hasattr(m, "systemSize") else 0
            r.iterations.append(m.testIter())
            r.head_disp.append(m.nodeDisp(HEAD, 1))
            r.head_force.append(m.getLoadFactor(2) * n.head_load if n.control == "force" else self.head_reaction())
        r.converged = True
        return r

    def nodal_forces(self, elements, nodes):
        """{node: [Fx, Fy, Fz]}: the summed resisting forces of `elements` at each of `nodes`."""
        m, acc = self.m, {}
        for e in elements:
            tags = m.eleNodes(e)
            if not nodes.intersection(tags):
                continue
            f = m.eleForce(e)
            for a, t in enumerate(tags):
                if t in nodes:
                    v = acc.setdefault(t, [0.0, 0.0, 0.0])
                    for i in range(3):
                        v[i] += f[3 * a + i]
        return acc

    def base_support(self):
        """(Fx, Fy, Fz) the pinned base exerts on the pile: the pile bricks' resisting forces at the
        base-face nodes (a retained node's reaction would leave out its constrained nodes)."""
        forces = self.nodal_forces(self.pile.elements, set(self.pile.groups["base"])).values()
        return [sum(v[i] for v in forces) for i in range(3)]

    def head_reaction(self):
        """Head force under an imposed head displacement, from global equilibrium along x (the
        weight is vertical): minus the soil supports' and the pile base's reactions."""
        m = self.m
        m.reactions()
        return -(sum(m.nodeReaction(t, 1) for t in self.fixed_soil) + self.base_support()[0])

    def interface_forces_on_pile(self):
        """[(x, y, z, Fx, Fy, Fz)]: the soil's action on each pile-surface node.

        Contact: minus the element's resisting force at the pile (constrained, first) node. Tied: minus the soil
        bricks' resisting forces at the soil node (what the pile exerts on the soil)."""
        m, out = self.m, []
        if self.contacts:
            for k, soil, pile, e in self.pairs:
                if e is not None:
                    x, f = m.nodeCoord(pile), m.eleResponse(e, "force")
                    out.append((x[0], x[1], x[2], -f[0], -f[1], -f[2]))
            return out
        last = len(self.levels) - 1  # the base ring is fixed on both sides: not part of the interface
        surface = {soil for (k, soil, _, _) in self.pairs if k < last}
        for t, v in self.nodal_forces(self.soil.elements, surface).items():
            x = m.nodeCoord(t)
            out.append((x[0], x[1], x[2], -v[0], -v[1], -v[2]))
        return out

    def profiles(self, r, head_force):
        """Moment about y at each level from the free body above it, and the mean deflection."""
        m = self.m
        forces = self.interface_forces_on_pile()
        r.z = list(self.levels)
        r.moment = []
        for z in self.levels:
            M = head_force * (self.levels[0] - z)  # the head load at z0 acting on the cut at z
            for (x, y, zi, fx, fy, fz) in forces:
                if zi > z + 1e-12:
                    M += (zi - z) * fx - x * fz
            r.moment.append(M)
        r.deflection = [sum(m.nodeDisp(t, 1) for t in self.pile.surfaces[0][k]) / len(self.pile.surfaces[0][k])
                        for k in range(len(self.levels))]
        if self.contacts:
            r.n_open = sum(1 for e in self.contacts if m.eleResponse(e, "status")[0] == 0)


def run(problem=LateralPile(), numerics=SolidNumerics(), m=None):
    t0 = time.perf_counter()
    model = SolidPileModel(problem, numerics, m).build()
    r = SolidResult(n_elements=len(model.soil.elements) + len(model.pile.elements))
    t1 = time.perf_counter()
    model.geostatic()
    t2 = time.perf_counter()
    model.push(r)
    t3 = time.perf_counter()
    if r.head_force:
        model.profiles(r, r.head_force[-1])
    r.build_time, r.geostatic_time, r.push_time = t1 - t0, t2 - t1, t3 - t2
    model.m.wipe()
    return r


def richardson(hs, values):
    """Extrapolate values(h) = v0 + C h^p from three levels (h decreasing); returns (v0, p)."""
    (h1, h2, h3), (f1, f2, f3) = hs, values
    # Solve (f1 - f2) / (f2 - f3) = (h1^p - h2^p) / (h2^p - h3^p) for p by bisection.
    target = (f1 - f2) / (f2 - f3)

    def g(p):
        return (h1**p - h2**p) / (h2**p - h3**p) - target

    lo, hi = 0.05, 8.0
    if g(lo) * g(hi) > 0:
        return f3, math.nan
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if g(lo) * g(mid) <= 0:
            hi = mid
        else:
            lo = mid
    p = 0.5 * (lo + hi)
    C = (f2 - f3) / (h2**p - h3**p)
    return f3 - C * h3**p, p

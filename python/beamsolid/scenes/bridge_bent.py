"""A bridge bent pushed transversely: piles lose contact on their trailing sides (issue 5).

The paper (Arduino, Petek & Mackenzie-Helnwein 2007, Figure 5) shows "a laterally
loaded bridge bent model in elastic soil ... pushed into the soil in the transverse
direction" whose piles "lose contact with the soil on the opposite pile sides", and the
contact forces on the pile surfaces. It gives no dimensions; the values below are ours.
Units: kN, m, kPa.

Model (defaults): three concrete piles of radius R = 0.5 m in a row along x, 3 m apart
(3 D), embedded L = 12 m down to the base of the soil block (L > the critical length
2 R (E_p / G*)^(2/7) = 10 m of Randolph 1981, so the base hardly touches the lateral
response); the piles stand 3 m above the ground and a stiff cap beam
(1.5 m x 1.5 m, elasticBeamColumn) joins their heads. Soil: elastic (E = 20 MPa,
nu = 0.3, gamma = 20 kN/m^3) in a block 12 m deep with 8 m of padding beyond the pile
tiles in x and 6 m in y, sides on rollers, base fixed. Each pile-surface soil node has
a BeamContact3D (Lagrange multiplier) chained along its pile (contact.pile_interface),
ContactMaterial3D mu = 0.5, stick stiffness 1000 kN/m per node. No end bearing (the
tips carry no BeamEndContact3D): vertical loads go to shaft friction. Each pile ends in a
stub half a layer below the base, so that the base-level soil nodes stay on the pile when
it rises (a node projecting beyond a pile's end is released).

Why the piles reach the base: with a tip above the base the hole below it is filled
with soil (mesh core_below) whose top face carries no overburden (a beam pile has no
volume), so the gravity stage is no longer the uniaxial-strain state and the faceted
closed form of the contact normal forces no longer holds exactly.

Stage 1, geostatic: soil weight as stdBrick body forces, contacts frictionless, every
pile node held (geostatic.geostatic_stage); sigma_h = K0 gamma d on each pile, the
faceted closed form sum N = n R sin(2 pi / n) integral_0^L sigma_h dz per pile.
Stage 2: friction on, piles released, the cap node above the middle pile pushed along
+x by DisplacementControl in equal steps (stepping.adaptive_analyze: a failing step is
cut in halves, up to `max_cuts` times, and grown back after easy steps). The soil on each pile's trailing side (x < pile axis) unloads
until its contacts open, from the ground surface downwards.

Per step: cap force, pile head shears and shares, open contacts and trailing-side gap
depth per pile, contact normal / friction sums per pile. Writes a Node recorder (cap /
pile heads), an Element recorder (pile localForce), a PVD time series and PNGs.
"""
import argparse
import math
import os
import time
from dataclasses import dataclass, field

from ..contact import pile_interface
from ..geostatic import geostatic_stage
from ..mesh import beam_pile, fix_soil_boundary, graded, pile_group
from ..model import Model
from ..stepping import adaptive_analyze

# Mesh levels: (n_theta, n_radial, n_z along the piles, n_padding).
LEVELS = {
    "coarse": (8, 2, 6, 2),
    "medium": (12, 3, 10, 3),
    "fine": (16, 4, 14, 4),
}

SOIL, CONTACT, SOIL_ELASTIC = 1, 2, 3  # material tags (SOIL wraps SOIL_ELASTIC)
PILE_TRANSF, CAP_TRANSF = 1, 2


@dataclass(frozen=True)
class BridgeBent:
    """Parameters of the bent (kN, m, kPa); `level` picks the mesh divisions."""

    level: str = "coarse"
    n_piles: int = 3
    pile_radius: float = 0.5
    spacing: float = 3.0  # centre to centre, along x
    embedded: float = 12.0  # pile length below the ground = depth of the soil block
    free_height: float = 3.0  # ground to cap
    n_free: int = 3  # beam elements above ground
    padding_x: float = 8.0  # soil beyond the pile tiles, each side
    padding_y: float = 6.0
    soil_E: float = 20e3
    soil_nu: float = 0.3
    gamma: float = 20.0
    pile_E: float = 30e6
    pile_nu: float = 0.2
    cap_width: float = 1.5  # square cap section
    mu: float = 0.5
    stick: float = 1000.0  # ContactMaterial3D G, kN/m per contact node
    push: float = 0.05  # final cap displacement along +x (5 % of D)
    steps: int = 10
    max_cuts: int = 4
    tol: float = 1e-8  # NormUnbalance, kN
    max_iter: int = 25
    z_ratio: float = 1.15  # each layer along the piles this much thicker than the one above

    def __post_init__(self):
        if self.level not in LEVELS:
            raise ValueError(f"BridgeBent: level must be one of {sorted(LEVELS)}, got {self.level!r}")
        if self.n_piles < 1:
            raise ValueError(f"BridgeBent: n_piles must be at least 1, got {self.n_piles}")

    @property
    def divisions(self):
        n_theta, n_radial, n_z, n_pad = LEVELS[self.level]
        return dict(n_theta=n_theta, n_radial=n_radial, n_z=n_z, n_padding=n_pad)

    @property
    def K0(self):
        return self.soil_nu / (1.0 - self.soil_nu)

    @property
    def pile_x(self):
        """x of the pile axes, centred on 0."""
        return [(p - 0.5 * (self.n_piles - 1)) * self.spacing for p in range(self.n_piles)]

    @property
    def loaded_pile(self):
        """The cap node above this pile is pushed (the middle one, or right of the middle)."""
        return self.n_piles // 2

    @property
    def faceted_normal_sum(self):
        """Geostatic sum of one pile's contact normal forces: n R sin(2 pi / n) integral_0^L sigma_h dz."""
        n = self.divisions["n_theta"]
        return n * self.pile_radius * math.sin(2.0 * math.pi / n) * 0.5 * self.K0 * self.gamma * self.embedded**2

    def levels(self):
        return graded(0.0, -self.embedded, self.divisions["n_z"], self.z_ratio)


@dataclass
class PileContacts:
    """One pile's contacts at one state (lists in contact-element order)."""

    angle: list = field(default_factory=list)  # degrees from +x (the push direction), in (-180, 180]
    z: list = field(default_factory=list)
    status: list = field(default_factory=list)
    normal: list = field(default_factory=list)  # compression +
    gap: list = field(default_factory=list)
    force_x: list = field(default_factory=list)  # contact force on the soil node
    force_y: list = field(default_factory=list)
    handovers: list = field(default_factory=list)  # hand-overs to a neighbouring segment so far
    elements: list = field(default_factory=list)


@dataclass
class BentResult:
    setup: BridgeBent
    n_contacts: int = 0
    n_soil_elements: int = 0
    geostatic_normal_sum: list = field(default_factory=list)  # per pile
    geostatic_iterations: int = 0
    cap_disp: list = field(default_factory=list)  # per step, 0 first
    cap_force: list = field(default_factory=list)  # load factor of the unit reference load
    head_shear: list = field(default_factory=list)  # per step: per pile, global x force the cap puts into it
    open_contacts: list = field(default_factory=list)  # per step: per pile
    gap_depth: list = field(default_factory=list)  # per step: per pile, deepest open contact on the trailing side
    max_gap: list = field(default_factory=list)  # per step: per pile, largest gap
    normal_sum: list = field(default_factory=list)  # per step: per pile
    friction_sum: list = field(default_factory=list)  # per step: per pile, sum of friction magnitudes
    contact_x: list = field(default_factory=list)  # per step: per pile, sum of contact force x on the soil
    contact_y: list = field(default_factory=list)
    status: list = field(default_factory=list)  # per step: per pile, the contact statuses in element order
    handovers: list = field(default_factory=list)  # per step: per pile, each contact's hand-overs so far
    soil_reaction_x: list = field(default_factory=list)  # per step: x reactions on the soil's x faces
    iterations: list = field(default_factory=list)  # per push step (summed over cuts)
    cuts: int = 0  # steps halved by the adaptive stepper
    grows: int = 0  # steps doubled back
    final: list = field(default_factory=list)  # per pile: PileContacts at the last step
    geostatic_time: float = 0.0
    push_time: float = 0.0
    failed_step: int = 0
    out: str = None
    files: dict = field(default_factory=dict)

    @property
    def shares(self):
        """Per step: each pile's share of the summed head shear."""
        return [[v / sum(row) if sum(row) else 0.0 for v in row] for row in self.head_shear]


class BentModel:
    """Builds the bent in `m` (a beamsolid.Model) and runs its stages."""

    def __init__(self, setup, m=None):
        self.s = setup
        self.m = m if m is not None else Model()

    def build(self):
        s, m = self.s, self.m
        d = s.divisions
        m.wipe()
        m.model("basic", "-ndm", 3, "-ndf", 3)
        # Wrapped so that the gravity stage's stresses survive InitialStateAnalysis('off').
        m.nDMaterial("ElasticIsotropic", SOIL_ELASTIC, s.soil_E, s.soil_nu)
        m.nDMaterial("InitialStateAnalysisWrapper", SOIL, SOIL_ELASTIC, 3)
        m.nDMaterial("ContactMaterial3D", CONTACT, s.mu, s.stick, 0.0, 0.0)
        levels = s.levels()
        self.soil = pile_group(m, piles=[(x, 0.0) for x in s.pile_x], pile_radius=s.pile_radius,
                               spacing=s.spacing, n_theta=d["n_theta"], n_radial=d["n_radial"],
                               padding=(s.padding_x, s.padding_x, s.padding_y, s.padding_y),
                               n_padding=d["n_padding"], levels=levels, material_tag=SOIL,
                               body_force=(0.0, 0.0, -s.gamma))
        fix_soil_boundary(m, self.soil, "roller", "roller")
        self.x_faces = sorted(set(self.soil.groups["xmin"]) | set(self.soil.groups["xmax"]))
        free = graded(s.free_height, 0.0, s.n_free)[:-1]
        below = self.soil.pile_levels
        # A stub below the base: the base-level soil nodes project inside a segment even when
        # the pile rises (otherwise they would slide off the pile's end and open).
        stub = [below[-1] - 0.5 * (below[-2] - below[-1])]
        G = s.pile_E / (2.0 * (1.0 + s.pile_nu))
        self.piles, self.interfaces = [], []
        for p, x in enumerate(s.pile_x):
            pile = beam_pile(m, x=x, y=0.0, levels=free + below + stub, radius=s.pile_radius, E=s.pile_E,
                             G=G, transf_tag=PILE_TRANSF, vecxz=(1.0, 0.0, 0.0) if p == 0 else None)
            self.piles.append(pile)
        for p, pile in enumerate(self.piles):
            self.interfaces.append(pile_interface(m, pile.nodes, self.soil.surface_nodes(p), s.pile_radius,
                                                  PILE_TRANSF, CONTACT))
        # Cap beam through the pile heads (they are its nodes: rigid pile-cap joints).
        self.heads = [pile.nodes[0] for pile in self.piles]
        m.geomTransf("Linear", CAP_TRANSF, 0.0, 0.0, 1.0)
        b = s.cap_width
        A, I = b * b, b**4 / 12.0
        J = 0.1406 * b**4  # torsion constant of a square
        first = max(m.getEleTags()) + 1
        self.cap_elements = []
        for k in range(len(self.heads) - 1):
            m.element("elasticBeamColumn", first + k, self.heads[k], self.heads[k + 1], A, s.pile_E, G, J, I, I,
                      CAP_TRANSF)
            self.cap_elements.append(first + k)
        self.cap = self.heads[s.loaded_pile]
        return self

    # --- queries ------------------------------------------------------------------
    def pile_contacts(self, p):
        m, iface = self.m, self.interfaces[p]
        cx = self.s.pile_x[p]
        c = PileContacts()
        for soil_node, e in iface.element_of.items():
            x, y, z = m.nodeCoord(soil_node)
            c.angle.append(math.degrees(math.atan2(y, x - cx)))
            c.z.append(z)
            c.status.append(int(m.eleResponse(e, "status")[0]))
            c.normal.append(m.eleResponse(e, "forcescalar")[0])
            c.gap.append(m.eleResponse(e, "gap")[0])
            f = m.eleResponse(e, "force")
            c.force_x.append(f[0])
            c.force_y.append(f[1])
            c.handovers.append(int(m.eleResponse(e, "handovers")[0]))
            c.elements.append(e)
        return c

    def record(self, r):
        m, s = self.m, self.s
        r.cap_disp.append(m.nodeDisp(self.cap, 1))
        r.cap_force.append(m.getLoadFactor(2) if r.cap_disp[-1] != 0.0 else 0.0)
        shear, n_open, depth, gmax, nsum, fsum, fx, fy, status, moved = [], [], [], [], [], [], [], [], [], []
        for p, pile in enumerate(self.piles):
            shear.append(m.eleResponse(pile.elements[0], "force")[0])
            c = self.pile_contacts(p)
            trailing = [-z for z, st, a in zip(c.z, c.status, c.angle) if st == 0 and abs(a) > 90.0 + 1e-6]
            n_open.append(c.status.count(0))
            depth.append(max(trailing, default=0.0))
            gmax.append(max(c.gap))
            nsum.append(sum(c.normal))
            fsum.append(sum(math.sqrt(sum(v * v for v in m.eleResponse(e, "frictionforce"))) for e in c.elements))
            fx.append(sum(c.force_x))
            fy.append(sum(c.force_y))
            status.append(c.status)
            moved.append(c.handovers)
        r.head_shear.append(shear)
        r.open_contacts.append(n_open)
        r.gap_depth.append(depth)
        r.max_gap.append(gmax)
        r.normal_sum.append(nsum)
        r.friction_sum.append(fsum)
        r.contact_x.append(fx)
        r.contact_y.append(fy)
        r.status.append(status)
        r.handovers.append(moved)
        # The soil's x faces carry the push (bricks only: an independent path from the contacts).
        m.reactions()
        r.soil_reaction_x.append(sum(m.nodeReaction(n, 1) for n in self.x_faces))

    # --- stages -----------------------------------------------------------------
    def geostatic(self, r):
        s, m = self.s, self.m
        for pile in self.piles:
            for n in pile.nodes:
                m.fix(n, 1, 1, 1, 1, 1, 1)
        state = geostatic_stage(m, soil_elements=self.soil.elements, gamma=s.gamma, K0=s.K0,
                                contact_materials=[CONTACT], tol=s.tol, max_iter=s.max_iter, check_tol=1e-8,
                                initial_state=True)
        r.geostatic_iterations = state.iterations
        r.geostatic_normal_sum = [sum(self.pile_contacts(p).normal) for p in range(len(self.piles))]
        for pile in self.piles:
            for n in pile.nodes:
                for dof in range(1, 7):
                    m.remove("sp", n, dof)

    def _analysis(self, du):
        m, s = self.m, self.s
        m.constraints("Transformation")
        m.numberer("RCM")
        m.system("UmfPack")
        m.test("NormUnbalance", s.tol, s.max_iter)
        m.algorithm("Newton")
        m.integrator("DisplacementControl", self.cap, 1, du)
        m.analysis("Static")

    def push(self, r, out=None):
        s, m = self.s, self.m
        m.timeSeries("Linear", 2)
        m.pattern("Plain", 2, 2)
        m.load(self.cap, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0)
        du = s.push / s.steps
        self._analysis(du)
        if out is not None:
            self.recorders(out, r)
            m.record()  # the geostatic state as the first row / file
        self.record(r)

        def on_step(progress, iterations):
            r.iterations.append(iterations)
            self.record(r)

        # Cut a failing step in halves (down to push / steps / 2^max_cuts), grow it back after easy steps.
        stepper = adaptive_analyze(m, s.push, s.steps, integrator=lambda d: ("DisplacementControl", self.cap, 1, d),
                                   adaptive=s.max_cuts > 0, min_fraction=0.5**s.max_cuts, on_step=on_step)
        r.cuts, r.grows = stepper.cuts, stepper.grows
        if not stepper.converged:
            r.failed_step = len(r.iterations) + 1

    def recorders(self, out, r):
        m = self.m
        os.makedirs(out, exist_ok=True)
        r.files["heads"] = os.path.join(out, "heads_disp.out")
        r.files["pile_forces"] = os.path.join(out, "pile_localForce.out")
        r.files["pvd"] = os.path.join(out, "bent.pvd")
        m.recorder("Node", "-file", r.files["heads"], "-time", "-precision", 10, "-node", *self.heads,
                   "-dof", 1, 2, 3, 4, 5, 6, "disp")
        m.recorder("Element", "-file", r.files["pile_forces"], "-time", "-precision", 10,
                   "-ele", *[e for pile in self.piles for e in pile.elements], "localForce")
        m.recorder("PVD", r.files["pvd"])


def run(setup=None, m=None, out=None):
    """Both stages of the bent; with `out` the recorders and the PVD go there."""
    setup = setup if setup is not None else BridgeBent()
    model = BentModel(setup, m).build()
    mm = model.m
    r = BentResult(setup=setup, out=out, n_contacts=sum(len(i.elements) for i in model.interfaces),
                   n_soil_elements=len(model.soil.elements))
    t0 = time.perf_counter()
    model.geostatic(r)
    t1 = time.perf_counter()
    model.push(r, out)
    r.push_time = time.perf_counter() - t1
    r.geostatic_time = t1 - t0
    r.final = [model.pile_contacts(p) for p in range(setup.n_piles)]
    mm.wipe()
    return r


# --- reporting -------------------------------------------------------------------------

def table(r):
    s = r.setup
    lines = [f"bridge bent, {s.n_piles} piles, level {s.level}: {r.n_soil_elements} bricks, {r.n_contacts} contacts; "
             f"geostatic {r.geostatic_time:.1f} s, push {r.push_time:.1f} s",
             "geostatic sum N per pile: " + ", ".join(f"{v:.3f}" for v in r.geostatic_normal_sum)
             + f" kN (faceted closed form {s.faceted_normal_sum:.3f})"]
    head = f"{'u cap':>7} {'H cap':>8} {'it':>3}" + "".join(
        f" | p{p} {'shear':>7} {'share':>5} {'open':>4} {'gap z':>5} {'sum N':>8} {'sum F':>6}" for p in range(s.n_piles))
    lines.append(head)
    lines.append("-" * len(head))
    for k in range(len(r.cap_disp)):
        row = f"{1e3 * r.cap_disp[k]:7.1f} {r.cap_force[k]:8.1f} {r.iterations[k - 1] if k else 0:3d}"
        total = sum(r.head_shear[k])
        for p in range(s.n_piles):
            share = r.head_shear[k][p] / total if total else 0.0
            row += (f" |    {r.head_shear[k][p]:7.1f} {share:5.2f} {r.open_contacts[k][p]:4d} {r.gap_depth[k][p]:5.2f}"
                    f" {r.normal_sum[k][p]:8.1f} {r.friction_sum[k][p]:6.1f}")
        lines.append(row)
    lines.append("u cap in mm, forces in kN; gap z: depth (m) of the deepest open contact on the trailing side; "
                 "sum F: summed friction force magnitudes")
    if r.failed_step:
        lines.append(f"step {r.failed_step} failed after {r.cuts} cuts (at most {r.setup.max_cuts} halvings of a step)")
    return "\n".join(lines)


def plots(r, out):
    """Cap force-displacement, gap depth per pile, and the final gap pattern (unrolled surfaces)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    s = r.setup
    files = {}
    u = [1e3 * v for v in r.cap_disp]
    fig, ax = plt.subplots(figsize=(5, 3.6))
    ax.plot(u, r.cap_force, "o-", label="cap force")
    for p in range(s.n_piles):
        ax.plot(u, [row[p] for row in r.head_shear], "--", label=f"pile {p} head shear")
    ax.set_xlabel("cap displacement (mm)")
    ax.set_ylabel("force (kN)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_title(f"bridge bent ({s.level})")
    fig.tight_layout()
    files["force"] = os.path.join(out, "bent_force_displacement.png")
    fig.savefig(files["force"], dpi=110)
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(5, 3.6))
    for p in range(s.n_piles):
        ax.plot(u, [row[p] for row in r.gap_depth], "o-", label=f"pile {p}")
    ax.set_xlabel("cap displacement (mm)")
    ax.set_ylabel("trailing-side gap depth (m)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    files["gap"] = os.path.join(out, "bent_gap_depth.png")
    fig.savefig(files["gap"], dpi=110)
    plt.close(fig)

    fig, axes = plt.subplots(1, s.n_piles, figsize=(3.2 * s.n_piles, 4.2), sharey=True, squeeze=False)
    vmax = max(max(c.normal) for c in r.final)
    for p, (ax, c) in enumerate(zip(axes[0], r.final)):
        closed = [k for k, st in enumerate(c.status) if st != 0]
        opened = [k for k, st in enumerate(c.status) if st == 0]
        sc = ax.scatter([c.angle[k] for k in closed], [c.z[k] for k in closed], c=[c.normal[k] for k in closed],
                        cmap="viridis", vmin=0.0, vmax=vmax, s=30)
        ax.scatter([c.angle[k] for k in opened], [c.z[k] for k in opened], marker="x", color="tab:red", s=30,
                   label="open")
        ax.set_xlim(-185, 185)
        ax.set_xticks([-180, -90, 0, 90, 180])
        ax.set_xlabel("angle from +x (deg)")
        ax.set_title(f"pile {p} (x = {s.pile_x[p]:g} m)", fontsize=9)
        ax.grid(alpha=0.3)
    axes[0][0].set_ylabel("z (m)")
    axes[0][0].legend(fontsize=8, loc="lower left")
    fig.colorbar(sc, ax=axes[0].tolist(), label="contact normal force (kN)")
    fig.suptitle(f"gap pattern at u = {u[-1]:.0f} mm (push along +x; trailing side at +-180 deg)", fontsize=9)
    files["pattern"] = os.path.join(out, "bent_gap_pattern.png")
    fig.savefig(files["pattern"], dpi=110)
    plt.close(fig)
    return files


def scene(level="coarse", out="bridge_bent_output", steps=None, adaptive=False):
    """`python -m beamsolid.scenes bridge_bent --level ...`: run, print the table, save the plots.
    --adaptive allows more step halvings (8 instead of 4)."""
    extra = {} if steps is None else {"steps": steps}
    if adaptive:
        extra["max_cuts"] = 8
    r = run(BridgeBent(level=level, **extra), out=out)
    print(table(r))
    r.files.update(plots(r, out))
    for name, path in r.files.items():
        print(f"{name:12s} {path}")
    return r


def main(argv=None):
    parser = argparse.ArgumentParser(prog="bridge_bent", description=__doc__.split("\n")[0])
    parser.add_argument("--level", choices=sorted(LEVELS), default="coarse")
    parser.add_argument("--out", default=None, help="output folder (default out/bridge_bent_<level>)")
    parser.add_argument("--piles", type=int, default=3)
    parser.add_argument("--steps", type=int, default=None)
    args = parser.parse_args(argv)
    out = args.out or os.path.join("out", f"bridge_bent_{args.level}")
    extra = {} if args.steps is None else {"steps": args.steps}
    setup = BridgeBent(level=args.level, n_piles=args.piles, **extra)
    r = run(setup, out=out)
    print(table(r))
    r.files.update(plots(r, out))
    for name, path in r.files.items():
        print(f"{name:12s} {path}")
    return 0 if not r.failed_step else 1


if __name__ == "__main__":
    raise SystemExit(main())

"""The lateral pile of `lateral_pile.LateralPile` as a beam on elastic (Winkler) springs.

The cheapest model of issue 5's laterally loaded pile: n elasticBeamColumn elements
along the pile axis (head at z = 0, tip at z = -L; Euler-Bernoulli, bending stiffness
E_pile I_pile) and, at every beam node, two elastic zeroLength springs (x and y) to a
fixed ground node, of stiffness k times the node's tributary length (h/2 at the head
and the tip, h between). Units: kN, m, kPa. The tip is free laterally (no base spring);
its axial and torsional dofs are fixed so that the system is not singular.

Modulus of subgrade reaction k (force per unit length of pile per unit deflection,
kN/m per m = kPa), two published choices (see docs/lateral_pile_winkler.md):

* Vesic (1961), "Bending of beams resting on isotropic elastic solid", J. Eng. Mech.
  Div. ASCE 87(EM2), 35-53 -- for a beam of width D on the surface of an elastic
  half-space (Es, nu):
      k = 0.65 (Es D^4 / (Ep Ip))^(1/12) Es / (1 - nu^2)
  (`vesic_k`). It is a surface-beam result; applied to an embedded pile it is known to
  be soft (soil on one side only).
* The k that reproduces Randolph's (1981) head compliance u/H of the flexible pile
  (`LateralPile.randolph_compliance`) for this pile: the k whose finite-length Winkler
  head deflection under H equals Randolph's (`randolph_k`; for a long pile it is the
  semi-infinite match 2 lambda / k = u/H, i.e. k = (2 / ((u/H) (4 Ep Ip)^(1/4)))^(4/3)).

Closed form (`winkler_closed_form`): EI y'''' + k y = 0 along the depth x, free head
with the shear EI y'''(0) = H and no moment, free tip EI y''(L) = EI y'''(L) = 0.
Hetenyi (1946), "Beams on Elastic Foundation", Univ. of Michigan Press: for a
semi-infinite beam (lambda L > ~4, lambda = (k / (4 EI))^(1/4))
    y(0) = 2 H lambda / k,   M(x) = (H / lambda) e^(-lambda x) sin(lambda x),
    M_max = 0.3224 H / lambda at lambda x = pi / 4.
The finite beam is solved exactly from the four exponential-trigonometric solutions
and the four end conditions.

Sign conventions of the results: deflection u along +x (the direction of the head
load), depth d = -z, moment M = EI d^2u/dd^2 (positive near the head of a pile pushed
along +x, as Hetenyi's M above).

No-tension springs (gapping behind the pile) are not offered: a spring that only
pushes, precompressed by the geostatic sigma_h, needs a no-tension material with an
initial strain (or a front and a back spring each with its own precompression), which
BeamSolid's ENT does not have.
"""
import math
import time
from dataclasses import dataclass, field

import numpy as np

from ..model import Model
from .lateral_pile import LateralPile

TRANSF = 1
SPRING_END, SPRING_INNER = 1, 2  # uniaxial material tags
GROUND = 100000  # ground node tags: GROUND + beam node tag


def bending_stiffness(problem: LateralPile):
    return problem.pile_E * problem.inertia


def vesic_k(problem: LateralPile):
    """Vesic (1961): k = 0.65 (Es D^4 / (Ep Ip))^(1/12) Es / (1 - nu^2), kN/m per m."""
    D = 2.0 * problem.pile_radius
    Es, nu = problem.soil_E, problem.soil_nu
    return 0.65 * (Es * D**4 / bending_stiffness(problem)) ** (1.0 / 12.0) * Es / (1.0 - nu**2)


def characteristic(EI, k):
    """lambda = (k / (4 EI))^(1/4), 1/m."""
    return (k / (4.0 * EI)) ** 0.25


def winkler_closed_form(EI, k, L, H, depths):
    """Exact deflection, slope and moment of a free-free beam of length L on Winkler
    springs k, loaded by H at x = 0: returns (y, y', M = EI y'') at `depths`."""
    lam = characteristic(EI, k)
    x = np.asarray(depths, dtype=float)
    # y = Re/Im of exp(a x) with a = lam (+-1 + i); the growing pair is scaled by
    # exp(-lam L) so that the system stays well conditioned for long beams.
    roots = [lam * (1.0 + 1.0j), lam * (-1.0 + 1.0j)]
    shifts = [L, 0.0]

    def basis(xx, order):
        cols = []
        for a, s in zip(roots, shifts):
            v = a**order * np.exp(a * xx - lam * s)
            cols += [v.real, v.imag]
        return np.array(cols).T

    A = np.array([basis(np.array([0.0]), 2)[0], basis(np.array([0.0]), 3)[0],
                  basis(np.array([L]), 2)[0], basis(np.array([L]), 3)[0]])
    c = np.linalg.solve(A, np.array([0.0, H / EI, 0.0, 0.0]))
    return basis(x, 0) @ c, basis(x, 1) @ c, EI * (basis(x, 2) @ c)


def semi_infinite_head(EI, k, H):
    """Hetenyi's semi-infinite beam: (y(0), M_max, depth of M_max)."""
    lam = characteristic(EI, k)
    return 2.0 * H * lam / k, 0.3224 * H / lam, math.pi / (4.0 * lam)


def randolph_k(problem: LateralPile, tol=1e-13):
    """The k whose finite-length Winkler head compliance equals Randolph's u/H."""
    EI, L, target = bending_stiffness(problem), problem.length, problem.randolph_compliance

    def compliance(k):
        return winkler_closed_form(EI, k, L, 1.0, [0.0])[0][0]

    # Start from the semi-infinite match and bracket (compliance falls with k).
    k0 = (2.0 / (target * (4.0 * EI) ** 0.25)) ** (4.0 / 3.0)
    lo, hi = 0.5 * k0, 2.0 * k0
    while compliance(lo) < target:
        lo *= 0.5
    while compliance(hi) > target:
        hi *= 2.0
    while hi - lo > tol * hi:
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if compliance(mid) > target else (lo, mid)
    return 0.5 * (lo + hi)


@dataclass
class WinklerResult:
    problem: LateralPile
    n_elements: int
    k: float
    depths: list = field(default_factory=list)  # beam node depths d = -z, head first
    deflection: list = field(default_factory=list)  # u_x at the nodes (m)
    moment: list = field(default_factory=list)  # M = EI u'' at the nodes (kN m)
    head_disp: float = 0.0
    head_force: float = 0.0
    head_rotation: float = 0.0  # du/dd at the head (negative: deflection falls with depth)
    equations: int = 0
    wall_time: float = 0.0
    curve: list = field(default_factory=list)  # (head displacement, head force) after each step

    @property
    def compliance(self):
        return self.head_disp / self.head_force


def run_winkler(problem: LateralPile = LateralPile(), n_elements: int = 40, k=None, head_force=None,
                head_disp=None, m=None, spring="zeroLength", spring_material=None, steps=1):
    """Beam-on-springs model of the lateral pile; give `head_force` (kN) or `head_disp`
    (m, default problem.head_disp). `k` in kN/m per m (default: `vesic_k`).

    The springs are zeroLength elements, or with spring="NonlinearSpring3D" the tutorial
    plugin's element (docs/plugins.md; load the plugin first), one along x and one along y
    at each node. Their material is Elastic with stiffness k times the tributary length, or
    what spring_material(m, matTag, stiffness) defines (e.g. an ElasticPP spring); a
    nonlinear spring wants steps > 1, which switches to Newton."""
    if spring not in ("zeroLength", "NonlinearSpring3D"):
        raise ValueError(f"run_winkler: spring must be 'zeroLength' or 'NonlinearSpring3D', got {spring!r}")
    if head_force is not None and head_disp is not None:
        raise ValueError("run_winkler: give head_force or head_disp, not both")
    if head_force is None and head_disp is None:
        head_disp = problem.head_disp
    if n_elements < 1:
        raise ValueError(f"run_winkler: n_elements must be >= 1, got {n_elements}")
    k = vesic_k(problem) if k is None else float(k)
    if not k > 0.0:
        raise ValueError(f"run_winkler: k must be positive, got {k}")
    own = m is None
    m = Model() if own else m
    t0 = time.perf_counter()
    n, L = n_elements, problem.length
    h = L / n
    EI = bending_stiffness(problem)
    m.wipe()
    m.model("basic", "-ndm", 3, "-ndf", 6)
    nodes = list(range(1, n + 2))  # node 1 at the head
    for a in nodes:
        z = -(a - 1) * h
        m.node(a, 0.0, 0.0, z)
        m.node(GROUND + a, 0.0, 0.0, z)
        m.fix(GROUND + a, 1, 1, 1, 1, 1, 1)
    m.fix(nodes[-1], 0, 0, 1, 0, 0, 1)  # tip: axial and torsion only
    m.geomTransf("Linear", TRANSF, 1.0, 0.0, 0.0)
    for e in range(n):
        m.element("elasticBeamColumn", e + 1, e + 1, e + 2, problem.area, problem.pile_E, problem.pile_G,
                  2.0 * problem.inertia, problem.inertia, problem.inertia, TRANSF)
    for mat, stiffness in ((SPRING_END, 0.5 * k * h), (SPRING_INNER, k * h)):
        if spring_material is None:
            m.uniaxialMaterial("Elastic", mat, stiffness)
        else:
            spring_material(m, mat, stiffness)
    for a in nodes:
        mat = SPRING_END if a in (nodes[0], nodes[-1]) else SPRING_INNER
        if spring == "zeroLength":
            m.element("zeroLength", n + a, GROUND + a, a, "-mat", mat, mat, "-dir", 1, 2)
        else:
            m.element(spring, n + a, GROUND + a, a, mat, "-orient", 1.0, 0.0, 0.0)
            m.element(spring, 2 * n + 1 + a, GROUND + a, a, mat, "-orient", 0.0, 1.0, 0.0)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.load(1, 1.0 if head_disp is not None else head_force, 0.0, 0.0, 0.0, 0.0, 0.0)
    m.constraints("Plain")
    m.numberer("RCM")
    m.system("BandSPD")
    m.test("NormDispIncr", 1e-12, 25)
    m.algorithm("Linear" if steps == 1 and spring_material is None else "Newton")
    if head_disp is not None:
        m.integrator("DisplacementControl", 1, 1, head_disp / steps)
    else:
        m.integrator("LoadControl", 1.0 / steps)
    m.analysis("Static")
    r = WinklerResult(problem=problem, n_elements=n, k=k)
    for _ in range(steps):
        if m.analyze(1) != 0:
            raise RuntimeError("run_winkler: the analysis failed")
        r.curve.append((m.nodeDisp(1, 1), m.getLoadFactor(1) * (1.0 if head_disp is not None else head_force)))
    r.equations = int(m.systemSize())
    r.head_force = m.getLoadFactor(1) if head_disp is not None else head_force
    r.depths = [(a - 1) * h for a in nodes]
    r.deflection = [m.nodeDisp(a, 1) for a in nodes]
    r.head_disp = r.deflection[0]
    r.head_rotation = -m.nodeDisp(1, 5)  # the rotation about y is du/dz = -du/dd
    # Element end moments about local y (local z = global x): the moment at the upper
    # node of each element; zero at the free tip.
    r.moment = [m.eleResponse(e + 1, "localForce")[4] for e in range(n)] + [0.0]
    r.wall_time = time.perf_counter() - t0
    if own:
        m.wipe()
    return r

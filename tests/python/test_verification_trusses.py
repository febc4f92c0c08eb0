"""truss, corotTruss and zeroLength through the Python commands.

A statically determinate truss is checked against equilibrium alone (bar
forces) and compatibility (displacements); the corotational truss against the
exact large-displacement equilibrium of a two-bar (von Mises) truss; elastic-
perfectly-plastic members against the piecewise-linear closed form, including
what a failed step must leave behind.
"""
import numpy as np
import pytest


def assert_close(actual, expected, rtol=1e-10, scale=None):
    actual, expected = np.asarray(actual, float), np.asarray(expected, float)
    scale = np.max(np.abs(expected)) if scale is None else scale
    assert scale > 0.0
    err = np.max(np.abs(actual - expected)) / scale
    assert err <= rtol, f"relative error {err:.3e} > {rtol:.0e}\nactual   {actual}\nexpected {expected}"


def static(m, integrator=("LoadControl", 1.0), test=("NormDispIncr", 1e-12, 20), algorithm="Newton"):
    m.constraints("Plain")
    m.numberer("RCM")
    m.system("UmfPack")
    m.test(*test)
    m.algorithm(algorithm)
    m.integrator(*integrator)
    m.analysis("Static")


# A simple space truss: three pinned supports, then each new node hangs on
# three existing ones, so bars = 3 x free nodes (statically determinate).
SUPPORTS = {1: (0.0, 0.0, 0.0), 2: (4.0, 0.0, 0.0), 3: (1.5, 3.5, 0.0)}
FREE = {4: (1.8, 1.1, 3.0), 5: (3.2, 1.9, 5.5), 6: (0.9, 2.4, 6.2), 7: (2.1, 0.6, 8.4)}
BARS = [(1, 4), (2, 4), (3, 4), (2, 5), (3, 5), (4, 5), (3, 6), (4, 6), (5, 6), (4, 7), (5, 7), (6, 7)]
LOADS = {5: (3.0, -1.0, -10.0), 6: (0.0, 4.0, -6.0), 7: (-2.0, 1.5, -8.0)}
E_BAR = 2.0e8


def test_statically_determinate_space_truss(model):
    m = model
    m.model("basic", "-ndm", 3, "-ndf", 3)
    coords = {**SUPPORTS, **FREE}
    for t, x in coords.items():
        m.node(t, *x)
    for t in SUPPORTS:
        m.fix(t, 1, 1, 1)
    m.uniaxialMaterial("Elastic", 1, E_BAR)
    areas = [1e-3 * (1 + 0.25 * b) for b in range(len(BARS))]
    for b, ((i, j), area) in enumerate(zip(BARS, areas)):
        m.element("truss", b + 1, i, j, area, 1)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    for t, p in LOADS.items():
        m.load(t, *p)
    static(m)
    assert m.analyze(1) == 0

    # Statics: sum of bar forces + load = 0 at every free node (N > 0 in tension).
    free = sorted(FREE)
    row = {t: 3 * k for k, t in enumerate(free)}
    B = np.zeros((3 * len(free), len(BARS)))
    lengths, units = [], []
    for b, (i, j) in enumerate(BARS):
        d = np.subtract(coords[j], coords[i])
        L = np.linalg.norm(d)
        e = d / L
        lengths.append(L)
        units.append(e)
        if i in row:
            B[row[i]:row[i] + 3, b] += e
        if j in row:
            B[row[j]:row[j] + 3, b] -= e
    P = np.zeros(3 * len(free))
    for t, p in LOADS.items():
        P[row[t]:row[t] + 3] = p
    N = np.linalg.solve(B, -P)
    # Compatibility: elongation e.(u_j - u_i) = N L / EA, i.e. -B^T u = elongation.
    elongation = N * np.array(lengths) / (E_BAR * np.array(areas))
    u = np.linalg.solve(-B.T, elongation)

    forces = [m.eleResponse(b + 1, "axialForce")[0] for b in range(len(BARS))]
    assert_close(forces, N)
    for t in free:
        assert_close(m.nodeDisp(t), u[row[t]:row[t] + 3], scale=np.abs(u).max())
    m.reactions()
    total = np.sum([m.nodeReaction(t) for t in SUPPORTS], axis=0)
    assert_close(total, -np.sum(list(LOADS.values()), axis=0))
    for t in SUPPORTS:  # each support takes the bars that meet it
        expected = np.zeros(3)
        for b, (i, j) in enumerate(BARS):
            if i == t:
                expected -= N[b] * units[b]
            if j == t:
                expected += N[b] * units[b]
        assert_close(m.nodeReaction(t), expected, scale=np.abs(N).max())


@pytest.mark.parametrize("stretch", [0.0, 0.01])
def test_corot_truss_large_rotation(model, stretch):
    """Node 2 driven by sp along a straight line to the bar turned by 60 degrees (and stretched):
    N = EA (l - L)/L along the current axis at every step; a rigid rotation leaves no force."""
    m = model
    L, EA, n_steps = 2.0, 5.0e4, 4
    m.model("basic", "-ndm", 3, "-ndf", 3)
    m.node(1, 0.0, 0.0, 0.0)
    m.node(2, L, 0.0, 0.0)
    m.fix(1, 1, 1, 1)
    m.uniaxialMaterial("Elastic", 1, EA)
    m.element("corotTruss", 1, 1, 2, 1.0, 1)
    angle = np.radians(60.0)
    axis = np.array([np.cos(angle), np.sin(angle), 0.0])
    target = L * (1 + stretch) * axis - np.array([L, 0.0, 0.0])
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    for d in range(3):
        m.sp(2, d + 1, target[d])
    static(m, integrator=("LoadControl", 1.0 / n_steps))
    for step in range(1, n_steps + 1):
        assert m.analyze(1) == 0
        x2 = np.array([L, 0.0, 0.0]) + step / n_steps * target
        length = np.linalg.norm(x2)
        N = EA * (length - L) / L
        assert_close(m.eleResponse(1, "axialForce"), [N], scale=EA * 1e-2)
        e = x2 / length
        assert_close(m.eleResponse(1, "force"), np.concatenate([-N * e, N * e]), scale=EA * 1e-2)
    assert abs(m.eleResponse(1, "axialForce")[0] - EA * stretch) <= 1e-10 * EA


def von_mises_load(w, half_span, rise, EA):
    """Apex load of the two-bar truss at apex deflection w (exact, engineering strain)."""
    L0 = np.hypot(half_span, rise)
    L = np.hypot(half_span, rise - w)
    N = EA * (L - L0) / L0
    return -2.0 * N * (rise - w) / L


def test_corot_von_mises_truss_through_the_limit_point(model):
    """DisplacementControl on the apex to full inversion: the load factor follows the exact curve."""
    m = model
    a, h, EA, P_ref = 4.0, 0.5, 1.0e4, 1.0
    m.model("basic", "-ndm", 3, "-ndf", 3)
    m.node(1, -a, 0.0, 0.0)
    m.node(2, a, 0.0, 0.0)
    m.node(3, 0.0, 0.0, h)
    m.fix(1, 1, 1, 1)
    m.fix(2, 1, 1, 1)
    m.fix(3, 0, 1, 0)
    m.uniaxialMaterial("Elastic", 1, EA)
    m.element("corotTruss", 1, 1, 3, 1.0, 1)
    m.element("corotTruss", 2, 2, 3, 1.0, 1)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.load(3, 0.0, 0.0, -P_ref)
    n_steps = 40
    static(m, integrator=("DisplacementControl", 3, 3, -2.0 * h / n_steps))
    loads = []
    for step in range(1, n_steps + 1):
        assert m.analyze(1) == 0
        w = -m.nodeDisp(3, 3)
        assert w == pytest.approx(2.0 * h * step / n_steps, rel=1e-12)
        assert abs(m.nodeDisp(3, 1)) < 1e-12
        loads.append(m.getTime() * P_ref)
        P = von_mises_load(w, a, h, EA)
        assert abs(loads[-1] - P) <= 1e-10 * 2 * EA * (h / a) ** 3
    # The path went over the limit point and through the snap-back branch.
    assert max(loads) > 0.0 > min(loads)
    assert abs(loads[n_steps // 2 - 1]) < 1e-9 * EA  # flat bars: zero load at w = h


# --- Elastic-perfectly-plastic truss and zeroLength in parallel -------------

L_BAR, EA_BAR, NY_BAR = 2.0, 4.0e3, 10.0      # truss: k1 = EA/L = 2000, yields at u = 5e-3
K_SPRING, FY_SPRING = 1.0e3, 20.0             # zeroLength: yields at u = 2e-2
CAPACITY = NY_BAR + FY_SPRING
LAMBDA_CAP = 0.97                             # capacity reached at this load factor


def parallel_epp(m):
    m.model("basic", "-ndm", 3, "-ndf", 3)
    m.node(1, 0.0, 0.0, 0.0)
    m.node(2, L_BAR, 0.0, 0.0)
    m.node(3, L_BAR, 0.0, 0.0)
    m.fix(1, 1, 1, 1)
    m.fix(2, 0, 1, 1)
    m.fix(3, 1, 1, 1)
    m.uniaxialMaterial("ElasticPP", 1, EA_BAR, NY_BAR / EA_BAR)
    m.uniaxialMaterial("ElasticPP", 2, K_SPRING, FY_SPRING / K_SPRING)
    m.element("truss", 1, 1, 2, 1.0, 1)
    m.element("zeroLength", 2, 3, 2, "-mat", 2, "-dir", 1)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.load(2, CAPACITY / LAMBDA_CAP, 0.0, 0.0)


def epp_response(P):
    """Closed form: (u, truss force, spring force) under monotonic load P < capacity."""
    k1 = EA_BAR / L_BAR
    u = P / (k1 + K_SPRING)
    if k1 * u <= NY_BAR:
        return u, k1 * u, K_SPRING * u
    u = (P - NY_BAR) / K_SPRING
    return u, NY_BAR, K_SPRING * u


def state(m):
    return (m.nodeDisp(2), m.eleResponse(1, "axialForce"), m.eleResponse(1, "material", "strain"),
            m.eleResponse(2, "basicForce"), m.eleResponse(2, "deformation"), m.getTime())


def test_epp_plateau_failed_step_and_retry(model):
    m = model
    parallel_epp(m)
    step = 0.1
    static(m, integrator=("LoadControl", step), test=("NormUnbalance", 1e-10, 10))
    P_ref = CAPACITY / LAMBDA_CAP

    def check_converged():
        lam = m.getTime()
        u, n_bar, f_spring = epp_response(lam * P_ref)
        assert_close(m.nodeDisp(2, 1), u)
        assert_close(m.eleResponse(1, "axialForce"), [n_bar])
        assert_close(m.eleResponse(2, "basicForce"), [f_spring])

    for k in range(9):
        assert m.analyze(1) == 0
        check_converged()
    # On the plateau: the truss carries exactly its yield force.
    assert m.getTime() == pytest.approx(0.9)
    assert m.eleResponse(1, "axialForce") == [pytest.approx(NY_BAR, rel=1e-14)]
    assert m.eleResponse(1, "material", "tangent") == [0.0]
    assert m.eleResponse(1, "material", "strain")[0] > NY_BAR / EA_BAR

    # A step to 1.0 > LAMBDA_CAP cannot converge: negative code, nothing moved.
    before = state(m)
    assert m.analyze(1) < 0
    assert state(m) == before
    assert m.analyze(3) < 0          # a multi-step call fails at its first step too
    assert state(m) == before

    # The usual retry loop: halve the step after a failure and carry on.
    failures = 0
    while step > 1e-4:
        if m.analyze(1) < 0:
            failures += 1
            step /= 2
            m.integrator("LoadControl", step)
            assert state(m)[-1] < LAMBDA_CAP
        else:
            check_converged()
    lam = m.getTime()
    assert LAMBDA_CAP - 2e-4 < lam < LAMBDA_CAP
    assert failures == 10  # 0.1 / 2**10 < 1e-4
    # Both members are on their plateaus' edge: the spring force is just below its yield force.
    assert FY_SPRING - m.eleResponse(2, "basicForce")[0] < 2e-4 * CAPACITY / LAMBDA_CAP

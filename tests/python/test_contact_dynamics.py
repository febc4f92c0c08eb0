"""BeamContact3D with friction under dynamics: a sliding block on a pile.

A point block of mass m (a soil node, ndf 3) rests by its weight on a short
horizontal beam ("pile", both ends fixed) through BeamContact3D with
ContactMaterial3D (mu, stick stiffness G). The ground shakes along the pile
axis with a_g = A sin(w t) for two cycles (UniformExcitation, Trig series);
Newmark average acceleration. The block's relative motion is that of a
rigid-plastic sliding block (Newmark 1965): it sticks while |a_g| < mu g and
slides, relative to the ground, with u'' = -a_g - mu g sgn(u') beyond it.

Closed form: a slide starts (from rest) at ts when |a_g| reaches mu g, in
the direction s = -sgn(a_g); its relative velocity is
v(t) = (A/w)(cos w t - cos w ts) - s mu g (t - ts) and its slip the integral
of v, both exact; it stops at v(te) = 0 (a root, by bisection), and the next
slide starts at once if |a_g(te)| > mu g (here the second slide of each cycle
follows the first without a stick).

The finite stick stiffness G is the model's departure from rigid-plastic:
each reversal passes through the elastic stick range 2 mu N / G, during
which friction is less than mu N, and the slide after it gains a little
velocity. The error falls with G and dt (measured slide errors, slides 2
and 3: G = 1e6: 3%; 1e7 and 2000 steps a cycle: 0.9%; 1e8 and 2000: 0.5%;
1e8 and 8000: 0.3%; the first slide, from rest: < 1e-4). Here G = 1e8 and
2000 steps a cycle; slips within 2% (the issue's tolerance), the stick
phase within 5% of m A / G.
"""
import math

import pytest

import beamsolid.opensees as ops

MU, G, M, R, L, GRAV = 0.3, 1.0e8, 1.0, 0.3, 2.0, 9.81
OMEGA = 4.0 * math.pi
PERIOD = 2.0 * math.pi / OMEGA
STEPS_PER_CYCLE = 2000
CYCLES = 2


def _run(amplitude, vertical=0.0, steps_after=500, tol=1e-12):
    """Rows (time, ux, uz, vx, friction force on the block x, normal force) per step."""
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    ops.node(1, 0.0, 0.0, 0.0)
    ops.node(2, L, 0.0, 0.0)
    for n in (1, 2):
        ops.fix(n, 1, 1, 1, 1, 1, 1)
    ops.geomTransf("Linear", 1, 0.0, 0.0, 1.0)
    ops.element("elasticBeamColumn", 10, 1, 2, 0.28, 3e7, 1.2e7, 0.0127, 0.0064, 0.0064, 1)
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    ops.node(3, L / 2, 0.0, R)  # the block, on top of the pile surface
    ops.node(4, L / 2, 0.0, R)  # the Lagrange multiplier node
    ops.mass(3, M, M, M)
    ops.nDMaterial("ContactMaterial3D", 1, MU, G, 0.0, 0.0)
    ops.element("BeamContact3D", 20, 1, 2, 3, 4, R, 1, 1, 1e-10, 1e-10)
    ops.updateMaterialStage("-material", 1, "-stage", 1)
    ops.timeSeries("Constant", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(3, 0.0, 0.0, -M * GRAV)
    ops.timeSeries("Trig", 2, 0.0, CYCLES * PERIOD, PERIOD, "-factor", amplitude)
    ops.pattern("UniformExcitation", 2, 1, "-accel", 2)
    if vertical:
        ops.timeSeries("Trig", 3, 0.0, CYCLES * PERIOD, PERIOD, "-factor", vertical)
        ops.pattern("UniformExcitation", 3, 3, "-accel", 3)
    ops.constraints("Transformation")
    ops.numberer("Plain")
    ops.system("UmfPack")
    ops.test("NormDispIncr", tol, 30)
    ops.algorithm("Newton")
    ops.integrator("Newmark", 0.5, 0.25)
    ops.analysis("Transient")
    dt = PERIOD / STEPS_PER_CYCLE
    rows = [(0.0, 0.0, 0.0, 0.0, 0.0, 0.0)]
    for _ in range(CYCLES * STEPS_PER_CYCLE + steps_after):
        assert ops.analyze(1, dt) == 0
        f = ops.eleResponse(20, "force")
        rows.append((ops.getTime(), ops.nodeDisp(3, 1), ops.nodeDisp(3, 3), ops.nodeVel(3, 1), f[0], f[2]))
    ops.wipe()
    return rows


def _ground_accel(t, amplitude):
    return amplitude * math.sin(OMEGA * t) if t <= CYCLES * PERIOD + 1e-12 else 0.0


def _bisect(f, lo, hi):
    """The root of f in [lo, hi], f(lo) and f(hi) of opposite signs."""
    flo = f(lo)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if (f(mid) < 0.0) == (flo < 0.0):
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def _newmark_sliding_block(amplitude, t_end):
    """Slides of the rigid-plastic block under A sin(w t): (start, end, slip) each, in closed form
    (the slide's velocity and slip are exact; its end time is a root, found by bisection)."""
    a, w, f = amplitude, OMEGA, MU * GRAV
    slides, t = [], 0.0
    while True:
        # Stuck until |a_g| reaches mu g (at once if it already exceeds it).
        if abs(a * math.sin(w * t)) < f:
            n = math.floor(w * t / math.pi)
            candidates = [(n * math.pi + k) / w for n in (n, n + 1) for k in (math.asin(f / a), math.pi - math.asin(f / a))]
            t = min(c for c in candidates if c > t)
        if t >= t_end:
            return slides
        ts, sign = t, -math.copysign(1.0, math.sin(w * t))  # slides against the ground's acceleration

        def velocity(x, ts=ts, sign=sign):
            return (a / w) * (math.cos(w * x) - math.cos(w * ts)) - sign * f * (x - ts)

        hi = ts + 1e-9
        while velocity(hi) * sign > 0.0 or hi == ts + 1e-9:
            hi += PERIOD / 50
        te = _bisect(velocity, ts + 1e-9, hi)
        d = te - ts
        slip = (a / w**2) * (math.sin(w * te) - math.sin(w * ts)) - (a / w) * math.cos(w * ts) * d - sign * f * d * d / 2
        slides.append((ts, te, slip))
        t = te + 1e-12


def _closed_form_displacement(slides, t):
    u = 0.0
    for ts, te, slip in slides:
        if t >= te:
            u += slip
        elif t > ts:
            a, w, f = 2.0 * MU * GRAV, OMEGA, MU * GRAV
            sign = math.copysign(1.0, slip)
            d = t - ts
            u += (a / w**2) * (math.sin(w * t) - math.sin(w * ts)) - (a / w) * math.cos(w * ts) * d - sign * f * d * d / 2
    return u


@pytest.fixture(scope="module")
def sliding():
    return _run(2.0 * MU * GRAV)


def test_block_sticks_below_mu_g():
    amplitude = 0.8 * MU * GRAV
    rows = _run(amplitude)
    peak = max(abs(r[1]) for r in rows)
    # Stuck: only the elastic stick deformation m a_g / G, never a slip.
    assert peak == pytest.approx(M * amplitude / G, rel=0.05)
    assert max(abs(r[4]) for r in rows) < MU * M * GRAV
    assert max(abs(r[2]) for r in rows) < 1e-12  # stays on the surface


def test_block_slides_by_the_newmark_sliding_block_displacement(sliding):
    # The slides that end while the ground still shakes (the closed form has a_g = A sin(w t) throughout).
    slides = [s for s in _newmark_sliding_block(2.0 * MU * GRAV, CYCLES * PERIOD) if s[1] <= CYCLES * PERIOD]
    assert len(slides) >= 2 * CYCLES - 1
    # Sliding starts when a_g first reaches mu g: before it the block moves only elastically.
    before = [r for r in sliding if r[0] < slides[0][0] - 2 * PERIOD / STEPS_PER_CYCLE]
    assert max(abs(r[1]) for r in before) <= 1.01 * MU * M * GRAV / G
    # Each slide's slip, and the whole history, against the closed form within 2%.
    for ts, te, slip in slides:
        u0 = min((r for r in sliding), key=lambda r: abs(r[0] - ts))[1]
        u1 = min((r for r in sliding), key=lambda r: abs(r[0] - te))[1]
        assert u1 - u0 == pytest.approx(slip, rel=0.02)
    peak = max(abs(s[2]) for s in slides)
    error = max(abs(r[1] - _closed_form_displacement(slides, r[0])) for r in sliding if r[0] <= slides[-1][1])
    assert error <= 0.02 * peak
    # While sliding, the friction force on the block is mu N against the slip velocity.
    for r in sliding:
        if abs(r[3]) > 1e-3:
            assert r[4] == pytest.approx(-math.copysign(MU * M * GRAV, r[3]), rel=1e-9)
            assert r[5] == pytest.approx(M * GRAV, rel=1e-9)


def test_friction_dissipates_and_energy_balances(sliding):
    amplitude = 2.0 * MU * GRAV
    work_in = dissipated = 0.0
    worst = lowest = 0.0
    scale = 0.0
    for a, b in zip(sliding, sliding[1:]):
        du = b[1] - a[1]
        work_in += -M * 0.5 * (_ground_accel(a[0], amplitude) + _ground_accel(b[0], amplitude)) * du
        dissipated += -0.5 * (a[4] + b[4]) * du  # work of friction on the block, taken out of it
        kinetic = 0.5 * M * b[3] ** 2
        scale = max(scale, abs(work_in))
        worst = max(worst, abs(work_in - kinetic - dissipated))
        lowest = min(lowest, dissipated)
    # Friction never creates energy: only the elastic stick energy (mu N)^2 / 2G can come back.
    assert lowest >= -((MU * M * GRAV) ** 2) / (2.0 * G) * 1.01
    assert dissipated > 0.9 * work_in > 0.0
    # Input work = kinetic energy + friction work (Newmark average acceleration, trapezoidal works).
    assert worst <= 1e-6 * scale


def test_vertical_shaking_lift_off_and_landing_stay_bounded():
    """Vertical shaking at 1.5 g throws the block off the pile (a_v < -g) and it lands again,
    many times. BeamContact3D decides contact at the commit (C20), so a landing node has
    penetrated by up to one step of its approach, v dt. In a transient analysis the closed
    contact then holds the target gap g_n + 3/4 dt gdot_n + dt^2/8 gddot_n: with the
    trapezoidal rule an inelastic impact spread over two steps (the normal velocity halves,
    then velocity and acceleration are zero), so no landing throws the block back out and no
    bounce gains energy. Checked: the penetration stays below 2 v_max dt (no sinking through
    the pile), the block never flies higher than its first flight, and once the shaking stops it
    rests: no velocity, contact force = weight (1e-6)."""
    dt = PERIOD / STEPS_PER_CYCLE
    rows = _run(0.0, vertical=1.5 * GRAV, tol=1e-8)  # lambda of ~6e3 kN at impact: round-off 1e-9
    uz = [r[2] for r in rows]
    shaking = [r for r in rows if r[0] <= CYCLES * PERIOD]
    v_max = max(abs(b[2] - a[2]) / dt for a, b in zip(rows, rows[1:]))
    assert max(uz) > 1e-3  # it does lift off
    assert min(uz) > -2.0 * v_max * dt, (min(uz), v_max * dt)
    # no growing bounces: the highest flight is the first one
    flights = []
    for a, b in zip(shaking, shaking[1:]):
        if b[2] > 0.0 and (not flights or a[2] <= 0.0):
            flights.append(b[2])
        elif b[2] > 0.0:
            flights[-1] = max(flights[-1], b[2])
    assert flights and max(flights) <= flights[0] * 1.5
    rest = rows[-50:]
    assert max(abs(r[2] - rest[-1][2]) for r in rest) < 1e-12
    assert rest[-1][5] == pytest.approx(M * GRAV, rel=1e-6)

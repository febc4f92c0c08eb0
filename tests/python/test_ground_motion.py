"""Time series, earthquake patterns and the synthetic record generator
against closed forms.

Static (LoadControl) checks run now: a spring-mass under UniformExcitation
carries -m a_g (u = -m a_g / k, reaction m a_g); MultipleSupport imposes the
ground displacement, its velocity and acceleration from a constant
acceleration a0 (v = a0 t exactly, u = a0 t^2/2 exactly since the
trapezoidal rule is exact on the linear velocity); periodic series match
their formulas. Dynamic checks need analysis('Transient') and skip with the
reason until it exists: a suddenly applied ground acceleration on an
undamped SDOF, u = -(m a0/k)(1 - cos w(t - dt/2)) (Newmark starts from rest,
so the jump acts at half the first step), to the Newmark period error; free
vibration from '-vel0', u = v0/w sin wt; and the absolute acceleration
recorded with '-timeSeries', which equilibrium makes -k u / m to round-off.
"""
import importlib.util
import json
import math
import os

import numpy as np
import pytest

import beamsolid

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
RECORD = os.path.join(ROOT, "examples", "records", "synthetic_kt_seed16.acc")


def _groundmotion():
    # Imported from the source tree by path so that the test works without numpy in the package deps.
    spec = importlib.util.spec_from_file_location("gm", os.path.join(ROOT, "python", "beamsolid", "groundmotion.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _sdof(ops, k=50.0, m=2.0):
    ops.model("basic", "-ndm", 1, "-ndf", 1)
    ops.node(1, 0.0)
    ops.node(2, 0.0)
    ops.fix(1, 1)
    ops.mass(2, m)
    ops.uniaxialMaterial("Elastic", 1, k)
    ops.element("zeroLength", 1, 1, 2, "-mat", 1, "-dir", 1)


def _static(ops, dt):
    ops.constraints("Transformation")
    ops.numberer("Plain")
    ops.system("FullGeneral")
    ops.test("NormUnbalance", 1e-12, 10)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", dt)
    ops.analysis("Static")


def test_uniform_excitation_static_effective_load(ops):
    k, m, a0, fact = 50.0, 2.0, 3.0, 1.5
    _sdof(ops, k, m)
    ops.timeSeries("Constant", 1, "-factor", a0)
    ops.pattern("UniformExcitation", 1, 1, "-accel", 1, "-fact", fact)
    _static(ops, 1.0)
    assert ops.analyze(1) == 0
    ops.reactions()
    assert ops.nodeDisp(2, 1) == pytest.approx(-m * fact * a0 / k, rel=1e-12)
    assert ops.nodeUnbalance(2)[0] == pytest.approx(-m * fact * a0, rel=1e-12)
    assert ops.nodeReaction(1, 1) == pytest.approx(m * fact * a0, rel=1e-12)


def test_uniform_excitation_vel_or_disp_only_applies_nothing(ops):
    _sdof(ops)
    ops.timeSeries("Constant", 1)
    ops.pattern("UniformExcitation", 1, 1, "-disp", 1)
    _static(ops, 1.0)
    assert ops.analyze(1) == 0
    assert ops.nodeDisp(2, 1) == 0.0


def test_multiple_support_integrates_constant_acceleration(ops):
    a0, k1, k2 = 4.0, 50.0, 30.0
    ops.model("basic", "-ndm", 1, "-ndf", 1)
    for n in (1, 2, 3):
        ops.node(n, 0.0)
    ops.fix(1, 1)
    ops.uniaxialMaterial("Elastic", 1, k1)
    ops.uniaxialMaterial("Elastic", 2, k2)
    ops.element("zeroLength", 1, 1, 2, "-mat", 1, "-dir", 1)
    ops.element("zeroLength", 2, 2, 3, "-mat", 2, "-dir", 1)
    ops.timeSeries("Path", 1, "-time", 0.0, 5.0, "-values", a0, a0)
    ops.pattern("MultipleSupport", 1)
    ops.groundMotion(1, "Plain", "-accel", 1)
    ops.imposedMotion(3, 1, 1)
    _static(ops, 0.25)
    for i in range(1, 9):
        assert ops.analyze(1) == 0
        t = 0.25 * i
        u = 0.5 * a0 * t * t
        assert ops.nodeDisp(3, 1) == pytest.approx(u, rel=1e-10)
        assert ops.nodeVel(3, 1) == pytest.approx(a0 * t, rel=1e-10)
        assert ops.nodeAccel(3, 1) == pytest.approx(a0, rel=1e-12)
        assert ops.nodeDisp(2, 1) == pytest.approx(u * k2 / (k1 + k2), rel=1e-10)


@pytest.mark.parametrize("bad, message", [
    (("pattern", "UniformExcitation", 1, 7, "-accel", 1), "dir must be 1..1"),
    (("pattern", "UniformExcitation", 1, 1), "no ground motion"),
    (("pattern", "UniformExcitation", 1, 1, "-accel", 9), "timeSeries 9"),
    (("groundMotion", 1, "Plain", "-accel", 1), "no MultipleSupport pattern"),
    (("imposedMotion", 2, 1, 5), "no MultipleSupport pattern"),
])
def test_excitation_errors_name_command_and_argument(ops, bad, message):
    _sdof(ops)
    ops.timeSeries("Constant", 1)
    with pytest.raises(beamsolid.OpenSeesError, match=message):
        getattr(ops, bad[0])(*bad[1:])


def test_ground_motion_errors(ops):
    _sdof(ops)
    ops.timeSeries("Linear", 1)
    ops.pattern("MultipleSupport", 1)
    with pytest.raises(beamsolid.OpenSeesError, match="groundMotion 1.*cannot integrate"):
        ops.groundMotion(1, "Plain", "-accel", 1)
    with pytest.raises(beamsolid.OpenSeesError, match="groundMotion 2.*Simpson"):
        ops.groundMotion(2, "Plain", "-disp", 1, "-int", "Simpson")
    ops.groundMotion(3, "Plain", "-disp", 1)
    with pytest.raises(beamsolid.OpenSeesError, match="imposedMotion 2.*ground motion 4 does not exist"):
        ops.imposedMotion(2, 1, 4)
    ops.imposedMotion(1, 1, 3)  # on a fixed dof: allowed, as OpenSees (see the test below)
    ops.pattern("MultipleSupport", 2)
    ops.groundMotion(5, "Plain", "-disp", 1)
    with pytest.raises(beamsolid.OpenSeesError, match="imposedMotion 1.*already has an imposed value in pattern 1"):
        ops.imposedMotion(1, 1, 5)


@pytest.mark.parametrize("handler, share", [(("Transformation",), 1.0), (("Penalty", 1e12, 1e12), 0.5)])
def test_imposed_motion_on_a_fixed_support(ops, handler, share):
    """Multiple-support scripts fix the supports, then impose their motion
    (OpenSeesPyDoc Example 4): as OpenSees, the imposed displacement governs
    under Transformation; under Penalty the fix and the motion are two equal
    springs, so the support moves half the ground displacement (OpenSeesPy
    3.7.1 does the same)."""
    _sdof(ops)
    values = [0.0, 0.001, 0.003, 0.006, 0.008, 0.009]
    ops.timeSeries("Path", 1, "-dt", 0.01, "-values", *values, 0.0)
    ops.pattern("MultipleSupport", 1)
    ops.groundMotion(1, "Plain", "-disp", 1, "-fact", 2.0)
    ops.imposedMotion(1, 1, 1)
    ops.constraints(*handler)
    ops.numberer("Plain")
    ops.system("FullGeneral")
    ops.test("NormDispIncr", 1e-12, 10)
    ops.algorithm("Newton")
    ops.integrator("Newmark", 0.5, 0.25)
    ops.analysis("Transient")
    for v in values[1:]:
        assert ops.analyze(1, 0.01) == 0
        assert ops.nodeDisp(1, 1) == pytest.approx(share * 2.0 * v, rel=1e-9)


@pytest.mark.parametrize("spec, formula", [
    (("Trig", 1.0, 3.0, 2.0, "-factor", 2.0), lambda t: 2.0 * math.sin(math.pi * (t - 1.0)) if 1 <= t <= 3 else 0.0),
    (("Rectangular", 1.0, 3.0, "-factor", 2.0), lambda t: 2.0 if 1 <= t <= 3 else 0.0),
    (("Pulse", 1.0, 3.0, 1.0, "-width", 0.25), lambda t: (1.0 if (t - 1.0) % 1.0 < 0.25 else 0.0) if 1 <= t <= 3 else 0.0),
    (("Triangle", 1.0, 3.0, 2.0), lambda t: (2 / math.pi) * math.asin(math.sin(math.pi * (t - 1.0))) if 1 <= t <= 3 else 0.0),
])
def test_periodic_series_through_a_unit_spring(ops, spec, formula):
    ops.model("basic", "-ndm", 1, "-ndf", 1)
    ops.node(1, 0.0)
    ops.node(2, 0.0)
    ops.fix(1, 1)
    ops.uniaxialMaterial("Elastic", 1, 1.0)
    ops.element("zeroLength", 1, 1, 2, "-mat", 1, "-dir", 1)
    ops.timeSeries(spec[0], 1, *spec[1:])
    ops.pattern("Plain", 1, 1)
    ops.load(2, 1.0)
    _static(ops, 0.125)
    for _ in range(30):
        assert ops.analyze(1) == 0
        t = ops.getTime()
        assert ops.nodeDisp(2, 1) == pytest.approx(formula(t), abs=1e-12), t


# --- dynamics (need analysis('Transient')) ---------------------------------

def _transient_or_skip(ops):
    try:
        ops.integrator("Newmark", 0.5, 0.25)
        ops.analysis("Transient")
    except beamsolid.OpenSeesError as e:
        pytest.skip(f"analysis('Transient') is not available yet: {e}")


def _dynamic_setup(ops):
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.system("FullGeneral")
    ops.test("NormUnbalance", 1e-10, 10)
    ops.algorithm("Newton")
    _transient_or_skip(ops)


def test_sudden_ground_acceleration_on_undamped_sdof(ops, tmp_path):
    k, m, a0 = 50.0, 2.0, 0.8
    w = math.sqrt(k / m)
    _sdof(ops, k, m)
    ops.timeSeries("Rectangular", 1, 0.0, 100.0, "-factor", a0)
    ops.pattern("UniformExcitation", 1, 1, "-accel", 1)
    out = str(tmp_path / "abs_accel.out")
    ops.recorder("Node", "-file", out, "-precision", 15, "-time", "-timeSeries", 1, "-node", 2, "-dof", 1, "accel")
    _dynamic_setup(ops)
    dt, worst, disps = 0.002, 0.0, []
    for _ in range(500):
        assert ops.analyze(1, dt) == 0
        t = ops.getTime()
        # Newmark starts from rest (a = 0 at t = 0), so the jump of a_g at t = 0
        # is averaged over the first step: the step acts at dt/2.
        exact = -(m * a0 / k) * (1.0 - math.cos(w * (t - 0.5 * dt)))
        worst = max(worst, abs(ops.nodeDisp(2, 1) - exact))
        disps.append(ops.nodeDisp(2, 1))
    # Average acceleration: period elongation (w dt)^2 / 12 = 8e-6, ~4e-5 rad over 5 rad.
    assert worst / (2 * m * a0 / k) < 1e-4
    ops.remove("recorders")
    absolute = np.loadtxt(out)[:, 1]
    np.testing.assert_allclose(absolute, -k / m * np.array(disps), atol=1e-9 * a0)


def test_initial_velocity_free_vibration(ops):
    k, m, v0 = 50.0, 2.0, 0.7
    w = math.sqrt(k / m)
    _sdof(ops, k, m)
    ops.timeSeries("Constant", 1, "-factor", 0.0)
    ops.pattern("UniformExcitation", 1, 1, "-accel", 1, "-vel0", v0)
    assert ops.nodeVel(2, 1) == v0 and ops.nodeVel(1, 1) == 0.0
    _dynamic_setup(ops)
    dt = 0.002
    for _ in range(500):
        assert ops.analyze(1, dt) == 0
        t = ops.getTime()
        assert ops.nodeDisp(2, 1) == pytest.approx(v0 / w * math.sin(w * t), abs=2e-4 * v0 / w)


# --- synthetic record ------------------------------------------------------

def test_record_generator_is_deterministic_and_ends_at_rest():
    gm = _groundmotion()
    a = gm.kanai_tajimi(duration=10.0, dt=0.01, pga=0.25, seed=3)
    b = gm.kanai_tajimi(duration=10.0, dt=0.01, pga=0.25, seed=3)
    c = gm.kanai_tajimi(duration=10.0, dt=0.01, pga=0.25, seed=4)
    assert np.array_equal(a, b) and not np.allclose(a, c)
    assert np.max(np.abs(a)) == pytest.approx(0.25, rel=1e-12)
    assert a[0] == 0.0 and abs(a[-1]) < 1e-15
    v = gm.integrate(a, 0.01)
    d = gm.integrate(v, 0.01)
    assert abs(v[-1]) < 1e-10 * np.max(np.abs(v)) and abs(d[-1]) < 1e-10 * np.max(np.abs(d))
    # The Kanai-Tajimi filter puts the energy around the ground frequency fg (2.5 Hz).
    spectrum = np.abs(np.fft.rfft(a)) ** 2
    f = np.fft.rfftfreq(len(a), 0.01)
    centroid = np.sum(f * spectrum) / np.sum(spectrum)
    assert 1.0 < centroid < 6.0


def test_shipped_record_is_the_generators_output(tmp_path):
    gm = _groundmotion()
    with open(RECORD + ".json") as fh:
        info = json.load(fh)
    dt, shipped = gm.read_record(RECORD)
    again = gm.kanai_tajimi(duration=info["duration"], dt=dt, pga=info["pga"], fg=info["fg"],
                            zeta_g=info["zeta_g"], seed=info["seed"])
    np.testing.assert_allclose(shipped, again, rtol=0, atol=1e-10 * info["pga"])
    assert len(shipped) == info["npts"]


def test_shipped_record_loads_as_a_path_series(ops):
    gm = _groundmotion()
    dt, acc = gm.read_record(RECORD)
    _sdof(ops)
    ops.timeSeries("Path", 1, "-dt", dt, "-filePath", RECORD, "-factor", 9.81)
    ops.pattern("UniformExcitation", 1, 1, "-accel", 1)
    _static(ops, dt)
    for i in range(1, 200):
        assert ops.analyze(1) == 0
        assert ops.nodeUnbalance(2)[0] == pytest.approx(-2.0 * 9.81 * acc[i], rel=1e-9, abs=1e-12)


def test_integrated_motion_at_the_record_end(ops):
    """An acceleration-only ground motion a = c t on N = 1000 samples (dt =
    0.01, the integration step): the trapezoids give v = c t^2 / 2 exactly and
    d = their running sum up to the last sample t_e = (N-1) dt, which counts
    although a '-dt' path is 0 at its last time; one step more, where the
    record is 0: v = v(t_e) + dt c t_e / 2, d = d(t_e) + dt (v(t_e) + v) / 2;
    then 0 (the integral ends). OpenSeesPy 3.7.1 gives these numbers on this
    record (149.70015, 498.50174925; 149.85, 499.9995); before, BeamSolid
    dropped the last sample and ended at t_e."""
    _sdof(ops)
    n, h, c = 1000, 0.01, 3.0
    ops.timeSeries("Path", 1, "-dt", h, "-values", *[c * k * h for k in range(n)])
    ops.pattern("MultipleSupport", 1)
    ops.groundMotion(1, "Plain", "-accel", 1)
    _imposed_at_node_1(ops)
    v = [c * (k * h) ** 2 / 2 for k in range(n)]
    d = [0.0]
    for k in range(1, n):
        d.append(d[-1] + h * (v[k - 1] + v[k]) / 2)
    te = (n - 1) * h
    assert ops.analyze(n - 1, h) == 0
    assert ops.nodeVel(1, 1) == pytest.approx(v[-1], rel=1e-9)
    assert ops.nodeDisp(1, 1) == pytest.approx(d[-1], rel=1e-9)
    assert ops.analyze(1, h) == 0
    v_end = v[-1] + h * c * te / 2
    assert ops.nodeVel(1, 1) == pytest.approx(v_end, rel=1e-9)
    assert ops.nodeDisp(1, 1) == pytest.approx(d[-1] + h * (v[-1] + v_end) / 2, rel=1e-9)
    assert ops.analyze(1, h) == 0
    assert ops.nodeDisp(1, 1) == 0.0 and ops.nodeVel(1, 1) == 0.0


def _imposed_at_node_1(ops):
    """Ground motion 1 imposed on node 1, dof 1; a linear Newmark analysis."""
    ops.imposedMotion(1, 1, 1)
    ops.constraints("Transformation")
    ops.numberer("Plain")
    ops.system("FullGeneral")
    ops.test("NormDispIncr", 1e-12, 10)
    ops.algorithm("Linear")
    ops.integrator("Newmark", 0.5, 0.25)
    ops.analysis("Transient")


def test_integrated_motion_of_an_explicit_time_path_ends_at_its_last_time(ops):
    """A '-time' path a = 6 t on [0, 4] (values 0, 12, fact 2): v = 3 t^2 and
    d = t^3 + 6 h^2 t / 12 (the trapezoids' error for a quadratic) at t = 4,
    and 0 one step later (no extra step, unlike a '-dt' path; OpenSeesPy 3.7.1:
    48 and 64.0002, then 0)."""
    _sdof(ops)
    ops.timeSeries("Path", 1, "-time", 0.0, 4.0, "-values", 0.0, 12.0)
    ops.pattern("MultipleSupport", 1)
    ops.groundMotion(1, "Plain", "-accel", 1, "-fact", 2.0)
    _imposed_at_node_1(ops)
    assert ops.analyze(400, 0.01) == 0
    assert ops.nodeVel(1, 1) == pytest.approx(48.0, rel=1e-9)
    assert ops.nodeDisp(1, 1) == pytest.approx(64.0 + 6 * 0.01**2 * 4 / 12, rel=1e-9)
    assert ops.analyze(1, 0.01) == 0
    assert ops.nodeDisp(1, 1) == 0.0 and ops.nodeVel(1, 1) == 0.0

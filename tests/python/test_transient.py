"""Transient analysis of a spring-mass oscillator against closed forms.

The model is one zeroLength spring k with a nodal mass m (1D); the load is
a Path series sampled at the analysis steps, so P(t_n) is exact. Checked:
- Newmark average acceleration: energy 1/2 m v^2 + 1/2 k u^2 of free
  vibration constant to round-off; the step's amplification matrix, fitted
  from the computed (u, v) sequence, has |lambda| = 1 and phase
  2 atan(w dt / 2) (period elongation, Chopra Table 5.3.1 / Hughes 9.3);
  the measured free-vibration period at dt = T/20 equals that elongated
  period; the response to P sin(w t) at resonance from rest matches
  P/(2k) (sin wt - wt cos wt);
- Rayleigh damping: the logarithmic decrement of free vibration gives
  zeta = alphaM / (2 w) + betaK w / 2;
- HHT: the spectral radius of its 3x3 amplification matrix, fitted from
  (u, v dt, a dt^2), at w dt = 1e6 is rho_inf = alpha / (2 - alpha)
  (Hilber, Hughes, Taylor 1977, with OpenSees' alpha = 1 + alpha_HHT);
- TRBDF2: the resonance response converges at second order;
- -doRayleigh 0 leaves a zeroLength undamped by betaK, alphaM still damps nodal mass;
- a failed step leaves u, v, a and time exactly at the last converged state;
- betaKcomm given after a static push past yield damps the first dynamic
  step with the yielded tangent (Linear step: du = dP / (kt (1 + betaKcomm
  gamma / (beta dt)) + m / (beta dt^2))).
"""
import math

import numpy as np
import pytest

import beamsolid

K, M = 400.0, 4.0
W = math.sqrt(K / M)
T = 2 * math.pi / W


def oscillator(m, integrator, dt, loads, rayleigh=None, test=("NormDispIncr", 1e-14, 10)):
    """SDOF with the load history `loads` sampled at t = 0, dt, 2 dt, ..."""
    m.model("basic", "-ndm", 1, "-ndf", 1)
    m.node(1, 0.0)
    m.node(2, 0.0)
    m.fix(1, 1)
    m.mass(2, M)
    m.uniaxialMaterial("Elastic", 1, K)
    m.element("zeroLength", 1, 1, 2, "-mat", 1, "-dir", 1, "-doRayleigh", 1)
    m.timeSeries("Path", 1, "-dt", dt, "-values", *loads)
    m.pattern("Plain", 1, 1)
    m.load(2, 1.0)
    if rayleigh:
        m.rayleigh(*rayleigh)
    m.constraints("Plain")
    m.numberer("Plain")
    m.system("FullGeneral")
    m.test(*test)
    m.algorithm("Newton")
    m.integrator(*integrator)
    m.analysis("Transient")


def run(m, steps, dt):
    rows = []
    for _ in range(steps):
        assert m.analyze(1, dt) == 0
        rows.append((m.nodeDisp(2, 1), m.nodeVel(2, 1), m.nodeAccel(2, 1)))
    return np.array(rows)


def pulse(steps):
    """A one-step load pulse, then free vibration."""
    return [0.0, 100.0] + [0.0] * (steps + 2)


def fitted_amplification(states):
    """A with states[n+1] = A states[n] (least squares over the sequence)."""
    x0, x1 = states[:-1].T, states[1:].T
    return x1 @ np.linalg.pinv(x0)


def test_average_acceleration_conserves_energy_to_round_off(model):
    dt, steps = T / 20, 400
    oscillator(model, ("Newmark", 0.5, 0.25), dt, pulse(steps))
    r = run(model, steps, dt)
    energy = 0.5 * M * r[2:, 1] ** 2 + 0.5 * K * r[2:, 0] ** 2  # free from step 2 on
    assert energy[0] > 0.0
    drift = np.max(np.abs(energy - energy[0])) / energy[0]
    assert drift < 1e-12, drift


def test_average_acceleration_period_elongation_matches_the_formula(model):
    dt, steps = T / 20, 400
    oscillator(model, ("Newmark", 0.5, 0.25), dt, pulse(steps))
    r = run(model, steps, dt)
    A = fitted_amplification(r[2:60, :2] * [1.0, dt])
    lam = np.linalg.eigvals(A)
    assert np.allclose(np.abs(lam), 1.0, atol=1e-10)
    phase = np.max(np.abs(np.angle(lam)))
    assert abs(phase - 2 * math.atan(W * dt / 2)) < 1e-10
    # The same elongation read from the zero crossings of u over 19 periods.
    u = r[2:, 0]
    t = dt * (np.arange(len(u)) + 3)
    up = [t[i] - u[i] * dt / (u[i + 1] - u[i]) for i in range(len(u) - 1) if u[i] < 0.0 <= u[i + 1]]
    measured = (up[-1] - up[0]) / (len(up) - 1)
    expected = 2 * math.pi * dt / (2 * math.atan(W * dt / 2))
    assert abs(measured / expected - 1) < 2e-5, (measured, expected)
    assert measured / T - 1 > 0.008  # the elongation (0.82 %) is really there


# Newmark average acceleration (measured 3.0e-4 at T/400) and TRBDF2, second
# order as well (OpenSees' full-dt sub-steps: measured 6.0e-4 at T/400).
@pytest.mark.parametrize("integrator, tol", [(("Newmark", 0.5, 0.25), 5e-4), (("TRBDF2",), 8e-4)])
def test_resonant_harmonic_load_grows_as_the_closed_form(model, integrator, tol):
    p, errors = 10.0, []
    for per_period in (200, 400):
        dt, steps = T / per_period, 5 * per_period  # five periods
        model.wipe()
        oscillator(model, integrator, dt, [p * math.sin(W * n * dt) for n in range(steps + 2)])
        r = run(model, steps, dt)
        t = dt * np.arange(1, steps + 1)
        exact = p / (2 * K) * (np.sin(W * t) - W * t * np.cos(W * t))
        errors.append(np.max(np.abs(r[:, 0] - exact)) / np.max(np.abs(exact)))
        assert np.max(np.abs(exact)) > 15 * p / K  # growing linearly: 5 pi P / k after five periods
    # Phase error (w dt)^2 / 12 per radian over w t = 10 pi: 6.5e-4 at T/400.
    assert errors[1] < tol, errors
    assert 3.8 < errors[0] / errors[1] < 4.2, errors  # second order


@pytest.mark.parametrize("rayleigh", [(0.8, 0.0, 0.0, 0.0), (0.0, 0.005, 0.0, 0.0), (0.0, 0.0, 0.005, 0.0)])
def test_logarithmic_decrement_gives_the_rayleigh_damping_ratio(model, rayleigh):
    dt, steps = T / 400, 4000
    oscillator(model, ("Newmark", 0.5, 0.25), dt, pulse(steps), rayleigh=rayleigh)
    r = run(model, steps, dt)
    u = r[2:, 0]
    peaks = [i for i in range(1, len(u) - 1) if u[i - 1] < u[i] >= u[i + 1] and u[i] > 0]

    def peak(i):  # parabola through three samples
        a, b, c = u[i - 1], u[i], u[i + 1]
        return b - 0.125 * (a - c) ** 2 / (a - 2 * b + c)

    n = len(peaks) - 1
    delta = math.log(peak(peaks[0]) / peak(peaks[-1])) / n
    zeta = delta / math.sqrt(4 * math.pi ** 2 + delta ** 2)
    expected = rayleigh[0] / (2 * W) + (rayleigh[1] + rayleigh[2]) * W / 2
    assert expected == pytest.approx(0.04 if rayleigh[0] else 0.025)
    assert abs(zeta / expected - 1) < 2e-3, (zeta, expected)


# At alpha = 2/3 the spurious root joins the principal pair at rho_inf: a
# triple root, whose fitted eigenvalues are perturbed as the cube root of the
# O(1 / (w dt)^2) distance from the limit (observed 7e-5 at w dt = 1e6).
@pytest.mark.parametrize("alpha, tol", [(2.0 / 3.0, 3e-4), (0.8, 1e-6), (0.9, 1e-6)])
def test_hht_spectral_radius_at_high_frequency(model, alpha, tol):
    dt = 1e6 / W
    oscillator(model, ("HHT", alpha), dt, pulse(20))
    r = run(model, 12, dt)
    A = fitted_amplification(r[2:9] * [1.0, dt, dt * dt])
    rho = np.max(np.abs(np.linalg.eigvals(A)))
    assert abs(rho - alpha / (2 - alpha)) < tol, (rho, alpha / (2 - alpha))


def test_hht_with_alpha_one_is_newmark(model):
    dt, steps = T / 30, 60
    oscillator(model, ("HHT", 1.0), dt, pulse(steps), rayleigh=(0.3, 0.001, 0.0, 0.0))
    hht = run(model, steps, dt)
    model.wipe()
    oscillator(model, ("Newmark", 0.5, 0.25), dt, pulse(steps), rayleigh=(0.3, 0.001, 0.0, 0.0))
    newmark = run(model, steps, dt)
    assert np.max(np.abs(hht - newmark)) <= 1e-14 * np.max(np.abs(newmark))


@pytest.mark.parametrize("integrator", [("Newmark", 0.5, 0.25), ("HHT", 0.7), ("Newmark", 0.5, 0.25, "-form", "A")])
def test_failed_step_reverts_displacement_velocity_and_acceleration(model, integrator):
    dt = T / 25
    oscillator(model, integrator, dt, [0.0] + [50.0 * math.sin(0.3 * n) for n in range(1, 40)],
               rayleigh=(0.2, 0.001, 0.0, 0.0))
    run(model, 5, dt)
    before = (model.getTime(), model.nodeDisp(2, 1), model.nodeVel(2, 1), model.nodeAccel(2, 1))
    model.test("NormDispIncr", 1e-30, 1)  # cannot converge in one iteration
    assert model.analyze(1, dt) < 0
    assert "failed to converge" in model.last_error()
    after = (model.getTime(), model.nodeDisp(2, 1), model.nodeVel(2, 1), model.nodeAccel(2, 1))
    assert after == before
    # Carrying on gives exactly what an uninterrupted run gives.
    model.test("NormDispIncr", 1e-14, 10)
    resumed = run(model, 3, dt)
    model.wipe()
    oscillator(model, integrator, dt, [0.0] + [50.0 * math.sin(0.3 * n) for n in range(1, 40)],
               rayleigh=(0.2, 0.001, 0.0, 0.0))
    straight = run(model, 8, dt)
    assert np.array_equal(resumed, straight[5:])


def test_central_difference_needs_the_linear_algorithm(model):
    dt = T / 50
    oscillator(model, ("CentralDifference",), dt, pulse(10))
    assert model.analyze(1, dt) == 0  # the first step's predictor is exact: one update
    assert model.analyze(1, dt) < 0
    model.algorithm("Linear")
    assert model.analyze(3, dt) == 0


def test_transient_command_errors(model):
    oscillator(model, ("Newmark", 0.5, 0.25), 0.01, pulse(5))
    with pytest.raises(beamsolid.OpenSeesError, match="analyze.*dt"):
        model.analyze(1)
    with pytest.raises(beamsolid.OpenSeesError, match="analyze.*dt must be positive"):
        model.analyze(1, -0.01)
    with pytest.raises(beamsolid.OpenSeesError, match="rayleigh.*betaKcomm"):
        model.rayleigh(0.1, 0.0, 0.0)
    with pytest.raises(beamsolid.OpenSeesError, match="integrator Newmark.*form"):
        model.integrator("Newmark", 0.5, 0.25, "-form", "X")
    with pytest.raises(beamsolid.OpenSeesError, match="integrator HHT.*alpha"):
        model.integrator("HHT", 1.5)
    model.integrator("LoadControl", 0.1)
    with pytest.raises(beamsolid.OpenSeesError, match="analysis Transient.*LoadControl is static"):
        model.analysis("Transient")
    model.integrator("Newmark", 0.5, 0.25)
    with pytest.raises(beamsolid.OpenSeesError, match="analysis Static.*Newmark is transient"):
        model.analysis("Static")


def test_do_rayleigh_flag_of_zero_length_and_nodal_mass_damping(model):
    """betaK damps a zeroLength only with -doRayleigh 1; alphaM on nodal mass always."""
    dt, steps = T / 50, 100

    def response(flag, rayleigh):
        model.wipe()
        oscillator(model, ("Newmark", 0.5, 0.25), dt, pulse(steps), rayleigh=rayleigh)
        model.remove("element", 1)
        model.element("zeroLength", 1, 1, 2, "-mat", 1, "-dir", 1, "-doRayleigh", flag)
        return run(model, steps, dt)

    undamped = response(0, None)
    assert np.array_equal(response(0, (0.0, 0.01, 0.0, 0.0)), undamped)
    damped = response(1, (0.0, 0.01, 0.0, 0.0))
    assert np.max(np.abs(damped[-20:, 0])) < 0.7 * np.max(np.abs(undamped[-20:, 0]))
    # Mass-proportional damping acts on the nodal mass whatever the flag.
    assert np.array_equal(response(0, (0.5, 0.0, 0.0, 0.0)), response(1, (0.5, 0.0, 0.0, 0.0)))
    assert not np.array_equal(response(0, (0.5, 0.0, 0.0, 0.0)), undamped)


@pytest.mark.parametrize("solver", [(), ("-fullGenLapack",)])
def test_eigen_before_and_after_gravity_with_pdelta(solver):
    """A cantilever column (one elasticBeamColumn, PDelta) with a lumped mass m at its
    top: its lateral stiffness is 3EI/L^3 (the top rotation condensed), and a gravity load
    P held by loadConst lowers it by P-Delta's P/L, so omega^2 goes from 3EI/(m L^3) to
    (3EI/L^3 - P/L)/m, exactly for one element."""
    import beamsolid

    E, A, I, L, m, P = 200e6, 0.01, 8e-5, 4.0, 50.0, 300.0
    model = beamsolid.Model()
    model.model("basic", "-ndm", 2, "-ndf", 3)
    model.node(1, 0.0, 0.0)
    model.node(2, 0.0, L)
    model.fix(1, 1, 1, 1)
    model.mass(2, m, 1e-9 * m, 0.0)
    model.geomTransf("PDelta", 1)
    model.element("elasticBeamColumn", 1, 1, 2, A, E, I, 1)
    before = model.eigen(*solver, 1)[0]
    assert before == pytest.approx(3 * E * I / L**3 / m, rel=1e-12)
    model.timeSeries("Linear", 1)
    model.pattern("Plain", 1, 1)
    model.load(2, 0.0, -P, 0.0)
    model.system("UmfPack")
    model.test("NormDispIncr", 1e-12, 10)
    model.algorithm("Newton")
    model.integrator("LoadControl", 0.1)
    model.analysis("Static")
    assert model.analyze(10) == 0
    model.loadConst("-time", 0.0)
    after = model.eigen(*solver, 1)[0]
    # The axial shortening (P L / EA) changes L by 6e-6 relative; the chord keeps its length in
    # the PDelta transformation, so the closed form holds to round-off.
    assert after == pytest.approx((3 * E * I / L**3 - P / L) / m, rel=1e-10)
    assert after < before
    model.wipe()


@pytest.mark.parametrize("factors, damped_k", [((0.0, 0.0, 0.0, 0.004), "tangent"),
                                               ((0.0, 0.0, 0.004, 0.0), "initial")])
def test_committed_stiffness_damping_given_after_a_static_push(model, factors, damped_k):
    """A Steel01 truss yielded statically, then rayleigh(); one Linear step of
    a load dP: betaKcomm uses the yielded (committed) tangent at once, not the
    initial stiffness (before, BeamSolid used k0 until the next commit)."""
    E, fy, b, A, L, m, dt, dP = 2.0e5, 250.0, 0.05, 1.0e-3, 2.0, 1.0e-3, 0.005, 20.0
    model.model("basic", "-ndm", 1, "-ndf", 1)
    model.node(1, 0.0)
    model.node(2, L)
    model.fix(1, 1)
    model.mass(2, m)
    model.uniaxialMaterial("Steel01", 1, fy, E, b)
    model.element("Truss", 1, 1, 2, A, 1, "-doRayleigh", 1)
    model.timeSeries("Linear", 1)
    model.pattern("Plain", 1, 1)
    model.load(2, 1.0)
    model.constraints("Plain")
    model.numberer("Plain")
    model.system("FullGeneral")
    model.test("NormDispIncr", 1e-12, 20)
    model.algorithm("Newton")
    model.integrator("DisplacementControl", 2, 1, 1.0e-3)
    model.analysis("Static")
    assert model.analyze(6) == 0
    u0 = model.nodeDisp(2, 1)
    model.loadConst("-time", 0.0)
    model.rayleigh(*factors)
    model.wipeAnalysis()
    model.timeSeries("Constant", 2)
    model.pattern("Plain", 2, 2)
    model.load(2, dP)
    model.constraints("Plain")
    model.numberer("Plain")
    model.system("FullGeneral")
    model.algorithm("Linear")
    model.integrator("Newmark", 0.5, 0.25)
    model.analysis("Transient")
    assert model.analyze(1, dt) == 0
    k0, kt = E * A / L, b * E * A / L
    beta_d = 0.004
    kd = kt if damped_k == "tangent" else k0
    expected = dP / (kt + beta_d * kd * 0.5 / (0.25 * dt) + m / (0.25 * dt * dt))
    assert model.nodeDisp(2, 1) - u0 == pytest.approx(expected, rel=1e-12)

"""integrator('ExplicitDifference') against closed forms on a spring-mass.

The leapfrog scheme on m u'' + k u = P is a two-step recurrence with
characteristic roots of modulus 1 while w dt < 2: the discrete frequency is
w~ = (2 / dt) asin(w dt / 2) (period shortening), and past w dt = 2 a root
exceeds 1 in modulus, so the response grows without bound. Measured: the
period of a step load's oscillation about P/k at dt = T/10 against 2 pi / w~
within 1e-3 (measured 2e-5; crossings located by linear interpolation);
bounded just below dt = 2/w, growing by orders of magnitude just above.
"""
import math

import pytest

import beamsolid.opensees as ops

M, K, P = 2.0, 100.0, 10.0
OMEGA = math.sqrt(K / M)


def _run(dt, steps):
    ops.wipe()
    ops.model("basic", "-ndm", 1, "-ndf", 1)
    ops.node(1, 0.0)
    ops.node(2, 0.0)
    ops.fix(1, 1)
    ops.mass(2, M)
    ops.uniaxialMaterial("Elastic", 1, K)
    ops.element("zeroLength", 1, 1, 2, "-mat", 1, "-dir", 1)
    ops.timeSeries("Constant", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, P)
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.system("FullGeneral")
    ops.algorithm("Linear")
    ops.integrator("ExplicitDifference")
    ops.analysis("Transient")
    out = []
    for _ in range(steps):
        assert ops.analyze(1, dt) == 0
        out.append((ops.getTime(), ops.nodeDisp(2, 1)))
    ops.wipe()
    return out


def test_period_is_the_leapfrog_discrete_period():
    dt = 2.0 * math.pi / OMEGA / 10.0
    rows = _run(dt, 400)
    # Upward crossings of the static position P/k, by linear interpolation.
    static = P / K
    crossings = [a[0] + (static - a[1]) * (b[0] - a[0]) / (b[1] - a[1])
                 for a, b in zip(rows, rows[1:]) if a[1] < static <= b[1]]
    period = (crossings[-1] - crossings[0]) / (len(crossings) - 1)
    discrete = 2.0 * math.pi / ((2.0 / dt) * math.asin(OMEGA * dt / 2.0))
    assert period == pytest.approx(discrete, rel=1e-3)
    # The shortening (1.6% here) is seen: not the exact period.
    assert abs(period - 2.0 * math.pi / OMEGA) > 1e-2 * period


def test_stability_limit_is_two_over_omega():
    critical = 2.0 / OMEGA
    below = _run(0.98 * critical, 400)
    early = max(abs(u) for _, u in below[:100])
    assert max(abs(u) for _, u in below[100:]) <= 1.05 * early  # bounded
    above = _run(1.02 * critical, 400)
    assert max(abs(u) for _, u in above[300:]) > 1e3 * max(abs(u) for _, u in above[:20])  # grows


def test_needs_the_linear_algorithm():
    ops.wipe()
    ops.model("basic", "-ndm", 1, "-ndf", 1)
    ops.node(1, 0.0)
    ops.node(2, 0.0)
    ops.fix(1, 1)
    ops.mass(2, M)
    ops.uniaxialMaterial("Elastic", 1, K)
    ops.element("zeroLength", 1, 1, 2, "-mat", 1, "-dir", 1)
    ops.timeSeries("Constant", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, P)
    ops.test("NormDispIncr", 1e-30, 5)
    ops.algorithm("Newton")
    ops.integrator("ExplicitDifference")
    ops.analysis("Transient")
    assert ops.analyze(1, 0.01) < 0  # a second update in a step fails
    ops.wipe()

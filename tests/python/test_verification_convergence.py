"""Per-iteration norms through testIter()/testNorm() on a one-equation nonlinear model.

The apex of a shallow two-bar corotational (von Mises) truss, restrained to
move vertically, has the exact equilibrium curve P(w) and tangent K(w) =
dP/dw. In one dimension the convergence constants are closed forms too:
Newton: dw_{k+1} / dw_k^2 -> |K'(w*) / (2 K(w*))|;
a fixed tangent K_f (ModifiedNewton: the tangent at the start of the step,
-initial: K(0)): dw_{k+1} / dw_k -> 1 - K(w*) / K_f.
"""
import math

import numpy as np
import pytest

A_HALF, RISE, EA = 4.0, 0.5, 1.0e4
L0 = math.hypot(A_HALF, RISE)


def load(w):
    L = math.hypot(A_HALF, RISE - w)
    return 2.0 * EA * (RISE - w) * (1.0 / L - 1.0 / L0)


def stiffness(w):
    return 2.0 * EA * (1.0 / L0 - A_HALF**2 / math.hypot(A_HALF, RISE - w) ** 3)


def stiffness_slope(w):
    L = math.hypot(A_HALF, RISE - w)
    return -6.0 * EA * A_HALF**2 * (RISE - w) / L**5


def exact_deflection(P):
    """w on the stable branch with load(w) = P, by bisection (independent of the FE code)."""
    lo, hi = 0.0, RISE - math.sqrt((A_HALF**2 * L0) ** (2.0 / 3.0) - A_HALF**2)  # up to the limit point
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if load(mid) < P else (lo, mid)
    return 0.5 * (lo + hi)


W_LIMIT = RISE - math.sqrt((A_HALF**2 * L0) ** (2.0 / 3.0) - A_HALF**2)
P_REF = 0.8 * load(W_LIMIT)


def truss(m, algorithm, test=("NormDispIncr", 1e-12, 80)):
    m.model("basic", "-ndm", 3, "-ndf", 3)
    m.node(1, -A_HALF, 0.0, 0.0)
    m.node(2, A_HALF, 0.0, 0.0)
    m.node(3, 0.0, 0.0, RISE)
    m.fix(1, 1, 1, 1)
    m.fix(2, 1, 1, 1)
    m.fix(3, 1, 1, 0)
    m.uniaxialMaterial("Elastic", 1, EA)
    m.element("corotTruss", 1, 1, 3, 1.0, 1)
    m.element("corotTruss", 2, 2, 3, 1.0, 1)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.load(3, 0.0, 0.0, -P_REF)
    m.constraints("Plain")
    m.numberer("Plain")
    m.system("UmfPack")
    m.test(*test)
    m.algorithm(*algorithm)
    m.integrator("LoadControl", 0.5)
    m.analysis("Static")


def two_steps(m):
    """Runs to 0.5 and 1.0; returns the norms of the second step and both converged w."""
    assert m.analyze(1) == 0
    w1 = -m.nodeDisp(3, 3)
    assert m.analyze(1) == 0
    norms = m.testNorm()[: m.testIter()]  # padded with zeros to maxIter, as OpenSees
    assert m.testIter() == len(norms)
    w2 = -m.nodeDisp(3, 3)
    assert w1 == pytest.approx(exact_deflection(0.5 * P_REF), rel=1e-10)
    assert w2 == pytest.approx(exact_deflection(P_REF), rel=1e-10)
    return np.array(norms), w1, w2


def test_newton_converges_quadratically(model):
    truss(model, ("Newton",))
    norms, _, w2 = two_steps(model)
    # Measured (second step): 6 iterations, norms 5.2e-2, 1.5e-2, 1.2e-3, 8.6e-6,
    # 4.2e-10, 7.5e-15; dw_4 / dw_3^2 = 5.7117 against |K'/2K| = 5.7117.
    assert len(norms) <= 6
    constant = abs(stiffness_slope(w2) / (2 * stiffness(w2)))
    observed = norms[2:-1] / norms[1:-2] ** 2
    assert observed[-1] == pytest.approx(constant, rel=0.02), observed
    orders = np.log(norms[2:-1] / norms[1:-2]) / np.log(norms[1:-2] / norms[:-3])
    assert orders[-1] > 1.8, orders


@pytest.mark.parametrize("algorithm,which", [(("ModifiedNewton",), "step start"),
                                             (("Newton", "-initial"), "initial"),
                                             (("ModifiedNewton", "-initial"), "initial")])
def test_fixed_tangent_converges_linearly_at_the_predicted_rate(model, algorithm, which):
    truss(model, algorithm)
    norms, w1, w2 = two_steps(model)
    fixed = stiffness(w1) if which == "step start" else stiffness(0.0)
    rate = 1.0 - stiffness(w2) / fixed
    # Measured over the iterations with 1e-10 < dw < 1e-4 (above round-off,
    # in the asymptotic range): ModifiedNewton 0.45491 .. 0.45545 against
    # 1 - K(w*)/K(w1) = 0.45544, 31 iterations; -initial 0.59185 .. 0.59259
    # against 1 - K(w*)/K(0) = 0.59259, 46 iterations.
    assert 0.4 < rate < 0.65
    ratios = norms[1:] / norms[:-1]
    window = (norms[:-1] < 1e-4) & (norms[1:] > 1e-10)
    assert window.sum() >= 10
    assert np.all(np.abs(ratios[window] - rate) < 2e-3 * rate), (rate, ratios[window])
    # The other fixed tangent would give a clearly different rate.
    other = 1.0 - stiffness(w2) / (stiffness(0.0) if which == "step start" else stiffness(w1))
    assert abs(other - rate) > 0.1


def test_initial_then_current_is_quadratic_after_the_first_iteration(model):
    truss(model, ("Newton", "-initialThenCurrent"))
    norms, w1, w2 = two_steps(model)
    # The first correction uses K(0): its size is exactly (P - P(w1)) / K(0).
    assert norms[0] == pytest.approx((P_REF - load(w1)) / stiffness(0.0), rel=1e-10)
    constant = abs(stiffness_slope(w2) / (2 * stiffness(w2)))
    assert (norms[-2] / norms[-3] ** 2) == pytest.approx(constant, rel=0.05), norms
    assert len(norms) <= 7


def test_newton_first_correction_and_unbalance_norms(model):
    """NormUnbalance: the first norm is the residual after the first correction, exactly."""
    truss(model, ("Newton",), test=("NormUnbalance", 1e-10, 20))
    assert model.analyze(1) == 0
    w1 = -model.nodeDisp(3, 3)
    assert model.analyze(1) == 0
    norms = model.testNorm()[: model.testIter()]  # padded with zeros to maxIter, as OpenSees
    w_first = w1 + (P_REF - load(w1)) / stiffness(w1)
    assert norms[0] == pytest.approx(abs(P_REF - load(w_first)), rel=1e-8)
    assert norms[-1] <= 1e-10 < norms[-2]
    assert model.testIter() == len(norms)

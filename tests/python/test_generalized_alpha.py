"""integrator('GeneralizedAlpha', alphaM, alphaF, <gamma, beta>) against an
independent recurrence: for a linear damped SDOF (m, c, k, constant load f)
each step solves
  m A_m + c V_f + k U_f = f,   X_m = (1 - alphaM) X_n + alphaM X_n+1,
  U_f, V_f likewise with alphaF,
with Newmark's relations between U, V, A at n+1 (OpenSees' convention:
alphaM = alphaF = 1 is Newmark). Linear, so 1e-10 relative; the defaults
gamma = 1/2 + alphaM - alphaF and beta = (1 + alphaM - alphaF)^2 / 4.
"""
import pytest

import beamsolid

M, C, K, F, DT = 1.5, 0.8, 120.0, 2.0, 0.03


def recurrence(alphaM, alphaF, gamma, beta, steps):
    u = v = a = 0.0
    out = []
    for _ in range(steps):
        # U, V, A at n+1 are linear in u1: evaluate the residual at two points.
        def state(u1):
            a1 = (u1 - u) / (beta * DT * DT) - v / (beta * DT) - (0.5 / beta - 1.0) * a
            v1 = v + DT * ((1.0 - gamma) * a + gamma * a1)
            am = (1 - alphaM) * a + alphaM * a1
            vf = (1 - alphaF) * v + alphaF * v1
            uf = (1 - alphaF) * u + alphaF * u1
            return F - M * am - C * vf - K * uf, v1, a1

        r0, r1 = state(0.0)[0], state(1.0)[0]
        u1 = -r0 / (r1 - r0)
        _, v1, a1 = state(u1)
        u, v, a = u1, v1, a1
        out.append((u, v, a))
    return out


def run_sdof(model, args, steps):
    model.model("basic", "-ndm", 1, "-ndf", 1)
    model.node(1, 0.0)
    model.node(2, 0.0)
    model.fix(1, 1)
    model.mass(2, M)
    model.uniaxialMaterial("Elastic", 1, K, 0.0)
    model.uniaxialMaterial("Viscous", 2, C, 1.0)
    model.element("zeroLength", 1, 1, 2, "-mat", 1, 2, "-dir", 1, 1)
    model.timeSeries("Constant", 1)
    model.pattern("Plain", 1, 1)
    model.load(2, F)
    model.system("FullGeneral")
    model.constraints("Plain")
    model.numberer("Plain")
    model.test("NormDispIncr", 1e-14, 10)
    model.algorithm("Newton")
    model.integrator("GeneralizedAlpha", *args)
    model.analysis("Transient")
    out = []
    for _ in range(steps):
        assert model.analyze(1, DT) == 0
        assert model.testIter() <= 2  # consistent tangent: a linear step converges at once
        out.append((model.nodeDisp(2, 1), model.nodeVel(2, 1), model.nodeAccel(2, 1)))
    return out


@pytest.mark.parametrize("args", [(1.0, 0.8), (1.2, 0.9), (0.95, 0.75), (1.1, 0.85, 0.7, 0.4), (1.0, 1.0)])
def test_matches_the_recurrence(model, args):
    alphaM, alphaF = args[:2]
    gamma, beta = args[2:] if len(args) == 4 else (0.5 + alphaM - alphaF, 0.25 * (1 + alphaM - alphaF) ** 2)
    got = run_sdof(model, args, 12)
    want = recurrence(alphaM, alphaF, gamma, beta, 12)
    scale = [max(abs(w[i]) for w in want) for i in range(3)]
    for g, w in zip(got, want):
        for i in range(3):
            assert abs(g[i] - w[i]) <= 1e-10 * scale[i]


@pytest.mark.parametrize("args, words", [
    ((1.0,), "alphaF"),
    ((0.0, 0.8), "alphaM"),
    ((1.0, 1.5), "alphaF"),
    ((1.0, 0.8, 0.5), "beta"),
    ((1.0, 0.8, -0.5, 0.25), "gamma"),
    ((1.0, 0.8, 0.5, 0.25, 3), "argument"),
])
def test_bad_input_names_the_argument(model, args, words):
    model.model("basic", "-ndm", 1, "-ndf", 1)
    with pytest.raises(beamsolid.OpenSeesError) as info:
        model.integrator("GeneralizedAlpha", *args)
    assert "GeneralizedAlpha" in str(info.value) and words in str(info.value)


def test_hht_generalized_is_generalized_alpha_under_another_name(model):
    # integrator('HHTGeneralized', alphaI, alphaF, <beta, gamma>) is
    # GeneralizedAlpha with alphaM = alphaI and beta, gamma swapped in order:
    # both give the same history on an SDOF, defaults and given values.
    def history(*args):
        model.wipe()
        model.model("basic", "-ndm", 1, "-ndf", 1)
        model.node(1, 0.0)
        model.node(2, 0.0)
        model.fix(1, 1)
        model.mass(2, 2.0)
        model.uniaxialMaterial("Elastic", 1, 50.0)
        model.element("zeroLength", 1, 1, 2, "-mat", 1, "-dir", 1)
        model.timeSeries("Linear", 1)
        model.pattern("Plain", 1, 1)
        model.load(2, 10.0)
        model.constraints("Plain")
        model.numberer("Plain")
        model.system("FullGeneral")
        model.test("NormDispIncr", 1e-12, 20)
        model.algorithm("Newton")
        model.integrator(*args)
        model.analysis("Transient")
        out = []
        for _ in range(6):
            assert model.analyze(1, 0.05) == 0
            out.append(model.nodeDisp(2, 1))
        return out
    assert history("HHTGeneralized", 0.9, 0.8) == pytest.approx(history("GeneralizedAlpha", 0.9, 0.8), rel=1e-14)
    assert history("HHTGeneralized", 1.0, 0.7, 0.3, 0.65) == pytest.approx(
        history("GeneralizedAlpha", 1.0, 0.7, 0.65, 0.3), rel=1e-14)
    assert history("HHTGeneralized", 1.0, 0.8) == pytest.approx(history("HHT", 0.8), rel=1e-14)

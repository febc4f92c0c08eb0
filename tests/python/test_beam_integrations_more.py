"""The beamIntegration rules UserDefined, FixedLocation, MidDistance, LowOrder,
Trapezoidal, CompositeSimpson, HingeMidpoint and HingeEndpoint: their points and weights from the
documented formulas, and an elastic forceBeamColumn cantilever whose tip
flexibility is the rule's sum of (L - x_i)^2 w_i L / EI (exactly L^3/(3 EI)
for rules exact for quadratics: FixedLocation with 3 or more points, LowOrder
with N - Nc >= 3, CompositeSimpson). Tolerance 1e-10 relative.
"""
import pytest

import beamsolid

L, E, A, I = 3.0, 2.0e5, 0.05, 4.0e-4
P = 10.0
G = 0.5 / 3**0.5  # two-point Gauss offset from the middle, as a fraction of the interval


def cantilever(m, rule, *args):
    m.model("basic", "-ndm", 2, "-ndf", 3)
    m.node(1, 0.0, 0.0)
    m.node(2, L, 0.0)
    m.fix(1, 1, 1, 1)
    m.section("Elastic", 1, E, A, I)
    m.section("Elastic", 2, E, A, 2 * I)
    m.geomTransf("Linear", 1)
    m.beamIntegration(rule, 1, *args)
    m.element("forceBeamColumn", 1, 1, 2, 1, 1)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.load(2, 0.0, P, 0.0)
    m.system("UmfPack")
    m.constraints("Plain")
    m.numberer("Plain")
    m.test("NormDispIncr", 1e-14, 10)
    m.algorithm("Newton")
    m.integrator("LoadControl", 1.0)
    m.analysis("Static")
    assert m.analyze(1) == 0


def points(m, n):
    return ([m.sectionLocation(1, i) / L for i in range(1, n + 1)],
            [m.sectionWeight(1, i) / L for i in range(1, n + 1)])


def tip_by_rule(xi, w, eis):
    return P * sum((L - x * L) ** 2 * wi * L / ei for x, wi, ei in zip(xi, w, eis))


CASES = [
    # rule, args, expected xi, expected weights, EI per point
    ("UserDefined", (5, 1, 2, 2, 2, 1, 0.1, 0.3, 0.5, 0.7, 0.9, 0.2, 0.15, 0.3, 0.15, 0.2),
     [0.1, 0.3, 0.5, 0.7, 0.9], [0.2, 0.15, 0.3, 0.15, 0.2], [1, 2, 2, 2, 1]),
    # Midpoints 0.1, 0.35, 0.65, 0.9 between 0, 0.2, 0.5, 0.8, 1. (The manual's example lists
    # 0.15, 0.2, 0.3, 0.2, 0.15, which contradicts its own formula; OpenSeesPy gives ours.)
    ("MidDistance", (5, 1, 2, 2, 2, 1, 0.0, 0.2, 0.5, 0.8, 1.0),
     [0.0, 0.2, 0.5, 0.8, 1.0], [0.1, 0.25, 0.3, 0.25, 0.1], [1, 2, 2, 2, 1]),
    # Three points at 0, 1/2, 1: Simpson's weights.
    ("FixedLocation", (3, 1, 1, 1, 0.0, 0.5, 1.0), [0.0, 0.5, 1.0], [1 / 6, 2 / 3, 1 / 6], [1, 1, 1]),
    # The manual's LowOrder example: w = 0.2 at 0 and 0.2 given; the other three integrate 1, x, x^2
    # with them: w2 + w3 + w4 = 0.6, 0.5 w2 + 0.8 w3 + w4 = 0.46, 0.25 w2 + 0.64 w3 + w4 = 1/3 - 0.008,
    # solved by hand.
    ("LowOrder", (5, 1, 2, 2, 2, 1, 0.0, 0.2, 0.5, 0.8, 1.0, 0.2, 0.2),
     [0.0, 0.2, 0.5, 0.8, 1.0], [0.2, 0.2, -34 / 225, 97 / 90, -49 / 150], [1, 2, 2, 2, 1]),
    # Nc = 0 is FixedLocation (Simpson at 0, 1/2, 1), Nc = N is UserDefined.
    ("LowOrder", (3, 1, 1, 1, 0.0, 0.5, 1.0), [0.0, 0.5, 1.0], [1 / 6, 2 / 3, 1 / 6], [1, 1, 1]),
    ("LowOrder", (3, 1, 2, 1, 0.9, 0.5, 0.1, 0.3, 0.3, 0.4), [0.9, 0.5, 0.1], [0.3, 0.3, 0.4], [1, 2, 1]),
    # One weight given at 0.9, the others integrate 1 and x: w1 + w2 = 0.7, 0.5 w1 + 0.1 w2 = 0.5 - 0.27.
    ("LowOrder", (3, 1, 2, 1, 0.9, 0.5, 0.1, 0.3), [0.9, 0.5, 0.1], [0.3, 0.4, 0.3], [1, 2, 1]),
    ("Trapezoidal", (1, 4), [0, 1 / 3, 2 / 3, 1], [1 / 6, 1 / 3, 1 / 3, 1 / 6], [1, 1, 1, 1]),
    ("Trapezoidal", (3, 1, 2, 1), [0, 0.5, 1], [0.25, 0.5, 0.25], [1, 2, 1]),
    ("CompositeSimpson", (1, 5), [0, 0.25, 0.5, 0.75, 1], [1 / 12, 1 / 3, 1 / 6, 1 / 3, 1 / 12], [1] * 5),
    ("CompositeSimpson", (3, 1, 2, 1), [0, 0.5, 1], [1 / 6, 2 / 3, 1 / 6], [1, 2, 1]),
    # Hinges lpI = 0.3 (a = 0.1 of L), lpJ = 0.6 (b = 0.2) of section 1, two Gauss points of section 2
    # on the interior 0.7 L; the hinge point at the hinge's middle or at the end, weighted lp.
    ("HingeMidpoint", (1, 0.3, 1, 0.6, 2), [0.05, 0.1 + 0.7 * (0.5 - G), 0.1 + 0.7 * (0.5 + G), 0.9],
     [0.1, 0.35, 0.35, 0.2], [1, 2, 2, 1]),
    ("HingeEndpoint", (1, 0.3, 1, 0.6, 2), [0.0, 0.1 + 0.7 * (0.5 - G), 0.1 + 0.7 * (0.5 + G), 1.0],
     [0.1, 0.35, 0.35, 0.2], [1, 2, 2, 1]),
]


@pytest.mark.parametrize("rule, args, xi, w, secs", CASES, ids=[f"{c[0]}{k}" for k, c in enumerate(CASES)])
def test_points_weights_and_tip_deflection(model, rule, args, xi, w, secs):
    cantilever(model, rule, *args)
    got_xi, got_w = points(model, len(xi))
    assert got_xi == pytest.approx(xi, rel=1e-12, abs=1e-14)
    assert got_w == pytest.approx(w, rel=1e-12)
    eis = [E * I * s for s in secs]
    assert model.nodeDisp(2, 2) == pytest.approx(tip_by_rule(xi, w, eis), rel=1e-10)


@pytest.mark.parametrize("rule, args", [
    ("FixedLocation", (3, 1, 1, 1, 0.1, 0.45, 0.8)),
    ("FixedLocation", (4, 1, 1, 1, 1, 0.0, 0.2, 0.7, 1.0)),
    ("LowOrder", (5, 1, 1, 1, 1, 1, 0.0, 0.2, 0.5, 0.8, 1.0, 0.2, 0.2)),
    ("CompositeSimpson", (1, 7)),
])
def test_rules_exact_for_quadratics_give_the_exact_cantilever(model, rule, args):
    cantilever(model, rule, *args)
    assert model.nodeDisp(2, 2) == pytest.approx(P * L**3 / (3 * E * I), rel=1e-10)


@pytest.mark.parametrize("rule, args, words", [
    ("UserDefined", (2, 1, 1, 0.2, 0.8, 0.5), "*wts"),
    ("UserDefined", (2, 1, 1, 0.2, 1.8, 0.5, 0.5), "loc"),
    ("FixedLocation", (2, 1, 1, 0.5, 0.5), "same location"),
    ("FixedLocation", (0,), "N"),
    ("LowOrder", (2, 1, 1, 0.2, 0.8, 0.5, 0.5, 0.5), "*wts"),
    ("LowOrder", (2, 1, 1, 0.2), "*locs"),
    ("LowOrder", (3, 1, 1, 1, 0.0, 0.5, 0.5, 0.2), "same location"),
    ("MidDistance", (3, 1, 1, 1, 0.5, 0.2, 0.9), "ascending"),
    ("MidDistance", (2, 1, 9, 0.2, 0.8), "9"),
    ("CompositeSimpson", (1, 4), "odd"),
    ("Trapezoidal", (1, 1), "N"),
])
def test_bad_input_names_the_argument(model, rule, args, words):
    model.model("basic", "-ndm", 2, "-ndf", 3)
    model.section("Elastic", 1, E, A, I)
    with pytest.raises(beamsolid.OpenSeesError) as info:
        model.beamIntegration(rule, 1, *args)
    assert f"beamIntegration {rule} 1" in str(info.value) and words in str(info.value)

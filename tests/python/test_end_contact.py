"""End bearing of a pile tip on soil: BeamEndContact3D (Lagrange) and BeamEndContact3Dp (penalty).

A pile (two elasticBeamColumns, head held laterally and in rotation) stands with its tip node on the
top centre node of a block of stdBrick soil. Checks against closed forms built from the soil's point
flexibility (the soil alone under a point load) and the pile's axial flexibility L/EA.
"""
import math

import pytest

import beamsolid

R = 0.3
E_PILE, L_PILE = 3e7, 5.0
E_SOIL, NU_SOIL = 1e4, 0.3
P = 100.0
TIP, HEAD, MULT, CONTACT = 1, 3, 900, 50
AREA = math.pi * R * R
PILE_FLEX = L_PILE / (E_PILE * AREA)


def soil_tag(i, j, k):
    return 100 + i + 5 * j + 25 * k


def build_soil(m):
    """Block [-1,1]^2 x [-1,0], 4 x 4 x 2 stdBricks, base fixed, sides on rollers; returns the top centre node."""
    m.model("basic", "-ndm", 3, "-ndf", 3)
    m.nDMaterial("ElasticIsotropic", 1, E_SOIL, NU_SOIL)
    for k in range(3):
        for j in range(5):
            for i in range(5):
                m.node(soil_tag(i, j, k), -1.0 + 0.5 * i, -1.0 + 0.5 * j, -1.0 + 0.5 * k)
                fx, fy, fz = int(k == 0 or i in (0, 4)), int(k == 0 or j in (0, 4)), int(k == 0)
                if fx or fy or fz:
                    m.fix(soil_tag(i, j, k), fx, fy, fz)
    tag = 1000
    for k in range(2):
        for j in range(4):
            for i in range(4):
                t = soil_tag
                m.element("stdBrick", tag, t(i, j, k), t(i + 1, j, k), t(i + 1, j + 1, k), t(i, j + 1, k),
                          t(i, j, k + 1), t(i + 1, j, k + 1), t(i + 1, j + 1, k + 1), t(i, j + 1, k + 1), 1)
                tag += 1
    return soil_tag(2, 2, 2)


def static(m, dt):
    m.constraints("Transformation")
    m.numberer("RCM")
    m.system("UmfPack")
    m.test("NormDispIncr", 1e-12, 25)
    m.algorithm("Newton")
    m.integrator("LoadControl", dt)
    m.analysis("Static")


def build_pile_on_soil(m, penalty=None):
    m.model("basic", "-ndm", 3, "-ndf", 6)
    for k in range(3):
        m.node(1 + k, 0.0, 0.0, 0.5 * L_PILE * k)
    m.fix(HEAD, 1, 1, 0, 1, 1, 1)
    m.geomTransf("Linear", 1, 1.0, 0.0, 0.0)
    inertia = math.pi * R**4 / 4.0
    for k in range(2):
        m.element("elasticBeamColumn", 1 + k, 1 + k, 2 + k, AREA, E_PILE, 1.2e7, 2 * inertia, inertia, inertia, 1)
    soil = build_soil(m)
    if penalty is None:
        m.node(MULT, 0.0, 0.0, 0.0)
        m.element("BeamEndContact3D", CONTACT, TIP, 2, soil, MULT, R, 1e-8, 1e-8)
    else:
        m.element("BeamEndContact3Dp", CONTACT, TIP, 2, soil, R, penalty)
    return soil


@pytest.fixture(scope="module")
def soil_flexibility():
    m = beamsolid.Model()
    centre = build_soil(m)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.load(centre, 0.0, 0.0, -P)
    static(m, 1.0)
    assert m.analyze(1) == 0
    flex = -m.nodeDisp(centre, 3) / P
    m.wipe()
    return flex


def test_head_load_is_carried_by_the_tip(ops, soil_flexibility):
    soil = build_pile_on_soil(ops)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(HEAD, 0.0, 0.0, -P, 0.0, 0.0, 0.0)
    static(ops, 0.25)
    assert ops.analyze(4) == 0
    assert ops.eleResponse(CONTACT, "forcescalar")[0] == pytest.approx(P, rel=1e-10)
    assert ops.eleResponse(CONTACT, "force") == pytest.approx([0.0, 0.0, -P], abs=1e-10 * P)
    assert ops.eleResponse(CONTACT, "masterforce") == pytest.approx([0.0, 0.0, P, 0.0, 0.0, 0.0], abs=1e-10 * P)
    assert ops.eleResponse(CONTACT, "status") == [1.0]
    assert ops.eleResponse(CONTACT, "normal") == pytest.approx([0.0, 0.0, -1.0], abs=1e-15)
    ops.reactions()
    base = sum(ops.nodeReaction(soil_tag(i, j, 0), 3) for i in range(5) for j in range(5))
    assert base == pytest.approx(P, rel=1e-9)
    settlement = -soil_flexibility * P
    scale = soil_flexibility * P
    assert abs(ops.eleResponse(CONTACT, "gap")[0]) <= 1e-12 * scale
    assert ops.nodeDisp(soil, 3) == pytest.approx(settlement, abs=1e-9 * scale)
    assert ops.nodeDisp(TIP, 3) == pytest.approx(settlement, abs=1e-9 * scale)
    assert ops.nodeDisp(HEAD, 3) == pytest.approx(settlement - PILE_FLEX * P, abs=1e-9 * scale)


def test_pull_releases_and_push_recloses_one_step_late(ops, soil_flexibility):
    fs, fp = soil_flexibility, PILE_FLEX
    soil = build_pile_on_soil(ops)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(HEAD, 0.0, 0.0, -P, 0.0, 0.0, 0.0)
    static(ops, 1.0)
    assert ops.analyze(1) == 0
    ops.loadConst("-time", 0.0)
    ops.wipeAnalysis()
    u0 = ops.nodeDisp(HEAD, 3)
    up = -0.5 * u0
    ops.timeSeries("Path", 2, "-time", 0.0, 1.0, 2.0, "-values", u0, up, u0)
    ops.pattern("Plain", 2, 2)
    ops.sp(HEAD, 3, 1.0)
    static(ops, 0.1)
    history = []
    in_contact = True
    scale = (fs + fp) * P
    for step in range(20):
        assert ops.analyze(1) == 0
        t = ops.getTime()
        wh = u0 + (up - u0) * t if t <= 1.0 else up + (u0 - up) * (t - 1.0)
        lam = ops.eleResponse(CONTACT, "forcescalar")[0]
        gap = ops.eleResponse(CONTACT, "gap")[0]
        assert ops.eleResponse(CONTACT, "status")[0] == (1.0 if in_contact else 0.0)
        if in_contact:
            assert lam == pytest.approx(-wh / (fs + fp), abs=1e-9 * P)
            assert abs(gap) <= 1e-12 * scale
        else:
            assert lam == 0.0
            assert gap == pytest.approx(wh, abs=1e-9 * scale)
            assert ops.nodeDisp(soil, 3) == pytest.approx(0.0, abs=1e-9 * scale)
        nxt = gap < 1e-8 and not (in_contact and lam <= -1e-8)
        if in_contact != nxt:
            history.append((round(t, 10), "release" if in_contact else "close", lam, gap))
        in_contact = nxt
    # Released after the first step with tension (t = 0.7, lambda < 0 held for that step), closed after
    # the first step that ends inside the soil (t = 1.4, g < 0 for that step).
    assert [(t, what) for t, what, _, _ in history] == [(0.7, "release"), (1.4, "close")]
    assert history[0][2] < 0.0
    assert history[1][3] < 0.0
    assert ops.eleResponse(CONTACT, "forcescalar")[0] == pytest.approx(P, rel=1e-9)


def tip_force(penalty, head_disp):
    m = beamsolid.Model()
    build_pile_on_soil(m, penalty)
    m.timeSeries("Linear", 2)
    m.pattern("Plain", 2, 2)
    m.sp(HEAD, 3, head_disp)
    static(m, 1.0)
    assert m.analyze(1) == 0
    force = m.eleResponse(CONTACT, "forcescalar")[0]
    m.wipe()
    return force


def test_penalty_converges_to_the_lagrange_answer(soil_flexibility):
    flex = soil_flexibility + PILE_FLEX
    head = -flex * P
    lagrange = tip_force(None, head)
    assert lagrange == pytest.approx(P, rel=1e-9)
    errors = []
    for k in range(3, 10):
        kappa = 10.0**k
        error = abs(tip_force(kappa, head) - lagrange) / lagrange
        predicted = (1.0 / kappa) / (flex + 1.0 / kappa)
        assert error == pytest.approx(predicted, rel=1e-4)
        errors.append(error)
    # First order once 1/kappa is small against fs + fp: each decade of penalty gains a decade of accuracy.
    rates = [math.log10(a / b) for a, b in zip(errors, errors[1:])]
    assert rates == sorted(rates), rates
    assert rates[-1] == pytest.approx(1.0, abs=1e-3)
    assert errors[-1] < 1e-5


def base_model(m):
    m.model("basic", "-ndm", 3, "-ndf", 6)
    m.node(1, 0.0, 0.0, 0.0)
    m.node(2, 0.0, 0.0, 1.0)
    m.node(5, 0.0, 0.0, 0.0)
    m.model("basic", "-ndm", 3, "-ndf", 3)
    m.node(3, 0.0, 0.0, 0.0)
    m.node(4, 0.0, 0.0, 0.0)


@pytest.mark.parametrize(
    "args, fragment",
    [
        (("BeamEndContact3D", 7, 1, 2, 3, 4, 0.0, 1e-8, 1e-8), "argument 7 (radius): expected a positive number"),
        (("BeamEndContact3D", 7, 3, 2, 1, 4, 0.3, 1e-8, 1e-8), "beam end node 3 has 3 dofs, expected 6"),
        (("BeamEndContact3D", 7, 1, 2, 5, 4, 0.3, 1e-8, 1e-8), "secondary (solid) node 5 has 6 dofs, expected 3"),
        (("BeamEndContact3D", 7, 1, 2, 3, 5, 0.3, 1e-8, 1e-8), "multiplier node 5 has 6 dofs, expected 3"),
        (("BeamEndContact3D", 7, 1, 2, 3, 3, 0.3, 1e-8, 1e-8), "node 3 appears twice"),
        (("BeamEndContact3D", 7, 1, 5, 3, 4, 0.3, 1e-8, 1e-8), "the beam nodes 1 and 5 coincide"),
        (("BeamEndContact3D", 7, 1, 2, 3, 4, 0.3, 1e-8, 1e-8, 3), "argument 10 (cFlag)"),
        (("BeamEndContact3D", 7, 1, 2, 3, 4, 0.3, 1e-8), "argument 9 (forceTol)"),
        (("BeamEndContact3Dp", 7, 1, 2, 3, 0.3, -5.0), "argument 7 (penalty): expected a positive number"),
        (("BeamEndContact3Dp", 7, 1, 2, 3, 0.3, 1e5, 0, 1), "element BeamEndContact3Dp 7"),
    ],
)
def test_bad_input_raises_clear_errors(model, args, fragment):
    base_model(model)
    with pytest.raises(beamsolid.OpenSeesError) as err:
        model.element(*args)
    assert fragment in str(err.value)
    assert f"element {args[0]} 7" in str(err.value)


def test_multiplier_node_must_be_free_and_own(model):
    base_model(model)
    model.element("BeamEndContact3D", 7, 1, 2, 3, 4, 0.3, 1e-8, 1e-8)
    model.node(6, 0.0, 0.0, 0.0)
    with pytest.raises(beamsolid.OpenSeesError, match="multiplier node 4 is also used by element 7"):
        model.element("BeamEndContact3D", 8, 1, 2, 6, 4, 0.3, 1e-8, 1e-8)
    model.fix(4, 1, 0, 0)
    model.system("UmfPack")
    model.constraints("Plain")
    model.numberer("Plain")
    model.test("NormDispIncr", 1e-10, 5)
    model.algorithm("Newton")
    model.integrator("LoadControl", 1.0)
    model.analysis("Static")
    assert model.analyze(1) == -3
    assert "element BeamEndContact3D 7: multiplier node 4 is fixed" in model.last_error()

"""Sensitivity analysis (sensitivityAlgorithm, sensNodeDisp): the direct differentiation method
against closed forms and against central differences of whole analyses.

OpenSeesPy comparisons are in the oracle script sensitivity_2d (test_opensees_oracle.py).
"""
import pytest

import beamsolid
import beamsolid.opensees as ops
from beamsolid import OpenSeesError


def _wf_cantilever(material, transf="Linear", n=1, L=5.0, d=0.5, tw=0.1, nfw=20, nip=5, spacing=None):
    """A cantilever along x of n dispBeamColumn elements with a web-only WFSection2d (depth d,
    thickness tw, nfw fibers); tip node 2 at x = L, the others `spacing` (L/n) apart."""
    spacing = L / n if spacing is None else spacing
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    ops.node(1, 0.0, 0.0)
    ops.node(2, L, 0.0)
    ops.fix(1, 1, 1, 1)
    material()
    ops.section("WFSection2d", 1, 1, d, tw, 0.1, 0.0, nfw, 0)
    ops.geomTransf(transf, 1)
    ops.beamIntegration("Legendre", 1, 1, nip)
    nodes = [1] + [9 + i for i in range(1, n)] + [2]
    for i in range(1, n):
        ops.node(9 + i, i * spacing, 0.0)
    for i in range(n):
        ops.element("dispBeamColumn", i + 1, nodes[i], nodes[i + 1], 1, 1)
    return n


def _parameters(names, n, coordinate=True):
    for k, name in enumerate(names, start=1):
        ops.parameter(k)
        for e in range(1, n + 1):
            ops.addToParameter(k, "element", e, name)
    if coordinate:
        ops.parameter(len(names) + 1, "node", 2, "coord", 1)


def _static(steps, test=1e-12):
    ops.system("BandGeneral")
    ops.numberer("RCM")
    ops.constraints("Transformation")
    ops.test("NormDispIncr", test, 20, 0)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", 1.0 / steps)
    ops.analysis("Static")
    ops.sensitivityAlgorithm("-computeAtEachStep")


def test_elastic_cantilever_closed_forms():
    # v = P L^3 / (3 E I) with the fibers' I = tw d^3 / 12 (1 - 1/n^2) (midpoint strips): dv/dE = -v/E,
    # dv/dd = -3 v/d, dv/dtw = -v/tw, and the tip's x coordinate is L: dv/dL = 3 v/L. One cubic
    # element is exact for a tip load.
    E, P, L, d, tw, nfw = 200e6, 30.0, 5.0, 0.5, 0.1, 20
    n = _wf_cantilever(lambda: ops.uniaxialMaterial("Elastic", 1, E), L=L, d=d, tw=tw, nfw=nfw)
    _parameters(("E", "d", "tw"), n)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, 0.0, P, 0.0)
    _static(1)
    assert ops.analyze(1) == 0
    I = tw * d**3 / 12.0 * (1.0 - 1.0 / nfw**2)
    v = P * L**3 / (3.0 * E * I)
    assert ops.nodeDisp(2, 2) == pytest.approx(v, rel=1e-12)
    assert ops.sensNodeDisp(2, 2, 1) == pytest.approx(-v / E, rel=1e-10)
    assert ops.sensNodeDisp(2, 2, 2) == pytest.approx(-3.0 * v / d, rel=1e-8)
    assert ops.sensNodeDisp(2, 2, 3) == pytest.approx(-v / tw, rel=1e-8)
    assert ops.sensNodeDisp(2, 2, 4) == pytest.approx(3.0 * v / L, rel=1e-8)
    # The tip rotation P L^2 / (2 E I): d/dL = 2 theta / L.
    theta = P * L**2 / (2.0 * E * I)
    assert ops.sensNodeDisp(2, 3, 4) == pytest.approx(2.0 * theta / L, rel=1e-8)
    # Under load control the load factor does not depend on the parameters.
    assert ops.sensLambda(1, 1) == 0.0


def _hardening_bar(E, Fy, Hiso, Hkin, L, A):
    """A bar along x of one dispBeamColumn: two fibers of linear-hardening steel (area A), only the
    tip's axial dof free."""
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    ops.node(1, 0.0, 0.0)
    ops.node(2, L, 0.0)
    ops.fix(1, 1, 1, 1)
    ops.fix(2, 0, 1, 1)
    ops.uniaxialMaterial("Hardening", 1, E, Fy, Hiso, Hkin)
    ops.section("Fiber", 1)
    ops.fiber(0.05, 0.0, A / 2, 1)
    ops.fiber(-0.05, 0.0, A / 2, 1)
    ops.geomTransf("Linear", 1)
    ops.beamIntegration("Legendre", 1, 1, 2)
    ops.element("dispBeamColumn", 1, 1, 2, 1, 1)


@pytest.mark.parametrize("hardening", ["kinematic", "isotropic"])
def test_hardening_bar_closed_forms(hardening):
    # A bar of linear-hardening steel pulled past yield to sigma and back to zero (elastic
    # unloading): u = L (sigma/E + (sigma - Fy)/H) at the peak and L (sigma - Fy)/H after; so
    # du/dFy = -L/H both times, du/dE = -L sigma/E^2 then 0, du/dH = -L (sigma - Fy)/H^2.
    E, Fy, H, L, A = 200e6, 400e3, 4e6, 2.0, 0.01
    Hiso, Hkin = (0.0, H) if hardening == "kinematic" else (H, 0.0)
    _hardening_bar(E, Fy, Hiso, Hkin, L, A)
    hname = "Hkin" if hardening == "kinematic" else "Hiso"
    _parameters(("E", "Fy", hname), 1, coordinate=False)
    sigma = 1.5 * Fy
    ops.timeSeries("Path", 1, "-time", 0.0, 1.0, 2.0, "-values", 0.0, 1.0, 0.0)
    ops.pattern("Plain", 1, 1)
    ops.load(2, sigma * A, 0.0, 0.0)
    _static(10)
    assert ops.analyze(10) == 0
    u = L * (sigma / E + (sigma - Fy) / H)
    assert ops.nodeDisp(2, 1) == pytest.approx(u, rel=1e-12)
    assert ops.sensNodeDisp(2, 1, 1) == pytest.approx(-L * sigma / E**2, rel=1e-9)
    assert ops.sensNodeDisp(2, 1, 2) == pytest.approx(-L / H, rel=1e-9)
    assert ops.sensNodeDisp(2, 1, 3) == pytest.approx(-L * (sigma - Fy) / H**2, rel=1e-9)
    # Elastic unloading: the initial tangent is exact (Newton's plastic first tangent would cycle).
    ops.algorithm("Newton", "-initial")
    assert ops.analyze(10) == 0
    assert ops.nodeDisp(2, 1) == pytest.approx(L * (sigma - Fy) / H, rel=1e-9)
    assert abs(ops.sensNodeDisp(2, 1, 1)) < 1e-12 * L / E
    assert ops.sensNodeDisp(2, 1, 2) == pytest.approx(-L / H, rel=1e-9)
    assert ops.sensNodeDisp(2, 1, 3) == pytest.approx(-L * (sigma - Fy) / H**2, rel=1e-9)


def _public_style_tip(sens=True, E=200e6, Fy=410e3, Hkin=0.02 / 0.98 * 200e6, d=0.5, L=5.0):
    """The cantilever of OpenSeesPy's sensitivity example: 5 corotational dispBeamColumn, a Trig
    load that yields the steel, turns the tip about 0.6 rad and reverses. Returns the tip's final
    displacement and its sensitivities to E, Fy, Hkin, d and L."""
    # The parameter L is the tip node's x: the other nodes stay 1 apart.
    n = _wf_cantilever(lambda: ops.uniaxialMaterial("Hardening", 1, E, Fy, 0.0, Hkin), "Corotational", n=5, L=L,
                       d=d, spacing=1.0)
    if sens:
        _parameters(("E", "Fy", "Hkin", "d"), n)
    ops.timeSeries("Trig", 1, 0.0, 1.0, 1.0)
    ops.pattern("Plain", 1, 1)
    ops.load(2, 0.0, 1710.0, 0.0)
    _static(500)
    if not sens:
        ops.wipeAnalysis()
        ops.test("NormDispIncr", 1e-12, 20, 0)
        ops.algorithm("Newton")
        ops.integrator("LoadControl", 1.0 / 500)
        ops.analysis("Static")
    for _ in range(500):
        assert ops.analyze(1) == 0
    tip = ops.nodeDisp(2, 2)
    return tip, [ops.sensNodeDisp(2, 2, k) for k in range(1, 6)] if sens else None


def test_corotational_plastic_matches_central_differences():
    # Each sensitivity against (u(theta + h) - u(theta - h)) / 2h of whole analyses, h = 1e-5 theta:
    # agreement measured at 1e-10 to 7e-9.
    values = dict(E=200e6, Fy=410e3, Hkin=0.02 / 0.98 * 200e6, d=0.5, L=5.0)
    tip, sens = _public_style_tip()
    assert abs(tip) > 3.0  # the tip went far (corotational) and the steel yielded both ways
    for k, (name, value) in enumerate(values.items()):
        h = 1e-5 * value
        plus, _ = _public_style_tip(False, **{name: value + h})
        minus, _ = _public_style_tip(False, **{name: value - h})
        assert sens[k] == pytest.approx((plus - minus) / (2 * h), rel=5e-8), name


def _displacement_controlled_bar(E=200e6, Fy=400e3, H=4e6, sens=True):
    """The hardening bar of test_hardening_bar_closed_forms pulled by displacement control to
    u = 3 Fy L / E (into the plastic range) in 10 steps; returns the load factor (the bar's force)
    and, with sens, its and the tip's sensitivities to E, Fy, Hkin."""
    L, A = 2.0, 0.01
    _hardening_bar(E, Fy, 0.0, H, L, A)
    if sens:
        _parameters(("E", "Fy", "Hkin"), 1, coordinate=False)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, 1.0, 0.0, 0.0)
    _static(10)
    ops.integrator("DisplacementControl", 2, 1, 3 * 400e3 * L / 200e6 / 10)
    ops.analysis("Static")
    assert ops.analyze(10) == 0
    if not sens:
        return ops.getTime(), None
    return ops.getTime(), [(ops.sensLambda(1, k), ops.sensNodeDisp(2, 1, k)) for k in (1, 2, 3)]


def test_displacement_control_load_factor_sensitivity():
    # The force at a fixed stretch: lambda = A (Fy + Et (eps - Fy/E)), Et = E H/(E + H), so
    # d lambda/d Fy = A (1 - Et/E) = A E/(E + H) (closed form); E and H against central
    # differences of whole analyses. The controlled dof does not move with theta.
    E, Fy, H, A = 200e6, 400e3, 4e6, 0.01
    lam, sens = _displacement_controlled_bar()
    eps = 3 * Fy / E
    Et = E * H / (E + H)
    assert lam == pytest.approx(A * (Fy + Et * (eps - Fy / E)), rel=1e-10)
    assert sens[1][0] == pytest.approx(A * E / (E + H), rel=1e-9)
    for k, (name, value) in enumerate((("E", E), ("Fy", Fy), ("H", H))):
        h = 1e-5 * value
        plus, _ = _displacement_controlled_bar(**{name: value + h}, sens=False)
        minus, _ = _displacement_controlled_bar(**{name: value - h}, sens=False)
        assert sens[k][0] == pytest.approx((plus - minus) / (2 * h), rel=1e-7), name
        assert abs(sens[k][1]) < 1e-14


def test_update_parameter_reaches_fibers_and_geometry():
    # updateParameter on a dispBeamColumn's section: E of the fibers' material, the depth d.
    P = 30.0
    n = _wf_cantilever(lambda: ops.uniaxialMaterial("Elastic", 1, 200e6))
    _parameters(("E", "d"), n, coordinate=False)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, 0.0, P, 0.0)
    _static(1)
    assert ops.analyze(1) == 0
    v0 = ops.nodeDisp(2, 2)
    ops.updateParameter(1, 100e6)
    ops.updateParameter(2, 1.0)
    ops.setTime(0.0)
    assert ops.analyze(1) == 0
    # v ~ 1/(E d^3): halving E and doubling d gives 2/8 of the first deflection.
    assert ops.nodeDisp(2, 2) == pytest.approx(v0 * 2.0 / 8.0, rel=1e-9)


def _elastic_beam_model():
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    ops.node(1, 0.0, 0.0)
    ops.node(2, 3.0, 0.0)
    ops.fix(1, 1, 1, 1)
    ops.geomTransf("Linear", 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, 0.0, 1.0, 0.0)


def test_elastic_section_closed_forms():
    # dispBeamColumn with an Elastic section: the tip's deflection P L^3/(3 E Iz) and stretch
    # N L/(E A) under a tip load (N, P).
    E, A, Iz, P, N, L = 200e6, 0.01, 1e-4, 30.0, 500.0, 3.0
    _elastic_beam_model()
    ops.section("Elastic", 1, E, A, Iz)
    ops.beamIntegration("Legendre", 1, 1, 3)
    ops.element("dispBeamColumn", 1, 1, 2, 1, 1)
    ops.load(2, N, P - 1.0, 0.0)  # the model's own load is (0, 1)
    _parameters(("E", "A", "Iz"), 1)
    _static(1)
    assert ops.analyze(1) == 0
    v, u = P * L**3 / (3 * E * Iz), N * L / (E * A)
    assert ops.nodeDisp(2, 2) == pytest.approx(v, rel=1e-12)
    assert ops.sensNodeDisp(2, 2, 1) == pytest.approx(-v / E, rel=1e-10)
    assert ops.sensNodeDisp(2, 1, 1) == pytest.approx(-u / E, rel=1e-10)
    assert ops.sensNodeDisp(2, 1, 2) == pytest.approx(-u / A, rel=1e-10)
    assert abs(ops.sensNodeDisp(2, 2, 2)) < 1e-12 * v / A
    assert ops.sensNodeDisp(2, 2, 3) == pytest.approx(-v / Iz, rel=1e-10)
    assert ops.sensNodeDisp(2, 2, 4) == pytest.approx(3 * v / L, rel=1e-8)
    assert ops.sensNodeDisp(2, 1, 4) == pytest.approx(u / L, rel=1e-8)


def test_elastic_elements_node_coordinates():
    # Elements without history take a node's coordinate by differences of their forces: an elastic
    # cantilever's tip deflection P L^3 / (3 E I) and an elastic bar's stretch P L / (E A).
    E, A, I, P, L = 200e6, 0.01, 1e-4, 30.0, 3.0
    _elastic_beam_model()
    ops.element("elasticBeamColumn", 1, 1, 2, A, E, I, 1)
    ops.parameter(1, "node", 2, "coord", 1)
    ops.parameter(2, "node", 2, "coord", 2)
    _static(1)
    assert ops.analyze(1) == 0
    assert ops.sensNodeDisp(2, 2, 1) == pytest.approx(P / 30.0 * L**2 / (E * I), rel=1e-8)
    # Moving the tip up turns the beam: the load gains an axial part, the deflection changes at
    # second order only, the axial displacement by -v/L (the chord's rotation) to first order.
    v = P / 30.0 * L**3 / (3 * E * I)
    assert ops.sensNodeDisp(2, 1, 2) == pytest.approx(-v / L + (P / 30.0) / (E * A), rel=1e-6)

    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 2)
    ops.node(1, 0.0, 0.0)
    ops.node(2, L, 0.0)
    ops.fix(1, 1, 1)
    ops.fix(2, 0, 1)
    ops.uniaxialMaterial("Elastic", 1, E)
    ops.element("Truss", 1, 1, 2, A, 1)
    ops.parameter(1, "node", 2, "coord", 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, P, 0.0)
    _static(1)
    assert ops.analyze(1) == 0
    assert ops.sensNodeDisp(2, 1, 1) == pytest.approx(P / (E * A), rel=1e-8)


def _corotational_elastic_tip(L, sens=True):
    """Two corotational elastic beams, the tip at x = L under a lateral load that bends it far."""
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    ops.node(1, 0.0, 0.0)
    ops.node(3, 1.5, 0.0)
    ops.node(2, L, 0.0)
    ops.fix(1, 1, 1, 1)
    ops.geomTransf("Corotational", 1)
    ops.element("elasticBeamColumn", 1, 1, 3, 0.01, 200e6, 1e-4, 1)
    ops.element("elasticBeamColumn", 2, 3, 2, 0.01, 200e6, 1e-4, 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, 0.0, 2000.0, 0.0)
    if sens:
        ops.parameter(1, "node", 2, "coord", 1)
    _static(20)
    assert ops.analyze(20) == 0
    return ops.nodeDisp(2, 2), ops.sensNodeDisp(2, 2, 1) if sens else None


def test_corotational_elastic_beam_node_coordinate_matches_central_differences():
    # A large deflection (about 0.5 L): the elastic beams have no history with the corotational
    # transformation either, so they differentiate their geometry by differences of their forces.
    L, h = 3.0, 3e-5
    tip, sens = _corotational_elastic_tip(L)
    assert tip > 0.25 * L
    plus, _ = _corotational_elastic_tip(L + h, False)
    minus, _ = _corotational_elastic_tip(L - h, False)
    assert sens == pytest.approx((plus - minus) / (2 * h), rel=1e-7)


def _loaded_elastic_cantilever(parameter):
    """The elastic WF cantilever with a tip load, one parameter on its element, load control."""
    n = _wf_cantilever(lambda: ops.uniaxialMaterial("Elastic", 1, 200e6))
    _parameters((parameter,), n, coordinate=False)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, 0.0, 1.0, 0.0)
    _static(1)


def test_unsupported_objects_fail_the_step_with_the_reason():
    # A material without sensitivities (ElasticPP) in a dispBeamColumn: its history's sensitivity
    # to the length is needed.
    _wf_cantilever(lambda: ops.uniaxialMaterial("ElasticPP", 1, 200e6, 0.002))
    ops.parameter(1, "node", 2, "coord", 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, 0.0, 1.0, 0.0)
    _static(1)
    assert ops.analyze(1) < 0
    assert "ElasticPP" in beamsolid.last_error() and "sensitivit" in beamsolid.last_error()
    assert ops.getTime() == 0.0  # the step was not kept

    # An element with a history that keeps no sensitivities (forceBeamColumn).
    _elastic_beam_model()
    ops.section("Elastic", 1, 200e6, 0.01, 1e-4)
    ops.beamIntegration("Lobatto", 1, 1, 3)
    ops.element("forceBeamColumn", 1, 1, 2, 1, 1)
    ops.parameter(1, "node", 2, "coord", 1)
    _static(1)
    assert ops.analyze(1) < 0
    assert "forceBeamColumn" in beamsolid.last_error() and "history" in beamsolid.last_error()

    # A name the element's sections do not have.
    _loaded_elastic_cantilever("notAParameter")
    assert ops.analyze(1) < 0
    assert "notAParameter" in beamsolid.last_error()

    # Arc length (d lambda / d theta with the arc's constraint) is not built.
    _loaded_elastic_cantilever("E")
    ops.integrator("ArcLength", 0.001, 1.0)
    ops.analysis("Static")
    assert ops.analyze(1) < 0
    assert "ArcLength" in beamsolid.last_error()


def test_bad_arguments_raise():
    n = _wf_cantilever(lambda: ops.uniaxialMaterial("Elastic", 1, 200e6))
    _parameters(("E",), n, coordinate=False)
    with pytest.raises(OpenSeesError, match="sensitivityAlgorithm.*option"):
        ops.sensitivityAlgorithm("-everyOtherStep")
    with pytest.raises(OpenSeesError, match="computeGradients.*no sensitivity algorithm"):
        ops.computeGradients()
    with pytest.raises(OpenSeesError, match="sensNodeDisp 99.*node 99 does not exist"):
        ops.sensNodeDisp(99, 1, 1)
    with pytest.raises(OpenSeesError, match="sensNodeDisp 2.*dof"):
        ops.sensNodeDisp(2, 4, 1)
    with pytest.raises(OpenSeesError, match="sensNodeDisp 2.*parameter 7 does not exist"):
        ops.sensNodeDisp(2, 1, 7)
    with pytest.raises(OpenSeesError, match="sensLambda 5.*pattern 5 does not exist"):
        ops.sensLambda(5, 1)
    # Before any step: zero, as nothing depends on theta yet.
    assert ops.sensNodeDisp(2, 2, 1) == 0.0

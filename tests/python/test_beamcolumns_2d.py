"""2D sections and 2D distributed-plasticity beam-columns against closed forms.

Moment-curvature of fiber sections through zeroLengthSection: an elastic-
perfectly-plastic steel rectangle (M = EI kappa up to My = fy b h^2/6, then
Mp (1 - (kappa_y/kappa)^2 / 3) towards Mp = fy b h^2/4), an RC section's
cracking point (uncracked transformed section) and its yield point
(cracked transformed section, no-tension concrete). Elastic cantilevers
(PL^3/3EI, exact for one force-based element and for Hermite elements), an
inelastic cantilever where dispBeamColumn meshes converge to the one
force-based element, the P-Delta amplification of a column against the
exact second-order solution and 1/(1 - P/Pcr), Timoshenko shear
flexibility through section('Elastic', ..., G, alphaY), and the errors for
sections of the wrong space.
"""
import math

import numpy as np
import pytest

import beamsolid


def relative_error(actual, expected):
    return abs(actual - expected) / abs(expected)


def static(ops, integrator, test=("NormUnbalance", 1e-9, 30)):
    ops.system("UmfPack")
    ops.numberer("Plain")
    ops.constraints("Plain")
    ops.test(*test)
    ops.algorithm("Newton")
    ops.integrator(*integrator)
    ops.analysis("Static")


def zero_length_section(ops, sec_tag):
    """Nodes 1 (fixed) and 2 (free axially and in rotation) joined by the section."""
    ops.node(1, 0.0, 0.0)
    ops.node(2, 0.0, 0.0)
    ops.fix(1, 1, 1, 1)
    ops.fix(2, 0, 1, 0)
    ops.element("zeroLengthSection", 1, 1, 2, sec_tag)


def moment_at_curvatures(ops, curvatures):
    """Drives the rotation of node 2 through `curvatures` (P = 0); the moments."""
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, 0.0, 0.0, 1.0)
    moments, previous = [], 0.0
    for kappa in curvatures:
        static(ops, ("DisplacementControl", 2, 3, kappa - previous))
        assert ops.analyze(1) == 0
        assert ops.nodeDisp(2, 3) == pytest.approx(kappa, rel=1e-12)
        moments.append(ops.eleResponse(1, "section", "force")[1])
        previous = kappa
    return np.array(moments)


# --- steel rectangle: My = fy b h^2/6, Mp = fy b h^2/4 ------------------------------

E, FY, B, H, STRIPS = 29000.0, 50.0, 4.0, 10.0, 400


def steel_rectangle(ops):
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    ops.uniaxialMaterial("ElasticPP", 1, E, FY / E)
    ops.section("Fiber", 1)
    # STRIPS fibers through the depth (y); z is ignored in 2D.
    ops.patch("rect", 1, STRIPS, 1, -H / 2, -B / 2, H / 2, B / 2)
    zero_length_section(ops, 1)


def test_steel_rectangle_follows_the_elastic_plastic_moment_curvature(ops):
    steel_rectangle(ops)
    kappa_y = 2.0 * FY / (E * H)
    my = FY * B * H**2 / 6.0
    mp = FY * B * H**2 / 4.0
    ratios = np.array([0.25, 0.5, 1.0, 2.0, 4.0, 10.0, 40.0])
    moments = moment_at_curvatures(ops, ratios * kappa_y)
    # Up to first yield all fibers are elastic; the midpoint strips hold
    # I = b h^3/12 (1 - 1/n^2) exactly, so M = My (1 - 1/n^2) kappa/kappa_y.
    elastic = my * (1.0 - 1.0 / STRIPS**2) * ratios[:3]
    for m, expected in zip(moments[:3], elastic):
        assert relative_error(m, expected) < 1e-10
    # Beyond: an elastic core of depth h kappa_y/kappa, M = Mp (1 - (kappa_y/kappa)^2/3).
    plastic = mp * (1.0 - 1.0 / (3.0 * ratios[3:] ** 2))
    errors = [relative_error(m, expected) for m, expected in zip(moments[3:], plastic)]
    assert max(errors) < 2e-5, errors  # strips cut by the elastic core: O(1/n^2)
    assert moments[-1] < mp


def test_steel_rectangle_tangent_is_the_elastic_core(ops):
    steel_rectangle(ops)
    kappa_y = 2.0 * FY / (E * H)
    moment_at_curvatures(ops, [5.0 * kappa_y])
    k = ops.eleResponse(1, "section", "stiffness")
    # EA and EI of the elastic core of depth h/5 (as fibers: 80 whole strips).
    core = H / 5.0
    assert relative_error(k[0], E * B * core) < 1e-12
    assert relative_error(k[3], E * B * core**3 / 12.0 * (1.0 - 1.0 / 80**2)) < 1e-12
    assert abs(k[1]) < 1e-9 * k[0] * H


# --- RC section: cracking and yield by transformed sections -----------------------

RC = dict(b=12.0, h=20.0, d=17.5, As=2.0, Ec=3600.0, Es=29000.0, fr=0.45, fy=60.0)
CONCRETE_STRIPS = 400


def rc_section(ops, concrete, steel):
    r = RC
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    ops.uniaxialMaterial(*concrete)
    ops.uniaxialMaterial(*steel)
    ops.section("Fiber", 1)
    ops.patch("rect", 1, CONCRETE_STRIPS, 1, -r["h"] / 2, -r["b"] / 2, r["h"] / 2, r["b"] / 2)
    # Two bars at depth d from the top (y = h/2 - d), placed as one layer.
    ops.layer("straight", 2, 2, r["As"] / 2, r["h"] / 2 - r["d"], -4.0, r["h"] / 2 - r["d"], 4.0)
    zero_length_section(ops, 1)


def test_rc_cracking_moment_from_the_uncracked_transformed_section(ops):
    r = RC
    rc_section(ops, ("Elastic", 1, r["Ec"]), ("Elastic", 2, r["Es"]))
    # Transformed section (depth from the top): the bars' extra area (n - 1) As
    # sits at d, the concrete's own bar area stays in the gross section.
    n = r["Es"] / r["Ec"]
    area = r["b"] * r["h"] + n * r["As"]  # fibers: gross concrete plus the bars in full
    top = (r["b"] * r["h"] * r["h"] / 2 + n * r["As"] * r["d"]) / area
    strips = r["b"] * r["h"] ** 3 / 12.0 * (1.0 - 1.0 / CONCRETE_STRIPS**2)
    inertia = strips + r["b"] * r["h"] * (r["h"] / 2 - top) ** 2 + n * r["As"] * (r["d"] - top) ** 2
    bottom = r["h"] - top
    m_cr = r["fr"] * inertia / bottom           # tension face reaches the modulus of rupture
    kappa_cr = r["fr"] / (r["Ec"] * bottom)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, 0.0, 0.0, m_cr)
    static(ops, ("LoadControl", 1.0))
    assert ops.analyze(1) == 0
    assert relative_error(ops.nodeDisp(2, 3), kappa_cr) < 1e-10
    # The strain at the tension face, from the section's eps and kappa about its reference axis.
    eps, kappa = ops.eleResponse(1, "section", "deformation")
    centroid = (r["b"] * r["h"] * 0.0 + r["As"] * (r["h"] / 2 - r["d"])) / (r["b"] * r["h"] + r["As"])
    strain_bottom = eps - (-r["h"] / 2 - centroid) * kappa
    assert relative_error(strain_bottom, r["fr"] / r["Ec"]) < 1e-10


def test_rc_yield_point_from_the_cracked_transformed_section(ops):
    r = RC
    rc_section(ops, ("ENT", 1, r["Ec"]), ("ElasticPP", 2, r["Es"], r["fy"] / r["Es"]))
    n = r["Es"] / r["Ec"]
    # b (kd)^2 / 2 = n As (d - kd): the neutral axis of the cracked section.
    a, bq, c = r["b"] / 2.0, n * r["As"], -n * r["As"] * r["d"]
    kd = (-bq + math.sqrt(bq * bq - 4.0 * a * c)) / (2.0 * a)
    kappa_y = r["fy"] / r["Es"] / (r["d"] - kd)
    m_y = r["As"] * r["fy"] * (r["d"] - kd / 3.0)
    moments = moment_at_curvatures(ops, [0.5 * kappa_y, 0.999 * kappa_y])
    # Linear between cracking and yield: M = kappa (Ec b kd^3/3 + Es As (d - kd)^2).
    cracked_ei = r["Ec"] * r["b"] * kd**3 / 3.0 + r["Es"] * r["As"] * (r["d"] - kd) ** 2
    assert relative_error(moments[0], 0.5 * kappa_y * cracked_ei) < 2e-5
    assert relative_error(moments[1], 0.999 * m_y) < 2e-5
    assert relative_error(cracked_ei * kappa_y, m_y) < 1e-12  # the two hand forms agree


# --- beam-columns -----------------------------------------------------------------

def cantilever(ops, element, n_elements, section_cmds, points=5, load=(0.0, 0.0, 0.0), transf="Linear",
               length=120.0):
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    for cmd in section_cmds:
        getattr(ops, cmd[0])(*cmd[1:])
    ops.geomTransf(transf, 1)
    rule = "Lobatto" if element == "forceBeamColumn" else "Legendre"
    ops.beamIntegration(rule, 1, 1, points)
    for k in range(n_elements + 1):
        ops.node(k + 1, 0.0, length * k / n_elements)
    ops.fix(1, 1, 1, 1)
    for k in range(n_elements):
        ops.element(element, k + 1, k + 1, k + 2, 1, 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(n_elements + 1, *load)
    return n_elements + 1


EI_SECTION = [("section", "Elastic", 1, 29000.0, 20.0, 800.0)]


@pytest.mark.parametrize("element", ["forceBeamColumn", "dispBeamColumn", "nonlinearBeamColumn"])
def test_elastic_cantilever_tip_is_pl3_over_3ei(ops, element):
    P, L, EI = 2.0, 120.0, 29000.0 * 800.0
    if element == "nonlinearBeamColumn":
        ops.model("basic", "-ndm", 2, "-ndf", 3)
        ops.section("Elastic", 1, 29000.0, 20.0, 800.0)
        ops.geomTransf("Linear", 1)
        ops.node(1, 0.0, 0.0)
        ops.node(2, 0.0, L)
        ops.fix(1, 1, 1, 1)
        ops.element("nonlinearBeamColumn", 1, 1, 2, 3, 1, 1)  # older form
        ops.timeSeries("Linear", 1)
        ops.pattern("Plain", 1, 1)
        ops.load(2, P, 0.0, 0.0)
        tip = 2
    else:
        tip = cantilever(ops, element, 1, EI_SECTION, points=3, load=(P, 0.0, 0.0))
    static(ops, ("LoadControl", 1.0))
    assert ops.analyze(1) == 0
    # One element is exact: the force-based one integrates the linear moment
    # exactly, the Hermite field of the displacement-based one is the cubic solution.
    assert relative_error(ops.nodeDisp(tip, 1), P * L**3 / (3.0 * EI)) < 1e-12
    assert relative_error(-ops.nodeDisp(tip, 3), P * L**2 / (2.0 * EI)) < 1e-12
    assert ops.eleResponse(1, "basicForce")[1] == pytest.approx(P * L, rel=1e-12)


def fiber_column(kind):
    return [("uniaxialMaterial", "Steel01", 1, 50.0, 29000.0, 0.01),
            ("section", "Fiber", 1),
            ("patch", "rect", 1, 40, 1, -5.0, -2.0, 5.0, 2.0)]


def inelastic_tip_force(ops, element, n_elements, points):
    tip = cantilever(ops, element, n_elements, fiber_column(element), points=points, load=(1.0, 0.0, 0.0))
    static(ops, ("DisplacementControl", tip, 1, 0.2), test=("NormDispIncr", 1e-10, 30))
    assert ops.analyze(10) == 0
    return ops.getLoadFactor(1)


def test_displacement_based_meshes_converge_to_the_force_based_element(ops):
    reference = inelastic_tip_force(ops, "forceBeamColumn", 1, 10)
    ops.wipe()
    errors = []
    for n in (1, 2, 4, 8):
        errors.append(relative_error(inelastic_tip_force(ops, "dispBeamColumn", n, 3), reference))
        ops.wipe()
    # The stiffer displacement-based answer approaches the force-based one as the mesh is refined.
    assert all(later < earlier for earlier, later in zip(errors, errors[1:])), errors
    assert errors[-1] < 0.02 and errors[0] > 3 * errors[-1], errors


def test_pdelta_amplifies_the_sway_of_a_column(ops):
    L, EI, H = 120.0, 29000.0 * 800.0, 1.0
    p_cr = math.pi**2 * EI / (4.0 * L**2)
    P = 0.3 * p_cr
    tip = cantilever(ops, "forceBeamColumn", 8, EI_SECTION, points=4, load=(0.0, -P, 0.0), transf="PDelta")
    static(ops, ("LoadControl", 1.0), test=("NormDispIncr", 1e-12, 20))
    assert ops.analyze(1) == 0
    ops.loadConst("-time", 0.0)
    ops.pattern("Plain", 2, 1)
    ops.load(tip, H, 0.0, 0.0)
    assert ops.analyze(1) == 0
    sway = ops.nodeDisp(tip, 1)
    first_order = H * L**3 / (3.0 * EI)
    # Exact second-order cantilever: delta = H (tan kL - kL) / (k^3 EI), k^2 = P/EI.
    k = math.sqrt(P / EI)
    exact = H * (math.tan(k * L) - k * L) / (k**3 * EI)
    assert relative_error(sway, exact) < 2e-3
    assert relative_error(sway / first_order, 1.0 / (1.0 - P / p_cr)) < 1e-2
    assert sway / first_order > 1.4


def test_displacement_based_element_leaves_the_shear_unstrained(ops):
    P, L, E, A, I, G, alpha = 2.0, 60.0, 29000.0, 20.0, 800.0, 11200.0, 5.0 / 6.0
    tip = cantilever(ops, "dispBeamColumn", 1, [("section", "Elastic", 1, E, A, I, G, alpha)], points=3,
                     load=(P, 0.0, 0.0), length=L)
    static(ops, ("LoadControl", 1.0))
    assert ops.analyze(1) == 0
    # Hermite bending: Euler-Bernoulli, the Vy component carries nothing (as OpenSees).
    assert relative_error(ops.nodeDisp(tip, 1), P * L**3 / (3.0 * E * I)) < 1e-12
    assert ops.eleResponse(1, "section", 1, "force")[2] == 0.0


def test_timoshenko_section_adds_shear_flexibility(ops):
    P, L, E, A, I, G, alpha = 2.0, 60.0, 29000.0, 20.0, 800.0, 11200.0, 5.0 / 6.0
    tip = cantilever(ops, "forceBeamColumn", 1, [("section", "Elastic", 1, E, A, I, G, alpha)], points=3,
                     load=(P, 0.0, 0.0), length=L)
    static(ops, ("LoadControl", 1.0))
    assert ops.analyze(1) == 0
    expected = P * L**3 / (3.0 * E * I) + P * L / (alpha * G * A)
    assert relative_error(ops.nodeDisp(tip, 1), expected) < 1e-12
    # Section shear V = (M_i + M_j) / L = P L / L.
    assert ops.eleResponse(1, "section", 1, "force")[2] == pytest.approx(P, rel=1e-12)


def test_wide_flange_section_stiffness(ops):
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    ops.uniaxialMaterial("Elastic", 1, 1000.0)
    ops.section("WFSection2d", 1, 1, 10.0, 1.0, 6.0, 2.0, 3, 2)
    zero_length_section(ops, 1)
    k = ops.eleResponse(1, "section", "stiffness")
    # Web 6 x 1 in three strips (y = -2, 0, 2), flanges 6 x 2 in two strips each.
    assert k[0] == pytest.approx(1000.0 * (6.0 + 2 * 12.0), rel=1e-14)
    assert k[3] == pytest.approx(1000.0 * (2.0 * 8.0 + 2 * 6.0 * (3.5**2 + 4.5**2)), rel=1e-14)


def test_rc_section_2d_areas_and_bar_layout(ops):
    # d 20, b 12, cover 2; 3 bars of 3 on top, 3 of 2 at the bottom, 1 of 1 on each side.
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    for tag, e in ((1, 1.0), (2, 10.0), (3, 1000.0)):
        ops.uniaxialMaterial("Elastic", tag, e)
    ops.section("RCSection2d", 1, 1, 2, 3, 20.0, 12.0, 2.0, 3.0, 2.0, 1.0, 10, 2, 3)
    zero_length_section(ops, 1)
    k = ops.eleResponse(1, "section", "stiffness")
    core, cover, bars = 16.0 * 8.0, 20.0 * 12.0 - 16.0 * 8.0, 3 * 3.0 + 3 * 2.0 + 2 * 1.0
    assert k[0] == pytest.approx(1.0 * core + 10.0 * cover + 1000.0 * bars, rel=1e-14)
    # About the area centroid yBar = (9 * 8 - 6 * 8) / (240 + 17): only the bars are unsymmetric.
    y_bar = 24.0 / 257.0
    first_moment = 1.0 * core * (0 - y_bar) + 10.0 * cover * (0 - y_bar) + 1000.0 * (24.0 - bars * y_bar)
    assert k[1] == pytest.approx(-first_moment, rel=1e-12)


# --- errors -------------------------------------------------------------------------

def test_sections_of_the_other_space_are_refused(ops):
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    ops.section("Elastic", 1, 29000.0, 20.0, 800.0)
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    ops.section("Elastic", 2, 29000.0, 20.0, 800.0, 500.0, 11200.0, 300.0)
    ops.node(1, 0.0, 0.0, 0.0)
    ops.node(2, 0.0, 0.0, 10.0)
    ops.geomTransf("Linear", 1, 1.0, 0.0, 0.0)
    ops.beamIntegration("Lobatto", 1, 1, 3)
    with pytest.raises(beamsolid.OpenSeesError, match=r"forceBeamColumn 1.*section Elastic 1 is a 2D section"):
        ops.element("forceBeamColumn", 1, 1, 2, 1, 1)
    with pytest.raises(beamsolid.OpenSeesError, match=r"zeroLengthSection 2.*secTag.*3D model.*2D section"):
        ops.element("zeroLengthSection", 2, 1, 2, 1)
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    ops.section("Elastic", 2, 29000.0, 20.0, 800.0, 500.0, 11200.0, 300.0)
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    ops.node(1, 0.0, 0.0)
    ops.node(2, 0.0, 10.0)
    ops.geomTransf("Linear", 1)
    ops.beamIntegration("Legendre", 1, 2, 2)
    with pytest.raises(beamsolid.OpenSeesError, match=r"dispBeamColumn 1.*section Elastic 2 is a 3D section"):
        ops.element("dispBeamColumn", 1, 1, 2, 1, 1)
    with pytest.raises(beamsolid.OpenSeesError, match=r"elasticBeamColumn 2: section 2 is a 3D Elastic section"):
        ops.element("elasticBeamColumn", 2, 1, 2, 2, 1)
    with pytest.raises(beamsolid.OpenSeesError, match=r"zeroLengthSection 3.*secTag.*2D model.*3D section"):
        ops.element("zeroLengthSection", 3, 1, 2, 2)


def test_2d_section_command_errors(ops):
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    ops.uniaxialMaterial("Elastic", 1, 100.0)
    with pytest.raises(beamsolid.OpenSeesError, match=r"section Aggregator 3.*code.*P, Mz, Vy.*3D component"):
        ops.section("Aggregator", 3, 1, "T")
    with pytest.raises(beamsolid.OpenSeesError, match=r"section Aggregator 4.*code.*'Q'"):
        ops.section("Aggregator", 4, 1, "Q")
    with pytest.raises(beamsolid.OpenSeesError, match=r"section Aggregator 5.*Mz is given twice"):
        ops.section("Aggregator", 5, 1, "Mz", 1, "Mz")
    with pytest.raises(beamsolid.OpenSeesError, match=r"section WFSection2d 6.*tf.*>= 0"):
        ops.section("WFSection2d", 6, 1, 10.0, 1.0, 6.0, -2.0, 3, 2)
    with pytest.raises(beamsolid.OpenSeesError, match=r"section WFSection2d 6.*Nff.*0\.\.100000"):
        ops.section("WFSection2d", 6, 1, 10.0, 1.0, 6.0, 2.0, 3, -1)
    with pytest.raises(beamsolid.OpenSeesError, match=r"section WFSection2d 6.*Nfw = 0.*without fibers"):
        ops.section("WFSection2d", 6, 1, 10.0, 1.0, 6.0, 2.0, 0, 0)
    with pytest.raises(beamsolid.OpenSeesError, match=r"section WFSection2d 7.*uniaxialMaterial 9 does not exist"):
        ops.section("WFSection2d", 7, 9, 10.0, 1.0, 6.0, 2.0, 3, 2)
    with pytest.raises(beamsolid.OpenSeesError, match=r"section Elastic 8: expected E, A, Iz.*got 6 \(the 3D form"):
        ops.section("Elastic", 8, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0)
    ops.section("Elastic", 9, 29000.0, 20.0, 800.0, 11200.0, 0.8)
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    # Vy is a 3D code now (shear component); the 2D section is what is wrong.
    with pytest.raises(beamsolid.OpenSeesError, match=r"section Aggregator 10.*section Elastic 9 is a 2D section"):
        ops.section("Aggregator", 10, 1, "Vy", "-section", 9)
    with pytest.raises(beamsolid.OpenSeesError, match=r"section Aggregator 11.*all of P, Mz, My and T"):
        ops.section("Aggregator", 11, 1, "P", 1, "Mz")
    with pytest.raises(beamsolid.OpenSeesError, match=r"section WFSection2d 12.*2D model"):
        ops.section("WFSection2d", 12, 1, 10.0, 1.0, 6.0, 2.0, 3, 2)


@pytest.mark.parametrize("tf, nfw, nff", [(0.0, 20, 0), (0.05, 20, 0), (0.05, 0, 2), (0.0, 4, 3)])
def test_wide_flange_without_flanges_or_web(ops, tf, nfw, nff):
    # tf = 0, Nff = 0 or Nfw = 0 leave the flanges or the web out (OpenSees
    # accepts them: a public sensitivity example uses tf = 0, Nff = 0). Closed
    # forms: midpoint strips of a rectangle b x h in n fibers have
    # sum(A y^2) = b h^3 / 12 (1 - 1/n^2).
    E, d, tw, bf = 29000.0, 0.5, 0.1, 0.1
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    ops.uniaxialMaterial("Elastic", 1, E)
    ops.section("WFSection2d", 1, 1, d, tw, bf, tf, nfw, nff)
    zero_length_section(ops, 1)
    web = d - 2 * tf
    ea = E * (tw * web * (nfw > 0) + 2 * bf * tf * (nff > 0))  # tf = 0: no flange area
    ei = E * (tw * web**3 / 12 * (1 - 1 / nfw**2) if nfw else 0.0)
    if nff and tf:
        ei += 2 * E * (bf * tf**3 / 12 * (1 - 1 / nff**2) + bf * tf * ((web + tf) / 2) ** 2)
    k = ops.eleResponse(1, "section", "stiffness")
    assert k[0] == pytest.approx(ea, rel=1e-12)
    assert k[3] == pytest.approx(ei, rel=1e-12)


def test_wide_flange_fibers_are_numbered_from_the_top_down(ops):
    # OpenSees numbers WFSection2d fibers top flange first, then the web, then
    # the bottom flange, each from the top down: 'fiber $i' follows that order.
    E, d, tw, bf, tf, nfw, nff = 1000.0, 10.0, 1.0, 6.0, 2.0, 3, 2
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    ops.uniaxialMaterial("Elastic", 1, E)
    ops.section("WFSection2d", 1, 1, d, tw, bf, tf, nfw, nff)
    zero_length_section(ops, 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, 0.0, 0.0, 1.0)
    static(ops, ("DisplacementControl", 2, 3, 1e-3))
    assert ops.analyze(1) == 0
    kappa = ops.nodeDisp(2, 3)
    web = d - 2 * tf
    ys = [d / 2 - (k + 0.5) * tf / nff for k in range(nff)]
    ys += [web / 2 - (k + 0.5) * web / nfw for k in range(nfw)]
    ys += [-web / 2 - (k + 0.5) * tf / nff for k in range(nff)]
    data = np.reshape(ops.eleResponse(1, "section", "fiberData"), (-1, 5))
    assert data[:, 0] == pytest.approx(ys, abs=1e-14)
    for i, y in enumerate(ys):
        stress, strain = ops.eleResponse(1, "section", "fiber", i, "stressStrain")
        assert strain == pytest.approx(-y * kappa, rel=1e-12, abs=1e-18)
        assert stress == pytest.approx(-E * y * kappa, rel=1e-12, abs=1e-15)


@pytest.mark.parametrize("element", ["elasticBeamColumn", "dispBeamColumn"])
def test_lumped_mass_flag_is_the_default_and_cmass_wins(ops, element):
    # A cantilever of one element, L = 10, EA = 100, m = 2 per length: the
    # lumped axial mode has omega^2 = EA / (L * m L / 2) = 1.0, the consistent
    # one (m L / 3 at the tip with the free end) 1.5 (as OpenSees, the
    # '-lMass' flag changes nothing and '-cMass' wins in any order).
    def axial_omega2(*flags):
        ops.wipe()
        ops.model("basic", "-ndm", 2, "-ndf", 3)
        ops.node(1, 0.0, 0.0)
        ops.node(2, 10.0, 0.0)
        ops.fix(1, 1, 1, 1)
        ops.fix(2, 0, 1, 1)
        ops.geomTransf("Linear", 1)
        if element == "elasticBeamColumn":
            ops.element(element, 1, 1, 2, 1.0, 100.0, 1.0, 1, "-mass", 2.0, *flags)
        else:
            ops.section("Elastic", 1, 100.0, 1.0, 1.0)
            ops.beamIntegration("Lobatto", 1, 1, 3)
            ops.element(element, 1, 1, 2, 1, 1, "-mass", 2.0, *flags)
        return ops.eigen("-fullGenLapack", 1)[0]

    assert axial_omega2() == pytest.approx(1.0, rel=1e-12)
    assert axial_omega2("-lMass") == pytest.approx(1.0, rel=1e-12)
    assert axial_omega2("-cMass", "-lMass") == pytest.approx(1.5, rel=1e-12)
    assert axial_omega2("-lMass", "-cMass") == pytest.approx(1.5, rel=1e-12)

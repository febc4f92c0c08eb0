"""The section truss: element('TrussSection', tag, i, j, secTag, ...) and its
OpenSees spelling element('Truss', tag, i, j, secTag, ...) (no area).

Closed forms (Popov's symmetric three-bar truss, bars at -alpha, 0, +alpha
meeting at one node, load P down):
* elastic: middle bar F1 = P / (1 + 2 cos^3 alpha), outer bars F1 cos^2 alpha,
  deflection F1 L / (E A), to 1e-12 with a fiber section, a Uniaxial 'P'
  section and a 3D fiber section (the fibers may sit off the axis: the
  section is referred to its centroid, so the bar does not bend);
* elastic-perfectly plastic: first yield at sigma_y A (1 + 2 cos^3 alpha) with
  the middle bar's deflection, collapse at sigma_y A (1 + 2 cos alpha) with
  deflection dispA / cos^2 alpha (to 1e-10);
* mass as the area truss (rho per unit length): a free-free bar's axial
  eigenvalue 4 k / (rho L) lumped, 12 k / (rho L) consistent;
* a section without an axial component is refused with OpenSeesError.
"""
import math

import pytest

import beamsolid

A, E, L, ALPHA, P = 10.0, 3000.0, 200.0, math.radians(30.0), 200.0


def three_bar(ops, define_section, load=P, series=("Linear", 1), ndm=2):
    ops.wipe()
    ops.model("basic", "-ndm", ndm, "-ndf", ndm)
    dx = L * math.tan(ALPHA)
    pad = [0.0] * (ndm - 2)
    for tag, x, y in ((1, 0.0, 0.0), (2, dx, 0.0), (3, 2 * dx, 0.0), (4, dx, -L)):
        ops.node(tag, x, y, *pad)
    for tag in (1, 2, 3):
        ops.fix(tag, *([1] * ndm))
    if ndm == 3:
        ops.fix(4, 0, 0, 1)
    define_section(ops)
    ops.element("Truss", 1, 1, 4, 1)
    ops.element("TrussSection", 2, 2, 4, 1)
    ops.element("trussSection", 3, 3, 4, 1)
    ops.timeSeries(*series)
    ops.pattern("Plain", 1, 1)
    ops.load(4, 0.0, -load, *pad)
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.system("ProfileSPD")
    ops.algorithm("Linear")
    ops.integrator("LoadControl", 1.0)
    ops.analysis("Static")


def fiber_off_axis(ops, mat=1):
    # Area A as 10 x 1 fibers, all on one side of the origin.
    ops.section("Fiber", 1, *(["-GJ", 1.0] if ops.getNDM()[0] == 3 else []))
    ops.patch("rect", mat, 10, 1, -A, -1.0, 0.0, 0.0)


def elastic_fiber(ops):
    ops.uniaxialMaterial("Elastic", 1, E)
    fiber_off_axis(ops)


def elastic_uniaxial(ops):
    ops.uniaxialMaterial("Elastic", 1, A * E)
    ops.section("Uniaxial", 1, 1, "P")


@pytest.mark.parametrize("define_section, ndm", [(elastic_fiber, 2), (elastic_uniaxial, 2), (elastic_fiber, 3)])
def test_elastic_three_bar_truss(ops, define_section, ndm):
    three_bar(ops, define_section, ndm=ndm)
    assert ops.analyze(1) == 0
    F1 = P / (1 + 2 * math.cos(ALPHA) ** 3)
    F2 = F1 * math.cos(ALPHA) ** 2
    for tag, expected in ((1, F2), (2, F1), (3, F2)):
        assert ops.eleResponse(tag, "axialForce")[0] == pytest.approx(expected, rel=1e-12)
    assert ops.nodeDisp(4, 2) == pytest.approx(-F1 * L / (A * E), rel=1e-12)
    # The section sees the bar's strain and no curvature.
    deformation = ops.eleResponse(2, "section", "deformation")
    assert deformation[0] == pytest.approx(F1 / (A * E), rel=1e-12)
    assert all(abs(v) < 1e-15 for v in deformation[1:])
    assert ops.eleResponse(2, "section", "force")[0] == pytest.approx(F1, rel=1e-12)
    assert ops.getEleClassTags(2) == [13]


@pytest.mark.parametrize("kind", ["fiber", "uniaxial"])
def test_elastic_plastic_three_bar_truss(ops, kind):
    sigma_y = 60.0
    PA = sigma_y * A * (1 + 2 * math.cos(ALPHA) ** 3)
    PB = sigma_y * A * (1 + 2 * math.cos(ALPHA))

    def epp(ops):
        if kind == "fiber":
            ops.uniaxialMaterial("ElasticPP", 1, E, sigma_y / E)
            fiber_off_axis(ops)
        else:
            ops.uniaxialMaterial("ElasticPP", 1, A * E, sigma_y / E)
            ops.section("Uniaxial", 1, 1, "P")

    three_bar(ops, epp, load=1.0, series=("Path", 1, "-dt", 1.0, "-values", 0.0, PA, PB, PB))
    assert ops.analyze(1) == 0
    dispA = -sigma_y / E * L  # the middle bar just yields
    assert ops.nodeDisp(4, 2) == pytest.approx(dispA, rel=1e-10)
    assert ops.analyze(1) == 0
    assert ops.nodeDisp(4, 2) == pytest.approx(dispA / math.cos(ALPHA) ** 2, rel=1e-10)
    for tag in (1, 2, 3):
        assert ops.eleResponse(tag, "axialForce")[0] == pytest.approx(sigma_y * A, rel=1e-10)


@pytest.mark.parametrize("flags, factor", [((), 4.0), (("-cMass", 1), 12.0)])
def test_mass_per_unit_length(ops, flags, factor):
    rho, length, EA = 2.0, 5.0, 100.0
    ops.model("basic", "-ndm", 2, "-ndf", 2)
    ops.node(1, 0.0, 0.0)
    ops.node(2, length, 0.0)
    ops.fix(1, 0, 1)
    ops.fix(2, 0, 1)
    ops.uniaxialMaterial("Elastic", 1, EA)
    ops.section("Uniaxial", 1, 1, "P")
    ops.element("Truss", 1, 1, 2, 1, "-rho", rho, *flags)
    lam = ops.eigen("-fullGenLapack", 2)
    assert abs(lam[0]) < 1e-9
    assert lam[1] == pytest.approx(factor * (EA / length) / (rho * length), rel=1e-12)


def test_section_without_axial_component_is_refused(ops):
    ops.model("basic", "-ndm", 2, "-ndf", 2)
    ops.node(1, 0.0, 0.0)
    ops.node(2, 1.0, 0.0)
    ops.uniaxialMaterial("Elastic", 1, 1.0)
    ops.section("Uniaxial", 1, 1, "Mz")
    with pytest.raises(beamsolid.OpenSeesError, match="TrussSection 1.*axial"):
        ops.element("TrussSection", 1, 1, 2, 1)
    with pytest.raises(beamsolid.OpenSeesError, match="secTag|section"):
        ops.element("Truss", 2, 1, 2, 7)
    with pytest.raises(beamsolid.OpenSeesError, match="option"):
        ops.element("TrussSection", 3, 1, 2, 1, "-bogus", 1)
    # A float is an area, not a section tag: the truss form, its material missing.
    with pytest.raises(beamsolid.OpenSeesError, match="element truss 4.*matTag"):
        ops.element("Truss", 4, 1, 2, 1.0)

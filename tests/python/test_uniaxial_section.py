"""section('Uniaxial', tag, matTag, quantity) against closed forms.

A cantilever of length L, flexural rigidity EI, on a base rotational spring
k (zeroLengthSection of a Uniaxial 'Mz' section) deflects P L^3/(3 EI) +
P L^2/k at the tip under a tip load P; a 3D torsional spring (Uniaxial 'T')
turns T/k; a forceBeamColumn/dispBeamColumn of an Aggregator of a Uniaxial
'Mz' section with an axial material is the elastic cantilever P L^3/(3 EI).
Linear answers: 1e-10 relative.
"""
import pytest

import beamsolid

P, L, EI, K = 3.0, 2.5, 4.0e3, 1.5e3


def solve(m, node, dofs):
    m.system("UmfPack")
    m.constraints("Plain")
    m.numberer("Plain")
    m.test("NormDispIncr", 1e-12, 10)
    m.algorithm("Newton")
    m.integrator("LoadControl", 1.0)
    m.analysis("Static")
    assert m.analyze(1) == 0
    return [m.nodeDisp(node, d) for d in dofs]


def test_rotational_spring_2d(model):
    model.model("basic", "-ndm", 2, "-ndf", 3)
    model.node(1, 0.0, 0.0)
    model.node(2, 0.0, 0.0)
    model.node(3, L, 0.0)
    model.fix(1, 1, 1, 1)
    model.equalDOF(1, 2, 1, 2)
    model.uniaxialMaterial("Elastic", 1, K)
    model.section("Uniaxial", 1, 1, "Mz")
    model.element("zeroLengthSection", 1, 1, 2, 1)
    model.geomTransf("Linear", 1)
    model.element("elasticBeamColumn", 2, 2, 3, 1.0, EI, 1.0, 1)
    model.timeSeries("Linear", 1)
    model.pattern("Plain", 1, 1)
    model.load(3, 0.0, P, 0.0)
    (v,) = solve(model, 3, [2])
    assert v == pytest.approx(P * L**3 / (3 * EI) + P * L * L / K, rel=1e-10)
    assert model.eleResponse(1, "section", "force") == pytest.approx([P * L], rel=1e-10)
    assert model.eleResponse(1, "section", "deformation") == pytest.approx([P * L / K], rel=1e-10)
    assert model.eleResponse(1, "section", "stiffness") == pytest.approx([K], rel=1e-12)


def test_torsional_spring_3d(model):
    model.model("basic", "-ndm", 3, "-ndf", 6)
    model.node(1, 0.0, 0.0, 0.0)
    model.node(2, 0.0, 0.0, 0.0)
    model.fix(1, 1, 1, 1, 1, 1, 1)
    model.fix(2, 1, 1, 1, 0, 1, 1)
    model.uniaxialMaterial("Elastic", 1, K)
    model.section("Uniaxial", 1, 1, "T")
    model.element("zeroLengthSection", 1, 1, 2, 1)
    model.timeSeries("Linear", 1)
    model.pattern("Plain", 1, 1)
    model.load(2, 0.0, 0.0, 0.0, P, 0.0, 0.0)
    (theta,) = solve(model, 2, [4])
    assert theta == pytest.approx(P / K, rel=1e-10)
    assert model.eleResponse(1, "section", "force") == pytest.approx([P], rel=1e-10)
    assert model.eleResponse(1, "section", "forceAndDeformation") == pytest.approx([P / K, P], rel=1e-10)


@pytest.mark.parametrize("element", ["forceBeamColumn", "dispBeamColumn"])
def test_aggregated_uniaxial_section_in_beams(model, element):
    model.model("basic", "-ndm", 2, "-ndf", 3)
    model.node(1, 0.0, 0.0)
    model.node(2, L, 0.0)
    model.fix(1, 1, 1, 1)
    model.uniaxialMaterial("Elastic", 1, EI)
    model.uniaxialMaterial("Elastic", 2, 1.0e7)
    model.section("Uniaxial", 1, 1, "Mz")
    model.section("Aggregator", 2, 2, "P", "-section", 1)
    model.geomTransf("Linear", 1)
    model.beamIntegration("Lobatto", 1, 2, 4)  # exact for the cubic deflection
    model.element(element, 1, 1, 2, 1, 1)
    model.timeSeries("Linear", 1)
    model.pattern("Plain", 1, 1)
    model.load(2, 0.0, P, 0.0)
    (v,) = solve(model, 2, [2])
    assert v == pytest.approx(P * L**3 / (3 * EI), rel=1e-10)


@pytest.mark.parametrize("ndm, args, words", [
    (2, (1, 1, "My"), "quantity"),
    (2, (1, 1, "Q"), "quantity"),
    (3, (1, 1, "Vy"), "shear"),
    (3, (1, 9, "P"), "9"),
    (2, (1, 1), "quantity"),
    (2, (1, 1, "P", 5), "argument"),
    (2, (1, "x", "P"), "matTag"),
])
def test_bad_input_names_the_argument(model, ndm, args, words):
    model.model("basic", "-ndm", ndm, "-ndf", 3 if ndm == 2 else 6)
    model.uniaxialMaterial("Elastic", 1, K)
    with pytest.raises(beamsolid.OpenSeesError) as info:
        model.section("Uniaxial", *args)
    assert "section Uniaxial" in str(info.value) and words in str(info.value)

"""mixedBeamColumn: the force-based element under OpenSees' mixed-element command (without
'-geomNonlinear' OpenSeesPy's mixed and force-based elements give the same states and iteration
counts; the oracle script mixed_beam_column compares with OpenSeesPy itself)."""
import pytest

import beamsolid


def _cantilever(m, element, *options, ndm=2):
    m.wipe()
    if ndm == 2:
        m.model("basic", "-ndm", 2, "-ndf", 3)
        m.node(1, 0.0, 0.0)
        m.node(2, 0.0, 4.0)
        m.fix(1, 1, 1, 1)
        m.geomTransf("Linear", 1)
    else:
        m.model("basic", "-ndm", 3, "-ndf", 6)
        m.node(1, 0.0, 0.0, 0.0)
        m.node(2, 0.0, 0.0, 4.0)
        m.fix(1, 1, 1, 1, 1, 1, 1)
        m.geomTransf("Linear", 1, 1.0, 0.0, 0.0)
    if ndm == 2:
        m.section("Elastic", 1, 200.0e6, 0.01, 2.0e-5)
    else:
        m.section("Elastic", 1, 200.0e6, 0.01, 2.0e-5, 3.0e-5, 80.0e6, 4.0e-5)
    m.beamIntegration("Lobatto", 1, 1, 4)
    m.element(element, 1, 1, 2, 1, 1, *options)


def test_elastic_cantilever_tip_is_the_closed_form():
    """P L^3 / 3 E I at the tip and P L^2 / 2 E I its rotation: exact for the force-based element."""
    m = beamsolid.Model()
    for ndm in (2, 3):
        _cantilever(m, "mixedBeamColumn", ndm=ndm)
        m.timeSeries("Linear", 1)
        m.pattern("Plain", 1, 1)
        P = 10.0
        m.load(2, *((P, 0.0, 0.0) if ndm == 2 else (P, 0.0, 0.0, 0.0, 0.0, 0.0)))
        m.analysis("Static")
        assert m.analyze(1) == 0
        # (3D: vecxz along global x puts the push about the local y axis, Iy = 3e-5)
        EI = 200.0e6 * (2.0e-5 if ndm == 2 else 3.0e-5)
        assert m.nodeDisp(2, 1) == pytest.approx(P * 4.0**3 / (3 * EI), rel=1e-12)
        rotation = m.nodeDisp(2, 3 if ndm == 2 else 5)
        assert abs(rotation) == pytest.approx(P * 4.0**2 / (2 * EI), rel=1e-12)


def test_lumped_mass_and_options_as_opensees():
    """'-mass' is lumped (two free dofs of the tip carry m L / 2); unknown options are ignored with a
    warning as OpenSees ignores them; '-geomNonlinear', the older form and '-doRayleigh 0' are refused."""
    m = beamsolid.Model()
    _cantilever(m, "mixedBeamColumn", "-mass", 3.0, "-iter", 10, 1e-12, "-cMass")
    EI, L, mass = 200.0e6 * 2.0e-5, 4.0, 3.0 * 4.0 / 2
    # Tip mass only (lumped): omega^2 = 3 EI / L^3 / m for the sway, EA / L / m axially.
    lam = sorted(m.eigen("-fullGenLapack", 2))
    assert lam[0] == pytest.approx(3 * EI / L**3 / mass, rel=1e-10)
    assert lam[1] == pytest.approx(200.0e6 * 0.01 / L / mass, rel=1e-10)
    for options, message in ((("-geomNonlinear",), "'-geomNonlinear'"), (("-doRayleigh", 0), "'-doRayleigh 0'")):
        with pytest.raises(beamsolid.OpenSeesError, match=message):
            _cantilever(m, "mixedBeamColumn", *options)
    m.wipe()
    m.model("basic", "-ndm", 2, "-ndf", 3)
    m.node(1, 0.0, 0.0)
    m.node(2, 0.0, 4.0)
    m.section("Elastic", 1, 200.0e6, 0.01, 2.0e-5)
    m.geomTransf("Linear", 1)
    with pytest.raises(beamsolid.OpenSeesError, match="element mixedBeamColumn 1: expected eleTag, iNode, jNode, "
                                                      "transfTag, integrationTag"):
        m.element("mixedBeamColumn", 1, 1, 2, 5, 1, 1)

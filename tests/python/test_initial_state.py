"""InitialStateAnalysis('on' | 'off') and nDMaterial InitialStateAnalysisWrapper.

One stdBrick (unit cube, base fixed, top free vertically only) under its weight b3 = -10:
uniaxial strain, sigma_zz = -5 (the mean weight above the Gauss points' common strain),
sigma_xx = sigma_yy = nu/(1-nu) sigma_zz = -5/3 for nu = 0.25, top settlement
w = -5 / M with M = E (1-nu) / ((1+nu)(1-2nu)) = 1200 for E = 1000.
OpenSeesPy 3.7 run on this script (benchmarks are not needed for a one-element check) gives:
without the wrapper, after 'off' the displacements are 0 and the stresses 0; with the wrapper,
the displacements are 0, the stresses and strains are those before 'off', and a further step
with the weight held constant moves nothing. The tests assert the same.
"""
import pytest

import beamsolid.opensees as ops
from beamsolid import Model, OpenSeesError

E, NU, B3 = 1000.0, 0.25, -10.0
M = E * (1 - NU) / ((1 + NU) * (1 - 2 * NU))
SIGMA = [-5.0 * NU / (1 - NU), -5.0 * NU / (1 - NU), -5.0]


def cube(m, wrapped):
    m.wipe()
    m.model("basic", "-ndm", 3, "-ndf", 3)
    pts = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
    for i, p in enumerate(pts):
        m.node(i + 1, *p)
    for i in range(1, 5):
        m.fix(i, 1, 1, 1)
    for i in range(5, 9):
        m.fix(i, 1, 1, 0)
    m.nDMaterial("ElasticIsotropic", 1, E, NU)
    mat = 1
    if wrapped:
        m.nDMaterial("InitialStateAnalysisWrapper", 2, 1, 3)
        mat = 2
    m.element("stdBrick", 1, *range(1, 9), mat, 0.0, 0.0, B3)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.constraints("Plain")
    m.numberer("Plain")
    m.system("FullGeneral")
    m.test("NormDispIncr", 1e-12, 10)
    m.algorithm("Newton")
    m.integrator("LoadControl", 1.0)
    m.analysis("Static")


def stresses(m):
    return m.eleResponse(1, "stresses")


@pytest.mark.parametrize("wrapped", [False, True])
def test_gravity_then_off(wrapped):
    m = Model()
    cube(m, wrapped)
    m.InitialStateAnalysis("on")
    assert m.analyze(1) == 0
    assert m.nodeDisp(7, 3) == pytest.approx(-5.0 / M, rel=1e-12)
    before_strain = m.eleResponse(1, "strains")
    for g in range(8):
        assert stresses(m)[6 * g:6 * g + 3] == pytest.approx(SIGMA, rel=1e-12)
    m.InitialStateAnalysis("off")
    assert all(m.nodeDisp(t, 3) == 0.0 for t in range(1, 9))
    s = stresses(m)
    if wrapped:
        for g in range(8):
            assert s[6 * g:6 * g + 3] == pytest.approx(SIGMA, rel=1e-12)
        # The wrapper reports the inner material's strain, the initial strain included.
        assert m.eleResponse(1, "strains") == pytest.approx(before_strain, rel=1e-12, abs=1e-15)
    else:
        assert max(abs(v) for v in s) < 1e-12  # re-evaluated at zero strain
    m.loadConst("-time", 0.0)
    assert m.analyze(1) == 0
    if wrapped:
        assert abs(m.nodeDisp(7, 3)) < 1e-14  # the weight is balanced at the reference geometry
    else:
        assert m.nodeDisp(7, 3) == pytest.approx(-5.0 / M, rel=1e-12)  # it settles again
    for g in range(8):
        assert stresses(m)[6 * g:6 * g + 3] == pytest.approx(SIGMA, rel=1e-12)


def test_wrapper_passes_parameters_and_reverts_to_start():
    m = Model()
    cube(m, True)
    m.InitialStateAnalysis("on")
    assert m.analyze(1) == 0
    m.InitialStateAnalysis("off")
    m.setParameter("-val", 2 * E, "-ele", 1, "E")  # reaches the inner material through the wrapper
    m.loadConst("-time", 0.0)
    assert m.analyze(1) == 0
    # Stiffer with the same initial strain: the stress doubles, so the weight pushes it back up.
    assert m.nodeDisp(7, 3) == pytest.approx(5.0 / (2 * M), rel=1e-10)


def test_the_command_module_has_it():
    ops.wipe()
    cube(ops.default_model(), True)
    ops.InitialStateAnalysis("on")
    assert ops.analyze(1) == 0
    ops.InitialStateAnalysis("off")
    assert ops.nodeDisp(7, 3) == 0.0
    ops.wipe()


@pytest.mark.parametrize("args, match", [
    (("maybe",), "InitialStateAnalysis.*flag must be 'on' or 'off'"),
    ((), "InitialStateAnalysis.*flag"),
    (("on", "extra"), "InitialStateAnalysis"),
])
def test_bad_flag(args, match):
    m = Model()
    cube(m, True)
    with pytest.raises(OpenSeesError, match=match):
        m.InitialStateAnalysis(*args)


@pytest.mark.parametrize("args, match", [
    ((3, 9, 3), "InitialStateAnalysisWrapper 3.*nDMatTag.*9 does not exist"),
    ((3, 1, 2), "InitialStateAnalysisWrapper 3.*nDim must be 3"),
    ((3, 3, 3), "InitialStateAnalysisWrapper 3.*its own tag"),
    ((3, 1), "InitialStateAnalysisWrapper 3.*nDim"),
    ((3, 5, 3), "InitialStateAnalysisWrapper 3.*no three-dimensional form"),
])
def test_bad_wrapper(args, match):
    m = Model()
    cube(m, False)
    m.nDMaterial("ContactMaterial3D", 5, 0.5, 1000.0, 0.0, 0.0)
    with pytest.raises(OpenSeesError, match=match):
        m.nDMaterial("InitialStateAnalysisWrapper", *args)


def test_wrapped_plastic_soil_reports_its_plastic_state():
    # A wrapped J2 brick sheared past yield reports the inner material's plastic strains (the
    # PVD recorder's plasticStrain arrays read them), equal to the same brick unwrapped.
    values = []
    for wrapped in (False, True):
        m = Model()
        m.model("basic", "-ndm", 3, "-ndf", 3)
        pts = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
        for i, p in enumerate(pts):
            m.node(i + 1, *p)
        for i in range(1, 9):
            m.fix(i, 0 if i > 4 else 1, 1, 1)
        m.nDMaterial("J2Plasticity", 1, 1000.0, 500.0, 1.0, 1.0, 0.0, 0.0)
        if wrapped:
            m.nDMaterial("InitialStateAnalysisWrapper", 2, 1, 3)
        m.element("bbarBrick", 1, *range(1, 9), 2 if wrapped else 1)
        m.timeSeries("Linear", 1)
        m.pattern("Plain", 1, 1)
        for i in range(5, 9):
            m.sp(i, 1, 0.01)  # shear strain 0.01, yield at 1 / (sqrt(3) 500) = 0.00115
        m.constraints("Transformation")
        m.numberer("Plain")
        m.system("UmfPack")
        m.test("NormDispIncr", 1e-12, 20)
        m.algorithm("Newton")
        m.integrator("LoadControl", 0.25)
        m.analysis("Static")
        assert m.analyze(4) == 0
        values.append((m.eleResponse(1, "equivalentPlasticStrains"), m.eleResponse(1, "plasticStrains")))
    (xi, ep), (xi_w, ep_w) = values
    assert min(xi) > 0.0
    assert xi_w == pytest.approx(xi, rel=1e-12)
    assert ep_w == pytest.approx(ep, rel=1e-12, abs=1e-15)

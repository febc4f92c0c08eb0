"""nDMaterial J2Plasticity and DruckerPrager through the commands: bricks and
quads accept them, stages switch elastic/plastic (and the constant-tangent
flag the condensed solver relies on), responses, Newton's quadratic rate on
a yielding brick mesh, and bad arguments named.

Material-point closed forms and tangent checks are in
tests/cpp/test_SoilPlasticity.cpp; OpenSeesPy comparisons in
test_soil_materials_oracle.py.
"""
import math

import numpy as np
import pytest

import beamsolid

K, G = 160e3, 80e3
E = 9 * K * G / (3 * K + G)
J2 = ("J2Plasticity", 1, K, G, 250.0, 250.0, 0.0, 2000.0)
DP = ("DruckerPrager", 1, 27777.78, 9259.26, 5.0, 0.398, 0.1, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 1.7)
CUBE = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]


def cube(m, material, top=None):
    """Unit stdBrick on symmetry planes; the top face (nodes 5-8) follows sp(top)."""
    m.wipe()
    m.model("basic", "-ndm", 3, "-ndf", 3)
    for i, x in enumerate(CUBE, start=1):
        m.node(i, *[float(c) for c in x])
        m.fix(i, int(x[0] == 0), int(x[1] == 0), int(x[2] == 0))
    m.nDMaterial(*material)
    m.element("stdBrick", 1, *range(1, 9), material[1])
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    for n in (5, 6, 7, 8):
        m.sp(n, 3, 1.0 if top is None else top)
    m.constraints("Transformation")
    m.numberer("Plain")
    m.system("UmfPack")
    m.test("NormDispIncr", 1e-12, 25)
    m.algorithm("Newton")


def test_brick_uniaxial_stress_yields_at_sig0_and_hardens(model):
    cube(model, J2)
    ey = 250.0 / E
    model.integrator("LoadControl", ey / 4)
    model.analysis("Static")
    stresses = []
    for _ in range(16):
        assert model.analyze(1) == 0
        stresses.append(model.eleResponse(1, "material", "1", "stress")[2])
    e = np.arange(1, 17) * ey / 4
    expected = np.where(e <= ey, E * e, 250.0 + E * 2000.0 / (E + 2000.0) * (e - ey))
    np.testing.assert_allclose(stresses, expected, rtol=1e-10)
    # Plastic strain response: eps_p33 = e - sigma / E after yield.
    ep = model.eleResponse(1, "material", "1", "plasticStrain")
    assert len(ep) == 6
    assert ep[2] == pytest.approx(e[-1] - stresses[-1] / E, rel=1e-9)
    xi = model.eleResponse(1, "material", "1", "equivalentPlasticStrain")
    assert xi[0] == pytest.approx(ep[2], rel=1e-9)


def test_quads_take_the_plane_forms(model):
    for material, kinds in ((J2, ("PlaneStrain", "PlaneStress")), (DP, ("PlaneStrain",))):
        for kind in kinds:
            model.wipe()
            model.model("basic", "-ndm", 2, "-ndf", 2)
            for i, x in enumerate([(0, 0), (1, 0), (1, 1), (0, 1)], start=1):
                model.node(i, float(x[0]), float(x[1]))
            model.nDMaterial(*material)
            model.element("quad", 1, 1, 2, 3, 4, 1.0, kind, 1)
            assert len(model.eleResponse(1, "material", "1", "stress")) == 3
            assert len(model.eleResponse(1, "material", "1", "stress3D")) == 6
    model.wipe()
    model.model("basic", "-ndm", 2, "-ndf", 2)
    for i, x in enumerate([(0, 0), (1, 0), (1, 1), (0, 1)], start=1):
        model.node(i, float(x[0]), float(x[1]))
    model.nDMaterial(*DP)
    with pytest.raises(beamsolid.OpenSeesError, match=r"element quad 1.*DruckerPrager.*no PlaneStress form"):
        model.element("quad", 1, 1, 2, 3, 4, 1.0, "PlaneStress", 1)


@pytest.mark.parametrize("material", [J2, DP], ids=["J2", "DP"])
def test_update_material_stage_switches_elastic_and_plastic(model, material):
    # Stage 0 (gravity): elastic, the tangent constant so that the condensed
    # solver may take the soil; stage 1: plastic, not constant any more.
    cube(model, material)
    model.updateMaterialStage("-material", 1, "-stage", 0)
    model.system("UmfPack", "-condense", "on")
    model.integrator("LoadControl", -0.002)
    model.analysis("Static")
    assert model.analyze(5) == 0
    info = model.solver_info()
    assert info["condensed"], info
    elastic = model.eleResponse(1, "material", "1", "stress")[2]
    Ey = 9 * material[2] * material[3] / (3 * material[2] + material[3])
    assert elastic == pytest.approx(-Ey * 0.01, rel=1e-10)
    model.updateMaterialStage("-material", 1, "-stage", 1)
    assert model.analyze(1) == 0
    info = model.solver_info()
    assert not info["condensed"], info
    plastic = model.eleResponse(1, "material", "1", "stress")[2]
    assert abs(plastic) < abs(elastic)
    with pytest.raises(beamsolid.OpenSeesError, match=r"updateMaterialStage.*stage must be 0 \(elastic\) or 1"):
        model.updateMaterialStage("-material", 1, "-stage", 3)


def test_stage_change_invalidates_the_bricks_cached_tangent(model):
    # An elastic brick caches its stiffness; after stage 1 the tangent must be
    # the plastic one (Newton would otherwise converge linearly or not at all).
    cube(model, J2)
    model.updateMaterialStage("-material", 1, "-stage", 0)
    model.integrator("LoadControl", 250.0 / E / 2)
    model.analysis("Static")
    assert model.analyze(1) == 0
    model.updateMaterialStage("-material", 1, "-stage", 1)
    model.integrator("LoadControl", 250.0 / E * 3)
    assert model.analyze(1) == 0
    # Two plastic iterations at most: a wrong (elastic) tangent would need many.
    assert model.testIter() <= 3


RATE_CASES = {
    # J2 with saturation hardening, pushed sideways and down.
    "J2": (("J2Plasticity", 1, K, G, 250.0, 320.0, 40.0, 900.0), -0.3, 0.004),
    # Non-associative Drucker-Prager (unsymmetric tangent) with hardening.
    "DP": (("DruckerPrager", 1, 27777.78, 9259.26, 5.0, 0.398, 0.1, 20.0, 5.0, 30.0, 0.0, 100.0, 1.0, 1.7), -0.5,
           0.001),
}


@pytest.mark.parametrize("case", sorted(RATE_CASES))
def test_newton_converges_quadratically_on_a_yielding_brick_mesh(model, case):
    # 2 x 2 x 2 bricks, bottom fixed, the top moved sideways and down: a
    # non-proportional strain field, every Gauss point plastic by step 3.
    material, down, step = RATE_CASES[case]
    model.model("basic", "-ndm", 3, "-ndf", 3)
    model.nDMaterial(*material)
    model.block3D(2, 2, 2, 1, 1, "stdBrick", 1, 1, 0.0, 0.0, 0.0, 2, 1.0, 0.0, 0.0, 3, 1.0, 1.0, 0.0, 4, 0.0, 1.0,
                  0.0, 5, 0.0, 0.0, 1.0, 6, 1.0, 0.0, 1.0, 7, 1.0, 1.0, 1.0, 8, 0.0, 1.0, 1.0)
    model.fixZ(0.0, 1, 1, 1)
    top = [n for n in model.getNodeTags() if abs(model.nodeCoord(n)[2] - 1.0) < 1e-12]
    model.timeSeries("Linear", 1)
    model.pattern("Plain", 1, 1)
    for n in top:
        model.sp(n, 1, 1.0)
        model.sp(n, 3, down)
    model.constraints("Transformation")
    model.numberer("Plain")
    model.system("UmfPack")
    model.test("NormDispIncr", 1e-14, 30)
    model.algorithm("Newton")
    model.integrator("LoadControl", step)
    model.analysis("Static")
    assert model.analyze(2) == 0
    assert model.analyze(1) == 0
    assert all(model.eleResponse(e, "equivalentPlasticStrains")[0] > 0 for e in range(1, 9))
    norms = np.array(model.testNorm()[: model.testIter()])
    norms = norms[norms > 1e-13]  # below: round-off
    assert len(norms) >= 4, norms
    orders = np.log(norms[2:] / norms[1:-1]) / np.log(norms[1:-1] / norms[:-2])
    assert orders[-1] >= 1.8, (norms, orders)


def test_bad_arguments_name_the_command_and_the_argument(model):
    model.model("basic", "-ndm", 3, "-ndf", 3)
    cases = [
        (("J2Plasticity", 1, K, G, 250.0, 250.0, 0.0), r"nDMaterial J2Plasticity 1.*\(H\)"),
        (("J2Plasticity", 1, K, G, 250.0, 250.0, 0.0, "x"), r"nDMaterial J2Plasticity 1.*\(H\)"),
        (("J2Plasticity", 1, K, -G, 250.0, 250.0, 0.0, 0.0), r"nDMaterial J2Plasticity 1: G must be positive"),
        (("J2Plasticity", 1, K, G, 250.0, 250.0, 0.0, 0.0, 0.1), r"nDMaterial J2Plasticity 1.*\(eta\)"),
        (("DruckerPrager", 1, 1e4, 5e3, 5.0, 0.3, 0.1, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0),
         r"nDMaterial DruckerPrager 1.*\(density\)"),
        (("DruckerPrager", 1, 1e4, 5e3, 5.0, 0.3, 0.5, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0),
         r"nDMaterial DruckerPrager 1: rhoBar must satisfy"),
        (("DruckerPrager", 1, 1e4, 5e3, 5.0, 0.3, 0.1, 0.0, 0.0, 0.0, 0.0, 0.0, 2.0, 0.0),
         r"nDMaterial DruckerPrager 1: theta must satisfy"),
    ]
    for args, pattern in cases:
        with pytest.raises(beamsolid.OpenSeesError, match=pattern):
            model.nDMaterial(*args)
    model.nDMaterial(*DP)
    with pytest.raises(beamsolid.OpenSeesError, match=r"nDMaterial 1 exists|duplicate|already"):
        model.nDMaterial(*DP)


def test_kinematic_option_gives_the_bauschinger_effect(model):
    # Ours: '-kinematic' Hkin. After +5 ey and back, reverse yield comes at
    # sigma_max - 2 sig0 (pure kinematic), not at -sigma_max (isotropic).
    mat = ("J2Plasticity", 1, K, G, 250.0, 250.0, 0.0, 0.0, 0.0, "-kinematic", 2000.0)
    cube(model, mat)
    ey = 250.0 / E
    model.integrator("LoadControl", ey / 2)
    model.analysis("Static")
    assert model.analyze(10) == 0
    smax = model.eleResponse(1, "material", "1", "stress")[2]
    assert smax == pytest.approx(250.0 + E * 2000.0 / (E + 2000.0) * 4 * ey, rel=1e-10)
    # Unload elastically by (2 sig0 - tiny) / E: still elastic; a little more yields.
    model.integrator("LoadControl", -(2 * 250.0 * 0.999) / E)
    assert model.analyze(1) == 0
    s = model.eleResponse(1, "material", "1", "stress")[2]
    assert s == pytest.approx(smax - 2 * 250.0 * 0.999, rel=1e-10)
    back = model.eleResponse(1, "material", "1", "backStress")
    assert back[2] == pytest.approx(2.0 / 3.0 * (smax - 250.0), rel=1e-9)


def test_element_plastic_responses_and_paraview_arrays(model, tmp_path):
    # Uniaxial stress past yield: every Gauss point has eps_p33 = e - sigma/E
    # and eps_p11 = eps_p22 = -eps_p33 / 2 (isochoric); the PVD cell arrays
    # are their means, and the elastic brick beside it reports zeros.
    import glob

    import meshio

    cube(model, J2)
    model.nDMaterial("ElasticIsotropic", 2, 1000.0, 0.25)
    for i, x in enumerate(CUBE, start=11):
        model.node(i, float(x[0]) + 2.0, float(x[1]), float(x[2]))
        model.fix(i, 1, 1, 1)
    model.element("stdBrick", 2, *range(11, 19), 2)
    model.recorder("PVD", str(tmp_path / "soil"))
    model.integrator("LoadControl", 3 * 250.0 / E)
    model.analysis("Static")
    assert model.analyze(1) == 0
    eps = 3 * 250.0 / E
    sigma = 250.0 + E * 2000.0 / (E + 2000.0) * (eps - 250.0 / E)
    ep = np.array(model.eleResponse(1, "plasticStrains")).reshape(8, 6)
    np.testing.assert_allclose(ep[:, 2], eps - sigma / E, rtol=1e-9)
    np.testing.assert_allclose(ep[:, 0], -(eps - sigma / E) / 2, rtol=1e-9)
    xi = np.array(model.eleResponse(1, "equivalentPlasticStrains"))
    np.testing.assert_allclose(xi, eps - sigma / E, rtol=1e-9)
    with pytest.raises(beamsolid.OpenSeesError):
        model.eleResponse(2, "plasticStrains")  # elastic material: no plastic state
    model.wipe()
    files = sorted(glob.glob(str(tmp_path / "soil" / "*.vtu")))
    assert files
    grid = meshio.read(files[-1])
    cells = {name: np.concatenate(blocks) for name, blocks in grid.cell_data.items()}
    order = list(cells["elementTag"].ravel())
    i1, i2 = order.index(1), order.index(2)
    np.testing.assert_allclose(cells["plasticStrain"][i1], ep.mean(axis=0), rtol=1e-9)
    np.testing.assert_allclose(cells["equivalentPlasticStrain"][i1].ravel(), [xi.mean()], rtol=1e-9)
    assert not np.any(cells["plasticStrain"][i2])


def test_wrapped_for_the_gravity_stage_keeps_its_stress_and_stage(model):
    # InitialStateAnalysisWrapper around Drucker-Prager: an elastic confined
    # stage (stage 0), 'off' zeroes the displacements and keeps the stress;
    # stage 1 then yields from that stress.
    model.model("basic", "-ndm", 3, "-ndf", 3)
    for i, x in enumerate(CUBE, start=1):
        model.node(i, *[float(c) for c in x])
        model.fix(i, int(x[0] == 0), int(x[1] == 0), int(x[2] == 0))
    model.nDMaterial(*DP)
    model.nDMaterial("InitialStateAnalysisWrapper", 2, 1, 3)
    model.element("stdBrick", 1, *range(1, 9), 2)
    model.updateMaterialStage("-material", 2, "-stage", 0)
    model.InitialStateAnalysis("on")
    model.timeSeries("Linear", 1)
    model.pattern("Plain", 1, 1)
    for n in (2, 3, 6, 7):
        model.load(n, -2.5, 0.0, 0.0)
    for n in (3, 4, 7, 8):
        model.load(n, 0.0, -2.5, 0.0)
    for n in (5, 6, 7, 8):
        model.load(n, 0.0, 0.0, -5.0)  # sigma (-10, -10, -20): inside the cone
    model.constraints("Transformation")
    model.numberer("Plain")
    model.system("UmfPack")
    model.test("NormDispIncr", 1e-12, 25)
    model.algorithm("Newton")
    model.integrator("LoadControl", 0.5)
    model.analysis("Static")
    assert model.analyze(2) == 0
    before = model.eleResponse(1, "material", "1", "stress")
    np.testing.assert_allclose(before[:3], [-10.0, -10.0, -20.0], rtol=1e-10)
    model.InitialStateAnalysis("off")
    assert model.nodeDisp(7) == [0.0, 0.0, 0.0]
    np.testing.assert_allclose(model.eleResponse(1, "material", "1", "stress"), before, rtol=1e-12, atol=1e-12)
    model.loadConst("-time", 0.0)
    model.updateMaterialStage("-material", 2, "-stage", 1)
    # Axial compression to failure on the cone: q = (sqrt(2/3) 5 + 3 rho 10) / (sqrt(2/3) - rho).
    model.timeSeries("Linear", 2)
    model.pattern("Plain", 2, 2)
    for n in (5, 6, 7, 8):
        model.sp(n, 3, -0.004)
    model.integrator("LoadControl", 0.1)
    assert model.analyze(10) == 0
    c = math.sqrt(2.0 / 3.0)
    qf = (c * 5.0 + 3 * 0.398 * 10.0) / (c - 0.398)
    s = model.eleResponse(1, "material", "1", "stress")
    assert s[2] == pytest.approx(-10.0 - qf, rel=1e-9)


def _quad_under_load(m, mat_cmds, quad_type, mat_tag):
    m.wipe()
    m.model("basic", "-ndm", 2, "-ndf", 2)
    for i, c in enumerate([(0.0, 0.0), (1.0, 0.0), (1.1, 0.9), (0.0, 1.0)]):
        m.node(i + 1, *c)
    m.fix(1, 1, 1)
    m.fix(4, 1, 0)
    for cmd in mat_cmds:
        m.nDMaterial(*cmd)
    m.element("quad", 1, 1, 2, 3, 4, 1.0, quad_type, mat_tag)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.load(2, 0.9, 0.2)
    m.load(3, 0.7, -0.1)
    m.integrator("LoadControl", 0.25)
    m.test("NormDispIncr", 1e-12, 30)
    m.algorithm("Newton")
    m.analysis("Static")
    assert m.analyze(4) == 0
    return m.nodeDisp(2) + m.nodeDisp(3) + m.eleResponse(1, "stresses")


@pytest.mark.parametrize("plane", ["PlaneStress", "PlaneStrain"])
def test_plane_material_wrappers_force_their_plane(model, plane):
    """nDMaterial('PlaneStress' | 'PlaneStrain', tag, mat3DTag) uses the 3D material in that plane
    whatever the quad declares (as OpenSees' wrappers do): the same answers as the 3D material
    under a quad of that type, for an elastic and a yielding (J2) material, to round-off."""
    other = "PlaneStrain" if plane == "PlaneStress" else "PlaneStress"
    for base in (("ElasticIsotropic", 1, 100.0, 0.3), ("J2Plasticity", 1, 100.0, 50.0, 1.0, 1.0, 0.0, 5.0)):
        direct = _quad_under_load(model, [base], plane, 1)
        for declared in (plane, other):
            wrapped = _quad_under_load(model, [base, (plane, 2, 1)], declared, 2)
            assert wrapped == pytest.approx(direct, rel=1e-12, abs=1e-14)
    model.wipe()
    model.model("basic", "-ndm", 2, "-ndf", 2)
    with pytest.raises(beamsolid.OpenSeesError, match=rf"nDMaterial {plane} 2: .*nDMaterial 9 does not exist"):
        model.nDMaterial(plane, 2, 9)
    model.nDMaterial("ContactMaterial3D", 3, 0.3, 1.0, 0.0, 0.0)
    with pytest.raises(beamsolid.OpenSeesError, match=rf"nDMaterial {plane} 4: nDMaterial 3 .*"):
        model.nDMaterial(plane, 4, 3)

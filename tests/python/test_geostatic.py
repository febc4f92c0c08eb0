"""The geostatic stage helper against the closed form of a soil column in uniaxial strain."""
import pytest

from beamsolid import Model
from beamsolid.geostatic import geostatic_stage, geostatic_stress_error
from beamsolid.scenes.donut_pullout import CONTACT, DonutModel, DonutPullout


def block(m, nu, gamma, n=3, depth=4.0, width=2.0, sides_on_rollers=True, wrapped=False):
    """A soil block [0, w]^2 x [-depth, 0] of n x n x n stdBricks carrying their weight
    (wrapped: in an InitialStateAnalysisWrapper, tag 1, of the elastic material 2)."""
    m.wipe()
    m.model("basic", "-ndm", 3, "-ndf", 3)
    if wrapped:
        m.nDMaterial("ElasticIsotropic", 2, 30e3, nu)
        m.nDMaterial("InitialStateAnalysisWrapper", 1, 2, 3)
    else:
        m.nDMaterial("ElasticIsotropic", 1, 30e3, nu)
    tag = lambda i, j, k: 1 + i + (n + 1) * (j + (n + 1) * k)
    for k in range(n + 1):
        for j in range(n + 1):
            for i in range(n + 1):
                # A little skew in plan keeps the test honest about distorted bricks.
                x, y = width * i / n + 0.05 * j, width * j / n
                m.node(tag(i, j, k), x, y, -depth * k / n)
    elements = []
    for k in range(n):
        for j in range(n):
            for i in range(n):
                bottom = [tag(i, j, k + 1), tag(i + 1, j, k + 1), tag(i + 1, j + 1, k + 1), tag(i, j + 1, k + 1)]
                top = [tag(i, j, k), tag(i + 1, j, k), tag(i + 1, j + 1, k), tag(i, j + 1, k)]
                e = len(elements) + 1
                m.element("stdBrick", e, *bottom, *top, 1, 0.0, 0.0, -gamma)
                elements.append(e)
    for k in range(n + 1):
        for j in range(n + 1):
            for i in range(n + 1):
                side = i in (0, n) or j in (0, n)
                m.fix(tag(i, j, k), int(side and sides_on_rollers), int(side and sides_on_rollers), int(k == n))
    return elements


@pytest.mark.parametrize("nu", [0.25, 0.3, 0.45])
def test_block_reaches_sigma_v_gamma_z_and_K0(nu):
    m, gamma = Model(), 18.0
    elements = block(m, nu, gamma)
    state = geostatic_stage(m, soil_elements=elements, gamma=gamma, K0=nu / (1 - nu), check_tol=1e-10)
    assert state.error_v < 1e-10 and state.error_h < 1e-10
    assert state.K0 == pytest.approx(nu / (1 - nu), rel=1e-10)
    assert m.getTime() == 0.0  # loadConst('-time', 0) ran


def test_wrong_boundary_conditions_are_caught():
    m, gamma = Model(), 18.0
    elements = block(m, 0.3, gamma, sides_on_rollers=False)  # the column can bulge: no uniaxial strain
    with pytest.raises(RuntimeError, match="off the closed form"):
        geostatic_stage(m, soil_elements=elements, gamma=gamma, K0=0.3 / 0.7, check_tol=1e-3)


def test_donut_with_a_held_pile_and_frictionless_contacts():
    s = DonutPullout(n_theta=8, n_radial=3, n_z=4, mu=0.5)
    model = DonutModel(s).build()
    m = model.m
    soil = [e for e in m.getEleTags() if e in model.mesh.elements]
    state = geostatic_stage(m, soil_elements=soil, gamma=s.gamma, K0=s.K0, contact_materials=[CONTACT],
                            check_tol=1e-10)
    assert state.iterations <= 3
    # The ring's normal forces carry sigma_h exactly (faceted ring, consistent nodal forces).
    assert model.normal_sum() == pytest.approx(s.faceted_normal_sum, rel=1e-10)
    ev, eh, _ = geostatic_stress_error(m, soil, s.gamma, s.K0)
    assert max(ev, eh) < 1e-10


def test_initial_state_zeroes_the_settlement_and_keeps_the_stresses():
    m, gamma, nu = Model(), 18.0, 0.3
    elements = block(m, nu, gamma, wrapped=True)
    state = geostatic_stage(m, soil_elements=elements, gamma=gamma, K0=nu / (1 - nu), check_tol=1e-10,
                            initial_state=True)
    assert state.error_v < 1e-10
    assert max(abs(v) for t in m.getNodeTags() for v in m.nodeDisp(t)) == 0.0
    ev, eh, k0 = geostatic_stress_error(m, elements, gamma, nu / (1 - nu))
    assert max(ev, eh) < 1e-10 and k0 == pytest.approx(nu / (1 - nu), rel=1e-10)
    # The weight stays balanced at the reference geometry: a further step moves nothing.
    m.integrator("LoadControl", 1.0)
    m.test("NormUnbalance", 1e-8, 5)
    m.algorithm("Newton")
    m.analysis("Static")
    assert m.analyze(1) == 0
    assert max(abs(v) for t in m.getNodeTags() for v in m.nodeDisp(t)) < 1e-14


def test_initial_state_without_the_wrapper_is_caught():
    m, gamma = Model(), 18.0
    elements = block(m, 0.3, gamma)  # plain ElasticIsotropic: 'off' re-evaluates it at zero strain
    with pytest.raises(RuntimeError, match="InitialStateAnalysisWrapper"):
        geostatic_stage(m, soil_elements=elements, gamma=gamma, K0=0.3 / 0.7, initial_state=True)

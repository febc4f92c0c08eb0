"""Verification of the beam-solid contact elements through the Python commands.

- BeamContact3Dp converges to the BeamContact3D (Lagrange) answer as the
  penalty grows, with the error of a spring in series, k_s / (k_s + penalty)
  (relative 2%), i.e. ~ 1/penalty.
- Rotational friction: a pile twisted inside the confined donut resists with
  the moment mu R sum(N_i) at full sliding (relative 1e-6).
- Newton's method converges at order >= 1.8 (median of the testNorm() order
  estimates) while every contact slides and the slip turns from axial to
  circumferential.
- An SPD-only system (Cholmod, ProfileSPD) is refused for contact models with
  an OpenSeesError that names the element and says to use UmfPack.
- Bad input for the contact commands raises clear errors.
"""
import math
import re
import statistics
from dataclasses import replace

import pytest

import beamsolid
from beamsolid.scenes.donut_pullout import DonutModel, DonutPullout, PulloutResult, run

COARSE = DonutPullout(mu=0.5, n_theta=8, n_radial=2, n_z=5, pull=0.05, steps=10)


def at_full_sliding(r):
    assert r.failed_step == 0 and r.full_sliding is not None
    return len(r.head_force) - 1


# --- penalty -> Lagrange ---------------------------------------------------------------


def test_penalty_contact_converges_to_the_lagrange_answer_as_one_over_penalty():
    ref = run(COARSE, extra_after_full_sliding=1)
    q_ref = ref.head_force[at_full_sliding(ref)]
    penalties = [1e4, 1e5, 1e6, 1e7]
    geo_err, q_err = [], []
    for kappa in penalties:
        r = run(replace(COARSE, contact="BeamContact3Dp", penalty=kappa), extra_after_full_sliding=1)
        k = at_full_sliding(r)
        assert r.head_force[k] == pytest.approx(COARSE.mu * r.normal_sum[k], rel=1e-6)
        geo_err.append(1.0 - r.geostatic_normal_sum / ref.geostatic_normal_sum)
        q_err.append(1.0 - r.head_force[k] / q_ref)
    for errors in (geo_err, q_err):
        # The penalty lets the soil nodes into the pile and relaxes the confinement: the
        # normal forces fall short, less so for a stiffer penalty.
        assert all(e > 0 for e in errors)
        assert all(a > b for a, b in zip(errors, errors[1:]))
        # A penalty spring in series with the soil's stiffness k_s: error k_s / (k_s + kappa),
        # k_s read off the stiffest penalty.
        k_s = penalties[-1] * errors[-1] / (1.0 - errors[-1])
        for kappa, e in zip(penalties, errors):
            assert e == pytest.approx(k_s / (k_s + kappa), rel=0.02), (kappa, e)
        # Asymptotically 1/kappa: error x kappa settles.
        assert errors[-1] * penalties[-1] == pytest.approx(errors[-2] * penalties[-2], rel=0.05)


# --- rotational friction ------------------------------------------------------------------


def test_twisted_pile_resists_with_mu_R_times_the_normal_sum():
    s = replace(COARSE, pull=0.0, twist=0.2, steps=10)
    model = DonutModel(s).build()
    r = PulloutResult(setup=s, n_contacts=len(model.contacts))
    r.geostatic_normal_sum = model.geostatic()
    model.release()
    model.record(r)
    model.pull(r, extra_after_full_sliding=1)
    k = at_full_sliding(r)
    assert r.sticking[k] == 0 and r.sliding[k] == r.n_contacts
    assert r.head_moment[k] == pytest.approx(s.mu * s.pile_radius * r.normal_sum[k], rel=1e-6)
    # Torsion leaves the confinement alone (up to the tangent-plane drift of the slip).
    assert r.normal_sum[k] == pytest.approx(r.geostatic_normal_sum, rel=1e-3)
    # The friction is mu N at every contact and goes round the pile (the slip's small axial
    # share comes from the soil's vertical motion as the normal forces change by ~1e-4).
    for f in model.contact_scalars():
        assert math.hypot(f[1], f[2]) == pytest.approx(s.mu * f[0], rel=1e-6)
        assert abs(f[1]) <= 1e-3 * abs(f[2])
    model.m.wipe()


# --- Newton's rate while sliding ------------------------------------------------------------


def order_estimates(norms, floor):
    """log(r_k+1 / r_k) / log(r_k / r_k-1) for the norms above `floor`."""
    good = [x for x in norms if x > floor]
    return [math.log(good[k + 1] / good[k]) / math.log(good[k] / good[k - 1]) for k in range(1, len(good) - 1)]


def test_newton_converges_quadratically_while_the_slip_turns():
    # A soft soil and a stiff stick law make the return map's change of direction the
    # governing nonlinearity: the pile is pulled until every contact slides, then twisted
    # in large steps so that each contact's slip turns from axial to circumferential.
    tol = 1e-8
    s = replace(COARSE, G=1e4, soil_E=2e3, pull=0.05, steps=3, tol=tol)
    model = DonutModel(s).build()
    m = model.m
    model.geostatic()
    model.release()
    for _ in range(3):
        assert m.analyze(1) == 0
    assert model.status_counts() == (0, len(model.contacts))
    m.loadConst("-time", 0.0)
    for n in model.pile_nodes:
        m.remove("sp", n, 6)
    m.timeSeries("Linear", 3)
    m.pattern("Plain", 3, 3)
    m.sp(model.pile_nodes[0], 6, 0.1)
    m.integrator("LoadControl", 0.25)
    estimates = []
    for _ in range(4):
        assert m.analyze(1) == 0
        assert model.status_counts() == (0, len(model.contacts))
        norms = m.testNorm()[: m.testIter()]  # padded with zeros to maxIter, as OpenSees
        assert 3 <= len(norms) <= 8
        # Norms within 100x of the tolerance are round-off, not the rate.
        estimates += order_estimates(norms, 100 * tol)
    assert len(estimates) >= 6, estimates
    assert statistics.median(estimates) >= 1.8, estimates
    m.wipe()


# --- solver choice and bad input ----------------------------------------------------------


def pile_and_soil_node(m):
    """A fixed pile segment (beam nodes 1, 2), soil node 3 on its surface, spare nodes."""
    m.model("basic", "-ndm", 3, "-ndf", 6)
    m.node(1, 0.0, 0.0, 0.0)
    m.node(2, 0.0, 0.0, 2.0)
    m.node(5, 0.3, 0.0, 0.5)  # a 6-dof node
    for n in (1, 2):
        m.fix(n, 1, 1, 1, 1, 1, 1)
    m.geomTransf("Linear", 1, 1.0, 0.0, 0.0)
    m.element("elasticBeamColumn", 10, 1, 2, 0.28, 3e7, 1.2e7, 0.0127, 0.0064, 0.0064, 1)
    m.model("basic", "-ndm", 3, "-ndf", 3)
    m.node(3, 0.3, 0.0, 1.0)
    m.node(4, 0.3, 0.0, 1.0)
    m.node(6, 0.0, 0.0, 3.0)  # a 3-dof node where a beam node belongs
    m.node(7, 0.3, 0.0, 1.5)
    m.nDMaterial("ContactMaterial3D", 1, 0.3, 1e5, 0.0, 0.0)
    m.nDMaterial("ElasticIsotropic", 2, 1e4, 0.3)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.load(3, -10.0, 0.0, 0.0)


def held_soil_node(m):
    """Spare nodes fixed; a soft spring (k = 1) ties soil node 3 to a fixed node 8, so the
    system is regular before a penalty contact closes."""
    for n in (6, 7):
        m.fix(n, 1, 1, 1)
    m.fix(5, 1, 1, 1, 1, 1, 1)
    m.node(8, 0.3, 0.0, 1.0)
    m.fix(8, 1, 1, 1)
    m.uniaxialMaterial("Elastic", 3, 1.0)
    m.element("zeroLength", 30, 3, 8, "-mat", 3, 3, 3, "-dir", 1, 2, 3)


def static(m, system):
    m.constraints("Plain")
    m.numberer("RCM")
    m.system(system)
    m.test("NormUnbalance", 1e-8, 10)
    m.algorithm("Newton")
    m.integrator("LoadControl", 1.0)
    m.analysis("Static")
    return m.analyze(1)


@pytest.mark.parametrize("system", ["Cholmod", "ProfileSPD"])
@pytest.mark.parametrize("element", [("BeamContact3D", 21, 1, 2, 3, 4, 0.3, 1, 1, 1e-8, 1e-8),
                                     ("BeamContact3Dp", 22, 1, 2, 3, 0.3, 1, 1, 1e7)])
def test_an_spd_only_system_is_refused_with_a_pointer_to_umfpack(model, system, element):
    pile_and_soil_node(model)
    held_soil_node(model)
    if element[0] == "BeamContact3Dp":
        model.fix(4, 1, 1, 1)  # no multiplier node
    model.element(*element)
    # analyze never raises (OpenSees' contract): the set-up failure is -1 and its reason is kept.
    assert static(model, system) == -1
    message = model.last_error()
    assert f"system {system}" in message
    assert f"element {element[0]} {element[1]}" in message
    assert "UmfPack" in message
    # The model is intact: with UmfPack it solves, the soil node pressed onto the pile
    # (the spring takes ~1e-6 of the load, or the penalty's penetration times k).
    assert static(model, "UmfPack") == 0
    assert model.eleResponse(element[1], "forcescalar")[0] == pytest.approx(10.0, rel=1e-5)


BAD_INPUT = [
    (("BeamContact3D", 1, 1, 2, 5, 4, 0.3, 1, 1, 1e-8, 1e-8), "secondary (solid) node 5 has 6 dofs, expected 3"),
    (("BeamContact3D", 1, 1, 6, 3, 4, 0.3, 1, 1, 1e-8, 1e-8), "primary (beam) node 6 has 3 dofs, expected 6"),
    (("BeamContact3D", 1, 1, 2, 3, 5, 0.3, 1, 1, 1e-8, 1e-8), "multiplier node 5 has 6 dofs, expected 3"),
    (("BeamContact3Dp", 1, 1, 2, 5, 0.3, 1, 1, 1e6), "secondary (solid) node 5 has 6 dofs, expected 3"),
    (("BeamContact3D", 1, 1, 2, 3, 4, 0.3, 1, 2, 1e-8, 1e-8), "nDMaterial 2 (ElasticIsotropic3D) is not a ContactMaterial3D"),
    (("BeamContact3Dp", 1, 1, 2, 3, 0.3, 1, 2, 1e6), "need a ContactMaterial3D"),
    (("BeamContact3D", 1, 1, 2, 3, 4, 0.3, 1, 9, 1e-8, 1e-8), "nDMaterial 9 does not exist"),
    (("BeamContact3D", 1, 1, 2, 3, 3, 0.3, 1, 1, 1e-8, 1e-8), "node 3 appears twice"),
    (("BeamContact3D", 1, 1, 2, 3, 4, -0.3, 1, 1, 1e-8, 1e-8), "(radius): expected a positive number"),
    (("BeamContact3D", 1, 1, 2, 3, 4, 0.3, 7, 1, 1e-8, 1e-8), "geomTransf 7 does not exist"),
    (("BeamContact3D", 1, 1, 2, 33, 4, 0.3, 1, 1, 1e-8, 1e-8), "node 33 does not exist"),
    (("BeamContact3D", 1, 1, 2, 3, 4, 0.3, 1, 1, 1e-8, 1e-8, 2), "(cSwitch): expected 0"),
    (("BeamContact3Dp", 1, 1, 2, 3, 0.3, 1, 1, -1.0), "(penalty): expected a positive number"),
]


@pytest.mark.parametrize("args, expected", BAD_INPUT)
def test_bad_contact_element_input_is_a_clear_error(model, args, expected):
    pile_and_soil_node(model)
    with pytest.raises(beamsolid.OpenSeesError) as error:
        model.element(*args)
    message = str(error.value)
    assert message.startswith(f"element {args[0]} 1: "), message
    assert expected in message, message


def test_a_shared_multiplier_node_is_refused(model):
    pile_and_soil_node(model)
    model.element("BeamContact3D", 1, 1, 2, 3, 4, 0.3, 1, 1, 1e-8, 1e-8)
    with pytest.raises(beamsolid.OpenSeesError, match=r"^element BeamContact3D 2: multiplier node 4 is also used "
                                                      r"by element 1; every BeamContact3D needs its own"):
        model.element("BeamContact3D", 2, 1, 2, 7, 4, 0.3, 1, 1, 1e-8, 1e-8)


def test_a_fixed_multiplier_node_is_refused_before_and_after_the_element(model):
    pile_and_soil_node(model)
    model.fix(4, 1, 0, 0)
    with pytest.raises(beamsolid.OpenSeesError, match=r"^element BeamContact3D 1: multiplier node 4 is fixed "
                                                      r"\(dof 1\); the multiplier node must stay free"):
        model.element("BeamContact3D", 1, 1, 2, 3, 4, 0.3, 1, 1, 1e-8, 1e-8)
    model.remove("sp", 4, 1)
    model.element("BeamContact3D", 1, 1, 2, 3, 4, 0.3, 1, 1, 1e-8, 1e-8)
    model.fix(4, 0, 1, 0)
    # Found at analyze, which never raises: a failed step with the reason kept.
    assert static(model, "UmfPack") < 0
    assert re.search(r"multiplier node 4 is fixed \(dof 2\)", model.last_error())


@pytest.mark.parametrize("args, expected", [
    ((5, -0.3, 1e5, 0.0, 0.0), "mu must be a number >= 0"),
    ((5, 0.3, -1.0, 0.0, 0.0), "G must be positive"),
    ((5, 0.3, 1e5, 0.0), "argument 6 (t): expected a number"),
])
def test_bad_contact_material_input_is_a_clear_error(model, args, expected):
    with pytest.raises(beamsolid.OpenSeesError) as error:
        model.nDMaterial("ContactMaterial3D", *args)
    assert str(error.value).startswith("nDMaterial ContactMaterial3D 5: ")
    assert expected in str(error.value)


def test_a_bad_friction_stage_is_a_clear_error(model):
    pile_and_soil_node(model)
    model.element("BeamContact3D", 1, 1, 2, 3, 4, 0.3, 1, 1, 1e-8, 1e-8)
    with pytest.raises(beamsolid.OpenSeesError, match="must be 0 \\(frictionless\\) or 1 \\(frictional\\)"):
        model.updateMaterialStage("-material", 1, "-stage", 3)
    with pytest.raises(beamsolid.OpenSeesError, match="^element BeamContact3D 1: .*must be 0"):
        model.setParameter("-val", 0.5, "-ele", 1, "friction")


def test_an_element_added_later_on_the_multiplier_node_is_refused_at_analyze(model):
    pile_and_soil_node(model)
    held_soil_node(model)
    model.element("BeamContact3D", 1, 1, 2, 3, 4, 0.3, 1, 1, 1e-8, 1e-8)
    assert static(model, "UmfPack") == 0
    model.element("zeroLength", 41, 8, 4, "-mat", 3, "-dir", 1)
    assert model.analyze(1) == -3  # found by the element's update: a failed step
    assert re.search(r"element BeamContact3D 1: multiplier node 4 is also used by element 41", model.last_error())
    model.remove("element", 41)
    assert model.analyze(1) == 0

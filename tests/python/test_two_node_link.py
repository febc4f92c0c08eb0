"""twoNodeLink against closed forms.

- Springs in a rotated frame: the deformations are the local components
  R (u_j - u_i), the basic forces k * deformation, the end forces -R^T q at
  node i and R^T q at node j (2D at 30 degrees, 3D with -orient).
- A rigid-body motion (translation plus a small rotation phi about the
  axis, theta_i = theta_j = phi, u_j - u_i = phi x (x_j - x_i)) deforms no
  spring, and the end forces of any deformation are in equilibrium (sum of
  forces and of moments about node i, r x F included, zero to 1e-12).
- Shear and moment coupling: a 2D link with a shear spring k only and node j
  turned by theta: d2 = -(1 - sD) L theta, q2 = k d2, moments
  M_i = -sD L q2, M_j = -(1 - sD) L q2.
- P-Delta with a full shear couple: a vertical link in tension P (axial
  spring) pushed sideways by H has the lateral stiffness k_shear + P / L.
- -mass m: lumped m/2 per translation: omega^2 = k / (m/2).
- Coincident nodes without -orient: the global axes (as OpenSees documents).
- Bad input raises OpenSeesError naming the command and the argument.
"""
import math

import numpy as np
import pytest

import beamsolid


def solve_sp(model, handler="Penalty"):
    if handler == "Penalty":
        model.constraints("Penalty", 1.0e16, 1.0e16)
    else:
        model.constraints(handler)
    model.system("FullGeneral")
    model.numberer("Plain")
    model.test("NormDispIncr", 1e-12, 10)
    model.algorithm("Newton")
    model.integrator("LoadControl", 1.0)
    model.analysis("Static")
    assert model.analyze(1) == 0


def impose(model, displacements):
    model.timeSeries("Constant", 1)
    model.pattern("Plain", 1, 1)
    for (node, dof), value in displacements.items():
        model.sp(node, dof, value)


def test_springs_in_a_rotated_frame_2d(model):
    angle, length = math.radians(30.0), 2.0
    c, s = math.cos(angle), math.sin(angle)
    k1, k2 = 500.0, 40.0
    model.model("basic", "-ndm", 2, "-ndf", 2)
    model.node(1, 0.0, 0.0)
    model.node(2, length * c, length * s)
    model.uniaxialMaterial("Elastic", 1, k1)
    model.uniaxialMaterial("Elastic", 2, k2)
    model.element("twoNodeLink", 1, 1, 2, "-mat", 1, 2, "-dir", 1, 2)
    du = np.array([0.013, -0.021])
    impose(model, {(1, 1): 0.0, (1, 2): 0.0, (2, 1): du[0], (2, 2): du[1]})
    solve_sp(model)
    R = np.array([[c, s], [-s, c]])
    d = R @ du
    q = np.array([k1, k2]) * d
    assert np.allclose(model.eleResponse(1, "basicDeformation"), d, rtol=0, atol=1e-14)
    assert np.allclose(model.eleResponse(1, "basicForce"), q, rtol=0, atol=1e-12)
    assert np.allclose(model.eleResponse(1, "force"), np.r_[-R.T @ q, R.T @ q], rtol=0, atol=1e-12)
    assert np.allclose(model.eleResponse(1, "localForce"), np.r_[-q, q], rtol=0, atol=1e-12)
    assert np.allclose(model.eleResponse(1, "localDisplacement"), np.r_[0.0, 0.0, d], rtol=0, atol=1e-14)


def test_springs_in_a_rotated_frame_3d_orient(model):
    x, yp = np.array([1.0, 1.0, 0.0]), np.array([0.0, 0.3, 1.0])
    ex = x / np.linalg.norm(x)
    ez = np.cross(x, yp) / np.linalg.norm(np.cross(x, yp))
    ey = np.cross(ez, ex)
    R = np.vstack([ex, ey, ez])
    k = np.array([300.0, 20.0, 50.0])
    model.model("basic", "-ndm", 3, "-ndf", 3)
    model.node(1, 0.0, 0.0, 0.0)
    model.node(2, 0.4, -0.2, 1.1)  # -orient overrides the node geometry
    for d in (1, 2, 3):
        model.uniaxialMaterial("Elastic", d, k[d - 1])
    model.element("twoNodeLink", 1, 1, 2, "-mat", 1, 2, 3, "-dir", 1, 2, 3, "-orient", *x, *yp)
    ui, uj = np.array([0.002, 0.001, -0.003]), np.array([0.011, -0.007, 0.004])
    impose(model, {**{(1, d + 1): ui[d] for d in range(3)}, **{(2, d + 1): uj[d] for d in range(3)}})
    solve_sp(model)
    d = R @ (uj - ui)
    q = k * d
    for axis, row in zip(("xaxis", "yaxis", "zaxis"), R):
        assert np.allclose(model.eleResponse(1, axis), row, rtol=0, atol=1e-15)
    assert np.allclose(model.eleResponse(1, "deformation"), d, rtol=0, atol=1e-15)
    assert np.allclose(model.eleResponse(1, "force"), np.r_[-R.T @ q, R.T @ q], rtol=0, atol=1e-12)


def link3d(model, xj, extra=(), dirs=(1, 2, 3, 4, 5, 6)):
    model.model("basic", "-ndm", 3, "-ndf", 6)
    model.node(1, 0.0, 0.0, 0.0)
    model.node(2, *xj)
    for d in dirs:
        model.uniaxialMaterial("Elastic", d, (1000.0, 10.0, 20.0, 100.0, 200.0, 300.0)[d - 1])
    model.element("twoNodeLink", 1, 1, 2, "-mat", *dirs, "-dir", *dirs, *extra)


@pytest.mark.parametrize("extra", [(), ("-shearDist", 0.2, 0.7), ("-orient", 0.0, 0.0, 1.0)])
def test_rigid_motion_deforms_nothing_and_forces_balance(model, extra):
    xj = np.array([1.0, 2.0, 0.5])
    phi = np.array([0.002, -0.001, 0.003])
    t = np.array([0.01, 0.02, -0.01])
    link3d(model, xj, extra)
    uj = t + np.cross(phi, xj)
    values = {**{(1, d + 1): t[d] for d in range(3)}, **{(1, d + 4): phi[d] for d in range(3)},
              **{(2, d + 1): uj[d] for d in range(3)}, **{(2, d + 4): phi[d] for d in range(3)}}
    impose(model, values)
    solve_sp(model)
    assert np.allclose(model.eleResponse(1, "basicDeformation"), 0.0, rtol=0, atol=1e-15)
    model.wipe()
    # Any deformation: the end forces balance.
    link3d(model, xj, extra)
    rng = np.random.default_rng(3)
    u = rng.normal(scale=1e-3, size=12)
    impose(model, {(1 + k // 6, 1 + k % 6): u[k] for k in range(12)})
    solve_sp(model)
    f = np.array(model.eleResponse(1, "force"))
    assert np.allclose(f[0:3] + f[6:9], 0.0, rtol=0, atol=1e-12)
    moment = f[3:6] + f[9:12] + np.cross(xj, f[6:9])
    assert np.allclose(moment, 0.0, rtol=0, atol=1e-12)


@pytest.mark.parametrize("sd", [0.5, 0.3])
def test_shear_moment_coupling_2d(model, sd):
    L, k, theta = 4.0, 25.0, 0.01
    model.model("basic", "-ndm", 2, "-ndf", 3)
    model.node(1, 0.0, 0.0)
    model.node(2, 0.0, L)  # local x = +Y, y = -X
    model.uniaxialMaterial("Elastic", 1, k)
    model.element("twoNodeLink", 1, 1, 2, "-mat", 1, "-dir", 2, "-shearDist", sd)
    impose(model, {(1, 1): 0.0, (1, 2): 0.0, (1, 3): 0.0, (2, 1): 0.0, (2, 2): 0.0, (2, 3): theta})
    solve_sp(model)
    d2 = -(1.0 - sd) * L * theta
    q2 = k * d2
    assert abs(model.eleResponse(1, "basicDeformation")[0] - d2) < 1e-15
    local = model.eleResponse(1, "localForce")
    assert np.allclose(local, [0.0, -q2, -sd * L * q2, 0.0, q2, -(1.0 - sd) * L * q2], rtol=0, atol=1e-12)


@pytest.mark.parametrize("P", [30.0, -30.0])
def test_pdelta_shear_couple_adds_p_over_l(model, P):
    """Node 2 above node 1 (L = 2), rotations fixed: H = (k + P/L) Delta."""
    L, k, H, ka = 2.0, 40.0, 0.5, 1.0e5
    model.model("basic", "-ndm", 2, "-ndf", 3)
    model.node(1, 0.0, 0.0)
    model.node(2, 0.0, L)
    model.fix(1, 1, 1, 1)
    model.fix(2, 0, 0, 1)
    model.uniaxialMaterial("Elastic", 1, ka)
    model.uniaxialMaterial("Elastic", 2, k)
    model.element("twoNodeLink", 1, 1, 2, "-mat", 1, 2, "-dir", 1, 2, "-pDelta", 0.0, 0.0)
    model.timeSeries("Linear", 1)
    model.pattern("Plain", 1, 1)
    model.load(2, H, P, 0.0)
    model.constraints("Plain")
    model.system("UmfPack")
    model.numberer("Plain")
    model.test("NormDispIncr", 1e-14, 10)
    model.algorithm("Newton")
    model.integrator("LoadControl", 1.0)
    model.analysis("Static")
    assert model.analyze(1) == 0
    assert abs(model.nodeDisp(2, 2) - P / ka) < 1e-14
    assert abs(model.nodeDisp(2, 1) - H / (k + P / L)) < 1e-12 * abs(H / k)
    # The end moments are the shear's L V (no P-Delta moments at the ends: r_i = r_j = 0).
    q = model.eleResponse(1, "basicForce")
    assert abs(q[0] - P) < 1e-9 and abs(q[1] + k * model.nodeDisp(2, 1)) < 1e-12


def test_lumped_mass(model):
    m, k1, k2 = 4.0, 10.0, 20.0
    model.model("basic", "-ndm", 2, "-ndf", 3)
    model.node(1, 0.0, 0.0)
    model.node(2, 3.0, 4.0)
    model.uniaxialMaterial("Elastic", 1, k1)
    model.uniaxialMaterial("Elastic", 2, k2)
    model.element("twoNodeLink", 1, 1, 2, "-mat", 1, 2, "-dir", 1, 2, "-mass", m)
    model.fix(1, 1, 1, 1)
    model.fix(2, 0, 0, 1)
    assert np.allclose(model.eigen("-fullGenLapack", 2), [k1 / (m / 2), k2 / (m / 2)], rtol=1e-12)


def test_coincident_nodes_use_global_axes(model):
    link3d(model, (0.0, 0.0, 0.0), dirs=(1, 2, 3))
    assert model.eleResponse(1, "xaxis") == [1.0, 0.0, 0.0]
    assert model.eleResponse(1, "yaxis") == [0.0, 1.0, 0.0]
    impose(model, {**{(n, d): 0.0 for n in (1, 2) for d in range(1, 7)}, (2, 1): 0.1, (2, 2): 0.2, (2, 3): 0.3})
    solve_sp(model)
    assert np.allclose(model.eleResponse(1, "basicForce"), [100.0, 2.0, 6.0], rtol=1e-12)


def error_of(model, *args):
    with pytest.raises(beamsolid.OpenSeesError) as err:
        model.element("twoNodeLink", *args)
    return str(err.value)


def test_bad_input_names_command_and_argument(model):
    model.model("basic", "-ndm", 2, "-ndf", 3)
    model.node(1, 0.0, 0.0)
    model.node(2, 1.0, 0.0)
    model.node(3, 2.0, 0.0)
    model.uniaxialMaterial("Elastic", 1, 10.0)
    cases = [
        ((5, 1, 2, 3, "-mat", 1, "-dir", 1), "exactly 2 nodes"),
        ((5, 1, 2, "-dir", 1), "'-mat'"),
        ((5, 1, 2, "-mat", 1), "'-dir'"),
        ((5, 1, 2, "-mat", 1, 1, "-dir", 1), "one direction per material"),
        ((5, 1, 2, "-mat", 9, "-dir", 1), "uniaxialMaterial 9"),
        ((5, 1, 2, "-mat", 1, "-dir", 4), "direction 4"),
        ((5, 1, 2, "-mat", 1, "-dir", 1, "-orient", 1.0, 0.0), "orientation"),
        ((5, 1, 2, "-mat", 1, "-dir", 1, "-pDelta", 0.5), "pDeltaVals"),
        ((5, 1, 2, "-mat", 1, "-dir", 1, "-shearDist", 0.5, 0.5), "sDratios"),
        ((5, 1, 2, "-mat", 1, "-dir", 1, "-mass", -1.0), "(m)"),
        ((5, 1, 2, "-mat", 1, "-dir", 1, "-doRayleigh", 1), "option"),
        ((5, 1, 2, "-mat", 1, "-dir", 1, "-bogus"), "option"),
        ((5, 1, 42, "-mat", 1, "-dir", 1), "42"),
        ((5, 1, 2, "-mat", 1, "-dir", 1, "-orient", 0.0, 0.0, 1.0), "plane"),
    ]
    for args, words in cases:
        msg = error_of(model, *args)
        assert "element twoNodeLink 5" in msg and words in msg, (args, msg)
    assert model.getEleTags() == []


def test_rotation_direction_needs_rotational_dofs(model):
    model.model("basic", "-ndm", 2, "-ndf", 2)
    model.node(1, 0.0, 0.0)
    model.node(2, 1.0, 0.0)
    model.uniaxialMaterial("Elastic", 1, 10.0)
    msg = error_of(model, 5, 1, 2, "-mat", 1, "-dir", 3)
    assert "element twoNodeLink 5" in msg and "rotation" in msg and "ndf 3" in msg


def test_wrong_space_and_mixed_ndf(model):
    model.model("basic", "-ndm", 1, "-ndf", 1)
    model.node(1, 0.0)
    model.node(2, 1.0)
    model.uniaxialMaterial("Elastic", 1, 10.0)
    msg = error_of(model, 5, 1, 2, "-mat", 1, "-dir", 1)
    assert "element twoNodeLink 5" in msg and "-ndm 1" in msg
    model.wipe()
    model.model("basic", "-ndm", 3, "-ndf", 6)
    model.node(1, 0.0, 0.0, 0.0)
    model.model("basic", "-ndm", 3, "-ndf", 3)
    model.node(2, 1.0, 0.0, 0.0)
    model.uniaxialMaterial("Elastic", 1, 10.0)
    msg = error_of(model, 5, 1, 2, "-mat", 1, "-dir", 1)
    assert "element twoNodeLink 5" in msg and "ndf" in msg

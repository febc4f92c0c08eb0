"""elasticBeamColumn through the Python commands against closed forms.

Euler-Bernoulli beams with nodal loads and consistent element loads are exact
at the nodes, so those checks use a relative tolerance of 1e-10. The P-Delta
column is an approximation (chord rotation only) and is checked for its
convergence with the mesh.
"""
import math

import numpy as np
import pytest

import beamsolid

E, G = 30.0e6, 12.0e6
A, J, IY, IZ = 0.5, 0.04, 0.02, 0.035  # Iy != Iz: the two bending planes differ


def local_axes(xi, xj, vecxz):
    """Rows x, y, z of the element's local frame (OpenSees convention)."""
    x = np.asarray(xj, float) - np.asarray(xi, float)
    x /= np.linalg.norm(x)
    v = np.asarray(vecxz, float)
    z = v - v.dot(x) * x
    z /= np.linalg.norm(z)
    y = np.cross(z, x)
    return np.vstack([x, y, z])


def cantilever_tip(L, local_force, local_moment):
    """Tip translation and rotation (local) of a cantilever under tip loads."""
    N, Vy, Vz = local_force
    T, My, Mz = local_moment
    u = np.array([
        N * L / (E * A),
        Vy * L**3 / (3 * E * IZ) + Mz * L**2 / (2 * E * IZ),
        Vz * L**3 / (3 * E * IY) - My * L**2 / (2 * E * IY),
    ])
    theta = np.array([
        T * L / (G * J),
        -Vz * L**2 / (2 * E * IY) + My * L / (E * IY),
        Vy * L**2 / (2 * E * IZ) + Mz * L / (E * IZ),
    ])
    return u, theta


def assert_close(actual, expected, rtol=1e-10):
    actual, expected = np.asarray(actual, float), np.asarray(expected, float)
    scale = np.max(np.abs(expected))
    assert scale > 0.0
    err = np.max(np.abs(actual - expected)) / scale
    assert err <= rtol, f"relative error {err:.3e} > {rtol:.0e}\nactual   {actual}\nexpected {expected}"


def linear_static(m, steps=1, algorithm=("Linear",)):
    m.constraints("Transformation")
    m.numberer("RCM")
    m.system("UmfPack")
    m.test("NormDispIncr", 1e-12, 20)
    m.algorithm(*algorithm)
    m.integrator("LoadControl", 1.0 / steps)
    m.analysis("Static")
    assert m.analyze(steps) == 0


def beam_line(m, xi, xj, n_el, transf_tag, first_node=1):
    """Nodes first_node..first_node+n_el along xi->xj and elements 1..n_el."""
    xi, xj = np.asarray(xi, float), np.asarray(xj, float)
    for k in range(n_el + 1):
        m.node(first_node + k, *(xi + (xj - xi) * k / n_el))
    for k in range(n_el):
        m.element("elasticBeamColumn", k + 1, first_node + k, first_node + k + 1, A, E, G, J, IY, IZ, transf_tag)


# A skew axis with no component equal to another and a vecxz off every axis.
XI = np.array([0.3, -0.2, 0.1])
XJ = XI + np.array([1.0, 2.0, 2.0])  # L = 3
VECXZ = (0.2, -0.4, 1.0)


@pytest.mark.parametrize("n_el", [1, 3])
def test_skew_cantilever_axial_bending_torsion(model, n_el):
    m = model
    m.model("basic", "-ndm", 3, "-ndf", 6)
    m.geomTransf("Linear", 1, *VECXZ)
    beam_line(m, XI, XJ, n_el, 1)
    m.fix(1, 1, 1, 1, 1, 1, 1)
    R = local_axes(XI, XJ, VECXZ)
    L = np.linalg.norm(XJ - XI)
    f_loc = np.array([10.0, -7.0, 5.0])   # N, Vy, Vz
    m_loc = np.array([3.0, 2.0, -4.0])    # T, My, Mz
    tip = n_el + 1
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.load(tip, *(R.T @ f_loc), *(R.T @ m_loc))
    linear_static(m)

    u_loc, th_loc = cantilever_tip(L, f_loc, m_loc)
    u = np.array(m.nodeDisp(tip))
    assert_close(u[:3], R.T @ u_loc)
    assert_close(u[3:], R.T @ th_loc)
    # Each term alone, so that a wrong Iy/Iz or GJ cannot hide behind another.
    assert_close((R @ u[:3])[0], f_loc[0] * L / (E * A))
    assert_close((R @ u[3:])[0], m_loc[0] * L / (G * J))

    # Reactions from statics: base force -F, base moment -(M + r x F).
    m.reactions()
    F, M = R.T @ f_loc, R.T @ m_loc
    react = np.array(m.nodeReaction(1))
    assert_close(react[:3], -F)
    assert_close(react[3:], -(M + np.cross(XJ - XI, F)))
    # Local end forces of the last element: end J carries the tip loads.
    local = np.array(m.eleResponse(n_el, "localForce"))
    assert_close(local[6:9], f_loc)
    assert_close(local[9:12], m_loc)


def test_skew_cantilever_uniform_load(model):
    """eleLoad -beamUniform Wy Wz Wx: w L^4 / 8EI at the tip, the exact curve at every node."""
    m = model
    n_el = 4
    m.model("basic", "-ndm", 3, "-ndf", 6)
    m.geomTransf("Linear", 1, *VECXZ)
    beam_line(m, XI, XJ, n_el, 1)
    m.fix(1, 1, 1, 1, 1, 1, 1)
    R = local_axes(XI, XJ, VECXZ)
    L = np.linalg.norm(XJ - XI)
    wy, wz, wx = -2.0, 1.5, 0.75
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.eleLoad("-ele", *range(1, n_el + 1), "-type", "-beamUniform", wy, wz, wx)
    linear_static(m)

    for k in range(n_el + 1):
        x = L * k / n_el
        shape = x**2 * (6 * L**2 - 4 * L * x + x**2) / 24.0   # E I v(x) / w
        slope = x * (3 * L**2 - 3 * L * x + x**2) / 6.0        # E I v'(x) / w
        u_loc = [wx * (L * x - x**2 / 2) / (E * A), wy * shape / (E * IZ), wz * shape / (E * IY)]
        th_loc = [0.0, -wz * slope / (E * IY), wy * slope / (E * IZ)]
        u = np.array(m.nodeDisp(k + 1))
        if k == 0:
            assert np.all(u == 0.0)
            continue
        assert_close(R @ u[:3], u_loc)
        assert_close((R @ u[3:])[1:], th_loc[1:])
    # Tip in the textbook form.
    u_tip = R @ np.array(m.nodeDisp(n_el + 1))[:3]
    assert_close(u_tip[1], wy * L**4 / (8 * E * IZ))
    assert_close(u_tip[2], wz * L**4 / (8 * E * IY))
    assert_close(u_tip[0], wx * L**2 / (2 * E * A))

    m.reactions()
    W = R.T @ np.array([wx, wy, wz]) * L
    react = np.array(m.nodeReaction(1))
    assert_close(react[:3], -W)
    assert_close(react[3:], -np.cross((XJ - XI) / 2, W))


def test_joint_offsets_match_rigid_arm_statics(model):
    """-jntOffset: flexible part between xI+dI and xJ+dJ, rigid arms to the nodes."""
    m = model
    xi = np.array([0.0, 0.0, 0.0])
    xj = np.array([2.0, 0.5, 1.2])
    d_i = np.array([0.1, -0.2, 0.3])
    d_j = np.array([-0.15, 0.25, 0.1])
    vecxz = (0.0, 0.3, 1.0)
    m.model("basic", "-ndm", 3, "-ndf", 6)
    m.geomTransf("Linear", 1, *vecxz, "-jntOffset", *d_i, *d_j)
    m.node(1, *xi)
    m.node(2, *xj)
    m.element("elasticBeamColumn", 1, 1, 2, A, E, G, J, IY, IZ, 1)
    m.fix(1, 1, 1, 1, 1, 1, 1)
    F = np.array([12.0, -8.0, 5.0])
    M = np.array([1.5, -2.0, 3.0])
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.load(2, *F, *M)
    linear_static(m)

    a, b = xi + d_i, xj + d_j           # ends of the flexible part
    R = local_axes(a, b, vecxz)
    L = np.linalg.norm(b - a)
    arm = xj - b                        # rigid arm from the flexible end to node J
    M_b = M + np.cross(arm, F)
    u_loc, th_loc = cantilever_tip(L, R @ F, R @ M_b)
    u_b, th_b = R.T @ u_loc, R.T @ th_loc
    u = np.array(m.nodeDisp(2))
    assert_close(u[:3], u_b + np.cross(th_b, arm))
    assert_close(u[3:], th_b)

    m.reactions()
    react = np.array(m.nodeReaction(1))
    assert_close(react[:3], -F)
    assert_close(react[3:], -(M + np.cross(xj - xi, F)))


def pdelta_tip(n_el, P, H):
    """Top displacement of a PDelta cantilever column under axial P and lateral H."""
    m = beamsolid.Model()
    L = 3.0
    m.model("basic", "-ndm", 3, "-ndf", 6)
    m.geomTransf("PDelta", 1, 1.0, 0.0, 0.0)   # local z = global X (uses Iy), local y = -Y (Iz)
    beam_line(m, (0, 0, 0), (0, 0, L), n_el, 1)
    m.fix(1, 1, 1, 1, 1, 1, 1)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.load(n_el + 1, H[0], H[1], -P, 0.0, 0.0, 0.0)
    m.constraints("Plain")
    m.numberer("RCM")
    m.system("UmfPack")
    m.test("NormDispIncr", 1e-12, 20)
    m.algorithm("Newton")
    m.integrator("LoadControl", 1.0)
    m.analysis("Static")
    assert m.analyze(1) == 0
    u = m.nodeDisp(n_el + 1)
    m.wipe()
    return np.array(u[:2]), L


def test_pdelta_column_converges_to_the_amplified_deflection():
    """Cantilever column: delta = H (tan kL - kL) / (P k), k = sqrt(P/EI), per bending plane."""
    P_cr = math.pi**2 * E * min(IY, IZ) / (4 * 3.0**2)
    P = 0.5 * P_cr
    H = (40.0, -25.0)
    meshes = [1, 2, 4, 8, 16]
    errors = []
    for n_el in meshes:
        u, L = pdelta_tip(n_el, P, H)
        exact = []
        for h, I in zip(H, (IY, IZ)):  # X bends about local y (Iy); Y about local z (Iz)
            k = math.sqrt(P / (E * I))
            exact.append(h * (math.tan(k * L) - k * L) / (P * k))
        errors.append(np.max(np.abs(u - exact) / np.abs(exact)))
    # The chord-rotation P-Delta element converges at second order: the error
    # falls towards four times per halving of the elements. Measured, X plane
    # (Iy, P = Pcr/2): 1: 1.45e-1, 2: 4.69e-2, 4: 1.25e-2, 8: 3.18e-3, 16: 7.99e-4;
    # Y plane (Iz, P = 0.29 Pcr_z): 6.3e-2, 1.9e-2, 5.0e-3, 1.28e-3, 3.2e-4.
    ratios = [coarse / fine for coarse, fine in zip(errors, errors[1:])]
    assert all(3.0 < r < 4.2 for r in ratios), errors
    assert abs(ratios[-1] - 4.0) < 0.05, errors
    assert errors[-1] < 1e-3, errors
    # One element has its own closed form: lateral stiffness 3EI/L^3 - P/L.
    u1, L = pdelta_tip(1, P, H)
    assert_close(u1, [h / (3 * E * I / L**3 - P / L) for h, I in zip(H, (IY, IZ))])
    # The amplification itself is large: the first-order answer is far off.
    first_order = H[0] * 3.0**3 / (3 * E * IY)
    k = math.sqrt(P / (E * IY))
    assert (math.tan(3 * k) - 3 * k) / (P * k) * H[0] / first_order > 1.5


def test_simply_supported_beam_under_path_series(model):
    """eleLoad in a pattern with a Path series: midspan 5 f(t) w L^4 / 384EI at every step."""
    m = model
    L, n_el, w = 4.0, 4, -3.0
    times = [0.0, 1.0, 2.0, 3.0]
    values = [0.0, 0.5, 2.0, 1.0]
    m.model("basic", "-ndm", 3, "-ndf", 6)
    m.geomTransf("Linear", 1, 0.0, 0.0, 1.0)  # local y = global Y, bending about Z uses Iz
    beam_line(m, (0, 0, 0), (L, 0, 0), n_el, 1)
    m.fix(1, 1, 1, 1, 1, 0, 0)
    m.fix(n_el + 1, 0, 1, 1, 0, 0, 0)
    m.timeSeries("Path", 7, "-dt", 1.0, "-values", *values)
    m.pattern("Plain", 3, 7)
    m.eleLoad("-range", 1, n_el, "-type", "-beamUniform", w, 0.0)
    m.constraints("Plain")
    m.numberer("Plain")
    m.system("ProfileSPD")
    m.test("NormUnbalance", 1e-9, 10)
    m.algorithm("Newton")
    m.integrator("LoadControl", 0.5)
    m.analysis("Static")
    mid = n_el // 2 + 1
    for step in range(1, 6):
        assert m.analyze(1) == 0
        t = 0.5 * step
        f = float(np.interp(t, times, values))
        assert m.getTime() == pytest.approx(t, abs=1e-14)
        assert m.getLoadFactor(3) == pytest.approx(f, rel=1e-14, abs=1e-15)
        assert_close(m.nodeDisp(mid, 2), 5 * f * w * L**4 / (384 * E * IZ))
        assert_close(m.nodeDisp(1, 6), f * w * L**3 / (24 * E * IZ))
        m.reactions()
        assert_close([m.nodeReaction(1, 2), m.nodeReaction(n_el + 1, 2)], [-f * w * L / 2] * 2)
    # A -dt path ends before its last point, as in OpenSees (oracle_scripts/time_series.py): unloaded at t = 3.
    assert m.analyze(1) == 0
    assert m.getLoadFactor(3) == 0.0
    assert m.nodeDisp(mid, 2) == pytest.approx(0.0, abs=1e-15)


def test_point_load_on_a_skew_cantilever(model):
    """eleLoad -beamPoint Py Pz xL Px on the first of two elements: tip P a^2 (3L - a) / 6EI."""
    m = model
    m.model("basic", "-ndm", 3, "-ndf", 6)
    m.geomTransf("Linear", 1, *VECXZ)
    beam_line(m, XI, XJ, 2, 1)
    m.fix(1, 1, 1, 1, 1, 1, 1)
    py, pz, px, x_over_l = -3.0, 2.0, 1.5, 0.3
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.eleLoad("-ele", 1, "-type", "-beamPoint", py, pz, x_over_l, px)
    linear_static(m)
    R = local_axes(XI, XJ, VECXZ)
    L = np.linalg.norm(XJ - XI)
    a = x_over_l * L / 2  # from the fixed end
    u = np.array(m.nodeDisp(3))
    assert_close(R @ u[:3], [px * a / (E * A), py * a**2 * (3 * L - a) / (6 * E * IZ),
                             pz * a**2 * (3 * L - a) / (6 * E * IY)])
    assert_close((R @ u[3:])[1:], [-pz * a**2 / (2 * E * IY), py * a**2 / (2 * E * IZ)])

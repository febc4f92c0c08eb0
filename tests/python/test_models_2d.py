"""1D and 2D models (-ndm 1 and 2): commands, trusses and 2D elastic beams.

Every answer is checked against a closed form: bar forces of a determinate
truss by the method of joints and a joint displacement by virtual work; an
indeterminate three-bar truss against its hand solution; a 1D spring chain
against the series stiffness; a 2D cantilever against PL^3/3EI, PL^2/2EI and
wL^4/8EI; a fixed-base portal frame against slope-deflection; the PDelta
transformation against its one-element linearization (exact) and the
amplified first-order sway; a shear building's periods against the
closed-form eigenvalues of a uniform chain.
"""
import math

import numpy as np
import pytest

import beamsolid


def assert_close(actual, expected, rtol, scale=None):
    actual, expected = np.asarray(actual, float), np.asarray(expected, float)
    scale = np.max(np.abs(expected)) if scale is None else scale
    assert scale > 0.0
    err = np.max(np.abs(actual - expected)) / scale
    assert err <= rtol, f"relative error {err:.3e} > {rtol:.0e}\nactual   {actual}\nexpected {expected}"
    return err


def static(m, test=("NormDispIncr", 1e-12, 20), steps=1):
    m.constraints("Plain")
    m.numberer("RCM")
    m.system("UmfPack")
    m.test(*test)
    m.algorithm("Newton")
    m.integrator("LoadControl", 1.0 / steps)
    m.analysis("Static")
    assert m.analyze(steps) == 0


# --- model, node and the dof commands in every space -----------------------------

@pytest.mark.parametrize("ndm, ndf", [(1, 1), (2, 3), (3, 6)])
def test_default_ndf_is_ndm_times_ndm_plus_one_over_two(model, ndm, ndf):
    model.model("basic", "-ndm", ndm)
    model.node(1, *([1.5] * ndm))
    assert model.getNDF(1) == [ndf]
    assert model.nodeCoord(1) == [1.5] * ndm
    assert model.nodeCoord(1, ndm) == 1.5


def test_node_coord_takes_the_axis_by_name(model):
    # OpenSees takes dim as 1..ndm or as X, Y, Z in either case.
    model.model("basic", "-ndm", 2, "-ndf", 3)
    model.node(1, 1.5, 2.5)
    assert [model.nodeCoord(1, d) for d in ("X", "y", 1, 2)] == [1.5, 2.5, 1.5, 2.5]
    with pytest.raises(beamsolid.OpenSeesError, match=r"nodeCoord 1.*dim 3 is out of range 1..2"):
        model.nodeCoord(1, "Z")
    with pytest.raises(beamsolid.OpenSeesError, match=r"nodeCoord 1: argument 2 \(dim\).*X, Y, Z"):
        model.nodeCoord(1, "W")


@pytest.mark.parametrize("ndm, ndf", [(1, 2), (2, 1), (2, 6), (3, 2), (4, 3)])
def test_ndf_outside_the_space_is_refused(model, ndm, ndf):
    with pytest.raises(beamsolid.OpenSeesError, match="model.*-nd[mf]"):
        model.model("basic", "-ndm", ndm, "-ndf", ndf)


@pytest.mark.parametrize("ndm, crds", [(2, (1.0,)), (2, (1.0, 2.0, 3.0)), (1, (1.0, 2.0)), (3, (1.0, 2.0))])
def test_node_needs_exactly_ndm_coordinates(model, ndm, crds):
    model.model("basic", "-ndm", ndm)
    with pytest.raises(beamsolid.OpenSeesError, match=rf"node 7: expected {ndm} coordinates? .* got {len(crds)}"):
        model.node(7, *crds)


def test_2d_dof_commands_queries_and_recorders(model, tmp_path):
    model.model("basic", "-ndm", 2, "-ndf", 2)
    model.node(1, 0.0, 0.0)
    model.node(2, 2.0, 0.0, "-mass", 3.0, 3.0)
    model.node(3, 2.0, 1.0)
    model.fix(1, 1, 1)
    model.fixY(0.0, 0, 1)
    model.equalDOF(2, 3, 1)
    model.uniaxialMaterial("Elastic", 1, 100.0)
    model.element("Truss", 1, 1, 2, 1.0, 1)
    model.element("Truss", 2, 2, 3, 1.0, 1)
    model.timeSeries("Linear", 1)
    model.pattern("Plain", 1, 1)
    model.load(2, 10.0, 0.0)
    model.sp(3, 2, 0.01)
    out = tmp_path / "disp.out"
    model.recorder("Node", "-file", str(out), "-node", 2, 3, "-dof", 1, 2, "disp")
    with pytest.raises(beamsolid.OpenSeesError, match="load 2: node 2 has 2 dofs but 3"):
        model.load(2, 1.0, 0.0, 0.0)
    with pytest.raises(beamsolid.OpenSeesError, match="fixZ needs a model with -ndm 3"):
        model.fixZ(0.0, 1, 1)
    static(model)
    u = 10.0 * 2.0 / 100.0  # bar 1 carries the load; bar 2 moves rigidly with node 2
    assert model.nodeDisp(2) == pytest.approx([u, 0.0], abs=1e-14)
    assert model.nodeDisp(3) == pytest.approx([u, 0.01], abs=1e-14)
    model.reactions()
    assert model.nodeReaction(1) == pytest.approx([-10.0, 0.0], abs=1e-12)
    # The sp stretches bar 2 by 0.01: N = 100 * 0.01 / 1 pulls node 2 up; its support pulls down.
    assert model.nodeReaction(2, 2) == pytest.approx(-1.0, rel=1e-12)
    rows = np.loadtxt(out, ndmin=2)
    assert rows[-1] == pytest.approx([u, 0.0, u, 0.01], abs=1e-12)
    printed = tmp_path / "model.txt"
    model.printModel("-file", str(printed), "-node", 2)
    text = printed.read_text()
    assert "coordinates 2 0, displacements" in text, text


# --- 2D trusses -----------------------------------------------------------------------

# A simply supported triangle on a 3-4-5 grid: pin at 1, roller (y) at 2.
TRI = {1: (0.0, 0.0), 2: (8.0, 0.0), 3: (4.0, 3.0)}
TRI_BARS = {1: (1, 2, 2.0), 2: (1, 3, 1.5), 3: (2, 3, 1.0)}  # tag: i, j, A
E_TRUSS = 2.0e5


def triangle(m, H, P, ndf=2):
    m.model("basic", "-ndm", 2, "-ndf", ndf)
    for tag, xy in TRI.items():
        m.node(tag, *xy)
    m.fix(1, 1, 1, *([1] * (ndf - 2)))
    m.fix(2, 0, 1, *([1] * (ndf - 2)))
    if ndf == 3:
        m.fix(3, 0, 0, 1)
    m.uniaxialMaterial("Elastic", 1, E_TRUSS)
    for tag, (i, j, area) in TRI_BARS.items():
        m.element("Truss", tag, i, j, area, 1)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.load(3, H, -P, *([0.0] * (ndf - 2)))
    static(m)


def joint_forces(H, P):
    """Method of joints (tension +): reactions by moments about the pin, then joints 2 and 1."""
    ry2 = (4.0 * P + 3.0 * H) / 8.0
    ry1 = P - ry2
    n23 = -ry2 / 0.6          # joint 2, vertical: 0.6 N23 + Ry2 = 0
    n12 = -0.8 * n23          # joint 2, horizontal: -0.8 N23 - N12 = 0
    n13 = -ry1 / 0.6          # joint 1, vertical: 0.6 N13 + Ry1 = 0
    return {1: n12, 2: n13, 3: n23}, (-H, ry1, ry2)


@pytest.mark.parametrize("ndf", [2, 3])
def test_determinate_2d_truss_against_method_of_joints_and_virtual_work(model, ndf):
    H, P = 30.0, 120.0
    triangle(model, H, P, ndf)
    forces, (rx1, ry1, ry2) = joint_forces(H, P)
    for tag in TRI_BARS:
        assert_close(model.eleResponse(tag, "axialForce"), [forces[tag]], 1e-13, scale=P)
    model.reactions()
    assert_close([model.nodeReaction(1, 1), model.nodeReaction(1, 2), model.nodeReaction(2, 2)],
                 [rx1, ry1, ry2], 1e-13, scale=P)
    # Virtual work: the drop of node 3 = sum N n L / (E A), n from a unit load down at 3.
    unit, _ = joint_forces(0.0, 1.0)
    lengths = {1: 8.0, 2: 5.0, 3: 5.0}
    drop = sum(forces[t] * unit[t] * lengths[t] / (E_TRUSS * TRI_BARS[t][2]) for t in TRI_BARS)
    assert_close(-model.nodeDisp(3, 2), drop, 1e-12)
    # Responses in OpenSees' layouts (bar 3 from node 2 to node 3, axis (-0.8, 0.6)).
    n = forces[3]
    f = model.eleResponse(3, "force")
    assert len(f) == 2 * ndf
    expected = [0.8 * n, -0.6 * n] + [0.0] * (ndf - 2)
    assert_close(f, expected + [-v for v in expected], 1e-13, scale=P)
    assert_close(model.eleResponse(3, "localForce"), [-n] + [0.0] * (ndf - 1) + [n] + [0.0] * (ndf - 1), 1e-13,
                 scale=P)
    assert_close(model.eleResponse(3, "basicDeformation"), [n * 5.0 / (E_TRUSS * 1.0)], 1e-12)
    assert_close(model.eleResponse(3, "material", 1, "stress"), [n / 1.0], 1e-13, scale=P)


def test_three_bars_meeting_at_a_point_against_the_hand_solution(model):
    """The classic indeterminate three-bar truss: vertical bar of length h, two
    diagonals at angle t to it, equal EA, a load P down at the joint:
    N_mid = P / (1 + 2 cos^3 t), N_diag = P cos^2 t / (1 + 2 cos^3 t)."""
    h, a, E, A, P = 3.0, 2.0, 2.0e5, 1.2, 50.0
    model.model("basic", "-ndm", 2, "-ndf", 2)
    model.node(1, -a, h)
    model.node(2, 0.0, h)
    model.node(3, a, h)
    model.node(4, 0.0, 0.0)
    for t in (1, 2, 3):
        model.fix(t, 1, 1)
    model.uniaxialMaterial("Elastic", 1, E)
    for t in (1, 2, 3):
        model.element("truss", t, t, 4, A, 1)
    model.timeSeries("Linear", 1)
    model.pattern("Plain", 1, 1)
    model.load(4, 0.0, -P)
    static(model)
    c = h / math.hypot(a, h)
    n_mid = P / (1.0 + 2.0 * c**3)
    n_diag = P * c**2 / (1.0 + 2.0 * c**3)
    assert_close([model.eleResponse(t, "axialForce")[0] for t in (1, 2, 3)], [n_diag, n_mid, n_diag], 1e-12)
    assert_close(model.nodeDisp(4), [0.0, -n_mid * h / (E * A)], 1e-12)


def test_corot_truss_in_2d_matches_the_small_displacement_bar_for_a_small_load(model):
    """A 2D corotTruss: an axial pull of a horizontal bar is exact (no rotation)."""
    model.model("basic", "-ndm", 2, "-ndf", 2)
    model.node(1, 0.0, 0.0)
    model.node(2, 4.0, 0.0)
    model.fix(1, 1, 1)
    model.fix(2, 0, 1)
    model.uniaxialMaterial("Elastic", 1, 1000.0)
    model.element("corotTruss", 1, 1, 2, 2.0, 1)
    model.timeSeries("Linear", 1)
    model.pattern("Plain", 1, 1)
    model.load(2, 20.0, 0.0)
    static(model)
    assert_close(model.nodeDisp(2, 1), 20.0 * 4.0 / (1000.0 * 2.0), 1e-12)
    assert_close(model.eleResponse(1, "axialForce"), [20.0], 1e-12)


def test_1d_chain_of_bars_gives_load_over_series_stiffness(model):
    E = 3.0e4
    lengths, areas = [1.0, 2.5, 0.7, 1.8], [2.0, 0.5, 1.0, 3.0]
    model.model("basic", "-ndm", 1)
    x = 0.0
    model.node(1, x)
    for k, L in enumerate(lengths, start=2):
        x += L
        model.node(k, x)
    model.fix(1, 1)
    model.uniaxialMaterial("Elastic", 1, E)
    for k, A in enumerate(areas, start=1):
        model.element("Truss", k, k, k + 1, A, 1)
    model.timeSeries("Linear", 1)
    model.pattern("Plain", 1, 1)
    P = 12.0
    model.load(len(lengths) + 1, P)
    static(model)
    flex = np.cumsum([L / (E * A) for L, A in zip(lengths, areas)])
    assert_close([model.nodeDisp(k, 1) for k in range(2, len(lengths) + 2)], P * flex, 1e-12)
    assert model.nodeCoord(3) == [3.5]
    model.reactions()
    assert_close(model.nodeReaction(1), [-P], 1e-12)
    assert_close(model.eleResponse(2, "force"), [-P, P], 1e-12)


# --- 2D elastic beams ------------------------------------------------------------------

E_BEAM, A_BEAM, I_BEAM = 2.0e8, 0.01, 8.0e-5


def cantilever(m, n, L=4.0, transf="Linear", angle=0.0):
    """n elements along direction `angle` (radians) from node 1 (fixed)."""
    m.model("basic", "-ndm", 2, "-ndf", 3)
    c, s = math.cos(angle), math.sin(angle)
    for k in range(n + 1):
        m.node(k + 1, c * L * k / n, s * L * k / n)
    m.fix(1, 1, 1, 1)
    m.geomTransf(transf, 1)
    for k in range(1, n + 1):
        m.element("elasticBeamColumn", k, k, k + 1, A_BEAM, E_BEAM, I_BEAM, 1)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)


@pytest.mark.parametrize("n, angle", [(1, 0.0), (3, 0.0), (2, 0.6)])
def test_2d_cantilever_tip_load(model, n, angle):
    L, P, N = 4.0, 15.0, 40.0
    cantilever(model, n, L, angle=angle)
    c, s = math.cos(angle), math.sin(angle)
    # P across the beam (local y), N along it.
    model.load(n + 1, -s * P + c * N, c * P + s * N, 0.0)
    static(model)
    u = model.nodeDisp(n + 1)
    along, across = c * u[0] + s * u[1], -s * u[0] + c * u[1]
    assert_close(across, P * L**3 / (3 * E_BEAM * I_BEAM), 1e-12)
    assert_close(u[2], P * L**2 / (2 * E_BEAM * I_BEAM), 1e-12)
    assert_close(along, N * L / (E_BEAM * A_BEAM), 1e-12)
    # The fixed end's forces: the element at the support carries N, -P and the moment P L.
    assert_close(model.eleResponse(1, "basicForce"), [N, -P * L, P * L * (n - 1) / n], 1e-12, scale=P * L)
    assert_close(model.eleResponse(1, "localForce")[:3], [-N, -P, -P * L], 1e-12, scale=P * L)


def test_2d_cantilever_uniform_load(model):
    L, w, n = 4.0, 6.0, 2
    cantilever(model, n, L)
    model.eleLoad("-ele", *range(1, n + 1), "-type", "-beamUniform", -w)
    static(model)
    assert_close(-model.nodeDisp(n + 1, 2), w * L**4 / (8 * E_BEAM * I_BEAM), 1e-12)
    assert_close(-model.nodeDisp(n + 1, 3), w * L**3 / (6 * E_BEAM * I_BEAM), 1e-12)
    model.reactions()
    assert_close(model.nodeReaction(1), [0.0, w * L, w * L**2 / 2], 1e-12)


@pytest.mark.parametrize("extra", [(0.0,), (0.0, 0.0), (0.0, 0.0, 1.0), (0.0, 0.0, 1.0, -6.0, 0.0)])
def test_2d_uniform_load_in_the_partial_form_over_the_whole_span(model, extra):
    """OpenSees 3.7 reads -beamUniform Wya, Wxa, aOverL, bOverL, Wyb, Wxb in 2D
    (OpenSeesPyDoc's Example 4 writes (-W, 0.0, 0.0)); the whole-span uniform
    case gives the cantilever's w L^4 / 8EI."""
    L, w = 4.0, 6.0
    cantilever(model, 1, L)
    model.eleLoad("-ele", 1, "-type", "-beamUniform", -w, *extra)
    static(model)
    assert_close(-model.nodeDisp(2, 2), w * L**4 / (8 * E_BEAM * I_BEAM), 1e-12)


@pytest.mark.parametrize("values, message", [
    ((-6.0, 0.0, 0.3), "over part of the element"),
    ((-6.0, 0.0, 0.0, 0.5), "over part of the element"),
    ((-6.0, 0.0, 0.0, 1.0, -3.0), "varying"),
    ((-6.0, 1.0, 0.0, 1.0, -6.0), "varying"),  # Wxb defaults to 0 once Wyb is given
    ((-6.0, 0.0, 0.5, 0.2), "aOverL and bOverL"),
    ((-6.0, 0.0, -0.1), "aOverL and bOverL"),
    ((-6.0, 0.0, 0.0, 1.0, -6.0, 0.0, 1.0), "at most"),
])
def test_2d_partial_or_varying_uniform_load_raises(model, values, message):
    cantilever(model, 1, 4.0)
    with pytest.raises(beamsolid.OpenSeesError, match="eleLoad.*" + message):
        model.eleLoad("-ele", 1, "-type", "-beamUniform", *values)


def test_2d_point_load_and_axial_uniform_load_on_a_cantilever(model):
    """-beamPoint Py at xL on one element: deflection at the tip P a^2 (3L - a) / 6EI;
    -beamUniform (0, wx): tip stretch wx L^2 / 2EA."""
    L, P, xL, wx = 4.0, 9.0, 0.3, 2.0
    cantilever(model, 1, L)
    model.eleLoad("-ele", 1, "-type", "-beamPoint", -P, xL)
    model.eleLoad("-ele", 1, "-type", "-beamUniform", 0.0, wx)
    static(model)
    a = xL * L
    assert_close(-model.nodeDisp(2, 2), P * a**2 * (3 * L - a) / (6 * E_BEAM * I_BEAM), 1e-12)
    assert_close(model.nodeDisp(2, 1), wx * L**2 / (2 * E_BEAM * A_BEAM), 1e-12)


def test_section_form_takes_e_a_iz_of_an_elastic_section(model):
    L, P = 4.0, 15.0
    model.model("basic", "-ndm", 2)
    model.node(1, 0.0, 0.0)
    model.node(2, L, 0.0)
    model.fix(1, 1, 1, 1)
    model.geomTransf("Linear", 1)
    model.section("Elastic", 3, E_BEAM, A_BEAM, I_BEAM)
    model.element("elasticBeamColumn", 1, 1, 2, 3, 1)
    model.timeSeries("Linear", 1)
    model.pattern("Plain", 1, 1)
    model.load(2, P, P, 0.0)
    static(model)
    assert_close(model.nodeDisp(2)[:2], [P * L / (E_BEAM * A_BEAM), P * L**3 / (3 * E_BEAM * I_BEAM)], 1e-12)
    with pytest.raises(beamsolid.OpenSeesError, match=r"section Elastic 4: expected E, A, Iz \(3 numbers\)"):
        model.section("Elastic", 4, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0)
    model.section("Fiber", 5, "-GJ", 1.0)
    with pytest.raises(beamsolid.OpenSeesError, match=r"elasticBeamColumn 2: section 5 is a .* section; .*Elastic"):
        model.element("elasticBeamColumn", 2, 1, 2, 5, 1)


def test_moment_release_makes_a_propped_cantilever(model):
    """-release 2 (hinge at J) on a beam fixed at I and propped at J: under w the
    prop takes 3wL/8 and the fixed end wL^2/8."""
    L, w = 5.0, 4.0
    model.model("basic", "-ndm", 2)
    model.node(1, 0.0, 0.0)
    model.node(2, L, 0.0)
    model.fix(1, 1, 1, 1)
    model.fix(2, 0, 1, 1)  # the rotation is fixed too: only the release frees the moment
    model.geomTransf("Linear", 1)
    model.element("elasticBeamColumn", 1, 1, 2, A_BEAM, E_BEAM, I_BEAM, 1, "-release", 2)
    model.timeSeries("Linear", 1)
    model.pattern("Plain", 1, 1)
    model.eleLoad("-ele", 1, "-type", "-beamUniform", -w)
    static(model)
    model.reactions()
    assert_close(model.nodeReaction(2), [0.0, 3 * w * L / 8, 0.0], 1e-12)
    assert_close(model.nodeReaction(1), [0.0, 5 * w * L / 8, w * L**2 / 8], 1e-12)


@pytest.mark.parametrize("Ib", [1.0e6, 2.0e-4, 1.0e-12])
def test_portal_frame_sway_against_slope_deflection(model, Ib):
    """Fixed-base portal, columns EIc, beam EIb, lateral H at the top: with c = EIc/h,
    g = EIb/b the sway is Delta = H h^2 (2c + 3g) / (4c (3c + 18g)) (axial strains
    neglected: A is taken huge). A rigid beam gives H h^3 / 24EIc, a pinned one H h^3 / 6EIc."""
    h, b, E, Ic, H = 3.0, 5.0, 2.0e8, 1.0e-4, 10.0
    big_A = 1.0e6
    model.model("basic", "-ndm", 2, "-ndf", 3)
    model.node(1, 0.0, 0.0)
    model.node(2, b, 0.0)
    model.node(3, 0.0, h)
    model.node(4, b, h)
    model.fix(1, 1, 1, 1)
    model.fix(2, 1, 1, 1)
    model.geomTransf("Linear", 1)
    model.element("elasticBeamColumn", 1, 1, 3, big_A, E, Ic, 1)
    model.element("elasticBeamColumn", 2, 2, 4, big_A, E, Ic, 1)
    model.element("elasticBeamColumn", 3, 3, 4, big_A, E, Ib, 1)
    model.timeSeries("Linear", 1)
    model.pattern("Plain", 1, 1)
    model.load(3, H, 0.0, 0.0)
    static(model)
    c, g = E * Ic / h, E * Ib / b
    sway = H * h**2 * (2 * c + 3 * g) / (4 * c * (3 * c + 18 * g))
    assert_close([model.nodeDisp(3, 1), model.nodeDisp(4, 1)], [sway, sway], 1e-9)


def test_pdelta_cantilever_column(model):
    """Column of height L, fixed at the base, axial P down and a small H at the top.
    One PDelta element solves (12EI/L^3 - P/L) u - 6EI/L^2 t = H, -6EI/L^2 u + 4EI/L t = 0,
    i.e. u = H / (3EI/L^3 - P/L) exactly; the amplified first-order sway
    u1 / (1 - P/Pcr) (Pcr = pi^2 EI / 4L^2) is within 5 %. Eight elements come within
    0.5 % of the exact elastic solution H (tan kL - kL) / (P k), k = sqrt(P/EI)."""
    L, H = 4.0, 1.0
    EI = E_BEAM * I_BEAM
    Pcr = math.pi**2 * EI / (4 * L**2)
    P = 0.2 * Pcr

    def run(n):
        model.wipe()
        cantilever(model, n, L, transf="PDelta", angle=math.pi / 2)
        model.load(n + 1, H, -P, 0.0)
        static(model, steps=2)
        return model.nodeDisp(n + 1, 1)

    one = run(1)
    assert_close(one, H / (3 * EI / L**3 - P / L), 1e-10)
    first_order = H * L**3 / (3 * EI)
    assert_close(one, first_order / (1 - P / Pcr), 0.05)
    eight = run(8)
    k = math.sqrt(P / EI)
    assert_close(eight, H * (math.tan(k * L) - k * L) / (P * k), 5e-3)
    # The Linear transformation ignores the axial load.
    model.wipe()
    cantilever(model, 1, L, transf="Linear", angle=math.pi / 2)
    model.load(2, H, -P, 0.0)
    static(model)
    assert_close(model.nodeDisp(2, 1), first_order, 1e-10)


def test_shear_building_periods_against_the_uniform_chain(model):
    """N storeys, each two fixed-fixed columns (k = 2 * 12EI/h^3) under a rigid floor
    (rotations and vertical dofs fixed) with mass m: lambda_n = 4k/m sin^2((2n-1) pi / (2(2N+1)))."""
    N, h, b, m = 3, 3.0, 6.0, 50.0
    model.model("basic", "-ndm", 2, "-ndf", 3)
    for level in range(N + 1):
        for side in (0, 1):
            model.node(10 * level + side, side * b, level * h)
    model.fix(0, 1, 1, 1)
    model.fix(1, 1, 1, 1)
    model.geomTransf("Linear", 1)
    tag = 1
    for level in range(1, N + 1):
        model.fix(10 * level, 0, 1, 1)
        model.fix(10 * level + 1, 0, 1, 1)
        model.equalDOF(10 * level, 10 * level + 1, 1)
        model.mass(10 * level, m / 2, 0.0, 0.0)
        model.mass(10 * level + 1, m / 2, 0.0, 0.0)
        for side in (0, 1):
            model.element("elasticBeamColumn", tag, 10 * (level - 1) + side, 10 * level + side, A_BEAM, E_BEAM,
                          I_BEAM, 1)
            tag += 1
    lam = model.eigen("-fullGenLapack", N)
    k = 2 * 12 * E_BEAM * I_BEAM / h**3
    expected = [4 * k / m * math.sin((2 * n - 1) * math.pi / (2 * (2 * N + 1)))**2 for n in range(1, N + 1)]
    assert_close(lam, expected, 1e-10)


# --- bad input in 2D ---------------------------------------------------------------------

def frame_2d(m):
    m.model("basic", "-ndm", 2)
    m.node(1, 0.0, 0.0)
    m.node(2, 3.0, 0.0)


def test_3d_only_element_in_a_2d_model_is_refused(model):
    model.model("basic", "-ndm", 2, "-ndf", 2)
    for t in range(1, 9):
        model.node(t, float(t % 2), float(t // 2))
    model.nDMaterial("ElasticIsotropic", 1, 1000.0, 0.3)
    with pytest.raises(beamsolid.OpenSeesError, match=r"element stdBrick 1: .*does not work in a 2D model.*-ndm 3"):
        model.element("stdBrick", 1, *range(1, 9), 1)


def test_3d_elastic_beam_arguments_in_2d_are_refused(model):
    frame_2d(model)
    model.geomTransf("Linear", 1)
    with pytest.raises(beamsolid.OpenSeesError, match=r"elasticBeamColumn 1: the 3D form .*-ndm 3.*A, E, Iz, transfTag"):
        model.element("elasticBeamColumn", 1, 1, 2, 1.0, 2.0, 1.0, 1.0, 1.0, 1.0, 1)


def test_2d_elastic_beam_arguments_in_3d_are_refused(model):
    model.model("basic", "-ndm", 3, "-ndf", 6)
    model.node(1, 0.0, 0.0, 0.0)
    model.node(2, 3.0, 0.0, 0.0)
    model.geomTransf("Linear", 1, 0.0, 0.0, 1.0)
    with pytest.raises(beamsolid.OpenSeesError, match=r"the 2D form .* needs a 2D model"):
        model.element("elasticBeamColumn", 1, 1, 2, 1.0, 2.0, 1.0, 1)


def test_geomtransf_with_vecxz_in_2d_is_refused(model):
    frame_2d(model)
    with pytest.raises(beamsolid.OpenSeesError, match=r"geomTransf Linear 1: vecxz is for 3D models.*geomTransf\('Linear', tag"):
        model.geomTransf("Linear", 1, 0.0, 0.0, 1.0)
    with pytest.raises(beamsolid.OpenSeesError, match=r"-jntOffset needs 4 numbers in 2D"):
        model.geomTransf("PDelta", 2, "-jntOffset", 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    with pytest.raises(beamsolid.OpenSeesError, match=r"geomTransf Corotational 3: vecxz is for 3D models"):
        model.geomTransf("Corotational", 3, 0.0, 0.0, 1.0)


def test_beam_on_ndf2_nodes_is_refused(model):
    model.model("basic", "-ndm", 2, "-ndf", 2)
    model.node(1, 0.0, 0.0)
    model.node(2, 3.0, 0.0)
    model.geomTransf("Linear", 1)
    with pytest.raises(beamsolid.OpenSeesError, match=r"elasticBeamColumn 1: node 1 has 2 dofs.*needs 3"):
        model.element("elasticBeamColumn", 1, 1, 2, 1.0, 2.0, 1.0, 1)


def test_joint_offsets_in_2d(model):
    """A cantilever of flexible length L whose clamped end sits on a rigid arm of
    length d from the fixed node: the tip moves as a cantilever of length L plus
    nothing (the arm is rigid and its node fixed)."""
    L, d, P = 3.0, 0.5, 4.0
    model.model("basic", "-ndm", 2)
    model.node(1, 0.0, 0.0)
    model.node(2, L + d, 0.0)
    model.fix(1, 1, 1, 1)
    model.geomTransf("Linear", 1, "-jntOffset", d, 0.0, 0.0, 0.0)
    model.element("elasticBeamColumn", 1, 1, 2, A_BEAM, E_BEAM, I_BEAM, 1)
    model.timeSeries("Linear", 1)
    model.pattern("Plain", 1, 1)
    model.load(2, 0.0, P, 0.0)
    static(model)
    assert_close(model.nodeDisp(2, 2), P * L**3 / (3 * E_BEAM * I_BEAM), 1e-12)
    model.reactions()
    assert_close(model.nodeReaction(1), [0.0, -P, -P * (L + d)], 1e-12)


def test_pvd_recorder_pads_2d_models_to_3d(model, tmp_path):
    """ParaView wants 3D points: a 2D node's (ux, uy, rz) is written as displacement
    (ux, uy, 0) and rotation (0, 0, rz); a 2D beam's local end forces (N, Vy, Mz) go to
    the N, Vy and Mz slots of the 12 localForce components."""
    meshio = pytest.importorskip("meshio")
    L, P = 3.0, 5.0
    cantilever(model, 1, L)
    model.load(2, 0.0, P, 0.0)
    name = str(tmp_path / "cantilever")
    model.recorder("PVD", name, "-precision", 15)
    static(model)
    steps = sorted((tmp_path / "cantilever").glob("cantilever_*.vtu"))
    assert len(steps) == 1
    grid = meshio.read(str(steps[0]))
    assert grid.points.tolist() == [[0.0, 0.0, 0.0], [L, 0.0, 0.0]]
    u = model.nodeDisp(2)
    assert_close(grid.point_data["displacement"][1], [u[0], u[1], 0.0], 1e-14)
    assert_close(grid.point_data["rotation"][1], [0.0, 0.0, u[2]], 1e-14)
    local = model.eleResponse(1, "localForce")
    expected = np.zeros(12)
    expected[[0, 1, 5, 6, 7, 11]] = local
    assert_close(np.concatenate(grid.cell_data["localForce"])[0], expected, 1e-14)


# --- quad (plane strain / plane stress) input errors ------------------------------

def quad_model(model, ndf=2):
    model.model("basic", "-ndm", 2, "-ndf", ndf)
    for i, (x, y) in enumerate([(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]):
        model.node(i + 1, x, y)
    model.nDMaterial("ElasticIsotropic", 1, 1000.0, 0.25)


@pytest.mark.parametrize("args, fragments", [
    ((1, 2, 3, 1.0, "PlaneStrain", 1), ["element quad 5", "4 node tags and thick"]),
    ((1, 2, 3, 4, 1, 1.0, "PlaneStrain", 1), ["element quad 5", "exactly 4 nodes"]),
    ((1, 2, 3, 4, 1.0, "PlaneStrian", 1), ["element quad 5", "(type)", "'PlaneStrain' or 'PlaneStress'"]),
    ((1, 2, 3, 4, 1.0, "PlaneStrain", 9), ["element quad 5", "nDMaterial 9 does not exist"]),
    ((1, 2, 3, 99, 1.0, "PlaneStrain", 1), ["node 99 does not exist"]),
    ((1, 4, 3, 2, 1.0, "PlaneStrain", 1), ["element quad 5", "Jacobian", "counterclockwise"]),
    ((1, 2, 3, 4, 0.0, "PlaneStrain", 1), ["element quad 5", "(thick)", "positive"]),
    ((1, 2, 3, 4, 1.0, "PlaneStrain", 1, 0.0, 0.0, 1.0, 2.0, 3.0), ["element quad 5", "at most 4"]),
])
def test_quad_bad_input_is_refused_by_name(model, args, fragments):
    quad_model(model)
    with pytest.raises(beamsolid.OpenSeesError) as info:
        model.element("quad", 5, *args)
    for f in fragments:
        assert f in str(info.value), str(info.value)


def test_quad_needs_a_2d_model_with_ndf_2(model):
    quad_model(model, ndf=3)
    with pytest.raises(beamsolid.OpenSeesError, match=r"element quad 5: node 1 has ndm 2 and ndf 3"):
        model.element("quad", 5, 1, 2, 3, 4, 1.0, "PlaneStress", 1)
    model.wipe()
    model.model("basic", "-ndm", 3, "-ndf", 3)
    with pytest.raises(beamsolid.OpenSeesError, match=r"element quad 5: quad is a 2D element.*-ndm 3"):
        model.element("quad", 5, 1, 2, 3, 4, 1.0, "PlaneStress", 1)
    model.wipe()
    quad_model(model)
    model.element("quad", 5, 1, 2, 3, 4, 1.0, "PlaneStress", 1)
    with pytest.raises(beamsolid.OpenSeesError, match=r"element 5 already exists"):
        model.element("quad", 5, 1, 2, 3, 4, 1.0, "PlaneStress", 1)
    model.timeSeries("Linear", 1)
    model.pattern("Plain", 1, 1)
    with pytest.raises(beamsolid.OpenSeesError, match=r"eleLoad: .*\(bx, by, <bz>\): expected at least 2"):
        model.eleLoad("-ele", 5, "-type", "-selfWeight", 1.0)


def test_parallel_numberer_names_number_as_their_serial_ones(model):
    # OpenSeesSP/MP's 'ParallelPlain' and 'ParallelRCM' run as Plain and RCM.
    results = {}
    for name in ("Plain", "ParallelPlain", "RCM", "ParallelRCM"):
        model.wipe()
        model.model("basic", "-ndm", 2, "-ndf", 2)
        for n in range(1, 5):
            model.node(n, float(n), 0.0)
        model.fix(1, 1, 1)
        model.uniaxialMaterial("Elastic", 1, 100.0)
        for e in range(1, 4):
            model.element("truss", e, e, e + 1, 1.0, 1)
        for n in range(2, 5):
            model.fix(n, 0, 1)
        model.timeSeries("Linear", 1)
        model.pattern("Plain", 1, 1)
        model.load(4, 1.0, 0.0)
        model.numberer(name)
        model.system("FullGeneral")
        model.integrator("LoadControl", 1.0)
        model.analysis("Static")
        assert model.analyze(1) == 0
        results[name] = model.nodeDisp(4, 1)
    # Three bars in series, EA/L = 100 each: u = 3 P / 100.
    assert all(v == pytest.approx(0.03, rel=1e-12) for v in results.values()), results

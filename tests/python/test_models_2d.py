"""1D and 2D models (-ndm 1 and 2): commands and trusses.

Every answer is checked against a closed form: bar forces of a determinate
truss by the method of joints and a joint displacement by virtual work; an
indeterminate three-bar truss against its hand solution; a 1D spring chain
against the series stiffness.
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


# --- bad input in 2D ---------------------------------------------------------------------

def test_3d_only_element_in_a_2d_model_is_refused(model):
    model.model("basic", "-ndm", 2, "-ndf", 2)
    for t in range(1, 9):
        model.node(t, float(t % 2), float(t // 2))
    model.nDMaterial("ElasticIsotropic", 1, 1000.0, 0.3)
    with pytest.raises(beamsolid.OpenSeesError, match=r"element stdBrick 1: .*does not work in a 2D model.*-ndm 3"):
        model.element("stdBrick", 1, *range(1, 9), 1)

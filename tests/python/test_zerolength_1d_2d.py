"""zeroLength in 1D (ndf 1) and 2D (ndf 2 and 3) models against closed forms.

A 1D chain of springs stretches by P times the summed flexibilities, also
when one spring's local x points backwards (-orient). A 2D node on rotated
springs (-orient x at angle a; OpenSees ignores yp in 2D and takes
yp = (-x2, x1, 0)) moves by u = R^T K^-1 R P, with R the rotation to the
local axes and K the diagonal spring stiffness; the spring forces are the
local components of P. The in-plane rotation (direction 3, or 6) carries a
moment over its stiffness. Errors for directions a space does not have.
Tolerances: 1e-12 relative (linear springs, one Newton step, direct solve).
"""
import math

import numpy as np
import pytest

import beamsolid


def static(m, steps=1):
    m.constraints("Plain")
    m.numberer("Plain")
    m.system("UmfPack")
    m.test("NormDispIncr", 1e-12, 20)
    m.algorithm("Newton")
    m.integrator("LoadControl", 1.0 / steps)
    m.analysis("Static")
    assert m.analyze(steps) == 0


def rel_err(actual, expected):
    actual, expected = np.asarray(actual, float), np.asarray(expected, float)
    return np.max(np.abs(actual - expected)) / np.max(np.abs(expected))


@pytest.mark.parametrize("reverse_middle", [False, True])
def test_1d_spring_chain_stretches_by_the_series_flexibility(model, reverse_middle):
    k = [300.0, 120.0, 75.0]
    model.model("basic", "-ndm", 1, "-ndf", 1)
    for n in range(1, 5):
        model.node(n, 0.0)
    model.fix(1, 1)
    for e, stiffness in enumerate(k, start=1):
        model.uniaxialMaterial("Elastic", e, stiffness)
        orient = ["-orient", -1.0, 0.0, 0.0, 0.0, 1.0, 0.0] if (reverse_middle and e == 2) else []
        model.element("zeroLength", e, e, e + 1, "-mat", e, "-dir", 1, *orient)
    model.timeSeries("Linear", 1)
    model.pattern("Plain", 1, 1)
    P = 6.0
    model.load(4, P)
    static(model)
    expected = P * np.cumsum([1.0 / s for s in k])
    assert rel_err([model.nodeDisp(n, 1) for n in (2, 3, 4)], expected) <= 1e-12
    sign = -1.0 if reverse_middle else 1.0
    # The reversed spring sees -(u_j - u_i) and carries -P in its local x.
    assert rel_err(model.eleResponse(2, "basicForce"), [sign * P]) <= 1e-12
    assert rel_err(model.eleResponse(2, "deformation"), [sign * P / k[1]]) <= 1e-12
    assert rel_err(model.eleResponse(2, "force"), [-P, P]) <= 1e-12
    model.reactions()
    assert rel_err(model.nodeReaction(1), [-P]) <= 1e-12


@pytest.mark.parametrize("ndf", [2, 3])
@pytest.mark.parametrize("angle", [0.0, 30.0, 125.0])
def test_2d_rotated_springs_against_r_transpose_k_inverse_r(model, ndf, angle):
    a = math.radians(angle)
    kx, ky, kr = 250.0, 40.0, 12.0
    model.model("basic", "-ndm", 2, "-ndf", ndf)
    model.node(1, 1.0, 2.0)
    model.node(2, 1.0, 2.0)
    model.fix(1, *([1] * ndf))
    model.uniaxialMaterial("Elastic", 1, kx)
    model.uniaxialMaterial("Elastic", 2, ky)
    model.uniaxialMaterial("Elastic", 3, kr)
    mats, dirs = ([1, 2, 3], [1, 2, 3]) if ndf == 3 else ([1, 2], [1, 2])
    # yp deliberately out of the plane: ignored in 2D.
    model.element("zeroLength", 1, 1, 2, "-mat", *mats, "-dir", *dirs,
                  "-orient", math.cos(a), math.sin(a), 0.0, 0.2, -0.7, 1.0)
    model.timeSeries("Linear", 1)
    model.pattern("Plain", 1, 1)
    P = np.array([3.0, -5.0])
    M = 0.8
    model.load(2, *P, *([M] if ndf == 3 else []))
    static(model)
    R = np.array([[math.cos(a), math.sin(a)], [-math.sin(a), math.cos(a)]])
    u = R.T @ np.diag([1.0 / kx, 1.0 / ky]) @ R @ P
    disp = model.nodeDisp(2)
    assert rel_err(disp[:2], u) <= 1e-12
    local = R @ P
    expected_forces = list(local) + ([M] if ndf == 3 else [])
    assert rel_err(model.eleResponse(1, "basicForce"), expected_forces) <= 1e-12
    assert rel_err(model.eleResponse(1, "localForce"), expected_forces) <= 1e-12
    expected_def = [local[0] / kx, local[1] / ky] + ([M / kr] if ndf == 3 else [])
    assert rel_err(model.eleResponse(1, "deformation"), expected_def) <= 1e-12
    if ndf == 3:
        assert abs(disp[2] - M / kr) <= 1e-12 * M / kr
    f = np.concatenate([-P, [-M] if ndf == 3 else [], P, [M] if ndf == 3 else []])
    assert rel_err(model.eleResponse(1, "force"), f) <= 1e-12
    assert rel_err(model.eleResponse(1, "xaxis"), [math.cos(a), math.sin(a), 0.0]) <= 1e-15
    assert rel_err(model.eleResponse(1, "yaxis"), [-math.sin(a), math.cos(a), 0.0]) <= 1e-15


def test_2d_direction_6_is_the_rotation_too(model):
    model.model("basic", "-ndm", 2, "-ndf", 3)
    model.node(1, 0.0, 0.0)
    model.node(2, 0.0, 0.0)
    model.fix(1, 1, 1, 1)
    model.fix(2, 1, 1, 0)
    model.uniaxialMaterial("Elastic", 1, 20.0)
    model.element("zeroLength", 1, 1, 2, "-mat", 1, "-dir", 6)
    model.timeSeries("Linear", 1)
    model.pattern("Plain", 1, 1)
    model.load(2, 0.0, 0.0, 1.5)
    static(model)
    assert abs(model.nodeDisp(2, 3) - 1.5 / 20.0) <= 1e-15


@pytest.mark.parametrize("ndm, ndf, dirs, match", [
    (1, 1, [2], r"direction 2 is not a translation of a 1D model"),
    (1, 1, [4], r"direction 4 is a rotation.*1D model has no rotations"),
    (2, 2, [3], r"direction 3 is a rotation, but node 1 has ndf 2"),
    (2, 2, [6], r"direction 6 is a rotation, but node 1 has ndf 2"),
])
def test_directions_a_space_does_not_have_are_refused(model, ndm, ndf, dirs, match):
    model.model("basic", "-ndm", ndm, "-ndf", ndf)
    model.node(1, *([0.0] * ndm))
    model.node(2, *([0.0] * ndm))
    model.uniaxialMaterial("Elastic", 1, 20.0)
    with pytest.raises(beamsolid.OpenSeesError, match="element zeroLength 1: " + match):
        model.element("zeroLength", 1, 1, 2, "-mat", *([1] * len(dirs)), "-dir", *dirs)


def test_orient_without_an_in_plane_x_is_refused_in_2d(model):
    model.model("basic", "-ndm", 2, "-ndf", 2)
    model.node(1, 0.0, 0.0)
    model.node(2, 0.0, 0.0)
    model.uniaxialMaterial("Elastic", 1, 20.0)
    with pytest.raises(beamsolid.OpenSeesError, match=r"element zeroLength 1: -orient: the x vector has no component"):
        model.element("zeroLength", 1, 1, 2, "-mat", 1, "-dir", 1, "-orient", 0.0, 0.0, 1.0, 0.0, 1.0, 0.0)


@pytest.mark.parametrize("handler", ["Transformation", "Penalty", "Lagrange"])
def test_a_fix_on_an_equaldof_constrained_dof(model, handler, capfd):
    """Springs 1-2 and 3-4 (k = 100), node 3 fixed and tied to node 2 by equalDOF, P2 = 10, P4 = 5.
    Transformation (as OpenSees, which the p-y pile example relies on): the tie wins and the fix is
    dropped with a warning, so 2 and 3 move together: u2 = (10 + 5)/k, u4 = u2 + 5/k. Penalty
    enforces both: u2 = u3 = 0, u4 = 5/k (OpenSeesPy 3.7.1 gives these numbers, and with Lagrange
    too). BeamSolid's Lagrange eliminates, so it cannot hold both: analyze fails and says why."""
    m = model
    m.model("basic", "-ndm", 1, "-ndf", 1)
    for tag in range(1, 5):
        m.node(tag, 0.0)
    m.fix(1, 1)
    m.fix(3, 1)
    m.uniaxialMaterial("Elastic", 1, 100.0)
    m.element("zeroLength", 1, 1, 2, "-mat", 1, "-dir", 1)
    m.element("zeroLength", 2, 3, 4, "-mat", 1, "-dir", 1)
    m.equalDOF(2, 3, 1)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.load(2, 10.0)
    m.load(4, 5.0)
    m.constraints(handler, *(() if handler == "Transformation" else (1e14, 1e14)))
    m.numberer("Plain")
    m.system("UmfPack")
    m.integrator("LoadControl", 1.0)
    m.algorithm("Linear")
    m.analysis("Static")
    if handler == "Lagrange":
        assert m.analyze(1) < 0
        assert "node 3 dof 1 is both fixed and constrained" in m.last_error()
        return
    assert m.analyze(1) == 0
    u = [m.nodeDisp(n, 1) for n in (2, 3, 4)]
    if handler == "Transformation":
        assert u == pytest.approx([0.15, 0.15, 0.2], rel=1e-12)
        assert "node 3 dof 1" in capfd.readouterr().err
        # Said once per model, not by every analysis of it.
        m.analysis("Static")
        assert m.analyze(1) == 0
        assert "node 3 dof 1" not in capfd.readouterr().err
    else:
        assert u == pytest.approx([0.0, 0.0, 0.05], abs=1e-10)


def test_lagrange_constraints_give_the_transformation_answer(model):
    """A 2D portal's beam tied to its columns' tops by equalDOF (and one rigidLink): the constraints
    Lagrange and Transformation give the same displacements (1e-12), since both enforce them exactly;
    alphaS/alphaM are accepted and change nothing; a non-positive one is refused."""
    def run(*handler):
        m = model
        m.wipe()
        m.model("basic", "-ndm", 2, "-ndf", 3)
        for tag, x, y in ((1, 0, 0), (2, 4, 0), (3, 0, 3), (4, 4, 3), (5, 0, 3), (6, 4, 3), (7, 2, 4)):
            m.node(tag, float(x), float(y))
        m.fix(1, 1, 1, 1)
        m.fix(2, 1, 1, 1)
        m.geomTransf("Linear", 1)
        m.element("elasticBeamColumn", 1, 1, 3, 0.1, 2e8, 1e-3, 1)
        m.element("elasticBeamColumn", 2, 2, 4, 0.1, 2e8, 1e-3, 1)
        m.element("elasticBeamColumn", 3, 5, 6, 0.1, 2e8, 2e-3, 1)
        m.equalDOF(3, 5, 1, 2)
        m.equalDOF(4, 6, 1, 2, 3)
        m.rigidLink("beam", 5, 7)
        m.timeSeries("Linear", 1)
        m.pattern("Plain", 1, 1)
        m.load(7, 50.0, -20.0, 5.0)
        m.load(3, 0.0, 0.0, 3.0)
        m.constraints(*handler)
        m.numberer("RCM")
        m.system("BandGeneral")
        m.integrator("LoadControl", 1.0)
        m.algorithm("Linear")
        m.analysis("Static")
        assert m.analyze(1) == 0
        return np.array([m.nodeDisp(n) for n in range(3, 8)])
    ref = run("Transformation")
    assert np.abs(ref).max() > 1e-4
    for handler in (("Lagrange",), ("Lagrange", 10.0, 10.0)):
        assert rel_err(run(*handler), ref) < 1e-12
    with pytest.raises(beamsolid.OpenSeesError, match="alphaM"):
        model.constraints("Lagrange", 1.0, -1.0)

"""responseSpectrumAnalysis against closed forms, and its errors.

The OpenSeesPy comparison is the oracle script response_spectrum.py; here a
single-degree-of-freedom oscillator must move Sa(T)/omega^2 (Gamma phi = 1)
and a two-mass shear building the textbook modal peak phi Gamma Sa/omega^2.
"""
import math

import numpy as np
import pytest

import beamsolid


def _sdof(m, k):
    ops = beamsolid.Model()
    ops.model("basic", "-ndm", 1, "-ndf", 1)
    ops.node(1, 0.0)
    ops.node(2, 0.0)
    ops.fix(1, 1)
    ops.mass(2, m)
    ops.uniaxialMaterial("Elastic", 1, k)
    ops.element("zeroLength", 1, 1, 2, "-mat", 1, "-dir", 1)
    return ops


def test_sdof_moves_sa_over_omega_squared():
    m, k = 2.0, 800.0
    ops = _sdof(m, k)
    ops.eigen("-fullGenLapack", 1)
    ops.modalProperties()
    omega2 = k / m
    T = 2.0 * math.pi / math.sqrt(omega2)
    ops.timeSeries("Path", 1, "-time", 0.0, 0.2, 0.5, "-values", 1.0, 3.0, 2.0)
    ops.responseSpectrumAnalysis(1, 1)
    sa = np.interp(T, [0.0, 0.2, 0.5], [1.0, 3.0, 2.0])
    assert ops.nodeDisp(2, 1) == pytest.approx(sa / omega2, rel=1e-12)
    # Lists are held constant past their ends.
    ops.responseSpectrumAnalysis(1, "-Tn", 0.5, 1.0, "-Sa", 4.0, 1.0)
    assert ops.nodeDisp(2, 1) == pytest.approx(4.0 / omega2, rel=1e-12)
    assert ops.eleForce(1)[1] == pytest.approx(k * 4.0 / omega2, rel=1e-12)


def test_two_storey_shear_building_modal_peaks():
    # Masses m1, m2 on springs k1 (ground-1), k2 (1-2): the 2x2 eigenproblem by hand.
    m1, m2, k1, k2 = 3.0, 2.0, 900.0, 500.0
    ops = beamsolid.Model()
    ops.model("basic", "-ndm", 1, "-ndf", 1)
    for n in (1, 2, 3):
        ops.node(n, 0.0)
    ops.fix(1, 1)
    ops.mass(2, m1)
    ops.mass(3, m2)
    ops.uniaxialMaterial("Elastic", 1, k1)
    ops.uniaxialMaterial("Elastic", 2, k2)
    ops.element("zeroLength", 1, 1, 2, "-mat", 1, "-dir", 1)
    ops.element("zeroLength", 2, 2, 3, "-mat", 2, "-dir", 1)
    ops.eigen("-fullGenLapack", 2)
    ops.modalProperties()
    ops.timeSeries("Linear", 1, "-factor", 7.0)  # Sa(T) = 7 T
    K = np.array([[k1 + k2, -k2], [-k2, k2]])
    M = np.diag([m1, m2])
    w2, phi = np.linalg.eig(np.linalg.solve(M, K))
    order = np.argsort(w2)
    for mode, i in enumerate(order, start=1):
        p = phi[:, i]
        gamma = p @ M @ np.ones(2) / (p @ M @ p)
        sa = 7.0 * 2.0 * math.pi / math.sqrt(w2[i])
        expected = p * gamma * sa / w2[i]
        ops.responseSpectrumAnalysis(1, 1, "-mode", mode)
        assert [ops.nodeDisp(2, 1), ops.nodeDisp(3, 1)] == pytest.approx(expected, rel=1e-10)


def test_errors_name_the_command_and_argument():
    ops = _sdof(1.0, 100.0)
    ops.timeSeries("Constant", 1)
    with pytest.raises(beamsolid.OpenSeesError, match="responseSpectrumAnalysis.*modalProperties"):
        ops.responseSpectrumAnalysis(1, 1)
    ops.eigen("-fullGenLapack", 1)
    with pytest.raises(beamsolid.OpenSeesError, match="responseSpectrumAnalysis.*modalProperties"):
        ops.responseSpectrumAnalysis(1, 1)
    ops.modalProperties()
    with pytest.raises(beamsolid.OpenSeesError, match="responseSpectrumAnalysis.*timeSeries 9"):
        ops.responseSpectrumAnalysis(9, 1)
    with pytest.raises(beamsolid.OpenSeesError, match="direction 2 is out of range 1..1"):
        ops.responseSpectrumAnalysis(1, 2)
    with pytest.raises(beamsolid.OpenSeesError, match="mode 2 is out of range 1..1"):
        ops.responseSpectrumAnalysis(1, 1, "-mode", 2)
    with pytest.raises(beamsolid.OpenSeesError, match="unknown option '-foo'"):
        ops.responseSpectrumAnalysis(1, 1, "-foo")
    with pytest.raises(beamsolid.OpenSeesError, match="-Tn has 2 periods but -Sa 1"):
        ops.responseSpectrumAnalysis(1, "-Tn", 0.1, 0.2, "-Sa", 1.0)
    with pytest.raises(beamsolid.OpenSeesError, match="no spectrum"):
        ops.responseSpectrumAnalysis(1, "-mode", 1)
    with pytest.raises(beamsolid.OpenSeesError, match="responseSpectrumAnalysis.*tsTag"):
        ops.responseSpectrumAnalysis("x", 1)
    # A new eigen analysis needs modalProperties again.
    ops.eigen("-fullGenLapack", 1)
    with pytest.raises(beamsolid.OpenSeesError, match="modalProperties"):
        ops.responseSpectrumAnalysis(1, 1)

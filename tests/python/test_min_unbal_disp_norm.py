"""integrator MinUnbalDispNorm against closed forms.

The von Mises two-bar truss (corotTruss, EA = 1000, half-span a = 10, rise
h = 1, apex load -lambda): every equilibrium state has
lambda = 2 EA (L0 - L) / L0 * y / L with y = h + v and L = sqrt(a^2 + y^2).
With '-det' the step's sign turns when the tangent's determinant does, so the
path goes over the limit point and snaps through to v = -2h; with the default
sign (that of the last step's load increment, as OpenSees) the path turns
back at the limit point, as OpenSeesPy's does (oracle_scripts/
min_unbal_disp_norm.py). A linear spring takes exactly dlambda1 per step, and
Jd / min / max adapt it as LoadControl's. Tolerances: 1e-9 of the limit load.
"""
import math

import pytest

import beamsolid

EA, A_HALF, H = 1000.0, 10.0, 1.0
L0 = math.hypot(A_HALF, H)


def closed_form(v):
    y = H + v
    length = math.hypot(A_HALF, y)
    return 2.0 * EA * (L0 - length) / L0 * y / length


def truss(m, *integrator, system="UmfPack"):
    m.wipe()
    m.model("basic", "-ndm", 2, "-ndf", 2)
    m.node(1, 0.0, 0.0)
    m.node(2, A_HALF, H)
    m.node(3, 2 * A_HALF, 0.0)
    m.fix(1, 1, 1)
    m.fix(3, 1, 1)
    m.fix(2, 1, 0)
    m.uniaxialMaterial("Elastic", 1, EA)
    m.element("corotTruss", 1, 1, 2, 1.0, 1)
    m.element("corotTruss", 2, 2, 3, 1.0, 1)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.load(2, 0.0, -1.0)
    m.system(system)
    m.constraints("Plain")
    m.numberer("RCM")
    m.test("NormDispIncr", 1e-12, 50)
    m.algorithm("Newton")
    m.integrator("MinUnbalDispNorm", *integrator)
    m.analysis("Static")


def path(m, steps):
    states = []
    for _ in range(steps):
        assert m.analyze(1) == 0
        states.append((m.getTime(), m.nodeDisp(2, 2)))
    return states


def test_det_sign_snaps_through_on_the_equilibrium_path():
    m = beamsolid.Model()
    truss(m, 0.05, "-det")
    states = path(m, 60)
    limit = max(closed_form(-H * k / 10000.0) for k in range(10001))
    for lam, v in states:
        assert lam == pytest.approx(closed_form(v), abs=1e-9 * limit)
    lams = [s[0] for s in states]
    peak = next(i for i in range(len(lams) - 1) if lams[i + 1] < lams[i])  # over the limit point
    assert lams[peak] == pytest.approx(limit, rel=0.02) and lams[peak] <= limit * (1 + 1e-12)
    assert min(lams) < -0.9 * limit  # down the unstable branch to the mirrored limit point
    assert min(v for _, v in states) < -1.9 * H  # through the snap, towards the mirror image at -2h


def test_default_sign_turns_back_at_the_limit_point_as_opensees():
    m = beamsolid.Model()
    truss(m, 0.05, system="BandGeneral")
    states = path(m, 20)
    for lam, v in states:
        assert lam == pytest.approx(closed_form(v), abs=1e-9)
    assert max(v for _, v in states) > min(v for _, v in states[:9])  # back up the loading branch
    assert all(v > -H for _, v in states)


def test_linear_spring_steps_and_the_jd_adaptation():
    m = beamsolid.Model()
    m.model("basic", "-ndm", 1, "-ndf", 1)
    m.node(1, 0.0)
    m.node(2, 0.0)
    m.fix(1, 1)
    m.uniaxialMaterial("Elastic", 1, 40.0)
    m.element("zeroLength", 1, 1, 2, "-mat", 1, "-dir", 1)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.load(2, 2.0)
    m.algorithm("Newton")
    m.integrator("MinUnbalDispNorm", 0.5, 3, 0.1, 1.2)
    m.analysis("Static")
    times = []
    for _ in range(3):
        assert m.analyze(1) == 0
        times.append(m.getTime())
        assert m.nodeDisp(2, 1) == pytest.approx(2.0 * m.getTime() / 40.0, rel=1e-12)
    # one iteration per step: 0.5, then 0.5 * 3 / 1 = 1.5 clamped to 1.2, then 1.2
    assert times == pytest.approx([0.5, 1.7, 2.9], rel=1e-12)


def test_bad_input():
    m = beamsolid.Model()
    m.model("basic", "-ndm", 1, "-ndf", 1)
    with pytest.raises(beamsolid.OpenSeesError, match="dlambda1"):
        m.integrator("MinUnbalDispNorm", 0.0)
    with pytest.raises(beamsolid.OpenSeesError, match="-foo"):
        m.integrator("MinUnbalDispNorm", 0.1, "-foo")
    with pytest.raises(beamsolid.OpenSeesError, match="maxLambda"):
        m.integrator("MinUnbalDispNorm", 0.1, 1, 0.1)

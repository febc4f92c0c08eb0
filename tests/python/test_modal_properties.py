"""modalProperties against the closed-form two-mass chain, and printA/printB
against the hand-assembled stiffness of a three-bar truss."""
import math

import numpy as np
import pytest

from beamsolid.model import Model


def _chain(k=100.0, m=2.0):
    ops = Model()
    ops.model("basic", "-ndm", 1, "-ndf", 1)
    for tag in (1, 2, 3):
        ops.node(tag, 0.0)
    ops.fix(1, 1)
    ops.uniaxialMaterial("Elastic", 1, k)
    ops.element("zeroLength", 1, 1, 2, "-mat", 1, "-dir", 1)
    ops.element("zeroLength", 2, 2, 3, "-mat", 1, "-dir", 1)
    ops.mass(2, m)
    ops.mass(3, m)
    ops.mass(1, 7.0)  # on the fixed node: in totalMass, not in totalFreeMass
    return ops


def test_two_mass_chain_closed_form(tmp_path):
    k, m = 100.0, 2.0
    ops = _chain(k, m)
    ops.eigen("-fullGenLapack", 2)
    d = ops.modalProperties("-return", "-unorm", "-file", str(tmp_path / "r.txt"))
    # K = k[[2,-1],[-1,1]], M = m I: lambda = (3 -+ sqrt5)/2 k/m, phi = [1, (1 +- sqrt5)/2].
    lam = [(3 - math.sqrt(5)) / 2 * k / m, (3 + math.sqrt(5)) / 2 * k / m]
    assert d["eigenLambda"] == pytest.approx(lam, rel=1e-12)
    assert d["eigenPeriod"] == pytest.approx([2 * math.pi / math.sqrt(x) for x in lam], rel=1e-12)
    assert d["totalMass"] == pytest.approx([2 * m + 7.0], rel=1e-14)
    assert d["totalFreeMass"] == pytest.approx([2 * m], rel=1e-14)
    assert d["domainSize"] == [1.0]
    factors, masses = [], []
    for r in ((1 + math.sqrt(5)) / 2, (1 - math.sqrt(5)) / 2):
        phi = np.array([1.0, r]) / max(1.0, abs(r))  # -unorm: largest component 1
        gm, l = m * phi @ phi, m * phi.sum()
        factors.append(l / gm)
        masses.append(l * l / gm)
    # The mode shapes' signs are arbitrary: compare factors in size.
    assert np.abs(d["partiFactorMX"]) == pytest.approx(np.abs(factors), rel=1e-10)
    assert d["partiMassMX"] == pytest.approx(masses, rel=1e-10)
    assert d["partiMassesCumuMX"][-1] == pytest.approx(2 * m, rel=1e-12)  # all modes: all the free mass
    assert d["partiMassRatiosCumuMX"][-1] == pytest.approx(100.0, rel=1e-12)
    text = (tmp_path / "r.txt").read_text()
    assert text.startswith("# MODAL ANALYSIS REPORT\n")
    assert "* 10. MODAL PARTICIPATION MASS RATIOS (%) (cumulative):" in text


def test_rotational_mass_about_centre_2d():
    # Two free masses at x = 0 and 4 (y free too): centre x = 4 m2/(m1 + m2),
    # RMZ = sum m (x - xc)^2 plus the nodal rotary inertia.
    ops = Model()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    ops.node(1, 0.0, 0.0)
    ops.node(2, 4.0, 0.0)
    ops.node(3, 0.0, -3.0)
    ops.fix(3, 1, 1, 1)
    ops.geomTransf("Linear", 1)
    ops.element("elasticBeamColumn", 1, 3, 1, 1.0, 100.0, 1.0, 1)
    ops.element("elasticBeamColumn", 2, 1, 2, 1.0, 100.0, 1.0, 1)
    ops.mass(1, 1.0, 1.0, 0.25)
    ops.mass(2, 3.0, 3.0, 0.5)
    ops.eigen("-fullGenLapack", 3)
    d = ops.modalProperties("-return")
    xc = 4 * 3.0 / 4.0
    assert d["centerOfMass"] == pytest.approx([xc, 0.0], abs=1e-14)
    assert d["totalMass"][2] == pytest.approx(1.0 * xc**2 + 3.0 * (4 - xc) ** 2 + 0.75, rel=1e-14)


def test_modal_properties_errors():
    ops = _chain()
    with pytest.raises(RuntimeError, match="modalProperties.*eigen"):
        ops.modalProperties("-return")
    ops.eigen("-fullGenLapack", 1)
    with pytest.raises(RuntimeError, match="modalProperties.*-bogus"):
        ops.modalProperties("-bogus")
    with pytest.raises(RuntimeError, match="modalProperties.*reportFileName"):
        ops.modalProperties("-file")


def test_print_a_and_b_three_bar_truss(tmp_path):
    ops = Model()
    ops.model("basic", "-ndm", 2, "-ndf", 2)
    ops.node(1, 0.0, 0.0)
    ops.node(2, 4.0, 0.0)
    ops.node(3, 2.0, 3.0)
    ops.fix(1, 1, 1)
    ops.fix(2, 0, 1)
    with pytest.raises(RuntimeError, match="printA.*analyze"):
        ops.printA("-ret")
    ops.uniaxialMaterial("Elastic", 1, 100.0)
    for e, (i, j) in enumerate(((1, 2), (1, 3), (2, 3)), start=1):
        ops.element("Truss", e, i, j, 1.0, 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(3, 1.0, -2.0)
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.system("FullGeneral")
    ops.integrator("LoadControl", 0.5)
    ops.algorithm("Newton")
    ops.analysis("Static")
    assert ops.analyze(1) == 0
    # Equations: node 2 x, node 3 x, node 3 y (Plain numberer, node tag order).
    k = np.zeros((3, 3))
    L = math.hypot(2.0, 3.0)
    c, s = -2.0 / L, 3.0 / L  # bar 2-3
    k[0, 0] = 100.0 / 4.0 + 100.0 / L * c * c
    k[0, 1] = k[1, 0] = -100.0 / L * c * c
    k[0, 2] = k[2, 0] = -100.0 / L * c * s
    c1, s1 = 2.0 / L, 3.0 / L  # bar 1-3
    k[1:, 1:] = 100.0 / L * (np.array([[c1 * c1, c1 * s1], [c1 * s1, s1 * s1]]) + np.array([[c * c, c * s], [c * s, s * s]]))
    a = np.array(ops.printA("-ret")).reshape(3, 3)
    assert a == pytest.approx(k, rel=1e-13, abs=1e-12)
    b = ops.printB("-ret")
    assert len(b) == 3 and max(abs(x) for x in b) < 1e-12  # converged: no unbalance left
    ops.printA("-file", str(tmp_path / "A.txt"))
    rows = (tmp_path / "A.txt").read_text().split("\n")
    assert rows[0] == "" and len(rows[1].split()) == 3
    assert float(rows[1].split()[0]) == pytest.approx(k[0, 0], rel=1e-5)

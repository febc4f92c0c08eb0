"""beamsolid.springs: soil resistance per depth, the springs it builds along a
beam pile, the pile's small-load response against the closed-form beam on a
Winkler foundation, and the pile on p-y / t-z / q-z springs against OpenSeesPy.

Checks:
* API RP 2A's C1, C2, C3 (the factorised form used) equal Reese, Cox & Koop's
  (1974) wedge and flow expressions they come from, 1e-12, at 25-40 degrees;
  Matlock's p_u and y50 at a few depths by hand;
* the springs carry the integral of p_u over the pile (trapezoid-free: the
  Gauss rule against the analytic integral of Matlock's piecewise-linear p_u,
  1e-7), each node its tributary length, the tip a q-z spring; bad profiles and
  piles raise ValueError naming the problem;
* a 2D pile on a uniform PyLayer under a small head load (p < 1e-3 pult: the
  springs are linear to 1e-9) against Hetenyi's finite beam on Winkler springs of
  modulus k = initial tangent / tributary length: the springs lumped at the nodes
  converge at second order (error ratio 4 +- 0.3 per halving; measured 3.99,
  4.00); the head-deflection error is 0.356 (lambda h)^2 (2.1e-3, 5.4e-4, 1.34e-4
  for 32, 64, 128 elements); asserted: 128 elements within 2e-4 and
  0.4 (lambda h)^2;
* (OpenSeesPy optional) oracle_scripts/pile_springs.py -- the same helper
  building a 2D pile in Matlock clay and in API sand, axial load then lateral
  cycles -- node by node: displacements 1e-8 of the largest, iteration counts
  equal; spring forces 1e-8 (clay) and 1e-6 (sand: on the step where a shallow
  sand spring's gap memory moves, OpenSeesPy's material iteration stops ~2e-6
  of the force short, and is back in step the step after).
"""
import json
import math
import os
import subprocess
import sys

import numpy as np
import pytest

import beamsolid
from beamsolid import springs as sp
from beamsolid.boundaries import Tags
from beamsolid.scenes.winkler_pile import characteristic, winkler_closed_form

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "oracle_scripts"))
import compare  # noqa: E402


def reese_wedge(phi_deg, gamma, z, D):
    """Reese, Cox & Koop (1974): the wedge (shallow) and flow (deep) resistance
    per unit length of a pile in sand, as they wrote them."""
    phi = math.radians(phi_deg)
    a, b = phi / 2, math.pi / 4 + phi / 2
    K0, Ka = 0.4, math.tan(math.pi / 4 - phi / 2) ** 2
    tb, ta, tp, tbp = math.tan(b), math.tan(a), math.tan(phi), math.tan(b - phi)
    shallow = gamma * z * (K0 * z * tp * math.sin(b) / (tbp * math.cos(a)) + tb / tbp * (D + z * tb * ta)
                           + K0 * z * tb * (tp * math.sin(b) - ta) - Ka * D)
    deep = Ka * D * gamma * z * (tb**8 - 1) + K0 * D * gamma * z * tp * tb**4
    return shallow, deep


@pytest.mark.parametrize("phi", [25.0, 30.0, 35.0, 40.0])
def test_api_coefficients_are_reeses_wedge_and_flow(phi):
    C1, C2, C3 = sp.api_sand_coefficients(phi)
    for z in (0.5, 3.0, 12.0):
        shallow, deep = reese_wedge(phi, 9.0, z, 1.2)
        assert (C1 * z + C2 * 1.2) * 9.0 * z == pytest.approx(shallow, rel=1e-12)
        assert C3 * 1.2 * 9.0 * z == pytest.approx(deep, rel=1e-12)
    # API RP 2A Fig. 6.8.6-1 at 30 degrees reads C1 ~ 1.9, C2 ~ 2.7, C3 ~ 29.
    if phi == 30.0:
        assert (C1, C2, C3) == pytest.approx((1.91, 2.67, 28.75), abs=0.01)


def test_api_sand_pult_and_y50():
    phi, gamma, z, D, k = 35.0, 10.0, 2.0, 1.0, 16300.0
    C1, C2, C3 = sp.api_sand_coefficients(phi)
    pult, y50 = sp.api_sand(phi, gamma * z, z, D, k)
    A = 3.0 - 0.8 * z / D
    pu = min(C1 * z + C2 * D, C3 * D) * gamma * z
    assert pult == pytest.approx(A * pu, rel=1e-14)
    # The API curve A pu tanh(k z y / (A pu)) is at half its asymptote at y50.
    assert A * pu * math.tanh(k * z * y50 / (A * pu)) == pytest.approx(0.5 * pult, rel=1e-14)
    assert sp.api_sand(phi, 0.0, 0.0, D, k) == (0.0, math.inf)


def test_matlock_by_hand():
    # su 20, gamma' 6, D 1, J 0.5: (3 + 6z/20 + 0.5z) 20 up to 9 su D = 180 at z = 7.5.
    assert sp.matlock_soft_clay(20.0, 12.0, 2.0, 1.0) == pytest.approx((92.0, 0.025))
    assert sp.matlock_soft_clay(20.0, 45.0, 7.5, 1.0)[0] == pytest.approx(180.0)
    assert sp.matlock_soft_clay(20.0, 60.0, 10.0, 1.0, eps50=0.02) == pytest.approx((180.0, 0.05))
    assert sp.api_alpha(10.0, 40.0) == pytest.approx(0.5 * 0.25**-0.5)
    assert sp.api_alpha(100.0, 25.0) == pytest.approx(0.5 * 4.0**-0.25)
    assert sp.api_sand_nq(32.5) == pytest.approx(30.0)


def _pile_2d(ops, n, L=12.0, E=2.0e7, D=0.8, head_above=0.0):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    for i in range(n + 1):
        ops.node(i + 1, 0.0, head_above - (L + head_above) * i / n)
    ops.geomTransf("Linear", 1)
    A, I = math.pi * D**2 / 4, math.pi * D**4 / 64
    for i in range(n):
        ops.element("elasticBeamColumn", i + 1, i + 1, i + 2, A, E, I, 1)
    return list(range(1, n + 2)), E * I


def test_springs_carry_the_integral_of_matlocks_resistance():
    m = beamsolid.Model()
    nodes, _ = _pile_2d(m, 26, L=12.0, head_above=1.0)
    clay = [sp.SoftClay(0.0, 12.0, su=15.0, su_gradient=1.0, gamma=6.0, eps50=0.02, J=0.5)]
    s = sp.pile_springs(m, Tags(node=500, element=500, material=1), nodes, 0.8, clay, ground=0.0)
    # Half-metre elements from 1 m above the ground: the two nodes above get
    # nothing, the ground node a quarter metre, the tip too.
    assert [r["pile_node"] for r in s.rows] == nodes[2:]
    assert s.rows[0]["tributary"] == pytest.approx((0.0, 0.25))
    assert s.rows[5]["tributary"] == pytest.approx((2.25, 2.75))

    # Matlock's p_u(z) = min((3 + 6z/su + 0.5z/0.8) su 0.8, 9 su 0.8), su = 15 + z:
    # integrate on a fine grid (the kink found by bisection) for the total.
    def pu(z):
        su = 15.0 + z
        return min((3.0 + 6.0 * z / su + 0.5 * z / 0.8) * su * 0.8, 9.0 * su * 0.8)
    lo, hi = 0.0, 12.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if (3.0 + 6.0 * mid / (15 + mid) + 0.5 * mid / 0.8) < 9.0 else (lo, mid)
    x1, w1 = np.polynomial.legendre.leggauss(40)
    total = 0.0
    for a, b in ((0.0, lo), (lo, 12.0)):
        total += sum(w * pu(a + 0.5 * (b - a) * (x + 1)) for x, w in zip(x1, w1)) * 0.5 * (b - a)
    assert sum(r["py"][1]["pult"] for r in s.rows) == pytest.approx(total, rel=1e-7)
    assert all(r["py"][1]["y50"] == pytest.approx(2.5 * 0.02 * 0.8) for r in s.rows)
    # Shaft friction by API's alpha and a q-z spring at the tip (9 su A_tip).
    assert all(r["tz"] is not None for r in s.rows[1:])
    tip = s.rows[-1]["qz"]
    assert tip["qult"] == pytest.approx(9.0 * 27.0 * math.pi * 0.8**2 / 4) and tip["qz_type"] == 1
    # The spring forces can be recorded per depth.
    m.constraints("Plain")
    m.numberer("Plain")
    m.system("UmfPack")
    m.test("NormDispIncr", 1e-12, 20)
    m.algorithm("Newton")
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.load(1, 10.0, 0.0, 0.0)
    m.integrator("LoadControl", 1.0)
    m.analysis("Static")
    assert m.analyze(1) == 0
    lateral = sum(m.eleResponse(r["element"], "force")[3] for r in s.rows)
    assert lateral == pytest.approx(10.0, rel=1e-9)


def test_bad_profiles_and_piles_raise():
    m = beamsolid.Model()
    nodes, _ = _pile_2d(m, 8)
    tags = Tags(node=500, element=500, material=1)
    with pytest.raises(ValueError, match="without gaps"):
        sp.pile_springs(m, tags, nodes, 0.8, [sp.SoftClay(0.0, 5.0, 10.0, 6.0), sp.SoftClay(6.0, 12.0, 10.0, 6.0)])
    with pytest.raises(ValueError, match="above the pile tip"):
        sp.pile_springs(m, tags, nodes, 0.8, [sp.SoftClay(0.0, 5.0, 10.0, 6.0)])
    with pytest.raises(ValueError, match="su > 0"):
        sp.pile_springs(m, tags, nodes, 0.8, [sp.SoftClay(0.0, 12.0, -10.0, 6.0)])
    with pytest.raises(ValueError, match="head to tip"):
        sp.pile_springs(m, tags, nodes[::-1], 0.8, [sp.SoftClay(0.0, 12.0, 10.0, 6.0)])
    with pytest.raises(ValueError, match="diameter"):
        sp.pile_springs(m, tags, nodes, 0.0, [sp.SoftClay(0.0, 12.0, 10.0, 6.0)])
    with pytest.raises(ValueError, match="k > 0"):
        sp.pile_springs(m, tags, nodes, 0.8, [sp.Sand(0.0, 12.0, phi=30.0, gamma=9.0, k=0.0)])
    m.node(99, 0.5, -3.0, "-ndf", 3)
    with pytest.raises(ValueError, match="vertical line"):
        sp.pile_springs(m, tags, nodes[:3] + [99], 0.8, [sp.SoftClay(0.0, 12.0, 10.0, 6.0)])


def _winkler_head(n, layer, H):
    m = beamsolid.Model()
    nodes, EI = _pile_2d(m, n, L=12.0)
    s = sp.pile_springs(m, Tags(node=1000, element=1000, material=1), nodes, 0.8, [layer], ground=0.0)
    m.fix(nodes[-1], 0, 1, 0)  # no axial springs in a PyLayer: hold the tip vertically
    m.constraints("Plain")
    m.numberer("Plain")
    m.system("UmfPack")
    m.test("NormDispIncr", 1e-14, 20)
    m.algorithm("Newton")
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.load(1, H, 0.0, 0.0)
    m.integrator("LoadControl", 1.0)
    m.analysis("Static")
    assert m.analyze(1) == 0
    largest = max(abs(m.eleResponse(r["element"], "force")[3]) / r["py"][1]["pult"] for r in s.rows)
    return m.nodeDisp(1, 1), EI, largest


def test_small_load_response_is_hetenyis_beam_on_winkler_springs():
    P, y50, Cd = 60.0, 0.02, 0.3  # p_ult per metre, y50
    layer = sp.PyLayer(0.0, 12.0, p_ult=P, y50=y50, soil_type=1, Cd=Cd)
    # The springs' initial tangent per unit length: far field 0.98, near field
    # 0.02, closure and drag 1 / (80 + 2 Cd), in y50 / pult.
    k = (P / y50) / (0.98 + 0.02 + 1.0 / (80.0 + 2.0 * Cd))
    H = 0.05
    errors = []
    for n in (32, 64, 128):
        head, EI, largest = _winkler_head(n, layer, H)
        assert largest < 1e-3  # p / pult: the springs stay in their linear range
        exact = winkler_closed_form(EI, k, 12.0, H, [0.0])[0][0]
        errors.append(abs(head - exact) / exact)
    lam_h = characteristic(EI, k) * 12.0 / 128
    assert errors[-1] < 2e-4 and errors[-1] < 0.4 * lam_h**2
    assert errors[0] / errors[1] == pytest.approx(4.0, abs=0.3)
    assert errors[1] / errors[2] == pytest.approx(4.0, abs=0.3)


def test_3d_pile_gets_two_lateral_springs_shaft_friction_and_a_tip_spring():
    m = beamsolid.Model()
    m.model("basic", "-ndm", 3, "-ndf", 6)
    n, L, D = 10, 10.0, 0.6
    for i in range(n + 1):
        m.node(i + 1, 0.0, 0.0, -L * i / n)
    m.geomTransf("Linear", 1, 1.0, 0.0, 0.0)
    A, I = math.pi * D**2 / 4, math.pi * D**4 / 64
    for i in range(n):
        m.element("elasticBeamColumn", i + 1, i + 1, i + 2, A, 2.0e7, 8.0e6, 2 * I, I, I, 1)
    sand = [sp.Sand(0.0, 10.0, phi=33.0, gamma=9.0, k=16300.0)]
    s = sp.pile_springs(m, Tags(node=100, element=100, material=1), list(range(1, n + 2)), D, sand)
    assert all(sorted(r["py"]) == [1, 2] for r in s.rows)
    assert s.rows[-1]["qz"]["qz_type"] == 2
    assert s.rows[-1]["qz"]["qult"] == pytest.approx(sp.api_sand_nq(33.0) * 90.0 * A)
    m.fix(1, 0, 0, 0, 1, 0, 0)  # torsion
    m.constraints("Plain")
    m.numberer("Plain")
    m.system("UmfPack")
    m.test("NormDispIncr", 1e-12, 30)
    m.algorithm("Newton")
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.load(1, 3.0, -2.0, -150.0, 0.0, 0.0, 0.0)
    m.integrator("LoadControl", 0.25)
    m.analysis("Static")
    assert m.analyze(4) == 0
    # Equilibrium: the springs carry the head loads.
    total = np.zeros(3)
    for r in s.rows:
        f = m.eleResponse(r["element"], "force")
        total += np.array(f[6:9])
        if r["qz"]:
            total[2] += m.eleResponse(r["qz"]["element"], "force")[8]
    assert total == pytest.approx([3.0, -2.0, -150.0], rel=1e-9, abs=1e-9)


ORACLE = compare.find_oracle_python()


@pytest.mark.skipif(ORACLE is None, reason="no Python with openseespy (set BEAMSOLID_ORACLE_PYTHON)")
def test_pile_on_springs_matches_opensees_node_by_node(tmp_path):
    import beamsolid.opensees as bops
    import pile_springs

    ours = pile_springs.run(bops)
    script = ("import sys, json; sys.path.insert(0, %r); import openseespy.opensees as ops, pile_springs; "
              "sys.stdout.write('RESULT' + json.dumps(pile_springs.run(ops)))") % os.path.dirname(
                  pile_springs.__file__)
    r = subprocess.run([ORACLE, "-c", script], capture_output=True, text=True, timeout=600, cwd=tmp_path,
                       env=compare.oracle_env())
    assert r.returncode == 0, r.stderr[-2000:]
    theirs = json.loads(r.stdout.split("RESULT", 1)[1])
    for soil in ("clay", "sand"):
        assert ours[soil + ".codes"] == theirs[soil + ".codes"] and set(ours[soil + ".codes"]) == {0}
        assert ours[soil + ".testIter"] == theirs[soil + ".testIter"]
        for key, rtol in (("disp", 1e-8), ("springForce", 1e-8 if soil == "clay" else 1e-6), ("pult", 1e-14),
                          ("y50", 1e-14)):
            a, b = np.array(ours[soil + "." + key]), np.array(theirs[soil + "." + key])
            assert a.shape == b.shape
            err = np.abs(a - b).max() / np.abs(b).max()
            assert err <= rtol, f"{soil}.{key}: {err:.2e}"
    # The sand springs near the head went far past y50 (the push is large).
    assert max(abs(f[0]) for step in theirs["sand.springForce"] for f in step[:3]) > 0.9 * theirs["sand.pult"][1]

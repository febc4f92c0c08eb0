"""Shear-deformable 3D sections in forceBeamColumn against closed forms.

section('Aggregator', tag, matY, 'Vy', matZ, 'Vz', '-section', elasticTag)
and section('Elastic', tag, E, A, Iz, Iy, G, J, alphaY, alphaZ): a cantilever
of length L under a tip load P deflects P L^3/(3 EI) + P L/k_v in each plane
(k_v the shear stiffness: the material's, or alpha G A); under a uniform load
w, w L^4/(8 EI) + w L^2/(2 k_v). Under a point load at a, the section shear
is the load's (V = dM/dx: -Py in y, +Pz in z before the load, zero beyond),
and a doubly symmetric section deflects the same along y and z. With a
Steel01 shear spring past yield, the tip moves P L^3/(3 EI) + gamma(P) L with
gamma from the bilinear law. Linear answers 1e-10 relative; the Steel01 one
1e-9 (element and global iterations converged to 1e-12).
"""
import pytest

import beamsolid

E, A, IZ, IY, G, J = 200.0, 10.0, 3.0, 2.0, 80.0, 5.0
L = 2.5
KVY, KVZ = 50.0, 70.0
ALPHA_Y, ALPHA_Z = 0.5, 0.7


def aggregator(m, shear_order=("Vy", "Vz")):
    m.uniaxialMaterial("Elastic", 2, KVY)
    m.uniaxialMaterial("Elastic", 3, KVZ)
    m.section("Elastic", 1, E, A, IZ, IY, G, J)
    pairs = {"Vy": (2, "Vy"), "Vz": (3, "Vz")}
    args = [v for code in shear_order for v in pairs[code]]
    m.section("Aggregator", 10, *args, "-section", 1)
    return KVY, KVZ


def elastic8(m):
    m.section("Elastic", 10, E, A, IZ, IY, G, J, ALPHA_Y, ALPHA_Z)
    return ALPHA_Y * G * A, ALPHA_Z * G * A


def cantilever(m, section, points=4, **kw):
    m.model("basic", "-ndm", 3, "-ndf", 6)
    m.node(1, 0.0, 0.0, 0.0)
    m.node(2, L, 0.0, 0.0)
    m.fix(1, 1, 1, 1, 1, 1, 1)
    k = section(m, **kw)
    m.geomTransf("Linear", 1, 0.0, 0.0, 1.0)
    m.beamIntegration("Lobatto", 1, 10, points)
    m.element("forceBeamColumn", 1, 1, 2, 1, 1)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    return k


def solve(m, steps=1):
    m.system("FullGeneral")
    m.constraints("Plain")
    m.numberer("Plain")
    m.test("NormDispIncr", 1e-12, 30)
    m.algorithm("Newton")
    m.integrator("LoadControl", 1.0 / steps)
    m.analysis("Static")
    assert m.analyze(steps) == 0


@pytest.mark.parametrize("section", [aggregator, elastic8])
def test_tip_load_both_planes(model, section):
    kvy, kvz = cantilever(model, section)
    py, pz = 1.3, -0.8
    model.load(2, 0.0, py, pz, 0.0, 0.0, 0.0)
    solve(model)
    uy = py * L ** 3 / (3 * E * IZ) + py * L / kvy
    uz = pz * L ** 3 / (3 * E * IY) + pz * L / kvz
    assert model.nodeDisp(2, 2) == pytest.approx(uy, rel=1e-10)
    assert model.nodeDisp(2, 3) == pytest.approx(uz, rel=1e-10)
    # The rotations are the bending ones alone.
    assert model.nodeDisp(2, 6) == pytest.approx(py * L ** 2 / (2 * E * IZ), rel=1e-10)
    assert model.nodeDisp(2, 5) == pytest.approx(-pz * L ** 2 / (2 * E * IY), rel=1e-10)


@pytest.mark.parametrize("section", [aggregator, elastic8])
def test_uniform_load_both_planes(model, section):
    kvy, kvz = cantilever(model, section, points=5)
    wy, wz = 0.9, 0.4
    model.eleLoad("-ele", 1, "-type", "-beamUniform", wy, wz, 0.0)
    solve(model)
    assert model.nodeDisp(2, 2) == pytest.approx(wy * L ** 4 / (8 * E * IZ) + wy * L ** 2 / (2 * kvy), rel=1e-10)
    assert model.nodeDisp(2, 3) == pytest.approx(wz * L ** 4 / (8 * E * IY) + wz * L ** 2 / (2 * kvz), rel=1e-10)


def test_point_load_shear_and_symmetry(model):
    # Section shear of a point load: V = dM/dx before the load, zero beyond;
    # a doubly symmetric section deflects alike along y and z.
    def symmetric(m):
        m.section("Elastic", 10, E, A, IZ, IZ, G, J, ALPHA_Y, ALPHA_Y)

    tips = []
    for py, pz in ((1.0, 0.0), (0.0, 1.0)):
        model.wipe()
        cantilever(model, symmetric, points=5)
        model.eleLoad("-ele", 1, "-type", "-beamPoint", py, pz, 0.35)
        solve(model)
        first = model.eleResponse(1, "section", "1", "force")  # [P, Mz, Vy, My, Vz, T] at x = 0
        last = model.eleResponse(1, "section", "4", "force")   # x = 0.83 L, beyond the load
        assert first[2] == pytest.approx(-py, abs=1e-12)
        assert first[4] == pytest.approx(pz, abs=1e-12)
        assert first[1] == pytest.approx(0.35 * L * py, rel=1e-12, abs=1e-12)
        assert first[3] == pytest.approx(-0.35 * L * pz, rel=1e-12, abs=1e-12)
        assert max(abs(v) for v in last) < 1e-12
        tips.append(model.nodeDisp(2, 2) + model.nodeDisp(2, 3))
    assert tips[0] == pytest.approx(tips[1], rel=1e-12)


def test_response_order(model):
    # OpenSees' orders: the Aggregator's own components, then the aggregated
    # ones as given; the Elastic section [P, Mz, Vy, My, Vz, T].
    for order in (("Vy", "Vz"), ("Vz", "Vy")):
        model.wipe()
        cantilever(model, aggregator, shear_order=order)
        model.load(2, 0.5, 1.0, 2.0, 0.0, 0.0, 0.0)
        solve(model)
        force = model.eleResponse(1, "section", "1", "force")
        shear = {"Vy": -1.0, "Vz": 2.0}
        assert force == pytest.approx([0.5, 1.0 * L, -2.0 * L, 0.0] + [shear[c] for c in order], abs=1e-12)
        k = {"Vy": KVY, "Vz": KVZ}
        stiffness = model.eleResponse(1, "section", "2", "stiffness")
        diagonal = [E * A, E * IZ, E * IY, G * J] + [k[c] for c in order]
        assert stiffness == pytest.approx([diagonal[r] if r == c else 0.0 for r in range(6) for c in range(6)])
        gamma = model.eleResponse(1, "section", "3", "deformation")[4:]
        assert gamma == pytest.approx([shear[c] / k[c] for c in order], rel=1e-12)
    model.wipe()
    kvy, kvz = cantilever(model, elastic8)
    model.load(2, 0.5, 1.0, 2.0, 0.0, 0.0, 0.0)
    solve(model)
    assert model.eleResponse(1, "section", "1", "force") == pytest.approx([0.5, L, -1.0, -2.0 * L, 2.0, 0.0], abs=1e-12)
    stiffness = model.eleResponse(1, "section", "1", "stiffness")
    diagonal = [E * A, E * IZ, kvy, E * IY, kvz, G * J]
    assert stiffness == pytest.approx([diagonal[r] if r == c else 0.0 for r in range(6) for c in range(6)])


def test_steel01_shear_pushover(model):
    # Shear force is P all along the cantilever: every section has the same
    # shear strain, gamma(P) of the bilinear Steel01 loaded monotonically.
    fy, e0, b = 0.6, 40.0, 0.05

    def steel_shear(m):
        m.uniaxialMaterial("Steel01", 2, fy, e0, b)
        m.uniaxialMaterial("Elastic", 3, KVZ)
        m.section("Elastic", 1, E, A, IZ, IY, G, J)
        m.section("Aggregator", 10, 2, "Vy", 3, "Vz", "-section", 1)

    cantilever(model, steel_shear, points=3)
    p = 1.5
    model.load(2, 0.0, p, 0.0, 0.0, 0.0, 0.0)
    solve(model, steps=10)
    gamma = fy / e0 + (p - fy) / (b * e0)
    assert model.nodeDisp(2, 2) == pytest.approx(p * L ** 3 / (3 * E * IZ) + gamma * L, rel=1e-9)
    for s in ("1", "2", "3"):
        assert model.eleResponse(1, "section", s, "deformation")[4] == pytest.approx(-gamma, rel=1e-9)


def test_existing_sections_keep_four_components(model):
    cantilever(model, lambda m: m.section("Elastic", 10, E, A, IZ, IY, G, J))
    model.load(2, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0)
    solve(model)
    assert len(model.eleResponse(1, "section", "1", "force")) == 4
    assert model.nodeDisp(2, 2) == pytest.approx(L ** 3 / (3 * E * IZ), rel=1e-10)


def test_bad_input(model):
    model.model("basic", "-ndm", 3, "-ndf", 6)
    with pytest.raises(beamsolid.OpenSeesError, match=r"section Elastic 1.*6 numbers.*\(8\).*got 7"):
        model.section("Elastic", 1, E, A, IZ, IY, G, J, 0.5)
    for alpha in (0.0, -0.5):
        with pytest.raises(beamsolid.OpenSeesError, match=r"section Elastic 1.*alphaY.*positive"):
            model.section("Elastic", 1, E, A, IZ, IY, G, J, alpha, 0.7)
    with pytest.raises(beamsolid.OpenSeesError, match=r"section Elastic 1.*alphaZ"):
        model.section("Elastic", 1, E, A, IZ, IY, G, J, 0.5, "x")
    model.uniaxialMaterial("Elastic", 2, KVY)
    model.section("Elastic", 1, E, A, IZ, IY, G, J)
    model.section("Elastic", 5, E, A, IZ, IY, G, J, 0.5, 0.7)
    with pytest.raises(beamsolid.OpenSeesError, match=r"section Aggregator 3.*code.*'Vy' is given twice"):
        model.section("Aggregator", 3, 2, "Vy", 2, "Vy", "-section", 1)
    with pytest.raises(beamsolid.OpenSeesError, match=r"section Aggregator 3.*code.*P, Mz, My, T, Vy, Vz.*'Vx'"):
        model.section("Aggregator", 3, 2, "Vx", "-section", 1)
    with pytest.raises(beamsolid.OpenSeesError, match=r"section Aggregator 3.*'-section' 5 is shear-deformable"):
        model.section("Aggregator", 3, 2, "Vy", "-section", 5)
    with pytest.raises(beamsolid.OpenSeesError, match=r"section Aggregator 3.*uniaxialMaterial 9"):
        model.section("Aggregator", 3, 9, "Vy", "-section", 1)
    with pytest.raises(beamsolid.OpenSeesError, match=r"section Aggregator 3.*all of P, Mz, My and T"):
        model.section("Aggregator", 3, 2, "Vy", 2, "Vz")
    model.section("Aggregator", 3, 2, "Vy", 2, "Vz", "-section", 1)
    model.node(1, 0.0, 0.0, 0.0)
    model.node(2, L, 0.0, 0.0)
    model.geomTransf("Linear", 1, 0.0, 0.0, 1.0)
    model.beamIntegration("Lobatto", 1, 3, 3)
    model.element("forceBeamColumn", 1, 1, 2, 1, 1)
    with pytest.raises(beamsolid.OpenSeesError, match=r"element forceBeamColumn 1"):
        model.element("forceBeamColumn", 1, 1, 2, 1, 1)


def test_disp_beam_leaves_shear_unstrained(model):
    # Hermite bending has no shear strain (as OpenSees' and the 2D element):
    # the Euler-Bernoulli deflection, Vy = Vz = 0 in the sections.
    model.model("basic", "-ndm", 3, "-ndf", 6)
    model.node(1, 0.0, 0.0, 0.0)
    model.node(2, L, 0.0, 0.0)
    model.fix(1, 1, 1, 1, 1, 1, 1)
    elastic8(model)
    model.geomTransf("Linear", 1, 0.0, 0.0, 1.0)
    model.beamIntegration("Legendre", 1, 10, 3)
    model.element("dispBeamColumn", 1, 1, 2, 1, 1)
    model.timeSeries("Linear", 1)
    model.pattern("Plain", 1, 1)
    model.load(2, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0)
    solve(model)
    assert model.nodeDisp(2, 2) == pytest.approx(L ** 3 / (3 * E * IZ), rel=1e-10)
    force = model.eleResponse(1, "section", "1", "force")
    assert force[2] == 0.0 and force[4] == 0.0

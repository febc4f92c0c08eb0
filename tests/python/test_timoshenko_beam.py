"""ElasticTimoshenkoBeam against beam theory with shear deformation.

A cantilever with a tip load deflects P L^3 / (3 EI) + P L / (G Av) (the
Timoshenko beam is exact for it with one element); under a uniform load the
tip moves w L^4 / (8 EI) + w L^2 / (2 G Av). In 3D each bending plane takes
its own shear area (Avy for bending about z, Avz about y). With a very large
shear area the element is elasticBeamColumn. OpenSees' element is
geometrically linear whatever the geomTransf; so is this one. Tolerance 1e-10
relative (linear, one direct solve). Masses and responses are compared with
OpenSeesPy in oracle_scripts/timoshenko_beam.py.
"""
import pytest

import beamsolid

E, G, A, IZ, IY, J, AVY, AVZ, L = 200.0, 80.0, 10.0, 30.0, 25.0, 20.0, 8.0, 7.0, 5.0


def solve(m):
    m.system("UmfPack")
    m.constraints("Plain")
    m.numberer("Plain")
    m.test("NormDispIncr", 1e-12, 10)
    m.algorithm("Newton")
    m.integrator("LoadControl", 1.0)
    m.analysis("Static")
    assert m.analyze(1) == 0


def cantilever_2d(m, transf="Linear", n=1, avy=AVY):
    m.wipe()
    m.model("basic", "-ndm", 2, "-ndf", 3)
    for i in range(n + 1):
        m.node(i + 1, L * i / n, 0.0)
    m.fix(1, 1, 1, 1)
    m.geomTransf(transf, 1)
    for i in range(n):
        m.element("ElasticTimoshenkoBeam", i + 1, i + 1, i + 2, E, G, A, IZ, avy, 1)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)


@pytest.mark.parametrize("transf", ["Linear", "PDelta", "Corotational"])
def test_tip_load_bending_plus_shear(transf):
    m = beamsolid.Model()
    cantilever_2d(m, transf)
    P, N = 2.0, -40.0  # an axial compression that would amplify a PDelta beam by 1/(1 - N/Ncr) = 1.07
    m.load(2, N, P, 0.0)
    solve(m)
    assert m.nodeDisp(2, 2) == pytest.approx(P * L**3 / (3 * E * IZ) + P * L / (G * AVY), rel=1e-10)
    assert m.nodeDisp(2, 3) == pytest.approx(P * L**2 / (2 * E * IZ), rel=1e-10)
    assert m.nodeDisp(2, 1) == pytest.approx(N * L / (E * A), rel=1e-10)


def test_uniform_load_on_four_elements():
    m = beamsolid.Model()
    cantilever_2d(m, n=4)
    w = -1.5
    m.eleLoad("-ele", 1, 2, 3, 4, "-type", "-beamUniform", w)
    solve(m)
    expected = w * L**4 / (8 * E * IZ) + w * L**2 / (2 * G * AVY)
    assert m.nodeDisp(5, 2) == pytest.approx(expected, rel=1e-10)
    # The fixed end carries w L and w L^2 / 2.
    assert m.eleResponse(1, "localForce")[1:3] == pytest.approx([-w * L, -w * L * L / 2], rel=1e-10)


def test_a_stiff_shear_area_gives_the_euler_bernoulli_beam():
    m = beamsolid.Model()
    cantilever_2d(m, avy=1e12)
    m.load(2, 0.0, 1.0, 0.0)
    solve(m)
    assert m.nodeDisp(2, 2) == pytest.approx(L**3 / (3 * E * IZ), rel=1e-8)


def test_3d_each_plane_has_its_shear_area():
    m = beamsolid.Model()
    m.model("basic", "-ndm", 3, "-ndf", 6)
    m.node(1, 0.0, 0.0, 0.0)
    m.node(2, L, 0.0, 0.0)
    m.fix(1, 1, 1, 1, 1, 1, 1)
    m.geomTransf("PDelta", 1, 0.0, 0.0, 1.0)
    m.element("ElasticTimoshenkoBeam", 1, 1, 2, E, G, A, J, IY, IZ, AVY, AVZ, 1)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    Py, Pz, T = 1.0, -0.5, 0.3
    m.load(2, -10.0, Py, Pz, T, 0.0, 0.0)
    solve(m)
    u = m.nodeDisp(2)
    assert u[1] == pytest.approx(Py * L**3 / (3 * E * IZ) + Py * L / (G * AVY), rel=1e-10)
    assert u[2] == pytest.approx(Pz * L**3 / (3 * E * IY) + Pz * L / (G * AVZ), rel=1e-10)
    assert u[3] == pytest.approx(T * L / (G * J), rel=1e-10)
    assert u[4] == pytest.approx(-Pz * L**2 / (2 * E * IY), rel=1e-10)


def test_bad_input():
    m = beamsolid.Model()
    cantilever_2d(m)
    with pytest.raises(beamsolid.OpenSeesError, match="ElasticTimoshenkoBeam 5.*6 numbers"):
        m.element("ElasticTimoshenkoBeam", 5, 1, 2, E, G, A, IZ, 1)
    with pytest.raises(beamsolid.OpenSeesError, match="Avy"):
        m.element("ElasticTimoshenkoBeam", 5, 1, 2, E, G, A, IZ, 0.0, 1)
    with pytest.raises(beamsolid.OpenSeesError, match="3D form"):
        m.element("ElasticTimoshenkoBeam", 5, 1, 2, E, G, A, J, IY, IZ, AVY, AVZ, 1)
    with pytest.raises(beamsolid.OpenSeesError, match="-foo"):
        m.element("ElasticTimoshenkoBeam", 5, 1, 2, E, G, A, IZ, AVY, 1, "-foo")
    with pytest.raises(beamsolid.OpenSeesError, match="geomTransf"):
        m.element("ElasticTimoshenkoBeam", 5, 1, 2, E, G, A, IZ, AVY, 9)
    m.element("ElasticTimoshenkoBeam", 5, 1, 2, E, G, A, IZ, AVY, 1)
    with pytest.raises(beamsolid.OpenSeesError, match="beamPoint"):
        m.eleLoad("-ele", 5, "-type", "-beamPoint", 1.0, 0.5)

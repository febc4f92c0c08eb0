"""Through-thickness plate sections ('PlateFiber', 'LayeredShell') of
nDMaterial('PlateFiber', ...) against closed forms: a strip in pure bending
(free long edges, as in test_shells.py) turns by M L / (E I) with I = b h^3 /
12 for 'PlateFiber' (five Gauss-Lobatto points integrate z^2 exactly) and
I = b h^3 / 12 (1 - 1/n^2) for n equal layers (one point at each layer's
middle); and bad input. OpenSeesPy agreement: oracle script layered_shells.
"""
import pytest

import beamsolid

E, NU = 1.0e4, 0.3
L, B, M = 4.0, 1.0, 2.0e-3


def bent_strip(m, section):
    m.model("basic", "-ndm", 3, "-ndf", 6)
    nx, ny = 4, 2
    tag = lambda i, j: 1 + i + (nx + 1) * j  # noqa: E731
    for j in range(ny + 1):
        for i in range(nx + 1):
            m.node(tag(i, j), L * i / nx + (0.13 if (i, j) == (2, 1) else 0.0), B * j / ny, 0.0)
    m.nDMaterial("ElasticIsotropic", 1, E, NU)
    m.nDMaterial("PlateFiber", 2, 1)
    m.section(*section)
    e = 0
    for j in range(ny):
        for i in range(nx):
            e += 1
            m.element("ShellMITC4", e, tag(i, j), tag(i + 1, j), tag(i + 1, j + 1), tag(i, j + 1), 1)
    for j in range(ny + 1):
        m.fix(tag(0, j), 1, int(j == 0), int(j != 1), 0, 1, 0)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    for j, share in ((0, 0.25), (1, 0.5), (2, 0.25)):
        m.load(tag(nx, j), 0.0, 0.0, 0.0, 0.0, -M * share, 0.0)
    m.system("UmfPack")
    m.numberer("RCM")
    m.constraints("Transformation")
    m.algorithm("Linear")
    m.integrator("LoadControl", 1.0)
    m.analysis("Static")
    assert m.analyze(1) == 0
    return [m.nodeDisp(tag(nx, j), 5) for j in range(ny + 1)]


def test_plate_fiber_section_bends_as_the_full_plate(model):
    h = 0.05
    rotations = bent_strip(model, ("PlateFiber", 1, 2, h))
    assert rotations == pytest.approx([-M * L / (E * B * h**3 / 12)] * 3, rel=1e-8)


@pytest.mark.parametrize("n", [3, 4, 8])
def test_equal_layers_bend_by_the_midpoint_rule(model, n):
    h = 0.05
    rotations = bent_strip(model, ("LayeredShell", 1, n, *([2, h / n] * n)))
    inertia = B * h**3 / 12 * (1 - 1 / n**2)
    assert rotations == pytest.approx([-M * L / (E * inertia)] * 3, rel=1e-9)


def test_bad_input(model):
    model.model("basic", "-ndm", 3, "-ndf", 6)
    model.nDMaterial("ElasticIsotropic", 1, E, NU)
    model.nDMaterial("PlateFiber", 2, 1)
    model.nDMaterial("ContactMaterial3D", 3, 0.3, 1.0, 0.0, 0.0)
    with pytest.raises(beamsolid.OpenSeesError, match=r"section LayeredShell 5: argument 3 \(nLayers\).*3\.\.10000"):
        model.section("LayeredShell", 5, 2, 2, 0.1, 2, 0.1)
    with pytest.raises(beamsolid.OpenSeesError, match=r"section LayeredShell 5: argument \d+ \(thickness\)"):
        model.section("LayeredShell", 5, 3, 2, 0.1, 2, -0.1, 2, 0.1)
    with pytest.raises(beamsolid.OpenSeesError, match=r"section PlateFiber 6: argument 3 \(matTag\).*plate fiber material"):
        model.section("PlateFiber", 6, 1, 0.1)
    with pytest.raises(beamsolid.OpenSeesError, match=r"section PlateFiber 6: argument 4 \(h\)"):
        model.section("PlateFiber", 6, 2, 0.0)
    with pytest.raises(beamsolid.OpenSeesError, match=r"nDMaterial PlateFiber 7: .*not a three-dimensional material"):
        model.nDMaterial("PlateFiber", 7, 3)

"""ShellMITC4 with ElasticMembranePlateSection against closed forms: the
membrane patch test on a distorted mesh (exact), a strip in pure bending
(exact: MITC4 passes the constant-curvature test), a simply supported square
plate under uniform load converging to Timoshenko's thin-plate value, and bad
input. OpenSeesPy agreement is in the oracle script `shells`."""
import math

import pytest

import beamsolid

E, NU = 1.0e4, 0.3


def mesh(m, nx, ny, lx, ly, h, moved=None, rho=0.0):
    m.model("basic", "-ndm", 3, "-ndf", 6)
    tag = lambda i, j: 1 + i + (nx + 1) * j  # noqa: E731
    for j in range(ny + 1):
        for i in range(nx + 1):
            dx, dy = (moved or {}).get((i, j), (0.0, 0.0))
            m.node(tag(i, j), lx * i / nx + dx, ly * j / ny + dy, 0.0)
    m.section("ElasticMembranePlateSection", 1, E, NU, h, rho)
    e = 0
    for j in range(ny):
        for i in range(nx):
            e += 1
            m.element("ShellMITC4", e, tag(i, j), tag(i + 1, j), tag(i + 1, j + 1), tag(i, j + 1), 1)
    return tag


def solve(m):
    m.system("UmfPack")
    m.numberer("RCM")
    m.constraints("Transformation")
    m.algorithm("Linear")
    m.integrator("LoadControl", 1.0)
    m.analysis("Static")
    assert m.analyze(1) == 0


def test_membrane_patch_test_on_a_distorted_mesh(model):
    # u = a x + b y, v = c x + d y with c = b: no rotation, so the drilling
    # term is idle; every interior node must follow the field exactly and
    # every Gauss point carry the constant membrane forces.
    a, b, d = 1e-3, 4e-4, -6e-4
    nx, ny = 3, 3
    moved = {(1, 1): (0.11, -0.07), (2, 1): (-0.09, 0.12), (1, 2): (0.05, 0.1), (2, 2): (-0.12, -0.04)}
    tag = mesh(model, nx, ny, 3.0, 3.0, 0.1, moved)
    model.timeSeries("Linear", 1)
    model.pattern("Plain", 1, 1)
    for j in range(ny + 1):
        for i in range(nx + 1):
            n = tag(i, j)
            x, y, _ = model.nodeCoord(n)
            model.fix(n, 0, 0, 1, 1, 1, 0)
            if i in (0, nx) or j in (0, ny):
                model.sp(n, 1, a * x + b * y)
                model.sp(n, 2, b * x + d * y)
                model.sp(n, 6, 0.0)
    solve(model)
    for n in (tag(1, 1), tag(2, 1), tag(1, 2), tag(2, 2)):
        x, y, _ = model.nodeCoord(n)
        assert model.nodeDisp(n, 1) == pytest.approx(a * x + b * y, rel=1e-10)
        assert model.nodeDisp(n, 2) == pytest.approx(b * x + d * y, rel=1e-10)
        assert model.nodeDisp(n, 6) == pytest.approx(0.0, abs=1e-13)
    c = E * 0.1 / (1 - NU**2)
    n11, n22, n12 = c * (a + NU * d), c * (d + NU * a), c * (1 - NU) / 2 * 2 * b
    for e in (1, 5, 9):
        # Stresses are in the element's frame: e1 along its xi direction.
        x = [model.nodeCoord(n) for n in model.eleNodes(e)]
        v1 = [0.5 * (x[1][k] + x[2][k] - x[0][k] - x[3][k]) for k in range(2)]
        t = math.atan2(v1[1], v1[0])
        cs, sn = math.cos(t), math.sin(t)
        expected = [n11 * cs * cs + n22 * sn * sn + 2 * n12 * sn * cs,
                    n11 * sn * sn + n22 * cs * cs - 2 * n12 * sn * cs,
                    (n22 - n11) * sn * cs + n12 * (cs * cs - sn * sn)]
        s = model.eleResponse(e, "stresses")
        for p in range(4):
            assert s[8 * p:8 * p + 3] == pytest.approx(expected, rel=1e-9)
            assert s[8 * p + 3:8 * p + 8] == pytest.approx([0.0] * 5, abs=1e-9)


def test_a_strip_in_pure_bending_is_exact(model):
    # A strip L x b, free long edges, end moment M, held at x = 0 by u = 0 and
    # theta_y = 0, and w = 0 at the two corners only (so the anticlastic
    # curvature -nu kappa forms freely): kappa = M / (E I) with I = b h^3 / 12,
    # tip rotation M L / (E I) and corner deflection M L^2 / (2 E I), on a
    # distorted mesh.
    L, b, h, M = 4.0, 1.0, 0.05, 2.0e-3
    tag = mesh(model, 4, 2, L, b, h, {(2, 1): (0.13, 0.06)})
    for j in range(3):
        model.fix(tag(0, j), 1, int(j == 0), int(j != 1), 0, 1, 0)
    model.timeSeries("Linear", 1)
    model.pattern("Plain", 1, 1)
    # The end moment about y as consistent nodal moments along the edge.
    for j, share in ((0, 0.25), (1, 0.5), (2, 0.25)):
        model.load(tag(4, j), 0.0, 0.0, 0.0, 0.0, -M * share, 0.0)
    solve(model)
    EI = E * b * h**3 / 12
    for j in range(3):
        assert model.nodeDisp(tag(4, j), 5) == pytest.approx(-M * L / EI, rel=1e-9)
    for j in (0, 2):
        assert model.nodeDisp(tag(4, j), 3) == pytest.approx(M * L**2 / (2 * EI), rel=1e-9)


def square_plate_centre_deflection(model, n):
    # Simply supported (w = 0 on the edges), uniform q, h / a = 0.01: the
    # thin-plate centre deflection is alpha q a^4 / D with alpha = 0.00406
    # (Timoshenko and Woinowsky-Krieger, table 8, nu = 0.3).
    a, h, q = 1.0, 0.01, 1.0
    tag = mesh(model, n, n, a, a, h)
    for j in range(n + 1):
        for i in range(n + 1):
            edge = i in (0, n) or j in (0, n)
            model.fix(tag(i, j), int(i == 0 and j == 0), int(i == 0 and j in (0, n)), int(edge), 0, 0, 1)
    model.timeSeries("Linear", 1)
    model.pattern("Plain", 1, 1)
    cell = (a / n) ** 2
    for j in range(n + 1):
        for i in range(n + 1):
            share = (0.5 if i in (0, n) else 1.0) * (0.5 if j in (0, n) else 1.0)
            model.load(tag(i, j), 0.0, 0.0, -q * cell * share, 0.0, 0.0, 0.0)
    solve(model)
    D = E * h**3 / (12 * (1 - NU**2))
    return -model.nodeDisp(tag(n // 2, n // 2), 3) / (q * a**4 / D)


def test_simply_supported_plate_converges_to_the_thin_plate_value(model):
    alpha = 0.00406235  # the series solution's value (table 8 gives 0.00406)
    errors = []
    for n in (4, 8, 16):
        model.wipe()
        errors.append(abs(square_plate_centre_deflection(model, n) / alpha - 1.0))
    assert errors[2] < errors[1] < errors[0]
    assert errors[2] < 5e-3
    # At least second order: the error drops four times or more per halving.
    assert errors[1] / errors[2] > 3.0


def test_bad_input(model):
    model.model("basic", "-ndm", 3, "-ndf", 6)
    for n, xyz in enumerate([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (2, 0, 0), (0.2, 0.2, 0)]):
        model.node(n + 1, *map(float, xyz))
    model.section("ElasticMembranePlateSection", 1, E, NU, 0.1)
    model.section("Elastic", 2, E, 1.0, 1.0, 1.0, 1.0, 1.0)
    with pytest.raises(beamsolid.OpenSeesError, match=r"element ShellMITC4 1.*Elastic 2 is a beam section"):
        model.element("ShellMITC4", 1, 1, 2, 3, 4, 2)
    with pytest.raises(beamsolid.OpenSeesError, match=r"element ShellMITC4 1.*section 9 does not exist"):
        model.element("ShellMITC4", 1, 1, 2, 3, 4, 9)
    with pytest.raises(beamsolid.OpenSeesError, match=r"element ShellMITC4 1: argument 7 \(secTag\)"):
        model.element("ShellMITC4", 1, 1, 2, 3, 4)
    with pytest.raises(beamsolid.OpenSeesError, match=r"element ShellMITC4 1.*collinear"):
        model.element("ShellMITC4", 1, 1, 2, 5, 2, 1)
    with pytest.raises(beamsolid.OpenSeesError, match=r"element ShellMITC4 1.*inverted or degenerate"):
        model.element("ShellMITC4", 1, 1, 2, 6, 4, 1)  # node 6 inside: a concave quadrilateral
    with pytest.raises(beamsolid.OpenSeesError, match=r"section ElasticMembranePlateSection 3: argument 4 \(nu\)"):
        model.section("ElasticMembranePlateSection", 3, E, 0.5, 0.1)
    with pytest.raises(beamsolid.OpenSeesError, match=r"section ElasticMembranePlateSection 3: argument 5 \(h\)"):
        model.section("ElasticMembranePlateSection", 3, E, 0.3, 0.0)
    model.geomTransf("Linear", 1, 0.0, 0.0, 1.0)
    model.beamIntegration("Lobatto", 1, 1, 3)
    with pytest.raises(beamsolid.OpenSeesError, match=r"forceBeamColumn 7.*plate section \(for shells\)"):
        model.element("forceBeamColumn", 7, 1, 2, 1, 1)
    model.wipe()
    model.model("basic", "-ndm", 3, "-ndf", 3)
    for n, xyz in enumerate([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]):
        model.node(n + 1, *map(float, xyz))
    model.section("ElasticMembranePlateSection", 1, E, NU, 0.1)
    with pytest.raises(beamsolid.OpenSeesError, match=r"element ShellMITC4 1: node 1 has 3 dofs, a shell needs 6"):
        model.element("ShellMITC4", 1, 1, 2, 3, 4, 1)
    model.wipe()
    model.model("basic", "-ndm", 2, "-ndf", 3)
    with pytest.raises(beamsolid.OpenSeesError, match=r"section ElasticMembranePlateSection 1.*3D model"):
        model.section("ElasticMembranePlateSection", 1, E, NU, 0.1)

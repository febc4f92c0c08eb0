"""tri31 (the 3-node constant-strain triangle) against closed forms.

- Patch test: on a mesh of distorted triangles a linear displacement field
  imposed on the boundary is reproduced at the interior nodes, and every
  element's strain and stress are the field's, to 1e-12.
- Cantilever in plane stress (clamped root, parabolic tip shear): the tip
  deflection converges at second order in the element size to Timoshenko's
  beam with shear, delta = P L^3/(3EI) + P L/(kappa G A), kappa = 5/6.
- One triangle: stiffness B^T D B t A with B of the constant gradients
  (every entry, both plane types); body force t A b / 3 per node; pressure
  p * edge length along the outward normal, half per end node; lumped mass
  rho t A / 3 per node and direction (element rho, else the material's).
- Bad input raises OpenSeesError naming the command and the argument.
"""
import numpy as np
import pytest

import beamsolid

E, NU = 1.0e4, 0.25
TRI = [(0.0, 0.0), (2.0, 0.3), (0.5, 1.5)]


def plane_d(kind, e=E, nu=NU):
    if kind == "PlaneStress":
        return e / (1 - nu**2) * np.array([[1, nu, 0], [nu, 1, 0], [0, 0, (1 - nu) / 2]])
    c = e / ((1 + nu) * (1 - 2 * nu))
    return c * np.array([[1 - nu, nu, 0], [nu, 1 - nu, 0], [0, 0, (1 - 2 * nu) / 2]])


def cst_b(xy):
    """Strain-displacement matrix of a triangle from its area coordinates."""
    x = np.asarray(xy, float)
    area = 0.5 * np.linalg.det(np.c_[np.ones(3), x])
    grads = np.linalg.inv(np.c_[np.ones(3), x])[1:, :].T  # dN_a/dx, dN_a/dy
    b = np.zeros((3, 6))
    for a in range(3):
        b[0, 2 * a], b[1, 2 * a + 1] = grads[a]
        b[2, 2 * a], b[2, 2 * a + 1] = grads[a, 1], grads[a, 0]
    return b, area


def mesh(model, nx, ny, lx, ly, kind, t=0.5, moved=None, extra=()):
    model.model("basic", "-ndm", 2, "-ndf", 2)
    tag = lambda i, j: 1 + i + (nx + 1) * j  # noqa: E731
    for j in range(ny + 1):
        for i in range(nx + 1):
            dx, dy = (moved or {}).get((i, j), (0.0, 0.0))
            model.node(tag(i, j), lx * i / nx + dx, ly * j / ny + dy)
    model.nDMaterial("ElasticIsotropic", 1, E, NU, 2.0)
    e = 0
    for j in range(ny):
        for i in range(nx):
            a, b, c, d = tag(i, j), tag(i + 1, j), tag(i + 1, j + 1), tag(i, j + 1)
            for tri in ((a, b, c), (a, c, d)) if (i + j) % 2 == 0 else ((a, b, d), (b, c, d)):
                e += 1
                model.element("tri31", e, *tri, t, kind, 1, *extra)
    return tag, e


def solve(model, handler="Plain"):
    model.constraints(handler)
    model.numberer("RCM")
    model.system("UmfPack")
    model.test("NormDispIncr", 1e-12, 5)
    model.algorithm("Linear")
    model.integrator("LoadControl", 1.0)
    model.analysis("Static")
    assert model.analyze(1) == 0


@pytest.mark.parametrize("kind", ["PlaneStrain", "PlaneStress"])
def test_patch_test_reproduces_constant_strain(model, kind):
    grad = np.array([[1.0e-3, 0.4e-3], [-0.6e-3, 0.7e-3]])  # du_i/dx_j
    moved = {(1, 1): (0.17, -0.09), (2, 1): (-0.12, 0.13), (1, 2): (0.05, 0.1), (2, 2): (0.1, -0.04)}
    nx, ny = 3, 3
    tag, count = mesh(model, nx, ny, 3.0, 2.0, kind, moved=moved)
    interior = {tag(i, j) for i in range(1, nx) for j in range(1, ny)}
    model.timeSeries("Constant", 1)
    model.pattern("Plain", 1, 1)
    for n in model.getNodeTags():
        if n not in interior:
            x = np.array(model.nodeCoord(n))
            for d in range(2):
                model.sp(n, d + 1, grad[d] @ x)
    solve(model, "Transformation")
    for n in interior:
        x = np.array(model.nodeCoord(n))
        assert np.allclose(model.nodeDisp(n), grad @ x, rtol=0, atol=1e-12 * 1e-3)
    eps = np.array([grad[0, 0], grad[1, 1], grad[0, 1] + grad[1, 0]])
    sigma = plane_d(kind) @ eps
    for e in range(1, count + 1):
        assert np.allclose(model.eleResponse(e, "strains"), eps, rtol=0, atol=1e-12 * 1e-3)
        assert np.allclose(model.eleResponse(e, "stresses"), sigma, rtol=0, atol=1e-12 * abs(sigma).max())
        assert np.allclose(model.eleResponse(e, "material", 1, "strain"), eps, rtol=0, atol=1e-15)


def cantilever_tip(model, nx, ny, L=10.0, h=1.0, t=0.5, P=1.0):
    tag, _ = mesh(model, nx, ny, L, h, "PlaneStress", t=t)
    for j in range(ny + 1):
        model.fix(tag(0, j), 1, 1)
    model.timeSeries("Linear", 1)
    model.pattern("Plain", 1, 1)
    # Parabolic shear over the tip edge, consistent nodal loads (Simpson: exact).
    loads = np.zeros(ny + 1)
    tau = lambda y: 1.5 * P / h * (1.0 - 4.0 * (y - h / 2) ** 2 / h**2)  # noqa: E731
    for j in range(ny):
        y0, y1 = h * j / ny, h * (j + 1) / ny
        dy, ym = y1 - y0, 0.5 * (y0 + y1)
        loads[j] += dy / 6.0 * (tau(y0) + 2.0 * tau(ym))
        loads[j + 1] += dy / 6.0 * (2.0 * tau(ym) + tau(y1))
    assert abs(loads.sum() - P) < 1e-12
    for j in range(ny + 1):
        model.load(tag(nx, j), 0.0, -loads[j])
    solve(model)
    tip = -model.nodeDisp(tag(nx, ny // 2), 2)
    model.wipe()
    return tip


def test_cantilever_converges_to_timoshenko_beam(model):
    L, h, t, P = 10.0, 1.0, 0.5, 1.0
    I, A, G = t * h**3 / 12.0, t * h, E / (2 * (1 + NU))
    timoshenko = P * L**3 / (3 * E * I) + P * L / (5.0 / 6.0 * G * A)
    tips = [cantilever_tip(model, 10 * m, 2 * m) for m in (2, 4, 8, 16)]
    # Constant-strain triangles are stiff in bending: the tip deflection
    # grows towards the limit, and at second order (successive differences
    # shrink by about 4; measured rates 1.57 from the coarse 20 x 4 mesh, then
    # 1.87).
    assert all(a < b for a, b in zip(tips, tips[1:])), tips
    diffs = np.diff(tips)
    rates = np.log2(diffs[:-1] / diffs[1:])
    assert 1.4 < rates[0] < rates[1] < 2.2, (tips, rates)
    limit = tips[-1] + (tips[-1] - tips[-2]) / 3.0
    assert abs(limit - timoshenko) / timoshenko < 5e-3, (tips, limit, timoshenko)
    # 160 x 32 itself: 0.7% below (measured).
    assert abs(tips[-1] - timoshenko) / timoshenko < 1e-2, (tips[-1], timoshenko)


def one_triangle(model, kind, extra=(), rho_mat=0.0, t=0.5):
    model.model("basic", "-ndm", 2, "-ndf", 2)
    for i, (x, y) in enumerate(TRI):
        model.node(i + 1, x, y)
    model.nDMaterial("ElasticIsotropic", 1, E, NU, rho_mat)
    model.element("tri31", 1, 1, 2, 3, t, kind, 1, *extra)


@pytest.mark.parametrize("kind", ["PlaneStrain", "PlaneStress"])
def test_stiffness_is_btdb_t_area(model, kind):
    """Each unit displacement u_k = 1 gives the resisting forces column k of
    t A B^T D B."""
    t = 0.5
    b, area = cst_b(TRI)
    k_exact = t * area * b.T @ plane_d(kind) @ b
    for k in range(6):
        one_triangle(model, kind, t=t)
        model.timeSeries("Constant", 1)
        model.pattern("Plain", 1, 1)
        for n in range(1, 4):
            for d in range(1, 3):
                model.sp(n, d, 1.0 if 2 * (n - 1) + d - 1 == k else 0.0)
        solve(model, "Transformation")
        f = np.array(model.eleResponse(1, "forces"))
        assert np.allclose(f, k_exact[:, k], rtol=0, atol=1e-12 * abs(k_exact).max())
        model.wipe()


def test_body_force_and_pressure_nodal_forces(model):
    """Undisplaced, the resisting force is minus the element loads: t A b / 3
    at every node, and p * (dy, -dx) / 2 at both ends of every edge."""
    t, p, b1, b2 = 0.5, 3.0, 0.7, -1.1
    one_triangle(model, "PlaneStress", (p, 0.0, b1, b2), t=t)
    _, area = cst_b(TRI)
    x = np.array(TRI)
    expected = np.tile(t * area / 3.0 * np.array([b1, b2]), 3)
    for a in range(3):
        d = x[(a + 1) % 3] - x[a]
        half = 0.5 * p * np.array([d[1], -d[0]])
        expected[2 * a:2 * a + 2] += half
        expected[2 * ((a + 1) % 3):2 * ((a + 1) % 3) + 2] += half
    f = np.array(model.eleResponse(1, "forces"))
    assert np.allclose(-f, expected, rtol=0, atol=1e-14)
    # The total pressure on a closed contour is zero.
    assert abs(expected.reshape(3, 2).sum(axis=0) - 3 * t * area / 3.0 * np.array([b1, b2])).max() < 1e-14


@pytest.mark.parametrize("rho_ele, rho_mat, used", [(1.7, 0.0, 1.7), (1.7, 2.5, 1.7), (0.0, 2.5, 2.5)])
def test_lumped_mass_rho_thick_area_over_three(model, rho_ele, rho_mat, used):
    """Only node 3's x dof free: omega^2 = K_55 / (rho t A / 3), rho the
    element's, else the material's."""
    t = 0.5
    one_triangle(model, "PlaneStress", (0.0, rho_ele, 0.0, 0.0), rho_mat=rho_mat, t=t)
    model.fix(1, 1, 1)
    model.fix(2, 1, 1)
    model.fix(3, 0, 1)
    b, area = cst_b(TRI)
    k = t * area * (b.T @ plane_d("PlaneStress") @ b)[4, 4]
    omega2 = model.eigen("-fullGenLapack", 1)[0]
    assert abs(omega2 - k / (used * t * area / 3.0)) < 1e-10 * omega2


def error_of(model, *args):
    with pytest.raises(beamsolid.OpenSeesError) as err:
        model.element(*args)
    return str(err.value)


def test_bad_input_names_command_and_argument(model):
    one_triangle(model, "PlaneStress")
    model.node(4, -1.0, 0.5)
    msg = error_of(model, "tri31", 2, 1, 2, 3, 4, 0.5, "PlaneStress", 1)
    assert "element tri31 2" in msg and "3 node" in msg
    msg = error_of(model, "tri31", 2, 1, 2, 0.5, "PlaneStress", 1)
    assert "element tri31 2" in msg and "3 node" in msg
    msg = error_of(model, "tri31", 2, 1, 2, 4, 0.5, "PlaneStress", 9)
    assert "element tri31 2" in msg and "nDMaterial 9 does not exist" in msg
    msg = error_of(model, "tri31", 2, 1, 2, 4, 0.5, "PlaneStrainX", 1)
    assert "element tri31 2" in msg and "type" in msg
    msg = error_of(model, "tri31", 2, 1, 2, 4, 0.0, "PlaneStress", 1)
    assert "element tri31 2" in msg and "thick" in msg
    msg = error_of(model, "tri31", 2, 1, 2, 4, 0.5, "PlaneStress", 1, 1.0, 2.0)
    assert "element tri31 2" in msg and "pressure, rho, b1, b2" in msg
    msg = error_of(model, "tri31", 2, 1, 2, 99, 0.5, "PlaneStress", 1)
    assert "element tri31 2" in msg and "99" in msg
    # Clockwise: negative area.
    msg = error_of(model, "tri31", 2, 1, 3, 2, 0.5, "PlaneStress", 1)
    assert "element tri31 2" in msg and "counterclockwise" in msg
    # A material without a plane form.
    model.nDMaterial("DruckerPrager", 7, 100.0, 80.0, 1.0, 0.2, 0.2, 0.2, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 101.0)
    msg = error_of(model, "tri31", 2, 1, 2, 4, 0.5, "PlaneStress", 7)
    assert "element tri31 2" in msg and "PlaneStress" in msg
    # The model is unchanged by the failed commands.
    assert model.getEleTags() == [1]


def test_tri31_in_a_3d_model_is_refused(model):
    model.model("basic", "-ndm", 3, "-ndf", 3)
    for i, (x, y) in enumerate(TRI):
        model.node(i + 1, x, y, 0.0)
    model.nDMaterial("ElasticIsotropic", 1, E, NU)
    msg = error_of(model, "tri31", 1, 1, 2, 3, 0.5, "PlaneStress", 1)
    assert "element tri31 1" in msg and "-ndm" in msg

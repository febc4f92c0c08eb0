"""FourNodeTetrahedron (the 4-node constant-strain tetrahedron) against
closed forms.

- Patch test: on a distorted mesh of tetrahedra (Kuhn's six per cell) a
  linear displacement field imposed on the boundary is reproduced at the
  interior nodes, with the field's strain and stress in every element, to
  1e-12.
- Uniaxial stress: a box of tetrahedra on rollers with a uniform traction
  sigma on its far face (consistent nodal forces, sigma A_face / 3 per
  triangle node): u = (sigma/E) x, v = -nu (sigma/E) y, w = -nu (sigma/E) z
  and stress (sigma, 0, 0, 0, 0, 0) in every element, to 1e-12.
- One tetrahedron: stiffness V B^T D B (every column); body force V b / 4
  per node; the one-point mass rho V N_a N_b at the centroid (rho V / 16
  for every pair of nodes; its total per direction is rho V).
- Bad input raises OpenSeesError naming the command and the argument.
"""
import itertools

import numpy as np
import pytest

import beamsolid

E, NU = 2.0e4, 0.3
TET = [(0.0, 0.0, 0.0), (2.0, 0.2, 0.1), (0.3, 1.5, -0.1), (0.2, 0.4, 1.7)]


def iso_d(e=E, nu=NU):
    lam, mu = e * nu / ((1 + nu) * (1 - 2 * nu)), e / (2 * (1 + nu))
    d = np.zeros((6, 6))
    d[:3, :3] = lam
    d[range(3), range(3)] += 2 * mu
    d[3, 3] = d[4, 4] = d[5, 5] = mu
    return d


def tet_b(xyz):
    x = np.asarray(xyz, float)
    m = np.c_[np.ones(4), x]
    volume = np.linalg.det(m) / 6.0
    g = np.linalg.inv(m)[1:, :].T
    b = np.zeros((6, 12))
    for a in range(4):
        dx, dy, dz = g[a]
        c = 3 * a
        b[0, c], b[1, c + 1], b[2, c + 2] = dx, dy, dz
        b[3, c], b[3, c + 1] = dy, dx
        b[4, c + 1], b[4, c + 2] = dz, dy
        b[5, c], b[5, c + 2] = dz, dx
    return b, volume


def box(model, n, size, moved=None, body=()):
    """Kuhn's split of an n[0] x n[1] x n[2] grid; returns tag(i, j, k) and the tets."""
    nx, ny, nz = n
    model.model("basic", "-ndm", 3, "-ndf", 3)
    tag = lambda i, j, k: 1 + i + (nx + 1) * (j + (ny + 1) * k)  # noqa: E731
    coords = {}
    for k in range(nz + 1):
        for j in range(ny + 1):
            for i in range(nx + 1):
                d = (moved or {}).get((i, j, k), (0.0, 0.0, 0.0))
                x = (size[0] * i / nx + d[0], size[1] * j / ny + d[1], size[2] * k / nz + d[2])
                coords[tag(i, j, k)] = x
                model.node(tag(i, j, k), *x)
    model.nDMaterial("ElasticIsotropic", 1, E, NU, 1.5)
    tets = []
    for k, j, i in itertools.product(range(nz), range(ny), range(nx)):
        for perm in itertools.permutations(range(3)):
            corner, path = [i, j, k], [(i, j, k)]
            for axis in perm:
                corner[axis] += 1
                path.append(tuple(corner))
            t = [tag(*p) for p in path]
            if np.linalg.det(np.c_[np.ones(4), [coords[a] for a in t]]) < 0:
                t[1], t[2] = t[2], t[1]
            tets.append(t)
    for e, t in enumerate(tets, start=1):
        model.element("FourNodeTetrahedron", e, *t, 1, *body)
    return tag, tets, coords


def solve(model, handler="Plain"):
    model.constraints(handler)
    model.numberer("RCM")
    model.system("UmfPack")
    model.test("NormDispIncr", 1e-12, 5)
    model.algorithm("Linear")
    model.integrator("LoadControl", 1.0)
    model.analysis("Static")
    assert model.analyze(1) == 0


def test_patch_test_reproduces_constant_strain(model):
    grad = np.array([[1.0e-3, 0.4e-3, -0.3e-3], [0.2e-3, -0.5e-3, 0.6e-3], [0.7e-3, 0.1e-3, 0.8e-3]])
    moved = {(1, 1, 1): (0.12, -0.07, 0.05), (2, 1, 1): (-0.09, 0.1, -0.06)}
    tag, tets, coords = box(model, (3, 2, 2), (3.0, 2.0, 1.6), moved)
    interior = {tag(i, 1, 1) for i in (1, 2)}
    model.timeSeries("Constant", 1)
    model.pattern("Plain", 1, 1)
    for n, x in coords.items():
        if n not in interior:
            for d in range(3):
                model.sp(n, d + 1, grad[d] @ np.array(x))
    solve(model, "Transformation")
    for n in interior:
        assert np.allclose(model.nodeDisp(n), grad @ np.array(coords[n]), rtol=0, atol=1e-15)
    eps = np.array([grad[0, 0], grad[1, 1], grad[2, 2], grad[0, 1] + grad[1, 0], grad[1, 2] + grad[2, 1],
                    grad[0, 2] + grad[2, 0]])
    sigma = iso_d() @ eps
    for e in range(1, len(tets) + 1):
        assert np.allclose(model.eleResponse(e, "strains"), eps, rtol=0, atol=1e-15)
        assert np.allclose(model.eleResponse(e, "stresses"), sigma, rtol=0, atol=1e-12 * abs(sigma).max())


def test_uniaxial_stress_box(model):
    sigma, size = 12.0, (2.0, 1.0, 1.5)
    tag, tets, coords = box(model, (2, 1, 2), size)
    for n, x in coords.items():
        model.fix(n, int(x[0] == 0.0), int(x[1] == 0.0), int(x[2] == 0.0))
    model.timeSeries("Linear", 1)
    model.pattern("Plain", 1, 1)
    loads = {}
    for t in tets:
        for face in itertools.combinations(t, 3):
            if all(coords[a][0] == size[0] for a in face):
                p = [np.array(coords[a]) for a in face]
                area = 0.5 * np.linalg.norm(np.cross(p[1] - p[0], p[2] - p[0]))
                for a in face:
                    loads[a] = loads.get(a, 0.0) + sigma * area / 3.0
    assert abs(sum(loads.values()) - sigma * size[1] * size[2]) < 1e-12
    for n, f in loads.items():
        model.load(n, f, 0.0, 0.0)
    solve(model)
    strain = sigma / E
    for n, x in coords.items():
        expected = [strain * x[0], -NU * strain * x[1], -NU * strain * x[2]]
        assert np.allclose(model.nodeDisp(n), expected, rtol=0, atol=1e-12 * strain)
    for e in range(1, len(tets) + 1):
        assert np.allclose(model.eleResponse(e, "stresses"), [sigma, 0, 0, 0, 0, 0], rtol=0, atol=1e-12 * sigma)


def one_tet(model, body=(), rho=0.0):
    model.model("basic", "-ndm", 3, "-ndf", 3)
    for i, x in enumerate(TET):
        model.node(i + 1, *x)
    model.nDMaterial("ElasticIsotropic", 1, E, NU, rho)
    model.element("FourNodeTetrahedron", 1, 1, 2, 3, 4, 1, *body)


def test_stiffness_is_v_btdb(model):
    b, volume = tet_b(TET)
    k_exact = volume * b.T @ iso_d() @ b
    for k in range(12):
        one_tet(model)
        model.timeSeries("Constant", 1)
        model.pattern("Plain", 1, 1)
        for n in range(1, 5):
            for d in range(1, 4):
                model.sp(n, d, 1.0 if 3 * (n - 1) + d - 1 == k else 0.0)
        solve(model, "Transformation")
        assert np.allclose(model.eleResponse(1, "forces"), k_exact[:, k], rtol=0, atol=1e-12 * abs(k_exact).max())
        model.wipe()


def test_body_force_is_v_b_over_four(model):
    b = np.array([0.7, -1.1, 0.4])
    one_tet(model, tuple(b))
    _, volume = tet_b(TET)
    assert np.allclose(-np.array(model.eleResponse(1, "forces")), np.tile(volume * b / 4.0, 4), rtol=0, atol=1e-14)


def test_one_point_mass(model):
    """One free dof (node 4, x): omega^2 = K_99 / (rho V / 16); all nodes
    tied to node 1 on a spring k per direction: omega^2 = k / (rho V)."""
    rho = 2.0
    b, volume = tet_b(TET)
    k99 = volume * (b.T @ iso_d() @ b)[9, 9]
    one_tet(model, rho=rho)
    for n in (1, 2, 3):
        model.fix(n, 1, 1, 1)
    model.fix(4, 0, 1, 1)
    omega2 = model.eigen("-fullGenLapack", 1)[0]
    assert abs(omega2 - k99 / (rho * volume / 16.0)) < 1e-10 * omega2
    model.wipe()
    one_tet(model, rho=rho)
    k = 1.0e3
    model.uniaxialMaterial("Elastic", 1, k)
    model.node(5, 0.0, 0.0, 0.0)
    model.fix(5, 1, 1, 1)
    model.element("zeroLength", 2, 5, 1, "-mat", 1, 1, 1, "-dir", 1, 2, 3)
    for n in (2, 3, 4):
        model.equalDOF(1, n, 1, 2, 3)
    for omega2 in model.eigen("-fullGenLapack", 3):
        assert abs(omega2 - k / (rho * volume)) < 1e-10 * omega2


def error_of(model, *args):
    with pytest.raises(beamsolid.OpenSeesError) as err:
        model.element(*args)
    return str(err.value)


def test_bad_input_names_command_and_argument(model):
    one_tet(model)
    model.node(5, 1.0, 1.0, 1.0)
    msg = error_of(model, "FourNodeTetrahedron", 2, 1, 2, 3, 4, 5, 1)
    assert "element FourNodeTetrahedron 2" in msg and "exactly 4 nodes" in msg
    msg = error_of(model, "FourNodeTetrahedron", 2, 1, 2, 3, 1)
    assert "element FourNodeTetrahedron 2" in msg and "matTag" in msg
    msg = error_of(model, "FourNodeTetrahedron", 2, 1, 2, 3, 5, 9)
    assert "element FourNodeTetrahedron 2" in msg and "nDMaterial 9 does not exist" in msg
    msg = error_of(model, "FourNodeTetrahedron", 2, 1, 2, 3, 5, 1, 0.0, -9.8)
    assert "element FourNodeTetrahedron 2" in msg and "0 or 3 body force" in msg
    msg = error_of(model, "FourNodeTetrahedron", 2, 1, 2, 3, 77, 1)
    assert "element FourNodeTetrahedron 2" in msg and "77" in msg
    msg = error_of(model, "FourNodeTetrahedron", 2, 1, 3, 2, 4, 1)
    assert "element FourNodeTetrahedron 2" in msg and "counterclockwise" in msg
    model.nDMaterial("ContactMaterial3D", 3, 0.3, 1e5, 0.0, 0.0)
    msg = error_of(model, "FourNodeTetrahedron", 2, 1, 2, 3, 5, 3)
    assert "element FourNodeTetrahedron 2" in msg and "ThreeDimensional" in msg
    assert model.getEleTags() == [1]


def test_tetrahedron_in_a_2d_model_is_refused(model):
    model.model("basic", "-ndm", 2, "-ndf", 2)
    for i, x in enumerate(TET):
        model.node(i + 1, *x[:2])
    model.nDMaterial("ElasticIsotropic", 1, E, NU)
    msg = error_of(model, "FourNodeTetrahedron", 1, 1, 2, 3, 4, 1)
    assert "element FourNodeTetrahedron 1" in msg and "2D" in msg

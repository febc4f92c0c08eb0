"""Eigen analysis and path-following integrators through the Python commands."""
import math

import pytest

import beamsolid


def cantilever(ops, n, length=2.0, E=200e9, I=8e-6, A=4e-3, rho=7850.0):
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    for k in range(n + 1):
        ops.node(k + 1, 0.0, 0.0, length * k / n)
    ops.fix(1, 1, 1, 1, 1, 1, 1)
    ops.geomTransf("Linear", 1, 1.0, 0.0, 0.0)
    for k in range(n):
        ops.element("elasticBeamColumn", k + 1, k + 1, k + 2, A, E, E / 2.6, 2 * I, I, I, 1, "-mass", rho * A)
    return math.sqrt(E * I / (rho * A)) / length**2


@pytest.mark.parametrize("solver", [(), ("-fullGenLapack",)])
def test_cantilever_frequencies_converge_to_euler_bernoulli(ops, solver):
    # omega_1 = 1.8751^2 sqrt(EI / m) / L^2; lumped mass converges from below at O(h^2).
    errors = []
    for n in (10, 20, 40):
        ops.wipe()
        scale = cantilever(ops, n)
        omega2 = ops.eigen(*solver, 2)
        # Two equal modes (x and y bending, Iy = Iz).
        assert omega2[0] == pytest.approx(omega2[1], rel=1e-8)
        errors.append(abs(math.sqrt(omega2[0]) - 1.87510407**2 * scale) / (1.87510407**2 * scale))
    assert errors[-1] < 1e-3, errors
    assert errors[0] / errors[1] > 3.0 and errors[1] / errors[2] > 3.0, errors  # second order


def test_eigenvectors_are_mass_normalized_and_fixed_dofs_zero(ops):
    cantilever(ops, 8)
    ops.eigen(3)
    phi = [ops.nodeEigenvector(k, 1) for k in range(1, 10)]
    assert phi[0] == [0.0] * 6
    m_node = 7850.0 * 4e-3 * 2.0 / 8  # lumped: m L / 2 per element end
    modal_mass = sum(m_node * (1.0 if k < 7 else 0.5) * (p[0] ** 2 + p[1] ** 2 + p[2] ** 2) for k, p in enumerate(phi[1:]))
    assert modal_mass == pytest.approx(1.0, rel=1e-8)


def test_elastic_perfectly_plastic_truss_under_displacement_control(ops):
    """An EPP bar and a parallel elastic bar pulled past yield by DisplacementControl.

    The EPP bar's force plateaus at A E eps_y; the elastic bar keeps the
    tangent regular (a bare plateau has zero stiffness, singular in OpenSees too).
    """
    E, A, eps_y, L = 200e3, 10.0, 0.002, 1000.0
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    ops.node(1, 0.0, 0.0, 0.0)
    ops.node(2, L, 0.0, 0.0)
    ops.fix(1, 1, 1, 1)
    ops.fix(2, 0, 1, 1)
    ops.uniaxialMaterial("ElasticPP", 1, E, eps_y)
    ops.element("truss", 1, 1, 2, A, 1)
    ops.uniaxialMaterial("Elastic", 2, E / 100)
    ops.element("truss", 2, 1, 2, A, 2)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, 1.0, 0.0, 0.0)
    ops.system("UmfPack")
    ops.test("NormDispIncr", 1e-12, 20)
    ops.algorithm("Newton")
    du = 0.1
    ops.integrator("DisplacementControl", 2, 1, du)
    ops.analysis("Static")
    path = []
    for step in range(60):
        assert ops.analyze(1) == 0
        path.append((ops.nodeDisp(2, 1), ops.getTime()))
    fy_force = A * E * eps_y  # 4000
    for u, load in path:
        expected = min(E * A * u / L, fy_force) + E / 100 * A * u / L
        assert load == pytest.approx(expected, rel=1e-10)
        assert u == pytest.approx(du * round(u / du), rel=1e-12)
    assert path[-1][0] == pytest.approx(60 * du, rel=1e-12)
    assert ops.eleResponse(1, "axialForce")[0] == pytest.approx(fy_force, rel=1e-12)


@pytest.mark.parametrize("solver", [(), ("-fullGenLapack",)])
def test_mass_on_a_rigidly_linked_node_reaches_the_system_only_through_the_pattern(ops, solver):
    """A mass at a node constrained by rigidLink('beam') couples the retained node's
    translations and rotations (T^T m T). With no element at either node nothing else
    couples them, and the sparse pattern lacked those entries: assembleMass wrote at
    position -1 (ASan heap-buffer-overflow, found by the command fuzzer). Now they are in
    the pattern, and eigen reports what is wrong with such a model instead."""
    import beamsolid

    ops.model("basic", "-ndm", 3, "-ndf", 6)
    ops.node(2, 1.0, 0.0, 0.0)
    ops.node(3, 1.0, 0.0, 1.0)
    ops.rigidLink("beam", 2, 3)
    ops.mass(3, 2.0, 2.0, 2.0, 0.0, 0.0, 0.0)
    with pytest.raises(beamsolid.OpenSeesError, match="(mechanism|singular).*node 2 dof [1-6]|node 2 dof [1-6].*mechanism"):
        ops.eigen(*solver, 1)
    ops.mass(3, -2.0, 2.0, 2.0, 0.0, 0.0, 0.0)
    with pytest.raises(beamsolid.OpenSeesError, match="node 2 dof 1 has a negative mass"):
        ops.eigen(*solver, 1)


def _offset_mass(ops, arm, solver):
    """A massless cantilever column (z) whose top carries a point mass (translational
    only) on an arm offset by (1, 0.5, 0): through rigidLink('beam') (arm None), or
    through a stiff elastic arm of stiffness factor `arm`."""
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    ops.node(1, 0.0, 0.0, 0.0)
    ops.node(2, 0.0, 0.0, 3.0)
    ops.node(3, 1.0, 0.5, 3.0)
    ops.fix(1, 1, 1, 1, 1, 1, 1)
    ops.geomTransf("Linear", 1, 1.0, 0.0, 0.0)
    ops.element("elasticBeamColumn", 1, 1, 2, 0.01, 200e6, 80e6, 2e-5, 1e-5, 1.5e-5, 1)
    if arm is None:
        ops.rigidLink("beam", 2, 3)
        ops.constraints("Transformation")
    else:
        ops.geomTransf("Linear", 2, 0.0, 0.0, 1.0)
        ops.element("elasticBeamColumn", 2, 2, 3, 0.01 * arm, 200e6, 80e6, 2e-5 * arm, 1e-5 * arm, 1e-5 * arm, 2)
    ops.mass(3, 2.0, 2.0, 2.0, 0.0, 0.0, 0.0)
    return ops.eigen(*solver, 3)


@pytest.mark.parametrize("solver", [(), ("-fullGenLapack",)])
def test_a_translational_mass_on_a_rigid_link_gives_the_stiff_arm_frequencies(ops, solver):
    """The mass of node 3 reaches node 2's six dofs through the rigid link as a 6x6 block
    of rank 3 whose diagonal is all positive (m r^2 on the rotations). Treated as a
    positive definite mass it gave 46.15 three times (Spectra) or unsorted values
    (dense); split by its eigenvectors it gives three modes, equal to those of the same
    mass on an elastic arm 1e6 times stiffer than the column (an independent model: no
    constraint, the arm's flexibility adds ~1e-6), and to OpenSeesPy's -fullGenLapack
    (79.1043, 101.0770, 1525.537; its default Arpack solver fails on this model)."""
    rigid = _offset_mass(ops, None, solver)
    # Mass-normalised modes: the point mass is the only mass, so m |u_3|^2 = 1, and the
    # linked node follows the rigid body motion u_3 = u_2 + theta_2 x r.
    for mode in (1, 2, 3):
        u2, u3 = ops.nodeEigenvector(2, mode), ops.nodeEigenvector(3, mode)
        assert 2.0 * sum(c * c for c in u3[:3]) == pytest.approx(1.0, rel=1e-9)
        r = (1.0, 0.5, 0.0)
        t = u2[3:]
        cross = (t[1] * r[2] - t[2] * r[1], t[2] * r[0] - t[0] * r[2], t[0] * r[1] - t[1] * r[0])
        assert u3[:3] == pytest.approx([u2[i] + cross[i] for i in range(3)], abs=1e-12)
    stiff_arm = _offset_mass(ops, 1e6, ())
    assert rigid == sorted(rigid)
    assert rigid == pytest.approx(stiff_arm, rel=1e-5)
    assert rigid == pytest.approx([79.10425324687188, 101.07699805261056, 1525.536837456452], rel=1e-9)
    ops.wipe()


def test_standard_eigenproblem_ignores_the_mass(ops):
    # eigen('-standard', n): K phi = lambda phi, as OpenSees. A 2D cantilever
    # column (EI = 100, EA = 100, L = 3) with a tip mass: the standard
    # eigenvalues are those of the tip's 3 x 3 stiffness (closed form), not
    # the generalized 3 EI / (L^3 m).
    np = pytest.importorskip("numpy")
    E, A, I, L = 100.0, 1.0, 1.0, 3.0
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    ops.node(1, 0.0, 0.0)
    ops.node(2, 0.0, L)
    ops.fix(1, 1, 1, 1)
    ops.mass(2, 7.0, 7.0, 0.0)
    ops.geomTransf("Linear", 1)
    ops.element("elasticBeamColumn", 1, 1, 2, A, E, I, 1)
    K = np.array([[12 * E * I / L**3, 0.0, -6 * E * I / L**2],
                  [0.0, E * A / L, 0.0],
                  [-6 * E * I / L**2, 0.0, 4 * E * I / L]])
    expected = np.linalg.eigvalsh(K)
    assert ops.eigen("-standard", 3) == pytest.approx(list(expected), rel=1e-10)
    assert ops.eigen("-standard", "-fullGenLapack", 2) == pytest.approx(list(expected[:2]), rel=1e-10)
    # Modes of unit length.
    phi = ops.nodeEigenvector(2, 1)
    assert sum(p * p for p in phi) == pytest.approx(1.0, rel=1e-10)
    assert ops.eigen(1) == pytest.approx([3 * E * I / L**3 / 7.0], rel=1e-10)


def test_mode_components_without_motion_are_exactly_zero(ops):
    # A cantilever stiffer about one axis: its first mode bends about the other only, so the
    # components along the stiff direction are round-off; they come out as exact zeros (as in
    # OpenSees' modes), which keeps modal participations of 0 from printing as 1e-28.
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    for k in range(5):
        ops.node(k + 1, 0.0, 0.0, 0.5 * k)
    ops.fix(1, 1, 1, 1, 1, 1, 1)
    ops.geomTransf("Linear", 1, 1.0, 0.0, 0.0)
    for k in range(4):
        ops.element("elasticBeamColumn", k + 1, k + 1, k + 2, 0.01, 2e8, 8e7, 2e-5, 1e-5, 4e-5, 1, "-mass", 10.0)
    ops.eigen(2)
    for mode in (1, 2):
        phi = ops.nodeEigenvector(5, mode)
        moving = 0 if abs(phi[0]) > abs(phi[1]) else 1
        assert abs(phi[moving]) > 0.0
        assert phi[1 - moving] == 0.0 and phi[2] == 0.0


@pytest.mark.parametrize("option", ["-UmfPack", "-SuperLU", "-ProfileSPD"])
def test_eigen_ignores_unknown_solver_options_with_a_warning(option, capfd):
    # OpenSeesPy's test_EigenFrameExtra passes system names to eigen; OpenSees
    # says "unknown option" and runs its default solver. A two-storey spring
    # chain k = m = 1 (springs 1-2, 2-3, node 1 fixed): lambda = (3 -+ sqrt 5) / 2.
    import beamsolid.opensees as ops

    ops.wipe()
    ops.model("basic", "-ndm", 1, "-ndf", 1)
    for tag, x in ((1, 0.0), (2, 1.0), (3, 2.0)):
        ops.node(tag, x)
    ops.fix(1, 1)
    ops.mass(2, 1.0)
    ops.mass(3, 1.0)
    ops.uniaxialMaterial("Elastic", 1, 1.0)
    ops.element("zeroLength", 1, 1, 2, "-mat", 1, "-dir", 1)
    ops.element("zeroLength", 2, 2, 3, "-mat", 1, "-dir", 1)
    lam = ops.eigen(option, 2)
    assert lam == pytest.approx([(3 - 5**0.5) / 2, (3 + 5**0.5) / 2], rel=1e-12)
    assert f"WARNING eigen - unknown option '{option}' ignored" in capfd.readouterr().err
    ops.wipe()


@pytest.mark.parametrize("integrator", ["DisplacementControl", "ArcLength"])
@pytest.mark.parametrize("element", ["elasticBeamColumn", "dispBeamColumn"])
def test_element_loads_of_the_pushed_pattern_are_in_the_reference_load(integrator, element):
    """An elastic cantilever with a tip load P and a uniform load w in the same (Linear) pattern:
    u_tip = lambda (P L^3 / 3EI + w L^4 / 8EI) is linear in lambda, so a path-following step whose
    reference load holds the element loads' nodal equivalents (as OpenSees' does) converges in one
    Newton iteration; without them it converged only linearly (50 iterations)."""
    m = beamsolid.Model()
    m.model("basic", "-ndm", 2, "-ndf", 3)
    L, E, A, I, P, w = 6.0, 2.0e5, 0.08, 1.0e-3, 1.0, 0.3
    m.node(1, 0.0, 0.0)
    m.node(2, 0.0, L / 2)
    m.node(3, 0.0, L)
    m.fix(1, 1, 1, 1)
    m.geomTransf("Linear", 1)
    m.section("Elastic", 1, E, A, I)
    m.beamIntegration("Legendre", 1, 1, 3)
    for tag, (i, j) in enumerate(((1, 2), (2, 3)), 1):
        if element == "elasticBeamColumn":
            m.element(element, tag, i, j, A, E, I, 1)
        else:
            m.element(element, tag, i, j, 1, 1)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.load(3, P, 0.0, 0.0)
    m.eleLoad("-ele", 1, 2, "-type", "-beamUniform", -w)  # local y of a column is -global x
    m.constraints("Plain")
    m.numberer("Plain")
    m.system("FullGeneral")
    m.test("NormDispIncr", 1.0e-12, 50)
    m.algorithm("Newton")
    if integrator == "DisplacementControl":
        m.integrator("DisplacementControl", 3, 1, 0.01)
    else:
        m.integrator("ArcLength", 0.01, 0.0)
    m.analysis("Static")
    flexibility = P * L**3 / (3 * E * I) + w * L**4 / (8 * E * I)
    for step in range(3):
        assert m.analyze(1) == 0
        assert m.testIter() == 1
        assert m.nodeDisp(3, 1) == pytest.approx(m.getLoadFactor(1) * flexibility, rel=1e-10)
    if integrator == "DisplacementControl":
        assert m.nodeDisp(3, 1) == pytest.approx(0.03, rel=1e-12)

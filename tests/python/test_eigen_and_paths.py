"""Eigen analysis and path-following integrators through the Python commands."""
import math

import pytest


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
    with pytest.raises(beamsolid.OpenSeesError, match="(mechanism|singular).*node 2 dof 6|node 2 dof 6.*mechanism"):
        ops.eigen(*solver, 1)
    ops.mass(3, -2.0, 2.0, 2.0, 0.0, 0.0, 0.0)
    with pytest.raises(beamsolid.OpenSeesError, match="node 2 dof 1 has a negative mass"):
        ops.eigen(*solver, 1)

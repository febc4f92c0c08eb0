"""quad elements against closed forms.

- Cantilever in plane stress (length L, depth h, thickness t), clamped
  nodes at the root and a tip shear P spread parabolically over the tip
  nodes (consistent loads): the tip deflection converges, at second order
  in the element size (meshes 16x4 to 128x32, observed rates 1.8 to 1.96),
  to within 0.5% (measured: 0.13%) of Timoshenko's beam with shear,
      delta = P L^3 / (3 E I) + P L / (kappa G A),  kappa = 5/6;
  the remaining difference is the clamped root (warping restrained), which
  beam theory does not model.
- Body forces: the base reactions of a mesh equal b * t * area; pressure:
  each edge of an element takes p * length along its outward normal.
- Lumped mass: its total equals rho * t * area (the one frequency of the
  element tied into a rigid block on a spring).
"""
import math

import numpy as np
import pytest

E, NU = 1.0e4, 0.25


def cantilever_tip(model, nx, ny, L=10.0, h=1.0, t=0.5, P=1.0):
    model.model("basic", "-ndm", 2, "-ndf", 2)
    tag = lambda i, j: 1 + i + (nx + 1) * j  # noqa: E731
    for j in range(ny + 1):
        for i in range(nx + 1):
            model.node(tag(i, j), L * i / nx, -h / 2 + h * j / ny)
    for j in range(ny + 1):
        model.fix(tag(0, j), 1, 1)
    model.nDMaterial("ElasticIsotropic", 1, E, NU)
    e = 0
    for j in range(ny):
        for i in range(nx):
            e += 1
            model.element("quad", e, tag(i, j), tag(i + 1, j), tag(i + 1, j + 1), tag(i, j + 1), t, "PlaneStress", 1)
    model.timeSeries("Linear", 1)
    model.pattern("Plain", 1, 1)
    # Parabolic shear tau(y) = 3P/(2A) (1 - 4y^2/h^2), integrated against the
    # linear shape functions of each tip edge (Simpson is exact: cubic).
    loads = np.zeros(ny + 1)
    for j in range(ny):
        y0, y1 = -h / 2 + h * j / ny, -h / 2 + h * (j + 1) / ny
        tau = lambda y: 1.5 * P / (h * t) * (1.0 - 4.0 * y * y / (h * h)) * t  # noqa: E731
        ym = 0.5 * (y0 + y1)
        dy = y1 - y0
        loads[j] += dy / 6.0 * (tau(y0) + 2.0 * tau(ym) * 1.0)
        loads[j + 1] += dy / 6.0 * (2.0 * tau(ym) * 1.0 + tau(y1))
    assert abs(loads.sum() - P) < 1e-12
    for j in range(ny + 1):
        model.load(tag(nx, j), 0.0, -loads[j])
    model.constraints("Plain")
    model.numberer("RCM")
    model.system("UmfPack")
    model.test("NormDispIncr", 1e-12, 5)
    model.algorithm("Linear")
    model.integrator("LoadControl", 1.0)
    model.analysis("Static")
    assert model.analyze(1) == 0
    tip = -model.nodeDisp(tag(nx, ny // 2), 2)
    model.wipe()
    return tip


def test_plane_stress_cantilever_converges_to_timoshenko(model):
    L, h, t, P = 10.0, 1.0, 0.5, 1.0
    I, A, G = t * h**3 / 12.0, t * h, E / (2 * (1 + NU))
    timoshenko = P * L**3 / (3 * E * I) + P * L / (5.0 / 6.0 * G * A)
    tips = [cantilever_tip(model, 8 * m, 2 * m) for m in (2, 4, 8, 16)]
    # Second order: successive differences shrink by 4 (measured rates 1.78,
    # 1.93, 1.96; the coarsest meshes lock in bending, so start at 16 x 4).
    diffs = np.diff(tips)
    rates = np.log2(np.abs(diffs[:-1] / diffs[1:]))
    assert np.all((rates > 1.7) & (rates < 2.3)), (tips, rates)
    # Richardson's limit within 0.5% of the beam with shear (measured 0.13%
    # below it; 128 x 32 itself is 0.39% below), and above Euler-Bernoulli.
    limit = tips[-1] + (tips[-1] - tips[-2]) / 3.0
    assert abs(limit - timoshenko) / timoshenko < 5e-3, (limit, timoshenko)
    assert limit > P * L**3 / (3 * E * I)


def block(model, kind, extra, nx=3, ny=2, lx=3.0, ly=2.0, t=0.4):
    model.model("basic", "-ndm", 2, "-ndf", 2)
    tag = lambda i, j: 1 + i + (nx + 1) * j  # noqa: E731
    for j in range(ny + 1):
        for i in range(nx + 1):
            dx = 0.1 * math.sin(i * j) if 0 < i < nx and 0 < j < ny else 0.0
            model.node(tag(i, j), lx * i / nx + dx, ly * j / ny - 0.07 * dx)
    for i in range(nx + 1):
        model.fix(tag(i, 0), 1, 1)
    model.nDMaterial("ElasticIsotropic", 1, E, NU, 2.0)
    e = 0
    for j in range(ny):
        for i in range(nx):
            e += 1
            model.element("quad", e, tag(i, j), tag(i + 1, j), tag(i + 1, j + 1), tag(i, j + 1), t, kind, 1, *extra)
    model.timeSeries("Linear", 1)
    model.pattern("Plain", 1, 1)
    return [tag(i, 0) for i in range(nx + 1)]


def solve(model):
    model.constraints("Plain")
    model.numberer("RCM")
    model.system("UmfPack")
    model.test("NormDispIncr", 1e-12, 5)
    model.algorithm("Newton")
    model.integrator("LoadControl", 1.0)
    model.analysis("Static")
    assert model.analyze(1) == 0
    model.reactions()


@pytest.mark.parametrize("kind", ["PlaneStrain", "PlaneStress"])
def test_body_force_resultant_is_b_times_volume(model, kind):
    base = block(model, kind, (0.0, 0.0, 1.5, -20.0))
    solve(model)
    volume = 0.4 * 3.0 * 2.0
    rx = sum(model.nodeReaction(n, 1) for n in base)
    ry = sum(model.nodeReaction(n, 2) for n in base)
    assert abs(rx + 1.5 * volume) < 1e-10 and abs(ry - 20.0 * volume) < 1e-10


@pytest.mark.parametrize("kind", ["PlaneStrain", "PlaneStress"])
def test_pressure_resultant_is_p_times_edge_length(model, kind):
    """One a x b rectangle, undisplaced: its resisting force is minus the
    pressure loads. Each edge carries p * length along its outward normal
    (OpenSees' pressure is per unit edge length: the thickness plays no
    part), half to each end: the top nodes take p a up, the right p b right."""
    a, b, p = 3.0, 2.0, 12.0
    model.model("basic", "-ndm", 2, "-ndf", 2)
    for i, (x, y) in enumerate([(0.0, 0.0), (a, 0.0), (a, b), (0.0, b)]):
        model.node(i + 1, x, y)
    model.nDMaterial("ElasticIsotropic", 1, E, NU)
    model.element("quad", 1, 1, 2, 3, 4, 0.4, kind, 1, p)
    f = np.array(model.eleResponse(1, "forces")).reshape(4, 2)
    assert abs(-(f[2, 1] + f[3, 1]) - p * a) < 1e-12 * p * a
    assert abs(-(f[1, 0] + f[2, 0]) - p * b) < 1e-12 * p * b
    assert np.allclose(-f, 0.5 * p * np.array([[-b, -a], [b, -a], [b, a], [-b, a]]), rtol=0, atol=1e-12 * p)


def test_lumped_mass_totals_rho_thick_area(model):
    """All nodes tied by equalDOF to node 1, which is held by two trusses of
    axial stiffness k, one along x and one along y: both modes have
    omega^2 = k / (rho t A)."""
    rho, t, k = 2.5, 0.4, 1.0e3
    model.model("basic", "-ndm", 2, "-ndf", 2)
    xy = [(0.0, 0.0), (2.0, 0.2), (2.2, 1.5), (-0.1, 1.2)]
    for i, (x, y) in enumerate(xy):
        model.node(i + 1, x, y)
    model.node(5, -1.0, 0.0)
    model.node(6, 0.0, -1.0)
    model.fix(5, 1, 1)
    model.fix(6, 1, 1)
    model.nDMaterial("ElasticIsotropic", 1, E, NU)
    model.element("quad", 1, 1, 2, 3, 4, t, "PlaneStress", 1, 0.0, rho)
    model.uniaxialMaterial("Elastic", 1, k)
    model.element("Truss", 2, 5, 1, 1.0, 1)
    model.element("Truss", 3, 6, 1, 1.0, 1)
    for n in (2, 3, 4):
        model.equalDOF(1, n, 1, 2)
    area = 0.5 * abs(sum(xy[a][0] * xy[(a + 1) % 4][1] - xy[(a + 1) % 4][0] * xy[a][1] for a in range(4)))
    for omega2 in model.eigen("-fullGenLapack", 2):
        assert abs(omega2 - k / (rho * t * area)) < 1e-10 * omega2

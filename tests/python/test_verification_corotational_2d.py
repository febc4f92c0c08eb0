"""geomTransf('Corotational') in 2D with elasticBeamColumn against closed forms.

- End moment M = 2 pi EI / L on a cantilever of N elements: every element
  carries the same moment, so each deforms into the same arc with its chord
  kept at L/N (no axial force); the nodes lie on a regular N-gon and the tip
  comes back to the root with rotation 2 pi, exactly (round-off).
- Tip load P on a cantilever (the elastica): tip displacements against
  Mattiasson (1981), "Numerical results from large deflection beam and frame
  problems analysed by means of elliptic integrals", IJNME 17, Table 1
  (values reproduced here by shooting on EI theta'' = -P cos theta):
      PL^2/EI   u/L (shortening)   w/L (deflection)   tip rotation
        1          0.05643            0.30172           0.46135
        3          0.25442            0.60325           0.98602
        5          0.38763            0.71379           1.21537
       10          0.55500            0.81061           1.43029
  With 40 elements the error is at most 9.1e-5 (of L, or relative for the
  rotation); the observed convergence rates between 10, 20 and 40 elements
  are 1.99 and 1.91 (error ~ h^2).
"""
import math

import numpy as np
import pytest

E, A, I, L = 1.0e4, 1.0, 1.0 / 12.0, 10.0


def cantilever(model, n, area=A):
    model.model("basic", "-ndm", 2, "-ndf", 3)
    for i in range(n + 1):
        model.node(i + 1, L * i / n, 0.0)
    model.fix(1, 1, 1, 1)
    model.geomTransf("Corotational", 1)
    for i in range(n):
        model.element("elasticBeamColumn", i + 1, i + 1, i + 2, area, E, I, 1)
    model.timeSeries("Linear", 1)
    model.pattern("Plain", 1, 1)


def load_control(model, steps, tol=1e-10):
    model.constraints("Plain")
    model.numberer("RCM")
    model.system("UmfPack")
    model.test("NormDispIncr", tol, 30)
    model.algorithm("Newton")
    model.integrator("LoadControl", 1.0 / steps)
    model.analysis("Static")
    for _ in range(steps):
        assert model.analyze(1) == 0


def test_end_moment_rolls_the_cantilever_into_a_full_circle(model):
    n = 12
    cantilever(model, n)
    model.load(n + 1, 0.0, 0.0, 2.0 * math.pi * E * I / L)
    load_control(model, 8)
    tip = model.nodeDisp(n + 1)
    # Back at the root: displacement (-L, 0), rotation 2 pi.
    assert abs(tip[0] + L) < 1e-9 * L
    assert abs(tip[1]) < 1e-9 * L
    assert abs(tip[2] - 2.0 * math.pi) < 1e-9
    # Every node on the regular n-gon of side L/n through the root.
    radius = (L / n) / (2.0 * math.sin(math.pi / n))
    for i in range(n + 1):
        phi = 2.0 * math.pi * i / n
        x = L * i / n + model.nodeDisp(i + 1, 1)
        y = model.nodeDisp(i + 1, 2)
        assert abs(x - radius * math.sin(phi)) < 1e-9 * L
        assert abs(y - radius * (1.0 - math.cos(phi))) < 1e-9 * L
    model.reactions()
    assert abs(model.nodeReaction(1, 3) + 2.0 * math.pi * E * I / L) < 1e-8 * E * I / L


MATTIASSON = {1.0: (0.05643, 0.30172, 0.46135), 3.0: (0.25442, 0.60325, 0.98602),
              5.0: (0.38763, 0.71379, 1.21537), 10.0: (0.55500, 0.81061, 1.43029)}


def elastica_tip(model, n, k):
    # The elastica is inextensible: EA 1e4 times EI/L^2 keeps the axial strain
    # below 1e-5 of the table's digits.
    cantilever(model, n, area=1.0e3)
    model.load(n + 1, 0.0, -k * E * I / L**2, 0.0)
    load_control(model, 10)
    u, w, theta = model.nodeDisp(n + 1)
    model.wipe()
    return np.array([-u / L, -w / L, -theta])


@pytest.mark.parametrize("k", sorted(MATTIASSON))
def test_tip_load_follows_the_elastica(model, k):
    tip = elastica_tip(model, 40, k)
    err = np.max(np.abs(tip - MATTIASSON[k]) / np.array([1.0, 1.0, MATTIASSON[k][2]]))
    # Table values carry 5 digits (5e-6); the 40-element error measured 9.1e-5 at most.
    assert err < 1.5e-4, f"PL^2/EI = {k}: {tip} vs {MATTIASSON[k]}"


def test_elastica_converges_at_second_order(model):
    k = 5.0
    errors = [abs(elastica_tip(model, n, k)[1] - 0.713790) for n in (10, 20, 40)]
    rates = [math.log2(errors[i] / errors[i + 1]) for i in range(2)]
    assert all(1.8 < r < 2.3 for r in rates), (errors, rates)


def test_rigid_rotation_of_a_free_beam_needs_no_force(model):
    """A two-element beam turned by 3 rad (past the branch of atan2 at pi)
    as a rigid body by imposed displacements: no reactions, no forces."""
    model.model("basic", "-ndm", 2, "-ndf", 3)
    for i in range(3):
        model.node(i + 1, 2.0 * i, 1.0)
    model.geomTransf("Corotational", 1, "-jntOffset", 0.1, 0.0, 0.0, 0.1)
    for i in range(2):
        model.element("elasticBeamColumn", i + 1, i + 1, i + 2, A, E, I, 1)
    model.timeSeries("Linear", 1)
    model.pattern("Plain", 1, 1)
    angle = 3.0
    c, s = math.cos(angle), math.sin(angle)
    for i in range(3):
        x, y = 2.0 * i, 1.0
        model.sp(i + 1, 1, c * x - s * y - x)
        model.sp(i + 1, 2, s * x + c * y - y)
        model.sp(i + 1, 3, angle)
    load_control(model, 6)
    model.reactions()
    for i in range(3):
        assert max(abs(r) for r in model.nodeReaction(i + 1)) < 1e-8
    for e in (1, 2):
        assert max(abs(f) for f in model.eleResponse(e, "basicForce")) < 1e-8

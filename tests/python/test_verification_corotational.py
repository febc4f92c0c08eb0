"""geomTransf('Corotational') through beamsolid.opensees: cantilevers at large rotation.

- An end moment M rolls a cantilever into a circle of radius R = EI/M, tip at
  (R sin t, R (1 - cos t)), t = M L / EI, up to the full circle t = 2 pi.
  Elements keep their length (N = 0) and turn by t h / L, so the nodes lie on
  the circle R_h = h / (2 sin(t h / 2L)): checked to 1e-12 L; the continuum
  circle is approached as R_h / R - 1 = (t h)^2 / 24 + O(h^4).
- A dead transverse tip load P: the elastica of Bisshopp & Drucker (1945).
  The reference here is an independent shooting solution of
  theta'' = -(P/EI) cos theta (RK4), checked against their tabulated values.
- Newton's per-iteration norms (testNorm) fall quadratically.
- A failed step leaves the model bit for bit at the last converged state.
"""
import math

import numpy as np
import pytest

import beamsolid

L, EI = 1.0, 1.0

# The elastica of Bisshopp & Drucker (1945) for P L^2 / EI = 1, 2, 5, 10, to
# 5 digits as commonly tabulated (e.g. Mattiasson 1981):
# (L - x_tip) / L and deflection / L.
BISSHOPP_DRUCKER = {
    1.0: (0.05643, 0.30172),
    2.0: (0.16064, 0.49346),
    5.0: (0.38763, 0.71379),
    10.0: (0.55500, 0.81061),
}


def rotation(w):
    """exp of the rotation vector w (Rodrigues)."""
    w = np.asarray(w, float)
    t = np.linalg.norm(w)
    k = np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]]) / t
    return np.eye(3) + math.sin(t) * k + (1 - math.cos(t)) * k @ k


SKEW = rotation([0.3, -0.8, 0.5])


def cantilever(ops, n, q, force, moment, ea=1.0e6, tol=1e-12, max_iter=30):
    """n elements along q e_x, bending in the plane of q e_x and q e_z; Newton with
    NormDispIncr, whose round-off floor (~1e-15) does not grow with EA as the unbalance's does."""
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    for i in range(n + 1):
        ops.node(i + 1, *(q @ [L * i / n, 0.0, 0.0]))
    ops.fix(1, 1, 1, 1, 1, 1, 1)
    ops.geomTransf("Corotational", 1, *(q @ [0.0, 0.0, 1.0]))
    for i in range(1, n + 1):
        ops.element("elasticBeamColumn", i, i, i + 1, ea, 1.0, 1.0, 1.0, EI, EI, 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(n + 1, *(q @ force), *(q @ moment))
    ops.constraints("Plain")
    ops.numberer("RCM")
    ops.system("UmfPack")
    ops.test("NormDispIncr", tol, max_iter)
    ops.algorithm("Newton")


def tip(ops, n, q):
    """Tip position and rotation dofs in the cantilever's own axes."""
    u = np.array(ops.nodeDisp(n + 1))
    return q.T @ (q @ [L, 0.0, 0.0] + u[:3]), q.T @ u[3:]


def elastica_tip_load(P, steps=500):
    """Tip (x, deflection, slope) of theta'' = -P cos theta, theta(0) = 0, theta'(1) = 0 (L = EI = 1),
    by shooting on theta'(0) = P x_tip in (0, P] with RK4 (error ~ 1e-12 at 500 steps)."""

    def shoot(kappa0):
        def rhs(theta, kappa):
            c, s = math.cos(theta), math.sin(theta)
            return kappa, -P * c, c, s

        theta, kappa, x, z, h = 0.0, kappa0, 0.0, 0.0, 1.0 / steps
        for _ in range(steps):
            a = rhs(theta, kappa)
            b = rhs(theta + 0.5 * h * a[0], kappa + 0.5 * h * a[1])
            c = rhs(theta + 0.5 * h * b[0], kappa + 0.5 * h * b[1])
            d = rhs(theta + h * c[0], kappa + h * c[1])
            theta, kappa, x, z = (
                v + h / 6.0 * (ka + 2 * kb + 2 * kc + kd)
                for v, ka, kb, kc, kd in zip((theta, kappa, x, z), a, b, c, d)
            )
        return theta, kappa, x, z

    lo, hi = 0.0, P
    for _ in range(55):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if shoot(mid)[1] < 0.0 else (lo, mid)
    theta, _, x, z = shoot(0.5 * (lo + hi))
    return x, z, theta


def test_shooting_reference_reproduces_the_bisshopp_drucker_table():
    for P, (shortening, deflection) in BISSHOPP_DRUCKER.items():
        x, z, _ = elastica_tip_load(P)
        assert 1.0 - x == pytest.approx(shortening, abs=6e-6)  # the table's rounding
        assert z == pytest.approx(deflection, abs=6e-6)


@pytest.mark.parametrize("q", [np.eye(3), SKEW], ids=["aligned", "skew"])
def test_end_moment_rolls_the_cantilever_into_a_full_circle(ops, q):
    n, steps = 20, 8
    h = L / n
    cantilever(ops, n, q, [0.0, 0.0, 0.0], [0.0, -2.0 * math.pi * EI / L, 0.0])  # about -y: tip goes to +z
    ops.integrator("LoadControl", 1.0 / steps)
    ops.analysis("Static")
    for step in range(1, steps + 1):
        assert ops.analyze(1) == 0
        t = 2.0 * math.pi * step / steps
        x, theta = tip(ops, n, q)
        r_h = h / (2.0 * math.sin(0.5 * t * h / L))
        np.testing.assert_allclose(x, [r_h * math.sin(t), 0.0, r_h * (1 - math.cos(t))], rtol=0, atol=1e-12)
        r = EI / (t * EI / L)
        circle = np.array([r * math.sin(t), 0.0, r * (1 - math.cos(t))])
        gap = np.linalg.norm(x - circle)
        assert gap <= 1.01 * r * (t * h) ** 2 / 24.0 * math.hypot(math.sin(t), 1 - math.cos(t)) + 1e-12
        assert theta[1] == pytest.approx(-t, abs=1e-12)
    x, _ = tip(ops, n, q)
    assert np.linalg.norm(x) < 1e-12  # back at the clamp


def test_end_moment_error_falls_as_one_over_n_squared(ops):
    """Half circle: tip at (0, 2R); the error is 2R (pi h)^2 / 24 to 1 %."""
    errors = []
    for n in (10, 20, 40):
        ops.wipe()
        cantilever(ops, n, np.eye(3), [0.0, 0.0, 0.0], [0.0, -math.pi, 0.0])
        ops.integrator("LoadControl", 0.25)
        ops.analysis("Static")
        assert ops.analyze(4) == 0
        x, _ = tip(ops, n, np.eye(3))
        error = math.hypot(x[0], x[2] - 2.0 / math.pi)
        assert error == pytest.approx(2.0 / math.pi * (math.pi / n) ** 2 / 24.0, rel=0.01)
        errors.append(error)
    assert errors[0] / errors[1] == pytest.approx(4.0, abs=0.05)
    assert errors[1] / errors[2] == pytest.approx(4.0, abs=0.05)


def test_tip_load_matches_the_elastica(ops):
    """20 elements, skew in space, EA = 1e6 EI/L^2: tip within 5e-4 L (x, deflection) and
    5e-4 rad (slope) of the elastica up to P L^2/EI = 10 (measured 4.5e-5, 2.9e-4, 3.8e-4)."""
    n = 20
    cantilever(ops, n, SKEW, [0.0, 0.0, -EI / L**2], [0.0, 0.0, 0.0])
    applied = 0.0
    for P in BISSHOPP_DRUCKER:
        ops.integrator("LoadControl", (P - applied) / 4.0)
        ops.analysis("Static")
        assert ops.analyze(4) == 0
        applied = P
        x, theta = tip(ops, n, SKEW)
        ex, ez, eslope = elastica_tip_load(P)
        assert x[0] == pytest.approx(ex, abs=5e-4)
        assert -x[2] == pytest.approx(ez, abs=5e-4)
        assert theta[1] == pytest.approx(eslope, abs=5e-4)
        assert abs(x[1]) < 1e-12


def test_newton_converges_quadratically(ops):
    """From a converged state near the half circle (end moment plus a lateral and an axial
    tip force), small load steps: the displacement increments obey e_{k+1} <= 1e3 e_k^2 at
    every iteration above the round-off floor and reach 1e-13 within 6 iterations. The
    constant alternates between small and large values as stiff axial and soft bending modes
    pass the error back and forth; a linearly convergent iteration would have
    e_{k+1}/e_k^2 ~ 1/e_k."""
    n = 20
    cantilever(ops, n, SKEW, [0.2, 0.5, 0.0], [0.3, -math.pi, 0.0], ea=1.0e4)
    ops.integrator("LoadControl", 0.125)
    ops.analysis("Static")
    assert ops.analyze(8) == 0
    for step in (0.02, 0.05):
        ops.test("NormDispIncr", 1e-13, 6)
        ops.integrator("LoadControl", step)
        assert ops.analyze(1) == 0
        e = ops.testNorm()
        assert e[0] > 1e-2
        pairs = [(a, b) for a, b in zip(e, e[1:]) if a <= 1e-2 and b >= 1e-13]
        assert len(pairs) >= 2, e
        assert all(b <= 1e3 * a * a for a, b in pairs), e


def test_failed_step_leaves_the_state_exact(ops):
    def run(fail):
        ops.wipe()
        cantilever(ops, 10, SKEW, [0.0, 1.0, -3.0], [0.0, -2.0, 1.0])
        ops.integrator("LoadControl", 0.25)
        ops.analysis("Static")
        assert ops.analyze(2) == 0
        if fail:
            before = [ops.eleResponse(e, "basicDeformation") for e in range(1, 11)]
            disp = ops.nodeDisp(11)
            ops.test("NormDispIncr", 1e-12, 1)
            ops.integrator("LoadControl", 1.0)
            assert ops.analyze(1) < 0
            assert ops.nodeDisp(11) == disp
            assert [ops.eleResponse(e, "basicDeformation") for e in range(1, 11)] == before
            ops.test("NormDispIncr", 1e-12, 30)
            ops.integrator("LoadControl", 0.25)
        assert ops.analyze(2) == 0
        return ops.nodeDisp(11) + [f for e in range(1, 11) for f in ops.eleResponse(e, "force")]

    assert run(False) == run(True)


def test_corotational_command_errors(ops):
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    with pytest.raises(beamsolid.OpenSeesError, match=r"geomTransf Corotational 1: .*vecxzY"):
        ops.geomTransf("Corotational", 1, 0.0)
    with pytest.raises(beamsolid.OpenSeesError, match="-jntOffset needs 6 numbers"):
        ops.geomTransf("Corotational", 2, 0.0, 0.0, 1.0, "-jntOffset", 1.0, 2.0)
    ops.node(1, 0.0, 0.0, 0.0)
    ops.node(2, 0.0, 0.0, 2.0)
    ops.geomTransf("Corotational", 3, 0.0, 0.0, 1.0)
    with pytest.raises(beamsolid.OpenSeesError, match="geomTransf Corotational 3: vecxz .* is parallel"):
        ops.element("elasticBeamColumn", 1, 1, 2, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 3)

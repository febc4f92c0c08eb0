"""The force-based element's state determination against an independent reimplementation.

forceBeamColumn follows OpenSees' element iterations (elements/ForceBeamCompatibility.h):
q runs one correction ahead of the sections when the element stops, the
stopping rule is |dv . dq| < tol after the sections moved, the first attempt
moves the sections with their tangent flexibility and the second (from the
same start, 10 maxIter iterations) with their initial one. The sections here
are Aggregators of an elastic axial material and a bilinear (Steel01) moment-
curvature law, so every state is exact in floating point and the element's
answer can be recomputed in a few lines of NumPy (below, written from the
algorithm, not from BeamSolid's code). Imposed end rotations from rest, with
few or many element iterations, tolerances that stop it after one iteration
or at convergence, and a second step that unloads.
"""
import numpy as np
import pytest

import beamsolid.opensees as ops

EA, EI, MY, HARD = 1000.0, 1000.0, 10.0, 0.1
L = 100.0


class Bilinear:
    """Steel01 without isotropic hardening, from its committed state."""

    def __init__(self):
        self.ec = self.sc = 0.0
        self.kc = EI
        self.set(0.0)

    def set(self, e):
        self.e = e
        if abs(e - self.ec) < 2.220446049250313e-16:
            self.s, self.k = self.sc, self.kc
            return
        trial = self.sc + EI * (e - self.ec)
        upper = HARD * EI * e + MY * (1 - HARD)
        lower = HARD * EI * e - MY * (1 - HARD)
        if trial > upper:
            self.s, self.k = upper, HARD * EI
        elif trial < lower:
            self.s, self.k = lower, HARD * EI
        else:
            self.s, self.k = trial, EI

    def commit(self):
        self.ec, self.sc, self.kc = self.e, self.s, self.k


class Section:
    def __init__(self):
        self.m = Bilinear()
        self.e = np.zeros(2)

    def set(self, e):
        self.e = np.array(e, float)
        self.m.set(self.e[1])

    @property
    def s(self):
        return np.array([EA * self.e[0], self.m.s])

    @property
    def f(self):
        return np.diag([1.0 / EA, 1.0 / self.m.k])


class Reference:
    """OpenSees' iterations as observed, for a cantilever's basic system."""

    def __init__(self, xi, w):
        self.xi, self.wl = xi, [x * L for x in w]
        self.b = [np.array([[1.0, 0, 0], [0, x - 1, x]]) for x in xi]
        self.f0 = np.diag([1.0 / EA, 1.0 / EI])
        self.secs = [Section() for _ in xi]
        self.K = np.linalg.inv(sum(wl * b.T @ self.f0 @ b for wl, b in zip(self.wl, self.b)))
        self.q = np.zeros(3)
        self.v = np.zeros(3)

    def attempt(self, v, dq, max_iter, tol, initial):
        for _ in range(max_iter):
            self.q = self.q + dq
            for b, s in zip(self.b, self.secs):
                f = self.f0 if initial else s.f
                s.set(s.e + f @ (b @ self.q - s.s))
            F = sum(wl * b.T @ s.f @ b for wl, b, s in zip(self.wl, self.b, self.secs))
            vr = sum(wl * b.T @ (s.e + s.f @ (b @ self.q - s.s)) for wl, b, s in zip(self.wl, self.b, self.secs))
            self.K = np.linalg.inv(F)
            dq = self.K @ (v - vr)
            if abs((v - vr) @ dq) < tol:
                self.q = self.q + dq
                return True
        return False

    def update(self, v, max_iter, tol):
        start = (self.q.copy(), self.K.copy(), [s.e.copy() for s in self.secs])
        dq = start[1] @ (v - self.v)
        ok = self.attempt(v, dq, max_iter, tol, False)
        if not ok:
            self.q, self.K = start[0].copy(), start[1].copy()
            for s, e in zip(self.secs, start[2]):
                s.set(e)
            ok = self.attempt(v, dq, 10 * max_iter, tol, True)
        self.v = v
        for s in self.secs:
            s.m.commit()
        return ok


def lobatto(n):
    if n == 3:
        return [0.0, 0.5, 1.0], [1 / 6, 4 / 6, 1 / 6]
    a = 0.5 - 0.5 / 5 ** 0.5
    return [0.0, a, 1 - a, 1.0], [1 / 12, 5 / 12, 5 / 12, 1 / 12]


def run_beamsolid(nip, max_iter, tol, rotations):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    ops.node(1, 0.0, 0.0)
    ops.node(2, L, 0.0)
    ops.node(3, 0.0, 50.0)
    ops.fix(1, 1, 1, 1)
    ops.fix(3, 0, 1, 1)
    ops.uniaxialMaterial("Elastic", 9, 1.0)
    ops.uniaxialMaterial("Elastic", 1, EA)
    ops.uniaxialMaterial("Steel01", 2, MY, EI, HARD)
    ops.section("Aggregator", 1, 1, "P", 2, "Mz")
    ops.geomTransf("Linear", 1)
    ops.beamIntegration("Lobatto", 1, 1, nip)
    ops.element("forceBeamColumn", 1, 1, 2, 1, 1, "-iter", max_iter, tol)
    ops.element("zeroLength", 2, 1, 3, "-mat", 9, "-dir", 1)
    ops.constraints("Transformation")
    ops.numberer("Plain")
    ops.system("FullGeneral")
    ops.test("FixedNumIter", 1)
    ops.algorithm("Linear")
    ops.integrator("LoadControl", 1.0)
    ops.analysis("Static")
    states = []
    for k, (ri, rj) in enumerate(rotations):
        if k:
            ops.remove("loadPattern", 10 + k - 1)
        ops.timeSeries("Constant", 10 + k)
        ops.pattern("Plain", 10 + k, 10 + k)
        # A cantilever tip moved by uy and turned by rz: theta_i = -uy/L, theta_j = rz - uy/L.
        ops.sp(2, 1, 0.0)
        ops.sp(2, 2, -ri * L)
        ops.sp(2, 3, rj - ri)
        assert ops.analyze(1) == 0
        q = np.array(ops.eleResponse(1, "basicForce"))
        e = np.array([ops.eleResponse(1, "section", i, "deformation") for i in range(1, nip + 1)])
        states.append((q, e))
    ops.wipe()
    return states


CASES = [
    # (integration points, maxIter, tol, steps of (theta_i, theta_j))
    (3, 1, 1e10, [(0.0, 1.07)]),   # stops after one iteration: q one correction ahead
    (3, 1, 10.0, [(0.0, 1.07)]),   # first attempt fails: initial-flexibility attempt
    (3, 2, 1e-12, [(0.0, 1.07)]),
    (3, 10, 1e-12, [(0.0, 1.07)]),
    (4, 1, 1e-12, [(0.0, 1.07), (0.0, 2.5), (0.0, -1.3), (-0.003, -0.203)]),
    (4, 10, 1e-12, [(0.0, 1.07), (0.0, 2.5), (0.0, -1.3), (-0.003, -0.203)]),
]


@pytest.mark.parametrize("nip,max_iter,tol,steps", CASES)
def test_force_beam_follows_the_reference_iterations(nip, max_iter, tol, steps):
    got = run_beamsolid(nip, max_iter, tol, steps)
    ref = Reference(*lobatto(nip))
    for k, ((ri, rj), (q, e)) in enumerate(zip(steps, got)):
        ref.update(np.array([0.0, ri, rj]), max_iter, tol)
        scale = max(1.0, np.abs(ref.q).max())
        assert np.abs(q - ref.q).max() < 1e-11 * scale, (k, q, ref.q)
        want = np.array([s.e for s in ref.secs])
        assert np.abs(e - want).max() < 1e-11 * np.abs(want).max(), (k, e, want)


def test_one_iteration_leaves_sections_behind_q():
    """tol large enough to stop at the first check: q has taken the second
    correction, the sections only the elastic predictor (hand-checkable: the
    predictor's curvatures are b K0 v / EI)."""
    (q, e), = run_beamsolid(3, 1, 1e10, [(0.0, 1.07)])
    K0 = np.array([[4.0, 2.0], [2.0, 4.0]]) * EI / L
    q1 = K0 @ np.array([0.0, 1.07])
    assert np.allclose(e[:, 1], [-q1[0] / EI, 0.5 * (q1[1] - q1[0]) / EI, q1[1] / EI], rtol=1e-13)
    assert not np.allclose(q[1:], q1)

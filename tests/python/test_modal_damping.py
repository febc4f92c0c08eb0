"""modalDamping and region Rayleigh damping against closed forms.

A two-mass chain (1D: fixed node 1, springs k between 1-2 and 2-3, masses m
at 2 and 3): w^2 = (k/m)(3 -+ sqrt 5)/2, mode shapes (1, (1+-sqrt 5)/2).
Released from rest in one mode shape, a classically damped system stays in
that mode and decays by exp(-zeta w t): the logarithmic decrement per cycle
is 2 pi zeta / sqrt(1 - zeta^2). Newmark average acceleration adds no
numerical damping, and with 400 steps a period the measured ratio is
within 1% of the one given (measured: < 0.1%).
"""
import math

import pytest

import beamsolid.opensees as ops

K, M = 1000.0, 1.0


def _free_vibration(mode, damping, periods=6.0, steps_per_period=400):
    """Displacements of node 3 after a release in mode `mode` (1 or 2)."""
    ops.wipe()
    ops.model("basic", "-ndm", 1, "-ndf", 1)
    for n in (1, 2, 3):
        ops.node(n, 0.0)
    ops.fix(1, 1)
    ops.mass(2, M)
    ops.mass(3, M)
    ops.uniaxialMaterial("Elastic", 1, K)
    ops.element("zeroLength", 1, 1, 2, "-mat", 1, "-dir", 1)
    ops.element("zeroLength", 2, 2, 3, "-mat", 1, "-dir", 1)
    root5 = math.sqrt(5.0)
    shape = (1.0, (1.0 + root5) / 2.0) if mode == 1 else (1.0, (1.0 - root5) / 2.0)
    omega2 = (K / M) * ((3.0 - root5) / 2.0 if mode == 1 else (3.0 + root5) / 2.0)
    # The static load K phi = omega^2 M phi holds the chain in the mode shape.
    ops.timeSeries("Constant", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, omega2 * M * shape[0] * 1e-3)
    ops.load(3, omega2 * M * shape[1] * 1e-3)
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.system("FullGeneral")
    ops.test("NormDispIncr", 1e-14, 50)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", 1.0)
    ops.analysis("Static")
    assert ops.analyze(1) == 0
    ops.remove("loadPattern", 1)
    ops.wipeAnalysis()
    lambdas = ops.eigen(2)
    damping()
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.system("FullGeneral")
    ops.test("NormDispIncr", 1e-14, 50)
    ops.algorithm("Newton")
    ops.integrator("Newmark", 0.5, 0.25)
    ops.analysis("Transient")
    period = 2.0 * math.pi / math.sqrt(omega2)
    rows = []
    for _ in range(int(periods * steps_per_period)):
        assert ops.analyze(1, period / steps_per_period) == 0
        rows.append((ops.nodeDisp(2, 1), ops.nodeDisp(3, 1)))
    ops.wipe()
    return lambdas, omega2, shape, rows


def _decay_ratio(values):
    """Damping ratio from the first and last positive peaks."""
    peaks = [values[i] for i in range(1, len(values) - 1) if values[i - 1] < values[i] >= values[i + 1] and values[i] > 0]
    delta = math.log(peaks[0] / peaks[-1]) / (len(peaks) - 1)
    return delta / math.sqrt(4.0 * math.pi**2 + delta**2)


@pytest.mark.parametrize("mode, factors, zeta", [
    (1, (0.05,), 0.05), (2, (0.05,), 0.05), (1, (0.02, 0.08), 0.02), (2, (0.02, 0.08), 0.08)])
def test_modal_damping_decays_each_mode_by_its_ratio(mode, factors, zeta):
    lambdas, omega2, shape, rows = _free_vibration(mode, lambda: ops.modalDamping(*factors))
    assert sorted(lambdas)[mode - 1] == pytest.approx(omega2, rel=1e-10)
    assert _decay_ratio([r[1] for r in rows]) == pytest.approx(zeta, rel=0.01)
    # Classical damping: the motion stays in the mode shape.
    for u2, u3 in rows:
        assert u3 == pytest.approx(u2 * shape[1] / shape[0], abs=1e-9 * 1e-3)


def test_region_rayleigh_on_the_masses_decays_by_alpha_over_two_omega():
    # alphaM only, on both nodes through a region of nodes: zeta = alphaM / (2 omega).
    alpha = 2.0
    lambdas, omega2, shape, rows = _free_vibration(1, lambda: ops.region(1, "-nodeOnly", 2, 3, "-rayleigh", alpha, 0.0, 0.0, 0.0))
    assert _decay_ratio([r[1] for r in rows]) == pytest.approx(alpha / (2.0 * math.sqrt(omega2)), rel=0.01)
    # The same region of the springs alone (no element mass, no stiffness factor) damps nothing.
    _, _, _, undamped = _free_vibration(1, lambda: ops.region(1, "-eleOnly", 1, 2, "-rayleigh", alpha, 0.0, 0.0, 0.0))
    assert _decay_ratio([r[1] for r in undamped]) == pytest.approx(0.0, abs=1e-6)

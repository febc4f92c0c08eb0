"""The Winkler model of the lateral pile (beamsolid.scenes.winkler_pile).

Checks:
* the finite-beam closed form: a long beam (lambda L = 20) reproduces Hetenyi's
  semi-infinite y(0) = 2 H lambda / k and M_max = H/lambda e^(-pi/4) sin(pi/4)
  (= 0.3224 H / lambda) at lambda x = pi/4 to 1e-10; the pile's own beam
  (lambda L = 4.06) is in equilibrium: integral k y dx = H and integral k y x dx = 0
  (no head moment) by trapezoidal quadrature on 20001 points, 1e-7 of H and H L;
* the beam-on-springs model (springs lumped at the nodes) converges to it at second
  order: the head deflection and moment errors fall by 4 +- 0.4 per halving of h,
  and the finest mesh (160 elements) is within 1e-3 of the closed form (deflection
  and moments at the nodes, relative to the head deflection / largest moment);
* the springs balance the head load to 1e-10 (force and moment about the head);
* head displacement control gives the same compliance as force control (1e-10);
* randolph_k reproduces Randolph's head compliance exactly in the closed form
  (1e-10) and within the discretization error (1e-3) in the model; for a very long
  pile it is the semi-infinite match k = (2 / ((u/H) (4 EI)^(1/4)))^(4/3) (1e-10).
"""
import dataclasses
import math

import numpy as np
import pytest

from beamsolid.scenes.lateral_pile import LateralPile
from beamsolid.scenes.winkler_pile import (bending_stiffness, characteristic, randolph_k, run_winkler,
                                           semi_infinite_head, vesic_k, winkler_closed_form)

PILE = LateralPile()
EI = bending_stiffness(PILE)
H = 100.0


def test_closed_form_long_beam_is_hetenyis_semi_infinite_beam():
    k = vesic_k(PILE)
    lam = characteristic(EI, k)
    L = 20.0 / lam
    x_max = math.pi / (4.0 * lam)
    y, dy, M = winkler_closed_form(EI, k, L, H, [0.0, x_max, 0.999 * x_max, 1.001 * x_max])
    y0, m_max, depth = semi_infinite_head(EI, k, H)
    assert depth == pytest.approx(x_max, rel=1e-15)
    assert y[0] == pytest.approx(y0, rel=1e-10)
    exact_m_max = H / lam * math.exp(-math.pi / 4.0) * math.sin(math.pi / 4.0)
    assert M[1] == pytest.approx(exact_m_max, rel=1e-10)
    assert m_max == pytest.approx(exact_m_max, rel=1e-4)  # Hetenyi's rounded 0.3224
    assert M[1] > M[2] and M[1] > M[3]
    assert dy[0] == pytest.approx(-2.0 * H * lam**2 / k, rel=1e-10)  # y' = -(2 H lam^2 / k) at the head
    assert abs(M[0]) < 1e-10 * exact_m_max


def test_closed_form_of_the_pile_is_in_equilibrium():
    k = vesic_k(PILE)
    L = PILE.length
    x = np.linspace(0.0, L, 20001)
    y, _, M = winkler_closed_form(EI, k, L, H, x)
    dx = x[1] - x[0]
    trapz = lambda f: dx * (f.sum() - 0.5 * (f[0] + f[-1]))  # noqa: E731
    assert trapz(k * y) == pytest.approx(H, abs=1e-7 * H)
    assert abs(trapz(k * y * x)) < 1e-7 * H * L
    assert abs(M[0]) < 1e-9 * H * L and abs(M[-1]) < 1e-9 * H * L


def _errors(n, k):
    r = run_winkler(PILE, n, k=k, head_force=H)
    y, _, M = winkler_closed_form(EI, k, PILE.length, H, r.depths)
    head = abs(r.head_disp - y[0]) / abs(y[0])
    profile = np.max(np.abs(np.array(r.deflection) - y)) / abs(y[0])
    moment = np.max(np.abs(np.array(r.moment) - M)) / np.max(np.abs(M))
    return r, head, profile, moment


def test_beam_on_springs_converges_at_second_order_to_the_closed_form():
    k = vesic_k(PILE)
    results = [_errors(n, k) for n in (10, 20, 40, 80, 160)]
    for (_, h1, p1, m1), (_, h2, p2, m2) in zip(results, results[1:]):
        assert 3.6 < h1 / h2 < 4.4, (h1, h2)
        assert 3.6 < m1 / m2 < 4.4, (m1, m2)
        assert 3.6 < p1 / p2 < 4.4, (p1, p2)
    r, head, profile, moment = results[-1]
    assert head < 1e-3 and profile < 1e-3 and moment < 1e-3, (head, profile, moment)
    # The largest moment lies near lambda x = pi/4 (the pile is nearly semi-infinite).
    lam = characteristic(EI, k)
    assert abs(r.depths[int(np.argmax(r.moment))] - math.pi / (4.0 * lam)) < 2.0 * PILE.length / 160
    assert r.equations == 6 * 161 - 2  # beam nodes with ndf 6, the tip's axial and torsion fixed


def test_springs_balance_the_head_load():
    k = vesic_k(PILE)
    n = 20
    r = run_winkler(PILE, n, k=k, head_force=H)
    h = PILE.length / n
    trib = np.full(n + 1, h)
    trib[0] = trib[-1] = 0.5 * h
    spring = k * trib * np.array(r.deflection)
    assert spring.sum() == pytest.approx(H, abs=1e-10 * H)
    assert abs((spring * np.array(r.depths)).sum()) < 1e-10 * H * PILE.length
    assert abs(r.moment[0]) < 1e-10 * H * PILE.length


def test_displacement_control_matches_force_control():
    by_force = run_winkler(PILE, 16, head_force=H)
    by_disp = run_winkler(PILE, 16)  # the problem's head displacement
    assert by_disp.head_disp == pytest.approx(PILE.head_disp, rel=1e-12)
    assert by_disp.compliance == pytest.approx(by_force.compliance, rel=1e-10)
    assert by_disp.head_force == pytest.approx(PILE.head_disp / by_force.compliance, rel=1e-10)
    with pytest.raises(ValueError, match="head_force or head_disp"):
        run_winkler(PILE, 4, head_force=1.0, head_disp=0.01)
    with pytest.raises(ValueError, match="k must be positive"):
        run_winkler(PILE, 4, k=-1.0)


def test_randolph_k_reproduces_randolphs_compliance():
    k = randolph_k(PILE)
    y, _, _ = winkler_closed_form(EI, k, PILE.length, 1.0, [0.0])
    assert y[0] == pytest.approx(PILE.randolph_compliance, rel=1e-10)
    r = run_winkler(PILE, 160, k=k, head_force=H)
    assert r.compliance == pytest.approx(PILE.randolph_compliance, rel=1e-3)
    # A very long pile: the finite-length match becomes the semi-infinite one.
    long_pile = dataclasses.replace(PILE, length=200.0)
    c = long_pile.randolph_compliance
    semi = (2.0 / (c * (4.0 * EI) ** 0.25)) ** (4.0 / 3.0)
    assert randolph_k(long_pile) == pytest.approx(semi, rel=1e-10)
    # Randolph's elastic continuum is stiffer than Vesic's surface-beam k for this pile.
    assert k > vesic_k(PILE)

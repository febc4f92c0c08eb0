"""Lateral capacity in yielding clay (issue 18).

Randolph and Houlsby (1984): a rigid cylinder moved laterally through weightless von Mises clay
(plane strain) reaches P / (s_u D) = 6 + pi = 9.142 with a smooth interface and
2 pi + 4 sqrt(2) = 11.940 with a fully rough one, with the soil in contact all around it. The
slice (scenes/capacity_slice.py) is one layer of bbarBricks with the pile a beam joined by
BeamContact3D; benchmarks/results/lateral_capacity_slice.md has the mesh refinement.

The lateral capacity scene (scenes/lateral_capacity.py) at its coarse level: Newton's rate while
the soil yields, equilibrium of the pile, and the capacities against Broms' (1964) closed form.
"""
import math

import numpy as np
import pytest

from beamsolid.scenes import capacity_slice as cs
from beamsolid.scenes import lateral_capacity as lc


# --- Randolph and Houlsby ---------------------------------------------------------------

def test_closed_forms():
    # N_p = pi + 2 D + 2 cos D + 4 (cos D/2 + sin D/2), D = asin(alpha): alpha = 0 and 1.
    for alpha, key in ((0.0, "smooth"), (1.0, "rough")):
        d = math.asin(alpha)
        assert cs.RANDOLPH_HOULSBY[key] == pytest.approx(
            math.pi + 2 * d + 2 * math.cos(d) + 4 * (math.cos(d / 2) + math.sin(d / 2)), rel=1e-15)
    assert cs.RANDOLPH_HOULSBY["smooth"] == pytest.approx(9.142, abs=5e-4)
    assert cs.RANDOLPH_HOULSBY["rough"] == pytest.approx(11.940, abs=5e-4)


@pytest.mark.parametrize("interface", ["smooth", "rough"])
def test_rigid_cylinder_reaches_the_randolph_houlsby_pressure(interface):
    # Measured (medium: 24 x 12 bbarBricks, contacts in tension): 9.337 (+2.1 %), 12.160 (+1.8 %);
    # the refinement descends towards the closed form from above (the benchmark).
    r = cs.run(cs.Slice(level="medium", interface=interface))
    assert r.converged
    assert abs(r.error) < 0.05, (r.limit, r.problem.closed_form)
    assert r.error > 0.0  # a displacement model of the soil: from above at this level
    # A plateau: the last step (0.03 % of D) added less than 1e-4 of the load.
    assert abs(r.pressure[-1] - r.pressure[-2]) < 1e-4 * r.pressure[-1]
    # The rise is elastic first: half the limit is reached before 1e-3 D.
    assert r.pressure[1] > 0.4 * r.limit
    # No gap: no contact opened at any step; the back of the pile carries tension instead.
    assert max(r.n_open) == 0
    assert min(r.min_normal) < 0.0
    # The interface slides all around in the limit state (mu = 0: nothing holds a node).
    if interface == "smooth":
        assert r.n_sliding[-1] == r.n_contacts


def test_confined_cylinder_keeps_every_contact_in_compression():
    # The other way to keep the gap shut: a confining pressure p0 = 10 s_u first. A stiff soil
    # reaches the limit at u ~ 2e-4 D, before the contact normals turn enough to matter.
    # Measured: 12.150 (+1.76 %), against 12.160 with tensile contacts.
    r = cs.run(cs.Slice(level="coarse", interface="rough", no_gap="confine", G_over_su=5e4, push=3e-4))
    tension = cs.run(cs.Slice(level="coarse", interface="rough"))
    assert r.converged
    assert max(r.n_open) == 0
    assert min(r.min_normal) > 0.0  # every contact stays in compression
    assert abs(r.error) < 0.05
    assert r.limit == pytest.approx(tension.limit, rel=2e-3)


def test_bad_slice_arguments():
    with pytest.raises(ValueError, match="interface"):
        cs.Slice(interface="sticky")
    with pytest.raises(ValueError, match="no_gap"):
        cs.Slice(no_gap="glue")
    with pytest.raises(ValueError, match="level"):
        cs.Slice(level="huge")


# --- Broms ----------------------------------------------------------------------------

def test_broms_short_pile_by_hand():
    p = lc.ClayPile()
    b = lc.broms(p)
    D, su, L = p.diameter, p.su, p.length
    # Both equations of the mechanism hold at the solution.
    f = b.H_short / (9 * su * D)
    assert b.f == pytest.approx(f, rel=1e-12)
    assert b.M_short == pytest.approx(b.H_short * (1.5 * D + f / 2), rel=1e-12)
    assert b.M_short == pytest.approx(2.25 * D * su * (L - 1.5 * D - f) ** 2, rel=1e-12)
    # The same by bisection on H (independent of the quadratic): 418.557 kN, 806.418 kNm.
    def mismatch(H):
        fh = H / (9 * su * D)
        return H * (1.5 * D + fh / 2) - 2.25 * D * su * (L - 1.5 * D - fh) ** 2

    lo, hi = 0.0, 9 * su * D * (L - 1.5 * D)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if mismatch(mid) < 0 else (lo, mid)
    assert b.H_short == pytest.approx(lo, rel=1e-12)
    assert b.H_short == pytest.approx(418.557, abs=1e-3)
    assert b.mode == "short"
    # A weak pile fails by a plastic hinge: H (1.5 D + f / 2) = My with f = H / (9 s_u D).
    weak = lc.broms(p, My=300.0)
    assert weak.mode == "long"
    fl = weak.H_long / (9 * su * D)
    assert weak.H_long * (1.5 * D + fl / 2) == pytest.approx(300.0, rel=1e-12)
    assert weak.H == weak.H_long < b.H_short


# --- the lateral capacity scene (coarse level) ---------------------------------------------

def _yielded(model):
    """Sum of the soil's mean equivalent plastic strains (each brick's Gauss points)."""
    m = model.m
    return sum(sum(m.eleResponse(e, "equivalentPlasticStrains")) for e in model.mesh.elements)


@pytest.fixture(scope="module")
def rough():
    """The coarse rough contact model pushed to 0.1 D in 8 steps (8 of the scene's 16), with the
    soil's plastic strain recorded after every step, solved by plain Newton (the scene's line
    search takes full Newton steps near the solution, but its shortened ones in between would
    blur the measured order). About 10 s of CPU."""
    plastic = []
    problem = lc.ClayPile(head_disp=0.1 * lc.ClayPile().diameter)
    r = lc.run_contact(problem, lc.Numerics(level="coarse", steps=8, algorithm="Newton"), "rough",
                       on_step=lambda model, result: plastic.append(_yielded(model)))
    return r, plastic, problem


def convergence_order(norms, floor=1e-10):
    """Order from the last norms above the round-off floor: log(e3/e2) / log(e2/e1) for the last
    three, or for the three before them when that is larger. One three-point estimate assumes the
    same constant in e_k+1 = C e_k^p over both pairs; a pre-asymptotic jump in the first pair
    spoils it (measured: 5.6e-2, 1.2e-5, 3.2e-10 reads 1.25 though e3 = 2.2 e2^2, while the
    triple before reads 2.46). A linear or superlinear rate reads below 1.8 in both."""
    e = [x for x in norms if x > floor]
    assert len(e) >= 3, norms
    t = e[-4:]
    return max(math.log(c / b) / math.log(b / a) for a, b, c in zip(t, t[1:], t[2:]))


def test_newton_stays_quadratic_while_the_soil_yields(rough):
    r, plastic, _ = rough
    assert r.converged
    # The plastic zone grows at every step (J2 yields from the first step on).
    assert plastic[0] > 0.0
    assert all(b > a for a, b in zip(plastic, plastic[1:])), plastic
    # Measured orders of the 9 steps: 2.46, 2.19, 2.11, 2.22, 2.18, 2.22, 2.20, 2.29, 3.13 (the first step was
    # halved once: its 16th-of-the-way attempt diverged).
    orders = [convergence_order(n) for n in r.norms[1:]]
    assert all(p >= 1.8 for p in orders), orders
    # A step in the middle of the push, the plastic strain growing by a third in it.
    k = len(plastic) // 2
    assert plastic[k] > 1.2 * plastic[k - 1]
    assert convergence_order(r.norms[k + 1]) >= 1.8


def test_pile_equilibrium_head_load_equals_the_soil_reaction(rough):
    r, _, _ = rough
    # The soil's forces on the pile (summed contact forces on the beam nodes) balance the head
    # load: measured 1e-11 relative (Newton converged to NormDispIncr 1e-8).
    assert r.soil_reaction == pytest.approx(-r.capacity, rel=1e-8)
    # Free head and tip: the beam's end moments are only what the contacts apply to the end nodes
    # (the adhesion's vertical forces at radius R; measured 4.2 kNm at the head, 0.5 % of M_max).
    scale = max(abs(x) for x in r.moment)
    assert r.moment[0] == pytest.approx(r.end_moments[0], abs=1e-9 * scale)
    assert r.moment[-1] == pytest.approx(-r.end_moments[1], abs=1e-9 * scale)
    assert abs(r.moment[0]) < 0.01 * scale


def test_py_model_equilibrium_and_profile():
    r = lc.run_py(lc.ClayPile(), lc.Numerics(level="coarse"))
    assert r.converged
    assert r.soil_reaction == pytest.approx(-r.capacity, rel=1e-8)
    assert abs(r.moment[0]) < 1e-6 * abs(r.max_moment)
    # A short pile: rigid rotation about a point in the lower half (deflection changes sign once).
    signs = [d > 0 for d in r.deflection]
    assert signs[0] and not signs[-1] and sum(a != b for a, b in zip(signs, signs[1:])) == 1


def test_capacities_within_a_band_of_broms(rough):
    # Broms (1964) is a bound-type hand method (no resistance over 1.5 D, 9 s_u D below); the
    # capacities at a head displacement of 0.1 D fall within 30 % of it. Measured (coarse):
    # rough contact 514 kN (1.23), p-y 319 kN (0.76), against Broms' 418.6 kN.
    r, _, problem = rough
    closed = lc.broms(problem)
    D = problem.diameter
    py = lc.run_py(lc.ClayPile(), lc.Numerics(level="coarse"))
    for name, H in (("rough contact", r.force_at(0.1 * D)), ("p-y", py.force_at(0.1 * D))):
        assert 0.7 * closed.H < H < 1.3 * closed.H, (name, H, closed.H)
    # The rough contact carries more than the Matlock springs (which mobilize p_u only at 8 y50,
    # and whose p_u stays below 9 s_u D down to 5.6 m here).
    assert r.force_at(0.1 * D) > py.force_at(0.1 * D)
    # The largest moment: within 30 % of Broms' at that load.
    assert 0.7 * closed.M_short < r.max_moment < 1.3 * closed.M_short


def test_scene_arguments():
    with pytest.raises(ValueError, match="level"):
        lc.Numerics(level="huge")
    with pytest.raises(ValueError, match="algorithm"):
        lc.Numerics(algorithm="KrylovNewton")
    with pytest.raises(ValueError, match="interface"):
        lc.run_contact(lc.ClayPile(), lc.Numerics(), "sticky")
    with pytest.raises(ValueError, match="model"):
        lc.run("winkler")

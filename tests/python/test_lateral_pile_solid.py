"""The brick-meshed pile reference of the accuracy benchmark: statics and extrapolation."""
import math

import pytest

from beamsolid.scenes.lateral_pile import LateralPile
from beamsolid.scenes.lateral_pile_solid import HEAD, SolidNumerics, SolidPileModel, SolidResult, richardson


def test_richardson_recovers_a_known_limit_and_order():
    hs = [0.4, 0.25, 0.15]
    for order in (1.0, 2.0, 1.5):
        v0, p = richardson(hs, [2.0 + 3.0 * h**order for h in hs])
        assert v0 == pytest.approx(2.0, rel=1e-9)
        assert p == pytest.approx(order, rel=1e-6)


@pytest.mark.parametrize("interface", ["tied", "contact"])
def test_pile_free_body_balances_the_head_load(interface):
    """Head load + the soil's action on the pile surface + the pinned base's support = 0 (x),
    the same head force from global equilibrium under an imposed displacement, and the free-body
    moment at the head level is zero (nothing above it but the load)."""
    p = LateralPile()
    H = 300.0
    model = SolidPileModel(p, SolidNumerics(level="coarse", interface=interface, head_load=H, steps=3)).build()
    model.geostatic()
    r = SolidResult()
    model.push(r)
    assert r.converged and r.head_force[-1] == pytest.approx(H, rel=1e-12)
    m = model.m
    forces = model.interface_forces_on_pile()
    m.reactions()
    base = model.base_support()[0]
    soil_x = sum(f[3] for f in forces)
    assert H + soil_x + base == pytest.approx(0.0, abs=1e-7 * H)
    assert model.head_reaction() == pytest.approx(H, rel=1e-7)
    model.profiles(r, H)
    assert r.moment[0] == pytest.approx(0.0, abs=1e-12)
    # The largest moment is of the order of Randolph's 0.1 H lc (a check of scale, not accuracy).
    assert 0.5 < r.max_moment / (0.1 * H * p.critical_length) < 2.5
    # The head moves along +x; the rigid head node follows the mean of the head section.
    assert m.nodeDisp(HEAD, 1) > 0
    assert math.isclose(r.deflection[0], m.nodeDisp(HEAD, 1), rel_tol=0.05)
    if interface == "contact":
        assert r.n_open > 0  # the gap opens behind the pile

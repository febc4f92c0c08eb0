"""Meshing helpers: geometry of the donut and a closed-form check of its volume."""
import math

import pytest

from beamsolid import mesh


def test_graded_spacing():
    pts = mesh.graded(1.0, 5.0, 4, 2.0)
    steps = [b - a for a, b in zip(pts, pts[1:])]
    assert pts[0] == 1.0 and pts[-1] == 5.0
    for a, b in zip(steps, steps[1:]):
        assert b / a == pytest.approx(2.0, rel=1e-12)


def test_donut_nodes_on_the_pile_surface_and_volume(model):
    model.model("basic", "-ndm", 3, "-ndf", 3)
    model.nDMaterial("ElasticIsotropic", 1, 1000.0, 0.3)
    n, ri, ro, h = 12, 0.5, 3.0, 4.0
    m = mesh.donut(model, inner_radius=ri, outer_radius=ro, z_top=0.0, z_bottom=-h,
                   n_theta=n, n_radial=3, n_z=4, body_force=(0.0, 0.0, -1.0))
    assert len(m.elements) == n * 3 * 4
    for tag in m.inner_nodes:
        x, y, _ = model.nodeCoord(tag)
        assert math.hypot(x, y) == pytest.approx(ri, rel=1e-14)
    for tag in m.outer_nodes:
        x, y, _ = model.nodeCoord(tag)
        assert math.hypot(x, y) == pytest.approx(ro, rel=1e-14)
    # Unit body force per volume: the base reactions add up to the volume of
    # the faceted annulus, 0.5 n sin(2 pi / n) (ro^2 - ri^2) h (stdBrick also
    # refuses a non-positive Jacobian, so building proves the orientation).
    model.fixZ(-h, 1, 1, 1)
    for tag in m.nodes.values():
        if tag not in m.base_nodes:
            model.fix(tag, 1, 1, 0)
    model.analysis("Static")
    assert model.analyze(1) == 0
    model.reactions()
    volume = 0.5 * n * math.sin(2 * math.pi / n) * (ro**2 - ri**2) * h
    assert sum(model.nodeReaction(t, 3) for t in m.base_nodes) == pytest.approx(volume, rel=1e-12)

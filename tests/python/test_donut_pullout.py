"""The donut pullout (paper Table 1) on coarse meshes: the gates of examples/donut_pullout.py.

(a) at full sliding the head force equals mu sum(N_i) and the summed friction
    (relative 1e-6);
(b) the geostatic sum of the normal forces equals n R sin(2 pi/n) int sigma_h dz,
    the consistent nodal forces of sigma_h on the inscribed n-gon (relative 1e-8;
    the derivation makes it exact for a uniaxial-strain state);
(c) Q / Qs = facet factor x unloading (relative 1e-6) with the facet factor
    n sin(2 pi/n) / (2 pi) and unloading = sum N at full sliding / geostatic sum N;
    refining the ring moves Q/Qs by the facet factor while the unloading, a
    property of the drag on the soil, changes little.
Plus global equilibrium of the soil (base reactions = weight of the faceted
annulus - head force) and a steady plateau once everything slides.
"""
import math
from dataclasses import replace

import pytest

from beamsolid.scenes.donut_pullout import DonutModel, DonutPullout, run

COARSE = DonutPullout(mu=0.5, n_theta=8, n_radial=2, n_z=5, pull=0.09, steps=30)


@pytest.fixture(scope="module")
def coarse():
    return run(COARSE, extra_after_full_sliding=3)


@pytest.mark.parametrize("n_theta", [6, 8, 12])
def test_geostatic_normal_sum_is_the_faceted_ring_value(n_theta):
    s = replace(COARSE, n_theta=n_theta)
    model = DonutModel(s).build()
    total = model.geostatic()
    exact = n_theta * s.pile_radius * math.sin(2 * math.pi / n_theta) * 0.5 * s.K0 * s.gamma * s.depth**2
    assert total == pytest.approx(exact, rel=1e-8)
    assert total == pytest.approx(s.facet_factor * 2 * math.pi * s.pile_radius * s.sigma_h_integral, rel=1e-12)
    # Every contact of a level carries the same normal force (rotational symmetry),
    # frictionless: no tangential force.
    scalars = model.contact_scalars()
    for level in range(s.n_z + 1):
        ring = scalars[level * n_theta:(level + 1) * n_theta]
        for f in ring:
            assert f[0] == pytest.approx(ring[0][0], rel=1e-9)
            assert abs(f[1]) + abs(f[2]) <= 1e-9 * ring[0][0]
    model.m.wipe()


def test_geostatic_state_is_uniaxial_strain():
    """Self weight with the laterally restrained boundary: no horizontal motion, and
    the soil weight (gamma x the faceted annulus' volume) goes to the base."""
    s = COARSE
    model = DonutModel(s).build()
    model.geostatic()
    m = model.m
    m.reactions()
    for tag in model.mesh.nodes.values():
        assert abs(m.nodeDisp(tag, 1)) < 1e-12 and abs(m.nodeDisp(tag, 2)) < 1e-12
    n = s.n_theta
    volume = 0.5 * n * math.sin(2 * math.pi / n) * (s.outer_radius**2 - s.pile_radius**2) * s.depth
    base = sum(m.nodeReaction(t, 3) for t in model.mesh.base_nodes)
    assert base == pytest.approx(s.gamma * volume, rel=1e-10)
    m.wipe()


def test_full_sliding_head_force_is_mu_times_the_normal_sum(coarse):
    r, s = coarse, coarse.setup
    assert r.failed_step == 0
    assert r.full_sliding is not None
    k = len(r.head_force) - 1
    assert r.sticking[k] == 0 and r.sliding[k] > 0
    assert r.head_force[k] == pytest.approx(s.mu * r.normal_sum[k], rel=1e-6)
    assert r.friction_sum[k] == pytest.approx(s.mu * r.normal_sum[k], rel=1e-6)
    assert r.q_contact == pytest.approx(r.head_force[k], rel=1e-6)
    # Sliding is steady: the step after full sliding changes nothing that matters.
    j = r.full_sliding
    assert r.head_force[k] == pytest.approx(r.head_force[j], rel=1e-3)


def test_steady_sliding_converges_in_one_newton_iteration_per_step(coarse):
    """Once every contact slides, each step starts from the converged state's sliding tangent
    (C16 with gamma = 0) and the problem is linear along the slide: one iteration per step, as
    OpenSeesPy takes on this scene. Before full sliding contacts change from stick to slip and
    need more."""
    r = coarse
    after = r.iterations[r.full_sliding + 1:]
    assert len(after) >= 2 and all(n == 1 for n in after), r.iterations
    assert max(r.iterations[:r.full_sliding + 1]) > 1


def test_pullout_q_over_beta_is_facet_factor_times_unloading(coarse):
    r, s = coarse, coarse.setup
    k = len(r.head_force) - 1
    assert s.facet_factor == pytest.approx(8 * math.sin(math.pi / 4) / (2 * math.pi), rel=1e-15)
    assert r.head_force[k] / s.beta_method == pytest.approx(s.facet_factor * r.unloading, rel=1e-6)
    # The pull unloads the confinement (it drags the soil up, against its weight).
    assert 0.9 < r.unloading < 1.0


def test_soil_base_carries_its_weight_minus_the_pull(coarse):
    """Vertical equilibrium of the soil at full sliding, re-run to query reactions."""
    s = COARSE
    model = DonutModel(s).build()
    model.geostatic()
    model.release()
    r = type(coarse)(setup=s, n_contacts=len(model.contacts))
    model.pull(r, extra_after_full_sliding=0)
    m = model.m
    m.reactions()
    n = s.n_theta
    volume = 0.5 * n * math.sin(2 * math.pi / n) * (s.outer_radius**2 - s.pile_radius**2) * s.depth
    base = sum(m.nodeReaction(t, 3) for t in model.mesh.base_nodes)
    head = m.nodeReaction(model.pile_nodes[0], 3)
    assert base == pytest.approx(s.gamma * volume - head, rel=1e-9)
    m.wipe()


def test_refining_the_ring_removes_the_facet_error_not_the_unloading():
    results = {n: run(replace(COARSE, n_theta=n), extra_after_full_sliding=1) for n in (8, 16)}
    ratio = {}
    for n, r in results.items():
        s = r.setup
        k = len(r.head_force) - 1
        ratio[n] = r.head_force[k] / s.beta_method
        assert ratio[n] == pytest.approx(s.facet_factor * r.unloading, rel=1e-6)
    assert abs(1 - ratio[16]) < abs(1 - ratio[8])
    # Facet error: 9.97% at n = 8, 2.55% at n = 16; the unloading moves by far less.
    assert abs(results[16].unloading - results[8].unloading) < 0.01


@pytest.mark.parametrize("level", ["coarse", "medium"])
def test_default_pull_reaches_full_sliding_on_every_level(level):
    """A node slides once its slip reaches mu N / G. The coarse ring's deepest nodes carry 3.7 times
    the paper ring's normal force, so the paper's pull (0.04 mu + 0.004) left mu = 0.5 and 1 short of
    full sliding there (gate (c) off by 5.5 % and 10 %): Q was not the frictional resistance."""
    from beamsolid.scenes.donut_cli import LEVELS

    n_theta, n_radial, n_z = LEVELS[level]
    for mu in (0.5, 1.0):
        s = DonutPullout(mu=mu, n_theta=n_theta, n_radial=n_radial, n_z=n_z)
        if level == "medium":  # the paper's ring keeps the paper's pull (Table 1 unchanged)
            assert s.head_pull == pytest.approx(0.04 * mu + 0.004, rel=1e-15)
        r = run(s)
        assert r.failed_step == 0
        assert r.full_sliding is not None
        assert r.q_contact == pytest.approx(r.sliding_resistance, rel=1e-8)


def test_scene_records_the_pull_and_its_files_agree(tmp_path):
    """python -m beamsolid.scenes donut_pullout: the head recorders, the PVD series (read with
    meshio) and the returned curves hold the same numbers; every mu reaches gate (c)."""
    import xml.etree.ElementTree as ET

    import meshio
    import numpy as np

    from beamsolid.scenes.__main__ import main
    from beamsolid.scenes.donut_cli import RECORDED_MU, scene

    assert main(["donut_pullout", "--level", "coarse", "--out", str(tmp_path / "cli")]) == 0
    results, files = scene(level="coarse", out=str(tmp_path))
    assert all(f.exists() for f in files)
    for r in results:
        assert r.q_contact == pytest.approx(r.sliding_resistance, rel=1e-8)
    r = next(r for r in results if r.setup.mu == RECORDED_MU)
    disp = np.loadtxt(tmp_path / "head_disp.out", ndmin=2)
    force = np.loadtxt(tmp_path / "head_reaction.out", ndmin=2)
    # One row per pull step (the released state before the pull is row 0 of the curves), written
    # with OpenSees' default 6 significant digits.
    assert len(disp) == len(r.head_disp) - 1
    assert disp[:, 1] == pytest.approx(r.head_disp[1:], rel=1e-5)
    assert force[:, 1] == pytest.approx(r.head_force[1:], rel=1e-5)
    assert r.head_disp[-1] == pytest.approx(r.setup.head_pull, rel=1e-12)
    listed = [d.get("file") for d in ET.parse(tmp_path / "donut_pullout.pvd").getroot().iter("DataSet")]
    grid = meshio.read(tmp_path / listed[-1])
    tags = grid.point_data["nodeTag"].ravel().astype(int).tolist()
    head = tags.index(_head_tag(r.setup))
    assert grid.point_data["displacement"][head][2] == pytest.approx(r.head_disp[-1], rel=1e-9)


def _head_tag(setup):
    model = DonutModel(setup).build()
    try:
        return model.pile_nodes[0]
    finally:
        model.m.wipe()

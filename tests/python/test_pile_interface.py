"""Pile-level contact (beamsolid.contact): a pile pulled out of a soil donut by more than three
element lengths keeps every soil node in contact through hand-overs, and its friction stays
mu times the normal force; the paper's single-segment elements lose the nodes that slide off
their segment."""
import math

import pytest

from beamsolid import contact, mesh

R = 0.3  # pile radius
MU = 0.4
N_PILE = 6  # beam elements of length 1, nodes 1..7 at z = -3..3
PULL = 3.1  # more than three element lengths (1.0)
STEP = 0.025


def build_pullout(ops, *, chain=True, penalty=None, levels=(2.8, 0.2), n_z=4, n_theta=8):
    """Pile of N_PILE elastic beams (z = -3..3) inside a stdBrick donut (R..1, z from
    levels[1] to levels[0]); contacts by contact.pile_interface; frictionless stage on."""
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    pile = list(range(1, N_PILE + 2))
    for k, tag in enumerate(pile):
        ops.node(tag, 0.0, 0.0, -3.0 + k)
    top = pile[-1]
    # The pile hangs from its top node: laterally and in rotation held there (so it stays stable
    # when contacts are lost), axially held now and pulled later.
    ops.fix(top, 1, 1, 1, 1, 1, 1)
    ops.geomTransf("Linear", 1, 1.0, 0.0, 0.0)
    area, inertia = math.pi * R**2, math.pi * R**4 / 4.0
    for k in range(N_PILE):
        ops.element("elasticBeamColumn", k + 1, pile[k], pile[k + 1], area, 3e7, 1.2e7, 2 * inertia, inertia,
                    inertia, 1)
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    ops.nDMaterial("ElasticIsotropic", 2, 1e4, 0.3)
    ops.nDMaterial("ContactMaterial3D", 1, MU, 2e4, 0.0, 0.0)
    donut = mesh.donut(ops, inner_radius=R, outer_radius=1.0, z_top=levels[0], z_bottom=levels[1], n_theta=n_theta,
                       n_radial=2, n_z=n_z, radial_ratio=1.0, material_tag=2, first_node=100, first_element=100)
    iface = contact.pile_interface(ops, pile, donut.inner_nodes, R, 1, 1, penalty=penalty, first_element=1000,
                                   first_node=1000, chain=chain)
    ops.updateMaterialStage("-material", 1, "-stage", 0)
    return pile, donut, iface


def analysis(ops, dt):
    ops.constraints("Transformation")
    ops.numberer("RCM")
    ops.system("UmfPack")
    # Absolute: the pull force is ~100; round-off grows with the pile's travel to ~1e-8.
    ops.test("NormUnbalance", 1e-6, 30)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", dt)
    ops.analysis("Static")


def confine(ops, donut, squeeze=2e-3):
    """Stage 1, frictionless: the outer boundary pushed in radially."""
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    for tag in donut.outer_nodes:
        x, y, _ = ops.nodeCoord(tag)
        r = math.hypot(x, y)
        ops.sp(tag, 1, -squeeze * x / r)
        ops.sp(tag, 2, -squeeze * y / r)
        ops.sp(tag, 3, 0.0)
    analysis(ops, 0.5)
    assert ops.analyze(2) == 0
    ops.loadConst("-time", 0.0)
    ops.wipeAnalysis()


def start_pull(ops, top, distance):
    """Stage 2: friction on, the pile top pulled up by `distance` over pseudo-time 1."""
    ops.updateMaterialStage("-material", 1, "-stage", 1)
    ops.remove("sp", top, 3)
    ops.timeSeries("Linear", 2)
    ops.pattern("Plain", 2, 2)
    ops.sp(top, 3, distance)


def test_chained_pullout_keeps_every_node_and_full_friction(ops):
    pile, donut, iface = build_pullout(ops)
    assert len(iface.elements) == len(donut.inner_nodes) == 5 * 8
    confine(ops, donut)
    confined = contact.interface_forces(ops, iface)
    assert confined.released == 0 and confined.normal > 0
    assert math.hypot(*confined.friction) == 0.0

    start_pull(ops, pile[-1], PULL)
    steps = round(PULL / STEP)
    analysis(ops, 1.0 / steps)
    all_sliding_from = None
    hand_overs, handed_steps = 0, 0
    for step in range(1, steps + 1):
        assert ops.analyze(1) == 0, f"step {step}"
        f = contact.interface_forces(ops, iface)
        assert f.released == 0, f"step {step}: {f.released} nodes released"
        if f.sliding == len(iface.elements):
            all_sliding_from = all_sliding_from or step
        if all_sliding_from is None:
            hand_overs = f.hand_overs
            continue
        # From then on (hand-over steps included): every node slides, the friction on the soil is
        # axial (up, dragging the soil with the pile) and mu times the normal force.
        assert f.sliding == len(iface.elements), f"step {step}"
        assert abs(f.friction[0]) + abs(f.friction[1]) <= 1e-8 * f.friction[2]
        error = abs(f.friction[2] - MU * f.normal) / (MU * f.normal)
        assert error <= 1e-10, f"step {step}: friction {f.friction[2]} vs mu N {MU * f.normal}"
        # OpenSeesPy's frictionforce is the friction on the pile: the pile pulled up reads it down.
        on_pile = [ops.eleResponse(e, "frictionforce") for e in iface.elements]
        assert all(v[2] < 0.0 for v in on_pile), f"step {step}"
        assert sum(v[2] for v in on_pile) == pytest.approx(-f.friction[2], rel=1e-14)
        # The pile's support carries it. A hand-over redistributes a contact force over the new
        # segment's nodes (statically equivalent: the sum over the pile is kept) and leaves a small
        # unbalance at the free pile nodes, which the next step removes.
        ops.reactions()
        total = sum(ops.nodeReaction(t, 3) for t in pile)
        assert abs(total - f.friction[2]) <= 1e-6 * f.friction[2], f"step {step}"
        top_error = abs(ops.nodeReaction(pile[-1], 3) - f.friction[2]) / f.friction[2]
        handed = f.hand_overs > hand_overs
        assert top_error <= (1e-4 if handed else 1e-6), f"step {step}"
        handed_steps += handed
        hand_overs = f.hand_overs
    assert all_sliding_from is not None and all_sliding_from <= 0.1 * steps
    assert handed_steps == 3 * 5  # each of the five levels three times, at distinct steps here
    # Every soil node passed three beam nodes relative to the pile and was handed over each time.
    final = contact.interface_forces(ops, iface)
    assert final.hand_overs == 3 * len(iface.elements)
    assert ops.nodeDisp(pile[-1], 3) == pytest.approx(PULL, rel=1e-12)
    # Each element now sits three segments further down the pile than where it started.
    for soil, ele in iface.element_of.items():
        i0, _ = iface.segment_of[soil]
        i, j = ops.eleNodes(ele)[:2]
        assert (i, j) == (i0 - 3, i0 - 2)


def test_single_segment_elements_lose_the_nodes_that_slide_off(ops):
    # The same model with the paper's elements: after one element length of pull every soil node
    # has left the segment it was assigned to and is released; the friction goes with it.
    pile, donut, iface = build_pullout(ops, chain=False)
    confine(ops, donut)
    start_pull(ops, pile[-1], PULL)
    steps = round(PULL / STEP)
    analysis(ops, 1.0 / steps)
    released_at = {}
    full_friction = None
    for step in range(1, round(1.5 / STEP) + 1):
        assert ops.analyze(1) == 0, f"step {step}"
        f = contact.interface_forces(ops, iface)
        if f.sliding == len(iface.elements) and full_friction is None:
            full_friction = f.friction[2]
        released_at[step] = f.released
    f = contact.interface_forces(ops, iface)
    assert full_friction is not None and full_friction > 0
    assert f.released == len(iface.elements)
    assert f.hand_overs == 0
    # Nodes go level by level as the pile moves on, never come back.
    counts = [released_at[s] for s in sorted(released_at)]
    assert counts == sorted(counts) and len(set(counts)) > 3
    assert abs(f.friction[2]) <= 1e-9 * full_friction  # friction deficit: all of it


def test_nodes_level_with_beam_nodes_are_held(ops):
    # Soil levels at z = 2, 1, 0 coincide with beam nodes 6, 5, 4.
    pile, donut, iface = build_pullout(ops, levels=(2.0, 0.0), n_z=2)
    for soil, ele in iface.element_of.items():
        z = ops.nodeCoord(soil)[2]
        below = pile[int(round(z)) + 3]  # the beam node at that level
        assert iface.segment_of[soil] == (below, below + 1)
    confine(ops, donut)
    f = contact.interface_forces(ops, iface)
    assert f.released == 0 and f.in_contact == len(iface.elements)
    # The paper's elements do not hold them: none at the start; after the confinement only those
    # the soil's Poisson drift moved into their segment (the top level, pushed up), not the
    # bottom level (pushed down, out of its segment).
    ops.wipe()
    pile, donut, iface = build_pullout(ops, levels=(2.0, 0.0), n_z=2, chain=False)
    assert all(ops.eleResponse(e, "status")[0] == 0.0 for e in iface.elements)
    confine(ops, donut)
    released = [e for e in iface.elements if ops.eleResponse(e, "status")[0] == 0.0]
    bottom = [iface.element_of[s] for s in donut.inner_nodes if ops.nodeCoord(s)[2] == 0.0]
    assert set(bottom) <= set(released)


def test_penalty_interface_hands_over_too(ops):
    pile, donut, iface = build_pullout(ops, penalty=1e5, levels=(1.8, 1.2), n_z=1, n_theta=6)
    assert iface.multiplier_nodes == [] and iface.element_type == "BeamContact3Dp"
    confine(ops, donut)
    start_pull(ops, pile[-1], 1.1)  # both levels pass beam node 5 (z = 1)
    steps = round(1.1 / STEP)
    analysis(ops, 1.0 / steps)
    for step in range(1, steps + 1):
        assert ops.analyze(1) == 0, f"step {step}"
        f = contact.interface_forces(ops, iface)
        assert f.released == 0
    assert f.sliding == len(iface.elements)
    assert abs(f.friction[2] - MU * f.normal) <= 1e-8 * MU * f.normal
    assert f.hand_overs == len(iface.elements)


def test_pile_interface_errors(ops):
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    for k in range(3):
        ops.node(k + 1, 0.0, 0.0, float(k))
    ops.geomTransf("Linear", 1, 1.0, 0.0, 0.0)
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    ops.nDMaterial("ContactMaterial3D", 1, MU, 2e4, 0.0, 0.0)
    ops.node(10, R, 0.0, 2.5)   # beyond the pile's top
    ops.node(11, 0.0, 0.0, 1.5)  # on the axis
    ops.node(12, R, 0.0, 0.5)
    with pytest.raises(ValueError, match="soil node 10 .* projects onto no segment"):
        contact.pile_interface(ops, [1, 2, 3], [12, 10], R, 1, 1)
    with pytest.raises(ValueError, match="soil node 11 .* lies on the pile axis"):
        contact.pile_interface(ops, [1, 2, 3], [11], R, 1, 1)
    with pytest.raises(ValueError, match="at least two beam nodes"):
        contact.pile_interface(ops, [1], [12], R, 1, 1)
    with pytest.raises(ValueError, match="node 2 is both a pile node and a soil node"):
        contact.pile_interface(ops, [1, 2, 3], [2], R, 1, 1)
    with pytest.raises(ValueError, match="penalty must be positive"):
        contact.pile_interface(ops, [1, 2, 3], [12], R, 1, 1, penalty=0.0)
    # Nothing was created by the failed calls; a good call numbers from the largest tags.
    assert sorted(ops.getNodeTags()) == [1, 2, 3, 10, 11, 12]
    iface = contact.pile_interface(ops, [1, 2, 3], [12], R, 1, 1)
    assert iface.elements == [1] and iface.multiplier_nodes == [13]
    assert iface.element_of == {12: 1} and iface.segment_of == {12: (1, 2)}
    assert ops.eleNodes(1) == [1, 2, 12, 13]


def test_displacement_control_pullout_across_a_beam_node(ops):
    # DisplacementControl forms its tangent before the step's first update: a handed-over element
    # must already have its matrices on the new segment's dofs. (A fully sliding pile has no axial
    # tangent stiffness, so a soft axial tie from the pile top to a fixed node keeps K regular.)
    pile, donut, iface = build_pullout(ops, levels=(1.8, 1.2), n_z=1, n_theta=6)
    confine(ops, donut)
    top = pile[-1]
    ops.node(99, 0.0, 0.0, 4.0, "-ndf", 6)
    ops.fix(99, 1, 1, 1, 1, 1, 1)
    tie_area, young = 1e-6, 3e7  # EA / L = 30
    ops.element("elasticBeamColumn", 99, top, 99, tie_area, young, 1.2e7, 1e-8, 1e-8, 1e-8, 1)
    ops.updateMaterialStage("-material", 1, "-stage", 1)
    ops.remove("sp", top, 3)
    ops.timeSeries("Linear", 2)
    ops.pattern("Plain", 2, 2)
    ops.load(top, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0)
    analysis(ops, 1.0)
    ops.integrator("DisplacementControl", top, 3, STEP)
    steps = round(1.1 / STEP)  # both levels pass beam node 5 (z = 1)
    for step in range(1, steps + 1):
        assert ops.analyze(1) == 0, f"step {step}"
        f = contact.interface_forces(ops, iface)
        assert f.released == 0
        if f.sliding == len(iface.elements):
            # The pull force (load factor times the unit reference load) is the friction plus the tie.
            tie = tie_area * young * ops.nodeDisp(top, 3) / 1.0
            assert ops.getLoadFactor(2) == pytest.approx(f.friction[2] + tie, rel=1e-8), f"step {step}"
            assert f.friction[2] == pytest.approx(MU * f.normal, rel=1e-10)
    assert f.hand_overs == len(iface.elements)
    assert ops.nodeDisp(top, 3) == pytest.approx(1.1, rel=1e-12)

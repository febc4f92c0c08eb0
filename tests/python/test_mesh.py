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


# --- ogrid, pile_group, solid_cylinder, beam_pile, pile_in_soil ---------------------------------

GAUSS = (-1.0 / math.sqrt(3.0), 1.0 / math.sqrt(3.0))
CORNERS = [(-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1), (-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1)]
FACES = [(0, 1, 2, 3), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]


def _jacobian_det(xyz, xi, eta, zeta):
    """det of d(x, y, z)/d(xi, eta, zeta) of the trilinear map of 8 corners (stdBrick order)."""
    J = [[0.0] * 3 for _ in range(3)]
    for (a, b, c), p in zip(CORNERS, xyz):
        dN = (a * (1 + b * eta) * (1 + c * zeta) / 8, b * (1 + a * xi) * (1 + c * zeta) / 8,
              c * (1 + a * xi) * (1 + b * eta) / 8)
        for r in range(3):
            for s in range(3):
                J[r][s] += p[r] * dN[s]
    return (J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) - J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0])
            + J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]))


def _bricks(model, elements):
    return {e: [int(n) for n in model.eleNodes(e)] for e in elements}


def _check_bricks(model, elements, scale):
    """Positive corner Jacobians; the 2x2x2 Gauss volume (exact for the trilinear map)."""
    volume = 0.0
    for e, nodes in _bricks(model, elements).items():
        xyz = [model.nodeCoord(n) for n in nodes]
        for corner in CORNERS:
            assert _jacobian_det(xyz, *corner) > 1e-12 * scale**3, f"element {e}"
        volume += sum(_jacobian_det(xyz, a, b, c) for a in GAUSS for b in GAUSS for c in GAUSS)
    return volume


def _boundary_faces(model, elements):
    """Faces of one brick only (each face a frozenset of node tags); asserts interior faces pair up."""
    count = {}
    for nodes in _bricks(model, elements).values():
        for face in FACES:
            key = frozenset(nodes[i] for i in face)
            count[key] = count.get(key, 0) + 1
    assert max(count.values()) == 2
    return [f for f, c in count.items() if c == 1]


def _no_duplicate_nodes(model, tags):
    keys = {tuple(round(c, 9) for c in model.nodeCoord(t)) for t in tags}
    assert len(keys) == len(tags)


def _ngon(n, r):
    """Area of the n-gon inscribed in a circle of radius r."""
    return 0.5 * n * r**2 * math.sin(2.0 * math.pi / n)


@pytest.fixture
def soil(model):
    model.model("basic", "-ndm", 3, "-ndf", 3)
    model.nDMaterial("ElasticIsotropic", 1, 1000.0, 0.3)
    return model


def _assert_on_circle(model, levels, centre, radius):
    for level in levels:
        for t in level:
            x, y, _ = model.nodeCoord(t)
            assert math.hypot(x - centre[0], y - centre[1]) == pytest.approx(radius, abs=1e-12)


@pytest.mark.parametrize("outer,n_theta", [("square", 16), ("square", 12), ("circle", 12), ("circle", 7)])
def test_ogrid_geometry_volume_and_conformity(soil, outer, n_theta):
    R, a, centre = 0.4, 2.0, (1.0, -0.5)
    m = mesh.ogrid(soil, pile_radius=R, outer_size=a, outer=outer, n_theta=n_theta, n_radial=3, radial_ratio=1.4,
                   z_top=1.0, z_bottom=-3.0, n_z=4, z_ratio=1.3, centre=centre, first_node=101, first_element=7)
    assert m.nodes == list(range(101, 101 + len(m.nodes))) and m.elements[0] == 7
    assert len(m.elements) == n_theta * 3 * 4 and len(m.surface) == 5
    _assert_on_circle(soil, m.surface, centre, R)
    _no_duplicate_nodes(soil, m.nodes)
    H = 4.0
    outer_area = 4 * a * a if outer == "square" else _ngon(n_theta, a)
    volume = _check_bricks(soil, m.elements, R)
    assert volume == pytest.approx((outer_area - _ngon(n_theta, R)) * H, rel=1e-10)
    surface = {t for level in m.surface for t in level}
    outer_nodes = set(m.groups["outer"])
    for face in _boundary_faces(soil, m.elements):
        z = {soil.nodeCoord(t)[2] for t in face}
        if len(z) == 1:
            assert z <= {1.0, -3.0}
            assert face <= set(m.groups["top" if z == {1.0} else "base"])
        else:
            assert face <= surface or face <= outer_nodes
            if face <= outer_nodes and outer == "square":
                assert any(face <= set(m.groups[s]) for s in ("xmin", "xmax", "ymin", "ymax"))
    if outer == "square":
        for side, (axis, value) in {"xmin": (0, centre[0] - a), "xmax": (0, centre[0] + a),
                                    "ymin": (1, centre[1] - a), "ymax": (1, centre[1] + a)}.items():
            assert all(soil.nodeCoord(t)[axis] == pytest.approx(value, abs=1e-13) for t in m.groups[side])
            assert len(m.groups[side]) == (n_theta // 4 + 1) * 5
    else:
        _assert_on_circle(soil, [m.groups["outer"]], centre, a)


def test_ogrid_core_below_the_tip(soil):
    R, a, n = 0.5, 3.0, 12
    levels = [0.0, -1.0, -2.5, -3.0, -4.0]
    m = mesh.ogrid(soil, pile_radius=R, outer_size=a, outer="circle", n_theta=n, n_radial=2, levels=levels,
                   core_below=-2.5)
    assert m.tip_level == 2 and m.pile_levels == [0.0, -1.0, -2.5] and len(m.surface) == 3
    _assert_on_circle(soil, m.surface, (0.0, 0.0), R)
    _no_duplicate_nodes(soil, m.nodes)
    volume = _check_bricks(soil, m.elements, R)
    assert volume == pytest.approx(_ngon(n, a) * 4.0 - _ngon(n, R) * 2.5, rel=1e-10)
    surface = {t for level in m.surface for t in level}
    for face in _boundary_faces(soil, m.elements):
        xyz = [soil.nodeCoord(t) for t in face]
        z = {p[2] for p in xyz}
        inside = all(math.hypot(p[0], p[1]) <= R * (1 + 1e-12) for p in xyz)
        # top, base, outer cylinder, pile surface above the tip, or the hole's bottom at the tip
        assert (z == {0.0} or z == {-4.0} or face <= set(m.groups["outer"]) or face <= surface
                or (z == {-2.5} and inside))


def test_pile_group_row_and_grid(soil):
    R, s, n = 0.5, 3.0, 8
    piles = [(0.0, 0.0), (3.0, 0.0), (6.0, 0.0), (3.0, 3.0)]  # a bent row plus one pile behind: cells fill
    pad = (2.0, 1.0, 1.5, 0.5)
    m = mesh.pile_group(soil, piles=piles, pile_radius=R, spacing=s, n_theta=n, n_radial=2, padding=pad,
                        n_padding=(2, 1, 2, 1), padding_ratio=1.5, levels=[0.0, -1.0, -2.0, -3.5], core_below=-2.0)
    assert len(m.surfaces) == 4 and all(len(levels) == 3 for levels in m.surfaces)
    for p, centre in enumerate(piles):
        _assert_on_circle(soil, m.surfaces[p], centre, R)
    _no_duplicate_nodes(soil, m.nodes)
    Lx, Ly = 3 * s + pad[0] + pad[1], 2 * s + pad[2] + pad[3]
    volume = _check_bricks(soil, m.elements, R)
    assert volume == pytest.approx(Lx * Ly * 3.5 - 4 * _ngon(n, R) * 2.0, rel=1e-10)
    box = {"xmin": (0, -1.5 - pad[0]), "xmax": (0, 7.5 + pad[1]), "ymin": (1, -1.5 - pad[2]),
           "ymax": (1, 4.5 + pad[3])}
    for side, (axis, value) in box.items():
        assert all(soil.nodeCoord(t)[axis] == pytest.approx(value, abs=1e-12) for t in m.groups[side])
    surfaces = [{t for level in levels for t in level} for levels in m.surfaces]
    for face in _boundary_faces(soil, m.elements):
        xyz = [soil.nodeCoord(t) for t in face]
        z = {p[2] for p in xyz}
        at_tip = z == {-2.0} and any(all(math.hypot(q[0] - c[0], q[1] - c[1]) <= R * (1 + 1e-12) for q in xyz)
                                     for c in piles)
        assert (z == {0.0} or z == {-3.5} or at_tip or any(face <= sf for sf in surfaces)
                or any(face <= set(m.groups[sd]) for sd in box))


def test_solid_cylinder_fits_the_hole(soil):
    R, n, levels = 0.5, 16, [0.0, -1.0, -2.0]
    hole = mesh.ogrid(soil, pile_radius=R, outer_size=2.0, outer="square", n_theta=n, n_radial=2, levels=levels)
    pile = mesh.solid_cylinder(soil, radius=R, levels=levels, n_theta=n)
    assert len(pile.surface) == 3 and len(pile.axis) == 3
    for k, z in enumerate(levels):
        for a, b in zip(hole.surface[k], pile.surface[k]):
            assert a != b and soil.nodeCoord(a) == soil.nodeCoord(b)
        assert soil.nodeCoord(pile.axis[k]) == [0.0, 0.0, z]
    _no_duplicate_nodes(soil, pile.nodes)
    assert _check_bricks(soil, pile.elements, R) == pytest.approx(_ngon(n, R) * 2.0, rel=1e-10)
    surface = {t for level in pile.surface for t in level}
    for face in _boundary_faces(soil, pile.elements):
        assert face <= set(pile.groups["top"]) or face <= set(pile.groups["base"]) or face <= surface
    odd = mesh.solid_cylinder(soil, radius=R, levels=[5.0, 4.0], n_theta=12, centre=(9.0, 9.0))
    assert odd.axis == []  # n_theta / 4 odd: the inner square has no centre node


def _oedometer(model, m, top, gamma, nu, H):
    """Sides on rollers, base fixed, self weight: each brick's stresses are the exact uniaxial-strain
    stresses at its mid-depth, sigma_v = -gamma d, sigma_h = nu / (1 - nu) sigma_v (the exact
    displacement is quadratic in z; the trilinear bricks give the exact nodal values and a constant
    strain per layer, the exact one at mid-layer). Relative to gamma H, 1e-8."""
    mesh.fix_soil_boundary(model, m, lateral="roller", base="fixed")
    model.system("UmfPack")
    model.analysis("Static")
    assert model.analyze(1) == 0
    for e in m.elements:
        nodes = model.eleNodes(e)
        z_mid = sum(model.nodeCoord(t)[2] for t in nodes) / 8.0
        sv = -gamma * (top - z_mid)
        s = model.eleResponse(e, "stresses")
        for g in range(8):
            expect = (nu / (1 - nu) * sv, nu / (1 - nu) * sv, sv, 0.0, 0.0, 0.0)
            for c in range(6):
                assert s[6 * g + c] == pytest.approx(expect[c], abs=1e-8 * gamma * H)
    model.reactions()
    weight = gamma * _check_bricks(model, m.elements, 1.0)
    assert sum(model.nodeReaction(t, 3) for t in m.groups["base"]) == pytest.approx(weight, rel=1e-10)


def test_oedometer_ogrid_filled(model):
    gamma, nu = 18.0, 0.3
    model.model("basic", "-ndm", 3, "-ndf", 3)
    model.nDMaterial("ElasticIsotropic", 1, 5000.0, nu)
    m = mesh.ogrid(model, pile_radius=0.5, outer_size=2.0, outer="square", n_theta=8, n_radial=2, z_top=0.0,
                   z_bottom=-5.0, n_z=4, z_ratio=1.5, core_below=0.0, body_force=(0.0, 0.0, -gamma))
    assert m.surfaces == [[]] and len(m.groups["top"]) == len(m.plan.points)
    _oedometer(model, m, 0.0, gamma, nu, 5.0)


def test_oedometer_pile_group_filled(model):
    gamma, nu = 20.0, 0.25
    model.model("basic", "-ndm", 3, "-ndf", 3)
    model.nDMaterial("ElasticIsotropic", 1, 8000.0, nu)
    m = mesh.pile_group(model, piles=[(0.0, 0.0), (2.0, 0.0)], pile_radius=0.4, spacing=2.0, n_theta=8, n_radial=2,
                        padding=1.0, n_padding=1, levels=[1.0, 0.0, -2.0], core_below=5.0,
                        body_force=(0.0, 0.0, -gamma))
    _oedometer(model, m, 1.0, gamma, nu, 3.0)


def test_beam_pile_on_the_axis(model):
    model.model("basic", "-ndm", 3, "-ndf", 3)
    levels = [0.0, -1.0, -3.0]
    p = mesh.beam_pile(model, x=2.0, y=-1.0, levels=levels, radius=0.5, E=3e7, G=1.25e7, transf_tag=4,
                       first_node=50, first_element=60)
    assert p.nodes == [50, 51, 52] and p.elements == [60, 61]
    for t, z in zip(p.nodes, levels):
        assert model.nodeCoord(t) == [2.0, -1.0, z] and model.getNDF(t) == [6]
    model.node(99, 0.0, 0.0, 0.0)  # builder back at ndf 3
    assert model.getNDF(99) == [3]


def test_pile_in_soil_geostatic_normal_sum(model):
    """Frictionless interface, fixed pile, self weight: the exact uniaxial-strain state; the contact
    normal forces add up to the faceted ring's n R sin(2 pi / n) integral(sigma_h dz), 1e-8."""
    from beamsolid import contact

    gamma, nu, n, R, D = 20.0, 0.3, 8, 0.5, 3.0
    model.model("basic", "-ndm", 3, "-ndf", 3)
    model.nDMaterial("ElasticIsotropic", 1, 20e3, nu)
    model.nDMaterial("ContactMaterial3D", 2, 0.5, 1000.0, 0.0, 0.0)
    built = mesh.pile_in_soil(model, pile_radius=R, outer_size=2.0, outer="square", pile_E=3e7, pile_G=1.25e7,
                              soil_material=1, contact_material=2, z_top=0.0, z_bottom=-D, n_z=3, z_ratio=1.2,
                              n_theta=n, n_radial=2, base="roller", body_force=(0.0, 0.0, -gamma))
    assert len(built.interface.elements) == n * 4 and built.pile.levels == built.soil.levels
    for t, z in zip(built.pile.nodes, built.soil.levels):
        assert model.nodeCoord(t) == [0.0, 0.0, z]
    for t in built.pile.nodes:
        model.fix(t, 1, 1, 1, 1, 1, 1)
    model.updateMaterialStage("-material", 2, "-stage", 0)
    model.constraints("Transformation")
    model.system("UmfPack")
    model.test("NormUnbalance", 1e-8, 10)
    model.algorithm("Newton")
    model.analysis("Static")
    assert model.analyze(1) == 0
    forces = contact.interface_forces(model, built.interface)
    expected = n * R * math.sin(2 * math.pi / n) * 0.5 * nu / (1 - nu) * gamma * D**2
    assert forces.normal == pytest.approx(expected, rel=1e-8)


@pytest.mark.parametrize("call,kwargs,word", [
    ("ogrid", dict(outer="square", n_theta=10), "n_theta"),
    ("ogrid", dict(outer_size=0.3), "outer_size"),
    ("ogrid", dict(outer="hexagon"), "outer"),
    ("ogrid", dict(n_radial=0), "n_radial"),
    ("ogrid", dict(core_below=-0.5), "core_below"),
    ("ogrid", dict(core_below=-1.0, n_theta=6), "n_theta"),
    ("ogrid", dict(core_below=-1.0, core_fraction=0.8), "core_fraction"),
    ("ogrid", dict(levels=[0.0, -1.0, -1.0]), "levels"),
    ("ogrid", dict(levels=[0.0, -1.0], n_z=3), "levels"),
    ("pile_group", dict(piles=[(0.0, 0.0), (2.5, 0.0)]), "piles"),
    ("pile_group", dict(piles=[(0.0, 0.0), (0.0, 1e-12)]), "overlap"),
    ("pile_group", dict(spacing=0.9), "spacing"),
    ("pile_group", dict(padding=-1.0), "padding"),
    ("pile_group", dict(padding=(1.0, 2.0)), "padding"),
    ("pile_group", dict(n_padding=0, padding=1.0), "n_padding"),
    ("ogrid", dict(element="quad"), "element"),
    ("pile_group", dict(element="brick"), "element"),
])
def test_bad_arguments_name_the_argument(soil, call, kwargs, word):
    base = dict(pile_radius=0.5, levels=[0.0, -1.0, -2.0])
    if call == "ogrid":
        base.update(outer_size=2.0, n_theta=8)
    else:
        base.update(piles=[(0.0, 0.0), (2.0, 0.0)], spacing=2.0, n_theta=8)
    base.update(kwargs)
    if "n_z" in kwargs:
        base.update(z_top=0.0)
    with pytest.raises(ValueError, match=word):
        getattr(mesh, call)(soil, **base)
    assert soil.getNodeTags() == []  # nothing was built


@pytest.mark.parametrize("element", ["bbarBrick", "SSPbrick"])
def test_other_bricks_build_the_same_mesh(soil, element):
    kw = dict(pile_radius=0.5, outer_size=2.0, n_theta=8, n_radial=2, levels=[0.0, -1.0, -2.0], core_below=-1.0)
    plain = mesh.ogrid(soil, **kw)
    other = mesh.ogrid(soil, **kw, element=element)
    assert len(other.elements) == len(plain.elements)
    for a, b in zip(plain.elements, other.elements):
        assert soil.eleType(a) != soil.eleType(b)
        assert [soil.nodeCoord(t) for t in soil.eleNodes(a)] == [soil.nodeCoord(t) for t in soil.eleNodes(b)]
    cyl = mesh.solid_cylinder(soil, radius=0.5, levels=[0.0, -1.0], n_theta=8, element=element)
    assert {soil.eleType(e) for e in cyl.elements} == {soil.eleType(other.elements[0])}


def test_pile_in_soil_refuses_a_tip_at_the_top(soil):
    with pytest.raises(ValueError, match="pile_tip"):
        mesh.pile_in_soil(soil, pile_radius=0.5, outer_size=2.0, pile_E=3e7, pile_G=1.25e7, soil_material=1,
                          contact_material=2, levels=[0.0, -1.0], pile_tip=0.0, n_theta=8, n_radial=2)
    assert soil.getNodeTags() == []


def test_plan_check_refuses_inverted_quads():
    """The safety net behind every builder: a clockwise or degenerate quad would give a
    non-positive brick Jacobian."""
    plan = mesh.Plan(points=[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)], quads=[[0, 1, 2, 3]])
    mesh._check_plan(plan, "test", "hint")
    plan.quads = [[0, 3, 2, 1]]
    with pytest.raises(ValueError, match="test: the plan has an inverted or degenerate quad.*hint"):
        mesh._check_plan(plan, "test", "hint")
    plan.points[2] = (0.5, 0.5)  # a corner on the diagonal
    plan.quads = [[0, 1, 2, 3]]
    with pytest.raises(ValueError, match="degenerate"):
        mesh._check_plan(plan, "test", "hint")

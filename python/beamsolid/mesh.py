"""Structured hexahedral soil meshes that honour a pile.

Soil nodes on the pile surface lie exactly on the circle of the pile radius,
so the beam-solid contact measures gaps from the true surface; beam nodes lie
on the axis. Every function creates nodes and 8-node bricks (stdBrick, or bbarBrick /
SSPbrick by `element`) through the given command module (``beamsolid.opensees`` or a
``beamsolid.Model``) and returns the tags a script needs (docs/meshing.md).

A mesh is a plan -- quads in the x-y plane (:class:`Plan`) -- extruded over a list of
z levels, top to bottom, into 8-node bricks: node tags run level by level
(top level first) and within a level in plan order; element tags run layer by layer
(top layer first) and within a layer in plan order. Each brick lists its bottom face
counterclockwise seen from above, then its top face (positive Jacobians).

Below a pile tip (``core_below``) the pile hole is filled with soil: a "butterfly"
core, an inner square block plus a ring of quads out to the circle, sharing the
circle nodes. A square boundary or a core needs n_theta to be a multiple of 4; the
circle then starts at angle 0 when n_theta / 4 is even and at pi / n_theta when it is
odd, so that the square's corners meet circle nodes' rays (mesh.theta0).
"""
import math
from dataclasses import dataclass, field

from .contact import pile_interface

__all__ = ["graded", "Plan", "SoilMesh", "BeamPile", "PileInSoil", "DonutMesh", "ogrid", "pile_group",
           "solid_cylinder", "beam_pile", "fix_soil_boundary", "pile_in_soil", "donut", "theta0", "plot_plan"]


def graded(start, stop, count, ratio=1.0):
    """count + 1 points from start to stop, each interval `ratio` times the previous."""
    if count < 1:
        raise ValueError("count must be at least 1")
    if abs(ratio - 1.0) < 1e-12:
        return [start + (stop - start) * k / count for k in range(count + 1)]
    first = (stop - start) * (ratio - 1.0) / (ratio**count - 1.0)
    points, x, step = [start], start, first
    for _ in range(count):
        x += step
        points.append(x)
        step *= ratio
    points[-1] = stop
    return points


# --- plans -------------------------------------------------------------------------------

@dataclass
class Plan:
    """A quad mesh in the x-y plane, to be extruded into bricks.

    Point keys (``label``): ``('ring', pile, i, j)`` for the O-grid around pile `pile`
    (angle index i from theta0 counterclockwise, ring j = 0 on the circle outwards),
    ``('grid', X, Y)`` for the lattice of square tiles and padding (pile_group and
    square ogrid; X, Y from the lower left corner), ``('core', pile, X, Y)`` for the
    inner square of a filled hole and ``('core_ring', pile, i, j)`` for its ring
    (j = 0 on the inner square). A point shared by two keys has one index.
    """

    points: list = field(default_factory=list)  # (x, y)
    quads: list = field(default_factory=list)  # 4 point indices, counterclockwise seen from above
    label: dict = field(default_factory=dict)  # key -> point index
    groups: dict = field(default_factory=dict)  # outer boundary: 'outer', 'xmin', ... -> point indices
    core_quads: set = field(default_factory=set)  # quad indices that exist only below the pile tips
    piles: list = field(default_factory=list)  # (x, y) of each pile axis
    circles: list = field(default_factory=list)  # per pile: circle point indices by angle

    def point(self, key, xy):
        """Index of the point `key`, added at `xy` unless it exists."""
        if key not in self.label:
            self.label[key] = len(self.points)
            self.points.append(xy)
        return self.label[key]

    def core_points(self):
        """Points used by core quads only (they exist only where the hole is filled)."""
        core, other = set(), set()
        for q, quad in enumerate(self.quads):
            (core if q in self.core_quads else other).update(quad)
        return core - other


def theta0(n_theta, square):
    """Angle of the first circle node: 0, or pi / n_theta when a square (boundary or core)
    with n_theta / 4 odd divisions per side needs its corners on the nodes' rays."""
    return math.pi / n_theta if square and (n_theta // 4) % 2 == 1 else 0.0


def _perimeter_step(i, n_theta):
    """Step of circle node i along a square's perimeter, counterclockwise from its (+, -) corner."""
    m = n_theta // 4
    return (i + (m + 1) // 2) % n_theta


def _perimeter_lattice(u, m):
    """Lattice (X, Y) in 0..m of perimeter step u: right side up, top leftwards, left down, bottom."""
    side, l = divmod(u, m)
    return [(m, l), (m - l, m), (0, m - l), (l, 0)][side]


def _check_plan(plan, where, hint):
    """Every quad convex with its corners counterclockwise (positive brick Jacobians)."""
    for quad in plan.quads:
        p = [plan.points[i] for i in quad]
        for c in range(4):
            ax, ay = p[(c + 1) % 4][0] - p[c][0], p[(c + 1) % 4][1] - p[c][1]
            bx, by = p[c - 1][0] - p[c][0], p[c - 1][1] - p[c][1]
            if ax * by - ay * bx <= 1e-10 * math.hypot(ax, ay) * math.hypot(bx, by):
                raise ValueError(f"{where}: the plan has an inverted or degenerate quad near "
                                 f"({p[c][0]:.6g}, {p[c][1]:.6g}); {hint}")


def _add_core(plan, pile, circle, n_theta, radius, core_fraction, n_core):
    """Butterfly core inside the circle points `circle`: an inner square block plus a ring."""
    cx, cy = plan.piles[pile]
    m = n_theta // 4
    b = core_fraction * radius
    first = len(plan.quads)
    for X in range(m + 1):
        for Y in range(m + 1):
            plan.point(("core", pile, X, Y), (cx - b + 2.0 * b * X / m, cy - b + 2.0 * b * Y / m))
    rings = [[plan.label[("core", pile, *_perimeter_lattice(_perimeter_step(i, n_theta), m))]
              for i in range(n_theta)]]
    for j in range(1, n_core):
        t = j / n_core
        ring = []
        for i in range(n_theta):
            (qx, qy), (px, py) = plan.points[rings[0][i]], plan.points[circle[i]]
            ring.append(plan.point(("core_ring", pile, i, j), (qx + t * (px - qx), qy + t * (py - qy))))
        rings.append(ring)
    rings.append(list(circle))
    for j in range(n_core):
        for i in range(n_theta):
            ip = (i + 1) % n_theta
            plan.quads.append([rings[j][i], rings[j + 1][i], rings[j + 1][ip], rings[j][ip]])
    for i in range(n_theta):
        plan.label.setdefault(("core_ring", pile, i, 0), rings[0][i])
    for X in range(m):
        for Y in range(m):
            plan.quads.append([plan.label[("core", pile, X, Y)], plan.label[("core", pile, X + 1, Y)],
                               plan.label[("core", pile, X + 1, Y + 1)], plan.label[("core", pile, X, Y + 1)]])
    plan.core_quads.update(range(first, len(plan.quads)))


def _circle_plan(centre, radius, outer_radius, n_theta, n_radial, radial_ratio, angle0):
    """Annulus: ring j (radius graded from the pile radius outwards) j-major, angle i minor."""
    plan = Plan(piles=[tuple(centre)])
    radii = graded(radius, outer_radius, n_radial, radial_ratio)
    for j, r in enumerate(radii):
        for i in range(n_theta):
            theta = angle0 + 2.0 * math.pi * i / n_theta
            plan.point(("ring", 0, i, j), (centre[0] + r * math.cos(theta), centre[1] + r * math.sin(theta)))
    ring = [[plan.label[("ring", 0, i, j)] for i in range(n_theta)] for j in range(n_radial + 1)]
    for j in range(n_radial):
        for i in range(n_theta):
            ip = (i + 1) % n_theta
            plan.quads.append([ring[j][i], ring[j + 1][i], ring[j + 1][ip], ring[j][ip]])
    plan.circles.append(ring[0])
    plan.groups["outer"] = ring[n_radial]
    return plan, radii


def _padding_lines(edge, width, count, ratio, outwards):
    if width == 0.0:
        return []
    pts = graded(edge, edge + outwards * width, count, ratio)[1:]
    return pts if outwards > 0 else pts[::-1]


def _tile_plan(where, piles, radius, spacing, n_theta, n_radial, radial_ratio, padding, n_padding,
               padding_ratio):
    """Square O-grid tiles of side `spacing` centred on the piles (on a regular grid of tiles),
    solid lattice blocks in grid cells without a pile, and graded padding around them."""
    m = n_theta // 4
    x0, y0 = piles[0]
    cells = {}
    for p, (px, py) in enumerate(piles):
        fx, fy = (px - x0) / spacing, (py - y0) / spacing
        tx, ty = round(fx), round(fy)
        if abs(fx - tx) > 1e-9 or abs(fy - ty) > 1e-9:
            raise ValueError(f"{where}: piles[{p}] = ({px}, {py}) is not on the grid of tiles of size "
                             f"spacing = {spacing} started by piles[0] (centre distances must be multiples of "
                             f"spacing)")
        if (tx, ty) in cells:
            raise ValueError(f"{where}: piles[{cells[(tx, ty)]}] and piles[{p}] overlap: they share a tile of "
                             f"size spacing = {spacing}")
        cells[(tx, ty)] = p
    txs, tys = [c[0] for c in cells], [c[1] for c in cells]
    tx_min, ty_min = min(txs), min(tys)
    nx, ny = max(txs) - tx_min + 1, max(tys) - ty_min + 1
    x_left, y_low = x0 + (tx_min - 0.5) * spacing, y0 + (ty_min - 0.5) * spacing
    pad, npad = padding, n_padding
    left = _padding_lines(x_left, pad[0], npad[0], padding_ratio, -1)
    low = _padding_lines(y_low, pad[2], npad[2], padding_ratio, -1)
    xs = (left + [x_left + spacing * X / m for X in range(nx * m + 1)]
          + _padding_lines(x_left + nx * spacing, pad[1], npad[1], padding_ratio, +1))
    ys = (low + [y_low + spacing * Y / m for Y in range(ny * m + 1)]
          + _padding_lines(y_low + ny * spacing, pad[3], npad[3], padding_ratio, +1))
    X0, Y0 = len(left), len(low)  # lattice index of the tiles' lower left corner
    plan = Plan(piles=[tuple(map(float, p)) for p in piles])

    def grid(X, Y):
        return plan.point(("grid", X, Y), (xs[X], ys[Y]))

    ts = graded(0.0, 1.0, n_radial, radial_ratio)
    angle0 = theta0(n_theta, True)
    for p, (cx, cy) in enumerate(plan.piles):
        tx, ty = round((cx - x0) / spacing) - tx_min, round((cy - y0) / spacing) - ty_min
        circle, square = [], []
        for i in range(n_theta):
            theta = angle0 + 2.0 * math.pi * i / n_theta
            circle.append((cx + radius * math.cos(theta), cy + radius * math.sin(theta)))
            X, Y = _perimeter_lattice(_perimeter_step(i, n_theta), m)
            square.append((X0 + tx * m + X, Y0 + ty * m + Y))
        ring = []
        for j in range(n_radial):
            row = []
            for i in range(n_theta):
                (ax, ay), (bx, by) = circle[i], (xs[square[i][0]], ys[square[i][1]])
                xy = circle[i] if j == 0 else (ax + ts[j] * (bx - ax), ay + ts[j] * (by - ay))
                row.append(plan.point(("ring", p, i, j), xy))
            ring.append(row)
        ring.append([grid(*square[i]) for i in range(n_theta)])
        for i in range(n_theta):
            plan.label[("ring", p, i, n_radial)] = ring[n_radial][i]
        for j in range(n_radial):
            for i in range(n_theta):
                ip = (i + 1) % n_theta
                plan.quads.append([ring[j][i], ring[j + 1][i], ring[j + 1][ip], ring[j][ip]])
        plan.circles.append(ring[0])
    piled = {(tx - tx_min, ty - ty_min) for tx, ty in cells}
    for Y in range(len(ys) - 1):
        for X in range(len(xs) - 1):
            if X0 <= X < X0 + nx * m and Y0 <= Y < Y0 + ny * m and ((X - X0) // m, (Y - Y0) // m) in piled:
                continue
            plan.quads.append([grid(X, Y), grid(X + 1, Y), grid(X + 1, Y + 1), grid(X, Y + 1)])
    NX, NY = len(xs) - 1, len(ys) - 1
    plan.groups["xmin"] = [plan.label[("grid", 0, Y)] for Y in range(NY + 1)]
    plan.groups["xmax"] = [plan.label[("grid", NX, Y)] for Y in range(NY + 1)]
    plan.groups["ymin"] = [plan.label[("grid", X, 0)] for X in range(NX + 1)]
    plan.groups["ymax"] = [plan.label[("grid", X, NY)] for X in range(NX + 1)]
    plan.groups["outer"] = sorted(set().union(*(plan.groups[s] for s in ("xmin", "xmax", "ymin", "ymax"))))
    return plan


# --- extrusion ---------------------------------------------------------------------------

@dataclass
class SoilMesh:
    """Tags of an extruded brick mesh (ogrid, pile_group, solid_cylinder)."""

    nodes: list = field(default_factory=list)  # every node tag, level by level
    elements: list = field(default_factory=list)
    node_at: dict = field(default_factory=dict)  # (plan point index, level index) -> node tag
    plan: Plan = None
    levels: list = field(default_factory=list)  # z of each node level, top to bottom
    surfaces: list = field(default_factory=list)  # per pile: per level from the top to the tip: tags by angle
    piles: list = field(default_factory=list)  # (x, y) of each pile axis
    tip_level: int = 0  # index of the pile tips' level (the last level without a core)
    groups: dict = field(default_factory=dict)  # 'top', 'base', 'outer', 'xmin', 'xmax', 'ymin', 'ymax' -> tags
    axis: list = field(default_factory=list)  # solid_cylinder: centre node by level (n_theta a multiple of 8)
    coords: dict = field(default_factory=dict)  # node tag -> (x, y, z)
    n_theta: int = 0

    def node(self, key, level):
        """Tag of plan point `key` (see Plan) at level index `level`."""
        return self.node_at[(self.plan.label[key], level)]

    @property
    def surface(self):
        """The pile-surface nodes (by level, then angle) of a mesh with one pile."""
        if len(self.surfaces) != 1:
            raise ValueError(f"surface: the mesh has {len(self.surfaces)} piles; use surfaces[pile]")
        return self.surfaces[0]

    def surface_nodes(self, pile=0):
        """Flat list of pile `pile`'s surface nodes, level by level (for contact.pile_interface)."""
        return [t for level in self.surfaces[pile] for t in level]

    @property
    def pile_levels(self):
        """z of the levels along the piles: from the top to the tips."""
        return self.levels[:self.tip_level + 1]


def _levels(where, levels, z_top, z_bottom, n_z, z_ratio):
    if levels is not None:
        if (z_top, z_bottom, n_z) != (None, None, None):
            raise ValueError(f"{where}: give either levels or z_top, z_bottom and n_z, not both")
        levels = [float(z) for z in levels]
    else:
        if None in (z_top, z_bottom, n_z):
            raise ValueError(f"{where}: give levels (z, top to bottom) or z_top, z_bottom and n_z")
        if n_z < 1:
            raise ValueError(f"{where}: n_z must be at least 1, got {n_z}")
        if not z_ratio > 0:
            raise ValueError(f"{where}: z_ratio must be positive, got {z_ratio}")
        levels = graded(float(z_top), float(z_bottom), n_z, z_ratio)
    if len(levels) < 2 or any(b >= a for a, b in zip(levels, levels[1:])):
        raise ValueError(f"{where}: levels must be at least two z values strictly decreasing (top to bottom), "
                         f"got {levels}")
    return levels


def _fill_from(where, levels, core_below):
    """Index of the first level of the filled core (len(levels): no core)."""
    if core_below is None:
        return len(levels)
    tol = 1e-9 * (levels[0] - levels[-1])
    if core_below >= levels[0] - tol:
        return 0
    for k, z in enumerate(levels[:-1]):
        if abs(z - core_below) <= tol:
            return k
    raise ValueError(f"{where}: core_below = {core_below} must be one of the levels above the bottom one "
                     f"(or at or above the top for a block without a hole); levels are {levels}")


def _first_tags(ops, first_node, first_element):
    if first_node is None:
        first_node = max(ops.getNodeTags(), default=0) + 1
    if first_element is None:
        first_element = max(ops.getEleTags(), default=0) + 1
    return first_node, first_element


SOLID_BRICKS = ("stdBrick", "bbarBrick", "SSPbrick")


def _check_element(where, element):
    if element not in SOLID_BRICKS:
        raise ValueError(f"{where}: element must be one of {', '.join(SOLID_BRICKS)} (8-node bricks with the "
                         f"arguments nodes, matTag, b1, b2, b3), got {element!r}")
    return element


def _extrude(ops, plan, levels, fill_from, material_tag, first_node, first_element, body_force, n_theta,
             element="stdBrick"):
    first_node, first_element = _first_tags(ops, first_node, first_element)
    mesh = SoilMesh(plan=plan, levels=list(levels), piles=list(plan.piles), n_theta=n_theta)
    core_only = plan.core_points()
    tag = first_node
    for k, z in enumerate(levels):
        for p, (x, y) in enumerate(plan.points):
            if k < fill_from and p in core_only:
                continue
            ops.node(tag, x, y, z)
            mesh.node_at[(p, k)] = tag
            mesh.nodes.append(tag)
            mesh.coords[tag] = (x, y, z)
            tag += 1
    ele = first_element
    for k in range(len(levels) - 1):
        for q, quad in enumerate(plan.quads):
            if k < fill_from and q in plan.core_quads:
                continue
            # Bottom face (level k + 1, lower z) counterclockwise seen from above, then the top face.
            bottom = [mesh.node_at[(p, k + 1)] for p in quad]
            top = [mesh.node_at[(p, k)] for p in quad]
            ops.element(element, ele, *bottom, *top, material_tag, *body_force)
            mesh.elements.append(ele)
            ele += 1
    last = len(levels) - 1
    mesh.tip_level = min(fill_from, last)
    if fill_from > 0:
        mesh.surfaces = [[[mesh.node_at[(c, k)] for c in circle] for k in range(mesh.tip_level + 1)]
                         for circle in plan.circles]
    else:
        mesh.surfaces = [[] for _ in plan.circles]
    for name, points in plan.groups.items():
        mesh.groups[name] = [mesh.node_at[(p, k)] for k in range(last + 1) for p in points]
    mesh.groups["top"] = [mesh.node_at[(p, 0)] for p in range(len(plan.points)) if (p, 0) in mesh.node_at]
    mesh.groups["base"] = [mesh.node_at[(p, last)] for p in range(len(plan.points)) if (p, last) in mesh.node_at]
    return mesh


def _check_theta(where, n_theta, square):
    if n_theta < 3:
        raise ValueError(f"{where}: n_theta must be at least 3, got {n_theta}")
    if square and n_theta % 4 != 0:
        raise ValueError(f"{where}: n_theta must be a multiple of 4 for a square boundary or a filled core "
                         f"(core_below), got {n_theta}")


def _check_core(where, n_theta, core_fraction, n_core):
    if not 0.0 < core_fraction < 1.0 / math.sqrt(2.0):
        raise ValueError(f"{where}: core_fraction (inner square half-width / pile radius) must lie in "
                         f"(0, 0.707) so that the square fits in the circle, got {core_fraction}")
    if n_core is None:
        n_core = max(1, round((n_theta // 4) * (1.0 - core_fraction) / (2.0 * core_fraction)))
    if n_core < 1:
        raise ValueError(f"{where}: n_core must be at least 1, got {n_core}")
    return n_core


def _check_radial(where, n_radial, radial_ratio):
    if n_radial < 1:
        raise ValueError(f"{where}: n_radial must be at least 1, got {n_radial}")
    if not radial_ratio > 0:
        raise ValueError(f"{where}: radial_ratio must be positive, got {radial_ratio}")


def ogrid(ops, *, pile_radius, outer_size, outer="circle", n_theta=16, n_radial=6, radial_ratio=1.3,
          levels=None, z_top=None, z_bottom=None, n_z=None, z_ratio=1.0, centre=(0.0, 0.0), material_tag=1,
          first_node=None, first_element=None, body_force=(0.0, 0.0, 0.0), core_below=None, core_fraction=0.5,
          n_core=None, element="stdBrick"):
    """O-grid of brick soil around a vertical pile hole of radius `pile_radius`.

    outer='circle': an annulus out to radius `outer_size` (radial spacing graded by
    `radial_ratio` outwards, ring j at graded radii); outer='square': out to a square of
    half-width `outer_size`, ring j on the straight line from circle node i to its square
    node (the square's nodes equally spaced, n_theta / 4 per side; graded by radial_ratio).
    Levels: `levels` (z, top to bottom) or z_top, z_bottom, n_z with `z_ratio` (each layer
    z_ratio times the one above: > 1 is finer at the top). `core_below` = z of a level:
    below it the hole is filled (butterfly core of inner square half-width
    core_fraction * pile_radius and n_core rings), so a pile can end above the base; at or
    above the top level, the block has no hole. The model must be in an ndf-3 state.
    Node and element tags start at first_node / first_element (default: one above the
    largest in use). `element`: 'stdBrick', or 'bbarBrick' / 'SSPbrick' for soil that
    flows at constant volume (J2, undrained clay: docs/solid_elements.md). Returns a
    SoilMesh; groups 'outer' (+ 'xmin' ... for a square), 'top', 'base'.
    """
    where = "ogrid"
    _check_element(where, element)
    if outer not in ("circle", "square"):
        raise ValueError(f"{where}: outer must be 'circle' or 'square', got {outer!r}")
    square = outer == "square" or core_below is not None
    _check_theta(where, n_theta, square)
    _check_radial(where, n_radial, radial_ratio)
    if not pile_radius > 0:
        raise ValueError(f"{where}: pile_radius must be positive, got {pile_radius}")
    if not outer_size > pile_radius:
        raise ValueError(f"{where}: outer_size = {outer_size} puts the outer boundary inside the pile "
                         f"(pile_radius = {pile_radius})")
    levels = _levels(where, levels, z_top, z_bottom, n_z, z_ratio)
    fill_from = _fill_from(where, levels, core_below)
    if outer == "circle":
        plan, _ = _circle_plan(centre, pile_radius, outer_size, n_theta, n_radial, radial_ratio,
                               theta0(n_theta, square))
    else:
        plan = _tile_plan(where, [tuple(centre)], pile_radius, 2.0 * outer_size, n_theta, n_radial, radial_ratio,
                          (0.0,) * 4, (0,) * 4, 1.0)
    if core_below is not None:
        n_core = _check_core(where, n_theta, core_fraction, n_core)
        _add_core(plan, 0, plan.circles[0], n_theta, pile_radius, core_fraction, n_core)
    _check_plan(plan, where, "outer_size is too close to pile_radius for this n_theta / radial_ratio")
    return _extrude(ops, plan, levels, fill_from, material_tag, first_node, first_element, body_force, n_theta,
                    element)


def _four(where, name, value, kind):
    values = tuple(value) if isinstance(value, (tuple, list)) else (value,) * 4
    if len(values) != 4:
        raise ValueError(f"{where}: {name} must be one value or four (xmin, xmax, ymin, ymax), got {value}")
    return tuple(kind(v) for v in values)


def pile_group(ops, *, piles, pile_radius, spacing, n_theta=16, n_radial=4, radial_ratio=1.3, padding=0.0,
               n_padding=4, padding_ratio=1.3, levels=None, z_top=None, z_bottom=None, n_z=None, z_ratio=1.0,
               material_tag=1, first_node=None, first_element=None, body_force=(0.0, 0.0, 0.0), core_below=None,
               core_fraction=0.5, n_core=None, element="stdBrick"):
    """A rectangular soil block around piles on a regular grid of square tiles.

    Each pile (x, y) sits in the centre of a square O-grid tile of side `spacing`
    (n_theta / 4 divisions per side, n_radial rings graded by radial_ratio); piles must be
    whole multiples of `spacing` apart (a row for a bridge bent, or any grid). Tiles share
    their edge nodes; grid cells between piles without a pile are filled with a plain
    block; `padding` (one value or xmin, xmax, ymin, ymax) adds soil beyond the tiles in
    `n_padding` divisions growing outwards by padding_ratio. Levels and core_below as in
    ogrid. `element` as in ogrid. Returns a SoilMesh: surfaces[p] are pile p's surface nodes
    by level then angle; groups 'xmin', 'xmax', 'ymin', 'ymax', 'outer', 'top', 'base'.
    """
    where = "pile_group"
    _check_element(where, element)
    piles = [tuple(float(c) for c in p) for p in piles]
    if not piles or any(len(p) != 2 for p in piles):
        raise ValueError(f"{where}: piles must be a non-empty list of (x, y), got {piles}")
    _check_theta(where, n_theta, True)
    _check_radial(where, n_radial, radial_ratio)
    if not pile_radius > 0:
        raise ValueError(f"{where}: pile_radius must be positive, got {pile_radius}")
    if not spacing > 2.0 * pile_radius:
        raise ValueError(f"{where}: spacing = {spacing} must exceed the pile diameter {2.0 * pile_radius} "
                         "(the tile's boundary would cut the pile)")
    pad = _four(where, "padding", padding, float)
    npad = _four(where, "n_padding", n_padding, int)
    if any(p < 0 for p in pad):
        raise ValueError(f"{where}: padding must not be negative, got {padding}")
    if any(p > 0 and n < 1 for p, n in zip(pad, npad)):
        raise ValueError(f"{where}: n_padding must be at least 1 where padding > 0, got {n_padding}")
    if not padding_ratio > 0:
        raise ValueError(f"{where}: padding_ratio must be positive, got {padding_ratio}")
    levels = _levels(where, levels, z_top, z_bottom, n_z, z_ratio)
    fill_from = _fill_from(where, levels, core_below)
    plan = _tile_plan(where, piles, pile_radius, spacing, n_theta, n_radial, radial_ratio, pad, npad,
                      padding_ratio)
    if core_below is not None:
        n_core = _check_core(where, n_theta, core_fraction, n_core)
        for p in range(len(piles)):
            _add_core(plan, p, plan.circles[p], n_theta, pile_radius, core_fraction, n_core)
    _check_plan(plan, where, "spacing is too close to the pile diameter for this n_theta / radial_ratio")
    return _extrude(ops, plan, levels, fill_from, material_tag, first_node, first_element, body_force, n_theta,
                    element)


def solid_cylinder(ops, *, radius, levels=None, z_top=None, z_bottom=None, n_z=None, z_ratio=1.0, n_theta=16,
                   centre=(0.0, 0.0), core_fraction=0.5, n_core=None, material_tag=1, first_node=None,
                   first_element=None, body_force=(0.0, 0.0, 0.0), element="stdBrick"):
    """A solid circular pile of bricks (butterfly cross-section) with its own nodes.

    The surface nodes have the same coordinates as those of an ogrid / pile_group hole of
    the same radius, n_theta and levels (tie or contact them). Returns a SoilMesh:
    surfaces[0] = surface nodes by level then angle, axis = centre node by level (only
    when n_theta is a multiple of 8: otherwise the inner square has no centre node and
    axis is empty), groups 'outer' (= surface), 'top', 'base' (end faces).
    """
    where = "solid_cylinder"
    _check_element(where, element)
    _check_theta(where, n_theta, True)
    if not radius > 0:
        raise ValueError(f"{where}: radius must be positive, got {radius}")
    n_core = _check_core(where, n_theta, core_fraction, n_core)
    levels = _levels(where, levels, z_top, z_bottom, n_z, z_ratio)
    plan = Plan(piles=[tuple(centre)])
    angle0 = theta0(n_theta, True)
    circle = []
    for i in range(n_theta):
        theta = angle0 + 2.0 * math.pi * i / n_theta
        circle.append(plan.point(("ring", 0, i, 0), (centre[0] + radius * math.cos(theta),
                                                     centre[1] + radius * math.sin(theta))))
    plan.circles.append(circle)
    plan.groups["outer"] = list(circle)
    _add_core(plan, 0, circle, n_theta, radius, core_fraction, n_core)
    plan.core_quads.clear()  # everything exists at every level
    _check_plan(plan, where, "core_fraction / n_core give a degenerate core")
    mesh = _extrude(ops, plan, levels, len(levels), material_tag, first_node, first_element, body_force, n_theta,
                    element)
    mesh.surfaces = [[[mesh.node_at[(c, k)] for c in circle] for k in range(len(levels))]]
    mesh.tip_level = len(levels) - 1
    m = n_theta // 4
    if m % 2 == 0:
        mesh.axis = [mesh.node(("core", 0, m // 2, m // 2), k) for k in range(len(levels))]
    return mesh


# --- beams, supports, the whole pile in soil ------------------------------------------------

@dataclass
class BeamPile:
    """Tags of a pile of beam elements on a vertical axis."""

    nodes: list = field(default_factory=list)  # top to bottom, one per level
    elements: list = field(default_factory=list)  # element k joins nodes k and k + 1
    levels: list = field(default_factory=list)
    transf_tag: int = 0
    axis: tuple = (0.0, 0.0)


def beam_pile(ops, *, x, y, levels, radius, E, G, transf_tag=1, vecxz=(1.0, 0.0, 0.0), A=None, Iy=None,
              Iz=None, J=None, first_node=None, first_element=None, ndf_after=3):
    """elasticBeamColumn pile with one ndf-6 node per level (z, top to bottom) on the axis (x, y).

    Section of a solid circle of `radius` unless A, Iy, Iz, J are given. `vecxz` creates
    geomTransf('Linear', transf_tag, *vecxz) (None: transf_tag exists already). Switches
    the model builder to ndf 6 and back to `ndf_after` (None: leave it at 6).
    """
    where = "beam_pile"
    levels = [float(z) for z in levels]
    if len(levels) < 2 or any(b >= a for a, b in zip(levels, levels[1:])):
        raise ValueError(f"{where}: levels must be at least two z values strictly decreasing, got {levels}")
    if not radius > 0 or not E > 0 or not G > 0:
        raise ValueError(f"{where}: radius, E and G must be positive, got {radius}, {E}, {G}")
    A = math.pi * radius**2 if A is None else A
    Iy = math.pi * radius**4 / 4.0 if Iy is None else Iy
    Iz = math.pi * radius**4 / 4.0 if Iz is None else Iz
    J = Iy + Iz if J is None else J
    first_node, first_element = _first_tags(ops, first_node, first_element)
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    pile = BeamPile(levels=levels, transf_tag=transf_tag, axis=(float(x), float(y)))
    for k, z in enumerate(levels):
        ops.node(first_node + k, x, y, z)
        pile.nodes.append(first_node + k)
    if vecxz is not None:
        ops.geomTransf("Linear", transf_tag, *vecxz)
    for k in range(len(levels) - 1):
        ops.element("elasticBeamColumn", first_element + k, pile.nodes[k], pile.nodes[k + 1], A, E, G, J, Iy, Iz,
                    transf_tag)
        pile.elements.append(first_element + k)
    if ndf_after is not None:
        ops.model("basic", "-ndm", 3, "-ndf", ndf_after)
    return pile


def fix_soil_boundary(ops, mesh, lateral="roller", base="fixed"):
    """The usual supports of a soil block: its sides fixed normal to the boundary
    (lateral='roller'; a circular boundary fixes x and y) or in every direction
    ('fixed'); its base fixed ('fixed') or only vertically ('roller').

    Returns {node tag: [fx, fy, fz]} as passed to fix (one fix per node).
    """
    if lateral not in ("roller", "fixed"):
        raise ValueError(f"fix_soil_boundary: lateral must be 'roller' or 'fixed', got {lateral!r}")
    if base not in ("roller", "fixed"):
        raise ValueError(f"fix_soil_boundary: base must be 'roller' or 'fixed', got {base!r}")
    flags = {}

    def add(tags, dofs):
        for t in tags:
            f = flags.setdefault(t, [0, 0, 0])
            for d in dofs:
                f[d] = 1

    if "xmin" in mesh.groups:
        normal = {"xmin": (0,), "xmax": (0,), "ymin": (1,), "ymax": (1,)}
        for side, dofs in normal.items():
            add(mesh.groups[side], (0, 1, 2) if lateral == "fixed" else dofs)
    else:
        add(mesh.groups["outer"], (0, 1, 2) if lateral == "fixed" else (0, 1))
    add(mesh.groups["base"], (0, 1, 2) if base == "fixed" else (2,))
    for t, f in flags.items():
        ops.fix(t, *f)
    return flags


@dataclass
class PileInSoil:
    """Tags of pile_in_soil: the soil O-grid, the beam pile and their contact interface."""

    soil: SoilMesh
    pile: BeamPile
    interface: object  # contact.PileInterface
    fixed: dict  # soil node tag -> fix flags


def pile_in_soil(ops, *, pile_radius, outer_size, pile_E, pile_G, soil_material, contact_material, outer="circle",
                 pile_tip=None, levels=None, z_top=None, z_bottom=None, n_z=None, z_ratio=1.0, n_theta=16,
                 n_radial=6, radial_ratio=1.3, centre=(0.0, 0.0), body_force=(0.0, 0.0, 0.0), lateral="roller",
                 base="fixed", transf_tag=1, vecxz=(1.0, 0.0, 0.0), penalty=None, gap_tol=1e-8, force_tol=1e-8,
                 first_node=None, first_element=None):
    """A beam pile in an O-grid of soil, supported and joined by a chained contact interface.

    Builds (ndf 3) ogrid with core_below = pile_tip (None: the pile runs down to the
    base), fix_soil_boundary(lateral, base), the beam_pile on the axis with one node per
    soil level from the top to the tip (section of a solid circle, pile_E, pile_G), and
    contact.pile_interface over every pile-surface soil node (Lagrange multipliers, or
    BeamContact3Dp with `penalty`). soil_material (nDMaterial) and contact_material
    (ContactMaterial3D) must exist. The pile is left free: fix or load it as the problem
    needs. Leaves the model builder at ndf 3.
    """
    levels = _levels("pile_in_soil", levels, z_top, z_bottom, n_z, z_ratio)
    if pile_tip is not None and _fill_from("pile_in_soil", levels, pile_tip) == 0:
        raise ValueError(f"pile_in_soil: pile_tip = {pile_tip} is at or above the top level {levels[0]}: no pile")
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    soil = ogrid(ops, pile_radius=pile_radius, outer_size=outer_size, outer=outer, n_theta=n_theta,
                 n_radial=n_radial, radial_ratio=radial_ratio, levels=levels, centre=centre,
                 material_tag=soil_material, first_node=first_node, first_element=first_element,
                 body_force=body_force, core_below=pile_tip)
    fixed = fix_soil_boundary(ops, soil, lateral, base)
    pile = beam_pile(ops, x=centre[0], y=centre[1], levels=soil.pile_levels, radius=pile_radius, E=pile_E,
                     G=pile_G, transf_tag=transf_tag, vecxz=vecxz)
    iface = pile_interface(ops, pile.nodes, soil.surface_nodes(), pile_radius, transf_tag, contact_material,
                           gap_tol=gap_tol, force_tol=force_tol, penalty=penalty)
    return PileInSoil(soil=soil, pile=pile, interface=iface, fixed=fixed)


# --- the paper's donut ---------------------------------------------------------------------

@dataclass
class DonutMesh:
    """Tags of an annular (O-grid) soil mesh around a vertical pile axis."""

    nodes: dict = field(default_factory=dict)  # (i_theta, i_r, i_z) -> node tag
    elements: list = field(default_factory=list)
    inner_nodes: list = field(default_factory=list)  # on the pile surface, by level then angle
    outer_nodes: list = field(default_factory=list)
    base_nodes: list = field(default_factory=list)
    top_nodes: list = field(default_factory=list)
    levels: list = field(default_factory=list)  # z of each node level, top to bottom
    n_theta: int = 0
    radii: list = field(default_factory=list)


def donut(ops, *, inner_radius, outer_radius, z_top, z_bottom, n_theta=16, n_radial=4, n_z=10,
          radial_ratio=1.3, centre=(0.0, 0.0), material_tag=1, first_node=1, first_element=1,
          body_force=(0.0, 0.0, 0.0)):
    """An annulus of 8-node bricks from inner_radius to outer_radius (the paper's donut).

    The circular ogrid with n_z equal layers, in the donut's own terms. Nodes are
    numbered from `first_node`, elements from `first_element`. The model must be in an
    ndf-3 state (``model('basic', '-ndm', 3, '-ndf', 3)``). Radial spacing grows by
    `radial_ratio` outwards (finer near the pile).
    """
    if not (0 < inner_radius < outer_radius):
        raise ValueError("need 0 < inner_radius < outer_radius")
    if z_top <= z_bottom:
        raise ValueError("need z_top > z_bottom")
    if n_theta < 3:
        raise ValueError("n_theta must be at least 3")
    levels = [z_top + (z_bottom - z_top) * k / n_z for k in range(n_z + 1)]
    m = ogrid(ops, pile_radius=inner_radius, outer_size=outer_radius, outer="circle", n_theta=n_theta,
              n_radial=n_radial, radial_ratio=radial_ratio, levels=levels, centre=centre, material_tag=material_tag,
              first_node=first_node, first_element=first_element, body_force=body_force)
    mesh = DonutMesh(n_theta=n_theta, elements=m.elements, levels=m.levels,
                     radii=graded(inner_radius, outer_radius, n_radial, radial_ratio))
    for k in range(n_z + 1):
        for j in range(n_radial + 1):
            for i in range(n_theta):
                mesh.nodes[(i, j, k)] = m.node(("ring", 0, i, j), k)
    mesh.inner_nodes = m.surface_nodes()
    mesh.outer_nodes = m.groups["outer"]
    mesh.top_nodes, mesh.base_nodes = m.groups["top"], m.groups["base"]
    return mesh


def plot_plan(mesh, ax=None, **style):
    """Draw the plan (a Plan, or a SoilMesh's plan) with matplotlib; core quads dashed."""
    import matplotlib.pyplot as plt

    plan = mesh.plan if isinstance(mesh, SoilMesh) else mesh
    if ax is None:
        ax = plt.gca()
    for q, quad in enumerate(plan.quads):
        xy = [plan.points[p] for p in quad + quad[:1]]
        core = q in plan.core_quads
        ax.plot([p[0] for p in xy], [p[1] for p in xy], lw=0.6, color=style.get("color", "k"),
                ls="--" if core else "-", alpha=0.6 if core else 1.0)
    for circle in plan.circles:
        xy = [plan.points[p] for p in circle + circle[:1]]
        ax.plot([p[0] for p in xy], [p[1] for p in xy], lw=1.5, color=style.get("pile_color", "tab:red"))
    ax.set_aspect("equal")
    return ax

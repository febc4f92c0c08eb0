"""Wave boundaries for soil meshes of bricks: viscous (Lysmer-Kuhlemeyer)
dashpots, a compliant (elastic) bedrock, tied lateral sides and a free-field
soil column.

Every function acts only through the OpenSees command interface passed in as
``ops`` (``node``, ``fix``, ``equalDOF``, ``uniaxialMaterial('Viscous')``,
``element('zeroLength'|'stdBrick')``, ``timeSeries('Path')``, ``pattern``,
``load``, ``nodeCoord``, ``nodeDisp``), so a script that uses them runs the same
with ``beamsolid.opensees`` and with ``openseespy.opensees``. The module needs
numpy only. Models are 3D (``-ndm 3``), soil nodes of ndf 3 or more.

New objects take their tags from a :class:`Tags` counter (the first free tag of
each kind); every function returns the tags it created. Units are the model's.
See docs/dynamics.md for the formulas and a worked example.
"""
import math

import numpy as np

__all__ = ["Tags", "wave_speeds", "brick_faces", "face_areas", "viscous_boundary", "compliant_base", "tie_levels",
           "tie_periodic", "free_field_column", "attach_free_field"]


class Tags:
    """The next free tag of each kind; the helpers take tags from it in order."""

    def __init__(self, node=1, element=1, material=1, series=1, pattern=1):
        self._next = {"node": node, "element": element, "material": material, "series": series,
                      "pattern": pattern}

    def take(self, kind):
        tag = self._next[kind]
        self._next[kind] = tag + 1
        return tag


def wave_speeds(E, nu, rho):
    """(Vp, Vs) of an isotropic elastic solid: Vs = sqrt(G / rho) and
    Vp = sqrt((lambda + 2 G) / rho), the constrained-modulus (P-wave) speed."""
    if not (E > 0.0 and rho > 0.0 and -1.0 < nu < 0.5):
        raise ValueError("wave_speeds: need E > 0, rho > 0 and -1 < nu < 0.5")
    G = E / (2.0 * (1.0 + nu))
    M = E * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu))
    return math.sqrt(M / rho), math.sqrt(G / rho)


# The six faces of a stdBrick by local node (bottom 1-4 and top 5-8, each counterclockwise).
_BRICK_FACES = ((0, 1, 2, 3), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7))


def brick_faces(ops, elements, axis, value, tol=1e-6):
    """The 4-node faces of the given 8-node bricks (``eleNodes``) that lie in
    the plane where coordinate ``axis`` (1, 2 or 3) equals ``value``: the
    input of :func:`viscous_boundary` or :func:`compliant_base` for a side or
    the base of a brick mesh."""
    if axis not in (1, 2, 3):
        raise ValueError("brick_faces: axis is 1, 2 or 3")
    faces = []
    for e in elements:
        nodes = ops.eleNodes(e)
        if len(nodes) != 8:
            raise ValueError(f"brick_faces: element {e} does not have 8 nodes")
        on = [abs(ops.nodeCoord(n)[axis - 1] - value) <= tol for n in nodes]
        for face in _BRICK_FACES:
            if all(on[i] for i in face):
                faces.append([nodes[i] for i in face])
    return faces


_GAUSS = (-1.0 / math.sqrt(3.0), 1.0 / math.sqrt(3.0))


def face_areas(ops, faces):
    """Tributary area vectors of the nodes of 4-node faces: for each node a,
    the integral of N_a n dA over the faces that hold it (bilinear faces,
    2 x 2 Gauss; n the unit normal, oriented by the node order n1 -> n2 -> n3
    by the right-hand rule). Returns {node: area vector (numpy, 3)}."""
    out = {}
    for face in faces:
        if len(face) != 4:
            raise ValueError(f"face_areas: a face has 4 nodes, got {face!r}")
        x = np.array([ops.nodeCoord(n) for n in face], dtype=float)
        if x.shape[1] != 3:
            raise ValueError("face_areas: the model must be 3D (-ndm 3)")
        for xi in _GAUSS:
            for eta in _GAUSS:
                N = 0.25 * np.array([(1 - xi) * (1 - eta), (1 + xi) * (1 - eta), (1 + xi) * (1 + eta),
                                     (1 - xi) * (1 + eta)])
                dxi = 0.25 * np.array([-(1 - eta), (1 - eta), (1 + eta), -(1 + eta)]) @ x
                deta = 0.25 * np.array([-(1 - xi), -(1 + xi), (1 + xi), (1 - xi)]) @ x
                da = np.cross(dxi, deta)  # n dA per unit d(xi) d(eta)
                for a, n in enumerate(face):
                    out[n] = out.get(n, np.zeros(3)) + N[a] * da
    return out


def _dashpot_tensors(ops, faces, nodes, rho, vp, vs):
    """{node: C} with C = rho (Vp n n^T + Vs (I - n n^T)) |A| summed over the
    node's faces (or its given area vectors)."""
    areas = {}
    if faces:
        areas.update(face_areas(ops, faces))
    for n, a in (nodes or {}).items():
        areas[n] = areas.get(n, np.zeros(3)) + np.asarray(a, dtype=float)
    if not areas:
        raise ValueError("viscous_boundary: no faces and no nodes given")
    tensors = {}
    for n, a in areas.items():
        area = float(np.linalg.norm(a))
        if area == 0.0:
            continue
        nn = np.outer(a, a) / area**2
        tensors[n] = tensors.get(n, 0.0) + rho * area * (vp * nn + vs * (np.eye(3) - nn))
    return tensors


def viscous_boundary(ops, tags, rho, vp, vs, faces=None, nodes=None):
    """Lysmer-Kuhlemeyer dashpots on boundary nodes.

    ``faces``: 4-node faces of the boundary (any orientation); ``nodes``:
    {node: area vector} (tributary area times the unit normal) for nodes without
    faces. A node of area A and normal n gets the dashpot tensor
    C = rho A (Vp n n^T + Vs (I - n n^T)) (summed where faces of different
    planes meet), placed as one zeroLength from a new fixed node at the same
    coordinates, oriented along C's principal axes, with one
    ``Viscous(c, 1)`` per non-zero principal value. Pass vp = 0 (or vs = 0) to
    leave the normal (tangential) directions free.

    Returns {'nodes', 'elements', 'materials': new tags,
    'dashpots': {boundary node: (fixed node, element)}, 'tensors': {node: C}}.
    """
    if not (rho > 0.0 and vp >= 0.0 and vs >= 0.0 and vp + vs > 0.0):
        raise ValueError("viscous_boundary: need rho > 0, vp >= 0, vs >= 0, not both 0")
    tensors = _dashpot_tensors(ops, faces, nodes, rho, vp, vs)
    created = {"nodes": [], "elements": [], "materials": [], "dashpots": {}, "tensors": tensors}
    materials = {}
    for n in sorted(tensors):
        C = tensors[n]
        values, vectors = np.linalg.eigh(C)
        keep = [i for i in range(3) if values[i] > 1e-12 * values.max()]
        if not keep:
            continue
        # Local x along the largest principal value, y along the next; the
        # zeroLength's z = x cross y is the third eigenvector up to its sign.
        order = sorted(keep, key=lambda i: -values[i])
        x_axis = vectors[:, order[0]]
        y_axis = vectors[:, order[1]] if len(order) > 1 else _perpendicular(x_axis)
        local = {i: k + 1 for k, i in enumerate(order)}
        mats, dirs = [], []
        for i in order:
            c = float(values[i])
            if c not in materials:
                materials[c] = tags.take("material")
                ops.uniaxialMaterial("Viscous", materials[c], c, 1.0)
                created["materials"].append(materials[c])
            mats.append(materials[c])
            dirs.append(local[i])
        crd = ops.nodeCoord(n)
        ndf = len(ops.nodeDisp(n))
        fixed = tags.take("node")
        ops.node(fixed, *crd, "-ndf", ndf)
        ops.fix(fixed, *([1] * ndf))
        ele = tags.take("element")
        ops.element("zeroLength", ele, fixed, n, "-mat", *mats, "-dir", *dirs,
                    "-orient", *map(float, x_axis), *map(float, y_axis))
        created["nodes"].append(fixed)
        created["elements"].append(ele)
        created["dashpots"][n] = (fixed, ele)
    return created


def _perpendicular(v):
    w = np.array([1.0, 0.0, 0.0]) if abs(v[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    w = w - (w @ v) * v
    return w / np.linalg.norm(w)


def compliant_base(ops, tags, rho, vp, vs, record, dt, direction=1, kind="vel", incident=False,
                   faces=None, nodes=None, factor=1.0):
    """An elastic bedrock under the mesh (Joyner and Chen 1975).

    The rock half-space below a base node of area A acts on it as the dashpot
    C = rho A (Vp n n^T + Vs (I - n n^T)) (rock properties) plus the force
    2 C v_inc(t), v_inc the velocity of the wave coming up through the rock.
    A record on rock outcrop is twice the incident wave, so the force is
    C v_outcrop: ``record`` is the outcrop motion unless ``incident=True``.

    ``record``: values at t = 0, dt, 2 dt, ... of the velocity (``kind='vel'``)
    or acceleration (``kind='accel'``, integrated by the trapezoidal rule from
    v(0) = 0, the rule OpenSees uses for ground motions), times ``factor``,
    along the global ``direction`` (1, 2 or 3; a vertical record on a
    horizontal base is a P wave and gets rho Vp). Several components at once:
    ``record={1: values_x, 2: values_y, ...}`` (``direction`` is then unused).
    The dashpots are made once by :func:`viscous_boundary`; each component's
    force goes to a new ``Path`` series (``-dt``, ``-useLast``: after the
    record the velocity keeps its last value, as the ground does when the
    acceleration ends) in a new ``Plain`` pattern.

    Returns what :func:`viscous_boundary` returns plus 'series', 'pattern'
    and 'velocity', each {direction: tag or velocity values}.
    """
    if kind not in ("vel", "accel"):
        raise ValueError("compliant_base: kind is 'vel' or 'accel'")
    records = record if isinstance(record, dict) else {direction: record}
    if not records or any(d not in (1, 2, 3) for d in records):
        raise ValueError("compliant_base: direction is 1, 2 or 3")
    if not dt > 0.0 or any(len(r) < 2 for r in records.values()):
        raise ValueError("compliant_base: need dt > 0 and a record of at least two values")
    velocities = {}
    for d, r in records.items():
        values = np.asarray(r, dtype=float) * factor
        if kind == "accel":
            velocity = np.zeros_like(values)
            velocity[1:] = np.cumsum(0.5 * dt * (values[1:] + values[:-1]))
        else:
            velocity = values
        velocities[d] = velocity
    created = viscous_boundary(ops, tags, rho, vp, vs, faces=faces, nodes=nodes)
    scale = 2.0 if incident else 1.0
    series_tags, pattern_tags = {}, {}
    for d in sorted(velocities):
        series = tags.take("series")
        ops.timeSeries("Path", series, "-dt", dt, "-values", *map(float, velocities[d]), "-useLast")
        pattern = tags.take("pattern")
        ops.pattern("Plain", pattern, series)
        for n in sorted(created["tensors"]):
            force = scale * created["tensors"][n][:, d - 1]
            ndf = len(ops.nodeDisp(n))
            ops.load(n, *map(float, force), *([0.0] * (ndf - 3)))
        series_tags[d], pattern_tags[d] = series, pattern
    created.update(series=series_tags, pattern=pattern_tags, velocity=velocities)
    return created


def _levels(ops, nodes, axis, tol):
    """Nodes grouped by their coordinate along ``axis`` (1-based): {z: [nodes]}."""
    groups = []
    for n in sorted(nodes):
        z = ops.nodeCoord(n)[axis - 1]
        for g in groups:
            if abs(g[0] - z) <= tol:
                g[1].append(n)
                break
        else:
            groups.append((z, [n]))
    return {z: members for z, members in sorted(groups)}


def tie_levels(ops, nodes, dofs=(1, 2, 3), axis=3, tol=1e-6):
    """Ties all given nodes at the same height (coordinate ``axis``, within
    ``tol``) to the one of lowest tag by ``equalDOF`` in ``dofs``: the lateral
    sides of a one-element-wide soil column move together, as in a layer of
    infinite extent. Fixed nodes must not be passed (a fixed dof cannot also
    be constrained). Returns {height: retained node}."""
    retained = {}
    for z, members in _levels(ops, nodes, axis, tol).items():
        retained[z] = members[0]
        for n in members[1:]:
            ops.equalDOF(members[0], n, *dofs)
    return retained


def tie_periodic(ops, side_a, side_b, dofs=(1, 2, 3), tol=1e-6):
    """Periodic lateral sides: each node of ``side_b`` follows the node of
    ``side_a`` that has the same coordinates except along the axis that
    separates the two sides (equalDOF, retained node in side_a). Returns
    [(retained, constrained)]."""
    xa = {n: np.array(ops.nodeCoord(n), dtype=float) for n in side_a}
    xb = {n: np.array(ops.nodeCoord(n), dtype=float) for n in side_b}
    if not xa or not xb:
        raise ValueError("tie_periodic: both sides need nodes")
    axis = int(np.argmax(np.abs(np.mean(list(xb.values()), 0) - np.mean(list(xa.values()), 0))))
    other = [i for i in range(len(next(iter(xa.values())))) if i != axis]
    pairs = []
    for nb in sorted(xb):
        match = [na for na in sorted(xa) if np.all(np.abs(xa[na][other] - xb[nb][other]) <= tol)]
        if len(match) != 1:
            raise ValueError(f"tie_periodic: node {nb} has {len(match)} partners on the other side")
        ops.equalDOF(match[0], nb, *dofs)
        pairs.append((match[0], nb))
    return pairs


def free_field_column(ops, tags, heights, materials, x, y, width, base="fixed", body=None):
    """A separate one-element-wide column of stdBricks that computes the free
    field: nodes at the four corners of a ``width`` x ``width`` square centred
    on (x, y) at each of ``heights`` (bottom to top), brick k between heights k
    and k + 1 made of nDMaterial ``materials[k]`` (the layering of the main
    mesh), levels tied by :func:`tie_levels` in dofs 1, 2, 3. Make ``width``
    large (mass and stiffness grow as width^2, the wave speeds do not) so that
    the main mesh attached to it by :func:`attach_free_field` barely moves it.
    ``base='fixed'`` fixes the bottom nodes; ``'free'`` leaves them for
    :func:`compliant_base` / :func:`viscous_boundary` (faces: 'base_face');
    ``'rollers'`` fixes them vertically and ties them in dofs 1, 2 only (a
    base on horizontal dashpots that carries gravity; the vertical is fixed on
    every base node rather than on the retained one, since OpenSeesPy's
    Transformation handler moves nodes tied in a dof wrongly in transient runs
    when their retained node is fixed in it).
    ``body=(b1, b2, b3)``: the bricks' body force per unit volume (as the
    main mesh's, e.g. (0, 0, -rho g) for gravity).

    Returns {'levels': {height: retained node}, 'nodes', 'elements',
    'base_nodes', 'base_face', 'area'}."""
    heights = [float(z) for z in heights]
    if len(heights) < 2 or any(b <= a for a, b in zip(heights, heights[1:])):
        raise ValueError("free_field_column: heights must rise, at least two")
    if len(materials) != len(heights) - 1:
        raise ValueError("free_field_column: one material per brick (len(heights) - 1)")
    if base not in ("fixed", "free", "rollers"):
        raise ValueError("free_field_column: base is 'fixed', 'free' or 'rollers'")
    if not width > 0.0:
        raise ValueError("free_field_column: width must be > 0")
    h = 0.5 * width
    corners = [(x - h, y - h), (x + h, y - h), (x + h, y + h), (x - h, y + h)]
    rings = []
    for z in heights:
        ring = []
        for cx, cy in corners:
            n = tags.take("node")
            ops.node(n, cx, cy, z, "-ndf", 3)
            ring.append(n)
        rings.append(ring)
    elements = []
    for k, mat in enumerate(materials):
        e = tags.take("element")
        ops.element("stdBrick", e, *rings[k], *rings[k + 1], mat, *(body or ()))
        elements.append(e)
    levels = tie_levels(ops, [n for ring in rings[1:] for n in ring], (1, 2, 3))
    if base == "fixed":
        for n in rings[0]:
            ops.fix(n, 1, 1, 1)
        levels[heights[0]] = rings[0][0]
    else:
        if base == "rollers":
            for n in rings[0]:
                ops.fix(n, 0, 0, 1)
        levels.update(tie_levels(ops, rings[0], (1, 2) if base == "rollers" else (1, 2, 3)))
    levels = dict(sorted(levels.items()))
    return {"levels": levels, "nodes": [n for r in rings for n in r], "elements": elements,
            "base_nodes": rings[0], "base_face": rings[0], "area": width * width}


def attach_free_field(ops, levels, nodes, dofs=(1, 2, 3), axis=3, tol=1e-6):
    """The far boundary follows the free field: each of ``nodes`` is tied by
    equalDOF in ``dofs`` to the free-field column's node at its height
    (``levels`` from :func:`free_field_column`). Leave out fixed nodes.

    The default ties the vertical dof too: a vertically travelling shear wave
    needs the complementary shear tau_zx on the lateral faces, and a face that
    is free vertically lets the mesh rock (tests/python/test_shear_column.py:
    with dofs=(1, 2) the surface motion at the centre of a box 1.5 H wide is
    49 % off the free field, of one 12 H wide 1.7 %; with all three dofs it is
    the free field). Returns [(retained, constrained)]."""
    pairs = []
    heights = sorted(levels)
    for n in sorted(nodes):
        z = ops.nodeCoord(n)[axis - 1]
        match = [zz for zz in heights if abs(zz - z) <= tol]
        if not match:
            raise ValueError(f"attach_free_field: no free-field node at the height {z} of node {n}")
        ops.equalDOF(levels[match[0]], n, *dofs)
        pairs.append((levels[match[0]], n))
    return pairs

"""Pile-level beam-solid contact: one contact element per soil node, chained along the pile.

``pile_interface`` builds the interface between a pile (beam nodes on its axis, in order)
and the soil nodes on its surface: one BeamContact3D (Lagrange multiplier, with its own
multiplier node) or BeamContact3Dp (penalty) per soil node, on the segment the node
projects onto, with the ``'-pile'`` chain so that a node sliding past a beam node is handed
over to the neighbouring segment instead of being released (docs/beam_contact.md).
``interface_forces`` sums what the interface carries.

Both work through the given command module (``beamsolid.opensees`` or a
``beamsolid.Model``).
"""
import math
from dataclasses import dataclass, field

__all__ = ["PileInterface", "InterfaceForces", "pile_interface", "interface_forces"]


@dataclass
class PileInterface:
    """Tags of a pile interface built by :func:`pile_interface`."""

    elements: list = field(default_factory=list)  # contact element tags, in soil-node order
    multiplier_nodes: list = field(default_factory=list)  # Lagrange form; empty for the penalty form
    element_of: dict = field(default_factory=dict)  # soil node tag -> contact element tag
    segment_of: dict = field(default_factory=dict)  # soil node tag -> (iNode, jNode) at creation
    pile_nodes: list = field(default_factory=list)
    element_type: str = "BeamContact3D"
    chained: bool = True


@dataclass
class InterfaceForces:
    """What the interface carries at the last update (the converged state after ``analyze``)."""

    normal: float  # sum of the normal forces (compression +)
    friction: tuple  # sum of the friction forces on the soil nodes (global x, y, z)
    friction_magnitude: float  # sum of the friction force magnitudes
    in_contact: int  # elements in contact (sticking or sliding)
    sliding: int
    released: int  # elements out of contact
    hand_overs: int  # hand-overs to neighbouring segments since the start, all elements


def _coords(ops, tag):
    """Current position of a node (coordinates plus translations)."""
    x = ops.nodeCoord(tag)
    u = ops.nodeDisp(tag)
    return [x[i] + u[i] for i in range(3)]


def _segment_parameter(p, a, b):
    """Chord parameter t of the closest point to p on the line a-b, and the distance to it."""
    ab = [b[i] - a[i] for i in range(3)]
    length2 = sum(c * c for c in ab)
    t = sum((p[i] - a[i]) * ab[i] for i in range(3)) / length2
    foot = [a[i] + t * ab[i] for i in range(3)]
    return t, math.dist(p, foot), math.sqrt(length2)


def _is_beamsolid(ops):
    """True for a beamsolid.Model or the beamsolid.opensees module, False for OpenSeesPy."""
    module = ops.__name__ if isinstance(ops, type(math)) else type(ops).__module__
    return module.startswith("beamsolid")


def pile_interface(ops, pile_nodes, soil_nodes, radius, transf_tag, mat_tag, *, gap_tol=1e-8, force_tol=1e-8,
                   penalty=None, first_element=None, first_node=None, c_switch=0, chain=None,
                   bounds_tol=1e-9):
    """One contact element per soil node between a pile and the soil around it.

    pile_nodes: the pile's beam nodes (ndf 6) in order along its axis; soil_nodes: the solid
    nodes (ndf 3) on the pile surface. Each soil node gets a contact element on the segment
    nearest to it (its projection onto the segment's chord), including nodes exactly level
    with a beam node (such a node goes to the segment that starts there, a node level with
    the pile's last node to the last segment; the element refines this on the deformed pile). ``penalty=None`` gives BeamContact3D with one multiplier node (ndf 3,
    at the soil node's position) per soil node, numbered from ``first_node``;
    otherwise BeamContact3Dp with that penalty. Elements are numbered from ``first_element``.
    Defaults: one above the largest node / element tag in use.

    ``chain=False`` builds the paper's single-segment elements (no ``'-pile'``), which
    release a node once it slides off its segment, and which never hold a node level with a
    beam node -- for comparison only.

    Raises ValueError for a soil node that projects onto no segment (beyond the pile's ends by
    more than ``bounds_tol`` of a segment length), a soil node on the pile axis, or bad lists.
    """
    pile_nodes = [int(t) for t in pile_nodes]
    soil_nodes = [int(t) for t in soil_nodes]
    if len(pile_nodes) < 2:
        raise ValueError(f"pile_interface: pile_nodes needs at least two beam nodes, got {len(pile_nodes)}")
    if len(set(pile_nodes)) != len(pile_nodes):
        raise ValueError("pile_interface: pile_nodes lists a node twice")
    if len(set(soil_nodes)) != len(soil_nodes):
        raise ValueError("pile_interface: soil_nodes lists a node twice")
    both = set(pile_nodes) & set(soil_nodes)
    if both:
        raise ValueError(f"pile_interface: node {min(both)} is both a pile node and a soil node")
    if not radius > 0:
        raise ValueError(f"pile_interface: radius must be positive, got {radius}")
    if penalty is not None and not penalty > 0:
        raise ValueError(f"pile_interface: penalty must be positive (or None for Lagrange multipliers), got {penalty}")
    if c_switch not in (0, 1):
        raise ValueError(f"pile_interface: c_switch must be 0 (in contact) or 1 (not), got {c_switch}")
    if chain is None:  # '-pile' is BeamSolid's: leave it out when the commands are OpenSees' own
        chain = _is_beamsolid(ops)
    if first_element is None:
        first_element = max(ops.getEleTags(), default=0) + 1
    if first_node is None:
        first_node = max(ops.getNodeTags(), default=0) + 1

    pile_xyz = [_coords(ops, t) for t in pile_nodes]
    n_segments = len(pile_nodes) - 1
    for k in range(n_segments):
        if math.dist(pile_xyz[k], pile_xyz[k + 1]) == 0.0:
            raise ValueError(f"pile_interface: pile nodes {pile_nodes[k]} and {pile_nodes[k + 1]} coincide")
    iface = PileInterface(pile_nodes=list(pile_nodes), element_type="BeamContact3D" if penalty is None
                          else "BeamContact3Dp", chained=chain)
    assignments = []
    for s in soil_nodes:
        p = _coords(ops, s)
        # The segment nearest to the node (distance to the finite chord); of two equally near
        # ones (a node level with an interior beam node) the one that starts there.
        best = None  # (distance, segment, t)
        for k in range(n_segments):
            a, b = pile_xyz[k], pile_xyz[k + 1]
            t, _, _ = _segment_parameter(p, a, b)
            tc = min(max(t, 0.0), 1.0)
            distance = math.dist(p, [a[i] + tc * (b[i] - a[i]) for i in range(3)])
            if best is None or distance <= best[0] + 1e-12 * radius:
                best = (distance, k, t)
        distance, k, t = best
        if (k == 0 and t < -bounds_tol) or (k == n_segments - 1 and t > 1.0 + bounds_tol):
            raise ValueError(f"pile_interface: soil node {s} at {tuple(p)} projects onto no segment of the pile "
                             f"{pile_nodes[0]}..{pile_nodes[-1]} (it lies beyond the pile's ends)")
        if distance <= 1e-9 * radius:
            raise ValueError(f"pile_interface: soil node {s} at {tuple(p)} lies on the pile axis; "
                             "the contact normal is undefined")
        assignments.append((s, k, p))

    ele, lnode = first_element, first_node
    pile_args = ["-pile", *pile_nodes] if chain else []
    for s, k, p in assignments:
        i, j = pile_nodes[k], pile_nodes[k + 1]
        if penalty is None:
            ops.node(lnode, *p, "-ndf", 3)
            ops.element("BeamContact3D", ele, i, j, s, lnode, radius, transf_tag, mat_tag, gap_tol, force_tol,
                        c_switch, *pile_args)
            iface.multiplier_nodes.append(lnode)
            lnode += 1
        else:
            ops.element("BeamContact3Dp", ele, i, j, s, radius, transf_tag, mat_tag, penalty, c_switch, *pile_args)
        iface.elements.append(ele)
        iface.element_of[s] = ele
        iface.segment_of[s] = (i, j)
        ele += 1
    return iface


def interface_forces(ops, iface):
    """Sums of the interface's normal and friction forces and its status counts (eleResponse)."""
    normal, magnitude = 0.0, 0.0
    friction = [0.0, 0.0, 0.0]
    in_contact = sliding = released = hand_overs = 0
    for e in iface.elements:
        status = int(ops.eleResponse(e, "status")[0])
        normal += ops.eleResponse(e, "forcescalar")[0]
        f = ops.eleResponse(e, "soilFrictionForce")
        for i in range(3):
            friction[i] += f[i]
        magnitude += math.sqrt(sum(c * c for c in f))
        hand_overs += int(ops.eleResponse(e, "handovers")[0])
        if status == 0:
            released += 1
        else:
            in_contact += 1
            sliding += status == 2
    return InterfaceForces(normal=normal, friction=tuple(friction), friction_magnitude=magnitude,
                           in_contact=in_contact, sliding=sliding, released=released, hand_overs=hand_overs)

"""Structured hexahedral soil meshes that honour a pile.

Soil nodes on the pile surface lie exactly on the circle of the pile radius,
so the beam-solid contact measures gaps from the true surface; beam nodes lie
on the axis. Every function creates nodes and stdBrick elements through the
given command module (``beamsolid.opensees`` or a ``beamsolid.Model``) and
returns the tags a script needs.
"""
import math
from dataclasses import dataclass, field


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


def donut(ops, *, inner_radius, outer_radius, z_top, z_bottom, n_theta=16, n_radial=4, n_z=10,
          radial_ratio=1.3, centre=(0.0, 0.0), material_tag=1, first_node=1, first_element=1,
          body_force=(0.0, 0.0, 0.0)):
    """An annulus of 8-node bricks from inner_radius to outer_radius.

    Nodes are numbered from `first_node`, elements from `first_element`. The
    model must be in an ndf-3 state (``model('basic', '-ndm', 3, '-ndf', 3)``).
    Radial spacing grows by `radial_ratio` outwards (finer near the pile).
    """
    if not (0 < inner_radius < outer_radius):
        raise ValueError("need 0 < inner_radius < outer_radius")
    if z_top <= z_bottom:
        raise ValueError("need z_top > z_bottom")
    if n_theta < 3:
        raise ValueError("n_theta must be at least 3")
    mesh = DonutMesh(n_theta=n_theta)
    mesh.radii = graded(inner_radius, outer_radius, n_radial, radial_ratio)
    mesh.levels = [z_top + (z_bottom - z_top) * k / n_z for k in range(n_z + 1)]
    tag = first_node
    for k, z in enumerate(mesh.levels):
        for j, r in enumerate(mesh.radii):
            for i in range(n_theta):
                theta = 2.0 * math.pi * i / n_theta
                ops.node(tag, centre[0] + r * math.cos(theta), centre[1] + r * math.sin(theta), z)
                mesh.nodes[(i, j, k)] = tag
                tag += 1
    for k in range(n_z + 1):
        mesh.inner_nodes.extend(mesh.nodes[(i, 0, k)] for i in range(n_theta))
        mesh.outer_nodes.extend(mesh.nodes[(i, n_radial, k)] for i in range(n_theta))
    mesh.top_nodes = [mesh.nodes[(i, j, 0)] for j in range(n_radial + 1) for i in range(n_theta)]
    mesh.base_nodes = [mesh.nodes[(i, j, n_z)] for j in range(n_radial + 1) for i in range(n_theta)]
    ele = first_element
    for k in range(n_z):
        for j in range(n_radial):
            for i in range(n_theta):
                ip = (i + 1) % n_theta
                # Bottom face (k + 1, lower z) counterclockwise seen from above, then the top face.
                bottom = [mesh.nodes[(i, j, k + 1)], mesh.nodes[(i, j + 1, k + 1)],
                          mesh.nodes[(ip, j + 1, k + 1)], mesh.nodes[(ip, j, k + 1)]]
                top = [mesh.nodes[(i, j, k)], mesh.nodes[(i, j + 1, k)],
                       mesh.nodes[(ip, j + 1, k)], mesh.nodes[(ip, j, k)]]
                ops.element("stdBrick", ele, *bottom, *top, material_tag, *body_force)
                mesh.elements.append(ele)
                ele += 1
    return mesh

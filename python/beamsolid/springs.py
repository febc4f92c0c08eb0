"""p-y, t-z and q-z springs along a beam pile, from a layered soil profile, in one call.

:func:`pile_springs` walks the nodes of an existing beam pile, gives each node below
the ground surface a fixed twin node and a zeroLength element with
``PySimple1`` (lateral), ``TzSimple1`` (shaft friction) and, at the tip,
``QzSimple1`` (end bearing) materials whose capacities are the soil resistance per
unit length integrated over the node's tributary length. It acts only through the
OpenSees command interface passed in as ``ops`` (``nodeCoord``, ``nodeDisp``,
``node``, ``fix``, ``uniaxialMaterial``, ``element('zeroLength')``), so a script
that uses it runs the same with ``beamsolid.opensees`` and ``openseespy.opensees``
(as :mod:`beamsolid.boundaries`). New tags come from a
:class:`beamsolid.boundaries.Tags` counter; the function returns what it made, per
depth, so scenes can record spring forces.

Soil resistance per unit length of pile (docs/pile_springs.md has the equations and
the references):

* :class:`SoftClay` -- Matlock (1970), "Correlations for design of laterally loaded
  piles in soft clay", OTC 1204: ``p_u = min((3 + sigma'_v / s_u + J z / D) s_u D,
  9 s_u D)``, ``y50 = 2.5 eps50 D``; PySimple1 soilType 1. Shaft friction by API
  RP 2A's alpha method, tip by ``9 s_u`` (API RP 2A-WSD, 21st ed. 2000, 6.4).
* :class:`Sand` -- API RP 2A-WSD (2000) 6.8.6 (Reese, Cox & Koop 1974):
  ``p_us = (C1 z + C2 D) sigma'_v``, ``p_ud = C3 D sigma'_v``,
  ``p_u = min(p_us, p_ud)``, and the static curve ``p = A p_u tanh(k z y / (A p_u))``
  with ``A = max(3 - 0.8 z / D, 0.9)``. PySimple1 (soilType 2) takes its asymptote
  ``pult = A p_u`` and ``y50 = atanh(1/2) A p_u / (k z)``, where the tanh curve is at
  half of it. Shaft friction ``K sigma'_v tan(delta)``, tip ``Nq sigma'_v`` (API
  RP 2A 6.4.3).
* :class:`PyLayer` -- given ``p_ult`` (per unit length) and ``y50`` (uniform), for
  curves from elsewhere.

Depth z is measured down from ``ground`` along the vertical axis (the last
coordinate: z in 3D, y in 2D); sigma'_v sums gamma' over the layers above. A node's
tributary length runs half way to its neighbours (clipped to the ground and the
tip); its spring gets ``pult = integral of p_u dz`` over it and ``y50`` such that
``pult / y50 = integral of (p_u / y50) dz`` (capacity and initial stiffness of the
tributary length both kept; 8-point Gauss-Legendre on four pieces of each layer's share). Units are the
model's; the only dimensional defaults are the sand t-z peak displacement (0.1 in
= 0.00254, SI metres) and the unit weight of nothing.
"""
import math
from dataclasses import dataclass, field

import numpy as np

try:
    from .boundaries import Tags
except ImportError:  # loaded from its file (as the oracle scripts do under OpenSeesPy)
    Tags = None

__all__ = ["SoftClay", "Sand", "PyLayer", "SpringSet", "matlock_soft_clay", "api_sand_coefficients", "api_sand",
           "api_alpha", "api_sand_nq", "pile_springs", "Tags"]


@dataclass(frozen=True)
class SoftClay:
    """Soft clay between depths ``top`` and ``bottom`` (down from the ground).

    su: undrained strength at ``top`` (growing by ``su_gradient`` per unit depth);
    gamma: effective unit weight; eps50: strain at half the peak deviator stress
    (Matlock: 0.02 soft, 0.01 medium, 0.005 stiff); J: Matlock's 0.25-0.5;
    Cd: PySimple1 drag in an open gap as a fraction of pult; dashpot: radiation
    dashpot per unit length of pile (PySimple1 / TzSimple1 c); suction: QzSimple1
    uplift resistance as a fraction of q_ult (0 to 0.1).
    """
    top: float
    bottom: float
    su: float
    gamma: float
    eps50: float = 0.01
    su_gradient: float = 0.0
    J: float = 0.5
    Cd: float = 0.3
    dashpot: float = 0.0
    suction: float = 0.0
    soil_type = 1

    def su_at(self, z):
        return self.su + self.su_gradient * (z - self.top)


@dataclass(frozen=True)
class Sand:
    """Sand between depths ``top`` and ``bottom`` (API RP 2A).

    phi: friction angle in degrees; gamma: effective unit weight; k: initial
    modulus of subgrade reaction (force / length^3; API RP 2A Fig. 6.8.7-1, e.g.
    5.4, 16.3, 33.9 MN/m^3 for loose, medium, dense sand below the water table);
    K: lateral earth pressure coefficient on the shaft (API: 0.8 open-ended,
    1.0 plugged); delta: pile-soil friction angle (default phi - 5 degrees);
    Nq: bearing factor (default :func:`api_sand_nq`); z_peak: t-z displacement at
    the peak shaft friction (API: 0.1 in; given here in metres);
    Cd, dashpot: as :class:`SoftClay`.
    """
    top: float
    bottom: float
    phi: float
    gamma: float
    k: float
    K: float = 0.8
    delta: float = None
    Nq: float = None
    z_peak: float = 0.00254
    Cd: float = 1.0
    dashpot: float = 0.0
    soil_type = 2


@dataclass(frozen=True)
class PyLayer:
    """A layer with a given p-y capacity ``p_ult`` per unit length and ``y50``
    (uniform), PySimple1 ``soil_type`` 1 or 2; no t-z or q-z springs."""
    top: float
    bottom: float
    p_ult: float
    y50: float
    soil_type: int = 1
    Cd: float = 0.3
    dashpot: float = 0.0
    gamma: float = 0.0


def matlock_soft_clay(su, sigma_v, z, D, J=0.5, eps50=0.01):
    """Matlock (1970): (p_u per unit length, y50) at depth z, effective
    overburden sigma_v: p_u = min((3 + sigma_v/su + J z/D) su D, 9 su D),
    y50 = 2.5 eps50 D."""
    pu = min((3.0 + sigma_v / su + J * z / D) * su * D, 9.0 * su * D)
    return pu, 2.5 * eps50 * D


def api_sand_coefficients(phi_degrees):
    """API RP 2A (2000) Fig. 6.8.6-1 in closed form (Reese, Cox & Koop 1974):
    C1, C2, C3 with alpha = phi/2, beta = 45 + phi/2, K0 = 0.4,
    Ka = (1 - sin phi)/(1 + sin phi)."""
    phi = math.radians(phi_degrees)
    a, b = phi / 2.0, math.pi / 4.0 + phi / 2.0
    K0, Ka = 0.4, (1.0 - math.sin(phi)) / (1.0 + math.sin(phi))
    tb, ta, tp, tbp = math.tan(b), math.tan(a), math.tan(phi), math.tan(b - phi)
    C1 = tb**2 * ta / tbp + K0 * (tp * math.sin(b) / (math.cos(a) * tbp) + tb * (tp * math.sin(b) - ta))
    C2 = tb / tbp - Ka
    C3 = Ka * (tb**8 - 1.0) + K0 * tp * tb**4
    return C1, C2, C3


def api_sand(phi_degrees, sigma_v, z, D, k):
    """API RP 2A (2000) 6.8.6-6.8.7, static loading: (pult = A p_u, y50) at depth z
    for PySimple1, p_u = min((C1 z + C2 D), C3 D) sigma_v and
    y50 = atanh(1/2) A p_u / (k z) (where A p_u tanh(k z y / (A p_u)) = A p_u / 2)."""
    C1, C2, C3 = api_sand_coefficients(phi_degrees)
    pu = min(C1 * z + C2 * D, C3 * D) * sigma_v
    A = max(3.0 - 0.8 * z / D, 0.9)
    if z <= 0.0:
        # p_u ~ z^2 at the surface: the limit of A p_u / (k z) is 3 C2 D gamma / k,
        # which the caller gets from the first Gauss point below the surface.
        return 0.0, math.inf
    return A * pu, math.atanh(0.5) * A * pu / (k * z)


def api_alpha(su, sigma_v):
    """API RP 2A (2000) 6.4.2: adhesion factor alpha = 0.5 psi^-0.5 (psi <= 1),
    0.5 psi^-0.25 (psi > 1), psi = su / sigma_v, at most 1."""
    psi = su / sigma_v if sigma_v > 0.0 else math.inf
    alpha = 0.5 * psi**-0.5 if psi <= 1.0 else 0.5 * psi**-0.25
    return min(alpha, 1.0)


def api_sand_nq(phi_degrees):
    """API RP 2A (2000) Table 6.4.3-1 bearing factor Nq: 8, 12, 20, 40, 50 at
    phi = 20, 25, 30, 35, 40 degrees, linear between, constant beyond."""
    return float(np.interp(phi_degrees, [20.0, 25.0, 30.0, 35.0, 40.0], [8.0, 12.0, 20.0, 40.0, 50.0]))


@dataclass
class SpringSet:
    """What :func:`pile_springs` made. ``rows``: one dict per pile node below the
    ground, head to tip, with 'depth', 'pile_node', 'fixed_node', 'element',
    'tributary' (top, bottom), 'py' ({dof: dict(mat, soil_type, pult, y50, Cd, c)}),
    'tz' (dict(mat, tz_type, tult, z50, c) or None), 'qz' (dict(...) at the tip or
    None) and 'dofs' (the zeroLength directions in the order of its materials)."""
    rows: list = field(default_factory=list)
    nodes: list = field(default_factory=list)
    elements: list = field(default_factory=list)
    materials: list = field(default_factory=list)

    def by_depth(self):
        return {r["depth"]: r for r in self.rows}


_GAUSS = np.polynomial.legendre.leggauss(8)


def _overburden(layers, z):
    """sigma'_v at depth z: gamma' integrated over the layers above."""
    s = 0.0
    for L in layers:
        if z > L.top:
            s += L.gamma * (min(z, L.bottom) - L.top)
    return s


def _layer_at(layers, z):
    for L in layers:
        if L.top <= z <= L.bottom:
            return L
    return None


def _pieces(layers, a, b):
    """The parts of [a, b] inside each layer."""
    out = []
    for L in layers:
        lo, hi = max(a, L.top), min(b, L.bottom)
        if hi > lo:
            out.append((L, lo, hi))
    return out


def _integrate(layers, a, b, D, per_depth, parts=4):
    """Integrals over [a, b] of the values that per_depth(layer, z) returns (a
    tuple): 8-point Gauss-Legendre on `parts` equal pieces of each layer's share
    (exact for the polynomial pieces; the kinks of min() cost ~1e-7)."""
    total = None
    x, w = _GAUSS
    for L, lo, hi in _pieces(layers, a, b):
        edges = np.linspace(lo, hi, parts + 1)
        for p0, p1 in zip(edges[:-1], edges[1:]):
            h = 0.5 * (p1 - p0)
            for xi, wi in zip(x, w):
                v = np.asarray(per_depth(L, p0 + h * (xi + 1.0)), dtype=float) * (wi * h)
                total = v if total is None else total + v
    return total


def _check_layers(layers, D):
    if not layers:
        raise ValueError("pile_springs: give at least one soil layer")
    if not (D > 0.0):
        raise ValueError(f"pile_springs: the pile diameter must be positive, got {D}")
    ordered = sorted(layers, key=lambda L: L.top)
    for i, L in enumerate(ordered):
        if not (L.bottom > L.top >= 0.0):
            raise ValueError(f"pile_springs: layer {L} needs 0 <= top < bottom")
        if i and abs(L.top - ordered[i - 1].bottom) > 1e-9 * max(1.0, L.top):
            raise ValueError(f"pile_springs: layers must follow each other without gaps or overlaps "
                             f"(a layer ends at {ordered[i - 1].bottom}, the next starts at {L.top})")
        if isinstance(L, SoftClay) and not (L.su > 0.0 and L.eps50 > 0.0 and L.gamma >= 0.0):
            raise ValueError(f"pile_springs: SoftClay needs su > 0, eps50 > 0, gamma >= 0 ({L})")
        if isinstance(L, Sand) and not (0.0 < L.phi < 90.0 and L.gamma > 0.0 and L.k > 0.0):
            raise ValueError(f"pile_springs: Sand needs 0 < phi < 90, gamma > 0, k > 0 ({L})")
        if isinstance(L, PyLayer) and not (L.p_ult > 0.0 and L.y50 > 0.0 and L.soil_type in (1, 2)):
            raise ValueError(f"pile_springs: PyLayer needs p_ult > 0, y50 > 0, soil_type 1 or 2 ({L})")
    return ordered


def pile_springs(ops, tags, pile_nodes, diameter, layers, *, ground=0.0, lateral_dofs=None, axial=True, tip=True):
    """Soil springs on the beam pile through ``pile_nodes`` (head to tip, a
    vertical line; any node above ``ground`` gets none).

    ``layers``: :class:`SoftClay`, :class:`Sand` and :class:`PyLayer` objects
    covering the embedded length (depths down from ``ground``); ``diameter``: the
    pile's width D. ``lateral_dofs``: the p-y directions (default (1, 2) in 3D,
    (1,) in 2D), one PySimple1 each; ``axial``: TzSimple1 springs along the
    vertical dof (soilType 1 in clay, Reese & O'Neill, z50 = 0.0031 D, API RP 2A
    Fig. 6.4.4-1; type 2 in sand, Mosher, z50 = z_peak / 2); ``tip``: a
    QzSimple1 at the tip node (type 1 in clay with z50 = 0.013 D, API Fig.
    6.4.7-1; type 2 in sand with z50 = 0.125 * 0.1 D, Vijayvergiya's z_crit = 0.1 D),
    tip area pi D^2 / 4. PyLayer layers get p-y springs only.

    Returns a :class:`SpringSet`.
    """
    D = float(diameter)
    layers = _check_layers(list(layers), D)
    tip_depth_soil = layers[-1].bottom
    coords = [np.asarray(ops.nodeCoord(n), dtype=float) for n in pile_nodes]
    ndm = len(coords[0])
    if ndm not in (2, 3):
        raise ValueError("pile_springs: needs a 2D or 3D model")
    vertical = ndm - 1
    for n, c in zip(pile_nodes, coords):
        if np.linalg.norm(np.delete(c - coords[0], vertical)) > 1e-9 * max(1.0, D):
            raise ValueError(f"pile_springs: node {n} is off the vertical line of node {pile_nodes[0]}")
    depths = [ground - c[vertical] for c in coords]
    if any(b <= a for a, b in zip(depths, depths[1:])):
        raise ValueError("pile_springs: pile_nodes must go down from head to tip")
    if depths[-1] > tip_depth_soil + 1e-9 * max(1.0, D):
        raise ValueError(f"pile_springs: the layers end at depth {tip_depth_soil}, above the pile tip "
                         f"at depth {depths[-1]}")
    if lateral_dofs is None:
        lateral_dofs = (1, 2) if ndm == 3 else (1,)
    axial_dof = ndm  # the vertical translation: 3 in 3D, 2 in 2D
    tip_depth = depths[-1]

    def sigma_v(z):
        return _overburden(layers, z)

    def py_per_depth(L, z):
        if isinstance(L, PyLayer):
            pu, y50 = L.p_ult, L.y50
        elif isinstance(L, SoftClay):
            pu, y50 = matlock_soft_clay(L.su_at(z), sigma_v(z), z, D, L.J, L.eps50)
        else:
            pu, y50 = api_sand(L.phi, sigma_v(z), z, D, L.k)
        return pu, pu / y50, L.dashpot

    def tz_per_depth(L, z):
        if isinstance(L, SoftClay):
            su = L.su_at(z)
            f = api_alpha(su, sigma_v(z)) * su
        elif isinstance(L, Sand):
            delta = L.delta if L.delta is not None else L.phi - 5.0
            f = L.K * sigma_v(z) * math.tan(math.radians(delta))
        else:
            f = 0.0
        return f * math.pi * D, L.dashpot * (f > 0.0)

    out = SpringSet()
    for i, (node, z) in enumerate(zip(pile_nodes, depths)):
        if z < 0.0:
            continue
        above = depths[i - 1] if i > 0 else z
        below = depths[i + 1] if i + 1 < len(depths) else z
        a, b = max(0.0, 0.5 * (above + z)), min(tip_depth, 0.5 * (z + below))
        if b <= a:
            continue
        L = _layer_at(layers, z) or _layer_at(layers, 0.5 * (a + b))
        pult, stiffness, c = _integrate(layers, a, b, D, py_per_depth)
        row = {"depth": z, "pile_node": node, "tributary": (a, b), "py": {}, "tz": None, "qz": None}
        mats, dofs = [], []
        if pult > 0.0:
            y50 = pult / stiffness
            for dof in lateral_dofs:
                m = tags.take("material")
                ops.uniaxialMaterial("PySimple1", m, L.soil_type, float(pult), float(y50), float(L.Cd), float(c))
                row["py"][dof] = dict(mat=m, soil_type=L.soil_type, pult=float(pult), y50=float(y50), Cd=L.Cd,
                                      c=float(c))
                mats.append(m)
                dofs.append(dof)
        if axial and not isinstance(L, PyLayer):
            tult, ct = _integrate(layers, a, b, D, tz_per_depth)
            if tult > 0.0:
                tz_type, z50 = (1, 0.0031 * D) if isinstance(L, SoftClay) else (2, 0.5 * L.z_peak)
                m = tags.take("material")
                ops.uniaxialMaterial("TzSimple1", m, tz_type, float(tult), float(z50), float(ct))
                row["tz"] = dict(mat=m, tz_type=tz_type, tult=float(tult), z50=float(z50), c=float(ct))
                mats.append(m)
                dofs.append(axial_dof)
        if tip and i == len(pile_nodes) - 1 and not isinstance(L, PyLayer):
            area = math.pi * D * D / 4.0
            if isinstance(L, SoftClay):
                qz_type, qult, z50, suction = 1, 9.0 * L.su_at(z) * area, 0.013 * D, L.suction
            else:
                Nq = L.Nq if L.Nq is not None else api_sand_nq(L.phi)
                qz_type, qult, z50, suction = 2, Nq * sigma_v(z) * area, 0.125 * 0.1 * D, 0.0
            if qult > 0.0:
                m = tags.take("material")
                ops.uniaxialMaterial("QzSimple1", m, qz_type, float(qult), float(z50), float(suction), 0.0)
                row["qz"] = dict(mat=m, qz_type=qz_type, qult=float(qult), z50=float(z50), suction=suction)
                # The tip node's axial spring: t-z and q-z act in parallel on one dof, so
                # the q-z goes on its own element.
        if not mats and row["qz"] is None:
            continue
        ndf = len(ops.nodeDisp(node))
        fixed = tags.take("node")
        ops.node(fixed, *map(float, coords[i]), "-ndf", ndf)
        ops.fix(fixed, *([1] * ndf))
        row["fixed_node"] = fixed
        out.nodes.append(fixed)
        if mats:
            e = tags.take("element")
            ops.element("zeroLength", e, fixed, node, "-mat", *mats, "-dir", *dofs)
            row["element"], row["dofs"] = e, dofs
            out.elements.append(e)
        else:
            row["element"], row["dofs"] = None, []
        if row["qz"] is not None:
            e = tags.take("element")
            ops.element("zeroLength", e, fixed, node, "-mat", row["qz"]["mat"], "-dir", axial_dof)
            row["qz"]["element"] = e
            out.elements.append(e)
        out.materials += mats + ([row["qz"]["mat"]] if row["qz"] else [])
        out.rows.append(row)
    return out

"""modalProperties after eigen, as public examples call it: a 2D two-storey
frame with lumped masses ('-print', '-file', '-unorm', '-return'), a 3D
two-storey frame whose floors are rigid diaphragms (mass on the master nodes
and on the columns' top nodes, some of it on a fixed node), a 1D spring chain,
a 2D truss with ndf 2 (rotational mass from translations only), a portal
whose joints rotate more than they move, and a frame with element mass, one
column consistent (-cMass). Mode
shapes are defined up to their sign, so each mode's participation factors are
returned with the sign that makes its largest one positive, and the report
files with the signs of that section dropped.
"""

import math


def _signed_factors(d, directions):
    modes = len(d["eigenLambda"])
    out = {}
    for m in range(modes):
        row = [d["partiFactor" + k][m] for k in directions]
        big = max(row, key=abs)
        s = math.copysign(1.0, big)
        for k, v in zip(directions, row):
            out.setdefault("partiFactor" + k, []).append(s * v)
    return out


def _add(out, prefix, d, directions):
    for key, value in d.items():
        if not key.startswith("partiFactor"):
            out[prefix + key] = value
    for key, value in _signed_factors(d, directions).items():
        out[prefix + key] = value


def _report(name):
    # Section 6 (participation factors) loses its signs: they follow the mode shape's.
    lines, inside = [], False
    with open(name) as f:
        for line in f:
            if line.startswith("* "):
                inside = line.startswith("* 6.")
            lines.append(line.replace("-", " ") if inside and not line.startswith("#") else line)
    return "".join(lines)


def _frame_2d(ops):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    for tag, x, y in ((1, 0, 0), (2, 6, 0), (3, 0, 3), (4, 6, 3), (5, 0, 6), (6, 6, 6)):
        ops.node(tag, float(x), float(y))
    ops.fix(1, 1, 1, 1)
    ops.fix(2, 1, 1, 1)
    for n, m in ((3, 10.0), (4, 12.0), (5, 8.0), (6, 7.0)):
        ops.mass(n, m, 1.1 * m, 0.5)
    ops.geomTransf("Linear", 1)
    for e, (i, j, iz) in enumerate(((1, 3, 1e-3), (2, 4, 1e-3), (3, 5, 1e-3), (4, 6, 1e-3), (3, 4, 2e-3),
                                    (5, 6, 2e-3)), start=1):
        ops.element("elasticBeamColumn", e, i, j, 0.1, 2e8, iz, 1)


def _frame_3d(ops, fixed_mass):
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    corners = ((0.0, 0.0), (5.0, 0.0), (5.0, 4.0), (0.0, 4.0))
    for level, z in enumerate((0.0, 3.0, 6.0)):
        for i, (x, y) in enumerate(corners):
            ops.node(10 * level + i + 1, x, y, z)
    for i in range(4):
        ops.fix(i + 1, 1, 1, 1, 1, 1, 1)
    ops.geomTransf("Linear", 1, 1.0, 0.0, 0.0)
    ops.geomTransf("Linear", 2, 0.0, 0.0, 1.0)
    e = 1
    for level in (1, 2):
        for i in range(4):
            ops.element("elasticBeamColumn", e, 10 * (level - 1) + i + 1, 10 * level + i + 1,
                        0.1, 2e8, 8e7, 2e-3, 1e-3, 1.5e-3, 1)
            e += 1
        for i in range(4):
            ops.element("elasticBeamColumn", e, 10 * level + i + 1, 10 * level + (i + 1) % 4 + 1,
                        0.1, 2e8, 8e7, 2e-3, 1e-3, 1.5e-3, 2)
            e += 1
        master = 100 + level
        ops.node(master, 2.6, 2.1, 3.0 * level)
        ops.fix(master, 0, 0, 1, 1, 1, 0)
        ops.mass(master, 20.0 * level, 20.0 * level, 0.0, 0.0, 0.0, 30.0 * level)
        ops.rigidDiaphragm(3, master, *[10 * level + i + 1 for i in range(4)])
    for level in (1, 2):
        for i in range(4):
            ops.mass(10 * level + i + 1, 1.0 + i, 1.0 + i, 0.5, 0.01, 0.02, 0.03)
    if fixed_mass:
        ops.mass(1, 3.0, 3.0, 3.0, 0.0, 0.0, 0.0)
    ops.constraints("Transformation")


def run(ops):
    out = {}
    _frame_2d(ops)
    out["2d.eigen"] = ops.eigen(3)
    d = ops.modalProperties("-file", "modal_2d.txt", "-unorm", "-return")
    _add(out, "2d.unorm.", d, ("MX", "MY", "RMZ"))
    out["file:modal_2d.txt"] = _report("modal_2d.txt")
    d = ops.modalProperties("-return")
    _add(out, "2d.", d, ("MX", "MY", "RMZ"))
    out["2d.no -return"] = ops.modalProperties("-file", "modal_2d_plain.txt")
    out["file:modal_2d_plain.txt"] = _report("modal_2d_plain.txt")

    dirs3 = ("MX", "MY", "MZ", "RMX", "RMY", "RMZ")
    _frame_3d(ops, fixed_mass=True)
    out["3d.eigen"] = ops.eigen(4)
    d = ops.modalProperties("-unorm", "-return", "-file", "modal_3d.txt")
    # MZ participates only by round-off (1e-20 against masses of 100): compare it as zero.
    for key in [k for k in d if k.endswith("MZ") and "RMZ" not in k]:
        d[key] = [v if abs(v) > 1e-12 else 0.0 for v in d[key]]
    _add(out, "3d.unorm.", d, dirs3)
    _frame_3d(ops, fixed_mass=False)
    # (-fullGenLapack is left out here: with rigid diaphragms OpenSees does not
    # mass-normalize its mode shapes, which changes the factors without -unorm.)
    out["3d.eigen again"] = ops.eigen(4)
    d = ops.modalProperties("-return")
    for key in [k for k in d if k.endswith("MZ") and "RMZ" not in k]:
        d[key] = [v if abs(v) > 1e-12 else 0.0 for v in d[key]]
    _add(out, "3d.", d, dirs3)

    ops.wipe()
    ops.model("basic", "-ndm", 1, "-ndf", 1)
    for i in range(4):
        ops.node(i + 1, 0.0)
    ops.fix(1, 1)
    ops.uniaxialMaterial("Elastic", 1, 100.0)
    for i in range(3):
        ops.element("zeroLength", i + 1, i + 1, i + 2, "-mat", 1, "-dir", 1)
    for i in range(2, 5):
        ops.mass(i, float(i))
    ops.mass(1, 5.0)
    ops.eigen("-fullGenLapack", 2)
    d = ops.modalProperties("-return", "-file", "modal_1d.txt")
    _add(out, "1d.", d, ("MX",))
    out["file:modal_1d.txt"] = _report("modal_1d.txt")

    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 2)
    ops.node(1, 0.0, 0.0)
    ops.node(2, 4.0, 0.0)
    ops.node(3, 2.0, 3.0)
    ops.fix(1, 1, 1)
    ops.fix(2, 0, 1)
    ops.uniaxialMaterial("Elastic", 1, 100.0)
    for e, (i, j) in enumerate(((1, 2), (1, 3), (2, 3)), start=1):
        ops.element("Truss", e, i, j, 1.0, 1)
    ops.mass(3, 2.0, 3.0)
    ops.mass(2, 1.0, 1.0)
    ops.eigen("-fullGenLapack", 2)
    d = ops.modalProperties("-return", "-unorm")
    _add(out, "truss.", d, ("MX", "MY", "RMZ"))

    # A small portal (0.3 x 0.15) whose modes rotate the joints more than they
    # move them: '-unorm' divides by the largest component, a rotation here.
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    for tag, x, y in ((1, 0.0, 0.0), (2, 0.3, 0.0), (3, 0.0, 0.15), (4, 0.3, 0.15)):
        ops.node(tag, x, y)
    ops.fix(1, 1, 1, 1)
    ops.fix(2, 1, 1, 1)
    ops.mass(3, 10.0, 10.0, 0.001)
    ops.mass(4, 12.0, 12.0, 0.002)
    ops.geomTransf("Linear", 1)
    ops.element("elasticBeamColumn", 1, 1, 3, 0.1, 2e8, 1e-3, 1)
    ops.element("elasticBeamColumn", 2, 2, 4, 0.1, 2e8, 1e-3, 1)
    ops.element("elasticBeamColumn", 3, 3, 4, 0.1, 2e8, 2e-3, 1)
    ops.eigen("-fullGenLapack", 4)
    d = ops.modalProperties("-return", "-unorm")
    _add(out, "small portal.", d, ("MX", "MY", "RMZ"))

    # Element mass: lumped columns and girder, one column with a consistent
    # mass (-cMass): totals, centre and participation as OpenSees forms them.
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    for tag, x, y in ((1, 0.0, 0.0), (2, 6.0, 0.0), (3, 0.0, 3.0), (4, 6.0, 3.0)):
        ops.node(tag, x, y)
    ops.fix(1, 1, 1, 1)
    ops.fix(2, 1, 1, 1)
    ops.mass(3, 10.0, 10.0, 0.0)
    ops.mass(4, 12.0, 12.0, 0.0)
    ops.geomTransf("Linear", 1)
    ops.element("elasticBeamColumn", 1, 1, 3, 0.1, 2e8, 1e-3, 1, "-mass", 2.0)
    ops.element("elasticBeamColumn", 2, 2, 4, 0.1, 2e8, 1e-3, 1, "-mass", 2.0, "-cMass")
    ops.element("elasticBeamColumn", 3, 3, 4, 0.1, 2e8, 2e-3, 1, "-mass", 3.0)
    out["element mass.eigen"] = ops.eigen("-fullGenLapack", 3)
    d = ops.modalProperties("-return", "-unorm", "-file", "modal_element_mass.txt")
    _add(out, "element mass.", d, ("MX", "MY", "RMZ"))
    out["file:modal_element_mass.txt"] = _report("modal_element_mass.txt")
    return out

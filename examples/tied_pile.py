"""A pile tied to the soil (no gap, no slip): the cheapest solid-soil model.

A pile modelled with elastic beam elements, first as a free cantilever (checked
against P L^3 / 3 E I), then embedded in an elastic soil block of 8-node bricks
and tied to the soil nodes on its axis with equalDOF. Prints both head
deflections, writes OpenSees-format recorder files with their JSON sidecars,
and saves the deflection profile as a PNG.
"""
import json
import os
import pathlib
import time

import beamsolid.opensees as ops

OUT = pathlib.Path(os.environ.get("BEAMSOLID_OUT", pathlib.Path(__file__).parent / "output"))
OUT.mkdir(parents=True, exist_ok=True)

# Units: kN, m. Concrete pile, diameter 0.6 m, 10 m long; soft clay block.
E_PILE, G_PILE = 30e6, 12.5e6
D = 0.6
A = 3.141592653589793 * D**2 / 4
I = 3.141592653589793 * D**4 / 64
J = 2 * I
LENGTH, N_ELEM = 10.0, 10
H = 100.0  # lateral head load, kN
E_SOIL, NU_SOIL = 20e3, 0.35


def pile(first_node, x0, y0, z_top):
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    tags = []
    for k in range(N_ELEM + 1):
        tag = first_node + k
        ops.node(tag, x0, y0, z_top - k * LENGTH / N_ELEM)
        tags.append(tag)
    ops.geomTransf("Linear", 1, 1.0, 0.0, 0.0)
    for k in range(N_ELEM):
        ops.element("elasticBeamColumn", 1 + k, tags[k], tags[k + 1], A, E_PILE, G_PILE, J, I, I, 1)
    return tags


def static_analysis(steps):
    ops.constraints("Transformation")
    ops.numberer("RCM")
    ops.system("UmfPack")
    ops.test("NormDispIncr", 1e-10, 10)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", 1.0 / steps)
    ops.analysis("Static")
    assert ops.analyze(steps) == 0


def cantilever():
    ops.wipe()
    tags = pile(1, 0.0, 0.0, 0.0)
    ops.fix(tags[-1], 1, 1, 1, 1, 1, 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(tags[0], H, 0.0, 0.0, 0.0, 0.0, 0.0)
    static_analysis(1)
    return ops.nodeDisp(tags[0], 1)


def embedded(n_xy=8, half_width=5.0, n_z=10):
    """Soil block [-w, w]^2 x [-L, 0] with a node column on the pile axis."""
    ops.wipe()
    tags = pile(100000, 0.0, 0.0, 0.0)
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    ops.nDMaterial("ElasticIsotropic", 1, E_SOIL, NU_SOIL, 1.8)
    n = n_xy + 1
    node = lambda i, j, k: 1 + i + n * (j + n * k)
    for k in range(n_z + 1):
        for j in range(n):
            for i in range(n):
                x = -half_width + 2 * half_width * i / n_xy
                y = -half_width + 2 * half_width * j / n_xy
                ops.node(node(i, j, k), x, y, -LENGTH * k / n_z)
    ele = 1000
    for k in range(n_z):
        for j in range(n_xy):
            for i in range(n_xy):
                c = [node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j + 1, k + 1), node(i, j + 1, k + 1),
                     node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k)]
                ops.element("stdBrick", ele, *c, 1)
                ele += 1
    ops.fixZ(-LENGTH, 1, 1, 1)
    for x in (-half_width, half_width):
        ops.fixX(x, 1, 1, 0)
    for y in (-half_width, half_width):
        ops.fixY(y, 1, 1, 0)
    # Each pile node follows the soil node on the axis (translations only);
    # the pile tip sits on the base, which fixZ already holds.
    centre = n_xy // 2
    for k, tag in enumerate(tags[:-1]):
        ops.equalDOF(node(centre, centre, k), tag, 1, 2, 3)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(tags[0], H, 0.0, 0.0, 0.0, 0.0, 0.0)
    ops.recorder("Node", "-file", str(OUT / "pile_disp.out"), "-time", "-node", *tags, "-dof", 1, "disp")
    ops.recorder("Element", "-file", str(OUT / "pile_forces.out"), "-time", "-eleRange", 1, N_ELEM, "localForce")
    t0 = time.perf_counter()
    static_analysis(4)
    elapsed = time.perf_counter() - t0
    profile = [(ops.nodeCoord(t, 3), ops.nodeDisp(t, 1)) for t in tags]
    ops.wipe()  # closes and flushes the recorders
    return profile, elapsed, ele - 1000


def main():
    u_cantilever = cantilever()
    exact = H * LENGTH**3 / (3 * E_PILE * I)
    print(f"free cantilever head deflection {u_cantilever:.6e} m, closed form {exact:.6e} m "
          f"(relative error {abs(u_cantilever - exact) / exact:.1e})")
    profile, elapsed, n_bricks = embedded()
    print(f"pile tied into {n_bricks} soil bricks: head deflection {profile[0][1]:.6e} m "
          f"({elapsed:.2f} s for 4 load steps)")
    sidecar = json.loads((OUT / "pile_disp.out.json").read_text())
    print(f"recorded {len(sidecar['columns'])} columns into {OUT / 'pile_disp.out'} (names in its .json sidecar)")
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        z, u = zip(*profile)
        fig, ax = plt.subplots(figsize=(4, 5))
        ax.plot([1e3 * v for v in u], z, "o-")
        ax.set_xlabel("lateral deflection (mm)")
        ax.set_ylabel("z (m)")
        ax.set_title(f"Pile in elastic soil, H = {H:.0f} kN")
        fig.tight_layout()
        fig.savefig(OUT / "pile_deflection.png", dpi=120)
        print(f"saved {OUT / 'pile_deflection.png'}")
    except ImportError:
        print("matplotlib not installed: no plot")


if __name__ == "__main__":
    main()

"""Render the bridge bent's contact forces from the files the scene wrote (README picture).

Reads the last record of the scene's PVD collection with meshio and draws, with
matplotlib off-screen, the piles and the cap (beam cells), the contact vertices on the
pile surfaces coloured by their normal force, arrows of the normal forces (pointing
into the soil, length proportional to the force) and the open contacts as red crosses;
the soil is left out except for the outline of its top surface. Displacements are
magnified so that the push shows.

    python -m beamsolid.scenes bridge_bent --level medium --out out/bridge_bent_medium
    python examples/render_bent.py out/bridge_bent_medium/bent.pvd docs/img/bridge_bent_contact.png
"""
import argparse
import os
import sys
import xml.etree.ElementTree as ET

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import meshio  # noqa: E402
import numpy as np  # noqa: E402


def last_record(pvd):
    """(time, path of the .vtu) of the last DataSet in a .pvd collection."""
    root = ET.parse(pvd).getroot()
    sets = root.findall("./Collection/DataSet")
    if not sets:
        raise ValueError(f"render_bent: {pvd} lists no DataSet")
    last = sets[-1]
    return float(last.get("timestep")), os.path.join(os.path.dirname(pvd), last.get("file"))


def contact_table(vtu):
    """Per contact vertex: element tag, point (reference), status, normal force, gap, normal; as arrays."""
    mesh = meshio.read(vtu)
    blocks = [i for i, b in enumerate(mesh.cells) if b.type == "vertex"]
    if not blocks:
        raise ValueError(f"render_bent: {vtu} has no contact vertices")
    i = blocks[0]
    data = {k: v[i] for k, v in mesh.cell_data.items()}
    return mesh, {"element": data["elementTag"].astype(int).ravel(), "point": mesh.cells[i].data.ravel(),
                  "status": data["contactStatus"].astype(int).ravel(),
                  "normal_force": data["contactNormalForce"].ravel(), "gap": data["contactGap"].ravel(),
                  "normal": data["contactNormal"],
                  "friction": data["contactFrictionForce"]}


def render(pvd, png, magnify=40.0, arrow_scale=None):
    t, vtu = last_record(pvd)
    mesh, c = contact_table(vtu)
    xyz = mesh.points + magnify * mesh.point_data["displacement"]
    fig = plt.figure(figsize=(8.0, 6.0))
    ax = fig.add_subplot(projection="3d")
    ax.set_proj_type("ortho")
    # Soil: outline of the top surface (the bricks' top faces at the highest soil level).
    hexes = next(b.data for b in mesh.cells if b.type == "hexahedron")
    soil = np.unique(hexes)
    ztop = mesh.points[soil, 2].max()
    top = soil[np.abs(mesh.points[soil, 2] - ztop) < 1e-9]
    x0, x1 = mesh.points[top, 0].min(), mesh.points[top, 0].max()
    y0, y1 = mesh.points[top, 1].min(), mesh.points[top, 1].max()
    # Show only the soil near the piles; the padding stretches the picture.
    beams = next(b.data for b in mesh.cells if b.type == "line")
    bx = mesh.points[np.unique(beams), 0]
    pad = 2.0
    x0, x1 = max(x0, bx.min() - pad), min(x1, bx.max() + pad)
    y0, y1 = max(y0, -pad), min(y1, pad)
    ax.plot([x0, x1, x1, x0, x0], [y0, y0, y1, y1, y0], [ztop] * 5, color="0.6", lw=0.8)
    for line in beams:
        p = xyz[line]
        ax.plot(p[:, 0], p[:, 1], p[:, 2], color="k", lw=2.5)
    pts = xyz[c["point"]]
    closed = c["status"] != 0
    fmax = c["normal_force"].max()
    sc = ax.scatter(pts[closed, 0], pts[closed, 1], pts[closed, 2], c=c["normal_force"][closed], cmap="viridis",
                    vmin=0.0, vmax=fmax, s=14, depthshade=False)
    ax.scatter(pts[~closed, 0], pts[~closed, 1], pts[~closed, 2], marker="x", color="tab:red", s=18,
               depthshade=False, label="open contact")
    scale = arrow_scale if arrow_scale is not None else 1.2 / fmax  # m per kN: the largest arrow 1.2 m
    vec = c["normal"][closed] * (scale * c["normal_force"][closed])[:, None]
    ax.quiver(pts[closed, 0], pts[closed, 1], pts[closed, 2], vec[:, 0], vec[:, 1], vec[:, 2],
              color=plt.cm.viridis(c["normal_force"][closed] / fmax), linewidth=0.7, arrow_length_ratio=0.25)
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_zlabel("z (m)")
    zmin = xyz[np.unique(beams), 2].min()
    zmax = xyz[np.unique(beams), 2].max()
    # Depth compressed by half: the interesting part is the top few metres.
    ax.set_box_aspect((x1 - x0, y1 - y0, 0.5 * (zmax - zmin)))
    ax.set_yticks([round(y0), 0, round(y1)])
    ax.view_init(elev=14, azim=-118)  # from the trailing (-x) side
    ax.legend(loc="upper left", fontsize=8)
    fig.colorbar(sc, ax=ax, shrink=0.6, pad=0.02, label="contact normal force (kN)")
    ax.set_title(f"bridge bent pushed along +x: contact normal forces at cap force {t:.0f} kN\n"
                 f"(displacements x {magnify:g}; arrows: force on the soil; crosses: open contacts)", fontsize=9)
    fig.tight_layout()
    os.makedirs(os.path.dirname(png) or ".", exist_ok=True)
    fig.savefig(png, dpi=100)
    plt.close(fig)
    return png


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("pvd", nargs="?", default=os.path.join("out", "bridge_bent_medium", "bent.pvd"))
    parser.add_argument("png", nargs="?", default=os.path.join("docs", "img", "bridge_bent_contact.png"))
    parser.add_argument("--magnify", type=float, default=40.0)
    args = parser.parse_args(argv)
    print(render(args.pvd, args.png, args.magnify))
    return 0


if __name__ == "__main__":
    sys.exit(main())

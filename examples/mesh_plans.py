"""Plans of the meshing helpers (beamsolid.mesh), drawn for docs/meshing.md.

Saves docs/img/mesh_ogrid.png (a square O-grid, and a circular one whose hole is filled
below the pile tip: the butterfly core, dashed) and docs/img/mesh_pile_group.png (a bent of
three piles with padding). Run: PYTHONPATH=python python examples/mesh_plans.py
"""
import pathlib

import matplotlib.pyplot as plt

from beamsolid import Model, mesh

IMG = pathlib.Path(__file__).resolve().parent.parent / "docs" / "img"


def main():
    m = Model()
    m.model("basic", "-ndm", 3, "-ndf", 3)
    m.nDMaterial("ElasticIsotropic", 1, 20e3, 0.3)
    levels = [0.0, -1.0, -2.0]
    square = mesh.ogrid(m, pile_radius=0.5, outer_size=4.0, outer="square", n_theta=16, n_radial=6,
                        radial_ratio=1.3, levels=levels)
    circle = mesh.ogrid(m, pile_radius=0.5, outer_size=4.0, outer="circle", n_theta=16, n_radial=6,
                        radial_ratio=1.3, levels=levels, core_below=-1.0, centre=(10.0, 0.0))
    fig, axes = plt.subplots(1, 2, figsize=(10, 5))
    mesh.plot_plan(square, axes[0])
    axes[0].set_title("ogrid(outer='square', n_theta=16, n_radial=6)")
    mesh.plot_plan(circle, axes[1])
    axes[1].set_title("ogrid(outer='circle', core_below=z_tip): core dashed")
    fig.tight_layout()
    fig.savefig(IMG / "mesh_ogrid.png", dpi=110)

    group = mesh.pile_group(m, piles=[(0.0, 20.0), (3.0, 20.0), (6.0, 20.0)], pile_radius=0.4, spacing=3.0,
                            n_theta=16, n_radial=4, padding=4.0, n_padding=4, padding_ratio=1.3, levels=levels)
    fig, ax = plt.subplots(figsize=(10, 5))
    mesh.plot_plan(group, ax)
    ax.set_title("pile_group(piles=3 in a row, spacing=3, padding=4, n_padding=4)")
    fig.tight_layout()
    fig.savefig(IMG / "mesh_pile_group.png", dpi=110)
    print(f"saved {IMG / 'mesh_ogrid.png'} and {IMG / 'mesh_pile_group.png'}")


if __name__ == "__main__":
    main()

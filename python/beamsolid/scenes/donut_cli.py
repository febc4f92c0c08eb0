"""The donut pullout as a scene: python -m beamsolid.scenes donut_pullout --level coarse|medium|fine.

Runs the paper's Table 1 (mu = 0.1, 0.25, 0.5, 1 with G = 1000) on the level's mesh with
beamsolid.scenes.donut_pullout.run, prints Q against the paper and the beta method, records the
mu = 0.5 pull (Node recorder of the head, PVD time series) and saves the pullout curves as a PNG.
The medium level is the paper's mesh (16 x 4 x 10).
"""
import pathlib
import time
from dataclasses import replace

from ..model import Model
from ..stepping import adaptive_analyze
from .donut_pullout import PAPER_TABLE1, DonutModel, DonutPullout, PulloutResult, run

# (n_theta, n_radial, n_z) of the donut per level.
LEVELS = {"coarse": (8, 2, 5), "medium": (16, 4, 10), "fine": (32, 8, 20)}
RECORDED_MU = 0.5


def recorded_pull(setup, out, adaptive=False):
    """One pullout with recorders in `out` (and adaptive steps if asked): the stages of
    donut_pullout.run, with the pull driven by stepping.adaptive_analyze."""
    model = DonutModel(setup, Model()).build()
    r = PulloutResult(setup=setup, n_contacts=len(model.contacts))
    r.geostatic_normal_sum = model.geostatic()
    model.release()
    m, head = model.m, model.pile_nodes[0]
    m.recorder("Node", "-file", str(out / "head_disp.out"), "-time", "-node", head, "-dof", 3, "disp")
    m.recorder("Node", "-file", str(out / "head_reaction.out"), "-time", "-node", head, "-dof", 3, "reaction")
    m.recorder("PVD", str(out / "donut_pullout"))
    model.record(r)

    def on_step(_, iterations):
        r.iterations.append(iterations)
        model.record(r)

    stepper = adaptive_analyze(m, 1.0, setup.steps, adaptive=adaptive, on_step=on_step)
    r.failed_step = 0 if stepper.converged else len(r.iterations) + 1
    m.wipe()
    return r


def scene(level="coarse", out="donut_pullout_output", adaptive=False, steps=None):
    out = pathlib.Path(out)
    out.mkdir(parents=True, exist_ok=True)
    t0 = time.perf_counter()
    n_theta, n_radial, n_z = LEVELS[level]
    base = DonutPullout(n_theta=n_theta, n_radial=n_radial, n_z=n_z, **({} if steps is None else {"steps": steps}))
    print(f"donut_pullout ({level}: donut {n_theta} x {n_radial} x {n_z}, G = {base.G:g}); units kN, m")
    print(f"{'mu':>6s}{'Q_contact':>11s}{'Qs beta':>9s}{'%diff':>7s}{'facet':>8s}{'unload':>8s}{'gate c':>9s}"
          f"{'paper Q':>9s}{'paper Qs':>9s}{'iters':>7s}")
    results = []
    for mu, G, q_paper, qs_paper in PAPER_TABLE1:
        s = replace(base, mu=mu, G=G)
        r = recorded_pull(s, out, adaptive) if mu == RECORDED_MU else run(s)
        if mu != RECORDED_MU and r.failed_step and adaptive:
            r = recorded_pull(s, out / f"mu_{mu:g}", adaptive)  # retry with adaptive steps
        results.append(r)
        gate = r.q_contact / r.sliding_resistance - 1
        print(f"{mu:6.2f}{r.q_contact:11.2f}{s.beta_method:9.2f}{100 * (r.q_contact / s.beta_method - 1):7.1f}"
              f"{s.facet_factor:8.4f}{r.unloading:8.4f}{gate:9.1e}"
              f"{q_paper:9.0f}{qs_paper:9.0f}{sum(r.iterations):7d}{'' if not r.failed_step else '  FAILED'}")
    print("  %diff against beta = facet x unload - 1: facet = n sin(2 pi/n)/(2 pi), the inscribed n-gon's share of\n"
          "  the circle's normal force; unload = sum N at full sliding / geostatic sum N; gate c = Q / (facet unload Qs) - 1")
    files = [out / "head_disp.out", out / "head_reaction.out", out / "donut_pullout.pvd"]
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        fig, ax = plt.subplots(figsize=(6.0, 4.4))
        for r in results:
            line, = ax.plot([1e3 * d for d in r.head_disp], r.head_force, "o-", ms=3, label=f"mu = {r.setup.mu:g}")
            ax.axhline(r.setup.beta_method, color=line.get_color(), ls="--", lw=0.8)
        ax.set_xlabel("head displacement (mm)")
        ax.set_ylabel("head force Q (kN)")
        ax.set_title(f"Donut pullout ({level}); dashed: beta method")
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3)
        fig.tight_layout()
        files.append(out / "donut_pullout.png")
        fig.savefig(files[-1], dpi=120)
        plt.close(fig)
    except ImportError:
        print("matplotlib not installed: no plot")
    print(f"wrote {', '.join(f.name for f in files)} in {out}; wall time {time.perf_counter() - t0:.1f} s")
    return results, files

"""Mesh refinement of the Randolph-Houlsby slice: a rigid cylinder moved through von Mises clay.

The problem is scenes.capacity_slice.Slice (plane strain, one layer of bricks, the pile a beam
with BeamContact3D, weightless J2 soil with G = 5000 s_u, nu = 0.49; R_out = 20 R). The limit
pressures P / (s_u D) are compared with Randolph and Houlsby (1984): 6 + pi = 9.142 (smooth,
mu = 0, c = 0) and 2 pi + 4 sqrt(2) = 11.940 (rough, adhesion c = s_u). Runs:

* bbarBrick, two mesh families: "square" cells (n_radial = n_theta / 2) and "flat" cells
  (n_radial = n_theta, half as deep near the pile), levels coarse .. xfine (n_theta 16 .. 48;
  --full adds xxfine, 64), smooth and rough; the contacts carry tension (no gap);
* the same with the confinement instead of tensile contacts (p0 = 10 s_u), at two soil
  stiffnesses: the spurious force of the turning contact normals (docs/lateral_capacity.md);
* SSPbrick (its hourglass stiffness is elastic: no plateau);
* the bonded interface (the hole nodes moved with the pile: no slip, no gap; rough limit).

Writes benchmarks/results/lateral_capacity_slice.{md,json,png}. Wall times are of a shared
two-core machine (other jobs running): compare them only roughly.

    PYTHONPATH=python python benchmarks/lateral_capacity_slice.py [--full]
"""
import argparse
import dataclasses
import datetime
import json
import pathlib
import sys

import machine
from beamsolid.scenes.capacity_slice import LEVELS, RANDOLPH_HOULSBY, Slice, run

RESULTS = pathlib.Path(__file__).resolve().parents[1] / "benchmarks" / "results"


def plan(full):
    levels = ["coarse", "medium", "fine", "xfine"] + (["xxfine"] if full else [])
    runs = []
    for cells in ("square", "flat"):
        for level in levels:
            for interface in ("smooth", "rough"):
                runs.append(("bbar " + cells, Slice(level=level, cells=cells, interface=interface)))
    for G in (5000.0, 50000.0):
        for interface in ("smooth", "rough"):
            runs.append((f"confined, G = {G:g} s_u", Slice(level="medium", interface=interface, no_gap="confine",
                                                             G_over_su=G, push=0.003 * 5000.0 / G)))
    for level in ("coarse", "medium", "fine"):
        for interface in ("smooth", "rough"):
            runs.append(("SSPbrick square", Slice(level=level, interface=interface, element="SSPbrick")))
    for level in levels[:4]:
        runs.append(("bonded square", Slice(level=level, interface="bonded")))
    return runs


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--full", action="store_true", help="add the xxfine level (n_theta 64)")
    args = ap.parse_args()
    rows = []
    for family, problem in plan(args.full):
        r = run(problem)
        n_theta, n_radial = problem.mesh
        last, before = r.pressure[-1], r.pressure[-2]
        row = dict(family=family, level=problem.level, n_theta=n_theta, n_radial=n_radial,
                   interface=problem.interface, element=problem.element, no_gap=problem.no_gap,
                   G_over_su=problem.G_over_su, limit=r.limit, last=last,
                   closed_form=problem.closed_form, error=r.error, converged=r.converged,
                   # growth over the last step, per 1 % of D of displacement
                   slope=(last - before) / (100.0 * (r.disp[-1] - r.disp[-2])),
                   peak_disp=r.disp[r.pressure.index(r.limit)], equations=r.n_equations,
                   iterations=sum(r.iterations), cuts=r.cuts, wall=r.wall,
                   open=max(r.n_open), min_normal=min(r.min_normal) if r.n_contacts else None)
        rows.append(row)
        print(f"{family:26s} {problem.level:7s} {n_theta:3d} x {n_radial:3d} {problem.interface:7s} "
              f"P/(su D) {r.limit:8.4f} ({100 * r.error:+6.2f} %) last {last:8.4f} slope {row['slope']:+.4f}/%D "
              f"open {row['open']} {'ok' if r.converged else 'STOPPED'} {sum(r.iterations)} it {r.cuts} cuts "
              f"{r.wall:6.1f} s {r.n_equations} eqs", flush=True)

    lines = ["# Randolph-Houlsby limiting pressure: mesh refinement of the plane-strain slice", "",
             f"Run {datetime.datetime.now():%Y-%m-%d %H:%M}; command `PYTHONPATH=python python "
             f"benchmarks/lateral_capacity_slice.py{' --full' if args.full else ''}`. A rigid cylinder (beam + "
             "BeamContact3D, one per soil node) pushed by 0.003 D through weightless J2 clay (G = 5000 s_u, nu = 0.49, "
             "sig0 = sqrt(3) s_u, perfect plasticity), one layer of bricks with every z fixed, R_out = 20 R "
             "(scenes/capacity_slice.py). P / (s_u D) is the largest pile reaction over t s_u D; closed forms "
             f"{RANDOLPH_HOULSBY['smooth']:.3f} (smooth) and {RANDOLPH_HOULSBY['rough']:.3f} (rough, bonded). "
             "'slope': the growth of P / (s_u D) over the last step per 1 % of D (a plateau has none). "
             "'open': contacts that opened (none may: the solution assumes no gap); 'min N': the smallest contact "
             "normal force (kN, negative: tension carried instead of a gap). Wall times: a shared two-core machine.",
             "", "![limit pressure against mesh size](lateral_capacity_slice.png)", "",
             "| model | level | n_theta x n_radial | interface | P / (s_u D) | error | slope per % D | open | "
             "min N (kN) | equations | Newton iterations | step cuts | wall (s) |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        minN = "-" if r["min_normal"] is None else f"{r['min_normal']:.3f}"
        lines.append(f"| {r['family']} | {r['level']} | {r['n_theta']} x {r['n_radial']} | {r['interface']} | "
                     f"{r['limit']:.4f} | {100 * r['error']:+.2f} % | {r['slope']:+.4f} | {r['open']} | {minN} | "
                     f"{r['equations']} | {r['iterations']} | {r['cuts']} | {r['wall']:.1f} |")
    lines.append("")
    lines += machine.blas_report()
    RESULTS.mkdir(parents=True, exist_ok=True)
    (RESULTS / "lateral_capacity_slice.md").write_text("\n".join(lines) + "\n")
    (RESULTS / "lateral_capacity_slice.json").write_text(json.dumps(
        dict(rows=rows, levels=LEVELS, problem=dataclasses.asdict(Slice())), indent=1))
    chart(rows)
    print("\n".join(lines))


def chart(rows):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    for ax, interface in zip(axes, ("smooth", "rough")):
        exact = RANDOLPH_HOULSBY[interface]
        families = ["bbar square", "bbar flat", "SSPbrick square"] + (["bonded square"] if interface == "rough" else [])
        for i, family in enumerate(families):
            pts = [r for r in rows if r["family"] == family and r["interface"] in (interface, "bonded")]
            if not pts:
                continue
            ax.plot([1.0 / r["n_theta"] for r in pts], [r["limit"] / exact for r in pts], "os^D"[i] + "-",
                    color=f"C{i}", label=family)
        ax.axhline(1.0, color="k", lw=0.8)
        ax.axhspan(0.95, 1.05, color="0.9", zorder=0, label="within 5 %")
        ax.set_xlabel("1 / n_theta (pile-surface nodes per ring)")
        ax.set_ylabel(f"P / (s_u D) / {exact:.3f}")
        ax.set_xlim(0.0, None)
        ax.set_ylim(0.9, 1.3)
        ax.set_title(f"{interface} interface (Randolph and Houlsby: {exact:.3f})", fontsize=10)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("Limiting pressure on a rigid cylinder in von Mises clay: mesh refinement", fontsize=10)
    fig.tight_layout()
    fig.savefig(RESULTS / "lateral_capacity_slice.png", dpi=110)
    plt.close(fig)


if __name__ == "__main__":
    sys.exit(main())

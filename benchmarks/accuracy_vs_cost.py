"""Speed against accuracy for the lateral pile: four models of one physical problem (issue 5).

The problem is scenes.lateral_pile.LateralPile (a 1 m concrete pile, 20 m long, in elastic
soil confined by its weight) under a head load H = 700 kN, which opens a gap behind the pile
down to about 4 m. Models:

  (a)  beam pile + BeamContact3D (Lagrange multipliers, stick stiffness G = 1e5 kN/m per
       node: a stiff stick, rigid-plastic Coulomb friction) + brick soil: scenes.lateral_pile,
       interface "contact";
  (a') the same with BeamContact3Dp (penalty 1e7 kN/m, G = 1e5);
  (b)  the pile meshed with bricks in the same soil mesh, joined node to node by
       zeroLengthContact3D (Kn = 1e7, Kt = 1e5 kN/m, mu): scenes.lateral_pile_solid;
       the reference is the Richardson extrapolation of its three mesh levels;
  (c)  beam pile tied to the soil (rigid links: no gap, no slip);
  (d)  beam on elastic Winkler springs (zeroLength), k from Vesic (1961), no soil mesh.

Each model runs at three mesh levels (coarse, medium, fine: the soil O-grid of LEVELS;
for (d) 10, 20, 40 beam elements). For each run: head displacement u at H, the largest
pile bending moment M_max, wall time (build + gravity stage + push), equations. Errors are
|value - reference| / reference. Also the whole load path: error in u at each load step for
the finest level of each model against (b)'s finest, with (a)'s gap depth, showing where the
no-gap models stop being good enough.

Every run goes through beamsolid.sweep (docs/sweeps.md): a local Dask cluster, one worker per core
(or --workers N, or --scheduler ADDRESS), each run stored in a Parquet folder (--store; a re-run
skips the runs stored there, --fresh empties it first); --serial runs them one after the other here.
Runs on workers side by side share the machine's memory bandwidth: for the cleanest timings of
each model, use --serial (or --workers 1).

Writes benchmarks/results/accuracy_vs_cost.{md,json} and docs/img/accuracy_vs_cost.png,
docs/img/accuracy_vs_load.png. Timings depend on the machine and its load; the machine and
the BLAS kernel are recorded at the end of the table.

    PYTHONPATH=python python benchmarks/accuracy_vs_cost.py [--quick]
        [--serial | --workers N | --scheduler ADDRESS] [--store DIR] [--fresh]
"""
import argparse
import dataclasses
import datetime
import json
import os
import pathlib
import shutil
import sys
import time

import machine
from beamsolid import sweep
from beamsolid.scenes import lateral_pile_solid as solid
from beamsolid.scenes import winkler_pile as winkler
from beamsolid.scenes.lateral_pile import LEVELS, LateralPile, Numerics, run

ROOT = pathlib.Path(__file__).resolve().parents[1]
RESULTS = ROOT / "benchmarks" / "results"
IMG = ROOT / "docs" / "img"
H = 700.0  # kN
STEPS = 10
STICK_G = 1e5  # kN/m per contact node: every interface sticks stiffly
WINKLER_ELEMENTS = {"coarse": 10, "medium": 20, "fine": 40}

MODELS = {
    "a": "(a) beam + BeamContact3D (Lagrange)",
    "a'": "(a') beam + BeamContact3Dp (penalty 1e7)",
    "b": "(b) solid pile + zeroLengthContact3D",
    "c": "(c) beam tied to soil",
    "d": "(d) beam on Winkler springs (Vesic k)",
}


def size(level):
    """Mesh size parameter h ~ (number of soil bricks)^(-1/3); level: a LEVELS key or divisions."""
    n_theta, n_radial, n_z = LEVELS[level] if isinstance(level, str) else level
    return (n_theta * n_radial * n_z) ** (-1.0 / 3.0)


def run_model(key, level, problem):
    """{u, M, wall, equations, curve: [(H_i, u_i)], gap: [(H_i, depth_i)]} of one model at one level."""
    t0 = time.perf_counter()
    if key in ("a", "a'", "c"):
        interface = {"a": "contact", "a'": "penalty", "c": "tied"}[key]
        extra = {"contact_G": STICK_G, "penalty_factor": 1e3} if key == "a'" else {"contact_G": STICK_G}
        r = run(problem, Numerics(level=level, interface=interface, steps=STEPS, control="force", head_load=H,
                                  **extra))
        if not r.converged:
            return None
        return dict(u=r.head_disp[-1], M=max(abs(v) for v in r.moment), wall=time.perf_counter() - t0,
                    equations=r.n_equations, curve=list(zip(r.head_force, r.head_disp)),
                    gap=list(zip(r.head_force, r.gap_depth)), iterations=sum(r.iterations))
    if key == "b":
        r = solid.run(problem, solid.SolidNumerics(level=level, interface="contact", penalty_factor=1e3,
                                                    stick_G=STICK_G, control="force", head_load=H, steps=STEPS))
        if not r.converged:
            return None
        return dict(u=r.head_disp[-1], M=r.max_moment, wall=time.perf_counter() - t0, equations=r.n_equations,
                    curve=[(0.0, 0.0)] + list(zip(r.head_force, r.head_disp)), gap=[],
                    iterations=sum(r.iterations))
    k = winkler.vesic_k(problem)
    r = winkler.run_winkler(problem, WINKLER_ELEMENTS[level], k=k, head_force=H)
    return dict(u=r.head_disp, M=max(abs(v) for v in r.moment), wall=time.perf_counter() - t0,
                equations=r.equations, curve=[(H * f, r.head_disp * f) for f in [i / STEPS for i in range(STEPS + 1)]],
                gap=[], iterations=1)


def model_point(model, level):
    """The sweep's function: one model at one level on the default LateralPile. A run that does not
    converge is stored as failed, without results (the scenes do not report the analyze code)."""
    t0 = time.perf_counter()
    res = run_model(model, level, LateralPile())
    if res is None:
        return dict(returncode=None, error=f"did not converge ({time.perf_counter() - t0:.1f} s)")
    res.pop("wall")  # the sweep times every run itself (column wall)
    return res


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--quick", action="store_true", help="coarse and medium only (no reference worth the name)")
    ap.add_argument("--serial", action="store_true", help="run the models here, one after the other (no Dask)")
    ap.add_argument("--workers", type=int, help="local Dask worker processes (default: one per core)")
    ap.add_argument("--scheduler", metavar="ADDRESS", help="run on an existing Dask scheduler instead")
    ap.add_argument("--store", type=pathlib.Path, help="the sweep's Parquet folder (default: "
                    "build/sweeps/accuracy_vs_cost[_quick]); stored runs are not run again")
    ap.add_argument("--fresh", action="store_true", help="empty the store first (after a code change)")
    args = ap.parse_args()
    if args.store is None:
        args.store = ROOT / "build" / "sweeps" / f"accuracy_vs_cost{'_quick' if args.quick else ''}"
    if args.fresh and args.store.exists():
        shutil.rmtree(args.store)
    problem = LateralPile()
    levels = ["coarse", "medium"] if args.quick else ["coarse", "medium", "fine"]
    # The finest levels first: they take longest, so the workers finish together.
    points = [dict(model=key, level=level) for level in reversed(levels) for key in MODELS]
    summary = sweep.run(model_point, points, args.store, scheduler=args.scheduler, workers=args.workers,
                        serial=args.serial, name="accuracy_vs_cost")
    runner = ("serially in one process (--serial)" if args.serial else
              f"on the Dask scheduler {args.scheduler}" if args.scheduler else
              f"on a local Dask cluster of {args.workers or os.cpu_count()} worker processes, one BLAS thread each")
    print(f"{summary.points} runs, {summary.skipped} already stored, {summary.ran} run in {summary.wall:.1f} s "
          f"{runner}", flush=True)
    stored = {(p["model"], p["level"]): row for p, row in zip(points, sweep.read(args.store, points))}
    runs = {}
    for key in MODELS:
        for level in levels:
            row = stored[(key, level)]
            res = None
            if row["status"] == "ok":
                res = {k: row[k] for k in ("u", "M", "equations", "curve", "gap", "iterations")}
                res["curve"] = [tuple(x) for x in res["curve"]]
                res["gap"] = [tuple(x) for x in res["gap"]]
                res["wall"] = row["wall"]
            elif row["status"] == "error":
                print(f"{MODELS[key]:45s} {level:7s} raised: {row['error'].splitlines()[0]}", flush=True)
            runs[(key, level)] = res
            if res:
                print(f"{MODELS[key]:45s} {level:7s} u {res['u'] * 1e3:8.3f} mm  M_max {res['M']:8.1f} kNm  "
                      f"{res['wall']:7.2f} s  {res['equations']:6d} eqs  {res['iterations']} it", flush=True)
            else:
                print(f"{MODELS[key]:45s} {level:7s} did not converge", flush=True)

    # Reference: Richardson extrapolation of (b) over its levels (or its finest level).
    hs = [size(lv) for lv in levels]
    b = [runs[("b", lv)] for lv in levels]
    if len(levels) == 3 and all(b):
        u_ref, p_u = solid.richardson(hs, [x["u"] for x in b])
        M_ref, p_M = solid.richardson(hs, [x["M"] for x in b])
        reference = "Richardson extrapolation of (b) over coarse, medium, fine"
    else:
        u_ref, p_u, M_ref, p_M = b[-1]["u"], float("nan"), b[-1]["M"], float("nan")
        reference = f"(b) at {levels[-1]}"
    print(f"reference: {reference}: u = {u_ref * 1e3:.4f} mm (order {p_u:.2f}), M_max = {M_ref:.2f} kNm "
          f"(order {p_M:.2f})")

    rows = []
    for (key, level), res in runs.items():
        if res:
            rows.append(dict(model=key, level=level, u=res["u"], M=res["M"], wall=res["wall"],
                             equations=res["equations"], iterations=res["iterations"],
                             err_u=abs(res["u"] - u_ref) / abs(u_ref), err_M=abs(res["M"] - M_ref) / abs(M_ref)))

    # The goal: (a) within 5 % of the reference at a tenth of (b)'s time or less.
    b_finest = runs[("b", levels[-1])]
    curves_json = {f"{k} {lv}": (res["curve"] if res else None) for (k, lv), res in runs.items()}
    lines = ["# Speed against accuracy: the lateral pile", "",
             f"Run {datetime.datetime.now():%Y-%m-%d %H:%M}; command `PYTHONPATH=python python "
             f"benchmarks/accuracy_vs_cost.py{' --quick' if args.quick else ''}"
             f"{' --serial' if args.serial else ''}{f' --workers {args.workers}' if args.workers else ''}`, "
             f"runs {runner}. Head load H = {H:g} kN "
             f"in {STEPS} load steps; reference: {reference}: head displacement {u_ref * 1e3:.4f} mm "
             f"(observed order {p_u:.2f}), M_max {M_ref:.1f} kNm (order {p_M:.2f}).", "",
             "![error against wall time](../../docs/img/accuracy_vs_cost.png)", "",
             "| model | level | equations | Newton iterations | wall time (s) | u at H (mm) | error u | M_max (kNm) | error M_max |",
             "|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {MODELS[r['model']]} | {r['level']} | {r['equations']} | {r['iterations']} | "
                     f"{r['wall']:.2f} | {r['u'] * 1e3:.3f} | {r['err_u']:.1%} | {r['M']:.1f} | {r['err_M']:.1%} |")
    lines.append("")
    for key in ("a", "a'"):
        good = [r for r in rows if r["model"] == key and r["err_u"] <= 0.05 and r["err_M"] <= 0.05]
        if good and b_finest:
            cheapest = min(good, key=lambda r: r["wall"])
            lines.append(f"- {MODELS[key]}: within 5 % (u and M_max) at `{cheapest['level']}` in "
                         f"{cheapest['wall']:.2f} s = {cheapest['wall'] / b_finest['wall']:.3f} of (b)'s finest "
                         f"({b_finest['wall']:.1f} s).")
        else:
            lines.append(f"- {MODELS[key]}: not within 5 % of the reference at any level run here.")
    lines.append("")

    # Along the load path: where the no-gap models stop being good enough. The reference at each
    # load step is the Richardson extrapolation of (b)'s three levels at that step, like u_ref.
    finest = levels[-1]
    path_rows = []
    if all(b):
        curves = [dict(x["curve"]) for x in b]
        loads = [h for h, _ in b[-1]["curve"][1:]]
        lines += ["## Along the load path (finest level of each model against the reference at each load)", "",
                  "![error along the load path](../../docs/img/accuracy_vs_load.png)", "",
                  "| H (kN) | reference u (mm) | gap depth of (a) (m) | " +
                  " | ".join(f"error u {MODELS[k].split(' ')[0]}" for k in MODELS) + " |",
                  "|---|---|---|" + "---|" * len(MODELS)]
        gap = dict(runs[("a", finest)]["gap"]) if runs[("a", finest)] else {}
        for Hi in loads:
            values = [next(u for h, u in c.items() if abs(h - Hi) < 1e-6 * H) for c in curves]
            u_i = solid.richardson(hs, values)[0] if len(levels) == 3 else values[-1]
            errs = []
            for k in MODELS:
                res = runs[(k, finest)]
                match = [u for (h, u) in res["curve"] if abs(h - Hi) < 1e-6 * H] if res else []
                errs.append(abs(match[0] - u_i) / abs(u_i) if match else float("nan"))
            depth = min(gap.items(), key=lambda kv: abs(kv[0] - Hi))[1] if gap else float("nan")
            path_rows.append((Hi, depth, errs, u_i))
            lines.append(f"| {Hi:.0f} | {u_i * 1e3:.3f} | {depth:.2f} | " + " | ".join(f"{e:.1%}" for e in errs) + " |")
        lines.append("")

    lines += machine.blas_report()
    RESULTS.mkdir(parents=True, exist_ok=True)
    suffix = "_quick" if args.quick else ""
    (RESULTS / f"accuracy_vs_cost{suffix}.md").write_text("\n".join(lines) + "\n")
    (RESULTS / f"accuracy_vs_cost{suffix}.json").write_text(json.dumps(
        dict(reference=dict(u=u_ref, M=M_ref, order_u=p_u, order_M=p_M, what=reference), rows=rows,
             path=path_rows, curves=curves_json, problem=dataclasses.asdict(problem), H=H), indent=1))
    plots(rows, path_rows, suffix)
    print("\n".join(lines))


def plots(rows, path_rows, suffix):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    folder = IMG if not suffix else RESULTS
    styles = {"a": "o-", "a'": "D-", "b": "s-", "c": "^--", "d": "v:"}
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    for ax, key, label in ((axes[0], "err_u", "error in head displacement at H"),
                           (axes[1], "err_M", "error in the largest pile moment")):
        for model, name in MODELS.items():
            pts = [(r["wall"], max(r[key], 1e-5)) for r in rows if r["model"] == model]
            if pts:
                ax.loglog(*zip(*pts), styles[model], label=name, ms=5)
        ax.axhline(0.05, color="grey", lw=0.8, ls="--")
        ax.text(ax.get_xlim()[0] * 1.1 if ax.get_xlim()[0] > 0 else 1e-3, 0.055, "5 %", color="grey", fontsize=8)
        ax.set_xlabel("wall time (s): build + gravity + push")
        ax.set_ylabel(label)
        ax.grid(True, which="both", alpha=0.3)
    axes[0].legend(fontsize=7)
    fig.suptitle(f"Lateral pile, H = {H:g} kN: error against cost (markers: coarse, medium, fine)", fontsize=10)
    fig.tight_layout()
    fig.savefig(folder / f"accuracy_vs_cost{suffix}.png", dpi=110)
    plt.close(fig)
    if path_rows:
        fig, ax = plt.subplots(figsize=(6.5, 4.2))
        Hs = [p[0] for p in path_rows]
        for i, k in enumerate(MODELS):
            ax.plot(Hs, [100 * p[2][i] for p in path_rows], styles[k], label=MODELS[k], ms=4)
        ax.set_xlabel("head load H (kN)")
        ax.set_ylabel("error in head displacement vs the reference (%)")
        ax.grid(True, alpha=0.3)
        ax2 = ax.twinx()
        ax2.plot(Hs, [p[1] for p in path_rows], "k:", lw=1)
        ax2.set_ylabel("gap depth behind the pile, model (a) (m), dotted")
        ax.legend(fontsize=7, loc="upper left")
        fig.tight_layout()
        fig.savefig(folder / f"accuracy_vs_load{suffix}.png", dpi=110)
        plt.close(fig)


if __name__ == "__main__":
    sys.exit(main())

"""Accuracy against cost for the seismic pile (issue 16), as the static study does for the lateral pile.

The problem is scenes.seismic_pile.SeismicPile: a 0.8 m concrete pile through 10 m of elastic
soil on rigid bedrock, in a periodic soil box, shaken along x by the shipped synthetic record
after a gravity stage (Newmark average acceleration, Rayleigh damping 3 % at the soil column's
first two modes). Models: the beam pile with BeamContact3D (Lagrange multipliers, Coulomb
friction mu = 0.5) and the tied beam pile (rigid links). Each runs at mesh levels (LEVELS) and
time steps; the reference of each model is its finest run (finest level, smallest step).
Errors, relative to the reference: peak head displacement |u|max, the moment envelope (largest
difference over the pile's nodes, interpolated to the reference's elevations, over the
reference's largest moment) and the largest gap opening. Costs: wall time of the whole run
(build, gravity, shaking), per time step and per Newton iteration; equations.

Writes benchmarks/results/seismic_pile_accuracy{_quick}.{md,json} and a PNG chart there.
Timings depend on the machine and its load (two cores shared with other jobs here).

    PYTHONPATH=python python benchmarks/seismic_pile_accuracy.py [--quick] [--fine] [--scale S] [--duration T]
"""
import argparse
import dataclasses
import datetime
import json
import os
import pathlib
import sys

import numpy as np

import machine
from beamsolid.scenes.seismic_pile import LEVELS, Numerics, SeismicPile, run

RESULTS = pathlib.Path(__file__).resolve().parents[1] / "benchmarks" / "results"
MODELS = {"contact": "beam + BeamContact3D", "tied": "beam tied to soil", "py": "beam on p-y springs"}


def plan(quick, fine):
    """(level, dt) pairs, cheapest first; the last one is the reference."""
    runs = [("coarse", 0.02), ("coarse", 0.01), ("coarse", 0.005), ("medium", 0.01), ("medium", 0.005)]
    if quick:
        runs = [("coarse", 0.02), ("coarse", 0.01), ("medium", 0.01)]
    if fine:
        # The fine mesh's contact needs the smaller step to resolve its impacts (at 0.005 s an
        # open node sank into the pile at 2.81 s): 0.0025 s is the reference.
        runs += [("fine", 0.005), ("fine", 0.0025)]
    return runs


def envelope_error(r, ref):
    """max over the reference's nodes of |M_r(z) - M_ref(z)| / max M_ref (M_r linear between its nodes)."""
    z, zr = np.array(r.z)[::-1], np.array(ref.z)[::-1]  # increasing elevations for np.interp
    m, mr = np.array(r.moment_envelope)[::-1], np.array(ref.moment_envelope)[::-1]
    return float(np.max(np.abs(np.interp(zr, z, m) - mr)) / np.max(mr))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--quick", action="store_true", help="coarse and medium at two steps only")
    ap.add_argument("--fine", action="store_true", help="add the fine level (dt 0.005 and 0.0025, the reference)")
    ap.add_argument("--scale", type=float, default=0.05, help="factor on the record (PGA 0.3 g x scale)")
    ap.add_argument("--duration", type=float, default=3.0, help="seconds of the record")
    args = ap.parse_args()
    problem = SeismicPile(scale=args.scale, duration=args.duration)
    runs = plan(args.quick, args.fine)
    load = os.getloadavg()
    results = {}
    for key in MODELS:
        for level, dt in runs:
            r = run(problem, Numerics(level=level, interface=key, dt=dt))
            results[(key, level, dt)] = r
            steps = len(r.time) - 1
            print(f"{MODELS[key]:22s} {level:7s} dt {dt:<6g} {'ok' if r.converged else 'STOPPED':7s} "
                  f"u_max {1e3 * r.peak_head_disp:8.4f} mm  M_max {max(r.moment_envelope):8.2f} kNm  gap "
                  f"{1e3 * r.peak_gap:8.5f} mm  {r.timings['total']:7.1f} s  {steps} steps  {sum(r.iterations)} it  "
                  f"{r.n_equations} eqs", flush=True)

    rows, references = [], {}
    for key in MODELS:
        # The finest run that reached the end of the window (a contact run may stop on chatter).
        done = [(level, dt) for level, dt in runs if results[(key, level, dt)].converged]
        references[key] = done[-1] if done else runs[-1]
        ref = results[(key, *references[key])]
        for level, dt in runs:
            r = results[(key, level, dt)]
            steps, iterations = len(r.time) - 1, sum(r.iterations)
            shaking = r.timings["shaking"]
            rows.append(dict(model=key, level=level, dt=dt, converged=r.converged, equations=r.n_equations,
                             steps=steps, iterations=iterations, wall=r.timings["total"],
                             per_step=shaking / max(steps, 1), per_iteration=shaking / max(iterations, 1),
                             cpu=r.timings["cpu_total"], cpu_per_iteration=r.timings["cpu_shaking"] / max(iterations, 1),
                             solver_share=(r.timings.get("solver") or 0.0) / shaking if shaking > 0 else 0.0,
                             u=r.peak_head_disp, M=max(r.moment_envelope), gap=r.peak_gap,
                             err_u=abs(r.peak_head_disp - ref.peak_head_disp) / ref.peak_head_disp,
                             err_M=envelope_error(r, ref),
                             err_gap=(abs(r.peak_gap - ref.peak_gap) / ref.peak_gap if ref.peak_gap > 0 else None),
                             stopped_at=r.failed_at, reference=(level, dt) == references[key]))

    level_text = ", ".join(f"{k} {v[0]} x {v[1]} x {v[2]}" for k, v in LEVELS.items())
    lines = ["# Accuracy against cost: the seismic pile", "",
             f"Run {datetime.datetime.now():%Y-%m-%d %H:%M}; command `PYTHONPATH=python python "
             f"benchmarks/seismic_pile_accuracy.py{' --quick' if args.quick else ''}{' --fine' if args.fine else ''}"
             f" --scale {args.scale:g} --duration {args.duration:g}`. The first {args.duration:g} s of "
             f"{pathlib.Path(problem.record).name} x {args.scale:g} (PGA {0.3 * args.scale:.3g} g); soil box O-grid "
             f"(n_theta x n_radial x n_z): {level_text}. Reference of each model: its finest run that reached "
             "the end (" + ", ".join(f"{MODELS[k]}: {lv} at dt = {dt:g} s" for k, (lv, dt) in references.items())
             + "); a contact run that stops (an open node sinks into the pile: contact chatter, "
             "docs/seismic_pile.md) is compared over the part it ran. Errors: peak head displacement, the moment "
             "envelope (largest difference over the pile / largest moment), the largest gap. Times: whole run; per step "
             "and per Newton iteration of the shaking stage, and the share of it spent in factorizations and "
             "solves (`solver_info()['solver_seconds']`); CPU: the process's CPU time (steadier than wall time on a "
             f"shared machine; load average {load[0]:.1f} at the start, {os.getloadavg()[0]:.1f} at the end). The p-y "
             "model (no soil box) follows the free field of the 1D column; its levels differ only in the pile's nodes.",
             "",
             f"![error against wall time](seismic_pile_accuracy{'_quick' if args.quick else ''}.png)", "",
             "| model | level | dt (s) | equations | steps | Newton iterations | wall (s) | CPU (s) | ms / step | "
             "ms / iteration | CPU ms / iteration | solver share | peak u (mm) | error u | M_max (kNm) | "
             "error envelope | peak gap (mm) | error gap |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        gap_err = "-" if r["err_gap"] is None else f"{r['err_gap']:.1%}"
        stop = "" if r["converged"] else f" (stopped at {r['stopped_at']:.2f} s)"
        lines.append(f"| {MODELS[r['model']]} | {r['level']} | {r['dt']:g} | {r['equations']} | {r['steps']}"
                     f"{stop} | {r['iterations']} | {r['wall']:.1f} | {r['cpu']:.1f} | "
                     f"{1e3 * r['per_step']:.1f} | {1e3 * r['per_iteration']:.1f} | "
                     f"{1e3 * r['cpu_per_iteration']:.1f} | {r['solver_share']:.0%} | "
                     f"{1e3 * r['u']:.4f} | "
                     f"{'ref' if r['reference'] else format(r['err_u'], '.2%')} | {r['M']:.2f} | "
                     f"{'ref' if r['reference'] else format(r['err_M'], '.2%')} | {1e3 * r['gap']:.5f} | "
                     f"{'ref' if r['reference'] else gap_err} |")
    lines.append("")
    lines += machine.blas_report()
    suffix = "_quick" if args.quick else ""
    RESULTS.mkdir(parents=True, exist_ok=True)
    (RESULTS / f"seismic_pile_accuracy{suffix}.md").write_text("\n".join(lines) + "\n")
    (RESULTS / f"seismic_pile_accuracy{suffix}.json").write_text(json.dumps(
        dict(rows=rows, runs=runs, references=references, problem=dataclasses.asdict(problem)), indent=1))
    chart(rows, suffix)
    print("\n".join(lines))


def chart(rows, suffix):
    import matplotlib
    import matplotlib.ticker

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    markers = {"coarse": "o", "medium": "s", "fine": "D"}
    for ax, key, label in ((axes[0], "err_u", "error in peak head displacement"),
                           (axes[1], "err_M", "error in the moment envelope")):
        for i, model in enumerate(MODELS):
            pts = [r for r in rows if r["model"] == model and not r["reference"]]
            ax.loglog([r["cpu"] for r in pts], [max(r[key], 1e-6) for r in pts], "-", color=f"C{i}", lw=0.8,
                      label=MODELS[model])
            for r in pts:  # hollow: the run stopped on contact chatter
                ax.loglog(r["cpu"], max(r[key], 1e-6), markers[r["level"]], color=f"C{i}", ms=6,
                          mfc=f"C{i}" if r["converged"] else "none")
                ax.annotate(f"{r['dt']:g}", (r["cpu"], max(r[key], 1e-6)), fontsize=7, xytext=(3, 3),
                            textcoords="offset points")
        ax.set_xlabel("CPU time (s): build + gravity + shaking")
        ax.set_ylabel(label)
        ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
        ax.grid(True, which="both", alpha=0.3)
    axes[1].legend(fontsize=8, title="o coarse, s medium, D fine; hollow: stopped; labels: dt (s)",
                   title_fontsize=7, loc="center right")
    fig.suptitle("Seismic pile: error against cost (reference: each model's finest run)", fontsize=10)
    fig.tight_layout()
    fig.savefig(RESULTS / f"seismic_pile_accuracy{suffix}.png", dpi=110)
    plt.close(fig)


if __name__ == "__main__":
    sys.exit(main())

"""Accuracy against cost for the lateral capacity of a pile in clay (issue 18), as the other studies.

The problem is scenes.lateral_capacity.ClayPile: a 0.8 m elastic pile, 6 m in von Mises clay
(s_u = 40 kPa, E = 500 s_u), free head pushed to 0.2 D. Models: beam + BeamContact3D (rough,
smooth), the brick pile with zeroLengthContact3D (rough) and tied, the beam on Matlock p-y springs,
and Broms' closed form. Each runs at the scene's mesh levels; the reference is the finest run of
the most complete model (beam + BeamContact3D, rough: gap, adhesion and plasticity, finite
sliding). Errors against it: the capacity H(0.1 D) (the head load at a head displacement of 0.1 D),
the largest bending moment at the end of the push (0.2 D), and the curve (the largest difference of
H over the push, over the reference's largest H). Cost: CPU time of the run (the process, all
threads: the machine is shared, so wall times are noisy; both are written).

Writes benchmarks/results/lateral_capacity_accuracy{_quick}.{md,json,png}.

    PYTHONPATH=python python benchmarks/lateral_capacity_accuracy.py [--quick]
"""
import argparse
import dataclasses
import datetime
import json
import pathlib
import sys
import time

import numpy as np

import machine
from beamsolid.scenes.lateral_capacity import LEVELS, MODELS, PY_ELEMENTS, ClayPile, Numerics, broms, run

RESULTS = pathlib.Path(__file__).resolve().parents[1] / "benchmarks" / "results"
REFERENCE = "rough"


def curve_error(r, ref):
    """max |H_r(u) - H_ref(u)| over the reference's states, over max H_ref (H_r linear between its states)."""
    u = np.array(ref.head_disp)
    h = np.interp(u, np.array(r.head_disp), np.array(r.head_force))
    return float(np.max(np.abs(h - np.array(ref.head_force))) / np.max(np.abs(ref.head_force)))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--quick", action="store_true", help="coarse and medium only (the reference: medium)")
    args = ap.parse_args()
    problem = ClayPile()
    D = problem.diameter
    levels = ["coarse", "medium"] + ([] if args.quick else ["fine"])
    results = {}
    for level in levels:
        for key in MODELS:
            r = run(key, problem, Numerics(level=level))
            results[(key, level)] = r
            print(f"{MODELS[key]:42s} {level:7s} {'ok' if r.converged else 'STOPPED':7s} H(0.1D) "
                  f"{r.force_at(0.1 * D):7.1f} H(end) {r.capacity:7.1f} kN at {r.head_disp[-1] / D:.3f} D, M_max "
                  f"{r.max_moment:7.1f} kNm, {r.cpu:7.1f} s CPU, {r.wall:7.1f} s wall, {sum(r.iterations)} it, "
                  f"{r.n_equations} eqs", flush=True)
    t0 = time.process_time()
    closed = broms(problem)
    broms_cpu = time.process_time() - t0
    # The reference for H(0.1 D) and the curve: the finest run of the reference model that got
    # past 0.1 D; for M_max at the end: its finest run that reached the end (a push can stall
    # on Newton iterations that cycle, see docs/lateral_capacity.md).
    past = [lv for lv in levels if results[(REFERENCE, lv)].head_disp[-1] >= 0.1 * D]
    ended = [lv for lv in levels if results[(REFERENCE, lv)].converged]
    ref_level = past[-1] if past else levels[-1]
    ref_level_M = ended[-1] if ended else levels[-1]
    ref, ref_M = results[(REFERENCE, ref_level)], results[(REFERENCE, ref_level_M)]
    H_ref, M_ref = ref.force_at(0.1 * D), ref_M.max_moment
    rows = []
    for (key, level), r in results.items():
        H = r.force_at(0.1 * D)
        rows.append(dict(model=key, level=level, converged=r.converged, reached=r.head_disp[-1] / D,
                         fallback_at=r.fallback_at, equations=r.n_equations,
                         elements=r.n_elements, steps=len(r.iterations) - 1, iterations=sum(r.iterations),
                         cuts=r.cuts, cpu=r.cpu, wall=r.wall, H_01D=H, H_end=r.capacity, M_max=r.max_moment,
                         gap_depth=r.gap_depth[-1] if r.gap_depth else 0.0,
                         err_H=abs(H - H_ref) / H_ref if H == H else None,
                         err_M=abs(r.max_moment - M_ref) / abs(M_ref) if r.converged else None,
                         err_curve=curve_error(r, ref) if r.converged or r is ref else None,
                         reference=(key, level) == (REFERENCE, ref_level),
                         reference_M=(key, level) == (REFERENCE, ref_level_M)))
    rows.append(dict(model="broms", level="-", converged=True, equations=0, elements=0, steps=0, iterations=0,
                     cuts=0, cpu=broms_cpu, wall=broms_cpu, H_01D=closed.H, H_end=closed.H, M_max=closed.M_short,
                     gap_depth=0.0, err_H=abs(closed.H - H_ref) / H_ref,
                     err_M=abs(closed.M_short - M_ref) / abs(M_ref), err_curve=None, reference=False,
                     reference_M=False, reached=None, fallback_at=None))

    names = dict(MODELS, broms="Broms (1964), closed form")
    level_text = ", ".join(f"{k} {v[0]} x {v[1]} x {v[2]}+{v[3]} (p-y: {PY_ELEMENTS[k]} beams)"
                           for k, v in LEVELS.items() if k in levels)
    lines = ["# Accuracy against cost: lateral capacity of a pile in clay", "",
             f"Run {datetime.datetime.now():%Y-%m-%d %H:%M}; command `PYTHONPATH=python python "
             f"benchmarks/lateral_capacity_accuracy.py{' --quick' if args.quick else ''}`. "
             f"scenes/lateral_capacity.py: D = {D:g} m, L = {problem.length:g} m elastic pile, free head pushed to "
             f"{problem.head_disp / D:.2f} D in 16 steps, J2 clay s_u = {problem.su:g} kPa, E = {problem.soil_E:g} kPa, "
             f"gamma = {problem.gamma:g}. Soil O-grid (n_theta x n_radial x layers along + below the pile): "
             f"{level_text}. Reference: {names[REFERENCE]} at {ref_level} for H(0.1 D) = {H_ref:.1f} kN and the curve, "
             f"at {ref_level_M} for M_max = {M_ref:.1f} kNm (its finest runs past 0.1 D and to the end). A push "
             "that stops on the line search goes on with plain Newton from its last state ('fallback at'); "
             "'reached': the head displacement of its last converged state. Errors: H(0.1 D), the head load at a head displacement of 0.1 D; M_max at the "
             "end; the curve, the largest difference of H over the push over the reference's largest H. Cost: CPU "
             "seconds of the run (build, gravity stage, push; all threads), on a shared two-core machine; wall "
             "seconds for reference only (other jobs were running).", "",
             f"![error against CPU time](lateral_capacity_accuracy{'_quick' if args.quick else ''}.png)", "",
             "| model | level | equations | reached (D) | fallback at | steps | Newton iterations | step cuts | CPU (s) | "
             "wall (s) | H(0.1 D) (kN) | error | H(end) (kN) | M_max (kNm) | error | curve error | gap depth (m) |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]

    def pct(x, is_ref):
        return "ref" if is_ref else ("-" if x is None else f"{x:.1%}")

    for r in rows:
        reached = "-" if r["reached"] is None else f"{r['reached']:.3f}"
        fallback = "-" if r["fallback_at"] is None else f"{r['fallback_at'] * problem.head_disp / D:.3f} D"
        lines.append(f"| {names[r['model']]} | {r['level']} | {r['equations']} | {reached} | {fallback} | {r['steps']} | "
                     f"{r['iterations']} | {r['cuts']} | {r['cpu']:.2f} | {r['wall']:.1f} | {r['H_01D']:.1f} | "
                     f"{pct(r['err_H'], r['reference'])} | {r['H_end']:.1f} | {r['M_max']:.1f} | "
                     f"{pct(r['err_M'], r['reference_M'])} | {pct(r['err_curve'], r['reference'])} | "
                     f"{r['gap_depth']:.2f} |")
    lines.append("")
    lines += machine.blas_report()
    suffix = "_quick" if args.quick else ""
    RESULTS.mkdir(parents=True, exist_ok=True)
    (RESULTS / f"lateral_capacity_accuracy{suffix}.md").write_text("\n".join(lines) + "\n")
    curves = {f"{k}/{lv}": dict(u=r.head_disp, H=r.head_force, z=r.z, M=r.moment) for (k, lv), r in results.items()}
    (RESULTS / f"lateral_capacity_accuracy{suffix}.json").write_text(json.dumps(
        dict(rows=rows, levels=levels, problem=dataclasses.asdict(problem), curves=curves), indent=1))
    chart(rows, suffix, names)
    print("\n".join(lines))


def chart(rows, suffix, names):
    import matplotlib
    import matplotlib.ticker

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(11.5, 4.6))
    markers = {"coarse": "o", "medium": "s", "fine": "D", "-": "*"}
    keys = list(MODELS) + ["broms"]
    for ax, err, label in ((axes[0], "err_H", "error in the capacity H(0.1 D)"),
                           (axes[1], "err_M", "error in the largest moment")):
        for i, key in enumerate(keys):
            pts = [r for r in rows if r["model"] == key and r[err] is not None
                   and not r["reference" if err == "err_H" else "reference_M"]]
            if not pts:
                continue
            # Broms costs nothing measurable: drawn at 1 ms.
            xs = [max(r["cpu"], 1e-3) for r in pts]
            ys = [max(r[err], 1e-4) for r in pts]
            ax.loglog(xs, ys, "-", color=f"C{i}", lw=0.8, label=names[key])
            for x, y, r in zip(xs, ys, pts):
                ax.loglog(x, y, markers[r["level"]], color=f"C{i}", ms=7 if key == "broms" else 6)
        ax.set_xlabel("CPU time of the run (s); Broms drawn at 1 ms")
        ax.set_ylabel(label)
        ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
        ax.grid(True, which="both", alpha=0.3)
    axes[1].legend(fontsize=7, title="o coarse, s medium, D fine", title_fontsize=7, loc="lower left")
    fig.suptitle("Lateral capacity in clay: error against cost (reference: beam + BeamContact3D, rough, finest)",
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(RESULTS / f"lateral_capacity_accuracy{suffix}.png", dpi=110)
    plt.close(fig)


if __name__ == "__main__":
    sys.exit(main())

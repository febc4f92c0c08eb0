"""The lateral pile's head force against the stick stiffness G, and its runs with the paper's G.

Two tables for docs/lateral_pile.md, from beamsolid.scenes.lateral_pile (monotonic push of the
head to 20 mm, mu = 0.5):

    G        head force at 20 mm against the contact material's stick stiffness G (10 steps),
             Lagrange (BeamContact3D) and penalty (BeamContact3Dp, factor 1e3), coarse and medium;
             once G is stiff the answer should no longer depend on it, nor on the step count
             (the stiffest G is also run in 5 and 20 steps)
    paper    the paper's G = 1000 in 20 steps: equations, head force, gap depth, iterations,
             penetration and wall time of the push, per level and interface

Writes benchmarks/results/lateral_pile_tables.{md,json}.

    PYTHONPATH=python:benchmarks python benchmarks/lateral_pile_tables.py [--fine]

--fine adds the fine level to the paper table (Lagrange only; about 2 minutes).
"""
import argparse
import datetime
import json
import pathlib
import sys
import time

import machine
from beamsolid.scenes.lateral_pile import LateralPile, Numerics, run

RESULTS = pathlib.Path(__file__).resolve().parents[1] / "benchmarks" / "results"
G_VALUES = {"coarse": [1e3, 3e3, 1e4, 1e5, 1e6], "medium": [1e3, 1e4, 1e5, 1e6]}


def measure(level, interface, G, steps):
    t0 = time.perf_counter()
    r = run(LateralPile(), Numerics(level=level, interface=interface, contact_G=G, steps=steps))
    wall = time.perf_counter() - t0
    its = r.iterations[1:]
    return dict(level=level, interface=interface, G=G, steps=steps, converged=r.converged,
                H=r.head_force[-1], gap_depth=r.gap_depth[-1], iterations=sum(its), it_min=min(its),
                it_max=max(its), penetration=max(r.max_penetration), overlap=max(r.max_open_overlap),
                equations=r.n_equations, push=r.timings["push"], wall=wall)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--fine", action="store_true", help="add the fine level (Lagrange) to the paper table")
    args = ap.parse_args()
    started = time.perf_counter()
    rows_g, rows_paper = [], []
    for level, Gs in G_VALUES.items():
        for interface in ("contact", "penalty"):
            for G in Gs:
                rows_g.append(measure(level, interface, G, 10))
                print(rows_g[-1], flush=True)
        for steps in (5, 20):
            rows_g.append(measure(level, "contact", Gs[-1], steps))
            print(rows_g[-1], flush=True)
    for level in ("coarse", "medium") + (("fine",) if args.fine else ()):
        for interface in ("contact", "penalty") if level != "fine" else ("contact",):
            rows_paper.append(measure(level, interface, 1e3, 20))
            print(rows_paper[-1], flush=True)

    lines = ["# Lateral pile: head force against the stick stiffness G, and the paper's G = 1000", "",
             f"Run {datetime.datetime.now():%Y-%m-%d %H:%M}, command "
             f"`PYTHONPATH=python:benchmarks python benchmarks/lateral_pile_tables.py{' --fine' if args.fine else ''}`. "
             "Monotonic push of the head to 20 mm, mu = 0.5; penalty form: factor 1e3 x E_soil R.", "",
             "## Head force at 20 mm against G", "",
             "| level | interface | G (kN/m) | steps | H (kN) | H / H(stiffest G, 10 steps) | iterations per step |",
             "|---|---|---|---|---|---|---|"]
    for row in rows_g:
        ref = next(r for r in rows_g if r["level"] == row["level"] and r["interface"] == row["interface"]
                   and r["G"] == G_VALUES[row["level"]][-1] and r["steps"] == 10)
        lines.append(f"| {row['level']} | {row['interface']} | {row['G']:.0e} | {row['steps']} | "
                     + (f"{row['H']:.1f} | {row['H'] / ref['H']:.4f} | {row['it_min']}-{row['it_max']} |"
                        if row["converged"] else "fails | | |"))
    lines += ["", "## The paper's G = 1000, 20 steps", "",
              "| level | interface | equations | H at 20 mm (kN) | gap depth (m) | iterations / steps | "
              "max penetration (m) | max open overlap (m) | push (s) |",
              "|---|---|---|---|---|---|---|---|---|"]
    for row in rows_paper:
        lines.append(f"| {row['level']} | {row['interface']} | {row['equations']} | {row['H']:.1f} | "
                     f"{row['gap_depth']:.2f} | {row['iterations']} / {row['steps']} | {row['penetration']:.0e} | "
                     f"{row['overlap']:.0e} | {row['push']:.1f} |")
    lines += ["", f"Total wall time {time.perf_counter() - started:.0f} s.", ""] + machine.blas_report()
    RESULTS.mkdir(parents=True, exist_ok=True)
    (RESULTS / "lateral_pile_tables.md").write_text("\n".join(lines) + "\n")
    (RESULTS / "lateral_pile_tables.json").write_text(json.dumps(dict(G=rows_g, paper=rows_paper), indent=1))
    print("\n".join(lines))


if __name__ == "__main__":
    sys.exit(main())

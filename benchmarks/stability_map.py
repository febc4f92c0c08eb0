"""Where the contact methods fail: a convergence map of the lateral pile (issue 5).

The lateral pile of beamsolid.scenes.lateral_pile (coarse mesh unless --level) is
pushed at the head, monotonically to +d and cyclically 0 -> +d -> -d -> +d (the gap
opens and closes on both sides every cycle). Three maps per protocol, each against
the contact method (BeamContact3D with Lagrange multipliers, or BeamContact3Dp with
penalty = factor x E_soil R, factor 1e-2 .. 1e6):

    steps      load-step size over two decades (1, 10, 100 steps per quarter cycle),
               mu = 0.5, Newton
    mu         friction coefficient 0.1, 0.5, 1.0 (10 steps, cyclic 5; Newton)
    algorithm  Newton, NewtonLineSearch, KrylovNewton (10 steps, cyclic 5; mu = 0.5)
    G          the contact material's stick stiffness G, 1e2 .. 1e6 kN/m per contact node
               (10 steps, mu = 0.5, Newton; elsewhere G = 1e5, the lateral pile's default)

Each cell records: converged or not, Newton iterations per step, the largest
interpenetration of a closed contact and the largest overlap of an open one with
the pile (both relative to d), and the error of the head
force at the load peaks against the reference: Lagrange multipliers at the finest
step of the steps map, Newton, same mu and protocol (the finest converged answer). Every
cell that fails is run again with adaptive stepping (cut on failure, grow back)
to show where that rescues it.

Every run goes through beamsolid.sweep (docs/sweeps.md): a local Dask cluster, one worker per core
(or --workers N, or --scheduler ADDRESS), each run stored in a Parquet folder (--store; a re-run
skips the runs stored there, --fresh empties it first); --serial runs them one after the other here.

Writes benchmarks/results/stability_map[_PROTOCOL].{md,json} and docs/img/stability_*.png.

    PYTHONPATH=python python benchmarks/stability_map.py [--quick] [--level coarse] [--protocol P]
        [--serial | --workers N | --scheduler ADDRESS] [--store DIR] [--fresh]
"""
import argparse
import dataclasses
import datetime
import json
import math
import os
import pathlib
import shutil
import sys
import time

import machine
from beamsolid import sweep
from beamsolid.scenes.lateral_pile import LateralPile, Numerics, run

ROOT = pathlib.Path(__file__).resolve().parents[1]
RESULTS = ROOT / "benchmarks" / "results"
IMG = ROOT / "docs" / "img"

METHODS = ["Lagrange", 1e-2, 1e0, 1e2, 1e4, 1e6]  # Lagrange, then penalty factors
STEPS = {"monotonic": [1, 10, 100], "cyclic": [1, 10, 100]}  # steps per quarter cycle: two decades
MID_STEPS = {"monotonic": 10, "cyclic": 5}  # the other maps' step count
MUS = [0.1, 0.5, 1.0]
ALGORITHMS = ["Newton", "NewtonLineSearch", "KrylovNewton"]
PROTOCOLS = ["monotonic", "cyclic"]
STICK_G = [1e2, 1e3, 1e4, 1e5, 1e6]  # ContactMaterial3D stick stiffness G (kN/m per contact node)
REFERENCE_STEPS = {"monotonic": 100, "cyclic": 100}  # = the finest steps cell (run once, cached)
_CACHE = {}  # cell key -> result: filled from the sweep's store


def method_label(method):
    return "Lagrange" if method == "Lagrange" else f"penalty {method:.0e}"


def numerics(method, steps, algorithm, protocol, level, adaptive=False, contact_G=None):
    extra = {} if contact_G is None else {"contact_G": contact_G}
    if method == "Lagrange":
        return Numerics(level=level, interface="contact", algorithm=algorithm, steps=steps, protocol=protocol,
                        cycles=1, adaptive=adaptive, **extra)
    return Numerics(level=level, interface="penalty", penalty_factor=method, algorithm=algorithm, steps=steps,
                    protocol=protocol, cycles=1, adaptive=adaptive, **extra)


def peaks(result):
    """Head force at each load reversal and at the end: the states at |head_disp| = d."""
    d = max(abs(u) for u in result.head_disp) if result.head_disp else 0.0
    return [(u, f) for u, f in zip(result.head_disp, result.head_force) if d > 0 and abs(abs(u) - d) < 1e-9 * d]


def run_cell(problem, method, steps, mu, algorithm, protocol, level, adaptive=False, contact_G=None):
    """The cell's result: from the sweep's store (see run_cells), or run here if it was not swept."""
    key = (method, steps, mu, algorithm, protocol, level, adaptive, contact_G)
    if key not in _CACHE:
        _CACHE[key] = _run_cell(problem, method, steps, mu, algorithm, protocol, level, adaptive, contact_G)
    return dict(_CACHE[key])


def cell_point(method, steps, mu, algorithm, protocol, level, adaptive=False, contact_G=None):
    """A cell as a sweep point: the parameters are columns of the store, so the method is text."""
    return dict(method="Lagrange" if method == "Lagrange" else repr(float(method)), steps=int(steps), mu=float(mu),
                algorithm=algorithm, protocol=protocol, level=level, adaptive=bool(adaptive),
                contact_G=None if contact_G is None else float(contact_G))


def _cell_args(point):
    method = point["method"] if point["method"] == "Lagrange" else float(point["method"])
    return (method, point["steps"], point["mu"], point["algorithm"], point["protocol"], point["level"],
            point["adaptive"], point["contact_G"])


def cell(method, steps, mu, algorithm, protocol, level, adaptive, contact_G):
    """The sweep's function: one cell of the maps, on the default LateralPile. A cell that does not
    converge keeps its results and is stored as failed, with the analyze code and the reason."""
    point = dict(method=method, steps=steps, mu=mu, algorithm=algorithm, protocol=protocol, level=level,
                 adaptive=adaptive, contact_G=contact_G)
    out = _run_cell(LateralPile(), *_cell_args(point))
    out.pop("wall")  # the sweep times every run itself (column wall)
    return out


def run_cells(points, args, what):
    """Run the cells (sweep points) through beamsolid.sweep into args.store and load them into _CACHE."""
    points = list({sweep.point_key(p): p for p in points}.values())
    summary = sweep.run(cell, points, args.store, scheduler=args.scheduler, workers=args.workers,
                        serial=args.serial, name=f"stability_map {what}")
    print(f"{what}: {summary.points} cells, {summary.skipped} already stored, {summary.ran} run "
          f"({summary.failed} did not converge, {summary.errors} raised) in {summary.wall:.1f} s", flush=True)
    for point, row in zip(points, sweep.read(args.store, points)):
        result = {k: row.get(k) for k in ("converged", "iterations", "penetration", "overlap", "peaks", "steps_cut",
                                          "reached")}
        result["peaks"] = [tuple(p) for p in result["peaks"] or []]
        result["converged"] = bool(result["converged"])
        result["steps_cut"] = result["steps_cut"] or 0
        result["reached"] = result["reached"] or 0.0
        result.update(wall=row["wall"], error=row["error"] if row["status"] != "ok" else None,
                      returncode=row["returncode"])
        if row["status"] == "error":  # the function raised outside the lateral pile run (e.g. a lost worker)
            result.update(converged=False, iterations=None, penetration=None, overlap=None)
        _CACHE[_cell_args(point)] = result
    return summary


def _run_cell(problem, method, steps, mu, algorithm, protocol, level, adaptive, contact_G):
    p = dataclasses.replace(problem, mu=mu)
    t0 = time.perf_counter()
    try:
        r = run(p, numerics(method, steps, algorithm, protocol, level, adaptive, contact_G))
        error = None
    except Exception as exc:  # a cell that raises is a failed cell, with the reason kept
        r, error = None, f"{type(exc).__name__}: {exc}"
    wall = time.perf_counter() - t0
    if r is None:
        return dict(converged=False, iterations=None, penetration=None, overlap=None, peaks=[], wall=wall,
                    error=error, steps_cut=0, reached=0.0, returncode=None)
    n_steps = max(1, len(r.iterations))
    return dict(converged=bool(r.converged), iterations=sum(r.iterations) / n_steps,
                penetration=max(r.max_penetration, default=0.0) / p.head_disp,
                overlap=max(r.max_open_overlap, default=0.0) / p.head_disp,
                peaks=peaks(r), wall=wall, steps_cut=getattr(r, "steps_cut", 0), reached=len(r.head_disp),
                returncode=r.returncode,
                error=None if r.converged else f"stopped at protocol time {r.failed_at}: {r.error}")


def peak_error(cell, reference):
    """max over the reference's peaks of |F - F_ref| / max |F_ref| (None if a peak is missing)."""
    if not cell["converged"] or not reference["converged"]:
        return None
    ref = reference["peaks"]
    got = cell["peaks"]
    if len(got) != len(ref):
        return None
    scale = max(abs(f) for _, f in ref)
    return max(abs(f - fr) for (_, f), (_, fr) in zip(got, ref)) / scale


def maps(quick, protocol):
    """(name, rows, columns, cell parameters) of the maps."""
    methods = METHODS if not quick else ["Lagrange", 1e0, 1e4]
    steps = STEPS[protocol] if not quick else [1, 10]
    mid = MID_STEPS[protocol]
    return [
        ("steps", methods, steps, lambda m, c: dict(method=m, steps=c, mu=0.5, algorithm="Newton")),
        ("mu", methods, MUS if not quick else [0.1, 1.0],
         lambda m, c: dict(method=m, steps=mid, mu=c, algorithm="Newton")),
        ("algorithm", methods, ALGORITHMS if not quick else ["Newton", "KrylovNewton"],
         lambda m, c: dict(method=m, steps=mid, mu=0.5, algorithm=c)),
        ("G", methods, STICK_G if not quick else [1e3, 1e5],
         lambda m, c: dict(method=m, steps=mid, mu=0.5, algorithm="Newton", contact_G=c)),
    ]


def heatmap(name, protocol, methods, columns, cells, path):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    fig, axes = plt.subplots(1, 2, figsize=(10, 0.55 * len(methods) + 1.8))
    err = np.full((len(methods), len(columns)), np.nan)
    pen = np.full((len(methods), len(columns)), np.nan)
    for i, m in enumerate(methods):
        for j, c in enumerate(columns):
            cell = cells[(method_label(m), str(c))]
            if cell["converged"] and cell.get("peak_error") is not None:
                err[i, j] = math.log10(max(cell["peak_error"], 1e-12))
            if cell["converged"] and cell["penetration"] is not None:
                pen[i, j] = math.log10(max(cell["penetration"], cell.get("overlap") or 0.0, 1e-12))
    for ax, data, title in ((axes[0], err, "log10 error of peak head force"),
                            (axes[1], pen, "log10 overlap with the pile / d\n(closed: penetration; open: status lag)")):
        im = ax.imshow(data, cmap="viridis_r", aspect="auto", vmin=-8, vmax=0)
        ax.set_xticks(range(len(columns)), [str(c) for c in columns], rotation=15, fontsize=8)
        ax.set_yticks(range(len(methods)), [method_label(m) for m in methods])
        ax.set_xlabel(name)
        ax.set_title(title, fontsize=10)
        for i, m in enumerate(methods):
            for j, c in enumerate(columns):
                cell = cells[(method_label(m), str(c))]
                if cell["converged"]:
                    text = f"{cell['iterations']:.1f} it"
                elif cell.get("rescued"):
                    text = "fail\nA: ok"
                else:
                    text = "fail"
                ax.text(j, i, text, ha="center", va="center", fontsize=7,
                        color=("black" if not math.isnan(data[i, j]) and data[i, j] < -4 else "white")
                        if cell["converged"] else "red")
        fig.colorbar(im, ax=ax, shrink=0.8)
    fig.suptitle(f"Lateral pile, {protocol} head displacement: convergence against {name} "
                 "(text: Newton iterations per step; 'A: ok' = rescued by adaptive steps)", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def replot():
    """Redraw docs/img/stability_*.png from benchmarks/results/stability_map*.json."""
    for path in sorted(RESULTS.glob("stability_map*.json")):
        if "quick" in path.name:
            continue
        data = json.loads(path.read_text())
        for protocol, maps_ in data["maps"].items():
            for name, cells in maps_.items():
                if name == "references":
                    continue
                cells = {tuple(k.split(" | ")): v for k, v in cells.items()}
                methods = [m for m in METHODS if (method_label(m), next(iter(cells))[1]) in cells]
                columns = [c for c in dict.fromkeys(k[1] for k in cells)]
                heatmap(name, protocol, methods, columns, cells, IMG / f"stability_{protocol}_{name}.png")
                print(f"redrew stability_{protocol}_{name}.png")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--quick", action="store_true", help="a few cells only (a smoke run)")
    ap.add_argument("--level", default="coarse")
    ap.add_argument("--protocol", choices=("monotonic", "cyclic", "both"), default="both",
                    help="one protocol per process lets two cores run the two halves side by side")
    ap.add_argument("--replot", action="store_true", help="redraw the heatmaps from the JSON results only")
    ap.add_argument("--serial", action="store_true", help="run the cells here, one after the other (no Dask)")
    ap.add_argument("--workers", type=int, help="local Dask worker processes (default: one per core)")
    ap.add_argument("--scheduler", metavar="ADDRESS", help="run on an existing Dask scheduler instead")
    ap.add_argument("--store", type=pathlib.Path, help="the sweep's Parquet folder (default: "
                    "build/sweeps/stability_map[_quick]_LEVEL); stored cells are not run again")
    ap.add_argument("--fresh", action="store_true", help="empty the store first (after a code change)")
    args = ap.parse_args()
    if args.replot:
        return replot()
    if args.store is None:
        args.store = ROOT / "build" / "sweeps" / f"stability_map{'_quick' if args.quick else ''}_{args.level}"
    if args.fresh and args.store.exists():
        shutil.rmtree(args.store)
    problem = LateralPile()
    if problem != LateralPile():
        raise SystemExit("stability_map: the sweep's cells run the default LateralPile")
    started = time.perf_counter()
    protocols = PROTOCOLS if args.protocol == "both" else [args.protocol]
    # The runs, first all cells and references at once, then the adaptive re-runs of the cells that failed.
    cells_needed = []
    for protocol in protocols:
        for mu in sorted({0.5, *(MUS if not args.quick else [0.1, 1.0])}):
            cells_needed.append(cell_point("Lagrange", REFERENCE_STEPS[protocol] if not args.quick else 20, mu,
                                           "Newton", protocol, args.level))
        for name, methods, columns, params in maps(args.quick, protocol):
            if name == "G" and protocol == "cyclic":
                continue
            for m in methods:
                for c in columns:
                    kw = params(m, c)
                    cells_needed.append(cell_point(kw["method"], kw["steps"], kw["mu"], kw["algorithm"], protocol,
                                                   args.level, contact_G=kw.get("contact_G")))
    run_cells(cells_needed, args, "cells")
    rescues = [dict(p, adaptive=True) for p in cells_needed if not _CACHE[_cell_args(p)]["converged"]]
    run_cells(rescues, args, "adaptive re-runs")
    swept = time.perf_counter() - started
    results = {"level": args.level, "problem": dataclasses.asdict(problem), "maps": {}}
    lines = ["# Stability map: the lateral pile under monotonic and cyclic head displacement", "",
             f"Run {datetime.datetime.now():%Y-%m-%d %H:%M}, level `{args.level}`, command "
             f"`PYTHONPATH=python python benchmarks/stability_map.py{' --quick' if args.quick else ''}"
             f"{' --level ' + args.level if args.level != 'coarse' else ''}"
             f"{' --protocol ' + args.protocol if args.protocol != 'both' else ''}`.",
             f"Head displacement d = {problem.head_disp} m; penalty = factor x E_soil R = factor x "
             f"{problem.stiffness_scale:g} kN/m. Error: largest |F - F_ref| / max |F_ref| at the load peaks, "
             f"reference = Lagrange, the finest step (monotonic {REFERENCE_STEPS['monotonic']}, cyclic "
             f"{REFERENCE_STEPS['cyclic']} steps per quarter cycle), Newton, same mu. Cyclic: one full cycle "
             "0 -> +d -> 0 -> -d -> 0. pen: largest penetration of a closed contact / d; ovl: largest "
             "overlap of an open (released) contact with the pile / d, which the one-step status lag leaves "
             "until the next commit.", ""]
    for protocol in protocols:
        references = {}
        for mu in sorted({0.5, *(MUS if not args.quick else [0.1, 1.0])}):
            ref = run_cell(problem, "Lagrange", REFERENCE_STEPS[protocol] if not args.quick else 20, mu, "Newton",
                           protocol, args.level)
            references[mu] = ref
            print(f"{protocol:9s} reference mu={mu}: converged={ref['converged']} "
                  f"{ref['iterations'] or 0:.2f} it/step {ref['wall']:.1f} s", flush=True)
        results["maps"][protocol] = {"references": {str(k): v for k, v in references.items()}}
        for name, methods, columns, params in maps(args.quick, protocol):
            if name == "G" and protocol == "cyclic":
                continue  # the stick stiffness is mapped under monotonic loading only (cost)
            cells = {}
            for m in methods:
                for c in columns:
                    kw = params(m, c)
                    cell = run_cell(problem, kw["method"], kw["steps"], kw["mu"], kw["algorithm"], protocol,
                                    args.level, contact_G=kw.get("contact_G"))
                    cell["peak_error"] = peak_error(cell, references[kw["mu"]])
                    if not cell["converged"]:
                        rescue = run_cell(problem, kw["method"], kw["steps"], kw["mu"], kw["algorithm"], protocol,
                                          args.level, adaptive=True, contact_G=kw.get("contact_G"))
                        cell["rescued"] = rescue["converged"]
                        cell["rescue"] = {k: rescue[k] for k in ("converged", "iterations", "wall", "steps_cut")}
                        cell["rescue"]["peak_error"] = peak_error(rescue, references[kw["mu"]])
                    cells[(method_label(m), str(c))] = cell
                    print(f"{protocol:9s} {name:9s} {method_label(m):14s} {str(c):16s} "
                          f"{'ok  ' if cell['converged'] else 'FAIL'} "
                          f"it/step {cell['iterations'] or 0:5.2f} pen {cell['penetration'] or 0:.1e} "
                          f"ovl {cell['overlap'] or 0:.1e} "
                          f"err {cell['peak_error'] if cell['peak_error'] is not None else float('nan'):.1e} "
                          f"{'rescued' if cell.get('rescued') else ''} {cell['wall']:.1f} s", flush=True)
            results["maps"][protocol][name] = {f"{k[0]} | {k[1]}": v for k, v in cells.items()}
            folder = IMG if not args.quick else RESULTS
            folder.mkdir(parents=True, exist_ok=True)
            png = folder / f"stability_{protocol}_{name}{'_quick' if args.quick else ''}.png"
            heatmap(name, protocol, methods, columns, cells, png)
            link = f"../../docs/img/{png.name}" if not args.quick else png.name
            lines += [f"## {protocol}: against {name}", "", f"![{protocol} {name}]({link})", "",
                      "| method | " + " | ".join(f"{name} = {c}" for c in columns) + " |",
                      "|---|" + "---|" * len(columns)]
            for m in methods:
                row = []
                for c in columns:
                    cell = cells[(method_label(m), str(c))]
                    if cell["converged"]:
                        err = cell["peak_error"]
                        row.append(f"{cell['iterations']:.1f} it, pen {cell['penetration']:.0e}, "
                                   f"ovl {cell['overlap']:.0e}, err {err:.0e}" if err is not None
                                   else f"{cell['iterations']:.1f} it")
                    else:
                        rescue = cell.get("rescue", {})
                        row.append("**fails**" + (f"; adaptive: ok, {rescue['iterations']:.1f} it, "
                                                  f"{rescue['steps_cut']} cuts" if cell.get("rescued")
                                                  else "; adaptive fails too"))
                lines.append(f"| {method_label(m)} | " + " | ".join(row) + " |")
            lines.append("")
    runner = ("serially in one process (--serial)" if args.serial else
              f"on the Dask scheduler {args.scheduler}" if args.scheduler else
              f"on a local Dask cluster of {args.workers or os.cpu_count()} worker processes, one BLAS thread each")
    lines += [f"Total wall time {time.perf_counter() - started:.0f} s ({swept:.0f} s for the runs, {runner}; "
              f"store `{args.store}`).", ""] + machine.blas_report()
    RESULTS.mkdir(parents=True, exist_ok=True)
    suffix = ("_quick" if args.quick else "") + ("" if args.protocol == "both" else "_" + args.protocol)
    (RESULTS / f"stability_map{suffix}.md").write_text("\n".join(lines) + "\n")
    (RESULTS / f"stability_map{suffix}.json").write_text(json.dumps(results, indent=1, default=str))
    print("\n".join(lines))


if __name__ == "__main__":
    sys.exit(main())

"""The stability map on a local Dask cluster of 2 workers against the serial loop (issue 19).

Runs benchmarks/stability_map.py twice, each time from an empty store: with --serial (every
cell in one process, one after the other: the loop it had before the sweep) and with
--workers 2. The serial process runs with OPENBLAS_NUM_THREADS=1 like each worker
(--serial-blas-threads to change it): with 2 BLAS threads the factorizations sum in another
order and the results differ in the last digits (2e-11 relative in the quick map), so only
equal BLAS threads can give identical results. Times each whole run (process start to exit: cluster start-up, the runs, tables
and charts), then compares the two stores point by point (every column but wall, worker and
finished; nan equals nan) and the two Markdown tables line by line (but the lines with dates
and timings). The aim on 2 cores: the 2 workers take at most 0.6 of the serial time.

Writes benchmarks/results/sweep_speedup[_quick]_PROTOCOL.{md,json}. The machine's load average
is recorded before and after each run: other work on the machine slows either run.

    PYTHONPATH=python python benchmarks/sweep_speedup.py [--protocol monotonic] [--quick] [--workers 2]
"""
import argparse
import datetime
import json
import math
import os
import pathlib
import subprocess
import sys
import time

import machine
from beamsolid import sweep

ROOT = pathlib.Path(__file__).resolve().parents[1]
RESULTS = ROOT / "benchmarks" / "results"
VOLATILE = {"wall", "worker", "finished"}


def same(a, b):
    if isinstance(a, float) and isinstance(b, float) and math.isnan(a) and math.isnan(b):
        return True
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
    return a == b


def table_lines(path):
    """The Markdown without the lines that carry a date or a timing, and without the machine section
    (it reports the BLAS threads of the process that wrote it)."""
    text = path.read_text().split("## Machine and BLAS")[0]
    return [l for l in text.splitlines() if not l.startswith(("Run ", "Total wall time"))]


def run_map(args, mode, store, blas_threads=None):
    cmd = [sys.executable, str(ROOT / "benchmarks" / "stability_map.py"), "--protocol", args.protocol,
           "--store", str(store), "--fresh"] + (["--quick"] if args.quick else []) + mode
    load0 = os.getloadavg()
    cpu0 = sum(os.times()[2:4])
    t0 = time.perf_counter()
    env = dict(os.environ, PYTHONPATH=str(ROOT / "python"))
    if blas_threads:
        env["OPENBLAS_NUM_THREADS"] = env["OMP_NUM_THREADS"] = str(blas_threads)
    done = subprocess.run(cmd, env=env, capture_output=True, text=True)
    wall = time.perf_counter() - t0
    cpu = sum(os.times()[2:4]) - cpu0  # children's user + system time
    if done.returncode != 0:
        sys.exit(f"sweep_speedup: {' '.join(cmd)} failed:\n{done.stderr[-3000:]}")
    md = RESULTS / f"stability_map{'_quick' if args.quick else ''}_{args.protocol}.md"
    return dict(command=" ".join(cmd[1:]), wall=wall, cpu=cpu, load_before=load0, load_after=os.getloadavg(),
                table=table_lines(md))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--protocol", choices=("monotonic", "cyclic"), default="monotonic")
    ap.add_argument("--quick", action="store_true", help="the quick map (a few cells)")
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--serial-blas-threads", type=int, default=1,
                    help="OPENBLAS_NUM_THREADS of the serial run (0: leave the environment's)")
    args = ap.parse_args()
    stores = {m: ROOT / "build" / "sweeps" / f"speedup_{m}_{args.protocol}{'_quick' if args.quick else ''}"
              for m in ("serial", "dask")}
    serial = run_map(args, ["--serial"], stores["serial"], args.serial_blas_threads)
    print(f"serial: {serial['wall']:.1f} s", flush=True)
    dask = run_map(args, ["--workers", str(args.workers)], stores["dask"])
    print(f"{args.workers} workers: {dask['wall']:.1f} s", flush=True)

    a = {r[sweep.KEY]: r for r in sweep.read(stores["serial"])}
    b = {r[sweep.KEY]: r for r in sweep.read(stores["dask"])}
    differ = []
    for key in sorted(set(a) | set(b)):
        ra, rb = a.get(key), b.get(key)
        if ra is None or rb is None:
            differ.append((key, "stored by one run only"))
            continue
        cols = [c for c in sorted(set(ra) | set(rb)) if c not in VOLATILE and not same(ra.get(c), rb.get(c))]
        if cols:
            differ.append((key, f"columns {cols}"))
    tables_equal = serial["table"] == dask["table"]
    ratio = dask["wall"] / serial["wall"]
    suffix = ("_quick" if args.quick else "") + "_" + args.protocol
    lines = ["# The stability map: 2 Dask workers against the serial loop", "",
             f"Run {datetime.datetime.now():%Y-%m-%d %H:%M}, command `PYTHONPATH=python python "
             f"benchmarks/sweep_speedup.py --protocol {args.protocol}{' --quick' if args.quick else ''}"
             f"{' --workers ' + str(args.workers) if args.workers != 2 else ''}`: "
             f"`benchmarks/stability_map.py --protocol {args.protocol}{' --quick' if args.quick else ''}` from an "
             "empty store, once with `--serial` and once on a local Dask cluster. Wall time: the whole "
             "process (start-up, runs, tables, charts).", "",
             "| run | wall time (s) | load average before -> after (1 min) |", "|---|---|---|",
             f"| serial loop (`--serial`, OPENBLAS_NUM_THREADS={args.serial_blas_threads or 'unset'}) | "
             f"{serial['wall']:.1f} | {serial['load_before'][0]:.2f} -> "
             f"{serial['load_after'][0]:.2f} |",
             f"| local cluster, {args.workers} workers (`--workers {args.workers}`) | {dask['wall']:.1f} | "
             f"{dask['load_before'][0]:.2f} -> {dask['load_after'][0]:.2f} |", "",
             f"- CPU time of the benchmark's process tree: serial {serial['cpu']:.1f} s, workers {dask['cpu']:.1f} s "
             "(the load average counts other work on the machine too).",
             f"- Ratio {args.workers} workers / serial: **{ratio:.3f}** (aim on 2 cores: at most 0.6).",
             f"- Runs stored: {len(a)} serial, {len(b)} on the workers; identical point by point (every column "
             f"but wall, worker, finished): **{len(set(a) & set(b)) - len(differ)} of {len(set(a) | set(b))}**.",
             f"- The Markdown tables (but dates and timings) are {'identical' if tables_equal else 'DIFFERENT'}.",
             ""]
    for key, what in differ:
        lines.append(f"- differs: `{key}`: {what}")
    lines += machine.blas_report()
    RESULTS.mkdir(parents=True, exist_ok=True)
    (RESULTS / f"sweep_speedup{suffix}.md").write_text("\n".join(lines) + "\n")
    (RESULTS / f"sweep_speedup{suffix}.json").write_text(json.dumps(dict(
        serial={k: v for k, v in serial.items() if k != "table"}, dask={k: v for k, v in dask.items() if k != "table"},
        workers=args.workers, ratio=ratio, points=len(set(a) | set(b)), differ=differ, tables_equal=tables_equal,
        cpu_count=os.cpu_count()), indent=1))
    print("\n".join(lines))
    return 0 if not differ and tables_equal else 1


if __name__ == "__main__":
    sys.exit(main())

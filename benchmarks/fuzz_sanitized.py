"""The command fuzzer under AddressSanitizer + UBSan: 100,000 random command sequences.

Runs tools/fuzz_commands.py against the sanitizer build (`make sanitize-build`,
build-sanitize/) in child Pythons with the sanitizer runtimes preloaded, one
child per chunk of sequences, each chunk its own seed, so a crash or report
names the seed that reproduces it. A chunk that dies is re-run with --trace to
name the sequence and call. Writes benchmarks/results/fuzz_sanitized.md and
.json: sequences, calls, ok, OpenSeesErrors, findings (crashes, sanitizer
reports, exceptions other than OpenSeesError), the time taken, and the
command to reproduce. Not part of `make test` or CI.

    .venv/bin/python benchmarks/fuzz_sanitized.py                 # 100,000 sequences
    .venv/bin/python benchmarks/fuzz_sanitized.py --sequences 2000 --out /tmp/fuzz   # a quick look
"""
import argparse
import concurrent.futures
import datetime
import json
import os
import pathlib
import platform
import subprocess
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parents[1]
FUZZER = ROOT / "tools" / "fuzz_commands.py"
RESULTS = ROOT / "benchmarks" / "results"
# What earlier runs of this benchmark found, each fixed at its cause (git log names the commits).
FIXED_FINDINGS = [
    "UBSan signed-integer-overflow: `equalDOF(r, c, -2**31)` computed dof - 1 before any check "
    "(bindings/InterpreterModel.cpp; also `remove('sp', node, dof)`): a dof < 1 is now an OpenSeesError.",
    "ASan out-of-memory abort: `patch('circ', 1, 4, 2**31 - 1, ...)` asked for 200 GB of fibers "
    "(bindings/InterpreterSections.cpp): at most a million fibers per patch or layer, an OpenSeesError.",
    "Abort (std::terminate): an EnvelopeNode recorder on /dev/null failed to rewrite its file at wipe(), "
    "which raised half done, and the Domain destructor then threw the same error at exit (core/Domain.cpp, "
    "bindings/InterpreterModel.cpp, core/RecorderOutput.cpp): destructors report instead of throwing, "
    "removeRecorders closes every recorder before raising, wipe() finishes first, only regular files are "
    "cut back.",
    "ASan heap-buffer-overflow: a mass on a node constrained by rigidLink('beam') with no element at "
    "either node made AnalysisModel::assembleMass write at pattern position -1 (analysis/DofMap.cpp): "
    "the pattern now couples the equations of every dof tied to several.",
]
SANITIZER_MARKERS = ("ERROR: AddressSanitizer", "ERROR: LeakSanitizer", "runtime error:", "SUMMARY: UndefinedBehavior")


def sanitizer_runtimes(cxx="g++"):
    """The real paths of the ASan and UBSan runtimes of the compiler that built build-sanitize."""
    paths = []
    for name in ("libasan.so", "libubsan.so"):
        out = subprocess.run([cxx, f"-print-file-name={name}"], capture_output=True, text=True, check=True)
        path = os.path.realpath(out.stdout.strip())
        if not os.path.exists(path):
            raise SystemExit(f"{cxx} has no {name}: install the sanitizer runtime")
        paths.append(path)
    return paths


def sanitized_env(build):
    """The environment of `make sanitize`'s Python run (see the Makefile for the reasons)."""
    env = dict(os.environ)
    env.update({
        "LD_PRELOAD": " ".join(sanitizer_runtimes()),
        "PYTHONMALLOC": "malloc",  # so ASan sees Python's allocations too
        # Leak detection off: CPython and pybind11 keep interned objects and static
        # type data alive at exit by design; every other report aborts the child.
        "ASAN_OPTIONS": "detect_leaks=0:abort_on_error=1:halt_on_error=1",
        "UBSAN_OPTIONS": "print_stacktrace=1:halt_on_error=1",
        "PYTHONPATH": str(build / "python"),
    })
    return env


def check_build(build, env):
    probe = subprocess.run([sys.executable, "-c", "import beamsolid._beamsolid as b; print(b.__file__)"],
                           env=env, capture_output=True, text=True)
    where = probe.stdout.strip()
    if probe.returncode != 0 or not where.startswith(str(build) + "/"):
        raise SystemExit(f"the sanitizer build is not importable from {build}/python (run `make sanitize-build`):\n"
                         f"{where}\n{probe.stderr[-2000:]}")


def fuzz_command(seed, sequences, calls, first=0, trace=False):
    cmd = [sys.executable, str(FUZZER), "--seed", str(seed), "--sequences", str(sequences), "--calls", str(calls)]
    if first:
        cmd += ["--first", str(first)]
    return cmd + (["--trace"] if trace else [])


def classify(proc):
    text = proc.stderr
    if any(m in text for m in SANITIZER_MARKERS):
        return "sanitizer report"
    return f"crash (exit {proc.returncode})"


def run_chunk(seed, sequences, calls, env, timeout):
    """One child: its counts, or a finding describing how it died."""
    with tempfile.TemporaryDirectory(prefix=f"fuzz{seed}-") as cwd:  # recorders may write files
        start = time.perf_counter()
        try:
            proc = subprocess.run(fuzz_command(seed, sequences, calls), cwd=cwd, env=env, capture_output=True,
                                  text=True, timeout=timeout)
        except subprocess.TimeoutExpired:
            return {"seed": seed, "died": f"no answer in {timeout} s"}, time.perf_counter() - start
        seconds = time.perf_counter() - start
        if proc.returncode == 0 and "FUZZ " in proc.stdout:
            return json.loads(proc.stdout.split("FUZZ ", 1)[1]), seconds
        # Replay with a trace: the last traced line is the call that killed the child.
        replay = subprocess.run(fuzz_command(seed, sequences, calls, trace=True), cwd=cwd, env=env,
                                capture_output=True, text=True, timeout=timeout)
        calls_traced = [line for line in replay.stderr.splitlines() if line.startswith(f"seed {seed} sequence ")]
        return {"seed": seed, "died": classify(proc), "last_call": calls_traced[-1] if calls_traced else None,
                "stderr": proc.stderr[-4000:]}, seconds


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--sequences", type=int, default=100_000)
    p.add_argument("--calls", type=int, default=20, help="random commands per sequence")
    p.add_argument("--chunk", type=int, default=2_000, help="sequences per child process (one seed each)")
    p.add_argument("--first-seed", type=int, default=1)
    p.add_argument("--jobs", type=int, default=2)
    p.add_argument("--timeout", type=float, default=3600.0, help="seconds one child may take")
    p.add_argument("--build", default=str(ROOT / "build-sanitize"))
    p.add_argument("--out", default=str(RESULTS), help="folder for fuzz_sanitized.md/.json")
    a = p.parse_args()

    build = pathlib.Path(a.build).resolve()
    env = sanitized_env(build)
    check_build(build, env)
    chunks = []
    left = a.sequences
    seed = a.first_seed
    while left > 0:
        chunks.append((seed, min(a.chunk, left)))
        left -= a.chunk
        seed += 1

    start = time.perf_counter()
    results = []
    with concurrent.futures.ThreadPoolExecutor(a.jobs) as pool:
        futures = {pool.submit(run_chunk, s, n, a.calls, env, a.timeout): (s, n) for s, n in chunks}
        for future in concurrent.futures.as_completed(futures):
            counts, seconds = future.result()
            results.append((futures[future], counts, seconds))
            done = sum(c.get("sequences", 0) for _, c, _ in results)
            status = counts.get("died") or f"{counts['findings']} findings"
            print(f"seed {futures[future][0]}: {seconds:.0f} s, {status}; {done} sequences done", flush=True)
    wall = time.perf_counter() - start
    results.sort(key=lambda r: r[0][0])

    total = {k: sum(c.get(k, 0) for _, c, _ in results) for k in ("sequences", "calls", "ok", "errors", "wipe_errors",
                                                                    "findings")}
    died = [c for _, c, _ in results if "died" in c]
    exceptions = [d for _, c, _ in results for d in c.get("finding_details", [])]
    summary = {
        "date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
        "machine": f"{platform.processor() or platform.machine()}, {os.cpu_count()} logical cores, "
                   f"Python {platform.python_version()}",
        "build": str(build.relative_to(ROOT)) if build.is_relative_to(ROOT) else str(build),
        "sanitizers": "-fsanitize=address,undefined -fno-sanitize-recover=all (ASan reports abort the child)",
        "sequences_requested": a.sequences, "calls_per_sequence": a.calls, "chunk": a.chunk, "jobs": a.jobs,
        "seeds": [chunks[0][0], chunks[-1][0]],
        "sequences": total["sequences"], "calls": total["calls"], "ok": total["ok"],
        "opensees_errors": total["errors"], "wipe_opensees_errors": total["wipe_errors"],
        "findings": {"crashes": sum(1 for d in died if d["died"].startswith(("crash", "no answer"))),
                     "sanitizer_reports": sum(1 for d in died if d["died"] == "sanitizer report"),
                     "other_exceptions": total["findings"]},
        "finding_details": died + exceptions,
        "fixed_in_earlier_runs": FIXED_FINDINGS,
        "wall_seconds": round(wall, 1),
        "child_seconds": round(sum(s for _, _, s in results), 1),
        "reproduce": "make sanitize-build && .venv/bin/python benchmarks/fuzz_sanitized.py "
                     f"--sequences {a.sequences} --calls {a.calls} --chunk {a.chunk} --first-seed {a.first_seed}",
        "reproduce_one_chunk": "LD_PRELOAD=\"$(readlink -f $(g++ -print-file-name=libasan.so)) "
                               "$(readlink -f $(g++ -print-file-name=libubsan.so))\" PYTHONMALLOC=malloc "
                               "ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:"
                               "halt_on_error=1 PYTHONPATH=build-sanitize/python .venv/bin/python "
                               f"tools/fuzz_commands.py --seed SEED --sequences {a.chunk} --calls {a.calls} --trace",
    }
    out = pathlib.Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    (out / "fuzz_sanitized.json").write_text(json.dumps(summary, indent=1) + "\n")
    f = summary["findings"]
    md = [
        "# Command fuzzer under AddressSanitizer + UBSan",
        "",
        f"`benchmarks/fuzz_sanitized.py`, {summary['date']}, {summary['machine']}. Each sequence builds a small "
        f"model (beam and brick nodes, materials, a transformation, a beam, a load pattern), makes "
        f"{a.calls} random commands (`tools/fuzz_commands.py`) and wipes. The library, the extension and "
        f"the plugin are the sanitizer build (`{summary['build']}`, {summary['sanitizers']}); "
        f"{a.jobs} child Pythons at a time, one seed per {a.chunk} sequences "
        f"(seeds {chunks[0][0]} to {chunks[-1][0]}).",
        "",
        "| | count |",
        "|---|---:|",
        f"| sequences | {summary['sequences']:,} |",
        f"| calls | {summary['calls']:,} |",
        f"| ok | {summary['ok']:,} |",
        f"| OpenSeesError | {summary['opensees_errors']:,} |",
        f"| OpenSeesError from the wipe that ends a sequence | {summary['wipe_opensees_errors']:,} |",
        f"| findings: crashes | {f['crashes']} |",
        f"| findings: sanitizer reports | {f['sanitizer_reports']} |",
        f"| findings: exceptions other than OpenSeesError | {f['other_exceptions']} |",
        "",
        f"Wall time {summary['wall_seconds'] / 60:.1f} min ({summary['child_seconds'] / 60:.1f} min of child "
        f"time).",
        "",
    ]
    if summary["finding_details"]:
        md += ["## Findings", ""]
        for d in summary["finding_details"]:
            md.append(f"- `{json.dumps({k: v for k, v in d.items() if k != 'stderr'})}`")
        md.append("")
    md += ["## Findings of earlier runs, fixed", ""] + [f"- {f}" for f in FIXED_FINDINGS] + [""]
    md += ["## Reproduce", "", "```sh", summary["reproduce"], "# one seed, every call traced to stderr:",
           summary["reproduce_one_chunk"], "```", ""]
    (out / "fuzz_sanitized.md").write_text("\n".join(md))
    print("\n".join(md))
    return 1 if died or exceptions or total["findings"] else 0


if __name__ == "__main__":
    sys.exit(main())

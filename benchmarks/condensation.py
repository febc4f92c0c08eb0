"""Static condensation of the linear soil against the plain sparse solve, on the lateral pile.

For each mesh level the lateral pile scene (beam pile, BeamContact3D, elastic soil; gravity
then a 20-step push) runs twice in a fresh process: with the condensation BeamSolid picks by
itself (BEAMSOLID_CONDENSE unset) and with it switched off (BEAMSOLID_CONDENSE=off). Reported:
equations, interface size, Newton iterations, push time, time per iteration, peak memory
(ru_maxrss of the run's process), and the largest relative difference of the head force
between the two runs. Writes benchmarks/results/condensation.md and condensation.png.

    PYTHONPATH=python .venv/bin/python benchmarks/condensation.py [--levels coarse medium fine]

Timings depend on the machine and its load; the BLAS kernel is recorded.
"""
import argparse
import json
import os
import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "python"))
sys.path.insert(0, str(ROOT / "benchmarks"))
OUT = ROOT / "benchmarks" / "results"

CHILD = r"""
import json, resource, sys, time
import beamsolid
from beamsolid.scenes import lateral_pile as lp
level = sys.argv[1]
r = lp.run(lp.LateralPile(), lp.Numerics(level=level))
info = {"level": level, "equations": r.n_equations, "iterations": sum(r.iterations), "push": r.timings["push"],
        "build": r.timings["build"], "geostatic": r.timings["geostatic"], "head_force": r.head_force,
        "converged": r.converged, "maxrss_mb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0}
print("RESULT " + json.dumps(info))
"""


def run_level(level, condense):
    env = dict(os.environ, PYTHONPATH=str(ROOT / "python"))
    env.pop("BEAMSOLID_CONDENSE", None)
    if not condense:
        env["BEAMSOLID_CONDENSE"] = "off"
    proc = subprocess.run([sys.executable, "-c", CHILD, level], env=env, capture_output=True, text=True, timeout=7200)
    if proc.returncode != 0:
        raise RuntimeError(proc.stderr[-2000:])
    line = [ln for ln in proc.stdout.splitlines() if ln.startswith("RESULT ")][-1]
    result = json.loads(line[len("RESULT "):])
    notes = [ln for ln in proc.stderr.splitlines() if "condensing" in ln]
    result["note"] = notes[-1].split(": ", 1)[1] if notes else "plain"
    return result


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--levels", nargs="+", default=["coarse", "medium", "fine"])
    a = p.parse_args(argv)
    import beamsolid

    rows = []
    for level in a.levels:
        plain = run_level(level, False)
        cond = run_level(level, True)
        diff = max(abs(x - y) for x, y in zip(cond["head_force"], plain["head_force"])) / max(
            abs(y) for y in plain["head_force"])
        rows.append((level, plain, cond, diff))
        print(level, plain["equations"], f"plain {plain['push']:.1f} s", f"condensed {cond['push']:.1f} s",
              cond["note"], f"diff {diff:.1e}", flush=True)

    OUT.mkdir(exist_ok=True)
    lines = ["# Static condensation of the linear soil: lateral pile, plain against condensed", "",
             f"BLAS: {beamsolid.blas_info()}", "",
             "Command: `PYTHONPATH=python .venv/bin/python benchmarks/condensation.py` (each run in a fresh process; "
             "the machine's load at the time shows in the absolute numbers, the ratio is the result)", "",
             "| level | equations | interface | iterations | plain push (s) | condensed push (s) | plain ms/iter | "
             "condensed ms/iter | speed-up | peak MB plain / condensed | max rel. diff of head force |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for level, plain, cond, diff in rows:
        interface = cond["note"].split("interface of ")[-1] if "interface of" in cond["note"] else "-"
        lines.append(f"| {level} | {plain['equations']} | {interface} | {plain['iterations']} / {cond['iterations']} | "
                     f"{plain['push']:.1f} | {cond['push']:.1f} | {1e3 * plain['push'] / plain['iterations']:.0f} | "
                     f"{1e3 * cond['push'] / cond['iterations']:.0f} | {plain['push'] / cond['push']:.2f} | "
                     f"{plain['maxrss_mb']:.0f} / {cond['maxrss_mb']:.0f} | {diff:.1e} |")
    (OUT / "condensation.md").write_text("\n".join(lines) + "\n")
    (OUT / "condensation.json").write_text(json.dumps([{"level": r[0], "plain": r[1], "condensed": r[2],
                                                        "diff": r[3]} for r in rows], indent=1))
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        fig, ax = plt.subplots(figsize=(6, 4))
        n = [r[1]["equations"] for r in rows]
        ax.loglog(n, [1e3 * r[1]["push"] / r[1]["iterations"] for r in rows], "o-", label="plain (UMFPACK, whole system)")
        ax.loglog(n, [1e3 * r[2]["push"] / r[2]["iterations"] for r in rows], "s-", label="condensed soil")
        ax.set_xlabel("equations")
        ax.set_ylabel("push time per Newton iteration (ms)")
        ax.set_title("Lateral pile: condensing the linear soil")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
        fig.tight_layout()
        fig.savefig(OUT / "condensation.png", dpi=120)
    except ImportError:
        pass
    print((OUT / "condensation.md").read_text())


if __name__ == "__main__":
    main()

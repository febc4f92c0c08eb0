"""The cost of the everyday model-building and query commands, BeamSolid against OpenSeesPy.

Issue 17 asks that building a model by commands cost no more per command than OpenSeesPy. Each
program runs the same command loop in a fresh process (N commands of each kind; the programs take
turns, `--rounds` times, and the fastest round counts), CPU microseconds per command. The loop:
2N nodes, N fix, N equalDOF, N Truss, N mass, N load, N sp, then N nodeDisp and N nodeCoord;
then about N stdBricks on a structured grid of their own nodes.

    PYTHONPATH=python .venv/bin/python benchmarks/command_cost.py [--n 50000] [--rounds 3]

writes benchmarks/results/command_cost.md. OpenSeesPy is found as in the oracle tests
(BEAMSOLID_ORACLE_PYTHON or /work/oracle-venv/bin/python); without it only BeamSolid's column is
filled.
"""
import argparse
import json
import os
import pathlib
import subprocess
import sys
import time

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "tests" / "python" / "oracle_scripts"))

LOOP = r'''
import importlib, json, sys, time
ops = importlib.import_module(sys.argv[1])
N = int(sys.argv[2])
ops.wipe(); ops.model('basic', '-ndm', 3, '-ndf', 3)
out = {}
def timed(name, f):
    t = time.process_time(); f(); out[name] = (time.process_time() - t) / N * 1e6
timed('node', lambda: [ops.node(i + 1, float(i), 0.0, 0.0) for i in range(N)])
timed('node (second N)', lambda: [ops.node(i + 1 + N, float(i), 1.0, 0.0) for i in range(N)])
timed('fix', lambda: [ops.fix(i + 1, 1, 0, 1) for i in range(N)])
timed('equalDOF', lambda: [ops.equalDOF(i + 1, i + 1 + N, 1, 2) for i in range(N)])
ops.uniaxialMaterial('Elastic', 1, 100.0)
timed('element Truss', lambda: [ops.element('Truss', i + 1, i + 1, i + 1 + N, 1.0, 1) for i in range(N)])
timed('mass', lambda: [ops.mass(i + 1 + N, 1.0, 1.0, 1.0) for i in range(N)])
ops.timeSeries('Linear', 1); ops.pattern('Plain', 1, 1)
timed('load', lambda: [ops.load(i + 1 + N, 1.0, 0.0, 0.0) for i in range(N)])
timed('sp', lambda: [ops.sp(i + 1 + N, 3, 0.01) for i in range(N)])
timed('nodeDisp', lambda: [ops.nodeDisp(i + 1, 1) for i in range(N)])
timed('nodeCoord', lambda: [ops.nodeCoord(i + 1) for i in range(N)])
# A structured grid of about N stdBricks on their own nodes (per brick).
n = max(1, round(N ** (1 / 3)))
base = 2 * N
ops.wipe(); ops.model('basic', '-ndm', 3, '-ndf', 3)
for k in range(n + 1):
    for j in range(n + 1):
        for i in range(n + 1):
            ops.node(base + 1 + i + (n + 1) * (j + (n + 1) * k), float(i), float(j), float(k))
ops.nDMaterial('ElasticIsotropic', 1, 1000.0, 0.3)
def nid(i, j, k):
    return base + 1 + i + (n + 1) * (j + (n + 1) * k)
bricks = [(nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k), nid(i, j + 1, k), nid(i, j, k + 1),
           nid(i + 1, j, k + 1), nid(i + 1, j + 1, k + 1), nid(i, j + 1, k + 1))
          for k in range(n) for j in range(n) for i in range(n)]
t = time.process_time()
for e, nodes in enumerate(bricks):
    ops.element('stdBrick', e + 1, *nodes, 1)
out['element stdBrick'] = (time.process_time() - t) / len(bricks) * 1e6
print("RESULT" + json.dumps(out))
'''


def run(python, module, n, env):
    proc = subprocess.run([python, "-c", LOOP, module, str(n)], capture_output=True, text=True, env=env, timeout=3600)
    for line in proc.stdout.splitlines():
        if line.startswith("RESULT"):
            return json.loads(line[6:])
    raise RuntimeError(f"{module} failed:\n{proc.stderr[-2000:]}")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--n", type=int, default=50000)
    parser.add_argument("--rounds", type=int, default=3)
    args = parser.parse_args()
    import compare  # noqa: E402 - the oracle finder of the oracle tests

    oracle = compare.find_oracle_python()
    env = dict(os.environ, PYTHONPATH=str(HERE.parent / "python"))
    programs = [("beamsolid", sys.executable, "beamsolid.opensees", env)]
    if oracle:
        programs.append(("opensees", oracle, "openseespy.opensees", compare.oracle_env()))
    best = {}
    for _ in range(args.rounds):
        for name, python, module, penv in programs:
            result = run(python, module, args.n, penv)
            best[name] = {k: min(v, best.get(name, {}).get(k, v)) for k, v in result.items()}
    load = os.getloadavg()[0]
    lines = [
        "# Command cost: BeamSolid against OpenSeesPy",
        "",
        f"Written by `benchmarks/command_cost.py --n {args.n} --rounds {args.rounds}` "
        f"({time.strftime('%Y-%m-%d')}); CPU microseconds per command, the fastest of {args.rounds} rounds, "
        f"each program in a fresh process, taking turns; load average at the end {load:.1f} "
        "(2-core machine, shared).",
        "",
        "| command | BeamSolid us | OpenSeesPy us | BeamSolid / OpenSeesPy |",
        "|---|---:|---:|---:|",
    ]
    for key in best["beamsolid"]:
        b = best["beamsolid"][key]
        o = best.get("opensees", {}).get(key)
        lines.append(f"| {key} | {b:.2f} | {'-' if o is None else f'{o:.2f}'} | "
                     f"{'-' if o is None else f'{b / o:.2f}'} |")
    out = HERE / "results" / "command_cost.md"
    out.write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()

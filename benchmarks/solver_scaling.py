"""Assembly and sparse-solver cost on 3D brick blocks (UMFPACK vs CHOLMOD).

For n x n x n blocks of stdBrick elements fixed at the base and loaded on
top, times one linear static step (Newton, two iterations: the second
finds a zero correction) per system, and reports equations, time per
iteration and the ratio. Writes benchmarks/results/solver_scaling.md and a
PNG chart. Timings depend on the machine and its load; the BLAS that
SuiteSparse used is recorded (ldd), as is the kernel OpenBLAS ran and why (beamsolid.blas_info()).
"""
import os
import pathlib
import sys
import time

# This compares the two sparse factorizations themselves: no condensation of
# the (all-linear) blocks, which would solve them by CHOLMOD once for either
# system (benchmarks/condensation.py measures that).
os.environ["BEAMSOLID_CONDENSE"] = "off"

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "python"))
import beamsolid  # noqa: E402
import machine  # noqa: E402

OUT = pathlib.Path(__file__).parent / "results"


def block(m, n, system):
    m.model("basic", "-ndm", 3, "-ndf", 3)
    m.nDMaterial("ElasticIsotropic", 1, 1000.0, 0.3)
    tag = lambda i, j, k: 1 + i + (n + 1) * (j + (n + 1) * k)
    for k in range(n + 1):
        for j in range(n + 1):
            for i in range(n + 1):
                m.node(tag(i, j, k), i / n, j / n, k / n)
    e = 1
    for k in range(n):
        for j in range(n):
            for i in range(n):
                m.element("stdBrick", e, tag(i, j, k), tag(i + 1, j, k), tag(i + 1, j + 1, k), tag(i, j + 1, k),
                          tag(i, j, k + 1), tag(i + 1, j, k + 1), tag(i + 1, j + 1, k + 1), tag(i, j + 1, k + 1), 1)
                e += 1
    m.fixZ(0.0, 1, 1, 1)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    for j in range(n + 1):
        for i in range(n + 1):
            m.load(tag(i, j, n), 0.1, 0.0, -1.0)
    m.constraints("Transformation")
    m.numberer("RCM")
    m.system(system)
    m.test("NormDispIncr", 1e-10, 5)
    m.algorithm("Newton")
    m.integrator("LoadControl", 1.0)
    m.analysis("Static")


def main(sizes=(6, 10, 14, 18)):
    rows = []
    for n in sizes:
        for system in ("UmfPack", "Cholmod"):
            m = beamsolid.Model()
            t0 = time.perf_counter()
            block(m, n, system)
            build = time.perf_counter() - t0
            t0 = time.perf_counter()
            assert m.analyze(1) == 0
            solve = time.perf_counter() - t0
            iters = m.testIter()
            rows.append((n, system, m.systemSize(), build, solve, iters, solve / iters))
            m.wipe()
            print(f"n={n:3d} {system:8s} eqs={rows[-1][2]:7d} build {build:6.2f}s "
                  f"step {solve:6.3f}s ({iters} iterations, {solve / iters * 1e3:7.1f} ms/iteration)", flush=True)
    OUT.mkdir(exist_ok=True)
    lines = ["# Solver scaling on brick blocks", "",
             "Command: `make build && PYTHONPATH=python .venv/bin/python benchmarks/solver_scaling.py`",
             "", "| n | system | equations | model build (s) | step (s) | iterations | time per iteration (ms) |",
             "|---|---|---|---|---|---|---|"]
    for n, system, eqs, build, solve, iters, per in rows:
        lines.append(f"| {n} | {system} | {eqs} | {build:.2f} | {solve:.3f} | {iters} | {per * 1e3:.1f} |")
    lines += [""] + machine.blas_report()
    (OUT / "solver_scaling.md").write_text("\n".join(lines) + "\n")
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        fig, ax = plt.subplots(figsize=(5, 4))
        for system in ("UmfPack", "Cholmod"):
            pts = [(r[2], r[6] * 1e3) for r in rows if r[1] == system]
            ax.loglog(*zip(*pts), "o-", label=system)
        ax.set_xlabel("equations")
        ax.set_ylabel("time per Newton iteration (ms)")
        ax.legend()
        ax.grid(True, which="both", alpha=0.3)
        fig.tight_layout()
        fig.savefig(OUT / "solver_scaling.png", dpi=120)
    except ImportError:
        pass


if __name__ == "__main__":
    main()

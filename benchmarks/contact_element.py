"""Cost of BeamContact3D per contact element per Newton iteration, and of the donut pullout.

1. A model dominated by contacts: a fixed pile of 1 m segments with N soil nodes
   on its surface (16 angles x 3 heights per segment), each tied to a fixed
   anchor by a zeroLength spring (k = 1e4 in x, y, z) and touching the pile
   through one BeamContact3D (mu = 0.3, G = 1e4). The anchors are pressed
   inwards (normal force 10) and then dragged along the pile past the friction
   limit, so the steps slide. The same model without the contacts (springs
   only) is the baseline. Each step runs exactly 4 iterations (FixedNumIter),
   with Newton (tangent + factorization + residual every iteration) and with
   ModifiedNewton (residual and a triangular solve with the step's first
   factors). The time per iteration is fitted linearly in N; the slope of the
   contact model minus the slope of the baseline is the marginal cost of one
   contact per iteration: its update (gap, slip, return map, 18x18 tangent,
   force), the scatter into the global system and its share of the sparse LU
   of the larger system (6 extra equations per contact; the pile is fixed, so
   the system is block diagonal and the solve is linear in N).
2. The donut pullout of examples/donut_pullout.py (mu = 0.1 .. 1): total time,
   iterations per step and time per iteration.

Writes benchmarks/results/contact_element.md. Timings depend on the machine
and its load; they are never part of the tests.

    PYTHONPATH=python python benchmarks/contact_element.py [--quick]
"""
import argparse
import datetime
import math
import os
import pathlib
import platform
import statistics
import sys
import time

import beamsolid
import machine
from beamsolid.scenes.donut_pullout import PAPER_TABLE1, DonutPullout, run

RESULTS = pathlib.Path(__file__).parent / "results"
R = 0.3
PER_SEGMENT = 48  # 16 angles x 3 heights
ITERATIONS = 4


def contact_model(m, n_contacts, with_contacts):
    m.wipe()
    n_segments = max(1, n_contacts // PER_SEGMENT)
    m.model("basic", "-ndm", 3, "-ndf", 6)
    for k in range(n_segments + 1):
        m.node(1 + k, 0.0, 0.0, float(k))
        m.fix(1 + k, 1, 1, 1, 1, 1, 1)
    m.geomTransf("Linear", 1, 1.0, 0.0, 0.0)
    for k in range(n_segments):
        m.element("elasticBeamColumn", 1 + k, 1 + k, 2 + k, 0.28, 3e7, 1.2e7, 0.0127, 0.0064, 0.0064, 1)
    m.model("basic", "-ndm", 3, "-ndf", 3)
    m.uniaxialMaterial("Elastic", 1, 1e4)
    m.nDMaterial("ContactMaterial3D", 2, 0.3, 1e4, 0.0, 0.0)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    tag = 100000
    for i in range(n_contacts):
        segment, j = divmod(i, PER_SEGMENT)
        level, a = divmod(j, 16)
        theta = 2.0 * math.pi * (a + 0.5 * level) / 16
        x, y, z = R * math.cos(theta), R * math.sin(theta), segment + 0.25 * (level + 1)
        soil, anchor, mult = tag + 3 * i, tag + 3 * i + 1, tag + 3 * i + 2
        m.node(soil, x, y, z)
        m.node(anchor, x, y, z)
        m.element("zeroLength", soil, anchor, soil, "-mat", 1, 1, 1, "-dir", 1, 2, 3)
        if with_contacts:
            m.node(mult, x, y, z)
            m.element("BeamContact3D", mult, segment + 1, segment + 2, soil, mult, R, 1, 2, 1e-8, 1e-8)
        # Press by 1 mm (N = 10) and drag by 5 mm along the pile (friction limit 3).
        m.sp(anchor, 1, -1e-3 * math.cos(theta))
        m.sp(anchor, 2, -1e-3 * math.sin(theta))
        m.sp(anchor, 3, 5e-3)
    return m


def time_per_iteration(n_contacts, with_contacts, algorithm, steps=4, repeats=3):
    """Seconds per iteration: the fastest of `repeats` runs of `steps` steps (the machine may be shared)."""
    t_build = time.perf_counter()
    m = contact_model(beamsolid.Model(), n_contacts, with_contacts)
    t_build = time.perf_counter() - t_build
    m.constraints("Plain")
    m.numberer("RCM")
    m.system("UmfPack")
    m.test("FixedNumIter", ITERATIONS)
    m.algorithm(algorithm)
    m.integrator("LoadControl", 1.0 / (steps * repeats + 1))
    m.analysis("Static")
    t_warm = time.perf_counter()
    assert m.analyze(1) == 0  # warm-up: numbering, symbolic analysis
    t_warm = time.perf_counter() - t_warm
    cpu = wall = math.inf
    for _ in range(repeats):
        c0, t0 = time.process_time(), time.perf_counter()
        assert m.analyze(steps) == 0
        cpu, wall = min(cpu, time.process_time() - c0), min(wall, time.perf_counter() - t0)
    size = m.systemSize()
    sliding = None
    if with_contacts:
        status = [m.eleResponse(100002 + 3 * i, "status")[0] for i in range(n_contacts)]
        sliding = status.count(2.0) / n_contacts
    m.wipe()
    n = steps * ITERATIONS
    return cpu / n, wall / n, size, sliding, t_build, t_warm


def slope(xs, ys):
    mx, my = statistics.fmean(xs), statistics.fmean(ys)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="smaller models (a smoke run)")
    args = parser.parse_args()
    sizes = [480, 960, 1920] if args.quick else [960, 1920, 3840, 7680]
    lines = ["# BeamContact3D: cost per contact element per Newton iteration", "",
             f"Run {datetime.datetime.now():%Y-%m-%d %H:%M} on {platform.node()} ({platform.processor() or platform.machine()}, "
             f"{os.cpu_count()} logical CPUs, load average {os.getloadavg()[0]:.1f} at the start), "
             f"Python {platform.python_version()}, `benchmarks/contact_element.py{' --quick' if args.quick else ''}`.",
             ""]

    # --- 1. contact-dominated model ------------------------------------------------------
    table = {}
    for algorithm in ("Newton", "ModifiedNewton"):
        for with_contacts in (True, False):
            for n in sizes:
                t, wall, size, sliding, t_build, t_warm = time_per_iteration(n, with_contacts, algorithm)
                table[(algorithm, with_contacts, n)] = (t, wall, size, sliding, t_build, t_warm)
                print(f"{algorithm:15s} {'contacts' if with_contacts else 'springs ':8s} N = {n:5d}: "
                      f"{1e3 * t:8.3f} ms CPU ({1e3 * wall:8.3f} ms wall) per iteration, {size} equations, "
                      f"build {t_build:.2f} s, "
                      f"first step {t_warm:.2f} s"
                      + (f", {100 * sliding:.0f}% sliding" if sliding is not None else ""), flush=True)
    lines += ["## 1. Contact-dominated model", "",
              "A fixed pile with N soil nodes on its surface, each on a zeroLength spring to a fixed anchor and "
              "in contact through one BeamContact3D; the anchors press the nodes on (N = 10) and drag them "
              "along the pile past the friction limit (sliding). Baseline: the same springs without contacts. "
              f"{ITERATIONS} iterations per step (FixedNumIter); after a warm-up step, the fastest of 3 runs of 4 steps "
              "(the machine is shared); UmfPack, RCM. Build: creating the model through the commands; first "
              "step: numbering, symbolic analysis and the first contact checks.",
              "", "| algorithm | N contacts | equations | contacts: CPU ms/iteration (wall) | springs only: CPU ms/iteration (wall) "
              "| difference per contact (CPU us) | build s (contacts / springs) | first step s (contacts / springs) |",
              "|---|---:|---:|---:|---:|---:|---:|---:|"]
    costs = {}
    for algorithm in ("Newton", "ModifiedNewton"):
        for n in sizes:
            tc, wallc, size, _, bc, wc = table[(algorithm, True, n)]
            t0, wall0, _, _, b0, w0 = table[(algorithm, False, n)]
            lines.append(f"| {algorithm} | {n} | {size} | {1e3 * tc:.2f} ({1e3 * wallc:.2f}) | {1e3 * t0:.2f} "
                         f"({1e3 * wall0:.2f}) | {1e6 * (tc - t0) / n:.2f} "
                         f"| {bc:.2f} / {b0:.2f} | {wc:.2f} / {w0:.2f} |")
        sc = slope(sizes, [table[(algorithm, True, n)][0] for n in sizes])
        s0 = slope(sizes, [table[(algorithm, False, n)][0] for n in sizes])
        costs[algorithm] = (sc, s0)
    sliding = table[("Newton", True, sizes[-1])][3]
    lines += ["", f"Sliding at the end: {100 * sliding:.0f}% of the contacts.", "",
              "Fitted slopes of the CPU time (least squares over N; the process's CPU time, all threads, is "
              "less disturbed by other processes on a shared machine than wall time):", "",
              "| algorithm | contact model, us per contact per iteration | springs only, us per node "
              "| marginal cost of one contact (us per iteration) |", "|---|---:|---:|---:|"]
    for algorithm, (sc, s0) in costs.items():
        lines.append(f"| {algorithm} | {1e6 * sc:.2f} | {1e6 * s0:.2f} | **{1e6 * (sc - s0):.2f}** |")
    build_c = [table[("Newton", True, n)][4] for n in sizes]
    build_0 = [table[("Newton", False, n)][4] for n in sizes]
    lines += ["", f"Building the model: from N = {sizes[0]} to {sizes[-1]} ({sizes[-1] // sizes[0]}x) the contact "
              f"model's build time grows {build_c[-1] / build_c[0]:.0f}x, the springs' {build_0[-1] / build_0[0]:.0f}x: "
              "each BeamContact3D checks at creation that its multiplier node is used by no other element and "
              "is not constrained, by a scan of the whole model, which makes building quadratic in N for large "
              "N. The first update after a model change uses one shared index of the multiplier nodes' uses "
              "instead (linear: see the first step).", ""]
    lines += ["", "Newton: element update (gap, slip, return map, tangent and force), scatter of the 18x18 "
              "tangent and the 18 forces, and the contact's share of the numeric LU (UMFPACK) and solve. "
              "ModifiedNewton: element update and residual scatter plus a triangular solve with the step's "
              "first factors (the element computes its tangent in update() either way); the difference "
              "between the two rows is the tangent assembly and factorization per contact.", ""]

    # --- 2. donut pullout ------------------------------------------------------------------
    lines += ["## 2. Donut pullout (examples/donut_pullout.py)", ""]
    base = DonutPullout()
    rows = []
    for mu, G, _, _ in PAPER_TABLE1:
        s = DonutPullout(mu=mu, G=G)
        best = None
        for _ in range(2):  # the faster of two runs
            c0, t0 = time.process_time(), time.perf_counter()
            r = run(s)
            total, cpu = time.perf_counter() - t0, time.process_time() - c0
            if best is None or total < best[0]:
                best = (total, cpu, r)
        total, cpu, r = best
        its = sum(r.iterations)
        rows.append((mu, total, r.geostatic_time, len(r.iterations), its, sum(r.step_time), cpu, sum(r.step_cpu)))
        print(f"donut mu = {mu}: {total:.2f} s, {its} iterations in {len(r.iterations)} steps", flush=True)
    t_all = sum(row[1] for row in rows)
    n_contacts = (base.n_z + 1) * base.n_theta
    n_bricks = base.n_theta * base.n_radial * base.n_z
    lines += [f"Mesh {base.n_theta} x {base.n_radial} x {base.n_z}: {n_bricks} stdBrick, {n_contacts} BeamContact3D, "
              f"{base.steps} pullout steps per mu, UmfPack, NormUnbalance {base.tol:g}; the faster of two runs. "
              "ms/iteration: the pullout steps' analyze time over their iterations.", "",
              "| mu | total s (CPU s) | geostatic s | steps | iterations | iterations/step "
              "| ms/iteration (CPU ms) |", "|---:|---:|---:|---:|---:|---:|---:|"]
    for mu, total, geo, steps, its, solve, cpu, solve_cpu in rows:
        lines.append(f"| {mu:g} | {total:.2f} ({cpu:.2f}) | {geo:.2f} | {steps} | {its} | {its / steps:.2f} | "
                     f"{1e3 * solve / its:.1f} ({1e3 * solve_cpu / its:.1f}) |")
    its = sum(r[4] for r in rows)
    steps = sum(r[3] for r in rows)
    per_it = sum(r[5] for r in rows) / its
    per_it_cpu = sum(r[7] for r in rows) / its
    contact_share = n_contacts * costs["Newton"][0] / per_it_cpu
    lines += ["", f"All four: {t_all:.1f} s wall ({sum(row[6] for row in rows):.1f} s CPU), {steps} steps, "
              f"{its} iterations ({its / steps:.2f} per step), {1e3 * per_it:.1f} ms wall "
              f"({1e3 * per_it_cpu:.1f} ms CPU) per iteration. The {n_contacts} contacts account for about "
              f"{1e3 * n_contacts * costs['Newton'][0]:.2f} ms CPU of that ({100 * contact_share:.1f}%) at the cost "
              "per contact of section 1; the rest is the soil bricks and above all the sparse LU of the "
              "unsymmetric soil system.", ""]

    # --- BLAS ---------------------------------------------------------------------------------
    lines += machine.blas_report()
    RESULTS.mkdir(parents=True, exist_ok=True)
    out = RESULTS / "contact_element.md"
    out.write_text("\n".join(lines))
    print("\n".join(lines))
    print(f"wrote {out}")


if __name__ == "__main__":
    sys.exit(main())

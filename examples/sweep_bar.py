"""A parameter sweep on Dask (docs/sweeps.md): a steel bar pulled past yield, over a grid of loads and lengths.

The bar (E = 200 GPa, A = 10 cm^2, fy = 250 MPa, elastic-perfectly-plastic) carries at most
N_y = fy A = 250 kN: below it the end moves P L / (E A), above it no equilibrium exists, the
Newton iterations fail and analyze returns a negative code. The sweep stores those points as
failed, with the code and the reason, and completes the others. Units: kN, m.

    PYTHONPATH=python python examples/sweep_bar.py [--workers 2] [--scheduler ADDRESS] [--serial]

or from the shell, with the same function:

    PYTHONPATH=python python -m beamsolid.sweep run examples/sweep_bar.py:pull sweep_bar_out \\
        --grid P=100,200,300 --grid L=2,4
"""
import argparse

import beamsolid
from beamsolid import sweep

E, AREA, FY = 200e6, 10e-4, 250e3  # kPa, m^2, kPa


def pull(P, L, steps=5):
    """End displacement and force of the bar under P (kN), or AnalyzeFailed past yield."""
    m = beamsolid.Model()
    m.model("basic", "-ndm", 1)
    m.node(1, 0.0)
    m.node(2, float(L))
    m.fix(1, 1)
    m.uniaxialMaterial("ElasticPP", 1, E, FY / E)
    m.element("Truss", 1, 1, 2, AREA, 1)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.load(2, float(P))
    m.constraints("Plain")
    m.numberer("RCM")
    m.system("UmfPack")
    m.test("NormDispIncr", 1e-12, 10)
    m.algorithm("Newton")
    m.integrator("LoadControl", 1.0 / steps)
    m.analysis("Static")
    sweep.analyze(m, steps)  # raises sweep.AnalyzeFailed(code, reason) on a negative code
    return {"u": m.nodeDisp(2, 1), "N": m.eleResponse(1, "axialForce")[0]}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--scheduler", help="an existing Dask scheduler's address")
    ap.add_argument("--serial", action="store_true")
    ap.add_argument("--store", default="sweep_bar_out")
    args = ap.parse_args()
    points = sweep.grid(P=[100.0, 200.0, 300.0], L=[2.0, 4.0])
    summary = sweep.run(pull, points, args.store, workers=args.workers, scheduler=args.scheduler,
                        serial=args.serial)
    print(summary)
    print(f"{'P (kN)':>8} {'L (m)':>6}  status  {'u (mm)':>8}  closed form P L / (E A) (mm)")
    for p, row in zip(points, sweep.read(args.store, points)):
        exact = p["P"] * p["L"] / (E * AREA) * 1e3 if p["P"] <= FY * AREA else float("nan")
        u = row["u"] * 1e3 if row["status"] == "ok" else float("nan")
        print(f"{p['P']:8.0f} {p['L']:6.1f}  {row['status']:6s}  {u:8.4f}  {exact:8.4f}"
              + (f"  (code {row['returncode']}: {row['error'].splitlines()[0][:60]})" if row["status"] != "ok" else ""))


if __name__ == "__main__":
    main()

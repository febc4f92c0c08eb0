"""A fourth, finer level of the brick-meshed pile (model (b) of accuracy_vs_cost.py).

The three-level Richardson reference of accuracy_vs_cost.py rests on bricks that converge
slowly (they lock in bending). This runs (b) once more on the O-grid (n_theta, n_radial, n_z) =
(32, 16, 36), about 78,000 equations and 15 minutes, and extrapolates again from the three finest
levels. Writes benchmarks/results/accuracy_reference_xfine.json.

    PYTHONPATH=python:benchmarks python benchmarks/accuracy_reference_xfine.py
"""
import json
import pathlib
import time

from accuracy_vs_cost import size
from beamsolid.scenes import lateral_pile_solid as solid
from beamsolid.scenes.lateral_pile import LateralPile

XFINE = (32, 16, 36)
RESULTS = pathlib.Path(__file__).resolve().parent / "results"


def main():
    problem = LateralPile()
    previous = json.loads((RESULTS / "accuracy_vs_cost.json").read_text())
    b = {row["level"]: row for row in previous["rows"] if row["model"] == "b"}
    t0 = time.perf_counter()
    r = solid.run(problem, solid.SolidNumerics(level=XFINE, interface="contact", penalty_factor=1e3, stick_G=1e5,
                                               control="force", head_load=700.0, steps=10))
    wall = time.perf_counter() - t0
    hs = [size("medium"), size("fine"), size(XFINE)]
    u_ref, p_u = solid.richardson(hs, [b["medium"]["u"], b["fine"]["u"], r.head_disp[-1]])
    M_ref, p_M = solid.richardson(hs, [b["medium"]["M"], b["fine"]["M"], r.max_moment])
    out = dict(divisions=XFINE, converged=r.converged, u=r.head_disp[-1], M=r.max_moment, wall=wall,
               equations=r.n_equations, iterations=sum(r.iterations),
               reference_from_medium_fine_xfine=dict(u=u_ref, order_u=p_u, M=M_ref, order_M=p_M),
               reference_from_coarse_medium_fine=previous["reference"])
    (RESULTS / "accuracy_reference_xfine.json").write_text(json.dumps(out, indent=1))
    print(json.dumps(out, indent=1))


if __name__ == "__main__":
    main()

"""The tutorial plugin in a scene: the lateral pile of docs/lateral_pile_winkler.md on
NonlinearSpring3D springs (two at each beam node, along x and y, to fixed ground nodes).

1. Elastic springs: the plugin's pile against the same pile on built-in zeroLength springs and
   against Hetenyi's closed form for the finite beam on a Winkler foundation.
2. Elastic-perfectly-plastic springs (ElasticPP, yielding at a deflection y_y: a crude p-y
   curve): a head push in steps, against the zeroLength model with the same material.

    PYTHONPATH=python .venv/bin/python examples/plugins/spring_pile.py build/plugins/libnonlinear_spring.so
"""
import sys

import beamsolid
from beamsolid.scenes.lateral_pile import LateralPile
from beamsolid.scenes.winkler_pile import bending_stiffness, run_winkler, vesic_k, winkler_closed_form


def elastic(plugin, head_force=500.0, n_elements=40):
    """(plugin model, zeroLength model, closed-form head deflection) under head_force (kN)."""
    problem = LateralPile()
    k = vesic_k(problem)
    m = beamsolid.Model()
    m.loadPlugin(plugin)
    mine = run_winkler(problem, n_elements, k, head_force=head_force, m=m, spring="NonlinearSpring3D")
    builtin = run_winkler(problem, n_elements, k, head_force=head_force)
    y, _, _ = winkler_closed_form(bending_stiffness(problem), k, problem.length, head_force, [0.0])
    return mine, builtin, float(y[0])


def plastic(plugin, yield_deflection=0.005, head_disp=0.05, steps=20, n_elements=40):
    """The head pushed to head_disp (m) on springs that yield at yield_deflection (m):
    (plugin model, zeroLength model)."""
    problem = LateralPile()
    k = vesic_k(problem)

    def elastoplastic(m, tag, stiffness):
        m.uniaxialMaterial("ElasticPP", tag, stiffness, yield_deflection)

    m = beamsolid.Model()
    m.loadPlugin(plugin)
    runs = [run_winkler(problem, n_elements, k, head_disp=head_disp, m=model, spring=spring,
                        spring_material=elastoplastic, steps=steps)
            for model, spring in ((m, "NonlinearSpring3D"), (None, "zeroLength"))]
    return tuple(runs)


def main(plugin):
    mine, builtin, closed = elastic(plugin)
    print(f"Elastic springs, H = {mine.head_force:.0f} kN, {mine.n_elements} beams, k = {mine.k:.0f} kPa")
    print(f"  head deflection  plugin {1e3 * mine.head_disp:.4f} mm   zeroLength {1e3 * builtin.head_disp:.4f} mm"
          f"   closed form {1e3 * closed:.4f} mm ({100 * (mine.head_disp / closed - 1):+.2f} %)")
    mine, builtin = plastic(plugin)
    print("ElasticPP springs (yield at 5 mm): head push")
    print("  head disp (mm)   force plugin (kN)   force zeroLength (kN)")
    for (u, f), (_, g) in zip(mine.curve, builtin.curve):
        print(f"  {1e3 * u:14.2f}   {f:17.2f}   {g:21.2f}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "build/plugins/libnonlinear_spring.so")

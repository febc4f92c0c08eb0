"""The paper's Table 1 test: a pile pulled up through a "donut" of confined elastic soil.

Arduino, Petek & Mackenzie-Helnwein (2007) pull a pile of beam elements up
through a ring of elastic solid elements and compare the maximum frictional
resistance of the BeamContact3D interface with the beta method. This script
runs the same test for mu = 0.1, 0.25, 0.5, 1.0 with G = 1000 (set-up in
beamsolid/scenes/donut_pullout.py and docs/donut_pullout.md; units kN, m):

  stage 1  soil self weight (stdBrick body force b3 = -gamma), uniaxial strain:
           outer nodes fixed in x and y, base in z, pile fixed, contacts
           frictionless -> sigma_h = K0 gamma depth, K0 = nu / (1 - nu);
  stage 2  loadConst, friction on, the pile released along its axis and pulled
           up by an imposed head displacement until no contact sticks.

It prints the table next to the paper's numbers, checks three gates and saves
the pullout curves (head force vs head displacement) as a PNG:
  (a) at full sliding the head force equals mu sum(N_i) (relative 1e-6);
  (b) the geostatic sum of normal forces equals n R sin(2 pi/n) integral(sigma_h dz)
      (relative 1e-6, well inside the 1% asked for);
  (c) Q / Qs = facet factor x unloading, where facet factor = n sin(2 pi/n)/(2 pi)
      and unloading = sum N at full sliding / geostatic sum N (relative 1e-6).

    python examples/donut_pullout.py               # the table (about a minute)
    python examples/donut_pullout.py --refinement  # + the mesh refinement study
"""
import argparse
import math
import os
import pathlib
import sys
import time
from dataclasses import replace

import beamsolid
from beamsolid.scenes.donut_pullout import PAPER_TABLE1, DonutPullout, run

OUT = pathlib.Path(os.environ.get("BEAMSOLID_OUT", pathlib.Path(__file__).parent / "output"))
GATE_TOL = 1e-6


def relative(a, b):
    return abs(a - b) / abs(b)


def check_gates(r):
    """The three gates of one run: [(name, measured relative error)]."""
    s = r.setup
    k = len(r.head_force) - 1
    gates = [("(b) geostatic sum N = n R sin(2pi/n) int sigma_h dz", relative(r.geostatic_normal_sum,
                                                                              s.faceted_normal_sum))]
    if r.full_sliding is None or r.failed_step:
        gates.append(("(a) full sliding reached", math.inf))
        return gates
    gates.append(("(a) head force = mu sum N", relative(r.head_force[k], s.mu * r.normal_sum[k])))
    gates.append(("(a) summed friction = mu sum N", relative(r.friction_sum[k], s.mu * r.normal_sum[k])))
    gates.append(("(c) Q/Qs = facet x unloading", relative(r.head_force[k] / s.beta_method,
                                                           s.facet_factor * r.unloading)))
    return gates


def describe(s):
    print("Donut pullout (Arduino, Petek & Mackenzie-Helnwein 2007, Table 1); units kN, m")
    print(f"  pile: elasticBeamColumn, B = {2 * s.pile_radius:g} m, E = {s.pile_E:.3g} kPa, "
          f"{s.n_z + 1} elements, nodes half a layer off the soil levels")
    print(f"  soil: stdBrick O-grid R = {s.pile_radius:g} .. {s.outer_radius:g} m, depth D = {s.depth:g} m, "
          f"n_theta x n_radial x n_z = {s.n_theta} x {s.n_radial} x {s.n_z}, "
          f"E = {s.soil_E:g} kPa, nu = {s.soil_nu:g}, gamma = {s.gamma:g} kN/m3")
    print(f"  confinement: self weight, uniaxial strain: sigma_h = K0 gamma z, K0 = nu/(1-nu) = {s.K0:.4f}, "
          f"int_0^D sigma_h dz = {s.sigma_h_integral:.3f} kN/m")
    print(f"  contacts: {(s.n_z + 1) * s.n_theta} BeamContact3D, ContactMaterial3D(mu, G = {s.G:g}, c = 0, t = 0)")
    blas = beamsolid.blas_info()
    print(f"  BLAS: {blas.config.split(' NO_')[0] or 'not OpenBLAS'}, kernel {blas.kernel or '-'}: {blas.reason}")


def table(results):
    print()
    print(f"{'':13s}{'this model':>39s}{'beta':>10s}{'':>24s}{'paper (Table 1)':>27s}")
    print(f"{'mu':>5s}{'G':>8s}{'Q_contact':>11s}{'mu*sum(N)':>11s}{'open':>6s}{'d_full':>7s}"
          f"{'Qs':>10s}{'%diff':>7s}{'facet':>8s}{'unload':>8s}{'|':>3s}"
          f"{'Q_contact':>10s}{'Qs':>7s}{'%diff':>7s}")
    for r, (mu, G, q_paper, qs_paper) in zip(results, PAPER_TABLE1):
        s = r.setup
        k = len(r.head_force) - 1
        q = r.q_contact
        d_full = f"{1e3 * r.head_disp[r.full_sliding]:7.1f}" if r.full_sliding is not None else f"{'-':>7s}"
        print(f"{mu:5.2f}{G:8.0f}{q:11.2f}{mu * r.normal_sum[k]:11.2f}{r.open:6d}{d_full}"
              f"{s.beta_method:10.2f}{100 * (q - s.beta_method) / s.beta_method:7.1f}"
              f"{s.facet_factor:8.4f}{r.unloading:8.4f}{'|':>3s}"
              f"{q_paper:10.0f}{qs_paper:7.0f}{100 * (q_paper - qs_paper) / qs_paper:7.1f}")
    print("  Q_contact: maximum head force (= summed friction); open: contacts the pull has opened "
          "(top level);\n  d_full: head displacement (mm) at which no contact sticks any more; "
          "facet: n sin(2pi/n)/(2pi);\n  unload: sum N at full sliding / geostatic sum N")


def plot(results, path):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    for r, (mu, _, q_paper, qs_paper) in zip(results, PAPER_TABLE1):
        line, = ax.plot([1e3 * d for d in r.head_disp], r.head_force, "o-", ms=3, label=f"mu = {mu:g}")
        ax.axhline(r.setup.beta_method, color=line.get_color(), ls="--", lw=0.8)
        ax.plot([1e3 * r.head_disp[-1]], [q_paper], "s", color=line.get_color(), mfc="none")
    ax.plot([], [], "k--", lw=0.8, label="beta method Qs")
    ax.plot([], [], "ks", mfc="none", label="paper, Table 1")
    ax.set_xlabel("head displacement (mm)")
    ax.set_ylabel("head force Q (kN)")
    ax.set_title("Donut pullout: BeamContact3D, G = 1000")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def drag_estimate(s):
    """1 - unloading if the drag above depth z, Q(z) = mu pi B K0 gamma z^2 / 2, unloaded the
    vertical stress uniformly over the annulus and sigma_h followed by K0:
    int K0 Q(z)/A dz / int sigma_h dz = mu pi B K0 D / (3 A), A = pi (R_out^2 - R^2)."""
    area = math.pi * (s.outer_radius**2 - s.pile_radius**2)
    return s.mu * math.pi * 2.0 * s.pile_radius * s.K0 * s.depth / (3.0 * area)


def refinement_study(mu=1.0):
    """Facet factor and unloading under mesh refinement at full sliding (mu = 1)."""
    # Fixed increments of 4 mm until two steps past full sliding.
    base = DonutPullout(mu=mu, pull=0.12, steps=30)
    meshes = [("n_theta", dict(n_theta=n)) for n in (8, 16, 32)]
    meshes += [("n_radial", dict(n_radial=n)) for n in (2, 4, 8)]
    meshes += [("n_z", dict(n_z=n)) for n in (5, 10, 20)]
    meshes += [("all", dict(n_theta=8 * k, n_radial=2 * k, n_z=5 * k)) for k in (1, 2, 4)]
    # Not a mesh change: a wider donut spreads the drag over more soil.
    meshes += [("R_out", dict(outer_radius=r, n_radial=n)) for r, n in ((2.5, 3), (10.0, 6))]
    print(f"\nMesh refinement at full sliding, mu = {mu:g} (base mesh 16 x 4 x 10, R_out = 5 m)")
    print(f"{'refined':>9s}{'mesh':>12s}{'facet':>8s}{'unload':>8s}{'Q/Qs':>8s}{'facet*unl':>10s}"
          f"{'open':>6s}{'d_full mm':>10s}{'1-unl est':>10s}{'time s':>8s}")
    rows = []
    for name, change in meshes:
        s = replace(base, **change)
        t0 = time.perf_counter()
        r = run(s, extra_after_full_sliding=2)
        k = len(r.head_force) - 1
        if r.full_sliding is None:
            print(f"{name:>9s}: no full sliding within {1e3 * s.head_pull:g} mm")
            continue
        ratio = r.head_force[k] / s.beta_method
        rows.append((name, s, r, ratio))
        print(f"{name:>9s}{f'{s.n_theta}x{s.n_radial}x{s.n_z}':>12s}{s.facet_factor:8.4f}{r.unloading:8.4f}"
              f"{ratio:8.4f}{s.facet_factor * r.unloading:10.4f}{r.open:6d}{1e3 * r.head_disp[r.full_sliding]:10.1f}"
              f"{drag_estimate(s):10.4f}{time.perf_counter() - t0:8.1f}")
    return rows


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--refinement", action="store_true", help="also run the mesh refinement study")
    args = parser.parse_args(argv)

    t0 = time.perf_counter()
    base = DonutPullout()
    describe(base)
    results = [run(replace(base, mu=mu, G=G)) for mu, G, _, _ in PAPER_TABLE1]
    table(results)

    print("\nGates (relative errors)")
    failed = False
    for r in results:
        for name, err in check_gates(r):
            ok = err <= GATE_TOL
            failed |= not ok
            print(f"  mu = {r.setup.mu:4.2f}  {name:52s} {err:9.1e}  {'ok' if ok else 'FAILED'}")

    its = sum(len(r.iterations) for r in results), sum(sum(r.iterations) for r in results)
    solve = sum(sum(r.step_time) for r in results)
    print(f"\n{its[0]} pullout steps, {its[1]} Newton iterations ({its[1] / its[0]:.2f} per step), "
          f"{1e3 * solve / its[1]:.0f} ms per iteration; total {time.perf_counter() - t0:.1f} s")

    OUT.mkdir(parents=True, exist_ok=True)
    try:
        plot(results, OUT / "donut_pullout.png")
        print(f"saved {OUT / 'donut_pullout.png'}")
    except ImportError:
        print("matplotlib not installed: no plot")

    if args.refinement:
        refinement_study()
    if failed:
        sys.exit("a gate failed")


if __name__ == "__main__":
    main()

"""A reinforced-concrete circular pile pushed laterally as a cantilever to 5 % drift.

Units: kN, m, kPa (1 MPa = 1000 kPa).

The pile (D = 0.6 m, L = 3 m above the fixed base, vertical along global Z)
has a fiber section: confined core and unconfined cover in Concrete02
(circ patches), 12 bars of 25 mm in Steel02 on a circ layer, elastic
torsion through '-GJ'. One forceBeamColumn with 5 Lobatto points and a
Corotational transform. A constant axial load of 0.1 f'c Ag is applied
first (LoadControl, then loadConst), then the head is pushed along X with
DisplacementControl to 5 % drift in equal steps; a step that fails is
retried in 2, 4, ..., 32 substeps (the usual OpenSees step-cut loop), and
the curve is recorded at the base step levels only, so that two programs
report the same drift levels.

`run(ops)` works with `import beamsolid.opensees as ops` and with
OpenSeesPy and returns a dict of plain lists (JSON-friendly).

    python examples/rc_pile_pushover.py     # table + examples/output/rc_pile_pushover.png
"""
import math
import os
import pathlib
import sys
import time

# --- geometry and materials (kN, m, kPa) ---------------------------------------------
D = 0.6                    # pile diameter
COVER = 0.05               # cover to the core edge (hoop centreline)
L = 3.0                    # cantilever length (base to head)
N_BARS = 12
D_BAR = 0.025
A_BAR = math.pi * D_BAR**2 / 4
R_CORE = D / 2 - COVER
R_BARS = R_CORE - D_BAR / 2
FPC = 30000.0              # unconfined f'c
EPSC0 = 0.002
FCC = 39000.0              # confined core strength (Mander-like)
EPSCC = 0.0046
FY, ES, B_HARD = 420000.0, 2.0e8, 0.01
AG = math.pi * D**2 / 4
P_AXIAL = 0.1 * FPC * AG   # compression at the head
DRIFT_MAX = 0.05
N_STEPS = 100
N_CIRC, N_RAD_CORE, N_RAD_COVER = 24, 8, 2
COVER_MAT, CORE_MAT, STEEL_MAT = 1, 2, 3

CONCRETE_COVER = (-FPC, -EPSC0, -0.2 * FPC, -0.005, 0.1, 0.1 * FPC, 0.1 * FPC / EPSC0)
CONCRETE_CORE = (-FCC, -EPSCC, -0.85 * FCC, -0.02, 0.1, 0.1 * FPC, 0.1 * FPC / EPSC0)
STEEL = (FY, ES, B_HARD, 18.0, 0.925, 0.15)


def build(ops):
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    ops.node(1, 0.0, 0.0, 0.0)
    ops.node(2, 0.0, 0.0, L)
    ops.fix(1, 1, 1, 1, 1, 1, 1)
    ops.uniaxialMaterial("Concrete02", COVER_MAT, *CONCRETE_COVER)
    ops.uniaxialMaterial("Concrete02", CORE_MAT, *CONCRETE_CORE)
    ops.uniaxialMaterial("Steel02", STEEL_MAT, *STEEL)
    ec = 2 * FPC / EPSC0
    gj = ec / (2 * 1.2) * math.pi * D**4 / 32
    ops.section("Fiber", 1, "-GJ", gj)
    ops.patch("circ", CORE_MAT, N_CIRC, N_RAD_CORE, 0.0, 0.0, 0.0, R_CORE, 0.0, 360.0)
    ops.patch("circ", COVER_MAT, N_CIRC, N_RAD_COVER, 0.0, 0.0, R_CORE, D / 2, 0.0, 360.0)
    ops.layer("circ", STEEL_MAT, N_BARS, A_BAR, 0.0, 0.0, R_BARS)
    ops.geomTransf("Corotational", 1, 1.0, 0.0, 0.0)
    ops.beamIntegration("Lobatto", 1, 1, 5)
    ops.element("forceBeamColumn", 1, 1, 2, 1, 1)


def analysis_setup(ops, integrator):
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.system("UmfPack")
    ops.test("NormDispIncr", 1e-10, 50)
    ops.algorithm("Newton")
    ops.integrator(*integrator)
    ops.analysis("Static")


def max_bar_strain(ops):
    """Largest bar strain at the base section: eps + R |kappa| (tension positive)."""
    e = ops.eleResponse(1, "section", 1, "deformation")
    return e[0] + R_BARS * math.hypot(e[1], e[2])


def run(ops, n_steps=N_STEPS, drift_max=DRIFT_MAX):
    build(ops)
    # 1) constant axial load
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, 0.0, 0.0, -P_AXIAL, 0.0, 0.0, 0.0)
    analysis_setup(ops, ("LoadControl", 0.1))
    if ops.analyze(10) != 0:
        return {"status": "axial load failed"}
    ops.loadConst("-time", 0.0)
    axial_disp = ops.nodeDisp(2, 3)
    # 2) lateral push with a unit reference load
    ops.timeSeries("Linear", 2)
    ops.pattern("Plain", 2, 2)
    ops.load(2, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    du = drift_max * L / n_steps
    ops.wipeAnalysis()
    analysis_setup(ops, ("DisplacementControl", 2, 1, du))
    rows = {"drift": [0.0], "disp": [0.0], "shear": [0.0], "bar_strain": [max_bar_strain(ops)],
            "iters": [0], "cuts": [0]}
    status = "ok"
    for _ in range(n_steps):
        ok, iters, cuts = ops.analyze(1), 0, 0
        if ok == 0:
            iters = ops.testIter()
        n_sub = 1
        while ok != 0 and n_sub < 32:
            n_sub *= 2
            cuts += 1
            ops.integrator("DisplacementControl", 2, 1, du / n_sub)
            ok, iters = 0, 0
            for _ in range(n_sub):
                ok = ops.analyze(1)
                if ok != 0:
                    break
                iters += ops.testIter()
            ops.integrator("DisplacementControl", 2, 1, du)
            # a partially done cut leaves the head between grid levels: finish it
            # at the finer size before the next, finer try would overshoot.
            if ok != 0:
                break
        if ok != 0:
            status = "failed at drift %.5f" % (ops.nodeDisp(2, 1) / L)
            break
        ops.reactions()
        u = ops.nodeDisp(2, 1)
        rows["drift"].append(u / L)
        rows["disp"].append(u)
        rows["shear"].append(-ops.nodeReaction(1, 1))
        rows["bar_strain"].append(max_bar_strain(ops))
        rows["iters"].append(iters)
        rows["cuts"].append(cuts)
    rows["status"] = status
    rows["axial_disp"] = axial_disp
    rows["P"] = P_AXIAL
    return rows


def summary(r):
    """Peak, drift at peak, load at the last drift and first yield (interpolated)."""
    shear, drift = r["shear"], r["drift"]
    k = max(range(len(shear)), key=lambda i: shear[i])
    ey = FY / ES
    fy_drift = fy_shear = None
    for i in range(1, len(shear)):
        e0, e1 = r["bar_strain"][i - 1], r["bar_strain"][i]
        if e0 < ey <= e1:
            t = (ey - e0) / (e1 - e0)
            fy_drift = drift[i - 1] + t * (drift[i] - drift[i - 1])
            fy_shear = shear[i - 1] + t * (shear[i] - shear[i - 1])
            break
    return {"peak": shear[k], "drift_at_peak": drift[k], "last_drift": drift[-1],
            "last_shear": shear[-1], "first_yield_drift": fy_drift, "first_yield_shear": fy_shear,
            "total_iters": sum(r["iters"]), "cuts": sum(r["cuts"])}


def main():
    sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "python"))
    import beamsolid.opensees as ops

    t0 = time.perf_counter()
    r = run(ops)
    elapsed = time.perf_counter() - t0
    s = summary(r)
    print("RC pile D = %.2f m, L = %.1f m, P = %.0f kN (0.1 f'c Ag); status %s, %.2f s"
          % (D, L, P_AXIAL, r["status"], elapsed))
    print("%8s %10s %12s %12s %6s" % ("drift%", "u [m]", "V [kN]", "bar strain", "iters"))
    for i in range(0, len(r["drift"]), 5):
        print("%8.3f %10.5f %12.2f %12.5f %6d" % (100 * r["drift"][i], r["disp"][i], r["shear"][i],
                                                 r["bar_strain"][i], r["iters"][i]))
    print("first yield: drift %.3f %%, V %.1f kN" % (100 * s["first_yield_drift"], s["first_yield_shear"]))
    print("peak: V %.1f kN at drift %.3f %%" % (s["peak"], 100 * s["drift_at_peak"]))
    print("at drift %.2f %%: V %.1f kN (%.1f %% of peak)" % (100 * s["last_drift"], s["last_shear"],
                                                          100 * s["last_shear"] / s["peak"]))
    print("Newton iterations %d, step cuts %d" % (s["total_iters"], s["cuts"]))
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    out = pathlib.Path(os.environ.get("BEAMSOLID_OUT", pathlib.Path(__file__).parent / "output"))
    out.mkdir(parents=True, exist_ok=True)
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot([100 * d for d in r["drift"]], r["shear"], "-", label="BeamSolid")
    ax.plot([100 * s["first_yield_drift"]], [s["first_yield_shear"]], "o", label="first yield")
    ax.plot([100 * s["drift_at_peak"]], [s["peak"]], "s", label="peak")
    ax.set_xlabel("drift [%]")
    ax.set_ylabel("base shear [kN]")
    ax.set_title("RC pile pushover (D = 0.6 m, P = 0.1 f'c Ag)")
    ax.grid(True)
    ax.legend()
    fig.tight_layout()
    fig.savefig(out / "rc_pile_pushover.png", dpi=120)
    print("saved", out / "rc_pile_pushover.png")


if __name__ == "__main__":
    main()

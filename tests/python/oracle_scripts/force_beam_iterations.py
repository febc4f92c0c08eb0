"""The force-based element's own iterations, one state determination at a time.

A cantilever forceBeamColumn whose tip is moved by sp constraints with the
Linear algorithm (one element update per step, committed after it), so that
the basic forces and section deformations it answers are those of its
compatibility iterations alone, for several '-iter' maxIter and tol:
- Aggregator sections (elastic P, bilinear Steel01 M-kappa), 4 Lobatto
  points: exact piecewise-linear states, up to 3 loading and reversing steps;
- a Steel01 fiber section, 5 Lobatto points, first yield to 20 yield strains;
- a Concrete01 M-kappa law near its peak (smooth, slow initial-flexibility
  iterations), where enough iterations converge;
- a 3D element jumping to 12 yield displacements of an ElasticPP rectangle
  (the plastic section's flexibility is singular; both programs end above
  Mp) against the same path walked in 100 steps.
"""

L = 100.0


def _cantilever_2d(ops, section, nip, max_iter, tol):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    ops.node(1, 0.0, 0.0)
    ops.node(2, L, 0.0)
    ops.node(3, 0.0, 50.0)
    ops.fix(1, 1, 1, 1)
    ops.fix(3, 0, 1, 1)
    ops.uniaxialMaterial("Elastic", 9, 1.0)
    section(ops)
    ops.geomTransf("Linear", 1)
    ops.beamIntegration("Lobatto", 1, 1, nip)
    ops.element("forceBeamColumn", 1, 1, 2, 1, 1, "-iter", max_iter, tol)
    ops.element("zeroLength", 2, 1, 3, "-mat", 9, "-dir", 1)
    ops.constraints("Transformation")
    ops.numberer("Plain")
    ops.system("FullGeneral")
    ops.test("FixedNumIter", 1)
    ops.algorithm("Linear")
    ops.integrator("LoadControl", 1.0)
    ops.analysis("Static")


def _impose(ops, steps, nip, out, key, ndf=3, node=2):
    for k, disp in enumerate(steps):
        if k:
            ops.remove("loadPattern", 10 + k - 1)
        ops.timeSeries("Constant", 10 + k)
        ops.pattern("Plain", 10 + k, 10 + k)
        for dof in range(ndf):
            ops.sp(node, dof + 1, disp[dof])
        code = ops.analyze(1)
        out[f"{key}.step{k}"] = [code, ops.eleResponse(1, "basicForce")] + [
            ops.eleResponse(1, "section", i, "deformation") for i in range(1, nip + 1)]


def _bilinear(ops):
    ops.uniaxialMaterial("Elastic", 1, 1000.0)
    ops.uniaxialMaterial("Steel01", 2, 10.0, 1000.0, 0.1)
    ops.section("Aggregator", 1, 1, "P", 2, "Mz")


def _steel_fibers(ops):
    ops.uniaxialMaterial("Steel01", 3, 50.0, 29000.0, 0.02)
    ops.section("Fiber", 1)
    for y, area in ((-10.0, 1.0), (-5.0, 2.0), (0.0, 3.0), (5.0, 2.0), (10.0, 1.0)):
        ops.fiber(y, 0.0, area, 3)


def _concrete(ops):
    ops.uniaxialMaterial("Elastic", 1, 1000.0)
    ops.uniaxialMaterial("Concrete01", 2, -10.0, -0.02, -2.0, -0.1)
    ops.section("Aggregator", 1, 1, "P", 2, "Mz")


def _jump_3d(ops, out, key, max_iter, steps):
    E, fy, b, h, length = 2.0e5, 300.0, 0.1, 0.2, 2.0
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    ops.node(1, 0.0, 0.0, 0.0)
    ops.node(2, length, 0.0, 0.0)
    ops.node(3, 0.0, 0.0, 1.0)
    ops.fix(1, 1, 1, 1, 1, 1, 1)
    ops.fix(3, 0, 1, 1, 1, 1, 1)
    ops.geomTransf("Linear", 1, 0.0, 0.0, 1.0)
    ops.uniaxialMaterial("ElasticPP", 1, E, fy / E)
    ops.uniaxialMaterial("Elastic", 9, 1.0)
    ops.section("Fiber", 1, "-GJ", 1.0e4)
    ops.patch("rect", 1, 40, 2, -h / 2, -b / 2, h / 2, b / 2)
    ops.beamIntegration("Lobatto", 1, 1, 5)
    ops.element("forceBeamColumn", 1, 1, 2, 1, 1, "-iter", max_iter, 1e-16)
    ops.element("zeroLength", 2, 1, 3, "-mat", 9, "-dir", 1)
    ops.constraints("Transformation")
    ops.numberer("Plain")
    ops.system("FullGeneral")
    ops.test("FixedNumIter", 1)
    ops.algorithm("Linear")
    ops.integrator("LoadControl", 1.0)
    ops.analysis("Static")
    for k in range(1, steps + 1):
        if k > 1:
            ops.remove("loadPattern", k - 1)
        ops.timeSeries("Constant", k)
        ops.pattern("Plain", k, k)
        for dof in range(6):
            ops.sp(2, dof + 1, 0.08 * k / steps if dof == 1 else 0.0)
        ops.analyze(1)
    out[key] = ops.eleResponse(1, "basicForce")


def run(ops):
    out = {}
    agg_steps = ((0.0, 0.0, 1.07), (0.0, 0.0, 2.5), (0.0, 0.0, -1.3), (0.01, 0.3, -0.2))
    for max_iter in (1, 2, 10):
        for tol in (1e10, 10.0, 1e-12):
            _cantilever_2d(ops, _bilinear, 4, max_iter, tol)
            _impose(ops, agg_steps, 4, out, f"bilinear.iter{max_iter}.tol{tol:g}")
    steel_steps = ((0.01, 0.0, 0.008), (0.02, 0.0, 0.015), (0.05, 0.0, 0.04), (0.0, 0.0, -0.01))
    for max_iter in (1, 3, 4, 10):
        for tol in (1e10, 1e-6, 1e-12):
            _cantilever_2d(ops, _steel_fibers, 5, max_iter, tol)
            _impose(ops, steel_steps, 5, out, f"steel.iter{max_iter}.tol{tol:g}")
    for max_iter, tol in ((3, 1e-6), (4, 1e-6), (10, 1e-6), (10, 1e-12)):
        _cantilever_2d(ops, _concrete, 4, max_iter, tol)
        _impose(ops, ((0.0, -36.0, -0.96),), 4, out, f"concrete.iter{max_iter}.tol{tol:g}")
    for max_iter in (1, 10):
        _jump_3d(ops, out, f"jump3d.iter{max_iter}", max_iter, 1)
    _jump_3d(ops, out, "walk3d", 10, 100)
    ops.wipe()
    return out

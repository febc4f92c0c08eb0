"""twoNodeLink in 2D (ndf 2 and 3) and 3D (ndf 3 and 6): one link between
a fixed and a loaded node with springs in every direction, in skewed
positions with the default axes, -orient (3 and 6 numbers), -shearDist and
-pDelta; every end displaced in turn (sp) to read the whole transformation
through 'force', 'localForce', 'basicForce', 'basicDeformation',
'localDisplacement' and the axes; a cantilever column of links with
-pDelta pushed sideways under axial load (nonlinear geometry); a Steel01
link cycled; the lumped -mass in eigen and a Newmark run with a Viscous
damper link.
"""

K = (1000.0, 10.0, 20.0, 100.0, 200.0, 300.0)


def _analysis(ops, handler="Plain", test=("NormDispIncr", 1e-12, 10)):
    ops.wipeAnalysis()
    ops.constraints(*handler) if isinstance(handler, tuple) else ops.constraints(handler)
    ops.system("FullGeneral")
    ops.numberer("Plain")
    ops.test(*test)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", 1.0)
    ops.analysis("Static")


def _link(ops, ndm, ndf, xj, dirs, extra):
    ops.wipe()
    ops.model("basic", "-ndm", ndm, "-ndf", ndf)
    ops.node(1, *([0.0] * ndm))
    ops.node(2, *xj)
    for d in dirs:
        ops.uniaxialMaterial("Elastic", d, K[d - 1])
    ops.element("twoNodeLink", 1, 1, 2, "-mat", *dirs, "-dir", *dirs, *extra)


def _unit_columns(ops, out, name, ndm, ndf, xj, dirs, extra):
    """Each of the 2 ndf end displacements set to 1 in turn (the others 0)."""
    for k in range(2 * ndf):
        _link(ops, ndm, ndf, xj, dirs, extra)
        ops.timeSeries("Constant", 1)
        ops.pattern("Plain", 1, 1)
        for n in (1, 2):
            for d in range(1, ndf + 1):
                ops.sp(n, d, 1.0e-3 if ndf * (n - 1) + d - 1 == k else 0.0)
        _analysis(ops, ("Penalty", 1.0e16, 1.0e16))
        ops.analyze(1)
        p = f"{name}.u{k + 1}."
        for r in ("force", "localForce", "basicForce", "basicDeformation", "localDisplacement"):
            out[p + r] = ops.eleResponse(1, r)
    for axis in ("xaxis", "yaxis", "zaxis"):
        out[f"{name}.{axis}"] = ops.eleResponse(1, axis)
    out[name + ".classTags"] = ops.getEleClassTags(1)


def _column_pdelta(ops, out, name, ratios):
    """Three links stacked into a 2D column (ndf 3), axial load and a push."""
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    for n in range(4):
        ops.node(n + 1, 0.3 * n, 2.0 * n)
    ops.fix(1, 1, 1, 1)
    for d in (1, 2, 3):
        ops.uniaxialMaterial("Elastic", d, (5.0e4, 60.0, 800.0)[d - 1])
    extra = ("-pDelta", *ratios) if ratios is not None else ()
    for e in range(3):
        ops.element("twoNodeLink", e + 1, e + 1, e + 2, "-mat", 1, 2, 3, "-dir", 1, 2, 3, *extra)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(4, 3.0, -40.0, 0.0)
    _analysis(ops)
    ops.integrator("LoadControl", 0.25)
    out[name + ".codes"] = [ops.analyze(1) for _ in range(4)]
    out[name + ".disp"] = [ops.nodeDisp(n) for n in (2, 3, 4)]
    ops.reactions()
    out[name + ".reaction"] = ops.nodeReaction(1)
    for e in (1, 3):
        out[f"{name}.ele{e}.localForce"] = ops.eleResponse(e, "localForce")
        out[f"{name}.ele{e}.basicForce"] = ops.eleResponse(e, "basicForce")


def run(ops):
    out = {}
    _unit_columns(ops, out, "2d.ndf2", 2, 2, (3.0, 4.0), (1, 2), ())
    _unit_columns(ops, out, "2d.ndf3", 2, 3, (3.0, 4.0), (1, 2, 3), ())
    _unit_columns(ops, out, "2d.ndf3.dirs32", 2, 3, (3.0, -4.0), (3, 2), ())
    _unit_columns(ops, out, "2d.ndf3.shear", 2, 3, (-2.0, 1.5), (1, 2, 3), ("-shearDist", 0.3))
    _unit_columns(ops, out, "2d.ndf3.orient3", 2, 3, (3.0, 4.0), (1, 2, 3), ("-orient", 1.0, 1.0, 0.0))
    _unit_columns(ops, out, "2d.ndf3.pdelta", 2, 3, (3.0, 4.0), (1, 2, 3), ("-pDelta", 0.3, 0.2))
    _unit_columns(ops, out, "3d.ndf3", 3, 3, (1.0, 2.0, 0.5), (1, 2, 3), ())
    _unit_columns(ops, out, "3d.ndf6", 3, 6, (1.0, 2.0, 0.5), (1, 2, 3, 4, 5, 6), ())
    _unit_columns(ops, out, "3d.ndf6.alongY", 3, 6, (0.0, 2.0, 0.0), (1, 2, 3, 4, 5, 6), ())
    _unit_columns(ops, out, "3d.ndf6.alongZ", 3, 6, (0.0, 0.0, -2.0), (1, 2, 6), ())
    _unit_columns(ops, out, "3d.ndf6.shear", 3, 6, (1.0, 2.0, 0.5), (1, 2, 3, 4, 5, 6), ("-shearDist", 0.2, 0.7))
    _unit_columns(ops, out, "3d.ndf6.orient3", 3, 6, (1.0, 2.0, 0.5), (1, 2, 3, 5), ("-orient", 0.0, 0.0, 1.0))
    _unit_columns(ops, out, "3d.ndf6.orient6", 3, 6, (1.0, 2.0, 0.5), (1, 2, 3, 4, 5, 6),
                  ("-orient", 1.0, 0.0, 0.0, 0.0, 1.0, 1.0))
    _unit_columns(ops, out, "3d.ndf6.zero", 3, 6, (0.0, 0.0, 0.0), (1, 2, 3, 4, 5, 6),
                  ("-orient", 0.0, 1.0, 0.0, 0.0, 0.0, 1.0))
    _unit_columns(ops, out, "3d.ndf6.pdelta", 3, 6, (1.0, 2.0, 0.5), (1, 2, 3, 4, 5, 6),
                  ("-pDelta", 0.1, 0.2, 0.3, 0.25))
    _column_pdelta(ops, out, "column.none", None)
    _column_pdelta(ops, out, "column.couple", (0.0, 0.0))
    _column_pdelta(ops, out, "column.ends", (0.5, 0.4))

    # A Steel01 link (3D, ndf 6) cycled along a skew line through the shear direction.
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    ops.node(1, 0.0, 0.0, 0.0)
    ops.node(2, 0.5, 0.2, 1.5)
    ops.fix(1, 1, 1, 1, 1, 1, 1)
    ops.fix(2, 0, 0, 0, 1, 1, 1)
    ops.uniaxialMaterial("Steel01", 1, 5.0, 300.0, 0.05)
    ops.uniaxialMaterial("Elastic", 2, 900.0)
    ops.element("twoNodeLink", 1, 1, 2, "-mat", 2, 1, 1, "-dir", 1, 2, 3)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.sp(2, 1, 1.0)
    ops.sp(2, 2, -0.4)
    ops.wipeAnalysis()
    ops.constraints("Transformation")
    ops.system("FullGeneral")
    ops.numberer("Plain")
    ops.test("NormDispIncr", 1e-12, 10)
    ops.algorithm("Newton")
    forces, codes = [], []
    for steps, dlambda in ((4, 0.01), (9, -0.01), (8, 0.01)):
        ops.integrator("LoadControl", dlambda)
        ops.analysis("Static")
        for _ in range(steps):
            codes.append(ops.analyze(1))
            forces.append(ops.eleResponse(1, "basicForce"))
    out["steel.codes"] = codes
    out["steel.basicForce"] = forces
    out["steel.force"] = ops.eleResponse(1, "force")
    out["steel.material2.stress"] = ops.eleResponse(1, "material", 2, "stress")

    # Lumped mass: eigen of a 2D link (ndf 3) and a 3D link (ndf 6).
    for ndm, ndf, xj in ((2, 3, (3.0, 4.0)), (3, 6, (1.0, 2.0, 0.5))):
        dirs = (1, 2, 3) if ndm == 2 else (1, 2, 3, 4, 5, 6)
        _link(ops, ndm, ndf, xj, dirs, ("-mass", 4.0))
        ops.fix(1, *([1] * ndf))
        ops.fix(2, *([0] * ndm + [1] * (ndf - ndm)))
        out[f"mass.{ndm}d.eigen"] = ops.eigen("-fullGenLapack", ndm)

    # A Viscous damper link and a spring in a Newmark run (SDOF pushed and released).
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 2)
    ops.node(1, 0.0, 0.0)
    ops.node(2, 2.0, 1.0)
    ops.fix(1, 1, 1)
    ops.fix(2, 0, 1)
    ops.uniaxialMaterial("Elastic", 1, 400.0)
    ops.uniaxialMaterial("Viscous", 2, 15.0, 1.0)
    ops.element("twoNodeLink", 1, 1, 2, "-mat", 1, "-dir", 1, "-mass", 6.0)
    ops.element("twoNodeLink", 2, 1, 2, "-mat", 2, "-dir", 1)
    ops.mass(2, 1.0, 1.0)
    ops.timeSeries("Constant", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, 10.0, 0.0)
    ops.wipeAnalysis()
    ops.constraints("Plain")
    ops.system("FullGeneral")
    ops.numberer("Plain")
    ops.test("NormDispIncr", 1e-12, 10)
    ops.algorithm("Newton")
    ops.integrator("Newmark", 0.5, 0.25)
    ops.analysis("Transient")
    hist = []
    for _ in range(8):
        ops.analyze(1, 0.02)
        hist.append([ops.nodeDisp(2, 1), ops.nodeVel(2, 1), ops.eleResponse(2, "basicForce")[0]])
    out["damper.history"] = hist

    # Rayleigh damping (betaK) reaches only the link with -doRayleigh.
    for flag in ((), ("-doRayleigh",)):
        ops.wipe()
        ops.model("basic", "-ndm", 3, "-ndf", 3)
        ops.node(1, 0.0, 0.0, 0.0)
        ops.node(2, 1.0, 0.5, 2.0)
        ops.fix(1, 1, 1, 1)
        ops.uniaxialMaterial("Elastic", 1, 400.0)
        ops.uniaxialMaterial("Elastic", 2, 150.0)
        ops.element("twoNodeLink", 1, 1, 2, "-mat", 1, 2, 2, "-dir", 1, 2, 3, "-mass", 2.0, *flag)
        ops.mass(2, 1.0, 1.0, 1.0)
        ops.rayleigh(0.0, 0.02, 0.0, 0.0)
        ops.timeSeries("Constant", 1)
        ops.pattern("Plain", 1, 1)
        ops.load(2, 5.0, -3.0, 2.0)
        ops.wipeAnalysis()
        ops.constraints("Plain")
        ops.system("FullGeneral")
        ops.numberer("Plain")
        ops.test("NormDispIncr", 1e-12, 10)
        ops.algorithm("Newton")
        ops.integrator("Newmark", 0.5, 0.25)
        ops.analysis("Transient")
        hist = []
        for _ in range(8):
            ops.analyze(1, 0.02)
            hist.append(ops.nodeDisp(2))
        out[f"rayleigh{len(flag)}.history"] = hist
    return out

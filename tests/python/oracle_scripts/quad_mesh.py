"""A 3 x 2 mesh of quad elements (interior nodes moved so that no element is
a parallelogram) on a fixed base, once in plane strain and once in plane
stress: under the element's pressure and body-force arguments (which act in
full at every step), then with an eleLoad '-selfWeight' in a Linear pattern
(which replaces the body force by its factored share), with every response
and an Element recorder; and the lowest eigenvalues of the lumped mass.
"""
import re

NX, NY = 3, 2
LX, LY = 3.0, 2.0
E, NU, RHO = 2.0e4, 0.3, 1.8
THICK = 0.4
PRESSURE, BODY = 12.0, (1.5, -20.0)
MOVED = {(1, 1): (0.13, -0.08), (2, 1): (-0.1, 0.11)}


def _tag(i, j):
    return 1 + i + (NX + 1) * j


def _build(ops, kind, extra):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 2)
    for j in range(NY + 1):
        for i in range(NX + 1):
            dx, dy = MOVED.get((i, j), (0.0, 0.0))
            ops.node(_tag(i, j), LX * i / NX + dx, LY * j / NY + dy + 0.05 * i * j)
    for i in range(NX + 1):
        ops.fix(_tag(i, 0), 1, 1)
    ops.nDMaterial("ElasticIsotropic", 1, E, NU, RHO)
    tag = 0
    for j in range(NY):
        for i in range(NX):
            tag += 1
            nodes = (_tag(i, j), _tag(i + 1, j), _tag(i + 1, j + 1), _tag(i, j + 1))
            ops.element("quad", tag, *nodes, THICK, kind, 1, *extra)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)


def _analyse(ops, dlambda, steps):
    ops.system("UmfPack")
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.test("NormDispIncr", 1e-12, 10)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", dlambda)
    ops.analysis("Static")
    codes, iters = [], []
    for _ in range(steps):
        codes.append(ops.analyze(1))
        iters.append(ops.testIter())
    return codes, iters


def _results(ops, out, prefix):
    out[prefix + "disp"] = [ops.nodeDisp(_tag(i, j)) for j in range(1, NY + 1) for i in range(NX + 1)]
    ops.reactions()
    base = [_tag(i, 0) for i in range(NX + 1)]
    out[prefix + "reactionSum"] = [sum(ops.nodeReaction(n, d) for n in base) for d in (1, 2)]
    for e in (1, 5):
        for r in ("forces", "stresses", "strains"):
            out[f"{prefix}ele{e}.{r}"] = ops.eleResponse(e, r)
        for k in (1, 3):
            out[f"{prefix}ele{e}.material{k}.stress"] = ops.eleResponse(e, "material", k, "stress")
            out[f"{prefix}ele{e}.material{k}.strain"] = ops.eleResponse(e, "material", k, "strain")


def run(ops):
    out = {}
    for kind in ("PlaneStrain", "PlaneStress"):
        # 1. pressure and body forces of the element command, constant.
        _build(ops, kind, (PRESSURE, 0.0, *BODY))
        ops.load(_tag(NX, NY), 40.0, -15.0)
        ops.recorder("Element", "-file", f"{kind}_stress.out", "-time", "-ele", 2, "stresses")
        ops.recorder("Element", "-xml", f"{kind}_force.xml", "-ele", 6, "forces")
        ops.recorder("Element", "-xml", f"{kind}_mat.xml", "-ele", 6, "material", 2, "strain")
        ops.recorder("Element", "-xml", f"{kind}_stresses.xml", "-ele", 6, "stresses")
        ops.recorder("Element", "-xml", f"{kind}_strains.xml", "-ele", 6, "strains")
        out[kind + ".codes"], out[kind + ".testIter"] = _analyse(ops, 0.5, 2)
        _results(ops, out, kind + ".")
        ops.wipe()
        with open(f"{kind}_stress.out") as f:
            out[kind + ".recorder.stress"] = f.read()
        for name in ("force", "mat", "stresses", "strains"):
            with open(f"{kind}_{name}.xml") as f:
                out[f"{kind}.recorder.{name}.names"] = re.findall(r"<ResponseType>(.*?)</ResponseType>", f.read())

        # 2. eleLoad -selfWeight: factors on b1, b2, scaled by the pattern.
        _build(ops, kind, (PRESSURE, RHO, *BODY))
        ops.eleLoad("-ele", *range(1, NX * NY + 1), "-type", "-selfWeight", 0.5, 2.0)
        out[kind + ".selfWeight.codes"], _ = _analyse(ops, 0.25, 2)
        _results(ops, out, kind + ".selfWeight.")

        # 3. Eigenvalues with the lumped mass (element rho, then the material's).
        for label, rho in (("element", 2.5), ("material", 0.0)):
            _build(ops, kind, (0.0, rho))
            out[f"{kind}.eigen.{label}"] = ops.eigen("-fullGenLapack", 3)
    ops.wipe()
    return out

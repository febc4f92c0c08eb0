"""OpenSees Example 3 (Mazzoni and McKenna, 2006): the 2D cantilever column with units, static pushover.

Written in the style of the public example (units as variables, build then
analyze, the pushover's fall-back loop), in two of its published builds:

1. "fiber01": the inelastic fiber section of confined core and cover
   (Concrete01, softening past eps1) with Steel01 bars, nonlinearBeamColumn
   with 5 Lobatto points, default element iterations (10, 1e-12).
2. "fiber02": one unconfined concrete patch (Concrete02 with tension) and
   Steel02 bars, the same element.

Gravity in 10 LoadControl steps (NormDispIncr 1e-8, 6 iterations),
loadConst('-time', 0.0), then DisplacementControl of the head by 0.001 LCol
to 0.05 LCol with EnergyIncr 1e-8 and 6 iterations; when analyze(Nsteps)
fails, the example's loop retries every step with Newton -initial
(NormDispIncr, 2000 iterations), then Broyden 8, then NewtonLineSearch 0.8.
Compared: return codes, iteration counts, load factors and head
displacements of every step, section forces and deformations at both ends,
the base reaction, and the recorder files the example writes (node
displacement and reaction, section 1 force and deformation; the example's
Drift recorder is left out: OpenSeesPy 3.7.1 refuses it, 'failed to get dof').
The concrete softens and both builds fail the plain Newton half way: the
fall-back path (element state determination included) is what is compared.
"""

# units (kip, inch, second)
inch = 1.0
kip = 1.0
sec = 1.0
ft = 12.0 * inch
ksi = kip / inch ** 2
psi = ksi / 1000.0
in2 = inch * inch
g = 32.2 * ft / sec ** 2


def _build(ops, variant):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    LCol = 36.0 * ft
    Weight = 2000.0 * kip
    HCol = 5.0 * ft
    BCol = 5.0 * ft
    PCol = Weight
    Mass = PCol / g
    ops.node(1, 0.0, 0.0)
    ops.node(2, 0.0, LCol)
    ops.fix(1, 1, 1, 1)
    ops.mass(2, Mass, 1e-9, 0.0)

    ColSecTag = 1
    coverCol = 5.0 * inch
    numBarsCol = 16 if variant == "fiber01" else 20
    barAreaCol = 2.25 * in2
    fc = -4.0 * ksi
    Ec = 57.0 * ksi * (-fc / psi) ** 0.5
    Fy = 66.8 * ksi
    Es = 29000.0 * ksi
    Bs = 0.01
    coverY = HCol / 2.0
    coverZ = BCol / 2.0
    coreY = coverY - coverCol
    coreZ = coverZ - coverCol
    if variant == "fiber01":
        IDconcCore, IDconcCover, IDreinf = 1, 2, 3
        Kfc = 1.3
        fc1C = Kfc * fc
        eps1C = 2.0 * fc1C / Ec
        fc2C = 0.2 * fc1C
        eps2C = 5.0 * eps1C
        fc1U = fc
        eps1U = -0.003
        fc2U = 0.2 * fc1U
        eps2U = -0.01
        ops.uniaxialMaterial("Concrete01", IDconcCore, fc1C, eps1C, fc2C, eps2C)
        ops.uniaxialMaterial("Concrete01", IDconcCover, fc1U, eps1U, fc2U, eps2U)
        ops.uniaxialMaterial("Steel01", IDreinf, Fy, Es, Bs)
        nfCoreY, nfCoreZ, nfCoverY, nfCoverZ = 16, 4, 16, 4
        ops.section("Fiber", ColSecTag)
        ops.patch("quad", IDconcCore, nfCoreZ, nfCoreY, -coreY, coreZ, -coreY, -coreZ, coreY, -coreZ, coreY, coreZ)
        ops.patch("quad", IDconcCover, 1, nfCoverY, -coverY, coverZ, -coreY, coreZ, coreY, coreZ, coverY, coverZ)
        ops.patch("quad", IDconcCover, 1, nfCoverY, -coreY, -coreZ, -coverY, -coverZ, coverY, -coverZ, coreY, -coreZ)
        ops.patch("quad", IDconcCover, nfCoverZ, 1, -coverY, coverZ, -coverY, -coverZ, -coreY, -coreZ, -coreY, coreZ)
        ops.patch("quad", IDconcCover, nfCoverZ, 1, coreY, coreZ, coreY, -coreZ, coverY, -coverZ, coverY, coverZ)
    else:
        IDconcU, IDreinf = 1, 2
        fc1U = fc
        eps1U = -0.003
        fc2U = 0.2 * fc1U
        eps2U = -0.01
        lam = 0.1
        ftU = -0.14 * fc1U
        Ets = ftU / 0.002
        ops.uniaxialMaterial("Concrete02", IDconcU, fc1U, eps1U, fc2U, eps2U, lam, ftU, Ets)
        ops.uniaxialMaterial("Steel02", IDreinf, Fy, Es, Bs, 18.0, 0.925, 0.15)
        nfY, nfZ = 16, 4
        ops.section("Fiber", ColSecTag)
        ops.patch("quad", IDconcU, nfZ, nfY, -coverY, coverZ, -coverY, -coverZ, coverY, -coverZ, coverY, coverZ)
    ops.layer("straight", IDreinf, numBarsCol, barAreaCol, -coreY, coreZ, -coreY, -coreZ)
    ops.layer("straight", IDreinf, numBarsCol, barAreaCol, coreY, coreZ, coreY, -coreZ)

    ColTransfTag = 1
    ops.geomTransf("Linear", ColTransfTag)
    numIntgrPts = 5
    ops.element("nonlinearBeamColumn", 1, 1, 2, numIntgrPts, ColSecTag, ColTransfTag)

    ops.recorder("Node", "-file", f"{variant}_DFree.out", "-time", "-node", 2, "-dof", 1, 2, 3, "disp")
    ops.recorder("Node", "-file", f"{variant}_RBase.out", "-time", "-node", 1, "-dof", 1, 2, 3, "reaction")
    ops.recorder("Element", "-file", f"{variant}_ForceColSec1.out", "-time", "-ele", 1, "section", 1, "force")
    ops.recorder("Element", "-file", f"{variant}_DefoColSec1.out", "-time", "-ele", 1, "section", 1,
                 "deformation")

    # gravity
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, 0.0, -PCol, 0.0)
    Tol = 1.0e-8
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.system("BandGeneral")
    ops.test("NormDispIncr", Tol, 6)
    ops.algorithm("Newton")
    NstepGravity = 10
    DGravity = 1.0 / NstepGravity
    ops.integrator("LoadControl", DGravity)
    ops.analysis("Static")
    code = ops.analyze(NstepGravity)
    ops.loadConst("-time", 0.0)
    return LCol, Weight, code


def _push(ops, out, key, LCol, Weight):
    IDctrlNode, IDctrlDOF = 2, 1
    Dmax = 0.05 * LCol
    Dincr = 0.001 * LCol
    ops.timeSeries("Linear", 2)
    ops.pattern("Plain", 200, 2)
    ops.load(2, Weight, 0.0, 0.0)
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.system("BandGeneral")
    Tol = 1.0e-8
    maxNumIter = 6
    printFlag = 0
    TestType = "EnergyIncr"
    ops.test(TestType, Tol, maxNumIter, printFlag)
    algorithmType = "Newton"
    ops.algorithm(algorithmType)
    ops.integrator("DisplacementControl", IDctrlNode, IDctrlDOF, Dincr)
    ops.analysis("Static")

    steps = []

    def record(code):
        steps.append([code, ops.testIter(), ops.getLoadFactor(200), ops.nodeDisp(IDctrlNode, IDctrlDOF)])

    # The example calls analyze(Nsteps) once; step by step gives the same path
    # (analyze stops at the first failure) and lets every step be compared.
    Nsteps = int(Dmax / Dincr)
    ok = 0
    for _ in range(Nsteps):
        ok = ops.analyze(1)
        record(ok)
        if ok != 0:
            break
    if ok != 0:
        ok = 0
        controlDisp = 0.0
        D0 = 0.0
        Dstep = (controlDisp - D0) / (Dmax - D0)
        while Dstep < 1.0 and ok == 0:
            controlDisp = ops.nodeDisp(IDctrlNode, IDctrlDOF)
            Dstep = (controlDisp - D0) / (Dmax - D0)
            ok = ops.analyze(1)
            record(ok)
            if ok != 0:
                ops.test("NormDispIncr", Tol, 2000, 0)
                ops.algorithm("Newton", "-initial")
                ok = ops.analyze(1)
                record(ok)
                ops.test(TestType, Tol, maxNumIter, 0)
                ops.algorithm(algorithmType)
            if ok != 0:
                ops.algorithm("Broyden", 8)
                ok = ops.analyze(1)
                record(ok)
                ops.algorithm(algorithmType)
            if ok != 0:
                ops.algorithm("NewtonLineSearch", 0.8)
                ok = ops.analyze(1)
                record(ok)
                ops.algorithm(algorithmType)
    out[key + "steps"] = steps
    out[key + "final"] = ok
    for n in (1, 5):
        out[key + f"section{n}"] = ops.eleResponse(1, "section", n, "force") + ops.eleResponse(1, "section", n,
                                                                                               "deformation")
    out[key + "basicForce"] = ops.eleResponse(1, "basicForce")
    ops.reactions()
    out[key + "reaction"] = ops.nodeReaction(1)
    out[key + "disp"] = ops.nodeDisp(2)


def run(ops):
    out = {}
    for variant in ("fiber01", "fiber02"):
        LCol, Weight, code = _build(ops, variant)
        out[variant + ".gravity"] = [code, ops.nodeDisp(2)]
        _push(ops, out, variant + ".push.", LCol, Weight)
        ops.remove("recorders")
        for name in ("DFree", "RBase", "ForceColSec1", "DefoColSec1"):
            with open(f"{variant}_{name}.out") as f:
                out[f"file:{variant}_{name}.out"] = f.read()
    ops.wipe()
    return out

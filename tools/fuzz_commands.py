"""The command fuzzer: random command sequences against small live models.

A sequence is a fresh small model (3D: beam and brick nodes, materials, a
transformation, a beam, a load pattern; every other sequence 2D: a frame,
quad and truss nodes), then `calls_per_sequence` random
commands, then `wipe`. A command is either a valid call from TEMPLATES, used
as is or mutated (an argument replaced, dropped or added), or a random one
(valid type names, wrong types, wrong counts, unknown tags, huge and negative
numbers). Every call must either succeed or raise
OpenSeesError; any other exception is a finding. A crash or a sanitizer report
ends the process, so callers run this in a subprocess (tests/python/
test_fuzz_commands.py with a small count; benchmarks/fuzz_sanitized.py with
100,000 sequences under the sanitizer build).

Sequence i of seed s draws from its own random stream, so any sequence can be
replayed alone:

    python tools/fuzz_commands.py --seed s --first i --sequences 1 --calls C --trace
"""
import argparse
import json
import os
import random
import sys
import tempfile

WORDS = ["-ndf", "-mass", "-file", "/dev/null", "-time", "-node", "-ele", "-dof", "disp", "force",
         "-type", "-beamUniform", "-jntOffset", "-mat", "-dir", "-orient", "-val", "friction",
         "-material", "-stage", "-JSON", "basic", "-ndm", "Plain", "Linear", "Static", "ele", "node",
         "recorders", "sp", "mp", "-fact", "-tol", "-values", "-dt", "stresses", "localForce", ""]

# Commands whose first argument is a registered type name.
TYPED_COMMANDS = ("element", "uniaxialMaterial", "nDMaterial", "geomTransf", "timeSeries", "recorder",
                  "constraints", "numberer", "system", "test", "algorithm", "integrator", "section",
                  "beamIntegration")

# Valid calls against the model of build() (nodes 1-4 with 6 dofs, 5-12 with 3,
# a unit cube of them at 5-12), each used as is or with an argument replaced,
# dropped or added: purely random argument lists rarely get past the parser,
# while these reach the elements, the analysis and the recorders.
TEMPLATES = [
    ("node", (13, 1.5, 0.0, 0.0)), ("node", (14, 0.5, 0.5, 0.5, "-mass", 1.0, 1.0, 1.0)),
    ("model", ("basic", "-ndm", 3, "-ndf", 6)), ("model", ("basic", "-ndm", 3, "-ndf", 3)),
    ("fix", (3, 1, 1, 1, 1, 1, 1)), ("fix", (8, 1, 1, 1)), ("fixZ", (0.0, 1, 1, 1)), ("fixX", (0.0, 1, 1, 1)),
    ("mass", (2, 1.0, 1.0, 1.0, 0.0, 0.0, 0.0)), ("equalDOF", (2, 3, 1, 2, 3)), ("rigidLink", ("beam", 2, 3)),
    ("rigidLink", ("bar", 5, 6)),
    ("uniaxialMaterial", ("Steel01", 2, 50.0, 100.0, 0.02)),
    ("uniaxialMaterial", ("Steel02", 3, 50.0, 100.0, 0.02)),
    ("uniaxialMaterial", ("ElasticPP", 4, 100.0, 0.01)),
    ("uniaxialMaterial", ("Concrete01", 5, -30.0, -0.002, -20.0, -0.005)),
    ("uniaxialMaterial", ("Concrete02", 6, -30.0, -0.002, -20.0, -0.005, 0.1, 3.0, 100.0)),
    ("uniaxialMaterial", ("ENT", 7, 100.0)),
    ("nDMaterial", ("ContactMaterial3D", 2, 0.3, 1000.0, 0.0, 0.0)),
    ("nDMaterial", ("InitialStateAnalysisWrapper", 3, 1, 3)),
    ("geomTransf", ("PDelta", 2, 0.0, 0.0, 1.0)), ("geomTransf", ("Corotational", 3, 0.0, 0.0, 1.0)),
    ("geomTransf", ("Corotational", 4, 0.0, 0.0, 1.0, "-jntOffset", 0.1, 0.0, 0.0, 0.0, 0.0, 0.0)),
    ("section", ("Elastic", 1, 100.0, 1.0, 1.0, 1.0, 40.0, 1.0)), ("section", ("Fiber", 2, "-GJ", 1e3)),
    ("patch", ("rect", 1, 4, 2, -0.2, -0.1, 0.2, 0.1)), ("patch", ("circ", 1, 4, 2, 0.0, 0.0, 0.1, 0.3)),
    ("layer", ("straight", 1, 4, 0.01, 0.0, -1.0, 0.0, 1.0)), ("layer", ("circ", 1, 6, 0.01, 0.0, 0.0, 0.2)),
    ("fiber", (0.0, 0.1, 0.01, 1)),
    ("beamIntegration", ("Lobatto", 1, 1, 3)), ("beamIntegration", ("Legendre", 2, 2, 2)),
    ("beamIntegration", ("HingeRadau", 3, 1, 0.1, 1, 0.1, 1)),
    ("element", ("elasticBeamColumn", 2, 2, 3, 1.0, 100.0, 40.0, 1.0, 1.0, 1.0, 1)),
    ("element", ("dispBeamColumn", 3, 2, 3, 1, 1)), ("element", ("forceBeamColumn", 4, 3, 4, 1, 1)),
    ("element", ("forceBeamColumn", 4, 3, 4, 3, 2, "-iter", 10, 1e-12)),
    ("element", ("stdBrick", 5, 8, 5, 7, 6, 12, 9, 11, 10, 1)), ("element", ("truss", 6, 5, 11, 1.0, 1)),
    ("element", ("corotTruss", 7, 8, 11, 1.0, 1)),
    ("element", ("zeroLength", 8, 3, 4, "-mat", 1, 1, "-dir", 1, 2)),
    ("element", ("zeroLengthContact3D", 9, 5, 8, 1e3, 1e3, 0.3, 0.0, 1)),
    ("element", ("BeamContact3D", 10, 1, 2, 5, 13, 0.3, 1, 2, 1e-8, 1e-8)),
    ("element", ("BeamContact3Dp", 11, 1, 2, 6, 0.3, 1, 1e6, 0.3)),
    ("element", ("BeamEndContact3D", 12, 1, 2, 7, 13, 0.3, 1e-8, 1e-8)),
    ("timeSeries", ("Constant", 2)), ("timeSeries", ("Path", 3, "-dt", 0.1, "-values", 0.0, 1.0, 2.0)),
    ("timeSeries", ("Path", 4, "-time", 0.0, 1.0, "-values", 0.0, 1.0, "-factor", 2.0)),
    ("pattern", ("Plain", 2, 1)), ("load", (2, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0)), ("load", (11, 0.0, 0.0, -1.0)),
    ("sp", (5, 1, 0.01)), ("eleLoad", ("-ele", 1, "-type", "-beamUniform", 1.0, 0.0)),
    ("eleLoad", ("-ele", 1, "-type", "-beamPoint", 1.0, 0.0, 0.5)),
    ("constraints", ("Transformation",)), ("constraints", ("Plain",)), ("constraints", ("Penalty", 1e8, 1e8)),
    ("numberer", ("RCM",)), ("numberer", ("AMD",)), ("system", ("UmfPack",)), ("system", ("BandSPD",)),
    ("system", ("FullGeneral",)), ("test", ("NormDispIncr", 1e-8, 10)), ("test", ("EnergyIncr", 1e-10, 5, 2)),
    ("test", ("NormUnbalance", 1e-8, 10)), ("test", ("FixedNumIter", 3)), ("algorithm", ("Newton",)),
    ("algorithm", ("KrylovNewton",)), ("algorithm", ("NewtonLineSearch", 0.8)), ("algorithm", ("ModifiedNewton",)),
    ("algorithm", ("Linear",)), ("integrator", ("LoadControl", 0.1)),
    ("integrator", ("DisplacementControl", 2, 1, 0.01)), ("integrator", ("ArcLength", 1.0, 1.0)),
    ("analysis", ("Static",)), ("analyze", (1,)), ("analyze", (3,)), ("eigen", (2,)), ("eigen", ("-fullGenLapack", 1)),
    ("recorder", ("Node", "-file", "n.out", "-time", "-node", 2, "-dof", 1, 2, "disp")),
    ("recorder", ("Node", "-xml", "n.xml", "-node", 2, 5, "-dof", 1, "reaction")),
    ("recorder", ("Element", "-file", "e.out", "-ele", 1, "localForce")),
    ("recorder", ("EnvelopeNode", "-file", "en.out", "-node", 2, "-dof", 1, "disp")),
    ("recorder", ("EnvelopeElement", "-binary", "ee.bin", "-ele", 1, "force")),
    ("recorder", ("PVD", "pvd", "disp", "reaction")), ("record", ()),
    ("nodeDisp", (2, 1)), ("nodeReaction", (1,)), ("nodeEigenvector", (2, 1, 1)), ("nodeUnbalance", (2,)),
    ("eleResponse", (1, "localForce")), ("eleResponse", (1, "basicDeformation")), ("eleForce", (1, 2)),
    ("eleNodes", (1,)), ("reactions", ()), ("loadConst", ("-time", 0.0)), ("setTime", (1.0,)),
    ("remove", ("ele", 1)), ("remove", ("node", 4)), ("remove", ("sp", 1, 1)), ("remove", ("recorders",)),
    ("remove", ("loadPattern", 1)), ("remove", ("mp", 3)), ("wipeAnalysis", ()), ("testNorms", ()),
    ("systemSize", ()), ("setParameter", ("-val", 0.5, "-ele", 1, "friction")),
    ("updateMaterialStage", ("-material", 1, "-stage", 1)), ("InitialStateAnalysis", ("on",)),
    ("testUniaxialMaterial", (1,)), ("setStrain", (0.01,)), ("getStress", ()), ("getTangent", ()),
    # Materials, sections and commands of issue 15 (they work in every space).
    ("uniaxialMaterial", ("Hardening", 8, 100.0, 1.0, 5.0, 5.0)),
    ("uniaxialMaterial", ("Hysteretic", 9, 1.0, 0.01, 1.5, 0.05, -1.0, -0.01, -1.5, -0.05, 0.8, 0.2, 0.0, 0.0, 0.5)),
    ("uniaxialMaterial", ("MultiLinear", 10, 0.01, 1.0, 0.02, 1.5, 0.05, 1.6)),
    ("uniaxialMaterial", ("ElasticMultiLinear", 11, "-strain", -1.0, 0.0, 1.0, "-stress", -2.0, 0.0, 1.0)),
    ("uniaxialMaterial", ("Parallel", 12, 1, 2)), ("uniaxialMaterial", ("Series", 13, 1, 8)),
    ("uniaxialMaterial", ("MinMax", 14, 2, "-min", -0.02, "-max", 0.02)),
    ("uniaxialMaterial", ("InitStrainMaterial", 15, 1, 0.001)),
    ("section", ("Aggregator", 3, 1, "T", "-section", 2)),
    ("element", ("zeroLengthSection", 13, 3, 4, 1, "-orient", 1.0, 0.0, 0.0, 0.0, 1.0, 0.0)),
    ("rigidDiaphragm", (3, 2, 3, 4)), ("basicForce", (1,)), ("sectionForce", (4, 1)), ("sectionLocation", (4,)),
    ("nodeBounds", ()), ("getFixedNodes", ()), ("getFixedDOFs", (1,)), ("getConstrainedNodes", ()),
    ("getRetainedNodes", (3,)), ("nodeResponse", (2, 1, 1)), ("setNodeCoord", (13, 1, 2.0)),
    ("setNodeDisp", (2, 1, 0.01, "-commit")), ("domainChange", ()), ("numIter", ()),
    ("element", ("FourNodeTetrahedron", 14, 8, 5, 7, 12, 1, 0.0, 0.0, -1.0)),
    ("element", ("twoNodeLink", 15, 2, 3, "-mat", 1, 2, "-dir", 1, 5, "-pDelta", 0.2, 0.2, 0.3, 0.3, "-mass", 1.0)),
    ("element", ("twoNodeLink", 16, 3, 4, "-mat", 1, "-dir", 2, "-orient", 0.0, 0.0, 1.0, "-shearDist", 0.3, 0.6)),
]

# The 2D model of build_2d() (nodes 1-4 with ndf 3 in a frame, 5-9 with ndf 2
# on a quad and a truss): half the sequences start from it.
TEMPLATES_2D = [
    ("node", (10, 2.0, 2.0)), ("fix", (2, 1, 1, 0)), ("mass", (3, 1.0, 1.0, 0.0)), ("equalDOF", (3, 4, 1)),
    ("rigidLink", ("beam", 3, 4)), ("rigidLink", ("bar", 6, 7)),
    ("geomTransf", ("PDelta", 2)), ("geomTransf", ("Corotational", 3)),
    ("geomTransf", ("Linear", 4, "-jntOffset", 0.1, 0.0, 0.0, 0.1)),
    ("section", ("Elastic", 1, 100.0, 1.0, 1.0)), ("section", ("Elastic", 4, 100.0, 1.0, 1.0, 40.0, 0.8)),
    ("section", ("Fiber", 2)), ("patch", ("rect", 1, 4, 1, -0.2, -0.1, 0.2, 0.1)),
    ("layer", ("straight", 1, 3, 0.01, 0.15, 0.0, -0.15, 0.0)), ("fiber", (0.1, 0.0, 0.01, 1)),
    ("section", ("WFSection2d", 3, 1, 0.3, 0.01, 0.2, 0.02, 4, 2)),
    ("section", ("Aggregator", 5, 1, "Vy", "-section", 2)),
    ("beamIntegration", ("Lobatto", 1, 2, 3)),
    ("element", ("elasticBeamColumn", 2, 2, 3, 1.0, 100.0, 1.0, 1)),
    ("element", ("elasticBeamColumn", 3, 3, 4, 1.0, 100.0, 1.0, 1, "-release", 3)),
    ("element", ("forceBeamColumn", 4, 3, 4, 1, 1)), ("element", ("dispBeamColumn", 5, 2, 4, 1, 1, "-cMass")),
    ("element", ("nonlinearBeamColumn", 6, 2, 4, 3, 2, 1)),
    ("element", ("quad", 7, 5, 6, 7, 8, 1.0, "PlaneStrain", 1, 0.5, 1.0, 0.0, -1.0)),
    ("element", ("quad", 8, 5, 6, 7, 8, 0.1, "PlaneStress", 1)), ("element", ("truss", 9, 6, 9, 1.0, 1)),
    ("element", ("corotTruss", 10, 7, 9, 1.0, 1)), ("element", ("zeroLength", 11, 3, 4, "-mat", 1, 1, "-dir", 1, 3)),
    ("element", ("zeroLengthSection", 12, 3, 4, 1)),
    ("element", ("tri31", 13, 5, 6, 7, 1.0, "PlaneStress", 1, 0.1, 1.0, 0.0, -1.0)),
    ("element", ("twoNodeLink", 14, 3, 4, "-mat", 1, 1, "-dir", 2, 3, "-shearDist", 0.3, "-doRayleigh")),
    ("load", (3, 1.0, 0.0, 0.0)), ("load", (7, 0.0, -1.0)), ("sp", (6, 1, 0.01)),
    ("eleLoad", ("-ele", 1, "-type", "-beamUniform", -1.0)), ("eleLoad", ("-ele", 7, "-type", "-selfWeight", 0.0, -1.0)),
    ("block2D", (2, 2, 1, 100, "quad", 1.0, "PlaneStrain", 1, 1, 0.0, 0.0, 2, 1.0, 0.0, 3, 1.0, 1.0, 4, 0.0, 1.0)),
    ("integrator", ("DisplacementControl", 3, 1, 0.01)), ("analysis", ("Static",)), ("analyze", (2,)),
    ("eigen", (1,)), ("eleResponse", (4, "section", 1, "force")), ("eleResponse", (7, "stresses")),
    ("nodeDisp", (3,)), ("reactions", ()), ("remove", ("ele", 2)),
]

# loadPlugin would dlopen random paths; nothing else is left out.
SKIPPED_COMMANDS = ("loadPlugin",)


def sequence_rng(seed, index):
    """The random stream of sequence `index` of `seed` (independent of the others)."""
    return random.Random(seed * 1_000_000_007 + index)


def value(rng):
    r = rng.random()
    if r < 0.45:
        return rng.choice([0, 1, 2, 3, 4, 5, 6, -1, 7, 8, 100, 2**31 - 1, -2**31])
    if r < 0.75:
        return rng.choice([0.0, 1.0, -1.0, 0.5, 1e-300, 1e300, -2.5, 3.0, float("inf")])
    return rng.choice(WORDS)


def build(m):
    """The small model every sequence starts from."""
    m.model("basic", "-ndm", 3, "-ndf", 6)
    for i in range(1, 5):
        m.node(i, float(i), 0.0, 0.0)
    m.model("basic", "-ndm", 3, "-ndf", 3)
    for i in range(5, 13):
        m.node(i, float(i % 2), float((i // 2) % 2), float(i >= 9))
    m.fix(1, 1, 1, 1, 1, 1, 1)
    m.uniaxialMaterial("Elastic", 1, 100.0)
    m.nDMaterial("ElasticIsotropic", 1, 1000.0, 0.3)
    m.geomTransf("Linear", 1, 0.0, 0.0, 1.0)
    m.element("elasticBeamColumn", 1, 1, 2, 1.0, 100.0, 40.0, 1.0, 1.0, 1.0, 1)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)


def build_2d(m):
    """The small 2D model of the other sequences."""
    m.model("basic", "-ndm", 2, "-ndf", 3)
    for i, (x, y) in enumerate([(0.0, 0.0), (2.0, 0.0), (0.0, 1.0), (2.0, 1.0)], start=1):
        m.node(i, x, y)
    m.model("basic", "-ndm", 2, "-ndf", 2)
    for i, (x, y) in enumerate([(3.0, 0.0), (4.0, 0.0), (4.0, 1.0), (3.0, 1.0), (5.0, 0.5)], start=5):
        m.node(i, x, y)
    m.fix(1, 1, 1, 1)
    m.fix(5, 1, 1)
    m.uniaxialMaterial("Elastic", 1, 100.0)
    m.nDMaterial("ElasticIsotropic", 1, 1000.0, 0.3)
    m.geomTransf("Linear", 1)
    m.element("elasticBeamColumn", 1, 1, 3, 1.0, 100.0, 1.0, 1)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)


def mutate(rng, args):
    """`args` with one or two arguments replaced, dropped, added or set to a small tag."""
    args = list(args)
    for _ in range(rng.randint(1, 2)):
        r = rng.random()
        at = rng.randrange(len(args) + 1)
        if r < 0.4 and args:
            args[min(at, len(args) - 1)] = value(rng)
        elif r < 0.6 and args:
            del args[min(at, len(args) - 1)]
        elif r < 0.8:
            args.insert(at, value(rng))
        elif args:
            args[min(at, len(args) - 1)] = rng.randint(-1, 14)
    return args


def random_call(rng, commands, types, templates):
    """A command name and an argument list: a template call (often mutated) or a random one."""
    if templates and rng.random() < 0.6:
        name, args = rng.choice(templates)
        return name, (mutate(rng, args) if rng.random() < 0.5 else list(args))
    name = rng.choice(commands)
    args = []
    if types.get(name) and rng.random() < 0.8:
        args.append(rng.choice(types[name]))
    args += [value(rng) for _ in range(rng.randint(0, 14))]
    return name, args


def run(seed, sequences, calls_per_sequence, first=0, trace=None, max_findings=20):
    """Run sequences first .. first+sequences-1 of `seed`; return the counts.

    Returns a dict: sequences, calls, ok, errors (OpenSeesError), wipe_errors
    (OpenSeesError from the wipe that ends a sequence), findings (calls that
    raised anything else) and the first `max_findings` of them in detail
    (seed, sequence, call index, command, arguments, exception). With `trace`
    (a text stream), every call is written and flushed before it is made, so the
    last line names the call that crashed the process.
    """
    import beamsolid
    from beamsolid import OpenSeesError

    types = {name: beamsolid.registered_types(name) for name in TYPED_COMMANDS}
    commands = [c for c in beamsolid.command_names() if c not in SKIPPED_COMMANDS]
    templates = [t for t in TEMPLATES if t[0] in commands]
    templates_2d = [t for t in TEMPLATES_2D + TEMPLATES[-20:] if t[0] in commands]
    counts = {"seed": seed, "first": first, "sequences": 0, "calls": 0, "ok": 0, "errors": 0, "wipe_errors": 0,
              "findings": 0, "finding_details": []}
    m = beamsolid.Model()
    for index in range(first, first + sequences):
        rng = sequence_rng(seed, index)
        two_d = index % 2 == 1
        start = build_2d if two_d else build
        start(m)
        call = 0
        while call < calls_per_sequence:
            name, args = random_call(rng, commands, types, templates_2d if two_d else templates)
            if name == "wipe" and rng.random() < 0.9:
                continue  # a wipe ends the interesting state: keep it rare
            call += 1
            if trace is not None:
                trace.write(f"seed {seed} sequence {index} call {call}: {name}{tuple(args)!r}\n")
                trace.flush()
            counts["calls"] += 1
            try:
                getattr(m, name)(*args)
                counts["ok"] += 1
                if name == "wipe":
                    start(m)
            except OpenSeesError:
                counts["errors"] += 1
            except Exception as e:  # any other exception type is a defect
                counts["findings"] += 1
                if len(counts["finding_details"]) < max_findings:
                    counts["finding_details"].append(
                        {"seed": seed, "sequence": index, "call": call, "command": name, "args": repr(args),
                         "exception": f"{type(e).__name__}: {e}"})
        try:
            m.wipe()
        except OpenSeesError:
            counts["wipe_errors"] += 1  # e.g. a recorder that cannot write; the model is wiped all the same
        except Exception as e:
            counts["findings"] += 1
            if len(counts["finding_details"]) < max_findings:
                counts["finding_details"].append({"seed": seed, "sequence": index, "call": "final wipe",
                                                  "command": "wipe", "args": "[]",
                                                  "exception": f"{type(e).__name__}: {e}"})
        counts["sequences"] += 1
    return counts


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--seed", type=int, required=True)
    p.add_argument("--sequences", type=int, required=True)
    p.add_argument("--calls", type=int, required=True, help="random commands per sequence")
    p.add_argument("--first", type=int, default=0, help="index of the first sequence")
    p.add_argument("--trace", action="store_true", help="print every call to stderr before making it")
    a = p.parse_args(argv)
    # Fuzzed recorders write files named after random words: keep them out of the caller's folder.
    with tempfile.TemporaryDirectory(prefix="fuzz-") as scratch:
        here = os.getcwd()
        os.chdir(scratch)
        try:
            counts = run(a.seed, a.sequences, a.calls, first=a.first, trace=sys.stderr if a.trace else None)
        finally:
            os.chdir(here)
    print("FUZZ " + json.dumps(counts), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())

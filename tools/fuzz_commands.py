"""The command fuzzer: random command sequences against small live models.

A sequence is a fresh small model (beam and brick nodes, materials, a
transformation, a beam, a load pattern), then `calls_per_sequence` random
commands (valid type names, wrong types, wrong counts, unknown tags, huge and
negative numbers), then `wipe`. Every call must either succeed or raise
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
import random
import sys

WORDS = ["-ndf", "-mass", "-file", "/dev/null", "-time", "-node", "-ele", "-dof", "disp", "force",
         "-type", "-beamUniform", "-jntOffset", "-mat", "-dir", "-orient", "-val", "friction",
         "-material", "-stage", "-JSON", "basic", "-ndm", "Plain", "Linear", "Static", "ele", "node",
         "recorders", "sp", "mp", "-fact", "-tol", "-values", "-dt", "stresses", "localForce", ""]

# Commands whose first argument is a registered type name.
TYPED_COMMANDS = ("element", "uniaxialMaterial", "nDMaterial", "geomTransf", "timeSeries", "recorder",
                  "constraints", "numberer", "system", "test", "algorithm", "integrator")

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


def random_call(rng, commands, types):
    """A command name and a random argument list for it."""
    name = rng.choice(commands)
    args = []
    if types.get(name) and rng.random() < 0.8:
        args.append(rng.choice(types[name]))
    args += [value(rng) for _ in range(rng.randint(0, 14))]
    return name, args


def run(seed, sequences, calls_per_sequence, first=0, trace=None, max_findings=20):
    """Run sequences first .. first+sequences-1 of `seed`; return the counts.

    Returns a dict: sequences, calls, ok, errors (OpenSeesError), findings (calls
    that raised anything else) and the first `max_findings` of them in detail
    (seed, sequence, call index, command, arguments, exception). With `trace`
    (a text stream), every call is written and flushed before it is made, so the
    last line names the call that crashed the process.
    """
    import beamsolid
    from beamsolid import OpenSeesError

    types = {name: beamsolid.registered_types(name) for name in TYPED_COMMANDS}
    commands = [c for c in beamsolid.command_names() if c not in SKIPPED_COMMANDS]
    counts = {"seed": seed, "first": first, "sequences": 0, "calls": 0, "ok": 0, "errors": 0, "findings": 0,
              "finding_details": []}
    m = beamsolid.Model()
    for index in range(first, first + sequences):
        rng = sequence_rng(seed, index)
        build(m)
        call = 0
        while call < calls_per_sequence:
            name, args = random_call(rng, commands, types)
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
                    build(m)
            except OpenSeesError:
                counts["errors"] += 1
            except Exception as e:  # any other exception type is a defect
                counts["findings"] += 1
                if len(counts["finding_details"]) < max_findings:
                    counts["finding_details"].append(
                        {"seed": seed, "sequence": index, "call": call, "command": name, "args": repr(args),
                         "exception": f"{type(e).__name__}: {e}"})
        m.wipe()
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
    counts = run(a.seed, a.sequences, a.calls, first=a.first, trace=sys.stderr if a.trace else None)
    print("FUZZ " + json.dumps(counts), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())

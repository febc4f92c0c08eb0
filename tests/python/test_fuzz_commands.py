"""Nothing a script can do crashes the interpreter.

Every command is called with thousands of random argument lists (valid
prefixes, wrong types, wrong counts, unknown tags, huge and negative numbers)
against a small live model. Each call must either succeed or raise
OpenSeesError. The fuzzing runs in a subprocess so that a crash shows up as a
failed test instead of killing pytest.
"""
import subprocess
import sys
import textwrap

from conftest import subprocess_env

FUZZ = textwrap.dedent(
    r'''
    import random, sys
    import beamsolid
    from beamsolid import OpenSeesError

    rng = random.Random(int(sys.argv[1]))
    TYPES = {
        "element": beamsolid.registered_types("element"),
        "uniaxialMaterial": beamsolid.registered_types("uniaxialMaterial"),
        "nDMaterial": beamsolid.registered_types("nDMaterial"),
        "geomTransf": beamsolid.registered_types("geomTransf"),
        "timeSeries": beamsolid.registered_types("timeSeries"),
        "recorder": beamsolid.registered_types("recorder"),
        "constraints": beamsolid.registered_types("constraints"),
        "numberer": beamsolid.registered_types("numberer"),
        "system": beamsolid.registered_types("system"),
        "test": beamsolid.registered_types("test"),
        "algorithm": beamsolid.registered_types("algorithm"),
        "integrator": beamsolid.registered_types("integrator"),
    }
    WORDS = ["-ndf", "-mass", "-file", "/dev/null", "-time", "-node", "-ele", "-dof", "disp", "force",
             "-type", "-beamUniform", "-jntOffset", "-mat", "-dir", "-orient", "-val", "friction",
             "-material", "-stage", "-JSON", "basic", "-ndm", "Plain", "Linear", "Static", "ele", "node",
             "recorders", "sp", "mp", "-fact", "-tol", "-values", "-dt", "stresses", "localForce", ""]

    def value():
        r = rng.random()
        if r < 0.45:
            return rng.choice([0, 1, 2, 3, 4, 5, 6, -1, 7, 8, 100, 2**31 - 1, -2**31])
        if r < 0.75:
            return rng.choice([0.0, 1.0, -1.0, 0.5, 1e-300, 1e300, -2.5, 3.0, float("inf")])
        return rng.choice(WORDS)

    def build(m):
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

    commands = [c for c in beamsolid.command_names() if c not in ("loadPlugin",)]
    calls = ok = errors = 0
    m = beamsolid.Model()
    build(m)
    for _ in range(int(sys.argv[2])):
        name = rng.choice(commands)
        args = []
        if name in TYPES and TYPES[name] and rng.random() < 0.8:
            args.append(rng.choice(TYPES[name]))
        args += [value() for _ in range(rng.randint(0, 14))]
        if name == "wipe" and rng.random() < 0.9:
            continue
        calls += 1
        try:
            getattr(m, name)(*args)
            ok += 1
            if name == "wipe":
                build(m)
        except OpenSeesError:
            errors += 1
        except Exception as e:  # any other exception type is a defect too
            print("NOT OpenSeesError:", name, args, type(e).__name__, e)
            sys.exit(3)
    print(f"calls {calls} ok {ok} errors {errors}")
    '''
)


def test_random_commands_never_crash(tmp_path):
    script = tmp_path / "fuzz.py"
    script.write_text(FUZZ)
    env = subprocess_env()
    for seed in (1, 2, 3):
        proc = subprocess.run([sys.executable, str(script), str(seed), "3000"], cwd=tmp_path, env=env,
                              capture_output=True, text=True, timeout=300)
        assert proc.returncode == 0, f"seed {seed}: exit {proc.returncode}\n{proc.stdout[-2000:]}\n{proc.stderr[-3000:]}"
        calls = int(proc.stdout.split("calls ")[1].split()[0])
        assert calls > 2000

"""Nothing a script can do crashes the interpreter.

tools/fuzz_commands.py builds a small live model, calls random commands with
random argument lists (valid prefixes, wrong types, wrong counts, unknown tags,
huge and negative numbers) and wipes, sequence after sequence. Each call must
either succeed or raise OpenSeesError. The fuzzing runs in a subprocess so that
a crash shows up as a failed test instead of killing pytest.
benchmarks/fuzz_sanitized.py runs the same fuzzer 100,000 sequences long under
the sanitizer build.
"""
import json
import pathlib
import subprocess
import sys

from conftest import subprocess_env

FUZZER = pathlib.Path(__file__).resolve().parents[2] / "tools" / "fuzz_commands.py"


def test_random_commands_never_crash(tmp_path):
    env = subprocess_env()
    for seed in (1, 2, 3):
        proc = subprocess.run([sys.executable, str(FUZZER), "--seed", str(seed), "--sequences", "100",
                               "--calls", "30"], cwd=tmp_path, env=env, capture_output=True, text=True, timeout=300)
        assert proc.returncode == 0, f"seed {seed}: exit {proc.returncode}\n{proc.stdout[-2000:]}\n{proc.stderr[-3000:]}"
        counts = json.loads(proc.stdout.split("FUZZ ", 1)[1])
        assert counts["findings"] == 0, counts["finding_details"]
        assert counts["sequences"] == 100 and counts["calls"] == 3000
        assert counts["ok"] + counts["errors"] == counts["calls"]
        # the model and the random calls are rich enough that both outcomes occur often
        assert counts["ok"] > 300 and counts["errors"] > 300


def test_a_sequence_replays_alone(tmp_path):
    """Sequence i of a seed draws from its own stream: run alone, it makes the same calls
    as inside the longer run (so a finding's seed and sequence reproduce it)."""
    env = subprocess_env()

    def traced(*args):
        proc = subprocess.run([sys.executable, str(FUZZER), "--seed", "7", "--calls", "20", "--trace", *args],
                              cwd=tmp_path, env=env, capture_output=True, text=True, timeout=300)
        assert proc.returncode == 0, proc.stderr[-3000:]
        return [line for line in proc.stderr.splitlines() if line.startswith("seed 7 sequence 4 ")]

    together = traced("--sequences", "6")
    alone = traced("--first", "4", "--sequences", "1")
    assert len(together) == 20 and together == alone

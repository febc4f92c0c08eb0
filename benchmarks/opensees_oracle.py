"""BeamSolid against OpenSeesPy: runs every oracle script with both and
writes the comparison table to benchmarks/results/opensees_oracle.md.

    PYTHONPATH=python python benchmarks/opensees_oracle.py [--oracle PYTHON] [--out FILE]

The oracle is a Python where `import openseespy` works (BEAMSOLID_ORACLE_PYTHON,
else /work/oracle-venv/bin/python). The scripts and the comparison rules are in
tests/python/oracle_scripts; tests/python/test_opensees_oracle.py asserts the
same comparison.
"""
import argparse
import datetime
import json
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "python"))
sys.path.insert(0, os.path.join(ROOT, "tests", "python", "oracle_scripts"))
sys.path.insert(0, os.path.join(ROOT, "tests", "python"))

import compare  # noqa: E402
from oracle_scripts import SCRIPTS  # noqa: E402

KIND_TEXT = {
    "same": "same",
    "differs": "DIFFERS",
    "raises": "raises (policy)",
    "extra": "extra name",
}


def _opensees_version(python):
    probe = subprocess.run([python, "-c", "import openseespy.opensees as o; print(o.version())"],
                           capture_output=True, text=True)
    lines = [l for l in probe.stdout.splitlines() if l.strip()]
    return lines[0] if lines else "unknown"


def _cell(text):
    return str(text).replace("|", "\\|").replace("\n", " ")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--oracle", help="Python with openseespy")
    parser.add_argument("--out", default=os.path.join(ROOT, "benchmarks", "results", "opensees_oracle.md"))
    args = parser.parse_args()
    if args.oracle:
        os.environ["BEAMSOLID_ORACLE_PYTHON"] = args.oracle
    python = compare.find_oracle_python()
    if python is None:
        sys.exit("no Python with openseespy found; set BEAMSOLID_ORACLE_PYTHON or pass --oracle")

    with tempfile.TemporaryDirectory(prefix="opensees_oracle_") as workdir:
        opensees = compare.run_opensees(python, SCRIPTS, workdir)
        beamsolid = compare.run_beamsolid(SCRIPTS, workdir)

    rows, summary = [], []
    for script in SCRIPTS:
        outcomes = compare.compare_script(beamsolid[script], opensees[script])
        counts = {"same": 0, "raises": 0, "extra": 0, "known": 0, "unexpected": 0}
        for key, o in outcomes.items():
            reason = compare.known_reason(script, key) if o.kind == "differs" else None
            if o.kind == "differs":
                counts["known" if reason else "unexpected"] += 1
            else:
                counts[o.kind] += 1
            rel = "" if o.rel == 0.0 else ("inf" if o.rel == float("inf") else f"{o.rel:.1e}")
            note = o.note if not reason else f"known: {reason}. {o.note}"
            rows.append((script, key, KIND_TEXT[o.kind], rel, note))
        summary.append((script, len(outcomes), counts))

    with open(args.out, "w") as f:
        f.write("# BeamSolid against OpenSeesPy\n\n")
        f.write(f"Written by `benchmarks/opensees_oracle.py` on {datetime.date.today().isoformat()}; "
                f"oracle: OpenSeesPy {_opensees_version(python)} (`{python}`).\n\n")
        f.write("Each script of `tests/python/oracle_scripts` runs unchanged with `import beamsolid.opensees as ops` "
                "and with `import openseespy.opensees as ops`. Numbers agree when |BeamSolid - OpenSees| <= 1e-8 "
                "of the largest magnitude of the entry (1e-6 for the Penalty-handler runs); iteration norms to 1e-6 of their size (floor 1e-9 of the "
                "largest norm); integers (iteration counts, return codes, sizes) and strings exactly; recorder "
                "files line by line and token by token, numbers to the printed digits. *raises (policy)*: "
                "BeamSolid raises where OpenSeesPy returns `[]` for a response name it does not know. *extra "
                "name*: BeamSolid answers a response name OpenSeesPy does not know.\n\n")
        f.write("## Summary\n\n| script | entries | same | raises (policy) | extra name | known differences "
                "| unexpected differences |\n|---|---|---|---|---|---|---|\n")
        for script, n, c in summary:
            f.write(f"| {script} | {n} | {c['same']} | {c['raises']} | {c['extra']} | {c['known']} "
                    f"| {c['unexpected']} |\n")
        f.write("\n## Known differences\n\n| script | entries | reason |\n|---|---|---|\n")
        for (script, pattern), reason in compare.KNOWN_DIFFERENCES.items():
            f.write(f"| {script} | `{_cell(pattern)}` | {_cell(reason)} |\n")
        f.write("\n## Every compared quantity\n\n| script | entry | result | max. rel. difference | note |\n"
                "|---|---|---|---|---|\n")
        for script, key, kind, rel, note in rows:
            f.write(f"| {script} | `{_cell(key)}` | {kind} | {rel} | {_cell(note)} |\n")
    print(f"wrote {args.out}")
    for script, n, c in summary:
        print(f"{script:20s} {n:4d} entries, {c['unexpected']} unexpected differences, {c['known']} known")
    return 0


if __name__ == "__main__":
    sys.exit(main())

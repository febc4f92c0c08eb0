"""The modified IMK materials (ModIMKPeakOriented, ModIMKPinching, Bilin) against OpenSeesPy on
many cyclic histories: where (if anywhere) the two first differ, and by how much.

Run: PYTHONPATH=python .venv/bin/python benchmarks/imk_oracle_histories.py [ModIMKPinching | Bilin]
Writes benchmarks/results/<material>_oracle_histories.md. Needs the oracle interpreter
(BEAMSOLID_ORACLE_PYTHON or /work/oracle-venv/bin/python).

Histories: random step sizes up to 0.002 rad through growing turning points, either into the
capping ranges only (to 0.09) or on into the residual and past theta_u (to 0.3), with or without
jumps (5% of the steps 15 times longer), three seeds each. "No deterioration" has Lamda_C = 1e12
for the ModIMK materials (OpenSeesPy's Lamda_C = 0 collapses the spring: docs/commands.md) and
Lamda_C = 0 for Bilin. A step counts as different
when the stress differs by more than 1e-10 of the largest stress or the tangent by more than
1e-8 of K0; the last column is the largest stress difference over the history, relative to the
largest stress.
"""
import json
import os
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "tests", "python", "oracle_scripts"))
import compare  # noqa: E402

import beamsolid  # noqa: E402

_ORACLE = r"""
import json, sys
import openseespy.opensees as ops
out = []
for args, path in json.load(sys.stdin):
    ops.wipe()
    ops.uniaxialMaterial(*args)
    ops.testUniaxialMaterial(1)
    rows = []
    for e in path:
        ops.setStrain(e)
        rows.append([ops.getStress(), ops.getTangent()])
    out.append(rows)
sys.stdout.write('RESULT' + json.dumps(out))
"""

SIDE = (1000.0, 0.02, 0.03, 10.0, -8.0)
PINCH = (0.3, 0.4, 0.6)  # FprPos, FprNeg, A_pinch
GEO = (0.03, 0.04, 0.1, 0.12, 0.3, 0.25, 0.2, 0.25)
DETERIORATION = {
    "none": (0, 1e12, 0, 0, 1, 1, 1, 1),
    "LS=2": (2, 1e12, 0, 0, 1, 1, 1, 1),
    "LC=2": (0, 2, 0, 0, 1, 1, 1, 1),
    "LK=2": (0, 1e12, 0, 2, 1, 1, 1, 1),
    "LS, LC, LK, c, D": (3, 2.5, 0, 4, 1.2, 0.9, 1, 1.1),
    "LA=2": (0, 1e12, 2, 0, 1, 1, 1, 1),
    "LA=0.5": (0, 1e12, 0.5, 0, 1, 1, 1, 1),
}
D = {"LS, LC, LK, c, D": (0.7, 0.9)}
# Bilin takes Lamda_C = 0 as "no post-capping deterioration" (OpenSees' ModIMK materials do not),
# and an nFactor after the D factors.
BILIN = {
    "none": (0, 0, 0, 0, 1, 1, 1, 1),
    "LS=2": (2, 0, 0, 0, 1, 1, 1, 1),
    "LC=2": (0, 2, 0, 0, 1, 1, 1, 1),
    "LK=2": (0, 0, 0, 2, 1, 1, 1, 1),
    "all, D, n=3": (3, 2.5, 1, 4, 1.2, 0.9, 1, 1.1),
}
BILIN_EXTRA = {"all, D, n=3": (0.7, 0.9, 3.0)}
TO_CAP = [0.02, -0.015, 0.035, 0.01, 0.05, -0.03, -0.06, 0.0, 0.07, -0.02, 0.08, -0.09, 0.03]
TO_RESIDUAL = [0.02, -0.03, 0.05, -0.01, 0.03, -0.07, 0.06, -0.09, 0.12, -0.13, 0.15, -0.2, 0.3]


def history(amplitudes, rng, jumps):
    path, current = [], 0.0
    for target in amplitudes:
        while abs(target - current) > 1e-15:
            size = 0.002 * (0.2 + 0.8 * rng.random())
            if jumps and rng.random() < 0.05:
                size *= 15.0
            current = target if abs(target - current) <= size else current + np.sign(target - current) * size
            path.append(float(current))
    return path


def parameter_sets(material):
    return BILIN if material == "Bilin" else DETERIORATION


def material_args(material, name):
    if material == "Bilin":
        return [material, 1, *SIDE, *BILIN[name], *GEO, *BILIN_EXTRA.get(name, (1.0, 1.0))]
    pinch = PINCH if material == "ModIMKPinching" else ()
    return [material, 1, *SIDE, *pinch, *DETERIORATION[name], *GEO, *D.get(name, (1.0, 1.0))]


def beamsolid_run(args, path):
    m = beamsolid.Model()
    m.uniaxialMaterial(*args)
    m.testUniaxialMaterial(1)
    rows = []
    for e in path:
        m.setStrain(e)
        rows.append((m.getStress(), m.getTangent()))
    return np.array(rows)


def main():
    material = sys.argv[1] if len(sys.argv) > 1 else "ModIMKPeakOriented"
    oracle = compare.find_oracle_python()
    if oracle is None:
        sys.exit("no Python with openseespy (set BEAMSOLID_ORACLE_PYTHON)")
    runs = []
    for name in parameter_sets(material):
        for amps_name, amps in (("to the cap", TO_CAP), ("into the residual", TO_RESIDUAL)):
            for jumps in (False, True):
                for seed in (1, 2, 3):
                    runs.append((name, amps_name, jumps, seed, material_args(material, name),
                                 history(amps, np.random.default_rng(seed), jumps)))
    spec = [[args, path] for *_, args, path in runs]
    r = subprocess.run([oracle, "-c", _ORACLE], input=json.dumps(spec), capture_output=True, text=True,
                       timeout=1200, env=compare.oracle_env())
    results = json.loads(r.stdout.split("RESULT", 1)[1])
    lines = ["| parameters | history | jumps | seed | steps | first differing step | strain | "
             "stress OpenSees / BeamSolid | tangent OpenSees / BeamSolid | max stress difference |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    same, worst = 0, {}
    for (name, amps_name, jumps, seed, args, path), theirs in zip(runs, results):
        theirs = np.array(theirs)
        ours = beamsolid_run(args, path)
        scale = np.max(np.abs(theirs[:, 0]))
        diff = np.abs(ours[:, 0] - theirs[:, 0])
        worst[name] = max(worst.get(name, 0.0), diff.max() / scale)
        bad = (diff > 1e-10 * scale) | (np.abs(ours[:, 1] - theirs[:, 1]) > 1e-8 * SIDE[0])
        head = f"| {name} | {amps_name} | {'yes' if jumps else 'no'} | {seed} | {len(path)} |"
        if not bad.any():
            same += 1
            lines.append(f"{head} none | | | | {diff.max() / scale:.1e} |")
            continue
        i = int(np.argmax(bad))
        lines.append(f"{head} {i} | {path[i]:.6g} | {theirs[i, 0]:.12g} / {ours[i, 0]:.12g} | "
                     f"{theirs[i, 1]:.10g} / {ours[i, 1]:.10g} | {diff.max() / scale:.1e} |")
    summary = "\n".join(f"- {name}: largest stress difference {w:.1e} of the largest stress" for name, w in worst.items())
    text = (f"# {material} against OpenSeesPy 3.7.1: {same} of {len(runs)} histories identical\n\n"
            f"Generated by benchmarks/imk_oracle_histories.py.\n\n{summary}\n\n" + "\n".join(lines) + "\n")
    out = os.path.join(HERE, "results", f"{material.lower()}_oracle_histories.md")
    with open(out, "w") as f:
        f.write(text)
    print(text)


if __name__ == "__main__":
    main()

"""PySimple1, TzSimple1 and QzSimple1 against OpenSeesPy 3.7.1, point by point.

Each material is driven through the same strain history in OpenSeesPy (run in a
subprocess with the oracle interpreter, see test_uniaxial_oracle.py) and in
BeamSolid, through testUniaxialMaterial / setStrain(strain, <rate>) (one committed
step per strain) / getStress / getTangent. Histories:

* 'cycles': +3, -1, +5, -5, +2, -6, +6, 0 y50 in steps of y50/10: the rigid range
  moves, the gap opens behind the pile and closes again (memory terms y0+, y0-),
  the drag mobilises in the open gap;
* 'jumps': cycles to +-10 y50 in random steps of up to y50/5, one step in twenty
  fifteen times longer (up to 3 y50 in one step);
* 'dashpot': cycles to +-4 y50 with a random strain rate at every step (c = 25).
q-z histories are the same with the sign turned (bearing first).

Tolerances: stress within 1e-9 of the largest |stress| of the history (measured:
2e-12 p-y and t-z, 1e-10 q-z), tangent within 1e-8 of the largest tangent
(measured 4e-12).

Not compared (docs/pile_springs.md, "Where OpenSees differs"): histories where
OpenSees' internal iteration does not converge -- a single step across a reversal
longer than about y50, or several y50 into the range where the near-field
tangent is below 1% of pult / y50 (OpenSees then returns up to 4 % different forces,
or pult itself); the soil-type 2 p-y spring with Cd = 0 on the 'jumps' history (a
3 y50 step through the gap-memory update leaves OpenSees 6e-3 pult off); and the
q-z tangent in an open gap without suction after a long uplift step (OpenSees
reports the drag floor 1e-4 qult / z50 there although there is no drag).

The module is skipped when the oracle interpreter or openseespy is missing.
"""
import json
import os
import subprocess
import sys

import numpy as np
import pytest

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "oracle_scripts"))
import compare  # noqa: E402

ORACLE = compare.find_oracle_python()
if ORACLE is None:
    pytest.skip("no Python with openseespy (set BEAMSOLID_ORACLE_PYTHON)", allow_module_level=True)

import beamsolid  # noqa: E402

_ORACLE_SCRIPT = r"""
import json, sys
import openseespy.opensees as ops
out = []
for mat, steps in json.load(sys.stdin):
    ops.wipe()
    ops.uniaxialMaterial(*mat)
    ops.testUniaxialMaterial(mat[1])
    rows = []
    for s in steps:
        ops.setStrain(*s)
        rows.append([ops.getStress(), ops.getTangent()])
    out.append(rows)
sys.stdout.write("RESULT" + json.dumps(out))
"""

Y50 = 0.01


def _steps_to(points, h):
    path, current = [], 0.0
    for target in points:
        n = int(round(abs(target - current) / h))
        path += list(np.linspace(current, target, n + 1)[1:])
        current = target
    return [float(y) for y in path]


def _jumps(points, increment, rng):
    path, current = [], 0.0
    for target in points:
        while abs(target - current) > 1e-15:
            size = increment * (0.2 + 0.8 * rng.random())
            if rng.random() < 0.05:
                size *= 15.0
            current = target if abs(target - current) <= size else current + np.sign(target - current) * size
            path.append(float(current))
    return path


def _histories():
    rng = np.random.default_rng(3)
    cycles = _steps_to([x * Y50 for x in (3, -1, 5, -5, 2, -6, 6, 0)], 0.1 * Y50)
    jumps = _jumps([x * Y50 for x in (2, -1, 6, -4, 8, -8, 3, -10, 10, 0)], 0.2 * Y50, rng)
    dash = _steps_to([x * Y50 for x in (2, -1, 4, -4, 1, 0)], 0.1 * Y50)
    rates = np.random.default_rng(11).normal(0.0, 0.5, len(dash))
    return {"cycles": [[y] for y in cycles], "jumps": [[y] for y in jumps],
            "dashpot": [[y, float(r)] for y, r in zip(dash, rates)]}


def _cases():
    h = _histories()
    flip = {name: [[-v for v in s] for s in steps] for name, steps in h.items()}
    cases = {}
    for name, steps in h.items():
        c = 25.0 if name == "dashpot" else 0.0
        for soil in (1, 2):
            for Cd in (0.0, 0.3, 1.0):
                if name == "jumps" and soil == 2 and Cd == 0.0:
                    continue  # OpenSees does not converge through the memory update (module docstring)
                cases[f"py{soil}-Cd{Cd}-{name}"] = (("PySimple1", 1, soil, 100.0, Y50, Cd, c), steps, True)
            cases[f"tz{soil}-{name}"] = (("TzSimple1", 1, soil, 35.0, Y50, c), steps, True)
            for suction in (0.0, 0.1):
                tangent = not (name == "jumps" and suction == 0.0)  # module docstring
                cases[f"qz{soil}-s{suction}-{name}"] = (("QzSimple1", 1, soil, 800.0, Y50, suction, c), flip[name],
                                                        tangent)
    return cases


CASES = _cases()


@pytest.fixture(scope="module")
def oracle_results():
    spec = [[list(mat), steps] for mat, steps, _ in CASES.values()]
    r = subprocess.run([ORACLE, "-c", _ORACLE_SCRIPT], input=json.dumps(spec), capture_output=True, text=True,
                       timeout=600, env=compare.oracle_env())
    assert r.returncode == 0, r.stderr[-2000:]
    return dict(zip(CASES, json.loads(r.stdout.split("RESULT", 1)[1])))


def _beamsolid(mat, steps):
    m = beamsolid.Model()
    m.uniaxialMaterial(*mat)
    m.testUniaxialMaterial(mat[1])
    rows = []
    for s in steps:
        m.setStrain(*s)
        rows.append((m.getStress(), m.getTangent()))
    return np.array(rows)


@pytest.mark.parametrize("name", list(CASES))
def test_soil_spring_matches_opensees(name, oracle_results):
    mat, steps, compare_tangent = CASES[name]
    ours, theirs = _beamsolid(mat, steps), np.array(oracle_results[name])
    assert ours.shape == theirs.shape
    stress_err = np.abs(ours[:, 0] - theirs[:, 0]) / np.max(np.abs(theirs[:, 0]))
    worst = int(np.argmax(stress_err))
    assert stress_err.max() <= 1e-9, (f"{name}: stress differs by {stress_err.max():.2e} of the largest at step "
                                      f"{worst} (strain {steps[worst]}): {ours[worst, 0]!r} vs {theirs[worst, 0]!r}")
    if compare_tangent:
        tangent_err = np.abs(ours[:, 1] - theirs[:, 1]) / np.max(np.abs(theirs[:, 1]))
        worst = int(np.argmax(tangent_err))
        assert tangent_err.max() <= 1e-8, (f"{name}: tangent differs by {tangent_err.max():.2e} at step {worst}: "
                                           f"{ours[worst, 1]!r} vs {theirs[worst, 1]!r}")
    # The history reaches the plastic range: the stress passes half the capacity.
    assert np.max(np.abs(theirs[:, 0])) > 0.5 * mat[3]


def test_large_reversal_step_is_solved_exactly():
    """One step of 1.5 y50 across a reversal: BeamSolid gives what two half
    steps give (the series solved exactly); OpenSeesPy 3.7.1's one step is 4 %
    off its own two-step answer (-44.748 against -43.135, soil type 1)."""
    one = _beamsolid(("PySimple1", 1, 1, 100.0, Y50, 0.0), [[Y50], [-0.5 * Y50]])[-1, 0]
    two = _beamsolid(("PySimple1", 1, 1, 100.0, Y50, 0.0), [[Y50], [0.25 * Y50], [-0.5 * Y50]])[-1, 0]
    assert one == pytest.approx(two, rel=1e-13)
    r = subprocess.run([ORACLE, "-c", _ORACLE_SCRIPT], capture_output=True, text=True, timeout=120,
                       env=compare.oracle_env(),
                       input=json.dumps([[["PySimple1", 1, 1, 100.0, Y50, 0.0], [[Y50], [0.25 * Y50], [-0.5 * Y50]]],
                                         [["PySimple1", 1, 1, 100.0, Y50, 0.0], [[Y50], [-0.5 * Y50]]]]))
    theirs_two, theirs_one = json.loads(r.stdout.split("RESULT", 1)[1])
    assert two == pytest.approx(theirs_two[-1][0], rel=1e-12)
    assert abs(theirs_one[-1][0] - two) > 0.03 * abs(two)

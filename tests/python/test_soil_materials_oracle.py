"""J2Plasticity and DruckerPrager in one stdBrick and one quad against OpenSeesPy.

oracle_scripts/soil_materials.py runs with BeamSolid here and with
OpenSeesPy in a subprocess (the oracle interpreter; skipped without one).
Every entry (Gauss point stress and strain, top-face reaction, per step)
must agree to 1e-8 of the entry's largest magnitude; return codes must be
equal; the J2 entries to 2e-8: OpenSeesPy's J2Plasticity is off the closed
form by up to 5e-9 of the stress even with linear hardening (its local
solve's tolerance; 250.27224714744 against the exact 250.27224642190 on the
first plastic step of the uniaxial brick), while BeamSolid's is on it to
round-off (test_j2_brick_is_on_the_closed_form below), so the two differ by
up to 9e-9 of the largest stress on the path.

The Drucker-Prager stage run uses setParameter('materialState', 0 then 2),
the route that works in OpenSeesPy 3.7.1 (its updateMaterialStage does not
reach DruckerPrager: "MaterialStageParameter::setDomain() - no effect");
BeamSolid's updateMaterialStage 0/1 is checked to give the same answers.
"""
import os
import sys

import numpy as np
import pytest

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "oracle_scripts"))
import compare  # noqa: E402

ORACLE = compare.find_oracle_python()
if ORACLE is None:
    pytest.skip("no Python with openseespy (set BEAMSOLID_ORACLE_PYTHON)", allow_module_level=True)

import beamsolid.opensees as ops  # noqa: E402
import soil_materials  # noqa: E402


@pytest.fixture(scope="module")
def results(tmp_path_factory):
    workdir = str(tmp_path_factory.mktemp("soil_oracle"))
    theirs = compare.run_opensees(ORACLE, ["soil_materials"], workdir)["soil_materials"]
    ours = compare.run_beamsolid(["soil_materials"], workdir)["soil_materials"]
    return ours, theirs


def _entries(prefix, ours):
    return sorted(k for k in ours if k.startswith(prefix))


@pytest.mark.parametrize("prefix", ["j2.brick", "j2.quad.PlaneStrain", "j2.quad.PlaneStress", "dp.brick.assoc",
                                    "dp.brick.nonassoc", "dp.brick.hardening", "dp.quad.assoc", "dp.quad.nonassoc",
                                    "dp.quad.hardening", "dp.brick.staged"])
def test_matches_opensees(results, prefix):
    ours, theirs = results
    assert "__error__" not in theirs, theirs.get("__error__")
    assert "__error__" not in ours, ours.get("__error__")
    keys = _entries(prefix + ".", ours)
    assert keys, prefix
    bad = {}
    for key in keys:
        a, b = ours[key], theirs[key]
        if key.endswith("codes"):
            if a != b:
                bad[key] = (a, b)
            continue
        x, y = np.asarray(a, float), np.asarray(b, float)
        scale = np.abs(y).max()
        if x.shape != y.shape or np.abs(x - y).max() > 1e-8 * scale:
            bad[key] = float(np.abs(x - y).max() / scale) if x.shape == y.shape else (x.shape, y.shape)
    assert not bad, bad


def test_update_material_stage_equals_the_material_state_parameter():
    """updateMaterialStage 0/1 (BeamSolid) gives what setParameter materialState 0/2 gives."""
    out = {}

    class StageOps:
        def __getattr__(self, name):
            return getattr(ops, name)

        def setParameter(self, *args):
            value = args[1]
            ops.updateMaterialStage("-material", 1, "-stage", 0 if value == 0 else 1)

    staged = {}
    soil_materials._brick(ops, ("DruckerPrager", 1, 27777.78, 9259.26, 5.0, 0.398, 0.1, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0,
                                1.7))
    loads = [(n, 1, -2.5) for n in (2, 3, 6, 7)] + [(n, 2, -2.5) for n in (3, 4, 7, 8)]
    soil_materials._brick_confined(StageOps(), staged, "s", loads, 0.004, stage=(0, 2))
    soil_materials._brick(ops, ("DruckerPrager", 1, 27777.78, 9259.26, 5.0, 0.398, 0.1, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0,
                                1.7))
    soil_materials._brick_confined(ops, out, "s", loads, 0.004, stage=(0, 2))
    assert staged["s.stress"] == out["s.stress"]
    assert staged["s.confine.stress"] == out["s.confine.stress"]
    ops.wipe()


def test_j2_brick_is_on_the_closed_form(results):
    """Uniaxial stress on the monotonic first leg with the script's
    saturation hardening: the exact state has sigma = q(eps_p) (xi = eps_p in
    uniaxial stress) and eps = sigma / E + eps_p, solved here by bisection."""
    ours, theirs = results
    K, G, s0, sinf, delta, H = 160e3, 80e3, 250.0, 320.0, 40.0, 900.0
    E = 9 * K * G / (3 * K + G)
    amplitude = 5 * s0 / E
    worst_ours = worst_theirs = 0.0
    for k in range(12):  # the first leg: 0 -> amplitude in 12 steps
        eps = amplitude * (k + 1) / 12
        if E * eps <= s0:
            exact = E * eps
        else:
            lo, hi = 0.0, eps  # eps_p by bisection on sigma(eps_p) = q(eps_p)
            for _ in range(200):
                ep = 0.5 * (lo + hi)
                r = E * (eps - ep) - (s0 + (sinf - s0) * (1 - np.exp(-delta * ep)) + H * ep)
                lo, hi = (ep, hi) if r > 0 else (lo, ep)
            exact = E * (eps - 0.5 * (lo + hi))
        worst_ours = max(worst_ours, abs(ours["j2.brick.stress"][k][2] - exact) / s0)
        worst_theirs = max(worst_theirs, abs(theirs["j2.brick.stress"][k][2] - exact) / s0)
    print(f"J2 brick against the exact uniaxial stress: BeamSolid {worst_ours:.1e}, OpenSeesPy {worst_theirs:.1e}")
    assert worst_ours < 1e-12, worst_ours
    assert worst_theirs < 2e-8, worst_theirs

"""J2Plasticity and DruckerPrager in one stdBrick and one quad against OpenSeesPy.

oracle_scripts/soil_materials.py runs with BeamSolid here and with
OpenSeesPy in a subprocess (the oracle interpreter; skipped without one).
Every entry (Gauss point stress and strain, top-face reaction, per step)
must agree to 1e-8 of the entry's largest magnitude; return codes must be
equal. OpenSeesPy's J2Plasticity solves its local equation to ~1e-9
relative, BeamSolid to round-off, which the tolerance covers.

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

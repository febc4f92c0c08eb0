"""BeamSolid against OpenSeesPy, run as an independent oracle.

Every script in tests/python/oracle_scripts runs twice: with
``beamsolid.opensees`` in this process and with ``openseespy.opensees`` in a
subprocess (the Python named by BEAMSOLID_ORACLE_PYTHON, else
/work/oracle-venv/bin/python). The module is skipped when no such Python
exists.

Tolerances (see oracle_scripts/compare.py): numbers 1e-8 relative to the
largest magnitude of the entry (linear answers and nonlinear answers
converged to 1e-12), 1e-6 for the Penalty-handler runs (alpha 1e12, converged
to 1e-9); iteration norms 1e-6 of their own size down to 1e-9 of the largest
norm; iteration counts, return codes and sizes equal; recorder
files with the same lines, delimiters and tokens, numbers equal to the
printed digits (2e-5 of the line's largest value).

Two documented policies are not failures: BeamSolid raises where OpenSeesPy
returns [] for a response name it does not know, and BeamSolid answers some
names OpenSeesPy does not know (aliases). Differences that remain on purpose
are listed in KNOWN_DIFFERENCES with the reason; an entry that starts to
agree fails the test so that the list stays true.
"""
import fnmatch
import os
import sys

import pytest

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "oracle_scripts"))

import compare  # noqa: E402
from oracle_scripts import SCRIPTS  # noqa: E402

ORACLE_PYTHON = compare.find_oracle_python()
if ORACLE_PYTHON is None:
    pytest.skip("no Python with openseespy (set BEAMSOLID_ORACLE_PYTHON)", allow_module_level=True)

KNOWN_DIFFERENCES = compare.KNOWN_DIFFERENCES
_known = compare.known_reason


@pytest.fixture(scope="module")
def results(tmp_path_factory):
    workdir = str(tmp_path_factory.mktemp("oracle"))
    opensees = compare.run_opensees(ORACLE_PYTHON, SCRIPTS, workdir)
    beamsolid = compare.run_beamsolid(SCRIPTS, workdir)
    return beamsolid, opensees


@pytest.mark.parametrize("script", SCRIPTS)
def test_script_matches_opensees(results, script):
    beamsolid, opensees = results
    assert "__error__" not in opensees[script], "the OpenSeesPy run failed:\n" + opensees[script]["__error__"]
    assert "__error__" not in beamsolid[script], "the BeamSolid run failed:\n" + beamsolid[script]["__error__"]
    outcomes = compare.compare_script(beamsolid[script], opensees[script])
    unexpected = {k: o.note for k, o in outcomes.items() if o.kind == "differs" and not _known(script, k)}
    assert not unexpected, "differences from OpenSeesPy:\n" + "\n".join(f"  {k}: {n}" for k, n in unexpected.items())
    # Every known difference must still be there (and match some entry).
    for (s, pattern), reason in KNOWN_DIFFERENCES.items():
        if s != script:
            continue
        matching = [k for k in outcomes if fnmatch.fnmatchcase(k, pattern)]
        assert matching, f"KNOWN_DIFFERENCES entry {pattern!r} matches no result of {script}"
        assert any(outcomes[k].kind == "differs" for k in matching), (
            f"{script} {pattern!r} now agrees with OpenSeesPy; remove it from KNOWN_DIFFERENCES ({reason})")


def test_comparison_detects_differences():
    """The comparison itself: noise against the entry's scale passes, a real
    difference, a size change or a different integer fails."""
    assert compare.compare_values("x", [1.0, 1e-13], [1.0, 0.0]).ok
    assert not compare.compare_values("x", [1.0, 1e-6], [1.0, 0.0]).ok
    assert not compare.compare_values("x", [1.0, 2.0], [1.0, 2.0, 0.0]).ok
    assert not compare.compare_values("testIter", [2, 3], [2, 2]).ok
    assert not compare.compare_values("x", 1, 1.0).ok
    text = "0.1 1e-05 -3\n0.2 2e-05 -6\n"
    assert compare.compare_values("file:a.out", text, text).ok
    assert not compare.compare_values("file:a.out", text.replace("\n", " \n"), text).ok
    assert not compare.compare_values("file:a.out", text.replace("-6", "-6.1"), text).ok
    assert not compare.compare_values("file:a.out", text + "0.3 3e-05 -9\n", text).ok
    assert compare.compare_values("x", "error", "[]").kind == "raises"
    assert compare.compare_values("x", [1.0], "[]").kind == "extra"

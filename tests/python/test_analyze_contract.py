"""analyze keeps OpenSees' contract: a negative code, never an exception, once it runs.

Scripts written for OpenSees try an analysis and, when analyze returns a negative
code, change the system, the algorithm or the step and try again. So whatever happens
while analyze runs (no convergence, a singular matrix, a system that cannot take the
model, an element that throws) must return -1/-2/-3, leave the model at its last
converged state and keep the reason (beamsolid.last_error()). Bad arguments of analyze
itself still raise at the call.

Answers are checked against closed forms: a 2D cantilever's tip under P (PL^3/3EI,
PL^2/2EI) for every system name OpenSeesPy's examples use, and a bar's force-displacement
for the retry idioms.
"""
import re

import pytest

import beamsolid

# Every system name of OpenSeesPy's examples and manual (SparseSYM and SparseSPD crash
# OpenSeesPy 3.7.1 itself with "free(): invalid pointer"; here they are CHOLMOD).
SYSTEMS = ("BandGen", "BandGEN", "BandGeneral", "BandSPD", "ProfileSPD", "SProfileSPD", "ParallelProfileSPD",
           "SparseGeneral", "SparseGEN", "SparseSYM", "SparseSPD", "FullGeneral", "UmfPack", "Umfpack", "Mumps",
           "SuperLU", "Cholmod", "Diagonal", "MPIDiagonal")

E, A, I, L, P = 200e6, 0.01, 8e-5, 3.0, 10.0


def cantilever_2d(m):
    m.model("basic", "-ndm", 2, "-ndf", 3)
    m.node(1, 0.0, 0.0)
    m.node(2, 0.0, L)
    m.fix(1, 1, 1, 1)
    m.geomTransf("Linear", 1)
    m.element("elasticBeamColumn", 1, 1, 2, A, E, I, 1)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.load(2, P, 0.0, 0.0)


def static(m, system="UmfPack", algorithm=("Newton",), test=("NormDispIncr", 1e-12, 10), dlam=1.0):
    m.constraints("Plain")
    m.numberer("RCM")
    m.system(system)
    m.test(*test)
    m.algorithm(*algorithm)
    m.integrator("LoadControl", dlam)
    m.analysis("Static")


@pytest.mark.parametrize("system", SYSTEMS)
def test_every_system_name_solves_the_cantilever(system):
    m = beamsolid.Model()
    cantilever_2d(m)
    static(m, system, ("Linear",))
    assert m.analyze(1) == 0
    assert m.last_error() == ""
    ux, uy, rz = m.nodeDisp(2)
    # Tip of a cantilever under a transverse end load P (local y = -global x here: the
    # column runs along global y, so P along x bends it): PL^3/3EI and PL^2/2EI, axial 0.
    assert ux == pytest.approx(P * L**3 / (3 * E * I), rel=1e-12)
    assert rz == pytest.approx(-P * L**2 / (2 * E * I), rel=1e-12)
    assert abs(uy) <= 1e-15


def test_system_options_of_other_solvers_are_read_and_ignored():
    m = beamsolid.Model()
    cantilever_2d(m)
    m.system("Mumps", "-ICNTL14", 20)
    m.system("BandGeneral", "-piv")
    m.system("UmfPack", "-lvalueFact", 10)
    m.analysis("Static")
    assert m.analyze(1) == 0
    assert m.nodeDisp(2, 1) == pytest.approx(P * L**3 / (3 * E * I), rel=1e-10)


def contact_model(m):
    """A fixed pile segment and a soil node pressed onto it through BeamContact3D: the
    Lagrange multipliers make the system indefinite, so SPD-only systems cannot take it."""
    m.model("basic", "-ndm", 3, "-ndf", 6)
    m.node(1, 0.0, 0.0, 0.0)
    m.node(2, 0.0, 0.0, 2.0)
    for n in (1, 2):
        m.fix(n, 1, 1, 1, 1, 1, 1)
    m.geomTransf("Linear", 1, 1.0, 0.0, 0.0)
    m.element("elasticBeamColumn", 10, 1, 2, 0.28, 3e7, 1.2e7, 0.0127, 0.0064, 0.0064, 1)
    m.model("basic", "-ndm", 3, "-ndf", 3)
    m.node(3, 0.3, 0.0, 1.0)
    m.node(4, 0.3, 0.0, 1.0)
    m.node(8, 0.3, 0.0, 1.0)
    m.fix(8, 1, 1, 1)
    m.uniaxialMaterial("Elastic", 3, 1.0)
    m.element("zeroLength", 30, 3, 8, "-mat", 3, 3, 3, "-dir", 1, 2, 3)
    m.nDMaterial("ContactMaterial3D", 1, 0.3, 1e5, 0.0, 0.0)
    m.element("BeamContact3D", 21, 1, 2, 3, 4, 0.3, 1, 1, 1e-8, 1e-8)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.load(3, -10.0, 0.0, 0.0)


def test_a_script_looping_over_systems_moves_on_when_one_fails(capfd):
    """The idiom of the issue: try systems in turn until analyze returns 0."""
    m = beamsolid.Model()
    contact_model(m)
    tried = {}
    for system in ("SparseSYM", "BandSPD", "ProfileSPD", "UmfPack"):
        static(m, system, test=("NormUnbalance", 1e-8, 10))
        tried[system] = m.analyze(1)
        if tried[system] == 0:
            break
        # Nothing moved: the failed attempt left the model where it was.
        assert m.getTime() == 0.0
        assert m.nodeDisp(3) == [0.0, 0.0, 0.0]
    assert tried == {"SparseSYM": -1, "BandSPD": -1, "ProfileSPD": -1, "UmfPack": 0}
    assert m.last_error() == ""
    # The soil node is pressed onto the pile: the contact carries the 10 kN (the soft
    # k = 1 spring takes its 1e-5 share of the compliance).
    assert m.eleResponse(21, "forcescalar")[0] == pytest.approx(10.0, rel=1e-5)
    err = capfd.readouterr().err
    assert err.count("WARNING analyze:") == 3
    assert "system SparseSYM" in err and "UmfPack" in err


def test_the_reason_is_kept_for_last_error():
    m = beamsolid.Model()
    contact_model(m)
    static(m, "SparseSYM")
    assert m.analyze(1) == -1
    reason = m.last_error()
    assert "could not be set up" in reason
    assert "system SparseSYM" in reason and "element BeamContact3D 21" in reason and "UmfPack" in reason


def test_module_level_last_error_follows_the_opensees_commands():
    from beamsolid import opensees as ops

    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    ops.node(1, 0.0, 0.0)
    ops.node(2, 0.0, L)
    ops.geomTransf("Linear", 1)
    ops.element("elasticBeamColumn", 1, 1, 2, A, E, I, 1)  # no supports: a mechanism
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, P, 0.0, 0.0)
    ops.analysis("Static")
    assert ops.analyze(1) == -3
    assert re.search(r"singular", beamsolid.last_error())
    ops.fix(1, 1, 1, 1)
    assert ops.analyze(1) == 0
    assert beamsolid.last_error() == ""
    ops.wipe()


def test_a_singular_model_returns_minus_3_and_keeps_the_recorded_data(tmp_path):
    m = beamsolid.Model()
    m.model("basic", "-ndm", 2, "-ndf", 2)
    m.node(1, 0.0, 0.0)
    m.node(2, 2.0, 0.0)
    m.fix(1, 1, 1)
    m.uniaxialMaterial("Elastic", 1, 100.0)
    m.element("Truss", 1, 1, 2, 1.0, 1)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.load(2, 5.0, 0.0)
    out = tmp_path / "disp.out"
    m.recorder("Node", "-file", str(out), "-time", "-node", 2, "-dof", 1, "disp")
    static(m)
    # Node 2 has no stiffness across the bar: singular before any step converged.
    assert m.analyze(1) == -3
    assert "singular before any step converged" in m.last_error()
    assert m.getTime() == 0.0
    m.fix(2, 0, 1)
    assert m.analyze(2) == 0
    m.close()
    rows = [list(map(float, line.split())) for line in out.read_text().splitlines()]
    # u = F L / (E A) at each of the two load steps.
    assert rows == [[1.0, pytest.approx(0.1, rel=1e-12)], [2.0, pytest.approx(0.2, rel=1e-12)]]


def hardening_bar(m):
    """A bar of Steel01 (E 1000, fy 10, b 0.01) pulled by a load past yield."""
    m.model("basic", "-ndm", 1, "-ndf", 1)
    m.node(1, 0.0)
    m.node(2, 1.0)
    m.fix(1, 1)
    m.uniaxialMaterial("Steel01", 1, 10.0, 1000.0, 0.01)
    m.element("Truss", 1, 1, 2, 1.0, 1)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.load(2, 12.0)


def test_switching_the_algorithm_after_a_failure_completes_the_step():
    """ModifiedNewton on the initial stiffness (1000) crawls along the yield plateau
    (10) and fails in 5 iterations; Newton then converges from the same committed state."""
    m = beamsolid.Model()
    hardening_bar(m)
    static(m, algorithm=("ModifiedNewton", "-initial"), test=("NormDispIncr", 1e-10, 5))
    assert m.analyze(1) == -3
    assert "ModifiedNewton" in m.last_error() or "did not converge" in m.last_error()
    assert m.getTime() == 0.0 and m.nodeDisp(2, 1) == 0.0
    m.algorithm("Newton")
    assert m.analyze(1) == 0
    # Past yield: u = fy/E + (F - fy)/(b E) = 0.01 + 2/10 = 0.21.
    assert m.nodeDisp(2, 1) == pytest.approx(0.21, rel=1e-12)


def test_halving_the_step_after_a_failure_converges():
    """The other idiom: a step too big for the iteration budget fails; the script halves
    it until it passes, then lets it grow again, and steps on to the full load.
    ModifiedNewton keeps the tangent of the step's start, so the step that crosses yield
    (stiffness 1000 -> 10) converges only once its overshoot past yield is small."""
    m = beamsolid.Model()
    hardening_bar(m)
    static(m, algorithm=("ModifiedNewton",), test=("NormDispIncr", 1e-8, 3))
    done, dlam, failures, attempts = 0.0, 0.25, 0, 0
    while done < 1.0 - 1e-12 and attempts < 200:
        attempts += 1
        m.integrator("LoadControl", min(dlam, 1.0 - done))
        if m.analyze(1) == 0:
            assert m.last_error() == ""
            done = m.getTime()
            dlam *= 2.0
        else:
            failures += 1
            assert m.getTime() == done  # back at the last converged step
            dlam /= 2.0
    assert failures > 0
    assert done == pytest.approx(1.0, abs=1e-12)
    # u = fy/E + (F - fy)/(b E) = 0.21, within the 1e-8 displacement tolerance.
    assert m.nodeDisp(2, 1) == pytest.approx(0.21, abs=1e-7)


@pytest.mark.parametrize("args, message", [
    (("one",), r"analyze.*numIncr"),
    ((-1,), r"analyze.*non-negative"),
    ((), r"analyze.*numIncr"),
])
def test_bad_arguments_of_analyze_still_raise(args, message):
    m = beamsolid.Model()
    cantilever_2d(m)
    m.analysis("Static")
    with pytest.raises(beamsolid.OpenSeesError, match=message):
        m.analyze(*args)


def test_analyze_without_an_analysis_raises_as_in_opensees():
    m = beamsolid.Model()
    cantilever_2d(m)
    with pytest.raises(beamsolid.OpenSeesError, match="no analysis"):
        m.analyze(1)

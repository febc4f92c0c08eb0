"""beamsolid.stepping.adaptive_analyze: the cut/grow logic on a scripted model, and the
integrator re-issue on a real one (LoadControl and DisplacementControl)."""
import pytest

import beamsolid
from beamsolid.stepping import adaptive_analyze


class ScriptedModel:
    """Stands in for a Model: a step converges iff its increment is at most limit(progress);
    a failed step leaves the progress where it was (as beamsolid's analysis does)."""

    def __init__(self, limit, iterations=3):
        self.limit, self.its = limit, iterations
        self.progress, self.increment = 0.0, None
        self.calls = []  # (progress, increment, ok)

    def integrator(self, kind, d):
        assert kind == "LoadControl"
        self.increment = d

    def analyze(self, n):
        assert n == 1
        ok = self.increment <= self.limit(self.progress) + 1e-15
        self.calls.append((self.progress, self.increment, ok))
        if ok:
            self.progress += self.increment
        return 0 if ok else -3

    def testIter(self):
        return self.its


def test_fixed_steps_reach_the_end_in_nominal_increments():
    m = ScriptedModel(lambda s: 1.0)
    r = adaptive_analyze(m, 2.0, 8, adaptive=False)
    assert r.converged and r.steps == 8 and r.failures == 0 and r.cuts == 0
    assert r.increments == pytest.approx([0.25] * 8, rel=1e-15)
    assert m.progress == pytest.approx(2.0, rel=1e-15)


def test_without_adaptive_the_first_failure_ends_the_run():
    m = ScriptedModel(lambda s: 0.1 if s >= 0.5 else 1.0)
    r = adaptive_analyze(m, 1.0, 4, adaptive=False)
    assert not r.converged
    assert r.failed_at == pytest.approx(0.5) and r.steps == 2 and r.failures == 1 and r.cuts == 0
    assert r.returncode == -3 and r.error == ""  # the failed analyze's code; this stand-in keeps no reason


def test_a_failed_run_keeps_the_code_and_the_reason_of_the_last_analyze(model):
    """A bar of ElasticPP (yield force 20) loaded to 40: the step past yield has no stiffness."""
    _bar(model)
    model.uniaxialMaterial("ElasticPP", 2, 4000.0, 0.005)
    model.element("truss", 2, 1, 2, 1.0, 2)
    model.remove("element", 1)
    model.integrator("LoadControl", 1.0)
    model.analysis("Static")
    r = adaptive_analyze(model, 40.0, 4, adaptive=False)
    assert not r.converged and r.failed_at == pytest.approx(20.0)
    assert r.returncode < 0 and r.error == model.last_error() and "singular" in r.error


def test_cut_on_failure_and_grow_back_after_easy_steps():
    # Steps beyond progress 0.5 must be at most 0.07 until 0.75, then anything goes.
    m = ScriptedModel(lambda s: 0.07 if 0.5 - 1e-12 <= s < 0.75 - 1e-12 else 1.0)
    seen = []
    r = adaptive_analyze(m, 1.5, 6, min_fraction=1 / 16, grow_after=2, on_step=lambda s, it: seen.append(s))
    assert r.converged and m.progress == pytest.approx(1.5, rel=1e-14)
    # 0.25 fails at 0.5, so does 0.125: two cuts to 0.0625; two easy steps double it to 0.125,
    # which fails again before 0.75 (third cut); past 0.75 it doubles back to the nominal 0.25.
    assert r.increments == pytest.approx([0.25, 0.25, 0.0625, 0.0625, 0.0625, 0.0625, 0.125, 0.125, 0.25, 0.25])
    assert [c[1] for c in m.calls if not c[2]] == pytest.approx([0.25, 0.125, 0.125])
    assert r.cuts == 3 and r.failures == 3 and r.grows == 3
    assert seen == pytest.approx([sum(r.increments[:k + 1]) for k in range(r.steps)], rel=1e-14)
    assert len(seen) == r.steps == len(r.iterations)


def test_gives_up_at_the_smallest_step():
    m = ScriptedModel(lambda s: 0.001 if s >= 0.5 - 1e-12 else 1.0)
    r = adaptive_analyze(m, 1.0, 2, min_fraction=1 / 8)
    assert not r.converged and r.failed_at == pytest.approx(0.5)
    assert [c[1] for c in m.calls if not c[2]] == pytest.approx([0.5, 0.25, 0.125, 0.0625])
    assert r.cuts == 3


def test_breakpoints_are_hit_exactly_and_no_sliver_steps():
    m = ScriptedModel(lambda s: 1.0)
    seen = []
    r = adaptive_analyze(m, 3.0, 3, breakpoints=(1.0, 2.0), on_step=lambda s, it: seen.append(s))
    assert seen == [1.0, 2.0, 3.0]  # exactly
    m = ScriptedModel(lambda s: 1.0)
    r = adaptive_analyze(m, 1.0, 3, breakpoints=(0.5,))
    assert r.increments == pytest.approx([1 / 3, 1 / 6, 1 / 3, 1 / 6])
    # A remainder under 1 % of the step is merged into it.
    m = ScriptedModel(lambda s: 1.0)
    r = adaptive_analyze(m, 1.0, 3, breakpoints=(1 / 3 + 1e-4,))
    assert r.steps == 3 and r.increments[0] == pytest.approx(1 / 3 + 1e-4)


def test_bad_arguments():
    m = ScriptedModel(lambda s: 1.0)
    for kwargs in (dict(total=0.0, steps=1), dict(total=1.0, steps=0), dict(total=1.0, steps=1, min_fraction=0.0)):
        with pytest.raises(ValueError, match="adaptive_analyze"):
            adaptive_analyze(m, **kwargs)


def _bar(m):
    """A truss bar along x, EA/L = 2000, node 2 loaded by a unit reference load in x."""
    m.model("basic", "-ndm", 3, "-ndf", 3)
    m.node(1, 0.0, 0.0, 0.0)
    m.node(2, 2.0, 0.0, 0.0)
    m.fix(1, 1, 1, 1)
    m.fix(2, 0, 1, 1)
    m.uniaxialMaterial("Elastic", 1, 4000.0)
    m.element("truss", 1, 1, 2, 1.0, 1)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.load(2, 1.0, 0.0, 0.0)
    m.constraints("Plain")
    m.numberer("Plain")
    m.system("UmfPack")
    m.test("NormUnbalance", 1e-10, 5)
    m.algorithm("Newton")


def test_real_model_load_control_and_displacement_control(model):
    _bar(model)
    model.integrator("LoadControl", 1.0)
    model.analysis("Static")
    r = adaptive_analyze(model, 10.0, 4, breakpoints=(5.0,))
    assert r.converged and model.getTime() == pytest.approx(10.0, rel=1e-14)
    assert model.nodeDisp(2, 1) == pytest.approx(10.0 / 2000.0, rel=1e-12)
    # DisplacementControl: the progress is the controlled displacement; the load factor follows.
    model.wipeAnalysis()
    _ = [model.constraints("Plain"), model.numberer("Plain"), model.system("UmfPack"),
         model.test("NormUnbalance", 1e-10, 5), model.algorithm("Newton")]
    model.integrator("DisplacementControl", 2, 1, 1.0)
    model.analysis("Static")
    u0 = model.nodeDisp(2, 1)
    r = adaptive_analyze(model, 0.01, 3, integrator=lambda d: ("DisplacementControl", 2, 1, d))
    assert r.converged and r.steps == 3
    assert model.nodeDisp(2, 1) == pytest.approx(u0 + 0.01, rel=1e-12)
    assert model.getLoadFactor(1) == pytest.approx(2000.0 * (u0 + 0.01), rel=1e-10)
